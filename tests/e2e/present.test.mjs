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
  test(`presentation mode at ${w} × ${h}: the figure fills the screen, text ≥ ${need} px`, { timeout: 90000 }, async () => {
    for (const text of ['normal', 'largest']) {
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
      assert.ok(bar <= (w < 1280 ? 110 : 64), `the bar is small: ${bar} px`);
      assert.ok(box.width >= w - 2 && box.bottom >= h - bar - 1 && box.height >= h - bar - 60, `the figure fills the screen: ${JSON.stringify(box)}`);
      const min = await smallestLabel(page);
      assert.ok(min >= need, `text=${text}: smallest figure text ${min} px < ${need} px`);
      await shoot(page, `present-${text}-${w}x${h}.png`);
      await page.addScriptTag({ path: AXE });
      const axe = await page.evaluate(async () => (await window.axe.run(document, { runOnly: ['wcag2a', 'wcag2aa'] })).violations.map((v) => `${v.id}: ${v.nodes.length}`));
      assert.deepEqual(axe, []);
      assert.deepEqual(problems, []);
      await close();
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
