// The frame loop: drawing paced to the GPU and the page's maxFps, frame statistics, and
// recovering from a lost device: methods of the demo (demo.js).

/** Frame statistics are over this window up to now (ms). */
const STATS_WINDOW_MS = 2000;
/** Drawn frames this far apart (ms), RESCUE_FRAMES in a row, make the demo do less work:
 * a device that slow freezes the page and may get it given up by the browser. */
const RESCUE_MS = 1000;
const RESCUE_FRAMES = 3;

/**
 * Drawn frames over the last STATS_WINDOW_MS up to `now` (ms): `fps` (frames drawn in the
 * window / its length; the window starts no earlier than the loop did), `frameMs` (median
 * interval between them) and `longestFrameMs` (longest interval, counting the wait since
 * the last frame, so a freeze shows while it lasts). `times`: drawn frames' times, oldest first.
 */
export function frameStats(times, since, now) {
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

/** The demo's frame loop and device recovery. */
export const frameLoopMethods = {

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
  },

  _tick(time) {
    this._frame = 0;
    if (this._dead || !this._core) return;
    // Paced: while the GPU is still on the last frame, this animation frame draws nothing
    // (a slow GPU gets fewer frames rather than a growing queue of them).
    if (!this._core.canDraw() || (this._last && time - this._last < this._minFrameMs())) {
      this._run();
      return;
    }
    if (this._element.checkVisibility && !this._element.checkVisibility({ opacityProperty: true, visibilityProperty: true })) {
      // Hidden by its page while still in the viewport (a deck's other slides at opacity 0):
      // no frame and no simulated time until it shows again, looked at every animation frame.
      this._last = 0;
      this._frames.length = 0; // the time hidden is no interval between drawn frames
      this._simTimes.length = 0;
      this._run();
      return;
    }
    // The backing store follows the canvas's size on screen, transforms included (a slide
    // deck scaling its slides, its overview), which no resize observer reports.
    this._sizeCanvas(this._canvas);
    if (!this._prepared) {
      // The start-up's work, a piece per animation frame (no long task): see WebDemo.prepare.
      try {
        this._prepared = this._core.prepare(this._canvas.width, this._canvas.height);
      } catch (error) {
        this._recover(error);
        return;
      }
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
    else {
      const interval = time - this._frames[this._frames.length - 1];
      this._costsNote(time, interval);
      this._readingsNote(time);
      this._pickedNote(time);
      this._rescue(interval);
    }
    this._frames.push(time);
    this._framesDrawn++;
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
  },

  // Frames over a second apart, several in a row: first the resolution goes automatic, then
  // the simulation grid halves (down to its smallest), each with a notice.
  _rescue(interval) {
    // (A frame cap of about one a second is the page's wish, not a device too slow.)
    const slow = interval > Math.max(RESCUE_MS, 2 * this._minFrameMs());
    this._slowFrames = slow ? (this._slowFrames || 0) + 1 : 0;
    if (this._slowFrames < RESCUE_FRAMES) return;
    this._slowFrames = 0;
    if (this.get("quality") !== 0) {
      this.set("quality", 0);
      this._notice(this._words.page("notice-slow-resolution"));
      return;
    }
    const size = this.get("sim_size");
    const smallest = Math.min(...this._table.find((p) => p.name === "sim_size").choices);
    if (size > smallest) {
      const given = this.set("sim_size", size / 2);
      this._notice(this._words.page("notice-slow-grid", { cells: this._words.number(given, 0) }));
    }
  },

  // Shortest interval between drawn frames (ms) under the maxFps option; a few ms short of
  // 1000 / maxFps, since animation frames come at the display's own ticks.
  _minFrameMs() {
    return this._opts.maxFps ? 1000 / this._opts.maxFps - 4 : 0;
  },

  // A lost device is recreated on a fresh canvas; a loss within 10 s of the last restart
  // (or any other error) is reported instead, so a failing device cannot loop.
  async _recover(error) {
    const text = String(error && error.message ? error.message : error);
    const now = performance.now();
    if (!/lost/.test(text) || now - this._lastRestart < 10000) {
      this._fail(this.text("error-stopped", { reason: text }));
      return;
    }
    this._lastRestart = now;
    this._restarts++;
    const saved = this._saveState();
    this._detachCore();
    try {
      this._status(this.text("status-device-lost"));
      await this._restart(saved);
    } catch (e) {
      this._fail(this.text("error-device-lost", { reason: e.message || e }));
    }
  },

  /** The parameters and camera, to carry across a new context. */
  _saveState() {
    const core = this._core;
    return { params: this._table.map((p) => [p.name, core.get(p.name)]), camera: core.camera(), sketch: core.sketch() };
  },

  /** A new context with `saved` parameters and camera (the water starts calm), running. */
  async _restart(saved) {
    await this._start();
    for (const [name, v] of saved.params) this._core.set(name, v);
    this._core.setCamera(...saved.camera);
    if (saved.sketch) this._core.setSketch(saved.sketch);
    this._refreshControls();
    this._status(null);
    this._run();
  }
};
