import { test } from 'node:test';
import assert from 'node:assert/strict';
import { parseTry } from './explain.js';

test('every kind of Try button', () => {
  assert.deepEqual(parseTry('preset:fig5.3'), { kind: 'preset', id: 'fig5.3' });
  assert.deepEqual(parseTry('pf:paper'), { kind: 'set', key: 'pf', value: 'paper' });
  assert.deepEqual(parseTry('alpha:0.5'), { kind: 'set', key: 'alpha', value: '0.5' });
  assert.deepEqual(parseTry('compare:on'), { kind: 'set', key: 'compare', value: '1' });
  assert.deepEqual(parseTry('map:off:0.05:2'), { kind: 'map', side: 'off', delta: 0.05, alpha: 2 });
  assert.deepEqual(parseTry('state:k=2&eps_ratio=1.33'), { kind: 'state', query: 'k=2&eps_ratio=1.33' });
});

test('malformed specs do nothing', () => {
  for (const bad of ['', 'preset', 'map:left:1:2', 'map:off:x:2', 'frobnicate:1']) assert.equal(parseTry(bad), null, bad);
});

test('set: names any settings, in pairs', () => {
  assert.deepEqual(parseTry('set:alpha1:0.5:alpha2:2'), { kind: 'sets', pairs: [['alpha1', '0.5'], ['alpha2', '2']] });
  assert.deepEqual(parseTry('set:inner:sampled'), { kind: 'sets', pairs: [['inner', 'sampled']] });
  assert.equal(parseTry('set:alpha1'), null);
  assert.equal(parseTry('set:'), null);
  assert.equal(parseTry('set::2'), null);
});
