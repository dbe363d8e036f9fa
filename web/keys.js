// Which keys stay in the pool: the one place that decides. A key pressed in the pool (on its
// canvas or in one of its controls) goes no further than the pool's shadow root when the pool
// uses it, so the host page (a slide deck turning pages on arrows and Space, a docs site's
// search shortcut) does not act on it as well. Every other key (Tab, Esc, the host's own
// shortcuts, keys with Ctrl/Alt/Meta) reaches the host as usual.

const ARROWS = ["ArrowLeft", "ArrowRight", "ArrowUp", "ArrowDown"];
const JUMPS = ["Home", "End", "PageUp", "PageDown"];

/** Keys that move a closed select's choice (the Preset select waits for Enter after them). */
export const BROWSING_KEYS = [...ARROWS, ...JUMPS];

/** The keys a focused control of each kind uses (what browsers do with them). */
const CONTROL_KEYS = {
  range: [...ARROWS, ...JUMPS],
  checkbox: [" "],
  button: [" ", "Enter"],
  summary: [" ", "Enter"],
  select: [...ARROWS, ...JUMPS, " ", "Enter"], // and typing a choice's first letters
};

function controlKind(element) {
  if (!element || !element.tagName) return null;
  const tag = element.tagName.toLowerCase();
  if (tag === "input") return element.type === "range" || element.type === "checkbox" ? element.type : null;
  return tag in CONTROL_KEYS ? tag : null;
}

/**
 * Whether the pool keeps `event`, a key pressed with `target` focused: the canvas's own key
 * handler (input.js) used it, which it says by cancelling the key's default action, or the
 * focused control uses it.
 */
export function poolKeeps(target, event) {
  if (event.key === "Tab" || event.key === "Escape") return false;
  if (event.ctrlKey || event.metaKey || event.altKey) return false;
  if (event.defaultPrevented) return true;
  const kind = controlKind(target);
  if (!kind) return false;
  return CONTROL_KEYS[kind].includes(event.key) || (kind === "select" && event.key.length === 1);
}

/**
 * Stops the keys the pool keeps at its shadow root: keydown, and the keypress and keyup of
 * the same key. Returns the function that takes the guard away.
 */
export function keepKeys(shadow) {
  // Physical keys (event.code) whose keydown was kept, until their keyup: a key's value can
  // change between the two (Shift let go first), its position cannot.
  const held = new Set();
  const guard = (event) => {
    const target = event.composedPath()[0];
    if (event.type === "keydown") {
      if (!poolKeeps(target, event)) return;
      held.add(event.code);
    } else if (event.type === "keyup") {
      if (!held.delete(event.code)) return;
    } else if (!held.has(event.code) && !poolKeeps(target, event)) {
      return;
    }
    event.stopPropagation();
  };
  const forget = () => held.clear(); // focus gone: those keyups go to the page
  const types = ["keydown", "keypress", "keyup"];
  for (const type of types) shadow.addEventListener(type, guard);
  shadow.addEventListener("focusout", forget);
  return () => {
    types.forEach((type) => shadow.removeEventListener(type, guard));
    shadow.removeEventListener("focusout", forget);
  };
}
