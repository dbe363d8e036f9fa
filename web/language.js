// The language the demo speaks: the Language select in the controls, setLanguage() at run
// time (the controls made again in the new words; the water and the view untouched), and the
// words a page may show beside the demo (text()); methods of the demo (demo.js). The words
// themselves are i18n.js's.

import { LANGUAGES, englishWords, loadWords, supportedTag } from "./i18n.js";
import { warn } from "./options.js";

export const languageMethods = {
  // The Language select: the languages there are catalogues for, each in its own words.
  _languageRow() {
    const row = document.createElement("div");
    row.className = "row language";
    const label = document.createElement("label");
    label.htmlFor = `wavepool-${this._id}-language`;
    label.textContent = this._words.page("language");
    const select = document.createElement("select");
    select.id = label.htmlFor;
    const shown = LANGUAGES.some((l) => l.tag === this._words.tag) ? LANGUAGES : [...LANGUAGES, { tag: this._words.tag, name: this._words.tag }];
    for (const l of shown) {
      const option = new Option(l.name, l.tag);
      option.lang = l.tag;
      select.append(option);
    }
    select.value = this._words.tag;
    select.addEventListener("change", () => this.setLanguage(select.value));
    row.append(label, select);
    return row;
  },

  /** Shows the controls, notices and help in language `tag` ("cs", "sr-Latn", ...; see
   * LANGUAGES): its catalogue is fetched (or `catalogue`, a Fluent text of a page's own, is
   * taken for any tag) and the controls are made again in it; the water, the view and the
   * parameters are not touched. Resolves once they show it. */
  async setLanguage(tag, catalogue) {
    const asked = catalogue === undefined ? supportedTag(tag) : String(tag);
    if (!asked) {
      warn(`setLanguage: "${tag}" is not one of ${LANGUAGES.map((l) => l.tag).join(", ")} (or give its catalogue)`);
      return;
    }
    const words = await this._loadWords(asked, catalogue);
    if (this._dead) return;
    this._setWords(words);
    if (this._drawer) {
      const focused = this._shadow.activeElement && this._shadow.activeElement.id;
      const open = this._drawer.open;
      this._drawer.remove();
      this._controls.clear();
      this._dependants.clear();
      this._plot = this._costs = this._readings = this._pickedGroup = null;
      this._buildControls();
      this._drawer.open = open;
      if (focused) this._shadow.getElementById(focused)?.focus();
    }
    if (this._overlayUpdate) this._stage.querySelector(".overlay")?.remove();
    this._buildOverlay();
    this._element.dispatchEvent(new CustomEvent("wavepool:language", { detail: words.tag, bubbles: true }));
  },

  /** The language the demo shows (a tag of LANGUAGES: "en", "cs", "sr-Latn", ...). */
  language() {
    return this._text().tag;
  },

  /** The demo's words in the language it shows: message `id` of locales/en.ftl ("page-intro"),
   * its `{ $name }`s filled in from `args`; for a page that shows them beside it. */
  text(id, args = {}) {
    return this._text().page(String(id), args);
  },

  // The words shown: English until a language's are loaded.
  _text() {
    return this._words || (this._words = englishWords());
  },

  // The words of `tag` (i18n.js; from `catalogue` if given), or English with a warning where
  // they cannot be had.
  async _loadWords(tag, catalogue) {
    try {
      return await loadWords(tag, catalogue);
    } catch (error) {
      warn(`the ${tag} catalogue could not be loaded (${error.message || error}); showing English`);
      return loadWords("en");
    }
  },

  // Words to show from now on; the controls' `lang` follows them, for screen readers, and the
  // canvas's label is said in them.
  _setWords(words) {
    this._words = words;
    this._root.lang = words.tag;
    if (this._canvas) this._canvas.setAttribute("aria-label", words.page("canvas-label"));
  },

  // The words being loaded at mount (embed.js), once they are (English if they failed).
  async _settledWords() {
    if (this._wordsLoading) this._setWords(await this._wordsLoading);
    return this._text();
  },

};
