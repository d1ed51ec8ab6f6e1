// The offline file (issue 33): one HTML file that opens from disk with no server and no network.
// The test command builds it (`flexarm bundle`, into target/offline/); here it is opened from
// file:// with the network off — at the three sizes, with both drawing paths — and must show the
// paper's outcomes (Fig. 5.3 unstable, Fig. 5.2 stable), carry a teacher's lesson and student
// mode, export a PNG and log no error. The page's own "Save for offline" makes a file that opens
// where the page was, and says its size beside the button.

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';
import { pathToFileURL } from 'node:url';
import { SIZES, launch, serve, openPage, openUrl, clickForDownload, root, shots, www } from './harness.mjs';

/** What the test command built: the page's start, no lesson. */
const ARTEFACT = path.join(root, 'target', 'offline', 'flexarm-offline.html');
const FLEXARM = path.join(root, 'target', 'debug', 'flexarm');
const PNG_SIGNATURE = Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
const MB = (/** @type {number} */ n) => `${(n / 1e6).toFixed(2)} MB`;

const env = { browser: /** @type {any} */ (null), dir: '' };
before(async () => {
  assert.ok(fs.existsSync(ARTEFACT), `${ARTEFACT} is missing: the test command builds it (flexarm bundle)`);
  env.browser = await launch();
  env.dir = fs.mkdtempSync(path.join(os.tmpdir(), 'flexarm-offline-'));
});
after(async () => {
  await env.browser?.close();
  fs.rmSync(env.dir, { recursive: true, force: true });
});

/** A copy of `file` elsewhere (as a teacher sends it), its file:// URL. @param {string} file @param {string} name */
function sent(file, name) {
  const to = path.join(env.dir, name);
  fs.copyFileSync(file, to);
  return pathToFileURL(to).href;
}

/** Makes an offline file with the CLI. @param {string} name @param {string[]} args */
function bundle(name, args) {
  const out = path.join(env.dir, name);
  execFileSync(FLEXARM, ['bundle', '--out', out, ...args], { stdio: 'pipe' });
  return out;
}

const verdict = (/** @type {any} */ page) => page.waitForFunction(() => document.querySelector('#verdict')?.dataset.verdict || null, null, { timeout: 20000 }).then((/** @type {any} */ h) => h.jsonValue());

test('the built file opens from disk with the network off at three sizes: Fig. 5.3 unstable, then Fig. 5.2 stable', { timeout: 240000 }, async () => {
  const url = sent(ARTEFACT, 'flexarm-offline.html');
  // What it weighs against the gzip of what the served page loads (the same files).
  const served = ['index.html', 'style.css', 'present.css', 'embed.css', 'pkg/flexarm.js', 'pkg/flexarm_bg.wasm', 'lessons/paper.md',
    ...fs.readdirSync(path.join(www, 'js')).filter((f) => f.endsWith('.js') && !f.endsWith('.test.js') && f !== 'offline.js').map((f) => `js/${f}`)]
    .reduce((sum, f) => sum + zlib.gzipSync(fs.readFileSync(path.join(www, f)), { level: 9 }).length, 0);
  const size = fs.statSync(ARTEFACT).size;
  console.log(`# offline file ${MB(size)}; the served page loads ${MB(served)} gzip: ${(size / served).toFixed(2)}×`);
  assert.ok(size <= 1.5 * served, `the file is ${(size / served).toFixed(2)}× the served page's gzip (aim ≤ 1.5×)`);
  for (const [name, options] of Object.entries(SIZES)) {
    const { page, problems, close } = await openUrl(env.browser, url, { ...options, offline: true });
    assert.equal(await verdict(page), 'unstable', `${name}: the page's start is Fig. 5.3, unstable`);
    assert.equal(await page.isVisible('#offline-note'), true);
    assert.match(await page.textContent('#offline-start'), /δ = 0\.01 s/);
    await page.screenshot({ path: path.join(shots, `offline-${name}.png`) });
    // K_pr on: the paper's Fig. 5.2 (the switch may be in a closed sheet on a phone: clicked as a user's tap would).
    await page.$eval('#pf-toggle', (el) => /** @type {HTMLInputElement} */ (el).click());
    await page.waitForFunction(() => document.querySelector('#verdict')?.dataset.verdict === 'stable', null, { timeout: 20000 });
    // The address now holds the state: a reload keeps it, though the file carries another start.
    await page.waitForFunction(() => /pf=paper/.test(location.search), null, { timeout: 10000 });
    await page.reload();
    assert.equal(await verdict(page), 'stable', `${name}: reloaded, the state is kept`);
    // "Back to this start" goes back to the file's own.
    await page.click('#offline-restart');
    await page.waitForFunction(() => document.querySelector('#verdict')?.dataset.verdict === 'unstable', null, { timeout: 20000 });
    assert.deepEqual(problems, [], name);
    await close();
  }
});

