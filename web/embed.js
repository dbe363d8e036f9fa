// wavepool embedding module: `const demo = await mount(element, options)` puts an interactive
// water pool (and, unless `controls: false`, its controls) inside `element`. Everything lives
// in a shadow root, so the host page's CSS and ours never meet; nothing is put on `window`.
// The simulation and rendering are Rust (wavepool.js + wavepool_bg.wasm, next to this file).

import init, { WebDemo, fresnelCurve, optionTable, paramTable, presetTable } from "./wavepool.js";
import { acquireContext, contextsHeld, releaseContext, watchNear } from "./context-budget.js";
import { FresnelPlot } from "./fresnel-plot.js";

let ready = null; // one instantiation of the wasm module for every demo on the page
const live = new Set(); // mounted demos, told when the wasm module panics

// The single-file build (scripts/standalone.py) declares WAVEPOOL_INLINE = { css, wasm, picture }
// ahead of this code in the same module: the stylesheet's text, the wasm module (gzip then
// base 85 in the alphabet it carries, its gzip length in wasmBytes) and the no-GPU picture (a data: URL). Otherwise they are files next to this one.
// eslint-disable-next-line no-undef
const inline = typeof WAVEPOOL_INLINE === "undefined" ? null : WAVEPOOL_INLINE;
let inlineSheet = null; // the inline stylesheet, shared by every demo's shadow root
let wasmMemory = null; // the module's linear memory (for stats().wasmMemoryBytes)
/** Linear memory made available at load: one demo at the defaults uses 9.7 MB. */
const START_MEMORY_BYTES = 16 * 1024 * 1024;

/** The inline wasm module's bytes: base 85 decoded (5 digits, most significant first, per
 * 4 bytes big-endian), then gunzipped by the browser. */
async function inlineWasm() {
  const digit = new Uint8Array(128);
  for (let i = 0; i < inline.alphabet.length; i++) digit[inline.alphabet.charCodeAt(i)] = i;
  const text = inline.wasm;
  const packed = new Uint8Array((text.length / 5) * 4);
  for (let i = 0, o = 0; i < text.length; i += 5, o += 4) {
    let n = 0;
    for (let j = 0; j < 5; j++) n = n * 85 + digit[text.charCodeAt(i + j)];
    packed[o] = n >>> 24;
    packed[o + 1] = (n >>> 16) & 255;
    packed[o + 2] = (n >>> 8) & 255;
    packed[o + 3] = n & 255;
  }
  const stream = new Blob([packed.subarray(0, inline.wasmBytes)]).stream().pipeThrough(new DecompressionStream("gzip"));
  return new Response(stream).arrayBuffer();
}

