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
  const out = { preset: null, delta: null, alpha1: null, alpha2: null, speed: null, repeat: null, enums: {} };
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
  if (el.runNote.textContent.startsWith('Paused')) setRunNote('');
  state.needsRender = true;
  state.forceStatus = true;
}

function resetRun() {
  if (!state.sim) return;
  guard('Reset failed', () => state.sim.reset());
  state.finished = false;
  state.lastTs = null;
  setRunNote('');
  state.needsRender = true;
  state.forceStatus = true;
}

function poke() {
  if (!state.sim) return;
  guard('Poke failed', () => state.sim.poke(POKE.t1, POKE.t2, POKE.duration));
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

  let detail;
  if (verdict === 'diverged') {
    const at = m.diverged_at != null ? m.diverged_at.toFixed(2) : '?';
    const why = DIVERGENCE_REASONS[m.divergence_reason] || '';
    detail = `diverged at t = ${at} s${why ? ` (${why})` : ''} — change a parameter or press reset`;
  } else if (m.growth_rate == null) {
    detail = 'so far — no growth measured yet';
  } else if (verdict === 'unstable') {
    detail = 'the errors grow exponentially';
  } else {
    detail = 'the errors stay bounded';
  }
  setText(el.verdictDetail, detail);

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
  let rhoText = 'linear analysis: ρ = —';
  if (rho != null && Number.isFinite(rho)) {
    rhoText = `linear analysis: ρ = ${rho.toFixed(4)} ${rho < 1 ? '< 1 ⇒ stable' : '≥ 1 ⇒ unstable'}`;
    const a = state.analysis;
    if (a && !state.analysisStale && Number.isFinite(a.growth_rate)) {
      rhoText += ` (ln ρ/δ = ${minus(a.growth_rate.toFixed(2))} 1/s)`;
    }
  }
  setText(el.verdictRho, rhoText);

  // Readouts
  setText(el.roTime, `${m.time.toFixed(2)} s`);
  if (s) setText(el.roError, `${sci(s.error[0])}, ${sci(s.error[1])} rad`);
  setText(el.roMaxSlew, `${sci(m.max_error_slew[0])}, ${sci(m.max_error_slew[1])} rad`);
  setText(el.roMaxAfter, `${sci(m.max_error_after[0])}, ${sci(m.max_error_after[1])} rad`);
  setText(el.roTorque, `${sig(m.max_torque[0])}, ${sig(m.max_torque[1])} N m`);
  const a = state.analysis;
  setText(el.roA4, a && !state.analysisStale ? formatPair(a.limit_pair) : '—');
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
      xTicks: [],
      yTicks: [],
      // last applied values
      x: NaN, y: NaN, w: NaN, h: NaN,
      xr0: NaN, xr1: NaN, yr0: NaN, yr1: NaN,
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
  for (const s of entry.xTicks) s.hidden = true;
  for (const s of entry.yTicks) s.hidden = true;
  entry.x = NaN; // force a full update when it comes back
}

const seenPanels = new Set();
let shownMagnification = NaN;
const NO_TICKS = Object.freeze([]);
/** Captions for panels that have no axis titles. */
const PANEL_CAPTIONS = { arm: 'arm, top view' };

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
    const xTicks = p.x_ticks || NO_TICKS;
    const yTicks = p.y_ticks || NO_TICKS;
    const geometryChanged = e.x !== p.x || e.y !== p.y || e.w !== p.width || e.h !== p.height;
    const xChanged = geometryChanged || e.xr0 !== xr0 || e.xr1 !== xr1 || !sameArray(xTicks, e.xTickVals);
    const yChanged = geometryChanged || e.yr0 !== yr0 || e.yr1 !== yr1 || !sameArray(yTicks, e.yTickVals);
    const titlesChanged = anyGeometryChanged || e.xLabel !== p.x_label || e.yLabel !== p.y_label;
    if (!xChanged && !yChanged && !titlesChanged) continue;
    e.visible = true;
    e.x = p.x;
    e.y = p.y;
    e.w = p.width;
    e.h = p.height;

    if (xChanged) {
      e.xr0 = xr0;
      e.xr1 = xr1;
      e.xTickVals = xTicks.slice();
      const span = xr1 - xr0 || 1;
      const fmt = tickFormatter(xTicks);
      const top = p.y + p.height + 3;
      placeTicks(e.xTicks, xTicks, fmt, (v) => {
        const px = p.x + ((v - xr0) / span) * p.width;
        return `translate(${px.toFixed(1)}px, ${top.toFixed(1)}px) translateX(-50%)`;
      });
    }
    if (yChanged) {
      e.yr0 = yr0;
      e.yr1 = yr1;
      e.yTickVals = yTicks.slice();
      const span = yr1 - yr0 || 1;
      const fmt = tickFormatter(yTicks);
      const right = p.x - 5;
      placeTicks(e.yTicks, yTicks, fmt, (v) => {
        const py = p.y + p.height - ((v - yr0) / span) * p.height;
        return `translate(${right.toFixed(1)}px, ${py.toFixed(1)}px) translate(-100%, -50%)`;
      });
    }
    if (titlesChanged) {
      e.xLabel = p.x_label;
      e.yLabel = p.y_label;
      const yTitle = p.y_label || PANEL_CAPTIONS[p.id] || '';
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
  state.needsRender = true;
  state.layoutPending = true;
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
  try {
    r.render(state.sim);
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
  if (layout) updateAxes(layout);
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
  el.play.addEventListener('click', togglePlay);
  el.step.addEventListener('click', stepOnce);
  el.reset.addEventListener('click', resetRun);
  el.poke.addEventListener('click', poke);
  el.exportCsv.addEventListener('click', exportCsv);
  document.addEventListener('keydown', onKeyDown);
}

function setControlsEnabled(enabled) {
  for (const node of [el.play, el.step, el.reset, el.poke, el.delta, el.alpha1, el.alpha2, el.linkAlpha,
    el.pf, el.friction, el.inner, el.repeat, el.preset, el.speed, el.showTorque, el.exportCsv]) {
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
    notices.push(`Ignored invalid URL value ${bad.name}=${bad.raw} (allowed ${bad.allowed}); using ${using}`);
  }

  if (out.delta != null) config.controller.sampling_period = out.delta;
  if (out.alpha1 != null) config.controller.alpha[0] = out.alpha1;
  if (out.alpha2 != null) config.controller.alpha[1] = out.alpha2;
  for (const [name, value] of Object.entries(out.enums)) config[ENUMS[name].field] = value;
  if (out.repeat != null) config.reference.repeat_hold = out.repeat ? REPEAT_HOLD : null;
  if (out.speed != null) state.speed = out.speed;

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

  el.loading.hidden = true;
  setControlsEnabled(true);
  observeSize();
  requestAnimationFrame(frame);
  await createRenderer();
}

main();

// For debugging in the console (and for tests): the live state.
window.flexarm = state;
