import { test } from 'node:test';
import assert from 'node:assert/strict';
import { growthDue, GROWTH_REFRESH_MS, playAction } from './run.js';

test('the observation is rewritten on a new verdict, its first measurement, a new analysis, or once a second', () => {
  const shown = { verdict: 'unstable', measured: true, rho: 'ρ = 1.0239', shownAt: 1000 };
  const same = { verdict: 'unstable', measured: true, rho: 'ρ = 1.0239' };
  assert.equal(growthDue(shown, same, 1500), false, 'not yet');
  assert.equal(growthDue(shown, same, 1000 + GROWTH_REFRESH_MS), true);
  assert.equal(growthDue(shown, { ...same, verdict: 'diverged' }, 1100), true);
  assert.equal(growthDue({ ...shown, measured: false }, same, 1100), true, 'the first measurement shows at once');
  assert.equal(growthDue(shown, { ...same, rho: 'ρ = 1.0240' }, 1100), true, 'the analysis moved: its rates with it');
});

test('the Play button says what it will do: Restart once the runs have diverged', () => {
  assert.equal(playAction(true, false).text, '❚❚ Pause');
  assert.equal(playAction(false, false).text, '▶ Play');
  assert.equal(playAction(true, true).action, 'restart');
  assert.equal(playAction(false, true).text, '↺ Restart');
});
