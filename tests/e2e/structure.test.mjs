// Issue 37: the paper's Section 3 made visible, and sentences true on the arm shown. The
// explanation's section "The structure behind it" fills in the arm's V*, zero dynamics, quotient
// A4, index and the horizon probes (never "—"); its Try buttons set k below the index with its m
// in one go, and the run then fails as the section says; on the heavier motor In short says the
// paper's gains leave the pair unstable. Screenshots at the three sizes go to
// screenshots/structure-*.png.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { shared, openPage, SIZES, shots } from './harness.mjs';

const env = shared();

/** The live texts of the explanation, once the analysis has filled them. */
async function live(page) {
  await page.waitForFunction(() => document.querySelector('[data-live="structure_quotient"]')?.textContent.includes('A4 ='), null, { timeout: 30000 });
  return page.evaluate(() => Object.fromEntries([...document.querySelectorAll('[data-live]')].map((n) => [n.dataset.live, n.textContent])));
}

test('Section 3 on the heavier motor: the structure for the arm shown, and k below the index tried', { timeout: 180000 }, async () => {
  const { page, problems, close } = await openPage(env.browser, env.server.base, '?arm=heavier&pf=paper&mode=full');
  await page.evaluate(() => { document.getElementById('explain').open = true; });
  const s = await live(page);
  assert.match(s.structure_v_star, /is 6-dimensional/);
  assert.match(s.structure_zero_dynamics, /at −2 1\/s \(×6\).*no finite zeros of its own/);
  // The heavier motor's A4 (I_r1 × 4): 2.91 ± 20.76j, and the paper's gains leave it unstable.
  assert.match(s.structure_quotient, /A4 = 2\.91 ± 20\.76j 1\/s, unstable.*with paper K_?pr it moves to 1\.08 ± 20\.94j 1\/s, unstable/);
  assert.match(s.kpr_cure, /small δ still fail/);
  assert.doesNotMatch(s.kpr_cure, /then every small δ works/);
  assert.match(s.structure_index, /^Index 5 .*, 3 with the stabilized/);
  for (const [name, size] of Object.entries(SIZES)) {
    const shot = await openPage(env.browser, env.server.base, '?arm=heavier&pf=paper&mode=full', size);
    if (name === 'phone') await shot.page.getByText('Controls, verdict and lesson').first().click();
    await shot.page.evaluate(() => { document.getElementById('explain').open = true; });
    await live(shot.page);
    await shot.page.evaluate(() => document.querySelector('section[aria-labelledby="ex-structure"]').scrollIntoView({ block: 'start' }));
    await shot.page.waitForTimeout(400);
    await shot.page.screenshot({ path: path.join(shots, `structure-${name}.png`) });
    assert.deepEqual(shot.problems, [], name);
    await shot.close();
  }
  // Try k = 2 (m = 1.33): both at once; the run is thrown off course, ρ ≈ 2.
  await page.locator('button.try', { hasText: 'Try: k = 2 (m = 1.33)' }).click();
  await page.waitForFunction(() => new URL(location.href).searchParams.get('k') === '2', null, { timeout: 10000 });
  await page.waitForFunction(() => /Diverged|UNSTABLE|Unstable/i.test(document.getElementById('strip-word')?.textContent ?? ''), null, { timeout: 30000 });
  const after = await live(page);
  assert.match(after.rho, /^2\.1/, `ρ at k = 2: ${after.rho}`);
  // k = 3, the index: as the paper's k = 12 (the heavier motor stays unstable with the paper's gains, ρ 1.0095).
  await page.locator('button.try', { hasText: 'k = 3 (m = 2)' }).click();
  await page.waitForFunction(() => new URL(location.href).searchParams.get('k') === '3', null, { timeout: 10000 });
  await page.waitForFunction(() => document.querySelector('[data-live="rho"]')?.textContent.startsWith('1.009'), null, { timeout: 30000 });
  assert.deepEqual(problems, []);
  await close();
});
