//! The drawing model without a GPU: ticks, autoscale, layout, painter, traces, arm, scene.

use flexarm::analysis::{log_space, stability_map};
use flexarm::control::{Column, Snapshot, Traces};
use flexarm::plot::color::rho_color;
use flexarm::plot::contour::{chain_segments, marching_squares};
use flexarm::plot::ticks::{log_ticks, nice_ceil, Ticks};
use flexarm::session::{Run, RunSettings};
use flexarm::view::autoscale::{Autoscale, AutoscaleSettings};
use flexarm::view::layout::{gutters, Arrangement, Tab};
use flexarm::view::loop_poles::PoleStyle;
use flexarm::view::panels::arm::drawing::{
    drawn_twist, spring_end_angle, ArmFrame, ArmPose, MAX_DRAWN_TWIST, WORLD_HALF_EXTENT,
};
use flexarm::view::panels::pole_plot::drawing::{
    draw_a4, draw_flexible_halo, draw_poles, PoleFrame, RUN_VERTEX_BUDGET,
};
use flexarm::view::panels::stability_maps::grid::StabilityGrid;
use flexarm::view::panels::time_plots::drawing::{draw_series, draw_series_within, max_abs, PlotFrame};
use flexarm::view::time_window::TimeWindow;
use flexarm::view::*;
use flexarm::{ClosedLoop, PreliminaryFeedbackChoice, SimulationConfig};

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * a.abs().max(b.abs()).max(1e-300)
}

// ---------------------------------------------------------------- ticks

#[test]
fn nice_ceil_climbs_the_1_2_5_ladder() {
    let cases = [
        (0.7, 1.0),
        (1.0, 1.0),
        (1.01, 2.0),
        (2.0, 2.0),
        (3.0, 5.0),
        (5.0, 5.0),
        (7.3, 10.0),
        (10.0, 10.0),
        (1e-4, 1e-4),
        (1.1e-4, 2e-4),
        (3.4, 5.0),
        (0.0012, 0.002),
        (4.9e-7, 5e-7),
        (123.0, 200.0),
    ];
    for (v, want) in cases {
        assert!(close(nice_ceil(v), want), "nice_ceil({v}) = {}, want {want}", nice_ceil(v));
    }
}

#[test]
fn nice_ceil_is_never_below_its_argument_over_many_decades() {
    let mut v = 1.3e-9;
    while v < 1e9 {
        let n = nice_ceil(v);
        assert!(n >= v * (1.0 - 1e-12) && n <= 2.5 * v * (1.0 + 1e-12), "nice_ceil({v}) = {n}");
        let decade = 10f64.powf(n.log10().floor());
        let m = (n / decade * 1e6).round() / 1e6;
        assert!([1.0, 2.0, 5.0, 10.0].contains(&m), "nice_ceil({v}) = {n} has mantissa {m}");
        v *= 1.37;
    }
}

#[test]
fn ticks_of_a_time_window() {
    let t: Vec<f64> = Ticks::new(0.0, 10.0, 5).collect();
    assert_eq!(t, vec![0.0, 2.0, 4.0, 6.0, 8.0, 10.0]);
    let t: Vec<f64> = Ticks::new(13.37, 23.37, 5).collect();
    assert_eq!(t, vec![14.0, 16.0, 18.0, 20.0, 22.0]);
}

#[test]
fn ticks_of_a_symmetric_error_range_include_zero_and_the_ends() {
    let t: Vec<f64> = Ticks::new(-2e-4, 2e-4, 4).collect();
    assert_eq!(t.len(), 5);
    assert_eq!(t[2], 0.0);
    assert!(close(t[0], -2e-4) && close(t[4], 2e-4), "{t:?}");
}

#[test]
fn tick_count_and_range_are_respected() {
    for i in 0..200 {
        let sign = if i % 2 == 0 { -1.0 } else { 1.0 };
        let lo = sign * 3.7e-5 * 1.1f64.powi(i % 40);
        let hi = lo + 1e-6 * (1.0 + i as f64 * 7.3);
        for max in 2..10 {
            let ticks = Ticks::new(lo, hi, max);
            let step = ticks.step;
            let v: Vec<f64> = ticks.collect();
            assert!(v.len() <= max + 1, "{lo}..{hi}, max {max}: {v:?}");
            // A step of at most 2.5 × range / max fits inside the range once max ≥ 3.
            assert!(max < 3 || !v.is_empty(), "{lo}..{hi}, max {max}: no ticks");
            for w in v.windows(2) {
                assert!((w[1] - w[0] - step).abs() < 1e-9 * step, "{lo}..{hi}, max {max}: {v:?}, step {step}");
            }
            for x in &v {
                assert!(*x >= lo - 1e-9 * step && *x <= hi + 1e-9 * step, "{x} outside {lo}..{hi}");
            }
        }
    }
}

#[test]
fn empty_or_invalid_ranges_have_no_ticks() {
    assert_eq!(Ticks::new(1.0, 1.0, 5).count(), 0);
    assert_eq!(Ticks::new(2.0, 1.0, 5).count(), 0);
    assert_eq!(Ticks::new(f64::NAN, 1.0, 5).count(), 0);
    assert_eq!(Ticks::new(0.0, f64::INFINITY, 5).count(), 0);
}

// ---------------------------------------------------------------- autoscale

#[test]
fn stable_run_errors_of_1e_4_give_a_scale_of_about_1e_4() {
    let mut s = Autoscale::new(AutoscaleSettings::ERROR);
    let y = s.update(0.9e-4, 0.0);
    assert!((1e-4..=2e-4).contains(&y), "Y = {y}");
    let y = s.update(1.2e-4, 0.1);
    assert!(close(y, 2e-4), "Y = {y}");
}

#[test]
fn growing_errors_grow_the_scale_at_once() {
    let mut s = Autoscale::new(AutoscaleSettings::ERROR);
    let mut e = 1e-4;
    let mut t = 0.0;
    while e < 3.2 {
        let y = s.update(e, t);
        assert!(y >= 1.1 * e * (1.0 - 1e-12), "Y = {y} below 1.1 × {e}");
        assert!(y <= 2.5 * 1.1 * e, "Y = {y} far above {e}");
        e *= 1.5;
        t += 0.1;
    }
    // A divergence to π fits on a ±5 rad scale.
    assert!(close(s.update(core::f64::consts::PI, t), 5.0));
}

#[test]
fn the_scale_shrinks_only_after_the_data_stayed_small_for_a_while() {
    let settings = AutoscaleSettings::ERROR;
    let mut s = Autoscale::new(settings);
    assert!(close(s.update(0.8, 0.0), 1.0));
    // Half of Y: no shrinking however long it lasts.
    for i in 1..50 {
        assert!(close(s.update(0.5, i as f64 * 0.1), 1.0));
    }
    // Below a third: held for `shrink_after`, then shrinks to the data.
    let t0 = 10.0;
    let mut t = t0;
    while t < t0 + settings.shrink_after - 0.05 {
        assert!(close(s.update(0.01, t), 1.0), "shrank early at {t}");
        t += 0.05;
    }
    let y = s.update(0.01, t0 + settings.shrink_after + 0.01);
    assert!(close(y, 0.02), "Y = {y}");
    // A brief small dip does not shrink it.
    let mut s = Autoscale::new(settings);
    s.update(0.8, 0.0);
    s.update(0.01, 1.0);
    s.update(0.9, 1.5);
    assert!(close(s.update(0.01, 2.2), 1.0));
}

#[test]
fn reset_floor_and_non_finite_data() {
    let mut s = Autoscale::new(AutoscaleSettings::ERROR);
    assert!(close(s.update(0.0, 0.0), 1e-6), "floor 1e-6 rad");
    assert!(close(s.update(1e-9, 0.1), 1e-6));
    s.update(2.0, 0.2);
    assert!(close(s.update(f64::NAN, 0.3), 5.0), "NaN leaves the scale alone");
    assert!(close(s.update(f64::INFINITY, 0.4), 5.0));
    s.reset();
    assert!(close(s.limit(), 1e-6));
}

// ---------------------------------------------------------------- layout

const SIZES: [(f64, f64); 8] = [
    (1280.0, 800.0),
    (1200.0, 560.0),
    (800.0, 600.0),
    (640.0, 480.0),
    (600.0, 900.0),
    (390.0, 844.0),
    (2560.0, 1440.0),
    (320.0, 320.0),
];

/// Every combination of the panel options (the arm and the errors on and off too, as an embed
/// may ask), on each tab.
fn all_options() -> impl Iterator<Item = LayoutOptions> {
    (0..3072u16).map(|bits| LayoutOptions {
        show_torque: bits & 1 != 0,
        show_poles: bits & 2 != 0,
        show_map: bits & 4 != 0,
        pair: bits & 8 != 0,
        z_plane: bits & 16 != 0,
        show_rho: bits & 32 != 0,
        tab: Tab::ALL[((bits >> 6) & 3) as usize % Tab::ALL.len()],
        show_arm: bits & 256 == 0,
        show_errors: bits & 512 == 0,
        show_velocity: bits & 1024 != 0,
        show_study: bits & 2048 != 0,
    })
}

