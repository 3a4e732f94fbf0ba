// "Explain this pixel": the worked example, as a normal shareable URL, whose
// inputs are the window of numbers the lab used at one output pixel, and
// where in that example's result the same number is (`key`, `index`).
// Rows of numbers in, a link out ({ id, hash, key, index }, through url.js).
// Which example explains what is the catalog's word, not this file's: each
// catalog entry names its lab family (`lab`) and the lab readings it
// `explains`; a link is null when the catalog names no example for it.

import { buildHash, MAX_URL_VALUE_LENGTH } from "../url.js";

/** "family reading" → the id of the example that explains it (from useCatalog). */
let explainers = new Map();

/** Takes the catalog's entries (core.js loadCatalog()): the examples the lab links to, by family and reading. */
export function useCatalog(entries) {
  explainers = new Map();
  for (const e of entries) for (const reading of e.explains ?? []) explainers.set(`${e.lab} ${reading}`, e.id);
}

/** The id of the worked example that explains `reading` of lab family `family`, or null. */
export function exampleFor(family, reading) {
  return explainers.get(`${family} ${reading}`) ?? null;
}

/** A link to the example explaining `family`'s `reading`, with `entries` as its inputs: { id, hash, key, index } or null. */
function linkTo(family, reading, entries, key) {
  const id = exampleFor(family, reading);
  return id ? { id, hash: buildHash(id, entries), key, index: null } : null;
}

/** Rows of numbers as the matrix text the forms read ("1,2,3;4,5,6"). */
export function matrixText(rows) {
  return rows.map((row) => row.map((v) => String(v)).join(",")).join(";");
}

/** A flat row-major array as rows of `w`. */
export function toRows(flat, w) {
  const rows = [];
  for (let i = 0; i < flat.length; i += w) rows.push(Array.from(flat.slice(i, i + w)));
  return rows;
}

/** Kernel side of the filter-window kernels. */
export function kernelSide(kernel) {
  return kernel === "gaussian-5" || kernel === "log" ? 5 : 3;
}

/**
 * The selected pixel of a window of `w × h` read round the lab's pixel (the
 * neighbourhood under the lab's border policy: the pixel is always its
 * centre), as the examples' 1-based `select_c`, `select_r`.
 */
export function centreSelection(w, h) {
  return [["select_c", String((w + 1) / 2)], ["select_r", String((h + 1) / 2)]];
}

/**
 * filter-window: the (k+2)×(k+2) neighbourhood read under the lab's border
 * policy, its centre (the lab's pixel) selected; the example's `selected`
 * (its answer line) and the centre of its 3×3 `output` are the lab's value.
 */
export function filterLink(kernel, window, side) {
  return linkTo("filters", "window", [["window", matrixText(toRows(window, side))], ["kernel", kernel], ...centreSelection(side, side)], "selected");
}

/**
 * filter-window with a custom kernel (`rows`, `divisor`): the neighbourhood
 * one pixel wider than the kernel on each side, `w` columns, its centre (the
 * lab's pixel) selected; the example's `selected` is the lab's value.
 */
export function customFilterLink(rows, divisor, window, w) {
  const h = window.length / w;
  return linkTo("filters", "window", [
    ["window", matrixText(toRows(window, w))],
    ["kernel", "custom"],
    ["custom_kernel", matrixText(rows)],
    ["custom_divisor", String(divisor)],
    ...centreSelection(w, h),
  ], "selected");
}

/**
 * edge-window: the 5×5 neighbourhood, its centre (the lab's pixel)
 * selected: the example's selected_gx, selected_gy, selected_magnitude (its
 * answer line) are the lab's gx, gy, magnitude there. edge-window has no
 * direction result: a direction pixel links to the same window with
 * `derive` saying how its value follows from the example's gx and gy
 * (`direction(gx, gy)`).
 */
export function edgeLink(operator, window, layerName) {
  const dir = layerName === "direction";
  const l = linkTo("edges", "window", [["window", matrixText(toRows(window, 5))], ["operator", operator], ...centreSelection(5, 5)], dir ? "selected_gx" : `selected_${layerName}`);
  return l && dir ? { ...l, derive: { keys: ["selected_gx", "selected_gy"], words: "Gx and Gy at the selected pixel", formula: "atan2(Gy, Gx) in degrees" } } : l;
}

