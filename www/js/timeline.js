// The timeline under the canvas: a scrubber over the kept past (the last 30 s), one sampling
// period back, and "continue from here". Where the session looks and what it says about it are
// the session's; this maps the scrubber's position to a time and back.

import { byId, setText } from './dom.js';

/** Scrubber resolution. */
const STEPS = 1000;

/** The scrubber's position (0…STEPS) for time `t` in [start, end] (pure). */
export function positionOf(/** @type {number} */ t, /** @type {number} */ start, /** @type {number} */ end) {
  if (!(end > start)) return STEPS;
  return Math.round(Math.min(Math.max((t - start) / (end - start), 0), 1) * STEPS);
}

/** The time at scrubber position `p` (pure). */
export function timeAt(/** @type {number} */ p, /** @type {number} */ start, /** @type {number} */ end) {
  return start + (Math.min(Math.max(p, 0), STEPS) / STEPS) * (end - start);
}

/**
 * @typedef {{ live: boolean, time: number, start: number, end: number, text: string }} TimelineStatus
 * @param {{ viewAt: (t: number) => void, stepBack: () => void, continueHere: () => void }} on
 */
export function createTimeline(on) {
  const scrub = /** @type {HTMLInputElement} */ (byId('scrub'));
  const text = byId('timeline-text');
  const here = byId('continue-here');
  /** The span the scrubber maps onto, as of the last status. */
  let span = { start: 0, end: 0 };
  let dragging = false;

  scrub.addEventListener('pointerdown', () => (dragging = true));
  scrub.addEventListener('pointerup', () => (dragging = false));
  scrub.addEventListener('blur', () => (dragging = false));
  scrub.addEventListener('input', () => on.viewAt(timeAt(Number(scrub.value), span.start, span.end)));
  byId('step-back').addEventListener('click', on.stepBack);
  here.addEventListener('click', on.continueHere);

  /** @param {TimelineStatus} s */
  function render(s) {
    span = { start: s.start, end: s.end };
    setText(text, s.text);
    here.hidden = s.live;
    scrub.setAttribute('aria-valuetext', s.live ? `now, t = ${s.end.toFixed(2)} s` : `t = ${s.time.toFixed(2)} s of ${s.end.toFixed(2)} s`);
    if (!dragging) {
      const p = String(positionOf(s.time, s.start, s.end));
      if (scrub.value !== p) scrub.value = p;
    }
  }

  return { render };
}
