import { test } from 'node:test';
import assert from 'node:assert/strict';
import { blobType } from './outputs.js';

test('text and SVG are offered as UTF-8, other data as it is', () => {
  assert.equal(blobType('text/csv'), 'text/csv;charset=utf-8');
  assert.equal(blobType('text/x-python'), 'text/x-python;charset=utf-8');
  assert.equal(blobType('image/svg+xml'), 'image/svg+xml;charset=utf-8');
  assert.equal(blobType('image/png'), 'image/png');
  assert.equal(blobType('application/json'), 'application/json');
});
