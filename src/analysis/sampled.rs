//! The sampled closed loop of Fig. 2.1 linearized at rest: its one-period map, eigenvalues λ and
//! spectral radius ρ (the loop is stable iff ρ < 1), and the report the page and the CLI show.
//!
//! What ρ certifies: local stability of one rest point (the slew's end unless told otherwise),
//! with the friction cancelled ([`describes`]). It is an asymptotic rate — errors behave like ρⁿ
//! over many periods —, not a bound per period: a non-normal loop can first grow many times
//! over even with ρ < 1.

use nalgebra::{Complex, SMatrix};
use serde::{Deserialize, Serialize};

use super::digital::{digital_eigenvalues, digital_loop, digital_spectral_radius, DigitalLoop};
use super::energy::{swing_energy, EnergyModel, SwingEnergy};
use super::resonance::ResonanceReport;
use crate::control::config::{
    ControllerModel, ControllerParameters, InnerLoop, LqWeights, PreliminaryFeedbackChoice, SimulationConfig,
    TwistFeedback,
};
use crate::control::feedback::{resolve_gain, FeedbackGain};
use crate::control::linear::{expm, limit_pair, linearize_at_rest, predictor_gain, LinearModel, Mat10, Mat8};
use crate::control::sensing::VelocityEstimator;
use crate::error::Error;
use crate::model::params::PlantParameters;

/// What the linear analysis of a configuration depends on, and nothing else: the friction
/// compensation, the slew's start and timing, the trace spacing and the divergence bound do not
/// change ρ (the analysis takes the friction as cancelled). Two configurations with equal
/// `LinearSettings` have the same eigenvalues — this is the key every cache of analyses uses.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinearSettings {
    pub plant: PlantParameters,
    /// Link angles (q1, q2) of the rest point, rad.
    pub rest: [f64; 2],
    pub controller: ControllerParameters,
    pub preliminary_feedback: PreliminaryFeedbackChoice,
    /// The twist feedback's gains (`Twist`).
    pub twist: TwistFeedback,
    /// The LQ design's weights (`Lq`).
    pub lq: LqWeights,
    pub inner_loop: InnerLoop,
    /// Operating point q2 of the LQ design, rad.
    pub lq_design_q2: f64,
    /// The arm the controller assumes.
    pub model: ControllerModel,
    /// How a digital controller estimates velocities (sensors on, [`super::digital`]); None for
    /// the paper's loop. The noise level does not change ρ, so it is not here.
    pub sensing: Option<VelocityEstimator>,
}

impl LinearSettings {
    /// The settings of `config`, linearized at the end of its slew (or at link-2 angle `q2`).
    pub fn of(config: &SimulationConfig, q2: Option<f64>) -> Self {
        Self {
            plant: config.plant,
            rest: [config.reference.end[0], q2.unwrap_or(config.reference.end[1])],
            controller: config.controller,
            preliminary_feedback: config.preliminary_feedback,
            twist: config.twist,
            lq: config.lq,
            inner_loop: config.inner_loop,
            lq_design_q2: config.lq_design_q2,
            model: config.model,
            sensing: config.sensors.is_digital().then_some(config.sensors.estimator()),
        }
    }

    /// The same settings at another sampling period and α1 = α2 = `alpha` (a map cell).
    pub fn at(&self, delta: f64, alpha: [f64; 2]) -> Self {
        let mut s = *self;
        s.controller.sampling_period = delta;
        s.controller.alpha = alpha;
        s
    }

    /// The same settings with another preliminary feedback (the twist gains and the LQ weights
    /// kept only where they act, so that a map without them is one cache entry whatever they are).
    pub fn with_feedback(&self, pf: PreliminaryFeedbackChoice) -> Self {
        let twist = if pf == PreliminaryFeedbackChoice::Twist { self.twist } else { TwistFeedback::default() };
        let lq = if pf == PreliminaryFeedbackChoice::Lq { self.lq } else { LqWeights::default() };
        Self { preliminary_feedback: pf, twist, lq, ..*self }
    }

