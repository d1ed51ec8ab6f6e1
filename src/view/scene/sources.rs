//! What a frame is drawn from: a page session (its runs, their analyses, kept states and maps),
//! closed loops with or without their analyses, or a bare snapshot and traces. Each becomes the
//! [`RunState`]s that [`Scene::draw_runs`] draws.

use super::{RunState, Scene};
use crate::analysis::StabilityReport;
use crate::control::{ClosedLoop, Snapshot, Traces};
use crate::model::reference::Reference;
use crate::session::{MapSide, Run, Session};
use crate::view::painter::Vertex;

impl Scene {
    /// Copies the rows of the session's maps that the scene does not have yet.
    fn sync_maps(&mut self, session: &Session) {
        for side in MapSide::BOTH {
            let Some(entry) = session.maps().shown(side) else { continue };
            let job = entry.job();
            if self.panels.maps.follow(side, entry.generation(), job.deltas(), job.alphas(), job.values()) {
                self.rebuild_static();
                self.info_generation += 1;
            }
        }
    }

    /// Copies the session's sensor study when it moved (a start, a run done, another limit).
    fn sync_study(&mut self, session: &Session) {
        let generation = session.study_generation();
        let limit = session.run(0).and_then(|a| a.closed_loop().config().sensors.limit());
        if generation == self.panels.study.generation() && limit == self.panels.study.limit() {
            return;
        }
        if self.panels.study.follow(generation, session.study_facts().as_ref(), limit) {
            self.rebuild_static();
            self.info_generation += 1;
        }
    }

    /// Builds the frame for a session: run A, and run B beside it when comparing, with their
    /// analyses, and the session's maps (copied only when they have new rows).
    pub fn draw_session(&mut self, session: &Session) -> &[Vertex] {
        self.follow_view(&session.drawn_view());
        self.sync_maps(session);
        self.sync_study(session);
        let a = session.run(0).expect("a session always has run A");
        self.frame.cursor = session.viewing();
        let sa = session.shown_snapshot(0).unwrap_or_else(|| a.closed_loop().snapshot());
        let ra = Reference::new(a.closed_loop().config().reference);
        let mut run_a = run_state(a, &sa, Some(&ra));
        run_a.windows = session.cached_windows();
        if self.frame.windows_hidden != session.windows_hidden() {
            // ρ(δ)'s note says why it is empty.
            self.frame.windows_hidden = session.windows_hidden();
            self.info_generation += 1;
        }
        run_a.ghost = session.ghost().map(|g| &g.traces);
        match session.run(1) {
            Some(b) => {
                let sb = session.shown_snapshot(1).unwrap_or_else(|| b.closed_loop().snapshot());
                self.draw_runs(run_a, Some(run_state(b, &sb, None)));
            }
            None => {
                self.draw_runs(run_a, None);
            }
        }
        self.painter.vertices()
    }

    /// Builds the frame for one closed loop without an analysis (no poles).
    pub fn draw(&mut self, closed_loop: &ClosedLoop) -> &[Vertex] {
        self.draw_loops(closed_loop, None, None)
    }

    /// Builds the frame for one closed loop with its analysis, and a second one beside it.
    pub fn draw_loops(
        &mut self,
        a: &ClosedLoop,
        analysis: Option<&StabilityReport>,
        b: Option<(&ClosedLoop, Option<&StabilityReport>)>,
    ) -> &[Vertex] {
        self.frame.cursor = None;
        let reference = Reference::new(a.config().reference);
        let snap_a = a.snapshot();
        let run_a = RunState {
            reference: Some(&reference),
            config: Some(a.config()),
            analysis,
            ..RunState::bare(&snap_a, a.traces())
        };
        match b {
            Some((b, analysis_b)) => {
                let snap_b = b.snapshot();
                let run_b =
                    RunState { config: Some(b.config()), analysis: analysis_b, ..RunState::bare(&snap_b, b.traces()) };
                self.draw_runs(run_a, Some(run_b))
            }
            None => self.draw_runs(run_a, None),
        }
    }

    /// Builds the frame from a snapshot and traces without a configuration (no poles, no map
    /// markers); `reference` (if given) shades the slews.
    pub fn draw_state(&mut self, snapshot: &Snapshot, traces: &Traces, reference: Option<&Reference>) -> &[Vertex] {
        self.draw_runs(RunState { reference, ..RunState::bare(snapshot, traces) }, None)
    }
}

/// What the scene draws of a session's run.
fn run_state<'a>(run: &'a Run, snapshot: &'a Snapshot, reference: Option<&'a Reference>) -> RunState<'a> {
    RunState {
        reference,
        config: Some(run.closed_loop().config()),
        analysis: run.analysis().report(),
        history: Some(run.closed_loop().history()),
        sweep: run.closed_loop().latest_sweep(),
        ..RunState::bare(snapshot, run.closed_loop().traces())
    }
}
