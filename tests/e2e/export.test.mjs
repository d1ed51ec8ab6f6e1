// End-to-end test of the page's exports: the PNG of the figure, the WebM video, the SVG figures,
// the embed snippet, the Python script and the data behind the figures (JSON, CSV), each checked
// from the file the browser offers.
// Run: node --test tests/e2e/export.test.mjs (needs the wasm in www/pkg, like page.test.mjs).

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { openPage, clickForDownload, shared } from './harness.mjs';

const PAGE = '?preset=fig5.3&mode=full&speed=2';
const PNG_SIGNATURE = Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
const EBML_MAGIC = Buffer.from([0x1a, 0x45, 0xdf, 0xa3]);

const env = shared();

const kB = (/** @type {Buffer} */ b) => `${(b.length / 1024).toFixed(1)} kB`;

test('the picture: a PNG of the canvas with its labels and the whole caption, at 2×', { timeout: 120000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, PAGE);
  await page.waitForTimeout(1500);
  const { name, bytes } = await clickForDownload(page, '#export-png');
  assert.equal(name, 'flexarm-fig5.3-figure@2x.png', 'named after what it shows and its scale');
  assert.deepEqual(bytes.subarray(0, 8), PNG_SIGNATURE, 'PNG signature');
  const width = bytes.readUInt32BE(16);
  const height = bytes.readUInt32BE(20);
  const css = await page.evaluate(() => {
    const r = document.querySelector('#canvas').getBoundingClientRect();
    return { width: r.width, height: r.height, dpr: window.devicePixelRatio || 1, labels: document.querySelectorAll('#axes-overlay .label:not([hidden])').length };
  });
  console.log(`# PNG ${width}×${height} px, ${kB(bytes)} (canvas ${css.width}×${css.height} CSS px at ${css.dpr}×, ${css.labels} labels)`);
  assert.ok(bytes.length > 20 * 1024, `PNG only ${kB(bytes)}`);
  // Twice the canvas' CSS pixels (this screen is 1×): the figure drawn again at 2×, not scaled up.
  const scale = Math.max(2, css.dpr);
  assert.equal(width, Math.round(css.width * scale));
  assert.ok(height > css.height * scale, `PNG height ${height} leaves no caption under ${css.height}×${scale}`);
  // The whole state string under it, wrapped rather than cut: at 2× on a 1280-px canvas it takes
  // two lines or more (one line is 28 CSS px).
  assert.ok(height >= Math.round((css.height + 28 + 18) * scale), `a caption of one line: ${height} px`);
  // The canvas, resized to draw the picture at 2×, is back at the screen's pixels.
  assert.equal(await page.evaluate(() => document.querySelector('#canvas').width), Math.round(css.width * css.dpr));
  assert.match(await page.textContent('#export-status'), /flexarm-fig5\.3-figure@2x\.png/);
  // Its caption says when (a running figure changes by the second) and the whole state string.
  const caption = await page.evaluate(() => window.flexarm.session.pictureCaption());
  const state = await page.evaluate(() => window.flexarm.session.stateString());
  assert.match(caption, /^flexarm at t = [\d.]+ s — Fig\. 5\.3: /);
  assert.ok(caption.endsWith(` — state: ${state}`), caption);
  assert.deepEqual(problems, []);
  await close();
});

test('the video: recording toggles, counts the time and gives a WebM', { timeout: 120000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, PAGE);
  assert.equal(await page.isDisabled('#record-video'), false, await page.textContent('#export-status'));
  await page.click('#record-video');
  assert.equal(await page.getAttribute('#record-video', 'aria-pressed'), 'true');
  await page.waitForTimeout(3000);
  const label = await page.textContent('#record-video');
  assert.match(label, /^Stop recording \(0:0[2-4]\)$/, `button while recording: ${label}`);
  const { name, bytes } = await clickForDownload(page, '#record-video');
  console.log(`# WebM ${kB(bytes)} for about 3 s`);
  assert.equal(name, 'flexarm-run.webm');
  assert.deepEqual(bytes.subarray(0, 4), EBML_MAGIC, 'WebM (EBML) magic');
  assert.ok(bytes.length > 10 * 1024, `WebM only ${kB(bytes)}`);
  assert.equal(await page.getAttribute('#record-video', 'aria-pressed'), 'false');
  assert.doesNotMatch(await page.textContent('#record-video'), /Stop/);
  assert.deepEqual(problems, []);
  await close();
});

