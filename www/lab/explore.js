// The lab's view without a mouse and without sight: buttons that zoom and
// pan (beside the wheel, the drag and the keys), a description of the photo
// and of every result layer (its size, its range of values; the points found
// and the first few of them), generated from the data on screen, and the
// "Data" view: the 7 × 7 pixels around the keyboard's cursor (view.js) as
// tables with row and column headers, of the grey values and of the layer
// shown, the cursor's cell marked in words.

import { el } from "../dom.js";
import { fmt, paintedOf } from "./view.js";

/** The Data view's neighbourhood: HALF pixels each side of the cursor. */
const HALF = 3;
/** The description names this many of the points found. */
const FIRST_POINTS = 5;

/** Photos up to this many pixels have their grey range in the description (a loop over the values on the page). */
const RANGE_PIXELS = 1 << 22;

/** The smallest and largest finite value of `data` (once per array). */
const ranges = new WeakMap();
function rangeOf(data) {
  let r = ranges.get(data);
  if (!r) {
    let [lo, hi] = [Infinity, -Infinity];
    for (let i = 0; i < data.length; i++) {
      const v = data[i];
      if (v < lo) lo = v;
      if (v > hi) hi = v;
    }
    r = Number.isFinite(lo) ? [lo, hi] : null;
    ranges.set(data, r);
  }
  return r;
}

/**
 * A layer in words: its name, size, where it starts when not at (0, 0),
 * its range (`scale`: the painting's, { min, max }; null: not painted yet).
 */
export function layerWords(l, scale) {
  const at = l.c0 || l.r0 ? ` from column ${l.c0}, row ${l.r0}` : "";
  const range = !scale ? "its range is given when it is shown" : Number.isFinite(scale.min) ? `values from ${fmt(scale.min)} to ${fmt(scale.max)}` : "no values";
  return `${l.name}, ${l.width} × ${l.height} pixels${at}, ${range}${l.signed ? " (signed)" : ""}`;
}

/**
 * Points in words (`p`: 6 numbers each, worker.js; `op`: "forstner" —
 * [c, r, λmax(Σuv), σmax, σmin, angle], the most precise first — or
 * "moravec" — [c, r, mean, …], the strongest first).
 */
export function pointsWords(p, op) {
  const n = p.length / 6;
  const forstner = op === "forstner";
  // the first FIRST_POINTS in that order (the earlier of equals first), one pass: a 12 MP photo may have 100 000 points
  const key = (i) => (forstner ? p[6 * i + 3] : -p[6 * i + 2]);
  const idx = [];
  for (let i = 0; i < n; i++) {
    const k = key(i);
    if (idx.length === FIRST_POINTS && !(k < key(idx[FIRST_POINTS - 1]))) continue;
    let j = idx.length;
    while (j > 0 && key(idx[j - 1]) > k) j--;
    idx.splice(j, 0, i);
    if (idx.length > FIRST_POINTS) idx.pop();
  }
  const first = idx.map((i) => `column ${fmt(p[6 * i])}, row ${fmt(p[6 * i + 1])} (${forstner ? `σmax ${fmt(p[6 * i + 3], 3)} px` : `mean ${fmt(p[6 * i + 2])}`})`);
  if (!n) return "No interest points found.";
  return `${n} interest point${n === 1 ? "" : "s"} found; ${forstner ? "the most precise (smallest error ellipse)" : "the strongest"}: ${first.join("; ")}.`;
}

