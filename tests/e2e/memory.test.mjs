// A long flat-out run (issue 12): the page at its highest speed, the session advanced flat out
// between frames as well, δ changed and the run reset every few seconds through the page's own
// controls — and the wasm module's memory stays flat. WebAssembly memory only grows, so a leak
// or an unbounded history would show as growth between a warmed-up "before" and the "after".
// Run: node --test tests/e2e/memory.test.mjs (needs the wasm in www/pkg).

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { openPage, shared } from './harness.mjs';

/** Wall time of the measured run, and of the warm-up before it, ms. The heap settles after a
 * few resets (31 → 34 MiB in the first 25 s here, with traces regrown from empty each time, then
 * flat): "before" is taken after that. */
const RUN_MS = 60_000;
const WARM_UP_MS = 30_000;
/** A change through the controls this often, ms (δ changed, then the run reset, in turn). */
const CHANGE_MS = 5_000;
const MiB = 1024 * 1024;

const env = shared();

test('a long flat-out run keeps the wasm memory flat', { timeout: 240_000 }, async () => {
  // Stable runs that never stop (the paper's K_pr, the slew repeating), A and B side by side,
  // every figure shown, at the speed control's maximum.
  const { page, problems, close } = await openPage(env.browser, env.server.base,
    '?preset=fig5.1&repeat=1&mode=full&torque=1&compare=1&b_pf=paper&b_delta=0.02&speed=4');
  try {
    const speed = new URL(page.url()).searchParams.get('speed');
    assert.equal(speed, '4', 'the speed control at its maximum');
    await page.waitForFunction(() => document.querySelector('#map-progress')?.dataset.done === 'true', null, { timeout: 60_000 });
    /** The wasm memory, the JS heap and the frames counted so far. */
    const measure = () => page.evaluate(async () => ({
      wasm: await (await import('/js/wasm.js')).wasmMemoryBytes(),
      // @ts-ignore: Chromium's non-standard heap figure
      js: performance.memory?.usedJSHeapSize ?? 0,
      frames: window.flexarmPerf().frames,
    }));
    const start = await measure();
    // Flat out: between frames, the session advanced as fast as it goes for 30 ms of every 60 ms
    // (each call covers at most 0.25 s); the frame loop keeps drawing at the page's speed.
    await page.evaluate(() => {
      const flexarm = /** @type {any} */ (window).flexarm;
      const w = /** @type {any} */ (window);
      w.flatOut = { simulated: 0, calls: 0 };
      w.flatOutTimer = setInterval(() => {
        const end = performance.now() + 30;
        while (performance.now() < end) {
          w.flatOut.simulated += flexarm.session.advance(1);
          w.flatOut.calls += 1;
        }
      }, 60);
    });
    let changes = 0;
    /** The wasm memory every CHANGE_MS of the measured run, MiB. */
    const samples = [];
    /** Runs for `ms` of wall time, changing δ or resetting every CHANGE_MS through the controls. */
    const run = async (/** @type {number} */ ms, /** @type {number[] | null} */ trace) => {
      const until = Date.now() + ms;
      while (Date.now() < until) {
        await page.waitForTimeout(Math.min(CHANGE_MS, until - Date.now()));
        if (trace) trace.push((await measure()).wasm / MiB);
        if (Date.now() >= until) break;
        changes += 1;
        if (changes % 2 === 1) {
          await page.fill('#delta-number', changes % 4 === 1 ? '0.02' : '0.04');
          await page.press('#delta-number', 'Enter');
        } else {
          await page.click('#reset');
        }
      }
    };
    await run(WARM_UP_MS, null);
    const simulatedAtStart = await page.evaluate(() => /** @type {any} */ (window).flatOut.simulated);
    const warm = await measure();
    const t0 = Date.now();
    await run(RUN_MS, samples);
    const end = await measure();
    const wall = (Date.now() - t0) / 1000;
    const flat = await page.evaluate(() => {
      const w = /** @type {any} */ (window);
      clearInterval(w.flatOutTimer);
      return w.flatOut;
    });
    const simulated = flat.simulated - simulatedAtStart;
    const mib = (/** @type {number} */ b) => (b / MiB).toFixed(2);
    console.log(`# wasm memory: ${mib(start.wasm)} MiB at the start, ${mib(warm.wasm)} MiB after a ${WARM_UP_MS / 1000}-s warm-up, `
      + `${mib(end.wasm)} MiB after ${wall.toFixed(0)} s flat out (${simulated.toFixed(0)} simulated s, ${(simulated / wall).toFixed(0)} per wall s, `
      + `at ${speed}× plus the flat-out pump; ${changes} changes of δ or resets; ${end.frames - warm.frames} frames); `
      + `JS heap ${mib(warm.js)} → ${mib(end.js)} MiB`);
    console.log(`# wasm memory every ${CHANGE_MS / 1000} s of the run, MiB: ${samples.map((m) => m.toFixed(2)).join(' ')}`);
    assert.ok(simulated > 10 * RUN_MS / 1000, `only ${simulated} simulated s in ${wall} s: not flat out`);
    assert.ok(end.frames > warm.frames + 60, `${end.frames - warm.frames} frames drawn in ${wall} s`);
    assert.ok(end.wasm <= warm.wasm * 1.1 + MiB, `the wasm memory grew from ${mib(warm.wasm)} to ${mib(end.wasm)} MiB`);
    assert.deepEqual(problems, []);
  } finally {
    await close();
  }
});
