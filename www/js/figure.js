// The figure on the canvas: the renderer (once the GPU is ready; dropped after repeated errors),
// drawing a frame and, when the frame's description changed, everything placed from it (the labels
// over the canvas, the tabs, the key, the keyboard's regions, the z-plane's buttons); the pointer
// and the z-plane's zoom on it; and the message in the canvas' place when it cannot draw. What is
// drawn, and what lies under the pointer, is the renderer's (Rust).

import { byId, make, messageOf } from './dom.js';
import { writeUrl } from './url.js';
import { createTabs } from './tabs.js';
import { createLegend } from './legend.js';
import { createFocus } from './focus.js';
import { createZoom } from './zplane_zoom.js';
import { createPointer } from './pointer.js';

/** @typedef {import('./flexarm.js').Page} Page */
/** @typedef {import('../pkg/flexarm.js').Renderer} Renderer */
/** @typedef {ReturnType<typeof import('./store.js').createStore>} Store */
/** @typedef {ReturnType<typeof import('./overlays.js').createOverlays>} Overlays */

/** Shows `title` and `detail` where the canvas was. @param {string} title @param {string} detail */
export function canvasProblem(title, detail) {
  byId('canvas-message').replaceChildren(make('strong', { text: title }), make('span', { text: detail }));
  byId('canvas-message').hidden = false;
  byId('canvas').hidden = true;
}

/**
 * @param {{ session: Page, store: Store, overlays: Overlays,
 *   guard: <T>(what: string, fn: () => T, fallback?: T) => T | undefined, report: (what: string, e: unknown) => void,
 *   change: (fn: () => void) => void, scrubTo: (t: number) => void, touch: () => void,
 *   design: ReturnType<typeof import('./design.js').createDesign> }} on
 */
export function createFigure({ session, store, overlays, guard, report, change, scrubTo, touch, design }) {
  /** @type {Renderer | null} */
  let renderer = null;
  /** The frame's description as last read (`Renderer.layout()`). @type {any} */
  let layout = null;
  let layoutGeneration = -1;

  const tabs = createTabs({ select: (id) => change(() => session.set('tab', id)) });
  const legend = createLegend();
  const focus = createFocus({
    stepOnMap: (side, d, a) => change(() => session.stepOnMap(side, d, a)),
    enterMap: (side) => change(() => session.stepOnMap(side, 0, 0)),
    stepDelta: (d) => change(() => session.stepValue('delta', d)),
    probe: (x, y) => (renderer ? guard('Pointer', () => renderer?.probe(x, y, 2), null) : null),
    showTip: overlays.showTip,
    hideTip: overlays.hideTip,
    zKey: (action) => zoom.by(action),
    attachZ: (el) => pointer.attach(el),
  });
  const zoom = createZoom({ session, renderer: () => renderer, layout: () => layout, guard, changed: () => (writeUrl(session.stateString()), touch()) });
  const pointer = createPointer({
    probe: (x, y, reach) => (renderer ? guard('Pointer', () => renderer?.probe(x, y, reach), null) : null),
    pick: (map, delta, alpha) => change(() => session.setFromMap(map, delta, alpha)),
    pickDelta: (delta) => change(() => session.pickDelta(delta)),
    showTip: overlays.showTip,
    hideTip: overlays.hideTip,
    timeAt: (x, y) => renderer?.timeAt(x, y),
    scrubTo,
    onZ: zoom.on,
    zoomZ: zoom.zoomAt,
    panZ: zoom.panBy,
    onHandle: (x, y, reach) => design.placeable() && Boolean(renderer?.pairHandleAt(x, y, reach)),
    holdPoles: (hold) => renderer?.holdPolePlot(hold),
    placeAt: (x, y) => {
      const s = renderer?.polePlotPoint(x, y);
      if (s) design.place(s[0], Math.abs(s[1]));
    },
  });

  /** Draws a frame; refreshes the labels when the frame's description changed. */
  function render() {
    if (!renderer) return false;
    try {
      renderer.render(session.session);
      store.dispatch({ type: 'render-ok' });
    } catch (e) {
      store.dispatch({ type: 'render-failed' });
      report('Drawing failed', e);
      if (store.get().renderFailures >= 3) {
        renderer = null;
        canvasProblem('Drawing stopped after repeated errors.', messageOf(e));
      }
      return false;
    }
    const generation = renderer.infoGeneration();
    if (generation !== layoutGeneration) {
      layout = guard('Renderer layout', () => renderer?.layout(), null);
      layoutGeneration = generation;
      if (layout) {
        // The bar, its verdict and the key grow with the text size chosen (presentation mode).
        document.body.style.setProperty('--present-text', String(layout.page_text));
        overlays.update(layout);
        tabs.render(layout.tabs);
        legend.render(layout.legend);
        focus.update(layout);
        zoom.update(layout);
      }
    }
    overlays.scroll(renderer.windowStart(), renderer.windowEnd());
    return true;
  }

  return {
    render,
    /** The renderer drawing the figure, if any. */
    renderer: () => renderer,
    /** The GPU is ready: this renderer draws from now on. @param {Renderer} r */
    use(r) {
      renderer = r;
    },
    /** The frame's description as last read. */
    layout: () => layout,
    /** The pointer's tooltip and marks go (a change moved what they pointed at). */
    hidePointer: () => pointer.hide(),
    /** + − 0 P over the z-plane, where the pointer last was; true if they zoomed. @param {KeyboardEvent} ev */
    zoomKey: (ev) => zoom.key(ev, pointer.last()),
  };
}
