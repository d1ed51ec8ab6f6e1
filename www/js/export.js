// Export of what is on screen: a PNG of the figure with a caption line, a WebM video of a run,
// the SVG figures Rust writes and the data behind the figures (JSON, CSV) (the embed: embed.js).
// The picture is composited here (the wgpu canvas, the HTML labels over it, a caption); what the
// SVGs, the data and the snippet say is Rust's.

import { byId, messageOf, setText } from './dom.js';

/** Height of a one-line caption strip under the figure, and of each further line, CSS px. */
const CAPTION_PX = 28;
const CAPTION_LINE_PX = 18;
/** The caption's font size, CSS px. */
const CAPTION_FONT_PX = 13;
/** "Save the picture" draws at least this many pixels per CSS px (a slide wants more than 1×). */
export const PICTURE_SCALE = 2;
/** Frames per second of the recorded video. */
const VIDEO_FPS = 30;
/** A recording stops by itself after this long, ms. */
const VIDEO_MAX_MS = 60_000;
/** The recorded video is at most this wide, px (a 2× screen would give very large frames). */
const VIDEO_MAX_WIDTH = 1920;
/** The video formats tried, best first. */
export const VIDEO_TYPES = ['video/webm;codecs=vp9', 'video/webm;codecs=vp8', 'video/webm'];

// ---------------------------------------------------------------- pure helpers (unit-tested)

/**
 * `text`, shortened with … at the end so that `measure` of it is at most `maxWidth`.
 * @param {string} text @param {number} maxWidth @param {(s: string) => number} measure
 */
export function fitText(text, maxWidth, measure) {
  if (measure(text) <= maxWidth) return text;
  const chars = Array.from(text);
  let lo = 0;
  let hi = chars.length - 1;
  // The longest prefix whose shortened form fits (binary search: widths grow with length).
  while (lo < hi) {
    const mid = Math.ceil((lo + hi) / 2);
    if (measure(`${chars.slice(0, mid).join('')}…`) <= maxWidth) lo = mid;
    else hi = mid - 1;
  }
  return lo === 0 ? '…' : `${chars.slice(0, lo).join('').trimEnd()}…`;
}

/**
 * `text` broken into lines that each `measure` at most `maxWidth`, after a space or an `&` (the
 * state string's breaks); nothing is cut: put together, the lines are `text` (pure).
 * @param {string} text @param {number} maxWidth @param {(s: string) => number} measure
 */
export function wrapText(text, maxWidth, measure) {
  /** @type {string[]} */
  const lines = [];
  let line = '';
  for (const piece of text.split(/(?<=[ &])/)) {
    if (line && measure(line + piece) > maxWidth) {
      lines.push(line);
      line = piece;
    } else {
      line += piece;
    }
  }
  if (line || lines.length === 0) lines.push(line);
  return lines;
}

/** The first of `types` that `supported` accepts, or '' for none. @param {string[]} types @param {(t: string) => boolean} supported */
export function firstSupported(types, supported) {
  return types.find((t) => supported(t)) ?? '';
}

/** Elapsed time as m:ss. @param {number} ms */
export function formatElapsed(ms) {
  const s = Math.max(0, Math.floor(ms / 1000));
  return `${Math.floor(s / 60)}:${String(s % 60).padStart(2, '0')}`;
}

/** The caption strip's height for `lines` lines, CSS px. @param {number} lines */
export function captionHeight(lines) {
  return CAPTION_PX + Math.max(0, lines - 1) * CAPTION_LINE_PX;
}

/**
 * The pixel size of a composite of a canvas `cssWidth`×`cssHeight` CSS px at `scale` px per CSS
 * px, with the caption strip of `lines` lines below.
 * @param {number} cssWidth @param {number} cssHeight @param {number} scale @param {number} [lines]
 */
export function figureSize(cssWidth, cssHeight, scale, lines = 1) {
  return { width: Math.max(1, Math.round(cssWidth * scale)), height: Math.max(1, Math.round((cssHeight + captionHeight(lines)) * scale)) };
}

/**
 * Where a text's alphabetic baseline lies in a line box (CSS: half the leading above the font's
 * ascent). @param {number} top @param {number} lineHeight @param {number} ascent @param {number} descent
 */
export function baselineIn(top, lineHeight, ascent, descent) {
  return top + (lineHeight - ascent - descent) / 2 + ascent;
}

