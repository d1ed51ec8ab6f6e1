import { test } from 'node:test';
import assert from 'node:assert/strict';
import { choicesQuery } from './embed.js';

test('the builder sends its form as it stands: what is left empty is left out', () => {
  const q = new URLSearchParams(choicesQuery({ views: ['zplane', 'rho'], width: ' 760', height: '480', paused: true, t: '3', strip: ['reset', 'delta'], lesson: null }));
  assert.deepEqual([...q.keys()], ['views', 'width', 'height', 'paused', 't', 'strip']);
  assert.equal(q.get('views'), 'zplane,rho');
  assert.equal(q.get('width'), '760');
  assert.equal(q.get('strip'), 'reset,delta');
  const lesson = new URLSearchParams(choicesQuery({ views: [], width: '', height: '', paused: false, t: ' ', strip: [], lesson: '4' }));
  assert.equal(lesson.get('views'), '', 'no panel: the session says why that cannot be');
  assert.equal(lesson.has('paused') || lesson.has('t'), false);
  assert.equal(lesson.get('lesson'), '4');
});
