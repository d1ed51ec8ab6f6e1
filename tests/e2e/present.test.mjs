// Presentation mode and the text size (issue 23 item 2), and comparing at a glance (item 5), in
// the page: on a projector the figure fills the screen and its smallest text is at least 18 px at
// 1920 × 1080 and 14 px at 1024 × 768; the button enters the mode and Esc leaves it; two compared
// runs show both verdicts over the figure and, a decade apart, log axes that say so.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import fs from 'node:fs';
import { shared, openPage, shots, AXE } from './harness.mjs';

const env = shared();
const EXTRA = process.env.SHOTS23 || '';

/** The smallest font size (px) of the texts over the canvas, as the browser computes it. */
async function smallestLabel(page) {
  await page.waitForFunction(() => document.querySelectorAll('#axes-overlay .label:not([hidden])').length > 5, null, { timeout: 20000 });
  return page.$$eval('#axes-overlay .label:not([hidden])', (spans) => Math.min(...spans.map((s) => parseFloat(getComputedStyle(s).fontSize))));
}

async function shoot(page, name) {
  await page.screenshot({ path: path.join(shots, name) });
  if (EXTRA) {
    fs.mkdirSync(EXTRA, { recursive: true });
    await page.screenshot({ path: path.join(EXTRA, name) });
  }
}

for (const [w, h, need] of [[1920, 1080, 18], [1024, 768, 14]]) {
  test(`presentation mode at ${w} × ${h}: the figure fills the screen, text ≥ ${need} px, each size larger than the last`, { timeout: 180000 }, async () => {
    /** @type {{ text: string, figure: number, bar: number, verdict: number }[]} */
    const sizes = [];
    for (const text of ['normal', 'large', 'larger', 'largest']) {
      const query = `?preset=fig5.3&mode=full&plane=z&present=1&text=${text}&paused=1&t=3`;
      const { page, problems, close } = await openPage(env.browser, env.server.base, query, { viewport: { width: w, height: h } });
      assert.equal(await page.getAttribute('body', 'data-present'), 'true');
      assert.equal(await page.isVisible('.page-header'), false, 'the header folds away');
      assert.equal(await page.isVisible('#panel'), false, 'the controls fold into the bar');
      assert.ok(await page.isVisible('#present-bar'));
      assert.match(await page.textContent('#present-verdict') ?? '', /Unstable|Diverged/i, 'the verdict stays in the corner');
      const box = await page.$eval('#canvas-wrap', (n) => n.getBoundingClientRect().toJSON());
      // Everything but the bar (two rows below 1280 px: the verdict over the controls) and the
      // tabs, where the canvas shows one view at a time.
      const bar = await page.$eval('#present-bar', (n) => n.getBoundingClientRect().height);
      // At Normal the bar is one row (two below 1280 px); the larger sizes may take one more.
      if (text === 'normal') assert.ok(bar <= (w < 1280 ? 110 : 64), `the bar is small: ${bar} px`);
      // The compact key sits between the figure and the bar: a line or three, not the page's key.
      const key = await page.$eval('#figure-key', (n) => n.getBoundingClientRect().height);
      if (text === 'normal') assert.ok(key > 0 && key <= 0.16 * h, `the key is compact: ${key} px`);
      assert.ok(box.width >= w - 2 && box.bottom >= h - bar - key - 1 && box.height >= h - bar - key - 60, `the figure fills the screen: ${JSON.stringify(box)}, key ${key} px`);
      const min = await smallestLabel(page);
      assert.ok(min >= need, `text=${text}: smallest figure text ${min} px < ${need} px`);
      const px = (/** @type {string} */ sel) => page.$eval(sel, (n) => parseFloat(getComputedStyle(n).fontSize));
      sizes.push({ text, figure: min, bar: await px('#present-play'), verdict: await px('#present-verdict strong') });
      await shoot(page, `present-${text}-${w}x${h}.png`);
      await page.addScriptTag({ path: AXE });
      const axe = await page.evaluate(async () => (await window.axe.run(document, { runOnly: ['wcag2a', 'wcag2aa'] })).violations.map((v) => `${v.id}: ${v.nodes.length}`));
      assert.deepEqual(axe, []);
      assert.deepEqual(problems, []);
      await close();
    }
    // Every size visibly larger than the last, in rendered pixels: the figure's smallest text, the
    // bar's buttons and the verdict.
    console.log(`# presentation text at ${w} × ${h} (px): ${sizes.map((s) => `${s.text} ${s.figure}/${s.bar}/${s.verdict}`).join(', ')}`);
    for (let i = 1; i < sizes.length; i++) {
      for (const part of /** @type {const} */ (['figure', 'bar', 'verdict'])) {
        assert.ok(sizes[i][part] >= sizes[i - 1][part] * 1.1, `${part}: ${sizes[i].text} is not larger than ${sizes[i - 1].text}: ${JSON.stringify(sizes)}`);
      }
    }
  });
}

