// Every text the page shows fits (issue 20): at a phone (390 × 844, touch), a laptop (1280 × 800)
// and a large screen (1920 × 1080), in the light and the dark scheme, in the full view, with the
// lesson open and embedded, every tooltip of every pole and of a map lies inside its box and the
// viewport, no label over the canvas overlaps another, and a label shortened with "…" carries its
// whole text as its title.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { shared, openPage, shots } from './harness.mjs';

const env = shared();

const SIZES = [
  { name: 'phone', viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true },
  { name: 'laptop', viewport: { width: 1280, height: 800 } },
  { name: 'large', viewport: { width: 1920, height: 1080 } },
];
const STATES = [
  ['full', '?preset=fig5.3&mode=full&tab=poles&speed=0.5'],
  ['lesson', '?lesson=5'],
  ['zoom', '?preset=fig5.3&mode=full&predict=1&swing=1&speed=0.5'],
  ['embed', '?preset=fig5.3&embed=1&views=arm,traces,zplane,rho,map&speed=0.5'],
];

/** Boxes of the visible labels over the canvas, with their texts and titles. */
const labelsOf = (page) => page.$$eval('#axes-overlay span.label', (spans) => spans
  .filter((s) => !s.hidden && s.offsetParent !== null)
  .map((s) => {
    const r = s.getBoundingClientRect();
    return { text: s.textContent, title: s.title, x: r.x, y: r.y, w: r.width, h: r.height };
  }));

/** Whether the tooltip's text fits its box, and the box the wrapper and the viewport. */
const tipFits = (page) => page.evaluate(() => {
  const tip = document.getElementById('plot-tip');
  const wrap = document.getElementById('canvas-wrap').getBoundingClientRect();
  const r = tip.getBoundingClientRect();
  const lines = [...tip.children].map((c) => ({ text: c.textContent, over: c.scrollWidth - c.clientWidth }));
  return {
    visible: !tip.hidden,
    inside: r.left >= wrap.left - 1 && r.right <= wrap.right + 1 && r.top >= wrap.top - 1 && r.bottom <= wrap.bottom + 1,
    inView: r.left >= 0 && r.right <= window.innerWidth + 1 && r.top >= 0 && r.bottom <= window.innerHeight + 1,
    spill: tip.scrollWidth - tip.clientWidth,
    lines: lines.filter((l) => l.over > 1),
    text: tip.textContent,
  };
});

for (const size of SIZES) {
  for (const scheme of ['light', 'dark']) {
    for (const [state, query] of STATES) {
      test(`texts fit: ${size.name}, ${scheme}, ${state}`, { timeout: 90000 }, async () => {
        const { name, ...options } = size;
        const { page, problems, close } = await openPage(env.browser, env.server.base, query, { ...options, colorScheme: scheme });
        await page.waitForFunction(() => (window.flexarm?.lastLayout?.labels || []).length > 5, null, { timeout: 20000 });
        await page.waitForTimeout(800);
        // No two labels overlap; a shortened one carries its whole text.
        const labels = await labelsOf(page);
        for (const [i, a] of labels.entries()) {
          if (a.text.endsWith('…')) assert.ok(a.title.length > a.text.length - 1, `${a.text} has no title`);
          for (const b of labels.slice(i + 1)) {
            const apart = a.x + a.w <= b.x + 0.5 || b.x + b.w <= a.x + 0.5 || a.y + a.h <= b.y + 0.5 || b.y + b.h <= a.y + 0.5;
            assert.ok(apart, `'${a.text}' overlaps '${b.text}'`);
          }
        }
        // Hover the poles (each of a ± pair once) and a map cell: every tooltip fits.
        const layout = await page.evaluate(() => window.flexarm.lastLayout);
        const box = await page.locator('#canvas').boundingBox();
        const points = layout.poles.filter((p) => p.in_view && p.x != null && p.im >= 0).slice(0, 8).map((p) => [p.x, p.y]);
        const map = layout.panels.find((p) => p.id === 'map-on' || p.id === 'map-off');
        if (map) points.push([map.x + map.width * 0.9, map.y + map.height * 0.1]);
        let shown = 0;
        for (const [x, y] of points) {
          await page.mouse.move(box.x + x, box.y + y);
          await page.waitForTimeout(150);
          const fit = await tipFits(page);
          if (!fit.visible) continue;
          shown += 1;
          assert.ok(fit.inside && fit.inView, `${fit.text}: outside the figure or the viewport`);
          assert.ok(fit.spill <= 1 && fit.lines.length === 0, `${fit.text}: text wider than its box ${JSON.stringify(fit.lines)}`);
        }
        if (points.length > 0 && state !== 'lesson') assert.ok(shown > 0, 'some tooltip was hovered');
        await page.screenshot({ path: path.join(shots, `fit-${size.name}-${scheme}-${state}.png`) });
        assert.deepEqual(problems, []);
        await close();
      });
    }
  }
}

/** Visible controls smaller than a 44-px touch target (a checkbox counts with its row). */
const smallTargets = (page) => page.evaluate(() => [...document.querySelectorAll('button, input, select, summary, [tabindex="0"]')]
  .filter((el) => el.getBoundingClientRect().height > 0 && getComputedStyle(el).visibility !== 'hidden')
  .map((el) => {
    const row = el.type === 'checkbox' || el.type === 'radio' ? el.closest('.field, .choice, label') : null;
    const r = (row ?? el).getBoundingClientRect();
    return { what: `${el.tagName.toLowerCase()}#${el.id} "${(el.textContent || el.getAttribute('aria-label') || '').trim().slice(0, 40)}"`, w: r.width, h: r.height };
  })
  .filter((t) => t.w < 44 || t.h < 44)
  .map((t) => `${t.what} ${Math.round(t.w)}×${Math.round(t.h)}`));

for (const [state, query] of [['controls', '?preset=fig5.3&mode=full'], ['lesson', '?lesson=5']]) {
  test(`a phone with the sheet open (${state}): the figure stays in view above it, every control is a 44-px target`, { timeout: 90000 }, async () => {
    const { name, ...options } = SIZES[0];
    const { page, problems, close } = await openPage(env.browser, env.server.base, query, options);
    await page.waitForSelector('#sheet-toggle');
    if (state === 'controls') await page.tap('#sheet-toggle');
    await page.waitForFunction(() => document.getElementById('panel').classList.contains('open'));
    await page.waitForTimeout(600);
    const view = await page.evaluate(() => {
      const canvas = document.getElementById('canvas').getBoundingClientRect();
      const sheet = document.getElementById('panel').getBoundingClientRect();
      const first = document.querySelector('#panel .open, #lesson:not([hidden]) h2, #verdict')?.getBoundingClientRect();
      return { canvasTop: canvas.top, canvasBottom: canvas.bottom, canvasHeight: canvas.height, sheetTop: sheet.top, firstBottom: first?.bottom ?? 0, height: window.innerHeight };
    });
    assert.ok(view.canvasTop >= 0 && view.canvasBottom <= view.sheetTop + 1, `the figure (${Math.round(view.canvasTop)}–${Math.round(view.canvasBottom)} px) lies above the sheet (from ${Math.round(view.sheetTop)} px)`);
    assert.ok(view.canvasHeight >= 0.25 * view.height, `the figure keeps a useful height (${Math.round(view.canvasHeight)} px)`);
    assert.ok(view.firstBottom <= view.height, 'the sheet shows its first lines');
    assert.deepEqual(await smallTargets(page), [], 'controls smaller than 44 px');
    await page.screenshot({ path: path.join(shots, `phone-sheet-${state}.png`) });
    assert.deepEqual(problems, []);
    await close();
  });
}
