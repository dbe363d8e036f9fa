// mount()'s options and the parameters' values as pages write them: reading, clamping with a
// console warning.

import { optionTable, presetTable } from "./wavepool.js";

/** Options understood by mount(), with defaults. Parameter names from `params()` are accepted too. */
export const DEFAULT_OPTIONS = Object.freeze({
  backend: "auto", // "auto" | "webgpu" | "webgl2"
  float: "auto", // "none": simulate on the CPU and keep 8-bit caustics, as without float render targets
  // meshSize, causticsSize: ranges and defaults from the core's optionTable()
  controls: true, // show the controls under the canvas
  maxPixelRatio: 2, // cap on devicePixelRatio for the canvas's backing store
  maxPixels: 1920 * 1080, // cap on the canvas's backing pixels (width * height)
  aspect: 4 / 3, // width / height when the element has no height of its own
  maxFps: 0, // cap on drawn frames per second (1-240; 0: as many as the browser and GPU give)
  camera: null, // "yaw,pitch,distance" (degrees, degrees, m) to start from; null: the default view
  preset: null, // a named starting state from presets(): its values, then the page's own options
  sketch: null, // what was drawn with the pointer (the tank's walls and ruler), as shareLink() writes it
  lang: null, // the language of the controls ("cs", "sr-Latn", ...; i18n.js); null: the page's or the browser's
  lazy: true, // start when scrolled near the viewport (false: at once); see context-budget.js
});

/** The `aspect` option (width / height) as mount() reads it before the core has loaded, so the
 * pool's space is reserved at once; readOptions() warns about a bad value. */
export function readAspect(options) {
  const v = Number(options && options.aspect);
  return Number.isFinite(v) ? Math.min(ASPECT_RANGE[1], Math.max(ASPECT_RANGE[0], v)) : DEFAULT_OPTIONS.aspect;
}

/** Least and greatest `aspect` (width / height). */
const ASPECT_RANGE = [0.25, 4];

export function warn(message) {
  console.warn(`wavepool: ${message}`);
}

function clampNumber(name, value, min, max, fallback) {
  const v = Number(value);
  if (!Number.isFinite(v)) {
    warn(`option ${name} = ${value} is not a number; using ${fallback}`);
    return fallback;
  }
  if (v < min || v > max) {
    const c = Math.min(max, Math.max(min, v));
    warn(`option ${name} = ${v} is outside [${min}, ${max}]; using ${c}`);
    return c;
  }
  return v;
}

// Splits user options into demo options and parameter values, clamping and warning.
export function readOptions(options, table) {
  const out = { ...DEFAULT_OPTIONS, params: {} };
  const created = new Map(optionTable().map((o) => [o.name, o]));
  for (const o of created.values()) out[o.name] = o.default;
  const names = new Set(table.map((p) => p.name));
  for (const [key, value] of Object.entries(options || {})) {
    if (key === "params" && value && typeof value === "object") {
      Object.assign(out.params, value);
    } else if (names.has(key)) {
      out.params[key] = value;
    } else if (key === "backend") {
      const b = String(value).toLowerCase();
      if (["auto", "webgpu", "webgl2"].includes(b)) out.backend = b;
      else warn(`backend "${value}" is not auto, webgpu or webgl2; using auto`);
    } else if (key === "float") {
      const f = String(value).toLowerCase();
      if (["auto", "none"].includes(f)) out.float = f;
      else warn(`float "${value}" is not auto or none; using auto`);
    } else if (created.has(key)) {
      const o = created.get(key);
      out[key] = Math.round(clampNumber(key, value, o.min, o.max, o.default));
    } else if (key === "controls" || key === "lazy") {
      out[key] = !(value === false || value === 0 || value === "0" || value === "false");
    } else if (key === "maxPixelRatio") {
      out.maxPixelRatio = clampNumber(key, value, 0.25, 4, DEFAULT_OPTIONS.maxPixelRatio);
    } else if (key === "maxPixels") {
      out.maxPixels = clampNumber(key, value, 64 * 64, 8192 * 8192, DEFAULT_OPTIONS.maxPixels);
    } else if (key === "maxFps") {
      out.maxFps = Number(value) === 0 ? 0 : clampNumber(key, value, 1, 240, DEFAULT_OPTIONS.maxFps);
    } else if (key === "preset") {
      const preset = presetTable().find((p) => p.name === String(value).toLowerCase());
      if (preset) out.preset = preset;
      else warn(`preset "${value}" is not one of ${presetTable().map((p) => p.name).join(", ")}; ignored`);
    } else if (key === "camera") {
      const v = (Array.isArray(value) ? value : String(value).split(",")).map(Number);
      if (v.length === 3 && v.every(Number.isFinite)) out.camera = v;
      else warn(`camera "${value}" is not "yaw,pitch,distance" (three numbers); using the default view`);
    } else if (key === "lang") {
      out.lang = value ? String(value) : null; // chosen and checked before (i18n.js, at mount)
    } else if (key === "sketch") {
      out.sketch = String(value); // read by the core, which warns if it cannot
    } else if (key === "aspect") {
      out.aspect = clampNumber(key, value, ...ASPECT_RANGE, DEFAULT_OPTIONS.aspect);
    } else {
      warn(`unknown option "${key}" ignored; options: ${[...Object.keys(DEFAULT_OPTIONS), ...created.keys()].join(", ")}, ` +
        `and the parameters ${[...names].join(", ")}`);
    }
  }
  return out;
}

// Turns "true"/"false"/"1.5" from a URL or attribute, or a choice's name ("duck" for
// objects), into a number for set(). `spec`: the parameter's table entry, if known.
export function toNumber(value, spec) {
  if (spec && spec.kind === "choice" && typeof value === "string") {
    const named = (name) => spec.choices[spec.choiceNames.indexOf(name.trim().toLowerCase())];
    if (named(value) !== undefined) return named(value);
    // A set of choices ("ball,duck" for objects) adds their values, if that is a choice too.
    const sum = value.split(",").reduce((total, name) => total + named(name), 0);
    if (value.includes(",") && spec.choices.includes(sum)) return sum;
  }
  if (value === true || value === "true" || value === "on") return 1;
  if (value === false || value === "false" || value === "off") return 0;
  return Number(value);
}

const CAMEL_OPTIONS = new Set([...Object.keys(DEFAULT_OPTIONS), "meshSize", "causticsSize"]);

/** An attribute's name as a mount option or parameter name: `max-fps` -> `maxFps`, `wave-speed` -> `wave_speed`. */
export function optionName(attribute) {
  const camel = attribute.replace(/-([a-z])/g, (_, c) => c.toUpperCase());
  return CAMEL_OPTIONS.has(camel) ? camel : attribute.replace(/-/g, "_");
}

