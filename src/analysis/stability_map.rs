//! Stability maps: ρ over a grid of sampling periods δ and α1 = α2 = α, computed row by row as a
//! resumable [`MapJob`] (the page spreads one over frames; the CLI runs it to the end).

use serde::{Deserialize, Serialize};

use super::sampled::{LinearSettings, LoopModel};
use crate::control::config::{PreliminaryFeedbackChoice, SimulationConfig};
use crate::error::Error;

/// Which of the two maps: without or with preliminary feedback.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum MapSide {
    Off,
    On,
}

impl MapSide {
    pub const BOTH: [MapSide; 2] = [MapSide::Off, MapSide::On];

    /// "off" or "on", as the page names the maps.
    pub fn parse(name: &str) -> Result<MapSide, String> {
        match name {
            "off" => Ok(MapSide::Off),
            "on" => Ok(MapSide::On),
            _ => Err(format!("unknown map '{name}': \"off\" (without preliminary feedback) or \"on\" (with it)")),
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            MapSide::Off => "off",
            MapSide::On => "on",
        }
    }

    /// The map a configuration with this preliminary feedback belongs to.
    pub fn for_feedback(pf: PreliminaryFeedbackChoice) -> MapSide {
        match pf {
            PreliminaryFeedbackChoice::Off => MapSide::Off,
            PreliminaryFeedbackChoice::Paper | PreliminaryFeedbackChoice::Lq | PreliminaryFeedbackChoice::Twist => {
                MapSide::On
            }
        }
    }

    /// The preliminary feedback this side maps, given run A's: none on the left; on the right A's
    /// own feedback if it is the LQ design or a twist damper, else the paper's.
    pub fn feedback(self, current: PreliminaryFeedbackChoice) -> PreliminaryFeedbackChoice {
        match (self, current) {
            (MapSide::Off, _) => PreliminaryFeedbackChoice::Off,
            (MapSide::On, PreliminaryFeedbackChoice::Lq) => PreliminaryFeedbackChoice::Lq,
            (MapSide::On, PreliminaryFeedbackChoice::Twist) => PreliminaryFeedbackChoice::Twist,
            (MapSide::On, _) => PreliminaryFeedbackChoice::Paper,
        }
    }

    /// Index into two-element arrays.
    pub fn index(self) -> usize {
        self as usize
    }

    /// What this side's rows are, given run A's feedback: with the twist damper the right map is
    /// the design map, ρ over δ and k_d at run A's α; otherwise ρ over δ and α.
    pub fn rows(self, current: PreliminaryFeedbackChoice) -> MapRows {
        match (self, current) {
            (MapSide::On, PreliminaryFeedbackChoice::Twist) => MapRows::TwistDamping,
            _ => MapRows::Alpha,
        }
    }
}

/// What a map's rows vary: α1 = α2 = α, or the twist damping k_d at the settings' α (the design
/// map: the cure region above k_d = 3α Ir1 − Bv1 and the digital limit in one picture).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum MapRows {
    #[default]
    Alpha,
    TwistDamping,
}

impl MapRows {
    /// The span of the design map's k_d rows, N m s/rad: the k_d control's, from 1 (a log axis).
    pub const TWIST_DAMPING_SPAN: [f64; 2] = [1.0, 200.0];

    /// The settings of a row with value `value` (α or k_d) at the grid's first δ.
    fn row_settings(self, settings: &LinearSettings, delta: f64, value: f64) -> LinearSettings {
        match self {
            MapRows::Alpha => settings.at(delta, [value, value]),
            MapRows::TwistDamping => {
                let mut s = settings.at(delta, settings.controller.alpha);
                s.twist.damping = value;
                s
            }
        }
    }
}

/// Seconds to compute ρ of one cell on the development machine (measured 30 µs for the default
/// grid with k = 12, rounded up): what [`crate::control::Work`] estimates a map or sweep with.
pub const SECONDS_PER_CELL: f64 = 40e-6;