/** Whether a computed CSS colour paints nothing. @param {string} colour */
export function isTransparent(colour) {
  const c = colour.replace(/\s+/g, '');
  return c === '' || c === 'transparent' || /^rgba\(\d+,\d+,\d+,0(\.0*)?\)$/.test(c) || /\/0(\.0*)?\)$/.test(c);
}

/**
 * The data behind the figures (the long CSV Rust writes: `# ` lines, then
 * `quantity,i,j,row,column,value,unit`) reshaped into the JSON `flexarm data --json` prints:
 * `{head, state, quantities: {NAME: {rows, columns, values, units}}}`, one table per quantity,
 * non-finite numbers null. @param {string} csv
 */
export function dataJsonFromCsv(csv) {
  /** @type {string[]} */
  const head = [];
  /** @type {Record<string, {rows: string[], columns: string[], values: (number | null)[][], units: string[][]}>} */
  const quantities = {};
  let header = true;
  for (const line of csv.split('\n')) {
    if (line.startsWith('# ')) {
      head.push(line.slice(2));
    } else if (header) {
      header = false; // the columns' names
    } else if (line) {
      const [quantity, i, j, row, column, value, unit] = line.split(',');
      const t = (quantities[quantity] ??= { rows: [], columns: [], values: [], units: [] });
      const [r, c] = [Number(i), Number(j)];
      if (t.rows.length === r) {
        t.rows.push(row);
        t.values.push([]);
        t.units.push([]);
      }
      if (t.columns.length === c) t.columns.push(column);
      const v = Number(value);
      t.values[r].push(Number.isFinite(v) ? v : null);
      t.units[r].push(unit);
    }
  }
  const state = head.find((l) => l.startsWith('flexarm state: '))?.slice('flexarm state: '.length) ?? '';
  return { head, state, quantities };
}

/** The same as JSON text, indented. @param {string} csv */
export function dataJsonText(csv) {
  return `${JSON.stringify(dataJsonFromCsv(csv), null, 1)}\n`;
}

/** The scales a figure's PNG is offered at (px per figure px). */
export const FIGURE_SCALES = [1, 2, 4];

/**
 * The file name of a figure, with what it shows (`label`: the preset or the key settings, the
 * session's): `flexarm-fig5.3-zplane.svg`, `flexarm-delta0.02-alpha5-pf-off-zplane@2x.png` (pure).
 * @param {string} panel @param {string} format @param {number} scale @param {string} [label]
 */
export function figureFileName(panel, format, scale, label = '') {
  const stem = label ? `flexarm-${label}-${panel}` : `flexarm-${panel}`;
  return format === 'png' ? `${stem}@${scale}x.png` : `${stem}.svg`;
}

/**
 * The PNG's pixel size for a figure `width`×`height` px at `scale` (pure).
 * @param {number} width @param {number} height @param {number} scale
 */
export function figurePngSize(width, height, scale) {
  return { width: Math.max(1, Math.round(width * scale)), height: Math.max(1, Math.round(height * scale)) };
}

/**
 * A figure's options as Rust reads them, `key=value` joined by `&`, leaving out those not chosen
 * (pure). @param {Record<string, string>} choices
 */
export function figureOptionsText(choices) {
  return Object.entries(choices).filter(([, v]) => v !== '').map(([k, v]) => `${k}=${v}`).join('&');
}

/**
 * The options of the figure list, as Rust lists the panels shown, keeping `selected` when it is
 * still among them (pure). @param {{ id: string, label: string }[]} panels @param {string} selected
 */
export function figureOptions(panels, selected) {
  const keep = panels.some((p) => p.id === selected) ? selected : (panels[0]?.id ?? '');
  return panels.map((p) => ({ value: p.id, text: p.label, selected: p.id === keep }));
}

/** What a data file lacks while the maps are unfinished (or hidden, and so not computed), else "". @param {import('./flexarm.js').Page} session */
function mapsNote(session) {
  return session.status().maps.done ? '' : ', with the stability maps only as far as they are computed (see "omitted" in it)';
}

/** The canvas font of a computed style (size in CSS px: the context is scaled). @param {CSSStyleDeclaration} s */
function fontOf(s) {
  return `${s.fontStyle} ${s.fontWeight} ${s.fontSize} ${s.fontFamily}`;
}

// ---------------------------------------------------------------- compositing

