// An embed you control (issue 23, item 7): the builder in "Share and export" writes snippets for
// three choices; each, loaded in an iframe of a 760-px-wide course page, shows exactly the panels
// asked for and exactly the strip's controls chosen; the preview announces a panel that does not
// fit; after divergence the embed's Play says Restart; lesson step 4 embeds with its text and
// buttons. Screenshots go to /tmp/shots23/ (embed-builder-*.png, embed-host-760.png).

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { serve, launch, AXE } from './harness.mjs';

// One server and one browser for the file (as harness.mjs's `shared`); E2E_WWW serves another
// copy of www/ (a build of one's own while others rebuild www/pkg).
const env = { server: /** @type {any} */ (null), browser: /** @type {any} */ (null) };
before(async () => {
  env.server = await serve(process.env.E2E_WWW || undefined);
  env.browser = await launch();
});
after(async () => {
  await env.browser?.close();
  await env.server?.close();
});
const SHOTS = process.env.SHOTS23 || '/tmp/shots23';
fs.mkdirSync(SHOTS, { recursive: true });

/** A page in a context of its own, its problems collected. */
async function open(query, context = { viewport: { width: 1280, height: 800 } }) {
  const ctx = await env.browser.newContext(context);
  const page = await ctx.newPage();
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  if (query !== null) {
    await page.goto(`${env.server.base}/${query}`);
    await page.waitForFunction(() => document.querySelector('#backend')?.textContent?.trim().length > 0, null, { timeout: 30000 });
  }
  return { page, problems, close: () => ctx.close() };
}

/** Sets the builder's form: checkboxes by value, the size, the start, the lesson. */
async function choose(page, { views, size, paused = false, t = '', strip, lesson = null }) {
  const before = await page.inputValue('#embed-code');
  await page.evaluate(({ views, size, paused, t, strip, lesson }) => {
    const set = (el, v) => { el.checked = v; };
    for (const b of document.querySelectorAll('input[name="embed-views"]')) set(b, views.includes(b.value));
    for (const b of document.querySelectorAll('input[name="embed-strip"]')) set(b, strip.includes(b.value));
    const [w, h] = size;
    document.querySelector('#embed-width').value = String(w);
    document.querySelector('#embed-height').value = String(h);
    set(document.querySelector('#embed-paused'), paused);
    document.querySelector('#embed-t').value = t;
    set(document.querySelector('#embed-lesson-on'), lesson != null);
    if (lesson != null) document.querySelector('#embed-lesson').value = String(lesson);
    document.querySelector('#embed-builder').dispatchEvent(new Event('change', { bubbles: true }));
  }, { views, size, paused, t, strip, lesson });
  // The snippet follows the form once it has settled, and the preview says whether the panels fit.
  await page.waitForFunction(([w, h, before]) => {
    const code = document.querySelector('#embed-code').value;
    return code !== before && code.includes(`width="${w}" height="${h}"`) && /^(fits|hidden)$/.test(document.querySelector('#embed-fit').dataset.state ?? '')
      && document.querySelector('#embed-fit').textContent.includes(`${w} × ${h}`);
  }, [...size, before], { timeout: 30000 });
  // The preview is the snippet's page.
  const [code, preview] = await page.evaluate(() => [document.querySelector('#embed-code').value, document.querySelector('#embed-preview').getAttribute('src')]);
  const src = await page.evaluate((html) => new DOMParser().parseFromString(html, 'text/html').querySelector('iframe').getAttribute('src'), code);
  assert.equal(preview, src, 'the preview shows the snippet');
  return code;
}

/** The snippet parsed: one iframe, its attributes. */
async function parse(page, code) {
  return page.evaluate((html) => {
    const doc = new DOMParser().parseFromString(html, 'text/html');
    const frames = doc.querySelectorAll('iframe');
    const f = frames[0];
    return { count: frames.length, src: f.getAttribute('src'), width: f.getAttribute('width'), height: f.getAttribute('height'), title: f.getAttribute('title'), rest: doc.body.children.length };
  }, code);
}

