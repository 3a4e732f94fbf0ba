// The lab's operator families: each builds its controls, asks the worker
// for results, draws them, and explains a clicked output pixel with the link
// to its worked example (explain.js). The parameters are those of the
// worked examples.

import { el } from "../dom.js";
import * as X from "./explain.js";

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

const filters = {
  id: "filters",
  title: "Filters (smoothing, Laplacian, sharpening, median)",
  create(lab, box) {
    const [kernel, kernelLabel] = select("lab-kernel", "Kernel", KERNELS, "mean");
    const [border, borderLabel] = select("lab-border", "Border", BORDERS, "replicate");
    const run = runButton();
    box.append(kernelLabel, " ", borderLabel, " ", run);
    let used = null;
    run.addEventListener("click", async () => {
      if (!needImage(lab)) return;
      const args = { kernel: kernel.value, border: border.value };
      const r = await lab.run("filter", args, "Filtering");
      if (!r) return;
      used = args;
      lab.setLayers(r.layers);
    });
    return {
      async pick(c, r) {
        const layer = currentLayer(lab);
        const v = layerValue(layer, c, r);
        if (!used || v === null) return;
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
    const [op, opLabel] = select("lab-operator", "Operator", [["prewitt", "Prewitt"], ["sobel", "Sobel"]], "sobel");
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
        if (layer.name !== "direction") {
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
    const [op, opLabel] = select("lab-interest", "Operator", [["forstner", "Förstner"], ["moravec", "Moravec"]], "forstner");
    const [size, sizeLabel] = number("lab-window", "Window", 5, { min: "3", max: "15", step: "1" });
    const [sigma, sigmaLabel] = number("lab-sigma", "σn (grey values)", 8, { min: "0.01" });
    const [thr, thrLabel] = number("lab-threshold", "Threshold T (px)", 0.5, { min: "0.01" });
    const [qmin, qLabel] = number("lab-qmin", "Roundness q ≥", 0.5, { min: "0", max: "1" });
    const [mthr, mthrLabel] = number("lab-mthreshold", "Moravec threshold", 2000, { min: "0" });
    const run = runButton();
    const note = el("p", { class: "muted" });
    const sync = () => {
      const f = op.value === "forstner";
      for (const l of [sigmaLabel, thrLabel, qLabel]) l.hidden = !f;
      mthrLabel.hidden = f;
      if (!f && Number(size.value) === 5) size.value = "4";
      if (f && Number(size.value) === 4) size.value = "5";
      note.textContent = f
        ? `Lecture 21's rule: keep pixels whose error ellipse has λmax(Σuv) ≤ T² (and q ≥ the roundness), then the best in each window. Ellipses drawn ${ELLIPSE_MAGNIFY}× enlarged.`
        : "The worked examples' rule (Example 14): keep pixels whose mean of squared differences exceeds the threshold, then the largest in each window.";
    };
    op.addEventListener("change", sync);
    sync();
    box.append(opLabel, " ", sizeLabel, " ", sigmaLabel, " ", thrLabel, " ", qLabel, " ", mthrLabel, " ", run, note);
    let used = null;
    run.addEventListener("click", async () => {
      if (!needImage(lab)) return;
      const args = { size: Number(size.value), sigmaN: Number(sigma.value), thresholdPx: Number(thr.value), qMin: Number(qmin.value), threshold: Number(mthr.value) };
      const r = await lab.run(op.value, args, op.value === "forstner" ? "Förstner operator" : "Moravec operator");
      if (!r) return;
      used = { op: op.value, ...args };
      lab.setLayers(r.layers);
      const shapes = [];
      const p = r.points;
      for (let i = 0; i < p.length; i += 6) {
        if (used.op === "forstner") {
          shapes.push({ kind: "ellipse", c: p[i], r: p[i + 1], a: p[i + 3] * ELLIPSE_MAGNIFY, b: p[i + 4] * ELLIPSE_MAGNIFY, angle: p[i + 5] + Math.PI / 2, colour: "#ff8c00" });
        } else {
          shapes.push({ kind: "dot", c: p[i], r: p[i + 1], size: 3, colour: "#ff8c00" });
        }
      }
      lab.viewer.setShapes(shapes);
      lab.say(`${p.length / 6} interest points found.`);
      document.body.dataset.points = String(p.length / 6);
    });
    return {
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
