import { test } from 'node:test';
import assert from 'node:assert/strict';
import { positionOf, timeAt } from './timeline.js';

test('the scrubber maps the kept span onto its track and back', () => {
  assert.equal(positionOf(15, 10, 20), 500);
  assert.equal(timeAt(500, 10, 20), 15);
  assert.equal(positionOf(25, 10, 20), 1000, 'clamped to now');
  assert.equal(positionOf(3, 10, 20), 0, 'clamped to the oldest kept');
  assert.equal(positionOf(0, 0, 0), 1000, 'nothing kept yet: live');
  for (const p of [0, 137, 999, 1000]) assert.equal(positionOf(timeAt(p, 2, 32), 2, 32), p);
});
