// Loads the core once per page: wavepool.js and wavepool_bg.wasm next to this file, or with the
// single-file build the inline module; tells every mounted demo when the core panics.

import init from "./wavepool.js";

let ready = null; // one instantiation of the wasm module for every demo on the page
export const live = new Set(); // mounted demos, told when the wasm module panics

// The single-file build (scripts/standalone.py) declares WAVEPOOL_INLINE = { css, wasm, picture,
// locales, fluent } ahead of this code in the same module: the stylesheet's text, the wasm
// module (gzip then base 85 in the alphabet it carries, its gzip length in wasmBytes), the
// no-GPU picture (a data: URL), the message catalogues but English's and the Fluent runtime
// (each [base 85 of gzip, gzip length]). Otherwise they are files next to this one.
// eslint-disable-next-line no-undef
export const inline = typeof WAVEPOOL_INLINE === "undefined" ? null : WAVEPOOL_INLINE;
let assetBase = null; // setAssetLocation()'s folder (null: the files are next to this module)
let wasmMemory = null; // the module's linear memory (for stats().wasmMemoryBytes)
/** Linear memory made available at load: one demo at the defaults uses 9.7 MB. */
const START_MEMORY_BYTES = 16 * 1024 * 1024;

/** Bytes the single file carries packed (`length` bytes of gzip, written in base 85: 5 digits,
 * most significant first, per 4 bytes big-endian): decoded, then gunzipped by the browser. */
export async function inlineBytes(text, length) {
  const digit = new Uint8Array(128);
  for (let i = 0; i < inline.alphabet.length; i++) digit[inline.alphabet.charCodeAt(i)] = i;
  const packed = new Uint8Array((text.length / 5) * 4);
  for (let i = 0, o = 0; i < text.length; i += 5, o += 4) {
    let n = 0;
    for (let j = 0; j < 5; j++) n = n * 85 + digit[text.charCodeAt(i + j)];
    packed[o] = n >>> 24;
    packed[o + 1] = (n >>> 16) & 255;
    packed[o + 2] = (n >>> 8) & 255;
    packed[o + 3] = n & 255;
  }
  const stream = new Blob([packed.subarray(0, length)]).stream().pipeThrough(new DecompressionStream("gzip"));
  return new Response(stream).arrayBuffer();
}

/** Where the demo's files are: a folder's URL (see embed.d.ts); before the core loads. */
export function setAssetLocation(url) {
  if (ready) console.warn("wavepool: setAssetLocation() after the core has loaded applies to pictures and links only");
  assetBase = new URL(String(url), document.baseURI);
  if (!assetBase.pathname.endsWith("/")) assetBase.pathname += "/";
}

/** A file of the demo's own: at setAssetLocation()'s folder, else `local` (next to this module,
 * written as `new URL("./name", import.meta.url)` where it is used, so bundlers copy the file). */
export function assetUrl(name, local) {
  return assetBase ? new URL(name, assetBase).href : local.href;
}

/** The demo's own page `name` (index.html, embed.html): next to the assets; the single file is its own. */
export function demoPage(name) {
  // (Not `new URL("./index.html", import.meta.url)` written out: a bundler would look for the
  // page in the package, which carries none.)
  return inline ? location.href.split(/[?#]/)[0] : assetUrl(name, new URL(name, import.meta.url));
}

export function loadCore() {
  if (!ready) {
    const located = assetBase ? { module_or_path: new URL("wavepool_bg.wasm", assetBase) } : undefined;
    const module = inline ? inlineBytes(inline.wasm, inline.wasmBytes).then((bytes) => ({ module_or_path: bytes })) : Promise.resolve(located);
    ready = module.then((source) => init(source)).then(
      (exports) => {
        wasmMemory = exports.memory;
        // Grow the memory to what a demo needs before any demo code runs, once, instead of
        // while the first demo is being created: WebKit (JavaScriptCore) has stopped a demo
        // with "Out of bounds memory access" in its first calls after such growth (2 of ~20
        // loads here).
        const pages = Math.ceil((START_MEMORY_BYTES - wasmMemory.buffer.byteLength) / 65536);
        if (pages > 0) wasmMemory.grow(pages);
        window.addEventListener("wavepool:panic", (event) => {
          for (const demo of live) demo._fail(demo.text("error-crashed", { reason: event.detail }));
        });
        // Printing: a GPU canvas prints blank or not at all, so each demo puts a still of its
        // current frame in its place until the print is done.
        window.addEventListener("beforeprint", () => live.forEach((demo) => demo._printShot()));
        window.addEventListener("afterprint", () => live.forEach((demo) => demo._printShot(false)));
      },
      (error) => {
        throw new Error(loadFailure(error));
      },
    );
  }
  return ready;
}

/** Bytes of the core's linear memory (null before it loaded). */
export function memoryBytes() {
  return wasmMemory ? wasmMemory.buffer.byteLength : null;
}

/** Why the WebAssembly module did not load, in words a page author can act on. */
function loadFailure(error) {
  const text = String((error && error.message) || error);
  if (/Content.Security.Policy|CSP|unsafe-eval|wasm-eval/i.test(text)) {
    return (
      "This page's Content-Security-Policy does not let it run WebAssembly: its script-src " +
      "directive needs 'wasm-unsafe-eval' (for example script-src 'self' 'wasm-unsafe-eval'). " +
      `Details: ${text}`
    );
  }
  return `The water demo could not load its WebAssembly module (wavepool_bg.wasm next to embed.js): ${text}`;
}

