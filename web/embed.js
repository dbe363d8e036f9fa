// wavepool embedding module: `const demo = await mount(element, options)` puts an interactive
// water pool (and, unless `controls: false`, its controls) inside `element`. Everything lives
// in a shadow root, so the host page's CSS and ours never meet; nothing is put on `window`.
// The simulation and rendering are Rust (wavepool.js + wavepool_bg.wasm, next to this file).

import { paramTable, presetTable } from "./wavepool.js";
import { acquireContext, watchNear } from "./context-budget.js";
import { Demo } from "./demo.js";
import { assetUrl, inline, live, loadCore, setAssetLocation } from "./loader.js";
import { optionName, readAspect, readOptions } from "./options.js";
import { LANGUAGES, browserLanguage, chooseLanguage } from "./i18n.js";

export { setAssetLocation, browserLanguage };

/** The languages there are catalogues for, each with its name in its own words (i18n.js). */
export const languages = LANGUAGES;

/** The presets: named starting states, each parameter values and maybe a camera. */
export async function presets() {
  await loadCore();
  return presetTable();
}

/** The parameter table: name, label, group, unit, kind, min, max, step, default, help. */
export async function params() {
  await loadCore();
  return paramTable();
}

let inlineSheet = null; // the inline stylesheet, shared by every demo's shadow root
let instances = 0;

/**
 * Mounts a demo in `element`. Resolves to the demo's handle once the first frame is drawn
 * (with `lazy`, the default, that is once the element has come near the viewport); rejects
 * (after showing a readable message in the element) when no GPU backend works.
 */
export async function mount(element, options = {}) {
  if (!(element instanceof Element)) throw new TypeError("wavepool.mount: the first argument must be an element");
  const started = performance.now();
  const shadow = element.shadowRoot || element.attachShadow({ mode: "open" });
  shadow.replaceChildren();
  const fillsElement = element.clientHeight > 0;
  const root = document.createElement("div");
  root.className = "root" + (fillsElement ? " fill" : "");
  let style = [];
  if (inline) {
    // A constructed stylesheet: no <style> element, so a strict style-src allows it too.
    if (!inlineSheet) {
      inlineSheet = new CSSStyleSheet();
      inlineSheet.replaceSync(inline.css);
    }
    shadow.adoptedStyleSheets = [inlineSheet];
  } else {
    style = [document.createElement("link")];
    style[0].rel = "stylesheet";
    style[0].href = assetUrl("wavepool.css", new URL("./wavepool.css", import.meta.url));
  }
  const stage = document.createElement("div");
  stage.className = "stage";
  const message = document.createElement("div");
  message.className = "message";
  message.setAttribute("role", "alert");
  message.hidden = true;
  stage.append(message);
  root.append(stage);
  shadow.append(...style, root);
  const id = ++instances;

  const handle = new Demo(element, shadow, root, stage, message, id, started);
  handle._fills = fillsElement;
  handle._aspect = readAspect(options);
  if (!fillsElement) {
    // The pool's space at once, before the core loads: nothing below it moves when it starts.
    stage.style.aspectRatio = String(handle._aspect);
    handle._fitStage();
  }
  live.add(handle);
  pending.set(element, handle);
  try {
    // The language: its catalogue fetched while the core loads and the GPU starts (English
    // needs none: its words are the core's; until the core is here i18n.js has the status's).
    const language = chooseLanguage(options && options.lang, element);
    handle._pageLanguage = chooseLanguage(null, element);
    const words = (handle._wordsLoading = handle._loadWords(language));
    handle._status(handle.text("status-loading"));
    words.then((w) => w.tag !== "en" && !handle._core && !handle._dead && handle._status(w.page("status-loading")));
    await loadCore();
    const table = paramTable();
    const opts = readOptions(options, table);
    handle._table = table;
    handle._opts = opts;
    // A GPU context only when near the viewport (lazy) and one of the page's few is free.
    handle._eager = !opts.lazy;
    handle._unwatch = watchNear(element, (near) => handle._nearChanged(near));
    await acquireContext(handle);
    if (handle._dead) throw new Error("wavepool: the demo was destroyed before it started");
    await handle._start();
    // prefers-reduced-motion: start still (nothing falls, no waves) until the visitor presses
    // play, unless the page asked for `paused` itself.
    if (!("paused" in opts.params) && matchMedia("(prefers-reduced-motion: reduce)").matches) opts.params.paused = 1;
    handle._defaultCamera = handle._core.camera();
    // A preset's values first; the page's own options override them. The camera last, once the
    // scene it looks at is chosen (its ranges are the scene's: `scene=sea&preset=storm` put the
    // storm's camera in the pool's ranges before the sea was chosen); a preset's view only in
    // its own scene (`preset=calm&scene=sea` opens the sea on the sea's view).
    if (opts.preset) {
      for (const [name, value] of opts.preset.values) if (!(name in opts.params)) handle.set(name, value);
    }
    for (const [name, value] of Object.entries(opts.params)) handle.set(name, value);
    const presetScene = opts.preset?.values.find(([name]) => name === "scene")?.[1] ?? 0;
    const presetView = opts.preset?.camera && handle.get("scene") === presetScene ? opts.preset.camera : null;
    const camera = opts.camera || presetView;
    if (camera) handle._core.setCamera(...camera);
    // The bodies start where these values put them (a sphere without gravity under the water).
    handle._core.reset();
    // The pool's first picture shows rings and their caustics (start_drops), unless it starts
    // still (paused, or the visitor asked for reduced motion).
    if (!handle.get("paused")) handle._core.startDrops();
    if (opts.sketch) handle._core.setSketch(opts.sketch);
    handle._setWords(await words);
    handle._noticeReduced();
    // What "Reset" returns to: this page's own start, not the table's defaults.
    handle._startState = handle._saveState();
    handle._buildOverlay();
    if (opts.controls) handle._buildControls();
    handle._status(null);
    handle._run();
    await handle._firstFrame;
    return handle;
  } catch (error) {
    handle._fail(String(error && error.message ? error.message : error));
    throw error;
  } finally {
    if (pending.get(element) === handle) pending.delete(element);
  }
}

