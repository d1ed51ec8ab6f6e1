//! The sensor study's job and what the page sees of it (the session's `sensor_study` runs it).

use crate::analysis::sensor_study::{LinearRow, SensorStudy};
use crate::control::config::SimulationConfig;
use crate::control::sensor_sweep::SensorSweep;

/// The running study and what it was started for.
#[derive(Clone, Debug, Default)]
pub struct StudyJob {
    /// Run A's configuration with δ normalized away.
    pub(super) key: Option<SimulationConfig>,
    pub(super) sweep: Option<SensorSweep>,
    /// ρ and the linear prediction at each δ studied, computed with the sweep.
    pub(super) linear: Vec<LinearRow>,
    /// Counts the study's changes (a start, each run done): the figure copies the facts only
    /// when this moved.
    pub(super) generation: u64,
}

/// The study as the page shows it: facts, and the words and table rendered from them.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct SensorStudyView {
    /// The facts (not sent to the page, which shows the words and the table).
    #[serde(skip)]
    pub study: SensorStudy,
    /// The share of the runs done, 0 … 1.
    pub progress: f64,
    /// "a 1024-count encoder, velocities differenced over δ, …".
    pub sensors: String,
    /// The header row and one row per δ, as text.
    pub table: Vec<Vec<String>>,
    /// What the columns are.
    pub table_note: String,
    /// The row of the least error (0-based, without the header), once known.
    pub best_row: Option<usize>,
    /// The row nearest run A's δ.
    pub current_row: usize,
    /// Each row's δ, s: what choosing the row sets.
    pub deltas: Vec<f64>,
    pub summary: Vec<String>,
    /// The linear prediction at run A's δ.
    pub prediction: String,
    pub done: bool,
}
