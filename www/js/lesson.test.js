import { test } from 'node:test';
import assert from 'node:assert/strict';
import { choiceMark } from './lesson.js';

test('a chosen answer is marked, with words as well as colour', () => {
  const open = { prompt: 'Q', choices: ['a', 'b', 'c'], chosen: null, correct: null };
  assert.deepEqual(choiceMark(open, 0), { cls: '', note: '' }, 'nothing before the prediction');
  const wrong = { ...open, chosen: 0, correct: 2 };
  assert.deepEqual(choiceMark(wrong, 0), { cls: 'wrong', note: ' — your prediction' });
  assert.deepEqual(choiceMark(wrong, 2), { cls: 'right', note: ' — the right answer' });
  assert.deepEqual(choiceMark(wrong, 1), { cls: '', note: '' });
  const right = { ...open, chosen: 1, correct: 1 };
  assert.equal(choiceMark(right, 1).note, ' — your prediction, right');
});
