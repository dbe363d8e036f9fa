// A small plot of Fresnel reflectance against the angle of incidence, drawn by the page (SVG,
// no inline style, so a strict Content-Security-Policy allows it): the chosen model over the
// exact curve, seen from the air (solid) and from under the water (dashed, where total
// internal reflection sends everything back past 48.6°), and a mark at the angle the camera
// looks at the middle of the pool. The curves come from the core (`fresnelCurve`, the same
// formulas as the surface shader).

const SVG = "http://www.w3.org/2000/svg";
/** Plot area in the SVG's own units: left, top, width, height. */
const AREA = { x: 30, y: 8, w: 180, h: 100 };
/** Points per curve. */
const SAMPLES = 91;

function element(name, attributes, parent) {
  const e = document.createElementNS(SVG, name);
  for (const [k, v] of Object.entries(attributes)) e.setAttribute(k, String(v));
  if (parent) parent.append(e);
  return e;
}

/** An SVG path through reflectances `r` (an array or a Float32Array) at angles evenly from 0° to 90°. */
function pathOf(r) {
  const last = r.length - 1;
  return Array.from(r, (v, i) => `${i ? "L" : "M"}${(AREA.x + (i / last) * AREA.w).toFixed(1)},${(AREA.y + (1 - v) * AREA.h).toFixed(1)}`).join("");
}

export class FresnelPlot {
  /** `curve(model, fromWater, samples)`: the core's fresnelCurve. */
  // words: the language's (i18n.js), for the axis, the caption and the label.
  constructor(curve, words) {
    this._curve = curve;
    this._model = null;
    this.element = document.createElement("figure");
    this.element.className = "fresnel-plot";
    const svg = element("svg", {
      viewBox: "0 0 220 132",
      role: "img",
      "aria-label": words.page("fresnel-plot"),
    });
    const { x, y, w, h } = AREA;
    element("rect", { x, y, width: w, height: h, class: "frame" }, svg);
    for (const [v, label] of [[0, "0"], [0.5, "0.5"], [1, "1"]]) {
      element("line", { x1: x, x2: x + w, y1: y + (1 - v) * h, y2: y + (1 - v) * h, class: "grid" }, svg);
      element("text", { x: x - 4, y: y + (1 - v) * h + 3, class: "tick end" }, svg).textContent = label;
    }
    for (const deg of [0, 30, 60, 90]) {
      element("text", { x: x + (deg / 90) * w, y: y + h + 11, class: "tick middle" }, svg).textContent = `${deg}°`;
    }
    element("text", { x: x + w / 2, y: y + h + 22, class: "tick middle" }, svg).textContent = words.page("fresnel-angle");
    const exactAir = curve(0, false, SAMPLES);
    const exactWater = curve(0, true, SAMPLES);
    element("path", { d: pathOf(exactWater), class: "exact water" }, svg);
    element("path", { d: pathOf(exactAir), class: "exact air" }, svg);
    this._water = element("path", { class: "model water" }, svg);
    this._air = element("path", { class: "model air" }, svg);
    this._mark = element("line", { y1: y, y2: y + h, class: "view" }, svg);
    const caption = document.createElement("figcaption");
    caption.textContent = words.page("fresnel-caption");
    this.element.append(svg, caption);
  }

  /** Redraws the model's curves if `model` changed, and puts the view mark at `angleDeg` (null hides it). */
  update(model, angleDeg) {
    if (model !== this._model) {
      this._model = model;
      this._air.setAttribute("d", pathOf(this._curve(model, false, SAMPLES)));
      this._water.setAttribute("d", pathOf(this._curve(model, true, SAMPLES)));
      this.element.dataset.model = String(model);
    }
    const show = Number.isFinite(angleDeg);
    this._mark.setAttribute("visibility", show ? "visible" : "hidden");
    if (show) {
      const px = AREA.x + (Math.min(90, Math.max(0, angleDeg)) / 90) * AREA.w;
      this._mark.setAttribute("x1", px.toFixed(1));
      this._mark.setAttribute("x2", px.toFixed(1));
    }
  }
}
