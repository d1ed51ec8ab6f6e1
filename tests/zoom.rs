//! The page's zoom on one sampling instant (the paper's Fig. 2.1, live; `view/scene/cycle.rs`)
//! and the swing's shape on the arm (`view/scene/swing.rs`): what they draw and say, that they
//! follow the instant shown, and that a frame of them allocates nothing once warm.

mod common;
use common::{play, session};

use std::alloc::{GlobalAlloc, Layout, System};

use flexarm::plot::{palette, Color};
use flexarm::view::{PanelKind, Scene, ViewOptions};

/// Counts the allocations of each thread of this test binary: the test harness and the other
/// tests allocate on their own threads at any time (a shared counter saw them under load).
struct Counting;

thread_local! {
    static ALLOCATIONS: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

fn note_allocation() {
    // A const-initialized Cell has no destructor: `try_with` only fails during thread teardown.
    let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
}

/// This thread's allocations so far.
fn allocations() -> usize {
    ALLOCATIONS.with(|c| c.get())
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        note_allocation();
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        note_allocation();
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// The other tests of this binary allocate at the same time; the counting test takes this lock.
static ONE_AT_A_TIME: std::sync::Mutex<()> = std::sync::Mutex::new(());

fn count(scene: &Scene, color: Color) -> usize {
    scene.vertices().iter().filter(|v| v.color == color.0).count()
}

fn zoomed(scene: &Scene) -> flexarm::view::time_window::TimeWindow {
    scene.time_window()
}

#[test]
fn the_zoom_follows_the_instant_shown_three_periods_around_it() {
    let _one = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let mut s = session("preset=fig5.3&mode=full&predict=1");
    play(&mut s, 2.0);
    let mut scene = Scene::new(ViewOptions::default(), 1280.0, 800.0, 1.0);
    scene.draw_session(&s);
    let delta = 0.01;
    let newest = s.run(0).unwrap().closed_loop().history().span().unwrap()[1];
    let w = zoomed(&scene);
    assert!(
        (w.start - (newest - 1.25 * delta)).abs() < 1e-9 && (w.end - (newest + 2.25 * delta)).abs() < 1e-9,
        "{w:?}"
    );
    // Looking back: the newest instant kept (or the one before, if the run is right at it), then
    // two periods further.
    s.step_back();
    let first = s.viewing().unwrap();
    assert!((first - newest).abs() < 1e-9 || (first - (newest - delta)).abs() < 1e-9);
    s.step_back();
    s.step_back();
    scene.draw_session(&s);
    let tn = s.viewing().unwrap();
    assert!((tn - (first - 2.0 * delta)).abs() < 1e-9);
    assert!((zoomed(&scene).start - (tn - 1.25 * delta)).abs() < 1e-9);
    // One period forward.
    s.step_period();
    scene.draw_session(&s);
    assert!((zoomed(&scene).start - (tn + delta - 1.25 * delta)).abs() < 1e-9);
    // The ticks are the sampling instants, named after t_n, and stay put.
    let info = scene.panel_info();
    let torque = info.iter().find(|p| p.id == "torque").expect("the zoom shows the torque");
    let texts: Vec<&str> = torque.x_labels.iter().map(|l| l.text.as_str()).collect();
    assert_eq!(texts, ["tₙ−δ", "tₙ", "tₙ+δ", "tₙ+2δ"]);
    assert!(!torque.scrolls && torque.y_label.starts_with("u1, u2") && torque.x_label.contains("δ = 0.01 s"));
    // Dragging on a zoomed plot does not scrub (the window would chase the pointer).
    let e1 = info.iter().find(|p| p.id == "e1").unwrap();
    assert_eq!(scene.time_at(e1.x + 10.0, e1.y + 10.0), None);
    // Off again: the plots scroll over their 10 s.
    let mut s2 = session("preset=fig5.3&mode=full");
    play(&mut s2, 2.0);
    scene.draw_session(&s2);
    assert!((zoomed(&scene).width() - 10.0).abs() < 1e-9);
}

#[test]
fn the_zoom_draws_the_prediction_u_k_and_its_hold_and_the_caption_says_when() {
    let _one = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let mut s = session("preset=fig5.3&mode=full&predict=1");
    play(&mut s, 2.0);
    let mut scene = Scene::new(ViewOptions::default(), 1280.0, 800.0, 1.0);
    // Live: the horizon, U_k, the planned hold (dashed), the predicted arm.
    scene.draw_session(&s);
    assert!(count(&scene, palette::HORIZON_BAND) > 0, "the horizon");
    assert!(count(&scene, palette::PREDICTED) > 0, "U_k and the plan");
    assert!(count(&scene, palette::PREDICTED_ARM) > 0, "X_k on the arm");
    let live = s.status().cycle;
    assert!(live.contains("still to come"), "{live}");
    // Two periods back the hold has happened: its band, no plan.
    s.step_back();
    s.step_back();
    scene.draw_session(&s);
    assert!(count(&scene, palette::HOLD_BAND) > 0, "the hold");
    let back = s.status().cycle;
    let tn = s.viewing().unwrap();
    assert!(back.contains(&format!("tₙ = {tn:.3} s")) && !back.contains("still to come"), "{back}");
    assert!(back.contains(&format!("held from tₙ + δ = {:.3} s to tₙ + 2δ = {:.3} s", tn + 0.01, tn + 0.02)), "{back}");
    // The chosen torque quoted is the controller's U_k, which (without K_pr) the loop held.
    let sim = s.run(0).unwrap().closed_loop();
    let next = sim.history().at(tn + 0.01 + 1e-9).unwrap().0;
    let v = next.v_next.unwrap();
    assert!(back.contains(&flexarm::plot::format::significant(v[0], 4)), "{back} vs {v}");
    // The jump off the scale: the torque plot's note says so, the caption gives its size.
    let info = scene.panel_info();
    let torque = info.iter().find(|p| p.id == "torque").unwrap();
    assert!(torque.note.starts_with("U₁, U₂ off the scale (sizes in the caption)"), "{}", torque.note);
    assert!(back.contains("The first two, U₁ = ("), "{back}");
    // Off: no caption, no zoom colours.
    let mut off = session("preset=fig5.3&mode=full");
    play(&mut off, 1.0);
    scene.draw_session(&off);
    assert_eq!(off.status().cycle, "");
    assert_eq!(count(&scene, palette::HORIZON_BAND) + count(&scene, palette::PREDICTED_ARM), 0);
}

/// The zoom with K_pr: the caption separates the predictive part v from U_k.
#[test]
fn with_k_pr_the_caption_names_the_held_part_v() {
    let _one = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let mut s = session("preset=fig5.2&mode=full&predict=1");
    play(&mut s, 1.5);
    s.step_back();
    s.step_back();
    let text = s.status().cycle;
    assert!(text.contains("v = Uₖ − K_pr Xₖ"), "{text}");
}

#[test]
fn a_frame_of_the_zoom_allocates_nothing_once_warm_live_or_looking_back() {
    let _one = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let mut s = session("preset=fig5.3&mode=full&predict=1&swing=1");
    play(&mut s, 1.5);
    let mut scene = Scene::new(ViewOptions::default(), 1280.0, 800.0, 2.0);
    for _ in 0..20 {
        s.advance(1.0 / 60.0).unwrap();
        scene.draw_session(&s);
    }
    let mut most = 0;
    for frame in 0..120 {
        s.advance(1.0 / 60.0).unwrap();
        if frame == 60 {
            // Looking back: the sweep is computed again from the kept state, into the same buffers.
            for _ in 0..5 {
                s.step_back();
            }
            scene.draw_session(&s);
        }
        if frame > 60 && frame % 2 == 0 {
            s.step_back();
        }
        scene.set_clock(frame as f64 / 60.0);
        let before = allocations();
        scene.draw_session(&s);
        let after = allocations();
        assert_eq!(after - before, 0, "frame {frame} allocated");
        most = most.max(scene.vertices().len());
    }
    assert!(most > 1000);
}

#[test]
fn a_frame_of_the_velocity_panel_allocates_nothing_once_warm() {
    // What the controller reads, with a coarse encoder whose differenced velocity is clamped to
    // the true velocity's scale (tests/measured_traces.rs): the clamping allocates nothing either.
    let _one = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let mut s = session("preset=real-encoder&delta=0.002&encoder=256&measured=1&mode=full&torque=1");
    play(&mut s, 1.0);
    let mut scene = Scene::new(ViewOptions::default(), 1920.0, 1080.0, 2.0);
    for _ in 0..20 {
        s.advance(1.0 / 60.0).unwrap();
        scene.draw_session(&s);
    }
    assert!(scene.layout().panel(PanelKind::Velocity).is_some());
    for frame in 0..120 {
        s.advance(1.0 / 60.0).unwrap();
        let before = allocations();
        scene.draw_session(&s);
        assert_eq!(allocations() - before, 0, "frame {frame} allocated");
    }
    assert!(count(&scene, palette::VELOCITY1_EST) > 0);
}

#[test]
fn nothing_non_finite_reaches_the_renderer_when_the_zoomed_run_diverges() {
    let _one = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    for query in ["preset=fig5.3&mode=full&predict=1&swing=1", "delta=0.002&pf=off&alpha=5&mode=full&predict=1"] {
        let mut s = session(query);
        let mut scene = Scene::new(ViewOptions::default(), 900.0, 700.0, 1.0);
        let mut frames = 0;
        while !s.run(0).unwrap().closed_loop().is_finished() && frames < 2000 {
            s.advance(0.05).unwrap();
            scene.draw_session(&s);
            assert!(scene.vertices().iter().all(|v| v.position.iter().all(|p| p.is_finite())), "{query}");
            frames += 1;
        }
        assert!(s.run(0).unwrap().closed_loop().is_finished(), "{query}: diverges");
        s.step_back();
        scene.draw_session(&s);
        assert!(scene.vertices().iter().all(|v| v.position.iter().all(|p| p.is_finite())));
    }
}

#[test]
fn the_swing_turns_with_the_clock_and_asks_for_frames_only_while_shown() {
    let _one = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let mut s = session("preset=fig5.3&mode=full&swing=1");
    play(&mut s, 0.5);
    let mut scene = Scene::new(ViewOptions::default(), 1280.0, 800.0, 1.0);
    let amber = |scene: &Scene| -> Vec<[f32; 2]> {
        scene.vertices().iter().filter(|v| v.color == palette::SWING.0).map(|v| v.position).collect()
    };
    scene.set_clock(0.0);
    scene.draw_session(&s);
    let first = amber(&scene);
    assert!(!first.is_empty() && scene.animating());
    // A quarter of the drawn swing later (ω/10 slower) the pose differs; a whole one later it is back.
    let omega = scene.swing_shape().unwrap().omega / flexarm::view::scene::SWING_SLOWDOWN;
    scene.set_clock(0.25 * core::f64::consts::TAU / omega);
    scene.draw_session(&s);
    assert_ne!(amber(&scene), first);
    scene.set_clock(core::f64::consts::TAU / omega);
    scene.draw_session(&s);
    let back = amber(&scene);
    assert_eq!(back.len(), first.len());
    assert!(back.iter().zip(&first).all(|(a, b)| (a[0] - b[0]).abs() < 0.05 && (a[1] - b[1]).abs() < 0.05));
    // The key gives the shape in numbers; the arm's title says what amber is.
    let legend = scene.legend();
    let group = legend.iter().find(|g| g.title == "the swing's shape").expect("its key");
    let key = &group.items[0].text;
    assert!(key.contains("against it"), "{key}");
    // The README quotes Fig. 5.3's shape from this key.
    let readme = include_str!("../README.md").split_whitespace().collect::<Vec<_>>().join(" ");
    let [l1, l2] = [
        key.find("link 1 (q1): ").unwrap() + "link 1 (q1): ".len(),
        key.find("link 2 (q2, at its joint): ").unwrap() + "link 2 (q2, at its joint): ".len(),
    ];
    let first = |from: usize| key[from..].split(", ").next().unwrap().to_string();
    let (ratio1, ratio2) = (first(l1), first(l2));
    let lag1 = key[l1..].split(", ").nth(1).unwrap().split(':').next().unwrap().to_string();
    let quoted = format!(
        "link 1 {}, {lag1} it; link 2 {},",
        ratio1.replace(" × the motor's angle", " × the motor's angle"),
        ratio2.replace(" the motor's angle", "")
    );
    assert!(readme.contains(&quoted), "README should quote «{quoted}» from the key «{key}»");
    let arm = scene.panel_info().into_iter().find(|p| p.id == "arm").unwrap();
    assert!(arm.title.contains("amber: the swing's shape"));
    // Off: nothing animates.
    let mut off = session("preset=fig5.3&mode=full");
    play(&mut off, 0.5);
    scene.draw_session(&off);
    assert!(!scene.animating() && amber(&scene).is_empty());
    assert!(scene.layout().panel(PanelKind::Arm).is_some());
}

/// The log view's dashed slope ln ρ/δ describes the free motion about rest (trial 8: it was drawn
/// through the slews): none while the reference moves, and from the start of the rest at most.
#[test]
fn the_predicted_slope_is_drawn_over_the_rest_only() {
    let _one = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    // The slew repeats: 1 s there, 1.5 s hold, 1 s back, … Fig. 5.3 grows.
    let mut s = session("preset=fig5.3&mode=full&log=1");
    let mut scene = Scene::new(ViewOptions::default(), 1280.0, 800.0, 1.0);
    let dashes = |scene: &Scene| count(scene, palette::PREDICTED);
    let e1 = |scene: &Scene| scene.layout().panel(PanelKind::Error1).unwrap().rect;
    // During the second slew (t from 2.5 to 3.5 s): no slope.
    play(&mut s, 2.9);
    scene.draw_session(&s);
    assert_eq!(dashes(&scene), 0, "while the reference moves");
    // In the rest after it (from 3.5 s): a slope, starting no earlier than 3.5 s.
    play(&mut s, 0.9);
    scene.draw_session(&s);
    assert!(dashes(&scene) > 0, "at rest");
    let w = scene.time_window();
    let r = e1(&scene);
    let x_rest = r.x + r.w * (3.5 - w.start) / w.width();
    let leftmost = scene
        .vertices()
        .iter()
        .filter(|v| v.color == palette::PREDICTED.0)
        .map(|v| v.position[0] as f64)
        .fold(f64::INFINITY, f64::min);
    assert!(leftmost >= x_rest - 3.0, "the slope starts at {leftmost} px, the rest at {x_rest} px");
    // And it stays inside the plots (e1's and e2's).
    let r2 = scene.layout().panel(PanelKind::Error2).unwrap().rect;
    for v in scene.vertices().iter().filter(|v| v.color == palette::PREDICTED.0) {
        let (x, y) = (v.position[0] as f64, v.position[1] as f64);
        let within = |r: &flexarm::view::Rect| {
            x >= r.x - 0.01 && x <= r.right() + 0.01 && y >= r.y - 0.01 && y <= r.bottom() + 0.01
        };
        assert!(within(&r) || within(&r2), "a dash at ({x}, {y}) outside {r:?} and {r2:?}");
    }
}

/// The pole plot's Im s range follows the arm (trial 8: on the stiffer spring the flexible pair was
/// off the scale, edge arrows only): the paper's arm keeps ±40 rad/s, a stiffer spring's pair is in
/// view, with its A4 markers, and the ticks follow.
#[test]
fn the_pole_plot_shows_a_stiffer_arms_flexible_pair() {
    let _one = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    for (query, half) in [
        ("preset=fig5.3&mode=full", 40.0),
        ("preset=fig5.3&mode=full&k1=4610.4", 80.0),
        ("preset=fig5.3&mode=full&k1=18441.6", 160.0),
    ] {
        let mut s = session(query);
        play(&mut s, 0.2);
        let mut scene = Scene::new(ViewOptions::default(), 1280.0, 800.0, 1.0);
        scene.draw_session(&s);
        let poles = scene.panel_info().into_iter().find(|p| p.id == "poles").unwrap();
        assert_eq!(poles.y_range, [-half, half], "{query}");
        assert!(poles.y_ticks.iter().any(|t| *t >= 0.5 * half), "{query}: ticks {:?}", poles.y_ticks);
        for p in scene.pole_info().iter().filter(|p| p.flexible || p.kind != flexarm::view::PoleKind::Loop) {
            assert!(p.in_view, "{query}: {:?} at {} ± {}j", p.kind, p.re, p.im);
        }
    }
}

/// Step ▸ moves the zoom to the instant it reaches (trial 9: the first press left tₙ where it
/// was), and the caption says where the run is.
#[test]
fn step_shows_the_instant_it_reaches() {
    let _one = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let mut s = session("preset=fig5.3&mode=full&predict=1");
    play(&mut s, 1.03);
    let mut scene = Scene::new(ViewOptions::default(), 1280.0, 800.0, 1.0);
    for _ in 0..3 {
        s.step_period();
        let now = s.run(0).unwrap().closed_loop().time();
        scene.draw_session(&s);
        let w = zoomed(&scene);
        assert!((w.start - (now - 1.25 * 0.01)).abs() < 1e-9, "tₙ is the instant reached, {now} s");
        let caption = s.status().cycle;
        assert!(caption.contains(&format!("tₙ = {now:.3} s")) && caption.contains("the run is at tₙ"), "{caption}");
    }
    // Mid-period the caption gives the run's own time.
    s.advance(0.004).unwrap();
    let caption = s.status().cycle;
    let now = s.run(0).unwrap().closed_loop().time();
    assert!(caption.contains(&format!("the run is at t = {now:.3} s")), "{caption}");
}
