// Page-load benchmark: how long the page takes to its first frame in headless Chromium here, for
// one build of www/ or two side by side (A against B, loaded alternately so that the machine's
// noise falls on both alike). Prints the medians of the page's own performance marks.
//
//   node bench/page_load.mjs [--loads N] [--fresh] [WWW_A [WWW_B]]
//
// WWW_A defaults to www/ (it must hold pkg/, e.g. after `bash scripts/serve.sh`); a second
// directory is another copy of www/ with another pkg/ (e.g. the build before a change).
// --fresh starts a new browser for every load, so each pays for Chromium's GPU process starting
// (≈ 0.3–0.4 s here); by default the browser stays up and every load gets a new context, as a
// reader's browser would. Uses the end-to-end tests' Playwright and Chromium (tests/e2e).

import { launch, serve, www } from '../tests/e2e/harness.mjs';

const args = process.argv.slice(2);
const flag = (name) => {
  const i = args.indexOf(name);
  if (i < 0) return null;
  args.splice(i, 1);
  return true;
};
const option = (name, fallback) => {
  const i = args.indexOf(name);
  if (i < 0) return fallback;
  const [, value] = args.splice(i, 2);
  return value;
};
const loads = Number(option('--loads', '11'));
const fresh = flag('--fresh') ?? false;
const dirs = args.length ? args : [www];
if (!Number.isInteger(loads) || loads < 1 || dirs.length > 2) {
  console.error('usage: node bench/page_load.mjs [--loads N] [--fresh] [WWW_A [WWW_B]]');
  process.exit(2);
}

const MARKS = ['flexarm:main-start', 'flexarm:wasm-ready', 'flexarm:session-ready', 'flexarm:renderer-ready', 'flexarm:first-frame'];

const servers = await Promise.all(dirs.map((d) => serve(d)));
let browser = fresh ? null : await launch();
/** @type {Record<string, number>[][]} */
const samples = dirs.map(() => []);
try {
  for (let i = 0; i < loads; i++) {
    for (let k = 0; k < dirs.length; k++) {
      if (fresh) browser = await launch();
      const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
      const page = await context.newPage();
      await page.goto(`${servers[k].base}/`);
      await page.waitForFunction(() => performance.getEntriesByName('flexarm:first-frame').length > 0, null, { timeout: 30000 });
      samples[k].push(await page.evaluate((names) => {
        const at = (n) => performance.getEntriesByName(n)[0]?.startTime ?? NaN;
        const wasm = performance.getEntriesByType('resource').find((r) => r.name.endsWith('.wasm'));
        return { ...Object.fromEntries(names.map((n) => [n.replace('flexarm:', ''), at(n)])), 'wasm-fetched': wasm ? wasm.responseEnd : NaN };
      }, MARKS));
      await context.close();
      if (fresh) await browser.close();
    }
  }
} finally {
  if (!fresh) await browser.close();
  await Promise.all(servers.map((s) => s.close()));
}

const median = (xs) => {
  const s = xs.filter(Number.isFinite).sort((a, b) => a - b);
  return s.length ? s[(s.length - 1) >> 1] : NaN;
};
const keys = Object.keys(samples[0][0]);
console.log(`${loads} loads${dirs.length > 1 ? ' each, alternating' : ''}, ${fresh ? 'a fresh browser per load' : 'one browser, a new context per load'}; medians in ms after navigation`);
console.log(['', ...dirs.map((d, k) => `${'AB'[k]}: ${d}`)].join('\n  '));
for (const key of keys) {
  const m = samples.map((s) => median(s.map((x) => x[key])));
  const ratio = m.length > 1 ? `  B/A ${(m[1] / m[0]).toFixed(2)}` : '';
  console.log(`${key.padEnd(16)} ${m.map((v) => v.toFixed(0).padStart(6)).join(' ')}${ratio}`);
}
console.log(`first frames: ${samples.map((s, k) => `${'AB'[k]} ${s.map((x) => x['first-frame'].toFixed(0)).join(' ')}`).join(' | ')}`);
