// Where a value sits along an axis (pure): the page places the Rust-made tick labels with it.

/**
 * The fraction (0 at the start, 1 at the end) of an axis from r0 to r1 at value v.
 * @param {number} v @param {number} r0 @param {number} r1 @param {string} scale "linear" or "log"
 */
export function axisFraction(v, r0, r1, scale) {
  if (scale === 'log') return Math.log(v / r0) / Math.log(r1 / r0);
  return (v - r0) / (r1 - r0 || 1);
}

/**
 * Free height above panel `i`: down from the canvas top, or from the lowest panel (with its tick
 * labels) that sits above it in an overlapping column.
 * @param {{ x: number, y: number, width: number, height: number, x_labels?: unknown[] }[]} panels
 * @param {number} i @param {number} tickRow height of a row of tick labels, px
 */
export function roomAbove(panels, i, tickRow) {
  const p = panels[i];
  let top = 0;
  panels.forEach((q, j) => {
    if (j === i || !(q.x < p.x + p.width && p.x < q.x + q.width) || q.y >= p.y) return;
    top = Math.max(top, q.y + q.height + (q.x_labels && q.x_labels.length ? tickRow : 0));
  });
  return p.y - top;
}