fn all_layouts() -> impl Iterator<Item = (f64, f64, f64, LayoutOptions, Layout)> {
    SIZES.into_iter().flat_map(|(w, h)| {
        [1.0, 1.25, 2.0, 3.0].into_iter().flat_map(move |dpr| {
            all_options().map(move |options| {
                let layout = Layout::compute(w, h, dpr, &options);
                (w, h, dpr, options, layout)
            })
        })
    })
}

/// A panel's rectangle with its label gutters.
fn with_gutters(p: &flexarm::view::layout::Panel) -> Rect {
    let [l, t, r, b] = gutters(p.kind);
    Rect::new(p.rect.x - l, p.rect.y - t, p.rect.w + l + r, p.rect.h + t + b)
}

#[test]
fn panels_lie_inside_the_canvas_and_do_not_overlap() {
    for (w, h, dpr, options, layout) in all_layouts() {
        let canvas = Rect::new(0.0, 0.0, w, h);
        let kinds: Vec<PanelKind> = layout.panels.iter().map(|p| p.kind).collect();
        let mut want = Vec::new();
        if options.show_arm {
            want.push(PanelKind::Arm);
            if options.pair {
                want.push(PanelKind::ArmB);
            }
        }
        if options.show_errors {
            want.extend([PanelKind::Error1, PanelKind::Error2]);
        }
        if options.show_torque {
            want.push(PanelKind::Torque);
        }
        if options.show_velocity {
            want.push(PanelKind::Velocity);
        }
        if options.show_poles {
            want.push(if options.z_plane { PanelKind::ZPlane } else { PanelKind::Poles });
        }
        if options.show_rho {
            want.push(PanelKind::RhoCurve);
        }
        if options.show_study {
            want.extend([PanelKind::StudyError, PanelKind::StudyTorque]);
        }
        if options.show_map {
            want.extend([PanelKind::MapOff, PanelKind::MapOn]);
        }
        let holds = |tab: Tab, k: PanelKind| match tab {
            Tab::Run => k.is_stage() || k.is_time_plot(),
            Tab::Poles => k.is_pole_plot() || k == PanelKind::RhoCurve,
            Tab::Maps => k.is_map(),
            Tab::Study => k.is_study(),
        };
        let requested = want.clone();
        match layout.tab {
            // A phone shows the panels of one tab: the one asked for if it has panels. Tabs are
            // offered only where two or more have panels, and each offered tab has some.
            Some(tab) => {
                assert_eq!(layout.arrangement, Arrangement::Tabbed);
                assert!(layout.tabs.contains(&tab) && layout.tabs.len() >= 2, "{:?}", layout.tabs);
                assert!(layout.tabs.iter().all(|t| requested.iter().any(|k| holds(*t, *k))), "{:?}", layout.tabs);
                if layout.tabs.contains(&options.tab) {
                    assert_eq!(tab, options.tab);
                }
                want.retain(|k| holds(tab, *k));
            }
            None => assert!(layout.tabs.is_empty()),
        }
        assert_eq!(kinds, want, "{w}×{h} {options:?}");
        // What is not shown is said, never dropped silently: exactly the panels of the other
        // tabs, each on a tab offered.
        let hidden = layout.hidden(&options);
        let expected: Vec<PanelKind> = requested.iter().copied().filter(|k| !want.contains(k)).collect();
        assert_eq!(hidden, expected, "{w}×{h} {options:?}");
        assert!(hidden.iter().all(|k| layout.tabs.iter().any(|t| holds(*t, *k))), "{w}×{h} {options:?}: {hidden:?}");
        for (i, a) in layout.panels.iter().enumerate() {
            assert!(canvas.contains_rect(&a.rect), "{w}×{h}@{dpr} {options:?}: {:?} outside", a);
            let min_size = if w >= 600.0 && h >= 400.0 { 60.0 } else { 1.0 };
            assert!(a.rect.w >= min_size && a.rect.h >= min_size, "{w}×{h} {options:?}: {:?} too small", a);
            // The label gutters stay free of other panels (and on the canvas), except on a tiny
            // canvas where the rows are thinner than their gutters.
            if h < 360.0 {
                continue;
            }
            let mine = with_gutters(a);
            assert!(canvas.contains_rect(&mine), "{w}×{h} {options:?}: gutters of {:?} off canvas", a.kind);
            for b in &layout.panels[i + 1..] {
                assert!(!a.rect.overlaps(&b.rect), "{w}×{h} {options:?}: {:?} overlaps {:?}", a, b);
                assert!(
                    !mine.overlaps(&with_gutters(b)),
                    "{w}×{h} {options:?}: gutters of {:?} and {:?} overlap",
                    a.kind,
                    b.kind
                );
            }
        }
    }
}

#[test]
fn wide_canvases_show_everything_in_two_bands_at_readable_sizes() {
    // The page's canvas on a laptop (1280 × 800), a large screen (1920 × 1080) and a projector.
    for ((w, h), min_side) in [((830.0, 600.0), 125.0), ((1450.0, 900.0), 200.0), ((2500.0, 1300.0), 330.0)] {
        for torque in [false, true] {
            let options = LayoutOptions { show_torque: torque, ..LayoutOptions::default() };
            let l = Layout::compute(w, h, 1.0, &options);
            assert_eq!(l.arrangement, Arrangement::Bands, "{w}×{h}");
            let arm = l.panel(PanelKind::Arm).unwrap().rect;
            let e1 = l.panel(PanelKind::Error1).unwrap().rect;
            let last_time = l.panel(if torque { PanelKind::Torque } else { PanelKind::Error2 }).unwrap().rect;
            assert!(arm.right() < e1.x && (arm.y - e1.y).abs() < 1e-9, "{w}×{h}: the arm left of the traces, on top");
            assert!(arm.w.min(arm.h) >= min_side, "{w}×{h}: the arm {arm:?}");
            let analysis: Vec<Rect> = [PanelKind::Poles, PanelKind::RhoCurve, PanelKind::MapOff, PanelKind::MapOn]
                .into_iter()
                .map(|k| l.panel(k).unwrap().rect)
                .collect();
            for r in &analysis {
                assert!(r.y > arm.bottom() && r.y > last_time.bottom(), "{w}×{h}: the analysis below the top band");
                // Three time plots take height from the analysis row.
                let h_share = if torque { 0.75 } else { 0.9 };
                assert!(r.w >= min_side && r.h >= min_side * h_share, "{w}×{h}: analysis panel {r:?} too small");
            }
            // One row across the whole width, in reading order.
            assert!(analysis.windows(2).all(|p| p[0].y == p[1].y && p[0].right() < p[1].x), "{w}×{h}");
            assert!(analysis[0].x < arm.right(), "{w}×{h}: the row starts under the arm");
        }
    }
}

#[test]
fn phones_show_one_tab_at_a_time_across_the_whole_width() {
    // The page's canvas on a 390-px phone.
    let (w, h) = (372.0, 520.0);
    let l = Layout::compute(w, h, 3.0, &LayoutOptions::default());
    assert_eq!((l.arrangement, l.tab), (Arrangement::Tabbed, Some(Tab::Run)));
    assert_eq!(l.tabs, [Tab::Run, Tab::Poles, Tab::Maps]);
    let arm = l.panel(PanelKind::Arm).unwrap().rect;
    let e2 = l.panel(PanelKind::Error2).unwrap().rect;
    assert!(arm.w >= 0.9 * w && e2.right() > 0.95 * w, "the run fills the width: {arm:?} {e2:?}");
    let maps = Layout::compute(w, h, 3.0, &LayoutOptions { tab: Tab::Maps, ..LayoutOptions::default() });
    let kinds: Vec<PanelKind> = maps.panels.iter().map(|p| p.kind).collect();
    assert_eq!(kinds, [PanelKind::MapOff, PanelKind::MapOn]);
    for p in &maps.panels {
        assert!(p.rect.w >= 250.0 && p.rect.h >= 120.0, "{p:?}");
    }
    // A tab without panels falls back to the run; the intro has no tabs.
    let none =
        Layout::compute(w, h, 3.0, &LayoutOptions { tab: Tab::Maps, show_map: false, ..LayoutOptions::default() });
    assert_eq!(none.tab, Some(Tab::Run));
    assert_eq!(none.tabs, [Tab::Run, Tab::Poles]);
    let intro = LayoutOptions { show_poles: false, show_rho: false, show_map: false, ..LayoutOptions::default() };
    let l = Layout::compute(w, h, 3.0, &intro);
    assert_eq!((l.arrangement, l.tab), (Arrangement::Stacked, None));
}

#[test]
fn two_arms_share_the_stage() {
    let l = Layout::compute(1400.0, 900.0, 2.0, &LayoutOptions { pair: true, ..LayoutOptions::default() });
    let a = l.panel(PanelKind::Arm).unwrap().rect;
    let b = l.panel(PanelKind::ArmB).unwrap().rect;
    assert!(!a.overlaps(&b));
    assert_eq!(a.y, b.y, "side by side in the top band");
    assert!(a.w.min(a.h) >= 300.0 && b.w.min(b.h) >= 300.0, "{a:?} {b:?}");
    let e1 = l.panel(PanelKind::Error1).unwrap().rect;
    assert!(b.right() < e1.x);
    assert_eq!(PanelKind::ArmB.id(), "arm-b");
}