test('the Present button enters the mode, Esc leaves it, the text size stays in the link', { timeout: 90000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, '?preset=fig5.3&mode=full', { viewport: { width: 1280, height: 800 } });
  const before = await smallestLabel(page);
  assert.ok(before < 14, `the laptop's figure text is the normal 12 px (${before})`);
  await page.click('#present-enter');
  await page.waitForFunction(() => document.body.dataset.present === 'true');
  assert.match(page.url(), /present=1/);
  await page.selectOption('#present-text', 'larger');
  await page.waitForFunction(() => /text=larger/.test(window.location.search));
  await page.waitForFunction(() => Math.min(...[...document.querySelectorAll('#axes-overlay .label:not([hidden])')].map((s) => parseFloat(getComputedStyle(s).fontSize))) >= 18);
  // δ steps from the bar, as from the panel.
  const delta = await page.textContent('#present-delta');
  await page.click('#present-delta-up');
  await page.waitForFunction((d) => document.querySelector('#present-delta')?.textContent !== d, delta);
  // Headless Chromium may refuse full screen; Esc leaves the mode either way.
  if (await page.evaluate(() => Boolean(document.fullscreenElement))) await page.keyboard.press('Escape');
  await page.keyboard.press('Escape');
  await page.waitForFunction(() => document.body.dataset.present === 'false');
  assert.doesNotMatch(page.url(), /present=1/);
  assert.match(page.url(), /text=larger/, 'the text size stays chosen outside the mode');
  assert.deepEqual(problems, []);
  await close();
});

test('two compared runs: both verdicts over the figure, and log axes when they are a decade apart', { timeout: 90000 }, async () => {
  // Fig. 5.3 (A, no K_pr, grows) beside Fig. 5.2 (B, K_pr, settles), six seconds in.
  const { page, problems, close } = await openPage(env.browser, env.server.base, '?preset=fig5.3&mode=full&compare=1&b_pf=paper&paused=1&t=6', { viewport: { width: 1280, height: 800 } });
  await page.waitForFunction(() => document.querySelectorAll('#figure-verdicts .figure-verdict').length === 2, null, { timeout: 20000 });
  const verdicts = await page.$$eval('#figure-verdicts .figure-verdict', (v) => v.map((n) => [n.getAttribute('data-verdict'), n.textContent]));
  assert.match(verdicts[0][1] ?? '', /run A/);
  assert.match(verdicts[1][1] ?? '', /run B/);
  assert.ok(['unstable', 'diverged'].includes(verdicts[0][0] ?? ''), `A: ${verdicts[0]}`);
  assert.equal(verdicts[1][0], 'stable', `B: ${verdicts[1]}`);
  // Both sit above the fold, over the figure.
  const top = await page.$eval('#figure-verdicts', (n) => n.getBoundingClientRect().bottom);
  assert.ok(top < 800, `the verdicts are above the fold (${top})`);
  await page.waitForFunction(() => window.flexarm.lastLayout?.panels.find((p) => p.id === 'e1')?.y_scale === 'log', null, { timeout: 10000 });
  const note = await page.evaluate(() => window.flexarm.lastLayout.panels.find((p) => p.id === 'e1').note);
  assert.match(note, /differ by more than 10×/);
  await shoot(page, 'compare-log-laptop.png');
  assert.deepEqual(problems, []);
  await close();
});

test('presentation from a link: a typo is said, Fig. 2.1 and its caption with predict=1, the key, and Copy link keeps the mode and the text size', { timeout: 90000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, '?preset=fig5.3&present=1&predict=1&text=huge&paused=1&t=2', { viewport: { width: 1920, height: 1080 } });
  // The typo, said over the figure (the normal view says it too).
  await page.waitForSelector('#url-notice:not([hidden])', { timeout: 10000 });
  assert.ok(await page.isVisible('#url-notice'));
  assert.match(await page.textContent('#url-notice-list') ?? '', /text/);
  // predict=1 works without mode=full: the zoom on one instant, with its caption.
  await page.waitForSelector('#zoom-caption:not([hidden])', { timeout: 10000 });
  assert.ok(await page.isVisible('#zoom-caption'), 'Fig. 2.1\'s caption shows in presentation mode');
  assert.match(await page.textContent('#zoom-caption') ?? '', /\S/);
  // Paused at the link's moment, the address keeps it; Copy link writes present and text too.
  await page.selectOption('#present-text', 'larger');
  await page.waitForFunction(() => /text=larger/.test(location.search));
  // Running, Copy link pauses first: the address names the moment the screen holds.
  await page.click('#present-play');
  await page.waitForFunction(() => document.querySelector('#present-play')?.textContent === '❚❚ Pause');
  await page.click('#present-link');
  await page.waitForFunction(() => document.querySelector('#present-play')?.textContent === '▶ Play', null, { timeout: 5000 });
  await page.waitForFunction(() => /present=1/.test(location.search) && /text=larger/.test(location.search) && /paused=1&t=/.test(location.search), null, { timeout: 5000 });
  assert.match(await page.textContent('#present-link') ?? '', /Copied|address bar/);
  await shoot(page, 'present-predict-1920x1080.png');
  assert.deepEqual(problems, []);
  await close();
  // Diverged (Fig. 5.3 at 5 s), Play restarts: one restart control in the bar, not two.
  const diverged = await openPage(env.browser, env.server.base, '?preset=fig5.3&present=1&t=5', { viewport: { width: 1920, height: 1080 } });
  await diverged.page.waitForFunction(() => document.querySelector('#present-play')?.textContent === '↺ Restart', null, { timeout: 20000 });
  assert.equal(await diverged.page.isVisible('#present-reset'), false, 'one restart control');
  await diverged.close();
  // The full view's figures keep a compact key in this mode.
  const full = await openPage(env.browser, env.server.base, '?preset=fig5.3&mode=full&present=1&paused=1&t=3', { viewport: { width: 1920, height: 1080 } });
  await full.page.waitForSelector('#figure-key:not([hidden])', { timeout: 10000 });
  assert.ok(await full.page.isVisible('#figure-key'), 'the key shows');
  const key = await full.page.$eval('#figure-key', (n) => n.getBoundingClientRect().height);
  assert.ok(key <= 140, `the key is compact: ${key} px`);
  await shoot(full.page, 'present-key-1920x1080.png');
  assert.deepEqual(full.problems, []);
  await full.close();
});
