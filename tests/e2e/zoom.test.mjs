// The paper's Fig. 2.1, live (issue 19): the zoom on one sampling instant is a switch of the
// View group; it zooms the time plots on t_n (ticks named after it), says in words what the
// controller measured, predicted and holds, and Step ◂ ▸ walk it one period at a time. The swing's
// shape animates on the arm while the run is paused. Prints what a frame costs with both on.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { shared, openPage, shots, pictureDifference } from './harness.mjs';

const env = shared();
const caption = (page) => page.evaluate(() => window.flexarm.session.status().cycle);
const instant = (text) => Number(/tₙ = ([0-9.]+) s/.exec(text)?.[1]);
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

test('Fig. 2.1 live: the zoom names t_n, predicts, holds one period later, and Step ◂ ▸ walk it', { timeout: 90000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, '?preset=fig5.3&mode=full');
  await page.waitForFunction(() => window.flexarm.session.status().timeline.end > 1.5, null, { timeout: 20000 });
  await page.click('#play');
  assert.equal(await page.$eval('#zoom-caption', (e) => e.hidden), true, 'no caption before the zoom');
  await page.check('#predict');
  await page.waitForFunction(() => /predict=1/.test(location.search));
  await page.waitForFunction(() => !document.querySelector('#zoom-caption').hidden, null, { timeout: 5000 });
  const live = await page.textContent('#zoom-caption');
  assert.match(live, /^Fig\. 2\.1 at tₙ = [0-9.]+ s \(δ = 0\.01 s\): the controller measured x\(tₙ\)/);
  assert.match(live, /still to come/);
  // The plots are zoomed: the torque panel is there, its ticks are the sampling instants.
  await page.waitForFunction(() => window.flexarm.lastLayout?.panels.some((p) => p.id === 'torque'));
  const torque = await page.evaluate(() => window.flexarm.lastLayout.panels.find((p) => p.id === 'torque'));
  assert.deepEqual(torque.x_labels.map((l) => l.text), ['tₙ−δ', 'tₙ', 'tₙ+δ', 'tₙ+2δ']);
  assert.equal(torque.y_label, 'u1, u2 [N m]');
  await page.waitForFunction(() => /Fig\. 2\.1: one sampling instant/.test(document.querySelector('#figure-key').textContent));
  await page.screenshot({ path: path.join(shots, 'zoom-live-laptop.png') });
  // Step ◂ twice: t_n two periods back, the hold has happened.
  await page.click('#step-back');
  const once = instant(await caption(page));
  await page.click('#step-back');
  await page.waitForFunction((t) => /tₙ = ([0-9.]+) s/.exec(window.flexarm.session.status().cycle)?.[1] !== t.toFixed(3), once);
  const back = await caption(page);
  assert.ok(Math.abs(instant(back) - (once - 0.01)) < 1e-6, `${back} after ${once}`);
  assert.doesNotMatch(back, /still to come/);
  assert.match(back, /held from tₙ \+ δ = [0-9.]+ s to tₙ \+ 2δ = [0-9.]+ s \(green\)\./);
  await page.waitForFunction(() => !document.querySelector('#zoom-caption').hidden && /held from/.test(document.querySelector('#zoom-caption').textContent));
  await page.screenshot({ path: path.join(shots, 'zoom-back-laptop.png') });
  // Step ▸ one period forward.
  await page.click('#step');
  await page.waitForFunction((t) => /tₙ = ([0-9.]+) s/.exec(window.flexarm.session.status().cycle)?.[1] !== t.toFixed(3), instant(back));
  assert.ok(Math.abs(instant(await caption(page)) - (instant(back) + 0.01)) < 1e-6);
  // The figure's text alternative says it too.
  assert.match(await page.textContent('#figure-description'), /zoomed on one sampling instant/);
  // Off again: the caption goes.
  await page.uncheck('#predict');
  await page.waitForFunction(() => document.querySelector('#zoom-caption').hidden);
  assert.deepEqual(problems, []);
  await close();
});

test('the swing\'s shape animates on the arm while the run is paused, and stops when switched off', { timeout: 90000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, '?preset=fig5.3&mode=full&swing=1&predict=1');
  await page.waitForFunction(() => window.flexarm.session.status().timeline.end > 1.0, null, { timeout: 20000 });
  await page.click('#play');
  await page.waitForFunction(() => document.querySelector('#play').getAttribute('aria-pressed') === 'false');
  const arm = await page.evaluate(() => window.flexarm.lastLayout.panels.find((p) => p.id === 'arm'));
  const clip = async () => {
    const box = await page.locator('#canvas').boundingBox();
    return page.screenshot({ clip: { x: box.x + arm.x, y: box.y + arm.y, width: arm.width, height: arm.height } });
  };
  const a = await clip();
  await page.waitForTimeout(400);
  const b = await clip();
  const moving = await pictureDifference(page, a, b);
  assert.ok(moving.differ > 0.001, `the swing moves while paused: ${JSON.stringify(moving)}`);
  await page.screenshot({ path: path.join(shots, 'swing-laptop.png') });
  // What a frame costs with the zoom and the swing on (every frame draws while it animates).
  const before = await page.evaluate(() => window.flexarmPerf());
  await page.waitForTimeout(2000);
  const after = await page.evaluate(() => window.flexarmPerf());
  console.log(`# paused with the zoom and the swing: ${after.frames - before.frames} frames in 2 s; script per frame median ${after.script_ms_median?.toFixed(2)} ms`);
  // The key says the shape in numbers.
  const key = await page.textContent('#figure-key');
  assert.match(key, /the swing's shape/);
  assert.match(key, /link 1 \(q1\): [0-9.]+ × the motor's angle/);
  // Off: the arm stands still.
  await page.uncheck('#swing');
  await page.waitForTimeout(300);
  const c = await clip();
  await page.waitForTimeout(400);
  const d = await clip();
  const still = await pictureDifference(page, c, d);
  assert.ok(still.differ < 0.0005, `still once off: ${JSON.stringify(still)}`);
  assert.deepEqual(problems, []);
  await close();
});
