// The page's budget of GPU contexts (context-budget.js): giving the context up when scrolled
// away (showing a still of the last frame) and taking one again when near; and the stills a
// print shows: methods of the demo (demo.js).

import { acquireContext, releaseContext } from "./context-budget.js";

/** The demo's methods for suspending, waking and stills. */
export const suspendMethods = {

  _nearChanged(near) {
    this._near = near;
    if (!near) this._leftAt = performance.now();
    else if (this._suspended) this._wake();
  },

  /** Holds a running context it can give up now (not while one is being created). */
  _suspendable() {
    return !!this._core && !this._dead && !this._waking;
  },

  /** Every context is taken by demos on screen: say so until one scrolls away. */
  _blocked() {
    if (!this._suspended && !this._core) {
      this._status(this.text("status-waiting"));
    }
  },

  /** Gives the context up, keeping the last frame on show and the parameters and camera. */
  _suspend() {
    this._saved = this._saveState();
    this._still = this._copyFrame("still");
    this._detachCore();
    this._looping = false;
    this._suspended = true;
    this._element.dataset.suspended = "true";
    releaseContext(this);
  },

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
      this._fail(this.text("error-restart", { reason: e.message || e }));
    } finally {
      this._waking = false;
    }
  },

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
  },

  // Puts a still of the current frame over the GPU canvas (for printing); `false` takes it away.
  _printShot(show = true) {
    const old = this._stage.querySelector(".print-shot");
    if (old) old.remove();
    if (show && this._core && this._canvas) this._copyFrame("print-shot");
  },

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
};
