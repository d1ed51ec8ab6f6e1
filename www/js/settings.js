// Changes go to the session: the controls built from the schema (and the embed's strip of them),
// the intro/full switch, the feedback switches, the preset and arm menus, α1 and α2 linked. Every
// change runs through `change`: the session takes it (or the page says why not), and the controls,
// the page's mode and the URL follow the session whatever happened; then the picture (`changed`).

import { byId, make } from './dom.js';
import { buildControls } from './controls.js';
import { createEmbedStrip } from './embed.js';
import { writeUrl } from './url.js';
import { PAUSED_NOTE } from './transport.js';

/** @typedef {import('./flexarm.js').Page} Page */
/** @typedef {import('./wasm.js').Wasm} Wasm */
/** @typedef {import('./controls.js').ControlValue} ControlValue */
/** @typedef {ReturnType<typeof import('./store.js').createStore>} Store */

/** The key a control's change goes to (its slider, its box, its steps): with α linked, either α
 * moves both (pure).
 * @param {string} key @param {boolean} linkAlpha */
export function linkedKey(key, linkAlpha) {
  return linkAlpha && (key === 'alpha1' || key === 'alpha2') ? 'alpha' : key;
}

/** The whole page for an embed's state: the same state, not embedded (pure).
 * @param {string} pathname @param {string} state */
export function wholePageLink(pathname, state) {
  return `${pathname}?${state.replace(/(^|&)embed=1/, '')}`;
}

/**
 * @param {{ wasm: Wasm, session: Page, store: Store, guard: <T>(what: string, fn: () => T, fallback?: T) => T | undefined,
 *   reset: () => void, synced: (value: (key: string) => ControlValue | undefined) => void, changed: () => void }} on
 *   `synced`: the other views of the session's values (the presentation bar); `changed`: the picture follows a change
 */
export function createSettings({ wasm, session, store, guard, reset, synced, changed }) {
  const controls = buildControls(wasm.schema(), {
    // One path for the slider and its exact box: with α linked, either moves both.
    onSet: (key, text) => change(() => session.set(linked(key), text)),
    onPosition: (key, f) => change(() => session.setPosition(linked(key), f)),
    onStep: (key, steps) => change(() => session.stepValue(linked(key), steps)),
  });
  // The embed's strip: the controls `strip=` names, its δ and α sliders built like the page's.
  const embedStrip = createEmbedStrip(wasm.schema(), {
    onSet: (key, text) => change(() => session.set(key, text)),
    onPosition: (key, f) => change(() => session.setPosition(key, f)),
    onStep: (key, steps) => change(() => session.stepValue(key, steps)),
    reset: () => reset(),
  });
  /** @param {string} key */
  const linked = (key) => linkedKey(key, store.get().linkAlpha);

  /** Runs a change; the controls, the URL and the picture follow the session whatever happened.
   * @param {() => void} fn */
  function change(fn) {
    const ok = guard('Applying the settings failed', () => (fn(), true), false);
    const now = ok && !store.get().playing ? session.status() : null;
    if (now && now.timeline.live && now.note === '') session.setNote(PAUSED_NOTE);
    sync();
    writeUrl(session.stateString());
    changed();
  }

  /** The controls, the intro's feedback switch and the page's mode show the session's values. */
  function sync() {
    const values = session.controls();
    controls.sync(values);
    embedStrip.sync(values);
    const value = (/** @type {string} */ key) => values.find((v) => v.key === key)?.value;
    synced((key) => values.find((v) => v.key === key));
    const full = value('mode') === 'full';
    if (document.body.dataset.mode !== (full ? 'full' : 'intro')) document.body.dataset.mode = full ? 'full' : 'intro';
    byId('mode-intro').setAttribute('aria-pressed', String(!full));
    byId('mode-full').setAttribute('aria-pressed', String(full));
    // Unequal α1 and α2 (a link, a lesson step, a preset) are not linked: the box says so.
    const link = /** @type {HTMLInputElement} */ (byId('link-alpha'));
    if (link.checked && value('alpha1') !== value('alpha2')) {
      link.checked = false;
      store.dispatch({ type: 'link-alpha', value: false });
    }
    /** @type {HTMLInputElement} */ (byId('pf-toggle')).checked = value('pf') !== 'off';
    /** @type {HTMLInputElement} */ (byId('embed-pf')).checked = value('pf') !== 'off';
    const embed = value('embed') === '1';
    if (document.body.dataset.embed !== String(embed)) document.body.dataset.embed = String(embed);
    // The whole page, for the reader who wants more.
    if (embed) /** @type {HTMLAnchorElement} */ (byId('embed-open')).href = wholePageLink(window.location.pathname, session.stateString());
  }
  wireSwitches(wasm, session, store, change);

  const link = /** @type {HTMLInputElement} */ (byId('link-alpha'));
  link.addEventListener('change', () => {
    store.dispatch({ type: 'link-alpha', value: link.checked });
    const a1 = session.controls().find((c) => c.key === 'alpha1');
    if (link.checked && a1) change(() => session.set('alpha', a1.value));
  });

  return {
    change,
    sync,
    /** The controls' fields (disabled when the simulation crashed). */
    controls,
    /** Unequal α1 and α2 are meant: the sliders move apart. */
    unlinkAlpha() {
      link.checked = false;
      store.dispatch({ type: 'link-alpha', value: false });
    },
  };
}

/**
 * The intro/full switch, the feedback switches (the intro's and the embed's), the preset and arm
 * menus.
 * @param {Wasm} wasm @param {Page} session @param {Store} store @param {(fn: () => void) => void} change
 */
function wireSwitches(wasm, session, store, change) {
  byId('mode-intro').addEventListener('click', () => change(() => session.set('mode', 'intro')));
  byId('mode-full').addEventListener('click', () => change(() => session.set('mode', 'full')));
  for (const id of ['pf-toggle', 'embed-pf']) {
    const box = /** @type {HTMLInputElement} */ (byId(id));
    box.addEventListener('change', () => change(() => session.set('pf', box.checked ? 'paper' : 'off')));
  }
  const presetSelect = /** @type {HTMLSelectElement} */ (byId('preset'));
  for (const p of wasm.presets()) presetSelect.append(make('option', { value: p.id, text: p.title }));
  // The arm: the paper's with one part changed (arm=ID), restarting from rest.
  const armSelect = /** @type {HTMLSelectElement} */ (byId('arm-preset'));
  for (const a of wasm.arms()) armSelect.append(make('option', { value: a.id, text: a.title }));
  armSelect.addEventListener('change', () => {
    if (armSelect.value) change(() => session.readState(`arm=${armSelect.value}`));
  });
  presetSelect.addEventListener('change', () => {
    if (presetSelect.value) change(() => session.applyPreset(presetSelect.value));
    store.dispatch({ type: 'play' });
  });
}
