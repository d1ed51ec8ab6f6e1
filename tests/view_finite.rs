//! A diverging run never sends a NaN or an infinity to the renderer (issue 12): over 30 δ spread
//! logarithmically across the δ slider's span, without preliminary feedback, at α from the
//! slider's smallest to its largest, each run is played until it diverges (or for a while if it
//! does not), and every number the view hands the renderer and the page is checked, as the page
//! takes them: at every frame the per-frame triangles and the time window, the static layer (the
//! maps, ρ(δ)) whenever it is rebuilt, the frame's description (panel rectangles, ranges, ticks,
//! tick labels, marks, every label, the pole markers, the series, the legend) whenever it changes,
//! and after the divergence what the pointer reads anywhere (probes, the time under it) — on a
//! wide canvas and on a phone, in the s- and z-plane, linear and log errors, with run B beside A,
//! and while looking back at the diverged run.

use flexarm::schema::{ALPHA_SPEC, DELTA_SPEC};
use flexarm::session::Session;
use flexarm::view::{Scene, ViewOptions};
use serde::ser::{self, Serialize};

/// Runs that have not diverged stop after this much simulated time, s.
const MAX_SECONDS: f64 = 10.0;
/// Runs the linear analysis calls unstable (ρ > 1) are played this long at most, s.
const MAX_SECONDS_UNSTABLE: f64 = 60.0;
/// Simulated time per frame, s (the page's frames at speed 3×, 20 fps).
const FRAME: f64 = 0.25;
/// Frames drawn after the divergence (the page keeps drawing the final state).
const FRAMES_AFTER: usize = 5;

#[test]
fn the_smallest_alpha_of_the_slider() {
    every_delta_at(ALPHA_SPEC.control[0]);
}

#[test]
fn a_small_alpha() {
    every_delta_at(0.5);
}

#[test]
fn the_papers_alpha() {
    every_delta_at(2.0);
}

#[test]
fn the_largest_alpha_of_the_slider() {
    every_delta_at(ALPHA_SPEC.control[1]);
}

/// Errors growing at least this fast (ln ρ / δ, 1/s) diverge well within [`MAX_SECONDS_UNSTABLE`].
const SURELY_DIVERGES: f64 = 0.5;

/// 30 δ across the slider's span at `alpha`, without preliminary feedback, run B beside run A at
/// another δ; every frame of every run checked, on a wide canvas and a phone.
fn every_delta_at(alpha: f64) {
    let [d_lo, d_hi] = DELTA_SPEC.control;
    let deltas: Vec<f64> = (0..30).map(|i| d_lo * (d_hi / d_lo).powf(f64::from(i) / 29.0)).collect();
    let (mut s, notices) =
        Session::open(&format!("mode=full&pf=off&repeat=1&torque=1&alpha={alpha}&compare=1&b_pf=off&b_alpha={alpha}"));
    assert!(notices.is_empty(), "{notices:?}");
    // Both maps, once (the same for every δ): their cells and contours are drawn too.
    let mut clock = 0.0;
    let mut tick = || {
        clock += 1.0;
        clock
    };
    while s.maps_mut().work(&mut tick, 1e6) {}
    let mut wide = Watched::new(Scene::new(ViewOptions::default(), 1280.0, 800.0, 1.0));
    let mut phone = Watched::new(Scene::new(ViewOptions::default(), 390.0, 600.0, 2.0));
    let mut stats = Stats::default();
    let mut missed = Vec::new();
    for (i, &delta) in deltas.iter().enumerate() {
        let label = format!("α = {alpha}, δ = {delta:.5}");
        s.set("delta", &delta.to_string()).unwrap();
        // Run B further along the δ list: one run diverges while the other goes on.
        s.set("b_delta", &deltas[(i + 7) % deltas.len()].to_string()).unwrap();
        s.set("plane", if i % 2 == 0 { "s" } else { "z" }).unwrap();
        s.set("log", if i % 3 == 0 { "0" } else { "1" }).unwrap();
        s.set("tab", ["run", "poles", "maps"][i % 3]).unwrap();
        s.reset().unwrap();
        let growth = s.run(0).unwrap().analysis().report().map_or(0.0, |r| r.spectral_radius.ln() / delta);
        let diverged = play_and_check(&mut s, &mut [&mut wide, &mut phone], growth > 0.0, &label, &mut stats);
        stats.runs += 1;
        stats.diverged += usize::from(diverged);
        if growth >= SURELY_DIVERGES && !diverged {
            missed.push(format!("{label} (ln ρ/δ = {growth:.2} 1/s)"));
        }
    }
    println!(
        "α = {alpha}: {} runs ({} diverged), {} frames ({} described anew), {} numbers checked, all finite",
        stats.runs, stats.diverged, stats.frames, stats.descriptions, stats.numbers
    );
    // Otherwise the test would not be testing what it says.
    assert!(missed.is_empty(), "fast-growing runs that did not diverge: {missed:?}");
}

