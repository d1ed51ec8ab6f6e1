// Everything the page says about the session, from one status (a few times a second from the frame
// loop, and at once after a lesson's action or a look back): the figure's description and the
// z-plane's caption, the verdicts and readouts (status.js), Play's words once every run has
// diverged, which line is which, the verdicts over the figure, the lesson (its sheet opened once
// for a lesson a link opened), the answers' record, the timeline.

import { byId, setText } from './dom.js';

/** @typedef {import('./flexarm.js').Page} Page */
/** @typedef {import('./status.js').Status} Status */

/**
 * The status' views, each told its part.
 * @param {{ session: Page, guard: <T>(what: string, fn: () => T, fallback?: T) => T | undefined,
 *   status: ReturnType<typeof import('./status.js').createStatus>,
 *   transport: { showFinished: (all: boolean) => void },
 *   present: ReturnType<typeof import('./present.js').createPresent>,
 *   lesson: ReturnType<typeof import('./lesson.js').createLesson>,
 *   answers: ReturnType<typeof import('./answers.js').createAnswers>,
 *   timeline: ReturnType<typeof import('./timeline.js').createTimeline>,
 *   layout: () => any, openSheet: (open: boolean) => void,
 *   design: ReturnType<typeof import('./design.js').createDesign> }} on
 * @returns {() => void} the refresh
 */
export function createRefresh({ session, guard, status, transport, present, lesson, answers, timeline, layout, openSheet, design }) {
  const figureDescription = byId('figure-description');
  const zoomCaption = byId('zoom-caption');
  /** The open lesson's sheet has been opened once. */
  let lessonShown = false;
  return function refreshStatus() {
    // The clock the answers' record stamps a task with when the session sees it done.
    session.setWallClock(Date.now());
    /** @type {Status & { figure: string, cycle: string, design: import('./design.js').DesignStatus | null } | null | undefined} */
    const s = guard('Status', () => session.status(), null);
    if (!s) return;
    setText(figureDescription, s.figure);
    zoomCaption.hidden = !s.cycle;
    setText(zoomCaption, s.cycle);
    // A lesson opened from a link shows its step: on a phone, the sheet it lives in opens once.
    if (s.lesson && !lessonShown) {
      lessonShown = true;
      openSheet(true);
    }
    if (!s.lesson) lessonShown = false;
    status.render(s, performance.now());
    design.render(s.design);
    transport.showFinished(s.runs.every((r) => r.finished));
    status.renderLegend(s, layout()?.series ?? []);
    present.render(s.runs, layout()?.series ?? []);
    lesson.render(s.lesson);
    answers.sync(s.lesson, s.hidden);
    timeline.render(s.timeline);
  };
}
