// The arm is a setting (issue 18): its group is reachable and usable by keyboard and on a phone,
// moving an arm slider moves A4, ρ and the windows of δ, the URL carries the arm (k1=…) and a
// reload reproduces it, and an impossible arm is refused with a reason while the page goes on.
// Prints the time from one change of the arm to ρ, A4 and the windows recomputed (medians in
// the page's wasm) and how long both maps take after it.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { shared, openPage, shots } from './harness.mjs';

const env = shared();
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const story = (page) => page.evaluate(() => window.flexarm.session.status().story);
const windowsText = (page) => page.evaluate(() => window.flexarm.session.status().windows?.text ?? '');

test('an arm slider moves A4, ρ and the windows; the URL keeps the arm and a reload reproduces it', { timeout: 120000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, '?preset=fig5.3&mode=full&speed=0.5');
  await page.waitForFunction(() => window.flexarm?.session.status().story != null, null, { timeout: 20000 });
  await page.waitForFunction(() => window.flexarm.session.status().windows != null, null, { timeout: 20000 });
  const paper = { story: await story(page), windows: await windowsText(page) };
  assert.equal(paper.story.arm, "the paper's arm");
  // The equations are MathML in the page, with the sentence's numbers.
  await page.waitForFunction(() => document.querySelector('[data-math="re_a4"] math') != null);
  const re = await page.$eval('[data-math="re_a4"]', (e) => e.textContent);
  assert.ok(re.includes(paper.story.re_a4.replace(' 1/s', '')), `${re} has ${paper.story.re_a4}`);
  // By keyboard: open the group, Tab to the stiffness slider, arrow keys up through round values.
  await page.focus('#arm-details > summary');
  await page.keyboard.press('Enter');
  assert.equal(await page.$eval('#arm-details', (d) => d.open), true);
  await page.focus('#k1');
  for (let i = 0; i < 4; i++) await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => /k1=/.test(location.search));
  const k1 = new URL(page.url()).searchParams.get('k1');
  assert.ok(Number(k1) > 1152.6, `K1 went up: ${k1}`);
  await page.waitForFunction((a4) => window.flexarm.session.status().story?.a4 !== a4, paper.story.a4);
  await page.waitForFunction((w) => (window.flexarm.session.status().windows?.text ?? w) !== w, paper.windows, { timeout: 20000 });
  const stiff = { story: await story(page), windows: await windowsText(page) };
  assert.match(stiff.story.arm, /^K1 = /);
  assert.notEqual(stiff.story.omega_joint, paper.story.omega_joint, 'a stiffer spring rings faster');
  assert.notEqual(stiff.story.rho, paper.story.rho);
  // The selector says it is an arm of its own (the status is drawn a few times a second).
  await page.waitForFunction(() => document.querySelector('#arm-preset').value === '', null, { timeout: 5000 });
  assert.match(await page.textContent('#run-note'), /arm changed/);
  await page.screenshot({ path: path.join(shots, 'arm-keyboard-k1.png') });
  // The URL reproduces it.
  const url = page.url();
  const again = await openPage(env.browser, env.server.base, new URL(url).search);
  await again.page.waitForFunction(() => window.flexarm?.session.status().story != null, null, { timeout: 20000 });
  const reloaded = await story(again.page);
  assert.equal(reloaded.a4, stiff.story.a4);
  assert.equal(reloaded.arm, stiff.story.arm);
  assert.deepEqual(again.problems, []);
  await again.close();

  // Speed: one change of the arm to ρ, A4 and the windows of δ recomputed, in the page's wasm.
  const ms = await page.evaluate(() => {
    const s = window.flexarm.session;
    const out = [];
    for (const v of [1000, 1100, 1200, 1300, 1400, 1500, 1600, 1700, 1800]) {
      const t0 = performance.now();
      s.set('k1', String(v));
      const st = s.status();
      if (!st.story || !st.windows) throw new Error('not recomputed');
      out.push(performance.now() - t0);
    }
    return out;
  });
  console.log(`# arm change to ρ, A4 and the windows of δ: median ${median(ms).toFixed(1)} ms over ${ms.length} changes of K1 (goal ≤ 16 ms)`);
  // A drag of the stiffness slider for about three seconds, as a hand makes it: the page's main
  // thread should not block (long tasks over 50 ms are counted, not asserted: a figure).
  await page.evaluate(() => {
    window.__longTasks = [];
    new PerformanceObserver((list) => { for (const e of list.getEntries()) window.__longTasks.push(e.duration); })
      .observe({ type: 'longtask', buffered: false });
  });
  const box = await page.locator('#k1').boundingBox();
  await page.mouse.move(box.x + box.width * 0.3, box.y + box.height / 2);
  await page.mouse.down();
  for (let i = 0; i <= 90; i++) {
    await page.mouse.move(box.x + box.width * (0.3 + 0.4 * Math.sin(i / 15) ** 2), box.y + box.height / 2);
    await page.waitForTimeout(33);
  }
  await page.mouse.up();
  await page.waitForTimeout(300);
  const long = await page.evaluate(() => window.__longTasks);
  const observed = await page.evaluate(() => PerformanceObserver.supportedEntryTypes.includes('longtask'));
  assert.ok(observed, 'this Chromium reports long tasks');
  assert.notEqual(new URL(page.url()).searchParams.get('k1'), k1, 'the drag moved K1');
  console.log(`# a 3-s drag of K1: ${long.length} main-thread tasks over 50 ms${long.length ? ` (longest ${Math.max(...long).toFixed(0)} ms)` : ''} (goal: none)`);
  // Both maps after a change made as a user makes it (the page schedules their work then).
  await page.fill('#k1-number', '2000');
  // Every finished map is counted: done with two more than before is the new arm's pair. (Not the
  // line's text: two arms' maps can take the same time to the hundredth of a second, and the text
  // is then the same — a wait on a changed text hung once in CI.)
  const before = await page.evaluate(() => window.flexarm.session.session.mapTimes().length);
  const mapStart = await page.evaluate(() => performance.now());
  await page.press('#k1-number', 'Enter');
  await page.waitForFunction((b) => {
    const m = window.flexarm.session.status().maps;
    return m.done && window.flexarm.session.session.mapTimes().length >= b + 2;
  }, before, { timeout: 60000 });
  const mapEnd = await page.evaluate(() => performance.now());
  const line = await page.evaluate(() => window.flexarm.session.status().maps.text);
  console.log(`# both maps after an arm change: ${(mapEnd - mapStart).toFixed(0)} ms from the key press (goal ≤ 500 ms); the page's line: ${line}`);
  assert.deepEqual(problems, []);
  await close();
});

