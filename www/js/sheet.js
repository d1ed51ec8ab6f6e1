// On a phone the controls, the verdict and the lesson live in a sheet over the bottom of the page:
// its button opens and closes it and says what it holds; the figure, shrunk by the stylesheet,
// goes to the top of the screen above it. On any narrow screen, where the figure does not stay
// beside the text, `showFigure` brings it into view.

import { byId, setText } from './dom.js';

/** The sheet button's words (pure). @param {boolean} open @param {boolean} inLesson */
export function sheetLabel(open, inLesson) {
  if (open) return 'Close ▾';
  return inLesson ? 'The lesson, controls and verdict ▴' : 'Controls, verdict and lesson ▴';
}

export function createSheet() {
  const sheet = byId('panel');
  const toggle = byId('sheet-toggle');
  const phone = window.matchMedia('(max-width: 700px)');
  const stage = /** @type {HTMLElement} */ (document.querySelector('.stage'));
  /** Opens or closes the sheet. @param {boolean} open */
  const openSheet = (open) => {
    sheet.classList.toggle('open', open);
    document.body.classList.toggle('sheet-open', open);
    // The figure, shrunk by the stylesheet, goes to the top of the screen above the sheet.
    if (open && phone.matches) requestAnimationFrame(() => stage.scrollIntoView({ block: 'start' }));
    toggle.setAttribute('aria-expanded', String(open));
    setText(toggle, sheetLabel(open, document.body.classList.contains('in-lesson')));
  };
  toggle.addEventListener('click', () => openSheet(!sheet.classList.contains('open')));
  return { open: openSheet };
}

/** Brings the figure into view if it is out of sight (narrow screens, where it does not stay
 * beside the text): what a "Try:" button or an answer changes is seen at once. */
export function showFigure() {
  const wrap = byId('canvas-wrap');
  const r = wrap.getBoundingClientRect();
  // On a phone the verdict strip stays over the top of the screen: the figure goes below it, not
  // under it (it hid the top of e1).
  const strip = byId('verdict-strip');
  const over = getComputedStyle(strip).position === 'sticky' ? strip.getBoundingClientRect().height + 6 : 0;
  const seen = over > 0 ? r.top >= over - 1 : r.bottom > 80;
  if (seen && r.top < window.innerHeight - 80) return;
  const smooth = !matchMedia('(prefers-reduced-motion: reduce)').matches;
  window.scrollBy({ top: r.top - over, behavior: smooth ? 'smooth' : 'auto' });
}
