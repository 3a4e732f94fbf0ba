// The filters family: the filter-window example's kernels over the whole
// photo, a k×k mean on a live size slider, and a custom kernel typed by the
// student (checked by the lab's wasm module, ops::custom_kernel, in the
// worker: the messages name the field).

import { el } from "../../dom.js";
import * as X from "../explain.js";
import { Live } from "../live.js";
import { testHook } from "../../test-hooks.js";
import { BORDERS, currentLayer, layerValue, needImage, runButton, select, showPixel } from "./common.js";

const KERNELS = [
  ["mean", "3×3 mean (1/9)"], ["weighted-mean", "3×3 weighted mean (1/10)"], ["gaussian-3", "3×3 Gaussian (1/16)"],
  ["gaussian-5", "5×5 Gaussian (1/256)"], ["laplacian-4", "Laplacian, 4 neighbours"], ["laplacian-8", "Laplacian, 8 neighbours"],
  ["log", "Laplacian of Gaussian (5×5)"], ["sharpen", "Sharpening (Lecture 7)"], ["high-pass", "High-pass (Lecture 7)"], ["median", "3×3 median"],
];

/** The size slider's largest side, and the help's (ops::MAX_CUSTOM_KERNEL: the worker's check says it too). */
const MAX_KERNEL = 15;

/** The divisor field as the worker's check takes it: blank normalises (undefined), else its number (NaN when it is none: the check says so). */
function divisorOf(text) {
  return text.trim() === "" ? undefined : Number(text);
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
    // the custom kernel checked by the lab's wasm module (ops::custom_kernel,
    // the rules run_filter reads it by) in the worker: { rows, divisor,
    // width, height } or { field, error }; null when a newer text is being
    // checked (a worker replaced meanwhile, by a cancel or a trap: asked
    // again of the fresh one)
    let checks = 0;
    const check = async () => {
      const gen = ++checks;
      let k;
      try {
        const r = await lab.client.call("checkKernel", { custom: customText.value, divisor: divisorOf(divisor.value) });
        const rows = Array.from(r.rows, (row) => Array.from(row));
        k = { rows, divisor: r.divisor, width: rows[0].length, height: rows.length };
      } catch (e) {
        if (e.cancelled || e.trapped) return gen === checks ? check() : null;
        const m = /^(custom_kernel|custom_divisor): ([^]*)$/.exec(e.message);
        k = m ? { field: m[1], error: m[2] } : { field: "custom_kernel", error: e.message };
      }
      if (gen !== checks) return null;
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
    const go = async () => {
      if (!needImage(lab)) return;
      const name = kernel.value;
      let args = { kernel: name, border: border.value };
      let custom = null;
      if (name === "custom") {
        const text = customText.value;
        const d = divisorOf(divisor.value);
        custom = await check();
        if (!custom) return;
        if (custom.error) {
          (custom.field === "custom_divisor" ? divisor : customText).focus();
          return;
        }
        args = { ...args, kernel: "custom", custom: text, divisor: d };
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
          used = { ...args, name, custom, args };
          r.layers[0].name = layerName;
          lab.setLayers(r.layers);
          testHook("filterShown", layerName);
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
          await showPixel(lab, `${layer.name} at column ${c}, row ${r}:`, v, { op: "filter", args: used.args, layer: layer.name, c, r }, link);
          return;
        }
        const k = X.kernelSide(used.kernel);
        const side = k + 2;
        const win = await lab.run("neighbourhood", { c, r, w: side, h: side, border: used.border }, "Reading the window");
        const link = win ? X.filterLink(used.kernel, win, side) : null;
        await showPixel(lab, `${used.kernel} at column ${c}, row ${r}:`, v, { op: "filter", args: used.args, layer: layer.name, c, r }, link);
      },
    };
  },
};

export default filters;
