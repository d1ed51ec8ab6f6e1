import { test } from 'node:test';
import assert from 'node:assert/strict';
import { PAUSED_NOTE, START_NOTE, pauseNote } from './transport.js';

test('Play takes away only the notes a pause put there', () => {
  assert.ok(pauseNote(PAUSED_NOTE));
  assert.ok(pauseNote(START_NOTE));
  assert.ok(!pauseNote(''));
  assert.ok(!pauseNote('Paused because your system asks for reduced motion: press Play to run.'));
});
