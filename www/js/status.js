// Everything the page says about the session besides the verdicts: the readouts, the note under
// the verdict, the maps' progress, which run is which, the preset in force.

import { byId, make, setText, setSymbols } from './dom.js';
import { createRunView } from './run.js';

/**
 * @typedef {import('./run.js').RunStatus} RunStatus
 * @typedef {{ runs: RunStatus[], note: string, preset: string, arm: string, showing: string, ghost: string,
 *   maps: { percent: number, done: boolean, text: string, points: number, shown: boolean, title: string },
 *   windows: { text: string, windows: number[][], bands: number[][] } | null,
 *   timeline: import('./timeline.js').TimelineStatus, lesson: import('./lesson.js').LessonStatus | null,
 *   story: Record<string, string> | null, hidden: { text: string, controls: string[] } | null }} Status
 * @typedef {{ run: string, color: string, style: string, pole_marker: string }} Series
 */

/** A CSS gradient for a slider track with `bands` (positions 0–1) in `band`, elsewhere `rest` (pure). */
export function bandGradient(bands, band, rest) {
  const stops = [`${rest} 0%`];
  for (const [a, b] of bands) {
    const [pa, pb] = [(100 * a).toFixed(2), (100 * b).toFixed(2)];
    stops.push(`${rest} ${pa}%`, `${band} ${pa}%`, `${band} ${pb}%`, `${rest} ${pb}%`);
  }
  stops.push(`${rest} 100%`);
  return `linear-gradient(to right, ${stops.join(', ')})`;
}

/** The text of live number `key` from a status' story: "—" while it is missing (pure).
 * @param {Record<string, string> | null} story @param {string} key */
export function liveText(story, key) {
  return story?.[key] ?? '—';
}

/** Colours of the δ slider's track: the stable windows, and the rest (the stylesheet's, so the
 * dark scheme has its own). */
const TRACK = { band: 'var(--band-stable)', rest: 'var(--band-rest)' };

