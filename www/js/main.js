// flexarm's page: loads the simulation, opens a session from the URL, builds the controls from the
// schema, and wires controls, canvas, keyboard and frame loop to the session and the renderer.
// Every decision about the physics is the session's (Rust); this file only connects.

import { byId, make, messageOf, setText } from './dom.js';
import { createErrors } from './errors.js';
import { createStore } from './store.js';
import { enableTransport, openPage } from './boot.js';
import { createSettings } from './settings.js';
import { START_NOTE, createTransport } from './transport.js';
import { createStatus } from './status.js';
import { createOverlays } from './overlays.js';
import { createPointer } from './pointer.js';
import { createLoop } from './loop.js';
import { wireTryButtons } from './explain.js';
import { wireKeys } from './keys.js';
import { writeUrl } from './url.js';
import { createAnswers } from './answers.js';
import { createLesson } from './lesson.js';
import { createTabs } from './tabs.js';
import { createExport } from './export.js';
import { createEmbedBuilder } from './embed.js';
import { createLegend } from './legend.js';
import { createFocus } from './focus.js';
import { createZoom } from './zoomz.js';
import { createPresent } from './present.js';
import { download, wireOutputs } from './outputs.js';
import { createSheet, showFigure } from './sheet.js';

const store = createStore();
const errors = createErrors(store);
const { guard } = errors;

main().catch((e) => errors.report('Starting the page failed', e));

