//! The session's changes: a setting typed, slid, stepped or picked on a figure, a preset or a
//! state string read — each validated whole, then carried to the runs (live, or from rest where
//! the old state does not fit the new settings: another arm, another reference).

use super::*;
use crate::analysis::MapRows;

impl Session {
    /// Sets one parameter from its text (a selector's value, a number typed): within the
    /// parameter's limits, which may reach beyond its slider's span.
    pub fn set(&mut self, key: &str, text: &str) -> Result<(), Error> {
        let p = schema::param(key).ok_or_else(|| not_a_setting(key))?;
        let v = p.parse(text, false)?;
        self.set_value(key, v)?;
        // A value typed beyond the slider's span is taken (it is within the limits), and said.
        if let (Some(spec), Value::Number(x)) = (p.number(), v) {
            if !spec.in_control(x) && self.note.is_empty() {
                let [lo, hi] = spec.control;
                self.note = format!(
                    "{} = {} {} is outside the slider's {}–{} {}: taken as typed; the slider shows its end.",
                    p.symbol,
                    schema::format_number(x),
                    p.unit,
                    schema::format_number(lo),
                    schema::format_number(hi),
                    p.unit
                );
            }
        }
        Ok(())
    }

    /// Sets a numeric parameter from its control's position in [0, 1] (a slider).
    pub fn set_position(&mut self, key: &str, position: f64) -> Result<(), Error> {
        let p = schema::param(key).ok_or_else(|| not_a_setting(key))?;
        let Kind::Number(n) = p.kind else { return Err(not_a_setting(key)) };
        self.set_value(key, Value::Number(n.value_at(position)))
    }

    /// Moves a numeric parameter `steps` arrow-key steps from its value (round values on a
    /// logarithmic control: 0.01 → 0.012 → 0.015 → 0.02 s).
    pub fn step_value(&mut self, key: &str, steps: i32) -> Result<(), Error> {
        let p = schema::param(key).ok_or_else(|| not_a_setting(key))?;
        let (Kind::Number(n), Some(Value::Number(v))) = (p.kind, self.settings.get(key)) else {
            return Err(not_a_setting(key));
        };
        self.set_value(key, Value::Number(n.step_from(v, steps)))
    }

    /// Sets one parameter to a checked value and carries the change to the runs.
    pub fn set_value(&mut self, key: &str, value: Value) -> Result<(), Error> {
        if schema::param(key).is_some_and(|p| matches!(p.scope, Scope::Run | Scope::Compare)) {
            // A change while looking back changes the run from that moment on.
            self.continue_from_here()?;
        }
        let mut next = self.settings;
        next.set(key, value)?;
        // A panel turned on (or shown otherwise) comes into view: on a narrow canvas, its tab.
        // (Two compared runs a decade apart get log axes from the view itself.)
        if let Some(tab) = super::named::tab_of(key, &next.view).filter(|_| next.view != self.settings.view) {
            next.view.tab = tab;
        }
        // The reference jumping under a moving arm would be a kick, not the setting: start over.
        let new_reference = key == "repeat" && next.a.repeat != self.settings.a.repeat;
        // Another arm is another run: it starts from rest (the old state is not this arm's).
        let b_plant = |s: &Settings| s.b.map(|b| b.run(&s.a).plant);
        // (A run B appearing or going is the comparison starting or stopping, not another arm.)
        let b_changed = self.settings.b.is_some() && next.b.is_some() && b_plant(&next) != b_plant(&self.settings);
        let new_arm = next.a.plant != self.settings.a.plant || b_changed;
        let restart = new_reference || new_arm;
        let why = if new_arm {
            "The arm changed, so the run restarted from rest."
        } else if new_reference {
            "The reference changed, so the run restarted from rest."
        } else {
            ""
        };
        self.apply(next, restart, why)
    }

    /// Applies a preset (its settings over the current ones) and restarts from rest.
    pub fn apply_preset(&mut self, id: &str) -> Result<(), Error> {
        let p = preset(id).ok_or_else(|| {
            Error::Parse(ParseError {
                key: "preset".into(),
                text: id.into(),
                expected: format!("one of {}", PRESETS.iter().map(|p| p.id).collect::<Vec<_>>().join(" | ")),
            })
        })?;
        let mut next = self.settings;
        next.apply_preset(p)?;
        // A figure is the paper's: say so when it brings the paper's arm back.
        let arm =
            if next.a.plant != self.settings.a.plant { " It runs on the paper's arm, as the paper did." } else { "" };
        self.apply(next, true, &format!("Preset applied; the run restarted: {}.{arm}", p.title))
    }

    /// Reads a state string (a URL query) over the current settings and restarts from rest.
    pub fn read_state(&mut self, state: &str) -> Result<Vec<Notice>, Error> {
        let mut next = self.settings;
        let notices = next.read(state, Source::Page)?;
        if let Some(tab) = super::named::tab_named_in(state, &next.view) {
            next.view.tab = tab;
        }
        self.apply(next, true, "")?;
        Ok(notices)
    }

