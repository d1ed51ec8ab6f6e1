// Keyboard shortcuts: Space plays or pauses, → steps one sampling period forward and ← back (in
// the kept past), R resets; with the pointer over the z-plane, + − 0 P zoom it (`zoomKey` says
// whether they did) — unless the focus is somewhere that needs the key itself.

/** True if the key belongs to the focused element (typing, a select, a button's own Space). */
export function keyBelongsTo(/** @type {{ tagName?: string, type?: string, isContentEditable?: boolean }} */ t, /** @type {string} */ key) {
  const tag = t.tagName ?? '';
  if (t.isContentEditable || tag === 'TEXTAREA' || tag === 'SELECT') return true;
  if (tag === 'INPUT' && !['range', 'checkbox', 'radio', 'button', 'submit', 'reset'].includes(t.type ?? '')) return true;
  if (key === ' ' && (tag === 'BUTTON' || t.type === 'checkbox' || t.type === 'radio')) return true;
  if ((key === 'ArrowRight' || key === 'ArrowLeft') && (t.type === 'range' || t.type === 'radio')) return true;
  return false;
}

/** @param {{ togglePlay: () => void, step: () => void, stepBack: () => void, reset: () => void,
 *   zoomKey?: (ev: KeyboardEvent) => boolean }} on */
export function wireKeys(on) {
  document.addEventListener('keydown', (ev) => {
    if (ev.defaultPrevented || ev.ctrlKey || ev.metaKey || ev.altKey) return;
    const key = ev.code === 'Space' ? ' ' : ev.key;
    if (on.zoomKey && !keyBelongsTo(/** @type {any} */ (ev.target ?? {}), key) && on.zoomKey(ev)) {
      ev.preventDefault();
      return;
    }
    if (![' ', 'ArrowRight', 'ArrowLeft', 'r', 'R'].includes(key) || keyBelongsTo(/** @type {any} */ (ev.target ?? {}), key)) return;
    ev.preventDefault();
    if (key === ' ') on.togglePlay();
    else if (key === 'ArrowRight') on.step();
    else if (key === 'ArrowLeft') on.stepBack();
    else on.reset();
  });
}
