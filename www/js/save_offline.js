// "Save for offline": the page as one HTML file that opens from disk — a USB stick, a course's
// file area, a message — with no server and no network (what `flexarm bundle` writes; which files
// and the file's layout are Rust's, src/offline). The page gathers its own files (fetched, or in
// an offline file the ones it carries), the browser gzips their archive once (as soon as the
// button comes into view, so that its size is said beside it), and the classroom writes the file
// opening where the page is now. An offline file also says where it opens, with a way back there.

import { byId, setText } from './dom.js';
import { offlineFile, readFile } from './files.js';

/** @typedef {import('./wasm.js').Wasm} Wasm */
/** @typedef {import('../pkg/flexarm.js').OfflineBundle} OfflineBundle */

/** The name the file is saved under. */
const FILE_NAME = 'flexarm-offline.html';

/** `bytes` gzip-compressed by the browser. @param {Uint8Array} bytes */
async function gzip(bytes) {
  const stream = new Blob([/** @type {Uint8Array<ArrayBuffer>} */ (bytes)]).stream().pipeThrough(new CompressionStream('gzip'));
  return new Uint8Array(await new Response(stream).arrayBuffer());
}

/** The bundle of the page's files and their compressed archive. @param {Wasm} wasm */
async function gather(wasm) {
  const bundle = new wasm.OfflineBundle();
  for (let path = bundle.nextWanted(); path !== undefined; path = bundle.nextWanted()) bundle.add(path, await readFile(path));
  return { bundle, compressed: await gzip(bundle.archive()) };
}

/**
 * @param {{ wasm: Wasm, session: import('./flexarm.js').Page, paused: () => boolean,
 *   download: (name: string, data: BlobPart | null | undefined, type: string) => void,
 *   report: (what: string, e: unknown) => void }} on
 */
export function createSaveOffline({ wasm, session, paused, download, report }) {
  const button = /** @type {HTMLButtonElement} */ (byId('save-offline'));
  const status = byId('offline-size');
  /** @type {Promise<{ bundle: OfflineBundle, compressed: Uint8Array }> | null} */
  let prepared = null;
  const prepare = () => {
    prepared ??= gather(wasm).catch((e) => {
      prepared = null; // tried again on the next click
      throw e;
    });
    return prepared;
  };
  /** The file as it would be saved now. @param {{ bundle: OfflineBundle, compressed: Uint8Array }} p */
  const fileOf = (p) => session.offlineFile(p.bundle, p.compressed, paused());
  /** @param {{ bundle: OfflineBundle, compressed: Uint8Array }} p @param {Uint8Array} file */
  const sizeText = (p, file) => wasm.OfflineBundle.sizeText(file.length, p.compressed.length);

  // Its size, once the button can be seen (gathering costs a moment of work: not before).
  new IntersectionObserver((entries, observer) => {
    if (!entries.some((e) => e.isIntersecting)) return;
    observer.disconnect();
    setText(status, 'Save for offline: measuring the file (the page makes it once)…');
    prepare().then((p) => setText(status, sizeText(p, fileOf(p))), () => setText(status, ''));
  }).observe(button);

  button.addEventListener('click', async () => {
    button.disabled = true;
    setText(status, 'Making the offline file…');
    try {
      const p = await prepare();
      const file = fileOf(p);
      download(FILE_NAME, /** @type {Uint8Array<ArrayBuffer>} */ (file), 'text/html');
      setText(status, `Saved as ${FILE_NAME}, opening where the page is now. ${sizeText(p, file)}`);
    } catch (e) {
      setText(status, 'The offline file could not be made (the error is shown at the top of the page).');
      report('Saving for offline failed', e);
    } finally {
      button.disabled = false;
    }
  });

  // In an offline file: where it opens, shown and reachable again (its address may hold a newer
  // state once the page has run, which a reload keeps).
  const offline = offlineFile();
  if (offline) {
    const lesson = offline.start.lesson;
    setText(byId('offline-start'), wasm.OfflineBundle.describe(offline.start.query, lesson?.name, lesson?.text));
    byId('offline-note').hidden = false;
    byId('offline-restart').addEventListener('click', () => {
      window.location.href = window.location.href.replace(/[?#].*$/su, '');
    });
  }
}