test('the SVG figures: the errors at once, the maps once they are computed', { timeout: 120000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, PAGE);
  // The maps, clicked in the same task as the check that they are not done: a message, no file.
  const wasDone = await page.evaluate(() => {
    const done = document.querySelector('#map-progress').dataset.done === 'true';
    document.querySelector('#export-svg-maps').click();
    return done;
  });
  assert.equal(wasDone, false, 'the maps were already done when the page opened');
  const message = await page.textContent('#export-status');
  console.log(`# maps not done yet: "${message}"`);
  assert.match(message, /map/i);
  assert.equal(await page.isVisible('#error'), false, 'no error banner for maps not computed yet');

  const traces = await clickForDownload(page, '#export-svg-traces');
  const tracesText = traces.bytes.toString('utf8');
  console.log(`# SVG errors ${kB(traces.bytes)}`);
  assert.equal(traces.name, 'flexarm-fig5.3-errors.svg');
  assert.ok(tracesText.startsWith('<svg'), tracesText.slice(0, 80));
  assert.match(tracesText, /Tracking errors/);

  await page.waitForFunction(() => document.querySelector('#map-progress').dataset.done === 'true', null, { timeout: 100000 });
  const maps = await clickForDownload(page, '#export-svg-maps');
  const mapsText = maps.bytes.toString('utf8');
  console.log(`# SVG maps ${kB(maps.bytes)}`);
  assert.equal(maps.name, 'flexarm-fig5.3-maps.svg');
  assert.ok(mapsText.startsWith('<svg'), mapsText.slice(0, 80));
  // Both panels name their feedback (the map titles come from src/session/maps.rs).
  assert.match(mapsText, /ρ, no Kₚᵣ/);
  assert.match(mapsText, /ρ, paper Kₚᵣ/);
  assert.deepEqual(problems, []);
  await close();
});

test('the embed snippet: an iframe of the current state, shown and selected', { timeout: 120000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, PAGE);
  await page.click('#embed-snippet');
  await page.waitForSelector('#embed-code:not([hidden])', { timeout: 5000 });
  assert.equal(await page.isVisible('#embed-label'), true);
  const code = await page.inputValue('#embed-code');
  console.log(`# embed snippet ${code.length} characters`);
  assert.match(code, /<iframe/);
  assert.match(code, /embed=1/);
  await page.waitForFunction(() => /copied|select and copy/.test(document.querySelector('#export-status').textContent), null, { timeout: 5000 });
  const selected = await page.evaluate(() => {
    const t = document.querySelector('#embed-code');
    return t.selectionEnd - t.selectionStart === t.value.length;
  });
  assert.ok(selected, 'the snippet is selected');
  assert.deepEqual(problems, []);
  await close();
});

test('the model as a Python script: downloaded, and run with NumPy and SciPy it finds the page\'s ρ', { timeout: 120000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, PAGE);
  const { name, bytes } = await clickForDownload(page, '#export-python');
  assert.equal(name, 'flexarm_model.py');
  const script = bytes.toString('utf8');
  assert.match(script, /^#!\/usr\/bin\/env python3\n/);
  const state = await page.evaluate(() => window.flexarm.session.stateString());
  assert.ok(script.includes('State: delta=0.01&alpha=2&pf=off'), 'the script names the run settings');
  console.log(`# Python script ${kB(bytes)} for ${state}`);
  const python = process.env.FLEXARM_PYTHON;
  if (python) {
    const { execFileSync } = await import('node:child_process');
    const fs = await import('node:fs');
    const os = await import('node:os');
    const path = await import('node:path');
    const file = path.join(fs.mkdtempSync(path.join(os.tmpdir(), 'flexarm-')), name);
    fs.writeFileSync(file, bytes);
    const out = execFileSync(python, [file], { encoding: 'utf8' }).trim().split('\n');
    const result = JSON.parse(out[out.length - 1]);
    const verdict = await page.textContent('#verdict-detail');
    assert.ok(verdict.includes(`ρ = ${result.spectral_radius.toFixed(4)}`), `${verdict} vs ${result.spectral_radius}`);
    console.log(`# the script's ρ = ${result.spectral_radius.toFixed(6)}; the page says "${verdict.slice(0, 40)}…"`);
  }
  assert.deepEqual(problems, []);
  await close();
});

