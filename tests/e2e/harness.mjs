// Shared set-up of the end-to-end tests: www/ served from this process, and Debian's Chromium
// driven by Playwright (playwright-core, no bundled browser), software-rendered (SwiftShader).

import assert from 'node:assert/strict';
import http from 'node:http';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { before, after } from 'node:test';
import { chromium } from 'playwright-core';
import { createRequire } from 'node:module';

/** axe-core's script, injected into a page to check its accessibility. */
export const AXE = createRequire(import.meta.url).resolve('axe-core/axe.min.js');

/** The three screens every page is looked at on: a phone (touch), a laptop, a large screen. */
export const SIZES = {
  phone: { viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true, deviceScaleFactor: 2 },
  laptop: { viewport: { width: 1280, height: 800 } },
  large: { viewport: { width: 1920, height: 1080 } },
};

export const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
export const www = path.join(root, 'www');
export const shots = path.join(root, 'screenshots');
const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';

const MIME = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.mjs': 'text/javascript',
  '.css': 'text/css', '.wasm': 'application/wasm', '.json': 'application/json',
  '.svg': 'image/svg+xml', '.png': 'image/png', '.ico': 'image/x-icon',
};

/** Serves `dir` (www/ by default) on a free port of 127.0.0.1. @returns {Promise<{ base: string, close: () => Promise<void> }>} */
export async function serve(dir = www) {
  assert.ok(fs.existsSync(path.join(dir, 'pkg', 'flexarm_bg.wasm')), 'www/pkg is missing: build the wasm first (scripts/test.sh does)');
  // Long URLs are part of the tests (abuse.test.mjs): headers up to 64 kB, not Node's 16 kB.
  const server = http.createServer({ maxHeaderSize: 64 * 1024 }, (req, res) => {
    const url = new URL(req.url, 'http://localhost');
    let name;
    try {
      name = decodeURIComponent(url.pathname);
    } catch {
      res.writeHead(400).end('bad path');
      return;
    }
    let file = path.normalize(path.join(dir, name));
    if (!file.startsWith(dir)) { res.writeHead(403).end(); return; }
    if (fs.existsSync(file) && fs.statSync(file).isDirectory()) file = path.join(file, 'index.html');
    fs.readFile(file, (err, data) => {
      if (err) { res.writeHead(404).end('not found'); return; }
      res.writeHead(200, { 'Content-Type': MIME[path.extname(file)] || 'application/octet-stream' });
      res.end(data);
    });
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  return {
    base: `http://127.0.0.1:${server.address().port}`,
    close: () => new Promise((resolve) => server.close(() => resolve())),
  };
}

/** Chromium's switches for a software WebGPU adapter (SwiftShader's Vulkan). Together with the
 * SwiftShader ANGLE switches of every launch, and without --disable-gpu, WebGPU draws; with only
 * some of them Chromium offers an adapter but the canvas stays blank. */
/** One server and one browser for a test file, started before its tests and closed after them
 * (`node:test` hooks). Read `.server` and `.browser` inside the tests.
 * @param {{ webgpu?: boolean }} [options] */
export function shared(options = {}) {
  const env = { server: /** @type {any} */ (null), browser: /** @type {any} */ (null) };
  before(async () => {
    env.server = await serve();
    env.browser = await launch(options);
  });
  after(async () => {
    await env.browser?.close();
    await env.server?.close();
  });
  return env;
}

export const WEBGPU_ARGS = ['--enable-unsafe-webgpu', '--enable-features=Vulkan', '--use-vulkan=swiftshader'];

/** Chromium for the tests: WebGL2 through SwiftShader, and with `webgpu` a WebGPU adapter too. */
export function launch({ webgpu = false } = {}) {
  return chromium.launch({
    executablePath: CHROMIUM,
    args: ['--no-sandbox', '--disable-dev-shm-usage', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
      '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run',
      ...(webgpu ? WEBGPU_ARGS : [])],
  });
}

/**
 * Opens `base` + `query` in a new page (a browser context of its own: `viewport`, and any other
 * context option such as `reducedMotion` or `colorScheme`), collecting console errors, uncaught
 * exceptions and dialogs (dismissed: the page never opens one), and waits until the renderer has
 * started (#backend has text).
 * @param {import('playwright-core').Browser} browser
 */
export function openPage(browser, base, query = '', options = {}) {
  return openUrl(browser, `${base}/${query}`, options);
}

/** openPage for a whole URL (a file:// one, for the offline file); `offline` turns the network off
 * and counts any request that is not for the file itself, a blob or a data URL as a problem.
 * @param {import('playwright-core').Browser} browser @param {string} url */
export async function openUrl(browser, url, { viewport = { width: 1280, height: 800 }, acceptDownloads = true, offline = false, ...contextOptions } = {}) {
  const context = await browser.newContext({ viewport, acceptDownloads, ...contextOptions });
  const page = await context.newPage();
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('dialog', (d) => {
    problems.push(`dialog (${d.type()}): ${d.message()}`);
    d.dismiss().catch(() => {});
  });
  if (offline) {
    await context.setOffline(true);
    page.on('request', (r) => { if (!/^(file|blob|data):/u.test(r.url())) problems.push(`request while offline: ${r.url()}`); });
  }
  await page.goto(url);
  await page.waitForFunction(() => document.querySelector('#backend')?.textContent?.trim().length > 0, null, { timeout: 20000 });
  return { page, problems, close: () => context.close() };
}

/** The bytes of a Playwright download. @param {import('playwright-core').Download} download */
export async function downloadBytes(download) {
  const stream = await download.createReadStream();
  const chunks = [];
  for await (const chunk of stream) chunks.push(chunk);
  return Buffer.concat(chunks);
}

/** Clicks `selector` and returns the file it offers: its suggested name and bytes. */
export async function clickForDownload(page, selector, timeout = 30000) {
  const [download] = await Promise.all([page.waitForEvent('download', { timeout }), page.click(selector)]);
  return { name: download.suggestedFilename(), bytes: await downloadBytes(download) };
}

// ------------------------------------------------------------------- pixels, decoded by Chromium

/** The RGBA of pixel (x, y) of a PNG (a Buffer), decoded by Chromium in `page`. */
export async function pngPixel(page, png, x, y) {
  return page.evaluate(async ({ b64, x, y }) => {
    const img = new Image();
    img.src = `data:image/png;base64,${b64}`;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.width; c.height = img.height;
    const ctx = c.getContext('2d');
    ctx.drawImage(img, 0, 0);
    return [...ctx.getImageData(x, y, 1, 1).data];
  }, { b64: png.toString('base64'), x, y });
}

/** How far a pixel's colour must be from another (sum of |ΔR| + |ΔG| + |ΔB|) to count as different. */
const INK = 30;

/**
 * Fraction of canvas pixels that differ from its background colour (sampled at a corner), and
 * the number of distinct colours, decoded by the browser from a real screenshot (saved to `file`).
 * @param {import('playwright-core').Page} page @param {string} [file]
 */
export async function canvasInk(page, file) {
  const png = await page.locator('#canvas').screenshot({ path: file });
  return page.evaluate(async ({ b64, INK }) => {
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
      if (d > INK) { ink++; colours.add((data[i] >> 4) << 8 | (data[i + 1] >> 4) << 4 | (data[i + 2] >> 4)); }
    }
    return { ink: ink / (data.length / 4), colours: colours.size, width: c.width, height: c.height };
  }, { b64: png.toString('base64'), INK });
}

/**
 * For each rectangle (CSS px in the canvas): how much of it is drawn. `ink` is the fraction of
 * pixels that differ from the canvas background (its corner), `marks` the fraction that differ
 * from the rectangle's own most common colour, `colours` the distinct colours.
 * @param {import('playwright-core').Page} page @param {{ x: number, y: number, width: number, height: number }[]} rects @param {string} [file]
 */
export async function regionInk(page, rects, file) {
  const png = await page.locator('#canvas').screenshot({ path: file });
  return page.evaluate(async ({ b64, rects, INK }) => {
    const img = new Image();
    img.src = `data:image/png;base64,${b64}`;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.width; c.height = img.height;
    const ctx = c.getContext('2d');
    ctx.drawImage(img, 0, 0);
    const scale = img.width / document.querySelector('#canvas').getBoundingClientRect().width;
    const all = ctx.getImageData(0, 0, c.width, c.height).data;
    const bg = [all[0], all[1], all[2]];
    return rects.map((r) => {
      const x0 = Math.max(0, Math.floor(r.x * scale)); const y0 = Math.max(0, Math.floor(r.y * scale));
      const x1 = Math.min(c.width, Math.ceil((r.x + r.width) * scale)); const y1 = Math.min(c.height, Math.ceil((r.y + r.height) * scale));
      if (x1 <= x0 || y1 <= y0) return { ink: 0, marks: 0, colours: 0 };
      const { data } = ctx.getImageData(x0, y0, x1 - x0, y1 - y0);
      const counts = new Map();
      let ink = 0;
      for (let i = 0; i < data.length; i += 4) {
        const d = Math.abs(data[i] - bg[0]) + Math.abs(data[i + 1] - bg[1]) + Math.abs(data[i + 2] - bg[2]);
        if (d > INK) ink++;
        const key = (data[i] >> 3) << 10 | (data[i + 1] >> 3) << 5 | (data[i + 2] >> 3);
        counts.set(key, (counts.get(key) || 0) + 1);
      }
      const n = data.length / 4;
      const dominant = Math.max(...counts.values());
      return { ink: ink / n, marks: (n - dominant) / n, colours: counts.size };
    });
  }, { b64: png.toString('base64'), rects, INK });
}

/**
 * Two PNG pictures of the same size compared pixel by pixel in `page` (any page: Chromium only
 * decodes them): the fraction of pixels whose colours differ, and the largest difference.
 * @param {import('playwright-core').Page} page @param {Buffer} a @param {Buffer} b
 */
export async function pictureDifference(page, a, b) {
  return page.evaluate(async ({ a, b, INK }) => {
    const decode = async (/** @type {string} */ b64) => {
      const img = new Image();
      img.src = `data:image/png;base64,${b64}`;
      await img.decode();
      const c = document.createElement('canvas');
      c.width = img.width; c.height = img.height;
      const ctx = c.getContext('2d');
      ctx.drawImage(img, 0, 0);
      return ctx.getImageData(0, 0, c.width, c.height);
    };
    const [pa, pb] = [await decode(a), await decode(b)];
    if (pa.width !== pb.width || pa.height !== pb.height) return { sizes: [[pa.width, pa.height], [pb.width, pb.height]], differ: 1, largest: Infinity };
    let differ = 0;
    let largest = 0;
    for (let i = 0; i < pa.data.length; i += 4) {
      const d = Math.abs(pa.data[i] - pb.data[i]) + Math.abs(pa.data[i + 1] - pb.data[i + 1]) + Math.abs(pa.data[i + 2] - pb.data[i + 2]);
      if (d > INK) differ++;
      largest = Math.max(largest, d);
    }
    return { sizes: [[pa.width, pa.height]], differ: differ / (pa.data.length / 4), largest };
  }, { a: a.toString('base64'), b: b.toString('base64'), INK });
}