    /// A configuration with these settings (defaults elsewhere), for validation and the LQ design.
    fn config(&self) -> SimulationConfig {
        let mut c = SimulationConfig {
            plant: self.plant,
            controller: self.controller,
            preliminary_feedback: self.preliminary_feedback,
            twist: self.twist,
            lq: self.lq,
            inner_loop: self.inner_loop,
            lq_design_q2: self.lq_design_q2,
            model: self.model,
            ..SimulationConfig::default()
        };
        c.reference.end = self.rest;
        if let Some(velocity) = self.sensing {
            c.sensors.velocity = velocity.source;
            c.sensors.velocity_filter = velocity.filter;
        }
        c
    }
}

/// The linearized plant and the preliminary feedback for fixed α: everything but δ. Maps and the
/// search for stable windows reuse one `LoopModel` for many δ.
#[derive(Clone, Debug)]
pub struct LoopModel {
    settings: LinearSettings,
    /// The arm linearized: what the sampled plant is.
    model: LinearModel,
    /// The controller's model linearized, where it is not the arm (`model = paper` on another
    /// arm): what the predictor integrates instead of `model`.
    predictor: Option<LinearModel>,
    gain: FeedbackGain,
}

impl LoopModel {
    /// Validates the settings, designs the gain (LQ needs α) and linearizes at rest.
    pub fn new(settings: &LinearSettings) -> Result<Self, Error> {
        let config = settings.config();
        config.validate()?;
        let gain = resolve_gain(&config)?;
        let model = linearize_at_rest(&settings.plant, settings.controller.alpha, settings.rest);
        let predictor = config
            .has_model_error()
            .then(|| linearize_at_rest(&config.model_plant(), settings.controller.alpha, settings.rest));
        Ok(Self { settings: *settings, model, predictor, gain })
    }

    /// The settings at the model's own δ.
    pub fn settings(&self) -> &LinearSettings {
        &self.settings
    }

    /// The arm linearized (what the sampled plant is).
    pub(crate) fn arm(&self) -> &LinearModel {
        &self.model
    }

    /// What the predictor integrates: the controller's model of the arm linearized (the arm
    /// itself unless `model = paper` on another arm).
    pub(crate) fn predictor(&self) -> &LinearModel {
        self.predictor.as_ref().unwrap_or(&self.model)
    }

    /// The preliminary feedback's gain K.
    pub(crate) fn gain(&self) -> &FeedbackGain {
        &self.gain
    }

    /// The one-period map at sampling period `delta` (validated against the schema's range).
    pub fn loop_matrix(&self, delta: f64) -> Result<Mat10, Error> {
        let mut controller = self.settings.controller;
        controller.sampling_period = delta;
        controller.validate()?;
        let predictor = self.predictor.as_ref().unwrap_or(&self.model);
        sampled_loop_matrix(&self.model, predictor, &self.gain, &controller, self.settings.inner_loop)
    }

    /// The digital loop (sensors on) at sampling period `delta` with velocities estimated by `velocity`
    /// (validated against the schema's range): Φ_p, Γ_p from the arm, K_pred from the predictor.
    pub fn digital_loop(&self, delta: f64, velocity: VelocityEstimator) -> Result<DigitalLoop, Error> {
        let mut controller = self.settings.controller;
        controller.sampling_period = delta;
        controller.validate()?;
        digital_loop(&self.model, self.predictor(), &self.gain, &controller, velocity)
    }

    /// ρ at sampling period `delta`: the digital loop's with sensors on, else the sampled loop's.
    pub fn spectral_radius(&self, delta: f64) -> Result<f64, Error> {
        if let Some(velocity) = self.settings.sensing {
            return Ok(digital_spectral_radius(&self.digital_loop(delta, velocity)?.f));
        }
        Ok(loop_eigenvalues(&self.loop_matrix(delta)?).first().map(|c| c.norm()).unwrap_or(0.0))
    }

