// The words of the controls, notices and help in the language chosen: Project Fluent
// catalogues (locales/<tag>.ftl, read by @fluent/bundle), fetched with the Fluent runtime only
// for a language other than English; English comes from the core's own tables (the parameter
// table, the presets, pageWords()), so it needs no request. Numbers are written as the
// language writes them (Intl.NumberFormat: "0,6" in Czech).

import { pageWords } from "./wavepool.js";
import { assetUrl, inline, inlineBytes } from "./loader.js";
import { warn } from "./options.js";

/** The languages there are catalogues for, each named in its own words (the select's options). */
export const LANGUAGES = Object.freeze([
  { tag: "en", name: "English" },
  { tag: "cs", name: "Čeština" },
  { tag: "de", name: "Deutsch" },
  { tag: "es", name: "Español" },
  { tag: "ru", name: "Русский" },
  { tag: "sr-Latn", name: "Srpski (latinica)" },
  { tag: "sr-Cyrl", name: "Српски (ћирилица)" },
]);

/** The supported tag a BCP 47 tag asks for ("cs-CZ": "cs"; Serbian without a script: Cyrillic), or null. */
export function supportedTag(tag) {
  const lower = String(tag || "").trim().toLowerCase().replace(/_/g, "-");
  if (!lower) return null;
  const exact = LANGUAGES.find((l) => l.tag.toLowerCase() === lower);
  if (exact) return exact.tag;
  const [language, ...rest] = lower.split("-");
  if (language === "sr") return rest.includes("latn") ? "sr-Latn" : "sr-Cyrl";
  const base = LANGUAGES.find((l) => l.tag === language);
  return base ? base.tag : null;
}

/** The first of the browser's preferred languages there is a catalogue for, else English. */
export function browserLanguage() {
  for (const l of navigator.languages || [navigator.language]) {
    const tag = supportedTag(l);
    if (tag) return tag;
  }
  return "en";
}

/** The language a demo starts in: the `lang` option; else the element's own or its page's
 * `lang`; else the browser's preferred languages; else English. */
export function chooseLanguage(option, element) {
  if (option) {
    const tag = supportedTag(option);
    if (tag) return tag;
    warn(`lang "${option}" is not one of ${LANGUAGES.map((l) => l.tag).join(", ")}; choosing from the page`);
  }
  const marked = element && element.closest ? element.closest("[lang]") : null;
  const declared = marked ? marked.getAttribute("lang") : document.documentElement.lang;
  return declared ? supportedTag(declared) || "en" : browserLanguage();
}

/** The English words a demo can show before the core (which holds English's) has loaded, or
 * when it could not load: as src/page_words.rs has them (a test holds the two the same). */
const BEFORE_CORE = Object.freeze({
  "status-loading": "Loading the water…",
  "fallback-picture": "A still picture of the water pool (the live demo could not start here)",
});

let fluent = null; // the Fluent runtime's exports, once loaded

/** English's words: the core's tables (before the core has loaded, BEFORE_CORE's few). */
export function englishWords() {
  return new Words("en", null);
}

/** The words of language `tag`: English at once, any other once its catalogue is loaded
 * (`source`: its text, instead of locales/<tag>.ftl). */
export async function loadWords(tag, source) {
  if (tag === "en" && source === undefined) return englishWords();
  if (!fluent) {
    // Its one-file build sets globalThis.FluentBundle (the single file runs it from its text).
    if (inline) new Function(await inlineText(inline.fluent)).call(globalThis);
    else await import(assetUrl("locales/fluent-bundle.js", new URL("./locales/fluent-bundle.js", import.meta.url)));
    fluent = globalThis.FluentBundle;
  }
  source ??= inline ? await inlineText(inline.locales[tag]) : await fetchText(tag);
  const bundle = new fluent.FluentBundle(tag, { useIsolating: false });
  const errors = bundle.addResource(new fluent.FluentResource(source));
  for (const e of errors) warn(`catalogue ${tag}: ${e.message || e}`);
  return new Words(tag, bundle);
}

