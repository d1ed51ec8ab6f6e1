import { test } from 'node:test';
import assert from 'node:assert/strict';
import { keyBelongsTo } from './keys.js';

test('shortcuts give way to what the focus needs', () => {
  assert.equal(keyBelongsTo({ tagName: 'INPUT', type: 'number' }, 'r'), true, 'typing');
  assert.equal(keyBelongsTo({ tagName: 'INPUT', type: 'range' }, 'ArrowRight'), true, 'the slider moves');
  assert.equal(keyBelongsTo({ tagName: 'INPUT', type: 'range' }, ' '), false);
  assert.equal(keyBelongsTo({ tagName: 'BUTTON' }, ' '), true, 'a button presses itself');
  assert.equal(keyBelongsTo({ tagName: 'BODY' }, ' '), false);
  assert.equal(keyBelongsTo({ tagName: 'SELECT' }, 'ArrowRight'), true);
  assert.equal(keyBelongsTo({ tagName: 'INPUT', type: 'range' }, 'ArrowLeft'), true, 'the slider moves back');
  assert.equal(keyBelongsTo({ tagName: 'INPUT', type: 'radio' }, 'ArrowLeft'), true, 'the lesson\'s choices');
  assert.equal(keyBelongsTo({ tagName: 'BODY' }, 'ArrowLeft'), false);
});
