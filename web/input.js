// Input: pointer drags (drops, orbiting, moving a body, the split divider), pinch and wheel
// zoom, keys, resizes and visibility: methods of the demo (demo.js).

/** The demo's event listeners. */
export const inputMethods = {
  _on(target, type, listener, options) {
    target.addEventListener(type, listener, options);
    this._cleanups.push(() => target.removeEventListener(type, listener, options));
  },

  _listen() {
    const canvas = this._canvas;
    const resize = new ResizeObserver(() => this._sizeCanvas(canvas));
    resize.observe(canvas);
    const onScreen = new IntersectionObserver((entries) => {
      this._onScreen = entries[entries.length - 1].isIntersecting;
      if (this._onScreen) this._fit(); // shown (a slide come up): its room may be new
      this._run();
    });
    onScreen.observe(this._element);
    this._cleanups.push(() => resize.disconnect(), () => onScreen.disconnect());
    this._on(document, "visibilitychange", () => {
      this._visible = !document.hidden;
      this._run();
    });
    this._listenPointers(canvas);
    this._listenKeys(canvas);
  },

  // Drags (one pointer), pinches (two) and the wheel on the canvas.
  _listenPointers(canvas) {
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
  },

  // Keys act only while the canvas has focus, so the host page keeps its shortcuts.
  _listenKeys(canvas) {
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
};