    /// The shape of the flexible pair at sampling period `delta`: the upper eigenvector of the
    /// one-period map, as the angles (q1, q2, θ) relative to q1 (complex: amplitude and phase).
    /// None if there is no complex pair or q1 does not move in it.
    pub fn mode_shape(&self, delta: f64) -> Result<Option<[Complex<f64>; 3]>, Error> {
        let phi = self.loop_matrix(delta)?;
        let ev = loop_eigenvalues(&phi);
        let Some(lambda) = ev.iter().filter(|l| l.im > 1e-12 * l.norm()).max_by(|a, b| {
            let s = |l: &Complex<f64>| (l.ln() / delta).im.abs();
            s(a).total_cmp(&s(b))
        }) else {
            return Ok(None);
        };
        // With v_q1 = 1, the other nine rows of (Φ − λI) v = 0 give the rest of v.
        let m: SMatrix<Complex<f64>, 10, 10> = phi.map(|v| Complex::new(v, 0.0)) - SMatrix::identity() * *lambda;
        let a: SMatrix<Complex<f64>, 9, 9> = m.fixed_view::<9, 9>(1, 1).into_owned();
        let b: SMatrix<Complex<f64>, 9, 1> = -m.fixed_view::<9, 1>(1, 0).into_owned();
        Ok(a.lu().solve(&b).map(|v| [Complex::new(1.0, 0.0), v[0], v[1]]))
    }

    /// The flexible pair's energy over one period at sampling period `delta`, for its `mode` at
    /// that δ ([`super::energy`]).
    pub fn swing_energy(&self, delta: f64, mode: &super::swing::SwingMode) -> Result<SwingEnergy, Error> {
        let model = EnergyModel {
            arm: &self.model,
            gain: &self.gain,
            inner_loop: self.settings.inner_loop,
            plant: self.settings.plant,
            rest_q2: self.settings.rest[1],
        };
        swing_energy(&model, delta, mode)
    }

    /// The whole report at the model's own δ.
    pub fn report(&self) -> Result<StabilityReport, Error> {
        self.report_at(self.settings.controller.sampling_period)
    }

    /// The whole report at sampling period `delta`. With sensors on, ρ and the poles (sixteen)
    /// are the digital loop's, and the swing's mode and energy (of the 10-state map) are left out.
    pub fn report_at(&self, delta: f64) -> Result<StabilityReport, Error> {
        let (ev, phi) = match self.settings.sensing {
            Some(velocity) => (digital_eigenvalues(&self.digital_loop(delta, velocity)?.f), None),
            None => {
                let phi = self.loop_matrix(delta)?;
                (loop_eigenvalues(&phi), Some(phi))
            }
        };
        let spectral_radius = ev.first().map(|c| c.norm()).unwrap_or(0.0);
        let poles = ev
            .iter()
            .map(|l| Pole {
                discrete: [l.re, l.im],
                continuous: (l.norm() > 0.0).then(|| {
                    let s = l.ln() / delta;
                    [s.re, s.im]
                }),
            })
            .collect();
        let error = self.predictor.as_ref();
        let open = limit_pair_with_model(&self.model, error, &FeedbackGain::zeros())?;
        let with_pf = limit_pair_with_model(&self.model, error, &self.gain)?;
        // The paper's gains and a twist damper do not change with α: their α limit means something.
        let fixed = matches!(
            self.settings.preliminary_feedback,
            PreliminaryFeedbackChoice::Paper | PreliminaryFeedbackChoice::Twist
        );
        let resonance = ResonanceReport::new(
            &self.settings.plant,
            self.settings.controller.alpha,
            self.settings.rest[1],
            &self.gain,
            fixed,
        );
        let mut report = StabilityReport {
            sampling_period: delta,
            rest: self.settings.rest,
            spectral_radius,
            growth_rate: spectral_radius.ln() / delta,
            poles,
            limit_pair_open: pair(&open),
            limit_pair: pair(&with_pf),
            resonance,
            swing_mode: None,
            swing_energy: None,
        };
        if let (Some(phi), [Some(i), _]) = (phi, report.flexible_pair()) {
            let [re, im] = report.poles[i].discrete;
            report.swing_mode = super::swing::SwingMode::new(&phi, Complex::new(re, im));
            report.swing_energy = report.swing_mode.as_ref().and_then(|m| self.swing_energy(delta, m).ok());
        }
        Ok(report)
    }
}

