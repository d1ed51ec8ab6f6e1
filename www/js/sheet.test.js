import { test } from 'node:test';
import assert from 'node:assert/strict';
import { sheetLabel } from './sheet.js';

test('the sheet button says what a press does: close it, or open what it holds', () => {
  assert.equal(sheetLabel(true, false), 'Close ▾');
  assert.equal(sheetLabel(true, true), 'Close ▾');
  assert.equal(sheetLabel(false, false), 'Controls, verdict and lesson ▴');
  assert.equal(sheetLabel(false, true), 'The lesson, controls and verdict ▴', 'in a lesson, the lesson first');
});
