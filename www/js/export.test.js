import { test } from 'node:test';
import assert from 'node:assert/strict';
import { VIDEO_TYPES, baselineIn, captionText, figureSize, firstSupported, fitText, formatElapsed, isTransparent } from './export.js';

/** A monospace measure: 7 px a character. */
const mono = (/** @type {string} */ s) => 7 * Array.from(s).length;

test('the caption names the view and the state string', () => {
  assert.equal(captionText('Fig. 5.3', 'delta=0.01&pf=off'), 'flexarm — Fig. 5.3 — state: delta=0.01&pf=off');
});

test('a caption that fits is left alone; a long one ends with … and fits', () => {
  assert.equal(fitText('short', 100, mono), 'short');
  const long = captionText('run A', 'delta=0.01&alpha=2&pf=off&k=0.5&m=2&inner=pd&speed=2&mode=full');
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
