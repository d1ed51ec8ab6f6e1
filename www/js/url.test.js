import { test } from 'node:test';
import assert from 'node:assert/strict';
import { urlFor } from './url.js';

test('the URL keeps the path and the hash around the state string', () => {
  assert.equal(urlFor({ pathname: '/flexarm/', hash: '#explain' }, 'delta=0.01&pf=off'), '/flexarm/?delta=0.01&pf=off#explain');
  assert.equal(urlFor({ pathname: '/', hash: '' }, ''), '/');
});