test('offline, a picture exports, the help travels, a lesson by path is refused in one line and a dropped lesson works', { timeout: 120000 }, async () => {
  const url = sent(ARTEFACT, 'flexarm-offline.html');
  const { page, problems, close } = await openUrl(env.browser, `${url}?mode=full&lesson_src=lessons/mine.md`, { offline: true });
  await page.waitForSelector('#url-notice:not([hidden])', { timeout: 10000 });
  assert.match(await page.textContent('#url-notice-list'), /an offline file cannot load a lesson from a path.*drop the file on the page/);
  const { name, bytes } = await clickForDownload(page, '#export-png');
  assert.match(name, /^flexarm-[a-z0-9.-]+-figure@\d+x\.png$/);
  assert.deepEqual(bytes.subarray(0, 8), PNG_SIGNATURE);
  // The help page is carried (a blob URL, not a path that would fail from disk).
  assert.match(await page.getAttribute('footer a[href*="#paper"], a[href$="#paper"]', 'href'), /^blob:/);
  // An embed needs a server: said in one line.
  await page.click('#embed-snippet');
  assert.match(await page.textContent('#export-status'), /offline file cannot be embedded/);
  // A lesson file dropped (opened) on the page works offline as served.
  const homework = fs.readFileSync(path.join(www, 'lessons', 'windows.md'));
  await page.click('#lesson-start');
  await page.setInputFiles('#lesson-file', { name: 'windows.md', mimeType: 'text/markdown', buffer: homework });
  await page.waitForFunction(() => /Homework/.test(document.querySelector('#lesson-name')?.textContent ?? ''), null, { timeout: 10000 });
  assert.deepEqual(problems, []);
  await close();
});

test('a teacher\'s file: their lesson and student mode travel, and WebGPU draws it where offered', { timeout: 120000 }, async () => {
  const lesson = path.join(www, 'lessons', 'windows.md');
  const file = bundle('homework.html', ['--lesson', lesson, '--state', 'answers=hidden']);
  const url = sent(file, 'homework-for-class.html');
  const { page, problems, close } = await openUrl(env.browser, url, { ...SIZES.phone, offline: true });
  await page.waitForFunction(() => !document.querySelector('#lesson')?.hidden, null, { timeout: 10000 });
  assert.equal(await page.textContent('#lesson-title'), 'Where does the controller alone work?');
  assert.match(await page.textContent('#lesson-name'), /Homework: the windows of δ/);
  assert.match(await page.textContent('#offline-start'), /student mode/);
  // Student mode hides the verdict until the answer.
  await page.waitForFunction(() => /Student mode/.test(document.body.textContent ?? ''), null, { timeout: 10000 });
  await page.screenshot({ path: path.join(shots, 'offline-homework-phone.png') });
  // "Show me" makes the step's settings, and the address keeps them: a reload loses nothing.
  await page.click('#lesson-next');
  await page.waitForFunction(() => /Find a stable δ/.test(document.querySelector('#lesson-title')?.textContent ?? ''));
  await page.click('#lesson-reveal');
  await page.waitForFunction(() => /delta=0\.05/.test(location.search), null, { timeout: 10000 });
  await page.reload();
  await page.waitForFunction(() => /Find a stable δ/.test(document.querySelector('#lesson-title')?.textContent ?? ''), null, { timeout: 20000 });
  assert.equal(await page.evaluate(() => window.flexarm.session.controls().find((/** @type {any} */ c) => c.key === 'delta')?.value), '0.05');
  assert.deepEqual(problems, []);
  await close();

  const gpu = await launch({ webgpu: true });
  try {
    const { page: p, problems: pr, close: c } = await openUrl(gpu, url, { offline: true });
    const backend = await p.textContent('#backend');
    console.log(`# offline file drawn with: ${backend}`);
    assert.match(backend, /WebGPU/);
    assert.deepEqual(pr, []);
    await c();
  } finally {
    await gpu.close();
  }
});

