// Types of wavepool's embedding module (embed.js): mount(), the demo's handle, <wave-pool>
// and its events. The parameters, their choices, the presets and the creation options come
// from tables.d.ts, which scripts/package.mjs writes from the core's own tables at each build.

import type {
  CreationAttributes,
  CreationOptions,
  ParamAttributes,
  ParamName,
  ParamSpec,
  ParamValues,
  PresetName,
  PresetSpec,
  SceneName,
} from "./tables.js";

// Every table type is the module's too.
export type * from "./tables.js";

/** Options of mount() besides the parameters (all optional; bad values are clamped with a console warning). */
export interface DemoOptions extends CreationOptions {
  /** Which GPU interface to use: WebGPU when the browser gives an adapter, else WebGL2 ("auto"). Default "auto". */
  backend?: "auto" | "webgpu" | "webgl2";
  /** "none" takes the path for devices without float render targets (the water simulated on the CPU, 8-bit caustics). Default "auto". */
  float?: "auto" | "none";
  /** Show the controls under the picture. Default true. */
  controls?: boolean | 0 | 1 | "true" | "false";
  /** Cap on devicePixelRatio for the canvas's backing store (0.25–4). Default 2. */
  maxPixelRatio?: number;
  /** Cap on the canvas's backing pixels, width × height (4096–67108864). Default 1920 × 1080. */
  maxPixels?: number;
  /** Width / height of the picture when the element has no height of its own (0.25–4). Default 4/3. */
  aspect?: number;
  /** Cap on drawn frames per second (1–240; 0: no cap). Default 0. */
  maxFps?: number;
  /** "yaw,pitch,distance" (degrees, degrees, m) or the three numbers to start the camera from. Default: the scene's view. */
  camera?: string | [number, number, number];
  /** A named starting state: its parameter values and view, then the page's own options. */
  preset?: PresetName;
  /** What was drawn with the pointer in the ripple tank (walls, erasures, the ruler), as `shareLink()` writes it: e.g. "W-120,40,-120,200_R-200,0,200,0" (whole mm from the tray's middle). */
  sketch?: string;
  /** The language of the controls, notices and help: one of `languages` ("en", "cs", "de", "es", "ru", "sr-Latn", "sr-Cyrl"; "sr" is Cyrillic, "cs-CZ" is "cs"). Default: the element's or the page's `lang`, else the browser's preferred languages, else English. */
  lang?: LanguageTag | string;
  /** Start when the element comes within 200 px of the viewport (true), or at once (false). Default true. */
  lazy?: boolean | 0 | 1 | "true" | "false";
  /** Parameter values, as an object of their own (the same as giving them beside the options). */
  params?: Partial<ParamValues>;
}

/** What mount() takes: the options above and any parameter's starting value. */
export type MountOptions = DemoOptions & Partial<ParamValues>;

/** A position [x, y, z] in m, or null when the body is not in the scene. */
export type Position = [number, number, number] | null;

/** What stats() returns while the demo holds its GPU context. */
export interface Stats {
  /** false here (see SuspendedStats). */
  suspended: false;
  /** Frames drawn per second over the last 2 s. */
  fps: number;
  /** Median interval between drawn frames (ms). */
  frameMs: number;
  /** Longest interval between drawn frames, the wait since the last one included (ms). */
  longestFrameMs: number;
  /** Simulated seconds per wall second over those frames (1: real time). */
  simSpeed: number;
  /** Time from mount() to the first frame on screen (ms). */
  firstFrameMs: number | null;
  /** Frames drawn since the demo started. */
  framesDrawn: number;
  /** Bytes of the WebAssembly module's memory. */
  wasmMemoryBytes: number | null;
  /** GPU devices recreated after a loss. */
  restarts: number;
  /** Demos on the page that hold a GPU context. */
  contextsOnPage: number;
  /** The GPU interface in use. */
  backend: "webgpu" | "webgl2";
  /** The adapter's name, where the browser tells it ("" otherwise). */
  adapter: string;
  /** The canvas's colour format (on WebGPU the browser's preferred one). */
  canvasFormat: string;
  /** Cells per side of the simulation grid. */
  simSize: number;
  /** Where the water is simulated. */
  simEngine: "gpu" | "cpu";
  /** Simulated time (s). */
  simTime: number;
  /** The scene drawn. */
  scene: SceneName;
  /** Mean water level (m), read back a frame or two late. */
  meanLevel: number;
  /** Largest |height| of the water (m), read back a frame or two late. */
  maxAbsHeight: number;
  /** The canvas's backing size (px). */
  width: number;
  height: number;
  /** Fraction of the canvas's width and height the scene is drawn at. */
  renderScale: number;
  spherePosition: Position;
  duckPosition: Position;
  /** Every kind of floating body's position, by the kind's name. */
  bodies: Record<string, Position>;
  /** What the shown scene's instruments read, by name: the tank's "probe frequency" (Hz, once it has seen two periods), "probe swing" (mm) and "ruler" (mm). */
  readings: Record<string, { value: number; unit: string }>;
  /** Volume of the bodies under the water (m³). */
  submergedVolume: number;
  /** GPU time per render mode (ms), where the browser measures it; null otherwise. */
  gpuMs: { raytraced: number | null; flat: number | null; split: number | null } | null;
  /** The latest measured frame's GPU time per stage of the scene drawn (ms), where the browser measures it: the pool's simulation, waves, caustics and shading; the sea's simulation, waves, maps (its mirror and whitecaps) and shading. */
  stageMs: PoolStageMs | SeaStageMs | TankStageMs | null;
  /** Why flat water is not drawn now (under the water), or null. */
  flatNote: string | null;
  /** That note's message id in the catalogues (locales/en.ftl), for showing it in the demo's language (`text()`); null with no note. */
  flatNoteId: string | null;
  /** Sizes held to what this device affords. */
  reduced: { name: string; asked: number; given: number }[];
}

