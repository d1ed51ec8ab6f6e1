// One run's verdict block — the same view for run A and run B: the verdict (from ρ, known at
// once), the prediction in a sentence, what the simulation observed, the linear analysis. The
// words come from the session; screen readers hear only verdict changes (see `announce`).

import { byId, setText } from './dom.js';

/** The observation line changes a little all the time: refresh it at most this often, ms. */
export const GROWTH_REFRESH_MS = 1000;

/**
 * @typedef {{ time: string, error: string, max_slew: string, max_after: string, torque: string,
 *   growth: string, a4: string }} Readouts
 * @typedef {{ run: string, verdict: string, headline: string, detail: string, short: string, detail_short: string, observed: string,
 *   measured: boolean, finished: boolean, rho: string, announce: string, settings: string,
 *   readouts: Readouts, limits: string }} RunStatus
 */

/** Whether the observation line should be rewritten now (pure): a new verdict, the first
 * measurement, a new analysis (its rates are quoted in the line), or a second since the last
 * rewrite. */
export function growthDue(previous, next, now) {
  return next.verdict !== previous.verdict || next.measured !== previous.measured || next.rho !== previous.rho
    || now - previous.shownAt >= GROWTH_REFRESH_MS;
}

/**
 * What the Play/Pause button does next, in its words (pure): once every run has diverged it
 * restarts them; otherwise it pauses a playing run and plays a paused one.
 * @param {boolean} playing @param {boolean} finished
 */
export function playAction(playing, finished) {
  if (finished) return { action: 'restart', text: '↺ Restart', label: 'Restart the run from rest', pressed: false };
  return playing
    ? { action: 'pause', text: '❚❚ Pause', label: 'Pause the simulation', pressed: true }
    : { action: 'play', text: '▶ Play', label: 'Play the simulation', pressed: false };
}

/**
 * @param {string} prefix the element ids' prefix: "verdict" (A) or "verdict-b" (B)
 * @param {string} growthCell the id of the readout of the observed growth, refreshed with the
 *   observation line so that the two always show the same measurement
 */
export function createRunView(prefix, growthCell) {
  const box = byId(prefix);
  const word = byId(`${prefix}-word`);
  const detail = byId(`${prefix}-detail`);
  const observed = byId(`${prefix}-growth`);
  const rho = byId(`${prefix}-rho`);
  const limits = byId(`${prefix}-limits`);
  const growth = byId(growthCell);
  const last = { verdict: '', measured: false, rho: '', shownAt: -Infinity };
  return {
    /** @param {RunStatus} s @param {number} now ms */
    render(s, now) {
      if (box.dataset.verdict !== s.verdict) box.dataset.verdict = s.verdict;
      setText(word, s.headline);
      setText(detail, s.detail);
      if (growthDue(last, s, now)) {
        setText(observed, s.observed);
        setText(growth, s.readouts.growth);
        last.shownAt = now;
      }
      last.verdict = s.verdict;
      last.measured = s.measured;
      last.rho = s.rho;
      setText(rho, s.rho);
      // With sensors on: what limits the error (empty, and hidden, for the paper's perfect robot).
      setText(limits, s.limits);
      if (limits.hidden !== !s.limits) limits.hidden = !s.limits;
    },
    /** Shown when the wasm crashed. */
    crashed() {
      box.dataset.verdict = 'error';
      setText(word, 'crashed');
      setText(detail, 'reload the page');
      setText(observed, '');
      setText(rho, '');
    },
  };
}