test('an arm preset and an impossible arm: the damped motor is stable without K_pr; A3 = 2 is refused with its reason', { timeout: 90000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, '?preset=fig5.3&mode=full');
  await page.waitForFunction(() => window.flexarm?.session.status().story != null, null, { timeout: 20000 });
  await page.$eval('#arm-details', (d) => { d.open = true; });
  await page.selectOption('#arm-preset', 'damped');
  await page.waitForFunction(() => new URLSearchParams(location.search).get('bv1') === '15');
  await page.waitForFunction(() => document.querySelector('#verdict').dataset.verdict === 'stable', null, { timeout: 20000 });
  const s = await story(page);
  assert.match(s.damping_needed, /^B_v1 > 3α I_r1 = 11\.6 N m s\/rad as δ → 0; .* \(this arm: 15 N m s\/rad\)$/);
  assert.match(s.re_a4, /^−/, `Re A4 < 0: ${s.re_a4}`);
  await page.screenshot({ path: path.join(shots, 'arm-damped.png') });
  // Under the paper's gains on another arm, the page says they stay fixed (none without K_pr).
  assert.equal(await page.textContent('.kpr-note'), '');
  await page.selectOption('#pf', 'paper');
  await page.waitForFunction(() => /keeps its fixed gains, designed for the paper's arm/.test(document.querySelector('.kpr-note').textContent));
  // An impossible arm: refused with its reason, and the page goes on with the arm it had.
  await page.fill('#a3-number', '2');
  await page.press('#a3-number', 'Enter');
  await page.waitForSelector('#error:not([hidden])');
  assert.match(await page.textContent('#error'), /mass matrix positive definite/);
  assert.equal(new URLSearchParams(new URL(page.url()).search).get('a3'), null, 'the arm is unchanged');
  assert.equal(await page.inputValue('#a3-number'), '0.328');
  assert.deepEqual(problems.filter((p) => !/positive definite/.test(p)), []);
  await close();
});

test('the arm group on a phone: reachable in the sheet, every control a 44-px target', { timeout: 90000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, '?preset=fig5.3&mode=full',
    { viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true });
  await page.waitForSelector('#sheet-toggle');
  await page.tap('#sheet-toggle');
  await page.locator('#arm-details > summary').scrollIntoViewIfNeeded();
  await page.tap('#arm-details > summary');
  await page.locator('#k1').scrollIntoViewIfNeeded();
  const small = await page.$$eval('#arm-group input, #arm-group select, #arm-group summary', (els) => els
    .map((el) => {
      const r = el.getBoundingClientRect();
      return { id: el.id || el.tagName, w: r.width, h: r.height };
    })
    .filter((t) => t.h > 0 && (t.h < 44 || t.w < 44))
    .map((t) => `${t.id} ${Math.round(t.w)}×${Math.round(t.h)}`));
  assert.deepEqual(small, []);
  await page.screenshot({ path: path.join(shots, 'arm-phone.png') });
  assert.deepEqual(problems, []);
  await close();
});

test('the controller may assume the paper\'s arm: the damped motor then grows without K_pr, the page names the pair it tends to, and the link keeps it', { timeout: 90000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, '?preset=fig5.3&mode=full&arm=damped&delta=0.005');
  await page.waitForFunction(() => window.flexarm?.session.status().story != null, null, { timeout: 20000 });
  await page.waitForFunction(() => document.querySelector('#verdict').dataset.verdict === 'stable', null, { timeout: 20000 });
  assert.equal(await page.$eval('[data-live="model_note"]', (e) => e.textContent), '');
  await page.$eval('#arm-details', (d) => { d.open = true; });
  await page.selectOption('#model', 'paper');
  await page.waitForFunction(() => new URLSearchParams(location.search).get('model') === 'paper');
  // ρ > 1 now: the linear verdict turns (the run itself grows slowly, at ln ρ/δ).
  await page.waitForFunction(() => window.flexarm.session.status().runs[0].spectral_radius > 1, null, { timeout: 20000 });
  const s = await story(page);
  assert.match(s.model_note, /^The controller assumes the paper's arm/);
  assert.ok(s.model_note.includes(s.a4), 'the note names A4 for a controller that knows the arm');
  assert.equal(await page.$eval('#arm-group [data-live="model_note"]', (e) => e.textContent), s.model_note);
  await page.screenshot({ path: path.join(shots, 'arm-model-paper.png') });
  // The link reproduces it.
  const again = await openPage(env.browser, env.server.base, new URL(page.url()).search);
  await again.page.waitForFunction(() => window.flexarm?.session.status().story != null, null, { timeout: 20000 });
  assert.equal((await story(again.page)).model_note, s.model_note);
  assert.equal(await again.page.inputValue('#model'), 'paper');
  await again.close();
  assert.deepEqual(problems, []);
  await close();
});