test('the data behind the figures: JSON and CSV downloads with the state string, units and the page\'s ρ; the maps once computed', { timeout: 180000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, PAGE);
  await page.waitForTimeout(500);
  const json = await clickForDownload(page, '#export-data-json');
  assert.equal(json.name, 'flexarm-data.json');
  const data = JSON.parse(json.bytes.toString('utf8'));
  const q = data.quantities;
  console.log(`# data JSON ${kB(json.bytes)}: ${Object.keys(q).join(', ')}`);
  assert.ok(data.state.startsWith('delta=0.01&alpha=2&pf=off'), data.state);
  assert.ok(data.head.includes(`flexarm state: ${data.state}`), data.head.join('\n'));
  assert.match(await page.textContent('#export-status'), /flexarm-data\.json/);
  // The page's verdict quotes the same ρ; the largest |λ| listed is it.
  const rho = q.loop.values[q.loop.rows.indexOf('spectral_radius')][0];
  const verdict = await page.textContent('#verdict-detail');
  assert.ok(verdict.includes(`ρ = ${rho.toFixed(4)}`), `${verdict} vs ${rho}`);
  assert.deepEqual(q.eigenvalues.columns, ['re', 'im', 'abs', 's_re', 's_im']);
  assert.equal(q.eigenvalues.values.length, 10);
  assert.equal(Math.max(...q.eigenvalues.values.map((/** @type {number[]} */ e) => e[2])), rho);
  assert.deepEqual([q.Phi.rows.length, q.Phi.columns.length], [10, 10]);
  assert.equal(q.A.units[3][0], '1/s²');
  assert.ok(q.K_pr.values.flat().every((/** @type {number} */ v) => v === 0), 'no preliminary feedback: K_pr = 0');
  assert.deepEqual(q.rho_curve.columns, ['delta', 'rho']);
  assert.ok(q.rho_curve.values.length >= 100);

  const csv = await clickForDownload(page, '#export-data-csv');
  assert.equal(csv.name, 'flexarm-data.csv');
  const lines = csv.bytes.toString('utf8').trimEnd().split('\n');
  console.log(`# data CSV ${kB(csv.bytes)}, ${lines.length} lines`);
  const head = lines.filter((l) => l.startsWith('#'));
  assert.ok(head.includes(`# flexarm state: ${data.state}`), head.join('\n'));
  assert.ok(head.some((l) => l.includes('[rad/s]') && l.includes('[N m]')), 'the head names the units');
  assert.equal(lines[head.length], 'quantity,i,j,row,column,value,unit');
  const rows = lines.slice(head.length + 1).map((l) => l.split(','));
  assert.ok(rows.every((r) => r.length === 7 && r[6] !== ''), 'seven cells and a unit on every row');
  assert.equal(Number(rows.find((r) => r[0] === 'loop' && r[3] === 'spectral_radius')?.[5]), rho);
  const a = rows.filter((r) => r[0] === 'A');
  assert.equal(a.length, 64);
  assert.equal(Number(a.find((r) => r[1] === '3' && r[2] === '0')?.[5]), q.A.values[3][0]);

  // Once the maps are computed the data has them whole.
  await page.waitForFunction(() => document.querySelector('#map-progress').dataset.done === 'true', null, { timeout: 100000 });
  const full = JSON.parse((await clickForDownload(page, '#export-data-json')).bytes.toString('utf8'));
  for (const side of ['map_off', 'map_on']) {
    assert.deepEqual([full.quantities[side].values.length, full.quantities[side].columns.length], [60, 100], side);
  }
  assert.ok(!full.head.some((/** @type {string} */ l) => l.startsWith('omitted')), full.head.join('\n'));
  assert.ok(full.head.some((/** @type {string} */ l) => l.includes('map_on paper')), 'the right map has the paper\'s K_pr');
  assert.deepEqual(problems, []);
  await close();
});
