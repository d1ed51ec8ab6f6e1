// Time on the page: Play and Pause (the page's, the embed's and the presentation bar's buttons say
// what a press will do; once every run has diverged, Restart from rest), one sampling period
// forward and back, Reset, a poke; and looking back: the scrubber and "continue from here"
// (timeline.js). The notes a run shows while a change or a link's moment holds it paused go on
// Play. Whether the runs have diverged, and what a step does, are the session's to say.

import { byId, setText } from './dom.js';
import { playAction } from './run.js';
import { writeUrl } from './url.js';
import { createTimeline } from './timeline.js';

/** @typedef {import('./flexarm.js').Page} Page */
/** @typedef {ReturnType<typeof import('./store.js').createStore>} Store */

/** The note shown when a setting changes while the run is paused. */
export const PAUSED_NOTE = 'Paused: the change takes effect at the next sampling instant (press Step or Play).';
/** What a link to a moment (`paused=1`) opens with. */
export const START_NOTE = 'Opened paused at this moment: press Play to run on.';

/** Whether Play takes the run's note away: it is one of the notes a pause put there (pure). @param {string} note */
export function pauseNote(note) {
  return [PAUSED_NOTE, START_NOTE].includes(note);
}

/**
 * @param {{ session: Page, store: Store, guard: <T>(what: string, fn: () => T, fallback?: T) => T | undefined,
 *   change: (fn: () => void) => void, loop: { touch: () => void, resync: () => void }, refresh: () => void }} on
 */
export function createTransport({ session, store, guard, change, loop, refresh }) {
  const play = byId('play');
  const embedPlay = byId('embed-play');
  const presentPlay = byId('present-play');
  const embedReset = byId('embed-reset');
  const presentReset = byId('present-reset');
  /** Every run has diverged (the session says so): the button restarts them. */
  let finished = false;
  /** The Play buttons (the page's and the embed's) say what a press will do. */
  const showPlay = () => {
    const next = playAction(store.get().playing, finished);
    for (const button of [play, embedPlay, presentPlay]) {
      setText(button, next.text);
      button.setAttribute('aria-pressed', String(next.pressed));
      button.setAttribute('aria-label', next.label);
    }
    // Once Play restarts, the embed's Reset would be a second button doing the same.
    embedReset.classList.toggle('same-as-play', next.action === 'restart');
    presentReset.hidden = next.action === 'restart';
  };
  store.subscribe((s, prev) => {
    if (s.playing !== prev.playing) {
      // Paused, the address names the moment (`paused=1&t=…`): a reload or a copy of it opens
      // here; playing, it holds the settings only.
      guard('Updating the address', () => writeUrl(s.playing ? session.stateString() : session.momentQuery()));
      showPlay();
      if (s.playing && pauseNote(session.status().note)) session.setNote('');
      loop.resync();
      loop.touch();
    }
  });
  /** Play, Pause, or — after divergence — Restart from rest, playing. */
  const togglePlay = () => {
    if (playAction(store.get().playing, finished).action === 'restart') {
      reset();
      store.dispatch({ type: 'play' });
      return;
    }
    store.dispatch({ type: 'toggle-play' });
  };
  play.addEventListener('click', togglePlay);
  embedPlay.addEventListener('click', togglePlay);
  const step = () => {
    store.dispatch({ type: 'pause' });
    guard('Step failed', () => session.stepPeriod());
    loop.touch();
  };
  const stepBack = () => {
    store.dispatch({ type: 'pause' });
    session.stepBack();
    loop.touch();
  };
  const reset = () => change(() => session.reset());
  byId('step').addEventListener('click', step);
  byId('reset').addEventListener('click', reset);
  byId('poke').addEventListener('click', () => change(() => session.poke()));

  /** Looks back at time t (pausing: the picture holds still there). @param {number} t */
  const scrubTo = (t) => {
    store.dispatch({ type: 'pause' });
    session.viewAt(t);
    loop.touch();
    refresh();
  };
  const timeline = createTimeline({
    viewAt: scrubTo,
    stepBack,
    continueHere: () => {
      change(() => session.continueFromHere());
      store.dispatch({ type: 'play' });
    },
  });

  return {
    togglePlay,
    step,
    stepBack,
    reset,
    scrubTo,
    timeline,
    /** Play's words follow the session: whether every run has diverged. @param {boolean} all */
    showFinished(all) {
      if (finished === all) return;
      finished = all;
      showPlay();
    },
  };
}
