import { test } from 'node:test';
import assert from 'node:assert/strict';
import { nextTab } from './tabs.js';

test('arrow keys go round the tabs', () => {
  assert.equal(nextTab(0, 'ArrowRight', 3), 1);
  assert.equal(nextTab(2, 'ArrowRight', 3), 0);
  assert.equal(nextTab(0, 'ArrowLeft', 3), 2);
  assert.equal(nextTab(1, 'End', 3), 2);
  assert.equal(nextTab(1, 'Enter', 3), null);
});
