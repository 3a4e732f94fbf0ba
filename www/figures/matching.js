// Figures of the "Least-squares matching" topic (seed 000, Examples 10–11;
// seed 003):
//   lsm-1d: the search window, the template and the resampled search patch
//     overlaid at the position of the chosen iteration (a step-through
//     slider), and the parameters against the iteration number;
//   lsm-2d, lsm-affine: template, resampled patch and difference image side
//     by side as enlarged pixel grids at the chosen iteration, and the
//     parameters against the iteration number.

import { formatNumber } from "../format.js";
import { matrixTable, seriesTable } from "./data-view.js";
import { COLORS, FONT_SIZE_SMALL, GREY_LEGEND, dot, drawGrid, finite, greyLegend, greyScaleOf, line, text, textWidth, wrapWords } from "./draw.js";

const PAD = Object.freeze({ left: 44, right: 16, top: 34, bottom: 38 });
const DOT = 4;
const DIGITS = 5;
/** Cells at least this large (CSS px) show their numbers. */
const CELL_TEXT_MIN = 30;
const GRID_GAP = 18;
const GRID_TITLE = 22;
/** A grey scale's legend line under the grids (one for the template, one for the patch). */
const LEGEND_LINE = GREY_LEGEND.height + 4;
const MINI_HEIGHT = 74;
const MINI_GAP = 12;

const f = (x) => formatNumber(x, DIGITS);

/** The step holding the per-iteration arrays. */
function table(solution) {
  return (solution.steps ?? []).find((s) => s.title === "Every iteration")?.values ?? {};
}

function iterations(solution) {
  return Array.isArray(table(solution).sigma0) ? table(solution).sigma0.length : 0;
}

function sliderSpec(solution) {
  const n = iterations(solution);
  return n > 0 ? { label: "Iteration", min: 1, max: n, value: 1 } : null;
}

/** The chosen iteration, 0-based and clamped. */
function chosen(solution, state) {
  const n = iterations(solution);
  const k = Number.isInteger(state?.slider) ? state.slider : 1;
  return Math.min(Math.max(k, 1), Math.max(n, 1)) - 1;
}

/**
 * Motion (issue 34; index.js `frames`): iteration by iteration, each frame the
 * parameters at the iteration's start, their increments and σ₀, as the
 * "Every iteration" step carries them; the figure's own slider follows.
 */
function frames(solution) {
  const v = table(solution);
  const n = iterations(solution);
  const step = (solution.steps ?? []).findIndex((s) => s.title === "Every iteration");
  const names = Object.keys(v).filter((key) => Array.isArray(v[key]) && Array.isArray(v[`d${key}`]));
  return Array.from({ length: n }, (_, k) => ({
    k,
    slider: k + 1,
    step: step >= 0 ? step : null,
    get caption() {
      const params = names.map((key) => `${key} = ${f(v[key][k])} (d${key} = ${f(v[`d${key}`][k])})`).join(", ");
      return `Iteration ${k + 1} of ${n}: at its start ${params}; σ₀ = ${f(v.sigma0[k])}.`;
    },
  }));
}
const MOTION = Object.freeze({ frames, motion: Object.freeze({ noun: "iteration", all: false }) });

function statusWords(solution) {
  const s = solution.result?.status;
  return s === "converged" ? "converged" : s === "not-converged" ? "not converged" : s === "left-window" ? "left the search window" : s === "degenerate" ? "degenerate" : String(s ?? "");
}

// ---------------------------------------------------------------- 1-D profile