async function main() {
  const opened = await openPage(errors);
  if (!opened) return;
  const { wasm, session, rendererReady } = opened;
  const status = createStatus();
  const overlays = createOverlays();
  /** @type {import('../pkg/flexarm.js').Renderer | null} */
  let renderer = null;
  /** @type {any} */
  let layout = null;
  let layoutGeneration = -1;
  /** @type {ReturnType<typeof createPresent> | null} */
  let present = null;

  const loop = createLoop({
    wasmOk: () => !store.get().dead,
    playing: () => store.get().playing,
    finished: () => session.isFinished() && session.status().runs.every((r) => r.finished),
    advance: (dt) => guard('Simulation step failed', () => session.advance(dt), 0) ?? 0,
    render,
    animating: () => renderer?.animating() ?? false,
    status: refreshStatus,
    workMaps: (budget) => guard('Stability map', () => session.workMaps(budget), false) ?? false,
    backend: () => (renderer ? renderer.backend() : null),
  });

  // ---------------------------------------------------------------- changes go to the session
  const settings = createSettings({
    wasm, session, store, guard,
    reset: () => reset(),
    synced: (value) => present?.sync(value),
    changed: () => {
      loop.touch();
      loop.resync();
      pointer.hide();
      loop.scheduleMaps();
    },
  });
  const { change } = settings;

  // ---------------------------------------------------------------- transport and view
  const transport = createTransport({ session, store, guard, change, loop, refresh: () => refreshStatus() });
  const { togglePlay, step, stepBack, reset, scrubTo, timeline } = transport;
  present = createPresent({
    set: (key, value) => change(() => session.set(key, value)),
    step: (key, steps) => change(() => session.stepValue(key, steps)),
    togglePlay,
    reset,
    textChoices: (wasm.schema().find((/** @type {any} */ p) => p.key === 'text')?.options ?? []).map((/** @type {string[]} */ [value, label]) => ({ value, label })),
  });
  wireOutputs({ session, guard });
  createExport({
    session,
    canvas: /** @type {HTMLCanvasElement} */ (byId('canvas')),
    overlay: byId('axes-overlay'),
    renderNow: () => render(),
    download,
    report: (/** @type {string} */ what, /** @type {unknown} */ e) => errors.report(what, e),
  });
  createEmbedBuilder({ session });
  const sheet = createSheet();
  wireKeys({
    togglePlay,
    step,
    stepBack,
    reset,
    zoomKey: (ev) => zoom.key(ev, pointer.last()),
  });
  wireTryButtons({
    preset: (id) => change(() => session.applyPreset(id)),
    set: (key, value) => change(() => session.set(key, value)),
    sets: (pairs) => {
      // Unequal α1, α2 are meant: unlink the sliders first.
      if (pairs.some(([k]) => k === 'alpha1' || k === 'alpha2')) settings.unlinkAlpha();
      change(() => pairs.forEach(([k, v]) => session.set(k, v)));
    },
    map: (side, delta, alpha) => change(() => {
      session.set('map', '1');
      session.setFromMap(side, delta, alpha);
    }),
    after: () => {
      store.dispatch({ type: 'play' });
      // On a phone the sheet would cover what the button changed.
      sheet.open(false);
      showFigure();
    },
  });

  // ---------------------------------------------------------------- the lesson and the timeline
  /** A lesson action: the settings it makes, played from the start. */
  const lessonDo = (/** @type {() => void} */ fn) => {
    session.setWallClock(Date.now());
    change(fn);
    // A step may start paused at a moment (`paused=1&t=2`).
    store.dispatch({ type: session.takeStartPaused() ? 'pause' : 'play' });
    refreshStatus();
  };
  const lesson = createLesson({
    start: () => {
      lessonDo(() => session.lessonOpen(0));
      sheet.open(true);
    },
    next: () => lessonDo(() => session.lessonNext()),
    back: () => lessonDo(() => session.lessonBack()),
    leave: () => lessonDo(() => session.lessonLeave()),
    open: async (file) => {
      const bytes = new Uint8Array(await file.arrayBuffer());
      try {
        session.loadLesson(file.name, bytes);
      } catch (e) {
        errors.report('The lesson file could not be used (the lesson stays as it was)', e);
        return;
      }
      lessonDo(() => {});
    },
    answer: (choice) => {
      lessonDo(() => session.lessonAnswer(choice));
      showFigure();
    },
    reveal: () => {
      session.setWallClock(Date.now());
      guard('Lesson', () => session.lessonReveal());
      refreshStatus();
    },
  });
  const answers = createAnswers({
    session,
    presets: wasm.presets(),
    report: (what, e) => errors.report(what, e),
    download,
    changed: () => {
      loop.touch();
      refreshStatus();
    },
  });

  // ---------------------------------------------------------------- canvas
  const tabs = createTabs({ select: (id) => change(() => session.set('tab', id)) });
  const legend = createLegend();
  const focus = createFocus({
    stepOnMap: (side, d, a) => change(() => session.stepOnMap(side, d, a)),
    enterMap: (side) => change(() => session.stepOnMap(side, 0, 0)),
    stepDelta: (d) => change(() => session.stepValue('delta', d)),
    probe: (x, y) => (renderer ? guard('Pointer', () => renderer?.probe(x, y, 2), null) : null),
    showTip: overlays.showTip,
    hideTip: overlays.hideTip,
    zKey: (action) => zoom.by(action),
    attachZ: (el) => pointer.attach(el),
  });
  const zoom = createZoom({ session, renderer: () => renderer, layout: () => layout, guard, changed: () => (writeUrl(session.stateString()), loop.touch()) });
  const pointer = createPointer({
    probe: (x, y, reach) => (renderer ? guard('Pointer', () => renderer?.probe(x, y, reach), null) : null),
    pick: (map, delta, alpha) => change(() => session.setFromMap(map, delta, alpha)),
    pickDelta: (delta) => change(() => session.pickDelta(delta)),
    showTip: overlays.showTip,
    hideTip: overlays.hideTip,
    timeAt: (x, y) => renderer?.timeAt(x, y),
    scrubTo,
    onZ: zoom.on,
    zoomZ: zoom.zoomAt,
    panZ: zoom.panBy,
  });

  /** Draws a frame; refreshes the labels when the frame's description changed. */
  function render() {
    if (!renderer) return false;
    try {
      renderer.render(session.session);
      store.dispatch({ type: 'render-ok' });
    } catch (e) {
      store.dispatch({ type: 'render-failed' });
      errors.report('Drawing failed', e);
      if (store.get().renderFailures >= 3) {
        renderer = null;
        canvasProblem('Drawing stopped after repeated errors.', messageOf(e));
      }
      return false;
    }
    const generation = renderer.infoGeneration();
    if (generation !== layoutGeneration) {
      layout = guard('Renderer layout', () => renderer?.layout(), null);
      layoutGeneration = generation;
      if (layout) {
        overlays.update(layout);
        tabs.render(layout.tabs);
        legend.render(layout.legend);
        focus.update(layout);
        zoom.update(layout);
      }
    }
    overlays.scroll(renderer.windowStart(), renderer.windowEnd());
    return true;
  }

  /** Everything the page says about the session, from one status. */
  const figureDescription = byId('figure-description');
  const zoomCaption = byId('zoom-caption');
  let lessonShown = false;
  function refreshStatus() {
    // The clock the answers' record stamps a task with when the session sees it done.
    session.setWallClock(Date.now());
    const s = guard('Status', () => session.status(), null);
    if (!s) return;
    setText(figureDescription, s.figure);
    zoomCaption.hidden = !s.cycle;
    setText(zoomCaption, s.cycle);
    // A lesson opened from a link shows its step: on a phone, the sheet it lives in opens once.
    if (s.lesson && !lessonShown) {
      lessonShown = true;
      sheet.open(true);
    }
    if (!s.lesson) lessonShown = false;
    status.render(s, performance.now());
    transport.showFinished(s.runs.every((/** @type {{ finished: boolean }} */ r) => r.finished));
    status.renderLegend(s, layout?.series ?? []);
    present?.render(s.runs, layout?.series ?? []);
    lesson.render(s.lesson);
    answers.sync(s.lesson, s.hidden);
    timeline.render(s.timeline);
  }

  window.flexarmPanic = (/** @type {unknown} */ msg) => {
    store.dispatch({ type: 'crash' });
    errors.show(`The simulation crashed (Rust panic) — reload the page to start again. ${messageOf(msg)}`);
    canvasProblem('The simulation crashed.', 'See the error message above; reload the page to start again.');
    status.crashed();
    settings.controls.setEnabled(false);
  };
  // For tests and the console: the live objects, and the performance figures.
  Object.assign(window, {
    flexarm: { session, wasm, store, get lastLayout() { return layout; } },
    flexarmPerf: () => {
      const times = session.mapTimes();
      const last = times[times.length - 1];
      return loop.figures({ map_times: times, map_ms: last ? last.ms : null, map_compute_ms: last ? last.compute_ms : null });
    },
  });

  settings.sync();
  writeUrl(session.stateString());
  byId('loading').hidden = true;
  // A link to a moment (`paused=1&t=3`) opens paused there.
  if (session.takeStartPaused()) {
    store.dispatch({ type: 'pause' });
    session.setNote(START_NOTE);
  }
  // Motion only on request where the system asks for less of it.
  if (matchMedia('(prefers-reduced-motion: reduce)').matches) {
    store.dispatch({ type: 'pause' });
    session.setNote('Paused because your system asks for reduced motion: press Play to run.');
  }
  enableTransport(true);
  loop.start();

  // ---------------------------------------------------------------- the renderer
  try {
    renderer = await rendererReady;
    performance.mark('flexarm:renderer-ready');
    const backend = renderer.backend();
    store.dispatch({ type: 'renderer', backend });
    const label = byId('backend');
    setText(label, backend);
    label.dataset.backend = backend;
    watchSize(() => renderer);
    // The canvas follows the system's colour scheme, as the stylesheet does.
    const dark = matchMedia('(prefers-color-scheme: dark)');
    const scheme = () => {
      renderer?.setDark(dark.matches);
      loop.touch();
    };
    dark.addEventListener('change', scheme);
    scheme();
  } catch (e) {
    setText(byId('backend'), 'none');
    byId('backend').dataset.backend = 'none';
    canvasProblem('This browser cannot draw the animation (neither WebGPU nor WebGL2 works).', `${messageOf(e)} — the simulation, status and readouts still run.`);
    errors.show(`Renderer: ${messageOf(e)}`);
  }
  loop.touch();
  // The maps start once the first frame's work is done, so they do not delay it.
  loop.scheduleMaps();

  /** Keeps the renderer's size that of the canvas' box and the screen's pixel ratio. */
  function watchSize(/** @type {() => any} */ current) {
    const wrap = byId('canvas-wrap');
    const size = { w: 0, h: 0 };
    const resize = () => {
      const r = current();
      if (r && size.w > 0 && size.h > 0) guard('Renderer resize failed', () => r.resize(size.w, size.h, window.devicePixelRatio || 1, window.innerHeight));
      loop.touch();
    };
    new ResizeObserver((entries) => {
      for (const entry of entries) Object.assign(size, { w: Math.round(entry.contentRect.width), h: Math.round(entry.contentRect.height) });
      resize();
    }).observe(wrap);
    const watchDpr = () => {
      matchMedia(`(resolution: ${window.devicePixelRatio || 1}dppx)`).addEventListener('change', () => {
        watchDpr();
        resize();
      }, { once: true });
    };
    watchDpr();
    const rect = wrap.getBoundingClientRect();
    Object.assign(size, { w: Math.round(rect.width), h: Math.round(rect.height) });
    resize();
  }
}

function canvasProblem(/** @type {string} */ title, /** @type {string} */ detail) {
  byId('canvas-message').replaceChildren(make('strong', { text: title }), make('span', { text: detail }));
  byId('canvas-message').hidden = false;
  byId('canvas').hidden = true;
}