export class Explorer {
  constructor(lab) {
    this.lab = lab;
    this.points = null;
    const button = (id, text, label, f) => {
      const b = el("button", { type: "button", id, "aria-label": label, title: label }, text);
      b.addEventListener("click", () => {
        const v = lab.viewer;
        if (v.image) f(v, [v.canvas.width / 2, v.canvas.height / 2], 40 * (v.dpr || 1));
      });
      return b;
    };
    this.dataButton = el("button", { type: "button", id: "lab-data-toggle", "aria-expanded": "false", "aria-controls": "lab-data" }, "Data");
    this.dataButton.addEventListener("click", () => this.toggleData());
    this.bar = el("div", { class: "lab-viewbar", id: "lab-viewbar", role: "group", "aria-label": "Zoom and pan the view" },
      button("lab-zoom-in", "+", "Zoom in", (v, m) => v.zoomAt(1.25, ...m)),
      button("lab-zoom-out", "−", "Zoom out", (v, m) => v.zoomAt(0.8, ...m)),
      button("lab-fit", "Fit", "Fit the whole photo", (v) => v.fit()),
      button("lab-pan-left", "←", "Pan left", (v, m, s) => v.pan(s, 0)),
      button("lab-pan-up", "↑", "Pan up", (v, m, s) => v.pan(0, s)),
      button("lab-pan-down", "↓", "Pan down", (v, m, s) => v.pan(0, -s)),
      button("lab-pan-right", "→", "Pan right", (v, m, s) => v.pan(-s, 0)),
      this.dataButton);
    this.desc = el("p", { id: "lab-view-desc", class: "lab-view-desc" }, "No photo open yet.");
    this.tables = el("div", { class: "lab-data-tables", id: "lab-data-tables" });
    this.panel = el("section", { class: "lab-data", id: "lab-data", hidden: true, "aria-labelledby": "lab-data-title" },
      el("h3", { id: "lab-data-title" }, "Data"),
      this.desc,
      el("p", { class: "muted" }, "Focus the photo and move its cursor with the arrow keys: the tables show the pixels around it."),
      this.tables);
  }

  toggleData() {
    const open = this.panel.hidden;
    this.panel.hidden = !open;
    this.dataButton.setAttribute("aria-expanded", String(open));
    if (open) this.update();
  }

  /** The result's points (null: none) for the description. */
  setPoints(p, op) {
    this.points = p ? { p, op } : null;
    this.describe();
  }

  /**
   * The description of the view: the photo, the layers (the one shown
   * first), the points. Layer ranges come from their paintings (the
   * worker's); the newest call wins.
   */
  async describe() {
    const gen = (this.describeGen = (this.describeGen ?? 0) + 1);
    const lab = this.lab;
    const img = lab.image;
    if (!img) {
      this.desc.textContent = "No photo open yet.";
      return;
    }
    const g = img.width * img.height <= RANGE_PIXELS ? rangeOf(img.grey) : null;
    const parts = [`${img.name}: ${img.width} × ${img.height} pixels, ${g ? `grey values from ${fmt(g[0])} to ${fmt(g[1])}` : `grey values on a scale of 0 to ${fmt(img.maxValue)}`}.`];
    const shown = lab.layers[Number(lab.layerSelect.value)];
    const scales = await Promise.all(lab.layers.map((l) => paintedOf(l)));
    if (gen !== this.describeGen) return;
    const words = (l) => layerWords(l, scales[lab.layers.indexOf(l)]?.scale ?? null);
    if (shown) {
      const how = lab.modeSelect.value === "beside" ? "beside the photo" : `over the photo at ${Math.round(Number(lab.opacity.value) * 100)} % opacity`;
      parts.push(`Result layer shown (${how}): ${words(shown)}.`);
      const others = lab.layers.filter((l) => l !== shown);
      if (others.length) parts.push(`Other layers: ${others.map(words).join("; ")}.`);
    }
    if (this.points) parts.push(pointsWords(this.points.p, this.points.op));
    this.desc.textContent = parts.join(" ");
  }

  /** The description and, when the Data view is open, its tables around the cursor. */
  update() {
    this.describe();
    if (this.panel.hidden) return;
    const v = this.lab.viewer;
    const img = this.lab.image;
    if (!img) {
      this.tables.replaceChildren();
      return;
    }
    const at = v.cursor ?? (this.lab.picked ?? v.centrePixel());
    const layer = this.lab.layers[Number(this.lab.layerSelect.value)] ?? null;
    this.tables.replaceChildren(...aroundTables("lab-data", img, layer, at));
  }
}