function profileDraw(ctx, w, h, solution, state) {
  const first = solution.steps?.[0]?.values ?? {};
  const search = first.search ?? [];
  const template = first.template ?? [];
  const tv = table(solution);
  const k = chosen(solution, state);
  const n = iterations(solution);
  const c = tv.c?.[k] ?? solution.result?.c ?? 0;
  const a = tv.a?.[k] ?? 1;
  const b = tv.b?.[k] ?? 0;
  const patch = tv.patches?.[k]?.[0] ?? [];
  const half = (template.length - 1) / 2;
  const pos = template.map((_, i) => c - half + i);
  const modelled = patch.map((g) => a * g + b);
  const values = [...search, ...template, ...modelled].filter(Number.isFinite);
  let lo = Math.min(0, ...values);
  let hi = Math.max(1, ...values);
  const span = hi - lo || 1;
  lo -= 0.05 * span;
  hi += 0.08 * span;
  const x0 = PAD.left;
  const x1 = w - PAD.right;
  const y0 = PAD.top;
  const y1 = h - PAD.bottom;
  const X = (p) => x0 + ((p - 0.5) / Math.max(search.length, 1)) * (x1 - x0);
  const Y = (v) => y1 - ((v - lo) / (hi - lo)) * (y1 - y0);
  // axes and the search window's pixels as bars
  line(ctx, x0, y1, x1, y1, { color: COLORS.muted });
  line(ctx, x0, y0, x0, y1, { color: COLORS.muted });
  const bar = (x1 - x0) / Math.max(search.length, 1);
  search.forEach((g, i) => {
    const p = i + 1;
    ctx.fillStyle = COLORS.frameFill;
    ctx.fillRect(X(p) - bar * 0.4, Y(g), bar * 0.8, y1 - Y(g));
    text(ctx, String(p), X(p), y1 + 10, { size: FONT_SIZE_SMALL, color: COLORS.muted, align: "center" });
  });
  text(ctx, "search-window position c", (x0 + x1) / 2, y1 + 26, { size: FONT_SIZE_SMALL, color: COLORS.muted, align: "center" });
  for (const v of [lo + 0.05 * span, hi - 0.08 * span]) {
    text(ctx, f(v), x0 - 6, Y(v), { size: FONT_SIZE_SMALL, color: COLORS.muted, align: "right" });
  }
  // the template and the modelled resampled patch at the template's pixels
  const poly = (ys, color, dash) => {
    for (let i = 1; i < ys.length; i += 1) line(ctx, X(pos[i - 1]), Y(ys[i - 1]), X(pos[i]), Y(ys[i]), { color, width: 2, dash });
    ys.forEach((v, i) => dot(ctx, X(pos[i]), Y(v), DOT, color));
  };
  poly(template, COLORS.imageSystem, null);
  poly(modelled, COLORS.pixelSystem, [6, 4]);
  line(ctx, X(c), y0, X(c), y1, { color: COLORS.highlight, dash: [3, 3] });
  const gain = tv.a ? `, a = ${f(a)}, b = ${f(b)}` : "";
  text(ctx, `iteration ${k + 1} of ${n}: c = ${f(c)}${gain}`, x0 + 4, 12, { weight: "bold" });
  const key = text(ctx, "● template G_t", x0 + 4, 27, { color: COLORS.imageSystem, size: FONT_SIZE_SMALL });
  // the patch's key in full where it fits, else shorter
  const patchKeys = tv.a ? ["● a·G_s + b resampled at the template's pixels", "● a·G_s + b, resampled"] : ["● G_s resampled at the template's pixels", "● G_s, resampled"];
  const kx = Math.max(x0 + 104, key.x + key.w + 12);
  const patchKey = patchKeys.find((t) => kx + textWidth(t, FONT_SIZE_SMALL) <= w - 4) ?? patchKeys[patchKeys.length - 1];
  text(ctx, patchKey, kx, 27, { color: COLORS.pixelSystem, size: FONT_SIZE_SMALL });
}

function profileDescribe(solution, state) {
  const k = chosen(solution, state);
  const tv = table(solution);
  return `Search window as bars with the template and the resampled search patch overlaid at iteration ${k + 1} of ${iterations(solution)}, template centre at c = ${f(tv.c?.[k] ?? 0)}; the run ${statusWords(solution)} at c = ${f(solution.result?.c ?? 0)}.`;
}

// ---------------------------------------------------------------- 2-D grids

/** Blue for negative, orange for positive, white at zero: [r, g, b] for v within ±m. */
function divergingRgb(v, m) {
  const t = m > 0 ? Math.max(-1, Math.min(1, v / m)) : 0;
  const mix = (a, b) => Math.round(a + (b - a) * Math.abs(t));
  return t < 0 ? [mix(255, 29), mix(255, 95), mix(255, 191)] : [mix(255, 217), mix(255, 119), mix(255, 6)];
}

function gridLayout(w, rows, cols) {
  const cell = Math.max(4, Math.min(56, Math.floor((w - 2 * GRID_GAP - 24) / (3 * Math.max(cols, 1)))));
  return { cell, gw: cell * cols, gh: cell * rows };
}

function gridsData(solution, state) {
  const first = solution.steps?.[0]?.values ?? {};
  const tv = table(solution);
  const k = chosen(solution, state);
  const template = first.template ?? [];
  const patch = tv.patches?.[k] ?? [];
  const diff = tv.differences?.[k] ?? [];
  return { template, patch, diff, k, n: iterations(solution) };
}