async function fetchText(tag) {
  const url = assetUrl(`locales/${tag}.ftl`, new URL(`./locales/${tag}.ftl`, import.meta.url));
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: ${response.status}`);
  return response.text();
}

// A text the single file carries packed.
async function inlineText(packed) {
  if (!packed) throw new Error("the single file carries no such catalogue");
  return new TextDecoder().decode(await inlineBytes(...packed));
}

/** One language's words. Where its catalogue lacks a message the English shows, with a warning. */
export class Words {
  constructor(tag, bundle) {
    this.tag = tag;
    this._bundle = bundle;
    this._formats = new Map();
  }

  // English's words: the core's, or before it has loaded (or where it could not) the few a
  // page can need by then.
  get _english() {
    if (!this.__english) {
      try {
        this.__english = pageWords();
      } catch (_) {
        return BEFORE_CORE;
      }
    }
    return this.__english;
  }

  // The message `id`'s text (`attribute`: one of its attributes), or null where it has none.
  _lookup(id, attribute, args) {
    const message = this._bundle && this._bundle.getMessage(id);
    const pattern = message && (attribute ? message.attributes[attribute] : message.value);
    if (!pattern) {
      if (this._bundle) warn(`no ${this.tag} message ${id}${attribute ? "." + attribute : ""}; shown in English`);
      return null;
    }
    return this._bundle.formatPattern(pattern, args);
  }

  /** The page's own words: message `id` ("reset", or "reset.title"), its `{ $name }`s filled in from `args`. */
  page(id, args = {}) {
    const [message, attribute] = id.split(".");
    const text = this._bundle ? this._lookup(message, attribute, args) : null;
    return text ?? String(this._english[id] ?? id).replace(/\{ \$(\w+) \}/g, (_, name) => String(args[name]));
  }

  /** A parameter's label and help (`p`: its entry in the core's table, or a picked setting's; the core names its messages). */
  label(p) {
    return (this._bundle && this._lookup(p.messageId, null)) || p.label;
  }

  help(p) {
    return (this._bundle && this._lookup(p.messageId, "help")) || p.help;
  }

  /** The name of a parameter's group ("Flat water"). */
  group(p) {
    return (this._bundle && this._lookup(p.groupMessageId, null)) || p.group;
  }

  /** A preset's name and what it says (`p`: its entry in the core's presets). */
  presetLabel(p) {
    return (this._bundle && this._lookup(`preset-${p.name}`, null)) || p.label;
  }

  presetHelp(p) {
    return (this._bundle && this._lookup(`preset-${p.name}`, "help")) || p.help;
  }

  /** A choice's name as the controls show it: words translated, a set ("sphere,duck") by its members. */
  choice(p, name) {
    const word = (n) => {
      const id = p.choiceMessageIds[p.choiceNames.indexOf(n)];
      return (this._bundle && id && this._lookup(id, null)) || n;
    };
    return name.includes(",") ? name.split(",").map(word).join(", ") : word(name);
  }

  /** A parameter's unit as shown after a value: a symbol as it is, a word ("cells") in the language's words. */
  unit(p) {
    return (this._bundle && p.unitMessageId && this._lookup(p.unitMessageId, null)) || p.unit;
  }

  /** `v` with `decimals` decimals, as the language writes numbers. */
  number(v, decimals) {
    let format = this._formats.get(decimals);
    if (!format) {
      format = new Intl.NumberFormat(this.tag, { minimumFractionDigits: decimals, maximumFractionDigits: decimals, useGrouping: false });
      this._formats.set(decimals, format);
    }
    return format.format(v);
  }

  /** A parameter's value as the controls show it: on/off, a choice's name, or the number and its unit. */
  value(p, v) {
    if (p.kind === "toggle") return this.page(v >= 0.5 ? "on" : "off");
    if (p.kind === "choice") {
      const i = p.choices.indexOf(v);
      if (i >= 0 && p.choiceNames[i]) return this.choice(p, p.choiceNames[i]);
      return `${this.number(v, 0)}${p.unit ? ` ${this.unit(p)}` : ""}`;
    }
    const decimals = Math.max(0, -Math.floor(Math.log10(p.step) + 1e-9));
    return `${this.number(v, decimals)}${p.unit ? (p.unit === "°" ? "°" : ` ${this.unit(p)}`) : ""}`;
  }
}
