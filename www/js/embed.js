// The embed, both sides. In an embedded page (?embed=1) the strip under the figure shows the
// controls the session's `strip=` list names; its δ and α sliders are built from the schema as the
// page's own are. In the page, "Embed in a course page" opens the builder: a form whose values go
// to the session as a query, which checks them and writes the snippet (Rust); a live preview of
// it; and the preview's own word on the panels that do not fit (from its layout, Rust's too).

import { byId, messageOf, setText } from './dom.js';
import { buildControls } from './controls.js';
import { offlineFile } from './files.js';

/** The form's values are sent this long after the last change, ms (the preview reloads). */
const SETTLE_MS = 400;
/** How often the builder reads the preview's layout, ms. */
const FIT_POLL_MS = 500;

/**
 * The embedded page's strip.
 * @param {import('./controls.js').Param[]} schema
 * @param {{ onSet: (key: string, text: string) => void, onPosition: (key: string, f: number) => void,
 *   onStep: (key: string, steps: number) => void, reset: () => void }} on
 */
export function createEmbedStrip(schema, on) {
  const strip = byId('embed-strip');
  const sliders = buildControls(schema, on, { attribute: 'data-strip', prefix: 'embed-' });
  byId('embed-reset').addEventListener('click', on.reset);
  const items = /** @type {HTMLElement[]} */ ([...strip.querySelectorAll('[data-strip-item]')]);
  let shown = '';
  return {
    /** Shows the controls the session's strip list names, with their values. @param {import('./controls.js').ControlValue[]} values */
    sync(values) {
      const list = values.find((v) => v.key === 'strip')?.value ?? '';
      if (list !== shown) {
        shown = list;
        const names = list.split(',');
        for (const item of items) item.hidden = !names.includes(item.dataset.stripItem ?? '');
      }
      sliders.sync(values);
    },
  };
}

/**
 * The form's values as the query the session reads (pure): `views=…&width=…&height=…&paused=1
 * &t=…&strip=…&lesson=…`. What they mean and whether they are valid is the session's to say.
 * @param {{ views: string[], width: string, height: string, paused: boolean, t: string,
 *   strip: string[], lesson: string | null }} form
 */
export function choicesQuery(form) {
  const q = new URLSearchParams();
  q.set('views', form.views.join(','));
  q.set('width', form.width.trim());
  q.set('height', form.height.trim());
  if (form.paused) q.set('paused', '1');
  if (form.t.trim() !== '') q.set('t', form.t.trim());
  q.set('strip', form.strip.join(','));
  if (form.lesson != null) q.set('lesson', form.lesson.trim());
  return q.toString();
}

/**
 * The builder, in "Share and export".
 * @param {{ session: { embed: (url: string, choices: string) => any, embedDefaults: () => string } }} on
 */
