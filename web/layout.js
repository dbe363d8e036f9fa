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

/** Least height (CSS px) of the picture when fitted (also `.stage`'s min-height in wavepool.css). */
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

/** The factor the page scales `element` by on screen (transforms), 1 when it cannot tell. */
function screenScale(element) {
  const scale = element.offsetWidth ? element.getBoundingClientRect().width / element.offsetWidth : 1;
  return scale > 0 && Number.isFinite(scale) ? scale : 1;
}

/** Height (layout px) that `box`'s content other than `element` takes. */
function othersIn(box, element) {
  let child = element;
  while (child.parentElement !== box) child = child.parentElement;
  const scale = screenScale(box);
  const inside = box.getBoundingClientRect().top + box.clientTop * scale; // the box's padding edge
  const below = (e) => (e.getBoundingClientRect().bottom - element.getBoundingClientRect().bottom) / scale;
  if (child === element) {
    // Above it: its offset in the box (padding included); below it: its later siblings and
    // the box's bottom padding.
    let after = 0;
    for (let s = element.nextElementSibling; s; s = s.nextElementSibling) after = Math.max(after, below(s));
    const top = (element.getBoundingClientRect().top - inside) / scale + box.scrollTop;
    return top + after + parseFloat(getComputedStyle(box).paddingBottom);
  }
  // The box's child holding the pool: its other content, and where it starts unless the host
  // places it itself (absolutely, as reveal.js centres its slides).
  const placed = ["absolute", "fixed"].includes(getComputedStyle(child).position);
  const top = placed ? 0 : (child.getBoundingClientRect().top - inside) / scale + box.scrollTop;
  return top + child.offsetHeight - element.offsetHeight;
}

/** Whether `box` scrolls its content (a pane, treated as a screen) rather than holding it. */
function scrolls(box) {
  return /auto|scroll/.test(getComputedStyle(box).overflowY);
}

/** The drawer's height with its panel folded (its summary, padding and border). */
function foldedHeight(drawer) {
  return drawer.offsetHeight - (drawer.open ? drawer.querySelector(".panel").offsetHeight : 0);
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
      this._forgetBox(); // the page's layout may have changed which box holds the pool
      this._fit();
    };
    window.addEventListener("resize", this._onWindowResize);
    this._fit();
  },

  /** Looks for the pool's box again at the next fit (moved in the page, or the page changed). */
  _forgetBox() {
    if (this._box && this._fitObserver) this._fitObserver.unobserve(this._box);
    this._box = undefined;
  },

  /** Sizes the picture (and an open drawer's panel) to the room the pool has. */
  _fit() {
    if (this._fills || !this._element.isConnected || this._element.offsetWidth === 0) return; // not shown yet
    if (this._box && !this._box.contains(this._element)) this._forgetBox(); // moved elsewhere
    if (this._box === undefined) {
      this._box = findBox(this._element, this._stage);
      if (this._box) this._fitObserver.observe(this._box);
    }
    const box = this._box;
    const pane = box && scrolls(box);
    const drawer = this._root.querySelector(".controls");
    const panel = drawer && drawer.querySelector(".panel");
    let height;
    if (box && !pane) {
      // Everything in the box: the picture, the gap and the drawer (folded, or open and scrolling).
      const gap = drawer ? parseFloat(getComputedStyle(this._root).rowGap) || 0 : 0;
      const folded = drawer ? foldedHeight(drawer) : 0;
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
      // A scrolling page (or pane): the picture in the first screen below its top in the
      // document (the whole screen when it starts further down), wherever it is scrolled to.
      // In layout pixels (the page may scale the pool on screen).
      const scale = screenScale(this._element);
      const rect = this._element.getBoundingClientRect();
      const top = pane
        ? (rect.top - box.getBoundingClientRect().top) / scale + box.scrollTop
        : (rect.top + window.scrollY) / scale;
      const screen = pane ? box.clientHeight : window.innerHeight / scale;
      height = top < screen ? screen - top - 8 : screen;
      this._root.classList.remove("boxed");
    }
    setStyle(this._stage, "maxWidth", `${Math.floor(Math.max(MIN_FIT_PX, height) * this._aspect)}px`);
  },

  /** Whether the drawer opens at the start: room beside the groups, and room under the picture. */
  _drawerStartsOpen(drawer) {
    if (this._element.clientWidth < NARROW_PX) return false;
    const folded = foldedHeight(drawer);
    let room = null;
    if (this._fills) room = this._element.clientHeight - folded;
    else if (this._box && !scrolls(this._box)) room = this._box.clientHeight - othersIn(this._box, this._element) - folded;
    return room === null || drawer.querySelector(".panel").scrollHeight <= (1 - PICTURE_SHARE) * room;
  },

  _stopFitting() {
    if (this._fitObserver) this._fitObserver.disconnect();
    if (this._onWindowResize) window.removeEventListener("resize", this._onWindowResize);
    this._fitObserver = this._onWindowResize = null;
  }
};
