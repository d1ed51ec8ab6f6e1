// flexarm's page: loads the simulation, opens a session from the URL, and wires the page's parts
// (each a module with one job) to the session, the renderer, the frame loop and each other. Every
// decision about the physics is the session's (Rust); this file only connects.

import { createHomework } from './homework.js';
import { byId } from './dom.js';
import { createErrors } from './errors.js';
import { createStore } from './store.js';
import { begin, openPage } from './boot.js';
import { createStatus } from './status.js';
import { createOverlays } from './overlays.js';
import { createLoop } from './loop.js';
import { createSettings } from './settings.js';
import { createTransport } from './transport.js';
import { createPresent } from './present.js';
import { download, wireOutputs } from './outputs.js';
import { createExport } from './export.js';
import { createEmbedBuilder } from './embed.js';
import { createSheet, showFigure } from './sheet.js';
import { wireKeys } from './keys.js';
import { wireTryButtons } from './explain.js';
import { createClassroom } from './classroom.js';
import { createFigure } from './figure.js';
import { createRefresh } from './refresh.js';
import { createDesign } from './design.js';
import { createSensors } from './sensors.js';
import { createSaveOffline } from './save_offline.js';
import { installHooks } from './hooks.js';
import { startRenderer } from './renderer.js';

/** @typedef {import('./flexarm.js').Page} Page */

const store = createStore();
const errors = createErrors(store);
const { guard } = errors;
/** @param {string} what @param {unknown} e */
const report = (what, e) => errors.report(what, e);

main().catch((e) => errors.report('Starting the page failed', e));

async function main() {
  const opened = await openPage(errors);
  if (!opened) return;
  const { wasm, session, rendererReady } = opened;
  const status = createStatus();
  const overlays = createOverlays();
  // The frame loop; what it draws and says (`figure`, `refresh`) is built below.
  const loop = createLoop({
    wasmOk: () => !store.get().dead,
    playing: () => store.get().playing,
    finished: () => session.isFinished() && session.status().runs.every((/** @type {{ finished: boolean }} */ r) => r.finished),
    advance: (dt) => guard('Simulation step failed', () => session.advance(dt), 0) ?? 0,
    render: () => figure.render(),
    animating: () => figure.renderer()?.animating() ?? false,
    status: () => refresh(),
    workMaps: (budget) => guard('Stability map', () => session.workMaps(budget), false) ?? false,
    backend: () => figure.renderer()?.backend() ?? null,
  });
  const touch = () => loop.touch();

  // Changes go to the session; the picture follows them.
  const settings = createSettings({
    wasm, session, store, guard,
    reset: () => transport.reset(),
    synced: (value) => present.sync(value),
    changed: () => {
      loop.touch();
      loop.resync();
      figure.hidePointer();
      loop.scheduleMaps();
      sensors.changed();
    },
  });
  const { change } = settings;
  const transport = createTransport({ session, store, guard, change, loop, refresh: () => refresh() });
  const { togglePlay, reset } = transport;
  const present = createPresent({
    set: (key, value) => change(() => session.set(key, value)),
    step: (key, steps) => change(() => session.stepValue(key, steps)),
    togglePlay,
    reset,
    textChoices: (wasm.schema().find((/** @type {any} */ p) => p.key === 'text')?.options ?? []).map((/** @type {string[]} */ [value, label]) => ({ value, label })),
    momentQuery: () => session.momentQuery(),
    pause: () => store.dispatch({ type: 'pause' }),
  });
  const sensors = createSensors({
    study: (runs) => guard('Sensor study', () => session.sensorStudy(runs), null),
    processor: () => guard('Controller time', () => session.controllerTime().text, null),
    setDelta: (delta) => change(() => session.set('delta', String(delta))),
    drawn: () => guard('Sensor study', () => session.studyDrawn(), false) ?? false,
    touch,
  });
  wireOutputs({ session, guard });
  const canvas = /** @type {HTMLCanvasElement} */ (byId('canvas'));
  createExport({ session, canvas, overlay: byId('axes-overlay'), renderNow: () => figure.render(), renderer: () => figure.renderer(), touch, download, report });
  createEmbedBuilder({ session });
  createSaveOffline({ wasm, session, paused: () => !store.get().playing, download, report });
  const sheet = createSheet();
  wireKeys({ togglePlay, step: transport.step, stepBack: transport.stepBack, reset, zoomKey: (ev) => figure.zoomKey(ev) });
  wireTry(session, settings, sheet);

  // What the session says: the lesson, the figure, the status.
  const homework = createHomework({ wasm, session, report });
  const { lesson, answers } = createClassroom({
    session, store, presets: wasm.presets(), guard, report, change, refresh: () => refresh(), touch, openSheet: sheet.open, showFigure, download,
    mergeAnswers: (names, texts) => session.mergeAnswers(names, texts),
    loaded: () => {
      homework.refresh();
      // A reload keeps the lesson: it moves into the address, as a homework link carries it.
      homework.keepInAddress().then(() => {
        change(() => {}); // the address names its step now
        refresh();
      });
    },
  });
  // The pair placed by hand: the session answers "" or why not; the status follows at once.
  const placing = (/** @type {() => string} */ fn) => {
    let why = '';
    change(() => { why = fn(); });
    refresh();
    return why;
  };
  const design = createDesign({
    place: (re, im) => placing(() => session.placePair(re, im)),
    nudge: (re, im) => placing(() => session.nudgePair(re, im)),
  });
  const figure = createFigure({ session, store, overlays, guard, report, change, scrubTo: transport.scrubTo, touch, design });
  const refresh = createRefresh({
    session, guard, status, transport, present, lesson, answers, timeline: transport.timeline, layout: figure.layout, openSheet: sheet.open, design,
  });
  installHooks({ session, wasm, store, show: errors.show, status, controls: settings.controls, layout: figure.layout, figures: loop.figures });

  begin({ session, store, sync: settings.sync, loop });
  sensors.changed();
  await startRenderer({ ready: rendererReady, use: figure.use, current: figure.renderer, store, guard, show: errors.show, touch });
  loop.touch();
  // The maps start once the first frame's work is done, so they do not delay it.
  loop.scheduleMaps();
}

/**
 * The explanation's "Try:" buttons: each makes its settings, plays, and shows the figure.
 * @param {Page} session
 * @param {ReturnType<typeof createSettings>} settings
 * @param {ReturnType<typeof createSheet>} sheet
 */
function wireTry(session, { change, unlinkAlpha }, sheet) {
  wireTryButtons({
    preset: (id) => change(() => session.applyPreset(id)),
    set: (key, value) => change(() => session.set(key, value)),
    sets: (pairs) => {
      // Unequal α1, α2 are meant: unlink the sliders first.
      if (pairs.some(([k]) => k === 'alpha1' || k === 'alpha2')) unlinkAlpha();
      change(() => pairs.forEach(([k, v]) => session.set(k, v)));
    },
    // Settings that only fit together (k and m): read at once, as a link is.
    state: (query) => change(() => session.readState(query)),
    map: (side, delta, alpha) => change(() => {
      session.set('map', '1');
      session.setFromMap(side, delta, alpha);
    }),
    after: (stay) => {
      store.dispatch({ type: 'play' });
      if (stay) return;
      // On a phone the sheet would cover what the button changed.
      sheet.open(false);
      showFigure();
    },
  });
}
