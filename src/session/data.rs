//! The data behind every figure: the model (the arm, α, δ, k, ε, the preliminary
//! feedback's gain K_pr), the arm linearized at rest (A, B, C, D), the one-period map Φ of the
//! sampled loop with its eigenvalues, ρ and the δ → 0 pair A4, the ρ(δ) curve and both stability
//! maps, with units and the state string.
//!
//! One form is canonical: a long table, one number a row — `quantity,i,j,row,column,value,unit`
//! — headed by a few lines of text ([`FigureData::head`]). [`FigureData::write`] walks the
//! numbers once into a [`Sink`]; [`FigureData::to_csv`] is that table as CSV, the `head` as `# `
//! lines. The JSON is the same table reshaped, one object per quantity —
//! `{"head": [...], "state": "...", "quantities": {"A": {"rows": [...], "columns": [...],
//! "values": [[...]], "units": [[...]]}, ...}}`, non-finite numbers null — built by the CLI
//! (`flexarm data --json`) from the rows and by the page (`www/js/export.js`) from the CSV: only
//! they serialise JSON.
//!
//! Why one long table: one download and one parser for everything; every number sits beside its
//! unit and its place (the 0-based indices rebuild a matrix, the names say what the entry is); a
//! pivot on `quantity` gives any matrix, curve or map back in a spreadsheet or pandas. And the
//! page's module carries only this walker and a CSV writer (no per-field serialisation code,
//! nothing allocated per number but the text).

use core::fmt::{Display, Write};

use super::map_cache::MapSide;
use super::Session;
use crate::analysis::{
    stable_windows, LinearSettings, LoopModel, MapGrid, MapJob, MapRows, StabilityReport, StableWindows,
};
use crate::control::config::SimulationConfig;
use crate::control::linear::Mat10;
use crate::error::Error;
use crate::model::params::PlantParameters;
use crate::schema::{self, ARM_PARAMS};

/// The state x of the arm linearized at rest (the order of A's rows and columns; the trace
/// CSV's names), then the controller output v held over a period: ζ = (x, v), Φ's order.
pub const STATE: [&str; 10] = ["q1", "q2", "theta", "q1_dot", "q2_dot", "theta_dot", "w1", "w2", "v1", "v2"];
/// The input u: the torques, T1 on the motor, T2 on joint 2.
pub const INPUT: [&str; 2] = ["T1", "T2"];
/// The stabilized constraint's two rows, y = C x + D u = 0.
pub const OUTPUT: [&str; 2] = ["y1", "y2"];
/// The table's columns.
pub const COLUMNS: &str = "quantity,i,j,row,column,value,unit";

/// What the whole is, in words (the head's first line).
pub const ABOUT: &str = "flexarm: the numbers behind every figure (the linear analysis of run A), one a row, in SI \
     units. Columns: quantity; i, j (0-based row and column); row, column (their names); value; unit.";

/// What the linearized arm is, in words.
pub const LINEARIZED_ABOUT: &str = "A, B, C, D: the arm (4.1), the integrators (4.2) and the stabilized \
     constraint (4.3) linearized at rest (friction cancelled), in deviations from the rest point: dx/dt = A x + \
     B u, 0 = y = C x + D u. x = (q1, q2, theta [rad], q1_dot, q2_dot, theta_dot [rad/s], w1, w2 [rad/s^2]): the \
     link angles, the motor angle, their speeds and the integrators dw_i/dt = alpha_i^3 (q_i - q_ref_i); u = (T1, \
     T2) [N m], T1 on the motor, T2 on joint 2; y_i = q_i'' + 3 alpha_i q_i' + 3 alpha_i^2 q_i + w_i [rad/s^2]. \
     An entry's unit is its row's quantity (per s in A, B) over its column's. K_pr: u = K_pr x + v.";

/// What the one-period map and the other quantities are, in words.
pub const LOOP_ABOUT: &str = "Phi: the sampled loop of Fig. 2.1 over one period, zeta_{n+1} = Phi zeta_n, \
     zeta = (x(t_n), v on [t_n, t_n + delta)), v = (v1, v2) [N m] the controller's output (applied one period \
     after the x it is predicted from); rows 9-10 are the predictor. eigenvalues: those of Phi, largest |lambda| \
     first (re, im, abs [1]; s = ln(lambda)/delta [1/s]); loop: rho = max |lambda| (stable iff < 1), growth_rate \
     = ln(rho)/delta; limit_pair_open, limit_pair: A4, the pair the loop tends to as delta -> 0, without and with \
     K_pr; rho_curve: the rho(delta) panel; stable_windows: where rho < 1; map_off, map_on: rho on the grid \
     map_alpha x map_delta (rows alpha, columns delta); with the twist damper map_on is the design map, \
     on map_twist_damping x map_delta (rows k_d [N m s/rad] at run A's alpha).";

