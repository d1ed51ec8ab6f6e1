// The z-plane's zoom: its buttons (+, −, the whole circle, the flexible pair), placed under the
// panel's tick labels (the row of the x axis' title) from the rectangle the renderer reports, and
// the one place the page's gestures, keys and buttons reach the view through. What they do to the
// view is the renderer's (`zoomZ`, `panZ`) and the session's (`zView`); this routes them.

import { byId } from './dom.js';
import { zKey } from './focus.js';

/** The buttons' actions, by their data-z attribute (pure). @param {string} name */
export function zAction(name) {
  return { in: { zoom: 1.5 }, out: { zoom: 1 / 1.5 }, whole: { view: 'whole' }, pair: { view: 'pair' } }[name] ?? null;
}

/**
 * @param {{ session: import('./flexarm.js').Page, renderer: () => import('../pkg/flexarm.js').Renderer | null, layout: () => any,
 *   guard: (what: string, fn: () => any, fallback: any) => any, changed: () => void }} on
 */
export function createZoom(on) {
  const group = byId('zoom-z');
  const coarse = matchMedia('(pointer: coarse)');
  const panel = () => on.layout()?.panels?.find((/** @type {any} */ q) => q.region?.keys === 'zplane');
  /** Runs a change of the view; the URL and the picture follow (the runs go on). @param {() => any} fn */
  const run = (fn) => {
    const done = Boolean(on.guard('Zooming the z-plane failed', fn, false));
    if (done) on.changed();
    return done;
  };
  /** A zoom (about the centre), a pan (tenths of the panel) or a named view. @param {any} a */
  const by = (a) => {
    const r = on.renderer();
    const p = panel();
    if (a.view) return run(() => (on.session.zView(a.view), true));
    if (a.zoom) return run(() => r ? on.session.zoomZ(r, NaN, NaN, a.zoom) : false);
    if (a.pan && p) return run(() => r ? on.session.panZ(r, (-a.pan[0] * p.width) / 10, (a.pan[1] * p.height) / 10) : false);
    return false;
  };
  for (const b of group.querySelectorAll('button')) {
    b.addEventListener('click', () => {
      const action = zAction(/** @type {HTMLElement} */ (b).dataset.z ?? '');
      if (action) by(action);
    });
  }
  return {
    by,
    /** True if (x, y) (CSS px of the canvas) is on the z-plane. @param {number} x @param {number} y */
    on: (x, y) => Boolean(on.renderer()?.zAt(x, y)),
    /** @param {number} x @param {number} y @param {number} f */
    zoomAt: (x, y, f) => run(() => { const r = on.renderer(); return r ? on.session.zoomZ(r, x, y, f) : false; }),
    /** @param {number} dx @param {number} dy */
    panBy: (dx, dy) => run(() => { const r = on.renderer(); return r ? on.session.panZ(r, dx, dy) : false; }),
    /** + − 0 P with the pointer at `at` over the z-plane (the arrows keep stepping time).
     * @param {KeyboardEvent} ev @param {{ x: number, y: number } | null} at */
    key: (ev, at) => {
      const a = zKey(ev);
      return Boolean(a && !a.pan && at && on.renderer()?.zAt(at.x, at.y) && by(a));
    },
    /** Places the buttons for a new description of the frame. @param {any} layout */
    update(layout) {
      group.classList.toggle('coarse', coarse.matches);
      const p = (layout?.panels ?? []).find((/** @type {any} */ q) => q.region?.keys === 'zplane');
      group.hidden = !p;
      if (!p) return;
      // A touch screen's finger-wide buttons would cover the plot: they go under the figure.
      if (coarse.matches) {
        const wrap = byId('canvas-wrap');
        if (group.parentElement === wrap) wrap.after(group);
        Object.assign(group.style, { left: '', top: '', transform: '' });
        return;
      }
      // Under the tick labels, at the left of the row whose right end holds "Re λ"; that row grows
      // with the figure's text (Rust's text scale), and so do the buttons.
      const k = layout.text_scale ?? 1;
      Object.assign(group.style, { left: `${p.x}px`, top: `${p.y + p.height + 20 * k}px`, transform: k === 1 ? '' : `scale(${k})`, transformOrigin: '0 0' });
    },
  };
}