export function createStatus() {
  const runs = [createRunView('verdict', 'ro-growth'), createRunView('verdict-b', 'ro-b-growth')];
  // The observed growth is written by the run's view, together with its observation line.
  const keys = /** @type {const} */ (['time', 'error', 'max_slew', 'max_after', 'torque', 'a4']);
  const cell = (/** @type {string} */ run, /** @type {string} */ k) => byId(`ro-${run}${k.replace('_', '-')}`);
  const ro = [Object.fromEntries(keys.map((k) => [k, cell('', k)])), Object.fromEntries(keys.map((k) => [k, cell('b-', k)]))];
  const readouts = byId('readouts');
  const announce = byId('verdict-announce');
  const windowsText = byId('delta-windows');
  const ghost = byId('ghost-caption');
  let announced = '';
  let bandsKey = '';
  const note = byId('run-note');
  const preset = /** @type {HTMLSelectElement} */ (byId('preset'));
  const arm = /** @type {HTMLSelectElement} */ (byId('arm-preset'));
  const bControls = byId('b-controls');
  const progress = byId('map-progress');
  const mapTime = byId('map-time');
  const mapTitle = byId('map-row-title');
  const legend = byId('pair-legend');
  const showing = byId('showing');
  const mapRow = byId('map-row');
  let legendKey = '';

  // The explanation's numbers: each `data-live` element shows the story's entry of that name.
  const live = /** @type {HTMLElement[]} */ ([...document.querySelectorAll('[data-live]')]);
  const math = /** @type {HTMLElement[]} */ ([...document.querySelectorAll('[data-math]')]);
  /** @type {Map<HTMLElement, string>} */
  const shownMath = new Map();
  const strip = byId('verdict-strip');
  const embedVerdict = byId('embed-verdict');
  /** @param {Status} s @param {number} now */
  function render(s, now) {
    setSymbols(showing, s.showing);
    // The phone's strip over the figure: the same verdict, in a line.
    if (strip.dataset.verdict !== s.runs[0].verdict) strip.dataset.verdict = s.runs[0].verdict;
    setText(byId('strip-word'), s.runs[0].headline);
    setText(byId('strip-detail'), s.runs[0].detail);
    // The embed's strip is narrow: the short form, the whole sentence on hover.
    setText(embedVerdict, s.runs[0].short);
    if (embedVerdict.title !== `${s.runs[0].headline}: ${s.runs[0].detail}`) embedVerdict.title = `${s.runs[0].headline}: ${s.runs[0].detail}`;
    const [a, b] = s.runs;
    runs[0].render(a, now);
    bControls.hidden = !b;
    if (b) runs[1].render(b, now);
    readouts.classList.toggle('pair', Boolean(b));
    s.runs.forEach((r, i) => keys.forEach((k) => setText(ro[i][k], r.readouts[k])));
    // Screen readers hear a verdict once, when it or the settings it is about change (a new δ
    // with the same verdict word is news too: its ρ differs).
    const verdicts = s.runs.map((r) => `${r.run}:${r.verdict}:${r.rho}:${r.settings}`).join(' ');
    if (verdicts !== announced) {
      announced = verdicts;
      setText(announce, s.runs.map((r) => r.announce).join(' '));
    }
    setText(ghost, s.ghost);
    ghost.hidden = !s.ghost;
    renderWindows(s.windows);
    setText(note, s.note);
    note.hidden = s.note === '';
    if (preset.value !== s.preset) preset.value = s.preset;
    if (arm.value !== s.arm) arm.value = s.arm;
    const pct = String(s.maps.percent);
    if (progress.getAttribute('aria-valuenow') !== pct) {
      progress.setAttribute('aria-valuenow', pct);
      /** @type {HTMLElement} */ (progress.firstElementChild).style.width = `${pct}%`;
    }
    progress.setAttribute('aria-valuetext', s.maps.done ? 'done' : `${pct} %`);
    progress.dataset.done = s.maps.done ? 'true' : 'false';
    setText(mapTime, s.maps.text);
    setText(mapTitle, s.maps.title);
    mapRow.hidden = !s.maps.shown;
    for (const node of live) setSymbols(node, liveText(s.story, node.dataset.live ?? ''));
    // The equations: MathML the story writes (from Rust's own numbers, no user text in them).
    for (const node of math) {
      const html = s.story?.[`math_${node.dataset.math}`] ?? '';
      if (shownMath.get(node) !== html) {
        shownMath.set(node, html);
        node.innerHTML = html;
      }
    }
  }

  /** The stable windows of δ: in words under the slider, and as bands on its track (none while
   * they are not known, or while a lesson step keeps them hidden). */
  function renderWindows(/** @type {Status['windows']} */ w) {
    windowsText.hidden = !w;
    if (w) setSymbols(windowsText, w.text);
    const slider = /** @type {HTMLInputElement | null} */ (document.getElementById('delta'));
    const key = w ? JSON.stringify(w.bands) : '';
    if (!slider || key === bandsKey) return;
    bandsKey = key;
    slider.classList.toggle('banded', Boolean(w));
    if (!w) {
      delete slider.dataset.bands;
      return;
    }
    slider.style.setProperty('--bands', bandGradient(w.bands, TRACK.band, TRACK.rest));
    slider.dataset.bands = w.bands.map(([a, b]) => `${a.toFixed(4)}-${b.toFixed(4)}`).join(' ');
  }

  /** Which line is which when two runs are compared. @param {Status} s @param {Series[]} series */
  function renderLegend(s, series) {
    if (s.runs.length < 2) {
      legend.hidden = true;
      legendKey = '';
      return;
    }
    const items = s.runs.map((r) => ({ r, style: series.find((x) => x.run === r.run) }));
    const key = JSON.stringify(items.map(({ r, style }) => [r.settings, style]));
    legend.hidden = false;
    if (key === legendKey) return;
    legendKey = key;
    legend.replaceChildren(
      make('span', { class: 'map-row-title', text: 'Lines:' }),
      ...items.map(({ r, style }) => {
        const swatch = make('span', { class: `swatch${style?.style === 'thin' ? ' thin' : ''}`, 'aria-hidden': 'true' });
        if (style) swatch.style.color = style.color;
        const marker = style?.pole_marker === 'plus' ? ', loop poles +' : style ? ', loop poles ×' : '';
        const own = r.run === 'A' ? ' (the controls above)' : '';
        return make('span', { class: 'legend-item', 'data-run': r.run }, [swatch, make('span', { text: `${r.run}: ${r.settings}${own}${marker}` })]);
      }),
    );
  }

  return { render, renderLegend, crashed: () => runs.forEach((r) => r.crashed()) };
}
