// The controls, built from the schema the wasm gives (labels, units, ranges, help), wired to the
// session through `onSet` / `onPosition`. The page decides where a control goes (a placeholder
// `[data-param=key]`); the schema decides what it is.

import { make, setSymbols, setText } from './dom.js';

/** Slider resolution: positions 0…STEPS map onto the control's span. */
export const STEPS = 1000;

/** Steps a key moves a slider by (Home and End keep their own meaning: the span's ends). */
export const KEY_STEPS = Object.freeze({ ArrowRight: 1, ArrowUp: 1, ArrowLeft: -1, ArrowDown: -1, PageUp: 3, PageDown: -3 });

/** The element id of a parameter's input: `b_pf` → `b-pf`. @param {string} key */
export const inputId = (key) => key.replace(/_/g, '-');

/**
 * @typedef {{ key: string, label: string, unit: string, help: string, kind: string,
 *   scale?: string | null, control?: number[] | null, limits?: number[] | null, integer: boolean,
 *   options: string[][], default: string, allowed: string }} Param
 * @typedef {{ key: string, value: string, position?: number | null, text: string, shown?: boolean }} ControlValue
 */

/** A parameter's label, its symbol's subscript set as such (B_v1 → B<sub>v1</sub>). @param {Param} p @param {string} id */
function labelOf(p, id) {
  const label = make('label', { for: id, title: p.help });
  setSymbols(label, p.label);
  return label;
}

/**
 * Builds the field for one parameter inside `slot`; its elements' ids start with `prefix`.
 * @param {Param} p @param {HTMLElement} slot
 * @param {{ onSet: (key: string, text: string) => void, onPosition: (key: string, f: number) => void,
 *   onStep: (key: string, steps: number) => void }} on
 * @param {string} prefix
 */
function buildField(p, slot, on, prefix) {
  const id = `${prefix}${inputId(p.key)}`;
  slot.classList.add('field');
  if (p.kind === 'switch') {
    slot.classList.add('check');
    const input = /** @type {HTMLInputElement} */ (make('input', { type: 'checkbox', id }));
    input.addEventListener('change', () => on.onSet(p.key, input.checked ? '1' : '0'));
    slot.append(input, labelOf(p, id));
    return { input, output: null, exact: null };
  }
  const label = labelOf(p, id);
  if (p.kind === 'choice') {
    const select = /** @type {HTMLSelectElement} */ (make('select', { id }));
    for (const [value, text] of p.options) select.append(make('option', { value, text }));
    select.addEventListener('change', () => on.onSet(p.key, select.value));
    slot.append(label, select);
    return { input: select, output: null, exact: null };
  }
  const helpId = `${id}-help`;
  const output = make('output', { id: `${id}-value`, for: id, class: 'value' });
  const input = make('input', {
    type: 'range', id, min: '0', max: String(STEPS), step: '1', 'aria-describedby': helpId,
  });
  input.addEventListener('input', () => {
    // The slider moved: what was typed and not committed is dropped, and the field follows.
    delete exact.dataset.typing;
    on.onPosition(p.key, Number(/** @type {HTMLInputElement} */ (input).value) / STEPS);
  });
  // Arrow keys step through round values the session chooses (0.01 → 0.012 → 0.015 s), not
  // through slider positions that round back to the same value.
  input.addEventListener('keydown', (ev) => {
    const steps = KEY_STEPS[/** @type {KeyboardEvent} */ (ev).key];
    if (!steps) return;
    ev.preventDefault();
    delete exact.dataset.typing;
    on.onStep(p.key, steps);
  });
  const span = p.control ? `${p.allowed}${p.scale === 'log' ? ', logarithmic scale' : ''}` : p.allowed;
  // An exact value can be typed (within the parameter's limits, which may reach past the slider).
  const exact = /** @type {HTMLInputElement} */ (make('input', {
    type: 'number', id: `${id}-number`, class: 'exact', step: 'any', inputmode: 'decimal',
    'aria-label': `${p.label}: exact value${p.unit ? ` in ${p.unit}` : ''}`,
  }));
  if (p.limits) {
    if (Number.isFinite(p.limits[0])) exact.min = String(p.limits[0]);
    if (Number.isFinite(p.limits[1])) exact.max = String(p.limits[1]);
  }
  // Only a value the user typed is set (a change event can come after the slider has moved on).
  exact.addEventListener('input', () => { exact.dataset.typing = '1'; });
  exact.addEventListener('change', () => {
    const typed = exact.dataset.typing === '1';
    delete exact.dataset.typing;
    if (typed && exact.value.trim() !== '') on.onSet(p.key, exact.value.trim());
  });
  const exactRow = make('span', { class: 'exact-row' }, [exact, make('span', { class: 'unit', text: p.unit, 'aria-hidden': 'true' })]);
  slot.append(label, output, input, make('small', { id: helpId, class: 'help', text: span }), exactRow);
  return { input, output, exact };
}

/**
 * Builds every control whose placeholder the page has: `[data-param=key]`, or another attribute
 * for a second set of the same controls (the embed's strip: `data-strip`, ids prefixed `embed-`).
 * @param {Param[]} schema
 * @param {{ onSet: (key: string, text: string) => void, onPosition: (key: string, f: number) => void,
 *   onStep: (key: string, steps: number) => void }} on
 * @param {{ attribute?: string, prefix?: string }} [where]
 */
export function buildControls(schema, on, { attribute = 'data-param', prefix = '' } = {}) {
  /** @type {Map<string, { input: HTMLElement, output: HTMLElement | null, exact: HTMLInputElement | null, slot: HTMLElement }>} */
  const fields = new Map();
  for (const p of schema) {
    const slot = /** @type {HTMLElement | null} */ (document.querySelector(`[${attribute}="${p.key}"]`));
    if (slot && !fields.has(p.key)) fields.set(p.key, { ...buildField(p, slot, on, prefix), slot });
  }
  return {
    /** Shows the session's values. @param {ControlValue[]} values */
    sync(values) {
      for (const v of values) {
        const f = fields.get(v.key);
        if (!f) continue;
        // A setting that does nothing as the others are (the session says which) is not shown
        // (data-idle, apart from `hidden`, which the embed's strip uses for its own choice).
        f.slot.toggleAttribute('data-idle', v.shown === false);
        const input = /** @type {HTMLInputElement} */ (f.input);
        if (input.type === 'checkbox') {
          input.checked = v.value === '1';
        } else if (input.type === 'range') {
          const pos = String(Math.round((v.position ?? 0) * STEPS));
          if (input.value !== pos) input.value = pos;
          if (f.output) setText(f.output, v.text);
          if (input.getAttribute('aria-valuetext') !== v.text) input.setAttribute('aria-valuetext', v.text);
          // The typed field shows the value as set, unless the user is typing in it (not yet committed).
          if (f.exact && f.exact.dataset.typing !== '1' && f.exact.value !== v.value) f.exact.value = v.value;
        } else if (input.value !== v.value) {
          input.value = v.value;
        }
      }
    },
    /** @param {boolean} enabled */
    setEnabled(enabled) {
      for (const f of fields.values()) {
        /** @type {HTMLInputElement} */ (f.input).disabled = !enabled;
        if (f.exact) f.exact.disabled = !enabled;
      }
    },
    /** @param {string} key */
    input: (key) => fields.get(key)?.input ?? null,
  };
}
