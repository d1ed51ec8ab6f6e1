// Loading the simulation: the wasm module built by wasm-pack into ../pkg.

import { offlineFile } from './files.js';

/** @typedef {typeof import('../pkg/flexarm.js')} Wasm */

/** The initialised module. @returns {Promise<Wasm>} */
export async function loadWasm() {
  const mod = await import('../pkg/flexarm.js');
  // Served, the module fetches its .wasm beside itself; an offline file carries the bytes.
  const carried = offlineFile()?.files.get('pkg/flexarm_bg.wasm');
  await mod.default(carried ? { module_or_path: carried } : undefined);
  performance.mark('flexarm:wasm-ready');
  return mod;
}

/** Bytes of the module's linear memory (it can only grow; the end-to-end tests watch it stay
 * flat). Initialising an initialised module returns its exports at once. @returns {Promise<number>} */
export async function wasmMemoryBytes() {
  const mod = await import('../pkg/flexarm.js');
  return (await mod.default()).memory.buffer.byteLength;
}
