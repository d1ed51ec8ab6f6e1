// flexarm page: drives the wasm `Simulation`, the wgpu `Renderer`, the controls, the status and
// the URL state. One ES module, no dependencies.

// ---------------------------------------------------------------------------------------------
// Constants
// ---------------------------------------------------------------------------------------------

const SLIDER_STEPS = 1000; // every logarithmic slider runs 0..1000

const RANGES = {
  delta: { min: 0.002, max: 0.15, def: 0.01, digits: 3, allowed: '0.002–0.15 s' },
  alpha: { min: 0.1, max: 5, def: 2, digits: 3, allowed: '0.1–5 1/s' },
  speed: { min: 0.1, max: 4, def: 1, digits: 2, allowed: '0.1×–4×' },
};

const ENUMS = {
  pf: { values: ['off', 'paper', 'lq'], def: 'paper', field: 'preliminary_feedback' },
  friction: { values: ['continuous', 'held', 'off'], def: 'continuous', field: 'friction_compensation' },
  inner: { values: ['continuous', 'sampled'], def: 'continuous', field: 'inner_loop' },
};

/** Hold time of the repeated slew (there and back), s. */
const REPEAT_HOLD = 1.5;
/** The poke: T1, T2 (N m) for a duration (s). */
const POKE = { t1: 40, t2: 5, duration: 0.05 };
/** Longest wall-clock step one frame may advance, s. */
const MAX_WALL_DT = 0.1;
/** Metrics and readouts are refreshed at most this often, ms. */
const STATUS_INTERVAL_MS = 200;

const DIVERGENCE_REASONS = {
  error_bound: 'an error exceeded the bound',
  non_finite: 'the state became non-finite',
  newton_failure: "the predictor's Newton iteration failed",
};

// ---------------------------------------------------------------------------------------------
// DOM
// ---------------------------------------------------------------------------------------------

const $ = (id) => document.getElementById(id);

const el = {
  canvas: $('canvas'),
  canvasWrap: $('canvas-wrap'),
  overlay: $('axes-overlay'),
  loading: $('loading'),
  loadingText: $('loading-text'),
  canvasMessage: $('canvas-message'),
  backend: $('backend'),
  spring: $('spring-magnification'),
  error: $('error'),
  errorList: $('error-list'),
  errorDismiss: $('error-dismiss'),
  urlNotice: $('url-notice'),
  urlNoticeList: $('url-notice-list'),
  urlNoticeDismiss: $('url-notice-dismiss'),
  verdict: $('verdict'),
  verdictWord: $('verdict-word'),
  verdictDetail: $('verdict-detail'),
  verdictGrowth: $('verdict-growth'),
  verdictRho: $('verdict-rho'),
  runNote: $('run-note'),
  play: $('play'),
  step: $('step'),
  reset: $('reset'),
  poke: $('poke'),
  delta: $('delta'),
  deltaValue: $('delta-value'),
  alpha1: $('alpha1'),
  alpha1Value: $('alpha1-value'),
  alpha2: $('alpha2'),
  alpha2Value: $('alpha2-value'),
  linkAlpha: $('link-alpha'),
  pf: $('pf'),
  friction: $('friction'),
  inner: $('inner'),
  repeat: $('repeat'),
  preset: $('preset'),
  speed: $('speed'),
  speedValue: $('speed-value'),
  showTorque: $('show-torque'),
  exportCsv: $('export-csv'),
  roTime: $('ro-time'),
  roError: $('ro-error'),
  roMaxSlew: $('ro-max-slew'),
  roMaxAfter: $('ro-max-after'),
  roTorque: $('ro-torque'),
  roA4: $('ro-a4'),
  plotTip: $('plot-tip'),
  pairLegend: $('pair-legend'),
  mapRow: $('map-row'),
  mapProgress: $('map-progress'),
  mapTime: $('map-time'),
  mapHint: $('map-hint'),
  showPoles: $('show-poles'),
  showMap: $('show-map'),
  compare: $('compare'),
  bControls: $('b-controls'),
  verdictB: $('verdict-b'),
  verdictBWord: $('verdict-b-word'),
  verdictBDetail: $('verdict-b-detail'),
  verdictBRho: $('verdict-b-rho'),
  bPf: $('b-pf'),
  bDelta: $('b-delta'),
  bDeltaValue: $('b-delta-value'),
  bAlpha: $('b-alpha'),
  bAlphaValue: $('b-alpha-value'),
  explain: $('explain'),
};

// ---------------------------------------------------------------------------------------------
// State
// ---------------------------------------------------------------------------------------------

const state = {
  wasm: null, // the module namespace
  Simulation: null,
  sim: null,
  renderer: null,
  /** The configuration the controls describe (the simulation may still hold the previous one
   *  until its next sampling instant). */
  desired: null,
  speed: RANGES.speed.def,
  playing: true,
  presetId: '',
  finished: false,
  needsRender: true,
  lastTs: null,
  statusDue: 0,
  forceStatus: true,
  /** The in-force configuration has not been analysed yet. */
  analysisStale: true,
  analysis: null,
  /** ρ of the desired configuration (spectralRadius), shown until analysis() catches up. */
  rhoPreview: null,
  dead: false, // a Rust panic happened: stop calling into wasm
  rendererFailures: 0,
  layoutPending: true,
  lastVerdict: '',
  growthShownAt: 0,
  /** The renderer's latest layout() (panels, poles, series), for hover and clicks. */
  lastLayout: null,
  /** Which of the newer renderer options this renderer accepts (null: not tried yet). */
  rendererCaps: { show_poles: null, show_map: null },
  // Side by side: run B = A's configuration with its own PF, δ and α.
  compare: false,
  simB: null,
  /** B's own settings: {pf, delta, alpha: [α1, α2]}. */
  b: null,
  /** JSON of the configuration last handed to B (to skip no-op changes). */
  appliedB: '',
  finishedB: false,
  rhoPreviewB: null,
  /** Run B's settings from the URL (applied once the simulation exists). */
  urlB: null,
};

// ---------------------------------------------------------------------------------------------
// Small helpers
// ---------------------------------------------------------------------------------------------

const clamp = (v, lo, hi) => Math.min(hi, Math.max(lo, v));

function messageOf(e) {
  if (e instanceof Error) return e.message || String(e);
  if (typeof e === 'string') return e;
  try {
    return JSON.stringify(e);
  } catch {
    return String(e);
  }
}

/** Sets an element's text only when it changed (no DOM churn, no screen-reader chatter). */
function setText(node, text) {
  if (node.textContent !== text) node.textContent = text;
}

/** Real minus sign for negative numbers. */
const minus = (s) => (s.startsWith('-') ? '−' + s.slice(1) : s);

/** 3.34e-4 (scientific notation, `digits` significant digits). */
function sci(v, digits = 3) {
  if (v == null || !Number.isFinite(v)) return '—';
  if (v === 0) return '0';
  return minus(v.toExponential(digits - 1).replace('e+', 'e'));
}

/** `digits` significant digits, without exponent for ordinary magnitudes. */
function sig(v, digits = 3) {
  if (v == null || !Number.isFinite(v)) return '—';
  const a = Math.abs(v);
  if (a !== 0 && (a < 1e-3 || a >= 1e6)) return sci(v, digits);
  return minus(v.toPrecision(digits));
}

function posFromValue(v, r) {
  return Math.round((Math.log(v / r.min) / Math.log(r.max / r.min)) * SLIDER_STEPS);
}

function valueFromPos(pos, r) {
  const raw = r.min * Math.pow(r.max / r.min, pos / SLIDER_STEPS);
  return clamp(Number(raw.toPrecision(r.digits)), r.min, r.max);
}

function formatDelta(v) {
  return `${v.toPrecision(3)} s`;
}

function formatAlpha(v) {
  return `${v.toPrecision(3)} 1/s`;
}

function formatSpeed(v) {
  return `${v < 1 ? v.toPrecision(2) : v.toFixed(1)}×`;
}

/** Shows a slider's value next to it and to assistive technology (the position is logarithmic). */
function showSliderValue(slider, output, text) {
  setText(output, text);
  if (slider.getAttribute('aria-valuetext') !== text) slider.setAttribute('aria-valuetext', text);
}

// ---------------------------------------------------------------------------------------------
// Errors
// ---------------------------------------------------------------------------------------------

let lastErrorText = '';
let lastErrorItem = null;
let lastErrorCount = 0;

function showError(text) {
  if (text === lastErrorText && lastErrorItem && lastErrorItem.isConnected) {
    lastErrorCount += 1;
    lastErrorItem.textContent = `${text} (×${lastErrorCount})`;
  } else {
    const li = document.createElement('li');
    li.textContent = text;
    el.errorList.appendChild(li);
    while (el.errorList.children.length > 8) el.errorList.firstElementChild.remove();
    lastErrorText = text;
    lastErrorItem = li;
    lastErrorCount = 1;
  }
  el.error.hidden = false;
}

function reportError(context, e) {
  const text = `${context}: ${messageOf(e)}`;
  console.warn(text);
  showError(text);
}

/** Calls `fn`, reporting anything it throws; returns `fallback` then. */
function guard(context, fn, fallback = undefined) {
  if (state.dead) return fallback;
  try {
    return fn();
  } catch (e) {
    reportError(context, e);
    return fallback;
  }
}

el.errorDismiss.addEventListener('click', () => {
  el.error.hidden = true;
  el.errorList.replaceChildren();
  lastErrorText = '';
  lastErrorItem = null;
});

el.urlNoticeDismiss.addEventListener('click', () => {
  el.urlNotice.hidden = true;
});

// A Rust panic: the wasm instance must not be used any more.
window.flexarmPanic = (msg) => {
  state.dead = true;
  state.playing = false;
  showError(`The simulation crashed (Rust panic) — reload the page to start again. ${messageOf(msg)}`);
  el.canvasMessage.replaceChildren();
  const strong = document.createElement('strong');
  strong.textContent = 'The simulation crashed.';
  const p = document.createElement('span');
  p.textContent = 'See the error message above; reload the page to start again.';
  el.canvasMessage.append(strong, p);
  el.canvasMessage.hidden = false;
  el.verdict.dataset.verdict = 'error';
  setText(el.verdictWord, 'crashed');
  setText(el.verdictDetail, 'reload the page');
  setText(el.verdictGrowth, '');
  setText(el.verdictRho, '');
  updatePlayButton();
  setControlsEnabled(false);
};

window.addEventListener('error', (ev) => {
  if (ev.error || ev.message) showError(`Unexpected error: ${messageOf(ev.error || ev.message)}`);
});
window.addEventListener('unhandledrejection', (ev) => {
  showError(`Unexpected error: ${messageOf(ev.reason)}`);
});

// ---------------------------------------------------------------------------------------------
// URL state
// ---------------------------------------------------------------------------------------------

/**
 * Reads the query string into a list of settings to apply and a list of notices for invalid
 * values. Values are validated against the same ranges the controls have.
 */