/** What stats() returns while the demo has given its GPU context to others. */
export interface SuspendedStats {
  suspended: true;
  fps: 0;
  backend: "webgpu" | "webgl2" | undefined;
  firstFrameMs: number | null;
  restarts: number;
  contextsOnPage: number;
}

/** The settings of what the pointer picked (a tank's dipper): sliders, each with its value. */
export interface PickedSettings {
  /** "Dipper 2", in English. */
  title: string;
  /** The title's message in the page's words ("dipper") and the number it fills in (2). */
  titleId: string;
  number: number;
  settings: {
    name: string;
    label: string;
    group: string;
    unit: string;
    kind: "slider";
    min: number;
    max: number;
    step: number;
    default: number;
    help: string;
    value: number;
    messageId: string;
    groupMessageId: string;
    unitMessageId: string | null;
    choiceMessageIds: string[];
  }[];
}

export interface PoolStageMs { simulation: number; waves: number; caustics: number; shading: number }
/** The sea's frame stages (ms): its maps are the island's mirror and the kept whitecaps. */
export interface SeaStageMs { simulation: number; waves: number; maps: number; shading: number }
/** The ripple tank's stages: its water, (no free waves), the lamp's image on the screen, the picture. */
export interface TankStageMs { simulation: number; waves: number; screen: number; shading: number }

/** The handle mount() resolves to, and <wave-pool>'s `demo` once it is ready. */
export interface WavePool {
  /** A drop at x, z in the scene's water (m; the pool's −1…1, the sea's patch −16…16; outside, clamped with a warning); radius and strength in m as the parameters give them (default: the current ones; the sea grows them with its patch). */
  addDrop(x: number, z: number, radius?: number, strength?: number): void;
  /** Sets a parameter (a choice by name or number); out-of-range values are clamped with a warning. Returns the value in effect. */
  set<K extends ParamName>(name: K, value: ParamValues[K]): number;
  /** A parameter's current value (choices as their numbers). */
  get(name: ParamName): number;
  /** Where scene point (x, y, z) in m appears, in CSS px from the viewport's corner; null when not in view. */
  project(x: number, y: number, z: number): { x: number; y: number } | null;
  /** The parameter table. */
  params(): ParamSpec[];
  /** Back to how the page started: its parameters and camera, calm water. */
  reset(): void;
  /** Starts over from a preset: defaults, then its values and view, calm water. */
  applyPreset(name: PresetName): void;
  /**
   * A link to the demo's page (index.html next to the demo's files) with this demo's
   * parameters and view. The npm package carries no pages: in a bundled app, point
   * setAssetLocation() at a hosted copy of the demo for links that open.
   */
  shareLink(): string;
  /** What was drawn with the pointer in the ripple tank (walls W, erasures E, the ruler R, moved dippers D; whole mm from the tray's middle; dippers' own settings T: number from 0, Hz, mm, degrees), as the share link's `sketch`: e.g. "W-120,40,-120,200_R-200,0,200,0_T1,12.5,0.3,-90"; "" if nothing. */
  sketch(): string;
  /** Replaces what was drawn with `text` (as sketch() gives it); a text that cannot be read changes nothing and warns in the console. */
  setSketch(text: string): void;
  /** The language the demo shows. */
  language(): LanguageTag;
  /** Shows the controls, notices and help in another language (its catalogue is fetched, or `catalogue` is taken: a Fluent text with locales/en.ftl's ids, for a language of the page's own under any tag); the water, the view and the parameters stay. The element then fires `wavepool:language`. */
  setLanguage(tag: LanguageTag | string, catalogue?: string): Promise<void>;
  /** The demo's words in its language: a message of locales/en.ftl ("page-intro", "reset", "reset.title") with its `{ $name }`s filled from `args`; for a page showing them beside the demo. */
  text(id: string, args?: Record<string, string | number>): string;
  /** With the tank's move tool, the dipper last picked (the first until one is) and its own settings; null otherwise. */
  picked(): PickedSettings | null;
  /** Sets a setting of what picked() returns ("frequency" Hz, "amplitude" mm, "phase" degrees), clamped to its range; it goes into sketch(). */
  setPicked(name: string, value: number): void;
  /** An <iframe> of the demo's frame page (embed.html, found as shareLink()'s page) with this demo's parameters and view. */
  embedCode(): string;
  /** The camera as [yaw, pitch, distance] (degrees, degrees, m). */
  camera(): [number, number, number];
  /** Moves the camera (clamped to the scene's limits, with a warning). */
  setCamera(yaw: number, pitch: number, distance: number): void;
  /** Stops drawing and simulating. */
  pause(): void;
  /** Draws and simulates again. */
  resume(): void;
  /** Frame times, the backend, the water's figures. */
  stats(): Stats | SuspendedStats;
  /** The next frame as a PNG. */
  snapshot(): Promise<Blob>;
  /** Stops the demo, frees its GPU resources and empties the element. */
  destroy(): void;
}

