// End-to-end test of the flexarm page in a real browser: Playwright (playwright-core, no bundled
// browser) driving Debian's Chromium against www/ served from this process.
// Run: (cd tests/e2e && npm ci) && node --test tests/e2e/   (scripts/test.sh does both)
// Needs the release wasm in www/pkg (scripts/test.sh builds it). Screenshots go to screenshots/.

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import http from 'node:http';
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const www = path.join(root, 'www');
const shots = path.join(root, 'screenshots');
const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';

const MIME = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.mjs': 'text/javascript',
  '.css': 'text/css', '.wasm': 'application/wasm', '.json': 'application/json',
  '.svg': 'image/svg+xml', '.png': 'image/png', '.ico': 'image/x-icon',
};

let server;
let base;
let browser;

before(async () => {
  assert.ok(fs.existsSync(path.join(www, 'pkg', 'flexarm_bg.wasm')), 'www/pkg is missing: build the wasm first (scripts/test.sh does)');
  fs.mkdirSync(shots, { recursive: true });
  server = http.createServer((req, res) => {
    const url = new URL(req.url, 'http://localhost');
    let file = path.normalize(path.join(www, decodeURIComponent(url.pathname)));
    if (!file.startsWith(www)) { res.writeHead(403).end(); return; }
    if (fs.existsSync(file) && fs.statSync(file).isDirectory()) file = path.join(file, 'index.html');
    fs.readFile(file, (err, data) => {
      if (err) { res.writeHead(404).end('not found'); return; }
      res.writeHead(200, { 'Content-Type': MIME[path.extname(file)] || 'application/octet-stream' });
      res.end(data);
    });
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  base = `http://127.0.0.1:${server.address().port}`;
  browser = await chromium.launch({
    executablePath: CHROMIUM,
    args: ['--no-sandbox', '--disable-dev-shm-usage', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
      '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run'],
  });
});

after(async () => {
  await browser?.close();
  await new Promise((resolve) => (server ? server.close(resolve) : resolve()));
});

/** Opens the page at `query`, collecting console errors and uncaught exceptions. */
async function open(query = '') {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  await page.goto(`${base}/${query}`);
  await page.waitForFunction(() => document.querySelector('#backend')?.textContent?.trim().length > 0, null, { timeout: 20000 });
  return { page, problems };
}

const verdictOf = (page) => page.$eval('#verdict', (el) => el.dataset.verdict || '');

/** Waits until the status shows one of `words`; returns the word. */
async function waitForVerdict(page, words, timeout) {
  await page.waitForFunction((w) => w.includes(document.querySelector('#verdict')?.dataset.verdict), words, { timeout });
  return verdictOf(page);
}

/** Fraction of canvas pixels that differ from its background colour (sampled at a corner), and
 * the number of distinct colours, decoded by the browser from a real screenshot. */
async function canvasInk(page, file) {
  const png = await page.locator('#canvas').screenshot({ path: file });
  return page.evaluate(async (b64) => {
    const img = new Image();
    img.src = `data:image/png;base64,${b64}`;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.width; c.height = img.height;
    const ctx = c.getContext('2d');
    ctx.drawImage(img, 0, 0);
    const { data } = ctx.getImageData(0, 0, c.width, c.height);
    const bg = [data[0], data[1], data[2]];
    let ink = 0;
    const colours = new Set();
    for (let i = 0; i < data.length; i += 4) {
      const d = Math.abs(data[i] - bg[0]) + Math.abs(data[i + 1] - bg[1]) + Math.abs(data[i + 2] - bg[2]);
      if (d > 30) { ink++; colours.add((data[i] >> 4) << 8 | (data[i + 1] >> 4) << 4 | (data[i + 2] >> 4)); }
    }
    return { ink: ink / (data.length / 4), colours: colours.size, width: c.width, height: c.height };
  }, png.toString('base64'));
}

test('the canvas shows the arm and the traces', async () => {
  const { page, problems } = await open('?speed=1');
  await page.waitForTimeout(1500);
  const backend = (await page.textContent('#backend')).trim();
  assert.match(backend, /WebGPU|WebGL2/, `backend shown: ${backend}`);
  const ink = await canvasInk(page, path.join(shots, 'page-start.png'));
  assert.ok(ink.width > 300 && ink.height > 200, `canvas size ${ink.width}×${ink.height}`);
  assert.ok(ink.ink > 0.01, `only ${(100 * ink.ink).toFixed(2)} % of the canvas differs from the background`);
  assert.ok(ink.colours >= 4, `only ${ink.colours} colours drawn`);
  await page.screenshot({ path: path.join(shots, 'page-full.png') });
  assert.deepEqual(problems, []);
  await page.close();
});

test('Fig. 5.3 preset goes unstable; switching the preliminary feedback on makes it stable', async () => {
  const { page, problems } = await open('?speed=4');
  await page.selectOption('#preset', 'fig5.3');
  const word = await waitForVerdict(page, ['unstable', 'diverged'], 30000);
  await page.screenshot({ path: path.join(shots, 'fig5.3-unstable.png') });
  assert.ok(['unstable', 'diverged'].includes(word));
  const status = await page.textContent('#verdict');
  assert.match(status, /ρ|rho/i, `status shows ρ: ${status}`);
  await page.selectOption('#pf', 'paper');
  await page.waitForFunction(() => document.querySelector('#verdict')?.dataset.verdict === 'stable', null, { timeout: 30000 });
  // It stays stable for a while of simulated time.
  await page.waitForTimeout(3000);
  assert.equal(await verdictOf(page), 'stable');
  await page.screenshot({ path: path.join(shots, 'fig5.3-then-pf-stable.png') });
  assert.deepEqual(problems, []);
  await page.close();
});

test('δ in the URL sets the slider', async () => {
  const { page, problems } = await open('?delta=0.05&pf=off');
  const shown = await page.$eval('#delta', (el) => el.getAttribute('aria-valuetext') || el.value);
  assert.match(shown, /0\.05/, `slider shows ${shown}`);
  assert.equal(await page.$eval('#pf', (el) => el.value), 'off');
  assert.ok(new URL(page.url()).searchParams.get('delta').startsWith('0.05'));
  assert.deepEqual(problems, []);
  await page.close();
});

test('a garbage URL value gives a notice and the page still works', async () => {
  const { page, problems } = await open('?delta=abc&pf=maybe');
  const notice = await page.textContent('#url-notice');
  assert.ok(await page.isVisible('#url-notice'), 'notice visible');
  assert.match(notice, /delta/);
  assert.match(notice, /pf/);
  await page.screenshot({ path: path.join(shots, 'garbage-url.png') });
  const t0 = await page.$eval('#verdict', (el) => el.textContent);
  assert.ok(t0.length > 0);
  const ink = await canvasInk(page, path.join(shots, 'garbage-url-canvas.png'));
  assert.ok(ink.ink > 0.01);
  assert.deepEqual(problems, []);
  await page.close();
});

test('performance figures (printed for the README)', async () => {
  const wasm = fs.readFileSync(path.join(www, 'pkg', 'flexarm_bg.wasm'));
  const gzip = zlib.gzipSync(wasm, { level: 9 }).length;
  const { page, problems } = await open('?speed=1');
  await page.waitForTimeout(5000);
  const perf = await page.evaluate(() => window.flexarmPerf());
  // How fast the wasm build simulates when nothing else runs: 10 s of the paper's loop.
  const throughput = await page.evaluate(() => {
    const Sim = window.flexarm.wasm.Simulation;
    const sim = new Sim({ controller: { sampling_period: 0.01 }, preliminary_feedback: 'paper' });
    const t0 = performance.now();
    while (sim.time() < 10 - 1e-9) sim.advance(0.25, 1);
    const wall = (performance.now() - t0) / 1000;
    sim.free();
    return 10 / wall;
  });
  console.log(`# wasm ${(wasm.length / 1e6).toFixed(2)} MB raw, ${(gzip / 1e6).toFixed(2)} MB gzip`);
  console.log(`# first frame ${perf.first_frame_ms?.toFixed(0)} ms after navigation; script per frame median ${perf.script_ms_median?.toFixed(2)} ms, p99 ${perf.script_ms_p99?.toFixed(2)} ms over ${perf.frames} frames (${perf.fps} fps, ${perf.backend})`);
  console.log(`# live simulation rate ${perf.sim_rate} simulated s per wall s at speed 1×; wasm throughput ${throughput.toFixed(0)} simulated s per wall s`);
  assert.ok(gzip < 1.5e6, `wasm gzip ${gzip} bytes exceeds the 1.5 MB goal`);
  assert.ok(perf.frames > 20 && perf.first_frame_ms > 0, JSON.stringify(perf));
  assert.ok(throughput > 100, `wasm simulates only ${throughput} s per s`);
  assert.deepEqual(problems, []);
  await page.close();
});
