// What the page hands out besides export.js's pictures and data: the traces as CSV, the model as a
// Python script (its template, a file beside the page that Rust fills in, fetched when first asked
// for), the command line and a link to this moment (shown, and copied where the browser allows);
// and `download`, which offers data as a file.

import { byId, make, setText } from './dom.js';
import { readText } from './files.js';

/** @typedef {import('./flexarm.js').Page} Page */

/** A Blob's type for data of `type`: text and SVG say they are UTF-8 (pure). @param {string} type */
export function blobType(type) {
  return type.startsWith('text/') || type.includes('svg') ? `${type};charset=utf-8` : type;
}

/** Offers `data` as a file. @param {string} name @param {BlobPart | null | undefined} data @param {string} type */
export function download(name, data, type) {
  if (data == null) return;
  const url = URL.createObjectURL(data instanceof Blob ? data : new Blob([data], { type: blobType(type) }));
  const a = make('a', { href: url, download: name });
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

/** Shows the command line and copies it to the clipboard where the browser allows. @param {string} command */
function copyCommand(command) {
  const out = byId('command-line');
  setText(out, command);
  out.hidden = false;
  navigator.clipboard?.writeText(command).then(
    () => setText(out, `${command}  (copied)`),
    () => {},
  );
}

/**
 * The page's address with `query` (a moment's): its fragment kept, so that a lesson a homework
 * link carries goes with it; resolved against the page's address (a file opened from disk has
 * no origin to prefix).
 * @param {string} query
 */
export function momentLink(query) {
  return new URL(`?${query}${window.location.hash}`, window.location.href).href;
}

/**
 * The buttons for the traces' CSV, the Python script, the command line and the moment's link.
 * @param {{ session: Page, guard: <T>(what: string, fn: () => T, fallback?: T) => T | undefined }} on
 */
export function wireOutputs({ session, guard }) {
  byId('export-csv').addEventListener('click', () => download('flexarm-traces.csv', guard('Export failed', () => session.csv(), null), 'text/csv'));
  /** The script's template, once asked for. @type {Promise<string> | null} */
  let pythonTemplate = null;
  byId('export-python').addEventListener('click', async () => {
    pythonTemplate ??= readText('export/model_template.py').then((t) => t ?? '');
    const template = await pythonTemplate;
    download('flexarm_model.py', guard('Export failed', () => session.pythonScript(template), null), 'text/x-python');
  });
  byId('copy-command').addEventListener('click', () => copyCommand(session.commandLine()));
  // The page's address with this moment: it opens paused at the instant shown.
  // (Resolved against the page's address: a file opened from disk has no origin to prefix.)
  byId('copy-moment').addEventListener('click', () => copyCommand(momentLink(session.momentQuery())));
}
