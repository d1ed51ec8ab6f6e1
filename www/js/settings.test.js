import { test } from 'node:test';
import assert from 'node:assert/strict';
import { linkedKey, wholePageLink } from './settings.js';

test('with α linked, either α slider moves both', () => {
  assert.equal(linkedKey('alpha1', true), 'alpha');
  assert.equal(linkedKey('alpha2', true), 'alpha');
  assert.equal(linkedKey('alpha1', false), 'alpha1');
  assert.equal(linkedKey('alpha2', false), 'alpha2');
  assert.equal(linkedKey('delta', true), 'delta');
});

test('an embed links to the whole page with the same state, not embedded', () => {
  assert.equal(wholePageLink('/flexarm/', 'delta=0.02&embed=1&alpha=2'), '/flexarm/?delta=0.02&alpha=2');
  assert.equal(wholePageLink('/', 'delta=0.02'), '/?delta=0.02');
});
