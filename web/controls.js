// The controls drawer under the pool (one control per parameter, grouped, with the presets
// row, the Fresnel plot and the render modes' costs) and the overlay's play and fullscreen
// buttons: methods of the demo (demo.js).

import { fresnelCurve, presetTable } from "./wavepool.js";
import { FresnelPlot } from "./fresnel-plot.js";
import { BROWSING_KEYS } from "./keys.js";
import { warn } from "./options.js";

/** Paths of the overlay buttons' icons, on a 24 x 24 grid. */
const ICONS = {
  play: "M8 5v14l11-7z",
  pause: "M6 5h4v14H6zm8 0h4v14h-4z",
  fullscreen: "M4 4h6v2H6v4H4zm10 0h6v6h-2V6h-4zM4 14h2v4h4v2H4zm14 0h2v6h-6v-2h4z",
};

/** An inline SVG icon (no font glyph that a system may lack, no style attribute). */
function icon(path) {
  const ns = "http://www.w3.org/2000/svg";
  const svg = document.createElementNS(ns, "svg");
  svg.setAttribute("viewBox", "0 0 24 24");
  svg.setAttribute("aria-hidden", "true");
  const shape = document.createElementNS(ns, "path");
  shape.setAttribute("d", path);
  shape.setAttribute("fill", "currentColor");
  svg.append(shape);
  return svg;
}