function parseUrl(search) {
  const params = new URLSearchParams(search);
  const out = { preset: null, delta: null, alpha1: null, alpha2: null, speed: null, repeat: null, enums: {},
    compare: null, bPf: null, bDelta: null, bAlpha: null };
  const invalid = [];

  const num = (name, range) => {
    if (!params.has(name)) return null;
    const raw = params.get(name);
    const v = raw.trim() === '' ? NaN : Number(raw);
    if (!Number.isFinite(v) || v < range.min * (1 - 1e-9) || v > range.max * (1 + 1e-9)) {
      invalid.push({ name, raw, allowed: range.allowed });
      return null;
    }
    return clamp(v, range.min, range.max);
  };

  out.delta = num('delta', RANGES.delta);
  out.alpha1 = num('alpha1', RANGES.alpha);
  out.alpha2 = num('alpha2', RANGES.alpha);
  out.speed = num('speed', RANGES.speed);

  for (const [name, spec] of Object.entries(ENUMS)) {
    if (!params.has(name)) continue;
    const raw = params.get(name);
    if (spec.values.includes(raw)) out.enums[name] = raw;
    else invalid.push({ name, raw, allowed: spec.values.join(' | ') });
  }

  if (params.has('repeat')) {
    const raw = params.get('repeat');
    if (raw === '1' || raw === 'true') out.repeat = true;
    else if (raw === '0' || raw === 'false') out.repeat = false;
    else invalid.push({ name: 'repeat', raw, allowed: '1 | 0' });
  }

  if (params.has('compare')) {
    const raw = params.get('compare');
    if (raw === '1' || raw === 'true') out.compare = true;
    else if (raw === '0' || raw === 'false') out.compare = false;
    else invalid.push({ name: 'compare', raw, allowed: '1 | 0' });
  }
  out.bDelta = num('b_delta', RANGES.delta);
  out.bAlpha = num('b_alpha', RANGES.alpha);
  if (params.has('b_pf')) {
    const raw = params.get('b_pf');
    if (ENUMS.pf.values.includes(raw)) out.bPf = raw;
    else invalid.push({ name: 'b_pf', raw, allowed: ENUMS.pf.values.join(' | ') });
  }

  if (params.has('preset')) out.preset = params.get('preset');
  return { out, invalid };
}

/** Writes every parameter into the query string (shareable link). */
function writeUrl() {
  const c = state.desired;
  if (!c) return;
  const p = new URLSearchParams();
  if (state.presetId) p.set('preset', state.presetId);
  p.set('delta', String(c.controller.sampling_period));
  p.set('alpha1', String(c.controller.alpha[0]));
  p.set('alpha2', String(c.controller.alpha[1]));
  p.set('pf', c.preliminary_feedback);
  p.set('friction', c.friction_compensation);
  p.set('inner', c.inner_loop);
  p.set('speed', String(state.speed));
  p.set('repeat', c.reference.repeat_hold == null ? '0' : '1');
  if (state.compare && state.b) {
    p.set('compare', '1');
    p.set('b_pf', state.b.pf);
    p.set('b_delta', String(state.b.delta));
    p.set('b_alpha', String(state.b.alpha[0]));
  }
  const query = `?${p.toString()}`;
  if (query !== window.location.search) {
    try {
      history.replaceState(null, '', `${window.location.pathname}${query}${window.location.hash}`);
    } catch (e) {
      // Some embedders forbid replaceState (e.g. file: URLs); the page works without it.
      console.warn('could not update the URL:', messageOf(e));
    }
  }
}

function showUrlNotices(lines) {
  if (lines.length === 0) return;
  el.urlNoticeList.replaceChildren(
    ...lines.map((line) => {
      const li = document.createElement('li');
      li.textContent = line;
      return li;
    }),
  );
  el.urlNotice.hidden = false;
}

// ---------------------------------------------------------------------------------------------
// Controls ⇄ configuration
// ---------------------------------------------------------------------------------------------

function syncControlsFromDesired() {
  const c = state.desired;
  const d = c.controller.sampling_period;
  const [a1, a2] = c.controller.alpha;
  el.delta.value = String(posFromValue(clamp(d, RANGES.delta.min, RANGES.delta.max), RANGES.delta));
  showSliderValue(el.delta, el.deltaValue, formatDelta(d));
  el.alpha1.value = String(posFromValue(clamp(a1, RANGES.alpha.min, RANGES.alpha.max), RANGES.alpha));
  el.alpha2.value = String(posFromValue(clamp(a2, RANGES.alpha.min, RANGES.alpha.max), RANGES.alpha));
  showSliderValue(el.alpha1, el.alpha1Value, formatAlpha(a1));
  showSliderValue(el.alpha2, el.alpha2Value, formatAlpha(a2));
  el.pf.value = c.preliminary_feedback;
  el.friction.value = c.friction_compensation;
  el.inner.value = c.inner_loop;
  el.repeat.checked = c.reference.repeat_hold != null;
  el.speed.value = String(posFromValue(state.speed, RANGES.speed));
  showSliderValue(el.speed, el.speedValue, formatSpeed(state.speed));
  el.preset.value = state.presetId;
}

/**
 * Hands the desired configuration to the simulation. It takes effect at the next sampling
 * instant; a diverged run (which cannot continue) restarts with it instead.
 */
function applyDesired({ reset = false, why = '' } = {}) {
  const sim = state.sim;
  if (!sim || state.dead) return;
  const wasFinished = guard('isFinished', () => sim.isFinished(), false);
  const ok = guard('Applying the settings failed', () => {
    sim.setConfig(state.desired);
    return true;
  }, false);
  if (!ok) {
    // Fall back to what the simulation holds so the controls never lie.
    const current = guard('config', () => sim.config(), null);
    if (current) {
      state.desired = current;
      syncControlsFromDesired();
    }
    return;
  }
  if (reset || wasFinished) {
    guard('Reset failed', () => sim.reset());
    state.finished = false;
    state.lastTs = null;
    if (wasFinished && !reset) {
      setRunNote('The previous run had diverged, so it restarted from rest with the new settings.');
    } else if (why) {
      setRunNote(why);
    } else {
      setRunNote('');
    }
  } else if (!state.playing) {
    setRunNote('Paused: the change takes effect at the next sampling instant (press Step or Play).');
  } else {
    setRunNote('');
  }
  state.analysisStale = true;
  state.rhoPreview = guard('spectralRadius', () => state.wasm.spectralRadius(state.desired), null);
  state.needsRender = true;
  state.forceStatus = true;
  hideTip();
  // B follows A's slew, friction compensation and inner loop; an explicit restart restarts both.
  if (state.compare) applyB({ reset });
  ensureMaps();
  writeUrl();
}

function setRunNote(text) {
  setText(el.runNote, text);
  el.runNote.hidden = text === '';
}

/** A manual change leaves the preset. */
function leavePreset() {
  if (state.presetId !== '') {
    state.presetId = '';
    el.preset.value = '';
  }
}

function onDeltaInput() {
  const v = valueFromPos(Number(el.delta.value), RANGES.delta);
  showSliderValue(el.delta, el.deltaValue, formatDelta(v));
  if (v === state.desired.controller.sampling_period) return;
  state.desired.controller.sampling_period = v;
  leavePreset();
  applyDesired();
}

function onAlphaInput(which) {
  const slider = which === 0 ? el.alpha1 : el.alpha2;
  const v = valueFromPos(Number(slider.value), RANGES.alpha);
  const alpha = state.desired.controller.alpha;
  const next = el.linkAlpha.checked ? [v, v] : which === 0 ? [v, alpha[1]] : [alpha[0], v];
  if (el.linkAlpha.checked) {
    const other = which === 0 ? el.alpha2 : el.alpha1;
    other.value = slider.value;
  }
  showSliderValue(el.alpha1, el.alpha1Value, formatAlpha(next[0]));
  showSliderValue(el.alpha2, el.alpha2Value, formatAlpha(next[1]));
  if (next[0] === alpha[0] && next[1] === alpha[1]) return;
  state.desired.controller.alpha = next;
  leavePreset();
  applyDesired();
}

function onLinkChange() {
  if (!el.linkAlpha.checked) return;
  const alpha = state.desired.controller.alpha;
  if (alpha[0] === alpha[1]) return;
  // Linking copies α1 to α2.
  state.desired.controller.alpha = [alpha[0], alpha[0]];
  el.alpha2.value = el.alpha1.value;
  showSliderValue(el.alpha2, el.alpha2Value, formatAlpha(alpha[0]));
  leavePreset();
  applyDesired();
}

function onEnumChange(name) {
  const spec = ENUMS[name];
  const v = el[name].value;
  if (!spec.values.includes(v) || state.desired[spec.field] === v) return;
  state.desired[spec.field] = v;
  leavePreset();
  applyDesired();
}

function onRepeatChange() {
  state.desired.reference.repeat_hold = el.repeat.checked ? REPEAT_HOLD : null;
  // A new reference would jump under the arm mid-run: start over instead.
  applyDesired({ reset: true, why: 'The reference changed, so the run restarted from rest.' });
}

function onSpeedInput() {
  state.speed = valueFromPos(Number(el.speed.value), RANGES.speed);
  showSliderValue(el.speed, el.speedValue, formatSpeed(state.speed));
  writeUrl();
}

function onPresetChange() {
  const id = el.preset.value;
  if (id === '') {
    state.presetId = '';
    writeUrl();
    return;
  }
  const cfg = guard(`Preset ${id}`, () => state.Simulation.presetConfig(id, state.desired), null);
  if (!cfg) {
    el.preset.value = state.presetId;
    return;
  }
  state.presetId = id;
  state.desired = cfg;
  el.linkAlpha.checked = cfg.controller.alpha[0] === cfg.controller.alpha[1];
  syncControlsFromDesired();
  const title = el.preset.selectedOptions[0] ? el.preset.selectedOptions[0].textContent : id;
  applyDesired({ reset: true, why: `Preset applied; the run restarted: ${title}.` });
  resume();
}

// ---------------------------------------------------------------------------------------------
// Transport
// ---------------------------------------------------------------------------------------------

function updatePlayButton() {
  const playing = state.playing && !state.dead;
  setText(el.play, playing ? '❚❚ Pause' : '▶ Play');
  el.play.setAttribute('aria-pressed', playing ? 'true' : 'false');
  el.play.setAttribute('aria-label', playing ? 'Pause the simulation' : 'Play the simulation');
}

function togglePlay() {
  state.playing = !state.playing;
  state.lastTs = null;
  updatePlayButton();
  if (state.playing && el.runNote.textContent.startsWith('Paused')) setRunNote('');
}

function resume() {
  if (!state.playing) {
    state.playing = true;
    state.lastTs = null;
    updatePlayButton();
  }
}

function stepOnce() {
  if (!state.sim) return;
  if (state.playing) {
    state.playing = false;
    updatePlayButton();
  }
  guard('Step failed', () => state.sim.stepPeriod());
  const simB = state.compare ? state.simB : null;
  if (simB && !state.finishedB) {
    // B follows A's clock: it advances to A's new time (or one of its own periods if A stopped).
    guard('Step failed (run B)', () => {
      const dt = state.sim.time() - simB.time();
      if (dt > 1e-12) simB.advance(dt, 1);
      else if (state.finished) simB.stepPeriod();
    });
  }
  if (el.runNote.textContent.startsWith('Paused')) setRunNote('');
  state.needsRender = true;
  state.forceStatus = true;
}

