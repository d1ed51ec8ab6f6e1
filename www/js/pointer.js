// The pointer on the canvas: hovering (mouse) or tapping (touch, pen) a pole shows what it is,
// hovering a map shows ρ there, clicking a map runs at that point, dragging on ρ(δ) picks δ, and
// pressing and dragging on an error plot looks back at that instant. What lies under the pointer
// is the renderer's answer; this module only routes events.

import { byId } from './dom.js';

/** How far from a pole the pointer may be and still pick it, CSS px. */
const REACH = { mouse: 22, touch: 36 };

/**
 * @param {{ probe: (x: number, y: number, reach: number) => any, pick: (map: string, delta: number, alpha: number) => void,
 *   pickDelta: (delta: number) => void, showTip: (probe: any) => void, hideTip: () => void,
 *   timeAt: (x: number, y: number) => number | undefined, scrubTo: (t: number) => void }} on
 */
export function createPointer(on) {
  const canvas = byId('canvas');
  let pinned = false;
  /** The pointer that is dragging through time on an error plot, if any. */
  let scrubbing = /** @type {number | null} */ (null);

  /** @param {PointerEvent | MouseEvent} ev */
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
    canvas.classList.toggle('over-map', probe.kind === 'map' || probe.kind === 'rho');
  }

  /** @param {PointerEvent} ev */
  function onPointer(ev) {
    const touch = isTouch(ev);
    const { x, y } = at(ev);
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
      if (drag && (drag.kind === 'rho' || drag.kind === 'map')) {
        if (drag.kind === 'rho') on.pickDelta(drag.delta);
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
    if (!probe || (probe.kind !== 'map' && probe.kind !== 'rho')) return;
    if (probe.kind === 'map') on.pick(probe.map, probe.delta, probe.alpha);
    else on.pickDelta(probe.delta);
    const mouse = !ev.pointerType || ev.pointerType === 'mouse';
    if (mouse) show(on.probe(x, y, 0) ?? probe);
    else hide();
  }

  canvas.addEventListener('pointermove', onPointer);
  canvas.addEventListener('pointerdown', onPointer);
  const endScrub = (/** @type {PointerEvent} */ ev) => {
    if (scrubbing === ev.pointerId) scrubbing = null;
  };
  canvas.addEventListener('pointerup', endScrub);
  canvas.addEventListener('pointercancel', endScrub);
  canvas.addEventListener('pointerleave', (ev) => {
    if (ev.pointerType === 'mouse' && !pinned) hide();
  });
  canvas.addEventListener('click', onClick);
  document.addEventListener('pointerdown', (ev) => {
    if (pinned && ev.target !== canvas) hide();
  });
  return { hide };
}