/** gridsHeight's count of note lines, by solution and width (the slider's repaints ask again). */
const noteLines = new WeakMap();

function gridsHeight(width, solution) {
  const { template } = gridsData(solution, null);
  const rows = template.length || 1;
  const cols = template[0]?.length || 1;
  const { gh } = gridLayout(width, rows, cols);
  // the notes' lines differ little between iterations: room for the longest
  const known = noteLines.get(solution);
  let lines = known?.width === width ? known.lines : 0;
  if (known?.width !== width) {
    const n = Math.max(1, iterations(solution));
    for (let k = 1; k <= n; k++) lines = Math.max(lines, gridNotes(width, gridsData(solution, { slider: k })).length);
    noteLines.set(solution, { width, lines });
  }
  return gh + GRID_TITLE + 36 + 2 * LEGEND_LINE + 16 * lines;
}

/** The grids' left edge. */
function gridsLeft(w, rows, cols) {
  const { gw } = gridLayout(w, rows, cols);
  return Math.max(8, (w - (3 * gw + 2 * GRID_GAP)) / 2);
}

/** The notes under the grids, wrapped to the canvas width. */
function gridNotes(w, { template, diff }) {
  const left = gridsLeft(w, template.length || 1, template[0]?.length || 1);
  const max = w - left - 8;
  const d = diff.flat().map((v) => finite(v));
  const dmax = Math.max(1e-9, ...d.map((v) => Math.abs(v)));
  const rms = Math.sqrt(d.reduce((sum, v) => sum + v * v, 0) / Math.max(1, d.length));
  return [...wrapWords("dL = template − (a·Gₛ + b); grey scales stretched per grid", max, FONT_SIZE_SMALL), ...wrapWords(`dL: orange positive, blue negative, up to ±${f(dmax)}; rms ${f(rms)}`, max, FONT_SIZE_SMALL)];
}

function gridsDraw(ctx, w, h, solution, state) {
  const { template, patch, diff, k, n } = gridsData(solution, state);
  const rows = template.length;
  const cols = template[0]?.length ?? 0;
  if (!rows || !cols) return;
  const { cell, gw } = gridLayout(w, rows, cols);
  const left = gridsLeft(w, rows, cols);
  const top = GRID_TITLE + 20;
  // the shared grey scale (draw.js: dark = low), stretched per grid
  const format = (v) => formatNumber(v, 4);
  const tScale = greyScaleOf(template, { name: "template", format });
  const pScale = greyScaleOf(patch.length ? patch : [0, 1], { name: "resampled Gₛ", format });
  const dmax = Math.max(1e-9, ...diff.flat().map((v) => Math.abs(finite(v))));
  text(ctx, `iteration ${k + 1} of ${n} — ${statusWords(solution)} after ${n}`, left, 12, { weight: "bold" });
  const titles = ["template", "resampled Gₛ", "difference dL"];
  const grids = [
    [template, tScale, 4],
    [patch, pScale, 4],
    [diff, { fill: (v) => `rgb(${divergingRgb(v, dmax).join(", ")})` }, 3],
  ];
  grids.forEach(([m, shade, digits], g) => {
    const x = left + g * (gw + GRID_GAP);
    text(ctx, titles[g], x, top - 10, { size: FONT_SIZE_SMALL, color: COLORS.muted });
    if (!m.length || !m[0]?.length) return;
    // one pixel a cell, no lines between them; the numbers where they fit; a frame round the grid
    drawGrid(ctx, m, x, top, cell, { shade: { fill: shade.fill, ink: shade.ink, scale: shade.note ? shade : null }, digits, numbersFrom: CELL_TEXT_MIN, lines: false });
    ctx.strokeStyle = COLORS.frameStroke;
    ctx.strokeRect(x + 0.5, top + 0.5, m[0].length * cell - 1, m.length * cell - 1);
  });
  let legendY = top + rows * cell + 6;
  for (const scale of patch.length ? [tScale, pScale] : [tScale]) {
    greyLegend(ctx, left, legendY, scale, { maxWidth: w - left - 8 });
    legendY += LEGEND_LINE;
  }
  const below = top + rows * cell + 14 + 2 * LEGEND_LINE;
  const notes = gridNotes(w, { template, diff });
  notes.forEach((t, i) => text(ctx, t, left, below + 16 * i, { size: FONT_SIZE_SMALL, color: COLORS.muted }));
}

