import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createStore, initialState, reduce } from './store.js';

test('play, pause and toggle', () => {
  let s = reduce(initialState, { type: 'pause' });
  assert.equal(s.playing, false);
  s = reduce(s, { type: 'toggle-play' });
  assert.equal(s.playing, true);
  assert.equal(reduce(s, { type: 'play' }), s, 'no change, same object');
});

test('a crash stops everything for good', () => {
  const s = reduce(initialState, { type: 'crash' });
  assert.deepEqual([s.dead, s.playing], [true, false]);
  assert.equal(reduce(s, { type: 'play' }).playing, false);
  assert.equal(reduce(s, { type: 'toggle-play' }).playing, false);
});

test('α linking and unknown actions', () => {
  assert.equal(reduce(initialState, { type: 'link-alpha', value: false }).linkAlpha, false);
  assert.throws(() => reduce(initialState, { type: 'view', name: 'showTorque', value: true }), /unknown action/, 'views are the session\'s');
  assert.throws(() => reduce(initialState, { type: 'frobnicate' }), /unknown action/);
});

test('the store tells its subscribers about changes only', () => {
  const store = createStore();
  const seen = [];
  const off = store.subscribe((next, prev) => seen.push([prev.playing, next.playing]));
  store.dispatch({ type: 'pause' });
  store.dispatch({ type: 'pause' });
  off();
  store.dispatch({ type: 'play' });
  assert.deepEqual(seen, [[true, false]]);
  assert.equal(store.get().playing, true);
  assert.ok(Object.isFrozen(initialState));
});

test('render failures are counted and cleared', () => {
  let s = reduce(initialState, { type: 'render-failed' });
  s = reduce(s, { type: 'render-failed' });
  assert.equal(s.renderFailures, 2);
  assert.equal(reduce(s, { type: 'render-ok' }).renderFailures, 0);
  assert.equal(reduce(s, { type: 'renderer', backend: 'WebGL2' }).backend, 'WebGL2');
});
