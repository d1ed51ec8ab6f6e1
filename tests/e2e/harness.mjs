// Shared set-up of the end-to-end tests: www/ served from this process, and Debian's Chromium
// driven by Playwright (playwright-core, no bundled browser), software-rendered (SwiftShader).

import assert from 'node:assert/strict';
import http from 'node:http';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

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
  const server = http.createServer((req, res) => {
    const url = new URL(req.url, 'http://localhost');
    let file = path.normalize(path.join(dir, decodeURIComponent(url.pathname)));
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

/** Chromium for the tests. */
export function launch() {
  return chromium.launch({
    executablePath: CHROMIUM,
    args: ['--no-sandbox', '--disable-dev-shm-usage', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
      '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run'],
  });
}

/**
 * Opens `base` + `query` in a new page, collecting console errors and uncaught exceptions, and
 * waits until the renderer has started (#backend has text).
 * @param {import('playwright-core').Browser} browser
 */
export async function openPage(browser, base, query = '', { viewport = { width: 1280, height: 800 }, acceptDownloads = true } = {}) {
  const context = await browser.newContext({ viewport, acceptDownloads });
  const page = await context.newPage();
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  await page.goto(`${base}/${query}`);
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