function resetRun() {
  if (!state.sim) return;
  guard('Reset failed', () => state.sim.reset());
  state.finished = false;
  if (state.compare && state.simB) {
    guard('Reset failed (run B)', () => state.simB.reset());
    state.finishedB = false;
  }
  state.lastTs = null;
  setRunNote('');
  state.needsRender = true;
  state.forceStatus = true;
}

function poke() {
  if (!state.sim) return;
  guard('Poke failed', () => state.sim.poke(POKE.t1, POKE.t2, POKE.duration));
  if (state.compare && state.simB) guard('Poke failed (run B)', () => state.simB.poke(POKE.t1, POKE.t2, POKE.duration));
  state.forceStatus = true;
}

function exportCsv() {
  if (!state.sim) return;
  const csv = guard('Export failed', () => state.sim.tracesCsv(), null);
  if (csv == null) return;
  const blob = new Blob([csv], { type: 'text/csv;charset=utf-8' });
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = 'flexarm-traces.csv';
  a.style.display = 'none';
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

// ---------------------------------------------------------------------------------------------
// Side by side: run B
// ---------------------------------------------------------------------------------------------

const PF_SHORT = { off: 'no K_pr', paper: 'paper K_pr', lq: 'LQ K_pr' };

/** B's default: A's configuration with the preliminary feedback switched (off → paper, else off). */
function defaultB() {
  const c = state.desired;
  return {
    pf: c.preliminary_feedback === 'off' ? 'paper' : 'off',
    delta: c.controller.sampling_period,
    alpha: c.controller.alpha.slice(),
  };
}

/** A's configuration with B's own preliminary feedback, δ and α. */
function configB() {
  const c = JSON.parse(JSON.stringify(state.desired));
  c.preliminary_feedback = state.b.pf;
  c.controller.sampling_period = state.b.delta;
  c.controller.alpha = state.b.alpha.slice();
  return c;
}

function syncBControls() {
  const b = state.b;
  if (!b) return;
  el.bPf.value = b.pf;
  el.bDelta.value = String(posFromValue(clamp(b.delta, RANGES.delta.min, RANGES.delta.max), RANGES.delta));
  showSliderValue(el.bDelta, el.bDeltaValue, formatDelta(b.delta));
  el.bAlpha.value = String(posFromValue(clamp(b.alpha[0], RANGES.alpha.min, RANGES.alpha.max), RANGES.alpha));
  const alphaText = b.alpha[0] === b.alpha[1] ? formatAlpha(b.alpha[0]) : `${b.alpha[0].toPrecision(3)}, ${formatAlpha(b.alpha[1])}`;
  showSliderValue(el.bAlpha, el.bAlphaValue, alphaText);
}

/**
 * Switches the comparison on or off. On: run B starts (by default A's settings with the
 * preliminary feedback switched) and both runs restart from rest together.
 */
function setCompare(on, { b = null } = {}) {
  if (!state.sim || state.dead) return;
  if (on) {
    state.b = b || defaultB();
    const cfg = configB();
    if (state.simB) {
      state.simB.free();
      state.simB = null;
    }
    const sim = guard('Could not start run B', () => new state.Simulation(cfg), null);
    if (!sim) {
      state.compare = false;
      el.compare.checked = false;
      el.bControls.hidden = true;
      return;
    }
    state.simB = sim;
    state.appliedB = JSON.stringify(cfg);
    state.compare = true;
    state.finishedB = false;
    guard('Reset failed', () => state.sim.reset());
    state.finished = false;
    state.rhoPreviewB = guard('spectralRadius', () => state.wasm.spectralRadius(cfg), null);
    syncBControls();
    el.verdictB.dataset.verdict = '';
    setRunNote('Comparing two runs: both restarted from rest together.');
  } else {
    state.compare = false;
    if (state.simB) {
      state.simB.free();
      state.simB = null;
    }
    setRunNote('');
  }
  el.compare.checked = state.compare;
  el.bControls.hidden = !state.compare;
  state.lastTs = null;
  state.needsRender = true;
  state.layoutPending = true;
  state.forceStatus = true;
  hideTip();
  updateLegend();
  writeUrl();
}

/** Hands B's configuration to run B (next sampling instant; a diverged B restarts). */
function applyB({ reset = false } = {}) {
  const sim = state.simB;
  if (!sim || !state.compare || state.dead) return;
  const cfg = configB();
  const json = JSON.stringify(cfg);
  if (json === state.appliedB && !reset) return;
  const wasFinished = guard('isFinished (run B)', () => sim.isFinished(), false);
  const ok = guard('Applying the settings of run B failed', () => {
    sim.setConfig(cfg);
    return true;
  }, false);
  if (!ok) {
    const current = guard('config (run B)', () => sim.config(), null);
    if (current) {
      state.b = {
        pf: current.preliminary_feedback,
        delta: current.controller.sampling_period,
        alpha: current.controller.alpha.slice(),
      };
      syncBControls();
    }
    return;
  }
  state.appliedB = json;
  if (reset || wasFinished) {
    guard('Reset failed (run B)', () => sim.reset());
    state.finishedB = false;
    if (wasFinished && !reset) setRunNote('Run B had diverged, so it restarted from rest with the new settings.');
  }
  state.rhoPreviewB = guard('spectralRadius', () => state.wasm.spectralRadius(cfg), null);
  state.needsRender = true;
  state.forceStatus = true;
  hideTip();
  updateLegend();
  writeUrl();
}

function onBPfChange() {
  const v = el.bPf.value;
  if (!state.b || !ENUMS.pf.values.includes(v) || state.b.pf === v) return;
  state.b.pf = v;
  applyB();
}

function onBDeltaInput() {
  const v = valueFromPos(Number(el.bDelta.value), RANGES.delta);
  showSliderValue(el.bDelta, el.bDeltaValue, formatDelta(v));
  if (!state.b || state.b.delta === v) return;
  state.b.delta = v;
  applyB();
}

function onBAlphaInput() {
  const v = valueFromPos(Number(el.bAlpha.value), RANGES.alpha);
  showSliderValue(el.bAlpha, el.bAlphaValue, formatAlpha(v));
  if (!state.b || (state.b.alpha[0] === v && state.b.alpha[1] === v)) return;
  state.b.alpha = [v, v];
  applyB();
}

/** One line describing a run's controller settings. */
function describeRun(pf, delta, alpha) {
  const a = alpha[0] === alpha[1] ? `α = ${Number(alpha[0].toPrecision(3))}` : `α = ${Number(alpha[0].toPrecision(3))}, ${Number(alpha[1].toPrecision(3))}`;
  return `${PF_SHORT[pf] || pf}, δ = ${Number(delta.toPrecision(3))} s, ${a} 1/s`;
}

/** A colour from the renderer ([r, g, b(, a)] in 0–1 or 0–255, or a CSS string), else `fallback`. */
function cssColor(c, fallback) {
  if (typeof c === 'string' && c) return c;
  if (Array.isArray(c) && c.length >= 3 && c.every((v) => Number.isFinite(v))) {
    const f = c.slice(0, 3).every((v) => v <= 1) ? 255 : 1;
    const [r, g, b] = c.slice(0, 3).map((v) => Math.round(clamp(v * f, 0, 255)));
    return `rgb(${r}, ${g}, ${b})`;
  }
  if (c && typeof c === 'object' && ['r', 'g', 'b'].every((k) => Number.isFinite(c[k]))) {
    return cssColor([c.r, c.g, c.b], fallback);
  }
  return fallback;
}

const LEGEND_FALLBACK = { A: { color: '#1f5fa8', thin: false }, B: { color: '#7a3db8', thin: true } };
let legendSignature = '';

/** Which line is A and which B: colours and dashes from layout().series when the renderer says. */
function updateLegend() {
  if (!state.compare || !state.b || !state.desired) {
    el.pairLegend.hidden = true;
    legendSignature = '';
    return;
  }
  const series = Array.isArray(state.lastLayout?.series) ? state.lastLayout.series : [];
  const styleOf = (run) => {
    const s = series.find((x) => x && String(x.run).toUpperCase() === run);
    const fb = LEGEND_FALLBACK[run];
    if (!s) return { color: fb.color, thin: fb.thin, marker: '' };
    const thin = s.style != null ? s.style === 'thin' : fb.thin;
    const marker = s.pole_marker === 'plus' ? '+' : s.pole_marker === 'cross' ? '×' : '';
    return { color: cssColor(s.color, fb.color), thin, marker };
  };
  const drawn = !!state.renderer && typeof state.renderer.renderPair === 'function';
  const c = state.desired;
  const runs = [
    { run: 'A', text: describeRun(c.preliminary_feedback, c.controller.sampling_period, c.controller.alpha), ...styleOf('A') },
    { run: 'B', text: describeRun(state.b.pf, state.b.delta, state.b.alpha) + (drawn ? '' : ' — not drawn by this renderer'), ...styleOf('B') },
  ];
  const signature = JSON.stringify(runs);
  el.pairLegend.hidden = false;
  if (signature === legendSignature) return;
  legendSignature = signature;
  const items = runs.map((r) => {
    const item = document.createElement('span');
    item.className = 'legend-item';
    item.dataset.run = r.run;
    const sw = document.createElement('span');
    sw.className = `swatch${r.thin ? ' thin' : ''}`;
    sw.style.color = r.color;
    sw.setAttribute('aria-hidden', 'true');
    const label = document.createElement('span');
    const poles = r.marker ? `, loop poles ${r.marker}` : '';
    label.textContent = `${r.run}: ${r.text}${r.run === 'A' ? ' (the controls above)' : ''}${poles}`;
    item.append(sw, label);
    return item;
  });
  const head = document.createElement('span');
  head.className = 'map-row-title';
  head.textContent = 'Lines:';
  el.pairLegend.replaceChildren(head, ...items);
}

// ---------------------------------------------------------------------------------------------
// Stability maps ρ(δ, α), computed in small chunks
// ---------------------------------------------------------------------------------------------

const MAP = {
  deltaMin: 0.002, deltaMax: 0.25, nDelta: 100,
  alphaMin: 0.1, alphaMax: 5, nAlpha: 60,
  /** Wall time per chunk, ms: the page stays responsive. */
  budgetMs: 8,
  /** Maps kept in the cache (each 6000 numbers). */
  cacheSize: 8,
};
const MAP_POINTS = MAP.nDelta * MAP.nAlpha;

const maps = {
  /** key → {key, pf, job, started, computeMs, ms, done, failed, values, used} */
  cache: new Map(),
  /** The key each map panel shows. */
  shown: { off: null, on: null },
  timer: null,
  started: false,
  unavailable: false,
  /** Start-to-done wall time of every map computed, ms. */
  times: [],
  /** Map panels whose job has new rows the renderer has not copied yet. */
  dirty: new Set(),
};

/** The preliminary feedback of a map: none for "off"; for "on" the selected one if LQ, else the paper's. */
function mapPf(which) {
  if (which === 'off') return 'off';
  return state.desired && state.desired.preliminary_feedback === 'lq' ? 'lq' : 'paper';
}

/** Everything except δ and α that changes ρ. */
function mapKey(c, pf) {
  return JSON.stringify([pf, c.inner_loop, c.controller.horizon_steps, c.controller.eps_ratio, c.plant,
    c.reference.end, c.lq_design_q2]);
}

function pushMap(which, entry) {
  const r = state.renderer;
  if (!r || typeof r.setMap !== 'function' || !entry || entry.failed) return;
  guard('Drawing the stability map', () => r.setMap(which, entry.job));
  state.needsRender = true;
  state.layoutPending = true;
}

function pushAllMaps() {
  for (const which of ['off', 'on']) pushMap(which, maps.cache.get(maps.shown[which]));
}

function evictMaps() {
  if (maps.cache.size <= MAP.cacheSize) return;
  const inUse = new Set(Object.values(maps.shown));
  const old = [...maps.cache.values()].filter((e) => !inUse.has(e.key)).sort((a, b) => a.used - b.used);
  while (maps.cache.size > MAP.cacheSize && old.length) {
    const e = old.shift();
    maps.cache.delete(e.key);
    try {
      e.job.free();
    } catch {
      // already gone
    }
  }
}

/** Makes both map panels show the maps of the current settings, from the cache or newly started. */
function ensureMaps() {
  if (!maps.started || !state.wasm || !state.desired || state.dead) return;
  const Job = state.wasm.StabilityMapJob;
  if (typeof Job !== 'function') {
    if (!maps.unavailable) {
      maps.unavailable = true;
      setText(el.mapTime, 'not available in this build');
    }
    return;
  }
  for (const which of ['off', 'on']) {
    const pf = mapPf(which);
    const key = mapKey(state.desired, pf);
    let entry = maps.cache.get(key);
    if (!entry) {
      const cfg = JSON.parse(JSON.stringify(state.desired));
      cfg.preliminary_feedback = pf;
      const job = guard('Stability map', () => new Job(cfg, MAP.deltaMin, MAP.deltaMax, MAP.nDelta,
        MAP.alphaMin, MAP.alphaMax, MAP.nAlpha), null);
      if (!job) continue;
      entry = { key, pf, job, started: null, computeMs: 0, ms: null, done: false, failed: false, values: null, used: 0 };
      maps.cache.set(key, entry);
    }
    entry.used = performance.now();
    if (maps.shown[which] !== key) {
      maps.shown[which] = key;
      pushMap(which, entry);
    }
  }
  evictMaps();
  updateMapProgress();
  scheduleMapWork();
}

/** The next chunk runs as a fresh task right away (a MessageChannel message: nested setTimeout(0)
 *  would wait ≥ 4 ms each time); the browser still draws frames and handles input in between. */
const mapChannel = typeof MessageChannel === 'function' ? new MessageChannel() : null;
if (mapChannel) mapChannel.port1.onmessage = () => mapWork();

function queueMapChunk() {
  maps.timer = true;
  if (mapChannel) mapChannel.port2.postMessage(0);
  else setTimeout(mapWork, 0);
}

function scheduleMapWork() {
  if (maps.timer != null || !maps.started || state.dead || !el.showMap.checked) return;
  queueMapChunk();
}

/** One chunk of the first unfinished map shown (map-off first), then yields to the page. */
function mapWork() {
  maps.timer = null;
  if (state.dead || !el.showMap.checked) return;
  const pending = ['off', 'on'].map((w) => maps.cache.get(maps.shown[w])).filter((e) => e && !e.done);
  if (pending.length === 0) {
    updateMapProgress();
    return;
  }
  const entry = pending[0];
  const t0 = performance.now();
  if (entry.started == null) entry.started = t0;
  const ok = guard('Stability map', () => {
    entry.job.step(MAP.budgetMs);
    return true;
  }, false);
  const t1 = performance.now();
  entry.computeMs += t1 - t0;
  entry.values = null;
  if (!ok) {
    entry.done = true;
    entry.failed = true;
  } else if (entry.job.isDone()) {
    entry.done = true;
    entry.ms = t1 - entry.started;
    maps.times.push({ pf: entry.pf, ms: entry.ms, compute_ms: entry.computeMs });
  }
  // The renderer copies the grid once per frame at most (see renderFrame), and at the end.
  for (const which of ['off', 'on']) {
    if (maps.shown[which] !== entry.key) continue;
    if (entry.done) pushMap(which, entry);
    else {
      maps.dirty.add(which);
      state.needsRender = true;
    }
  }
  updateMapProgress();
  if (!entry.done || pending.length > 1) queueMapChunk();
}

/** Hands the rows computed since the last frame to the renderer. */
function flushMaps() {
  if (maps.dirty.size === 0) return;
  for (const which of maps.dirty) pushMap(which, maps.cache.get(maps.shown[which]));
  maps.dirty.clear();
}

let mapProgressShown = -1;

function updateMapProgress() {
  const entries = ['off', 'on'].map((w) => maps.cache.get(maps.shown[w])).filter(Boolean);
  if (entries.length === 0) return;
  const frac = entries.reduce((sum, e) => sum + (e.done ? 1 : guard('progress', () => e.job.progress(), 0)), 0) / entries.length;
  const pct = Math.round(frac * 100);
  const allDone = entries.every((e) => e.done);
  if (pct !== mapProgressShown) {
    mapProgressShown = pct;
    el.mapProgress.setAttribute('aria-valuenow', String(pct));
    el.mapProgress.firstElementChild.style.width = `${pct}%`;
  }
  el.mapProgress.setAttribute('aria-valuetext', allDone ? 'done' : `${pct} %`);
  el.mapProgress.dataset.done = allDone ? 'true' : 'false';
  let text;
  if (!el.showMap.checked && !allDone) {
    text = `paused at ${pct} % (maps hidden)`;
  } else if (allDone) {
    const parts = entries.filter((e) => !e.failed).map((e) => `${e.ms != null ? (e.ms / 1000).toFixed(2) : '—'} s ${e.pf === 'off' ? 'without K_pr' : `with ${PF_SHORT[e.pf]}`}`);
    text = `map: ${MAP_POINTS} points in ${parts.join(', ')}`;
  } else {
    text = `computing ${MAP_POINTS} points per map… ${pct} %`;
  }
  setText(el.mapTime, text);
  const drawable = !!state.renderer && typeof state.renderer.setMap === 'function' && state.rendererCaps.show_map !== false;
  setText(el.mapHint, drawable ? 'click a map to run at that δ and α' : 'this renderer cannot draw the maps yet');
}

/** ρ of a map at (δ, α): the nearest grid point, NaN if not computed yet. */
function mapRho(which, delta, alpha) {
  const entry = maps.cache.get(maps.shown[which]);
  if (!entry || entry.failed) return NaN;
  if (!entry.values) entry.values = guard('map values', () => entry.job.values(), null);
  if (!entry.values) return NaN;
  const fi = Math.log(delta / MAP.deltaMin) / Math.log(MAP.deltaMax / MAP.deltaMin);
  const fj = Math.log(alpha / MAP.alphaMin) / Math.log(MAP.alphaMax / MAP.alphaMin);
  const i = clamp(Math.round(fi * (MAP.nDelta - 1)), 0, MAP.nDelta - 1);
  const j = clamp(Math.round(fj * (MAP.nAlpha - 1)), 0, MAP.nAlpha - 1);
  return entry.values[j * MAP.nDelta + i];
}

/**
 * Runs A at (δ, α1 = α2 = α) with the map's preliminary feedback (none for the left map; for the
 * right one the selected feedback, or the paper's if none is selected), through the same path
 * as the sliders.
 */
function setFromMap(which, delta, alpha) {
  if (!state.desired || state.dead) return;
  const dRaw = Number(delta.toPrecision(3));
  const d = clamp(dRaw, RANGES.delta.min, RANGES.delta.max);
  const a = clamp(Number(alpha.toPrecision(3)), RANGES.alpha.min, RANGES.alpha.max);
  const current = state.desired.preliminary_feedback;
  const pf = which === 'off' ? 'off' : current !== 'off' ? current : 'paper';
  const c = state.desired;
  el.linkAlpha.checked = true;
  if (c.controller.sampling_period !== d || c.controller.alpha[0] !== a || c.controller.alpha[1] !== a
    || c.preliminary_feedback !== pf) {
    c.controller.sampling_period = d;
    c.controller.alpha = [a, a];
    c.preliminary_feedback = pf;
    leavePreset();
    syncControlsFromDesired();
    applyDesired();
  }
  if (dRaw > RANGES.delta.max) {
    setRunNote(`The map goes to δ = ${MAP.deltaMax} s, the controls to ${RANGES.delta.max} s: using δ = ${RANGES.delta.max} s.`);
  }
}

// ---------------------------------------------------------------------------------------------
// Pointer: pole tooltips, map hover and clicks
// ---------------------------------------------------------------------------------------------

const POLE_KINDS = {
  loop: 'loop pole (sampled loop, s = ln λ / δ)',
  a4_open: 'A4 without PF (δ → 0 limit)',
  a4: 'A4 with PF (δ → 0 limit)',
};

const MAP_PANELS = { 'map-off': 'off', 'map-on': 'on' };

let tipPinned = false;

function hideTip() {
  tipPinned = false;
  if (!el.plotTip.hidden) el.plotTip.hidden = true;
  el.canvas.classList.remove('over-map', 'over-pole');
}

/** Shows the tooltip near (x, y) (CSS px in the canvas) with `lines` ([text, className?]). */
function showTip(x, y, title, lines) {
  const strong = document.createElement('strong');
  strong.textContent = title;
  const spans = lines.map(([text, cls]) => {
    const span = document.createElement('span');
    span.className = `tip-line${cls ? ` ${cls}` : ''}`;
    span.textContent = text;
    return span;
  });
  el.plotTip.replaceChildren(strong, ...spans);
  el.plotTip.hidden = false;
  const w = el.plotTip.offsetWidth;
  const h = el.plotTip.offsetHeight;
  const W = el.canvasWrap.clientWidth;
  const H = el.canvasWrap.clientHeight;
  let left = x + 14;
  if (left + w > W - 4) left = x - 14 - w;
  let top = y - h - 10;
  if (top < 4) top = y + 16;
  left = clamp(left, 4, Math.max(4, W - w - 4));
  top = clamp(top, 4, Math.max(4, H - h - 4));
  el.plotTip.style.transform = `translate(${left.toFixed(0)}px, ${top.toFixed(0)}px)`;
}

function canvasPoint(ev) {
  const r = el.canvas.getBoundingClientRect();
  return { x: ev.clientX - r.left, y: ev.clientY - r.top };
}

function inPanel(p, x, y, margin = 0) {
  return x >= p.x - margin && x <= p.x + p.width + margin && y >= p.y - margin && y <= p.y + p.height + margin;
}

function panelsOf(layout) {
  return layout && Array.isArray(layout.panels) ? layout.panels : [];
}

/** The value at fraction f (0–1) along an axis. */
function axisValue(f, r0, r1, scale) {
  return scale === 'log' ? r0 * Math.pow(r1 / r0, f) : r0 + f * (r1 - r0);
}

/** The fraction (0–1) of an axis at value v. */
function axisFraction(v, r0, r1, scale) {
  if (scale === 'log') return Math.log(v / r0) / Math.log(r1 / r0);
  return (v - r0) / (r1 - r0 || 1);
}

/** The nearest pole to (x, y) in a pole panel, within `reach` CSS px: {pole, px, py, others}. */
function nearestPole(x, y, reach) {
  const layout = state.lastLayout;
  const poles = layout && Array.isArray(layout.poles) ? layout.poles : [];
  if (poles.length === 0) return null;
  let best = null;
  for (const p of panelsOf(layout)) {
    if (!String(p.id).startsWith('poles') || !p.x_range || !p.y_range || !inPanel(p, x, y, reach / 2)) continue;
    const pts = [];
    for (const pole of poles) {
      if (!Number.isFinite(pole.re) || !Number.isFinite(pole.im)) continue;
      let px;
      let py;
      if (Number.isFinite(pole.x) && Number.isFinite(pole.y)) {
        // The renderer says where it drew the marker (a chevron at the edge if out of range).
        px = pole.x;
        py = pole.y;
      } else {
        const fx = axisFraction(pole.re, p.x_range[0], p.x_range[1], p.x_scale);
        const fy = axisFraction(pole.im, p.y_range[0], p.y_range[1], p.y_scale);
        if (fx < -0.02 || fx > 1.02 || fy < -0.02 || fy > 1.02) continue; // outside the plotted range
        px = p.x + fx * p.width;
        py = p.y + p.height - fy * p.height;
      }
      if (!inPanel(p, px, py, 12)) continue;
      pts.push({ pole, px, py, d: Math.hypot(px - x, py - y) });
    }
    for (const q of pts) {
      if (q.d <= reach && (!best || q.d < best.d)) best = q;
    }
    if (best) best.others = pts.filter((q) => q !== best && Math.hypot(q.px - best.px, q.py - best.py) < 4).length;
  }
  return best;
}

function showPoleTip(hit) {
  const { pole } = hit;
  const im = Math.abs(pole.im);
  const s = im > 1e-9 ? `s = ${sig(pole.re, 3)} ± ${sig(im, 4)}j 1/s` : `s = ${sig(pole.re, 3)} 1/s`;
  const lines = [[s]];
  if (Number.isFinite(pole.zeta)) lines.push([`damping ratio ζ = ${sig(pole.zeta, 3)}`]);
  if (Number.isFinite(pole.omega)) lines.push([`frequency ω = ${sig(pole.omega, 3)} rad/s`]);
  if (pole.unstable === true) lines.push(['unstable: Re s > 0, it grows', 'tip-bad']);
  else if (pole.unstable === false) lines.push(['stable: it decays', 'tip-good']);
  if (pole.in_view === false) lines.push(['outside the shown range (marked at the edge)']);
  if (hit.others > 0) lines.push([`(${hit.others} more pole${hit.others > 1 ? 's' : ''} at the same spot)`]);
  let title = POLE_KINDS[pole.kind] || (pole.kind ? String(pole.kind) : 'pole');
  if (pole.run && state.lastLayout && state.lastLayout.mode === 'pair') title += ` — run ${pole.run}`;
  showTip(hit.px, hit.py, title, lines);
  el.canvas.classList.add('over-pole');
  el.canvas.classList.remove('over-map');
}

function mapPanelAt(x, y) {
  for (const p of panelsOf(state.lastLayout)) {
    if (MAP_PANELS[p.id] && p.width > 0 && p.height > 0 && inPanel(p, x, y)) return p;
  }
  return null;
}

/** (δ, α) under (x, y) in map panel p: log axes, y from the bottom. */
function mapPointAt(p, x, y) {
  const fx = clamp((x - p.x) / p.width, 0, 1);
  const fy = clamp(1 - (y - p.y) / p.height, 0, 1);
  const xr = Array.isArray(p.x_range) ? p.x_range : [MAP.deltaMin, MAP.deltaMax];
  const yr = Array.isArray(p.y_range) ? p.y_range : [MAP.alphaMin, MAP.alphaMax];
  return {
    delta: axisValue(fx, xr[0], xr[1], p.x_scale || 'log'),
    alpha: axisValue(fy, yr[0], yr[1], p.y_scale || 'log'),
  };
}

function showMapTip(p, x, y) {
  const which = MAP_PANELS[p.id];
  const { delta, alpha } = mapPointAt(p, x, y);
  const rho = mapRho(which, delta, alpha);
  const lines = [[`δ = ${sig(delta, 3)} s, α = ${sig(alpha, 3)} 1/s`]];
  if (Number.isFinite(rho)) lines.push([`ρ = ${rho.toFixed(3)}: ${rho < 1 ? 'stable' : 'unstable'}`, rho < 1 ? 'tip-good' : 'tip-bad']);
  else lines.push(['ρ not computed yet']);
  lines.push(['click to run here']);
  const pf = mapPf(which);
  showTip(x, y, pf === 'off' ? 'without preliminary feedback' : `with ${PF_SHORT[pf]}`, lines);
  el.canvas.classList.add('over-map');
  el.canvas.classList.remove('over-pole');
}

/** Hover (mouse) or tap (touch, pen): a pole's tooltip, or the map value under the pointer. */
function onCanvasPointer(ev) {
  if (state.dead || !state.lastLayout) return;
  const touch = ev.pointerType === 'touch' || ev.pointerType === 'pen';
  if (ev.type === 'pointermove' && (touch || tipPinned)) return;
  const { x, y } = canvasPoint(ev);
  const pole = nearestPole(x, y, touch ? 36 : 22);
  if (pole) {
    showPoleTip(pole);
    tipPinned = touch && ev.type === 'pointerdown';
    return;
  }
  const map = mapPanelAt(x, y);
  if (map && !touch) {
    showMapTip(map, x, y);
    return;
  }
  hideTip();
}

function onCanvasClick(ev) {
  if (state.dead || !state.lastLayout) return;
  const { x, y } = canvasPoint(ev);
  const p = mapPanelAt(x, y);
  if (!p) return;
  const { delta, alpha } = mapPointAt(p, x, y);
  setFromMap(MAP_PANELS[p.id], delta, alpha);
  if (ev.pointerType === 'mouse' || ev.pointerType === undefined || ev.pointerType === '') showMapTip(p, x, y);
  else hideTip();
}

// ---------------------------------------------------------------------------------------------
// "Try" buttons in the explanation
// ---------------------------------------------------------------------------------------------

function setBothAlphas(v) {
  const a = clamp(v, RANGES.alpha.min, RANGES.alpha.max);
  state.desired.controller.alpha = [a, a];
  el.linkAlpha.checked = true;
}

function tryAction(spec) {
  if (!state.sim || state.dead) return;
  const [kind, a, b, c] = String(spec).split(':');
  switch (kind) {
    case 'preset':
      el.preset.value = a;
      onPresetChange();
      break;
    case 'pf':
      if (!ENUMS.pf.values.includes(a) || state.desired.preliminary_feedback === a) break;
      el.pf.value = a;
      onEnumChange('pf');
      break;
    case 'alpha':
      setBothAlphas(Number(a));
      leavePreset();
      syncControlsFromDesired();
      applyDesired();
      break;
    case 'delta':
      state.desired.controller.sampling_period = clamp(Number(a), RANGES.delta.min, RANGES.delta.max);
      leavePreset();
      syncControlsFromDesired();
      applyDesired();
      break;
    case 'compare':
      if (!state.compare) setCompare(true);
      el.compare.scrollIntoView({ block: 'nearest', behavior: 'smooth' });
      break;
    case 'map':
      if (!el.showMap.checked) {
        el.showMap.checked = true;
        onShowMapChange();
      }
      setFromMap(a === 'on' ? 'on' : 'off', Number(b), Number(c));
      break;
    default:
      return;
  }
  resume();
}

function onShowMapChange() {
  applyRendererOptions();
  if (el.showMap.checked) {
    ensureMaps();
    scheduleMapWork();
  }
  updateMapProgress();
  el.mapRow.classList.toggle('maps-hidden', !el.showMap.checked);
}

// ---------------------------------------------------------------------------------------------
// Status and readouts
// ---------------------------------------------------------------------------------------------

function sameControllerSettings(a, b) {
  return (
    a.controller.sampling_period === b.controller.sampling_period &&
    a.controller.alpha[0] === b.controller.alpha[0] &&
    a.controller.alpha[1] === b.controller.alpha[1] &&
    a.preliminary_feedback === b.preliminary_feedback &&
    a.inner_loop === b.inner_loop &&
    a.friction_compensation === b.friction_compensation
  );
}

function verdictDetail(m) {
  if (m.verdict === 'diverged') {
    const at = m.diverged_at != null ? m.diverged_at.toFixed(2) : '?';
    const why = DIVERGENCE_REASONS[m.divergence_reason] || '';
    return `diverged at t = ${at} s${why ? ` (${why})` : ''} — change a parameter or press reset`;
  }
  if (m.growth_rate == null) {
    // With a repeating slew the growth is measured cycle to cycle (two full cycles are needed),
    // so say what the linear analysis expects meanwhile.
    const rho = state.rhoPreview;
    if (rho != null && Number.isFinite(rho) && rho >= 1) {
      return 'so far — no growth measured yet, but ρ ≥ 1 predicts the errors will grow';
    }
    return 'so far — no growth measured yet';
  }
  if (m.verdict === 'unstable') return 'the errors grow exponentially';
  return 'the errors stay bounded';
}

function rhoText(rho) {
  if (rho == null || !Number.isFinite(rho)) return 'linear analysis: ρ = —';
  return `linear analysis: ρ = ${rho.toFixed(4)} ${rho < 1 ? '< 1 ⇒ stable' : '≥ 1 ⇒ unstable'}`;
}

/** analysis() of the configuration in force, once it has caught up with the controls. */
function refreshAnalysis() {
  if (!state.analysisStale) return;
  const sim = state.sim;
  const inForce = guard('config', () => sim.config(), null);
  if (!inForce || !sameControllerSettings(inForce, state.desired)) return;
  state.analysisStale = false;
  state.analysis = guard('Linear analysis failed', () => sim.analysis(), null);
  if (state.analysis) state.rhoPreview = state.analysis.spectral_radius;
}

function formatPair(pair) {
  if (!pair || pair.length < 1) return '—';
  const [re, im] = pair[0];
  return `${sig(re, 3)} ± ${sig(Math.abs(im), 4)}j 1/s`;
}

function updateStatus() {
  const sim = state.sim;
  if (!sim || state.dead) return;
  refreshAnalysis();
  const m = guard('metrics', () => sim.metrics(), null);
  const s = guard('snapshot', () => sim.snapshot(), null);
  if (!m) return;

  state.finished = m.verdict === 'diverged';
  const verdict = m.verdict;
  if (el.verdict.dataset.verdict !== verdict) el.verdict.dataset.verdict = verdict;
  // Until a growth rate has been fitted, "stable" only means "nothing has grown yet".
  const observing = verdict === 'stable' && m.growth_rate == null ? 'true' : 'false';
  if (el.verdict.dataset.observing !== observing) el.verdict.dataset.observing = observing;
  setText(el.verdictWord, verdict);

  setText(el.verdictDetail, verdictDetail(m));

  // The fitted rate moves a little all the time: refresh its text about once a second (and at
  // once when the verdict changes) so the live region does not chatter.
  const g = m.growth_rate;
  const now = performance.now();
  if (g == null || verdict !== state.lastVerdict || now - state.growthShownAt >= 1000) {
    state.growthShownAt = now;
    setText(
      el.verdictGrowth,
      g == null ? 'observed growth rate: observing…' : `observed growth rate: ${minus(g.toFixed(2))} 1/s`,
    );
  }
  state.lastVerdict = verdict;

  const rho = state.rhoPreview;
  let rhoLine = rhoText(rho);
  if (rho != null && Number.isFinite(rho)) {
    const a = state.analysis;
    if (a && !state.analysisStale && Number.isFinite(a.growth_rate)) {
      rhoLine += ` (ln ρ/δ = ${minus(a.growth_rate.toFixed(2))} 1/s)`;
    }
  }
  setText(el.verdictRho, rhoLine);

  // Readouts
  setText(el.roTime, `${m.time.toFixed(2)} s`);
  if (s) setText(el.roError, `${sci(s.error[0])}, ${sci(s.error[1])} rad`);
  setText(el.roMaxSlew, `${sci(m.max_error_slew[0])}, ${sci(m.max_error_slew[1])} rad`);
  setText(el.roMaxAfter, `${sci(m.max_error_after[0])}, ${sci(m.max_error_after[1])} rad`);
  setText(el.roTorque, `${sig(m.max_torque[0])}, ${sig(m.max_torque[1])} N m`);
  const a = state.analysis;
  setText(el.roA4, a && !state.analysisStale ? formatPair(a.limit_pair) : '—');

  if (state.compare && state.simB) updateStatusB();
}

/** Run B's verdict (#verdict-b): the same words and ρ as A's. */
function updateStatusB() {
  const m = guard('metrics (run B)', () => state.simB.metrics(), null);
  if (!m) return;
  state.finishedB = m.verdict === 'diverged';
  if (el.verdictB.dataset.verdict !== m.verdict) el.verdictB.dataset.verdict = m.verdict;
  const observing = m.verdict === 'stable' && m.growth_rate == null ? 'true' : 'false';
  if (el.verdictB.dataset.observing !== observing) el.verdictB.dataset.observing = observing;
  setText(el.verdictBWord, m.verdict);
  setText(el.verdictBDetail, verdictDetail(m));
  setText(el.verdictBRho, rhoText(state.rhoPreviewB));
}

// ---------------------------------------------------------------------------------------------
// Axis labels over the canvas
// ---------------------------------------------------------------------------------------------

/** Per panel: the label elements and the values they show. */
const axes = new Map();

function makeLabel(cls) {
  const span = document.createElement('span');
  span.className = cls;
  el.overlay.appendChild(span);
  return span;
}

function ensurePanelEntry(id) {
  let entry = axes.get(id);
  if (!entry) {
    entry = {
      xTitle: makeLabel('axis-title'),
      yTitle: makeLabel('axis-title'),
      note: null,
      xTicks: [],
      yTicks: [],
      // last applied values
      x: NaN, y: NaN, w: NaN, h: NaN,
      xr0: NaN, xr1: NaN, yr0: NaN, yr1: NaN, xs: '', ys: '',
      xTickVals: [], yTickVals: [],
      xLabel: null, yLabel: null,
      visible: true,
    };
    entry.yTitle.classList.add('y-title');
    entry.xTitle.classList.add('x-title');
    axes.set(id, entry);
  }
  return entry;
}

function sameArray(a, b) {
  if (!b || a.length !== b.length) return false;
  for (let i = 0; i < a.length; i += 1) if (a[i] !== b[i]) return false;
  return true;
}

/** A formatter suited to a set of ticks: fixed decimals, or exponents for tiny/huge values. */
function tickFormatter(ticks) {
  let maxAbs = 0;
  let step = Infinity;
  for (let i = 0; i < ticks.length; i += 1) {
    maxAbs = Math.max(maxAbs, Math.abs(ticks[i]));
    if (i > 0) step = Math.min(step, Math.abs(ticks[i] - ticks[i - 1]));
  }
  if (!Number.isFinite(step) || step === 0) step = maxAbs || 1;
  if (maxAbs !== 0 && (maxAbs < 1e-2 || maxAbs >= 1e5)) {
    const tol = step * 1e-6;
    return (v) => {
      if (Math.abs(v) < tol) return '0';
      // The fewest mantissa digits that still name the tick exactly: 5e-4, 1e-3, 2.5e-4.
      let text = v.toExponential(6);
      for (let d = 0; d <= 6; d += 1) {
        const candidate = v.toExponential(d);
        if (Math.abs(Number(candidate) - v) <= tol) {
          text = candidate;
          break;
        }
      }
      return minus(text.replace('e+', 'e'));
    };
  }
  const decimals = clamp(-Math.floor(Math.log10(step) + 1e-9), 0, 6);
  return (v) => {
    const s = v.toFixed(decimals);
    return Number(s) === 0 ? '0' : minus(s);
  };
}

function placeTicks(pool, values, format, place) {
  while (pool.length < values.length) pool.push(makeLabel('tick'));
  for (let i = 0; i < pool.length; i += 1) {
    const span = pool[i];
    if (i < values.length) {
      setText(span, format(values[i]));
      span.style.transform = place(values[i]);
      span.hidden = false;
    } else {
      span.hidden = true;
    }
  }
}

function hideEntry(entry) {
  if (!entry.visible) return;
  entry.visible = false;
  entry.xTitle.hidden = true;
  entry.yTitle.hidden = true;
  if (entry.note) entry.note.hidden = true;
  for (const s of entry.xTicks) s.hidden = true;
  for (const s of entry.yTicks) s.hidden = true;
  entry.x = NaN; // force a full update when it comes back
}

const seenPanels = new Set();
let shownMagnification = NaN;
const NO_TICKS = Object.freeze([]);
/** Caption of a panel that has no axis titles. */
function panelCaption(id) {
  if (id === 'arm') return state.compare && state.simB ? 'A: arm, top view' : 'arm, top view';
  if (id === 'arm-b') return 'B: arm, top view';
  return '';
}
/** A short note inside the top of a panel: which map it is. */
function panelNote(id) {
  if (id === 'map-off') return 'ρ without K_pr';
  if (id === 'map-on') return `ρ with ${PF_SHORT[mapPf('on')]}`;
  return '';
}

/** 1-2-5 ticks of a logarithmic axis from lo to hi. */
function logTicks(lo, hi) {
  const out = [];
  if (!(lo > 0 && hi > lo)) return out;
  for (let e = Math.floor(Math.log10(lo)); e <= Math.ceil(Math.log10(hi)); e += 1) {
    for (const m of [1, 2, 5]) {
      const v = Number((m * Math.pow(10, e)).toPrecision(3));
      if (v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9)) out.push(v);
    }
  }
  return out;
}