#[test]
fn without_analysis_panels_the_arm_sits_left_on_landscape_canvases_and_on_top_on_portrait_ones() {
    let intro = LayoutOptions { show_poles: false, show_rho: false, show_map: false, ..LayoutOptions::default() };
    let wide = Layout::compute(1280.0, 720.0, 1.0, &intro);
    assert_eq!(wide.arrangement, Arrangement::SideBySide);
    let arm = wide.panel(PanelKind::Arm).unwrap().rect;
    let e1 = wide.panel(PanelKind::Error1).unwrap().rect;
    let e2 = wide.panel(PanelKind::Error2).unwrap().rect;
    assert!(arm.right() < e1.x, "arm left of the plots");
    assert!((arm.w / 1280.0 - 0.4).abs() < 0.05, "arm ≈ 40 % wide: {}", arm.w);
    assert!(e1.bottom() < e2.y, "e1 above e2");
    assert!((e1.w - e2.w).abs() < 1e-9 && (e1.h - e2.h).abs() < 1e-9);
    // A small landscape canvas (presentation mode's largest text on a 1024 × 768 projector lays
    // out 512 × 350) keeps the arm beside the plots too: its square is larger there than on top.
    let small = Layout::compute(500.0, 400.0, 2.0, &intro);
    assert_eq!(small.arrangement, Arrangement::SideBySide);
    let arm = small.panel(PanelKind::Arm).unwrap().rect;
    assert!(
        arm.w.min(arm.h) > 0.42 * 400.0,
        "the arm's square {} beats the stacked 42 % of the height",
        arm.w.min(arm.h)
    );
    for (w, h) in [(390.0, 844.0), (600.0, 900.0), (360.0, 400.0)] {
        let narrow = Layout::compute(w, h, 2.0, &intro);
        assert_eq!(narrow.arrangement, Arrangement::Stacked, "{w}×{h}");
        let arm = narrow.panel(PanelKind::Arm).unwrap().rect;
        let e1 = narrow.panel(PanelKind::Error1).unwrap().rect;
        assert!(arm.bottom() < e1.y, "{w}×{h}: arm above the plots");
    }
    // Portrait canvases with the analysis stack it under the time plots.
    let tall = Layout::compute(700.0, 900.0, 1.0, &LayoutOptions::default());
    assert_eq!(tall.arrangement, Arrangement::Stacked);
    let e2 = tall.panel(PanelKind::Error2).unwrap().rect;
    assert!(tall.panels.iter().filter(|p| p.kind.is_analysis()).all(|p| p.rect.y > e2.bottom()));
}

#[test]
fn device_pixel_ratio_scales_physical_pixels_only() {
    let l1 = Layout::compute(1000.0, 600.0, 1.0, &LayoutOptions::default());
    let l2 = Layout::compute(1000.0, 600.0, 2.0, &LayoutOptions::default());
    assert_eq!(l1.panels, l2.panels, "CSS rectangles do not depend on the ratio");
    assert_eq!(l1.physical_size(), (1000, 600));
    assert_eq!(l2.physical_size(), (2000, 1200));
    assert_eq!(Layout::compute(333.0, 201.0, 1.5, &LayoutOptions::default()).physical_size(), (500, 302));
    let r = l2.panels[1].rect;
    let p = l2.to_physical(r);
    assert_eq!((p.x, p.y, p.w, p.h), (2.0 * r.x, 2.0 * r.y, 2.0 * r.w, 2.0 * r.h));
}

#[test]
fn degenerate_sizes_still_give_a_usable_layout() {
    for (w, h, dpr) in [(0.0, 0.0, 1.0), (f64::NAN, 100.0, 2.0), (100.0, 100.0, 0.0), (-5.0, 50.0, f64::INFINITY)] {
        let l = Layout::compute(w, h, dpr, &LayoutOptions::default());
        let (pw, ph) = l.physical_size();
        assert!(pw >= 1 && ph >= 1);
        assert!(l.device_pixel_ratio.is_finite() && l.device_pixel_ratio > 0.0);
        for p in &l.panels {
            assert!(p.rect.w >= 0.0 && p.rect.h >= 0.0 && p.rect.x.is_finite() && p.rect.y.is_finite());
        }
    }
}

// ---------------------------------------------------------------- painter

#[test]
fn vertex_layout_matches_the_gpu_buffer() {
    assert_eq!(Vertex::SIZE, 24);
    assert_eq!(Vertex::COLOR_OFFSET, 8);
    let mut p = Painter::new();
    p.line([0.0, 0.0], [10.0, 0.0], 2.0, Color::hex(0x102030));
    assert_eq!(p.len(), 6);
    assert_eq!(p.vertex_bytes().len(), 6 * 24);
    let first = f32::from_le_bytes(p.vertex_bytes()[8..12].try_into().unwrap());
    assert!((first - 0x10 as f32 / 255.0).abs() < 1e-7, "red component at byte 8");
    for v in p.vertices() {
        assert!(v.position[1].abs() == 1.0, "a 2 px line along x spans y = ±1");
    }
}

#[test]
fn shapes_are_whole_triangles_and_finite() {
    let mut p = Painter::new();
    let c = Color::hex(0x336699).with_alpha(0.5);
    p.rect(Rect::new(1.0, 2.0, 30.0, 40.0), c);
    p.rect_outline(Rect::new(1.0, 2.0, 30.0, 40.0), 2.0, c);
    p.circle([50.0, 50.0], 20.0, c);
    p.circle([50.0, 50.0], 0.0, c); // nothing
    p.ring([50.0, 50.0], 20.0, 3.0, c);
    p.arc([50.0, 50.0], 20.0, 0.0, 1.0, 3.0, c);
    p.polyline([[0.0, 0.0], [10.0, 5.0], [10.0, 5.0], [20.0, 0.0], [f64::NAN, 0.0], [30.0, 0.0], [40.0, 1.0]], 3.0, c);
    assert_eq!(p.len() % 3, 0);
    assert!(p.vertices().iter().all(|v| v.position.iter().all(|x| x.is_finite())));
    assert!(p.vertices().iter().all(|v| v.color == c.0));
}

#[test]
fn a_non_finite_point_lifts_the_pen() {
    let mut p = Painter::new();
    let c = Color::hex(0);
    p.polyline([[0.0, 0.0], [10.0, 0.0], [f64::NAN, 0.0], [20.0, 0.0], [30.0, 0.0]], 2.0, c);
    // Two separate straight segments, no join, no bridge across the gap.
    assert_eq!(p.len(), 12);
    assert!(p.vertices().iter().all(|v| !(v.position[0] > 10.0 && v.position[0] < 20.0)));
}

#[test]
fn clear_keeps_the_memory() {
    let mut p = Painter::new();
    for i in 0..1000 {
        p.circle([i as f64, 0.0], 10.0, Color::hex(0));
    }
    let cap = p.capacity();
    p.clear();
    assert!(p.is_empty());
    assert_eq!(p.capacity(), cap);
}

// ---------------------------------------------------------------- traces

#[test]
fn the_time_window_scrolls_after_w_seconds() {
    assert_eq!(TimeWindow::ending_at(3.0, 10.0), TimeWindow { start: 0.0, end: 10.0 });
    assert_eq!(TimeWindow::ending_at(10.0, 10.0), TimeWindow { start: 0.0, end: 10.0 });
    assert_eq!(TimeWindow::ending_at(12.5, 10.0), TimeWindow { start: 2.5, end: 12.5 });
    let t: Vec<f64> = (0..1000).map(|i| i as f64 * 0.01).collect();
    let w = TimeWindow { start: 2.0, end: 5.0 };
    let r = w.indices(&t);
    assert!(t[r.start] >= 2.0 && t[r.start - 1] < 2.0);
    assert!(t[r.end - 1] <= 5.0 && t[r.end] > 5.0);
    assert_eq!(TimeWindow { start: 20.0, end: 30.0 }.indices(&t), 1000..1000);
    assert_eq!(max_abs(&[1.0, -3.0, f64::NAN, 2.0]), 3.0);
}

#[test]
fn ten_thousand_samples_cost_two_points_per_pixel_column_and_keep_spikes() {
    let n = 10_000;
    let t: Vec<f64> = (0..n).map(|i| i as f64 * 0.001).collect();
    let mut v: Vec<f64> = t.iter().map(|t| (40.0 * t).sin() * 1e-4).collect();
    v[5_123] = 9e-4; // a one-sample spike
    let frame = PlotFrame {
        log: false,
        rect: Rect::new(100.0, 50.0, 400.0, 200.0),
        window: TimeWindow { start: 0.0, end: 10.0 },
        y_lo: -1e-3,
        y_hi: 1e-3,
    };
    let mut p = Painter::new();
    draw_series(&mut p, &frame, &t, &v, 2.0, Color::hex(0));
    let segments = p.len() / 6;
    assert!(segments < 2 * 400, "{segments} segments for a 400-px-wide plot");
    let top = p.vertices().iter().map(|v| v.position[1]).fold(f32::INFINITY, f32::min);
    let spike_y = frame.y(9e-4) as f32;
    assert!(top <= spike_y + 0.01 && top >= spike_y - 1.01, "spike kept: top {top}, spike at {spike_y}");
    assert!(p.vertices().iter().all(|v| v.position[0] >= 99.0 && v.position[0] <= 501.0));
}

