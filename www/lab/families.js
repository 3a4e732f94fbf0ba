// The lab's operator families: each builds its controls, asks the worker
// for results, draws them, and explains a clicked output pixel with the link
// to its worked example (explain.js). The parameters are those of the
// worked examples.

import { el } from "../dom.js";
import * as X from "./explain.js";
import { fmt } from "./view.js";
import { Live } from "./live.js";

const BORDERS = [["replicate", "replicate the edge"], ["reflect", "reflect at the edge"], ["zero", "zero outside"], ["crop", "crop (interior only)"]];
const KERNELS = [
  ["mean", "3×3 mean (1/9)"], ["weighted-mean", "3×3 weighted mean (1/10)"], ["gaussian-3", "3×3 Gaussian (1/16)"],
  ["gaussian-5", "5×5 Gaussian (1/256)"], ["laplacian-4", "Laplacian, 4 neighbours"], ["laplacian-8", "Laplacian, 8 neighbours"],
  ["log", "Laplacian of Gaussian (5×5)"], ["sharpen", "Sharpening (Lecture 7)"], ["high-pass", "High-pass (Lecture 7)"], ["median", "3×3 median"],
];

export function select(id, label, options, value) {
  const s = el("select", { id }, options.map(([v, t]) => el("option", { value: v }, t)));
  s.value = value;
  return [s, el("label", {}, `${label} `, s)];
}

export function number(id, label, value, attrs = {}) {
  const i = el("input", { id, type: "number", value: String(value), step: "any", ...attrs });
  return [i, el("label", {}, `${label} `, i)];
}

export function runButton(text = "Run") {
  return el("button", { type: "button", class: "lab-run", id: "lab-run" }, text);
}

export function needImage(lab) {
  if (!lab.image) {
    lab.showError("Open a photo first (a sample or your own file).");
    return false;
  }
  return true;
}

function layerValue(layer, c, r) {
  if (!layer || c < layer.c0 || r < layer.r0 || c >= layer.c0 + layer.width || r >= layer.r0 + layer.height) return null;
  const v = layer.data[(r - layer.r0) * layer.width + (c - layer.c0)];
  return Number.isFinite(v) ? v : null;
}

function currentLayer(lab) {
  return lab.layers[Number(lab.layerSelect.value)] ?? null;
}

// ---------------------------------------------------------------- filters

/** The largest custom kernel side (as in filter-window and lab/src/ops.rs). */
export const MAX_KERNEL = 15;

/**
 * A custom kernel typed as rows of numbers (rows on lines or after ";",
 * numbers by spaces or commas) and a divisor (blank: normalised by the
 * weights' sum). The same rules and messages as ops::custom_kernel in
 * Rust (which checks it again): `{ rows, divisor }` or `{ field, error }`.
 */
export function parseKernel(text, divisorText = "") {
  const rows = [];
  for (const line of text.split(/[\n;]/)) {
    if (!line.trim()) continue;
    const row = [];
    for (const token of line.trim().split(/[ ,\t\r]+/).filter(Boolean)) {
      const v = /^[+-]?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?$/i.test(token) ? Number(token) : NaN;
      if (!Number.isFinite(v)) return { field: "custom_kernel", error: `row ${rows.length + 1}: "${token}" is not a number` };
      row.push(v);
    }
    if (rows.length && rows[0].length !== row.length) {
      return { field: "custom_kernel", error: `row ${rows.length + 1} has ${row.length} numbers but row 1 has ${rows[0].length}; every row needs the same number` };
    }
    rows.push(row);
  }
  const h = rows.length;
  const w = h ? rows[0].length : 0;
  if (!h) return { field: "custom_kernel", error: "is empty; type rows of numbers, e.g. 1 2 1 / 2 4 2 / 1 2 1 on three lines" };
  if (h > MAX_KERNEL || w > MAX_KERNEL) return { field: "custom_kernel", error: `is ${h}×${w} (rows × columns); at most ${MAX_KERNEL}×${MAX_KERNEL} is allowed` };
  if (h % 2 === 0 || w % 2 === 0) return { field: "custom_kernel", error: `is ${h}×${w} (rows × columns); a kernel needs an odd number of rows and of columns, so that it has a centre pixel` };
  if (rows.flat().every((v) => v === 0)) return { field: "custom_kernel", error: "all weights are 0: the result would be 0 everywhere" };
  let divisor;
  if (divisorText.trim() === "") {
    divisor = rows.flat().reduce((a, b) => a + b, 0);
    if (divisor === 0) return { field: "custom_divisor", error: "the weights sum to 0, so the kernel cannot be normalised; give a divisor (1 applies it as written)" };
  } else {
    divisor = Number(divisorText);
    if (!Number.isFinite(divisor) || divisor === 0) return { field: "custom_divisor", error: "must be a finite number other than 0" };
  }
  return { rows, divisor, width: w, height: h, normalised: divisorText.trim() === "" };
}

