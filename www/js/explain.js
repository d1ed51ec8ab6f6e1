// The explanation's "Try:" buttons: each names an action as `kind:args` (data-try), e.g.
// `preset:fig5.3`, `pf:paper`, `delta:0.04`, `map:off:0.05:2`, `compare:on`, or any settings as
// `set:key:value[:key:value…]` (`set:alpha1:0.5:alpha2:2`), or settings read together as a state
// string, `state:k=2&eps_ratio=1.33` (values that only fit each other, as k and m).

/**
 * The action a button's spec names (pure).
 * @param {string} spec
 * @returns {{ kind: 'preset', id: string } | { kind: 'set', key: string, value: string }
 *   | { kind: 'map', side: string, delta: number, alpha: number }
 *   | { kind: 'sets', pairs: [string, string][] } | { kind: 'state', query: string } | null}
 */
export function parseTry(spec) {
  const [kind, a, b, c] = String(spec).split(':');
  switch (kind) {
    case 'set': {
      const words = String(spec).split(':').slice(1);
      if (words.length === 0 || words.length % 2 !== 0 || words.some((w) => w === '')) return null;
      /** @type {[string, string][]} */
      const pairs = [];
      for (let i = 0; i < words.length; i += 2) pairs.push([words[i], words[i + 1]]);
      return { kind: 'sets', pairs };
    }
    case 'state':
      return a ? { kind: 'state', query: a } : null;
    case 'preset':
      return a ? { kind: 'preset', id: a } : null;
    case 'pf':
    case 'delta':
      return a ? { kind: 'set', key: kind, value: a } : null;
    case 'alpha':
      return a ? { kind: 'set', key: 'alpha', value: a } : null;
    case 'compare':
      return { kind: 'set', key: 'compare', value: a === 'off' ? '0' : '1' };
    case 'map': {
      const [delta, alpha] = [Number(b), Number(c)];
      return (a === 'off' || a === 'on') && delta > 0 && alpha > 0 ? { kind: 'map', side: a, delta, alpha } : null;
    }
    default:
      return null;
  }
}

/**
 * Wires every `button.try`. `after(stay)`: `stay` for a button marked `data-try-stay`, whose result
 * shows beside it (the sensors' table), not in the figure.
 * @param {{ preset: (id: string) => void, set: (key: string, value: string) => void,
 *   sets: (pairs: [string, string][]) => void, state: (query: string) => void,
 *   map: (side: string, delta: number, alpha: number) => void, after: (stay: boolean) => void }} on
 */
export function wireTryButtons(on) {
  for (const button of document.querySelectorAll('button.try')) {
    button.addEventListener('click', () => {
      const action = parseTry(/** @type {HTMLElement} */ (button).dataset.try ?? '');
      if (!action) return;
      if (action.kind === 'preset') on.preset(action.id);
      else if (action.kind === 'set') on.set(action.key, action.value);
      else if (action.kind === 'sets') on.sets(action.pairs);
      else if (action.kind === 'state') on.state(action.query);
      else on.map(action.side, action.delta, action.alpha);
      on.after(/** @type {HTMLElement} */ (button).dataset.tryStay !== undefined);
    });
  }
}
