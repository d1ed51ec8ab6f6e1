import { test } from 'node:test';
import assert from 'node:assert/strict';
import { axisFraction, roomAbove } from './axes.js';

test('linear and log fractions', () => {
  assert.equal(axisFraction(5, 0, 10, 'linear'), 0.5);
  assert.equal(axisFraction(3, 3, 3, 'linear'), 0, 'an empty range does not divide by zero');
  assert.ok(Math.abs(axisFraction(0.01, 0.001, 0.1, 'log') - 0.5) < 1e-12);
});

test('room above a panel stops at the panel above it and its tick labels', () => {
  const panels = [
    { x: 0, y: 10, width: 100, height: 50, x_labels: [1] },
    { x: 0, y: 100, width: 100, height: 50, x_labels: [] },
    { x: 200, y: 100, width: 100, height: 50 },
  ];
  assert.equal(roomAbove(panels, 1, 19), 100 - (60 + 19));
  assert.equal(roomAbove(panels, 2, 19), 100, 'nothing above in its column');
  assert.equal(roomAbove(panels, 0, 19), 10);
});
