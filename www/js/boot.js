// Starting the page: the built-in lesson fetched while the simulation loads, the renderer started
// (the GPU's start is mostly waiting on the browser, done while the page builds its controls), a
// teacher's lesson (`lesson_src=`), the session opened from the URL, and the notice of what the
// URL held that was not taken; and, once the page is wired, its start (the transport buttons wait
// for it): paused where a link's moment or the system's wish for less motion asks.

import { Page } from './flexarm.js';
import { byId, make, messageOf, setText } from './dom.js';
import { loadWasm } from './wasm.js';
import { noticeLines, writeUrl } from './url.js';
import { offlineFile, readFile, readText } from './files.js';
import { START_NOTE } from './transport.js';
import { inflate } from './homework.js';

/** @typedef {import('./wasm.js').Wasm} Wasm */
/** @typedef {import('../pkg/flexarm.js').Renderer} Renderer */

/** The buttons that do nothing until the session is open. */
const TRANSPORT = ['play', 'step', 'reset', 'poke', 'export-csv', 'copy-command'];

/** Enables (or disables) the buttons that need the session. @param {boolean} enabled */
function enableTransport(enabled) {
  for (const id of TRANSPORT) /** @type {HTMLButtonElement} */ (byId(id)).disabled = !enabled;
}

/**
 * Loads the simulation and opens the session for the page's URL; null when the module could not
 * be loaded (the page says so, and how to build it).
 * @param {{ show: (text: string) => void }} errors
 * @returns {Promise<{ wasm: Wasm, session: Page, rendererReady: Promise<Renderer> } | null>}
 */
export async function openPage(errors) {
  performance.mark('flexarm:main-start');
  enableTransport(false);
  // The lesson is a file beside the page (the session parses it), fetched while the module loads.
  const lessonText = readText('lessons/paper.md');
  /** @type {Wasm} */
  let wasm;
  try {
    wasm = await loadWasm();
  } catch (e) {
    setText(byId('loading-text'), 'Could not load the simulation.');
    byId('loading').querySelector('.spinner')?.remove();
    errors.show(offlineFile()
      ? `Starting the simulation failed: ${messageOf(e)}.`
      : `Loading ./pkg/flexarm.js failed: ${messageOf(e)}. Build it with "bash scripts/serve.sh".`);
    return null;
  }
  // The GPU starts up (mostly waiting on the browser) while the page builds its controls.
  performance.mark('flexarm:renderer-start');
  const rendererReady = wasm.Renderer.create(/** @type {HTMLCanvasElement} */ (byId('canvas')));
  rendererReady.catch(() => {}); // handled where it is awaited
  // A teacher's lesson (`lesson_src=PATH`): fetched only from a path of this site (the session
  // says why anything else is refused, and checks the file as it checks the built-in lesson); in
  // an offline file, from the files it carries, else the lesson the file carries.
  const offline = offlineFile();
  const query = startQuery(offline);
  // A homework link carries its lesson in the address's fragment (#lesson=…), checked as a file.
  const linked = await linkedLesson(wasm);
  const teacher = (await fetchTeacherLesson(wasm, query)) ?? linked.lesson ?? carriedLesson(offline);
  const session = new Page(wasm, query, await lessonText, teacher, offline !== null);
  performance.mark('flexarm:session-ready');
  showNotices([...linked.notices, ...session.notices()]);
  return { wasm, session, rendererReady };
}

/**
 * The wired page shows the session and starts: the controls and the URL show its state, the
 * loading screen goes, and the frame loop runs — paused where a link to a moment (`paused=1&t=3`)
 * or the system (reduced motion) asks.
 * @param {{ session: Page, store: ReturnType<typeof import('./store.js').createStore>, sync: () => void,
 *   loop: { start: () => void } }} on
 */
export function begin({ session, store, sync, loop }) {
  sync();
  writeUrl(session.stateString());
  byId('loading').hidden = true;
  // A link to a moment (`paused=1&t=3`) opens paused there.
  if (session.takeStartPaused()) {
    store.dispatch({ type: 'pause' });
    session.setNote(START_NOTE);
  }
  // Motion only on request where the system asks for less of it.
  if (matchMedia('(prefers-reduced-motion: reduce)').matches) {
    store.dispatch({ type: 'pause' });
    session.setNote('Paused because your system asks for reduced motion: press Play to run.');
  }
  enableTransport(true);
  loop.start();
}

/**
 * The query the page opens with: its address's, or, in an offline file whose address holds none,
 * the start the file carries.
 * @param {import('./files.js').Offline | null} offline
 */
function startQuery(offline) {
  const own = window.location.search;
  return offline && own.replace(/^\?/u, '') === '' ? offline.start.query : own;
}

/** The lesson an offline file carries, as the session takes a teacher's. @param {import('./files.js').Offline | null} offline */
function carriedLesson(offline) {
  const lesson = offline?.start.lesson;
  return lesson ? { path: lesson.name, bytes: new TextEncoder().encode(lesson.text), carried: true } : null;
}

/**
 * The lesson a homework link carries in the address's fragment, unpacked, as the session takes a
 * teacher's; and, when the fragment holds one that cannot be read, the notice that says why.
 * @param {Wasm} wasm
 */
async function linkedLesson(wasm) {
  try {
    const carried = wasm.readLessonFragment(window.location.hash);
    if (!carried) return { lesson: null, notices: [] };
    const bytes = await inflate(new Uint8Array(carried.bytes));
    return { lesson: { path: carried.name, bytes, carried: true, fragment: window.location.hash }, notices: [] };
  } catch (e) {
    return { lesson: null, notices: [{ key: 'lesson', text: `The homework link's lesson could not be read: ${messageOf(e)}` }] };
  }
}

/** The bytes of the lesson file `lesson_src=` names, if it is on this site and loads. @param {Wasm} wasm @param {string} query */
async function fetchTeacherLesson(wasm, query) {
  const value = new URLSearchParams(query).get('lesson_src');
  if (value === null) return null;
  try {
    const path = wasm.lessonSourcePath(value);
    return { path, bytes: await readFile(path), carried: false };
  } catch {
    return null; // the session's notice says why
  }
}

/** The URL's values that were not taken. @param {{ key: string, text: string }[]} notices */
function showNotices(notices) {
  if (notices.length === 0) return;
  byId('url-notice-list').replaceChildren(...noticeLines(notices).map((text) => make('li', { text })));
  byId('url-notice').hidden = false;
  byId('url-notice-dismiss').addEventListener('click', () => (byId('url-notice').hidden = true), { once: true });
}
