// "A real robot": the sensors' settings and the study of what bounds δ with them (Rust runs one
// simulated slew per call and writes every word and cell; this module only asks while the section
// is open and the study unfinished, and puts the answers on the page).

import { byId, setSymbols, setText } from './dom.js';

/**
 * @typedef {{ sensors: string, table: string[][], table_note: string, best_row: number | null, current_row: number,
 *   deltas: number[], summary: string[], prediction: string, done: boolean, progress: number }} SensorStudy
 */

/** Milliseconds of simulation per frame while the study fills. */
const BUDGET_MS = 40;

/**
 * @param {{ study: (runs: number) => SensorStudy | null, processor: () => string | null,
 *   setDelta: (delta: number) => void, drawn: () => boolean, touch: () => void }} on
 */
export function createSensors(on) {
  const details = /** @type {HTMLDetailsElement} */ (byId('sensors-details'));
  const summary = byId('sensors-summary');
  const table = /** @type {HTMLTableElement} */ (byId('sensors-table'));
  const findings = byId('sensors-summary-list');
  const prediction = byId('sensors-prediction');
  const note = byId('sensors-table-note');
  const progress = byId('sensors-progress');
  const processor = byId('sensors-processor');
  let scheduled = false;
  /** The settings changed since the processor was last timed. */
  let retime = true;

  /** @param {SensorStudy} s */
  function render(s) {
    setText(summary, s.sensors);
    const [head, ...rows] = s.table;
    const thead = document.createElement('thead');
    const hr = document.createElement('tr');
    for (const cell of head ?? []) {
      const th = document.createElement('th');
      th.scope = 'col';
      setSymbols(th, cell);
      hr.append(th);
    }
    thead.append(hr);
    const tbody = document.createElement('tbody');
    rows.forEach((row, i) => {
      const tr = document.createElement('tr');
      if (i === s.best_row) tr.classList.add('best');
      if (i === s.current_row) tr.classList.add('current');
      row.forEach((cell, j) => {
        const td = document.createElement(j === 0 ? 'th' : 'td');
        if (j === 0) {
          td.setAttribute('scope', 'row');
          // The row's δ is a button: choosing it runs the arm at that δ.
          const delta = s.deltas[i];
          const button = document.createElement('button');
          button.type = 'button';
          button.className = 'row-delta';
          button.textContent = cell;
          button.setAttribute('aria-label', `Run at δ = ${cell} s`);
          if (delta !== undefined) button.addEventListener('click', () => on.setDelta(delta));
          td.append(button);
        } else {
          setSymbols(td, cell);
        }
        tr.append(td);
      });
      tbody.append(tr);
    });
    table.replaceChildren(thead, tbody);
    findings.replaceChildren(...s.summary.map((line) => {
      const li = document.createElement('li');
      setSymbols(li, line);
      return li;
    }));
    setSymbols(prediction, s.prediction);
    setSymbols(note, s.table_note);
    setText(progress, s.done ? '' : `Simulating the slew at each δ: ${Math.round(100 * s.progress)} % done…`);
  }

  function tick() {
    scheduled = false;
    // The study runs while its section is open or the figure draws it (Rust says which).
    const drawn = on.drawn();
    if (!details.open && !drawn) return;
    if (retime && details.open) {
      retime = false;
      setText(processor, on.processor() ?? '');
    }
    // As many slews as fit in a share of the frame (each is one simulated slew of 3 s).
    const start = performance.now();
    let s = on.study(1);
    while (s && !s.done && performance.now() - start < BUDGET_MS) s = on.study(1);
    if (!s) return;
    render(s);
    if (drawn) on.touch();
    if (!s.done) schedule();
  }

  function schedule() {
    if (scheduled) return;
    scheduled = true;
    requestAnimationFrame(tick);
  }

  details.addEventListener('toggle', () => {
    if (details.open) schedule();
  });

  return {
    /** The settings changed: the study (if shown) starts over, the summary follows. */
    changed() {
      retime = true;
      const s = details.open || on.drawn() ? null : on.study(0);
      if (s) setText(summary, s.sensors);
      schedule();
    },
  };
}
