// One homework link (issue 35): a teacher's lesson carried inside the page's address, in the
// fragment, which no server sees. Rust writes and reads the link and checks its size
// (`classroom::link`); the browser compresses (raw deflate), as it does for the offline file.

import { byId, setText } from './dom.js';

/** The bytes of `text`, compressed with raw deflate. @param {string} text */
export async function deflate(text) {
  const stream = new Blob([text]).stream().pipeThrough(new CompressionStream('deflate-raw'));
  return new Uint8Array(await new Response(stream).arrayBuffer());
}

/** The bytes `packed` (raw deflate) unpacked. @param {Uint8Array} packed */
export async function inflate(packed) {
  const stream = new Blob([/** @type {Uint8Array<ArrayBuffer>} */ (packed)]).stream().pipeThrough(new DecompressionStream('deflate-raw'));
  return new Uint8Array(await new Response(stream).arrayBuffer());
}

/**
 * The teacher's side: with a teacher's lesson open, "make a homework link" writes the link into a
 * field (and the clipboard, where the browser allows), with its length.
 * @param {{ wasm: import('./wasm.js').Wasm, session: { teacherLesson: () => { name: string, text: string } | null,
 *   carryInLink: (name: string, compressed: Uint8Array) => string },
 *   report: (what: string, e: unknown) => void }} on
 */
export function createHomework({ wasm, session, report }) {
  const row = byId('lesson-link-row');
  const out = byId('lesson-link-out');
  const field = /** @type {HTMLInputElement} */ (byId('lesson-link'));
  const size = byId('lesson-link-size');

  function refresh() {
    row.hidden = session.teacherLesson() === null;
    if (row.hidden) out.hidden = true;
  }

  byId('lesson-link-make').addEventListener('click', async () => {
    const lesson = session.teacherLesson();
    if (!lesson) return;
    try {
      const packed = await deflate(lesson.text);
      const link = wasm.lessonLink(`${location.origin}${location.pathname}`, lesson.name, packed);
      field.value = link;
      setText(size, `${link.length} characters; the lesson travels inside it, after the #, which no server sees. It opens the lesson's first step in student mode.`);
      out.hidden = false;
      // Where the teacher looks next: the link, in view.
      out.scrollIntoView({ block: 'nearest' });
      field.select();
      navigator.clipboard?.writeText(link).catch(() => {});
    } catch (e) {
      report('No homework link for this lesson', e);
    }
  });
  /**
   * A lesson just opened from a file moves into the address, as a homework link carries it: a
   * reload brings it back. One too long for an address stays until the page is left, and the
   * teacher is told so.
   */
  async function keepInAddress() {
    const lesson = session.teacherLesson();
    if (!lesson) return;
    try {
      const fragment = session.carryInLink(lesson.name, await deflate(lesson.text));
      history.replaceState(null, '', `${location.pathname}${location.search}#${fragment}`);
    } catch (e) {
      // An earlier lesson's fragment would bring that lesson back on a reload.
      if (location.hash) history.replaceState(null, '', `${location.pathname}${location.search}`);
      report('This lesson stays until you leave the page, not after a reload', e);
    }
  }

  refresh();
  return { refresh, keepInAddress };
}