/// A scene and the description the page last read from it (the page reads it again only when
/// `info_generation` changes, as `www/js/main.js` does).
struct Watched {
    scene: Scene,
    generation: Option<u64>,
    static_generation: Option<u64>,
}

impl Watched {
    fn new(scene: Scene) -> Self {
        Self { scene, generation: None, static_generation: None }
    }

    /// Draws the session and checks what the page would take from this frame: the triangles
    /// always, the description when it changed, and with `probes` what the pointer reads.
    fn frame(&mut self, s: &Session, at: &str, probes: bool, stats: &mut Stats) {
        self.scene.draw_session(s);
        // The renderer uploads the static layer again only when it was rebuilt.
        let rebuilt = self.static_generation != Some(self.scene.static_generation());
        self.static_generation = Some(self.scene.static_generation());
        let described = self.generation != Some(self.scene.info_generation());
        self.generation = Some(self.scene.info_generation());
        check_frame(&self.scene, at, Layers { rebuilt, described, probes }, stats);
    }
}

#[derive(Default)]
struct Stats {
    runs: usize,
    diverged: usize,
    frames: usize,
    descriptions: usize,
    numbers: usize,
}

/// Plays run A until it diverges (then a few frames more, and a look back at it) or for
/// [`MAX_SECONDS`] ([`MAX_SECONDS_UNSTABLE`] if the analysis says `unstable`), checking every
/// frame of each scene (and what the pointer reads once A has diverged). True if A diverged.
fn play_and_check(
    s: &mut Session,
    scenes: &mut [&mut Watched],
    unstable: bool,
    label: &str,
    stats: &mut Stats,
) -> bool {
    let mut after = 0;
    let cap = if unstable { MAX_SECONDS_UNSTABLE } else { MAX_SECONDS };
    loop {
        let finished = s.run(0).unwrap().closed_loop().is_finished();
        let t = s.run(0).unwrap().closed_loop().time();
        for scene in scenes.iter_mut() {
            scene.frame(s, &format!("{label}, t = {t:.3} s"), finished, stats);
        }
        if finished {
            after += 1;
            if after > FRAMES_AFTER {
                break;
            }
        } else if t >= cap {
            return false;
        }
        // The page's frame: wall time × speed (advance caps what one call may cover).
        s.advance(FRAME / s.settings().speed).unwrap();
    }
    // Looking back at the diverged run, halfway and just before the end.
    let end = s.run(0).unwrap().closed_loop().time();
    for t in [0.5 * end, end - 0.01] {
        s.view_at(t);
        for scene in scenes.iter_mut() {
            scene.frame(s, &format!("{label}, looking back at t = {t:.3} s"), true, stats);
        }
    }
    s.view_at(f64::INFINITY);
    true
}

/// What of a frame goes to the page besides its per-frame triangles.
struct Layers {
    /// The static layer (the maps' cells and contours, ρ(δ)) was rebuilt.
    rebuilt: bool,
    /// The description for the labels changed.
    described: bool,
    /// What the pointer would read anywhere on the canvas (a coarse grid).
    probes: bool,
}

/// Every number of one frame that goes to the page.
fn check_frame(scene: &Scene, at: &str, what: Layers, stats: &mut Stats) {
    stats.frames += 1;
    let static_layer: &[_] = if what.rebuilt { scene.static_vertices() } else { &[] };
    for (layer, vertices) in [("per-frame", scene.vertices()), ("static", static_layer)] {
        for (i, v) in vertices.iter().enumerate() {
            if !(v.position.iter().chain(&v.color).all(|x| x.is_finite())) {
                panic!("{at}: {layer} vertex {i} is not finite: {v:?}");
            }
        }
        stats.numbers += 6 * vertices.len();
    }
    let window = scene.time_window();
    finite(&[window.start, window.end], "time window", at, stats);
    if what.described {
        stats.descriptions += 1;
        finite(&scene.panel_info(), "panel_info", at, stats);
        finite(&scene.labels(), "labels", at, stats);
        finite(&scene.pole_info(), "pole_info", at, stats);
        finite(&scene.series_info(), "series_info", at, stats);
        finite(&scene.legend(), "legend", at, stats);
    }
    if !what.probes {
        return;
    }
    let layout = scene.layout();
    for panel in &layout.panels {
        let r = panel.rect;
        for fx in [0.02, 0.25, 0.5, 0.75, 0.98] {
            for fy in [0.02, 0.5, 0.98] {
                let (x, y) = (r.x + fx * r.w, r.y + fy * r.h);
                finite(&scene.probe(x, y, 12.0), "probe", at, stats);
                finite(&scene.time_at(x, y), "time_at", at, stats);
            }
        }
    }
}

