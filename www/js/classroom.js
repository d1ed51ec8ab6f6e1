// The lesson and the answers' record, wired to the session's classroom: a lesson's action (start,
// next, back, leave, an answer, a teacher's file) makes its settings and plays them from the start,
// or holds still where a step opens at a moment; a revealed task and a change of the record are
// shown at once. Which step, what it sets up and what counts as done are the session's (Rust).

import { createLesson } from './lesson.js';
import { createAnswers } from './answers.js';
import { createClassTable } from './class.js';
import { messageOf } from './dom.js';

/** @typedef {import('./flexarm.js').Page} Page */
/** @typedef {ReturnType<typeof import('./store.js').createStore>} Store */

/**
 * @param {{ session: Page, store: Store, presets: { id: string, title: string, settings_title: string }[],
 *   guard: <T>(what: string, fn: () => T, fallback?: T) => T | undefined, report: (what: string, e: unknown) => void,
 *   change: (fn: () => void) => void, refresh: () => void, touch: () => void,
 *   openSheet: (open: boolean) => void, showFigure: () => void,
 *   download: (name: string, text: string, type: string) => void, loaded?: () => void,
 *   mergeAnswers: (names: string[], texts: string[]) => import('./class.js').Merged }} on
 */
export function createClassroom({ session, store, presets, report, change, refresh, openSheet, showFigure, download, loaded, mergeAnswers }) {
  const classTable = createClassTable({ merge: mergeAnswers, download, report });
  /** A lesson action: the settings it makes, played from the start. @param {() => void} fn */
  const lessonDo = (fn) => {
    session.setWallClock(Date.now());
    change(fn);
    // A step may start paused at a moment (`paused=1&t=2`).
    store.dispatch({ type: session.takeStartPaused() ? 'pause' : 'play' });
    refresh();
  };
  const lesson = createLesson({
    start: () => {
      lessonDo(() => session.lessonOpen(0));
      openSheet(true);
    },
    next: () => lessonDo(() => session.lessonNext()),
    back: () => lessonDo(() => session.lessonBack()),
    leave: () => lessonDo(() => session.lessonLeave()),
    open: async (file) => {
      const bytes = new Uint8Array(await file.arrayBuffer());
      try {
        session.loadLesson(file.name, bytes);
      } catch (e) {
        // Where the teacher acted (beside "open a lesson file…", also for a file dropped on the
        // page): the file's name, the faulty line and what is wrong with it.
        const why = 'The lesson file could not be used (the lesson stays as it was)';
        if (!lesson.fileError(`${why}: ${messageOf(e)}`)) report(why, e);
        return;
      }
      lesson.fileError('');
      loaded?.();
      lessonDo(() => {});
    },
    merge: (files) => classTable.merge(files),
    answer: (choice) => {
      lessonDo(() => session.lessonAnswer(choice));
      showFigure();
    },
    // "Show me": the step's settings, which the controls and the address follow like any change.
    reveal: () => {
      session.setWallClock(Date.now());
      change(() => session.lessonReveal());
      refresh();
    },
  });
  const answers = createAnswers({
    session,
    presets,
    report,
    download,
    // Student mode kept or lifted, answers given back: the controls and the address follow.
    changed: () => {
      change(() => {});
      refresh();
    },
  });
  return { lesson, answers };
}
