// A z-plane to look into (issue 23, item 4): at Fig. 5.3 the flexible pair (|λ| = 1.024) is shown
// outside the unit circle by default with |λ| − 1 written beside it; the wheel, the + − keys and
// buttons, a drag and a two-finger pinch zoom and pan it; the zoom is in the link and survives a
// reload. Screenshots of the zoomed z-plane at Fig. 5.3 go to /tmp/shots23/zplane-*.png.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { shared, openPage, SIZES, AXE } from './harness.mjs';

const env = shared();
const SHOTS = '/tmp/shots23';
fs.mkdirSync(SHOTS, { recursive: true });
const FIG53 = '?preset=fig5.3&mode=full&plane=z';

/** The z-plane's panel as the page last placed it (page CSS px), once it is there. */
async function zPanel(page) {
  await page.waitForFunction(() => window.flexarm.lastLayout?.panels.some((p) => p.id === 'z-plane'), null, { timeout: 20000 });
  return page.evaluate(() => window.flexarm.lastLayout.panels.find((p) => p.id === 'z-plane'));
}

/** The page's point (viewport px) at a fraction of the z-plane's panel. */
async function zPoint(page, fx = 0.5, fy = 0.5) {
  const p = await zPanel(page);
  const c = await page.locator('#canvas').boundingBox();
  return { x: c.x + p.x + fx * p.width, y: c.y + p.y + fy * p.height };
}

/** A number of the address (NaN if missing). */
const param = (page, key) => Number(new URL(page.url()).searchParams.get(key) ?? NaN);

/** Waits until the address's zsize satisfies `ok`, and returns it. */
async function zsizeWhen(page, ok, what) {
  for (let i = 0; i < 100; i++) {
    const z = param(page, 'zsize');
    if (ok(z)) return z;
    await page.waitForTimeout(50);
  }
  assert.fail(`zsize never ${what}: ${page.url()}`);
}

/** Waits until the address's zsize has not changed for a while (a wheel's events come spread
 * over time), and returns it. */
async function settled(page) {
  let last = param(page, 'zsize');
  for (let same = 0; same < 6; ) {
    await page.waitForTimeout(100);
    const z = param(page, 'zsize');
    same = z === last || (Number.isNaN(z) && Number.isNaN(last)) ? same + 1 : 0;
    last = z;
  }
  return last;
}

/** The |λ| − 1 the labels overlay says, or null. */
const gapSaid = (page) => page.evaluate(() => {
  const text = [...document.querySelectorAll('#axes-overlay .label')].map((l) => l.textContent).find((t) => t.includes('|λ| − 1 = '));
  return text ? Number(text.split('|λ| − 1 = ')[1].replace('−', '-').replace('+', '')) : null;
});

