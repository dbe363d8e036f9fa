// The settings of what the pointer picked (the tank's dipper, with the move tool): a group of
// their own under the scene's controls, shown while something is picked and refreshed four
// times a second; methods of the demo (demo.js).

export const pickedMethods = {
  /** What the pointer picked that has settings of its own: `{ title, settings }` (each setting a slider's spec with its `value`), or null. */
  picked() {
    return this._suspended ? null : this._alive().picked();
  },

  /** Sets the picked thing's setting `name` to `value` (clamped to its range; with nothing picked, a console warning). */
  setPicked(name, value) {
    this._alive().setPicked(String(name), Number(value));
    this._refreshPicked();
  },

  // The group's fieldset, empty and hidden until something is picked.
  _pickedFieldset() {
    const fieldset = document.createElement("fieldset");
    fieldset.className = "picked";
    fieldset.hidden = true;
    fieldset.append(document.createElement("legend"));
    this._pickedGroup = fieldset;
    this._pickedAt = -Infinity;
    return fieldset;
  },

  // The picked thing's title in the words shown ("Dipper 2": the message the core names, its number filled in).
  _pickedTitle(picked) {
    return this._words.page(picked.titleId, { number: this._words.number(picked.number, 0) });
  },

  _pickedNote(time) {
    if (!this._pickedGroup || time - this._pickedAt < 250) return;
    this._pickedAt = time;
    this._refreshPicked();
  },

  _refreshPicked() {
    const group = this._pickedGroup;
    if (!group) return;
    const picked = this._core.picked();
    group.hidden = !picked;
    if (!picked) return;
    const key = [picked.title, ...picked.settings.map((s) => s.name)].join(" ");
    if (group.dataset.key !== key) {
      // Another thing picked: its title and a slider per setting.
      group.dataset.key = key;
      group.querySelector("legend").textContent = this._pickedTitle(picked);
      group.querySelectorAll(".row").forEach((row) => row.remove());
      for (const s of picked.settings) group.append(this._pickedRow(s));
    }
    for (const s of picked.settings) {
      const input = group.querySelector(`[name="${s.name}"]`);
      // Not under the user's hand while it is being moved.
      if (document.activeElement !== input) input.value = String(s.value);
      input.nextElementSibling.textContent = this._words.value(s, s.value);
      input.setAttribute("aria-valuetext", input.nextElementSibling.textContent);
    }
  },

  // One setting's row: label, slider and value, as the parameters' rows are made.
  _pickedRow(s) {
    const row = document.createElement("div");
    row.className = "row";
    const id = `wavepool-${this._id}-picked-${s.name}`;
    const label = document.createElement("label");
    label.htmlFor = id;
    label.textContent = this._words.label(s);
    label.title = this._words.help(s);
    const input = document.createElement("input");
    const title = label.title;
    Object.assign(input, { id, name: s.name, title, type: "range", min: s.min, max: s.max, step: s.step });
    input.addEventListener("input", () => this.setPicked(s.name, Number(input.value)));
    const output = document.createElement("output");
    output.htmlFor = id;
    output.setAttribute("aria-hidden", "true");
    row.append(label, input, output);
    return row;
  },
};
