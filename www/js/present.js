// Presentation mode (`present=1`): the figure over the whole screen, the verdict in a corner, a
// small bar of controls, full screen where the browser allows. The session holds the setting and
// Rust's layout sizes the figure's text for the screen; this file switches the mode, wires the bar
// and shows the verdicts over the figure (also when two runs are compared, outside the mode).

import { byId, make, setText } from './dom.js';
import { momentLink } from './outputs.js';
import { writeUrl } from './url.js';

/**
 * @typedef {{ run: string, verdict: string, headline: string, detail: string, detail_short: string, settings: string }} RunLine
 * @param {{ set: (key: string, value: string) => void, step: (key: string, steps: number) => void,
 *   togglePlay: () => void, reset: () => void, textChoices: { value: string, label: string }[],
 *   momentQuery: () => string, pause: () => void }} on
 */
export function createPresent(on) {
  const body = document.body;
  const fullscreen = byId('present-fullscreen');
  const text = /** @type {HTMLSelectElement} */ (byId('present-text'));
  const pf = /** @type {HTMLInputElement} */ (byId('present-pf'));
  const verdicts = byId('figure-verdicts');
  // The bar is small: the choices' first words ("Large", not "Large (×1.25)").
  for (const c of on.textChoices) text.append(make('option', { value: c.value, text: c.label.split(' (')[0] }));
  const barVerdict = byId('present-verdict');
  /** Presentation mode was entered with full screen: leaving full screen leaves it too. */
  let withFullscreen = false;

  const canFullscreen = Boolean(document.fullscreenEnabled && document.documentElement.requestFullscreen);
  fullscreen.hidden = !canFullscreen;

  async function toggleFullscreen() {
    try {
      if (document.fullscreenElement) await document.exitFullscreen();
      else await document.documentElement.requestFullscreen();
    } catch {
      // Refused (an iframe without allowfullscreen, a browser setting): the mode works without it.
    }
  }

  function enter() {
    on.set('present', '1');
    if (canFullscreen && !document.fullscreenElement) {
      withFullscreen = true;
      toggleFullscreen();
    }
  }

  function leave() {
    withFullscreen = false;
    if (document.fullscreenElement) document.exitFullscreen().catch(() => {});
    on.set('present', '0');
  }

  byId('present-enter').addEventListener('click', enter);
  byId('present-leave').addEventListener('click', leave);
  byId('present-play').addEventListener('click', on.togglePlay);
  byId('present-reset').addEventListener('click', on.reset);
  byId('present-delta-down').addEventListener('click', () => on.step('delta', -1));
  byId('present-delta-up').addEventListener('click', () => on.step('delta', 1));
  fullscreen.addEventListener('click', () => {
    withFullscreen = false;
    toggleFullscreen();
  });
  text.addEventListener('change', () => on.set('text', text.value));
  // A link to this moment as shown: presentation mode, its text size, paused at this instant.
  // It goes to the clipboard where the browser allows, and to the address bar in any case.
  const link = byId('present-link');
  let linkSaid = 0;
  link.addEventListener('click', async () => {
    // A link to a moment is a link to a paused run: the run stops here first, so the address
    // (which names the moment while paused) says what the screen shows.
    on.pause();
    const query = on.momentQuery();
    writeUrl(query);
    // Said at once (a clipboard may wait on a permission), and again once it is copied.
    setText(link, 'In the address bar');
    window.clearTimeout(linkSaid);
    linkSaid = window.setTimeout(() => setText(link, 'Copy link'), 2500);
    try {
      await navigator.clipboard.writeText(momentLink(query));
      setText(link, 'Copied ✓');
    } catch {
      // Refused: the address bar holds it.
    }
  });
  pf.addEventListener('change', () => on.set('pf', pf.checked ? 'paper' : 'off'));
  document.addEventListener('fullscreenchange', () => {
    const full = Boolean(document.fullscreenElement);
    fullscreen.setAttribute('aria-pressed', String(full));
    setText(fullscreen, full ? 'Leave full screen' : 'Full screen');
    if (!full && withFullscreen && body.dataset.present === 'true') leave();
  });
  document.addEventListener('keydown', (ev) => {
    // Esc leaves the mode (in full screen the browser takes Esc itself: leaving full screen
    // entered with the mode leaves the mode too, above).
    if (ev.key === 'Escape' && body.dataset.present === 'true') leave();
  });

  /** The bar and the page follow the session's values. @param {(key: string) => { value: string, text: string } | undefined} value */
  function sync(value) {
    const present = value('present')?.value === '1';
    if (body.dataset.present !== String(present)) body.dataset.present = String(present);
    pf.checked = value('pf')?.value !== 'off';
    setText(byId('present-delta'), `δ = ${value('delta')?.text ?? '—'}`);
    const size = value('text')?.value ?? 'normal';
    if (text.value !== size) text.value = size;
  }

  /** The verdicts: in the bar in presentation mode (clear of the figure), over the figure when
   * two runs are compared. @param {RunLine[]} runs @param {{ color: string }[]} [series] the runs' colours */
  function render(runs, series = []) {
    const present = body.dataset.present === 'true';
    if (present) {
      barVerdict.dataset.verdict = runs[0].verdict;
      const key = runs.map((r, i) => `${r.run}|${r.headline}|${r.detail}|${series[i]?.color}`).join('\n');
      if (barVerdict.dataset.key !== key) {
        barVerdict.dataset.key = key;
        // One run: its word and sentence. Two: each word with its curves' colour, so the error
        // plots read without the key under the figure (hidden in this mode).
        barVerdict.replaceChildren(
          ...(runs.length > 1
            ? runs.flatMap((r, i) => [
              make('span', { class: 'run-swatch', style: `background:${series[i]?.color ?? 'currentColor'}`, 'aria-hidden': 'true' }),
              make('strong', { class: `verdict-${r.verdict.replace(' ', '-')}`, text: `${r.run}: ${r.headline}` }),
              ' ',
            ])
            // The whole sentence, or (a short screen: present.css) its first clause.
            : [make('strong', { text: runs[0].headline }), ' ', make('span', { class: 'verdict-long', text: runs[0].detail }),
              make('span', { class: 'verdict-short', text: runs[0].detail_short })]),
        );
        barVerdict.title = runs.map((r) => `${runs.length > 1 ? `${r.run}: ` : ''}${r.headline} ${r.detail}`).join('\n');
      }
    }
    const shown = runs.length > 1 && !present;
    verdicts.hidden = !shown;
    if (!shown) return;
    const key = runs.map((r) => `${r.run}|${r.verdict}|${r.headline}|${r.detail}|${r.settings}`).join('\n');
    if (verdicts.dataset.key === key) return;
    verdicts.dataset.key = key;
    verdicts.replaceChildren(
      ...runs.map((r) => {
        const chip = make('span', { class: 'figure-verdict' });
        chip.dataset.verdict = r.verdict;
        const head = make('span', { class: 'fv-head' });
        if (runs.length > 1) head.append(make('span', { class: 'fv-run', text: `run ${r.run}` }), ' ');
        head.append(make('strong', { text: r.headline }), ` · ${r.settings}`);
        chip.append(head, make('span', { class: 'fv-detail', text: r.detail }));
        return chip;
      }),
    );
  }

  return { sync, render };
}
