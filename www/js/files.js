// The page's own files, read by path (the lessons, the Python template, the simulation):
// fetched beside the page when it is served, or, in an offline file (js/offline.js, which opened
// it), taken from the files it carries — a file opened from disk may fetch nothing.

/**
 * What an offline file carries (set by js/offline.js before the page starts), or null when served.
 * @typedef {{ files: Map<string, Uint8Array>, start: { query: string, lesson: { name: string, text: string } | null },
 *   packedBytes: number }} Offline
 */

/** The offline file this page came in, or null when the page is served. @returns {Offline | null} */
export function offlineFile() {
  return /** @type {any} */ (window).flexarmOffline ?? null;
}

/** The bytes of the page's file at `path` (relative to the page); throws with the reason. @param {string} path */
export async function readFile(path) {
  const offline = offlineFile();
  if (offline) {
    const bytes = offline.files.get(path);
    if (bytes === undefined) throw new Error(`${path} is not among the files this offline file carries`);
    return bytes;
  }
  const r = await fetch(path);
  if (!r.ok) throw new Error(`${path}: the server answered ${r.status} ${r.statusText}`);
  return new Uint8Array(await r.arrayBuffer());
}

/** The text of the page's file at `path`, or undefined if it cannot be read. @param {string} path */
export async function readText(path) {
  try {
    return new TextDecoder().decode(await readFile(path));
  } catch {
    return undefined;
  }
}