/// Panics naming the path of every number in `value` that is not finite.
fn finite<T: Serialize + ?Sized>(value: &T, what: &str, at: &str, stats: &mut Stats) {
    let mut check = FiniteCheck { path: vec![what.to_string()], bad: Vec::new(), numbers: 0 };
    value.serialize(&mut check).expect("the check never fails");
    stats.numbers += check.numbers;
    if !check.bad.is_empty() {
        panic!("{at}: {} non-finite number(s) sent to the page: {}", check.bad.len(), check.bad.join("; "));
    }
}

// ------------------------------------------------------- a serializer that only looks at numbers

/// Walks any `Serialize` value and notes every floating-point number that is NaN or infinite,
/// with its path (`panel_info[3].y_range[1]`). Serialising through JSON would not do: it writes
/// NaN as `null`, the same as a missing optional value.
struct FiniteCheck {
    path: Vec<String>,
    bad: Vec<String>,
    numbers: usize,
}

impl FiniteCheck {
    fn float(&mut self, v: f64) {
        self.numbers += 1;
        if !v.is_finite() {
            self.bad.push(format!("{} = {v}", self.path.join("")));
        }
    }

    fn nested<T: Serialize + ?Sized>(&mut self, segment: String, value: &T) -> Result<(), Never> {
        self.path.push(segment);
        let r = value.serialize(&mut *self);
        self.path.pop();
        r
    }
}

#[derive(Debug)]
struct Never;

impl std::fmt::Display for Never {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("never")
    }
}

impl std::error::Error for Never {}

impl ser::Error for Never {
    fn custom<T: std::fmt::Display>(_: T) -> Self {
        Never
    }
}

/// A sequence, tuple, map or struct being walked: counts its elements for the path.
struct Compound<'a> {
    check: &'a mut FiniteCheck,
    index: usize,
}

impl Compound<'_> {
    fn element<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Never> {
        let segment = format!("[{}]", self.index);
        self.index += 1;
        self.check.nested(segment, value)
    }

    fn field<T: Serialize + ?Sized>(&mut self, key: &str, value: &T) -> Result<(), Never> {
        self.check.nested(format!(".{key}"), value)
    }
}

impl<'a> ser::Serializer for &'a mut FiniteCheck {
    type Ok = ();
    type Error = Never;
    type SerializeSeq = Compound<'a>;
    type SerializeTuple = Compound<'a>;
    type SerializeTupleStruct = Compound<'a>;
    type SerializeTupleVariant = Compound<'a>;
    type SerializeMap = Compound<'a>;
    type SerializeStruct = Compound<'a>;
    type SerializeStructVariant = Compound<'a>;

