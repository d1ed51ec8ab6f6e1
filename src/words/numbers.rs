//! Numbers as the sentences say them: a rate with two decimals, an e-folding time, ρ with as many
//! decimals as tell it from 1, a share in percent, a complex pair, with U+2212 for every minus.

use crate::plot::format::{minus, rounded_summands, significant_trimmed};

/// A rate with two decimals and a real minus sign, never "−0.00".
#[inline(never)]
pub fn two_decimals(v: f64) -> String {
    if v.abs() < 0.005 {
        "0.00".into()
    } else {
        minus(&format!("{v:.2}"))
    }
}

/// "e-fold every 0.42 s" for a rate (1/s).
#[inline(never)]
pub fn e_folding(rate: f64) -> String {
    format!("e-fold every {} s", significant_trimmed(1.0 / rate.abs(), 2))
}

/// ρ as the verdict prints it: five decimals where it is nearly 1.
#[inline(never)]
pub fn rho(rho: f64) -> String {
    if (rho - 1.0).abs() < 5e-4 {
        format!("{rho:.5}")
    } else {
        format!("{rho:.4}")
    }
}

/// "1.5 %" (one decimal, U+2212 for minus).
#[inline(never)]
pub fn percent(v: f64) -> String {
    minus(&format!("{:.1} %", 100.0 * v))
}

/// "2.64 ± 29.58j 1/s".
#[inline(never)]
pub fn complex_pair(re: f64, im: f64) -> String {
    minus(&format!("{re:.2} ± {:.2}j 1/s", im.abs()))
}

/// Two eigenvalues of a real matrix, each [re, im] (a conjugate pair or two real ones), with
/// `decimals` decimals: "2.6391 ± 29.5823j 1/s", or "0.0765 and -143.6381 1/s (two real
/// eigenvalues)" where both are real — never a real pair written as "± 0.0000j". ASCII minus, as
/// the command line's tables print; the page's sentences wrap it in [`minus`].
pub fn eigen_pair(pair: [[f64; 2]; 2], decimals: usize) -> String {
    let [[r0, i0], [r1, i1]] = pair;
    let scale = r0.abs().max(r1.abs()).max(1.0);
    if i0.abs() <= 1e-12 * scale && i1.abs() <= 1e-12 * scale {
        let (hi, lo) = if r0 >= r1 { (r0, r1) } else { (r1, r0) };
        format!("{hi:.decimals$} and {lo:.decimals$} 1/s (two real eigenvalues)")
    } else {
        format!("{r0:.decimals$} ± {:.decimals$}j 1/s", i0.abs())
    }
}

/// The eigenvalues of a real 2×2 matrix from its trace and determinant: "2.64 ± 29.58j 1/s", or
/// "−1.00 and −5.00 1/s" where they are real.
pub fn eigenvalues_2x2(trace: f64, det: f64) -> String {
    let (mean, disc) = (trace / 2.0, trace * trace / 4.0 - det);
    if disc < 0.0 {
        complex_pair(mean, (-disc).sqrt())
    } else {
        minus(&format!("{:.2} and {:.2} 1/s", mean + disc.sqrt(), mean - disc.sqrt()))
    }
}

/// "2.64 1/s" with a minus sign where negative.
#[inline(never)]
pub fn per_second(v: f64) -> String {
    minus(&format!("{v:.2} 1/s"))
}

/// The swing's energy shares as printed, as fractions: W_v, W_K, D and their net |λ|² − 1, each
/// rounded to 0.1 % so that the printed balance adds up (the net is |λ|² − 1 rounded; a share
/// may be rounded the other way, by less than 0.1 %).
pub fn energy_shares(e: &crate::analysis::energy::SwingEnergy) -> [f64; 4] {
    let parts = [e.held_torque, e.preliminary_feedback, -e.damping].map(|v| 100.0 * v);
    let [v, k, d] = rounded_summands(parts, 0.1);
    [v, k, -d, v + k + d].map(|p| p / 100.0)
}