test('"Save for offline" on the served page: its size beside the button, and the file opens paused where the page was', { timeout: 120000 }, async () => {
  const server = await serve();
  try {
    const { page, problems, close } = await openPage(env.browser, server.base, '?preset=fig5.2&mode=full&paused=1&t=2');
    await page.locator('#save-offline').scrollIntoViewIfNeeded();
    await page.waitForFunction(() => /MB/.test(document.querySelector('#offline-size')?.textContent ?? ''), null, { timeout: 30000 });
    const said = await page.textContent('#offline-size');
    console.log(`# beside the button: ${said}`);
    const ratio = Number(said.match(/\(([\d.]+)× their/)?.[1]);
    assert.ok(ratio > 1 && ratio <= 1.5, said);
    const { name, bytes } = await clickForDownload(page, '#save-offline');
    assert.equal(name, 'flexarm-offline.html');
    // As numbers: the page writes 1.70 MB as "1.7 MB".
    const mb = Number(said.match(/([\d.]+) MB/)?.[1]);
    assert.equal(mb, Number((bytes.length / 1e6).toPrecision(3)), `the size said is the size saved: ${said} against ${bytes.length} bytes`);
    assert.deepEqual(problems, []);
    await close();
    const saved = path.join(env.dir, 'saved.html');
    fs.writeFileSync(saved, bytes);
    const opened = await openUrl(env.browser, sent(saved, 'sent-to-class.html'), { ...SIZES.laptop, offline: true });
    assert.equal(await verdict(opened.page), 'stable');
    assert.match(await opened.page.textContent('#offline-start'), /paused at t = 2 s/);
    assert.equal(await opened.page.evaluate(() => window.flexarm.session.time()), 2);
    await opened.page.screenshot({ path: path.join(shots, 'offline-saved-laptop.png') });
    // An offline file makes offline files too, from the files it carries.
    const again = await clickForDownload(opened.page, '#save-offline');
    assert.ok(Math.abs(again.bytes.length - bytes.length) < 0.02 * bytes.length, `${again.bytes.length} against ${bytes.length}`);
    assert.deepEqual(opened.problems, []);
    await opened.close();
  } finally {
    await server.close();
  }
});

test('the served page opened from disk says in one sentence why it cannot start and what to do', { timeout: 60000 }, async () => {
  const context = await env.browser.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  await page.goto(pathToFileURL(path.join(www, 'index.html')).href);
  await page.waitForFunction(() => /web server/.test(document.querySelector('#loading-text')?.textContent ?? ''), null, { timeout: 10000 });
  const said = (await page.textContent('#loading-text')) ?? '';
  assert.match(said, /^Opened from disk, a browser will not start this page: it needs a web server \(bash scripts\/serve\.sh\), or use the offline file/);
  assert.equal(said.split(/(?<=\.) /).length, 1, `one sentence: ${said}`);
  assert.equal(await page.$('#loading .spinner'), null, 'no spinner turning forever');
  assert.equal(await page.textContent('#verdict-detail'), 'not started: see the message in the figure', 'not "starting…" forever');
  await page.screenshot({ path: path.join(shots, 'opened-from-disk-laptop.png') });
  await context.close();
});
