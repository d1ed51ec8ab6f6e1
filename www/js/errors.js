// The error area: what went wrong, once per message (repeats are counted), and `guard`, which
// runs a call into the wasm and reports instead of throwing.

import { byId, messageOf } from './dom.js';

/** How many messages stay listed. */
const KEPT = 8;

/** @param {{ get: () => { dead: boolean } }} store */
export function createErrors(store) {
  const area = byId('error');
  const list = byId('error-list');
  /** @type {{ text: string, item: HTMLElement | null, count: number }} */
  const last = { text: '', item: null, count: 0 };
  byId('error-dismiss').addEventListener('click', () => {
    area.hidden = true;
    list.replaceChildren();
    last.text = '';
    last.item = null;
  });

  /** @param {string} text */
  function show(text) {
    if (text === last.text && last.item && last.item.isConnected) {
      last.count += 1;
      last.item.textContent = `${text} (×${last.count})`;
    } else {
      const li = document.createElement('li');
      li.textContent = text;
      list.appendChild(li);
      while (list.children.length > KEPT) list.firstElementChild?.remove();
      Object.assign(last, { text, item: li, count: 1 });
    }
    area.hidden = false;
  }

  /** @param {string} context @param {unknown} e */
  function report(context, e) {
    const text = `${context}: ${messageOf(e)}`;
    console.warn(text);
    show(text);
  }

  /**
   * Calls `fn`, reporting anything it throws; returns `fallback` then (or when the wasm crashed).
   * @template T
   * @param {string} context @param {() => T} fn @param {T} [fallback]
   * @returns {T | undefined}
   */
  function guard(context, fn, fallback = undefined) {
    if (store.get().dead) return fallback;
    try {
      return fn();
    } catch (e) {
      report(context, e);
      return fallback;
    }
  }

  window.addEventListener('error', (ev) => {
    if (ev.error || ev.message) show(`Unexpected error: ${messageOf(ev.error || ev.message)}`);
  });
  window.addEventListener('unhandledrejection', (ev) => show(`Unexpected error: ${messageOf(ev.reason)}`));
  return { show, report, guard };
}