/** Log-axis tick labels: 0.002, 0.005, 0.01, 0.2, 1, 5 (no exponents, no trailing zeros). */
function formatLogTick(v) {
  return minus(String(Number(v.toPrecision(3))));
}

/** The labels of a log axis that fit: the renderer's ticks (its grid lines) first, then the
 *  other 1-2-5 values — decades, then 5s, then 2s — each at least `minPx` from those kept. */
function thinLogTicks(ticks, extra, pos, minPx) {
  const rank = (v) => {
    const m = Math.round(v / Math.pow(10, Math.floor(Math.log10(v) + 1e-9)));
    return m === 1 ? 0 : m === 5 ? 1 : m === 2 ? 2 : 3;
  };
  const near = (a, b) => Math.abs(a / b - 1) < 1e-6;
  const candidates = [...ticks.filter((v) => v > 0)];
  for (const v of extra) if (!candidates.some((c) => near(c, v))) candidates.push(v);
  const given = (v) => (ticks.some((t) => near(t, v)) ? 0 : 1);
  const order = candidates.slice().sort((a, b) => given(a) - given(b) || rank(a) - rank(b) || a - b);
  const kept = [];
  for (const v of order) {
    const q = pos(v);
    if (kept.every((k) => Math.abs(k.q - q) >= minPx)) kept.push({ v, q });
  }
  return kept.sort((a, b) => a.v - b.v).map((k) => k.v);
}
/** Least distance between log-axis labels, CSS px. */
const LOG_LABEL_PX = { x: 38, y: 17 };

