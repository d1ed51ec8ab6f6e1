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
    /// q_d1, q_d2, rad.
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
    Qd1 qd1 "qd1 [rad]" |s| s.qd[0];
    Qd2 qd2 "qd2 [rad]" |s| s.qd[1];
    E1 e1 "e1 [rad]" |s| s.error[0];
    E2 e2 "e2 [rad]" |s| s.error[1];
    Torque1 torque1 "T1 [N m]" |s| s.torque[0];
    Torque2 torque2 "T2 [N m]" |s| s.torque[1];
    V1 v1 "v1 [N m]" |s| s.v[0];
    V2 v2 "v2 [N m]" |s| s.v[1];
    Xf1Hat xf1_hat "xf1_hat [N m]" |s| s.xf_hat[0];
    Xf2Hat xf2_hat "xf2_hat [N m]" |s| s.xf_hat[1];
}

impl Column {
    /// The column with this key.
    pub fn from_key(key: &str) -> Option<Column> {
        Column::ALL.into_iter().find(|c| c.key() == key)
    }
}

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

    /// The CSV header row: each column's name and unit.
    pub fn csv_header() -> String {
        Column::ALL.map(Column::header).join(",")
    }

    /// Writes the series as CSV: an optional `# ` comment line (the state string), the header
    /// row, then one row per sample.
    pub fn write_csv(&self, out: &mut impl Write, comment: Option<&str>) -> std::io::Result<()> {
        if let Some(c) = comment {
            writeln!(out, "# {}", c.replace('\n', " "))?;
        }
        writeln!(out, "{}", Self::csv_header())?;
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

    /// The series as CSV (see [`Traces::write_csv`]).
    pub fn to_csv(&self, comment: Option<&str>) -> String {
        let mut out = Vec::with_capacity(self.len() * Column::ALL.len() * 18 + 200);
        // Writing to a Vec cannot fail.
        let _ = self.write_csv(&mut out, comment);
        String::from_utf8(out).unwrap_or_default()
    }
}