/// Where the rows go: a CSV writer, or the CLI's JSON.
pub trait Sink {
    /// One number: `quantity`'s entry (`i`, `j`), named `row` and `column`, in `unit`.
    #[allow(clippy::too_many_arguments)]
    fn row(
        &mut self,
        quantity: &str,
        i: usize,
        j: usize,
        row: &dyn Display,
        column: &dyn Display,
        value: f64,
        unit: &str,
    );
}

/// A number as the table writes it: in full, `{:e}`.
pub struct Exp(pub f64);

impl Display for Exp {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "{:e}", self.0)
    }
}

impl Sink for String {
    fn row(
        &mut self,
        quantity: &str,
        i: usize,
        j: usize,
        row: &dyn Display,
        column: &dyn Display,
        value: f64,
        unit: &str,
    ) {
        let _ = writeln!(self, "{quantity},{i},{j},{row},{column},{},{unit}", Exp(value));
    }
}

/// A quantity's unit as far as the ratios here need it: rad (`rad` = 1) or N m (0) times a power
/// of s. An entry's unit is a power of s times 1, rad/(N m) or N m/rad.
#[derive(Clone, Copy)]
struct Unit {
    rad: i8,
    s: i8,
}

const RAD: Unit = Unit { rad: 1, s: 0 };
const RAD_S: Unit = Unit { rad: 1, s: -1 };
const RAD_S2: Unit = Unit { rad: 1, s: -2 };
const RAD_S3: Unit = Unit { rad: 1, s: -3 };
const NM: Unit = Unit { rad: 0, s: 0 };
/// ζ = (x, v): angles, speeds, the integrators, torques.
const UNITS: [Unit; 10] = [RAD, RAD, RAD, RAD_S, RAD_S, RAD_S, RAD_S2, RAD_S2, NM, NM];
/// dx/dt.
const DX: [Unit; 8] = [RAD_S, RAD_S, RAD_S, RAD_S2, RAD_S2, RAD_S2, RAD_S3, RAD_S3];

impl Unit {
    /// The unit of an entry mapping a quantity in `column` to one in `self`.
    fn over(self, column: Unit) -> &'static str {
        const RATIO: [&str; 7] = ["1/s³", "1/s²", "1/s", "1", "s", "s²", "s³"];
        const RAD_PER_NM: [&str; 7] = ["rad/(N m s³)", "rad/(N m s²)", "rad/(N m s)", "rad/(N m)", "", "", ""];
        const NM_PER_RAD: [&str; 7] = ["", "", "", "N m/rad", "N m s/rad", "N m s²/rad", "N m s³/rad"];
        let table = match self.rad - column.rad {
            0 => &RATIO,
            1 => &RAD_PER_NM,
            _ => &NM_PER_RAD,
        };
        table.get((self.s - column.s + 3) as usize).copied().unwrap_or("")
    }
}

/// The controller's constants: key, unit (values in this order in [`FigureData::write`]).
const CONTROLLER: [[&str; 2]; 9] = [
    ["alpha1", "1/s"],
    ["alpha2", "1/s"],
    ["delta", "s"],
    ["k", "1"],
    ["eps_ratio", "1"],
    ["eps", "s"],
    ["horizon", "s"],
    ["rest_q1", "rad"],
    ["rest_q2", "rad"],
];

/// The numbers behind the figures of one configuration, ready to be written: the analysis, the
/// ρ(δ) curve and the maps borrowed from where they were computed.
pub struct FigureData<'a> {
    /// The state string of the settings (the page's URL query, `--state` on the command line).
    pub state: String,
    config: SimulationConfig,
    model: LoopModel,
    phi: Mat10,
    report: &'a StabilityReport,
    windows: Option<&'a StableWindows>,
    maps: Vec<(MapSide, &'a MapJob)>,
    omitted: String,
}

