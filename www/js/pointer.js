// The pointer on the canvas: hovering (mouse) or tapping (touch, pen) a pole shows what it is,
// hovering a map shows ρ there, clicking a map runs at that point, dragging on ρ(δ) picks δ, and
// pressing and dragging on an error plot looks back at that instant; on the z-plane the wheel and
// a two-finger pinch zoom and a drag pans. What lies under the pointer, and what a gesture does to
// the view, is the renderer's answer; this module only routes events and their sizes.

import { byId } from './dom.js';

/** How far from a pole the pointer may be and still pick it, CSS px. */
const REACH = { mouse: 22, touch: 36 };
/** A press on the z-plane becomes a drag (pan) after moving this far, CSS px: a tap stays a tap. */
const DRAG_START = 5;

/** The zoom factor of a wheel event: a notch (100 px, 3 lines) zooms by about 1.2 (pure). */
export function wheelFactor(/** @type {{ deltaY: number, deltaMode: number }} */ ev) {
  const px = ev.deltaY * (ev.deltaMode === 1 ? 33 : ev.deltaMode === 2 ? 400 : 1);
  return Math.exp(-Math.max(-400, Math.min(400, px)) * 0.0018);
}

/**
 * @param {{ probe: (x: number, y: number, reach: number) => any, pick: (map: string, delta: number, alpha: number) => void,
 *   pickDelta: (delta: number) => void, showTip: (probe: any) => void, hideTip: () => void,
 *   timeAt: (x: number, y: number) => number | undefined, scrubTo: (t: number) => void,
 *   onZ: (x: number, y: number) => boolean, zoomZ: (x: number, y: number, factor: number) => boolean,
 *   panZ: (dx: number, dy: number) => boolean, onHandle: (x: number, y: number, reach: number) => boolean,
 *   placeAt: (x: number, y: number) => void, holdPoles: (hold: boolean) => void }} on
 */
