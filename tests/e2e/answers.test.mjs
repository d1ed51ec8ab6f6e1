// Answers to hand in and student mode (issue 21, items 2 and 3), in the page: a student's
// predictions and tasks are summed up at the end of the lesson, downloaded as CSV and JSON (each
// row with the lesson's title and hash, the step, the choice, right/wrong, the state and the
// time), kept across a reload in this browser only and cleared by a visible button. With
// `answers=hidden` the verdict, ρ, the windows and the maps are hidden — for the eye and the screen
// reader alike — until the step's question is answered.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { shared, openPage, shots, clickForDownload } from './harness.mjs';
import { csvCells } from '../../www/js/answers.js';

const env = shared();
const HOMEWORK = '?lesson_src=lessons/windows.md';

/** Answers every question with its second choice and presses "Show me" on every task, to the end. */
async function walk(page) {
  for (let i = 0; i < 10; i++) {
    if (await page.isVisible('#lesson-question') && await page.isEnabled('#lesson-choice-1')) await page.check('#lesson-choice-1');
    if (await page.isVisible('#lesson-reveal')) await page.click('#lesson-reveal');
    if (await page.isDisabled('#lesson-next')) return;
    await page.click('#lesson-next');
  }
}

test('the answers are summed up at the end, downloaded, kept across a reload and cleared', { timeout: 90000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, HOMEWORK);
  await page.waitForFunction(() => !document.querySelector('#lesson').hidden, null, { timeout: 10000 });
  // Nothing yet; the summary stays folded before the last step.
  assert.equal(await page.textContent('#lesson-record-summary'), 'Your answers (0)');
  assert.equal(await page.$eval('#lesson-record', (d) => /** @type {HTMLDetailsElement} */ (d).open), false);
  await walk(page);
  // The last step opens the summary by itself.
  await page.waitForFunction(() => /** @type {HTMLDetailsElement} */ (document.querySelector('#lesson-record')).open);
  const headline = await page.textContent('#lesson-record-headline');
  assert.match(headline ?? '', /^Your predictions: \d of 3 right\. Tasks: 0 of 2 done yourself, 2 shown by “Show me”\.$/);
  assert.equal(await page.$$eval('#lesson-record-rows li', (li) => li.length), 5);
  await page.locator('#lesson-record').scrollIntoViewIfNeeded();
  await page.screenshot({ path: path.join(shots, 'answers-summary-laptop.png') });

  // The name, asked once: it goes into the file and its name (a teacher gets 60 files).
  await page.fill('#student-name', 'Ada Lovelace 12345');
  await page.press('#student-name', 'Tab');
  const download = await clickForDownload(page, '#answers-csv');
  assert.equal(download.name, 'flexarm-answers-homework-the-windows-of-ada-lovelace-12345.csv');
  const lines = download.bytes.toString('utf8').trim().split('\n');
  assert.match(lines[0], /^# flexarm lesson answers: Homework: the windows of δ \(fnv1a64:[0-9a-f]{16}, 5 steps\)/);
  assert.equal(lines[1], '# student: Ada Lovelace 12345');
  // The last line checks the name and the rows (the teacher's merge finds an edited row by it).
  assert.match(lines[lines.length - 1], /^# check: fnv1a64:[0-9a-f]{16}$/);
  const csv = lines.filter((l) => !l.startsWith('#'));
  csv.unshift(lines[0]);
  assert.equal(csv[1], 'lesson,lesson_hash,step,step_title,kind,choice,choice_text,result,state,time');
  assert.equal(csv.length, 2 + 5);
  for (const row of csv.slice(2)) {
    assert.match(row, /^Homework: the windows of δ,fnv1a64:[0-9a-f]{16},[1-5],/);
    assert.match(row, /,(right|wrong|shown|done),[^,]*lesson_src=lessons%2Fwindows\.md&lesson=[1-5],\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ$/);
  }
  const json = JSON.parse((await clickForDownload(page, '#answers-json')).bytes.toString('utf8'));
  // The same rows as the CSV, named by its columns; only the lesson's own data (nothing of the
  // browser, the page's storage or the user).
  assert.deepEqual(Object.keys(json).sort(), ['entries', 'head']);
  assert.equal(json.entries.length, 5);
  assert.deepEqual(Object.keys(json.entries[0]), csv[1].split(','));
  assert.ok(json.entries.every((e) => e.lesson === 'Homework: the windows of δ' && /^fnv1a64:/.test(e.lesson_hash)));
  // A reload gives them back (localStorage, one key per lesson text).
  await page.reload();
  await page.waitForFunction(() => document.querySelector('#lesson-record-summary')?.textContent === 'Your answers (5)', null, { timeout: 15000 });
  assert.equal(await page.inputValue('#student-name'), 'Ada Lovelace 12345', 'the name is asked once');
  const keys = await page.evaluate(() => Object.keys(localStorage));
  assert.deepEqual(keys.filter((k) => k.startsWith('flexarm.answers.')).length, 1);

  // Clear: asked twice in the button, then gone here and in the browser's memory.
  await page.click('#answers-clear');
  assert.equal(await page.textContent('#answers-clear'), 'Click again to clear them all');
  await page.click('#answers-clear');
  await page.waitForFunction(() => document.querySelector('#lesson-record-summary')?.textContent === 'Your answers (0)');
  assert.equal(await page.evaluate(() => Object.keys(localStorage).filter((k) => k.startsWith('flexarm.answers.')).length), 0);
  assert.deepEqual(problems, []);
  await close();
});

test('student mode hides the verdict, ρ, the windows and the maps until the step is answered', { timeout: 90000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, `${HOMEWORK}&answers=hidden&map=1`);
  await page.waitForFunction(() => !document.querySelector('#lesson').hidden, null, { timeout: 10000 });
  await page.waitForTimeout(1500);
  const said = async () => page.evaluate(() => [
    document.querySelector('#verdict')?.textContent,
    document.querySelector('#verdict-announce')?.textContent,
    document.querySelector('#figure-description')?.textContent,
    document.querySelector('#verdict-strip')?.textContent,
    document.querySelector('#showing')?.textContent,
  ].join(' | '));
  const hidden = await said();
  assert.doesNotMatch(hidden, /ρ = \d|[Uu]nstable|Stable|1\.02\d\d/, hidden);
  assert.match(await page.textContent('#hidden-text') ?? '', /Student mode: .* hidden until you answer this step's question/);
  assert.equal(await page.isVisible('#show-answers'), true);
  assert.equal(await page.isHidden('#delta-windows'), true);
  assert.equal(await page.$eval('#delta', (s) => s.classList.contains('banded')), false);
  assert.equal(await page.isDisabled('#map'), true);
  assert.equal(await page.isDisabled('#poles'), true);
  assert.equal(await page.isDisabled('#export-data-csv'), true);
  // The page's own sentences that state the answer are gone too (innerText: what is shown).
  assert.doesNotMatch(await page.evaluate(() => /** @type {HTMLElement} */ (document.querySelector('.intro')).innerText), /unstable/);
  assert.equal(await page.isVisible('#explain'), false);
  await page.screenshot({ path: path.join(shots, 'student-mode-hidden-laptop.png') });

  // Answering (right or wrong) shows them.
  await page.check('#lesson-choice-0');
  await page.waitForFunction(() => document.querySelector('#hidden-note')?.hasAttribute('hidden'));
  await page.waitForFunction(() => /ρ = \d/.test(document.querySelector('#verdict')?.textContent ?? ''), null, { timeout: 10000 });
  assert.match(await said(), /[Uu]nstable/);

  // The next step hides them again; "Show them" lifts student mode and the record says so.
  await page.click('#lesson-next');
  await page.waitForSelector('#hidden-note:not([hidden])');
  await page.click('#show-answers');
  await page.waitForFunction(() => document.querySelector('#hidden-note')?.hasAttribute('hidden'));
  await page.waitForFunction(() => /You showed the hidden answers/.test(document.querySelector('#lesson-record-headline')?.textContent ?? ''));
  assert.deepEqual(problems, []);
  await close();
});

test('the teacher drops 60 answer files on the page: one table, each step\'s share right, the edited file named', { timeout: 120000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, '?lesson_src=lessons/windows.md&mode=full');
  await page.waitForFunction(() => !document.querySelector('#lesson').hidden, null, { timeout: 10000 });
  // 60 students walk the homework in this page's classroom, each naming themselves: student n
  // picks the first choice of every question when n is a multiple of 3, else the second.
  const files = await page.evaluate(() => {
    const s = /** @type {any} */ (window).flexarm.session;
    const out = [];
    for (let n = 0; n < 60; n++) {
      s.lessonOpen(0);
      s.clearAnswers();
      s.setStudent(`Student ${String(n).padStart(2, '0')}`);
      for (;;) {
        const l = s.status().lesson;
        if (l.question) s.lessonAnswer(n % 3 === 0 ? 0 : 1);
        if (!l.can_next) break;
        s.lessonNext();
      }
      out.push({ name: `student-${String(n).padStart(2, '0')}.csv`, text: s.answersCsv() });
    }
    return out;
  }).catch(async () => null);
  assert.ok(files, 'the students\' files were made');
  // Student 3 turns a wrong answer right by hand.
  const edited = files[3].text.replace(',wrong,', ',right,');
  assert.notEqual(edited, files[3].text);
  files[3].text = edited;
  await page.setInputFiles('#class-files', files.map((f) => ({ name: f.name, mimeType: 'text/csv', buffer: Buffer.from(f.text) })));
  await page.waitForSelector('#class-table:not([hidden])', { timeout: 10000 });
  assert.equal(await page.textContent('#class-summary'), '59 answer files counted, 1 not.');
  assert.match(await page.textContent('#class-refused') ?? '', /Not counted: student-03\.csv — its check does not match: a row or the name was edited/);
  const rows = await page.$$eval('#class-rows tr', (trs) => trs.map((tr) => [...tr.children].map((c) => c.textContent)));
  console.log(`# the class table:\n${rows.map((r) => `#   ${r.join(' | ')}`).join('\n')}`);
  // Each question's share right is what the 59 intact files say, counted here from their rows.
  const asked = rows.filter((r) => r[1]);
  assert.ok(asked.length >= 2, JSON.stringify(rows));
  for (const r of asked) {
    const step = Number((r[0] ?? '').split('.')[0]);
    const right = files.filter((f, i) => i !== 3 && f.text.split('\n').some((line) => {
      const c = csvCells(line);
      return c[2] === String(step) && c[4] === 'prediction' && c[7] === 'right';
    })).length;
    assert.match(r[1] ?? '', new RegExp(`^${right} of 59, `), JSON.stringify(r));
  }
  // Each student's row: the 59 who counted, by name, right at the first try as their own rows say.
  assert.equal(await page.evaluate(() => /** @type {HTMLDialogElement} */ (document.querySelector('#class-dialog')).open), true, 'the table opens in its own window');
  const rowsOfStudents = await page.$$eval('#class-students tr', (trs) => trs.map((tr) => [...tr.children].map((c) => c.textContent)));
  const students = rowsOfStudents.filter((r) => !/^not counted/.test(r[1] ?? ''));
  assert.equal(students.length, 59);
  assert.ok(!students.some((r) => r[0] === 'Student 03'), 'the edited file has no row of marks');
  assert.deepEqual(rowsOfStudents.filter((r) => /^not counted/.test(r[1] ?? '')).map((r) => r[0]), ['student-03.csv'], 'it is named among the students');
  for (const n of [0, 1, 42]) {
    const name = `Student ${String(n).padStart(2, '0')}`;
    const mine = files[n].text.split('\n').map(csvCells).filter((c) => c[4] === 'prediction');
    const firsts = new Map();
    for (const c of mine) if (!firsts.has(c[2])) firsts.set(c[2], c[7]);
    const right = [...firsts.values()].filter((r) => r === 'right').length;
    const row = students.find((r) => r[0] === name);
    assert.equal(row?.[1], `${right} of ${firsts.size}`, `${name}: ${JSON.stringify(row)}`);
    // A mark per step: ✓ or ✗ where they answered, as their first try was.
    const heads = await page.$$eval('#class-students-head th', (ths) => ths.map((th) => th.textContent));
    for (const [step, result] of firsts) {
      assert.equal(row?.[heads.indexOf(step)], result === 'right' ? '✓' : '✗', `${name}, step ${step}`);
    }
  }
  // The table's window is as wide as the screen allows, not the side panel's width.
  const width = await page.$eval('#class-dialog', (d) => d.getBoundingClientRect().width);
  assert.ok(width > 900, `the class's window is ${width} px wide`);
  await page.locator('#class-dialog').screenshot({ path: path.join(shots, 'class-table-laptop.png') });
  await page.click('#class-close');
  assert.equal(await page.evaluate(() => /** @type {HTMLDialogElement} */ (document.querySelector('#class-dialog')).open), false);
  await page.click('#class-show');
  assert.equal(await page.evaluate(() => /** @type {HTMLDialogElement} */ (document.querySelector('#class-dialog')).open), true, 'shown again');
  assert.deepEqual(problems, []);
  await close();
});
