// The page's URL holds the session's state string, so a link shows the same thing to anyone.

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
