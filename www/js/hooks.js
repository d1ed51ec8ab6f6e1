// What the page adds to `window`: the hook Rust's panic handler calls (the page stops, says so and
// disables its controls), and, for the end-to-end tests and the console, the live objects and the
// performance figures (`flexarmPerf()`).

import { messageOf } from './dom.js';
import { canvasProblem } from './figure.js';

/** @typedef {import('./flexarm.js').Page} Page */
/** @typedef {import('./wasm.js').Wasm} Wasm */
/** @typedef {ReturnType<typeof import('./store.js').createStore>} Store */

/**
 * @param {{ session: Page, wasm: Wasm, store: Store, show: (text: string) => void,
 *   status: { crashed: () => void }, controls: { setEnabled: (enabled: boolean) => void },
 *   layout: () => any, figures: (extra: object) => object }} on
 */
export function installHooks({ session, wasm, store, show, status, controls, layout, figures }) {
  window.flexarmPanic = (/** @type {unknown} */ msg) => {
    store.dispatch({ type: 'crash' });
    show(`The simulation crashed (Rust panic) — reload the page to start again. ${messageOf(msg)}`);
    canvasProblem('The simulation crashed.', 'See the error message above; reload the page to start again.');
    status.crashed();
    controls.setEnabled(false);
  };
  // For tests and the console: the live objects, and the performance figures.
  Object.assign(window, {
    flexarm: { session, wasm, store, get lastLayout() { return layout(); } },
    flexarmPerf: () => {
      const times = session.mapTimes();
      const last = times[times.length - 1];
      return figures({ map_times: times, map_ms: last ? last.ms : null, map_compute_ms: last ? last.compute_ms : null });
    },
  });
}
