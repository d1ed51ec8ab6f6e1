import { test } from 'node:test';
import assert from 'node:assert/strict';
import { bandGradient } from './status.js';

test('the slider track shows each window as a hard-edged band', () => {
  const g = bandGradient([[0.25, 0.5]], 'green', 'red');
  assert.equal(g, 'linear-gradient(to right, red 0%, red 25.00%, green 25.00%, green 50.00%, red 50.00%, red 100%)');
  assert.equal(bandGradient([], 'g', 'r'), 'linear-gradient(to right, r 0%, r 100%)');
});