/** Height a title row needs above a panel, CSS px. */
const TITLE_ROW_PX = 19;
/** Height of the tick labels below a panel, CSS px. */
const TICK_ROW_PX = 19;

/** Free vertical space above panel `i`: down from the canvas top or from the lowest panel (with
 *  its tick labels) that sits above it in an overlapping column. */
function roomAbove(panels, i) {
  const p = panels[i];
  let top = 0;
  for (let j = 0; j < panels.length; j += 1) {
    if (j === i) continue;
    const q = panels[j];
    const overlaps = q.x < p.x + p.width && p.x < q.x + q.width;
    if (!overlaps || q.y >= p.y) continue;
    const bottom = q.y + q.height + (q.x_ticks && q.x_ticks.length ? TICK_ROW_PX : 0);
    top = Math.max(top, bottom);
  }
  return p.y - top;
}

function hideIfUnseen(entry, id) {
  if (!seenPanels.has(id)) hideEntry(entry);
}

function updateAxes(layout) {
  if (!layout || !Array.isArray(layout.panels)) return;
  seenPanels.clear();
  const panels = layout.panels;
  // Any panel moved or resized: every title is placed again (their room depends on neighbours).
  let anyGeometryChanged = false;
  for (let i = 0; i < panels.length; i += 1) {
    const p = panels[i];
    const e = axes.get(p.id);
    if (!e || e.x !== p.x || e.y !== p.y || e.w !== p.width || e.h !== p.height || !e.visible) {
      anyGeometryChanged = true;
    }
  }
  for (let i = 0; i < panels.length; i += 1) {
    const p = panels[i];
    seenPanels.add(p.id);
    const e = ensurePanelEntry(p.id);
    const xr0 = p.x_range ? p.x_range[0] : 0;
    const xr1 = p.x_range ? p.x_range[1] : 1;
    const yr0 = p.y_range ? p.y_range[0] : 0;
    const yr1 = p.y_range ? p.y_range[1] : 1;
    const xs = p.x_scale === 'log' ? 'log' : 'linear';
    const ys = p.y_scale === 'log' ? 'log' : 'linear';
    const xTicks = p.x_ticks || NO_TICKS;
    const yTicks = p.y_ticks || NO_TICKS;
    const geometryChanged = e.x !== p.x || e.y !== p.y || e.w !== p.width || e.h !== p.height;
    const xChanged = geometryChanged || e.xr0 !== xr0 || e.xr1 !== xr1 || e.xs !== xs || !sameArray(xTicks, e.xTickVals);
    const yChanged = geometryChanged || e.yr0 !== yr0 || e.yr1 !== yr1 || e.ys !== ys || !sameArray(yTicks, e.yTickVals);
    const caption = panelCaption(p.id);
    const titlesChanged = anyGeometryChanged || e.xLabel !== p.x_label || e.yLabel !== p.y_label || e.caption !== caption;
    const note = panelNote(p.id);
    if (note || e.note) {
      if (!e.note) e.note = makeLabel('panel-note');
      setText(e.note, note);
      e.note.hidden = !note;
      if (note && (geometryChanged || !e.visible)) {
        // Bottom centre: the smallest α, where little happens on the maps.
        e.note.style.transform = `translate(${(p.x + p.width / 2).toFixed(1)}px, ${(p.y + p.height - 2).toFixed(1)}px) translate(-50%, -100%)`;
      }
    }
    if (!xChanged && !yChanged && !titlesChanged) continue;
    e.visible = true;
    e.x = p.x;
    e.y = p.y;
    e.w = p.width;
    e.h = p.height;

    if (xChanged) {
      e.xr0 = xr0;
      e.xr1 = xr1;
      e.xs = xs;
      e.xTickVals = xTicks.slice();
      const at = (v) => p.x + axisFraction(v, xr0, xr1, xs) * p.width;
      const shown = xs === 'log' ? thinLogTicks(xTicks, logTicks(xr0, xr1), at, LOG_LABEL_PX.x) : xTicks;
      const fmt = xs === 'log' ? formatLogTick : tickFormatter(xTicks);
      const top = p.y + p.height + 3;
      placeTicks(e.xTicks, shown, fmt, (v) => `translate(${at(v).toFixed(1)}px, ${top.toFixed(1)}px) translateX(-50%)`);
    }
    if (yChanged) {
      e.yr0 = yr0;
      e.yr1 = yr1;
      e.ys = ys;
      e.yTickVals = yTicks.slice();
      const at = (v) => p.y + p.height - axisFraction(v, yr0, yr1, ys) * p.height;
      const shown = ys === 'log' ? thinLogTicks(yTicks, logTicks(yr0, yr1), at, LOG_LABEL_PX.y) : yTicks;
      const fmt = ys === 'log' ? formatLogTick : tickFormatter(yTicks);
      const right = p.x - 5;
      placeTicks(e.yTicks, shown, fmt, (v) => `translate(${right.toFixed(1)}px, ${at(v).toFixed(1)}px) translate(-100%, -50%)`);
    }
    if (titlesChanged) {
      e.xLabel = p.x_label;
      e.yLabel = p.y_label;
      e.caption = caption;
      const yTitle = p.y_label || caption || '';
      setText(e.yTitle, yTitle);
      e.yTitle.hidden = !yTitle;
      setText(e.xTitle, p.x_label || '');
      e.xTitle.hidden = !p.x_label;
      if (roomAbove(panels, i) >= TITLE_ROW_PX) {
        // A header row above the panel: y title on the left, x title on the right.
        e.yTitle.style.transform = `translate(${p.x.toFixed(1)}px, ${(p.y - 2).toFixed(1)}px) translate(-0.25rem, -100%)`;
        e.xTitle.style.transform = `translate(${(p.x + p.width).toFixed(1)}px, ${(p.y - 2).toFixed(1)}px) translate(calc(-100% + 0.25rem), -100%)`;
        e.yTitle.classList.remove('inside');
        e.xTitle.classList.remove('inside');
        // A narrow panel (the pole plot): if the two titles would overlap, the x title goes inside
        // the bottom-left corner (the right half plane, where trouble shows, stays clear).
        if (p.x_label && p.y_label && e.yTitle.offsetWidth + e.xTitle.offsetWidth + 6 > p.width + 8) {
          e.xTitle.style.transform = `translate(${(p.x + 3).toFixed(1)}px, ${(p.y + p.height - 3).toFixed(1)}px) translateY(-100%)`;
          e.xTitle.classList.add('inside');
        }
      } else {
        // No room: inside the panel's top-left and bottom-right corners.
        e.yTitle.style.transform = `translate(${(p.x + 6).toFixed(1)}px, ${(p.y + 4).toFixed(1)}px)`;
        e.xTitle.style.transform = `translate(${(p.x + p.width - 6).toFixed(1)}px, ${(p.y + p.height - 4).toFixed(1)}px) translate(-100%, -100%)`;
        e.yTitle.classList.add('inside');
        e.xTitle.classList.add('inside');
      }
    }
  }
  axes.forEach(hideIfUnseen);

  const mag = layout.spring_magnification;
  if (typeof mag === 'number' && Number.isFinite(mag) && mag !== shownMagnification) {
    shownMagnification = mag;
    setText(el.spring, `spring twist ×${Number(mag.toPrecision(3))}`);
  }
}

