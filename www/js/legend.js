// The key under the figure: the entries and the colour bar come from Rust (the same palette and
// ramp the panels are drawn with, `Renderer.layout().legend`); this draws each glyph and text.

import { byId, make } from './dom.js';

/**
 * @typedef {{ glyph: string, color: string, dark: string, text: string, short: string }} Item
 * @typedef {{ name: string, label: string, stops: [number, string][], dark_stops: [number, string][],
 *   ticks: [number, string][] }} Scale
 * @typedef {{ title: string, items: Item[], scale: Scale | null }} Group
 */

const SVG = 'http://www.w3.org/2000/svg';

/** The SVG markup of a glyph, 14 × 14 (pure). @param {string} glyph @param {string} color */
export function glyphSvg(glyph, color) {
  const stroke = `stroke="${color}" stroke-width="2" fill="none"`;
  const shapes = {
    cross: `<path d="M3 3L11 11M11 3L3 11" ${stroke}/>`,
    plus: `<path d="M7 2V12M2 7H12" ${stroke}/>`,
    ring: `<circle cx="7" cy="7" r="4.5" ${stroke}/>`,
    diamond: `<path d="M7 2L12 7L7 12L2 7Z" ${stroke}/>`,
    halo: `<circle cx="7" cy="7" r="6" fill="${color}"/>`,
    line: `<path d="M1 7H13" ${stroke}/>`,
    dashed: `<path d="M1 7H13" ${stroke} stroke-dasharray="3 2"/>`,
    swatch: `<rect x="1" y="2" width="12" height="10" fill="${color}" stroke="var(--line)"/>`,
    chevron: `<path d="M10 2L4 7L10 12" ${stroke}/>`,
  };
  return `<svg xmlns="${SVG}" width="14" height="14" viewBox="0 0 14 14" aria-hidden="true">${shapes[/** @type {keyof typeof shapes} */ (glyph)] ?? ''}</svg>`;
}

/** A CSS gradient for the colour bar (pure), in the dark scheme's colours when `dark`.
 * @param {Scale} scale @param {boolean} [dark] */
export function scaleGradient(scale, dark = false) {
  const stops = dark ? scale.dark_stops : scale.stops;
  return `linear-gradient(to right, ${stops.map(([p, c]) => `${c} ${(100 * p).toFixed(1)}%`).join(', ')})`;
}

export function createLegend() {
  const key = byId('figure-key');
  let shown = '';
  // The key follows the system's colour scheme, as the canvas does (its colours come from Rust).
  const scheme = matchMedia('(prefers-color-scheme: dark)');
  /** @type {Group[]} */
  let last = [];
  scheme.addEventListener('change', () => render(last));

  /** @param {Group[]} groups */
  function render(groups) {
    last = groups;
    const dark = scheme.matches;
    const id = JSON.stringify(groups) + String(dark);
    if (id === shown) return;
    shown = id;
    key.hidden = groups.length === 0;
    key.replaceChildren(
      ...groups.map((g) => {
        const items = g.items.map((it) => {
          const glyph = make('span', { class: 'glyph' });
          glyph.innerHTML = glyphSvg(it.glyph, dark ? it.dark : it.color);
          // The compact key of presentation mode shows the name alone (CSS picks one).
          return make('li', {}, [glyph, make('span', { class: 'key-long', text: it.text }), make('span', { class: 'key-short', text: it.short })]);
        });
        const parts = [make('h3', { text: g.title }), make('ul', {}, items)];
        if (g.scale) {
          const bar = make('div', { class: 'rho-bar', role: 'img', 'aria-label': g.scale.label });
          bar.style.background = scaleGradient(g.scale, dark);
          const ticks = make('div', { class: 'rho-ticks', 'aria-hidden': 'true' }, g.scale.ticks.map(([p, t]) => {
            // The end labels ("≤ 0.8", "≥ 1.2") align with the bar's ends, inside its width: centred,
            // the first sat under the scale's name.
            const span = make('span', { text: t, class: p <= 0.001 ? 'at-start' : p >= 0.999 ? 'at-end' : '' });
            span.style.left = `${(100 * p).toFixed(1)}%`;
            return span;
          }));
          parts.push(make('div', { class: 'rho-scale' }, [make('span', { class: 'rho-name', text: g.scale.name }), make('div', { class: 'rho-track' }, [bar, ticks])]));
        }
        return make('section', { class: 'key-group' }, parts);
      }),
    );
  }

  return { render };
}
