// Which keys stay in the pool: the one place that decides. A key pressed in the pool (on its
// canvas or in one of its controls) goes no further than the pool's shadow root when the pool
// uses it, so the host page (a slide deck turning pages on arrows and Space, a docs site's
// search shortcut) does not act on it as well. Every other key (Tab, Esc, the host's own
// shortcuts, keys with Ctrl/Alt/Meta) reaches the host as usual.

const ARROWS = ["ArrowLeft", "ArrowRight", "ArrowUp", "ArrowDown"];
const JUMPS = ["Home", "End", "PageUp", "PageDown"];

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
  const held = new Set(); // keys whose keydown was kept, until their keyup
  const guard = (event) => {
    const target = event.composedPath()[0];
    if (event.type === "keydown") {
      if (!poolKeeps(target, event)) return;
      held.add(event.key);
    } else if (event.type === "keyup") {
      if (!held.delete(event.key)) return;
    } else if (!held.has(event.key) && !poolKeeps(target, event)) {
      return;
    }
    event.stopPropagation();
  };
  const types = ["keydown", "keypress", "keyup"];
  for (const type of types) shadow.addEventListener(type, guard);
  return () => types.forEach((type) => shadow.removeEventListener(type, guard));
}