export function createPointer(on) {
  const canvas = byId('canvas');
  let pinned = false;
  /** The pointer that is dragging the flexible pair on the pole plot, if any. */
  let placing = /** @type {number | null} */ (null);
  /** The pointer that is dragging through time on an error plot, if any. */
  let scrubbing = /** @type {number | null} */ (null);
  /** Pointers pressed on the z-plane: where each is now and whether it has started dragging. */
  const zPointers = /** @type {Map<number, { x: number, y: number, dragging: boolean }>} */ (new Map());
  /** The pointer's latest position over the figure (for the zoom keys), or null once it left. */
  let last = /** @type {{ x: number, y: number } | null} */ (null);

  /** @param {PointerEvent | MouseEvent | Touch} ev */
  const at = (ev) => {
    const r = canvas.getBoundingClientRect();
    return { x: ev.clientX - r.left, y: ev.clientY - r.top };
  };
  const isTouch = (ev) => ev.pointerType === 'touch' || ev.pointerType === 'pen';

  function hide() {
    pinned = false;
    on.hideTip();
    canvas.classList.remove('over-map', 'over-pole');
  }

  /** @param {any} probe */
  function show(probe) {
    on.showTip(probe);
    canvas.classList.toggle('over-pole', probe.kind === 'pole');
    canvas.classList.toggle('over-handle', last !== null && on.onHandle(last.x, last.y, REACH.mouse));
    canvas.classList.toggle('over-map', probe.kind === 'map' || picksDelta(probe));
  }

  /** The z-plane's gestures: one pointer drags the plane, two pinch it; true if the event was one.
   * @param {PointerEvent} ev @param {number} x @param {number} y */
  function zGesture(ev, x, y) {
    if (ev.type === 'pointerdown' && ev.button === 0 && on.onZ(x, y)) {
      zPointers.set(ev.pointerId, { x, y, dragging: false });
      return false; // a press still shows what it is on (a tap on a pole)
    }
    const p = zPointers.get(ev.pointerId);
    if (!p || ev.type !== 'pointermove') return false;
    if (zPointers.size >= 2) {
      // Pinch: zoom by the change of the fingers' distance about their midpoint, pan by its move.
      const [a, b] = [...zPointers.values()];
      const before = { d: Math.hypot(a.x - b.x, a.y - b.y), x: (a.x + b.x) / 2, y: (a.y + b.y) / 2 };
      Object.assign(p, { x, y, dragging: true });
      const after = { d: Math.hypot(a.x - b.x, a.y - b.y), x: (a.x + b.x) / 2, y: (a.y + b.y) / 2 };
      if (before.d > 0 && after.d > 0) on.zoomZ(after.x, after.y, after.d / before.d);
      on.panZ(after.x - before.x, after.y - before.y);
    } else {
      const [dx, dy] = [x - p.x, y - p.y];
      if (!p.dragging && Math.hypot(dx, dy) < DRAG_START) return false;
      if (!p.dragging) {
        p.dragging = true;
        /** @type {Element} */ (ev.target).setPointerCapture?.(ev.pointerId);
      }
      Object.assign(p, { x, y });
      on.panZ(dx, dy);
    }
    hide();
    ev.preventDefault();
    return true;
  }

  /** @param {PointerEvent} ev */
  function onPointer(ev) {
    const touch = isTouch(ev);
    const { x, y } = at(ev);
    last = { x, y };
    if (zGesture(ev, x, y)) return;
    // Pressing on the pair's diamond (a design one can place) picks it up; dragging places it.
    if (ev.type === 'pointerdown' && ev.button === 0 && on.onHandle(x, y, touch ? REACH.touch : REACH.mouse)) {
      placing = ev.pointerId;
      on.holdPoles(true);
      canvas.setPointerCapture(ev.pointerId);
      hide();
      canvas.classList.add('placing');
      ev.preventDefault();
      return;
    }
    if (placing === ev.pointerId) {
      if (ev.type === 'pointermove') on.placeAt(x, y);
      return;
    }
    // Pressing on an error plot looks back at that instant; dragging moves through time.
    if (ev.type === 'pointerdown' && ev.button === 0) {
      const t = on.timeAt(x, y);
      if (t !== undefined) {
        scrubbing = ev.pointerId;
        canvas.setPointerCapture(ev.pointerId);
        hide();
        on.scrubTo(t);
        ev.preventDefault();
        return;
      }
    }
    if (scrubbing === ev.pointerId) {
      if (ev.type === 'pointermove') {
        const t = on.timeAt(x, y);
        if (t !== undefined) on.scrubTo(t);
      }
      return;
    }
    // Dragging on ρ(δ) picks δ, and on a map (δ, α), as the pointer moves.
    if (ev.type === 'pointermove' && ev.buttons === 1) {
      const drag = on.probe(x, y, 0);
      if (drag && (picksDelta(drag) || drag.kind === 'map')) {
        if (picksDelta(drag)) on.pickDelta(drag.delta);
        else on.pick(drag.map, drag.delta, drag.alpha);
        show(on.probe(x, y, 0) ?? drag);
        return;
      }
    }
    if (ev.type === 'pointermove' && (touch || pinned)) return;
    const probe = on.probe(x, y, touch ? REACH.touch : REACH.mouse);
    if (probe && (probe.kind === 'pole' || !touch)) {
      show(probe);
      pinned = touch && ev.type === 'pointerdown' && probe.kind === 'pole';
    } else {
      hide();
    }
  }

  /** @param {PointerEvent} ev */
  function onClick(ev) {
    const { x, y } = at(ev);
    const probe = on.probe(x, y, 0);
    if (!probe || (probe.kind !== 'map' && !picksDelta(probe))) return;
    if (probe.kind === 'map') on.pick(probe.map, probe.delta, probe.alpha);
    else on.pickDelta(probe.delta);
    const mouse = !ev.pointerType || ev.pointerType === 'mouse';
    if (mouse) show(on.probe(x, y, 0) ?? probe);
    else hide();
  }

  const endScrub = (/** @type {PointerEvent} */ ev) => {
    if (scrubbing === ev.pointerId) scrubbing = null;
    if (placing === ev.pointerId) {
      placing = null;
      on.holdPoles(false);
      canvas.classList.remove('placing');
    }
    zPointers.delete(ev.pointerId);
  };
  /** The wheel over the z-plane zooms about the pointer (elsewhere the page scrolls). @param {WheelEvent} ev */
  const onWheel = (ev) => {
    if (ev.ctrlKey && ev.deltaMode === 0 && Math.abs(ev.deltaY) < 1) return;
    const { x, y } = at(ev);
    if (on.zoomZ(x, y, wheelFactor(ev))) {
      ev.preventDefault();
      hide();
    }
  };
  /** Listens on `el` (the canvas, and the z-plane's region over it, which takes touch gestures). @param {HTMLElement} el */
  function attach(el) {
    el.addEventListener('pointermove', onPointer);
    el.addEventListener('pointerdown', onPointer);
    el.addEventListener('pointerup', endScrub);
    el.addEventListener('pointercancel', endScrub);
    el.addEventListener('pointerleave', (ev) => {
      if (ev.pointerType === 'mouse') last = null;
      if (ev.pointerType === 'mouse' && !pinned) hide();
    });
    el.addEventListener('wheel', onWheel, { passive: false });
  }
  attach(canvas);
  canvas.addEventListener('click', onClick);
  // A finger on the pair's diamond drags it: the page must not scroll instead (a pointer event's
  // preventDefault cannot stop that; a touchstart's can).
  canvas.addEventListener('touchstart', (ev) => {
    const t = ev.touches[0];
    if (ev.touches.length === 1 && t) {
      const { x, y } = at(t);
      if (on.onHandle(x, y, REACH.touch)) ev.preventDefault();
    }
  }, { passive: false });
  document.addEventListener('pointerdown', (ev) => {
    if (pinned && ev.target !== canvas && !(ev.target instanceof Element && ev.target.closest('.panel-focus'))) hide();
  });
  return { hide, attach, last: () => last };
}

/** True for a readout over δ alone (ρ(δ), the sensor study's panels): a click or a drag runs at its δ.
 * @param {{ kind: string }} probe */
function picksDelta(probe) {
  return probe.kind === 'rho' || probe.kind === 'study';
}