/**
 * The Data view's tables around pixel `at` [c, r] of a view: the grey values
 * of `img` and, when there is one, the values of `layer` (its own origin
 * c0, r0), with ids `${prefix}-grey` and `${prefix}-layer`. The photo's view
 * (Explorer) and the search photo's (families/correlation.js) show them.
 */
export function aroundTables(prefix, img, layer, [c, r]) {
  const cols = span(c, img.width);
  const rows = span(r, img.height);
  const tables = [table(`${prefix}-grey`, "Grey values", cols, rows, [c, r], (x, y) => img.grey[y * img.width + x])];
  if (layer) {
    tables.push(table(`${prefix}-layer`, `Layer “${layer.name}”`, cols, rows, [c, r], (x, y) => {
      if (x < layer.c0 || y < layer.r0 || x >= layer.c0 + layer.width || y >= layer.r0 + layer.height) return null;
      return layer.data[(y - layer.r0) * layer.width + (x - layer.c0)];
    }));
  }
  return tables;
}

/**
 * A second view's Data disclosure (the search photo's): a "Data" button
 * (aria-expanded, aria-controls) and its panel — a description (`desc`, the
 * view's aria-describedby) and the tables `fill()` makes while it is open.
 */
export function viewData(id, title, fill) {
  // named by its view ("Data: the search photo"): the photo's own Data button is beside it
  const button = el("button", { type: "button", id: `${id}-toggle`, class: "lab-data-button", "aria-expanded": "false", "aria-controls": id, "aria-label": title }, "Data");
  const desc = el("p", { id: `${id}-desc`, class: "lab-view-desc" }, "Nothing matched yet.");
  const tables = el("div", { class: "lab-data-tables" });
  const panel = el("section", { class: "lab-data", id, hidden: true, "aria-labelledby": `${id}-title` },
    el("h3", { id: `${id}-title` }, title),
    desc,
    el("p", { class: "muted" }, "Focus the view and move its cursor with the arrow keys: the tables show the pixels around it."),
    tables);
  const update = () => {
    if (!panel.hidden) tables.replaceChildren(...fill());
  };
  button.addEventListener("click", () => {
    panel.hidden = !panel.hidden;
    button.setAttribute("aria-expanded", String(!panel.hidden));
    update();
  });
  return { button, panel, desc, update };
}

/** The indices HALF either side of `i`, inside 0 … n − 1. */
function span(i, n) {
  const out = [];
  for (let k = Math.max(0, i - HALF); k <= Math.min(n - 1, i + HALF); k++) out.push(k);
  return out;
}

/** A table of `value(c, r)` over `cols` × `rows` with row and column headers, the cursor's cell marked. */
function table(id, what, cols, rows, [cc, cr], value) {
  return el("div", { class: "lab-data-scroll", tabindex: "0", role: "region", "aria-label": `${what} around the cursor` },
    el("table", { class: "lab-table lab-data-table", id },
      el("caption", {}, `${what}, columns ${cols[0]} to ${cols.at(-1)}, rows ${rows[0]} to ${rows.at(-1)}; the cursor (column ${cc}, row ${cr}) is outlined.`),
      el("thead", {}, el("tr", {}, el("th", { scope: "col" }, "row \\ column"), cols.map((c) => el("th", { scope: "col" }, String(c))))),
      el("tbody", {}, rows.map((r) => el("tr", {}, el("th", { scope: "row" }, String(r)),
        cols.map((c) => {
          const v = value(c, r);
          const text = Number.isFinite(v) ? fmt(v) : "–";
          return c === cc && r === cr
            ? el("td", { class: "lab-data-cursor", "data-value": String(v) }, el("strong", {}, text), el("span", { class: "visually-hidden" }, ", the cursor"))
            : el("td", { "data-value": String(v) }, text);
        }))))));
}
