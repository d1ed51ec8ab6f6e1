// End-to-end test of a figure per panel (issue 23, item 6): the "Figure" row of Share and export
// offers every panel shown; each downloads as SVG (well-formed, its caption the whole state string)
// and as PNG at 2× (twice the figure's width, read from the PNG's IHDR), light even when the
// system is dark; student mode refuses the analysis' figures.
// Run: node --test tests/e2e/figure.test.mjs (needs the wasm in www/pkg).

import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { openPage, clickForDownload, shared, AXE, pngPixel } from './harness.mjs';

const env = shared();
const SHOTS = '/tmp/shots23';
const PNG_SIGNATURE = Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);

/** Records the type of every Blob the page turns into a URL (the downloads' content types). */
async function recordBlobTypes(page) {
  await page.evaluate(() => {
    const original = URL.createObjectURL.bind(URL);
    /** @type {any} */ (window).blobTypes = [];
    URL.createObjectURL = (b) => {
      /** @type {any} */ (window).blobTypes.push(b instanceof Blob ? b.type : '');
      return original(b);
    };
  });
}

/** The page's SVG checked in the page: parsed as XML without error; its size, background and caption. */
async function readSvg(page, text) {
  return page.evaluate((text) => {
    const doc = new DOMParser().parseFromString(text, 'image/svg+xml');
    const error = doc.querySelector('parsererror');
    const svg = doc.documentElement;
    return {
      error: error ? error.textContent : '',
      root: svg.nodeName,
      width: Number(svg.getAttribute('width')),
      background: doc.querySelector('#background')?.getAttribute('fill') ?? '',
      caption: [...doc.querySelectorAll('text.state')].map((t) => t.textContent).join(''),
      title: doc.querySelector('text.figure-title')?.textContent ?? '',
    };
  }, text);
}

/** The colour of a PNG's pixel (x, y), decoded by Chromium. */
const pixel = pngPixel;

const lightness = (/** @type {number[]} */ [r, g, b]) => (0.2126 * r + 0.7152 * g + 0.0722 * b) / 255;

/** Downloads every panel listed, as SVG and as PNG at 2×; checks each; returns the ids. */
async function everyPanel(page, { save = false, darkSystem = false } = {}) {
  await recordBlobTypes(page);
  const ids = await page.$$eval('#figure-panel option', (os) => os.map((o) => /** @type {HTMLOptionElement} */ (o).value));
  const state = await page.evaluate(() => window.flexarm.session.stateString());
  // Every file is named after what it shows (the preset of these pages).
  const label = await page.evaluate(() => window.flexarm.session.fileLabel());
  assert.equal(label, 'fig5.3');
  for (const id of ids) {
    await page.selectOption('#figure-panel', id);
    await page.selectOption('#figure-format', 'svg');
    assert.equal(await page.isDisabled('#figure-scale'), true, 'the scale is for PNGs');
    const svg = await clickForDownload(page, '#figure-download');
    assert.equal(svg.name, `flexarm-${label}-${id}.svg`);
    const types = await page.evaluate(() => /** @type {any} */ (window).blobTypes);
    assert.match(types[types.length - 1], /^image\/svg\+xml/, `${id}: content type`);
    const text = svg.bytes.toString('utf8');
    const doc = await readSvg(page, text);
    assert.equal(doc.error, '', `${id}: well-formed XML`);
    assert.equal(doc.root, 'svg');
    assert.ok(doc.title.length > 0, `${id}: a title`);
    assert.equal(doc.caption, state, `${id}: the whole state string in the caption`);
    if (save) fs.writeFileSync(`${SHOTS}/figure-${id}.svg`, text);

    await page.selectOption('#figure-format', 'png');
    await page.selectOption('#figure-scale', '2');
    const png = await clickForDownload(page, '#figure-download');
    assert.equal(png.name, `flexarm-${label}-${id}@2x.png`);
    assert.deepEqual(png.bytes.subarray(0, 8), PNG_SIGNATURE, `${id}: a PNG`);
    const width = png.bytes.readUInt32BE(16);
    assert.equal(width, 2 * doc.width, `${id}: PNG width ${width} = 2 × ${doc.width}`);
    const corner = await pixel(page, png.bytes, 3, 3);
    assert.ok(lightness(corner) > 0.85, `${id}: a light background${darkSystem ? ' with the system dark' : ''} (${corner})`);
    if (save) fs.writeFileSync(`${SHOTS}/figure-${id}.png`, png.bytes);
    console.log(`# ${id}: SVG ${(svg.bytes.length / 1024).toFixed(0)} kB, PNG ${width} px wide`);
  }
  return ids;
}