// ---------------------------------------------------------------------------------------------
// Renderer
// ---------------------------------------------------------------------------------------------

function showCanvasProblem(title, detail) {
  const strong = document.createElement('strong');
  strong.textContent = title;
  const span = document.createElement('span');
  span.textContent = detail;
  el.canvasMessage.replaceChildren(strong, span);
  el.canvasMessage.hidden = false;
  el.canvas.hidden = true;
}

let resizeObserver = null;
let dprQuery = null;
let cssSize = { w: 0, h: 0 };

function resizeRenderer() {
  const r = state.renderer;
  if (!r || cssSize.w <= 0 || cssSize.h <= 0) return;
  const ok = guard('Renderer resize failed', () => {
    r.resize(cssSize.w, cssSize.h, window.devicePixelRatio || 1);
    return true;
  }, false);
  if (ok) {
    state.needsRender = true;
    state.layoutPending = true;
  }
}

function watchDevicePixelRatio() {
  if (dprQuery) dprQuery.removeEventListener('change', onDprChange);
  dprQuery = window.matchMedia(`(resolution: ${window.devicePixelRatio || 1}dppx)`);
  dprQuery.addEventListener('change', onDprChange);
}

function onDprChange() {
  watchDevicePixelRatio();
  resizeRenderer();
}

