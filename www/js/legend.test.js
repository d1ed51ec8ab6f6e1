import { test } from 'node:test';
import assert from 'node:assert/strict';
import { glyphSvg, scaleGradient } from './legend.js';

test('each glyph is a small SVG in its colour', () => {
  for (const g of ['cross', 'plus', 'ring', 'diamond', 'halo', 'line', 'dashed', 'swatch', 'chevron']) {
    const svg = glyphSvg(g, '#123456');
    assert.match(svg, /^<svg [^>]*width="14"/);
    assert.ok(svg.includes('#123456'), g);
  }
  const scale = { name: 'ρ', label: '', stops: [[0, '#00f'], [1, '#f00']], dark_stops: [[0, '#88f'], [1, '#f88']], ticks: [] };
  assert.equal(scaleGradient(scale), 'linear-gradient(to right, #00f 0.0%, #f00 100.0%)');
  assert.equal(scaleGradient(scale, true), 'linear-gradient(to right, #88f 0.0%, #f88 100.0%)', 'the dark scheme\'s colours');
});
