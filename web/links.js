// The demo's links and what it carries in them: the share link, the embed code, and the
// sketch (what was drawn with the pointer in the ripple tank): methods of the demo (demo.js).

import { demoPage } from "./loader.js";

/** The demo's methods that write its links. */
export const linkMethods = {
  /** The query string of this demo as it is now: parameters that differ from the defaults, and the camera. */
  _query() {
    const query = new URLSearchParams();
    for (const p of this._table) {
      const v = this.get(p.name);
      if (v === p.default) continue;
      const i = p.kind === "choice" ? p.choices.indexOf(v) : -1;
      query.set(p.name, i >= 0 && p.choiceNames[i] ? p.choiceNames[i] : String(v));
    }
    query.set("camera", this.camera().map((v) => Math.round(v * 10) / 10).join(","));
    const sketch = this.sketch();
    if (sketch) query.set("sketch", sketch);
    // The language shown, where it is not the one the page would choose by itself.
    if (this._words && this._words.tag !== this._pageLanguage) query.set("lang", this._words.tag);
    return query.toString().replace(/%2C/g, ",");
  },

  /** A link that opens the demo's page with this demo's parameters and view. */
  shareLink() {
    return `${demoPage("index.html")}?${this._query()}`;
  },

  /** An <iframe> showing this demo as it is now (the pool alone, `embed.html`; the single file when this is it). */
  embedCode() {
    const page = demoPage("embed.html");
    return (
      `<iframe src="${page}?${this._query()}" width="800" height="600" allow="fullscreen" ` +
      `title="${this.text("embed-title")}"></iframe>`
    );
  },

  /** What was drawn with the pointer (the tank's walls, erasures and ruler), as the share link's `sketch`. */
  sketch() {
    return this._suspended ? this._saved.sketch : this._alive().sketch();
  },

  /** Replaces what was drawn with `text` (as sketch() gives it); a text that cannot be read changes nothing (console warning). */
  setSketch(text) {
    if (this._suspended) this._saved.sketch = String(text);
    else this._alive().setSketch(String(text));
  },
};