function observeSize() {
  resizeObserver = new ResizeObserver((entries) => {
    for (const entry of entries) {
      const box = entry.contentRect;
      cssSize = { w: Math.round(box.width), h: Math.round(box.height) };
    }
    resizeRenderer();
  });
  resizeObserver.observe(el.canvasWrap);
  const rect = el.canvasWrap.getBoundingClientRect();
  cssSize = { w: Math.round(rect.width), h: Math.round(rect.height) };
  watchDevicePixelRatio();
}

function applyRendererOptions() {
  const r = state.renderer;
  if (!r) return;
  guard('Renderer options', () => r.setOptions({ show_torque: el.showTorque.checked }));
  // Newer options: a renderer that does not know them throws; it then keeps drawing without them.
  trySetOption(r, 'show_poles', el.showPoles.checked);
  trySetOption(r, 'show_map', el.showMap.checked);
  state.needsRender = true;
  state.layoutPending = true;
}

function trySetOption(r, name, value) {
  if (state.rendererCaps[name] === false) return;
  try {
    r.setOptions({ [name]: value });
    state.rendererCaps[name] = true;
  } catch (e) {
    state.rendererCaps[name] = false;
    console.info(`flexarm: this renderer has no option ${name} (${messageOf(e)})`);
  }
}

async function createRenderer() {
  performance.mark('flexarm:renderer-start');
  const Renderer = state.wasm.Renderer;
  if (typeof Renderer !== 'function' || typeof Renderer.create !== 'function') {
    setText(el.backend, 'renderer unavailable');
    el.backend.dataset.backend = 'none';
    setText(el.spring, 'spring twist ×—');
    showCanvasProblem(
      'Renderer unavailable',
      'This build has no drawing code; the simulation, status and readouts still run.',
    );
    return;
  }
  try {
    const r = await Renderer.create(el.canvas);
    performance.mark('flexarm:renderer-ready');
    if (state.dead) return;
    state.renderer = r;
    const backend = guard('Renderer backend', () => r.backend(), '?');
    setText(el.backend, String(backend));
    el.backend.dataset.backend = String(backend);
    applyRendererOptions();
    resizeRenderer();
    pushAllMaps();
  } catch (e) {
    const msg = messageOf(e);
    setText(el.backend, 'none');
    el.backend.dataset.backend = 'none';
    showCanvasProblem(
      'This browser cannot draw the animation (neither WebGPU nor WebGL2 works).',
      `${msg} — the simulation, status and readouts still run.`,
    );
    showError(`Renderer: ${msg}`);
  }
}

function renderFrame() {
  const r = state.renderer;
  if (!r) return;
  flushMaps();
  try {
    if (state.compare && state.simB && typeof r.renderPair === 'function') r.renderPair(state.sim, state.simB);
    else r.render(state.sim);
    state.rendererFailures = 0;
  } catch (e) {
    state.rendererFailures += 1;
    reportError('Drawing failed', e);
    if (state.rendererFailures >= 3) {
      state.renderer = null;
      showCanvasProblem('Drawing stopped after repeated errors.', messageOf(e));
    }
    return;
  }
  const layout = guard('Renderer layout', () => r.layout(), null);
  if (layout) {
    state.lastLayout = layout;
    updateAxes(layout);
    if (state.compare) updateLegend();
  }
  state.layoutPending = false;
}

// ---------------------------------------------------------------------------------------------
// Animation loop
// ---------------------------------------------------------------------------------------------

/** Frame statistics, averaged over each status interval (window.flexarmStats). */
const stats = {
  fps: 0,
  advance_ms: 0,
  render_ms: 0,
  /** Simulated seconds per wall-clock second actually achieved. */
  sim_rate: 0,
  frames: 0,
};
const acc = { frames: 0, advanceMs: 0, renders: 0, renderMs: 0, wall: 0, sim: 0 };

function publishStats() {
  if (acc.wall > 0) {
    stats.fps = Math.round(acc.frames / acc.wall);
    stats.sim_rate = Number((acc.sim / acc.wall).toFixed(3));
  }
  stats.advance_ms = acc.frames ? Number((acc.advanceMs / acc.frames).toFixed(3)) : 0;
  stats.render_ms = acc.renders ? Number((acc.renderMs / acc.renders).toFixed(3)) : 0;
  stats.frames += acc.frames;
  acc.frames = 0;
  acc.advanceMs = 0;
  acc.renders = 0;
  acc.renderMs = 0;
  acc.wall = 0;
  acc.sim = 0;
}
window.flexarmStats = stats;

/** Script time of each frame callback (ms), a ring of the last FRAME_SAMPLES frames, and the time
 * from navigation start to the first drawn frame. `window.flexarmPerf()` summarises them. */
const FRAME_SAMPLES = 1200;
const frameTimes = new Float64Array(FRAME_SAMPLES);
let frameCount = 0;
let firstFrameMs = null;
window.flexarmPerf = () => {
  const n = Math.min(frameCount, FRAME_SAMPLES);
  const sorted = Array.from(frameTimes.subarray(0, n)).sort((a, b) => a - b);
  const pick = (q) => (n ? sorted[Math.min(n - 1, Math.floor(q * n))] : null);
  return { frames: frameCount, first_frame_ms: firstFrameMs, script_ms_median: pick(0.5), script_ms_p99: pick(0.99),
    sim_rate: stats.sim_rate, fps: stats.fps, backend: state.renderer ? state.renderer.backend() : null,
    map_ms: maps.times.length ? maps.times[maps.times.length - 1].ms : null,
    map_compute_ms: maps.times.length ? maps.times[maps.times.length - 1].compute_ms : null,
    map_points: MAP_POINTS,
    map_times: maps.times.map((t) => ({ ...t })),
    marks: Object.fromEntries(performance.getEntriesByType('mark').map((m) => [m.name, Math.round(m.startTime)])) };
};

