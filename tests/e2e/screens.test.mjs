// Every screen, every person (issue 11): the page at phone, laptop and large sizes, embedded in
// a course page, in the dark scheme, by keyboard and for screen readers — checked in Chromium,
// with an axe-core audit of each. Screenshots go to screenshots/.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { shots, shared, AXE, SIZES, pngPixel } from './harness.mjs';

const env = shared();

/** A page in a context of its own (size, touch, colour scheme), with its errors collected. */
async function open(query, context = SIZES.laptop) {
  const ctx = await env.browser.newContext(context);
  const page = await ctx.newPage();
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  await page.goto(`${env.server.base}/${query}`);
  await page.waitForFunction(() => document.querySelector('#backend')?.textContent?.trim().length > 0, null, { timeout: 20000 });
  await page.waitForFunction(() => window.flexarm?.lastLayout != null, null, { timeout: 20000 });
  return { page, problems, close: () => ctx.close() };
}

/** axe-core's WCAG 2.1 A/AA violations on the page as it is. */
async function axe(page) {
  await page.addScriptTag({ path: AXE });
  const result = await page.evaluate(() => window.axe.run(document, { runOnly: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa'] }));
  return result.violations.map((v) => `${v.id} (${v.impact}): ${v.nodes.slice(0, 3).map((n) => n.target.join(' ')).join(' | ')}`);
}

/** The texts over the canvas as the env.browser lays them out: overlaps, and how Rust's width estimate compares. */
async function labelBoxes(page) {
  return page.evaluate(() => {
    const spans = [...document.querySelectorAll('#axes-overlay .label')].filter((s) => !s.hidden && s.textContent);
    const boxes = spans.map((s) => ({ text: s.textContent, r: s.getBoundingClientRect(), size: parseFloat(s.style.fontSize) }));
    const overlaps = [];
    for (let i = 0; i < boxes.length; i++) {
      for (let j = i + 1; j < boxes.length; j++) {
        const [a, b] = [boxes[i].r, boxes[j].r];
        if (a.left < b.right - 1 && b.left < a.right - 1 && a.top < b.bottom - 1 && b.top < a.bottom - 1) overlaps.push(`'${boxes[i].text}' × '${boxes[j].text}'`);
      }
    }
    // Rust's estimate of each text's box (view/labels.rs) against the browser's.
    const use = spans.map((s) => s.getBoundingClientRect().width / Number(s.dataset.estimate)).sort((x, y) => x - y);
    return { count: boxes.length, overlaps, widest: use[use.length - 1] ?? 0, smallest: Math.min(...boxes.map((b) => b.size)) };
  });
}

for (const [name, context] of Object.entries(SIZES)) {
  test(`${name}: no sideways scroll, the figure across the width, the verdict in the first screen, no overlapping text, axe clean`, { timeout: 120000 }, async () => {
    const { page, problems, close } = await open('?preset=fig5.3&mode=full&speed=1', context);
    await page.waitForTimeout(2500);
    const m = await page.evaluate(() => {
      const verdict = [...document.querySelectorAll('#verdict-strip, #verdict')].find((e) => e.getBoundingClientRect().height > 0 && getComputedStyle(e).display !== 'none');
      const v = verdict.getBoundingClientRect();
      return {
        scroll: document.documentElement.scrollWidth, width: innerWidth, height: innerHeight,
        figure: document.querySelector('#canvas-wrap').getBoundingClientRect().width,
        verdictTop: v.top, verdictBottom: v.bottom, verdictId: verdict.id,
      };
    });
    assert.ok(m.scroll <= m.width, `${name}: page ${m.scroll} px wide in a ${m.width}-px window`);
    if (name === 'phone') assert.ok(m.figure >= 0.9 * m.width, `phone: the figure is ${m.figure} of ${m.width} px`);
    assert.ok(m.verdictTop >= 0 && m.verdictBottom <= m.height, `${name}: #${m.verdictId} at ${m.verdictTop}–${m.verdictBottom} px of ${m.height}`);
    const labels = await labelBoxes(page);
    assert.deepEqual(labels.overlaps, [], `${name}: texts over the canvas overlap`);
    assert.ok(labels.smallest >= 11, `${name}: a ${labels.smallest}-px label`);
    assert.ok(labels.widest <= 1.0, `${name}: a text wider than Rust's estimate (×${labels.widest.toFixed(2)})`);
    console.log(`# ${name}: ${labels.count} labels, none overlapping; the widest takes ${(100 * labels.widest).toFixed(0)} % of its estimated width; figure ${m.figure.toFixed(0)} px of ${m.width}`);
    await page.screenshot({ path: path.join(shots, `screen-${name}.png`) });
    assert.deepEqual(await axe(page), [], `${name}: accessibility violations`);
    assert.deepEqual(problems, []);
    await close();
  });
}

test('axe finds nothing on the intro, a lesson step (and on the phone) or the embed, which fits a 640 × 400 frame', { timeout: 180000 }, async () => {
  for (const [query, context, shot] of [
    ['', SIZES.laptop, 'axe-intro.png'],
    ['?lesson=3', SIZES.laptop, 'axe-lesson.png'],
    ['?lesson=3', SIZES.phone, 'lesson-phone.png'],
    ['?preset=fig5.3&embed=1&views=arm,traces', { viewport: { width: 640, height: 400 } }, 'embed.png'],
  ]) {
    const { page, problems, close } = await open(query, context);
    await page.waitForTimeout(1500);
    if (query.includes('lesson') && context === SIZES.phone) assert.ok(await page.isVisible('#sheet-toggle'));
    if (query.includes('embed')) {
      const fit = await page.evaluate(() => [document.documentElement.scrollWidth, document.documentElement.scrollHeight]);
      assert.deepEqual(fit, [640, 400], 'the embed fits its frame without scrolling');
      assert.ok(await page.isVisible('#embed-play') && await page.isVisible('#embed-pf'));
      assert.ok(!(await page.isVisible('.page-header')), 'nothing but the figure and its strip');
      assert.match(await page.textContent('#embed-verdict'), /Unstable/);
    }
    await page.screenshot({ path: path.join(shots, shot) });
    assert.deepEqual(await axe(page), [], `${query || 'intro'}: accessibility violations`);
    assert.deepEqual(problems, []);
    await close();
  }
});

test('the dark scheme: dark page, dark canvas, light ink', { timeout: 120000 }, async () => {
  const { page, problems, close } = await open('?preset=fig5.3&mode=full', { ...SIZES.laptop, colorScheme: 'dark' });
  await page.waitForTimeout(2000);
  const png = await page.locator('#canvas').screenshot();
  const corner = (await pngPixel(page, png, 2, 2)).slice(0, 3);
  assert.ok(corner.every((v) => v < 60), `the canvas background is dark: ${corner}`);
  const [bg, ink] = await page.evaluate(() => [getComputedStyle(document.body).backgroundColor, getComputedStyle(document.body).color]);
  assert.match(bg, /rgb\((\d|[1-4]\d), /, `page background ${bg}`);
  assert.match(ink, /rgb\(2[0-5]\d, /, `ink ${ink}`);
  await page.screenshot({ path: path.join(shots, 'dark.png') });
  assert.deepEqual(await axe(page), [], 'dark: accessibility violations');
  assert.deepEqual(problems, []);
  await close();
});

test('by keyboard: the map point moves with the arrows, the poles read out, exact values can be typed', { timeout: 120000 }, async () => {
  const { page, problems, close } = await open('?preset=fig5.2&mode=full');
  await page.focus('.panel-focus[aria-label^="Stability map without"]');
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => new URLSearchParams(location.search).get('delta') === '0.012');
  assert.equal(new URL(page.url()).searchParams.get('pf'), 'off', 'the map without K_pr runs without it');
  await page.focus('.panel-focus[aria-label^="Pole plot"]');
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => document.querySelector('#figure-said').textContent.length > 10);
  assert.match(await page.textContent('#figure-said'), /pole|A4/);
  assert.ok(await page.isVisible('#plot-tip'), 'the tooltip shows the pole read out');
  await page.fill('#delta-number', '0.04');
  await page.press('#delta-number', 'Enter');
  await page.waitForFunction(() => new URLSearchParams(location.search).get('delta') === '0.04');
  assert.equal(await page.textContent('#delta-value'), '0.0400 s');
  // The slider moves on: the typed field follows it, and a value typed but not committed is dropped.
  const slider = await page.locator('#delta').boundingBox();
  await page.mouse.click(slider.x + 0.2 * slider.width, slider.y + slider.height / 2);
  await page.waitForFunction(() => new URLSearchParams(location.search).get('delta') !== '0.04');
  const afterSlider = new URL(page.url()).searchParams.get('delta');
  assert.equal(await page.inputValue('#delta-number'), afterSlider, 'the field shows the slider\'s δ');
  await page.fill('#delta-number', '0.07');
  await page.mouse.click(slider.x + 0.6 * slider.width, slider.y + slider.height / 2);
  await page.waitForFunction((before) => new URLSearchParams(location.search).get('delta') !== before, afterSlider);
  const second = new URL(page.url()).searchParams.get('delta');
  assert.notEqual(second, '0.07', 'the slider, moved last, sets δ');
  assert.equal(await page.inputValue('#delta-number'), second);
  await page.fill('#delta-number', '-1');
  await page.press('#delta-number', 'Enter');
  await page.waitForSelector('#error:not([hidden])');
  assert.match(await page.textContent('#error'), /must be from 1e-5 s to 10 s/, 'a typed value out of range is explained');
  const description = await page.textContent('#figure-description');
  assert.match(description, /The figure shows the arm/);
  assert.match(description, /Stable|Unstable/);
  assert.deepEqual(problems.filter((p) => !p.includes('must be from 1e-5 s to 10 s')), []);
  await close();
});

test('a phone shows one view at a time and switches with its tabs', { timeout: 120000 }, async () => {
  const { page, problems, close } = await open('?preset=fig5.3&mode=full', SIZES.phone);
  await page.waitForSelector('#view-tabs:not([hidden])');
  const ids = (l) => l.panels.map((p) => p.id).join(',');
  assert.equal(ids(await page.evaluate(() => window.flexarm.lastLayout)), 'arm,e1,e2');
  await page.tap('#tab-maps');
  await page.waitForFunction(() => window.flexarm.lastLayout.panels.map((p) => p.id).join(',') === 'map-off,map-on');
  assert.equal(await page.getAttribute('#tab-maps', 'aria-selected'), 'true');
  await page.screenshot({ path: path.join(shots, 'phone-maps-tab.png') });
  // The maps answer a tap.
  const map = (await page.evaluate(() => window.flexarm.lastLayout)).panels.find((p) => p.id === 'map-off');
  const box = await page.locator('#canvas').boundingBox();
  await page.touchscreen.tap(box.x + map.x + 0.75 * map.width, box.y + map.y + 0.5 * map.height);
  await page.waitForFunction(() => Number(new URLSearchParams(location.search).get('delta')) > 0.03);
  assert.deepEqual(problems, []);
  await close();
});