/**
 * Puts a demo in `element` (in a shadow root). Resolves once the first frame is drawn (with
 * `lazy`, once the element has come near the viewport); rejects, after showing a message
 * in the element, when no GPU backend works.
 */
export function mount(element: HTMLElement, options?: MountOptions): Promise<WavePool>;

/** The parameter table (loads the core). */
export function params(): Promise<ParamSpec[]>;

/** The presets (loads the core). */
export function presets(): Promise<PresetSpec[]>;

/**
 * Where the demo's files are (wavepool_bg.wasm, wavepool.css, no-gpu.webp, and the pages
 * share links open): a URL of a folder, e.g. "https://example.org/wavepool/". By default they
 * are next to embed.js (a bundler copies them there). Call it before the first mount().
 */
export function setAssetLocation(url: string | URL): void;

/** The languages there are catalogues for. */
export type LanguageTag = "en" | "cs" | "de" | "es" | "ru" | "sr-Latn" | "sr-Cyrl";

/** The languages there are catalogues for, each with its name in its own words. */
export const languages: ReadonlyArray<{ tag: LanguageTag; name: string }>;

/** The first of the browser's preferred languages there is a catalogue for, else "en". */
export function browserLanguage(): LanguageTag;

/** The events <wave-pool> fires. */
export interface WavePoolEventMap extends HTMLElementEventMap {
  /** The first frame is on screen; `detail` is the demo's handle. */
  "wavepool:ready": CustomEvent<WavePool>;
  /** The demo could not start; `detail` is the message shown in the element. */
  "wavepool:error": CustomEvent<string>;
}

/** `<wave-pool>`: its attributes are the options and parameters in kebab case (`max-fps`, `wave-speed`). */
export class WavePoolElement extends HTMLElement {
  /** The handle, once `wavepool:ready` has fired; undefined before, null after removal. */
  demo?: WavePool | null;
  addEventListener<K extends keyof WavePoolEventMap>(
    type: K,
    listener: (this: WavePoolElement, event: WavePoolEventMap[K]) => unknown,
    options?: boolean | AddEventListenerOptions,
  ): void;
  addEventListener(type: string, listener: EventListenerOrEventListenerObject, options?: boolean | AddEventListenerOptions): void;
  removeEventListener<K extends keyof WavePoolEventMap>(
    type: K,
    listener: (this: WavePoolElement, event: WavePoolEventMap[K]) => unknown,
    options?: boolean | EventListenerOptions,
  ): void;
  removeEventListener(type: string, listener: EventListenerOrEventListenerObject, options?: boolean | EventListenerOptions): void;
}

/** `<wave-pool>`'s attributes, for JSX and templates that check them. */
export interface WavePoolAttributes extends ParamAttributes, CreationAttributes {
  backend?: "auto" | "webgpu" | "webgl2";
  float?: "auto" | "none";
  controls?: "true" | "false" | "0" | "1";
  "max-pixel-ratio"?: string | number;
  "max-pixels"?: string | number;
  aspect?: string | number;
  "max-fps"?: string | number;
  camera?: string;
  preset?: PresetName;
  sketch?: string;
  lang?: string;
  lazy?: "true" | "false" | "0" | "1";
}

declare global {
  interface HTMLElementTagNameMap {
    "wave-pool": WavePoolElement;
  }
}
