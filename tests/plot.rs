//! The plotting foundation the canvas, its labels and the SVG share: ticks, labels, the ρ colour
//! ramp.

use flexarm::plot::color::{ramp_color, rho_color, rho_position};
use flexarm::plot::format::{self, TickFormat};
use flexarm::plot::palette;
use flexarm::plot::ticks::{label_log_ticks, log_minor_ticks, log_ticks, Ticks};

#[test]
fn ticks_are_nice() {
    assert_eq!(log_ticks(0.002, 0.25, 9), vec![0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2]);
    let minor = log_minor_ticks(0.002, 0.25, &log_ticks(0.002, 0.25, 9));
    assert!(minor.contains(&0.003) && minor.contains(&0.09) && !minor.contains(&0.002));
    assert_eq!(log_ticks(1e-6, 1e3, 9).len(), 10, "powers of ten only");
    assert_eq!(log_ticks(0.03, 0.045, 9).len(), 2);
    // Every tick an exact decimal: 0.6, not 0.6000000000000001.
    assert_eq!(Ticks::new(-0.3, 0.7, 5).collect::<Vec<_>>(), vec![-0.2, 0.0, 0.2, 0.4, 0.6]);
    assert_eq!(Ticks::new(0.0, 0.7, 7).collect::<Vec<_>>(), vec![0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7]);
    assert_eq!(format::number(0.002), "0.002");
    assert_eq!(format::number(-1.5), "−1.5");
    assert_eq!(format::number(2e-7), "2e−7");
    assert_eq!(format::number(250.0), "250");
}

#[test]
fn crowded_log_labels_keep_decades_first_and_their_spacing() {
    let grid = log_ticks(0.002, 0.25, 3);
    // A short axis: labels at least 38 px apart, the grid's decades kept first.
    let kept = label_log_ticks(&grid, 0.002, 0.25, 120.0, 38.0);
    let pos = |v: f64| (v / 0.002f64).ln() / (0.25f64 / 0.002).ln() * 120.0;
    for w in kept.windows(2) {
        assert!(pos(w[1]) - pos(w[0]) >= 38.0 - 1e-9, "{kept:?}");
    }
    for decade in [0.01, 0.1] {
        assert!(grid.contains(&decade) && kept.contains(&decade), "the grid's decades come first: {kept:?}");
    }
    // A long axis: every 1-2-5 value.
    assert_eq!(label_log_ticks(&grid, 0.002, 0.25, 2000.0, 38.0), log_ticks(0.002, 0.25, 100));
}

#[test]
fn tick_labels_name_each_tick() {
    let labels = |t: &[f64]| t.iter().map(|&v| TickFormat::for_ticks(t).format(v)).collect::<Vec<_>>();
    assert_eq!(labels(&[-0.4, -0.2, 0.0, 0.2, 0.4]), ["−0.4", "−0.2", "0", "0.2", "0.4"]);
    assert_eq!(labels(&[-1e-3, -5e-4, 0.0, 5e-4, 1e-3]), ["−1e−3", "−5e−4", "0", "5e−4", "1e−3"]);
    assert_eq!(labels(&[0.0, 2.0, 4.0, 6.0]), ["0", "2", "4", "6"]);
}

#[test]
fn the_map_colours_diverge_around_rho_1() {
    assert_eq!(rho_color(1.0), palette::MAP_NEUTRAL);
    let blue = rho_color(0.5).0;
    let red = rho_color(2.0).0;
    assert!(blue[2] > blue[0] && red[0] > red[2]);
    assert_eq!(rho_color(0.8), rho_color(0.1), "saturates at ρ = 0.8");
    assert_eq!(rho_color(1.2), rho_color(3.0), "saturates at ρ = 1.2");
    assert_eq!(rho_color(f64::NAN), palette::MAP_PENDING);
    // The ramp is what the colour bar draws: position ½ at ρ = 1, monotone on each side.
    assert_eq!(rho_position(1.0), 0.5);
    assert_eq!(ramp_color(rho_position(0.9)), rho_color(0.9));
    assert!(rho_position(0.98) < rho_position(0.99) && rho_position(1.01) < rho_position(1.02));
    // ρ = 0.98 and 1.02 are visibly coloured (the square-root ramp): a fifth of the way out.
    assert!((rho_position(1.02) - 0.5) > 0.15);
}

#[test]
fn the_dark_scheme_inverts_lightness_and_keeps_hue() {
    use flexarm::plot::Color;
    assert_eq!(Color::hex(0xffffff).for_dark().0, [0.0, 0.0, 0.0, 1.0], "white paper turns black");
    assert_eq!(Color::hex(0x000000).for_dark().0, [1.0, 1.0, 1.0, 1.0]);
    let blue = Color::hex(0x1b5599);
    let light = blue.for_dark();
    let lightness = |c: Color| (c.0[0].max(c.0[1]).max(c.0[2]) + c.0[0].min(c.0[1]).min(c.0[2])) / 2.0;
    assert!((lightness(light) - (1.0 - lightness(blue))).abs() < 1e-6);
    // The same channel differences: the same hue and chroma.
    assert!(((light.0[2] - light.0[0]) - (blue.0[2] - blue.0[0])).abs() < 1e-6);
    let back = light.for_dark();
    assert!(back.0.iter().zip(blue.0).all(|(a, b)| (a - b).abs() < 1e-6), "twice is the identity");
    assert_eq!(blue.with_alpha(0.5).for_dark().0[3], 0.5);
}

#[test]
fn grouped_numbers_set_thousands_apart_with_narrow_no_break_spaces() {
    use flexarm::plot::format::grouped;
    assert_eq!(grouped(48200.0), "48\u{202f}200");
    assert_eq!(grouped(1152.6), "1\u{202f}153");
    assert_eq!(grouped(999.4), "999");
    assert_eq!(grouped(-1234567.0), "−1\u{202f}234\u{202f}567");
    assert_eq!(grouped(f64::NAN), "—");
}

/// Parts rounded so that the printed parts add up to the printed total (the energy balance).
#[test]
fn rounded_summands_add_up_and_stay_within_a_step() {
    use flexarm::plot::format::rounded_summands;
    // −14.42 % − 2.34 % = −16.76 %: printed −14.4 − 2.4 = −16.8, not −14.4 − 2.3 = −16.8.
    let r = rounded_summands([-14.42, -2.34], 0.1);
    assert!((r[0] + r[1] - (-16.8)).abs() < 1e-9, "{r:?}");
    let mut seed = 7u64;
    let mut next = || {
        seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        ((seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 40.0
    };
    for _ in 0..2000 {
        let parts = [next(), next(), next()];
        let r = rounded_summands(parts, 0.1);
        let total: f64 = parts.iter().sum();
        assert!((r.iter().sum::<f64>() - (total / 0.1).round() * 0.1).abs() < 1e-9, "{parts:?} → {r:?}");
        for (a, b) in parts.iter().zip(r) {
            assert!((a - b).abs() < 0.1 + 1e-9, "{parts:?} → {r:?}");
            assert!(((b / 0.1).round() * 0.1 - b).abs() < 1e-9, "a multiple of the step");
        }
    }
}