/// The sampled closed loop linearized at rest, as a map of ζ = (x(t_ρ), v on [t_ρ, t_ρ+1)):
/// x_{ρ+1} = Φ x_ρ + Γ v_ρ (+ Γ K x_ρ for a sampled inner loop), v_{ρ+1} = K_pred x_ρ
/// (the prediction from x(t_ρ) is applied one period later, Fig. 2.1). Φ and Γ come from the
/// arm (`model`), K_pred from the controller's model of it (`predictor`, usually the same).
pub fn sampled_loop_matrix(
    model: &LinearModel,
    predictor: &LinearModel,
    gain: &FeedbackGain,
    controller: &ControllerParameters,
    inner_loop: InnerLoop,
) -> Result<Mat10, Error> {
    let delta = controller.sampling_period;
    let k_pred = predictor_gain(predictor, gain, controller)?;
    let a_plant = match inner_loop {
        InnerLoop::Continuous => model.with_feedback(gain),
        InnerLoop::Sampled => model.a,
    };
    let mut aug = Mat10::zeros();
    aug.fixed_view_mut::<8, 8>(0, 0).copy_from(&(a_plant * delta));
    aug.fixed_view_mut::<8, 2>(0, 8).copy_from(&(model.b * delta));
    let transition = expm(&aug);
    let phi: Mat8 = transition.fixed_view::<8, 8>(0, 0).into_owned();
    let gamma: SMatrix<f64, 8, 2> = transition.fixed_view::<8, 2>(0, 8).into_owned();
    let phi = match inner_loop {
        InnerLoop::Continuous => phi,
        InnerLoop::Sampled => phi + gamma * gain,
    };
    let mut m = Mat10::zeros();
    m.fixed_view_mut::<8, 8>(0, 0).copy_from(&phi);
    m.fixed_view_mut::<8, 2>(0, 8).copy_from(&gamma);
    m.fixed_view_mut::<2, 8>(8, 0).copy_from(&k_pred);
    Ok(m)
}

/// One eigenvalue of the sampled loop.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Pole {
    /// λ, the eigenvalue of the one-period map.
    pub discrete: [f64; 2],
    /// s = ln λ / δ, its continuous-time equivalent, 1/s (`None` for λ = 0).
    pub continuous: Option<[f64; 2]>,
}

/// The stability analysis of one configuration.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StabilityReport {
    /// δ, s.
    pub sampling_period: f64,
    /// Link angles of the rest point, rad.
    pub rest: [f64; 2],
    /// ρ, the spectral radius of the one-period map: the loop is stable iff ρ < 1.
    pub spectral_radius: f64,
    /// ln ρ / δ, the asymptotic growth rate of the errors, 1/s.
    pub growth_rate: f64,
    /// All the eigenvalues (ten; sixteen for the digital loop), largest |λ| first.
    pub poles: Vec<Pole>,
    /// The δ → 0 pair A4 without preliminary feedback, 1/s.
    pub limit_pair_open: [[f64; 2]; 2],
    /// The δ → 0 pair A4 with the configured preliminary feedback, 1/s.
    pub limit_pair: [[f64; 2]; 2],
    /// The joint's resonance in closed form at the rest point (what A4 is made of).
    pub resonance: ResonanceReport,
    /// The flexible pair as a mode: its eigenvectors, to split a run's errors ([`super::swing`]).
    pub swing_mode: Option<super::swing::SwingMode>,
    /// The flexible pair's energy over one period: who feeds it, who takes it out
    /// ([`super::energy`]); `None` without a flexible pair.
    pub swing_energy: Option<SwingEnergy>,
}