function gridsDescribe(solution, state) {
  const { template, k, n } = gridsData(solution, state);
  return `Template, resampled search patch and difference image as ${template.length}×${template[0]?.length ?? 0} pixel grids at iteration ${k + 1} of ${n}; the run ${statusWords(solution)}.`;
}

// ---------------------------------------------------------------- parameters

const SERIES = [
  ["c", "c"],
  ["r", "r"],
  ["a", "a (gain)"],
  ["b", "b (offset)"],
  ["a1", "a1"],
  ["a2", "a2"],
  ["a3", "a3 (shift c)"],
  ["a4", "a4"],
  ["a5", "a5"],
  ["a6", "a6 (shift r)"],
  ["a7", "a7 (gain)"],
  ["a8", "a8 (offset)"],
];

/** [{ label, values (per iteration, then the end), truth? }] */
function series(solution) {
  const tv = table(solution);
  const res = solution.result ?? {};
  const out = [];
  for (const [key, label] of SERIES) {
    const vals = tv[key];
    if (!Array.isArray(vals) || !vals.length) continue;
    let end = res[key];
    let truth = null;
    if (key.length === 2 && key[0] === "a" && /\d/.test(key[1])) {
      const j = Number(key[1]) - 1;
      end = res.parameters?.[j];
      truth = res.true_parameters?.[j] ?? null;
    }
    if (typeof end !== "number" && key === "a") end = res.a;
    out.push({ label, values: [...vals, finite(end, vals[vals.length - 1])], truth });
  }
  return out;
}

function paramsLayout(w, solution) {
  const s = series(solution);
  const perRow = s.length > 4 ? 2 : 1;
  return { s, perRow, rows: Math.ceil(s.length / perRow), cw: (w - 16 - (perRow - 1) * MINI_GAP) / perRow };
}

function paramsHeight(width, solution) {
  const { rows } = paramsLayout(width, solution);
  return 30 + rows * (MINI_HEIGHT + MINI_GAP);
}

function paramsDraw(ctx, w, h, solution) {
  const { s, perRow, cw } = paramsLayout(w, solution);
  text(ctx, "parameters by iteration", 8, 12, { weight: "bold" });
  s.forEach((ser, idx) => {
    const x = 8 + (idx % perRow) * (cw + MINI_GAP);
    const y = 28 + Math.floor(idx / perRow) * (MINI_HEIGHT + MINI_GAP);
    const vals = ser.values;
    const all = ser.truth === null ? vals : [...vals, ser.truth];
    let lo = Math.min(...all);
    let hi = Math.max(...all);
    if (hi - lo < 1e-12) {
      lo -= 1;
      hi += 1;
    }
    const px0 = x + 96;
    const px1 = x + cw - 6;
    const py0 = y + 6;
    const py1 = y + MINI_HEIGHT - 14;
    const X = (i) => px0 + (vals.length > 1 ? (i / (vals.length - 1)) * (px1 - px0) : 0);
    const Y = (v) => py1 - ((v - lo) / (hi - lo)) * (py1 - py0);
    ctx.strokeStyle = COLORS.grid;
    ctx.strokeRect(px0 + 0.5, py0 + 0.5, px1 - px0, py1 - py0);
    if (ser.truth !== null) line(ctx, px0, Y(ser.truth), px1, Y(ser.truth), { color: COLORS.imageSystem, dash: [4, 3] });
    for (let i = 1; i < vals.length; i += 1) line(ctx, X(i - 1), Y(vals[i - 1]), X(i), Y(vals[i]), { color: COLORS.pixelSystem, width: 1.5 });
    if (vals.length <= 60) vals.forEach((v, i) => dot(ctx, X(i), Y(v), 2.5, COLORS.pixelSystem));
    text(ctx, ser.label, x, y + 14, { weight: "bold", size: FONT_SIZE_SMALL });
    text(ctx, f(vals[vals.length - 1]), x, y + 30, { size: FONT_SIZE_SMALL, color: COLORS.pixelSystem });
    if (ser.truth !== null) text(ctx, `true ${f(ser.truth)}`, x, y + 45, { size: FONT_SIZE_SMALL, color: COLORS.imageSystem });
    text(ctx, "1", px0, py1 + 8, { size: FONT_SIZE_SMALL, color: COLORS.muted, align: "center" });
    text(ctx, "end", px1, py1 + 8, { size: FONT_SIZE_SMALL, color: COLORS.muted, align: "right" });
  });
}