    /// Runs A at a point picked on a map: (δ, α1 = α2 = α) — or on the design map (δ, k_d) —
    /// rounded to the controls' precision and kept within their spans, with the map's preliminary
    /// feedback (none on the left; on the right A's own if it has one, else the paper's).
    pub fn set_from_map(&mut self, side: MapSide, delta: f64, value: f64) -> Result<(), Error> {
        self.continue_from_here()?;
        let spec = |p: &schema::Param| *p.number().expect("δ, α and k_d are numbers");
        let pf = match (side, self.settings.a.pf) {
            (MapSide::Off, _) => PreliminaryFeedbackChoice::Off,
            (MapSide::On, PreliminaryFeedbackChoice::Off) => PreliminaryFeedbackChoice::Paper,
            (MapSide::On, current) => current,
        };
        let mut next = self.settings;
        next.a.delta = spec(&schema::DELTA).snap(delta);
        match side.rows(self.settings.a.pf) {
            MapRows::Alpha => {
                let a = spec(&schema::ALPHA).snap(value);
                next.a.alpha = [a, a];
            }
            MapRows::TwistDamping => next.a.twist.damping = spec(&schema::TWIST_DAMPING).snap(value),
        }
        next.a.pf = pf;
        self.apply(next, false, "")
    }

    /// Moves run A's point on a map by arrow-key steps (δ across, α or k_d up), running with that
    /// map's preliminary feedback: the keyboard's way of clicking a map.
    pub fn step_on_map(&mut self, side: MapSide, delta_steps: i32, value_steps: i32) -> Result<(), Error> {
        let spec = |p: &schema::Param| *p.number().expect("δ, α and k_d are numbers");
        let a = self.settings.a;
        let delta = spec(&schema::DELTA).step_from(a.delta, delta_steps);
        let value = match side.rows(a.pf) {
            MapRows::Alpha => spec(&schema::ALPHA).step_from(a.alpha[0], value_steps),
            MapRows::TwistDamping => spec(&schema::TWIST_DAMPING).step_from(a.twist.damping, value_steps),
        };
        self.set_from_map(side, delta, value)
    }

    /// Runs A at a sampling period picked on ρ(δ): rounded to the δ control's precision and kept
    /// within its span.
    pub fn pick_delta(&mut self, delta: f64) -> Result<(), Error> {
        let spec = schema::DELTA.number().expect("δ is a number");
        let d = spec.value_at(spec.position(schema::round_significant(delta, spec.digits)));
        self.set_value(schema::DELTA.key, Value::Number(d))
    }

    /// Makes `next` the settings: run A (and B) take it live, or restart when `restart` or when
    /// they had diverged; the comparison starts and stops here. Invalid settings change nothing.
    pub(super) fn apply(&mut self, next: Settings, restart: bool, why: &str) -> Result<(), Error> {
        // Validate everything first, so a failure leaves the session as it was.
        next.validate()?;
        // Hidden maps do no work.
        self.maps.enabled = next.view.shown().map;
        if !restart && next.a == self.settings.a && next.b == self.settings.b {
            // The view or the speed: the runs go on as they were (even a diverged one).
            self.settings = next;
            return Ok(());
        }
        if restart {
            self.viewing = None;
        }
        let was_comparing = self.b.is_some();
        if restart || self.a.closed_loop().is_finished() || (next.b.is_some() && !was_comparing) {
            self.keep_ghost();
        }
        // Another arm's errors are another experiment on another scale: drawn under the new run
        // they were an off-scale comb of grey strokes. The ghost compares runs of one arm.
        if next.a.plant != self.settings.a.plant {
            self.forget_ghost();
        }
        let a_restarted = self.a.change(next.a, restart)?;
        let mut notes = Vec::new();
        match (next.b, self.b.as_mut()) {
            (Some(b), Some(run)) => {
                if run.change(b.run(&next.a), restart)? && !restart {
                    notes.push("Run B had diverged, so it restarted from rest with the new settings.");
                }
            }
            (Some(b), None) => {
                self.b = Some(Run::new(b.run(&next.a))?);
                self.viewing = None;
                // A fresh B beside a running A would compare different moments: restart A too.
                self.a.reset()?;
                notes.push("Comparing two runs: both restarted from rest together.");
            }
            (None, _) => self.b = None,
        }
        if a_restarted && !restart && was_comparing == next.b.is_some() {
            notes.insert(0, "The previous run had diverged, so it restarted from rest with the new settings.");
        }
        self.settings = next;
        self.note = if !why.is_empty() { why.to_string() } else { notes.join(" ") };
        self.maps.show(&self.linear_settings());
        Ok(())
    }
}

impl Session {
    /// Shows this part of the z-plane: centre (Re λ, Im λ) and half the shorter side (0: the
    /// default view around the flexible pair, centre ignored). Checked against the schema's
    /// limits (`zre`, `zim`, `zsize`) like any setting; the runs go on.
    pub fn set_z_view(&mut self, center: [f64; 2], half: f64) -> Result<(), Error> {
        let mut next = self.settings;
        let center = if half > 0.0 { center } else { [0.0, 0.0] };
        for (p, v) in [(&schema::ZRE, center[0]), (&schema::ZIM, center[1]), (&schema::ZSIZE, half)] {
            next.view.set(p.key, Value::Number(p.check(v)?));
        }
        self.apply(next, false, "")
    }
}
