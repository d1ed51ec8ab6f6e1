// The preliminary feedback as a design, beside its settings: where its pair is, what it costs on an
// analog and on a sampled inner loop and in motor torque (the status' `design`, Rust's words), and
// the handle that places the pair — dragged on the pole plot (pointer.js) or moved here by the
// arrow keys. Placing writes the twist gains into the settings (the session decides, and refuses a
// target no twist feedback reaches with the reason, shown here).

import { byId, setSymbols, setText } from './dom.js';
import { arrowSteps } from './focus.js';

/**
 * @typedef {{ pair: string, target: number[], placeable: boolean, analog: string, sampled: string,
 *   delta_max: (number | null)[], inner: string, torque: string, parts: string }} DesignStatus
 */

/**
 * @param {{ place: (re: number, im: number) => string, nudge: (re: number, im: number) => string }} on
 *   each returns "" when placed, else why not
 */
export function createDesign(on) {
  const box = byId('design');
  const handle = /** @type {HTMLButtonElement} */ (byId('pair-handle'));
  const refusal = byId('design-refusal');
  const fields = /** @type {HTMLElement[]} */ ([...box.querySelectorAll('[data-design]')]);
  /** @type {DesignStatus | null} */
  let shown = null;

  /** @param {string} why */
  function said(why) {
    setText(refusal, why);
    refusal.hidden = why === '';
  }

  handle.addEventListener('keydown', (ev) => {
    const steps = arrowSteps(ev.key);
    if (!steps) return;
    ev.preventDefault();
    said(on.nudge(steps[0], steps[1]));
  });

  return {
    /** @param {DesignStatus | null | undefined} d */
    render(d) {
      box.hidden = !d;
      shown = d ?? null;
      if (!d) return;
      for (const node of fields) {
        const key = /** @type {keyof DesignStatus} */ (node.dataset.design ?? '');
        const text = String(d[key] ?? '');
        setSymbols(node, text);
        node.hidden = text === '';
      }
      box.dataset.inner = d.inner;
      handle.hidden = !d.placeable;
      const [re, im] = d.target;
      handle.setAttribute(
        'aria-label',
        `The flexible pair's target, s = ${re.toFixed(2)} ± ${im.toFixed(2)}j 1/s: arrow keys move it (left: more damping, up: faster)`,
      );
    },
    /** The pair can be dragged now. */
    placeable: () => Boolean(shown?.placeable),
    /** Places the pair at (re, im) from a drag; shows why not. @param {number} re @param {number} im */
    place(re, im) {
      said(on.place(re, im));
    },
  };
}
