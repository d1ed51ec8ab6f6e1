// The frame loop: advance the session by the wall time passed, draw, refresh the labels when the
// frame's description changed, the status a few times a second; and the maps' work in chunks
// between frames. It also keeps the performance figures `window.flexarmPerf()` reports.

/** Longest wall-clock step one frame may advance, s (a stalled tab skips ahead). */
const MAX_WALL_DT = 0.1;
/** The status is refreshed at most this often, ms. */
const STATUS_INTERVAL_MS = 200;
/** Wall time per chunk of map work, ms: the page stays responsive. */
const MAP_BUDGET_MS = 8;
/** Frames whose script time is kept for the figures. */
const FRAME_SAMPLES = 1200;

/**
 * @param {{ wasmOk: () => boolean, playing: () => boolean, advance: (dt: number) => number, finished: () => boolean,
 *   render: () => boolean, status: () => void, workMaps: (budget: number) => boolean, backend: () => string | null,
 *   animating?: () => boolean }} on
 */
export function createLoop(on) {
  const perf = { frames: 0, firstFrameMs: /** @type {number | null} */ (null), times: new Float64Array(FRAME_SAMPLES), mapWork: false };
  const acc = { frames: 0, wall: 0, sim: 0, fps: 0, simRate: 0 };
  let lastTs = /** @type {number | null} */ (null);
  let statusDue = 0;
  let dirty = true;
  let statusNow = true;

  function frame(/** @type {number} */ ts) {
    if (!on.wasmOk()) return;
    requestAnimationFrame(frame);
    const start = performance.now();
    const wallDt = lastTs == null ? 0 : Math.min(Math.max((ts - lastTs) / 1000, 0), MAX_WALL_DT);
    lastTs = ts;
    acc.frames += 1;
    acc.wall += wallDt;
    if (on.playing() && wallDt > 0 && !on.finished()) {
      acc.sim += on.advance(wallDt);
      dirty = true;
    }
    if (dirty || on.animating?.()) {
      dirty = false;
      if (on.render() && perf.firstFrameMs === null) {
        perf.firstFrameMs = performance.now();
        performance.mark('flexarm:first-frame');
      }
    }
    if (statusNow || ts >= statusDue) {
      if (ts >= statusDue && acc.wall > 0) {
        acc.fps = Math.round(acc.frames / acc.wall);
        acc.simRate = Number((acc.sim / acc.wall).toFixed(3));
        Object.assign(acc, { frames: 0, wall: 0, sim: 0 });
      }
      statusNow = false;
      statusDue = ts + STATUS_INTERVAL_MS;
      on.status();
    }
    perf.times[perf.frames % FRAME_SAMPLES] = performance.now() - start;
    perf.frames += 1;
  }

  // The next chunk runs as a fresh task right away (a MessageChannel message: nested
  // setTimeout(0) would wait ≥ 4 ms each time); frames and input still get their turn between.
  const channel = new MessageChannel();
  channel.port1.onmessage = () => {
    perf.mapWork = false;
    if (!on.wasmOk()) return;
    const more = on.workMaps(MAP_BUDGET_MS);
    dirty = true;
    statusNow = true;
    if (more) scheduleMaps();
  };
  function scheduleMaps() {
    if (perf.mapWork) return;
    perf.mapWork = true;
    channel.port2.postMessage(0);
  }

  /** The performance figures so far. @param {object} extra */
  function figures(extra) {
    const n = Math.min(perf.frames, FRAME_SAMPLES);
    const sorted = Array.from(perf.times.subarray(0, n)).sort((a, b) => a - b);
    const pick = (/** @type {number} */ q) => (n ? sorted[Math.min(n - 1, Math.floor(q * n))] : null);
    return {
      frames: perf.frames,
      first_frame_ms: perf.firstFrameMs,
      script_ms_median: pick(0.5),
      script_ms_p99: pick(0.99),
      sim_rate: acc.simRate,
      fps: acc.fps,
      backend: on.backend(),
      marks: Object.fromEntries(performance.getEntriesByType('mark').map((m) => [m.name, Math.round(m.startTime)])),
      ...extra,
    };
  }

  return {
    start: () => requestAnimationFrame(frame),
    /** Something changed: draw again and say so. */
    touch() {
      dirty = true;
      statusNow = true;
    },
    /** The wall clock restarts (after a pause or a restart of the run). */
    resync() {
      lastTs = null;
    },
    scheduleMaps,
    figures,
  };
}