export function createEmbedBuilder(on) {
  const button = byId('embed-snippet');
  const builder = byId('embed-builder');
  const code = /** @type {HTMLTextAreaElement} */ (byId('embed-code'));
  const fit = byId('embed-fit');
  const box = byId('embed-preview-box');
  /** The live preview: an iframe of the snippet's page, while the builder is open. */
  const preview = /** @type {HTMLIFrameElement} */ (document.createElement('iframe'));
  preview.id = 'embed-preview';
  preview.className = 'embed-preview';
  preview.title = 'Preview of the embed';
  const size = /** @type {HTMLSelectElement} */ (byId('embed-size'));
  const width = /** @type {HTMLInputElement} */ (byId('embed-width'));
  const height = /** @type {HTMLInputElement} */ (byId('embed-height'));
  const paused = /** @type {HTMLInputElement} */ (byId('embed-paused'));
  const t = /** @type {HTMLInputElement} */ (byId('embed-t'));
  const lessonOn = /** @type {HTMLInputElement} */ (byId('embed-lesson-on'));
  const lesson = /** @type {HTMLInputElement} */ (byId('embed-lesson'));
  const boxes = (/** @type {string} */ name) => /** @type {HTMLInputElement[]} */ ([...builder.querySelectorAll(`input[name="${name}"]`)]);
  const status = byId('export-status');
  const say = (/** @type {string} */ text) => setText(status, text);
  /** @type {{ src: string, width: number, height: number } | null} */
  let current = null;
  let timer = 0;
  let poll = 0;

  const form = () => ({
    views: boxes('embed-views').filter((b) => b.checked).map((b) => b.value),
    width: width.value,
    height: height.value,
    paused: paused.checked,
    t: t.value,
    strip: boxes('embed-strip').filter((b) => b.checked).map((b) => b.value),
    lesson: lessonOn.checked ? lesson.value : null,
  });

  /** The form as the session's defaults say (what is on screen now). */
  function fill() {
    const d = new URLSearchParams(on.session.embedDefaults());
    const views = (d.get('views') ?? '').split(',');
    for (const b of boxes('embed-views')) b.checked = views.includes(b.value);
    const strip = (d.get('strip') ?? '').split(',');
    for (const b of boxes('embed-strip')) b.checked = strip.includes(b.value);
    width.value = d.get('width') ?? '';
    height.value = d.get('height') ?? '';
    // The limits are the session's (it refuses a size outside them, naming them).
    Object.assign(width, { min: d.get('min_width') ?? '', max: d.get('max_width') ?? '' });
    Object.assign(height, { min: d.get('min_height') ?? '', max: d.get('max_height') ?? '' });
    syncPreset();
    paused.checked = false;
    t.value = '';
    lessonOn.checked = d.has('lesson');
    if (d.has('lesson')) lesson.value = d.get('lesson') ?? '1';
  }
  const syncPreset = () => {
    const wh = `${width.value}x${height.value}`;
    size.value = [...size.options].some((o) => o.value === wh) ? wh : '';
  };

  /** Asks the session for the snippet; shows it, the preview, or what is wrong. */
  function update() {
    lesson.disabled = !lessonOn.checked;
    syncPreset();
    let made;
    try {
      made = on.session.embed(window.location.href, choicesQuery(form()));
    } catch (e) {
      current = null;
      code.value = '';
      setText(fit, `Cannot embed this: ${messageOf(e)}`);
      fit.dataset.state = 'error';
      return null;
    }
    code.value = made.html;
    if (!current || current.src !== made.src) {
      setText(fit, 'Preview loading…');
      fit.dataset.state = 'loading';
      preview.src = made.src;
    }
    current = { src: made.src, width: made.width, height: made.height };
    place();
    return made;
  }
  /** The preview at the embed's size, scaled down to the column if wider. */
  function place() {
    if (!current) return;
    const room = builder.clientWidth || current.width;
    const scale = Math.min(1, room / current.width);
    preview.style.width = `${current.width}px`;
    preview.style.height = `${current.height}px`;
    preview.style.transform = scale < 1 ? `scale(${scale})` : '';
    box.style.width = `${Math.floor(current.width * scale)}px`;
    box.style.height = `${Math.floor(current.height * scale)}px`;
  }
  /** What the preview's own layout says of the panels that do not fit (Rust's words). */
  function readFit() {
    if (!current) return;
    /** @type {any} */
    let layout = null;
    try {
      layout = /** @type {any} */ (preview.contentWindow)?.flexarm?.lastLayout ?? null;
    } catch {
      layout = null;
    }
    if (!layout) return;
    const note = layout.hidden_note
      ? `At ${current.width} × ${current.height}: ${layout.hidden_note}`
      : `Every panel chosen fits at ${current.width} × ${current.height}.`;
    setText(fit, note);
    fit.dataset.state = layout.hidden_note ? 'hidden' : 'fits';
  }
  const later = () => {
    clearTimeout(timer);
    timer = window.setTimeout(update, SETTLE_MS);
  };

  // Poles and the z-plane are two pictures of the same eigenvalues: one or the other.
  for (const [a, b] of [['embed-v-poles', 'embed-v-zplane'], ['embed-v-zplane', 'embed-v-poles']]) {
    const box1 = /** @type {HTMLInputElement} */ (byId(a));
    box1.addEventListener('change', () => {
      if (box1.checked) /** @type {HTMLInputElement} */ (byId(b)).checked = false;
    });
  }
  size.addEventListener('change', () => {
    if (!size.value) return;
    const [w, h] = size.value.split('x');
    width.value = w;
    height.value = h;
    later();
  });
  for (const input of [width, height]) input.addEventListener('input', () => { syncPreset(); later(); });
  builder.addEventListener('change', later);
  t.addEventListener('input', later);
  lesson.addEventListener('input', later);
  new ResizeObserver(place).observe(builder);

  button.addEventListener('click', async () => {
    if (offlineFile()) {
      setText(byId('export-status'), 'An offline file cannot be embedded in a course page: an embed needs the page on a web server (bash scripts/serve.sh, or www/ on any host).');
      return;
    }
    const open = builder.hidden;
    builder.hidden = !open;
    button.setAttribute('aria-expanded', String(open));
    clearInterval(poll);
    if (!open) {
      preview.remove();
      preview.removeAttribute('src');
      current = null;
      return;
    }
    box.append(preview);
    fill();
    const made = update();
    poll = window.setInterval(readFit, FIT_POLL_MS);
    if (!made) return;
    code.focus();
    code.select();
    await copy(made.html, 'Embed snippet copied to the clipboard.', 'The embed snippet is selected below: select and copy it.');
  });
  byId('embed-copy').addEventListener('click', () => {
    code.select();
    copy(code.value, 'Embed snippet copied to the clipboard.', 'The embed snippet is selected: copy it with Ctrl+C (⌘C).');
  });

  /** Copies `text` where the browser allows, and says so. @param {string} text @param {string} done @param {string} otherwise */
  async function copy(text, done, otherwise) {
    try {
      if (!navigator.clipboard) throw new Error('no clipboard');
      await navigator.clipboard.writeText(text);
      say(done);
    } catch {
      say(otherwise);
    }
  }
}
