import { test } from 'node:test';
import assert from 'node:assert/strict';
import { placement } from './overlays.js';

test('a label sits on its anchor by the point its alignment names', () => {
  const l = { panel: 'e1', class: 'tick', text: '0.5', x: 100, y: 50, align: [1, 0.5], size: 12, time: null, width: 20 };
  assert.equal(placement(l), 'translate(100.0px, 50.0px) translate(-100%, -50%)');
  assert.equal(placement({ ...l, align: [0.5, 0] }, 42.25), 'translate(42.3px, 50.0px) translate(-50%, 0%)');
});