function paramsDescribe(solution) {
  const s = series(solution);
  return `The parameters against the iteration number: ${s.map((x) => `${x.label} ends at ${f(x.values[x.values.length - 1])}`).join("; ")}; the run ${statusWords(solution)} after ${iterations(solution)} iterations.`;
}

// ---------------------------------------------------------------- Data views (index.js tables())

const cellText = (v) => (typeof v === "number" && Number.isFinite(v) ? f(v) : "no value");

function gridsTables(solution, state) {
  const { template, patch, diff, k, n } = gridsData(solution, state);
  const rows = template.length;
  const cols = template[0]?.length ?? 0;
  const mark = (r, c) => (patch.length ? `resampled Gₛ ${cellText(patch[r]?.[c])}, difference dL ${cellText(diff[r]?.[c])}` : null);
  return {
    summary: `${gridsDescribe(solution, state)} ${paramsDescribe(solution)}`,
    tables: [
      matrixTable(`Template (each cell also gives the resampled patch and the difference at iteration ${k + 1} of ${n})`, template, {
        format: cellText,
        mark,
        explore: {
          rect(r, c, width) {
            const { cell } = gridLayout(width, rows, cols);
            return { x: gridsLeft(width, rows, cols) + c * cell, y: GRID_TITLE + 20 + r * cell, w: cell, h: cell };
          },
        },
      }),
      matrixTable(`Resampled search patch Gₛ at iteration ${k + 1}`, patch, { format: cellText }),
      matrixTable(`Difference dL at iteration ${k + 1}`, diff, { format: cellText }),
    ],
  };
}

function paramsTables(solution) {
  const s = series(solution);
  const n = Math.max(0, ...s.map((x) => x.values.length - 1));
  const truth = s.some((x) => x.truth !== null);
  const columns = [...Array.from({ length: n }, (_, i) => `iteration ${i + 1}`), "end", ...(truth ? ["true value"] : [])];
  return {
    summary: paramsDescribe(solution),
    tables: [
      {
        caption: "Each parameter at the start of every iteration and after the last update (the plotted series)",
        corner: "parameter",
        columns,
        rowHeaders: s.map((x) => x.label),
        rows: s.map((x) => [...x.values.map(cellText), ...(truth ? [x.truth === null ? "" : cellText(x.truth)] : [])]),
      },
    ],
  };
}

function profileTables(solution, state) {
  const first = solution.steps?.[0]?.values ?? {};
  const search = Array.isArray(first.search) ? first.search : [];
  const template = Array.isArray(first.template) ? first.template : [];
  const tv = table(solution);
  const k = chosen(solution, state);
  const patch = tv.patches?.[k]?.[0] ?? [];
  return {
    summary: `${profileDescribe(solution, state)} ${paramsDescribe(solution)}`,
    tables: [
      seriesTable("The search window (the bars)", ["position", "grey value"], search.map((v, i) => [String(i + 1), cellText(v)])),
      seriesTable(`The template and the search patch resampled at iteration ${k + 1}`, ["template pixel", "template G_t", "resampled G_s"], template.map((v, i) => [String(i + 1), cellText(v), cellText(patch[i])])),
    ],
  };
}

const PARAMS = Object.freeze({
  tables: paramsTables,
  caption: "Each parameter at the start of every iteration and after the last update; dashed: the true value where it is known.",
  height: paramsHeight,
  describe: paramsDescribe,
  draw: paramsDraw,
});

const GRIDS = Object.freeze({
  caption: "Template, the search patch resampled (bilinear) at the chosen iteration's parameters, and their difference. Move the slider to step through the iterations.",
  height: gridsHeight,
  describe: gridsDescribe,
  draw: gridsDraw,
  tables: gridsTables,
  slider: sliderSpec,
  ...MOTION,
});

export const figures = {
  "lsm-1d": [
    {
      caption: "The search window (bars), the template and the resampled search patch at the chosen iteration; the dashed line marks the template's centre c. Move the slider to step through the iterations.",
      height: () => 280,
      describe: profileDescribe,
      draw: profileDraw,
      tables: profileTables,
      slider: sliderSpec,
      ...MOTION,
    },
    PARAMS,
  ],
  "lsm-2d": [GRIDS, PARAMS],
  "lsm-affine": [GRIDS, PARAMS],
};
