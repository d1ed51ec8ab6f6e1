// HTML over the canvas: every text Rust placed (tick labels, axis and panel titles, notes, marks
// at points — `Renderer.layout().labels`: anchor, alignment, size), the time ticks moved with the
// scrolling window, and the tooltip. Nothing here decides where a text goes.

import { byId, make, setText } from './dom.js';

/** Time ticks closer than this to a plot's left edge are hidden (they would meet the y ticks). */
const EDGE_PX = 14;

/**
 * @typedef {{ value: number, text: string }} TickLabel
 * @typedef {{ id: string, x: number, y: number, width: number, height: number, x_label: string,
 *   y_label: string, title: string, note: string, x_range: number[], y_range: number[],
 *   x_labels: TickLabel[], y_labels: TickLabel[], x_scale: string, y_scale: string,
 *   scrolls: boolean, marks: { x: number, y: number, text: string }[] }} Panel
 * @typedef {{ panel: string, class: string, text: string, x: number, y: number, align: number[],
 *   size: number, time: number | null, width: number, full: string }} Label
 * @typedef {{ generation: number, panels: Panel[], mode: string, series: any[], poles: any[],
 *   spring_magnification: number, backend: string, labels: Label[],
 *   tabs: { id: string, label: string, selected: boolean }[] }} Layout
 */

/** The CSS transform that puts a label's alignment point on its anchor (pure). @param {Label} l @param {number} x */
export function placement(l, x = l.x) {
  return `translate(${x.toFixed(1)}px, ${l.y.toFixed(1)}px) translate(${(-100 * l.align[0]).toFixed(0)}%, ${(-100 * l.align[1]).toFixed(0)}%)`;
}

export function createOverlays() {
  const overlay = byId('axes-overlay');
  const spring = byId('spring-magnification');
  const tip = byId('plot-tip');
  const wrap = byId('canvas-wrap');
  /** Label elements, reused from one description to the next. @type {HTMLElement[]} */
  const pool = [];
  /** @type {{ span: HTMLElement, label: Label, panel: Panel }[]} */
  let scrolling = [];

  /** Places everything for a new description of the frame. @param {Layout} layout */
  function update(layout) {
    const panels = new Map(layout.panels.map((p) => [p.id, p]));
    while (pool.length < layout.labels.length) pool.push(overlay.appendChild(make('span')));
    scrolling = [];
    pool.forEach((span, i) => {
      const l = layout.labels[i];
      span.hidden = !l;
      if (!l) return;
      span.className = `label ${l.class}`;
      setText(span, l.text);
      // A label shortened to fit carries its whole text as its title.
      if (span.title !== l.full) span.title = l.full;
      span.style.fontSize = `${l.size}px`;
      span.dataset.estimate = l.width.toFixed(1);
      span.style.transform = placement(l);
      const panel = panels.get(l.panel);
      if (l.time != null && panel) scrolling.push({ span, label: l, panel });
    });
    setText(spring, `spring twist ×${Number(layout.spring_magnification.toPrecision(3))}`);
  }

  /** Moves the time labels with the scrolling window [start, end] (every frame). */
  function scroll(/** @type {number} */ start, /** @type {number} */ end) {
    for (const { span, label, panel: p } of scrolling) {
      const f = ((label.time ?? 0) - start) / (end - start || 1);
      span.hidden = f * p.width < EDGE_PX || f > 1.001;
      if (!span.hidden) span.style.transform = placement(label, p.x + f * p.width);
    }
  }

  /**
   * The tooltip near (x, y) (CSS px in the canvas).
   * @param {{ title: string, lines: { text: string, tone: string }[], x: number, y: number }} probe
   */
  function showTip(probe) {
    const lines = probe.lines.map((l) => make('span', { class: `tip-line${l.tone ? ` tip-${l.tone}` : ''}`, text: l.text }));
    tip.replaceChildren(make('strong', { text: probe.title }), ...lines);
    tip.hidden = false;
    const [w, h, W, H] = [tip.offsetWidth, tip.offsetHeight, wrap.clientWidth, wrap.clientHeight];
    let left = probe.x + 14;
    if (left + w > W - 4) left = probe.x - 14 - w;
    let top = probe.y - h - 10;
    if (top < 4) top = probe.y + 16;
    left = Math.min(Math.max(left, 4), Math.max(4, W - w - 4));
    top = Math.min(Math.max(top, 4), Math.max(4, H - h - 4));
    tip.style.transform = `translate(${left.toFixed(0)}px, ${top.toFixed(0)}px)`;
  }

  function hideTip() {
    if (!tip.hidden) tip.hidden = true;
  }

  return { update, scroll, showTip, hideTip };
}