/** The k×k mean as a custom kernel (ones, divisor k²): the size slider's kernel. */
export function meanKernel(k) {
  return { rows: Array.from({ length: k }, () => Array(k).fill(1)), divisor: k * k, width: k, height: k };
}

const filters = {
  id: "filters",
  title: "Filters (smoothing, sharpening, median)",
  create(lab, box) {
    const kernels = [...KERNELS, ["mean-k", "k×k mean (size slider, live)"], ["custom", "Custom kernel (type it)"]];
    const [kernel, kernelLabel] = select("lab-kernel", "Kernel", kernels, "mean");
    const [border, borderLabel] = select("lab-border", "Border", BORDERS, "replicate");
    const run = runButton();
    // the size slider: recomputes while dragged (a new value cancels the run)
    const size = el("input", { type: "range", id: "lab-size", min: "3", max: String(MAX_KERNEL), step: "2", value: "5", "aria-describedby": "lab-size-out" });
    const sizeOut = el("output", { id: "lab-size-out", for: "lab-size" }, "5×5");
    const sizeLabel = el("label", { class: "lab-slider" }, "Size ", size, " ", sizeOut);
    // the custom kernel: text, divisor, the message at the field
    const customText = el("textarea", { id: "lab-custom", rows: "4", cols: "24", spellcheck: "false", "aria-describedby": "lab-custom-help lab-custom-error" }, "1 2 1\n2 4 2\n1 2 1");
    const divisor = el("input", { id: "lab-divisor", type: "text", inputmode: "decimal", size: "8", placeholder: "normalise", "aria-describedby": "lab-custom-help lab-custom-error" });
    const customError = el("p", { class: "field-error lab-field-error", id: "lab-custom-error", role: "alert", hidden: true });
    const customBox = el("div", { class: "lab-custom", id: "lab-custom-box" },
      el("label", {}, "Kernel rows ", customText), " ",
      el("label", {}, "Divisor ", divisor),
      customError,
      el("p", { class: "muted", id: "lab-custom-help" }, `One row per line (or rows separated by ;), numbers by spaces or commas; odd sizes up to ${MAX_KERNEL}×${MAX_KERNEL}, rows and columns may differ. Applied as written (no flip). Leave the divisor empty to normalise (divide by the sum of the weights).`));
    box.append(kernelLabel, " ", sizeLabel, " ", borderLabel, " ", run, customBox);
    let used = null;
    const sync = () => {
      sizeLabel.hidden = kernel.value !== "mean-k";
      customBox.hidden = kernel.value !== "custom";
      sizeOut.textContent = `${size.value}×${size.value}`;
    };
    const check = () => {
      const k = parseKernel(customText.value, divisor.value);
      customError.hidden = !k.error;
      customError.textContent = k.error ? `${k.field === "custom_divisor" ? "Divisor" : "Kernel"}: ${k.error}` : "";
      customText.setAttribute("aria-invalid", String(k.field === "custom_kernel"));
      divisor.setAttribute("aria-invalid", String(k.field === "custom_divisor"));
      return k;
    };
    kernel.addEventListener("change", sync);
    customText.addEventListener("input", check);
    divisor.addEventListener("input", check);
    sync();
    const live = new Live(lab, "filter");
    const go = () => {
      if (!needImage(lab)) return;
      const name = kernel.value;
      let args = { kernel: name, border: border.value };
      let custom = null;
      if (name === "custom") {
        custom = check();
        if (custom.error) {
          (custom.field === "custom_divisor" ? divisor : customText).focus();
          return;
        }
        args = { ...args, kernel: "custom", custom: customText.value, divisor: custom.normalised ? undefined : custom.divisor };
      } else if (name === "mean-k") {
        const k = Number(size.value);
        custom = meanKernel(k);
        args = { ...args, kernel: "custom", custom: custom.rows.map((r) => r.join(" ")).join("\n"), divisor: custom.divisor };
      }
      const layerName = name === "mean-k" ? `mean ${size.value}×${size.value}` : name;
      live.request({
        type: "filter",
        args,
        label: `Filtering (${layerName})`,
        cancel: true,
        apply(r) {
          used = { ...args, name, custom };
          r.layers[0].name = layerName;
          lab.setLayers(r.layers);
          document.body.dataset.filterShown = layerName;
        },
      });
    };
    run.addEventListener("click", go);
    size.addEventListener("input", () => {
      sync();
      if (lab.image) go();
    });
    return {
      async pick(c, r) {
        const layer = currentLayer(lab);
        const v = layerValue(layer, c, r);
        if (!used || v === null) return;
        if (used.custom) {
          const { rows, divisor: d, width, height } = used.custom;
          const win = await lab.run("neighbourhood", { c, r, w: width + 2, h: height + 2, border: used.border }, "Reading the window");
          const link = win ? X.customFilterLink(rows, d, win, width + 2) : null;
          lab.showExplain(`${layer.name} at column ${c}, row ${r}:`, v, link);
          return;
        }
        const k = X.kernelSide(used.kernel);
        const side = k + 2;
        const win = await lab.run("neighbourhood", { c, r, w: side, h: side, border: used.border }, "Reading the window");
        const link = win ? X.filterLink(used.kernel, win, side) : null;
        lab.showExplain(`${used.kernel} at column ${c}, row ${r}:`, v, link);
      },
    };
  },
};

