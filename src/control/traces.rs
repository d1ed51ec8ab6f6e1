//! What a run records: the newest state ([`Snapshot`]) and the time series ([`Traces`]), whose
//! columns are declared once in [`Column`] — the CSV header, the page's typed arrays and the view
//! all read that one table.

use std::io::Write;

use serde::{Deserialize, Serialize};

/// The newest state, for drawing.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Snapshot {
    /// t, s.
    pub time: f64,
    /// q1, q2, θ, rad.
    pub q: [f64; 3],
    /// q̇1, q̇2, θ̇, rad/s.
    pub qdot: [f64; 3],
    /// The reference slew q_ref = (q_d1, q_d2), rad (the CSV's `q1_ref`, `q2_ref`).
    pub qd: [f64; 2],
    /// e1, e2, rad.
    pub error: [f64; 2],
    /// Applied T1, T2, N m.
    pub torque: [f64; 2],
    /// Controller output v, N m.
    pub v: [f64; 2],
    /// Observed friction x̂f, N m.
    pub xf_hat: [f64; 2],
    /// Controller integrators w, rad/s².
    pub w: [f64; 2],
    /// The errors as the controller read them, m_n − q_d(t_n), held from the sampling instant t_n
    /// over its period, rad (with the sensors off: `error`).
    pub error_meas: [f64; 2],
    /// The velocities q̇1, q̇2, θ̇ as the controller estimated them, ν_n, held over the period,
    /// rad/s (with the sensors off: `qdot`).
    pub qdot_est: [f64; 3],
}

/// Declares the trace columns once: variant, accessor and key, CSV header with unit, and the value
/// taken from a [`Snapshot`].
macro_rules! columns {
    ($($variant:ident $key:ident $header:literal $value:expr;)*) => {
        /// One recorded quantity.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum Column { $($variant),* }

        impl Column {
            /// Every column, in CSV order.
            pub const ALL: [Column; [$(Column::$variant),*].len()] = [$(Column::$variant),*];

            /// The key the page asks for (`"e1"`, `"torque1"`, …).
            pub fn key(self) -> &'static str {
                match self { $(Column::$variant => stringify!($key)),* }
            }

            /// The CSV header cell: name and unit.
            pub fn header(self) -> &'static str {
                match self { $(Column::$variant => $header),* }
            }

            /// This column's value in a snapshot.
            pub fn of(self, s: &Snapshot) -> f64 {
                let f: fn(&Snapshot) -> f64 = match self { $(Column::$variant => $value),* };
                f(s)
            }

            fn index(self) -> usize {
                self as usize
            }
        }

        impl Traces {
            $(
                #[doc = concat!("The column ", $header, ".")]
                pub fn $key(&self) -> &[f64] {
                    &self.columns[Column::$variant.index()]
                }
            )*
        }
    };
}

columns! {
    T t "t [s]" |s| s.time;
    Q1 q1 "q1 [rad]" |s| s.q[0];
    Q2 q2 "q2 [rad]" |s| s.q[1];
    Theta theta "theta [rad]" |s| s.q[2];
    Q1Dot q1_dot "q1_dot [rad/s]" |s| s.qdot[0];
    Q2Dot q2_dot "q2_dot [rad/s]" |s| s.qdot[1];
    ThetaDot theta_dot "theta_dot [rad/s]" |s| s.qdot[2];
    Q1Ref q1_ref "q1_ref [rad]" |s| s.qd[0];
    Q2Ref q2_ref "q2_ref [rad]" |s| s.qd[1];
    E1 e1 "e1 [rad]" |s| s.error[0];
    E2 e2 "e2 [rad]" |s| s.error[1];
    Torque1 torque1 "T1 [N m]" |s| s.torque[0];
    Torque2 torque2 "T2 [N m]" |s| s.torque[1];
    V1 v1 "v1 [N m]" |s| s.v[0];
    V2 v2 "v2 [N m]" |s| s.v[1];
    Xf1Hat xf1_hat "xf1_hat [N m]" |s| s.xf_hat[0];
    Xf2Hat xf2_hat "xf2_hat [N m]" |s| s.xf_hat[1];
    E1Meas e1_meas "e1_meas [rad]" |s| s.error_meas[0];
    E2Meas e2_meas "e2_meas [rad]" |s| s.error_meas[1];
    Q1DotEst q1_dot_est "q1_dot_est [rad/s]" |s| s.qdot_est[0];
    Q2DotEst q2_dot_est "q2_dot_est [rad/s]" |s| s.qdot_est[1];
    ThetaDotEst theta_dot_est "theta_dot_est [rad/s]" |s| s.qdot_est[2];
}

