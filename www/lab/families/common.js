// What the lab's operator families share: their controls (a select, a
// number, the Run button), the photo check, the value of the layer on
// screen at a pixel, and a link to a worked example. Each family is one
// module beside this one (www/lab/families/<family>.js, its default export:
// { id, title, create(lab, box) }); lab.js lists them in the menu's order.

import { el } from "../../dom.js";
import { fmt } from "../view.js";

/** The border rules of filters and edges (ops::border's names). */
export const BORDERS = [["replicate", "replicate the edge"], ["reflect", "reflect at the edge"], ["zero", "zero outside"], ["crop", "crop (interior only)"]];

/** A labelled <select> of [value, text] options: [the select, its label]. */
export function select(id, label, options, value) {
  const s = el("select", { id }, options.map(([v, t]) => el("option", { value: v }, t)));
  s.value = value;
  return [s, el("label", {}, `${label} `, s)];
}

/** A labelled number input: [the input, its label]. */
export function number(id, label, value, attrs = {}) {
  const i = el("input", { id, type: "number", value: String(value), step: "any", ...attrs });
  return [i, el("label", {}, `${label} `, i)];
}

/** The family's Run button (#lab-run). */
export function runButton(text = "Run") {
  return el("button", { type: "button", class: "lab-run", id: "lab-run" }, text);
}

/** Whether a photo is open; if not, says so and returns false. */
export function needImage(lab) {
  if (!lab.image) {
    lab.showError("Open a photo first (a sample or your own file).");
    return false;
  }
  return true;
}

/** The value of `layer` at pixel (c, r): null outside it or where it has none. */
export function layerValue(layer, c, r) {
  if (!layer || c < layer.c0 || r < layer.r0 || c >= layer.c0 + layer.width || r >= layer.r0 + layer.height) return null;
  const v = layer.data[(r - layer.r0) * layer.width + (c - layer.c0)];
  return Number.isFinite(v) ? v : null;
}

/** The result layer on screen, or null. */
export function currentLayer(lab) {
  return lab.layers[Number(lab.layerSelect.value)] ?? null;
}

/** A link to a worked example (explain.js's { hash, key }) with `text`. */
export function link(l, text) {
  return el("a", { href: `index.html${l.hash}`, "data-key": l.key }, text);
}

/**
 * "Explain this pixel" with its number: the exact value — the reference
 * function on the pixel's window, in the worker (wasm exact_at), the
 * number the worked example computes — and beside it the layer's own value
 * (`f32`: the fast path's result, rounded), so both are there to compare.
 * `ask`: the worker's `exact` request, { op, args, layer, c, r } (`op` and
 * `args` as the family asked for the layer). Without an exact value (an
 * error, already shown), the layer's value alone.
 */
export async function showPixel(lab, text, value, ask, link) {
  const exact = await lab.run("exact", ask, "Computing the exact value");
  if (!Number.isFinite(exact)) {
    lab.showExplain(text, value, link);
    return;
  }
  lab.showExplain(text, exact, link);
  lab.explain.querySelector("#lab-explain-value")?.after(
    " ",
    el("span", { class: "lab-layer-value muted", id: "lab-layer-value", "data-value": String(value) },
      `exact · the layer (f32) holds ${value === exact ? "the same" : fmt(value, 9)}`),
  );
}