/** What an embedded page shows: the panels Rust laid out, the strip's visible controls, the lesson. */
async function shows(frame) {
  await frame.waitForFunction(() => window.flexarm?.lastLayout?.panels, null, { timeout: 30000 });
  return frame.evaluate(() => {
    const visible = (el) => el && getComputedStyle(el).display !== 'none' && el.getClientRects().length > 0;
    return {
      panels: window.flexarm.lastLayout.panels.map((p) => p.id),
      strip: [...document.querySelectorAll('#embed-strip [data-strip-item]')].filter(visible).map((e) => e.dataset.stripItem),
      lesson: visible(document.querySelector('#lesson')) ? document.querySelector('#lesson-title').textContent : null,
      time: window.flexarm.session.time(),
      play: document.querySelector('#embed-play').textContent,
      scroll: [document.documentElement.scrollWidth, document.documentElement.scrollHeight, innerWidth, innerHeight],
    };
  });
}

const CHOICES = [
  // The eigenvalues on the unit circle and ρ(δ) alone, paused at t = 3 s, with δ and Reset.
  { name: 'z-plane and ρ(δ)', form: { views: ['zplane', 'rho'], size: [760, 480], paused: true, t: '3', strip: ['reset', 'delta'] },
    panels: ['z-plane', 'rho-curve'], strip: ['reset', 'delta'] },
  // Fig. 5.3's arm and errors with Play, Reset and K_pr, from t = 5 s: it has diverged (at 4.1 s).
  // Reset was asked for, but once Play restarts it would be a second restart button: it hides.
  { name: 'Fig. 5.3 diverged', form: { views: ['arm', 'traces'], size: [760, 480], t: '5', strip: ['play', 'reset', 'pf'] },
    panels: ['arm', 'e1', 'e2'], strip: ['play', 'pf'] },
  // Lesson step 4, with its text and buttons beside the arm and errors.
  { name: 'lesson step 4', form: { views: ['arm', 'traces'], size: [760, 480], strip: ['play', 'reset'], lesson: 4 },
    panels: ['arm', 'e1', 'e2'], strip: ['play', 'reset'] },
];