impl Column {
    /// The column with this key.
    pub fn from_key(key: &str) -> Option<Column> {
        Column::ALL.into_iter().find(|c| c.key() == key)
    }
}

/// What the CSV's columns are, in words: its second `# ` line (after the state string).
pub const CSV_COLUMNS: &str = "columns: t time; q1, q2 the link angles, theta the motor angle, q1_dot, q2_dot, \
     theta_dot their velocities; q1_ref, q2_ref the reference slew; e1, e2 the errors e = q - q_ref; T1, T2 the \
     applied torques (T1 on the motor, T2 on joint 2); v1, v2 the controller's output; xf1_hat, xf2_hat the \
     friction observer's estimate; e1_meas, e2_meas the errors as the controller read them (m - q_ref at the last \
     sampling instant, held over the period) and q1_dot_est, q2_dot_est, theta_dot_est the velocities as it \
     estimated them (with the sensors off: e1, e2 and the true velocities)";

/// The recorded time series, one column per [`Column`] (equal lengths).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Traces {
    columns: [Vec<f64>; Column::ALL.len()],
}

impl Traces {
    /// Traces with the given columns filled (the others empty): for figures of synthetic data.
    pub fn from_columns(columns: impl IntoIterator<Item = (Column, Vec<f64>)>) -> Self {
        let mut t = Traces::default();
        for (c, values) in columns {
            t.columns[c.index()] = values;
        }
        t
    }

    /// Number of samples.
    pub fn len(&self) -> usize {
        self.columns[Column::T.index()].len()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// One column.
    pub fn column(&self, c: Column) -> &[f64] {
        &self.columns[c.index()]
    }

    /// Appends one row: every column's value in `s`.
    pub fn push(&mut self, s: &Snapshot) {
        for c in Column::ALL {
            self.columns[c.index()].push(c.of(s));
        }
    }

    /// Drops the oldest samples so that at most `keep` remain (for bounded live traces).
    pub fn truncate_front(&mut self, keep: usize) {
        let n = self.len();
        if n > keep {
            for col in &mut self.columns {
                col.drain(..n - keep);
            }
        }
    }

    /// Drops the samples after time `t` (a run going back in time).
    pub fn truncate_after(&mut self, t: f64) {
        let keep = self.columns[Column::T.index()].partition_point(|&s| s <= t + 1e-9);
        for col in &mut self.columns {
            col.truncate(keep);
        }
    }

    /// Empties every column, keeping the allocations (for a run written out in chunks).
    pub fn clear(&mut self) {
        for col in &mut self.columns {
            col.clear();
        }
    }

    /// Row `i`: every column's value.
    fn row(&self, i: usize) -> Row {
        std::array::from_fn(|j| self.columns[j][i])
    }

    fn push_row(&mut self, row: &Row) {
        for (col, v) in self.columns.iter_mut().zip(row) {
            col.push(*v);
        }
    }

    /// The CSV header row: each column's name and unit.
    pub fn csv_header() -> String {
        Column::ALL.map(Column::header).join(",")
    }

    /// Writes the CSV head: an optional `# ` comment line (the state string), the `# ` line
    /// [`CSV_COLUMNS`] that says what the columns are, then the header row.
    pub fn write_csv_head(out: &mut impl Write, comment: Option<&str>) -> std::io::Result<()> {
        if let Some(c) = comment {
            writeln!(out, "# {}", c.replace('\n', " "))?;
        }
        writeln!(out, "# {CSV_COLUMNS}")?;
        writeln!(out, "{}", Self::csv_header())
    }

    /// Writes one CSV row per sample (no head): a long run streams its traces chunk by chunk.
    pub fn write_csv_rows(&self, out: &mut impl Write) -> std::io::Result<()> {
        for i in 0..self.len() {
            for (j, col) in self.columns.iter().enumerate() {
                if j > 0 {
                    out.write_all(b",")?;
                }
                write!(out, "{:.10e}", col[i])?;
            }
            out.write_all(b"\n")?;
        }
        Ok(())
    }

    /// Writes the series as CSV: the head ([`Traces::write_csv_head`]), then one row per sample.
    pub fn write_csv(&self, out: &mut impl Write, comment: Option<&str>) -> std::io::Result<()> {
        Self::write_csv_head(out, comment)?;
        self.write_csv_rows(out)
    }

    /// The series as CSV (see [`Traces::write_csv`]).
    pub fn to_csv(&self, comment: Option<&str>) -> String {
        let mut out = Vec::with_capacity(self.len() * Column::ALL.len() * 18 + 200);
        // Writing to a Vec cannot fail.
        let _ = self.write_csv(&mut out, comment);
        String::from_utf8(out).unwrap_or_default()
    }
}

/// The envelope of a run of any length in bounded memory, for a figure: the rows are grouped in
/// buckets of `stride` consecutive samples and each bucket keeps only its rows with the smallest
/// and largest e1 and e2. When more than `limit` rows are held, the stride doubles and the held
/// rows are regrouped. A figure that itself draws each pixel's minimum and maximum (the SVG) looks
/// the same as from the full traces as long as `limit` is several times its number of buckets.
#[derive(Clone, Debug)]
pub struct TraceEnvelope {
    kept: Traces,
    /// Index in the whole run of each kept row.
    index: Vec<u64>,
    /// The open bucket's candidates: the rows with min e1, max e1, min e2, max e2.
    open: [Option<(u64, Row)>; 4],
    stride: u64,
    seen: u64,
    limit: usize,
}

type Row = [f64; Column::ALL.len()];

impl TraceEnvelope {
    /// An empty envelope holding at most about `limit` rows (at least 64).
    pub fn new(limit: usize) -> Self {
        TraceEnvelope {
            kept: Traces::default(),
            index: Vec::new(),
            open: [None; 4],
            stride: 1,
            seen: 0,
            limit: limit.max(64),
        }
    }