/**
 * Draws the figure into `target` (sized by the caller, `scale` px per CSS px): the wgpu canvas
 * as just rendered, every label shown over it, and the caption's `lines`. False when nothing was
 * drawn.
 * @param {CanvasRenderingContext2D} ctx
 * @param {number} scale
 * @param {{ canvas: HTMLCanvasElement, overlay: HTMLElement, renderNow: () => boolean, caption: () => string }} from
 * @param {string[]} lines
 */
export function composeFigure(ctx, scale, from, lines) {
  const box = from.canvas.getBoundingClientRect();
  const page = getComputedStyle(document.body);
  const surface = getComputedStyle(from.canvas.parentElement ?? document.body).backgroundColor;
  ctx.setTransform(scale, 0, 0, scale, 0, 0);
  ctx.fillStyle = isTransparent(surface) ? '#ffffff' : surface;
  ctx.fillRect(0, 0, box.width, box.height + captionHeight(lines.length));
  // Rendered and copied in the same task: the drawing buffer is still the frame's.
  if (!from.renderNow()) return false;
  ctx.drawImage(from.canvas, 0, 0, box.width, box.height);
  drawLabels(ctx, from.overlay, box);
  drawCaption(ctx, box, lines, page);
  return true;
}

/** The caption's font on this page. @param {CSSStyleDeclaration} page */
function captionFont(page) {
  return `400 ${CAPTION_FONT_PX}px ${page.fontFamily}`;
}

/**
 * The caption's lines for a figure `width` CSS px wide: the whole text, wrapped (`whole`), or cut
 * to one line with … (a video's frames keep one size).
 * @param {string} text @param {number} width @param {boolean} whole
 */
function captionLines(text, width, whole) {
  const ctx = document.createElement('canvas').getContext('2d');
  if (!ctx) return [text];
  ctx.font = captionFont(getComputedStyle(document.body));
  const measure = (/** @type {string} */ t) => ctx.measureText(t).width;
  const room = width - 2 * CAPTION_PAD;
  return whole ? wrapText(text, room, measure) : [fitText(text, room, measure)];
}

/** Every label shown over the canvas, where it is on screen. @param {CanvasRenderingContext2D} ctx @param {HTMLElement} overlay @param {DOMRect} box */
function drawLabels(ctx, overlay, box) {
  for (const span of /** @type {NodeListOf<HTMLElement>} */ (overlay.querySelectorAll('.label'))) {
    if (span.hidden || span.getClientRects().length === 0 || !span.textContent) continue;
    const s = getComputedStyle(span);
    if (s.visibility === 'hidden' || s.display === 'none') continue;
    const r = span.getBoundingClientRect();
    const x = r.left - box.left;
    const y = r.top - box.top;
    if (!isTransparent(s.backgroundColor)) {
      ctx.fillStyle = s.backgroundColor;
      ctx.beginPath();
      ctx.roundRect(x, y, r.width, r.height, parseFloat(s.borderTopLeftRadius) || 0);
      ctx.fill();
    }
    ctx.font = fontOf(s);
    ctx.fillStyle = s.color;
    ctx.textAlign = 'left';
    ctx.textBaseline = 'alphabetic';
    const m = ctx.measureText(span.textContent);
    const left = x + (parseFloat(s.paddingLeft) || 0) + (parseFloat(s.borderLeftWidth) || 0);
    const top = y + (parseFloat(s.paddingTop) || 0) + (parseFloat(s.borderTopWidth) || 0);
    const inner = r.height - (parseFloat(s.paddingTop) || 0) - (parseFloat(s.paddingBottom) || 0);
    ctx.fillText(span.textContent, left, baselineIn(top, inner, m.fontBoundingBoxAscent, m.fontBoundingBoxDescent));
  }
}

/** The caption's side margin, CSS px. */
const CAPTION_PAD = 8;

/** The caption strip under the figure. @param {CanvasRenderingContext2D} ctx @param {DOMRect} box @param {string[]} lines @param {CSSStyleDeclaration} page */
function drawCaption(ctx, box, lines, page) {
  ctx.fillStyle = page.color || '#1b2330';
  ctx.fillRect(0, box.height, box.width, 1);
  ctx.font = captionFont(page);
  ctx.textAlign = 'left';
  ctx.textBaseline = 'middle';
  lines.forEach((line, k) => ctx.fillText(line, CAPTION_PAD, box.height + CAPTION_PX / 2 + k * CAPTION_LINE_PX));
}

