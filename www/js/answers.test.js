import { test } from 'node:test';
import assert from 'node:assert/strict';
import { answersFileName, answersJson, clock, storageKey } from './answers.js';

test('a lesson text has its own storage key', () => {
  assert.equal(storageKey('fnv1a64:00ff'), 'flexarm.answers.fnv1a64:00ff');
  assert.notEqual(storageKey('fnv1a64:00ff'), storageKey('fnv1a64:00fe'));
});

test('the download is named after the lesson, in safe characters', () => {
  assert.equal(answersFileName('Homework: the windows of δ', 'csv'), 'flexarm-answers-homework-the-windows-of.csv');
  assert.equal(answersFileName('<script>', 'json'), 'flexarm-answers-script.json');
  // With the student's name: 60 files of one lesson do not share a name.
  assert.equal(answersFileName('Homework: the windows of δ', 'csv', 'Ada Lovelace 12345'), 'flexarm-answers-homework-the-windows-of-ada-lovelace-12345.csv');
  assert.equal(answersFileName('', 'csv'), 'flexarm-answers-lesson.csv');
});

test('the time reads as a UTC clock', () => {
  assert.equal(clock('2026-11-26T05:19:43Z'), '05:19:43 UTC');
  assert.equal(clock(''), '');
});

test('the JSON is the CSV\'s rows, named by its columns', () => {
  const csv = '# flexarm lesson answers: T (fnv1a64:00, 2 steps)\nlesson,lesson_hash,step,step_title,kind,choice,choice_text,result,state,time\nT,fnv1a64:00,1,"A, b",prediction,2,"say ""hi""",right,delta=0.01,2026-11-26T05:03:00Z\nT,fnv1a64:00,2,C,task,,,shown,pf=off,\n';
  const j = answersJson(csv);
  assert.deepEqual(j.head, ['flexarm lesson answers: T (fnv1a64:00, 2 steps)']);
  assert.equal(j.entries.length, 2);
  assert.deepEqual(j.entries[0], { lesson: 'T', lesson_hash: 'fnv1a64:00', step: 1, step_title: 'A, b', kind: 'prediction', choice: 2, choice_text: 'say "hi"', result: 'right', state: 'delta=0.01', time: '2026-11-26T05:03:00Z' });
  assert.equal(j.entries[1].choice, '');
});
