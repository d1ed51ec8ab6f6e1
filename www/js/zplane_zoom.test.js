// The z-plane's gestures and keys as sizes and actions (the view's maths is Rust's, tests/zplane.rs).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { wheelFactor } from './pointer.js';
import { zKey } from './focus.js';
import { zAction } from './zplane_zoom.js';

test('a wheel notch zooms by about 1.2, up in and down out, the same in lines and pixels', () => {
  const notch = wheelFactor({ deltaY: -100, deltaMode: 0 });
  assert.ok(notch > 1.15 && notch < 1.25, `${notch}`);
  assert.ok(Math.abs(wheelFactor({ deltaY: 100, deltaMode: 0 }) * notch - 1) < 1e-12, 'out undoes in');
  assert.ok(Math.abs(wheelFactor({ deltaY: -3, deltaMode: 1 }) - notch) < 0.01, 'three lines are a notch');
  assert.ok(wheelFactor({ deltaY: -1e6, deltaMode: 0 }) < 3, 'one huge event is bounded');
});

test('+ − 0 P zoom, show the whole circle or the pair; Shift and the arrows pan; other keys do nothing', () => {
  assert.deepEqual(zKey({ key: '+' }), { zoom: 1.5 });
  assert.deepEqual(zKey({ key: '=' }), { zoom: 1.5 });
  assert.deepEqual(zKey({ key: '-' }), { zoom: 1 / 1.5 });
  assert.deepEqual(zKey({ key: '0' }), { view: 'whole' });
  assert.deepEqual(zKey({ key: 'P' }), { view: 'pair' });
  assert.deepEqual(zKey({ key: 'ArrowUp', shiftKey: true }), { pan: [0, 1] });
  assert.equal(zKey({ key: 'ArrowUp' }), null, 'plain arrows step from pole to pole');
  assert.equal(zKey({ key: 'r' }), null);
  assert.deepEqual(zAction('in'), zKey({ key: '+' }));
  assert.deepEqual(zAction('whole'), { view: 'whole' });
  assert.equal(zAction('bogus'), null);
});
