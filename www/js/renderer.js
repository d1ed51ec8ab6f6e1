// The renderer once the browser's GPU is ready: which backend it got (shown, and kept in the
// store), its size kept that of the canvas' box at the screen's pixel ratio, the colour scheme
// followed as the stylesheet follows it; or, when neither WebGPU nor WebGL2 works, a message in
// the figure's place (the simulation, the status and the readouts run on without it).

import { byId, messageOf, setText } from './dom.js';
import { canvasProblem } from './figure.js';

/** @typedef {import('../pkg/flexarm.js').Renderer} Renderer */
/** @typedef {ReturnType<typeof import('./store.js').createStore>} Store */

/**
 * Waits for the renderer and puts it to work (`use`); `current` is the one drawing now (none
 * after repeated errors).
 * @param {{ ready: Promise<Renderer>, use: (r: Renderer) => void, current: () => Renderer | null, store: Store,
 *   guard: <T>(what: string, fn: () => T, fallback?: T) => T | undefined, show: (text: string) => void, touch: () => void }} on
 */
export async function startRenderer({ ready, use, current, store, guard, show, touch }) {
  try {
    const renderer = await ready;
    use(renderer);
    performance.mark('flexarm:renderer-ready');
    const backend = renderer.backend();
    store.dispatch({ type: 'renderer', backend });
    const label = byId('backend');
    setText(label, backend);
    label.dataset.backend = backend;
    watchSize(current, guard, touch);
    // The canvas follows the system's colour scheme, as the stylesheet does.
    const dark = matchMedia('(prefers-color-scheme: dark)');
    const scheme = () => {
      current()?.setDark(dark.matches);
      touch();
    };
    dark.addEventListener('change', scheme);
    scheme();
  } catch (e) {
    setText(byId('backend'), 'none');
    byId('backend').dataset.backend = 'none';
    canvasProblem('This browser cannot draw the animation (neither WebGPU nor WebGL2 works).', `${messageOf(e)} — the simulation, status and readouts still run.`);
    show(`Renderer: ${messageOf(e)}`);
  }
}

/**
 * Keeps the renderer's size that of the canvas' box and the screen's pixel ratio.
 * @param {() => Renderer | null} current
 * @param {<T>(what: string, fn: () => T, fallback?: T) => T | undefined} guard
 * @param {() => void} touch
 */
function watchSize(current, guard, touch) {
  const wrap = byId('canvas-wrap');
  const size = { w: 0, h: 0 };
  const resize = () => {
    const r = current();
    if (r && size.w > 0 && size.h > 0) guard('Renderer resize failed', () => r.resize(size.w, size.h, window.devicePixelRatio || 1, window.innerHeight));
    touch();
  };
  new ResizeObserver((entries) => {
    for (const entry of entries) Object.assign(size, { w: Math.round(entry.contentRect.width), h: Math.round(entry.contentRect.height) });
    resize();
  }).observe(wrap);
  const watchDpr = () => {
    matchMedia(`(resolution: ${window.devicePixelRatio || 1}dppx)`).addEventListener('change', () => {
      watchDpr();
      resize();
    }, { once: true });
  };
  watchDpr();
  const rect = wrap.getBoundingClientRect();
  Object.assign(size, { w: Math.round(rect.width), h: Math.round(rect.height) });
  resize();
}
