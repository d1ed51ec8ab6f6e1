import { test } from 'node:test';
import assert from 'node:assert/strict';
import { growthDue, GROWTH_REFRESH_MS } from './run.js';

test('the growth line is rewritten on a new verdict, while observing, or once a second', () => {
  const shown = { verdict: 'unstable', growth: 'observed growth rate: 2.27 1/s', shownAt: 1000 };
  const same = { verdict: 'unstable', growth: 'observed growth rate: 2.28 1/s' };
  assert.equal(growthDue(shown, same, 1500), false, 'not yet');
  assert.equal(growthDue(shown, same, 1000 + GROWTH_REFRESH_MS), true);
  assert.equal(growthDue(shown, { ...same, verdict: 'diverged' }, 1100), true);
  assert.equal(growthDue(shown, { ...same, growth: 'observed growth rate: observing…' }, 1100), true);
});