#[test]
fn sparse_samples_are_drawn_as_they_are() {
    let t = [0.0, 1.0, 2.0, 3.0];
    let v = [0.0, 1.0, -1.0, 0.5];
    let frame = PlotFrame {
        log: false,
        rect: Rect::new(0.0, 0.0, 300.0, 100.0),
        window: TimeWindow { start: 0.0, end: 10.0 },
        y_lo: -2.0,
        y_hi: 2.0,
    };
    let mut p = Painter::new();
    draw_series(&mut p, &frame, &t, &v, 2.0, Color::hex(0));
    assert_eq!(p.len(), 3 * 6, "three segments");
}

/// The previous run's faint curve, ten times the plot's range (lesson step 2: Fig. 5.1's errors
/// behind Fig. 5.2's): clipped at the edges, so every piece that leaves the range runs to the edge
/// and stops there — no stubs ending short of it, nothing along the edge — sparse and dense alike.
#[test]
fn a_ghost_beyond_the_range_is_clipped_at_the_edges() {
    let frame = PlotFrame {
        log: false,
        rect: Rect::new(100.0, 50.0, 400.0, 200.0),
        window: TimeWindow { start: 0.0, end: 10.0 },
        y_lo: -1.0,
        y_hi: 1.0,
    };
    let (top, bottom) = (50.0_f32, 250.0_f32);
    for n in [200, 20_000] {
        let t: Vec<f64> = (0..n).map(|i| 10.0 * i as f64 / n as f64).collect();
        // Ten crossings of the window, each steeper than the window is tall per sample when sparse.
        let v: Vec<f64> = t.iter().map(|t| 10.0 * (core::f64::consts::PI * t).sin()).collect();
        let mut p = Painter::new();
        draw_series_within(&mut p, &frame, &t, &v, 2.0, Color::hex(0));
        let ys: Vec<f32> = p.vertices().iter().map(|v| v.position[1]).collect();
        assert!(!ys.is_empty(), "n = {n}: the crossings are drawn");
        // Within the plot (the stroke's half-width aside), and reaching both edges.
        assert!(ys.iter().all(|&y| y >= top - 1.01 && y <= bottom + 1.01), "n = {n}: drawn outside the plot");
        assert!(
            ys.iter().any(|&y| y <= top + 0.01) && ys.iter().any(|&y| y >= bottom - 0.01),
            "n = {n}: not clipped at the edges"
        );
        // Each crossing is one piece from edge to edge: its ten segments' worth of ink, not more
        // (a run along the edge would add pixels at the edge beyond the crossings' own).
        let at_edge = ys.iter().filter(|&&y| y < top + 1.5 || y > bottom - 1.5).count();
        assert!(at_edge <= 10 * 2 * 6 * 2, "n = {n}: {at_edge} vertices at the edges: a line along an edge");
    }
    // The same samples inside the range are drawn exactly as draw_series draws them.
    let t = [0.0, 1.0, 2.0, 3.0];
    let v = [0.0, 0.5, -0.5, 0.25];
    let (mut a, mut b) = (Painter::new(), Painter::new());
    draw_series(&mut a, &frame, &t, &v, 2.0, Color::hex(0));
    draw_series_within(&mut b, &frame, &t, &v, 2.0, Color::hex(0));
    assert_eq!(a.vertices().len(), b.vertices().len());
    assert!(a.vertices().iter().zip(b.vertices()).all(|(x, y)| x.position == y.position));
    // A diverged run swings from far above to far below between two samples: no stroke across
    // the plot for it (it would read as a grey bar of data), while its samples inside still draw.
    let t: Vec<f64> = (0..200).map(|i| 0.05 * i as f64).collect();
    let v: Vec<f64> = (0..200).map(|i| if i % 2 == 0 { 300.0 } else { -300.0 }).collect();
    let mut p = Painter::new();
    draw_series_within(&mut p, &frame, &t, &v, 2.0, Color::hex(0));
    assert!(p.vertices().is_empty(), "{} vertices for swings that never stop inside the range", p.vertices().len());
    // A diverging swing, sampled finely enough to land inside the range at every crossing: once it
    // is ten ranges out it is not followed (each crossing would be a near-vertical stroke: a
    // comb); before, it is drawn as it crosses.
    let n = 20_000;
    let t: Vec<f64> = (0..n).map(|i| 10.0 * i as f64 / n as f64).collect();
    let v: Vec<f64> = t.iter().map(|t| 0.5 * (0.8 * t).exp() * (30.0 * t).sin()).collect();
    let mut p = Painter::new();
    draw_series_within(&mut p, &frame, &t, &v, 2.0, Color::hex(0));
    let xs: Vec<f32> = p.vertices().iter().map(|v| v.position[0]).collect();
    // |v| first passes 21 (an edge plus ten ranges of 2) near t = ln 42 / 0.8 ≈ 4.67 s.
    let last = xs.iter().cloned().fold(f32::MIN, f32::max);
    let x_far = (100.0 + 400.0 * (42f64.ln() / 0.8) / 10.0) as f32;
    assert!(!xs.is_empty() && last < x_far + 10.0, "strokes up to x = {last}, the run left the picture at {x_far}");
}

// ---------------------------------------------------------------- arm

#[test]
fn spring_twist_is_magnified_and_clamped() {
    let pose = ArmPose { q1: 0.5, q2: 0.0, theta: 0.51 };
    assert!((spring_end_angle(&pose, 20.0) - 0.7).abs() < 1e-12);
    assert!((drawn_twist(&pose, 1.0) - 0.01).abs() < 1e-12);
    let wild = ArmPose { q1: 0.0, q2: 0.0, theta: 3.0 };
    assert_eq!(drawn_twist(&wild, 20.0), MAX_DRAWN_TWIST);
    assert_eq!(drawn_twist(&ArmPose { theta: -3.0, ..wild }, 20.0), -MAX_DRAWN_TWIST);
    assert_eq!(drawn_twist(&ArmPose { theta: f64::NAN, ..wild }, 20.0), 0.0);
}

#[test]
fn arm_geometry_and_fit() {
    let pose = ArmPose { q1: core::f64::consts::FRAC_PI_2, q2: -core::f64::consts::FRAC_PI_2, theta: 0.0 };
    let e = pose.elbow();
    let tip = pose.tip();
    assert!(e[0].abs() < 1e-12 && (e[1] - 1.0).abs() < 1e-12);
    assert!((tip[0] - 0.75).abs() < 1e-12 && (tip[1] - 1.0).abs() < 1e-12);
    let panel = Rect::new(10.0, 20.0, 400.0, 300.0);
    let f = ArmFrame::fit(panel, 1.0);
    assert_eq!(f.base, [210.0, 170.0]);
    assert!((f.scale * WORLD_HALF_EXTENT - 150.0).abs() < 1e-9);
    let p = f.point(tip);
    assert!(p[0] > f.base[0] && p[1] < f.base[1], "y up in the world is up on screen");
    let (xr, yr) = f.world_range(panel);
    assert!((yr[1] - WORLD_HALF_EXTENT).abs() < 1e-9 && (yr[0] + WORLD_HALF_EXTENT).abs() < 1e-9);
    assert!(xr[1] > WORLD_HALF_EXTENT);
}

// ---------------------------------------------------------------- options

#[test]
fn options_update_validates_every_field() {
    let mut o = ViewOptions::default();
    assert_eq!((o.show_torque, o.time_window, o.spring_magnification), (false, 10.0, 20.0));
    o.apply(&OptionsUpdate { show_torque: Some(true), ..Default::default() }).unwrap();
    assert!(o.show_torque);
    assert_eq!(o.time_window, 10.0, "missing fields unchanged");
    let before = o;
    assert!(o
        .apply(&OptionsUpdate { time_window: Some(5.0), spring_magnification: Some(-1.0), ..Default::default() })
        .is_err());
    assert_eq!(o, before, "a rejected update changes nothing");
    assert!(o.apply(&OptionsUpdate { time_window: Some(f64::NAN), ..Default::default() }).is_err());
    o.apply(&OptionsUpdate { time_window: Some(30.0), spring_magnification: Some(1.0), ..Default::default() }).unwrap();
    assert_eq!((o.time_window, o.spring_magnification), (30.0, 1.0));
    assert!(OptionsUpdate::check_field("time_window").is_ok());
    let e = OptionsUpdate::check_field("showTorque").unwrap_err();
    assert!(e.contains("showTorque") && e.contains("show_torque"), "{e}");
}

// ---------------------------------------------------------------- scene

fn run(feedback: PreliminaryFeedbackChoice, seconds: f64) -> ClosedLoop {
    let mut config = SimulationConfig::default();
    config.controller.sampling_period = 0.01;
    config.preliminary_feedback = feedback;
    let mut sim = ClosedLoop::new(config).unwrap();
    sim.advance(seconds).unwrap();
    sim
}

