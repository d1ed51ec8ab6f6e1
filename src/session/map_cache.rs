//! The two stability maps the page shows — without and with preliminary feedback — for the
//! current settings: which map a setting change needs (decided here, not in the page), a small
//! cache of maps already computed, and the work spread over frames.

pub use crate::analysis::stability_map::MapSide;
use crate::analysis::{log_space, LinearSettings, MapGrid, MapJob, MapRows};
use crate::control::config::PreliminaryFeedbackChoice;
use crate::words::settings::feedback_short;

/// Maps kept (each 6000 numbers); the least recently shown go first.
pub const CACHE_SIZE: usize = 8;

/// One map, computed or being computed.
#[derive(Clone, Debug)]
pub struct MapEntry {
    /// The settings mapped, with δ and α normalized away (the cache key).
    key: LinearSettings,
    job: MapJob,
    /// Why the job stopped, if it failed.
    failed: Option<String>,
    /// Wall-clock bookkeeping, ms: first chunk, total computing, start to done.
    started_ms: Option<f64>,
    compute_ms: f64,
    done_ms: Option<f64>,
    last_shown: u64,
    /// Distinguishes entries, so the picture knows when it shows another map.
    id: u64,
}

impl MapEntry {
    pub fn job(&self) -> &MapJob {
        &self.job
    }

    pub fn is_done(&self) -> bool {
        self.failed.is_some() || self.job.is_done()
    }

    /// Changes whenever the picture of this map would: another map, or more rows.
    pub fn generation(&self) -> (u64, usize) {
        (self.id, self.job.rows_done())
    }

    pub fn feedback(&self) -> PreliminaryFeedbackChoice {
        self.key.preliminary_feedback
    }
}

/// The job of a side's map for run A's linear settings `a` on `grid` (rows of α, or of k_d on
/// the design map): the page's and the CLI's `data` alike.
pub fn job_for(a: &LinearSettings, side: MapSide, grid: &MapGrid) -> Result<MapJob, crate::error::Error> {
    let key = Maps::key(a, side);
    match side.rows(a.preliminary_feedback) {
        MapRows::Alpha => MapJob::on_grid(&key, grid),
        MapRows::TwistDamping => {
            let [lo, hi] = MapRows::TWIST_DAMPING_SPAN;
            MapJob::with_rows(&key, grid.deltas(), log_space(lo, hi, grid.n_alpha), MapRows::TwistDamping)
        }
    }
}

/// How long a finished map took, ms (for the page's performance figures).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct MapTime {
    pub pf: &'static str,
    pub ms: f64,
    pub compute_ms: f64,
}

/// The progress line under the maps.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct MapStatus {
    /// 0–100.
    pub percent: u32,
    pub done: bool,
    pub text: String,
    /// Cells per map.
    pub points: usize,
    /// The maps are shown (and worked on).
    pub shown: bool,
    /// The row's title: what the maps show ("Stability maps ρ(δ, α)").
    pub title: String,
}

/// The maps the page shows and the cache behind them.
#[derive(Clone, Debug)]
pub struct Maps {
    grid: MapGrid,
    entries: Vec<MapEntry>,
    /// Index into `entries` of the map each side shows.
    shown: [Option<usize>; 2],
    /// Work pauses while the maps are hidden.
    pub enabled: bool,
    counter: u64,
    times: Vec<MapTime>,
}

impl Default for Maps {
    fn default() -> Self {
        Self::new(MapGrid::DEFAULT)
    }
}

impl Maps {
    pub fn new(grid: MapGrid) -> Self {
        Self { grid, entries: Vec::new(), shown: [None; 2], enabled: true, counter: 0, times: Vec::new() }
    }

    pub fn grid(&self) -> &MapGrid {
        &self.grid
    }

    /// Makes both sides show the maps of run A's linear settings `a` (starting jobs as needed).
    pub fn show(&mut self, a: &LinearSettings) {
        for side in MapSide::BOTH {
            let key = Self::key(a, side);
            self.counter += 1;
            let index = match self.entries.iter().position(|e| e.key == key) {
                Some(i) => i,
                None => {
                    let (job, failed) = match job_for(a, side, &self.grid) {
                        Ok(job) => (job, None),
                        // An empty job that reports the problem (the map panel stays grey).
                        Err(e) => (
                            MapJob::new(&key, Vec::new(), Vec::new())
                                .unwrap_or_else(|e| panic!("an empty job is valid: {e}")),
                            Some(e.to_string()),
                        ),
                    };
                    self.entries.push(MapEntry {
                        key,
                        job,
                        failed,
                        started_ms: None,
                        compute_ms: 0.0,
                        done_ms: None,
                        last_shown: 0,
                        id: self.counter,
                    });
                    self.entries.len() - 1
                }
            };
            self.entries[index].last_shown = self.counter;
            self.shown[side.index()] = Some(index);
        }
        self.evict();
    }