/**
 * A 2D canvas sized for the figure at `scale` with a caption of `lines` lines.
 * @param {HTMLCanvasElement} canvas @param {number} scale @param {number} lines
 */
function figureCanvas(canvas, scale, lines) {
  const box = canvas.getBoundingClientRect();
  const out = document.createElement('canvas');
  Object.assign(out, figureSize(box.width, box.height, scale, lines));
  const ctx = out.getContext('2d');
  if (!ctx) throw new Error('this browser has no 2D canvas');
  return { out, ctx };
}

// ---------------------------------------------------------------- the buttons

/**
 * @param {{ session: import('./flexarm.js').Page, canvas: HTMLCanvasElement, overlay: HTMLElement, renderNow: () => boolean,
 *   renderer: () => import('../pkg/flexarm.js').Renderer | null, touch: () => void,
 *   download: (name: string, data: BlobPart | null | undefined, type: string) => void,
 *   report: (what: string, e: unknown) => void }} on
 */
export function createExport(on) {
  const status = byId('export-status');
  const say = (/** @type {string} */ text) => setText(status, text);
  const from = {
    canvas: on.canvas,
    overlay: on.overlay,
    renderNow: on.renderNow,
    caption: () => on.session.pictureCaption(),
  };
  /** A click handler that reports what fails. @param {string} what @param {() => void | Promise<void>} fn */
  const guarded = (what, fn) => async () => {
    try {
      await fn();
    } catch (e) {
      on.report(what, e);
    }
  };

  byId('export-png').addEventListener('click', guarded('Saving the picture failed', () => savePng(on, from, say)));
  wireVideo(on, from, say);
  // The errors and the maps as figures: the same SVG as the Figure row's (view/figure in Rust).
  byId('export-svg-traces').addEventListener('click', guarded('Saving the error figure failed', () => {
    const name = figureFileName('errors', 'svg', 1, on.session.fileLabel());
    on.download(name, on.session.figureSvg('errors'), 'image/svg+xml');
    say(`Saved ${name}.`);
  }));
  byId('export-svg-maps').addEventListener('click', guarded('Saving the map figure failed', () => {
    let svg;
    try {
      svg = on.session.figureSvg('maps');
    } catch (e) {
      say(messageOf(e)); // not computed yet: an expected state, not an error
      return;
    }
    const name = figureFileName('maps', 'svg', 1, on.session.fileLabel());
    on.download(name, svg, 'image/svg+xml');
    say(`Saved ${name}.`);
  }));
  wireFigure(on, say, guarded);
  byId('export-data-json').addEventListener('click', guarded('Saving the data failed', () => {
    on.download('flexarm-data.json', dataJsonText(on.session.dataCsv()), 'application/json');
    say(`Saved flexarm-data.json${mapsNote(on.session)}.`);
  }));
  byId('export-data-csv').addEventListener('click', guarded('Saving the data failed', () => {
    on.download('flexarm-data.csv', on.session.dataCsv(), 'text/csv');
    say(`Saved flexarm-data.csv${mapsNote(on.session)}.`);
  }));
}

/**
 * Composites the figure and offers it as flexarm-<what it shows>-figure.png: drawn again at
 * [`PICTURE_SCALE`] pixels per CSS px or the screen's, whichever is more (the renderer resized
 * for the one frame, then back), with the whole caption wrapped under it.
 * @param {{ download: (name: string, data: Blob, type: string) => void, session: { fileLabel: () => string },
 *   renderer: () => import('../pkg/flexarm.js').Renderer | null, touch: () => void }} on
 * @param {Parameters<typeof composeFigure>[2]} from @param {(text: string) => void} say
 */
async function savePng(on, from, say) {
  const dpr = window.devicePixelRatio || 1;
  const scale = Math.max(PICTURE_SCALE, dpr);
  const box = from.canvas.getBoundingClientRect();
  const lines = captionLines(from.caption(), box.width, true);
  const { out, ctx } = figureCanvas(from.canvas, scale, lines.length);
  const renderer = on.renderer();
  const [w, h] = [Math.round(box.width), Math.round(box.height)];
  let drawn;
  try {
    if (renderer && scale !== dpr) renderer.resize(w, h, scale, window.innerHeight);
    drawn = composeFigure(ctx, scale, from, lines);
  } finally {
    if (renderer && scale !== dpr) renderer.resize(w, h, dpr, window.innerHeight);
    on.touch();
  }
  if (!drawn) {
    say('Nothing to save: the figure is not drawn in this browser.');
    return;
  }
  /** @type {Blob | null} */
  const blob = await new Promise((resolve) => out.toBlob(resolve, 'image/png'));
  if (!blob) throw new Error('the browser made no PNG');
  const name = `flexarm-${on.session.fileLabel()}-figure@${scale}x.png`;
  on.download(name, blob, 'image/png');
  say(`Saved ${name} (${out.width}×${out.height} px).`);
}