/// A run of the session (with its analysis) at δ = 0.01 s after `seconds`.
fn analysed(feedback: PreliminaryFeedbackChoice, seconds: f64) -> Run {
    let mut r = Run::new(RunSettings { delta: 0.01, pf: feedback, ..Default::default() }).unwrap();
    r.advance(seconds, 60.0).unwrap();
    r
}

fn info<'a>(panels: &'a [PanelInfo], id: &str) -> &'a PanelInfo {
    panels.iter().find(|p| p.id == id).unwrap()
}

#[test]
fn scene_autoscale_reads_both_a_stable_and_a_diverging_run() {
    let stable = run(PreliminaryFeedbackChoice::Paper, 3.0);
    let mut scene = Scene::new(ViewOptions::default(), 1200.0, 600.0, 1.0);
    scene.draw(&stable);
    let panels = scene.panel_info();
    let e1 = info(&panels, "e1");
    let max_e1 = max_abs(stable.traces().e1());
    assert!(max_e1 < 1e-3, "the stable run's e1 is small: {max_e1}");
    assert!(e1.y_range[1] >= max_e1 && e1.y_range[1] <= 5.0 * max_e1, "{:?} for max {max_e1}", e1.y_range);
    assert_eq!(e1.y_range[0], -e1.y_range[1]);
    assert_eq!(e1.x_range, [0.0, 10.0]);
    assert_eq!((e1.x_label.as_str(), e1.y_label), ("t [s]", "e1 [rad]"));
    assert!(e1.y_ticks.contains(&0.0));

    let unstable = run(PreliminaryFeedbackChoice::Off, 3.8);
    let mut scene = Scene::new(ViewOptions::default(), 1200.0, 600.0, 1.0);
    scene.draw(&unstable);
    let panels = scene.panel_info();
    for id in ["e1", "e2"] {
        let p = info(&panels, id);
        let column = if id == "e1" { &unstable.traces().e1() } else { &unstable.traces().e2() };
        let m = max_abs(column);
        assert!(m > 0.05, "the unstable run's {id} grows: {m}");
        assert!(p.y_range[1] >= m && p.y_range[1] <= 2.5 * 1.1 * m, "{id}: {:?} for max {m}", p.y_range);
    }
}

#[test]
fn scene_scrolls_resets_and_reports_panels() {
    let mut sim = run(PreliminaryFeedbackChoice::Paper, 12.5);
    let mut scene = Scene::new(ViewOptions::default(), 1000.0, 700.0, 2.0);
    scene.set_options(&OptionsUpdate { show_torque: Some(true), ..Default::default() }).unwrap();
    scene.draw(&sim);
    let panels = scene.panel_info();
    let ids: Vec<&str> = panels.iter().map(|p| p.id).collect();
    assert_eq!(ids, ["arm", "e1", "e2", "torque", "poles", "rho-curve", "map-off", "map-on"]);
    let e2 = info(&panels, "e2");
    assert!((e2.x_range[0] - 2.5).abs() < 1e-9 && (e2.x_range[1] - 12.5).abs() < 1e-9, "{:?}", e2.x_range);
    assert!(e2.x_ticks.iter().all(|t| *t >= 2.5 && *t <= 12.5));
    assert_eq!(info(&panels, "torque").y_label, "T1, T2 [N m]");
    let arm = info(&panels, "arm");
    assert!(arm.x_ticks.is_empty() && arm.y_ticks.is_empty());
    let layout = scene.layout();
    assert_eq!(arm.width, layout.panels[0].rect.w, "panel info is in CSS pixels");

    // A reset (time going back) drops the scales back to the floor before growing again.
    let big = info(&panels, "e1").y_range[1];
    sim.reset().unwrap();
    scene.draw(&sim);
    let e1 = info(&scene.panel_info(), "e1").y_range[1];
    assert!(e1 <= big && e1 == 1e-6, "after reset: {e1}");
}

#[test]
fn scene_vertices_stay_on_the_canvas() {
    let sim = run(PreliminaryFeedbackChoice::Off, 4.0);
    let mut scene = Scene::new(ViewOptions::default(), 900.0, 500.0, 1.5);
    scene.draw(&sim);
    let (w, h) = scene.physical_size();
    assert!(!scene.vertices().is_empty());
    assert_eq!(scene.vertices().len() % 3, 0);
    assert!(!scene.static_vertices().is_empty(), "empty maps still draw their panels");
    assert_eq!(scene.static_vertices().len() % 3, 0);
    for v in scene.vertices().iter().chain(scene.static_vertices()) {
        let [x, y] = v.position;
        assert!(x >= -0.5 && x <= w as f32 + 0.5 && y >= -0.5 && y <= h as f32 + 0.5, "vertex {x},{y} off canvas");
        assert!(v.color.iter().all(|c| (0.0..=1.0).contains(c)));
    }
}

#[test]
fn the_arm_stays_within_its_vertex_budget() {
    use flexarm::view::panels::arm::drawing::{draw_arm_panel, VERTEX_BUDGET};
    let mut p = Painter::new();
    for (q1, q2, twist) in [(0.0, 0.0, 0.0), (1.0, 2.0, 0.3), (-2.0, 3.0, -5.0), (0.5, -0.5, 1e-4)] {
        for size in [100.0, 800.0, 4000.0] {
            p.clear();
            let pose = ArmPose { q1, q2, theta: q1 + twist };
            draw_arm_panel(&mut p, Rect::new(0.0, 0.0, size, size), 2.0, &pose, &pose, 20.0);
            assert!(p.len() <= VERTEX_BUDGET, "{} vertices", p.len());
        }
    }
}

#[test]
fn no_reallocation_after_warm_up() {
    let mut sim = run(PreliminaryFeedbackChoice::Paper, 0.0);
    let mut scene = Scene::new(ViewOptions { show_torque: true, ..Default::default() }, 1280.0, 720.0, 2.0);
    // Warm up over the first second (the slew: the busiest curves).
    for _ in 0..60 {
        sim.advance(1.0 / 60.0).unwrap();
        scene.draw(&sim);
    }
    let capacity = scene.painter().capacity();
    let mut most = 0;
    for _ in 0..900 {
        sim.advance(1.0 / 60.0).unwrap();
        scene.draw(&sim);
        most = most.max(scene.vertices().len());
        assert_eq!(scene.painter().capacity(), capacity, "the painter reallocated");
    }
    assert!(most > 1000, "frames have content: {most} vertices");
}

#[test]
fn the_reserved_capacity_covers_an_oscillating_run_from_the_first_frame() {
    let mut sim = run(PreliminaryFeedbackChoice::Off, 0.0);
    let mut scene = Scene::new(ViewOptions { show_torque: true, ..Default::default() }, 1100.0, 650.0, 1.5);
    let capacity = scene.painter().capacity();
    while !sim.is_finished() && sim.time() < 6.0 {
        sim.advance(1.0 / 30.0).unwrap();
        scene.draw(&sim);
        assert_eq!(scene.painter().capacity(), capacity, "reallocated at t = {}", sim.time());
    }
}

#[test]
fn a_diverged_state_with_non_finite_samples_draws_without_panicking() {
    let (mut t, mut e1, mut e2, mut torque1, mut torque2) = (vec![], vec![], vec![], vec![], vec![]);
    for i in 0..2000 {
        let ti = i as f64 * 0.002;
        let bad = i > 1500;
        t.push(ti);
        e1.push(if bad { f64::NAN } else { (ti * 30.0).sin() * ti });
        e2.push(if bad { f64::INFINITY } else { 1e-5 });
        torque1.push(0.0);
        torque2.push(if i % 2 == 0 { f64::NEG_INFINITY } else { 1.0 });
    }
    let traces = Traces::from_columns([
        (Column::T, t),
        (Column::E1, e1),
        (Column::E2, e2),
        (Column::Torque1, torque1),
        (Column::Torque2, torque2),
    ]);
    let snapshot = Snapshot {
        time: 4.0,
        q: [f64::NAN, 1.0, 2.0],
        qdot: [0.0; 3],
        qd: [1.0, 0.0],
        error: [f64::NAN, 0.0],
        torque: [0.0; 2],
        v: [0.0; 2],
        xf_hat: [0.0; 2],
        w: [0.0; 2],
        error_meas: [0.0; 2],
        qdot_est: [0.0; 3],
    };
    let mut scene = Scene::new(ViewOptions { show_torque: true, ..Default::default() }, 800.0, 600.0, 1.0);
    scene.draw_state(&snapshot, &traces, None);
    assert!(scene.vertices().iter().all(|v| v.position.iter().all(|x| x.is_finite())));
    let panels = scene.panel_info();
    assert!(panels.iter().all(|p| p.y_range.iter().all(|y| y.is_finite())));
}

// ---------------------------------------------------------------- log ticks

