// The page's one mutable state, changed only through named actions. Everything about the
// simulation and what the figures show lives in the wasm session (its state string); this holds
// what the page itself decides: whether it plays, whether α1 and α2 move together, which drawing
// backend it got, whether the wasm can still be used.

/** @typedef {{ playing: boolean, dead: boolean, linkAlpha: boolean,
 *   backend: string, renderFailures: number }} PageState */

/** @type {PageState} */
export const initialState = Object.freeze({
  playing: true,
  dead: false,
  linkAlpha: true,
  backend: '',
  renderFailures: 0,
});

/**
 * `state` with `patch` applied, or `state` itself when the patch changes nothing.
 * @param {PageState} state
 * @param {Partial<PageState>} patch
 * @returns {PageState}
 */
function patched(state, patch) {
  for (const [k, v] of Object.entries(patch)) {
    if (/** @type {any} */ (state)[k] !== v) return Object.freeze({ ...state, ...patch });
  }
  return state;
}

/**
 * The next state after `action` (pure): the same object when nothing changed.
 * @param {PageState} state
 * @param {{ type: string, [k: string]: any }} action
 * @returns {PageState}
 */
export function reduce(state, action) {
  switch (action.type) {
    case 'play':
      return state.dead ? state : patched(state, { playing: true });
    case 'pause':
      return patched(state, { playing: false });
    case 'toggle-play':
      return state.dead ? state : patched(state, { playing: !state.playing });
    case 'crash':
      return patched(state, { dead: true, playing: false });
    case 'link-alpha':
      return patched(state, { linkAlpha: Boolean(action.value) });
    case 'renderer':
      return patched(state, { backend: String(action.backend), renderFailures: 0 });
    case 'render-failed':
      return patched(state, { renderFailures: state.renderFailures + 1 });
    case 'render-ok':
      return patched(state, { renderFailures: 0 });
    default:
      throw new Error(`unknown action '${action.type}'`);
  }
}

/**
 * A store: `get()` the state, `dispatch(action)` to change it, `subscribe(fn)` to hear of changes
 * (fn(next, previous)); returns an unsubscribe function.
 * @param {PageState} [initial]
 */
export function createStore(initial = initialState) {
  let state = initial;
  /** @type {Set<(next: PageState, previous: PageState) => void>} */
  const listeners = new Set();
  return {
    get: () => state,
    /** @param {{ type: string, [k: string]: any }} action */
    dispatch(action) {
      const previous = state;
      state = reduce(state, action);
      if (state !== previous) for (const fn of listeners) fn(state, previous);
      return state;
    },
    /** @param {(next: PageState, previous: PageState) => void} fn */
    subscribe(fn) {
      listeners.add(fn);
      return () => listeners.delete(fn);
    },
  };
}