/**
 * The record button: a composited canvas redrawn every frame, recorded as WebM.
 * @param {{ download: (name: string, data: Blob, type: string) => void, report: (what: string, e: unknown) => void }} on
 * @param {Parameters<typeof composeFigure>[2]} from @param {(text: string) => void} say
 */
function wireVideo(on, from, say) {
  const button = /** @type {HTMLButtonElement} */ (byId('record-video'));
  const idleText = button.textContent ?? '';
  const type = typeof MediaRecorder === 'undefined' ? '' : firstSupported(VIDEO_TYPES, (t) => MediaRecorder.isTypeSupported(t));
  if (!type) {
    button.disabled = true;
    say('This browser cannot record video (no MediaRecorder for WebM).');
    return;
  }
  /** @type {{ stop: () => void } | null} */
  let recording = null;
  const showIdle = () => {
    setText(button, idleText);
    button.setAttribute('aria-pressed', 'false');
  };
  button.addEventListener('click', () => {
    if (recording) {
      recording.stop();
      return;
    }
    try {
      recording = record(type, from, {
        tick: (ms) => setText(button, `Stop recording (${formatElapsed(ms)})`),
        done: (blob) => {
          recording = null;
          showIdle();
          on.download('flexarm-run.webm', blob, 'video/webm');
          say(`Saved flexarm-run.webm (${Math.round(blob.size / 1024)} kB).`);
        },
        failed: (e) => {
          recording = null;
          showIdle();
          on.report('Recording the video failed', e);
        },
      });
      button.setAttribute('aria-pressed', 'true');
      setText(button, `Stop recording (${formatElapsed(0)})`);
      say('Recording… press the button again to stop (at most 1 minute).');
    } catch (e) {
      recording = null;
      showIdle();
      on.report('Recording the video failed', e);
    }
  });
}

/**
 * Starts recording the composited figure; `tick` gets the elapsed ms each frame, `done` the video.
 * @param {string} type @param {Parameters<typeof composeFigure>[2]} from
 * @param {{ tick: (ms: number) => void, done: (video: Blob) => void, failed: (e: unknown) => void }} to
 */
function record(type, from, to) {
  const box = from.canvas.getBoundingClientRect();
  const scale = Math.min(window.devicePixelRatio || 1, VIDEO_MAX_WIDTH / Math.max(1, box.width));
  const { out, ctx } = figureCanvas(from.canvas, scale, 1);
  const draw = () => {
    // The canvas may have changed size: the figure keeps the video's width, its caption one line.
    const width = Math.max(1, from.canvas.getBoundingClientRect().width);
    composeFigure(ctx, out.width / width, from, captionLines(from.caption(), width, false));
  };
  draw();
  const stream = out.captureStream(VIDEO_FPS);
  const recorder = new MediaRecorder(stream, { mimeType: type });
  /** @type {Blob[]} */
  const chunks = [];
  const t0 = performance.now();
  let frame = 0;
  let failed = false;
  const loop = () => {
    try {
      draw();
    } catch (e) {
      failed = true;
      to.failed(e);
      finish();
      return;
    }
    to.tick(performance.now() - t0);
    frame = requestAnimationFrame(loop);
  };
  const limit = setTimeout(() => finish(), VIDEO_MAX_MS);
  const finish = () => {
    cancelAnimationFrame(frame);
    clearTimeout(limit);
    if (recorder.state !== 'inactive') recorder.stop();
  };
  recorder.addEventListener('dataavailable', (e) => {
    if (e.data.size > 0) chunks.push(e.data);
  });
  recorder.addEventListener('stop', () => {
    stream.getTracks().forEach((t) => t.stop());
    if (!failed) to.done(new Blob(chunks, { type: 'video/webm' }));
  });
  recorder.addEventListener('error', (e) => {
    failed = true;
    cancelAnimationFrame(frame);
    clearTimeout(limit);
    to.failed(/** @type {any} */ (e).error ?? e);
  });
  recorder.start(1000);
  frame = requestAnimationFrame(loop);
  return { stop: finish };
}