test('Fig. 5.3: |λ| − 1 is readable by default; wheel, keys, buttons and a drag zoom and pan; the link keeps it', { timeout: 120000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, FIG53, SIZES.laptop);
  await zPanel(page);
  await page.waitForFunction(() => document.querySelector('#axes-overlay')?.textContent.includes('|λ| − 1 = '), null, { timeout: 20000 });
  const gap = await gapSaid(page);
  assert.ok(Math.abs(gap - 0.024) < 5e-4, `the paper's |λ| = 1.024: ${gap}`);
  assert.ok(Number.isNaN(param(page, 'zsize')), 'the default view writes nothing into the link');

  // The wheel over the z-plane zooms (and the page does not scroll).
  const mid = await zPoint(page);
  await page.mouse.move(mid.x, mid.y);
  const scrolled = await page.evaluate(() => window.scrollY);
  await page.mouse.wheel(0, -300);
  await zsizeWhen(page, (z) => z > 0, 'set by the wheel');
  const z1 = await settled(page);
  assert.equal(await page.evaluate(() => window.scrollY), scrolled, 'the wheel zoomed instead of scrolling');
  // + and − with the pointer over it.
  await page.keyboard.press('+');
  const z2 = await zsizeWhen(page, (z) => z < z1 * 0.9, 'smaller after +');
  await page.keyboard.press('-');
  const z3 = await zsizeWhen(page, (z) => z > z2 * 1.1, 'larger after −');
  assert.ok(Math.abs(z3 - z1) / z1 < 0.01, `− undoes + (${z1} → ${z2} → ${z3})`);
  // The buttons.
  await page.click('button[aria-label="Show the whole unit circle"]');
  await zsizeWhen(page, (z) => z === 1.2, 'the whole circle');
  await page.click('button[aria-label="Zoom in on the z-plane"]');
  await page.click('button[aria-label="Zoom in on the z-plane"]');
  await zsizeWhen(page, (z) => Math.abs(z - 1.2 / 2.25) < 0.01, 'zoomed in twice by the button');
  // A drag pans: the plane follows the pointer (dragging left shows more to the right).
  const re0 = Number(new URL(page.url()).searchParams.get('zre') ?? 0);
  const from = await zPoint(page, 0.6, 0.5);
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  await page.mouse.move(from.x - 40, from.y, { steps: 4 });
  await page.mouse.move(from.x - 80, from.y, { steps: 4 });
  await page.mouse.up();
  await page.waitForFunction((r) => Number(new URL(location.href).searchParams.get('zre') ?? 0) > r + 0.01, re0);
  // The state string carries the zoom, and a reload shows the same part of the plane.
  const state = await page.evaluate(() => window.flexarm.session.stateString());
  assert.match(state, /zsize=[0-9.]+/);
  assert.match(state, /zre=/);
  const before = await zPanel(page);
  await page.reload();
  await page.waitForFunction(() => document.querySelector('#backend')?.textContent?.trim().length > 0);
  const after = await zPanel(page);
  for (const k of ['x_range', 'y_range']) {
    for (const i of [0, 1]) assert.ok(Math.abs(after[k][i] - before[k][i]) < 1e-9, `${k} after a reload: ${after[k]} vs ${before[k]}`);
  }
  // By keyboard: the z-plane's region takes + − 0 P.
  await page.focus('.panel-focus.takes-pointer');
  await page.keyboard.press('0');
  await zsizeWhen(page, (z) => z === 1.2, 'the whole circle by the 0 key');
  await page.keyboard.press('p');
  await page.waitForFunction(() => !new URL(location.href).searchParams.has('zsize'));
  await page.addScriptTag({ path: AXE });
  const axe = await page.evaluate(async () => (await window.axe.run(document, { runOnly: ['wcag2a', 'wcag2aa'] })).violations.map((v) => `${v.id}: ${v.nodes.map((n) => n.target).join(', ')}`));
  assert.deepEqual(axe, []);
  assert.deepEqual(problems, []);
  await close();
});

test('a two-finger pinch zooms the z-plane on a phone', { timeout: 90000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, `${FIG53}&tab=poles`, SIZES.phone);
  await zPanel(page);
  const c = await zPoint(page);
  const cdp = await page.context().newCDPSession(page);
  const touch = (type, d) => cdp.send('Input.dispatchTouchEvent', {
    type,
    touchPoints: type === 'touchEnd' ? [] : [{ x: c.x - d, y: c.y, id: 1 }, { x: c.x + d, y: c.y, id: 2 }],
  });
  const before = (await zPanel(page)).y_range;
  await touch('touchStart', 20);
  for (const d of [30, 40, 50, 60]) await touch('touchMove', d);
  await touch('touchEnd', 0);
  const z = await zsizeWhen(page, (v) => v > 0, 'set by the pinch');
  // Fingers 40 → 120 px apart: three times closer than the default view.
  assert.ok(z > 0 && z < 0.1, `pinched in: zsize ${z}`);
  await page.waitForFunction((h) => {
    const p = window.flexarm.lastLayout.panels.find((q) => q.id === 'z-plane');
    return p.y_range[1] - p.y_range[0] < h / 2;
  }, before[1] - before[0]);
  assert.deepEqual(problems, []);
  await close();
});

for (const [name, size] of Object.entries(SIZES)) {
  test(`screenshot: the zoomed z-plane at Fig. 5.3 on the ${name} screen`, { timeout: 90000 }, async () => {
    const query = `${FIG53}${name === 'phone' ? '&tab=poles' : ''}`;
    const { page, problems, close } = await openPage(env.browser, env.server.base, query, size);
    await zPanel(page);
    await page.waitForFunction(() => window.flexarm.session.status().timeline.end > 2, null, { timeout: 30000 });
    await page.waitForFunction(() => document.querySelector('#axes-overlay')?.textContent.includes('|λ| − 1 = '));
    const canvas = await page.locator('#canvas').boundingBox();
    const z = await zPanel(page);
    // The default view, then zoomed on the pair with the + button.
    await page.screenshot({ path: path.join(SHOTS, `zplane-${name}-default.png`) });
    await page.click('button[aria-label="Zoom in on the z-plane"]');
    await zsizeWhen(page, (v) => v > 0, 'set by the button');
    await page.waitForTimeout(300);
    const clip = { x: canvas.x + z.x - 60, y: canvas.y + z.y - 50, width: z.width + 80, height: z.height + 100 };
    await page.screenshot({ path: path.join(SHOTS, `zplane-${name}.png`) });
    await page.screenshot({ path: path.join(SHOTS, `zplane-${name}-panel.png`), clip });
    assert.deepEqual(problems, []);
    await close();
  });
}