test('every panel of the full view at Fig. 5.3 (z-plane) as SVG and as PNG at 2×', { timeout: 300000 }, async () => {
  fs.mkdirSync(SHOTS, { recursive: true });
  const { page, problems, close } = await openPage(env.browser, env.server.base, '?preset=fig5.3&mode=full&torque=1&plane=z&paused=1&t=3', { viewport: { width: 1600, height: 1000 } });
  await page.waitForFunction(() => document.querySelector('#map-progress').dataset.done === 'true', null, { timeout: 200000 });
  await page.focus('#figure-panel');
  const ids = await everyPanel(page, { save: true });
  assert.deepEqual(ids, ['arm', 'errors', 'e1', 'e2', 'torque', 'zplane', 'rho', 'map-off', 'map-on', 'maps']);
  // The row passes axe.
  await page.addScriptTag({ path: AXE });
  const violations = await page.evaluate(() => window.axe.run(document.querySelector('.figure-row'), { runOnly: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa'] }))
    .then((r) => r.violations.map((v) => `${v.id}: ${v.nodes.slice(0, 3).map((n) => n.target.join(' ')).join(' | ')}`));
  assert.deepEqual(violations, []);
  // A dark figure on request.
  await page.check('#figure-dark');
  await page.selectOption('#figure-panel', 'zplane');
  const dark = await clickForDownload(page, '#figure-download');
  assert.ok(lightness(await pixel(page, dark.bytes, 3, 3)) < 0.2, 'dark on request');
  assert.deepEqual(problems, []);
  await close();
});

test('a slide figure: white or transparent, the text size, the caption, 16:9, the z-plane as the screen shows it', { timeout: 300000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, '?preset=fig5.3&mode=full&plane=z&paused=1&t=3', { viewport: { width: 1920, height: 1080 } });
  await page.focus('#figure-panel');
  await page.selectOption('#figure-panel', 'zplane');
  await page.selectOption('#figure-format', 'svg');
  /** Downloads the figure with the row's choices; its size, paper, ticks and caption. */
  const take = async (/** @type {Record<string, string>} */ choices) => {
    for (const [id, value] of Object.entries(choices)) await page.selectOption(`#figure-${id}`, value);
    const file = await clickForDownload(page, '#figure-download');
    const text = file.bytes.toString('utf8');
    const doc = await page.evaluate((text) => {
      const doc = new DOMParser().parseFromString(text, 'image/svg+xml');
      const svg = doc.documentElement;
      const view = (svg.getAttribute('viewBox') ?? '').split(' ').map(Number);
      const scale = Number(svg.getAttribute('width')) / view[2];
      const ticks = [...doc.querySelectorAll('text.tick')].map((t) => Number(t.getAttribute('font-size')) * scale);
      return {
        error: doc.querySelector('parsererror')?.textContent ?? '',
        width: Number(svg.getAttribute('width')),
        height: Number(svg.getAttribute('height')),
        background: doc.querySelector('#background')?.getAttribute('fill') ?? 'none',
        tick: Math.min(...ticks),
        caption: [...doc.querySelectorAll('text.state')].map((t) => t.textContent).join(''),
        zoom: [...doc.querySelectorAll('text')].map((t) => t.textContent).find((t) => /zoomed ×/.test(t ?? '')) ?? '',
      };
    }, text);
    assert.equal(doc.error, '', 'well-formed');
    fs.writeFileSync(`${SHOTS}/slide-${Object.values(choices).join('-') || 'default'}.svg`, text);
    return { ...doc, name: file.name };
  };
  const state = await page.evaluate(() => window.flexarm.session.stateString());
  const plain = await take({});
  assert.equal(plain.caption, state, 'by default the whole state string');
  assert.ok(plain.width > plain.height, `the z-plane is landscape: ${plain.width} × ${plain.height}`);
  // The screen's z-plane states its zoom (in its note, which a narrow panel may shorten on
  // screen); the figure shows the same view.
  const screenZoom = await page.evaluate(() => window.flexarm.lastLayout.panels.find((p) => p.id === 'z-plane')?.note ?? '');
  assert.match(screenZoom, /zoomed ×[\d.]+/);
  assert.equal(plain.zoom.match(/zoomed ×[\d.]+/)?.[0], screenZoom.match(/zoomed ×[\d.]+/)?.[0], `${plain.zoom} | ${screenZoom}`);

  const white = await take({ background: 'white', caption: 'settings' });
  assert.equal(white.background, '#ffffff');
  assert.ok(white.caption.includes('delta=0.01') && !/(^|&)(mode|plane|speed)=/.test(white.caption), white.caption);
  const bare = await take({ background: 'transparent', caption: 'none' });
  assert.equal(bare.background, 'none');
  assert.equal(bare.caption, '');
  let last = plain.tick;
  for (const text of ['large', 'larger', 'largest']) {
    const f = await take({ text });
    assert.ok(f.tick > 1.1 * last, `${text}: ticks ${f.tick} px after ${last} px`);
    last = f.tick;
  }
  const wide = await take({ text: 'large', shape: 'wide' });
  assert.ok(Math.abs(wide.width / wide.height - 16 / 9) < 0.02, `16:9: ${wide.width} × ${wide.height}`);
  // A PNG of it at 2×, named after what it shows.
  await page.selectOption('#figure-format', 'png');
  await page.selectOption('#figure-scale', '2');
  const png = await clickForDownload(page, '#figure-download');
  assert.equal(png.name, 'flexarm-fig5.3-zplane@2x.png');
  assert.equal(png.bytes.readUInt32BE(16), 2 * wide.width);
  fs.writeFileSync(`${SHOTS}/slide-zplane-wide@2x.png`, png.bytes);
  console.log(`# slide z-plane: ${plain.width} × ${plain.height} natural, ${wide.width} × ${wide.height} at 16:9; ticks ${plain.tick} → ${last} px; ${screenZoom}`);
  assert.deepEqual(problems, []);
  await close();
});

test('the s-plane with the system in dark mode: the PNGs stay light', { timeout: 300000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, '?preset=fig5.3&mode=full&torque=1&paused=1&t=3', { colorScheme: 'dark' });
  assert.equal(await page.evaluate(() => matchMedia('(prefers-color-scheme: dark)').matches), true);
  await page.waitForFunction(() => document.querySelector('#map-progress').dataset.done === 'true', null, { timeout: 200000 });
  const ids = await everyPanel(page, { darkSystem: true });
  assert.ok(ids.includes('poles') && !ids.includes('zplane'), ids.join(' '));
  // The pole plot, saved beside the z-plane's.
  const poles = await page.evaluate(() => window.flexarm.session.figureSvg('poles'));
  fs.writeFileSync(`${SHOTS}/figure-poles.svg`, poles);
  assert.deepEqual(problems, []);
  await close();
});

test('student mode: the analysis panels are neither offered nor given', { timeout: 120000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, '?preset=fig5.3&mode=full&plane=z&answers=hidden');
  const ids = await page.$$eval('#figure-panel option', (os) => os.map((o) => /** @type {HTMLOptionElement} */ (o).value));
  assert.deepEqual(ids, ['arm', 'errors', 'e1', 'e2']);
  for (const id of ['poles', 'zplane', 'rho', 'map-off', 'maps']) {
    const refused = await page.evaluate((id) => {
      try {
        window.flexarm.session.figureSvg(id);
        return '';
      } catch (e) {
        return String(e.message ?? e);
      }
    }, id);
    assert.match(refused, /student mode/, `${id} refused`);
  }
  const svg = await clickForDownload(page, '#figure-download');
  assert.equal(svg.name, 'flexarm-fig5.3-arm.svg');
  assert.deepEqual(problems, []);
  await close();
});
