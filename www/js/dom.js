// Small DOM helpers shared by the page's modules.

/** @param {string} id */
export function byId(id) {
  const node = document.getElementById(id);
  if (!node) throw new Error(`the page has no element #${id}`);
  return node;
}

/** Sets an element's text only when it changed (no DOM churn, no screen-reader chatter).
 * @param {Element} node @param {string} text */
export function setText(node, text) {
  if (node.textContent !== text) node.textContent = text;
}

/**
 * A new element with attributes and children.
 * @param {string} tag
 * @param {Record<string, string | boolean>} [attrs]
 * @param {(Node | string)[]} [children]
 */
export function make(tag, attrs = {}, children = []) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (v === false) continue;
    if (k === 'text') node.textContent = String(v);
    else node.setAttribute(k, v === true ? '' : String(v));
  }
  node.append(...children);
  return node;
}

/** The message of anything thrown. @param {unknown} e */
export function messageOf(e) {
  if (e instanceof Error) return e.message || String(e);
  if (typeof e === 'string') return e;
  try {
    return JSON.stringify(e);
  } catch {
    return String(e);
  }
}

/** The parts of a text with the paper's subscripts ("B_v1" → "B", sub "v1"): [text, isSubscript][] (pure).
 * @param {string} text @returns {[string, boolean][]} */
export function symbolParts(text) {
  /** @type {[string, boolean][]} */
  const parts = [];
  let last = 0;
  for (const m of text.matchAll(/(?<=[A-Za-zα-ωΑ-Ω])_([a-z0-9]+)/g)) {
    const at = m.index ?? 0;
    parts.push([text.slice(last, at), false], [m[1], true]);
    last = at + m[0].length;
  }
  parts.push([text.slice(last), false]);
  return parts.filter(([t]) => t !== '');
}

/** Sets an element's text with the paper's subscripts as <sub> (B_v1 → B<sub>v1</sub>), only
 * when it changed. @param {Element} node @param {string} text */
export function setSymbols(node, text) {
  const parts = symbolParts(text);
  if (node.textContent === parts.map(([t]) => t).join('') && node.childElementCount === parts.filter(([, s]) => s).length) return;
  node.replaceChildren(...parts.map(([t, sub]) => (sub ? make('sub', { text: t }) : document.createTextNode(t))));
}
