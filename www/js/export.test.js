import { test } from 'node:test';
import assert from 'node:assert/strict';
import { VIDEO_TYPES, baselineIn, dataJsonFromCsv, dataJsonText, figureSize, firstSupported, fitText, formatElapsed, figureOptionsText, isTransparent, wrapText } from './export.js';

/** A monospace measure: 7 px a character. */
const mono = (/** @type {string} */ s) => 7 * Array.from(s).length;

test('a caption that fits is left alone; a long one ends with … and fits', () => {
  assert.equal(fitText('short', 100, mono), 'short');
  const long = 'flexarm at t = 3 s — run A — state: delta=0.01&alpha=2&pf=off&k=0.5&m=2&inner=pd&speed=2&mode=full';
  const fitted = fitText(long, 200, mono);
  assert.ok(fitted.endsWith('…'), fitted);
  assert.ok(mono(fitted) <= 200, `${mono(fitted)} px`);
  assert.ok(mono(fitted) > 200 - 2 * 7, `as long as fits: ${fitted}`);
  assert.ok(long.startsWith(fitted.slice(0, -1)));
  assert.equal(fitText('abc', 3, mono), '…');
});

test('shortening does not split a character made of two UTF-16 units', () => {
  const fitted = fitText('ρ𝜌𝜌𝜌𝜌𝜌𝜌', 4 * 7, mono);
  assert.equal(fitted, 'ρ𝜌𝜌…');
});

test('the first supported video type is taken, best first', () => {
  assert.equal(firstSupported(VIDEO_TYPES, () => true), 'video/webm;codecs=vp9');
  assert.equal(firstSupported(VIDEO_TYPES, (t) => !t.includes('vp9')), 'video/webm;codecs=vp8');
  assert.equal(firstSupported(VIDEO_TYPES, (t) => t === 'video/webm'), 'video/webm');
  assert.equal(firstSupported(VIDEO_TYPES, () => false), '');
});

test('elapsed time reads m:ss', () => {
  assert.equal(formatElapsed(0), '0:00');
  assert.equal(formatElapsed(9_999), '0:09');
  assert.equal(formatElapsed(61_000), '1:01');
  assert.equal(formatElapsed(600_000), '10:00');
  assert.equal(formatElapsed(-5), '0:00');
});

test('the figure is the canvas at the pixel ratio with the caption strip below', () => {
  const one = figureSize(800, 500, 1);
  const two = figureSize(800, 500, 2);
  assert.equal(one.width, 800);
  assert.ok(one.height > 500);
  assert.deepEqual(two, { width: 1600, height: 2 * one.height });
  assert.deepEqual(figureSize(0, 0, 1).width, 1);
});

test('the baseline sits half the leading below the line top, then the ascent', () => {
  assert.equal(baselineIn(10, 13, 8, 2), 10 + 1.5 + 8);
  assert.equal(baselineIn(0, 10, 8, 2), 8);
});

test('transparent colours are recognised', () => {
  for (const c of ['transparent', 'rgba(0, 0, 0, 0)', 'rgb(0 0 0 / 0)', '']) assert.ok(isTransparent(c), c);
  for (const c of ['rgb(255, 255, 255)', 'rgba(255, 255, 255, 0.85)', '#fff']) assert.ok(!isTransparent(c), c);
});

test('the data as JSON: one table per quantity, rows and columns as written, non-finite numbers null', () => {
  const csv = [
    '# flexarm: the numbers behind every figure',
    '# flexarm state: delta=0.01&pf=off',
    'quantity,i,j,row,column,value,unit',
    'K_pr,0,0,T1,q1,1.023e2,N m/rad',
    'K_pr,0,1,T1,q2_dot,-1e-1,N m s/rad',
    'K_pr,1,0,T2,q1,1.617e1,N m/rad',
    'K_pr,1,1,T2,q2_dot,-2e-2,N m s/rad',
    'rho_curve,0,0,0,delta,2e-3,s',
    'rho_curve,0,1,0,rho,NaN,1',
    '',
  ].join('\n');
  const data = dataJsonFromCsv(csv);
  assert.equal(data.state, 'delta=0.01&pf=off');
  assert.deepEqual(data.head, ['flexarm: the numbers behind every figure', 'flexarm state: delta=0.01&pf=off']);
  assert.deepEqual(data.quantities.K_pr, {
    rows: ['T1', 'T2'],
    columns: ['q1', 'q2_dot'],
    values: [[102.3, -0.1], [16.17, -0.02]],
    units: [['N m/rad', 'N m s/rad'], ['N m/rad', 'N m s/rad']],
  });
  assert.deepEqual(data.quantities.rho_curve.values, [[0.002, null]]);
  const text = dataJsonText(csv);
  assert.ok(text.endsWith('}\n'));
  assert.deepEqual(JSON.parse(text), JSON.parse(JSON.stringify(data)));
});

test('a long caption is wrapped whole, after a space or an &, each line fitting', () => {
  const long = 'flexarm at t = 4.138 s — Fig. 5.3: δ = 0.01 s without preliminary feedback — state: delta=0.01&alpha=2&pf=off&friction=continuous&inner=continuous&repeat=0&k=12&eps_ratio=8&speed=1&mode=full';
  const lines = wrapText(long, 300, mono);
  assert.ok(lines.length >= 3, `${lines.length} lines`);
  assert.equal(lines.join(''), long, 'nothing cut');
  for (const l of lines) assert.ok(mono(l) <= 300 || !/[ &]/.test(l.slice(0, -1)), `fits: ${l}`);
  assert.ok(lines.slice(0, -1).every((l) => l.endsWith(' ') || l.endsWith('&')), 'broken after a space or &');
  assert.deepEqual(wrapText('short', 300, mono), ['short']);
  assert.deepEqual(wrapText('', 300, mono), ['']);
});

test('the caption strip grows a line at a time', () => {
  const one = figureSize(800, 500, 2, 1);
  const three = figureSize(800, 500, 2, 3);
  assert.equal(one.width, 1600);
  assert.ok(three.height > one.height && (three.height - one.height) % 2 === 0, `${one.height} → ${three.height}`);
});

test('the figure row\'s choices are written as Rust reads them, the unchosen left out', () => {
  assert.equal(figureOptionsText({ dark: '0', background: 'white', text: '', caption: 'settings', shape: 'wide', zview: '0.98,0.29,0.05' }),
    'dark=0&background=white&caption=settings&shape=wide&zview=0.98,0.29,0.05');
  assert.equal(figureOptionsText({ text: '' }), '');
});
