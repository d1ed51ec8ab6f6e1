// The WebGPU path (issue 12): Chromium with its software WebGPU adapter (SwiftShader's Vulkan)
// draws the page through WebGPU and says so, the canvas has the picture and keeps presenting new
// frames, and the layout report (panels, ticks, labels, poles, legend) equals the WebGL2 run's
// at the same size. A Chromium without a WebGPU adapter fails this test, saying so.
// Run: node --test tests/e2e/webgpu.test.mjs (needs the wasm in www/pkg). Screenshots: screenshots/.

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { serve, launch, openPage, canvasInk, pictureDifference, shots, WEBGPU_ARGS } from './harness.mjs';

let server;
/** @type {import('playwright-core').Browser | undefined} */
let webgpu;
/** @type {import('playwright-core').Browser | undefined} */
let webgl;

before(async () => {
  server = await serve();
  [webgpu, webgl] = await Promise.all([launch({ webgpu: true }), launch()]);
});

after(async () => {
  await webgpu?.close();
  await webgl?.close();
  await server?.close();
});

// Reduced motion starts the page paused at t = 0: both backends show exactly the same state.
const QUERY = '?preset=fig5.3&mode=full';
const CONTEXT = { viewport: { width: 1280, height: 800 }, reducedMotion: /** @type {const} */ ('reduce') };

/** Opens the page, waits for both maps, and returns the layout report and a canvas screenshot. */
async function frameOf(/** @type {import('playwright-core').Browser} */ browser, /** @type {string} */ name) {
  const opened = Date.now();
  const { page, problems, close } = await openPage(browser, server.base, QUERY, CONTEXT);
  const ready = Date.now() - opened;
  await page.waitForFunction(() => document.querySelector('#map-progress')?.dataset.done === 'true', null, { timeout: 60000 });
  // The frame after the last map rows: the description no longer changes.
  await page.waitForFunction(() => {
    const w = /** @type {any} */ (window);
    const g = w.flexarm.lastLayout?.generation;
    const same = g !== undefined && g === w.lastSeenGeneration;
    w.lastSeenGeneration = g;
    return same;
  }, null, { timeout: 10000, polling: 500 });
  const seen = await page.evaluate(() => ({
    shown: document.querySelector('#backend').textContent.trim(),
    data: /** @type {HTMLElement} */ (document.querySelector('#backend')).dataset.backend,
    perf: window.flexarmPerf().backend,
    layout: /** @type {any} */ (window).flexarm.lastLayout,
    time: /** @type {any} */ (window).flexarm.session.time(),
  }));
  const png = await page.locator('#canvas').screenshot({ path: path.join(shots, `${name}.png`) });
  const ink = await canvasInk(page);
  return { page, problems, close, ready, png, ink, ...seen };
}

/** Why there is no WebGPU here, for the failure message. */
async function webgpuDiagnosis(/** @type {import('playwright-core').Page} */ page) {
  return page.evaluate(async () => {
    const gpu = /** @type {any} */ (navigator).gpu;
    if (!gpu) return 'navigator.gpu is missing';
    try {
      const adapter = await gpu.requestAdapter();
      return adapter ? `an adapter exists (${JSON.stringify(adapter.info ?? {})}) but the page did not use it` : 'navigator.gpu.requestAdapter() gave no adapter';
    } catch (e) {
      return `requestAdapter() threw: ${e}`;
    }
  });
}

/** The layout report without what differs by backend or by how many frames it took. */
const comparable = (/** @type {any} */ layout) => {
  const { backend, generation, ...rest } = layout;
  return rest;
};

test('WebGPU draws the page, says so, presents new frames and lays it out as WebGL2 does', { timeout: 180000 }, async () => {
  const gpu = await frameOf(/** @type {any} */ (webgpu), 'webgpu');
  const gl = await frameOf(/** @type {any} */ (webgl), 'webgl2');
  try {
    // Drawn through WebGPU, and said so on the page, by the renderer and in the figures.
    if (gpu.shown !== 'WebGPU') {
      assert.fail(`Chromium (${WEBGPU_ARGS.join(' ')}) did not draw through WebGPU: the page says "${gpu.shown}"; ${await webgpuDiagnosis(gpu.page)}`);
    }
    assert.equal(gpu.data, 'WebGPU');
    assert.equal(gpu.perf, 'WebGPU');
    assert.equal(gpu.layout.backend, 'WebGPU');
    assert.equal(gl.shown, 'WebGL2', 'the default launch draws through WebGL2');
    assert.equal(gl.layout.backend, 'WebGL2');
    // The picture is there (a blank canvas is what a half-working WebGPU gives).
    for (const [name, r] of [['WebGPU', gpu], ['WebGL2', gl]]) {
      assert.ok(r.ink.ink > 0.05 && r.ink.colours >= 8, `${name}: ${(100 * r.ink.ink).toFixed(1)} % ink, ${r.ink.colours} colours`);
    }
    assert.equal(gpu.time, 0, 'paused at the start (reduced motion)');
    assert.equal(gl.time, 0);
    // The same layout: panels, ticks, labels, poles, legend, tabs.
    assert.deepEqual(comparable(gpu.layout), comparable(gl.layout), 'the layout reports differ');
    // The same picture, up to rasterisation.
    const diff = await pictureDifference(gpu.page, gpu.png, gl.png);
    assert.deepEqual(diff.sizes, [[gpu.ink.width, gpu.ink.height]], 'the same canvas size');
    // Playing: WebGPU keeps presenting new frames.
    await gpu.page.click('#play');
    await gpu.page.waitForFunction(() => /** @type {any} */ (window).flexarm.session.time() > 1, null, { timeout: 20000 });
    const playing = await gpu.page.locator('#canvas').screenshot({ path: path.join(shots, 'webgpu-playing.png') });
    const moved = await pictureDifference(gpu.page, gpu.png, playing);
    const perf = await gpu.page.evaluate(() => window.flexarmPerf());
    console.log(`# WebGPU: renderer ready ${gpu.ready} ms after navigation (WebGL2 ${gl.ready} ms); ${gpu.layout.panels.length} panels, `
      + `${gpu.layout.labels.length} labels, identical layout reports; pictures differ in ${(100 * diff.differ).toFixed(2)} % of `
      + `${gpu.ink.width}×${gpu.ink.height} pixels (largest difference ${diff.largest}); ink ${(100 * gpu.ink.ink).toFixed(1)} % vs `
      + `${(100 * gl.ink.ink).toFixed(1)} %; playing: ${(100 * moved.differ).toFixed(2)} % of pixels changed, ${perf.fps} fps, first frame ${perf.first_frame_ms?.toFixed(0)} ms`);
    assert.ok(diff.differ < 0.02, `WebGPU and WebGL2 pictures differ in ${(100 * diff.differ).toFixed(2)} % of pixels`);
    assert.ok(moved.differ > 0.001, 'the WebGPU canvas did not change while playing');
    assert.deepEqual(gpu.problems, []);
    assert.deepEqual(gl.problems, []);
  } finally {
    await gpu.close();
    await gl.close();
  }
});