// ---------------------------------------------------------------- a figure per panel

/**
 * The Figure row: which panel (those shown, listed by Rust), SVG or PNG at 1×, 2× or 4×, light
 * or dark, the paper, the text size, the caption and the shape (Rust reads and checks them). The
 * SVG is Rust's; a PNG is that SVG drawn into a canvas at the scale.
 * @param {{ session: import('./flexarm.js').Page, renderer: () => import('../pkg/flexarm.js').Renderer | null,
 *   download: (name: string, data: BlobPart | null | undefined, type: string) => void }} on
 * @param {(text: string) => void} say
 * @param {(what: string, fn: () => void | Promise<void>) => () => Promise<void>} guarded
 */
function wireFigure(on, say, guarded) {
  const panel = /** @type {HTMLSelectElement} */ (byId('figure-panel'));
  const format = /** @type {HTMLSelectElement} */ (byId('figure-format'));
  const scale = /** @type {HTMLSelectElement} */ (byId('figure-scale'));
  const dark = /** @type {HTMLInputElement} */ (byId('figure-dark'));
  const value = (/** @type {string} */ id) => /** @type {HTMLSelectElement} */ (byId(id)).value;
  /** The row's choices as the figure's options; the z-plane as the screen shows it. @param {ArrayLike<number> | undefined} zView */
  const figureChoices = (zView) => figureOptionsText({
    dark: dark.checked ? '1' : '0',
    background: value('figure-background'),
    text: value('figure-text'),
    caption: value('figure-caption'),
    shape: value('figure-shape'),
    zview: zView ? Array.from(zView).join(',') : '',
  });
  let listed = '';
  const refresh = () => {
    const panels = on.session.figurePanels();
    const id = JSON.stringify(panels);
    if (id === listed) return;
    listed = id;
    panel.replaceChildren(...figureOptions(panels, panel.value).map((o) => {
      const option = document.createElement('option');
      option.value = o.value;
      option.textContent = o.text;
      option.selected = o.selected;
      return option;
    }));
  };
  const syncScale = () => { scale.disabled = format.value !== 'png'; };
  refresh();
  syncScale();
  panel.addEventListener('focus', refresh);
  panel.addEventListener('pointerdown', refresh);
  format.addEventListener('change', syncScale);
  byId('figure-download').addEventListener('click', guarded('Saving the figure failed', async () => {
    refresh();
    const id = panel.value;
    let svg;
    try {
      svg = on.session.figureSvg(id, figureChoices(on.renderer()?.shownZView()));
    } catch (e) {
      say(messageOf(e)); // maps not computed, student mode: expected states, not errors
      return;
    }
    if (format.value !== 'png') {
      const name = figureFileName(id, 'svg', 1, on.session.fileLabel());
      on.download(name, svg, 'image/svg+xml');
      say(`Saved ${name}.`);
      return;
    }
    const k = Number(scale.value) || 1;
    const png = await svgToPng(svg, k);
    const name = figureFileName(id, 'png', k, on.session.fileLabel());
    on.download(name, png.blob, 'image/png');
    say(`Saved ${name} (${png.width}×${png.height} px).`);
  }));
}

/**
 * Draws an SVG document into a canvas at `scale` device px per figure px and makes a PNG of it.
 * @param {string} svg @param {number} scale
 */
async function svgToPng(svg, scale) {
  const url = URL.createObjectURL(new Blob([svg], { type: 'image/svg+xml' }));
  try {
    const img = new Image();
    await new Promise((resolve, reject) => {
      img.onload = resolve;
      img.onerror = () => reject(new Error('the browser could not draw the SVG figure'));
      img.src = url;
    });
    const out = document.createElement('canvas');
    Object.assign(out, figurePngSize(img.naturalWidth, img.naturalHeight, scale));
    const ctx = out.getContext('2d');
    if (!ctx) throw new Error('this browser has no 2D canvas');
    ctx.drawImage(img, 0, 0, out.width, out.height);
    /** @type {Blob | null} */
    const blob = await new Promise((resolve) => out.toBlob(resolve, 'image/png'));
    if (!blob) throw new Error('the browser made no PNG');
    return { blob, width: out.width, height: out.height };
  } finally {
    URL.revokeObjectURL(url);
  }
}