function frame(ts) {
  if (state.dead) return;
  requestAnimationFrame(frame);
  const sim = state.sim;
  if (!sim) return;
  const start = performance.now();
  frameBody(sim, ts);
  const end = performance.now();
  frameTimes[frameCount % FRAME_SAMPLES] = end - start;
  frameCount += 1;
}

function frameBody(sim, ts) {

  const last = state.lastTs;
  state.lastTs = ts;
  const wallDt = last == null ? 0 : clamp((ts - last) / 1000, 0, MAX_WALL_DT);

  acc.frames += 1;
  acc.wall += wallDt;
  if (state.playing && !state.finished && wallDt > 0) {
    try {
      const t0 = performance.now();
      acc.sim += sim.advance(wallDt, state.speed);
      acc.advanceMs += performance.now() - t0;
      state.needsRender = true;
      if (sim.isFinished()) {
        state.finished = true;
        state.forceStatus = true;
      }
    } catch (e) {
      reportError('Simulation step failed', e);
      state.playing = false;
      updatePlayButton();
    }
  }
  const simB = state.compare ? state.simB : null;
  if (simB && state.playing && !state.finishedB && wallDt > 0) {
    // The same wall time and speed as A: the two runs stay on one clock.
    try {
      simB.advance(wallDt, state.speed);
      state.needsRender = true;
      if (simB.isFinished()) {
        state.finishedB = true;
        state.forceStatus = true;
      }
    } catch (e) {
      reportError('Simulation step failed (run B)', e);
      state.finishedB = true;
    }
  }

  if (state.needsRender || state.layoutPending) {
    state.needsRender = false;
    if (state.renderer) {
      const t0 = performance.now();
      renderFrame();
      acc.renderMs += performance.now() - t0;
      acc.renders += 1;
      if (firstFrameMs === null) {
        firstFrameMs = performance.now();
        performance.mark('flexarm:first-frame');
      }
    }
  }

  if (state.forceStatus || ts >= state.statusDue) {
    const periodic = ts >= state.statusDue;
    state.forceStatus = false;
    state.statusDue = ts + STATUS_INTERVAL_MS;
    updateStatus();
    if (periodic) publishStats();
  }
}

// ---------------------------------------------------------------------------------------------
// Keyboard
// ---------------------------------------------------------------------------------------------

function isTextLike(target) {
  if (!(target instanceof HTMLElement)) return false;
  if (target.isContentEditable) return true;
  const tag = target.tagName;
  if (tag === 'TEXTAREA' || tag === 'SELECT') return true;
  if (tag === 'INPUT') return !['range', 'checkbox', 'radio', 'button', 'submit', 'reset'].includes(target.type);
  return false;
}

function onKeyDown(ev) {
  if (ev.defaultPrevented || ev.ctrlKey || ev.metaKey || ev.altKey) return;
  const t = ev.target;
  if (isTextLike(t)) return;
  const tag = t instanceof HTMLElement ? t.tagName : '';
  const type = tag === 'INPUT' ? t.type : '';
  if (ev.key === ' ' || ev.code === 'Space') {
    // Buttons and check boxes use space themselves.
    if (tag === 'BUTTON' || type === 'checkbox' || type === 'radio') return;
    ev.preventDefault();
    togglePlay();
  } else if (ev.key === 'ArrowRight') {
    if (type === 'range') return; // the slider moves
    ev.preventDefault();
    stepOnce();
  } else if (ev.key === 'r' || ev.key === 'R') {
    ev.preventDefault();
    resetRun();
  }
}

// ---------------------------------------------------------------------------------------------
// Start-up
// ---------------------------------------------------------------------------------------------

function wireControls() {
  el.delta.addEventListener('input', onDeltaInput);
  el.alpha1.addEventListener('input', () => onAlphaInput(0));
  el.alpha2.addEventListener('input', () => onAlphaInput(1));
  el.linkAlpha.addEventListener('change', onLinkChange);
  el.pf.addEventListener('change', () => onEnumChange('pf'));
  el.friction.addEventListener('change', () => onEnumChange('friction'));
  el.inner.addEventListener('change', () => onEnumChange('inner'));
  el.repeat.addEventListener('change', onRepeatChange);
  el.preset.addEventListener('change', onPresetChange);
  el.speed.addEventListener('input', onSpeedInput);
  el.showTorque.addEventListener('change', applyRendererOptions);
  el.showPoles.addEventListener('change', () => {
    hideTip();
    applyRendererOptions();
  });
  el.showMap.addEventListener('change', () => {
    hideTip();
    onShowMapChange();
  });
  el.compare.addEventListener('change', () => setCompare(el.compare.checked));
  el.bPf.addEventListener('change', onBPfChange);
  el.bDelta.addEventListener('input', onBDeltaInput);
  el.bAlpha.addEventListener('input', onBAlphaInput);
  el.canvas.addEventListener('pointermove', onCanvasPointer);
  el.canvas.addEventListener('pointerdown', onCanvasPointer);
  el.canvas.addEventListener('pointerleave', (ev) => {
    if (ev.pointerType === 'mouse' && !tipPinned) hideTip();
  });
  el.canvas.addEventListener('click', onCanvasClick);
  document.addEventListener('pointerdown', (ev) => {
    if (tipPinned && ev.target !== el.canvas) hideTip();
  });
  for (const b of document.querySelectorAll('button.try')) {
    b.addEventListener('click', () => tryAction(b.dataset.try));
  }
  el.play.addEventListener('click', togglePlay);
  el.step.addEventListener('click', stepOnce);
  el.reset.addEventListener('click', resetRun);
  el.poke.addEventListener('click', poke);
  el.exportCsv.addEventListener('click', exportCsv);
  document.addEventListener('keydown', onKeyDown);
}

function setControlsEnabled(enabled) {
  for (const node of [el.play, el.step, el.reset, el.poke, el.delta, el.alpha1, el.alpha2, el.linkAlpha,
    el.pf, el.friction, el.inner, el.repeat, el.preset, el.speed, el.showTorque, el.exportCsv,
    el.showPoles, el.showMap, el.compare, el.bPf, el.bDelta, el.bAlpha, ...document.querySelectorAll('button.try')]) {
    node.disabled = !enabled;
  }
}

/** The starting configuration: defaults with the repeated slew, then the URL. */
function initialConfig() {
  const { Simulation } = state;
  let config = Simulation.defaultConfig();
  config.reference.repeat_hold = REPEAT_HOLD;
  const { out, invalid } = parseUrl(window.location.search);
  const notices = [];

  if (out.preset != null && out.preset !== '') {
    try {
      config = Simulation.presetConfig(out.preset, config);
      state.presetId = out.preset;
    } catch (e) {
      const ids = Array.from(el.preset.options).map((o) => o.value).filter(Boolean);
      notices.push(`Ignored invalid URL value preset=${out.preset} (allowed ${ids.join(' | ')}); using no preset`);
    }
  }

  // Fallbacks are the values in force after the preset (or the defaults).
  const fallback = {
    delta: config.controller.sampling_period,
    alpha1: config.controller.alpha[0],
    alpha2: config.controller.alpha[1],
    speed: RANGES.speed.def,
  };
  const units = { delta: ' s', alpha1: ' 1/s', alpha2: ' 1/s', speed: '×' };
  for (const bad of invalid) {
    let using;
    if (bad.name in fallback) using = `${fallback[bad.name]}${units[bad.name]}`;
    else if (bad.name in ENUMS) using = config[ENUMS[bad.name].field];
    else if (bad.name === 'repeat') using = '1 (repeat the slew)';
    else if (bad.name === 'compare') using = '0 (one run)';
    else if (bad.name.startsWith('b_')) using = "run B's default (A's settings with the preliminary feedback switched)";
    notices.push(`Ignored invalid URL value ${bad.name}=${bad.raw} (allowed ${bad.allowed}); using ${using}`);
  }

  if (out.delta != null) config.controller.sampling_period = out.delta;
  if (out.alpha1 != null) config.controller.alpha[0] = out.alpha1;
  if (out.alpha2 != null) config.controller.alpha[1] = out.alpha2;
  for (const [name, value] of Object.entries(out.enums)) config[ENUMS[name].field] = value;
  if (out.repeat != null) config.reference.repeat_hold = out.repeat ? REPEAT_HOLD : null;
  if (out.speed != null) state.speed = out.speed;
  state.urlB = out;

  // A URL that changes what the preset set is no longer that preset.
  if (state.presetId) {
    const p = Simulation.presetConfig(state.presetId, config);
    if (!sameControllerSettings(p, config)) state.presetId = '';
  }

  showUrlNotices(notices);
  return config;
}

function fillPresets() {
  const list = guard('presets', () => state.Simulation.presets(), []);
  for (const p of list || []) {
    const opt = document.createElement('option');
    opt.value = p.id;
    opt.textContent = p.title;
    el.preset.appendChild(opt);
  }
}

async function main() {
  setControlsEnabled(false);
  wireControls();
  updatePlayButton();

  let mod;
  try {
    mod = await import('./pkg/flexarm.js');
    await mod.default();
    performance.mark('flexarm:wasm-ready');
  } catch (e) {
    setText(el.loadingText, 'Could not load the simulation.');
    el.loading.querySelector('.spinner')?.remove();
    showError(`Loading ./pkg/flexarm.js failed: ${messageOf(e)}. Build it with "wasm-pack build --target web --release --out-dir www/pkg".`);
    return;
  }
  state.wasm = mod;
  state.Simulation = mod.Simulation;

  fillPresets();
  let config;
  try {
    config = initialConfig();
  } catch (e) {
    reportError('Reading the settings failed', e);
    config = guard('defaultConfig', () => state.Simulation.defaultConfig(), undefined);
  }

  try {
    state.sim = new state.Simulation(config);
  } catch (e) {
    reportError('Could not start the simulation with these settings; using the defaults', e);
    state.presetId = '';
    config = state.Simulation.defaultConfig();
    config.reference.repeat_hold = REPEAT_HOLD;
    state.sim = guard('Simulation', () => new state.Simulation(config), null);
    if (!state.sim) return;
  }
  state.desired = guard('config', () => state.sim.config(), config);
  el.linkAlpha.checked = state.desired.controller.alpha[0] === state.desired.controller.alpha[1];
  syncControlsFromDesired();
  state.rhoPreview = guard('spectralRadius', () => mod.spectralRadius(state.desired), null);
  writeUrl();

  const u = state.urlB;
  if (u && u.compare) {
    const b = defaultB();
    if (u.bPf != null) b.pf = u.bPf;
    if (u.bDelta != null) b.delta = u.bDelta;
    if (u.bAlpha != null) b.alpha = [u.bAlpha, u.bAlpha];
    setCompare(true, { b });
    setRunNote('');
  }

  el.loading.hidden = true;
  setControlsEnabled(true);
  observeSize();
  requestAnimationFrame(frame);
  await createRenderer();
  // The maps start once the first frame's work is done, so they do not delay it.
  maps.started = true;
  ensureMaps();
}

main();

// For debugging in the console (and for tests): the live state.
window.flexarm = state;
