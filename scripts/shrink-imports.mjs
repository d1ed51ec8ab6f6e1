// Shortens the page module's import names after wasm-pack (scripts/setup.sh runs it on www/pkg).
//
// wasm-bindgen names each of the ~550 functions the module imports from its JS glue
// `__wbg_<name>_<16 hex digits>`, under the module "./flexarm_bg.js": ~20 kB of names, a third of
// them hex digits gzip cannot compress (≈ 5 kB of the gzip -9 size). This renames every import
// of that module to a short key (`_0`, `_1`, … in base 36) and the module to `w`, in the wasm's
// import section and in the glue's import object, where each old key must occur exactly once —
// anything else stops the build with a message, never a half-renamed pair.
//
// Usage: node scripts/shrink-imports.mjs DIR   (DIR holds flexarm_bg.wasm and flexarm.js)

import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';

const GLUE_MODULE = './flexarm_bg.js';
const SHORT_MODULE = 'w';

/** @param {string} message */
function fail(message) {
  console.error(`shrink-imports: ${message}`);
  process.exit(1);
}

/** Reads an unsigned LEB128 at `at`: [value, next offset]. @param {Uint8Array} b @param {number} at */
function leb(b, at) {
  let value = 0;
  let shift = 0;
  for (;;) {
    const byte = b[at++];
    value += (byte & 0x7f) * 2 ** shift;
    shift += 7;
    if (byte < 0x80) return [value, at];
  }
}

/** @param {number} v */
function encodeLeb(v) {
  const out = [];
  do {
    let byte = v % 128;
    v = Math.floor(v / 128);
    if (v > 0) byte |= 0x80;
    out.push(byte);
  } while (v > 0);
  return out;
}

/** @param {string} s */
function name(s) {
  const bytes = [...new TextEncoder().encode(s)];
  return [...encodeLeb(bytes.length), ...bytes];
}

/** The length of an import descriptor (kind byte and what follows). @param {Uint8Array} b @param {number} at */
function descriptorEnd(b, at) {
  const kind = b[at++];
  const limits = (/** @type {number} */ p) => {
    const flags = b[p++];
    [, p] = leb(b, p);
    if (flags & 1) [, p] = leb(b, p);
    return p;
  };
  switch (kind) {
    case 0x00: return leb(b, at)[1]; // function: type index
    case 0x01: return limits(at + 1); // table: reference type, limits
    case 0x02: return limits(at); // memory: limits
    case 0x03: return at + 2; // global: value type, mutability
    case 0x04: return leb(b, at + 1)[1]; // tag: attribute, type index
    default: return fail(`unknown import kind ${kind}`);
  }
}

const dir = process.argv[2] ?? fail('usage: node scripts/shrink-imports.mjs DIR');
const wasmPath = join(dir, 'flexarm_bg.wasm');
const jsPath = join(dir, 'flexarm.js');
const wasm = readFileSync(wasmPath);
let js = readFileSync(jsPath, 'utf8');
if (wasm.readUInt32LE(0) !== 0x6d736100) fail(`${wasmPath} is not a wasm module`);

const decoder = new TextDecoder();
/** @type {number[]} */
const out = [...wasm.subarray(0, 8)];
let at = 8;
let renamed = 0;
while (at < wasm.length) {
  const id = wasm[at];
  const [size, body] = leb(wasm, at + 1);
  const end = body + size;
  if (id !== 2) {
    for (let i = at; i < end; i++) out.push(wasm[i]);
    at = end;
    continue;
  }
  const [count, first] = leb(wasm, body);
  /** @type {number[]} */
  const section = [...encodeLeb(count)];
  let p = first;
  for (let i = 0; i < count; i++) {
    const [moduleLength, m] = leb(wasm, p);
    const module = decoder.decode(wasm.subarray(m, m + moduleLength));
    const [fieldLength, f] = leb(wasm, m + moduleLength);
    const field = decoder.decode(wasm.subarray(f, f + fieldLength));
    const descriptor = f + fieldLength;
    const next = descriptorEnd(wasm, descriptor);
    if (module === GLUE_MODULE) {
      const short = `_${(renamed++).toString(36)}`;
      // The key of the glue's import object: `        __wbg_x_0123456789abcdef: function(…`.
      const key = new RegExp(`(^|[\\s{,])${field.replace(/[$]/g, '\\$')}(?=\\s*:)`, 'gm');
      const hits = js.match(key)?.length ?? 0;
      if (hits !== 1) fail(`the import ${field} is a key ${hits} times in ${jsPath}, not once`);
      js = js.replace(key, `$1${short}`);
      section.push(...name(SHORT_MODULE), ...name(short));
    } else {
      section.push(...name(module), ...name(field));
    }
    for (let j = descriptor; j < next; j++) section.push(wasm[j]);
    p = next;
  }
  if (p !== end) fail('the import section did not parse to its end');
  out.push(2, ...encodeLeb(section.length), ...section);
  at = end;
}

const moduleKey = `"${GLUE_MODULE}": import0`;
if (js.split(moduleKey).length !== 2) fail(`${jsPath} does not name its import object once as ${moduleKey}`);
js = js.replace(moduleKey, `"${SHORT_MODULE}": import0`);
writeFileSync(wasmPath, Uint8Array.from(out));
writeFileSync(jsPath, js);
console.log(`shrink-imports: ${renamed} imports renamed in ${wasmPath} and ${jsPath}`);