// ---------------------------------------------------------------- edges

const edges = {
  id: "edges",
  title: "Edges (Prewitt, Sobel)",
  create(lab, box) {
    const [op, opLabel] = select("lab-operator", "Edge operator", [["prewitt", "Prewitt"], ["sobel", "Sobel"]], "sobel");
    const [border, borderLabel] = select("lab-border", "Border", BORDERS, "replicate");
    const run = runButton();
    box.append(opLabel, " ", borderLabel, " ", run,
      el("p", { class: "muted" }, "gx = top row minus bottom row, gy = right column minus left (the course's kernels, applied as written); direction = atan2(gy, gx) in degrees."));
    let used = null;
    run.addEventListener("click", async () => {
      if (!needImage(lab)) return;
      const args = { operator: op.value, border: border.value };
      const r = await lab.run("edges", args, "Finding edges");
      if (!r) return;
      used = args;
      lab.setLayers(r.layers, 2);
    });
    return {
      async pick(c, r) {
        const layer = currentLayer(lab);
        const v = layerValue(layer, c, r);
        if (!used || v === null) return;
        let link = null;
        {
          const win = await lab.run("neighbourhood", { c, r, w: 5, h: 5, border: used.border }, "Reading the window");
          if (win) link = X.edgeLink(used.operator, win, layer.name);
        }
        lab.showExplain(`${used.operator} ${layer.name} at column ${c}, row ${r}:`, v, link);
      },
    };
  },
};

// ---------------------------------------------------------------- interest operators

const ELLIPSE_MAGNIFY = 10;

