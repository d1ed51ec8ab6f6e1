// The page's URL holds the session's state string, so a link shows the same thing to anyone;
// what the URL held that the session did not take is listed in a notice (noticeLines).

/**
 * The URL for `query` on the current page (pure).
 * @param {{ pathname: string, hash: string }} location @param {string} query
 */
export function urlFor(location, query) {
  return `${location.pathname}${query ? `?${query}` : ''}${location.hash}`;
}

/** Rewrites the address bar to hold `query`, without a new history entry. @param {string} query */
export function writeUrl(query) {
  if (`?${query}` === window.location.search) return;
  try {
    history.replaceState(null, '', urlFor(window.location, query));
  } catch (e) {
    // Some embedders forbid replaceState (e.g. file: URLs); the page works without it.
    console.warn('could not update the URL:', e);
  }
}

/** Longest run of characters without a space that a notice repeats in full. */
const NOTICE_WORD = 60;
/** Longest notice line, characters (the longest the page writes itself is about 300). */
const NOTICE_LINE = 400;
/** Notices listed at most; the rest are counted. */
const NOTICES_SHOWN = 10;

/**
 * The lines of the "URL values were ignored" notice (pure): one per value not taken, a long value
 * shortened (a 10-kB value would fill the screen and push the page sideways), at most
 * NOTICES_SHOWN lines and then how many more.
 * @param {{ key: string, text: string }[]} notices @returns {string[]}
 */
export function noticeLines(notices) {
  const lines = notices.slice(0, NOTICES_SHOWN).map((n) => `Ignored URL value — ${shortenMiddle(shortenWords(n.text, NOTICE_WORD), NOTICE_LINE)}`);
  const more = notices.length - NOTICES_SHOWN;
  if (more > 0) lines.push(`… and ${more} more ignored value${more === 1 ? '' : 's'}.`);
  return lines;
}

/** `text` with every run of more than `max` non-space characters cut to `max` and "…" (and
 * how long it was). @param {string} text @param {number} max */
export function shortenWords(text, max) {
  return text.replace(/\S+/gu, (word) => {
    const chars = Array.from(word);
    if (chars.length <= max) return word;
    // The quotes and the colon of "= '…':" are the message's, not the value's: kept, not counted.
    const lead = word.match(/^['"]*/u)?.[0] ?? '';
    const tail = word.match(/['":,]*$/u)?.[0] ?? '';
    return `${chars.slice(0, max).join('')}… (${chars.length - lead.length - tail.length} characters)${tail}`;
  });
}

/** `text` cut to about `max` characters by leaving out its middle (a value of many short words),
 * keeping its start (what was wrong) and its end (what is allowed). @param {string} text @param {number} max */
export function shortenMiddle(text, max) {
  const chars = Array.from(text);
  if (chars.length <= max) return text;
  const half = Math.floor((max - 1) / 2);
  return `${chars.slice(0, half).join('')}…${chars.slice(chars.length - half).join('')}`;
}