function loadCore() {
  if (!ready) {
    const module = inline ? inlineWasm().then((bytes) => ({ module_or_path: bytes })) : Promise.resolve(undefined);
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
          for (const demo of live) demo._fail(`The water demo crashed: ${event.detail}`);
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

/** Options understood by mount(), with defaults. Parameter names from `params()` are accepted too. */
export const DEFAULT_OPTIONS = Object.freeze({
  backend: "auto", // "auto" | "webgpu" | "webgl2"
  float: "auto", // "none": simulate on the CPU and keep 8-bit caustics, as without float render targets
  // meshSize, causticsSize: ranges and defaults from the core's optionTable()
  controls: true, // show the controls under the canvas
  maxPixelRatio: 2, // cap on devicePixelRatio for the canvas's backing store
  maxPixels: 1920 * 1080, // cap on the canvas's backing pixels (width * height)
  aspect: 4 / 3, // width / height when the element has no height of its own
  maxFps: 0, // cap on drawn frames per second (1-240; 0: as many as the browser and GPU give)
  camera: null, // "yaw,pitch,distance" (degrees, degrees, m) to start from; null: the default view
  preset: null, // a named starting state from presets(): its values, then the page's own options
  lazy: true, // start when scrolled near the viewport (false: at once); see context-budget.js
});

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

function warn(message) {
  console.warn(`wavepool: ${message}`);
}

function clampNumber(name, value, min, max, fallback) {
  const v = Number(value);
  if (!Number.isFinite(v)) {
    warn(`option ${name} = ${value} is not a number; using ${fallback}`);
    return fallback;
  }
  if (v < min || v > max) {
    const c = Math.min(max, Math.max(min, v));
    warn(`option ${name} = ${v} is outside [${min}, ${max}]; using ${c}`);
    return c;
  }
  return v;
}

// Splits user options into demo options and parameter values, clamping and warning.
function readOptions(options, table) {
  const out = { ...DEFAULT_OPTIONS, params: {} };
  const created = new Map(optionTable().map((o) => [o.name, o]));
  for (const o of created.values()) out[o.name] = o.default;
  const names = new Set(table.map((p) => p.name));
  for (const [key, value] of Object.entries(options || {})) {
    if (key === "params" && value && typeof value === "object") {
      Object.assign(out.params, value);
    } else if (names.has(key)) {
      out.params[key] = value;
    } else if (key === "backend") {
      const b = String(value).toLowerCase();
      if (["auto", "webgpu", "webgl2"].includes(b)) out.backend = b;
      else warn(`backend "${value}" is not auto, webgpu or webgl2; using auto`);
    } else if (key === "float") {
      const f = String(value).toLowerCase();
      if (["auto", "none"].includes(f)) out.float = f;
      else warn(`float "${value}" is not auto or none; using auto`);
    } else if (created.has(key)) {
      const o = created.get(key);
      out[key] = Math.round(clampNumber(key, value, o.min, o.max, o.default));
    } else if (key === "controls" || key === "lazy") {
      out[key] = !(value === false || value === 0 || value === "0" || value === "false");
    } else if (key === "maxPixelRatio") {
      out.maxPixelRatio = clampNumber(key, value, 0.25, 4, DEFAULT_OPTIONS.maxPixelRatio);
    } else if (key === "maxPixels") {
      out.maxPixels = clampNumber(key, value, 64 * 64, 8192 * 8192, DEFAULT_OPTIONS.maxPixels);
    } else if (key === "maxFps") {
      out.maxFps = Number(value) === 0 ? 0 : clampNumber(key, value, 1, 240, DEFAULT_OPTIONS.maxFps);
    } else if (key === "preset") {
      const preset = presetTable().find((p) => p.name === String(value).toLowerCase());
      if (preset) out.preset = preset;
      else warn(`preset "${value}" is not one of ${presetTable().map((p) => p.name).join(", ")}; ignored`);
    } else if (key === "camera") {
      const v = (Array.isArray(value) ? value : String(value).split(",")).map(Number);
      if (v.length === 3 && v.every(Number.isFinite)) out.camera = v;
      else warn(`camera "${value}" is not "yaw,pitch,distance" (three numbers); using the default view`);
    } else if (key === "aspect") {
      out.aspect = clampNumber(key, value, 0.25, 4, DEFAULT_OPTIONS.aspect);
    } else {
      warn(`unknown option "${key}" ignored; options: ${[...Object.keys(DEFAULT_OPTIONS), ...created.keys()].join(", ")}, ` +
        `and the parameters ${[...names].join(", ")}`);
    }
  }
  return out;
}

// Turns "true"/"false"/"1.5" from a URL or attribute, or a choice's name ("duck" for
// objects), into a number for set(). `spec`: the parameter's table entry, if known.
function toNumber(value, spec) {
  if (spec && spec.kind === "choice" && typeof value === "string") {
    const i = spec.choiceNames.indexOf(value.toLowerCase());
    if (i >= 0) return spec.choices[i];
  }
  if (value === true || value === "true" || value === "on") return 1;
  if (value === false || value === "false" || value === "off") return 0;
  return Number(value);
}

function formatValue(p, v) {
  if (p.kind === "toggle") return v >= 0.5 ? "on" : "off";
  if (p.kind === "choice") {
    const i = p.choices.indexOf(v);
    if (i >= 0 && p.choiceNames[i]) return p.choiceNames[i];
    return `${v}${p.unit ? ` ${p.unit}` : ""}`;
  }
  const decimals = Math.max(0, -Math.floor(Math.log10(p.step) + 1e-9));
  return `${v.toFixed(decimals)}${p.unit ? (p.unit === "°" ? "°" : ` ${p.unit}`) : ""}`;
}

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
    style[0].href = new URL("./wavepool.css", import.meta.url).href;
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
  live.add(handle);
  pending.set(element, handle);
  try {
    handle._status("Loading the water…");
    await loadCore();
    const table = paramTable();
    const opts = readOptions(options, table);
    handle._table = table;
    handle._opts = opts;
    if (!fillsElement) {
      stage.style.aspectRatio = String(opts.aspect);
      handle._fitStage();
    }
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
    // A preset's values first; the page's own options override them.
    if (opts.preset) {
      for (const [name, value] of opts.preset.values) if (!(name in opts.params)) handle.set(name, value);
      if (opts.preset.camera && !opts.camera) handle._core.setCamera(...opts.preset.camera);
    }
    for (const [name, value] of Object.entries(opts.params)) handle.set(name, value);
    if (opts.camera) handle._core.setCamera(...opts.camera);
    // What "Reset" returns to: this page's own start, not the table's defaults.
    handle._startState = { params: table.map((p) => [p.name, handle.get(p.name)]), camera: handle._core.camera() };
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

/** Paths of the overlay buttons' icons, on a 24 x 24 grid. */
const ICONS = {
  play: "M8 5v14l11-7z",
  pause: "M6 5h4v14H6zm8 0h4v14h-4z",
  fullscreen: "M4 4h6v2H6v4H4zm10 0h6v6h-2V6h-4zM4 14h2v4h4v2H4zm14 0h2v6h-6v-2h4z",
};

/** An inline SVG icon (no font glyph that a system may lack, no style attribute). */
function icon(path) {
  const ns = "http://www.w3.org/2000/svg";
  const svg = document.createElementNS(ns, "svg");
  svg.setAttribute("viewBox", "0 0 24 24");
  svg.setAttribute("aria-hidden", "true");
  const shape = document.createElementNS(ns, "path");
  shape.setAttribute("d", path);
  shape.setAttribute("fill", "currentColor");
  svg.append(shape);
  return svg;
}

/** Below this width (CSS px) the controls start folded, so the pool comes first on a phone. */
const NARROW_PX = 600;
/** Least height (CSS px) the pool keeps when fitted into the first screen. */
const MIN_FIT_PX = 180;

/** Frame statistics are over this window up to now (ms). */
const STATS_WINDOW_MS = 2000;

/**
 * Drawn frames over the last STATS_WINDOW_MS up to `now` (ms): `fps` (frames drawn in the
 * window / its length; the window starts no earlier than the loop did), `frameMs` (median
 * interval between them) and `longestFrameMs` (longest interval, counting the wait since
 * the last frame, so a freeze shows while it lasts). `times`: drawn frames' times, oldest first.
 */
function frameStats(times, since, now) {
  const start = Math.max(now - STATS_WINDOW_MS, since ?? now);
  const inWindow = times.filter((t) => t > start && t <= now);
  const span = now - start;
  const intervals = [];
  for (let i = 1; i < times.length; i++) if (times[i] > start) intervals.push(times[i] - times[i - 1]);
  const sorted = [...intervals].sort((a, b) => a - b);
  const median = sorted.length ? sorted[Math.floor((sorted.length - 1) / 2)] : 0;
  const waiting = times.length ? now - times[times.length - 1] : 0;
  return {
    fps: span > 0 ? (inWindow.length * 1000) / span : 0,
    frameMs: median,
    longestFrameMs: Math.max(waiting, ...intervals, 0),
  };
}

/** The message shown when no backend started: what was tried, each one's reason, what to do. */
function backendFailure(backend, failures) {
  const name = { webgpu: "WebGPU", webgl2: "WebGL2" }[backend];
  const reasons = failures.map((f) => `• ${f}`).join("\n");
  if (name) {
    return (
      `This page asked for ${name} only (backend=${backend}), and this browser could not start it:\n` +
      `${reasons}\nRemove backend=${backend} from the address or the options (or set backend=auto) ` +
      "to let the demo choose a backend this browser has."
    );
  }
  return (
    "This browser could not start the water demo: neither WebGPU nor WebGL2 worked " +
    `(graphics acceleration may be turned off in its settings).\n${reasons}`
  );
}

class Demo {
  constructor(element, shadow, root, stage, message, id, started) {
    this._element = element;
    this._shadow = shadow;
    this._root = root;
    this._stage = stage;
    this._message = message;
    this._id = id;
    this._started = started;
    this._core = null;
    this._canvas = null;
    this._frame = 0; // requestAnimationFrame id
    this._last = 0; // time of the last frame (ms)
    this._frames = []; // times of the frames drawn in the last 2 s (ms), for stats()
    this._simTimes = []; // the simulated time (s) after each of those frames
    this._runningSince = null; // when the frame loop last started drawing (ms)
    this._looping = false; // whether the frame loop runs (false once stopped, until started again)
    this._userPaused = false;
    this._visible = true;
    this._onScreen = true;
    this._dead = false;
    this._restarts = 0; // devices recreated after a loss
    this._lastRestart = -Infinity;
    this._controls = new Map(); // parameter name -> update function
    this._dependants = new Map(); // parameter name -> update functions of controls shown by its value
    this._pointers = new Map(); // pointerId -> {x, y}
    this._pinch = 0; // distance between two touching pointers (px), 0 when not pinching
    this._firstFrameMs = null;
    this._firstFrame = new Promise((resolve, reject) => {
      this._firstFrameResolve = resolve;
      this._firstFrameReject = reject;
    });
    this._firstFrame.catch(() => {});
    this._cleanups = [];
    // The page's context budget (context-budget.js).
    this._near = false; // within its margin of the viewport
    this._leftAt = 0; // when it last stopped being near (ms)
    this._eager = false; // asks for a context even while far (lazy: false)
    this._unwatch = null; // stops watching nearness
    this._suspended = false; // gave its context up; shows `_still`, values in `_saved`
    this._saved = null; // { params: [[name, value]], camera } while suspended
    this._still = null; // the 2D canvas showing the last frame while suspended
    this._waking = false;
    this._plot = null; // the Fresnel plot in the Optics group (fresnel-plot.js), with the controls
    this._plotAt = -Infinity; // when its view mark last moved (ms)
    this._costs = null; // the render modes' costs, under the render_mode control
    this._costsAt = -Infinity; // when they were last written (ms)
    this._modeIntervals = [[], [], []]; // recent intervals between drawn frames per render mode (ms)
  }

  // ---- set-up -------------------------------------------------------------------------

  async _start() {
    const forced = this._opts.backend !== "auto";
    const order = forced ? [this._opts.backend] : ["webgpu", "webgl2"];
    const failures = [];
    for (const backend of order) {
      if (backend === "webgpu" && !navigator.gpu) {
        failures.push("WebGPU: this browser does not offer it (navigator.gpu is missing)");
        continue;
      }
      const canvas = this._makeCanvas();
      // The grid starts at the sim_size parameter's value (resampled if it changes later).
      const simSize = Number(this._opts.params.sim_size ?? this._table.find((p) => p.name === "sim_size").default);
      const o = this._opts;
      let core;
      try {
        core = await WebDemo.create(canvas, backend, simSize, o.meshSize, o.causticsSize, o.float !== "none");
      } catch (error) {
        canvas.remove();
        failures.push(`${backend === "webgpu" ? "WebGPU" : "WebGL2"}: ${error.message || error}`);
        continue;
      }
      [this._core, this._canvas] = [core, canvas];
      if (this._dead) {
        this._detachCore(); // destroyed while the context was being made
        throw new Error("wavepool: the demo was destroyed while it started");
      }
      this._element.dataset.backend = backend;
      this._listen();
      return;
    }
    throw new Error(backendFailure(this._opts.backend, failures));
  }

  // Without a height of its own the pool takes the element's width at its aspect ratio, but
  // no more height than the first screen has below the element's top (the whole viewport when
  // it starts further down), so a visitor sees all of it; narrower then, centred.
  _fitStage() {
    const fit = () => {
      const top = this._element.getBoundingClientRect().top + window.scrollY;
      const below = top < window.innerHeight ? window.innerHeight - top - 8 : window.innerHeight;
      const height = Math.max(MIN_FIT_PX, Math.min(window.innerHeight, below));
      this._stage.style.maxWidth = `${Math.floor(height * this._opts.aspect)}px`;
    };
    fit();
    this._fit = fit; // refitted on window resizes, from _listen (again after a device restart)
  }

  _makeCanvas() {
    const canvas = document.createElement("canvas");
    canvas.tabIndex = 0;
    canvas.setAttribute("role", "application");
    canvas.setAttribute(
      "aria-label",
      "Water pool. Drag on the water to make ripples, drag the sphere to move it, drag elsewhere " +
        "to turn the camera. Keys: arrows turn, + and - zoom, Enter makes a drop in the middle, space " +
        "pauses, G gravity, L light.",
    );
    this._stage.prepend(canvas);
    this._sizeCanvas(canvas);
    return canvas;
  }

  // Backing-store size from the displayed size, devicePixelRatio and the caps.
  _sizeCanvas(canvas) {
    const rect = canvas.getBoundingClientRect();
    const ratio = Math.min(window.devicePixelRatio || 1, this._opts.maxPixelRatio);
    let w = Math.max(1, Math.round(rect.width * ratio));
    let h = Math.max(1, Math.round(rect.height * ratio));
    const scale = Math.min(1, Math.sqrt(this._opts.maxPixels / (w * h)));
    w = Math.max(1, Math.floor(w * scale));
    h = Math.max(1, Math.floor(h * scale));
    if (canvas.width !== w) canvas.width = w;
    if (canvas.height !== h) canvas.height = h;
  }

  _on(target, type, listener, options) {
    target.addEventListener(type, listener, options);
    this._cleanups.push(() => target.removeEventListener(type, listener, options));
  }

  _listen() {
    if (this._fit) this._on(window, "resize", this._fit);
    const canvas = this._canvas;
    const resize = new ResizeObserver(() => this._sizeCanvas(canvas));
    resize.observe(canvas);
    const onScreen = new IntersectionObserver((entries) => {
      this._onScreen = entries[entries.length - 1].isIntersecting;
      this._run();
    });
    onScreen.observe(this._element);
    this._cleanups.push(() => resize.disconnect(), () => onScreen.disconnect());
    this._on(document, "visibilitychange", () => {
      this._visible = !document.hidden;
      this._run();
    });

    // Pointer position in backing pixels.
    const at = (e) => {
      const r = canvas.getBoundingClientRect();
      return [((e.clientX - r.left) * canvas.width) / r.width, ((e.clientY - r.top) * canvas.height) / r.height];
    };
    const spread = () => {
      const [a, b] = [...this._pointers.values()];
      return Math.hypot(a[0] - b[0], a[1] - b[1]);
    };
    this._on(canvas, "pointerdown", (e) => {
      if (e.button !== 0 && e.pointerType === "mouse") return;
      canvas.focus({ preventScroll: true });
      canvas.setPointerCapture(e.pointerId);
      this._pointers.set(e.pointerId, at(e));
      if (this._pointers.size === 1) {
        this._core.pointerDown(...at(e));
      } else if (this._pointers.size === 2) {
        this._core.pointerUp(); // a second finger turns the gesture into a pinch
        this._pinch = spread();
      }
      e.preventDefault();
    });
    this._on(canvas, "pointermove", (e) => {
      if (!this._pointers.has(e.pointerId)) {
        // Hovering: the split view's divider shows it can be dragged.
        if (this._core) canvas.style.cursor = this._core.overDivider(...at(e)) ? "ew-resize" : "";
        return;
      }
      this._pointers.set(e.pointerId, at(e));
      if (this._pointers.size === 1) {
        this._core.pointerMove(...at(e));
        if (this.get("render_mode") === 2) this._refreshControls("split");
      } else if (this._pointers.size === 2 && this._pinch > 0) {
        const d = spread();
        if (d > 0) this._core.zoom(-10 * Math.log(d / this._pinch));
        this._pinch = d;
      }
    });
    const release = (e) => {
      if (!this._pointers.delete(e.pointerId)) return;
      if (this._pointers.size === 0) this._core.pointerUp();
      if (this._pointers.size < 2) this._pinch = 0;
    };
    this._on(canvas, "pointerup", release);
    this._on(canvas, "pointercancel", release);
    this._on(canvas, "lostpointercapture", release);
    this._on(
      canvas,
      "wheel",
      (e) => {
        const lines = e.deltaMode === 1 ? 33 : e.deltaMode === 2 ? 400 : 1;
        this._core.zoom(Math.max(-3, Math.min(3, (e.deltaY * lines) / 100)));
        e.preventDefault();
      },
      { passive: false },
    );
    // Keys act only while the canvas has focus, so the host page keeps its shortcuts.
    this._on(canvas, "keydown", (e) => {
      if (e.ctrlKey || e.metaKey || e.altKey) return;
      const turn = { ArrowLeft: [-12, 0], ArrowRight: [12, 0], ArrowUp: [0, -12], ArrowDown: [0, 12] }[e.key];
      let used = true;
      if (turn) this._core.orbit(...turn);
      else if (e.key === "+" || e.key === "=") this._core.zoom(-1);
      else if (e.key === "-" || e.key === "_") this._core.zoom(1);
      else if (e.key === "Enter") this.addDrop(0, 0);
      else used = this._core.key(e.code);
      if (used) {
        e.preventDefault();
        this._refreshControls();
      }
    });
  }

  // ---- controls -----------------------------------------------------------------------

  _buildControls() {
    // A drawer under the pool: open where there is room beside the groups, folded on a phone.
    const drawer = document.createElement("details");
    drawer.className = "controls";
    drawer.open = this._element.clientWidth >= NARROW_PX;
    const summary = document.createElement("summary");
    summary.textContent = "Controls";
    const panel = document.createElement("div");
    panel.className = "panel";
    drawer.append(summary, panel);
    panel.append(this._presetRow());
    const groups = new Map();
    for (const p of this._table) {
      if (!groups.has(p.group)) {
        const fieldset = document.createElement("fieldset");
        const legend = document.createElement("legend");
        legend.textContent = p.group;
        fieldset.append(legend);
        groups.set(p.group, fieldset);
        panel.append(fieldset);
      }
      groups.get(p.group).append(this._control(p));
    }
    if (groups.has("Flat water")) {
      // What each render mode costs, measured while it is shown, under its control.
      this._costs = document.createElement("output");
      this._costs.className = "costs";
      groups.get("Flat water").querySelector("[name=render_mode]").closest(".row").after(this._costs);
    }
    if (groups.has("Optics")) {
      // The Fresnel models' curves beside their select.
      this._plot = new FresnelPlot(fresnelCurve);
      groups.get("Optics").append(this._plot.element);
      this._updatePlot();
    }
    const buttons = document.createElement("div");
    buttons.className = "buttons";
    const button = (label, title, action) => {
      const b = document.createElement("button");
      b.type = "button";
      b.textContent = label;
      b.title = title;
      b.addEventListener("click", action);
      buttons.append(b);
    };
    button("Reset", "Back to how this page started: its parameters and view, calm water, the objects in place", () =>
      this.reset(),
    );
    button("Defaults", "Set every parameter to its default", () => {
      for (const p of this._table) this.set(p.name, p.default);
    });
    const said = document.createElement("output");
    said.className = "said";
    said.setAttribute("aria-live", "polite");
    const copy = async (what, text) => {
      try {
        await navigator.clipboard.writeText(text);
        said.textContent = `${what} copied.`;
      } catch (_) {
        said.textContent = text; // no clipboard here (an insecure page, a sandbox): shown to copy by hand
      }
    };
    button("Share link", "Copy a link that opens this pool with these parameters and this view", () =>
      copy("Link", this.shareLink()),
    );
    button("Copy embed code", "Copy an <iframe> that shows this pool, as it is now, in another page", () =>
      copy("Embed code", this.embedCode()),
    );
    buttons.append(said);
    panel.append(buttons);
    this._root.append(drawer);
  }

  // The Preset select: a named starting state from the core's table.
  _presetRow() {
    const row = document.createElement("div");
    row.className = "row preset";
    const label = document.createElement("label");
    label.htmlFor = `wavepool-${this._id}-preset`;
    label.textContent = "Preset";
    const select = document.createElement("select");
    select.id = label.htmlFor;
    select.append(new Option("choose…", ""));
    for (const p of presetTable()) {
      const option = new Option(p.label, p.name);
      option.title = p.help;
      select.append(option);
    }
    if (this._opts.preset) select.value = this._opts.preset.name;
    select.addEventListener("change", () => select.value && this.applyPreset(select.value));
    row.append(label, select);
    return row;
  }

  _control(p) {
    const row = document.createElement("div");
    row.className = "row";
    const inputId = `wavepool-${this._id}-${p.name}`;
    const label = document.createElement("label");
    label.htmlFor = inputId;
    label.textContent = p.label;
    label.title = p.help;
    const input = document.createElement(p.kind === "choice" ? "select" : "input");
    input.id = inputId;
    input.name = p.name;
    input.title = p.help;
    const output = document.createElement("output");
    output.htmlFor = inputId;
    if (p.kind === "toggle") {
      input.type = "checkbox";
      input.addEventListener("change", () => this.set(p.name, input.checked ? 1 : 0));
    } else if (p.kind === "choice") {
      for (const v of p.choices) input.append(new Option(formatValue(p, v), String(v)));
      input.addEventListener("change", () => this.set(p.name, Number(input.value)));
    } else {
      input.type = "range";
      input.min = p.min;
      input.max = p.max;
      input.step = p.step;
      input.addEventListener("input", () => this.set(p.name, Number(input.value)));
    }
    const update = () => {
      const v = this.get(p.name);
      if (p.kind === "toggle") input.checked = v >= 0.5;
      else input.value = String(v);
      output.textContent = formatValue(p, v);
      input.setAttribute("aria-valuetext", output.textContent);
      // A model's own settings show only while that model is chosen.
      if (p.shownWhen) row.hidden = !p.shownWhen.values.includes(this.get(p.shownWhen.param));
    };
    this._controls.set(p.name, update);
    if (p.shownWhen) {
      const list = this._dependants.get(p.shownWhen.param) || [];
      this._dependants.set(p.shownWhen.param, [...list, update]);
    }
    update();
    row.append(label, input, output);
    return row;
  }

  // Records a drawn frame's interval under the render mode shown, and twice a second writes
  // each mode's cost: its GPU time where the browser measures it (stats().gpuMs), and the
  // median interval between its frames.
  _costsNote(time, interval) {
    const mode = Math.round(this.get("render_mode"));
    const list = this._modeIntervals[mode];
    if (list) {
      list.push(interval);
      if (list.length > 60) list.shift();
    }
    if (!this._costs || time - this._costsAt < 500) return;
    this._costsAt = time;
    const s = this._core.stats();
    const names = ["ray-traced", "flat", "split"];
    const keys = ["raytraced", "flat", "split"];
    const gpu = s.gpuMs
      ? "GPU time drawing the water: " +
        names.map((n, i) => `${n} ${s.gpuMs[keys[i]] === null ? "–" : s.gpuMs[keys[i]].toFixed(1) + " ms"}`).join(" · ")
      : "GPU time: this browser does not measure it (no WebGPU timestamps)";
    const between = names
      .map((n, i) => {
        const l = [...this._modeIntervals[i]].sort((a, b) => a - b);
        return `${n} ${l.length ? l[Math.floor((l.length - 1) / 2)].toFixed(0) + " ms" : "–"}`;
      })
      .join(" · ");
    this._costs.textContent = `${s.flatNote ? s.flatNote + " " : ""}${gpu}. Between frames: ${between}.`;
  }

  // The plot's model and the angle at which the view's centre meets the water (the camera's
  // pitch is its elevation above the pool's middle: incidence = 90° - |pitch|).
  _updatePlot() {
    if (!this._plot) return;
    this._plot.update(this.get("fresnel"), 90 - Math.abs(this.camera()[1]));
  }

  _refreshControls(name) {
    if (!name || name === "fresnel") this._updatePlot();
    if (name) {
      const update = this._controls.get(name);
      if (update) update();
      for (const dependant of this._dependants.get(name) || []) dependant();
    } else {
      for (const update of this._controls.values()) update();
    }
    if (this._overlayUpdate) this._overlayUpdate();
  }

  // Buttons over the pool, there with or without the controls: play/pause (the `paused`
  // parameter: a way to stop the motion, WCAG 2.2.2) and fullscreen (only where the page
  // allows it: an iframe needs allow="fullscreen").
  _buildOverlay() {
    const bar = document.createElement("div");
    bar.className = "overlay";
    const play = document.createElement("button");
    play.type = "button";
    play.className = "play";
    const playIcon = icon(ICONS.pause);
    play.append(playIcon);
    play.addEventListener("click", () => this.set("paused", this.get("paused") >= 0.5 ? 0 : 1));
    bar.append(play);
    if (document.fullscreenEnabled && this._element.requestFullscreen) {
      const full = document.createElement("button");
      full.type = "button";
      full.className = "fullscreen";
      full.append(icon(ICONS.fullscreen));
      full.title = "Fullscreen (Esc leaves it)";
      full.setAttribute("aria-label", "Fullscreen");
      full.addEventListener("click", () =>
        document.fullscreenElement === this._element
          ? document.exitFullscreen()
          : this._element.requestFullscreen().catch((e) => warn(`fullscreen refused: ${e.message || e}`)),
      );
      bar.append(full);
    }
    this._overlayUpdate = () => {
      if (!this._core) return;
      const paused = this.get("paused") >= 0.5;
      playIcon.firstChild.setAttribute("d", paused ? ICONS.play : ICONS.pause);
      play.setAttribute("aria-label", paused ? "Play" : "Pause");
      play.title = paused ? "Play: start the water and the objects moving" : "Pause: stop the water and the objects";
      play.setAttribute("aria-pressed", String(!paused));
    };
    this._overlayUpdate();
    this._stage.append(bar);
  }

  // ---- frame loop ---------------------------------------------------------------------

  // Starts or stops the frame loop as the demo's state asks. A loop that starts again
  // begins with a nominal frame time, not the time it was stopped for.
  _run() {
    const wanted = !this._dead && this._core && !this._userPaused && this._visible && this._onScreen;
    if (wanted && !this._frame) {
      if (!this._looping) this._last = 0;
      this._looping = true;
      this._frame = requestAnimationFrame((t) => this._tick(t));
    } else if (!wanted) {
      if (this._frame) cancelAnimationFrame(this._frame);
      this._frame = 0;
      this._looping = false;
      this._frames.length = 0;
      this._simTimes.length = 0;
    }
  }

  _tick(time) {
    this._frame = 0;
    if (this._dead || !this._core) return;
    // Paced: while the GPU is still on the last frame, this animation frame draws nothing
    // (a slow GPU gets fewer frames rather than a growing queue of them).
    if (!this._core.canDraw() || (this._last && time - this._last < this._minFrameMs())) {
      this._run();
      return;
    }
    const dt = this._last ? Math.min(0.25, (time - this._last) / 1000) : 1 / 60;
    this._last = time;
    try {
      this._core.frame(dt, this._canvas.width, this._canvas.height);
    } catch (error) {
      this._recover(error);
      return;
    }
    if (this._still) {
      // Woken: the still goes once the new context's frame is on screen.
      const still = this._still;
      this._still = null;
      requestAnimationFrame(() => still.remove());
    }
    if (this._plot && !(time - this._plotAt < 250)) {
      this._plotAt = time; // the view mark follows the camera, four times a second
      this._updatePlot();
    }
    if (this._frames.length === 0) this._runningSince = time;
    else this._costsNote(time, time - this._frames[this._frames.length - 1]);
    this._frames.push(time);
    this._simTimes.push(this._core.simTime);
    // Drawn frames of the last 2 s, and the one before them (for the first interval).
    while (this._frames.length > 2 && time - this._frames[1] > STATS_WINDOW_MS) {
      this._frames.shift();
      this._simTimes.shift();
    }
    if (this._firstFrameMs === null) {
      this._firstFrameMs = performance.now() - this._started;
      // Ready once the GPU has finished the first frame and the browser has composited it
      // (the animation frame after that): then the pool is on screen, not just on its way.
      const whenShown = () => {
        if (this._dead) return;
        if (this._core && !this._core.canDraw()) {
          requestAnimationFrame(whenShown);
          return;
        }
        requestAnimationFrame(() => {
          if (this._dead) return;
          this._element.dataset.ready = "true";
          this._firstFrameResolve();
        });
      };
      requestAnimationFrame(whenShown);
    }
    this._run();
  }

  // Shortest interval between drawn frames (ms) under the maxFps option; a few ms short of
  // 1000 / maxFps, since animation frames come at the display's own ticks.
  _minFrameMs() {
    return this._opts.maxFps ? 1000 / this._opts.maxFps - 4 : 0;
  }

  // A lost device is recreated on a fresh canvas; a loss within 10 s of the last restart
  // (or any other error) is reported instead, so a failing device cannot loop.
  async _recover(error) {
    const text = String(error && error.message ? error.message : error);
    const now = performance.now();
    if (!/lost/.test(text) || now - this._lastRestart < 10000) {
      this._fail(`The water demo stopped: ${text}`);
      return;
    }
    this._lastRestart = now;
    this._restarts++;
    const saved = this._saveState();
    this._detachCore();
    try {
      this._status("The graphics device was lost; restarting…");
      await this._restart(saved);
    } catch (e) {
      this._fail(`The graphics device was lost and could not be restarted: ${e.message || e}`);
    }
  }

  /** The parameters and camera, to carry across a new context. */
  _saveState() {
    return { params: this._table.map((p) => [p.name, this._core.get(p.name)]), camera: this._core.camera() };
  }

  /** A new context with `saved` parameters and camera (the water starts calm), running. */
  async _restart(saved) {
    await this._start();
    for (const [name, v] of saved.params) this._core.set(name, v);
    this._core.setCamera(...saved.camera);
    this._refreshControls();
    this._status(null);
    this._run();
  }

  // ---- the page's context budget (context-budget.js) -----------------------------------

  _nearChanged(near) {
    this._near = near;
    if (!near) this._leftAt = performance.now();
    else if (this._suspended) this._wake();
  }

  /** Holds a running context it can give up now (not while one is being created). */
  _suspendable() {
    return !!this._core && !this._dead && !this._waking;
  }

  /** Every context is taken by demos on screen: say so until one scrolls away. */
  _blocked() {
    if (!this._suspended && !this._core) {
      this._status("Waiting for a free GPU context: scroll another water demo on this page out of view.");
    }
  }

  /** Gives the context up, keeping the last frame on show and the parameters and camera. */
  _suspend() {
    this._saved = this._saveState();
    this._still = this._copyFrame("still");
    this._detachCore();
    this._looping = false;
    this._suspended = true;
    this._element.dataset.suspended = "true";
    releaseContext(this);
  }

  /** Near again: takes a context when one is free and goes on from the saved state. */
  async _wake() {
    if (this._waking || this._dead) return;
    this._waking = true;
    try {
      await acquireContext(this);
      if (this._dead) return;
      await this._restart(this._saved);
      this._saved = null;
      this._suspended = false;
      delete this._element.dataset.suspended;
    } catch (e) {
      this._fail(`The water demo could not start again: ${e.message || e}`);
    } finally {
      this._waking = false;
    }
  }

  _detachCore() {
    for (const cleanup of this._cleanups.splice(0)) cleanup();
    if (this._frame) cancelAnimationFrame(this._frame);
    this._frame = 0;
    const webgl = this._core && this._core.backend === "webgl2";
    if (this._core) {
      try {
        this._core.dispose();
        this._core.free();
      } catch (_) {
        // a poisoned module cannot free; the page drops it anyway
      }
    }
    this._core = null;
    if (this._canvas) {
      // Browsers keep a few WebGL contexts at most: give this one back now, not at GC.
      const gl = webgl && this._canvas.getContext("webgl2");
      const lose = gl && gl.getExtension("WEBGL_lose_context");
      if (lose) lose.loseContext();
      this._canvas.remove();
    }
    this._canvas = null;
  }

  _status(text) {
    this._message.hidden = !text;
    this._message.textContent = text || "";
    this._message.classList.remove("error");
  }

  _fail(text) {
    if (this._dead) return;
    this._dead = true;
    if (this._frame) cancelAnimationFrame(this._frame);
    this._frame = 0;
    // A still picture of the pool (made by `wavepool render`; 7 KB, so the single file
    // carries it too, as a data: URL) behind the message, so the box is not empty.
    if (!this._stage.querySelector(".fallback")) {
      const picture = new Image();
      picture.className = "fallback";
      picture.alt = "A still picture of the water pool (the live demo could not start here)";
      picture.src = inline ? inline.picture : new URL("./no-gpu.webp", import.meta.url).href;
      this._stage.prepend(picture);
    }
    this._message.hidden = false;
    this._message.classList.add("error");
    this._message.textContent = text;
    this._element.dataset.error = "true";
    console.error(`wavepool: ${text}`);
    if (!this._core) releaseContext(this);
    this._firstFrameReject(new Error(text));
  }

  // Puts a still of the current frame over the GPU canvas (for printing); `false` takes it away.
  _printShot(show = true) {
    const old = this._stage.querySelector(".print-shot");
    if (old) old.remove();
    if (show && this._core && this._canvas) this._copyFrame("print-shot");
  }

  // A copy of the current frame in a 2D canvas of class `className`, put in the stage: it
  // prints, and needs no image URL that a Content-Security-Policy could refuse.
  _copyFrame(className) {
    const { width, height } = this._canvas;
    this._core.frame(0, width, height);
    const shot = document.createElement("canvas");
    shot.className = className;
    shot.width = width;
    shot.height = height;
    // In the task that drew the frame, while the GPU canvas still holds it.
    shot.getContext("2d").drawImage(this._canvas, 0, 0);
    this._canvas.after(shot); // over the GPU canvas, under the message and the buttons
    return shot;
  }

  _alive() {
    if (this._suspended) {
      throw new Error("wavepool: this demo is scrolled away and gave its GPU context to others; it goes on when it is near the viewport");
    }
    if (this._dead || !this._core) throw new Error("wavepool: this demo is not running (destroyed, failed or not started)");
    return this._core;
  }

  /** While suspended: the saved [name, value] entry of a parameter. */
  _savedParam(name) {
    const entry = this._saved.params.find(([n]) => n === name);
    if (!entry) throw new Error(`wavepool: unknown parameter "${name}"`);
    return entry;
  }

  // ---- public API ---------------------------------------------------------------------

  /** Adds a drop at pool coordinates x, z (m, -1..1) with radius (m) and strength (m). */
  addDrop(x, z, radius = this.get("drop_radius"), strength = this.get("drop_strength")) {
    this._alive().addDrop(Number(x), Number(z), Number(radius), Number(strength));
  }

  /** Sets a parameter; out-of-range values are clamped (console warning). Returns the value in effect. */
  set(name, value) {
    const spec = this._table && this._table.find((p) => p.name === String(name));
    if (this._suspended) {
      // Kept until it wakes; clamped then.
      const entry = this._savedParam(String(name));
      entry[1] = toNumber(value, spec);
      this._refreshControls(String(name));
      return entry[1];
    }
    const v = this._alive().set(String(name), toNumber(value, spec));
    this._refreshControls(String(name));
    return v;
  }

  /** A parameter's current value; throws for unknown names. */
  get(name) {
    if (this._suspended) return this._savedParam(String(name))[1];
    return this._alive().get(String(name));
  }

  /** Where pool point (x, y, z) in m appears, in CSS pixels relative to the page's viewport; null when not visible. */
  project(x, y, z) {
    const p = this._alive().project(Number(x), Number(y), Number(z));
    if (p.length < 2) return null;
    const r = this._canvas.getBoundingClientRect();
    return { x: r.left + (p[0] * r.width) / this._canvas.width, y: r.top + (p[1] * r.height) / this._canvas.height };
  }

  /** The parameter table. */
  params() {
    return this._table.map((p) => ({ ...p }));
  }

  /** Back to how the page started: its parameters and camera, calm water, the objects in place. */
  reset() {
    const core = this._alive();
    for (const [name, value] of this._startState.params) core.set(name, value);
    core.setCamera(...this._startState.camera);
    core.reset();
    this._refreshControls();
  }

  /** Starts over from a preset (by name): defaults, then its values and view; calm water. */
  applyPreset(name) {
    const core = this._alive();
    const preset = presetTable().find((p) => p.name === String(name).toLowerCase());
    if (!preset) throw new Error(`wavepool: no preset "${name}"; presets: ${presetTable().map((p) => p.name).join(", ")}`);
    for (const p of this._table) if (p.group !== "Display") core.set(p.name, p.default);
    for (const [n, v] of preset.values) core.set(n, v);
    core.setCamera(...(preset.camera || this._defaultCamera));
    core.reset();
    this._refreshControls();
  }

  /** The query string of this demo as it is now: parameters that differ from the defaults, and the camera. */
  _query() {
    const query = new URLSearchParams();
    for (const p of this._table) {
      const v = this.get(p.name);
      if (v === p.default) continue;
      const i = p.kind === "choice" ? p.choices.indexOf(v) : -1;
      query.set(p.name, i >= 0 && p.choiceNames[i] ? p.choiceNames[i] : String(v));
    }
    query.set("camera", this.camera().map((v) => Math.round(v * 10) / 10).join(","));
    return query.toString().replace(/%2C/g, ",");
  }

  /** A link that opens the demo's page with this demo's parameters and view. */
  shareLink() {
    const page = inline ? location.href.split(/[?#]/)[0] : new URL("./index.html", import.meta.url).href;
    return `${page}?${this._query()}`;
  }

  /** An <iframe> showing this demo as it is now (the pool alone, `embed.html`; the single file when this is it). */
  embedCode() {
    const page = inline ? location.href.split(/[?#]/)[0] : new URL("./embed.html", import.meta.url).href;
    return (
      `<iframe src="${page}?${this._query()}" width="800" height="600" allow="fullscreen" ` +
      `title="Interactive water pool (wavepool)"></iframe>`
    );
  }

  /** The camera as [yaw, pitch, distance] (degrees, degrees, m). */
  camera() {
    if (this._suspended) return Array.from(this._saved.camera);
    return Array.from(this._alive().camera());
  }

  /** Moves the camera; out-of-range values are clamped (console warning). */
  setCamera(yaw, pitch, distance) {
    if (this._suspended) this._saved.camera = [Number(yaw), Number(pitch), Number(distance)];
    else this._alive().setCamera(Number(yaw), Number(pitch), Number(distance));
  }

  /** Stops the frame loop (and the water) until resume(). */
  pause() {
    this._userPaused = true;
    this._run();
  }

  resume() {
    this._userPaused = false;
    this._run();
  }

  /** { fps, frameMs, longestFrameMs, firstFrameMs, restarts, backend, adapter, simSize, ... } (see the README) */
  stats() {
    if (this._suspended) {
      // No context: what is known without one.
      const { backend } = this._element.dataset;
      return { suspended: true, fps: 0, backend, firstFrameMs: this._firstFrameMs, restarts: this._restarts, contextsOnPage: contextsHeld() };
    }
    const s = this._alive().stats();
    s.suspended = false;
    s.contextsOnPage = contextsHeld();
    Object.assign(s, frameStats(this._frames, this._runningSince, performance.now()));
    // Simulated seconds per wall second over the drawn frames of the window (1: real time).
    const [t, sim, n] = [this._frames, this._simTimes, this._frames.length];
    s.simSpeed = n > 1 && t[n - 1] > t[0] ? ((sim[n - 1] - sim[0]) * 1000) / (t[n - 1] - t[0]) : 0;
    s.firstFrameMs = this._firstFrameMs;
    s.wasmMemoryBytes = wasmMemory ? wasmMemory.buffer.byteLength : null;
    s.restarts = this._restarts;
    return s;
  }

  /** The next frame as a PNG Blob. */
  snapshot() {
    const core = this._alive();
    core.frame(0, this._canvas.width, this._canvas.height);
    return new Promise((resolve, reject) =>
      this._canvas.toBlob((blob) => (blob ? resolve(blob) : reject(new Error("snapshot failed"))), "image/png"),
    );
  }

  /** Stops the demo, frees its GPU resources and empties the element. */
  destroy() {
    this._detachCore();
    this._dead = true;
    live.delete(this);
    releaseContext(this);
    if (this._unwatch) this._unwatch();
    // Only what is still this demo's (a newer mount in the same element keeps its own).
    if (this._root.parentNode === this._shadow) {
      this._shadow.replaceChildren();
      delete this._element.dataset.backend;
      delete this._element.dataset.ready;
      delete this._element.dataset.suspended;
    }
  }
}

// ---- <wave-pool> ------------------------------------------------------------------------

/** Mount options whose attribute is spelt in kebab case (`max-fps` for `maxFps`). */
const CAMEL_OPTIONS = new Set([...Object.keys(DEFAULT_OPTIONS), "meshSize", "causticsSize"]);

/** An attribute's name as a mount option or parameter name: `max-fps` -> `maxFps`, `wave-speed` -> `wave_speed`. */
function optionName(attribute) {
  const camel = attribute.replace(/-([a-z])/g, (_, c) => c.toUpperCase());
  return CAMEL_OPTIONS.has(camel) ? camel : attribute.replace(/-/g, "_");
}

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