/// A logarithmic (δ, α) grid: ranges and sizes.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct MapGrid {
    /// δ from, to, s.
    pub delta: [f64; 2],
    pub n_delta: usize,
    /// α = α1 = α2 from, to, 1/s.
    pub alpha: [f64; 2],
    pub n_alpha: usize,
}

impl MapGrid {
    /// The grid of the page and of `flexarm map`: δ over the δ control's span (2 ms – 0.25 s) and
    /// α over the α control's span (0.1 – 5 1/s), 100 × 60 points.
    pub const DEFAULT: MapGrid = MapGrid {
        delta: crate::schema::DELTA_SPEC.control,
        n_delta: 100,
        alpha: crate::schema::ALPHA_SPEC.control,
        n_alpha: 60,
    };
    /// The most points per axis.
    pub const MAX_POINTS: usize = 2000;

    /// The δ values of the columns, s.
    pub fn deltas(&self) -> Vec<f64> {
        log_space(self.delta[0], self.delta[1], self.n_delta)
    }

    /// The α values of the rows, 1/s.
    pub fn alphas(&self) -> Vec<f64> {
        log_space(self.alpha[0], self.alpha[1], self.n_alpha)
    }
}

/// ρ over a grid of sampling periods and stabilizing constants (α1 = α2 = α).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StabilityMap {
    /// δ values, s.
    pub sampling_periods: Vec<f64>,
    /// α values, 1/s.
    pub alphas: Vec<f64>,
    /// ρ for alpha index i and δ index j at `i * sampling_periods.len() + j`.
    pub spectral_radius: Vec<f64>,
}

impl StabilityMap {
    /// ρ at (α index, δ index).
    pub fn at(&self, alpha_index: usize, delta_index: usize) -> f64 {
        self.spectral_radius[alpha_index * self.sampling_periods.len() + delta_index]
    }

    /// ρ along the row of α index `alpha_index`.
    pub fn row(&self, alpha_index: usize) -> &[f64] {
        let n = self.sampling_periods.len();
        &self.spectral_radius[alpha_index * n..(alpha_index + 1) * n]
    }

    /// The fraction of the cells with ρ < 1.
    pub fn stable_fraction(&self) -> f64 {
        let n = self.spectral_radius.len().max(1);
        self.spectral_radius.iter().filter(|r| **r < 1.0).count() as f64 / n as f64
    }
}

/// A stability map being computed, one row of α at a time.
#[derive(Clone, Debug)]
pub struct MapJob {
    settings: LinearSettings,
    deltas: Vec<f64>,
    alphas: Vec<f64>,
    /// ρ of the finished rows, row-major by α.
    rho: Vec<f64>,
    /// Cells whose analysis failed (ρ = NaN).
    failed: usize,
    /// What the rows (`alphas`) vary.
    rows: MapRows,
}

impl MapJob {
    /// A map of `settings` (its preliminary feedback, inner loop, k, m, plant; δ and α are the
    /// grid's) over the given axes. The corners are checked now, so a bad grid fails here.
    pub fn new(settings: &LinearSettings, deltas: Vec<f64>, alphas: Vec<f64>) -> Result<Self, Error> {
        Self::with_rows(settings, deltas, alphas, MapRows::Alpha)
    }

    /// A map whose rows vary `rows` over `values` (α, or k_d at the settings' α).
    pub fn with_rows(
        settings: &LinearSettings,
        deltas: Vec<f64>,
        values: Vec<f64>,
        rows: MapRows,
    ) -> Result<Self, Error> {
        for (d, v) in [(deltas.first(), values.first()), (deltas.last(), values.last())] {
            if let (Some(&d), Some(&v)) = (d, v) {
                rows.row_settings(settings, d, v).controller.validate()?;
            }
        }
        let rho = Vec::with_capacity(deltas.len() * values.len());
        Ok(Self { settings: *settings, deltas, alphas: values, rho, failed: 0, rows })
    }

    /// What the rows vary.
    pub fn rows(&self) -> MapRows {
        self.rows
    }