#[test]
fn log_ticks_follow_1_2_5_per_decade() {
    assert_eq!(log_ticks(0.002, 0.25, 10), vec![0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2]);
    assert_eq!(log_ticks(0.1, 5.0, 10), vec![0.1, 0.2, 0.5, 1.0, 2.0, 5.0]);
    // Too many for the room: 1 and 5, then powers of ten only, then every other decade.
    assert_eq!(log_ticks(0.002, 0.25, 4), vec![0.005, 0.01, 0.05, 0.1]);
    assert_eq!(log_ticks(0.002, 0.25, 2), vec![0.01, 0.1]);
    assert_eq!(log_ticks(1e-6, 1e6, 6), vec![1e-6, 1e-4, 0.01, 1.0, 100.0, 1e4, 1e6]);
    // Too short for two 1-2-5 ticks: every mantissa.
    assert_eq!(log_ticks(0.11, 0.45, 10), vec![0.2, 0.3, 0.4]);
    assert!(log_ticks(0.0, 1.0, 5).is_empty() && log_ticks(2.0, 1.0, 5).is_empty());
    assert!(log_ticks(1.0, f64::INFINITY, 5).is_empty() && log_ticks(f64::NAN, 1.0, 5).is_empty());
}

// ---------------------------------------------------------------- marching squares

fn linspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n).map(|i| a + (b - a) * i as f64 / (n - 1) as f64).collect()
}

#[test]
fn a_plane_has_a_straight_contour() {
    let xs = linspace(0.0, 2.0, 21);
    let ys = linspace(-1.0, 3.0, 9);
    let values: Vec<f64> = ys.iter().flat_map(|_| xs.iter().copied()).collect();
    // The level lies between grid lines: x = 1.03.
    let segments = marching_squares(&xs, &ys, &values, 1.03);
    assert_eq!(segments.len(), ys.len() - 1, "one segment per row of squares");
    for s in &segments {
        for p in s {
            assert!((p[0] - 1.03).abs() < 1e-12, "{p:?}");
        }
    }
    let lines = chain_segments(&segments);
    assert_eq!(lines.len(), 1, "one polyline");
    let line = &lines[0];
    assert_eq!(line.len(), ys.len());
    let (lo, hi) =
        (line.first().unwrap()[1].min(line.last().unwrap()[1]), line.first().unwrap()[1].max(line.last().unwrap()[1]));
    assert_eq!((lo, hi), (-1.0, 3.0), "from the bottom edge to the top edge");
    // A plane ρ = x at level 1 exactly on a grid line is still found.
    let values: Vec<f64> = ys.iter().flat_map(|_| xs.iter().copied()).collect();
    let segments = marching_squares(&xs, &ys, &values, 1.0);
    assert!(!segments.is_empty());
    assert!(segments.iter().flatten().all(|p| (p[0] - 1.0).abs() < 1e-12));
}

#[test]
fn a_cone_has_a_closed_circular_contour() {
    let xs = linspace(-2.0, 2.0, 61);
    let ys = linspace(-2.0, 2.0, 57);
    let values: Vec<f64> = ys.iter().flat_map(|&y| xs.iter().map(move |&x| x.hypot(y))).collect();
    // 1.3 = |(−1.2, 0.5)|: the contour runs exactly through a grid node there.
    let r = 1.3;
    let segments = marching_squares(&xs, &ys, &values, r);
    assert!(segments.len() > 50);
    for p in segments.iter().flatten() {
        assert!((p[0].hypot(p[1]) - r).abs() < 2e-3, "{p:?} off the circle");
    }
    let lines = chain_segments(&segments);
    assert_eq!(lines.len(), 1, "one closed polyline");
    let line = &lines[0];
    assert_eq!(line.first(), line.last(), "closed");
    assert_eq!(line.len(), segments.len() + 1);
}

#[test]
fn unknown_values_are_skipped_and_saddles_stay_separate() {
    let xs = [0.0, 1.0, 2.0];
    let ys = [0.0, 1.0];
    // The right square has a NaN corner; the left one crosses.
    let values = [0.0, 2.0, f64::NAN, 0.0, 2.0, 5.0];
    let segments = marching_squares(&xs, &ys, &values, 1.0);
    assert_eq!(segments.len(), 1);
    // A partial map (missing rows) is the same as NaN rows.
    assert_eq!(marching_squares(&xs, &ys, &values[..3], 1.0).len(), 0);
    // A saddle: two segments that do not touch.
    let saddle = marching_squares(&[0.0, 1.0], &[0.0, 1.0], &[2.0, 0.0, 0.0, 2.0], 1.0);
    assert_eq!(saddle.len(), 2);
    assert_eq!(chain_segments(&saddle).len(), 2);
}

// ---------------------------------------------------------------- maps

#[test]
fn the_map_colours_diverge_around_rho_1() {
    let white = rho_color(1.0).0;
    assert!(white[..3].iter().all(|c| *c > 0.9), "ρ = 1 near white: {white:?}");
    let stable = rho_color(0.8).0;
    assert!(stable[2] > stable[0] + 0.3, "ρ = 0.8 blue: {stable:?}");
    let unstable = rho_color(1.2).0;
    assert!(unstable[0] > unstable[2] + 0.3, "ρ = 1.2 red: {unstable:?}");
    assert_eq!(rho_color(0.5), rho_color(0.8), "clamped below");
    assert_eq!(rho_color(7.0), rho_color(1.2), "clamped above");
    assert_eq!(rho_color(f64::INFINITY), rho_color(1.2));
    assert_eq!(rho_color(f64::NAN), palette::MAP_PENDING, "not computed: grey");
    // Darker (lower sum of components) the further from 1, on both sides.
    let lum = |r: f64| rho_color(r).0[..3].iter().sum::<f32>();
    assert!(lum(0.99) > lum(0.95) && lum(0.95) > lum(0.85));
    assert!(lum(1.01) > lum(1.05) && lum(1.05) > lum(1.15));
    assert!(lum(0.98) < lum(1.0) - 0.1, "ρ = 0.98 is visibly coloured");
}

#[test]
fn a_stability_grid_validates_and_pads_partial_maps() {
    let mut g = StabilityGrid::default();
    assert!(g.is_empty());
    assert_eq!(g.delta_range(), flexarm::view::panels::stability_maps::grid::DEFAULT_DELTA_RANGE);
    g.set(&[0.01, 0.02, 0.04], &[1.0, 2.0], &[0.9, 1.1, 1.2]).unwrap();
    assert_eq!(g.rho().len(), 6);
    assert_eq!(g.at(0, 1), 1.1);
    assert!(g.at(1, 0).is_nan(), "rows not computed yet are NaN");
    assert!(g.at(0, 3).is_nan());
    assert_eq!((g.delta_range(), g.alpha_range()), ([0.01, 0.04], [1.0, 2.0]));
    assert!(g.set(&[0.01], &[1.0, 2.0], &[]).is_err(), "one column");
    assert!(g.set(&[0.02, 0.01], &[1.0, 2.0], &[]).is_err(), "decreasing");
    assert!(g.set(&[0.0, 0.01], &[1.0, 2.0], &[]).is_err(), "δ = 0 on a log axis");
    assert!(g.set(&[0.01, 0.02], &[1.0, 2.0], &[1.0; 5]).is_err(), "too many values");
    assert_eq!(g.rho().len(), 6, "a rejected map leaves the old one");
    assert_eq!(MapSide::parse("on"), Ok(MapSide::On));
    assert!(MapSide::parse("paper").unwrap_err().contains("\"off\""));
    assert_eq!(MapSide::for_feedback(PreliminaryFeedbackChoice::Lq), MapSide::On);
    assert_eq!(MapSide::for_feedback(PreliminaryFeedbackChoice::Off), MapSide::Off);
}

fn map_config(pf: PreliminaryFeedbackChoice) -> SimulationConfig {
    SimulationConfig { preliminary_feedback: pf, ..Default::default() }
}

#[test]
fn the_contour_of_the_map_without_feedback_brackets_the_stable_window() {
    // δ from 2 ms to 0.25 s, α around 2: the loop without preliminary feedback is stable only
    // for δ in a window of roughly 0.035–0.11 s.
    let deltas = log_space(0.002, 0.25, 40);
    let alphas = log_space(1.0, 4.0, 5);
    let map = stability_map(&map_config(PreliminaryFeedbackChoice::Off), &deltas, &alphas).unwrap();
    let ln_d: Vec<f64> = deltas.iter().map(|d| d.ln()).collect();
    let ln_a: Vec<f64> = alphas.iter().map(|a| a.ln()).collect();
    let segments = marching_squares(&ln_d, &ln_a, &map.spectral_radius, 1.0);
    // Where the contour crosses α = 2 (the middle row).
    let mid = 2f64.ln();
    let mut crossings: Vec<f64> = segments
        .iter()
        .filter(|s| (s[0][1] - mid) * (s[1][1] - mid) <= 0.0 && s[0][1] != s[1][1])
        .map(|s| {
            let t = (mid - s[0][1]) / (s[1][1] - s[0][1]);
            (s[0][0] + t * (s[1][0] - s[0][0])).exp()
        })
        .collect();
    crossings.sort_by(f64::total_cmp);
    crossings.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
    // (A second, narrow stable band near δ ≈ 0.16–0.22 s, where the sampling aliases the flexible
    // mode, adds two more crossings further right.)
    assert!(crossings.len() >= 2, "the window's edges at α = 2: {crossings:?}");
    assert!((0.025..0.045).contains(&crossings[0]), "lower edge {}", crossings[0]);
    assert!((0.09..0.14).contains(&crossings[1]), "upper edge {}", crossings[1]);
}

