// Loading the simulation: the wasm module built by wasm-pack into ../pkg.

/** @typedef {typeof import('../pkg/flexarm.js')} Wasm */

/** The initialised module. @returns {Promise<Wasm>} */
export async function loadWasm() {
  const mod = await import('../pkg/flexarm.js');
  await mod.default();
  performance.mark('flexarm:wasm-ready');
  return mod;
}

/** Bytes of the module's linear memory (it can only grow; the end-to-end tests watch it stay
 * flat). Initialising an initialised module returns its exports at once. @returns {Promise<number>} */
export async function wasmMemoryBytes() {
  const mod = await import('../pkg/flexarm.js');
  return (await mod.default()).memory.buffer.byteLength;
}