impl<'a> FigureData<'a> {
    /// The data for `config` linearized where `report` (its analysis) is, headed by `state`, with
    /// the ρ(δ) curve of `windows` and the `maps` as far as computed; `omitted` says what is left
    /// out.
    pub fn new(
        config: &SimulationConfig,
        state: String,
        report: &'a StabilityReport,
        windows: Option<&'a StableWindows>,
        maps: Vec<(MapSide, &'a MapJob)>,
        mut omitted: String,
    ) -> Result<Self, Error> {
        let model = LoopModel::new(&LinearSettings::of(config, Some(report.rest[1])))?;
        let phi = model.loop_matrix(report.sampling_period)?;
        for (_, job) in &maps {
            if !job.is_done() {
                let sep = if omitted.is_empty() { "" } else { "; " };
                let pf = job.settings().preliminary_feedback.name();
                let _ = write!(
                    omitted,
                    "{sep}the map with preliminary feedback {pf}: {} of {} rows",
                    job.rows_done(),
                    job.alphas().len()
                );
            }
        }
        Ok(FigureData { state, config: *config, model, phi, report, windows, maps, omitted })
    }

    /// The lines of text above the table: what it is, the state string, the settings in words,
    /// what the quantities are, what is left out.
    pub fn head(&self) -> Vec<String> {
        let c = &self.config;
        let on = MapSide::On.feedback(c.preliminary_feedback).name();
        let mut lines = vec![
            ABOUT.to_string(),
            format!("flexarm state: {}", self.state),
            format!(
                "preliminary feedback {}, inner loop {}, the controller assumes the {} arm; map_off has no preliminary \
                 feedback, map_on {on}",
                c.preliminary_feedback.name(),
                c.inner_loop.name(),
                if c.has_model_error() { "paper's" } else { "real" },
            ),
            LINEARIZED_ABOUT.to_string(),
            LOOP_ABOUT.to_string(),
        ];
        if !self.omitted.is_empty() {
            lines.push(format!("omitted: {}", self.omitted));
        }
        lines
    }

    /// Every number, row by row, into `sink`.
    pub fn write(&self, sink: &mut dyn Sink) {
        let config = &self.config;
        let r = self.report;
        let c = &config.controller;
        let mut arm = |name: &str, p: &PlantParameters| {
            for (i, (k, value)) in ARM_PARAMS.iter().zip(p.values()).enumerate() {
                sink.row(name, i, 0, &k.key, &"value", value, k.unit);
            }
        };
        arm("arm", &config.plant);
        if config.has_model_error() {
            arm("controller_arm", &config.model_plant());
        }
        let values = [
            c.alpha[0],
            c.alpha[1],
            r.sampling_period,
            c.horizon_steps as f64,
            c.eps_ratio,
            c.integration_step(),
            c.horizon(),
            r.rest[0],
            r.rest[1],
        ];
        for (i, ([key, unit], value)) in CONTROLLER.iter().zip(values).enumerate() {
            sink.row("controller", i, 0, key, &"value", value, unit);
        }
        let lin = self.model.arm();
        let x = &UNITS[..8];
        matrix(sink, "K_pr", &INPUT, &STATE[..8], &[NM; 2], x, self.model.gain().as_slice());
        matrix(sink, "A", &STATE[..8], &STATE[..8], &DX, x, lin.a.as_slice());
        matrix(sink, "B", &STATE[..8], &INPUT, &DX, &[NM; 2], lin.b.as_slice());
        matrix(sink, "C", &OUTPUT, &STATE[..8], &[RAD_S2; 2], x, lin.c.as_slice());
        matrix(sink, "D", &OUTPUT, &INPUT, &[RAD_S2; 2], &[NM; 2], lin.d.as_slice());
        matrix(sink, "Phi", &STATE, &STATE, &UNITS, &UNITS, self.phi.as_slice());
        for (i, p) in r.poles.iter().enumerate() {
            let [re, im] = p.discrete;
            let [s_re, s_im] = p.continuous.unwrap_or([f64::NAN; 2]);
            let cells = [
                ("re", re, "1"),
                ("im", im, "1"),
                ("abs", re.hypot(im), "1"),
                ("s_re", s_re, "1/s"),
                ("s_im", s_im, "1/s"),
            ];
            for (j, (column, v, unit)) in cells.into_iter().enumerate() {
                sink.row("eigenvalues", i, j, &i, &column, v, unit);
            }
        }
        sink.row("loop", 0, 0, &"spectral_radius", &"value", r.spectral_radius, "1");
        sink.row("loop", 1, 0, &"growth_rate", &"value", r.growth_rate, "1/s");
        let none: &[[f64; 2]] = &[];
        let (scan, windows) = self.windows.map_or((none, none), |w| (&w.scan[..], &w.windows[..]));
        let no_axis: &[f64] = &[];
        let axis_of = |rows: MapRows| {
            self.maps.iter().find(|(_, job)| job.rows() == rows).map_or(no_axis, |(_, job)| job.alphas())
        };
        let deltas = self.maps.first().map_or(no_axis, |(_, job)| job.deltas());
        let (alphas, dampings) = (axis_of(MapRows::Alpha), axis_of(MapRows::TwistDamping));
        type Pairs<'p> = (&'p str, &'p [[f64; 2]], [&'p str; 2], [&'p str; 2]);
        let tables: [Pairs; 4] = [
            ("limit_pair_open", &r.limit_pair_open, ["re", "im"], ["1/s"; 2]),
            ("limit_pair", &r.limit_pair, ["re", "im"], ["1/s"; 2]),
            ("rho_curve", scan, ["delta", "rho"], ["s", "1"]),
            ("stable_windows", windows, ["from", "to"], ["s"; 2]),
        ];
        for (name, list, columns, units) in tables {
            for (i, pair) in list.iter().enumerate() {
                for j in 0..2 {
                    sink.row(name, i, j, &i, &columns[j], pair[j], units[j]);
                }
            }
        }
        let axes =
            [("map_delta", deltas, "s"), ("map_alpha", alphas, "1/s"), ("map_twist_damping", dampings, "N m s/rad")];
        for (name, axis, unit) in axes {
            for (i, v) in axis.iter().enumerate() {
                sink.row(name, i, 0, &i, &"value", *v, unit);
            }
        }
        for (side, job) in &self.maps {
            let name = if *side == MapSide::Off { "map_off" } else { "map_on" };
            let n = job.deltas().len().max(1);
            for (k, v) in job.values().iter().enumerate() {
                let (i, j) = (k / n, k % n);
                sink.row(name, i, j, &Exp(job.alphas()[i]), &Exp(job.deltas()[j]), *v, "1");
            }
        }
    }

    /// The table as CSV: the head as `# ` lines, the columns' names, one row per number.
    pub fn to_csv(&self) -> String {
        let mut out = String::with_capacity(64 * 1024);
        for line in self.head() {
            let _ = writeln!(out, "# {line}");
        }
        out.push_str(COLUMNS);
        out.push('\n');
        self.write(&mut out);
        out
    }
}

/// The rows of a matrix given column-major (nalgebra's order), its rows in `row_units` (out of
/// line: one copy for six matrices in the page's module).
#[inline(never)]
#[allow(clippy::too_many_arguments)]
fn matrix(
    sink: &mut dyn Sink,
    name: &str,
    rows: &[&str],
    columns: &[&str],
    row_units: &[Unit],
    column_units: &[Unit],
    column_major: &[f64],
) {
    for (i, (row, ru)) in rows.iter().zip(row_units).enumerate() {
        for (j, (column, cu)) in columns.iter().zip(column_units).enumerate() {
            sink.row(name, i, j, row, column, column_major[j * rows.len() + i], ru.over(*cu));
        }
    }
}

/// Both maps of `config`'s settings at link-2 angle `q2` (without preliminary feedback, and with
/// the paper's or its LQ design, as the page pairs them) on the page's grid, computed to the end
/// (≈ 0.2 s).
pub fn computed_maps(config: &SimulationConfig, q2: Option<f64>) -> Result<Vec<(MapSide, MapJob)>, Error> {
    let linear = LinearSettings::of(config, q2);
    let mut maps = Vec::new();
    for side in MapSide::BOTH {
        let mut job = super::map_cache::job_for(&linear, side, &MapGrid::DEFAULT)?;
        job.step_while(|| true)?;
        maps.push((side, job));
    }
    Ok(maps)
}

/// The ρ(δ) curve of `config`'s settings as the page computes it: over the δ control's span.
pub fn rho_curve(config: &SimulationConfig, q2: Option<f64>) -> Result<StableWindows, Error> {
    let range = schema::DELTA.number().expect("δ is a number").control;
    stable_windows(&LinearSettings::of(config, q2), range)
}

impl Session {
    /// The data behind the figures on screen as CSV ([`FigureData::to_csv`]): run A's analysis
    /// at the rest point it linearizes at now, the ρ(δ) curve (unless a lesson step hides it until
    /// its answer) and the maps as far as they are computed.
    pub fn figure_data_csv(&self) -> Result<String, Error> {
        if self.answers_hidden() {
            // ρ, Φ's eigenvalues and the maps are the answers student mode keeps back.
            return Err(Error::NotReady(
                "student mode hides the data behind the figures (ρ, the eigenvalues, the maps) until you answer",
            ));
        }
        let config = self.settings.a.config();
        let report = self.a.analysis().report().ok_or(Error::Analysis("run A's settings have no linear analysis"))?;
        let mut omitted = String::new();
        let windows = if self.hidden.windows {
            omitted.push_str("the rho(delta) curve: hidden until the lesson step's question is answered");
            None
        } else {
            Some(rho_curve(&config, Some(report.rest[1]))?)
        };
        let maps = MapSide::BOTH.iter().filter_map(|&s| self.maps.shown(s).map(|e| (s, e.job()))).collect();
        let data = FigureData::new(&config, self.settings.run_query(), report, windows.as_ref(), maps, omitted)?;
        Ok(data.to_csv())
    }
}
