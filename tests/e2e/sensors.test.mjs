// Issue 36: what bounds δ from below on a real arm. The section "A real robot" takes an encoder,
// differenced velocities and a torque limit through the schema like δ; its study fills a table of
// error and torque against δ a slew per frame, says whether a best δ exists (from the numbers),
// and times the controller in this browser. The verdict says ρ is the noise-free loop's. Prints
// the time the study took and the controller's time; screenshots at the three sizes go to
// screenshots/sensors-*.png.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { shared, openPage, SIZES, shots } from './harness.mjs';

const env = shared();
const REAL = '?mode=full&preset=real-encoder';

/**
 * Opens the section and waits until the study of the sensors `named` (a pattern of the summary) is
 * done; returns its texts and the time it took.
 */
async function study(page, named) {
  const started = Date.now();
  await page.evaluate(() => {
    const d = /** @type {HTMLDetailsElement} */ (document.getElementById('sensors-details'));
    d.open = true;
    d.scrollIntoView({ block: 'start' });
  });
  await page.waitForFunction((source) => {
    const rows = [...document.querySelectorAll('#sensors-table tbody tr')];
    return new RegExp(source).test(document.getElementById('sensors-summary')?.textContent ?? '')
      && rows.length === 11 && !rows.some((r) => r.textContent.includes('…'))
      && document.getElementById('sensors-progress')?.textContent === '';
  }, named.source, { timeout: 60000, polling: 100 });
  const ms = Date.now() - started;
  const texts = await page.evaluate(() => ({
    summary: document.getElementById('sensors-summary')?.textContent ?? '',
    findings: [...document.querySelectorAll('#sensors-summary-list li')].map((n) => n.textContent),
    prediction: document.getElementById('sensors-prediction')?.textContent ?? '',
    processor: document.getElementById('sensors-processor')?.textContent ?? '',
    best: document.querySelector('#sensors-table tr.best th')?.textContent ?? '',
    current: document.querySelector('#sensors-table tr.current th')?.textContent ?? '',
    head: [...document.querySelectorAll('#sensors-table thead th')].map((n) => n.textContent),
  }));
  return { ...texts, ms };
}

