// Sizing the pool to where a page puts it: methods of the demo (demo.js).
//
// - An element with a height of its own (a grid cell, `style="height: 400px"`) is filled: the
//   picture takes what the drawer leaves, and an open drawer scrolls inside (wavepool.css).
// - In a box whose height does not follow its content (a reveal.js slide, a fixed panel) the
//   picture, the drawer's summary and, when open, the drawer (scrolling) fit in what the box's
//   other content leaves; the drawer starts folded when it would not fit. The room is measured
//   in layout pixels, so it is the same however the host scales or centres the slide and
//   whichever way the slide was reached.
// - On a scrolling page the picture fits the first screen below its top; the drawer follows.
// Without a height of its own the picture keeps the `aspect` option's shape.

/** Least height (CSS px) of the picture when fitted. */
const MIN_FIT_PX = 120;
/** Share of a box's room the picture keeps while the drawer is open in it. */
const PICTURE_SHARE = 0.55;
/** Below this width (CSS px) the drawer starts folded, so the pool comes first on a phone. */
const NARROW_PX = 600;

/**
 * The nearest ancestor of `element` whose height does not follow its content, found by growing
 * `stage` for a moment; null when every ancestor grows with it (the page scrolls).
 */
function findBox(element, stage) {
  const chain = [];
  for (let e = element.parentElement; e && e !== document.body && e !== document.documentElement; e = e.parentElement) {
    chain.push(e);
  }
  const before = chain.map((e) => e.clientHeight);
  const old = stage.style.minHeight;
  stage.style.minHeight = `${stage.offsetHeight + 64}px`;
  const after = chain.map((e) => e.clientHeight);
  stage.style.minHeight = old;
  const i = before.findIndex((h, k) => h > 0 && after[k] === h);
  return i < 0 ? null : chain[i];
}

/** Height (layout px) that `box`'s content other than `element` takes. */
function othersIn(box, element) {
  let child = element;
  while (child.parentElement !== box) child = child.parentElement;
  if (child === element) return box.scrollHeight - element.offsetHeight;
  // The box's child holding the pool: its other content, and where it starts unless the host
  // places it itself (absolutely, as reveal.js centres its slides).
  const placed = ["absolute", "fixed"].includes(getComputedStyle(child).position);
  const scale = box.offsetHeight ? box.getBoundingClientRect().height / box.offsetHeight : 1;
  const top = placed ? 0 : (child.getBoundingClientRect().top - box.getBoundingClientRect().top) / scale;
  return top + child.offsetHeight - element.offsetHeight;
}

/** Sets a style property only when it changes (so a fit that settles makes no more layout). */
function setStyle(element, property, value) {
  if (element.style[property] !== value) element.style[property] = value;
}

/** The demo's methods that size it to its place. */
export const layoutMethods = {

  /** Keeps the pool fitted to its place from now on (while it has no height of its own). */
  _fitStage() {
    // Refitted when the pool, its box or the window change size (and when shown: _run).
    this._fitObserver = new ResizeObserver(() => this._fit());
    this._fitObserver.observe(this._element);
    this._onWindowResize = () => {
      this._box = undefined; // the page's layout may have changed which box holds the pool
      this._fit();
    };
    window.addEventListener("resize", this._onWindowResize);
    this._fit();
  },

  /** Sizes the picture (and an open drawer's panel) to the room the pool has. */
  _fit() {
    if (this._fills || !this._element.isConnected || this._element.offsetWidth === 0) return; // not shown yet
    if (this._box === undefined) {
      this._box = findBox(this._element, this._stage);
      if (this._box) this._fitObserver.observe(this._box);
    }
    const box = this._box;
    const scrolls = box && /auto|scroll/.test(getComputedStyle(box).overflowY);
    const drawer = this._root.querySelector(".controls");
    const panel = drawer && drawer.querySelector(".panel");
    let height;
    if (box && !scrolls) {
      // Everything in the box: the picture, the gap and the drawer (folded, or open and scrolling).
      const gap = drawer ? parseFloat(getComputedStyle(this._root).rowGap) || 0 : 0;
      const folded = drawer ? drawer.offsetHeight - (drawer.open ? panel.offsetHeight : 0) : 0;
      const room = box.clientHeight - othersIn(box, this._element) - 2;
      height = room - (drawer ? gap + folded : 0);
      this._root.classList.add("boxed");
      if (drawer && drawer.open) {
        const picture = Math.max(height - panel.scrollHeight, PICTURE_SHARE * height);
        setStyle(panel, "maxHeight", `${Math.max(0, Math.floor(height - picture))}px`);
        height = picture;
      } else if (panel) {
        setStyle(panel, "maxHeight", "");
      }
    } else {
      // A scrolling page (or pane): the picture in the first screen below its top.
      const screen = scrolls ? box.getBoundingClientRect() : { top: 0, height: window.innerHeight };
      const top = this._element.getBoundingClientRect().top - screen.top;
      const scale = this._element.getBoundingClientRect().width / this._element.offsetWidth || 1;
      const below = top < screen.height ? screen.height - top - 8 : screen.height;
      height = Math.min(screen.height, below) / scale;
      this._root.classList.remove("boxed");
    }
    setStyle(this._stage, "maxWidth", `${Math.floor(Math.max(MIN_FIT_PX, height) * this._aspect)}px`);
  },

  /** Whether the drawer opens at the start: room beside the groups, and room under the picture. */
  _drawerStartsOpen(drawer) {
    if (this._element.clientWidth < NARROW_PX) return false;
    const panel = drawer.querySelector(".panel");
    const folded = drawer.offsetHeight - (drawer.open ? panel.offsetHeight : 0);
    let room = null;
    if (this._fills) room = this._element.clientHeight - folded;
    else if (this._box && !/auto|scroll/.test(getComputedStyle(this._box).overflowY)) {
      room = this._box.clientHeight - othersIn(this._box, this._element) - folded;
    }
    return room === null || panel.scrollHeight <= (1 - PICTURE_SHARE) * room;
  },

  _stopFitting() {
    if (this._fitObserver) this._fitObserver.disconnect();
    if (this._onWindowResize) window.removeEventListener("resize", this._onWindowResize);
    this._fitObserver = this._onWindowResize = null;
  }
};