    /// A job on `grid` for `settings`.
    pub fn on_grid(settings: &LinearSettings, grid: &MapGrid) -> Result<Self, Error> {
        Self::new(settings, grid.deltas(), grid.alphas())
    }

    /// The settings mapped (δ and α of the grid replace theirs).
    pub fn settings(&self) -> &LinearSettings {
        &self.settings
    }

    pub fn deltas(&self) -> &[f64] {
        &self.deltas
    }

    pub fn alphas(&self) -> &[f64] {
        &self.alphas
    }

    /// ρ of the rows computed so far, row-major by α.
    pub fn values(&self) -> &[f64] {
        &self.rho
    }

    pub fn rows_done(&self) -> usize {
        self.rho.len() / self.deltas.len().max(1)
    }

    /// True when every row is computed (at once for an empty grid).
    pub fn is_done(&self) -> bool {
        self.deltas.is_empty() || self.rows_done() >= self.alphas.len()
    }

    /// Fraction of rows computed, 0–1.
    pub fn progress(&self) -> f64 {
        if self.alphas.is_empty() {
            1.0
        } else {
            self.rows_done() as f64 / self.alphas.len() as f64
        }
    }

    /// Cells whose analysis failed so far (shown as NaN).
    pub fn failed_cells(&self) -> usize {
        self.failed
    }

    /// Computes the next row. A row whose linear algebra fails somewhere is redone cell by cell,
    /// the failing cells becoming NaN; configuration errors are returned.
    pub fn step_row(&mut self) -> Result<(), Error> {
        if self.is_done() {
            return Ok(());
        }
        let value = self.alphas[self.rows_done()];
        // The model of a row is built at the row's first δ (any δ of the grid would do: it only
        // fixes the row's α or k_d), so a key whose own δ was normalized away still validates.
        let row_settings = self.rows.row_settings(&self.settings, self.deltas[0], value);
        let before = self.rho.len();
        let row = LoopModel::new(&row_settings).and_then(|model| {
            for &delta in &self.deltas {
                self.rho.push(model.spectral_radius(delta)?);
            }
            Ok(())
        });
        match row {
            Ok(()) => Ok(()),
            Err(Error::Analysis(_)) => {
                self.rho.truncate(before);
                for &delta in &self.deltas {
                    let cell = LoopModel::new(&row_settings).and_then(|m| m.spectral_radius(delta));
                    let r = cell.unwrap_or(f64::NAN);
                    self.failed += usize::from(r.is_nan());
                    self.rho.push(r);
                }
                Ok(())
            }
            Err(e) => {
                self.rho.truncate(before);
                Err(e)
            }
        }
    }

    /// Computes rows until `stop()` says so (after at least one row) or the map is done.
    pub fn step_while(&mut self, mut keep_going: impl FnMut() -> bool) -> Result<(), Error> {
        while !self.is_done() {
            self.step_row()?;
            if !keep_going() {
                break;
            }
        }
        Ok(())
    }

    /// Runs to the end.
    pub fn finish(mut self) -> Result<StabilityMap, Error> {
        self.step_while(|| true)?;
        Ok(StabilityMap { sampling_periods: self.deltas, alphas: self.alphas, spectral_radius: self.rho })
    }
}

/// Computes ρ on the grid `alphas × sampling_periods`, all other settings from `config`.
pub fn stability_map(
    config: &SimulationConfig,
    sampling_periods: &[f64],
    alphas: &[f64],
) -> Result<StabilityMap, Error> {
    config.validate()?;
    MapJob::new(&LinearSettings::of(config, None), sampling_periods.to_vec(), alphas.to_vec())?.finish()
}

/// Geometric spacing from `lo` to `hi` with `n` points (for logarithmic axes).
pub fn log_space(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    match n {
        0 => vec![],
        1 => vec![lo],
        _ => (0..n).map(|i| lo * (hi / lo).powf(i as f64 / (n - 1) as f64)).collect(),
    }
}