    /// The settings a side maps, the cache key: run A's with δ normalized away and the side's
    /// feedback; α normalized away too on an α map, and k_d on the design map (its rows).
    pub fn key(a: &LinearSettings, side: MapSide) -> LinearSettings {
        let pf = side.feedback(a.preliminary_feedback);
        match side.rows(a.preliminary_feedback) {
            MapRows::Alpha => a.at(0.0, [0.0, 0.0]).with_feedback(pf),
            MapRows::TwistDamping => {
                let mut key = a.at(0.0, a.controller.alpha).with_feedback(pf);
                key.twist.damping = 0.0;
                key
            }
        }
    }

    fn evict(&mut self) {
        while self.entries.len() > CACHE_SIZE {
            let in_use = |i: usize| self.shown.contains(&Some(i));
            let Some(oldest) =
                (0..self.entries.len()).filter(|&i| !in_use(i)).min_by_key(|&i| self.entries[i].last_shown)
            else {
                return;
            };
            self.entries.remove(oldest);
            for s in self.shown.iter_mut().flatten() {
                if *s > oldest {
                    *s -= 1;
                }
            }
        }
    }

    /// The map a side shows.
    pub fn shown(&self, side: MapSide) -> Option<&MapEntry> {
        self.shown[side.index()].and_then(|i| self.entries.get(i))
    }

    /// True while a shown map is unfinished and the maps are enabled.
    pub fn pending(&self) -> bool {
        self.enabled && MapSide::BOTH.iter().any(|&s| self.shown(s).is_some_and(|e| !e.is_done()))
    }

    /// Computes rows of the first unfinished shown map (the left one first) until `now()` (ms)
    /// has moved `budget_ms` past the start (at least one row). Returns true if work remains.
    pub fn work(&mut self, now: &mut dyn FnMut() -> f64, budget_ms: f64) -> bool {
        if !self.enabled {
            return false;
        }
        let Some(index) =
            MapSide::BOTH.iter().filter_map(|&s| self.shown[s.index()]).find(|&i| !self.entries[i].is_done())
        else {
            return false;
        };
        let entry = &mut self.entries[index];
        let start = now();
        entry.started_ms.get_or_insert(start);
        let result = entry.job.step_while(|| now() - start < budget_ms);
        let end = now();
        entry.compute_ms += end - start;
        if let Err(e) = result {
            entry.failed = Some(e.to_string());
        } else if entry.job.is_done() {
            let ms = end - entry.started_ms.unwrap_or(start);
            entry.done_ms = Some(ms);
            self.times.push(MapTime { pf: entry.key.preliminary_feedback.name(), ms, compute_ms: entry.compute_ms });
        }
        self.pending()
    }

    /// ρ at (δ, row value: α or k_d) on a side's map: the nearest grid cell (in log scale); NaN
    /// where not computed yet.
    pub fn rho_at(&self, side: MapSide, delta: f64, value: f64) -> f64 {
        let Some(entry) = self.shown(side) else { return f64::NAN };
        let job = &entry.job;
        let nearest = |axis: &[f64], v: f64| {
            (0..axis.len()).min_by(|&i, &j| (axis[i] / v).ln().abs().total_cmp(&(axis[j] / v).ln().abs()))
        };
        match (nearest(job.deltas(), delta), nearest(job.alphas(), value)) {
            (Some(i), Some(j)) => job.values().get(j * job.deltas().len() + i).copied().unwrap_or(f64::NAN),
            _ => f64::NAN,
        }
    }

    /// What the rows of a side's map vary (α until a map is shown).
    pub fn rows(&self, side: MapSide) -> MapRows {
        self.shown(side).map_or(MapRows::Alpha, |e| e.job.rows())
    }

    /// Start-to-done times of every map finished so far.
    pub fn times(&self) -> &[MapTime] {
        &self.times
    }

    /// The progress line: "computing 6000 points per map… 37 %", then the times.
    pub fn status(&self) -> MapStatus {
        let points = self.grid.n_delta * self.grid.n_alpha;
        let entries: Vec<&MapEntry> = MapSide::BOTH.iter().filter_map(|&s| self.shown(s)).collect();
        if entries.is_empty() {
            return MapStatus {
                percent: 0,
                done: false,
                text: "waiting to start".into(),
                points,
                shown: self.enabled,
                title: String::new(),
            };
        }
        let progress = entries.iter().map(|e| if e.is_done() { 1.0 } else { e.job.progress() }).sum::<f64>()
            / entries.len() as f64;
        let percent = (progress * 100.0).round() as u32;
        let done = entries.iter().all(|e| e.is_done());
        let text = if let Some(e) = entries.iter().find_map(|e| e.failed.as_ref()) {
            format!("map failed: {e}")
        } else if done {
            let parts: Vec<String> = entries
                .iter()
                .map(|e| {
                    let time = e.done_ms.map_or("—".into(), |ms| format!("{:.2}", ms / 1000.0));
                    let which = match e.feedback() {
                        PreliminaryFeedbackChoice::Off => "without K_pr".to_string(),
                        f => format!("with {}", feedback_short(f)),
                    };
                    format!("{time} s {which}")
                })
                .collect();
            format!("map: {points} points in {}", parts.join(", "))
        } else if !self.enabled {
            format!("paused at {percent} % (maps hidden)")
        } else {
            format!("computing {points} points per map… {percent} %")
        };
        MapStatus { percent, done, text, points, shown: self.enabled, title: String::new() }
    }
}
