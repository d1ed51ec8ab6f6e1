import { test } from 'node:test';
import assert from 'node:assert/strict';
import { arrowSteps } from './focus.js';

test('arrow keys step across and up', () => {
  assert.deepEqual(arrowSteps('ArrowRight'), [1, 0]);
  assert.deepEqual(arrowSteps('ArrowDown'), [0, -1]);
  assert.equal(arrowSteps('Enter'), null);
});