    fn serialize_f32(self, v: f32) -> Result<(), Never> {
        self.float(f64::from(v));
        Ok(())
    }
    fn serialize_f64(self, v: f64) -> Result<(), Never> {
        self.float(v);
        Ok(())
    }
    fn serialize_bool(self, _: bool) -> Result<(), Never> {
        Ok(())
    }
    fn serialize_i8(self, _: i8) -> Result<(), Never> {
        Ok(())
    }
    fn serialize_i16(self, _: i16) -> Result<(), Never> {
        Ok(())
    }
    fn serialize_i32(self, _: i32) -> Result<(), Never> {
        Ok(())
    }
    fn serialize_i64(self, _: i64) -> Result<(), Never> {
        Ok(())
    }
    fn serialize_u8(self, _: u8) -> Result<(), Never> {
        Ok(())
    }
    fn serialize_u16(self, _: u16) -> Result<(), Never> {
        Ok(())
    }
    fn serialize_u32(self, _: u32) -> Result<(), Never> {
        Ok(())
    }
    fn serialize_u64(self, _: u64) -> Result<(), Never> {
        Ok(())
    }
    fn serialize_char(self, _: char) -> Result<(), Never> {
        Ok(())
    }
    fn serialize_str(self, _: &str) -> Result<(), Never> {
        Ok(())
    }
    fn serialize_bytes(self, _: &[u8]) -> Result<(), Never> {
        Ok(())
    }
    fn serialize_none(self) -> Result<(), Never> {
        Ok(())
    }
    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<(), Never> {
        value.serialize(self)
    }
    fn serialize_unit(self) -> Result<(), Never> {
        Ok(())
    }
    fn serialize_unit_struct(self, _: &'static str) -> Result<(), Never> {
        Ok(())
    }
    fn serialize_unit_variant(self, _: &'static str, _: u32, _: &'static str) -> Result<(), Never> {
        Ok(())
    }
    fn serialize_newtype_struct<T: Serialize + ?Sized>(self, _: &'static str, value: &T) -> Result<(), Never> {
        value.serialize(self)
    }
    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        value: &T,
    ) -> Result<(), Never> {
        self.nested(format!(".{variant}"), value)
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<Compound<'a>, Never> {
        Ok(Compound { check: self, index: 0 })
    }
    fn serialize_tuple(self, _: usize) -> Result<Compound<'a>, Never> {
        Ok(Compound { check: self, index: 0 })
    }
    fn serialize_tuple_struct(self, _: &'static str, _: usize) -> Result<Compound<'a>, Never> {
        Ok(Compound { check: self, index: 0 })
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Compound<'a>, Never> {
        Ok(Compound { check: self, index: 0 })
    }
    fn serialize_map(self, _: Option<usize>) -> Result<Compound<'a>, Never> {
        Ok(Compound { check: self, index: 0 })
    }
    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Compound<'a>, Never> {
        Ok(Compound { check: self, index: 0 })
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Compound<'a>, Never> {
        Ok(Compound { check: self, index: 0 })
    }
}

/// The sequence-like compounds: every element is checked the same way.
macro_rules! check_elements {
    ($($kind:ident::$method:ident),*) => {$(
        impl ser::$kind for Compound<'_> {
            type Ok = ();
            type Error = Never;
            fn $method<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Never> {
                self.element(value)
            }
            fn end(self) -> Result<(), Never> {
                Ok(())
            }
        }
    )*};
}

check_elements!(
    SerializeSeq::serialize_element,
    SerializeTuple::serialize_element,
    SerializeTupleStruct::serialize_field,
    SerializeTupleVariant::serialize_field
);

impl ser::SerializeMap for Compound<'_> {
    type Ok = ();
    type Error = Never;
    fn serialize_key<T: Serialize + ?Sized>(&mut self, key: &T) -> Result<(), Never> {
        // A key that is a number is checked like any other.
        self.check.nested(".<key>".to_string(), key)
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Never> {
        self.element(value)
    }
    fn end(self) -> Result<(), Never> {
        Ok(())
    }
}

impl ser::SerializeStruct for Compound<'_> {
    type Ok = ();
    type Error = Never;
    fn serialize_field<T: Serialize + ?Sized>(&mut self, key: &'static str, value: &T) -> Result<(), Never> {
        self.field(key, value)
    }
    fn end(self) -> Result<(), Never> {
        Ok(())
    }
}

impl ser::SerializeStructVariant for Compound<'_> {
    type Ok = ();
    type Error = Never;
    fn serialize_field<T: Serialize + ?Sized>(&mut self, key: &'static str, value: &T) -> Result<(), Never> {
        self.field(key, value)
    }
    fn end(self) -> Result<(), Never> {
        Ok(())
    }
}

/// The checker itself finds what it must, and lets absent optional values pass.
#[test]
fn the_finite_check_finds_nan_and_infinity_at_their_path() {
    #[derive(serde::Serialize)]
    struct Inner {
        x: f64,
        y: Option<f32>,
        none: Option<f64>,
    }
    #[derive(serde::Serialize)]
    struct Outer {
        ok: [f64; 2],
        items: Vec<Inner>,
        pair: (f64, String),
    }
    let value = Outer {
        ok: [1.0, -2.0],
        items: vec![
            Inner { x: 0.0, y: Some(1.0), none: None },
            Inner { x: f64::NAN, y: Some(f32::INFINITY), none: None },
        ],
        pair: (f64::NEG_INFINITY, "text".into()),
    };
    let mut check = FiniteCheck { path: vec!["v".into()], bad: Vec::new(), numbers: 0 };
    value.serialize(&mut check).unwrap();
    assert_eq!(check.bad, ["v.items[1].x = NaN", "v.items[1].y = inf", "v.pair[0] = -inf"]);
    assert_eq!(check.numbers, 7);
}
