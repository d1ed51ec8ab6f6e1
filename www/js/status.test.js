import { test } from 'node:test';
import assert from 'node:assert/strict';
import { bandGradient, liveText } from './status.js';

test('the slider track shows each window as a hard-edged band', () => {
  const g = bandGradient([[0.25, 0.5]], 'green', 'red');
  assert.equal(g, 'linear-gradient(to right, red 0%, red 25.00%, green 25.00%, green 50.00%, red 50.00%, red 100%)');
  assert.equal(bandGradient([], 'g', 'r'), 'linear-gradient(to right, r 0%, r 100%)');
});

test('a live number shows the story\'s text, or a dash while there is none', () => {
  assert.equal(liveText({ a4: '2.64 ± 29.58j 1/s' }, 'a4'), '2.64 ± 29.58j 1/s');
  assert.equal(liveText({ a4: '2.64 ± 29.58j 1/s' }, 'rho'), '—');
  assert.equal(liveText(null, 'a4'), '—');
});
