// Everything the page says about the session besides the verdicts: the readouts, the note under
// the verdict, the maps' progress, which run is which, the preset in force.

import { byId, make, setText } from './dom.js';
import { createRunView } from './run.js';

/**
 * @typedef {import('./run.js').RunStatus} RunStatus
 * @typedef {{ runs: RunStatus[], note: string, preset: string,
 *   maps: { percent: number, done: boolean, text: string, points: number } }} Status
 * @typedef {{ run: string, color: string, style: string, pole_marker: string }} Series
 */

export function createStatus() {
  const runs = [createRunView('verdict'), createRunView('verdict-b')];
  const ro = {
    time: byId('ro-time'), error: byId('ro-error'), max_slew: byId('ro-max-slew'),
    max_after: byId('ro-max-after'), torque: byId('ro-torque'), a4: byId('ro-a4'),
  };
  const note = byId('run-note');
  const preset = /** @type {HTMLSelectElement} */ (byId('preset'));
  const bControls = byId('b-controls');
  const progress = byId('map-progress');
  const mapTime = byId('map-time');
  const legend = byId('pair-legend');
  let legendKey = '';

  /** @param {Status} s @param {{ mapsShown: boolean }} ui @param {number} now */
  function render(s, ui, now) {
    const [a, b] = s.runs;
    runs[0].render(a, now);
    for (const k of /** @type {(keyof typeof ro)[]} */ (Object.keys(ro))) setText(ro[k], a.readouts[k]);
    bControls.hidden = !b;
    if (b) runs[1].render(b, now);
    setText(note, s.note);
    note.hidden = s.note === '';
    if (preset.value !== s.preset) preset.value = s.preset;
    const pct = String(s.maps.percent);
    if (progress.getAttribute('aria-valuenow') !== pct) {
      progress.setAttribute('aria-valuenow', pct);
      /** @type {HTMLElement} */ (progress.firstElementChild).style.width = `${pct}%`;
    }
    progress.setAttribute('aria-valuetext', s.maps.done ? 'done' : `${pct} %`);
    progress.dataset.done = s.maps.done ? 'true' : 'false';
    setText(mapTime, !ui.mapsShown && !s.maps.done ? `paused at ${pct} % (maps hidden)` : s.maps.text);
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