/** The lab's edge direction from gx and gy: atan2(gy, gx) in degrees (as `ops::edges`). */
export function direction(gx, gy) {
  return (Math.atan2(gy, gx) * 180) / Math.PI;
}

/** forstner-window: the window whose anchor is the pixel. */
export function forstnerLink(window, size, sigmaN, thresholdPx, layerName) {
  return linkTo("interest", "forstner", [
    ["window", matrixText(toRows(window, size))],
    ["sigma_n", String(sigmaN)],
    ["threshold_px", String(thresholdPx)],
  ], layerName === "q" ? "q" : "w");
}

/** moravec-window: the window whose anchor is the pixel; its `mean`. */
export function moravecLink(window, size) {
  return linkTo("interest", "moravec", [["window", matrixText(toRows(window, size))]], "mean");
}

/** ncc-2d: the template and the same-sized window of the search image at that position. */
export function nccLink(template, window, w) {
  return linkTo("correlation", "rho", [["a", matrixText(toRows(template, w))], ["b", matrixText(toRows(window, w))]], "rho");
}

/** subpixel-2d: the 3×3 ρ round the best position, at the lab's (0-based) pixel positions. */
export function subpixelLink(best, around) {
  const [c, r] = best;
  return linkTo("correlation", "subpixel", [
    ["c", [c - 1, c, c + 1].join(",")],
    ["r", [r - 1, r, r + 1].join(",")],
    ["rho", matrixText(toRows(around, 3))],
  ], "c_max");
}

/** The longest value a link carries (url.js reads at most MAX_URL_VALUE_LENGTH characters of one). */
function fits(entries) {
  return entries.every(([, v]) => v.length <= MAX_URL_VALUE_LENGTH);
}

/**
 * lsm-2d: the template, the LSM window and the start (0-based in the
 * window; the example counts from 1), gain 1 and offset 0; `model` "shift"
 * estimates the shift only (the example's `radiometric` off). Null when a
 * window is too long for a URL.
 */
export function lsmLink(template, tw, search, sw, start, model = "shift-radiometric") {
  const entries = [
    ["template", matrixText(toRows(template, tw))],
    ["search", matrixText(toRows(search, sw))],
    ["c0", String(start[0] + 1)],
    ["r0", String(start[1] + 1)],
    ["radiometric", model === "shift" ? "false" : "true"],
    ["a0", "1"],
    ["b0", "0"],
  ];
  return fits(entries) ? linkTo("correlation", "lsm", entries, "c") : null;
}

/**
 * lsm-affine with the given patches: the template, the LSM window and the
 * start (0-based in the window; the example counts from 1), the affine part
 * the identity, gain 1, offset 0. Null when a window is too long for a URL.
 */
export function lsmAffineLink(template, tw, search, sw, start) {
  const entries = [
    ["pair", "patches"],
    ["template", matrixText(toRows(template, tw))],
    ["search", matrixText(toRows(search, sw))],
    ["c0", String(start[0] + 1)],
    ["r0", String(start[1] + 1)],
  ];
  return fits(entries) ? linkTo("correlation", "affine-lsm", entries, "parameters") : null;
}

/** resample: the 4×4 patch round (x, y), its first pixel, the position. */
export function resampleLink(patch, firstC, firstR, x, y, method) {
  return linkTo("resampling", "window", [
    ["patch", matrixText(toRows(patch, 4))],
    ["first_c", String(firstC)],
    ["first_r", String(firstR)],
    ["c", String(x)],
    ["r", String(y)],
  ], method);
}

/** chain-code: the traced boundary as [c, r] rows. */
export function chainLink(pixels) {
  const rows = [];
  for (let i = 0; i < pixels.length; i += 2) rows.push([pixels[i], pixels[i + 1]]);
  return linkTo("boundaries", "code", [["pixels", matrixText(rows)]], "code");
}