/** The demo being mounted in an element, until its mount() settles (for <wave-pool>'s removal). */
const pending = new WeakMap();

/**
 * `<wave-pool wave-speed="0.8" objects="duck"></wave-pool>`: a demo whose attributes are the
 * mount options and parameters. It mounts when connected to a document and frees its GPU
 * resources when removed, so pages that insert it later (slide decks, single-page sites) work.
 * Its `demo` property is the handle once `wavepool:ready` has fired (`wavepool:error` else).
 */
export class WavePoolElement extends HTMLElement {
  connectedCallback() {
    if (this._mounting) return; // moved within the page: keep running
    const generation = (this._generation = (this._generation || 0) + 1);
    const options = {};
    for (const { name, value } of this.attributes) {
      if (name === "style" || name === "class" || name === "id" || name.startsWith("data-") || name.startsWith("aria-")) continue;
      options[optionName(name)] = value;
    }
    this._mounting = mount(this, options).then(
      (demo) => {
        if (generation !== this._generation || !this.isConnected) {
          demo.destroy(); // removed while it was starting
          return;
        }
        this.demo = demo;
        this.dispatchEvent(new CustomEvent("wavepool:ready", { detail: demo }));
      },
      (error) => {
        if (generation !== this._generation) return;
        this.dispatchEvent(new CustomEvent("wavepool:error", { detail: String(error.message || error) }));
      },
    );
  }

  disconnectedCallback() {
    // A move (removed and put back in the same task) keeps the demo; a removal frees it.
    queueMicrotask(() => {
      if (this.isConnected || !this._mounting) return;
      this._generation++;
      const starting = pending.get(this); // still waiting to come into view, or starting
      if (starting) starting.destroy();
      if (this.demo) this.demo.destroy();
      this.demo = null;
      this._mounting = null;
    });
  }
}

if (window.customElements && !customElements.get("wave-pool")) customElements.define("wave-pool", WavePoolElement);

