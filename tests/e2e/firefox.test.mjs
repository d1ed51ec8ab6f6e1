// The offline file in Firefox (issue 33): the file the test command built opens from disk in
// Debian's headless firefox-esr (driven over Marionette, firefox.mjs) with no server and nothing
// leaving the machine: Fig. 5.3 unstable, K_pr on is stable, a teacher's lesson travels.
// Headless Firefox on this machine offers no WebGL at all (not even to a bare test page), so
// the page says it cannot draw — its only complaint allowed here; the drawing itself is checked
// in Chromium (offline.test.mjs) through both WebGL2 and WebGPU.

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { FIREFOX, launchFirefox } from './firefox.mjs';
import { root, shots, www } from './harness.mjs';

const ARTEFACT = path.join(root, 'target', 'offline', 'flexarm-offline.html');
const FLEXARM = path.join(root, 'target', 'debug', 'flexarm');
const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'flexarm-firefox-file-'));

before(() => {
  assert.ok(fs.existsSync(FIREFOX), `${FIREFOX} is missing: the test command installs Debian's firefox-esr`);
  assert.ok(fs.existsSync(ARTEFACT), `${ARTEFACT} is missing: the test command builds it (flexarm bundle)`);
});
after(() => fs.rmSync(dir, { recursive: true, force: true }));

/** Polls `script` in the page until it returns something truthy. */
async function until(/** @type {any} */ ff, /** @type {string} */ script, ms = 30000) {
  const end = Date.now() + ms;
  for (;;) {
    const value = await ff.evaluate(script);
    if (value) return value;
    if (Date.now() > end) throw new Error(`timed out waiting for: ${script}`);
    await new Promise((r) => setTimeout(r, 250));
  }
}

/** What went wrong, as the page lists it, but the renderer's "cannot draw" (no WebGL here). */
const complaints = (/** @type {any} */ ff) => ff.evaluate(
  'return [...document.querySelectorAll("#error-list li")].map((li) => li.textContent).filter((t) => !/^Renderer: flexarm cannot draw/.test(t))');

test('Firefox opens the offline file from disk: Fig. 5.3 unstable, then Fig. 5.2 stable with K_pr on', { timeout: 120000 }, async () => {
  const copy = path.join(dir, 'flexarm-offline.html');
  fs.copyFileSync(ARTEFACT, copy);
  for (const [name, size] of [['laptop', { width: 1280, height: 800 }], ['narrow', { width: 390, height: 844 }]]) {
    const ff = await launchFirefox(size);
    try {
      await ff.navigate(pathToFileURL(copy).href);
      assert.equal(await until(ff, 'return document.querySelector("#verdict")?.dataset.verdict'), 'unstable', name);
      assert.match(await ff.evaluate('return document.querySelector("#offline-start").textContent'), /Fig\. 5\.3/);
      await ff.evaluate('document.querySelector("#pf-toggle").click()');
      await until(ff, 'return document.querySelector("#verdict")?.dataset.verdict === "stable"');
      // Nothing was fetched but the file itself.
      assert.deepEqual(await ff.evaluate('return performance.getEntriesByType("resource").map((e) => e.name).filter((n) => /^https?:/.test(n))'), []);
      fs.writeFileSync(path.join(shots, `offline-firefox-${name}.png`), await ff.screenshot());
      assert.deepEqual(await complaints(ff), [], name);
    } finally {
      await ff.close();
    }
  }
});

test('Firefox: a teacher\'s file opens their lesson in student mode', { timeout: 120000 }, async () => {
  const file = path.join(dir, 'homework.html');
  execFileSync(FLEXARM, ['bundle', '--out', file, '--lesson', path.join(www, 'lessons', 'windows.md'), '--state', 'answers=hidden'], { stdio: 'pipe' });
  const ff = await launchFirefox({ width: 1280, height: 800 });
  try {
    await ff.navigate(pathToFileURL(file).href);
    await until(ff, 'return !document.querySelector("#lesson")?.hidden');
    assert.equal(await ff.evaluate('return document.querySelector("#lesson-title").textContent'), 'Where does the controller alone work?');
    assert.equal(await until(ff, 'return document.querySelector("#verdict")?.dataset.verdict'), 'hidden');
    assert.deepEqual(await complaints(ff), []);
  } finally {
    await ff.close();
  }
});