impl StabilityReport {
    /// The indices (into `poles`) of the flexible pair, the joint's resonance in the sampled loop.
    /// It swings at about ω = |Im A4| (the δ → 0 pair with the loop's own preliminary feedback),
    /// so over one period its eigenvalues turn by ωδ — seen folded into [0, π]: aliased beyond the
    /// Nyquist frequency π/δ, and at it split into two real negative eigenvalues. The pair is the
    /// eigenvalue whose angle is nearest that, with its conjugate (or, real, its real twin).
    pub fn flexible_pair(&self) -> [Option<usize>; 2] {
        // A pair damped past its swing (two real eigenvalues as δ → 0, a strong twist damper) does
        // not turn: every real pole has angle 0, and the pair is the two real poles whose s are
        // nearest the limit's two — not the slow modes the links' law places near −α.
        let [[r0, i0], [r1, i1]] = self.limit_pair;
        if i0 == 0.0 && i1 == 0.0 && r0.is_finite() && r1.is_finite() {
            let real_s = |p: &Pole| match p.continuous {
                Some([re, im]) if im.abs() <= 1e-9 * re.abs().max(1e-300) => Some(re),
                _ => None,
            };
            let nearest = |target: f64, skip: Option<usize>| {
                self.poles
                    .iter()
                    .enumerate()
                    .filter(|(j, _)| Some(*j) != skip)
                    .filter_map(|(j, p)| real_s(p).map(|re| (j, (re - target).abs())))
                    .min_by(|a, b| a.1.total_cmp(&b.1))
                    .map(|(j, _)| j)
            };
            let first = nearest(r0, None);
            return [first, nearest(r1, first)];
        }
        let omega = self.limit_pair[0][1].abs();
        let turn = (omega * self.sampling_period).rem_euclid(core::f64::consts::TAU);
        let target = if turn > core::f64::consts::PI { core::f64::consts::TAU - turn } else { turn };
        let angle = |p: &Pole| p.discrete[1].atan2(p.discrete[0]).abs();
        let modulus = |p: &Pole| p.discrete[0].hypot(p.discrete[1]);
        let score = |p: &Pole| (angle(p) - target).abs();
        let real = |p: &Pole| p.discrete[1].abs() <= 1e-12 * modulus(p);
        let candidates =
            || self.poles.iter().enumerate().filter(|(_, p)| modulus(p) > 0.0 && p.discrete[1] >= -1e-12 * modulus(p));
        // Nearest angle first; of two as near, the larger |λ|.
        let better = |a: &Pole, b: &Pole| {
            let (sa, sb) = (score(a), score(b));
            if (sa - sb).abs() > 1e-9 {
                sa < sb
            } else {
                modulus(a) > modulus(b)
            }
        };
        let mut best: Option<usize> = None;
        for (i, p) in candidates() {
            if best.is_none_or(|j| better(p, &self.poles[j])) {
                best = Some(i);
            }
        }
        let Some(i) = best else { return [None, None] };
        let p = &self.poles[i];
        let partner = if real(p) {
            // Its real twin: the next real eigenvalue of the same sign nearest the angle.
            let mut twin: Option<usize> = None;
            for (j, q) in
                candidates().filter(|(j, q)| *j != i && real(q) && q.discrete[0].signum() == p.discrete[0].signum())
            {
                if twin.is_none_or(|k| better(q, &self.poles[k])) {
                    twin = Some(j);
                }
            }
            twin
        } else {
            // Its conjugate: the pole with λ nearest to conj(λ).
            let [lr, li] = p.discrete;
            self.poles
                .iter()
                .enumerate()
                .filter(|(j, _)| *j != i)
                .min_by(|(_, a), (_, b)| {
                    let da = (a.discrete[0] - lr).hypot(a.discrete[1] + li);
                    let db = (b.discrete[0] - lr).hypot(b.discrete[1] + li);
                    da.total_cmp(&db)
                })
                .map(|(j, _)| j)
        };
        [Some(i), partner]
    }
}

/// The δ → 0 pair when the controller's model of the arm (`predictor`) differs from the arm
/// (`plant`): the predictor's limit feedback K_lim, computed on its model, closes the real arm,
/// ẋ = (A + B(K + K_lim)) x, and the sampled loop's s = ln λ/δ tend to its eigenvalues as δ → 0
/// (`tests/model.rs` checks that at δ = 1e-4 s). With the model exact this is A4 on the
/// quotient, [`limit_pair`]; with a model error the six poles at −α move too and no quotient
/// separates the pair, so it is picked from all eight: the complex pair swinging fastest (the
/// joint's resonance), or, if none swings, the two rightmost.
pub fn limit_pair_with_model(
    plant: &LinearModel,
    predictor: Option<&LinearModel>,
    gain: &FeedbackGain,
) -> Result<[Complex<f64>; 2], Error> {
    let Some(predictor) = predictor else { return Ok(limit_pair(plant, gain)?.eigenvalues) };
    let limit = limit_pair(predictor, gain)?;
    let closed = plant.with_feedback(&(gain + limit.k_lim));
    // The sampled loop's 10×10 eigen-solver, with two padding eigenvalues beyond every eigenvalue
    // of the 8×8 block (|λ| ≤ 8 max |a_ij|): they come first by modulus and are dropped.
    let mut padded = Mat10::from_diagonal_element(-(1.0 + 16.0 * closed.amax()));
    padded.fixed_view_mut::<8, 8>(0, 0).copy_from(&closed);
    let ev = loop_eigenvalues(&padded);
    let ev = &ev[2..];
    if ev.iter().any(|l| !l.norm().is_finite()) {
        return Err(Error::Analysis("the loop with the controller's model error has no finite eigenvalues"));
    }
    let swinging = ev.iter().filter(|l| l.im > 1e-9 * l.norm()).max_by(|a, b| a.im.total_cmp(&b.im));
    if let Some(l) = swinging {
        return Ok([*l, l.conj()]);
    }
    // All real: the two rightmost.
    let rightmost = |skip: Option<usize>| {
        (0..ev.len()).filter(|&i| Some(i) != skip).max_by(|&i, &j| ev[i].re.total_cmp(&ev[j].re)).unwrap_or(0)
    };
    let first = rightmost(None);
    Ok([ev[first], ev[rightmost(Some(first))]])
}

