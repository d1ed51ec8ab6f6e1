// The tab bar of a narrow canvas: which views it offers and which it shows are the renderer's
// (Rust's layout) and the session's; this builds the bar and sends a choice to the session.

import { byId, make } from './dom.js';

/** @typedef {{ id: string, label: string, selected: boolean }} Tab */

/** The key a tab list's arrow keys move to (pure): -1 / +1 around the ring. */
export function nextTab(/** @type {number} */ i, /** @type {string} */ key, /** @type {number} */ n) {
  if (key === 'ArrowRight') return (i + 1) % n;
  if (key === 'ArrowLeft') return (i - 1 + n) % n;
  if (key === 'Home') return 0;
  if (key === 'End') return n - 1;
  return null;
}

/** @param {{ select: (id: string) => void }} on */
export function createTabs(on) {
  const bar = byId('view-tabs');
  let shown = '';

  /** @param {Tab[]} tabs */
  function render(tabs) {
    const key = JSON.stringify(tabs);
    if (key === shown) return;
    shown = key;
    bar.hidden = tabs.length === 0;
    const buttons = tabs.map((t, i) => {
      const b = make('button', {
        type: 'button', role: 'tab', id: `tab-${t.id}`, 'aria-selected': String(t.selected),
        'aria-controls': 'canvas-wrap', tabindex: t.selected ? '0' : '-1', text: t.label,
      });
      b.addEventListener('click', () => on.select(t.id));
      b.addEventListener('keydown', (ev) => {
        const j = nextTab(i, ev.key, tabs.length);
        if (j === null) return;
        ev.preventDefault();
        on.select(tabs[j].id);
        requestAnimationFrame(() => document.getElementById(`tab-${tabs[j].id}`)?.focus());
      });
      return b;
    });
    bar.replaceChildren(...buttons);
  }

  return { render };
}
