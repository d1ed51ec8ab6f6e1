import { test } from 'node:test';
import assert from 'node:assert/strict';
import { symbolParts } from './dom.js';

test('the paper\'s subscripts are found after a symbol, not in words or keys', () => {
  assert.deepEqual(symbolParts('B_v1 > 3α I_r1 = 11.6'), [['B', false], ['v1', true], [' > 3α I', false], ['r1', true], [' = 11.6', false]]);
  assert.deepEqual(symbolParts('K_pr'), [['K', false], ['pr', true]]);
  assert.deepEqual(symbolParts('no symbols here'), [['no symbols here', false]]);
  assert.deepEqual(symbolParts('eps_ratio=8'), [['eps', false], ['ratio', true], ['=8', false]], 'a key would be read as a symbol: keep keys out of such texts');
});