test('the builder writes a snippet per choice; in a 760-px course page each embed shows exactly what was chosen', { timeout: 240000 }, async () => {
  const { page, problems, close } = await open('?preset=fig5.3&mode=full');
  await page.click('#embed-snippet');
  await page.waitForSelector('#embed-builder:not([hidden])');
  assert.equal(await page.getAttribute('#embed-snippet', 'aria-expanded'), 'true');
  // It opens with what is on screen: the full view's panels.
  const start = await page.$$eval('input[name="embed-views"]:checked', (bs) => bs.map((b) => b.value));
  assert.deepEqual(start, ['arm', 'traces', 'poles', 'rho', 'map']);

  // A panel that cannot fit is announced in the preview (every panel at 640 × 400) …
  await choose(page, { views: ['arm', 'traces', 'poles', 'rho', 'map'], size: [640, 400], strip: ['play', 'reset', 'pf'] });
  await page.waitForFunction(() => document.querySelector('#embed-fit').dataset.state === 'hidden', null, { timeout: 30000 });
  const note = await page.textContent('#embed-fit');
  assert.match(note, /At 640 × 400: The pole plot, ρ\(δ\) and the stability maps do not fit beside the rest at this size: see the tabs “Poles and ρ\(δ\)” and “Stability maps”/);
  // … and the embed itself offers those tabs.
  const previewFrame = page.frames().find((f) => f.parentFrame() === page.mainFrame());
  assert.ok(previewFrame, 'the preview is a frame of the page');
  await previewFrame.waitForFunction(() => [...document.querySelectorAll('#view-tabs [role="tab"]')].length === 3, null, { timeout: 30000 });
  assert.ok(await previewFrame.isVisible('#view-tabs'), 'the embed shows its tabs');
  // A choice the session refuses is said, not written.
  await page.evaluate(() => {
    for (const b of document.querySelectorAll('input[name="embed-views"]')) b.checked = false;
    document.querySelector('#embed-builder').dispatchEvent(new Event('change', { bubbles: true }));
  });
  await page.waitForFunction(() => document.querySelector('#embed-fit').dataset.state === 'error', null, { timeout: 10000 });
  assert.match(await page.textContent('#embed-fit'), /Cannot embed this: .*views.*at least one figure/);
  assert.equal(await page.inputValue('#embed-code'), '');

  const snippets = [];
  for (const c of CHOICES) {
    const code = await choose(page, c.form);
    const f = await parse(page, code);
    assert.equal(f.count, 1, `${c.name}: one iframe`);
    assert.equal(f.rest, 1, `${c.name}: nothing else`);
    assert.deepEqual([f.width, f.height], c.form.size.map(String));
    assert.match(f.src, /^http:\/\/127\.0\.0\.1:\d+\/(index\.html)?\?/, `${c.name}: ${f.src}`);
    assert.match(f.src, /[?&]embed=1(&|$)/);
    assert.ok(f.title.startsWith('flexarm: '), f.title);
    snippets.push(code);
    console.log(`# ${c.name}: ${f.src.replace(/^[^?]*/, '')}`);
  }
  await page.evaluate(() => document.querySelector('#embed-builder').scrollIntoView({ block: 'start' }));
  await page.waitForTimeout(300);
  await page.screenshot({ path: path.join(SHOTS, 'embed-builder-1280x800.png') });
  // The builder passes axe.
  await page.addScriptTag({ path: AXE });
  const violations = await page.evaluate(() => window.axe.run(document.querySelector('#embed-builder'), { runOnly: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa'] }))
    .then((r) => r.violations.map((v) => `${v.id}: ${v.nodes.slice(0, 3).map((n) => n.target.join(' ')).join(' | ')}`));
  assert.deepEqual(violations, []);
  assert.deepEqual(problems, []);
  await close();

  // The course page: 760 px wide, the three snippets as pasted.
  const host = await open(null, { viewport: { width: 800, height: 1700 } });
  await host.page.setContent(`<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Course page</title>
    <style>body { font: 15px/1.4 system-ui, sans-serif; margin: 0; background: #eee; } main { width: 760px; margin: 0 auto; background: #fff; padding: 0 0 1rem; }
    h2 { font-size: 1rem; margin: 0.6rem 0.5rem; } iframe { display: block; }</style></head>
    <body><main>${snippets.map((s, i) => `<h2>${i + 1}. ${CHOICES[i].name}</h2>${s.replace(' loading="lazy"', '')}`).join('\n')}</main></body></html>`);
  await host.page.waitForFunction(() => document.querySelectorAll('iframe').length === 3);
  const frames = await Promise.all((await host.page.$$('iframe')).map((h) => h.contentFrame()));
  for (const [i, c] of CHOICES.entries()) {
    const s = await shows(frames[i]);
    console.log(`# ${c.name}: ${JSON.stringify(s)}`);
    assert.deepEqual(s.panels, c.panels, `${c.name}: exactly the panels asked for`);
    assert.deepEqual(s.strip, c.strip, `${c.name}: exactly the controls chosen`);
    const [sw, sh, iw, ih] = s.scroll;
    assert.ok(sw <= iw && sh <= ih, `${c.name}: fits its frame without scrolling (${sw}×${sh} in ${iw}×${ih})`);
    // The verdict in the strip, in its short form, whole: not cut by "…" (issue 35).
    const verdict = await frames[i].evaluate(() => {
      const v = document.querySelector('#embed-verdict');
      return v && v.getClientRects().length ? { text: v.textContent, fits: v.scrollWidth <= v.clientWidth + 1 } : null;
    });
    if (verdict) assert.ok(verdict.fits && /^[A-Z][a-z ]+: /.test(verdict.text ?? ''), `${c.name}: the verdict fits: ${JSON.stringify(verdict)}`);
  }
  // 1: paused at t = 3 s, and held; its δ slider sets δ.
  const a = frames[0];
  const t0 = await a.evaluate(() => window.flexarm.session.time());
  assert.ok(Math.abs(t0 - 3) < 0.01, `t = ${t0}`);
  await host.page.waitForTimeout(800);
  assert.equal(await a.evaluate(() => window.flexarm.session.time()), t0, 'held at t = 3 s');
  await a.focus('#embed-delta');
  await a.press('#embed-delta', 'ArrowRight');
  await a.waitForFunction(() => window.flexarm.session.controls().find((v) => v.key === 'delta').value === '0.012', null, { timeout: 5000 });
  // 2: diverged, so Play says Restart, and restarts the run.
  const b = frames[1];
  await b.waitForFunction(() => document.querySelector('#embed-play').textContent === '↺ Restart', null, { timeout: 20000 });
  assert.equal(await b.isVisible('#embed-reset'), false, 'one restart control after divergence, not Restart and Reset');
  await b.click('#embed-play');
  await b.waitForFunction(() => document.querySelector('#embed-play').textContent === '❚❚ Pause', null, { timeout: 5000 });
  assert.ok(await b.evaluate(() => window.flexarm.session.time()) < 2, 'restarted from rest');
  // 3: the lesson's step 4, its question or task and its buttons, beside the figure.
  const c3 = await shows(frames[2]);
  assert.match(c3.lesson ?? '', /Inside one period/);
  assert.ok(await frames[2].isVisible('#lesson-next') && await frames[2].isVisible('#lesson-back'), 'the step\'s buttons');
  assert.ok(!(await frames[2].isVisible('#lesson-record')), 'no answers record in an embed');
  const [canvasBox, lessonBox] = await frames[2].evaluate(() => ['#canvas-wrap', '#lesson'].map((s) => {
    const r = document.querySelector(s).getBoundingClientRect();
    return { x: r.x, right: r.right, width: r.width };
  }));
  assert.ok(lessonBox.x >= canvasBox.right - 1 && canvasBox.width > 380, `the step beside the figure: ${JSON.stringify([canvasBox, lessonBox])}`);
  // The embeds with sliders and with the lesson pass axe too.
  for (const f of [frames[0], frames[2]]) {
    await f.addScriptTag({ path: AXE });
    const v = await f.evaluate(() => window.axe.run(document, { runOnly: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa'] }))
      .then((r) => r.violations.map((x) => `${x.id}: ${x.nodes.slice(0, 3).map((n) => n.target.join(' ')).join(' | ')}`));
    assert.deepEqual(v, [], 'axe in the embed');
  }
  await host.page.waitForTimeout(500);
  await host.page.screenshot({ path: path.join(SHOTS, 'embed-host-760.png'), fullPage: true });
  assert.deepEqual(host.problems, []);
  await host.close();
});

test('the builder on a phone: its form and preview fit the screen', { timeout: 120000 }, async () => {
  const { page, problems, close } = await open('?preset=fig5.3&mode=full', { viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true, deviceScaleFactor: 2 });
  await page.click('#sheet-toggle');
  await page.click('#embed-snippet');
  await page.waitForSelector('#embed-builder:not([hidden])');
  await choose(page, CHOICES[0].form);
  const widths = await page.evaluate(() => {
    const panel = document.querySelector('#panel').getBoundingClientRect();
    const box = document.querySelector('#embed-preview-box').getBoundingClientRect();
    return { panel: panel.width, box: box.width, page: document.documentElement.scrollWidth, screen: innerWidth };
  });
  assert.ok(widths.box <= widths.panel && widths.page <= widths.screen, JSON.stringify(widths));
  await page.evaluate(() => document.querySelector('#embed-fit').scrollIntoView({ block: 'center' }));
  await page.waitForTimeout(300);
  await page.screenshot({ path: path.join(SHOTS, 'embed-builder-390x844.png') });
  assert.deepEqual(problems, []);
  await close();
});

test('a step of a homework link\'s lesson embeds, the link carried on in the embed\'s address', { timeout: 120000 }, async () => {
  // The teacher makes the link, then opens it as a student would and builds an embed of step 2.
  const teacher = await open('?lesson_src=lessons/windows.md&mode=full');
  await teacher.page.waitForSelector('#lesson-link-row:not([hidden])', { timeout: 20000 });
  await teacher.page.click('#lesson-link-make');
  await teacher.page.waitForSelector('#lesson-link-out:not([hidden])');
  const link = new URL(await teacher.page.inputValue('#lesson-link'));
  await teacher.close();
  const { page, problems, close } = await open(`${link.search}${link.hash}`);
  await page.waitForFunction(() => !document.querySelector('#lesson').hidden, null, { timeout: 20000 });
  await page.click('#embed-snippet');
  await page.waitForSelector('#embed-builder:not([hidden])');
  const code = await choose(page, { views: ['arm', 'traces'], size: [760, 480], strip: ['play', 'reset'], lesson: 2 });
  const src = (await parse(page, code)).src;
  assert.match(src, /lesson=2/);
  assert.ok(src.endsWith(link.hash), `the embed carries the link's lesson: ${src.slice(0, 160)}…`);
  // The embedded step is the teacher's lesson's second step.
  const frame = page.frames().find((f) => f.parentFrame() === page.mainFrame());
  await frame.waitForFunction(() => document.querySelector('#lesson-title')?.textContent === 'Find a stable δ', null, { timeout: 30000 });
  assert.deepEqual(problems, []);
  await close();
});
