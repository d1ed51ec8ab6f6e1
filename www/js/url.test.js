import { test } from 'node:test';
import assert from 'node:assert/strict';
import { noticeLines, shortenMiddle, shortenWords, urlFor } from './url.js';

test('the URL keeps the path and the hash around the state string', () => {
  assert.equal(urlFor({ pathname: '/flexarm/', hash: '#explain' }, 'delta=0.01&pf=off'), '/flexarm/?delta=0.01&pf=off#explain');
  assert.equal(urlFor({ pathname: '/', hash: '' }, ''), '/');
});

test('a notice shortens long values and counts what it does not list', () => {
  const long = 'x'.repeat(10240);
  const [line] = noticeLines([{ key: 'delta', text: `invalid delta = '${long}': expected a number (0.002–0.25 s)` }]);
  assert.ok(line.length < 200, line);
  assert.equal(line, `Ignored URL value — invalid delta = '${'x'.repeat(59)}… (10240 characters)': expected a number (0.002–0.25 s)`);
  const many = Array.from({ length: 13 }, (_, i) => ({ key: `k${i}`, text: `invalid k${i} = '1'` }));
  const lines = noticeLines(many);
  assert.equal(lines.length, 11);
  assert.equal(lines[10], '… and 3 more ignored values.');
  assert.equal(noticeLines(many.slice(0, 11))[10], '… and 1 more ignored value.');
  assert.equal(noticeLines(many.slice(0, 10)).length, 10);
  assert.deepEqual(noticeLines([]), []);
  assert.equal(shortenWords('short words stay', 5), 'short words stay');
  assert.equal(shortenWords('🤖'.repeat(4), 3), '🤖🤖🤖… (4 characters)', 'characters, not UTF-16 units');
  // Many short words: the middle goes, what was wrong and what is allowed stay.
  const [spaced] = noticeLines([{ key: 'alpha', text: `invalid alpha = '${'a '.repeat(5000)}': expected a number (0.1–5 1/s)` }]);
  assert.ok(spaced.length <= 420, `${spaced.length} characters`);
  assert.ok(spaced.startsWith("Ignored URL value — invalid alpha = 'a a") && spaced.endsWith("': expected a number (0.1–5 1/s)"), spaced);
  assert.equal(shortenMiddle('abcdefghij', 5), 'ab…ij');
  assert.equal(shortenMiddle('short', 5), 'short');
});