#[test]
fn maps_go_to_the_static_layer_and_change_only_on_set_map() {
    let deltas = log_space(0.002, 0.25, 24);
    let alphas = log_space(0.1, 5.0, 10);
    let full = stability_map(&map_config(PreliminaryFeedbackChoice::Off), &deltas, &alphas).unwrap();
    let sim = run(PreliminaryFeedbackChoice::Off, 0.5);
    let mut scene = Scene::new(ViewOptions::default(), 1400.0, 900.0, 2.0);
    scene.draw(&sim);
    let g0 = scene.static_generation();
    let empty = scene.static_vertices().len();
    // Half the rows so far.
    scene.set_map(MapSide::Off, &deltas, &alphas, &full.spectral_radius[..5 * deltas.len()]).unwrap();
    let g1 = scene.static_generation();
    assert!(g1 > g0);
    let half = scene.static_vertices().len();
    scene.set_map(MapSide::Off, &deltas, &alphas, &full.spectral_radius).unwrap();
    let whole = scene.static_vertices().len();
    assert!(half > empty && whole > half, "cells and contour: {empty} → {half} → {whole}");
    let g2 = scene.static_generation();
    for _ in 0..5 {
        scene.draw(&sim);
    }
    assert_eq!(scene.static_generation(), g2, "drawing frames does not rebuild the maps");
    // Everything stays inside the map panels (and ρ(δ), the other static panel).
    let off = scene.layout().to_physical(scene.layout().panel(PanelKind::MapOff).unwrap().rect);
    let on = scene.layout().to_physical(scene.layout().panel(PanelKind::MapOn).unwrap().rect);
    let rho = scene.layout().to_physical(scene.layout().panel(PanelKind::RhoCurve).unwrap().rect);
    for v in scene.static_vertices() {
        let [x, y] = [v.position[0] as f64, v.position[1] as f64];
        let inside = |r: Rect| x >= r.x - 0.01 && x <= r.right() + 0.01 && y >= r.y - 0.01 && y <= r.bottom() + 0.01;
        // The contour's halo may poke out by half its width.
        let near = |r: Rect| x >= r.x - 5.0 && x <= r.right() + 5.0 && y >= r.y - 5.0 && y <= r.bottom() + 5.0;
        assert!(
            inside(off) || inside(on) || near(off) || near(on) || inside(rho),
            "static vertex {x},{y} outside the maps"
        );
    }
    let panels = scene.panel_info();
    let map = info(&panels, "map-off");
    assert_eq!((map.x_scale, map.y_scale), ("log", "log"));
    assert_eq!((map.x_label.as_str(), map.y_label), ("δ [s]", "α [1/s]"));
    assert_eq!(map.x_range, [deltas[0], deltas[23]]);
    assert_eq!(map.y_range, [alphas[0], alphas[9]]);
    assert!(map.x_ticks.contains(&0.01) && map.y_ticks.contains(&1.0), "{:?} {:?}", map.x_ticks, map.y_ticks);
    assert!(panels
        .iter()
        .filter(|p| !p.id.starts_with("map") && p.id != "rho-curve")
        .all(|p| p.x_scale == "linear" && p.y_scale == "linear"));
    scene.set_options(&OptionsUpdate { show_map: Some(false), show_rho: Some(false), ..Default::default() }).unwrap();
    assert!(scene.static_vertices().is_empty(), "hidden maps draw nothing");
    assert!(scene.layout().panel(PanelKind::MapOff).is_none());
    scene.set_options(&OptionsUpdate { show_map: Some(true), show_rho: Some(true), ..Default::default() }).unwrap();
    assert_eq!(scene.static_vertices().len(), whole, "the map survives hiding");
    scene.clear_maps();
    assert!(scene.map(MapSide::Off).is_empty());
    assert_eq!(scene.static_vertices().len(), empty);
}

// ---------------------------------------------------------------- poles

fn loop_poles(poles: &[PoleInfo]) -> Vec<&PoleInfo> {
    poles.iter().filter(|p| p.kind == PoleKind::Loop).collect()
}

#[test]
fn preliminary_feedback_moves_the_flexible_pair_across_the_imaginary_axis() {
    let mut flexible_re = Vec::new();
    for pf in [PreliminaryFeedbackChoice::Off, PreliminaryFeedbackChoice::Paper] {
        let sim = analysed(pf, 0.1);
        let mut scene = Scene::new(ViewOptions::default(), 1400.0, 900.0, 1.0);
        scene.draw_loops(sim.closed_loop(), sim.analysis().report(), None);
        let poles = scene.pole_info();
        let loops = loop_poles(&poles);
        assert_eq!(loops.len(), 10);
        let flexible: Vec<_> = loops.iter().filter(|p| p.flexible).collect();
        assert_eq!(flexible.len(), 2, "{pf:?}: one flexible pair");
        assert!((flexible[0].re - flexible[1].re).abs() < 1e-9 && (flexible[0].im + flexible[1].im).abs() < 1e-9);
        assert!((flexible[0].im.abs() - 28.4).abs() < 1.0, "{pf:?}: Im ≈ 28.4 rad/s: {}", flexible[0].im);
        flexible_re.push(flexible[0].re);
        for p in &poles {
            assert_eq!(p.unstable, p.re > 0.0);
            assert!((p.omega - p.re.hypot(p.im)).abs() < 1e-9);
            assert!((p.zeta.unwrap() + p.re / p.omega).abs() < 1e-12);
            assert_eq!(p.run, "A");
        }
        let open: Vec<_> = poles.iter().filter(|p| p.kind == PoleKind::A4Open).collect();
        assert_eq!(open.len(), 2);
        assert!((open[0].re - 2.64).abs() < 0.05 && (open[0].im.abs() - 29.58).abs() < 0.05, "A4 open {:?}", open[0]);
        let a4: Vec<_> = poles.iter().filter(|p| p.kind == PoleKind::A4).collect();
        if pf == PreliminaryFeedbackChoice::Off {
            // No "A4 with K_pr" without K_pr: it would sit on A4 under a name that says otherwise.
            assert!(a4.is_empty(), "{a4:?}");
        } else {
            assert!((a4[0].re + 2.48).abs() < 0.05, "{pf:?}: A4 {:?}", a4[0]);
        }
        // Markers sit at their s in the panel; the far-left poles at the left edge.
        let panel = scene.layout().panel(PanelKind::Poles).unwrap().rect;
        let frame = PoleFrame::new(panel);
        for p in &poles {
            let (x, y) = (p.x.unwrap(), p.y.unwrap());
            assert!(x >= panel.x && x <= panel.right() && y >= panel.y && y <= panel.bottom(), "{p:?}");
            if p.in_view {
                assert!((x - frame.x(p.re)).abs() < 1e-9 && (y - frame.y(p.im)).abs() < 1e-9);
            }
        }
        // One keyboard stop per ± pair (a readout names both halves); a real λ is a stop of its own.
        for p in &poles {
            let twin = poles.iter().any(|q| {
                q.kind == p.kind
                    && (q.lambda[0] - p.lambda[0]).abs() < 1e-9
                    && (q.lambda[1] + p.lambda[1]).abs() < 1e-9
                    && q.lambda[1] != 0.0
            });
            if p.lambda[1] == 0.0 {
                assert!(p.keyboard_stop, "{p:?}");
            } else {
                assert!(twin, "every complex pole has its conjugate: {p:?}");
                assert_eq!(p.keyboard_stop, p.lambda[1] > 0.0, "{p:?}");
            }
        }
        let stops = poles.iter().filter(|p| p.keyboard_stop).count();
        let real = poles.iter().filter(|p| p.lambda[1] == 0.0).count();
        assert_eq!(2 * stops, poles.len() + real);
        let far: Vec<_> = loops.iter().filter(|p| p.re < -100.0).collect();
        assert_eq!(far.len(), 2, "the poles at −300 and −700 1/s");
        assert!(far.iter().all(|p| !p.in_view && p.x.unwrap() < panel.x + 10.0));
        let info = scene.panel_info();
        let plot = info.iter().find(|p| p.id == "poles").unwrap();
        assert_eq!((plot.x_label.as_str(), plot.y_label), ("Re s [1/s]", "Im s [rad/s]"));
        assert_eq!((plot.x_range, plot.y_range), ([-8.0, 6.0], [-40.0, 40.0]));
        assert!(plot.x_ticks.contains(&0.0) && plot.y_ticks.contains(&0.0) && plot.y_ticks.contains(&40.0));
    }
    assert!(flexible_re[0] > 2.0 && flexible_re[0] < 2.8, "without PF: Re ≈ +2.4, got {}", flexible_re[0]);
    assert!(flexible_re[1] < -1.5 && flexible_re[1] > -3.5, "with PF: Re ≈ −2.8, got {}", flexible_re[1]);
}

