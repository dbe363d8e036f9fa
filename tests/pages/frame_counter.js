// Counts the frames a page actually DRAWS, the same way for any page (ours, the classic, a
// WebGPU port), as /work/shared/notes/measuring.md asks: not animation-frame callbacks, which
// overstate the rate as soon as a page skips callbacks or queues work ahead of the GPU.
//
// Injected before any page script runs (DevTools `Page.addScriptToEvaluateOnNewDocument`, see
// `Browser::add_init_script` in tests/support/browser.rs); runs in every document of the tab,
// iframes included. Exposes:
//
//   window.__frameCounter.reset()  starts a new window
//   window.__frameCounter.read()   figures over the window since reset() (or since load):
//     { frames, seconds, fps, medianMs, p5Ms, p95Ms, longestMs, pending, api,
//       callbacks, callbacksFps, ticks, totalFrames, canvases: [...] }
//
// How a frame is counted:
// - WebGL / WebGL2: the draw calls (drawArrays, drawElements, their instanced and range forms,
//   the ANGLE_instanced_arrays / WEBGL_multi_draw extension draws, clear, blitFramebuffer) note
//   when they reach the default framebuffer (`null` bound for drawing, tracked by wrapping
//   bindFramebuffer / deleteFramebuffer). At each animation-frame callback, a canvas drew a frame
//   if such a draw happened since the previous callback. wgpu's GL backend presents with a
//   blitFramebuffer into the default framebuffer, the classic draws into it directly.
// - WebGPU: every GPUCanvasContext.getCurrentTexture() that returns a new texture, or comes after
//   a queue submission since the last call, starts a frame
//   of that canvas; at that moment queue.onSubmittedWorkDone() of the canvas's device resolves
//   when everything submitted so far (the previous frame) is finished: each resolution is one
//   finished frame, at the time it resolves. `pending` = frames submitted and not finished yet
//   (a page that paces itself keeps that at 1-2).
//
// Figures: `frames`, `fps` and the intervals are those of the canvas that drew most in the window
// (the demo on a one-demo page); `canvases` lists every canvas that drew, `totalFrames` is their
// sum. `medianMs` / `p5Ms` / `p95Ms` are over the intervals between consecutive frames (ms, null with fewer
// than two frames); `longestMs` also includes the gaps from the window's start to the first frame
// and from the last frame to read(), so a page that froze shows it. `callbacks` counts the
// animation frames in which the page's own requestAnimationFrame callbacks ran (`ticks`: all
// animation frames of the document), for reference only.
//
// Same-origin iframes report into the top document's counter (their canvases appear in its
// `canvases`); a cross-origin iframe has a counter of its own, readable only inside it.
(() => {
  "use strict";
  if (window.__frameCounter) return;

  // The state shared by the top document and its same-origin iframes.
  let state = null;
  try {
    if (window.top !== window && window.top.__frameCounter) state = window.top.__frameCounter._state;
  } catch (e) {
    // Cross-origin parent: count on our own.
  }
  const own = state === null;
  if (own) {
    // One clock for every document sharing the state: the top document's (documents have
    // different time origins).
    const clock = performance;
    state = {
      now: () => clock.now(),
      start: clock.now(), // ms, start of the window
      canvases: new Map(), // canvas -> its record (see canvasRecord)
      dirty: [], // records of canvases whose default framebuffer was drawn since the last tick
      tick: 0, // animation frames of the top document since load
      ticks: 0, // ... since reset()
      callbacks: 0, // animation frames in which the page's callbacks ran, since reset()
      lastCallbackTick: -1,
      device: null, // the last GPUDevice the page requested (for contexts configured before we saw it)
    };
  }
  const now = state.now;

  /// The record of one canvas: the times (ms) of its frames in the window, and WebGPU bookkeeping.
  function canvasRecord(canvas, api) {
    let r = state.canvases.get(canvas);
    if (!r) {
      let label = canvas.id ? `#${canvas.id}` : `canvas ${state.canvases.size + 1}`;
      const root = canvas.getRootNode && canvas.getRootNode();
      if (root && root.host) label = `${root.host.id ? "#" + root.host.id : root.host.tagName.toLowerCase()} > ${label}`;
      if (!own) label = `${location.pathname} ${label}`;
      r = { canvas, label, api, times: [], started: 0, pending: 0, dirty: false };
      state.canvases.set(canvas, r);
    }
    return r;
  }

  // ---- animation frames -------------------------------------------------------------------------
  const raf = window.requestAnimationFrame;
  if (own) {
    // Our own callback, registered before any page script, so it runs first in every animation
    // frame: the draws it finds were made since the previous animation frame.
    const loop = () => {
      state.tick++;
      state.ticks++;
      const t = now();
      for (const r of state.dirty) {
        r.dirty = false;
        // A canvas that is not in the document (a feature probe) shows nothing.
        if (r.canvas.isConnected !== false) r.times.push(t);
      }
      state.dirty.length = 0;
      raf.call(window, loop);
    };
    raf.call(window, loop);
  }
  // The page's callbacks: counted once per animation frame in which any of them ran.
  window.requestAnimationFrame = function requestAnimationFrame(callback) {
    if (typeof callback !== "function") return raf.call(window, callback); // throws as usual
    return raf.call(window, function (time) {
      if (state.lastCallbackTick !== state.tick) {
        state.lastCallbackTick = state.tick;
        state.callbacks++;
      }
      return callback.call(this, time);
    });
  };

  // ---- WebGL / WebGL2 ---------------------------------------------------------------------------
  const FRAMEBUFFER = 0x8d40;
  const DRAW_FRAMEBUFFER = 0x8ca9;
  const drawBinding = new WeakMap(); // context -> framebuffer bound for drawing (absent: null)
  const contextRecord = new WeakMap(); // context -> record of its canvas
  const extensionContext = new WeakMap(); // extension object -> its context
  const hookedExtensions = new WeakSet(); // extension prototypes already wrapped

  /// Notes a draw of `gl` (a context) if it reaches the default framebuffer.
  function noteDraw(gl, api) {
    if (!gl || drawBinding.get(gl)) return; // a framebuffer object is bound: off screen
    let r = contextRecord.get(gl);
    if (!r) contextRecord.set(gl, (r = canvasRecord(gl.canvas, api)));
    if (!r.dirty) {
      r.dirty = true;
      state.dirty.push(r);
    }
  }

  function wrap(proto, name, make) {
    const original = proto && proto[name];
    if (typeof original === "function") proto[name] = make(original);
  }

  function hookGl(Context, api) {
    if (!Context) return;
    const proto = Context.prototype;
    wrap(proto, "bindFramebuffer", (original) =>
      function bindFramebuffer(target, framebuffer) {
        if (target === FRAMEBUFFER || target === DRAW_FRAMEBUFFER) drawBinding.set(this, framebuffer || null);
        return original.apply(this, arguments);
      });
    // Deleting the bound framebuffer binds the default one again.
    wrap(proto, "deleteFramebuffer", (original) =>
      function deleteFramebuffer(framebuffer) {
        if (framebuffer && drawBinding.get(this) === framebuffer) drawBinding.set(this, null);
        return original.apply(this, arguments);
      });
    const draws = ["drawArrays", "drawElements", "drawArraysInstanced", "drawElementsInstanced", "drawRangeElements", "clear", "blitFramebuffer"];
    for (const name of draws) {
      wrap(proto, name, (original) =>
        function () {
          noteDraw(this, api);
          return original.apply(this, arguments);
        });
    }
    // Extension draws (ANGLE_instanced_arrays, WEBGL_multi_draw, ...): every method whose name
    // starts with "draw" or "multiDraw", on the extension's prototype, mapped to its context.
    wrap(proto, "getExtension", (original) =>
      function getExtension() {
        const ext = original.apply(this, arguments);
        if (ext && typeof ext === "object") {
          extensionContext.set(ext, this);
          const extProto = Object.getPrototypeOf(ext);
          if (extProto && extProto !== Object.prototype && !hookedExtensions.has(extProto)) {
            hookedExtensions.add(extProto);
            for (const name of Object.getOwnPropertyNames(extProto)) {
              if (!/^(draw|multiDraw)/.test(name)) continue;
              wrap(extProto, name, (method) =>
                function () {
                  noteDraw(extensionContext.get(this), api);
                  return method.apply(this, arguments);
                });
            }
          }
        }
        return ext;
      });
  }
  hookGl(window.WebGLRenderingContext, "webgl");
  hookGl(window.WebGL2RenderingContext, "webgl2");

  // ---- WebGPU -----------------------------------------------------------------------------------
  const contextDevice = new WeakMap(); // GPUCanvasContext -> device it was configured with
  const currentTexture = new WeakMap(); // GPUCanvasContext -> texture of its current frame
  const submitsSeen = new WeakMap(); // GPUCanvasContext -> queue submissions at its last getCurrentTexture
  let submits = 0; // queue submissions of the page so far
  if (window.GPUQueue) {
    wrap(GPUQueue.prototype, "submit", (original) =>
      function submit() {
        submits++;
        return original.apply(this, arguments);
      });
  }
  if (window.GPUAdapter) {
    wrap(GPUAdapter.prototype, "requestDevice", (original) =>
      function requestDevice() {
        return original.apply(this, arguments).then((device) => {
          state.device = device;
          return device;
        });
      });
  }
  if (window.GPUCanvasContext) {
    wrap(GPUCanvasContext.prototype, "configure", (original) =>
      function configure(configuration) {
        if (configuration && configuration.device) contextDevice.set(this, configuration.device);
        return original.apply(this, arguments);
      });
    wrap(GPUCanvasContext.prototype, "getCurrentTexture", (original) =>
      function getCurrentTexture() {
        const texture = original.apply(this, arguments);
        // The same texture until the frame is presented: a second call with no submission in
        // between is the same frame. (Firefox hands out the same texture object every frame.)
        if (currentTexture.get(this) !== texture || submitsSeen.get(this) !== submits) {
          currentTexture.set(this, texture);
          submitsSeen.set(this, submits);
          const r = canvasRecord(this.canvas, "webgpu");
          r.started++;
          const device = contextDevice.get(this) || state.device;
          if (device) {
            r.pending++;
            const finished = () => {
              r.pending--;
              r.times.push(now());
            };
            device.queue.onSubmittedWorkDone().then(finished, () => r.pending--);
          }
        }
        return texture;
      });
  }

  // ---- figures ----------------------------------------------------------------------------------
  const round = (x, digits = 2) => (x === null ? null : Math.round(x * 10 ** digits) / 10 ** digits);

  /// Figures of one canvas over the window [start, end] (ms).
  function figures(r, start, end) {
    const times = r.times.filter((t) => t >= start && t <= end);
    const intervals = [];
    for (let i = 1; i < times.length; i++) intervals.push(times[i] - times[i - 1]);
    const sorted = intervals.slice().sort((a, b) => a - b);
    const rank = (p) => (sorted.length ? sorted[Math.max(0, Math.ceil(p * sorted.length) - 1)] : null);
    const gaps = times.length ? [times[0] - start, end - times[times.length - 1]] : [end - start];
    const seconds = (end - start) / 1000;
    const canvas = r.canvas;
    return {
      label: r.label,
      api: r.api,
      width: canvas.width,
      height: canvas.height,
      frames: times.length,
      fps: round(seconds > 0 ? times.length / seconds : 0, 3),
      medianMs: round(rank(0.5), 1),
      p5Ms: round(rank(0.05), 1),
      p95Ms: round(rank(0.95), 1),
      longestMs: round(Math.max(...intervals, ...gaps), 1),
      started: r.started, // WebGPU: frames begun in the window
      pending: r.pending, // WebGPU: submitted, not finished, now
    };
  }

  const counter = {
    _state: state,
    reset() {
      state.start = now();
      state.ticks = 0;
      state.callbacks = 0;
      for (const r of state.canvases.values()) {
        r.times = [];
        r.started = 0;
      }
    },
    read() {
      const end = now();
      const seconds = (end - state.start) / 1000;
      const canvases = [...state.canvases.values()].map((r) => figures(r, state.start, end));
      canvases.sort((a, b) => b.frames - a.frames);
      const main = canvases[0] || { frames: 0, fps: 0, medianMs: null, p5Ms: null, p95Ms: null, longestMs: round(end - state.start, 1), api: null };
      return {
        frames: main.frames,
        seconds: round(seconds, 3),
        fps: main.fps,
        medianMs: main.medianMs,
        p5Ms: main.p5Ms,
        p95Ms: main.p95Ms,
        longestMs: main.longestMs,
        pending: canvases.reduce((n, c) => n + c.pending, 0),
        api: main.api,
        callbacks: state.callbacks,
        callbacksFps: round(seconds > 0 ? state.callbacks / seconds : 0, 3),
        ticks: state.ticks,
        totalFrames: canvases.reduce((n, c) => n + c.frames, 0),
        canvases,
      };
    },
  };
  Object.defineProperty(window, "__frameCounter", { value: counter, configurable: true });
})();
