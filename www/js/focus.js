// The figures by keyboard: a focusable region over each panel whose description has a `region`
// (the maps, the pole plot or z-plane, ρ(δ)), announced with its words. As the region's `keys`
// say: on a map the arrow keys move the running point (δ across, α up) and Enter runs with that
// map's feedback; on the pole plot they step from pole to pole and read each one out; on ρ(δ) they
// step δ; on the z-plane + and − zoom, 0 shows the whole circle, P the flexible pair, and Shift
// with the arrows pans. What a key does to the settings (and to the view) is the session's and the
// renderer's; this routes keys and places regions.

import { byId, make, setText } from './dom.js';

/** Arrow keys as (across, up) steps (pure). @param {string} key */
export function arrowSteps(key) {
  return { ArrowRight: [1, 0], ArrowLeft: [-1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1] }[key] ?? null;
}

/** What a key does to the z-plane's view (pure): a zoom factor, a pan (fractions of the panel), a
 * named view, or null. @param {{ key: string, shiftKey?: boolean }} ev */
export function zKey(ev) {
  if (ev.key === '+' || ev.key === '=') return { zoom: 1.5 };
  if (ev.key === '-' || ev.key === '_' || ev.key === '\u2212') return { zoom: 1 / 1.5 };
  if (ev.key === '0') return { view: 'whole' };
  if (ev.key === 'p' || ev.key === 'P') return { view: 'pair' };
  const steps = ev.shiftKey ? arrowSteps(ev.key) : null;
  return steps ? { pan: steps } : null;
}

/**
 * @param {{ stepOnMap: (side: string, d: number, a: number) => void, enterMap: (side: string) => void,
 *   stepDelta: (d: number) => void, probe: (x: number, y: number) => any, showTip: (p: any) => void,
 *   hideTip: () => void, zKey: (action: any, panel: any) => void, attachZ: (el: HTMLElement) => void }} on
 */
export function createFocus(on) {
  const layer = byId('focus-layer');
  const said = byId('figure-said');
  /** @type {Map<string, HTMLElement>} */
  const regions = new Map();
  /** @type {any[]} */
  let poles = [];
  /** The panels as last described, by id. @type {Map<string, any>} */
  const panels = new Map();
  let poleIndex = 0;

  /** A focusable region over panel `p`. @param {any} p */
  function region(p) {
    let r = regions.get(p.id);
    if (!r) {
      const el = make('div', { class: 'panel-focus', tabindex: '0', role: 'group', 'aria-label': p.region.label });
      el.addEventListener('keydown', (ev) => onKey(p.id, ev));
      el.addEventListener('blur', on.hideTip);
      // The z-plane's region takes the pointer too: touch gestures there pan and pinch the plane.
      if (p.region.keys === 'zplane') {
        el.classList.add('takes-pointer');
        on.attachZ(el);
      }
      layer.append(el);
      regions.set(p.id, el);
      r = el;
    }
    Object.assign(r.style, { left: `${p.x}px`, top: `${p.y}px`, width: `${p.width}px`, height: `${p.height}px` });
    return r;
  }

  /** What the keys do on the panel `id`, as its description says. @param {string} id @param {KeyboardEvent} ev */
  function onKey(id, ev) {
    const region = panels.get(id)?.region;
    if (!region) return;
    const z = region.keys === 'zplane' && !ev.ctrlKey && !ev.metaKey && !ev.altKey ? zKey(ev) : null;
    if (z) {
      on.zKey(z, panels.get(id));
      ev.preventDefault();
      return;
    }
    const steps = arrowSteps(ev.key);
    if (region.keys === 'map') {
      if (steps) on.stepOnMap(region.map, steps[0], steps[1]);
      else if (ev.key === 'Enter') on.enterMap(region.map);
      else return;
    } else if (region.keys === 'delta') {
      if (!steps || steps[0] === 0) return;
      on.stepDelta(steps[0]);
    } else {
      if (!steps || poles.length === 0) return;
      poleIndex = (poleIndex + steps[0] - steps[1] + poles.length) % poles.length;
      readPole();
    }
    ev.preventDefault();
  }

  function readPole() {
    const p = poles[poleIndex];
    const probe = p && on.probe(p.x, p.y);
    if (!probe) return;
    on.showTip(probe);
    setText(said, `${probe.title}. ${probe.lines.map((/** @type {any} */ l) => l.text).join('. ')}`);
  }

  /** Places the regions for a new description of the frame. @param {any} layout */
  function update(layout) {
    const ids = new Set();
    for (const p of layout.panels) {
      panels.set(p.id, p);
      if (!p.region) continue;
      ids.add(p.id);
      region(p).hidden = false;
    }
    for (const [id, el] of regions) if (!ids.has(id)) el.hidden = true;
    poles = (layout.poles ?? []).filter((/** @type {any} */ q) => q.in_view && q.x != null && q.keyboard_stop);
    poleIndex = Math.min(poleIndex, Math.max(0, poles.length - 1));
  }

  return { update };
}
