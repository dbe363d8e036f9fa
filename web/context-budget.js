// Many demos on one page: lazy start and a budget of GPU contexts.
//
// Browsers keep only a few WebGL contexts per page (Chromium 16, then it drops the oldest
// without asking) and every WebGPU device holds its own memory, so a course page with a
// dozen pools must not hold a dozen contexts. A demo asks for a context when it comes near
// the viewport; at most MAX_GPU_CONTEXTS hold one at a time. When one more is wanted and none
// is free, the holder that left the viewport longest ago gives its context up, showing its
// last frame as a still until it comes near again; a demo that finds every holder on screen
// waits until one scrolls away.
//
// A demo handed to this module has: `_near` (it is within NEAR_MARGIN_PX of the viewport),
// `_leftAt` (ms, when it last stopped being near), `_eager` (asks even while far: lazy off),
// `_suspendable()` (it holds a running context it can give up now), `_suspend()` (gives it
// up, calling releaseContext) and `_blocked()` (told when it waits on screen).

/** Demos on a page that may hold a GPU context at once. */
export const MAX_GPU_CONTEXTS = 8;
/** How far beyond the viewport's edges (CSS px) a demo counts as near: it starts before it is seen. */
export const NEAR_MARGIN_PX = 200;

const holders = new Set(); // demos holding a context (or creating one)
const waiting = []; // demos asking for one, first come first served

/** Resolves once `demo` may create a GPU context. */
export function acquireContext(demo) {
  if (holders.has(demo)) return Promise.resolve();
  return new Promise((resolve) => {
    waiting.push({ demo, resolve });
    grant();
  });
}

/** `demo` no longer holds (or waits for) a context; a wait it had ends (the demo then sees it is destroyed). */
export function releaseContext(demo) {
  const i = waiting.findIndex((w) => w.demo === demo);
  if (i >= 0) waiting.splice(i, 1)[0].resolve();
  if (holders.delete(demo)) grant();
}

/** Demos holding a context now. */
export function contextsHeld() {
  return holders.size;
}

/** Hands contexts to waiting demos that are near (or eager), freeing far holders' if need be. */
function grant() {
  for (const w of [...waiting]) {
    if (!w.demo._near && !w.demo._eager) continue;
    if (holders.size >= MAX_GPU_CONTEXTS) {
      const victim = [...holders]
        .filter((d) => !d._near && d._suspendable())
        .reduce((a, b) => (a && a._leftAt <= b._leftAt ? a : b), null);
      if (!victim) {
        // Every holder is near or starting: wait for one to scroll away.
        for (const x of waiting) if (x.demo._near) x.demo._blocked();
        return;
      }
      victim._suspend(); // calls releaseContext(victim), which re-enters grant(): done there
      return;
    }
    waiting.splice(waiting.indexOf(w), 1);
    holders.add(w.demo);
    w.resolve();
  }
}

/**
 * Calls `onChange(near)` whenever `element` comes within NEAR_MARGIN_PX of the viewport or
 * leaves it (once at the start), then lets waiting demos try again. Returns the disconnect.
 */
export function watchNear(element, onChange) {
  const observer = new IntersectionObserver(
    (entries) => {
      onChange(entries[entries.length - 1].isIntersecting);
      grant();
    },
    { rootMargin: `${NEAR_MARGIN_PX}px` },
  );
  observer.observe(element);
  return () => observer.disconnect();
}
