// What a student found on the page (issue 34, items 13, 16, 17 and 18), where only the browser
// shows it: α1's box links like its slider, the Showing line names a model error, the previous
// run's ghost is dropped after an arm change, the lesson's first task waits for the student's Play,
// and on a phone the verdict strip does not cover the figure nor the open sheet the timeline.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { shared, openPage, shots, SIZES } from './harness.mjs';

const env = shared();

test('typing α1 with "Link α1 = α2" ticked sets both, as the slider does', { timeout: 60000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, '?preset=fig5.3&mode=full');
  assert.equal(await page.isChecked('#link-alpha'), true);
  await page.fill('#alpha1-number', '5');
  await page.press('#alpha1-number', 'Enter');
  await page.waitForFunction(() => /α = 5 1\/s/u.test(document.getElementById('showing')?.textContent ?? ''), null, { timeout: 10000 });
  assert.equal(await page.inputValue('#alpha2-number'), '5', 'α2 follows α1');
  assert.match(page.url(), /[?&]alpha=5(&|$)/u);
  // The slider links the same way.
  await page.fill('#alpha2-number', '3');
  await page.press('#alpha2-number', 'Enter');
  await page.waitForFunction(() => /α = 3 1\/s/u.test(document.getElementById('showing')?.textContent ?? ''), null, { timeout: 10000 });
  assert.deepEqual(problems, []);
  await close();
  // Opened with unequal α, the box is not ticked.
  const apart = await openPage(env.browser, env.server.base, '?mode=full&alpha1=5&alpha2=2');
  assert.equal(await apart.page.isChecked('#link-alpha'), false);
  await apart.close();
});

test('the Showing line names a model error; the A4 row says what its value is', { timeout: 60000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, '?mode=full&arm=stiffer&model=paper&pf=off');
  await page.waitForFunction(() => (document.getElementById('showing')?.textContent ?? '').includes('assumes'), null, { timeout: 10000 });
  assert.match(await page.textContent('#showing'), /the controller assumes the paper's arm/u);
  assert.match(await page.textContent('#ro-a4'), /not A4/u);
  assert.doesNotMatch(await page.textContent('#ro-a4'), /\(A4\)/u);
  assert.deepEqual(problems, []);
  await close();
});

test('after an arm change the previous run is no ghost on the new arm\'s scale', { timeout: 60000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, '?preset=fig5.3&mode=full&speed=4');
  await page.waitForFunction(() => window.flexarm.session.status().runs[0].readouts.time.startsWith('3'), null, { timeout: 20000 });
  // A restart on the same arm keeps the previous run, faint, and says so.
  await page.click('#reset');
  await page.waitForFunction(() => !document.getElementById('ghost-caption').hidden, null, { timeout: 5000 });
  await page.waitForFunction(() => parseFloat(window.flexarm.session.status().runs[0].readouts.time) > 2, null, { timeout: 20000 });
  await page.click('#arm-details > summary');
  await page.selectOption('#arm-preset', 'stiffer');
  await page.waitForTimeout(500);
  assert.equal(await page.evaluate(() => window.flexarm.session.status().ghost), '');
  assert.equal(await page.isHidden('#ghost-caption'), true);
  await page.screenshot({ path: path.join(shots, 'student-ghost-after-arm.png') });
  assert.deepEqual(problems, []);
  await close();
});

test('the lesson\'s first task waits for the student\'s Play', { timeout: 60000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, '?lesson=1');
  await page.waitForTimeout(2500);
  const s = await page.evaluate(() => window.flexarm.session.status());
  assert.equal(s.runs[0].readouts.time, '0.00 s', 'nothing runs before Play');
  assert.match(s.lesson.record.headline, /Tasks: 0 of \d+ done yourself/u);
  assert.deepEqual(problems, []);
  await close();
});

test('phone: the verdict strip does not cover the figure, the open sheet not the timeline', { timeout: 90000 }, async () => {
  for (const query of ['?preset=fig5.3&mode=full', '?lesson=1', '?preset=fig5.3']) {
    const { page, problems, close } = await openPage(env.browser, env.server.base, query, SIZES.phone);
    await page.waitForTimeout(800);
    const box = (sel) => page.$eval(sel, (e) => { const r = e.getBoundingClientRect(); return { top: r.top, bottom: r.bottom }; });
    // Scrolled far down, then the figure brought back ("Try:", an answer): below the strip.
    await page.evaluate(() => window.scrollTo(0, document.body.scrollHeight));
    await page.evaluate(async () => (await import('./js/sheet.js')).showFigure());
    await page.waitForTimeout(900);
    const strip = await box('#verdict-strip');
    const wrap = await box('#canvas-wrap');
    assert.ok(wrap.top >= strip.bottom - 1, `${query}: the figure (top ${wrap.top}) under the strip (bottom ${strip.bottom})`);
    // The sheet open: the whole timeline, its "t = … drag" line included, above it.
    if (!(await page.evaluate(() => document.body.classList.contains('sheet-open')))) await page.click('#sheet-toggle');
    await page.waitForTimeout(900);
    const sheet = await box('#panel');
    const text = await box('#timeline-text');
    const wrapOpen = await box('#canvas-wrap');
    const stripOpen = await box('#verdict-strip');
    assert.ok(text.bottom <= sheet.top + 1, `${query}: the timeline's line (bottom ${text.bottom}) under the sheet (top ${sheet.top})`);
    assert.ok(wrapOpen.top >= stripOpen.bottom - 1, `${query}: the figure under the strip with the sheet open`);
    await page.screenshot({ path: path.join(shots, `student-phone-${query.includes('lesson') ? 'lesson' : query.includes('full') ? 'full' : 'intro'}.png`) });
    assert.deepEqual(problems, []);
    await close();
  }
});