const interest = {
  id: "interest",
  title: "Interest points (Förstner, Moravec)",
  create(lab, box) {
    const [op, opLabel] = select("lab-interest", "Interest operator", [["forstner", "Förstner"], ["moravec", "Moravec"]], "forstner");
    const [size, sizeLabel] = number("lab-window", "Window", 5, { min: "3", max: "15", step: "1" });
    const [sigma, sigmaLabel] = number("lab-sigma", "σn (grey values)", 8, { min: "0.01" });
    // the threshold is a live slider: it re-thresholds the kept map
    // its default is chosen for each photo (the strongest 0.1 % of w: ops::auto_threshold) until the student moves it
    const thr = el("input", { type: "range", id: "lab-threshold", min: "0.01", max: "3", step: "0.01", value: "0.5", "aria-describedby": "lab-threshold-out lab-threshold-rule" });
    const rule = el("p", { class: "muted", id: "lab-threshold-rule" });
    // while the photo's own T is used: its exact value (the slider shows its nearest step; the link leaves it out)
    let autoT = null;
    let thrSet = false;
    thr.addEventListener("change", () => {
      thrSet = true;
      autoT = null;
      delete thr.dataset.auto;
    });
    const thrOut = el("output", { id: "lab-threshold-out", for: "lab-threshold" }, "0.5 px");
    const thrLabel = el("label", { class: "lab-slider" }, "Threshold T ", thr, " ", thrOut);
    const [qmin, qLabel] = number("lab-qmin", "Roundness q ≥", 0.5, { min: "0", max: "1" });
    const [mthr, mthrLabel] = number("lab-mthreshold", "Moravec threshold", 2000, { min: "0" });
    const run = runButton();
    const note = el("p", { class: "muted" });
    const sync = () => {
      const f = op.value === "forstner";
      for (const l of [sigmaLabel, thrLabel, qLabel, rule]) l.hidden = !f;
      mthrLabel.hidden = f;
      if (!f && Number(size.value) === 5) size.value = "4";
      if (f && Number(size.value) === 4) size.value = "5";
      note.textContent = f
        ? `Lecture 21's rule: keep pixels whose error ellipse has λmax(Σuv) ≤ T² (and q ≥ the roundness), then the best in each window. Ellipses drawn ${ELLIPSE_MAGNIFY}× enlarged.`
        : "The worked examples' rule (Example 14): keep pixels whose mean of squared differences exceeds the threshold, then the largest in each window.";
    };
    op.addEventListener("change", sync);
    sync();
    box.append(opLabel, " ", sizeLabel, " ", sigmaLabel, " ", thrLabel, " ", qLabel, " ", mthrLabel, " ", run, note, rule);
    let used = null;
    const drawPoints = (p) => {
      const shapes = [];
      for (let i = 0; i < p.length; i += 6) {
        if (used.op === "forstner") {
          shapes.push({ kind: "ellipse", c: p[i], r: p[i + 1], a: p[i + 3] * ELLIPSE_MAGNIFY, b: p[i + 4] * ELLIPSE_MAGNIFY, angle: p[i + 5] + Math.PI / 2, colour: "#ff8c00" });
        } else {
          shapes.push({ kind: "dot", c: p[i], r: p[i + 1], size: 3, colour: "#ff8c00" });
        }
      }
      lab.viewer.setShapes(shapes);
      lab.say(`${p.length / 6} interest points found${used.op === "forstner" ? ` with T = ${fmt(used.thresholdPx, 3)} px` : ""}.`);
      document.body.dataset.points = String(p.length / 6);
    };
    // Förstner: the map once per window size (a new size cancels a running
    // map), then points for the current T, σn, q from the kept map
    const live = new Live(lab, "forstner");
    let mapSize = null;
    const params = () => ({ size: Number(size.value), sigmaN: Number(sigma.value), thresholdPx: autoT ?? Number(thr.value), qMin: Number(qmin.value), threshold: Number(mthr.value) });
    const points = () => {
      const args = params();
      live.request({
        type: "forstnerPoints",
        args: { sigmaN: args.sigmaN, thresholdPx: args.thresholdPx, qMin: args.qMin },
        label: "Thresholding the kept map",
        apply(r) {
          used = { op: "forstner", ...args, size: r.size };
          drawPoints(r.points);
          document.body.dataset.threshold = String(r.thresholdPx);
          document.body.dataset.mapRuns = String(r.mapRuns);
          document.body.dataset.pointsMs = r.pointsMs.toFixed(1);
        },
      });
    };
    const maps = () => {
      const n = Number(size.value);
      mapSize = null;
      live.request({
        type: "forstnerMaps",
        args: { size: n, sigmaN: Number(sigma.value) },
        label: `Förstner operator (${n}×${n} windows)`,
        cancel: true,
        apply(r) {
          mapSize = r.size;
          const a = r.auto;
          if (a && !thrSet) {
            autoT = a.thresholdPx;
            thr.value = String(autoT);
            thr.dataset.auto = "1";
            thrOut.textContent = `${fmt(autoT, 3)} px`;
          }
          rule.textContent = !a
            ? "This photo has no textured pixel (every w is 0): no threshold can be chosen from it."
            : thrSet
              ? `T = ${thr.value} px as you set it. For this photo the lab would choose ${fmt(a.thresholdPx, 3)} px: w at least ${fmt(a.wMin, 4)}, the w of its strongest ${a.share * 100} % of pixels.`
              : `T = ${fmt(a.thresholdPx, 3)} px, chosen for this photo: its strongest ${a.share * 100} % of pixels have w ≥ ${fmt(a.wMin, 4)}, and T = σn/√w_min = ${fmt(Number(sigma.value), 4)}/√${fmt(a.wMin, 4)} keeps the pixels whose λmin(N) ≥ w_min (w ≤ λmin(N) ≤ 2w). A fixed T would keep the photo's texture as well; move the slider to choose your own.`;
          used = { op: "forstner", ...params(), size: r.size };
          lab.setLayers(r.layers);
          document.body.dataset.mapRuns = String(r.mapRuns);
          points();
        },
      });
    };
    const retune = (ev) => {
      if (ev?.target === thr) {
        // the student's T (moved, not yet let go) stays theirs: a new map keeps it
        thrSet = true;
        autoT = null;
        delete thr.dataset.auto;
      }
      thrOut.textContent = autoT === null ? `${thr.value} px` : `${fmt(autoT, 3)} px`;
      if (op.value !== "forstner" || !lab.image) return;
      if (mapSize !== null && mapSize === Number(size.value)) points();
      // (while a map is computed, its points follow with the newest values)
    };
    for (const input of [thr, sigma, qmin]) input.addEventListener("input", retune);
    size.addEventListener("change", () => {
      if (op.value === "forstner" && lab.image && (mapSize !== null || live.busy)) maps();
    });
    run.addEventListener("click", async () => {
      if (!needImage(lab)) return;
      if (op.value === "forstner") {
        maps();
        return;
      }
      const args = params();
      const r = await lab.run(op.value, args, "Moravec operator");
      if (!r) return;
      used = { op: op.value, ...args };
      lab.setLayers(r.layers);
      drawPoints(r.points);
    });
    return {
      imageChanged() {
        mapSize = null;
        thrSet = false;
        autoT = null;
        rule.textContent = "";
      },
      async pick(c, r) {
        const layer = currentLayer(lab);
        const v = layerValue(layer, c, r);
        if (!used || v === null) return;
        const n = used.size;
        const a = Math.floor((n - 1) / 2);
        const win = await lab.run("window", { c: c - a, r: r - a, w: n, h: n }, "Reading the window");
        if (!win) return;
        const link = used.op === "forstner"
          ? X.forstnerLink(win, n, used.sigmaN, used.thresholdPx, layer.name)
          : X.moravecLink(win, n);
        lab.showExplain(`${layer.name} of the ${n}×${n} window at column ${c}, row ${r}:`, v, link);
      },
    };
  },
};

export const FAMILIES = [filters, edges, interest];