test('a real robot: a coarse encoder has a best δ, a fine one not; the controller timed here', { timeout: 240000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, REAL);
  const s = await study(page, /1024-count/);
  console.log(`sensor study (1024 counts, differenced, 150 N m): ${s.ms} ms to fill 11 δ × 2 runs; ${s.processor}`);
  assert.match(s.summary, /a 1024-count encoder, velocities differenced over δ, torque at most 150 N m/);
  assert.ok(s.head.some((h) => /at the limit/.test(h)), s.head.join(' | '));
  assert.match(s.findings.join(' '), /A best δ exists with these sensors: the error during the slew is smallest at δ = 0\.005 s/);
  assert.match(s.findings.join(' '), /sits at its 150 N m limit/);
  assert.equal(s.best.trim(), '0.005');
  assert.match(s.current, /0\.01/);
  assert.match(s.prediction, /^Linear prediction at δ = 0\.01 s .*ρ of the noise-free digital loop 0\.984/);
  assert.match(s.processor, /takes [\d.]+ (ns|µs|ms) per sample here: [\d.]+ % of δ = 10 ms/);
  // The run's status says what ρ is with sensors on: the same ρ as the prediction's.
  const rhoLine = await page.locator('#verdict-rho').textContent();
  assert.match(rhoLine ?? '', /the digital loop without its sensors' error\): ρ = 0\.9841 < 1/);
  // Under it, what limits the error: the encoder, through the differenced velocity, with the
  // prediction's own numbers.
  const limits = (await page.locator('#verdict-limits').textContent()) ?? '';
  assert.ok(await page.locator('#verdict-limits').isVisible());
  assert.match(limits, /^The sensors' noise: the 1024-count encoder through the velocities differenced over δ/);
  // The headline's promise with sensors: the errors shrink to the floor their error leaves.
  assert.match((await page.locator('#verdict-detail').textContent()) ?? '', /down to the floor the sensors' error leaves/);
  const e1 = /RMS e1 ([^ ]+) rad/.exec(s.prediction)?.[1];
  assert.ok(e1 && limits.includes(`${e1} rad RMS`), `${limits} | ${s.prediction}`);
  // The velocity filtered: the smallest δ no longer markedly worse, and the status says the filter.
  await page.locator('button.try', { hasText: 'Try: the real encoder with its velocity filtered' }).click();
  await page.waitForFunction(() => new URL(location.href).searchParams.get('velocity_filter') === '0.002', null, { timeout: 10000 });
  const filtered = await study(page, /filtered with τᵥ = 0\.002 s/);
  assert.doesNotMatch(filtered.findings.join(' '), /A best δ exists/);
  assert.match((await page.locator('#verdict-limits').textContent()) ?? '', /differenced over δ and filtered \(τᵥ = 0\.002 s\)/);
  // Choosing a row's δ runs the arm at it: the ▸ moves there.
  await page.locator('#sensors-table button.row-delta', { hasText: /^0\.005$/ }).click();
  await page.waitForFunction(() => new URL(location.href).searchParams.get('delta') === '0.005', null, { timeout: 10000 });
  await page.waitForFunction(() => document.querySelector('#sensors-table tr.current th')?.textContent === '0.005', null, { timeout: 10000 });
  // A finer encoder: no best δ above the smallest studied.
  await page.locator('button.try', { hasText: 'Try: a finer one (16384 counts)' }).click();
  await page.waitForFunction(() => new URL(location.href).searchParams.get('encoder') === '16384', null, { timeout: 10000 });
  const fine = await study(page, /16384-count/);
  assert.match(fine.summary, /16384-count encoder/);
  assert.doesNotMatch(fine.findings.join(' '), /A best δ exists/);
  assert.match(fine.findings.join(' '), /smallest at the smallest δ studied, 0\.002 s/);
  // Back to the paper's robot: the study is the paper's slew, once per δ, and nothing to predict.
  await page.locator('button.try', { hasText: "Back to the paper's perfect robot" }).click();
  await page.waitForFunction(() => !new URL(location.href).searchParams.has('encoder'), null, { timeout: 10000 });
  const paper = await study(page, /perfect sensors/);
  assert.match(paper.summary, /perfect sensors, unlimited torque/);
  assert.match(paper.prediction, /no noise to predict/);
  assert.ok(await page.locator('#verdict-limits').isHidden(), 'nothing limits the perfect robot');
  assert.deepEqual(problems, []);
  await close();

  for (const [name, size] of Object.entries(SIZES)) {
    const shot = await openPage(env.browser, env.server.base, REAL, size);
    if (name === 'phone') await shot.page.getByText('Controls, verdict and lesson').first().click();
    await study(shot.page, /1024-count/);
    await shot.page.evaluate(() => document.getElementById('sensors-study')?.scrollIntoView({ block: 'start' }));
    await shot.page.waitForTimeout(300);
    await shot.page.screenshot({ path: path.join(shots, `sensors-${name}.png`) });
    assert.deepEqual(shot.problems, [], name);
    await shot.close();
  }
});

// "What the controller reads": the switch in "A real robot" adds the measured errors (held over
// each period) to the error plots and says so in the key; the torque limit is drawn on the torques
// and keyed. Screenshots of the figure at the three sizes: screenshots/sensors-measured-*.png.
test('a real robot: the measured errors and the torque limit in the figure', { timeout: 180000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, `${REAL}&torque=1`);
  const key = () => page.evaluate(() => document.getElementById('figure-key')?.textContent ?? '');
  await page.waitForFunction(() => /limit ±150 N m/.test(document.getElementById('figure-key')?.textContent ?? ''), null, { timeout: 20000 });
  assert.doesNotMatch(await key(), /as measured/);
  // The switch sits in "A real robot".
  await page.evaluate(() => { /** @type {HTMLDetailsElement} */ (document.getElementById('sensors-details')).open = true; });
  const box = page.locator('#sensors-group [data-param="measured"] input[type="checkbox"]');
  assert.equal(await box.count(), 1);
  assert.equal(await box.isChecked(), false);
  await box.check();
  await page.waitForFunction(() => new URL(location.href).searchParams.get('measured') === '1', null, { timeout: 10000 });
  await page.waitForFunction(() => /What the controller reads.*e1 as measured/.test(document.getElementById('figure-key')?.textContent ?? ''), null, { timeout: 10000 });
  assert.match(await key(), /limit ±150 N m/);
  // The digital controller's velocity estimate beside the true q̇1, in a panel of its own.
  assert.match(await key(), /q̇1 as estimated/);
  await page.waitForFunction(() => window.flexarm.lastLayout?.panels?.some((/** @type {{id: string}} */ p) => p.id === 'velocity'), null, { timeout: 10000 });
  // The perfect robot: nothing to compare, and said so.
  await page.locator('button.try', { hasText: "Back to the paper's perfect robot" }).click();
  await page.waitForFunction(() => /sensors off: the controller reads the true state/.test(document.getElementById('figure-key')?.textContent ?? ''), null, { timeout: 10000 });
  assert.doesNotMatch(await key(), /limit ±/);
  assert.doesNotMatch(await key(), /q̇1 as estimated/);
  await page.waitForFunction(() => !window.flexarm.lastLayout?.panels?.some((/** @type {{id: string}} */ p) => p.id === 'velocity'), null, { timeout: 10000 });
  assert.deepEqual(problems, []);
  await close();

  for (const [name, size] of Object.entries(SIZES)) {
    const shot = await openPage(env.browser, env.server.base, `${REAL}&torque=1&measured=1&window=2`, size);
    await shot.page.waitForTimeout(3000);
    await shot.page.screenshot({ path: path.join(shots, `sensors-measured-${name}.png`) });
    if (name !== 'phone') {
      await shot.page.evaluate(() => document.getElementById('figure-key')?.scrollIntoView({ block: 'center' }));
      await shot.page.waitForTimeout(300);
      await shot.page.screenshot({ path: path.join(shots, `sensors-measured-key-${name}.png`) });
    }
    assert.deepEqual(shot.problems, [], name);
    await shot.close();
  }
});

test('a real robot: the study drawn against δ beside ρ(δ), filled with its section closed; a click runs the arm at a δ', { timeout: 180000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, `${REAL}&study=1`, SIZES.large);
  // The section stays closed: the figure asks for the study, and the page runs it for the figure.
  assert.equal(await page.evaluate(() => /** @type {HTMLDetailsElement} */ (document.getElementById('sensors-details')).open), false);
  const panel = (/** @type {string} */ id) => page.evaluate((i) => window.flexarm.lastLayout?.panels?.find((/** @type {{id: string}} */ p) => p.id === i) ?? null, id);
  await page.waitForFunction(() => ['study-error', 'study-torque'].every((id) => window.flexarm.lastLayout?.panels?.some((/** @type {{id: string}} */ p) => p.id === id)), null, { timeout: 20000 });
  await page.waitForFunction(() => window.flexarm.lastLayout?.panels?.find((/** @type {{id: string}} */ p) => p.id === 'study-error')?.note === 'error against δ', null, { timeout: 90000, polling: 200 });
  const since = await page.evaluate(() => performance.now());
  console.log(`# the study against δ drawn complete within ${since.toFixed(0)} ms of the navigation, the page's load included (11 δ × 2 slews of 3 s; polled every 200 ms)`);
  const error = await panel('study-error');
  assert.equal(error.x_scale, 'log');
  assert.equal(error.y_scale, 'log');
  assert.match(error.x_label, /δ \[s\]/);
  assert.match(error.y_label, /rad/);
  assert.match((await panel('study-torque')).y_label, /N m/);
  const key = await page.evaluate(() => document.getElementById('figure-key')?.textContent ?? '');
  for (const needle of ['max |e| during the slew, these sensors', 'perfect sensors', 'the best δ', 'torque limit']) assert.ok(key.includes(needle), needle);
  // A click over δ = 0.02 s on the error panel runs the arm at the row's δ.
  const canvas = await page.locator('#canvas').boundingBox();
  const [lo, hi] = error.x_range;
  const x = canvas.x + error.x + error.width * Math.log(0.02 / lo) / Math.log(hi / lo);
  await page.mouse.click(x, canvas.y + error.y + error.height / 2);
  await page.waitForFunction(() => new URL(location.href).searchParams.get('delta') === '0.02', null, { timeout: 10000 });
  assert.deepEqual(problems, []);
  await close();

  for (const [name, size] of Object.entries(SIZES)) {
    const shot = await openPage(env.browser, env.server.base, `${REAL}&study=1${name === 'phone' ? '&tab=study' : ''}`, size);
    await shot.page.waitForFunction(() => window.flexarm.lastLayout?.panels?.find((/** @type {{id: string}} */ p) => p.id === 'study-error')?.note === 'error against δ', null, { timeout: 90000, polling: 200 });
    await shot.page.waitForTimeout(500);
    await shot.page.screenshot({ path: path.join(shots, `sensors-study-${name}.png`) });
    assert.deepEqual(shot.problems, [], name);
    await shot.close();
  }
});
