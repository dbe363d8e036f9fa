#!/usr/bin/env node
// Makes the npm package from a built dist/: the modules embed.js loads (followed through their
// imports), the wasm core, the stylesheet and the no-GPU picture, embed.d.ts (written by hand)
// and tables.d.ts, written here from the core's own tables (parameters, presets, creation
// options: loaded from the built wasm, so the types cannot drift from what the demo accepts),
// package.json with the crate's version, a README and the licences.
//
// Usage: node scripts/package.mjs DIST OUT   (after `trunk build`; OUT is emptied first)

import { copyFileSync, mkdirSync, readdirSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { join, resolve } from "node:path";
import { fileURLToPath, pathToFileURL } from "node:url";

const [dist, out] = process.argv.slice(2).map((p) => resolve(p));
if (!dist || !out) {
  console.error("usage: node scripts/package.mjs DIST OUT");
  process.exit(2);
}
const root = fileURLToPath(new URL("..", import.meta.url));

/** The modules embed.js imports, directly or through each other, embed.js first. */
function moduleGraph(entry) {
  const seen = [];
  const visit = (name) => {
    if (seen.includes(name)) return;
    seen.push(name);
    const text = readFileSync(join(dist, name), "utf8");
    // `import … from "./x.js"`, `export … from './x.js'`, `import "./x.js"` and `import("./x.js")`.
    const imports = /\b(?:from|import)\s*\(?\s*["']\.\/([\w-]+\.js)["']/g;
    for (const [, dep] of text.matchAll(imports)) visit(dep);
  };
  visit(entry);
  return seen;
}

/** A doc comment's text, safe inside a comment. */
const doc = (text) => text.replace(/\*\//g, "* /");

const quote = (s) => JSON.stringify(s);

/** A choice's names, and for a set (`objects`: a name holds a comma) every other way to
 * write one of its sets: its single members (the power-of-two values) joined in any order. */
function choiceNames(p) {
  const names = p.choiceNames.filter(Boolean);
  if (!names.some((n) => n.includes(","))) return names;
  const members = p.choices.map((v, i) => [v, p.choiceNames[i]]).filter(([v, n]) => n && v > 0 && (v & (v - 1)) === 0);
  const orders = (list) => (list.length <= 1 ? [list] : list.flatMap((x, i) => orders(list.filter((_, j) => j !== i)).map((rest) => [x, ...rest])));
  const sets = [];
  for (let mask = 1; mask < 1 << members.length; mask++) {
    const chosen = members.filter((_, i) => mask & (1 << i));
    const sum = chosen.reduce((total, [v]) => total + v, 0);
    if (chosen.length > 1 && p.choices.includes(sum)) sets.push(...orders(chosen.map(([, n]) => n)).map((o) => o.join(",")));
  }
  return [...new Set([...names, ...sets])];
}

/** The TypeScript type a parameter's value takes in mount() options and set(). */
function valueType(p) {
  if (p.kind === "toggle") return 'boolean | 0 | 1 | "on" | "off"';
  if (p.kind === "choice") return [...choiceNames(p).map(quote), ...p.choices.map(String)].join(" | ");
  return "number";
}

/** What an attribute of <wave-pool> takes for a parameter (attributes are strings). */
function attributeType(p) {
  if (p.kind === "toggle") return '"true" | "false" | "on" | "off" | "0" | "1"';
  if (p.kind === "choice") return [...choiceNames(p), ...p.choices.map(String)].map(quote).join(" | ");
  return "string | number";
}

/** `meshSize` -> `mesh-size`. */
const kebab = (name) => name.replace(/[A-Z]/g, (c) => `-${c.toLowerCase()}`);

/** A parameter's doc comment: label, unit, range or choices, default, help. */
function paramDoc(p) {
  const unit = p.unit ? ` ${p.unit}` : "";
  let range;
  if (p.kind === "toggle") range = `on/off, default ${p.default >= 0.5 ? "on" : "off"}`;
  else if (p.kind === "choice") {
    const named = p.choices.map((v, i) => (p.choiceNames[i] ? `${p.choiceNames[i]} (${v})` : `${v}${unit}`));
    const d = p.choices.indexOf(p.default);
    range = `one of ${named.join(", ")}; default ${d >= 0 && p.choiceNames[d] ? p.choiceNames[d] : p.default}`;
  } else range = `${p.min}–${p.max}${unit}, default ${p.default}${unit}`;
  return `  /** ${doc(p.label)} (${doc(p.group)}): ${doc(range)}. ${doc(p.help)} */`;
}

function tablesDts(table, presets, options) {
  const lines = [
    "// Written by scripts/package.mjs from the core's parameter table, presets and creation",
    "// options at build time: do not edit.",
    "",
    "/** Every parameter's name. */",
    `export type ParamName =\n  | ${table.map((p) => quote(p.name)).join("\n  | ")};`,
    "",
    "/** What each parameter takes: a number in its range, on/off, or a choice by name or number. */",
    "export interface ParamValues {",
    ...table.flatMap((p) => [paramDoc(p), `  ${p.name}: ${valueType(p)};`]),
    "}",
    "",
    "/** <wave-pool>'s attributes for the parameters (kebab case). */",
    "export interface ParamAttributes {",
    ...table.flatMap((p) => [paramDoc(p), `  ${quote(p.name.replace(/_/g, "-"))}?: ${attributeType(p)};`]),
    "}",
    "",
    "/** A row of the parameter table. */",
    "export interface ParamSpec {",
    "  name: ParamName;",
    "  label: string;",
    "  group: string;",
    "  unit: string;",
    '  kind: "slider" | "toggle" | "choice";',
    "  min: number;",
    "  max: number;",
    "  step: number;",
    "  default: number;",
    "  help: string;",
    "  /** A choice's values, and their names where they have one. */",
    "  choices: number[];",
    "  choiceNames: string[];",
    "  /** Shown in the controls only while each named parameter has one of its values. */",
    "  shownWhen: { param: ParamName; values: number[] }[];",
    "  /** Where the message catalogues hold its label and help (`help` the attribute). */",
    "  messageId: string;",
    "  /** Where they hold its group's name, its unit's word (null for a symbol) and each choice name's word (\"\" for a number or a set). */",
    "  groupMessageId: string;",
    "  unitMessageId: string | null;",
    "  choiceMessageIds: string[];",
    "}",
    "",
    "/** Every preset's name. */",
    `export type PresetName =\n  | ${presets.map((p) => quote(p.name)).join("\n  | ")};`,
    "",
    "/** A preset: parameter values and maybe a view. */",
    "export interface PresetSpec {",
    "  name: PresetName;",
    "  label: string;",
    "  help: string;",
    "  values: [ParamName, number][];",
    "  /** [yaw, pitch, distance] (degrees, degrees, m), or null for the scene's view. */",
    "  camera: [number, number, number] | null;",
    "}",
    "",
    "/** Options fixed when the demo is created (mount() options). */",
    "export interface CreationOptions {",
    ...options.flatMap((o) => [
      `  /** ${doc(o.label)} (${o.min}–${o.max}, default ${o.default}). */`,
      `  ${o.name}?: number;`,
    ]),
    "}",
    "",
    "/** The creation options as <wave-pool>'s attributes (kebab case). */",
    "export interface CreationAttributes {",
    ...options.flatMap((o) => [
      `  /** ${doc(o.label)} (${o.min}–${o.max}, default ${o.default}). */`,
      `  ${quote(kebab(o.name))}?: string | number;`,
    ]),
    "}",
    "",
    "/** The scenes (the `scene` parameter's choices). */",
    `export type SceneName = ${table.find((p) => p.name === "scene").choiceNames.map(quote).join(" | ")};`,
    "",
  ];
  return lines.join("\n");
}

const cargo = readFileSync(join(root, "Cargo.toml"), "utf8");
const field = (name) => cargo.match(new RegExp(`^${name} = "(.*)"`, "m"))[1];

const modules = moduleGraph("embed.js");
// The message catalogues and the Fluent runtime, fetched by i18n.js for a language other than English.
const locales = readdirSync(join(dist, "locales")).map((name) => `locales/${name}`);
const assets = ["wavepool_bg.wasm", "wavepool.css", "no-gpu.webp", ...locales];

const core = await import(pathToFileURL(join(dist, "wavepool.js")).href);
core.initSync({ module: readFileSync(join(dist, "wavepool_bg.wasm")) });

rmSync(out, { recursive: true, force: true });
mkdirSync(join(out, "locales"), { recursive: true });
for (const name of [...modules, ...assets]) copyFileSync(join(dist, name), join(out, name));
copyFileSync(join(root, "web/embed.d.ts"), join(out, "embed.d.ts"));
writeFileSync(join(out, "tables.d.ts"), tablesDts(core.paramTable(), core.presetTable(), core.optionTable()));
// `import "wavepool/element"` registers <wave-pool> (embed.js does, when it is first imported).
writeFileSync(join(out, "element.js"), 'export { WavePoolElement } from "./embed.js";\n');
writeFileSync(join(out, "element.d.ts"), 'export { WavePoolElement } from "./embed.js";\n');
copyFileSync(join(root, "web/package-readme.md"), join(out, "README.md"));
for (const name of ["LICENSE-MIT", "LICENSE-APACHE"]) copyFileSync(join(root, name), join(out, name));

const files = [...modules, ...assets, "element.js", "element.d.ts", "embed.d.ts", "tables.d.ts", "LICENSE-MIT", "LICENSE-APACHE"];
const pkg = {
  name: "wavepool",
  version: field("version"),
  description: field("description"),
  license: field("license"),
  type: "module",
  main: "./embed.js",
  types: "./embed.d.ts",
  exports: {
    ".": { types: "./embed.d.ts", default: "./embed.js" },
    "./element": { types: "./element.d.ts", default: "./element.js" },
    "./wavepool.css": "./wavepool.css",
    "./wavepool_bg.wasm": "./wavepool_bg.wasm",
    "./package.json": "./package.json",
  },
  // Importing the module registers <wave-pool>: bundlers must keep it.
  sideEffects: ["./embed.js", "./element.js"],
  files,
  keywords: ["water", "webgpu", "webgl2", "wasm", "web-component", "physics", "education"],
};
writeFileSync(join(out, "package.json"), JSON.stringify(pkg, null, 2) + "\n");
console.log(`    npm package in ${out}: ${files.length + 2} files, version ${pkg.version}`);
