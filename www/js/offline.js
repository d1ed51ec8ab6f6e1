// The offline file's start-up: a classic script that src/offline/mod.rs puts at the end of the
// file's body (the served page never loads it). From file:// a browser fetches nothing, so the
// file carries its files inside: this unpacks them (#flexarm-files: base64 of a gzip-compressed
// archive), gives each module a blob URL under the name its importers use (an import map:
// `@flexarm/js/dom.js` → blob:…), points the help links at the help page it carries, keeps the
// other files and the file's start (#flexarm-start) for the page (`window.flexarmOffline`, read
// by js/files.js), and starts the page's main module.
(() => {
  /** Says on the loading screen why the file did not start. @param {string} text */
  const fail = (text) => {
    const label = document.getElementById('loading-text');
    if (label) label.textContent = text;
    document.querySelector('#loading .spinner')?.remove();
    console.error(text);
  };

  /** The archive's files by path. @param {Uint8Array} archive */
  const read = (archive) => {
    const headerLength = new DataView(archive.buffer, archive.byteOffset).getUint32(0, true);
    /** @type {[string, number][]} */
    const header = JSON.parse(new TextDecoder().decode(archive.subarray(4, 4 + headerLength)));
    /** @type {Map<string, Uint8Array>} */
    const files = new Map();
    let at = 4 + headerLength;
    for (const [path, length] of header) {
      files.set(path, archive.subarray(at, at + length));
      at += length;
    }
    return files;
  };

  const unpack = async () => {
    const holder = document.getElementById('flexarm-files');
    const startText = document.getElementById('flexarm-start')?.textContent;
    if (!holder || !startText || !holder.dataset.main) throw new Error('the file is incomplete (its files or its start are missing)');
    if (typeof DecompressionStream !== 'function') {
      throw new Error('this browser cannot unpack it (no DecompressionStream): open it in a current Chromium, Firefox, Edge or Safari');
    }
    const packed = Uint8Array.from(atob((holder.textContent ?? '').trim()), (c) => c.charCodeAt(0));
    const stream = new Blob([packed]).stream().pipeThrough(new DecompressionStream('gzip'));
    const files = read(new Uint8Array(await new Response(stream).arrayBuffer()));
    return { files, start: JSON.parse(startText), main: holder.dataset.main, packedBytes: packed.length };
  };

  unpack()
    .then(({ files, start, main, packedBytes }) => {
      /** @type {Map<string, string>} */
      const urls = new Map();
      /** A blob URL for a carried file. @param {string} path @param {string} type */
      const urlOf = (path, type) => {
        let url = urls.get(path);
        if (url === undefined) {
          url = URL.createObjectURL(new Blob([/** @type {Uint8Array<ArrayBuffer>} */ (files.get(path))], { type }));
          urls.set(path, url);
        }
        return url;
      };
      /** @type {Record<string, string>} */
      const imports = {};
      for (const path of files.keys()) if (path.endsWith('.js')) imports[`@flexarm/${path}`] = urlOf(path, 'text/javascript');
      const map = document.createElement('script');
      map.type = 'importmap';
      map.textContent = JSON.stringify({ imports });
      document.head.append(map);
      // The help page travels too; it opens beside the simulation, which keeps its state.
      if (files.has('help.html')) {
        for (const a of document.querySelectorAll('a[href^="help.html"]')) {
          const link = /** @type {HTMLAnchorElement} */ (a);
          link.href = urlOf('help.html', 'text/html') + (link.getAttribute('href') ?? '').slice('help.html'.length);
          link.target = '_blank';
        }
      }
      /** @type {any} */ (window).flexarmOffline = { files, start, packedBytes };
      return import(main);
    })
    .catch((e) => fail(`This offline file could not start: ${e instanceof Error ? e.message : String(e)}.`));
})();