fn pair(c: &[Complex<f64>; 2]) -> [[f64; 2]; 2] {
    [[c[0].re, c[0].im], [c[1].re, c[1].im]]
}

/// Eigenvalues of the one-period map, largest modulus first, computed on the map balanced
/// ([`balanced`]): the same eigenvalues, without the error a badly scaled map puts in them.
pub fn loop_eigenvalues(m: &Mat10) -> Vec<Complex<f64>> {
    let mut ev: Vec<Complex<f64>> = balanced(m).complex_eigenvalues().iter().copied().collect();
    crate::sort::sort_by(&mut ev, |a, b| b.norm().total_cmp(&a.norm()).then(b.im.total_cmp(&a.im)));
    ev
}

/// True if the linear analysis describes a run of `config`: it takes the friction as cancelled,
/// which only the continuous compensation does. Held over δ or left off, the Dahl friction at rest
/// acts as a presliding spring F_c/ε (≈ 48 000 N m/rad on the motor, forty times K1), which no
/// linearization with the friction cancelled contains: only the simulation can judge such a run.
/// With `model = paper` on an arm whose friction differs from the paper's, the observer cancels
/// the paper's friction, not the arm's: the rest is again a presliding spring only the
/// simulation has.
pub fn describes(config: &SimulationConfig) -> bool {
    let friction = |p: &PlantParameters| [p.fc1, p.fc2, p.eps1, p.eps2];
    config.friction_compensation == crate::control::config::FrictionCompensation::Continuous
        && friction(&config.model_plant()) == friction(&config.plant)
}

/// Analyses `config` linearized at rest at its final configuration, or at link-2 angle `q2`.
pub fn analyze(config: &SimulationConfig, q2: Option<f64>) -> Result<StabilityReport, Error> {
    config.validate()?;
    LoopModel::new(&LinearSettings::of(config, q2))?.report()
}

/// The spectral radius alone.
pub fn spectral_radius(config: &SimulationConfig, q2: Option<f64>) -> Result<f64, Error> {
    config.validate()?;
    let settings = LinearSettings::of(config, q2);
    LoopModel::new(&settings)?.spectral_radius(settings.controller.sampling_period)
}

/// D⁻¹ M D with D diagonal, powers of 2 chosen so that each state's row and column have about the
/// same size (Parlett and Reinsch's balancing, as LAPACK's `gebal` does before an eigen-solver):
/// the same eigenvalues, exactly (scaling by 2ᵏ rounds nothing). Why: an eigen-solver's error is
/// about 1e-16 times the matrix's norm, and the one-period map's scales differ by as much as the
/// arm's do: with a soft joint the predictor's gain from q1 to the motor torque is ~1/K1 while the
/// held torque's effect on q1 is ~K1 (Φ's entries span 1e-20 to 1e9 at K1 = 1e-12 N m/rad), and
/// nalgebra's solver, which does not balance, gave ρ = 70571 where the balanced map gives 1.0267.
fn balanced(m: &Mat10) -> Mat10 {
    let mut a = *m;
    if a.iter().all(|v| v.is_finite()) {
        balance(&mut a);
    }
    a
}

/// Balances `a` in place (D⁻¹ a D, D diagonal powers of 2, see [`balanced`]) and returns D's
/// diagonal. `a` must be finite. (One balancing for every size: [`super::digital::balance`].)
pub(crate) fn balance(a: &mut Mat10) -> [f64; 10] {
    super::digital::balance(a)
}
