// One run's verdict block — the same view for run A and run B: the verdict word, what it means,
// the observed growth and what the linear analysis says. The words come from the session.

import { byId, setText } from './dom.js';

/** The growth line changes a little all the time: refresh it at most this often, ms. */
export const GROWTH_REFRESH_MS = 1000;

/**
 * @typedef {{ run: string, verdict: string, observing: boolean, finished: boolean, detail: string,
 *   growth: string, rho: string, settings: string,
 *   readouts: { time: string, error: string, max_slew: string, max_after: string, torque: string, a4: string } }} RunStatus
 */

/** Whether the growth line should be rewritten now (pure). */
export function growthDue(previous, next, now) {
  return next.verdict !== previous.verdict || next.growth.endsWith('…') || now - previous.shownAt >= GROWTH_REFRESH_MS;
}

/** @param {string} prefix the element ids' prefix: "verdict" (A) or "verdict-b" (B) */
export function createRunView(prefix) {
  const box = byId(prefix);
  const word = byId(`${prefix}-word`);
  const detail = byId(`${prefix}-detail`);
  const growth = byId(`${prefix}-growth`);
  const rho = byId(`${prefix}-rho`);
  const last = { verdict: '', growth: '', shownAt: -Infinity };
  return {
    /** @param {RunStatus} s @param {number} now ms */
    render(s, now) {
      if (box.dataset.verdict !== s.verdict) box.dataset.verdict = s.verdict;
      const observing = s.observing ? 'true' : 'false';
      if (box.dataset.observing !== observing) box.dataset.observing = observing;
      setText(word, s.verdict);
      setText(detail, s.detail);
      if (growthDue(last, s, now)) {
        setText(growth, s.growth);
        last.shownAt = now;
      }
      last.verdict = s.verdict;
      setText(rho, s.rho);
    },
    /** Shown when the wasm crashed. */
    crashed() {
      box.dataset.verdict = 'error';
      setText(word, 'crashed');
      setText(detail, 'reload the page');
      setText(growth, '');
      setText(rho, '');
    },
  };
}
