// Links out (issue 21): the main page's footer links to the help page (the paper's reference, the
// source and README, the licence), and those links resolve; the help page's table of the settings
// a link can hold matches the schema the page builds its controls from, key by key, with the same
// values and defaults; the help page reads on a phone, a laptop and a large screen, light and dark,
// with no console errors and nothing axe objects to; and on a phone the footer's links are not
// hidden under the controls' sheet. Screenshots go to screenshots/.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { shared, openPage, shots, AXE, SIZES } from './harness.mjs';

const env = shared();

/** help.html (or `file`) in a context of its own, with its console errors and failed requests collected. */
async function openHelp(context = SIZES.laptop, file = 'help.html') {
  const ctx = await env.browser.newContext(context);
  const page = await ctx.newPage();
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('requestfailed', (r) => problems.push(`request failed: ${r.url()}`));
  page.on('response', (r) => { if (r.status() >= 400) problems.push(`HTTP ${r.status()}: ${r.url()}`); });
  const response = await page.goto(`${env.server.base}/${file}`);
  assert.equal(response?.status(), 200, `${file} loads`);
  return { page, problems, close: () => ctx.close() };
}

/** axe-core's WCAG 2.1 A/AA violations on the page as it is (as screens.test.mjs runs it). */
async function axe(page) {
  await page.addScriptTag({ path: AXE });
  const result = await page.evaluate(() => window.axe.run(document, { runOnly: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa'] }));
  return result.violations.map((v) => `${v.id} (${v.impact}): ${v.nodes.slice(0, 3).map((n) => n.target.join(' ')).join(' | ')}`);
}

test('the footer links to the help page, and every link resolves to a page and an anchor there', { timeout: 60000 }, async () => {
  const { page, close } = await openPage(env.browser, env.server.base, '');
  const links = await page.$$eval('footer .page-links a', (as) => as.map((a) => ({ text: a.textContent.trim(), href: a.getAttribute('href'), title: a.title })));
  assert.deepEqual(links.map((l) => l.text), ['Help', 'The paper', 'Source and README', 'Licence']);
  assert.deepEqual(links.map((l) => l.href), ['help.html', 'help.html#paper', 'help.html#source', 'help.html#licence']);
  // Following one lands on its section, in sight.
  await Promise.all([page.waitForURL(/\/help\.html#licence$/), page.click('footer .page-links a[href="help.html#licence"]')]);
  const landed = await page.evaluate(() => {
    const r = document.getElementById('licence').getBoundingClientRect();
    return { top: r.top, bottom: r.bottom, height: innerHeight };
  });
  assert.ok(landed.top >= 0 && landed.bottom <= landed.height, `#licence in sight: ${JSON.stringify(landed)}`);
  await close();

  const help = await openHelp();
  const ids = await help.page.evaluate(() => [...document.querySelectorAll('[id]')].map((e) => e.id));
  for (const { href } of links) {
    const id = href.split('#')[1];
    if (id) assert.ok(ids.includes(id), `help.html#${id} exists`);
  }
  // The paper's tooltip in the footer names the reference the help page gives.
  const cite = await help.page.textContent('#paper cite');
  assert.ok(cite && links[1].title.includes(cite.trim().replace(/\s+/g, ' ')), `'${links[1].title}' quotes '${cite}'`);
  assert.match(await help.page.textContent('#paper'), /von Wissel.*Nikoukhah.*Campbell/s);
  // Every in-page link has its target; ids are unique.
  const local = await help.page.$$eval('a[href^="#"]', (as) => as.map((a) => a.getAttribute('href').slice(1)));
  for (const id of local) assert.ok(ids.includes(id), `#${id} exists`);
  assert.equal(new Set(ids).size, ids.length, 'ids are unique');
  // The repository's address is kept in one place, a link that is a placeholder until it is given one.
  const source = await help.page.$$eval('#source-link', (as) => as.map((a) => a.getAttribute('href')));
  assert.equal(source.length, 1);
  if (source[0] !== null) assert.match(source[0], /^https:\/\//, 'the source link, once set, is a web address');
  // The other links of the help page resolve: pages and files beside it load, and each link to the
  // simulation holds settings the page takes without a notice.
  const hrefs = await help.page.$$eval('a[href]', (as) => [...new Set(as.map((a) => a.getAttribute('href')))]);
  for (const href of hrefs.filter((h) => !h.startsWith('#') && !/^https?:/.test(h))) {
    const file = href.split(/[?#]/)[0];
    const status = await help.page.evaluate(async (f) => (await fetch(f)).status, file);
    assert.equal(status, 200, `${href}: ${file} loads`);
  }
  await help.close();
});

test('every key of the help page\'s settings table is a setting, with its values and default; every setting is there', { timeout: 60000 }, async () => {
  const { page, close } = await openPage(env.browser, env.server.base, '');
  const wasm = await page.evaluate(() => {
    const w = window.flexarm.wasm;
    const viewsError = (() => {
      const s = new w.Session('views=nothing');
      const n = s.notices();
      s.free();
      return n.map((x) => x.text).join(' ');
    })();
    return {
      schema: w.schema().map((p) => ({ key: p.key, scope: p.scope, allowed: p.allowed, default: p.default })),
      presets: w.presets().map((p) => p.id),
      arms: w.arms().map((a) => a.id),
      viewsError,
    };
  });
  const help = await openHelp();
  const rows = await help.page.$$eval('#settings-table tbody tr:not(.group)', (trs) => trs.map((tr) => ({
    key: tr.dataset.key ?? null,
    special: tr.dataset.special ?? null,
    relative: tr.dataset.default === 'relative',
    cells: [...tr.cells].map((c) => c.textContent.trim().replace(/\s+/g, ' ')),
  })));
  const links = await help.page.$$eval('a[href^="index.html?"]', (as) => as.map((a) => a.getAttribute('href').slice('index.html?'.length)));
  await help.close();

  // The key written in the row is its key.
  for (const r of rows) assert.equal(r.cells[0], r.key ?? r.special, 'the first cell names the key');
  // Every schema key a link can hold (not the command line's own: duration, output_interval, q2)
  // is in the table, once, with the schema's values and default (run B's defaults follow run A).
  const byKey = new Map(wasm.schema.map((p) => [p.key, p]));
  const linkKeys = wasm.schema.filter((p) => p.scope !== 'cli').map((p) => p.key);
  const tableKeys = rows.filter((r) => r.key).map((r) => r.key);
  assert.deepEqual([...tableKeys].sort(), [...linkKeys].sort(), 'the table lists exactly the settings a link can hold');
  for (const r of rows.filter((x) => x.key)) {
    const p = byKey.get(r.key);
    assert.ok(p, `${r.key} is a setting`);
    assert.notEqual(p.scope, 'cli', `${r.key} can be in a link`);
    assert.equal(r.cells[2], p.allowed, `${r.key}: values`);
    if (r.relative) assert.equal(p.scope, 'compare', `${r.key}: only run B's defaults follow run A's`);
    else assert.equal(r.cells[3], p.default, `${r.key}: default`);
  }
  // The keys that are not settings of the schema: those the session reads itself.
  const special = Object.fromEntries(rows.filter((r) => r.special).map((r) => [r.special, r.cells]));
  assert.deepEqual(Object.keys(special).sort(), ['arm', 'lesson', 'lesson_src', 'preset', 'strip', 'views']);
  assert.equal(special.preset[2], wasm.presets.join(' | '), 'the presets');
  assert.equal(special.arm[2], wasm.arms.join(' | '), 'the arms');
  assert.ok(wasm.viewsError.includes(`a list of ${special.views[2]}`), `views: ${wasm.viewsError}`);

  // Each of them is known to the page (a notice, if any, is about the lesson's file, never an
  // unknown key), and every link of the help page to the simulation is taken without a notice.
  const notices = await page.evaluate(({ queries }) => queries.map((q) => {
    const s = new window.flexarm.wasm.Session(q);
    const n = s.notices();
    s.free();
    return { q, notices: n.map((x) => `${x.key}: ${x.text}`) };
  }), { queries: ['preset=fig5.3', 'arm=damped', 'views=arm,traces,zplane', 'lesson=2', 'lesson_src=lessons/windows.md', ...links] });
  for (const { q, notices: n } of notices) {
    assert.ok(!n.some((t) => /known setting/.test(t)), `${q}: ${n.join('; ')}`);
    if (!/lesson/.test(q)) assert.deepEqual(n, [], `${q} is taken as it is`);
  }
  assert.ok(links.length >= 3, `${links.length} links to the simulation`);
  await close();
});

for (const [name, context] of Object.entries(SIZES)) {
  test(`${name}: the help page has no console errors, no sideways scroll, nothing axe objects to (light and dark)`, { timeout: 60000 }, async () => {
    for (const colorScheme of ['light', 'dark']) {
      const { page, problems, close } = await openHelp({ ...context, colorScheme });
      const m = await page.evaluate(() => ({
        scroll: document.documentElement.scrollWidth, width: innerWidth,
        headings: [...document.querySelectorAll('h1, h2, h3')].map((h) => Number(h.tagName[1])),
        main: document.querySelectorAll('main').length,
      }));
      assert.ok(m.scroll <= m.width, `${name} ${colorScheme}: page ${m.scroll} px wide in a ${m.width}-px window`);
      assert.equal(m.main, 1);
      assert.equal(m.headings[0], 1, 'one h1 first');
      for (let i = 1; i < m.headings.length; i++) assert.ok(m.headings[i] <= m.headings[i - 1] + 1, `heading levels in order: ${m.headings.join(' ')}`);
      if (colorScheme === 'light' || name === 'phone') await page.screenshot({ path: path.join(shots, `help-${name}-${colorScheme}.png`), fullPage: true });
      assert.deepEqual(await axe(page), [], `${name} ${colorScheme}: accessibility violations`);
      assert.deepEqual(problems, []);
      await close();
    }
  });
}

for (const [name, context] of Object.entries(SIZES)) {
  test(`${name}: the footer's links can be reached, below the figure and clear of the controls' sheet`, { timeout: 60000 }, async () => {
    const { page, close } = await openPage(env.browser, env.server.base, '', context);
    await page.evaluate(() => window.scrollTo(0, document.documentElement.scrollHeight));
    await page.waitForTimeout(300);
    const m = await page.evaluate(() => {
      const canvas = document.querySelector('#canvas-wrap').getBoundingClientRect();
      const nav = document.querySelector('footer .page-links').getBoundingClientRect();
      const links = [...document.querySelectorAll('footer .page-links a')].map((a) => {
        const r = a.getBoundingClientRect();
        const hit = document.elementFromPoint(r.left + r.width / 2, r.top + r.height / 2);
        return { text: a.textContent, top: r.top, bottom: r.bottom, reachable: hit === a || a.contains(hit) };
      });
      return { canvasBottom: canvas.bottom, navTop: nav.top, height: innerHeight, links };
    });
    assert.ok(m.navTop >= m.canvasBottom, `${name}: the links (from ${m.navTop} px) below the figure (to ${m.canvasBottom} px)`);
    for (const l of m.links) {
      assert.ok(l.top >= 0 && l.bottom <= m.height, `${name}: '${l.text}' in the window at the end of the page (${l.top}–${l.bottom} of ${m.height})`);
      assert.ok(l.reachable, `${name}: '${l.text}' is not covered (by the controls' sheet on a phone)`);
    }
    await page.screenshot({ path: path.join(shots, `footer-${name}.png`) });
    await close();
  });
}
