// HTML over the canvas: axis titles and tick labels (their text and which ticks get one come from
// Rust; this places them), panel captions and notes, and the tooltip.

import { byId, make, setText } from './dom.js';
import { axisFraction, roomAbove } from './axes.js';

/** Height a title row needs above a panel, and of a row of tick labels below one, CSS px. */
const TITLE_ROW_PX = 19;
const TICK_ROW_PX = 19;

/**
 * @typedef {{ value: number, text: string }} TickLabel
 * @typedef {{ id: string, x: number, y: number, width: number, height: number, x_label: string,
 *   y_label: string, title: string, note: string, x_range: number[], y_range: number[],
 *   x_labels: TickLabel[], y_labels: TickLabel[], x_scale: string, y_scale: string,
 *   scrolls: boolean, marks: { x: number, y: number, text: string }[] }} Panel
 * @typedef {{ generation: number, panels: Panel[], mode: string, series: any[], poles: any[],
 *   spring_magnification: number, backend: string }} Layout
 */

export function createOverlays() {
  const overlay = byId('axes-overlay');
  const spring = byId('spring-magnification');
  const tip = byId('plot-tip');
  const wrap = byId('canvas-wrap');
  /** Label elements per panel id, reused from one description to the next. */
  const entries = new Map();
  /** @type {{ span: HTMLElement, panel: Panel, value: number }[]} */
  let scrolling = [];

  /** @param {string} cls */
  const label = (cls) => overlay.appendChild(make('span', { class: cls }));

  /** @param {string} id */
  function entry(id) {
    if (!entries.has(id)) {
      entries.set(id, { yTitle: label('axis-title y-title'), xTitle: label('axis-title x-title'), note: label('panel-note'), x: [], y: [], marks: [] });
    }
    return entries.get(id);
  }

  /** Shows `labels` in `pool`, each placed by `place(value)`. */
  function place(pool, labels, placeAt) {
    while (pool.length < labels.length) pool.push(label('tick'));
    pool.forEach((span, i) => {
      span.hidden = i >= labels.length;
      if (i < labels.length) {
        setText(span, labels[i].text);
        span.style.transform = placeAt(labels[i].value);
      }
    });
  }

  /** Places everything for a new description of the frame. @param {Layout} layout */
  function update(layout) {
    const seen = new Set();
    scrolling = [];
    layout.panels.forEach((p, i) => {
      seen.add(p.id);
      const e = entry(p.id);
      const xAt = (v) => p.x + axisFraction(v, p.x_range[0], p.x_range[1], p.x_scale) * p.width;
      const yAt = (v) => p.y + p.height - axisFraction(v, p.y_range[0], p.y_range[1], p.y_scale) * p.height;
      const below = p.y + p.height + 3;
      place(e.x, p.x_labels, (v) => `translate(${xAt(v).toFixed(1)}px, ${below.toFixed(1)}px) translateX(-50%)`);
      if (p.scrolls) e.x.slice(0, p.x_labels.length).forEach((span, k) => scrolling.push({ span, panel: p, value: p.x_labels[k].value }));
      place(e.y, p.y_labels, (v) => `translate(${(p.x - 5).toFixed(1)}px, ${yAt(v).toFixed(1)}px) translate(-100%, -50%)`);
      setText(e.note, p.note);
      e.note.hidden = !p.note;
      // Bottom centre: the smallest α, where little happens on the maps.
      e.note.style.transform = `translate(${(p.x + p.width / 2).toFixed(1)}px, ${(p.y + p.height - 2).toFixed(1)}px) translate(-50%, -100%)`;
      titles(e, p, roomAbove(layout.panels, i, TICK_ROW_PX) >= TITLE_ROW_PX);
      // Texts at points of the panel: beside the point, up and to the right.
      while (e.marks.length < p.marks.length) e.marks.push(label('panel-mark'));
      e.marks.forEach((span, k) => {
        const m = p.marks[k];
        span.hidden = !m;
        if (m) {
          setText(span, m.text);
          span.style.transform = `translate(${(m.x + 9).toFixed(1)}px, ${(m.y - 9).toFixed(1)}px) translateY(-100%)`;
        }
      });
    });
    for (const [id, e] of entries) {
      if (seen.has(id)) continue;
      for (const span of [e.xTitle, e.yTitle, e.note, ...e.x, ...e.y, ...e.marks]) span.hidden = true;
    }
    setText(spring, `spring twist ×${Number(layout.spring_magnification.toPrecision(3))}`);
  }

  /** Axis titles (or the caption of a panel without axes) above the panel, or inside it. */
  function titles(e, p, roomy) {
    const yTitle = p.y_label || p.title;
    setText(e.yTitle, yTitle);
    e.yTitle.hidden = !yTitle;
    setText(e.xTitle, p.x_label);
    e.xTitle.hidden = !p.x_label;
    e.yTitle.classList.toggle('inside', !roomy);
    e.xTitle.classList.toggle('inside', !roomy);
    if (!roomy) {
      e.yTitle.style.transform = `translate(${(p.x + 6).toFixed(1)}px, ${(p.y + 4).toFixed(1)}px)`;
      e.xTitle.style.transform = `translate(${(p.x + p.width - 6).toFixed(1)}px, ${(p.y + p.height - 4).toFixed(1)}px) translate(-100%, -100%)`;
      return;
    }
    // A header row: the y title on the left, the x title on the right.
    e.yTitle.style.transform = `translate(${p.x.toFixed(1)}px, ${(p.y - 2).toFixed(1)}px) translate(-0.25rem, -100%)`;
    e.xTitle.style.transform = `translate(${(p.x + p.width).toFixed(1)}px, ${(p.y - 2).toFixed(1)}px) translate(calc(-100% + 0.25rem), -100%)`;
    // A narrow panel (the pole plot): if the two would overlap, the x title goes inside the
    // bottom-left corner (the right half-plane, where trouble shows, stays clear).
    if (p.x_label && yTitle && e.yTitle.offsetWidth + e.xTitle.offsetWidth + 6 > p.width + 8) {
      e.xTitle.style.transform = `translate(${(p.x + 3).toFixed(1)}px, ${(p.y + p.height - 3).toFixed(1)}px) translateY(-100%)`;
      e.xTitle.classList.add('inside');
    }
  }

  /** Moves the time labels with the scrolling window [start, end] (every frame). */
  function scroll(start, end) {
    for (const { span, panel: p, value } of scrolling) {
      const f = (value - start) / (end - start || 1);
      span.hidden = f < -0.001 || f > 1.001;
      span.style.transform = `translate(${(p.x + f * p.width).toFixed(1)}px, ${(p.y + p.height + 3).toFixed(1)}px) translateX(-50%)`;
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
