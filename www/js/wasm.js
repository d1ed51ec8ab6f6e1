// Loading the simulation: the wasm module built by wasm-pack into ../pkg.

/** @typedef {typeof import('../pkg/flexarm.js')} Wasm */

/** The initialised module. @returns {Promise<Wasm>} */
export async function loadWasm() {
  const mod = await import('../pkg/flexarm.js');
  await mod.default();
  performance.mark('flexarm:wasm-ready');
  return mod;
}