/** The demo's methods that build and refresh its controls. */
export const controlMethods = {

  _buildControls() {
    // A drawer under the pool: open where there is room beside the groups, folded on a phone.
    const drawer = document.createElement("details");
    drawer.className = "controls";
    drawer.open = true; // measured open, then folded where it would not fit (layout.js)
    const summary = document.createElement("summary");
    summary.textContent = this._words.page("controls");
    const panel = document.createElement("div");
    panel.className = "panel";
    drawer.append(summary, panel);
    // The one live region of the controls: what a button or the Preset select did.
    this._said = document.createElement("p");
    this._said.className = "said";
    this._said.setAttribute("role", "status");
    // The language and the preset, one above the other in the panel's first cell.
    const choosers = document.createElement("div");
    choosers.className = "choosers";
    choosers.append(this._languageRow(), this._presetRow());
    panel.append(choosers);
    const groups = new Map();
    for (const p of this._table) {
      if (!groups.has(p.group)) {
        const fieldset = document.createElement("fieldset");
        const legend = document.createElement("legend");
        legend.textContent = this._words.group(p);
        fieldset.append(legend);
        groups.set(p.group, fieldset);
        panel.append(fieldset);
      }
      groups.get(p.group).append(this._control(p));
    }
    for (const fieldset of groups.values()) hideEmptyGroup(fieldset);
    if (groups.has("Flat water")) {
      // What each render mode costs, measured while it is shown, under its control.
      // Not a live region: the figures change twice a second, which a screen reader would
      // keep announcing.
      this._costs = document.createElement("p");
      this._costs.className = "costs";
      groups.get("Flat water").querySelector("[name=render_mode]").closest(".row").after(this._costs);
    }
    if (groups.has("Tank")) {
      // What the tank's instruments read (the probe, the ruler), twice a second.
      this._readings = document.createElement("p");
      this._readings.className = "readings";
      groups.get("Tank").append(this._readings);
      // The picked dipper's own settings (picked.js), after the tank's.
      groups.get("Tank").after(this._pickedFieldset());
    }
    if (groups.has("Optics")) {
      // The Fresnel models' curves beside their select.
      this._plot = new FresnelPlot(fresnelCurve, this._words);
      groups.get("Optics").append(this._plot.element);
      this._updatePlot();
    }
    const buttons = document.createElement("div");
    buttons.className = "buttons";
    const button = (id, action) => {
      const b = document.createElement("button");
      b.type = "button";
      b.textContent = this._words.page(id);
      b.title = this._words.page(`${id}.title`);
      b.addEventListener("click", action);
      buttons.append(b);
    };
    button("reset", () => this.reset());
    button("defaults", () => {
      for (const p of this._table) this.set(p.name, p.default);
    });
    const said = this._said;
    const copy = async (copied, text) => {
      try {
        await navigator.clipboard.writeText(text);
        said.textContent = this._words.page(copied);
      } catch (_) {
        said.textContent = text; // no clipboard here (an insecure page, a sandbox): shown to copy by hand
      }
    };
    button("share-link", () => copy("link-copied", this.shareLink()));
    button("embed-code", () => copy("embed-code-copied", this.embedCode()));
    buttons.append(said);
    panel.append(buttons);
    this._root.append(drawer);
    this._drawer = drawer;
    drawer.open = this._drawerStartsOpen(drawer);
    drawer.addEventListener("toggle", () => this._fit());
    this._fit();
  },

  // The Preset select: a named starting state from the core's table.
  _presetRow() {
    const row = document.createElement("div");
    row.className = "row preset";
    const label = document.createElement("label");
    label.htmlFor = `wavepool-${this._id}-preset`;
    label.textContent = this._words.page("preset");
    const select = document.createElement("select");
    select.id = label.htmlFor;
    select.append(new Option(this._words.page("preset-choose"), ""));
    for (const p of presetTable()) {
      const option = new Option(this._words.presetLabel(p), p.name);
      option.title = this._words.presetHelp(p);
      select.append(option);
    }
    if (this._opts.preset) select.value = this._opts.preset.name;
    // A preset starts the demo over, so it applies on a choice made (a click in the list, or
    // Enter), not while the arrow keys browse the closed select.
    let browsing = false;
    let applied = select.value; // what the select shows once nothing is being browsed
    const apply = () => {
      browsing = false;
      applied = select.value;
      if (select.value) this.applyPreset(select.value);
      const name = select.selectedOptions[0].textContent;
      this._say(select.value ? this._words.page("preset-applied", { name }) : "");
    };
    select.addEventListener("keydown", (e) => {
      if (e.key === "Enter") {
        e.preventDefault();
        apply();
      } else if (BROWSING_KEYS.includes(e.key) || (e.key.length === 1 && e.key !== " ")) {
        browsing = true;
      }
    });
    select.addEventListener("pointerdown", () => (browsing = false));
    // Left without Enter: it shows the preset in effect again, not one never applied.
    select.addEventListener("blur", () => {
      if (browsing) select.value = applied;
      browsing = false;
    });
    select.addEventListener("change", () => {
      if (!browsing) apply();
      else this._say(this._words.page("preset-press-enter", { name: select.selectedOptions[0].textContent }));
    });
    row.append(label, select);
    return row;
  },

  _control(p) {
    const row = document.createElement("div");
    row.className = "row";
    const inputId = `wavepool-${this._id}-${p.name}`;
    const label = document.createElement("label");
    label.htmlFor = inputId;
    label.textContent = this._words.label(p);
    label.title = this._words.help(p);
    const input = document.createElement(p.kind === "choice" ? "select" : "input");
    input.id = inputId;
    input.name = p.name;
    input.title = label.title;
    // The value as text, for the eye: the control itself tells assistive technology (a
    // slider's aria-valuetext, a select's option, a checkbox's state), so this is not read.
    const output = document.createElement("output");
    output.htmlFor = inputId;
    output.setAttribute("aria-hidden", "true");
    if (p.kind === "toggle") {
      input.type = "checkbox";
      input.addEventListener("change", () => this.set(p.name, input.checked ? 1 : 0));
    } else if (p.kind === "choice") {
      for (const v of p.choices) input.append(new Option(this._words.value(p, v), String(v)));
      input.addEventListener("change", () => this.set(p.name, Number(input.value)));
    } else {
      input.type = "range";
      input.min = p.min;
      input.max = p.max;
      input.step = p.step;
      input.addEventListener("input", () => this.set(p.name, Number(input.value)));
    }
    const update = () => {
      const v = this.get(p.name);
      if (p.kind === "toggle") input.checked = v >= 0.5;
      else input.value = String(v);
      output.textContent = this._words.value(p, v);
      if (input.type === "range") input.setAttribute("aria-valuetext", output.textContent);
      // A model's own settings show only while that model is chosen, a scene's in that scene.
      row.hidden = !p.shownWhen.every((w) => w.values.includes(this.get(w.param)));
      if (row.parentElement) hideEmptyGroup(row.parentElement);
    };
    this._controls.set(p.name, update);
    for (const w of p.shownWhen) {
      const list = this._dependants.get(w.param) || [];
      this._dependants.set(w.param, [...list, update]);
    }
    update();
    row.append(label, input, output);
    return row;
  },

  // Records a drawn frame's interval under the render mode shown, and twice a second writes
  // each mode's cost: its GPU time where the browser measures it (stats().gpuMs), and the
  // median interval between its frames.
  _costsNote(time, interval) {
    const mode = Math.round(this.get("render_mode"));
    const list = this._modeIntervals[mode];
    if (list) {
      list.push(interval);
      if (list.length > 60) list.shift();
    }
    if (!this._costs || time - this._costsAt < 500) return;
    this._costsAt = time;
    const s = this._core.stats();
    const w = this._words;
    const keys = ["raytraced", "flat", "split"];
    const spec = this._table.find((p) => p.name === "render_mode");
    const names = keys.map((k) => w.choice(spec, k));
    const ms = (v, decimals) => (v === null || v === undefined ? "–" : `${w.number(v, decimals)} ms`);
    const gpu = s.gpuMs
      ? w.page("costs-gpu", { times: names.map((n, i) => `${n} ${ms(s.gpuMs[keys[i]], 1)}`).join(" · ") })
      : w.page("costs-no-gpu-time");
    const between = names
      .map((n, i) => {
        const l = [...this._modeIntervals[i]].sort((a, b) => a - b);
        return `${n} ${ms(l.length ? l[Math.floor((l.length - 1) / 2)] : null, 0)}`;
      })
      .join(" · ");
    const note = s.flatNoteId ? `${w.page(s.flatNoteId)} ` : "";
    this._costs.textContent = `${note}${gpu} ${w.page("costs-between", { times: between })}`;
  },

  // Twice a second, what the shown scene's instruments read: "probe frequency 10.00 Hz · …".
  _readingsNote(time) {
    if (!this._readings || time - this._readingsAt < 500) return;
    this._readingsAt = time;
    const readings = Object.entries(this._core.stats().readings || {});
    this._readings.hidden = readings.length === 0;
    // Hertz to a hundredth; lengths to three figures or whole millimetres.
    const digits = (r) => (r.unit === "Hz" ? 2 : Math.abs(r.value) >= 100 ? 0 : Math.abs(r.value) >= 1 ? 1 : 3);
    this._readings.textContent = readings
      .map(([name, r]) => `${this._words.page(`reading-${name.replace(/ /g, "-")}`)}: ${this._words.number(r.value, digits(r))} ${r.unit}`)
      .join(" · ");
  },

  // The plot's model and the angle at which the view's centre meets the water (the camera's
  // pitch is its elevation above the pool's middle: incidence = 90° - |pitch|).
  _updatePlot() {
    if (!this._plot) return;
    this._plot.update(this.get("fresnel"), 90 - Math.abs(this.camera()[1]));
  },

  /** Says `text` in the controls' live region (shown under the buttons). */
  _say(text) {
    if (this._said) this._said.textContent = text;
  },

  _refreshControls(name) {
    if (!name || name === "fresnel") this._updatePlot();
    if (name) {
      const update = this._controls.get(name);
      if (update) update();
      for (const dependant of this._dependants.get(name) || []) dependant();
    } else {
      for (const update of this._controls.values()) update();
    }
    if (this._overlayUpdate) this._overlayUpdate();
  },

  // Buttons over the pool, there with or without the controls: play/pause (the `paused`
  // parameter: a way to stop the motion, WCAG 2.2.2) and fullscreen (only where the page
  // allows it: an iframe needs allow="fullscreen").
  _buildOverlay() {
    const bar = document.createElement("div");
    bar.className = "overlay";
    const play = document.createElement("button");
    play.type = "button";
    play.className = "play";
    const playIcon = icon(ICONS.pause);
    play.append(playIcon);
    play.addEventListener("click", () => this.set("paused", this.get("paused") >= 0.5 ? 0 : 1));
    bar.append(play);
    if (document.fullscreenEnabled && this._element.requestFullscreen) {
      const full = document.createElement("button");
      full.type = "button";
      full.className = "fullscreen";
      full.append(icon(ICONS.fullscreen));
      full.title = this._words.page("fullscreen.title");
      full.setAttribute("aria-label", this._words.page("fullscreen"));
      full.addEventListener("click", () =>
        document.fullscreenElement === this._element
          ? document.exitFullscreen()
          : this._element.requestFullscreen().catch((e) => warn(`fullscreen refused: ${e.message || e}`)),
      );
      bar.append(full);
    }
    this._overlayUpdate = () => {
      if (!this._core) return;
      const paused = this.get("paused") >= 0.5;
      playIcon.firstChild.setAttribute("d", paused ? ICONS.play : ICONS.pause);
      const id = paused ? "play" : "pause";
      play.setAttribute("aria-label", this._words.page(id));
      play.title = this._words.page(`${id}.title`);
      play.setAttribute("aria-pressed", String(!paused));
    };
    this._overlayUpdate();
    this._stage.append(bar);
  }
};

// A group of controls none of which is shown (the pool's bodies in the sea) is hidden whole.
function hideEmptyGroup(fieldset) {
  fieldset.hidden = [...fieldset.querySelectorAll(":scope > .row")].every((row) => row.hidden);
}
