// One mounted demo: its canvas and core (wasm-bindgen's WebDemo), start-up on the first
// backend that works, messages, and the public API a page calls. Input, controls, the frame
// loop and suspending are in their own modules, mixed into the class here.

import { WebDemo, presetTable } from "./wavepool.js";
import { contextsHeld, releaseContext } from "./context-budget.js";
import { controlMethods } from "./controls.js";
import { languageMethods } from "./language.js";
import { linkMethods } from "./links.js";
import { pickedMethods } from "./picked.js";
import { frameLoopMethods, frameStats } from "./frame-loop.js";
import { inputMethods } from "./input.js";
import { keepKeys } from "./keys.js";
import { layoutMethods } from "./layout.js";
import { assetUrl, inline, live, memoryBytes } from "./loader.js";
import { toNumber } from "./options.js";
import { suspendMethods } from "./suspend.js";

/** The message shown when no backend started, in `words`: what was tried, each one's reason
 * (a message id, or the browser's own words), what to do. */
function backendFailure(words, backend, failures) {
  const api = { webgpu: "WebGPU", webgl2: "WebGL2" }[backend];
  const reasons = failures.map((f) => `• ${f.id ? words.page(f.id) : f}`).join("\n");
  if (api) {
    const fix = words.page("error-backend-forced-fix", { backend });
    return `${words.page("error-backend-forced", { api, backend })}\n${reasons}\n${fix}`;
  }
  return `${words.page("error-no-backend")}\n${reasons}`;
}

/** How long a notice stays over the picture (ms). */
const NOTICE_MS = 12000;

export class Demo {
  constructor(element, shadow, root, stage, message, id, started) {
    this._element = element;
    this._shadow = shadow;
    this._root = root;
    this._stage = stage;
    this._message = message;
    this._id = id;
    this._started = started;
    this._core = null;
    this._prepared = false; // the core's start-up work is done (frame-loop.js)
    this._canvas = null;
    this._frame = 0; // requestAnimationFrame id
    this._last = 0; // time of the last frame (ms)
    this._frames = []; // times of the frames drawn in the last 2 s (ms), for stats()
    this._framesDrawn = 0; // frames drawn since the demo started
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
    this._readings = null; // the scene's instruments' readings, under its controls
    this._readingsAt = -Infinity;
    this._modeIntervals = [[], [], []]; // recent intervals between drawn frames per render mode (ms)
    // Sizing (layout.js).
    this._fills = false; // the element has a height of its own, which the pool fills
    this._aspect = 4 / 3; // width / height of the picture otherwise
    this._box = undefined; // the box it fits in (null: the page scrolls; undefined: not looked for yet)
    this._fitObserver = null;
    this._onWindowResize = null;
    // Keys the pool uses stay in it (keys.js).
    this._unkeepKeys = keepKeys(shadow);
  }

  // ---- set-up -------------------------------------------------------------------------

  async _start() {
    const forced = this._opts.backend !== "auto";
    const order = forced ? [this._opts.backend] : ["webgpu", "webgl2"];
    const failures = [];
    for (const backend of order) {
      if (backend === "webgpu" && !navigator.gpu) {
        failures.push({ id: "error-no-webgpu" });
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
      this._prepared = false; // the core's start-up work is not done (frame-loop.js)
      if (this._dead) {
        this._detachCore(); // destroyed while the context was being made
        throw new Error("wavepool: the demo was destroyed while it started");
      }
      this._element.dataset.backend = backend;
      this._listen();
      return;
    }
    throw new Error(backendFailure(await this._settledWords(), this._opts.backend, failures));
  }

  _makeCanvas() {
    const canvas = document.createElement("canvas");
    canvas.tabIndex = 0;
    canvas.setAttribute("role", "application");
    canvas.setAttribute("aria-label", this.text("canvas-label")); // again once the words are loaded
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

  _status(text) {
    this._message.hidden = !text;
    this._message.textContent = text || "";
    this._message.classList.remove("error");
  }

  /** A notice over the picture's corner that goes after a while (a size reduced, a mode
   * changed for the device's sake); a status, so screen readers say it once. */
  _notice(text) {
    let notice = this._stage.querySelector(".notice");
    if (!notice) {
      notice = document.createElement("p");
      notice.className = "notice";
      notice.setAttribute("role", "status");
      notice.addEventListener("click", () => (notice.hidden = true));
      this._stage.append(notice);
    }
    // Shown with the notices still up, each on its own line.
    if (notice.hidden) notice.replaceChildren();
    const line = document.createElement("span");
    line.textContent = text;
    notice.append(line);
    notice.hidden = false;
    console.warn(`wavepool: ${text}`);
    clearTimeout(this._noticeTimer);
    this._noticeTimer = setTimeout(() => (notice.hidden = true), NOTICE_MS);
  }

  /** Says which sizes the core held to what this device affords, if any. */
  _noticeReduced() {
    const reduced = this._core.stats().reduced;
    if (!reduced.length) return;
    const list = reduced.map((r) => `${r.name} ${r.asked} → ${r.given}`).join(", ");
    this._notice(this._words.page("notice-no-gpu", { sizes: list }));
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
      picture.alt = this.text("fallback-picture");
      picture.src = inline ? inline.picture : assetUrl("no-gpu.webp", new URL("./no-gpu.webp", import.meta.url));
      this._stage.prepend(picture);
    }
    this._message.hidden = false;
    this._message.classList.add("error");
    this._message.textContent = text;
    this._element.dataset.error = "true";
    console.error(`wavepool: ${text}`);
    // What it no longer needs: nothing more to fit, and no keys to keep.
    this._stopFitting();
    this._unkeepKeys();
    if (!this._core) releaseContext(this);
    this._firstFrameReject(new Error(text));
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
    if (this._startState.sketch) core.setSketch(this._startState.sketch);
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
    s.framesDrawn = this._framesDrawn;
    s.wasmMemoryBytes = memoryBytes();
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
    this._stopFitting();
    this._unkeepKeys();
    // Only what is still this demo's (a newer mount in the same element keeps its own).
    if (this._root.parentNode === this._shadow) {
      this._shadow.replaceChildren();
      delete this._element.dataset.backend;
      delete this._element.dataset.ready;
      delete this._element.dataset.suspended;
    }
  }
}

Object.assign(
  Demo.prototype,
  inputMethods,
  layoutMethods,
  controlMethods,
  languageMethods,
  linkMethods,
  pickedMethods,
  frameLoopMethods,
  suspendMethods,
);