    /// Adds every row of `chunk` (the next samples of the run).
    pub fn extend(&mut self, chunk: &Traces) {
        for i in 0..chunk.len() {
            self.add(chunk.row(i));
        }
    }

    /// Adds the run's next row (its index is `self.seen`).
    fn add(&mut self, row: Row) {
        if self.open[0].is_some_and(|(j, _)| j / self.stride != self.seen / self.stride) {
            self.close_bucket();
        }
        let (e1, e2) = (Column::E1.index(), Column::E2.index());
        for (slot, (col, lower)) in self.open.iter_mut().zip([(e1, true), (e1, false), (e2, true), (e2, false)]) {
            let wins = match slot {
                None => true,
                Some((_, r)) => (lower && row[col] < r[col]) || (!lower && row[col] > r[col]),
            };
            if wins {
                *slot = Some((self.seen, row));
            }
        }
        self.seen += 1;
    }

    /// Moves the open bucket's distinct candidates, in time order, to the kept rows.
    fn push_open(open: &[Option<(u64, Row)>; 4], kept: &mut Traces, index: &mut Vec<u64>) {
        let mut rows: [Option<&(u64, Row)>; 4] = std::array::from_fn(|k| open[k].as_ref());
        crate::sort::sort_by_key(&mut rows, |r| r.map(|(j, _)| *j));
        let mut last = None;
        for (j, row) in rows.into_iter().flatten() {
            if last != Some(*j) {
                kept.push_row(row);
                index.push(*j);
                last = Some(*j);
            }
        }
    }

    fn close_bucket(&mut self) {
        Self::push_open(&self.open, &mut self.kept, &mut self.index);
        self.open = [None; 4];
        if self.kept.len() > self.limit {
            // Regroup the kept rows into buckets twice as long (rare: the stride doubles each time).
            self.stride *= 2;
            let (held, index) = (std::mem::take(&mut self.kept), std::mem::take(&mut self.index));
            let mut refill = TraceEnvelope { stride: self.stride, ..TraceEnvelope::new(usize::MAX) };
            for (k, &j) in index.iter().enumerate() {
                refill.seen = j;
                refill.add(held.row(k));
            }
            Self::push_open(&refill.open, &mut refill.kept, &mut refill.index);
            (self.kept, self.index) = (refill.kept, refill.index);
        }
    }

    /// The envelope so far (the open bucket included).
    pub fn traces(&self) -> Traces {
        let (mut out, mut index) = (self.kept.clone(), self.index.clone());
        Self::push_open(&self.open, &mut out, &mut index);
        out
    }

    /// Samples seen in all.
    pub fn samples(&self) -> u64 {
        self.seen
    }
}