#[test]
fn the_analysis_is_cached_per_configuration() {
    let mut sim = analysed(PreliminaryFeedbackChoice::Off, 0.1);
    let mut scene = Scene::new(ViewOptions::default(), 1000.0, 700.0, 1.0);
    scene.draw_loops(sim.closed_loop(), sim.analysis().report(), None);
    let first = scene.analysis(0).cloned().unwrap();
    let mut cache = sim.analysis().clone();
    assert!(!cache.update(sim.closed_loop().config(), 0.0), "same configuration: no recomputation");
    let other = RunSettings { pf: PreliminaryFeedbackChoice::Paper, ..*sim.settings() };
    assert!(cache.update(&other.config(), 0.0));
    assert!(cache.update(&other.config(), 1.5 * std::f64::consts::PI), "another rest point: recomputed");
    sim.change(other, false).unwrap();
    sim.advance(0.05, 60.0).unwrap();
    scene.draw_loops(sim.closed_loop(), sim.analysis().report(), None);
    let second = scene.analysis(0).unwrap();
    assert!(second.spectral_radius < 1.0 && first.spectral_radius > 1.0);
    // Hiding the plot keeps the data for readouts, without positions.
    scene.set_options(&OptionsUpdate { show_poles: Some(false), ..Default::default() }).unwrap();
    scene.draw_loops(sim.closed_loop(), sim.analysis().report(), None);
    let poles = scene.pole_info();
    assert!(!poles.is_empty() && poles.iter().all(|p| p.x.is_none()));
    assert!(scene.panel_info().iter().all(|p| p.id != "poles"));
}

#[test]
fn pole_markers_stay_within_their_budget_and_panel() {
    let mut p = Painter::new();
    for pf in [PreliminaryFeedbackChoice::Off, PreliminaryFeedbackChoice::Paper] {
        for delta in [0.002, 0.01, 0.05, 0.2] {
            let mut c = map_config(pf);
            c.controller.sampling_period = delta;
            let report = flexarm::analysis::analyze(&c, None).unwrap();
            for dpr in [1.0, 3.0] {
                for size in [80.0, 600.0] {
                    p.clear();
                    let rect = Rect::new(10.0, 20.0, size * dpr, size * dpr);
                    let frame = PoleFrame::new(rect);
                    for style in [PoleStyle::RUN_A, PoleStyle::RUN_B] {
                        draw_flexible_halo(&mut p, &frame, &report, dpr);
                        draw_a4(&mut p, &frame, &report, &style, dpr);
                        draw_poles(&mut p, &frame, &report, &style, dpr);
                    }
                    assert!(p.len() <= 2 * RUN_VERTEX_BUDGET, "{} vertices", p.len());
                    let margin = 20.0 * dpr;
                    for v in p.vertices() {
                        let [x, y] = [v.position[0] as f64, v.position[1] as f64];
                        assert!(
                            x >= rect.x - margin
                                && x <= rect.right() + margin
                                && y >= rect.y - margin
                                && y <= rect.bottom() + margin,
                            "δ = {delta}: vertex {x},{y} far outside"
                        );
                    }
                }
            }
        }
    }
}

// ---------------------------------------------------------------- pair

#[test]
fn a_pair_shows_two_arms_both_errors_and_both_runs_poles() {
    let (ra, rb) = (analysed(PreliminaryFeedbackChoice::Off, 3.8), analysed(PreliminaryFeedbackChoice::Paper, 3.8));
    let (a, b) = (ra.closed_loop(), rb.closed_loop());
    let mut scene = Scene::new(ViewOptions::default(), 1400.0, 900.0, 2.0);
    scene.draw_loops(b, rb.analysis().report(), None);
    let single_e1 = info(&scene.panel_info(), "e1").y_range[1];
    scene.draw_loops(a, ra.analysis().report(), Some((b, rb.analysis().report())));
    assert!(scene.is_pair());
    let panels = scene.panel_info();
    let ids: Vec<&str> = panels.iter().map(|p| p.id).collect();
    assert_eq!(ids, ["arm", "arm-b", "e1", "e2", "poles", "rho-curve", "map-off", "map-on"]);
    // The scale covers both runs: A diverges, B stays small.
    let e1 = info(&panels, "e1").y_range[1];
    assert!(e1 >= max_abs(a.traces().e1()) && e1 >= max_abs(b.traces().e1()));
    assert!(e1 > 10.0 * single_e1, "pair scale {e1} vs B alone {single_e1}");
    let poles = scene.pole_info();
    assert_eq!(loop_poles(&poles).iter().filter(|p| p.run == "A").count(), 10);
    assert_eq!(loop_poles(&poles).iter().filter(|p| p.run == "B").count(), 10);
    let flex = |run: &str| loop_poles(&poles).into_iter().find(|p| p.run == run && p.flexible).unwrap().re;
    assert!(flex("A") > 0.0 && flex("B") < 0.0);
    let series = scene.series_info();
    assert_eq!(series.len(), 2);
    assert_eq!((series[0].run, series[1].run), ("A", "B"));
    assert_eq!(series[0].e1, palette::ERROR1.css());
    assert_ne!(series[1].e1, series[0].e1);
    assert!(series.iter().all(|s| s.color.starts_with('#') && s.color.len() == 7));
    assert_ne!(series[0].pole_marker, series[1].pole_marker);
    // Back to one run: the second arm goes away.
    scene.draw_loops(a, ra.analysis().report(), None);
    assert!(!scene.is_pair());
    assert!(scene.layout().panel(PanelKind::ArmB).is_none());
    assert_eq!(scene.series_info().len(), 1);
    assert!(scene.pole_info().iter().all(|p| p.run == "A"));
}

#[test]
fn a_pair_does_not_reallocate_after_warm_up() {
    let mut a = run(PreliminaryFeedbackChoice::Off, 0.0);
    let mut b = run(PreliminaryFeedbackChoice::Paper, 0.0);
    let mut scene = Scene::new(ViewOptions { show_torque: true, ..Default::default() }, 1400.0, 900.0, 3.0);
    let deltas = log_space(0.002, 0.25, 20);
    let alphas = log_space(0.1, 5.0, 8);
    let map = stability_map(a.config(), &deltas, &alphas).unwrap();
    scene.set_map(MapSide::Off, &deltas, &alphas, &map.spectral_radius).unwrap();
    scene.draw_loops(&a, None, Some((&b, None)));
    let capacity = scene.painter().capacity();
    let generation = scene.static_generation();
    // A diverges after ≈ 4 s and then stops advancing; keep drawing it.
    for _ in 0..180 {
        a.advance(1.0 / 30.0).unwrap();
        b.advance(1.0 / 30.0).unwrap();
        scene.draw_loops(&a, None, Some((&b, None)));
        assert_eq!(scene.painter().capacity(), capacity, "reallocated at t = {}", a.time());
    }
    assert_eq!(scene.static_generation(), generation);
}

#[test]
fn options_include_the_analysis_panels() {
    let mut o = ViewOptions::default();
    assert!(o.show_poles && o.show_map, "shown by default");
    o.apply(&OptionsUpdate { show_poles: Some(false), ..Default::default() }).unwrap();
    assert!(!o.show_poles && o.show_map);
    assert!(OptionsUpdate::check_field("show_map").is_ok() && OptionsUpdate::check_field("show_poles").is_ok());
    assert!(OptionsUpdate::check_field("showMap").is_err());
    assert_eq!(Color::hex(0x1f5fc4).css(), "#1f5fc4");
    assert_eq!(Color::hex(0xffffff).with_alpha(0.5).css(), "rgba(255, 255, 255, 0.5)");
}

/// The key follows the dark scheme as the canvas does (issue 20): every glyph's and every colour
/// bar stop's dark colour is the light one with its lightness inverted, as the shader inverts it.
#[test]
fn the_key_has_the_dark_schemes_colours_too() {
    use flexarm::plot::Color;
    let parse = |s: &str| {
        let v = u32::from_str_radix(s.trim_start_matches('#'), 16).unwrap();
        Color::hex(v)
    };
    // The same colour to a byte (the CSS text is rounded to bytes).
    let same = |a: Color, b: Color| a.0.iter().zip(b.0).all(|(x, y)| (x - y).abs() <= 1.5 / 255.0);
    // Every panel's key at once: the pole plot, the maps, log |e| and the zoom's (Fig. 2.1) among
    // them, two runs compared.
    let (mut session, _) = flexarm::session::Session::open("mode=full&torque=1&log=1&predict=1&compare=1");
    for _ in 0..30 {
        session.advance(1.0 / 30.0).unwrap();
    }
    let mut scene = Scene::new(ViewOptions::default(), 1600.0, 1000.0, 1.0);
    scene.draw_session(&session);
    let groups = scene.legend();
    for title in ["pole plot", "stability maps", "log |e|", "Fig. 2.1: one sampling instant tₙ"] {
        assert!(groups.iter().any(|g| g.title == title), "no key to {title}");
    }
    for group in groups {
        for it in &group.items {
            if it.color.starts_with('#') {
                assert!(same(parse(&it.dark), parse(&it.color).for_dark()), "{}: {} vs {}", it.text, it.dark, it.color);
            }
        }
        if let Some(scale) = &group.scale {
            for ((p, light), (q, dark)) in scale.stops.iter().zip(&scale.dark_stops) {
                assert_eq!(p, q);
                assert!(same(parse(dark), parse(light).for_dark()), "{dark} vs {light}");
            }
        }
    }
}
