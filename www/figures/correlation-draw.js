// Figures of the "Correlation" topic (seed 000, Examples 5–9):
//   ncc-1d: the template sliding along the search array, the ρ of every
//     position as a bar, the best one marked; a selected position (click or
//     ← →) shows its computation.
//   ncc-2d: A and B as grids of numbers shaded by grey value, and each pair
//     of deviations as a point (the sign of its product is the quadrant).
//   ncc-surface: template and search array as shaded grids, the correlation
//     surface as a heat map with its maximum and 3×3 neighbourhood; a
//     selected window (click or arrow keys) shows its computation.
//   subpixel-1d: the parabola through three ρ with its peak.
//   subpixel-2d: the fitted quadric as contours over the 3×3 ρ, with its peak.

import { formatNumber } from "../format.js";
import { COLORS, DASH, PALETTES, FONT_SIZE, FONT_SIZE_SMALL, GREY_LEGEND, LABEL_PAD, LINE_HEIGHT, Labels, dot, finite, fmt, greyLegend, greyScale, line, text, textBlock, blockSize } from "./draw.js";

/** Digits shown for ρ, means and sums in the figures. */
const RHO_DIGITS = 4;
const VALUE_DIGITS = 6;
const MARGIN = 12;
/** Cell sizes (CSS px) of the number grids: largest, and smallest that still shows numbers. */
const CELL_MAX = 40;
const CELL_NUMBERS = 24;
/** Largest heat-map cell; ρ gets four decimals (as the seed prints them) near this size. */
const HEAT_MAX = 64;
/** Width kept for the title above the template (CSS px). */
const TEMPLATE_TITLE_W = 80;
/** Positive ρ orange, negative ρ blue (the page's highlight and pixel colours). */
const RHO_POS = [217, 119, 6];
const RHO_NEG = [29, 95, 191];
const TITLE = { weight: "bold", size: FONT_SIZE };
/** The seed's usual acceptance threshold for a match. */
const THRESHOLD = 0.7;

const isNum = (v) => typeof v === "number" && Number.isFinite(v);
/** What a figure writes for a missing number. */
const NONE = "no value";
const list = (v) => (Array.isArray(v) ? v : []);
const matrix = (v) => list(v).filter(Array.isArray);

/** The values of the first step that has `key` among its values (as a list, with `asList`). */
function stepWith(solution, key, asList = false) {
  const has = (s) => s.values && Object.hasOwn(s.values, key) && (!asList || Array.isArray(s.values[key]));
  return list(solution.steps).find(has)?.values ?? {};
}

/** Room (CSS px) for a grey scale's legend under its grid. */
const LEGEND_ROOM = GREY_LEGEND.height + 6;

/**
 * The shade function of cells() for grey values in [lo, hi], on the shared
 * grey scale (draw.js: dark = low, as in an image); `.scale` records the cells.
 */
function grey(lo, hi, name) {
  const scale = greyScale(lo, hi, { name, format: (v) => formatNumber(v, 5) });
  return Object.assign((v) => ({ fill: scale.fill(v), ink: scale.ink(v) }), { scale });
}

/** Fill for a ρ in [−1, 1]: orange for positive, blue for negative, white at 0; none for null. */
function rhoShade(r) {
  if (!isNum(r)) return { fill: COLORS.noValue, ink: COLORS.muted };
  const a = Math.min(1, Math.abs(r));
  const [cr, cg, cb] = r >= 0 ? RHO_POS : RHO_NEG;
  const mix = (c) => Math.round(255 + (c - 255) * a);
  // the cells are mixed from white in both themes: their numbers in dark ink, white on the strongest
  return { fill: `rgb(${mix(cr)}, ${mix(cg)}, ${mix(cb)})`, ink: a > 0.6 ? "#ffffff" : PALETTES.light.ink };
}

function range(values) {
  const xs = values.filter(isNum);
  return xs.length ? [Math.min(...xs), Math.max(...xs)] : [0, 1];
}

/**
 * A grid of cells at (x, y), `size` px each; `shade(v)` gives { fill, ink };
 * numbers are written when the cells are large enough.
 */
function cells(ctx, rows, x, y, size, shade, digits = 4) {
  const show = typeof digits === "function" ? digits : (v) => formatNumber(v, digits);
  const showNumbers = size >= CELL_NUMBERS;
  const fontSize = Math.min(FONT_SIZE, Math.max(9, size * 0.36));
  rows.forEach((row, i) => {
    row.forEach((v, j) => {
      const { fill, ink } = shade(v);
      ctx.fillStyle = fill;
      ctx.fillRect(x + j * size, y + i * size, size, size);
      shade.scale?.note(v, x + j * size, y + i * size, size, size);
      if (showNumbers) {
        text(ctx, isNum(v) ? show(v) : "—", x + (j + 0.5) * size, y + (i + 0.5) * size, { color: ink, size: fontSize, align: "center" });
      }
    });
  });
  ctx.save();
  ctx.strokeStyle = COLORS.grid;
  ctx.lineWidth = 1;
  if (size >= 6) {
    for (let i = 0; i <= rows.length; i += 1) line(ctx, x, y + i * size, x + (rows[0]?.length ?? 0) * size, y + i * size, { color: COLORS.grid });
    for (let j = 0; j <= (rows[0]?.length ?? 0); j += 1) line(ctx, x + j * size, y, x + j * size, y + rows.length * size, { color: COLORS.grid });
  }
  ctx.restore();
}

function outline(ctx, x, y, w, h, color, width = 2.5, dash = null) {
  ctx.save();
  ctx.strokeStyle = color;
  ctx.lineWidth = width;
  ctx.setLineDash(dash ? [...dash] : []);
  ctx.strokeRect(x, y, w, h);
  ctx.restore();
}

/** Round tick values within [lo, hi]: steps of 1, 2 or 5 × 10ⁿ, about four of them. */
function niceTicks(lo, hi) {
  const raw = (hi - lo) / 4;
  if (!(raw > 0)) return [lo];
  const p = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((m) => m * p).find((s) => s >= raw) ?? 10 * p;
  const out = [];
  for (let v = Math.ceil(lo / step) * step; v <= hi + 1e-12; v += step) out.push(Math.abs(v) < step * 1e-9 ? 0 : v);
  return out;
}

/** Clamp an index into [0, n − 1] (NaN → the fallback). */
function clampIndex(i, n, fallback = 0) {
  if (!Number.isInteger(i)) return Math.min(Math.max(fallback, 0), Math.max(n - 1, 0));
  return Math.min(Math.max(i, 0), Math.max(n - 1, 0));
}

/** Arrow keys, Home and End on an index in [0, n): the new index, or undefined. */
function stepIndex(key, i, n, stride = 1) {
  const moves = { ArrowLeft: -1, ArrowRight: 1, ArrowUp: -stride, ArrowDown: stride };
  if (key === "Home") return 0;
  if (key === "End") return n - 1;
  if (!Object.hasOwn(moves, key)) return undefined;
  const next = i + moves[key];
  if (stride > 1 && (key === "ArrowLeft" || key === "ArrowRight") && Math.floor(next / stride) !== Math.floor(i / stride)) return i;
  return Math.min(Math.max(next, 0), n - 1);
}

// ---------------------------------------------------------------------------
// ncc-1d: sliding template, ρ bars

function oneD(solution) {
  const inp = solution.inputs ?? {};
  const res = solution.result ?? {};
  const all = stepWith(solution, "sum_dadb", true);
  const first = stepWith(solution, "mean_template");
  const template = list(inp.template).filter(isNum);
  const search = list(inp.search).filter(isNum);
  const rho = list(res.rho);
  const best = isNum(res.best) ? res.best - 1 : null;
  return {
    template,
    search,
    rho,
    best,
    means: list(res.mean_subwindows),
    sumDadb: list(all.sum_dadb),
    sumDb2: list(all.sum_db2),
    meanA: finite(first.mean_template),
    sumDa2: finite(first.sum_da2),
  };
}

function selected1d(d, state) {
  return clampIndex(state?.frame ? state.frame.k : state?.k, d.rho.length, d.best ?? 0);
}

const ONE_D = { rowH: 34, barsH: 150, gap: 14, label: 16, axis: 30, headroom: 16, legend: LEGEND_ROOM };

function layout1d(width, d) {
  const n = Math.max(d.search.length, 1);
  const cell = Math.min(CELL_MAX, (width - 2 * MARGIN - ONE_D.axis) / n);
  const x0 = MARGIN + ONE_D.axis + (width - 2 * MARGIN - ONE_D.axis - n * cell) / 2;
  const rowH = Math.min(ONE_D.rowH, Math.max(cell, 14));
  const ySearch = MARGIN + ONE_D.label;
  const yTemplate = ySearch + rowH + ONE_D.gap + ONE_D.label;
  const yBars = yTemplate + rowH + ONE_D.legend + ONE_D.gap + ONE_D.label;
  const yZero = yBars + ONE_D.headroom + ONE_D.barsH / 2;
  const yText = yBars + ONE_D.headroom + ONE_D.barsH + ONE_D.gap;
  return { cell, x0, rowH, ySearch, yTemplate, yBars, yZero, yText, n };
}

function lines1d(d, k) {
  const n = d.template.length;
  const window = d.search.slice(k, k + n);
  const shown = window.length > 12 ? `[${window.slice(0, 10).map((v) => fmt(v, VALUE_DIGITS, NONE)).join(", ")}, …]` : `[${window.map((v) => fmt(v, VALUE_DIGITS, NONE)).join(", ")}]`;
  return [
    { text: `Position ${k + 1}${k === d.best ? " (best)" : ""}: B${k + 1} = ${shown}`, weight: "bold", color: COLORS.point },
    { text: `Ā = ${fmt(d.meanA, VALUE_DIGITS, NONE)}, B̄ = ${fmt(d.means[k], VALUE_DIGITS, NONE)}` },
    { text: `Σ(A−Ā)(B−B̄) = ${fmt(d.sumDadb[k], VALUE_DIGITS, NONE)}, Σ(A−Ā)² = ${fmt(d.sumDa2, VALUE_DIGITS, NONE)}, Σ(B−B̄)² = ${fmt(d.sumDb2[k], VALUE_DIGITS, NONE)}` },
    {
      text: isNum(d.rho[k])
        ? `ρ${k + 1} = ${fmt(d.sumDadb[k], VALUE_DIGITS, NONE)} / √(${fmt(d.sumDa2, VALUE_DIGITS, NONE)} × ${fmt(d.sumDb2[k], VALUE_DIGITS, NONE)}) = ${fmt(d.rho[k], RHO_DIGITS, NONE)}`
        : `ρ${k + 1}: no value (a window without variance: 0/0)`,
      weight: "bold",
    },
  ];
}

function height1d(width, solution) {
  const d = oneD(solution);
  const L = layout1d(width, d);
  return L.yText + FONT_SIZE_SMALL * LINE_HEIGHT;
}

function draw1d(ctx, width, height, solution, state) {
  const d = oneD(solution);
  const L = layout1d(width, d);
  const k = selected1d(d, state);
  const n = d.template.length;
  const [lo, hi] = range([...d.search, ...d.template]);
  const shade = grey(lo, hi, "S and A");
  const X = (i) => L.x0 + i * L.cell;

  text(ctx, "Search array S", MARGIN, L.ySearch - 9, TITLE);
  cells(ctx, [d.search], X(0), L.ySearch, L.cell, shade);
  if (d.rho.length) outline(ctx, X(k), L.ySearch - 2, n * L.cell, L.cell + 4, COLORS.point, 2.5);

  text(ctx, `Template A, slid to position ${k + 1}`, MARGIN, L.yTemplate - 9, { ...TITLE, color: COLORS.point });
  cells(ctx, [d.template], X(k), L.yTemplate, L.cell, shade);
  outline(ctx, X(k), L.yTemplate, n * L.cell, L.cell, COLORS.point, 1.5);
  line(ctx, X(k), L.ySearch + L.cell + 2, X(k), L.yTemplate, { color: COLORS.point, dash: DASH });
  line(ctx, X(k + n), L.ySearch + L.cell + 2, X(k + n), L.yTemplate, { color: COLORS.point, dash: DASH });
  greyLegend(ctx, MARGIN, L.yTemplate + L.rowH + 4, shade.scale, { maxWidth: width - 2 * MARGIN });

  // ρ bars at each window's centre
  text(ctx, "ρ at each position", MARGIN, L.yBars - 9, TITLE);
  const half = ONE_D.barsH / 2 - 4;
  const Y = (r) => L.yZero - r * half;
  line(ctx, X(0), Y(1), X(L.n), Y(1), { color: COLORS.grid });
  line(ctx, X(0), Y(1), X(0), Y(-1), { color: COLORS.muted });
  line(ctx, X(0), Y(-1), X(L.n), Y(-1), { color: COLORS.grid });
  line(ctx, X(0), Y(THRESHOLD), X(L.n), Y(THRESHOLD), { color: COLORS.muted, dash: DASH });
  line(ctx, X(0), L.yZero, X(L.n), L.yZero, { color: COLORS.ink });
  text(ctx, "+1", X(0) - 3, Y(1), { color: COLORS.muted, size: FONT_SIZE_SMALL, align: "right" });
  text(ctx, "0", X(0) - 3, L.yZero, { color: COLORS.muted, size: FONT_SIZE_SMALL, align: "right" });
  text(ctx, "−1", X(0) - 3, Y(-1), { color: COLORS.muted, size: FONT_SIZE_SMALL, align: "right" });
  text(ctx, "0.7", X(0) - 3, Y(THRESHOLD), { color: COLORS.muted, size: FONT_SIZE_SMALL, align: "right" });
  const barW = Math.max(1, Math.min(L.cell * 0.7, 26));
  const labels = new Labels(ctx, width, height);
  const bars = [];
  const f = state?.frame ?? null; // motion: the positions after the frame's not yet computed, the best so far held
  const best = f ? f.best : d.best;
  d.rho.forEach((r, i) => {
    const cx = X(i + n / 2);
    if (f && i > f.k) return;
    if (!isNum(r)) {
      labels.avoid(text(ctx, "×", cx, L.yZero, { color: COLORS.muted, align: "center", size: FONT_SIZE_SMALL }));
      return;
    }
    ctx.fillStyle = i === best ? COLORS.highlight : r >= 0 ? "rgba(217, 119, 6, 0.45)" : "rgba(29, 95, 191, 0.55)";
    const top = Math.min(Y(r), L.yZero);
    const h = Math.abs(Y(r) - L.yZero);
    ctx.fillRect(cx - barW / 2, top, barW, h);
    labels.avoidRect(cx - barW / 2, top, barW, h, 1);
    if (i === k) {
      outline(ctx, cx - barW / 2 - 2, top - 2, barW + 4, h + 4, COLORS.point, 2);
      labels.avoidRect(cx - barW / 2 - 3, top - 3, barW + 6, h + 6);
    }
    bars.push({ i, r, cx });
  });
  labels.avoidLine(X(0), Y(THRESHOLD), X(L.n), Y(THRESHOLD), 1);
  if (best !== null) {
    const cx = X(best + n / 2);
    labels.add(f && f.k < d.rho.length - 1 ? "best so far" : "best", cx, L.yZero + ONE_D.barsH / 2 + 2, { color: COLORS.highlight, weight: "bold", size: FONT_SIZE_SMALL, candidates: ["S"], gap: 0 });
  }
  // each bar's ρ beside its end (a negative one also just above the axis);
  // the best and the selected bars first, the others only where they fit
  if (d.rho.length <= 40) {
    const size = L.cell >= 30 ? FONT_SIZE_SMALL : 10;
    const order = [...bars].sort((a, b) => (b.i === best) - (a.i === best) || (b.i === k) - (a.i === k) || a.i - b.i);
    for (const { i, r, cx } of order) {
      const end = Y(r);
      const pad = L.cell >= 30 ? LABEL_PAD : 1;
      const lh = size * LINE_HEIGHT + pad;
      // below a negative bar's end, or just above the axis, or lower down
      const spots = r >= 0 ? ["N", { at: "N", dy: -6 }, { at: "N", dy: -12 }] : ["S", { cx, cy: L.yZero - 2 - lh / 2 }, { at: "S", dy: lh }, { at: "S", dy: 2 * lh }, { at: "S", dy: 3 * lh }];
      labels.add(formatNumber(r, 2), cx, end, {
        size,
        pad,
        gap: 3,
        candidates: spots,
        optional: !(i === best || i === k),
      });
    }
  }
  labels.draw();
}

function select1d(solution, p) {
  const d = oneD(solution);
  const L = layout1d(p.width, d);
  const n = d.template.length;
  if (!d.rho.length) return undefined;
  // nearest window centre to the click
  const i = Math.round((p.x - L.x0) / L.cell - n / 2);
  return { k: clampIndex(i, d.rho.length) };
}

function key1d(solution, key, state) {
  const d = oneD(solution);
  const next = stepIndex(key, selected1d(d, state), d.rho.length);
  return next === undefined ? undefined : { k: next };
}

function describe1d(solution, state) {
  const d = oneD(solution);
  if (!d.rho.length) return "No positions.";
  const k = selected1d(d, state);
  const best = d.best === null ? "No position has a correlation coefficient." : `The best match is position ${d.best + 1} with ρ = ${fmt(d.rho[d.best], RHO_DIGITS, NONE)}.`;
  const all = d.rho.map((r, i) => `${i + 1}: ${isNum(r) ? formatNumber(r, 2) : "no value"}`).join(", ");
  return `The template of ${d.template.length} values slides along the search array of ${d.search.length}; bars show ρ at each of ${d.rho.length} positions (${all}). ${best} Selected: ${lines1d(d, k).map((l) => l.text).join("; ")}.`;
}

const ncc1d = {
  caption: "The template slides along the search array; each bar is the correlation coefficient at one position, drawn under the centre of its window (dashed: the usual 0.7 threshold). Click a bar or use ← → on the figure to see that position's computation.",
  height: height1d,
  describe: describe1d,
  draw: draw1d,
  select: select1d,
  key: key1d,
  status: (solution, state) => {
    const d = oneD(solution);
    return d.rho.length ? lines1d(d, selected1d(d, state)).map((l) => l.text).join("\n") : "";
  },
};

// ---------------------------------------------------------------------------
// ncc-2d: A and B shaded, deviation pairs

function twoD(solution) {
  const inp = solution.inputs ?? {};
  const res = solution.result ?? {};
  return { a: matrix(inp.a), b: matrix(inp.b), ma: finite(res.mean_a), mb: finite(res.mean_b), rho: res.rho, res };
}

function layout2d(width, d) {
  const rows = d.a.length;
  const cols = d.a[0]?.length ?? 1;
  const cell = Math.min(CELL_MAX, (width - 3 * MARGIN) / (2 * cols));
  const gridW = cols * cell;
  const xa = MARGIN + (width - 3 * MARGIN - 2 * gridW) / 2;
  const xb = xa + gridW + MARGIN;
  const y = MARGIN + 18;
  const plotTop = y + rows * cell + LEGEND_ROOM + 30;
  const plotSize = Math.min(width - 2 * MARGIN - 40, 260);
  return { cell, xa, xb, y, plotTop, plotSize, rows, cols };
}

function draw2d(ctx, width, height, solution, state) {
  const d = twoD(solution);
  const L = layout2d(width, d);
  const [loA, hiA] = range(d.a.flat());
  const [loB, hiB] = range(d.b.flat());
  text(ctx, `A (Ā = ${fmt(d.ma, VALUE_DIGITS, NONE)})`, L.xa, L.y - 10, TITLE);
  text(ctx, `B (B̄ = ${fmt(d.mb, VALUE_DIGITS, NONE)})`, L.xb, L.y - 10, TITLE);
  const shadeA = grey(loA, hiA, "A");
  const shadeB = grey(loB, hiB, "B");
  cells(ctx, d.a, L.xa, L.y, L.cell, shadeA, 5);
  cells(ctx, d.b, L.xb, L.y, L.cell, shadeB, 5);
  // each array's legend under it (each is stretched over its own range)
  const legendY = L.y + L.rows * L.cell + 5;
  greyLegend(ctx, L.xa, legendY, shadeA.scale, { maxWidth: L.xb - L.xa - 6 });
  greyLegend(ctx, L.xb, legendY, shadeB.scale, { maxWidth: width - L.xb - 4 });
  const total = L.rows * L.cols;
  const sel = Number.isInteger(state?.i) && state.i < total ? state.i : null;
  if (sel !== null) {
    const [i, j] = [Math.floor(sel / L.cols), sel % L.cols];
    outline(ctx, L.xa + j * L.cell, L.y + i * L.cell, L.cell, L.cell, COLORS.point);
    outline(ctx, L.xb + j * L.cell, L.y + i * L.cell, L.cell, L.cell, COLORS.point);
  }

  // deviations: x = A − Ā, y = B − B̄; a product's sign is its quadrant
  const pts = deviations2d(d);
  const ext = Math.max(1e-9, ...pts.map(([x, y]) => Math.max(Math.abs(x), Math.abs(y))));
  const s = L.plotSize / 2 / (ext * 1.1);
  const cx = width / 2;
  const cy = L.plotTop + L.plotSize / 2;
  ctx.fillStyle = "rgba(217, 119, 6, 0.08)";
  ctx.fillRect(cx, cy - L.plotSize / 2, L.plotSize / 2, L.plotSize / 2);
  ctx.fillRect(cx - L.plotSize / 2, cy, L.plotSize / 2, L.plotSize / 2);
  ctx.fillStyle = "rgba(29, 95, 191, 0.08)";
  ctx.fillRect(cx - L.plotSize / 2, cy - L.plotSize / 2, L.plotSize / 2, L.plotSize / 2);
  ctx.fillRect(cx, cy, L.plotSize / 2, L.plotSize / 2);
  line(ctx, cx - L.plotSize / 2, cy, cx + L.plotSize / 2, cy, { color: COLORS.muted });
  line(ctx, cx, cy - L.plotSize / 2, cx, cy + L.plotSize / 2, { color: COLORS.muted });
  const labels = new Labels(ctx, width, height);
  labels.avoid(text(ctx, "A − Ā", cx + L.plotSize / 2 + 4, cy, { color: COLORS.muted, size: FONT_SIZE_SMALL }));
  labels.avoid(text(ctx, "B − B̄", cx + 4, cy - L.plotSize / 2 - 2, { color: COLORS.muted, size: FONT_SIZE_SMALL, baseline: "bottom" }));
  labels.avoidLine(cx - L.plotSize / 2, cy, cx + L.plotSize / 2, cy, 1);
  labels.avoidLine(cx, cy - L.plotSize / 2, cx, cy + L.plotSize / 2, 1);
  pts.forEach(([x, y], i) => {
    const r = i === sel ? 6 : 4;
    dot(ctx, cx + x * s, cy - y * s, r, i === sel ? COLORS.point : COLORS.ink);
    labels.avoidDot(cx + x * s, cy - y * s, r, 2);
  });
  // each quadrant pair named in a corner of one of its quadrants where no point is
  const half = L.plotSize / 2;
  const inset = 3;
  const corner = (sx, sy) => ({ at: sy < 0 ? (sx > 0 ? "SW" : "SE") : sx > 0 ? "NW" : "NE", dx: 0, dy: 0, x: cx + sx * (half - inset), y: cy + sy * (half - inset) });
  const quadrantLabel = (str, color, spots) => {
    // spots: [sx, sy] corners (outer corners of the quadrants), tried in order
    const [first, ...rest] = spots.map(([sx, sy]) => corner(sx, sy));
    labels.add(str, first.x, first.y, {
      color,
      size: FONT_SIZE_SMALL,
      gap: 0,
      candidates: [first, ...rest].map((c) => ({ at: c.at, dx: c.x - first.x, dy: c.y - first.y })),
    });
  };
  quadrantLabel("product > 0", COLORS.highlight, [
    [1, -1],
    [-1, 1],
    [1, -0.55],
    [-1, 0.55],
  ]);
  quadrantLabel("product < 0", COLORS.pixelSystem, [
    [-1, -1],
    [1, 1],
    [-1, -0.55],
    [1, 0.55],
  ]);
  labels.draw();
  textBlock(ctx, lines2d(d, sel, pts), MARGIN, L.plotTop + L.plotSize + 10, { size: FONT_SIZE_SMALL });
}

/** Each pair's deviations [A − Ā, B − B̄], row by row. */
export const deviations2d = (d) => d.a.flatMap((row, i) => row.map((v, j) => [v - d.ma, finite(d.b[i]?.[j]) - d.mb]));

/** The lines under the ncc-2d scatter (and its status): ρ, and the selected pair (index `sel`) of the deviations `pts`. */
export function lines2d(d, sel, pts) {
  const cols = d.a[0]?.length ?? 1;
  const lines = [{ text: isNum(d.rho) ? `ρ = ${fmt(d.res.sum_dadb, VALUE_DIGITS, NONE)} / √(${fmt(d.res.sum_da2, VALUE_DIGITS, NONE)} × ${fmt(d.res.sum_db2, VALUE_DIGITS, NONE)}) = ${fmt(d.rho, RHO_DIGITS, NONE)}` : "ρ: no value (an array without variance: 0/0)", weight: "bold" }];
  if (sel !== null && pts[sel]) {
    const [x, y] = pts[sel];
    lines.push({ text: `Selected (row ${Math.floor(sel / cols) + 1}, column ${(sel % cols) + 1}): (${fmt(x, 5, NONE)}) × (${fmt(y, 5, NONE)}) = ${fmt(x * y, 5, NONE)}`, color: COLORS.point });
  }
  return lines;
}

function select2d(solution, p) {
  const d = twoD(solution);
  const L = layout2d(p.width, d);
  const i = Math.floor((p.y - L.y) / L.cell);
  for (const x0 of [L.xa, L.xb]) {
    const j = Math.floor((p.x - x0) / L.cell);
    if (i >= 0 && i < L.rows && j >= 0 && j < L.cols) return { i: i * L.cols + j };
  }
  return undefined;
}

function key2d(solution, key, state) {
  const d = twoD(solution);
  const cols = d.a[0]?.length ?? 1;
  const total = d.a.length * cols;
  const next = stepIndex(key, Number.isInteger(state?.i) ? Math.min(state.i, total - 1) : -1, total, cols);
  return next === undefined ? undefined : { i: Math.max(0, next) };
}

const ncc2d = {
  caption: "A and B shaded by grey value (dark = low, each over its own range: see the legends), and every pair of deviations (A − Ā, B − B̄) as a point: points in the orange quadrants add to the sum of products, points in the blue ones subtract. Click a cell (or use the arrow keys) to follow one pair.",
  height: (width, solution) => {
    const L = layout2d(width, twoD(solution));
    return L.plotTop + L.plotSize + 10 + 2 * FONT_SIZE_SMALL * LINE_HEIGHT + 12 + MARGIN;
  },
  describe: (solution) => {
    const d = twoD(solution);
    return `Arrays A and B of ${d.a.length}×${d.a[0]?.length ?? 0} grey values, shaded, with means ${fmt(d.ma, VALUE_DIGITS, NONE)} and ${fmt(d.mb, VALUE_DIGITS, NONE)}, and a scatter of their deviations. ρ = ${fmt(d.rho, RHO_DIGITS, NONE)}.`;
  },
  draw: draw2d,
  select: select2d,
  key: key2d,
};

// ---------------------------------------------------------------------------
// ncc-surface: search array, template, heat map

function surf(solution) {
  const inp = solution.inputs ?? {};
  const res = solution.result ?? {};
  const all = stepWith(solution, "sum_dadb", true);
  const first = stepWith(solution, "mean_template");
  const rho = matrix(res.rho);
  return {
    template: matrix(inp.template),
    search: matrix(inp.search),
    rho,
    h: rho.length,
    w: rho[0]?.length ?? 0,
    best: isNum(res.best_row) ? [res.best_row - 1, res.best_col - 1] : null,
    bestC: res.best_c,
    bestR: res.best_r,
    meanB: matrix(all.mean_b),
    sumDadb: matrix(all.sum_dadb),
    sumDb2: matrix(all.sum_db2),
    meanT: finite(first.mean_template),
    sumDa2: finite(first.sum_da2),
  };
}

function selectedSurface(d, state) {
  const [br, bc] = d.best ?? [0, 0];
  const at = state?.frame ?? state; // a motion frame (correlation.js frames) is the selection
  return [clampIndex(at?.r, d.h, br), clampIndex(at?.c, d.w, bc)];
}

function layoutSurface(width, d) {
  const th = d.template.length;
  const tw = d.template[0]?.length ?? 1;
  const sh = d.search.length;
  const sw = d.search[0]?.length ?? 1;
  const avail = width - 3 * MARGIN;
  let cell = Math.min(CELL_MAX - 4, avail / (tw + sw));
  const xt = MARGIN;
  // room for the title "Template T" even above a narrow template
  const xs = xt + Math.max(tw * cell, TEMPLATE_TITLE_W) + MARGIN;
  cell = Math.min(cell, (width - MARGIN - xs) / sw);
  const y1 = MARGIN + 18;
  const y2 = y1 + Math.max(th, sh) * cell + LEGEND_ROOM + 34;
  const heat = Math.min(HEAT_MAX, (width - 2 * MARGIN) / Math.max(d.w, 1));
  const xh = MARGIN + (width - 2 * MARGIN - d.w * heat) / 2;
  const y3 = y2 + d.h * heat + 14;
  return { th, tw, sh, sw, cell, xt, xs, y1, y2, heat, xh, y3 };
}

function linesSurface(d, r, c) {
  const pos = r * d.w + c + 1;
  const isBest = d.best && d.best[0] === r && d.best[1] === c;
  const rhoV = d.rho[r]?.[c];
  return [
    { text: `Position ${pos}${isBest ? " (best)" : ""}: rows ${r + 1}–${r + d.template.length}, columns ${c + 1}–${c + (d.template[0]?.length ?? 0)} of S`, weight: "bold", color: COLORS.point },
    { text: `T̄ = ${fmt(d.meanT, VALUE_DIGITS, NONE)}, B̄ = ${fmt(d.meanB[r]?.[c], VALUE_DIGITS, NONE)}` },
    { text: `Σ(T−T̄)(B−B̄) = ${fmt(d.sumDadb[r]?.[c], VALUE_DIGITS, NONE)}, Σ(T−T̄)² = ${fmt(d.sumDa2, VALUE_DIGITS, NONE)}, Σ(B−B̄)² = ${fmt(d.sumDb2[r]?.[c], VALUE_DIGITS, NONE)}` },
    { text: isNum(rhoV) ? `ρ = ${fmt(rhoV, RHO_DIGITS, NONE)}` : "ρ: no value (a window without variance: 0/0)", weight: "bold" },
  ];
}

function drawSurface(ctx, width, height, solution, state) {
  const d = surf(solution);
  const L = layoutSurface(width, d);
  const [r, c] = selectedSurface(d, state);
  const [lo, hi] = range([...d.search.flat(), ...d.template.flat()]);
  const shade = grey(lo, hi, "T and S");
  text(ctx, "Template T", L.xt, L.y1 - 10, TITLE);
  cells(ctx, d.template, L.xt, L.y1, L.cell, shade);
  text(ctx, "Search array S", L.xs, L.y1 - 10, TITLE);
  cells(ctx, d.search, L.xs, L.y1, L.cell, shade);
  greyLegend(ctx, MARGIN, L.y1 + Math.max(L.th, L.sh) * L.cell + 5, shade.scale, { maxWidth: width - 2 * MARGIN });
  if (d.h) outline(ctx, L.xs + c * L.cell, L.y1 + r * L.cell, L.tw * L.cell, L.th * L.cell, COLORS.point, 3);
  const f = state?.frame ?? null; // motion: positions after the frame's not yet computed, the best so far held
  const best = f ? f.best : d.best;
  const final = Boolean(best && d.best && best[0] === d.best[0] && best[1] === d.best[1]);
  if (best) {
    // the best window's centre pixel
    const [br, bc] = best;
    const cx = L.xs + (bc + L.tw / 2) * L.cell;
    const cy = L.y1 + (br + L.th / 2) * L.cell;
    outline(ctx, cx - L.cell / 2, cy - L.cell / 2, L.cell, L.cell, COLORS.highlight, 2, DASH);
  }

  text(ctx, "Correlation surface ρ (orange > 0, blue < 0)", MARGIN, L.y2 - 12, TITLE);
  // ρ as the seed prints it: four decimals where they fit, two otherwise
  const decimals = L.heat >= HEAT_MAX - 4 ? 4 : 2;
  cells(ctx, d.rho, L.xh, L.y2, L.heat, rhoShade, (v) => v.toFixed(decimals).replace("-", "\u2212"));
  for (let i = f ? f.index + 1 : d.h * d.w; i < d.h * d.w; i += 1) {
    const [x, y] = [L.xh + (i % d.w) * L.heat, L.y2 + Math.floor(i / d.w) * L.heat];
    ctx.fillStyle = COLORS.background;
    ctx.fillRect(x, y, L.heat, L.heat);
    outline(ctx, x, y, L.heat, L.heat, COLORS.grid, 1);
  }
  if (best && final) {
    const [br, bc] = best;
    // the 3×3 neighbourhood Example 9 fits, clipped to the surface
    const r0 = Math.max(0, br - 1);
    const c0 = Math.max(0, bc - 1);
    const r1 = Math.min(d.h, br + 2);
    const c1 = Math.min(d.w, bc + 2);
    outline(ctx, L.xh + c0 * L.heat, L.y2 + r0 * L.heat, (c1 - c0) * L.heat, (r1 - r0) * L.heat, COLORS.ink, 1.5, DASH);
  }
  if (best) outline(ctx, L.xh + best[1] * L.heat + 1, L.y2 + best[0] * L.heat + 1, L.heat - 2, L.heat - 2, COLORS.highlight, 3);
  if (d.h) outline(ctx, L.xh + c * L.heat - 1, L.y2 + r * L.heat - 1, L.heat + 2, L.heat + 2, COLORS.point, 2.5);
  if (best && !final) text(ctx, `Best so far: position ${best[0] * d.w + best[1] + 1}, ρ = ${fmt(d.rho[best[0]]?.[best[1]], RHO_DIGITS, NONE)}`, MARGIN, L.y3 + 6, { color: COLORS.highlight, weight: "bold", size: FONT_SIZE_SMALL });
  if (final) {
    const words = `Best: position ${d.best[0] * d.w + d.best[1] + 1}, centre pixel c = ${fmt(d.bestC, VALUE_DIGITS, NONE)}, r = ${fmt(d.bestR, VALUE_DIGITS, NONE)}`;
    text(ctx, words, MARGIN, L.y3 + 6, { color: COLORS.highlight, weight: "bold", size: FONT_SIZE_SMALL });
  }
}

function selectSurface(solution, p) {
  const d = surf(solution);
  const L = layoutSurface(p.width, d);
  const inHeat = [Math.floor((p.y - L.y2) / L.heat), Math.floor((p.x - L.xh) / L.heat)];
  if (inHeat[0] >= 0 && inHeat[0] < d.h && inHeat[1] >= 0 && inHeat[1] < d.w) return { r: inHeat[0], c: inHeat[1] };
  const inSearch = [Math.floor((p.y - L.y1) / L.cell), Math.floor((p.x - L.xs) / L.cell)];
  if (inSearch[0] >= 0 && inSearch[0] < L.sh && inSearch[1] >= 0 && inSearch[1] < L.sw) {
    // the window centred on the clicked pixel, as near as it fits
    return { r: clampIndex(inSearch[0] - Math.floor(L.th / 2), d.h), c: clampIndex(inSearch[1] - Math.floor(L.tw / 2), d.w) };
  }
  return undefined;
}

function keySurface(solution, key, state) {
  const d = surf(solution);
  if (!d.h) return undefined;
  const [r, c] = selectedSurface(d, state);
  const next = stepIndex(key, r * d.w + c, d.h * d.w, d.w);
  return next === undefined ? undefined : { r: Math.floor(next / d.w), c: next % d.w };
}

const nccSurface = {
  caption: "Template and search array shaded by grey value (dark = low, as the legend says); the outlined window is the selected position. The heat map is ρ at every position, the best one outlined in orange with its 3×3 neighbourhood dashed. Click the heat map or the search array (or use the arrow keys) to see a window's computation.",
  height: (width, solution) => {
    const L = layoutSurface(width, surf(solution));
    return L.y3 + FONT_SIZE_SMALL * LINE_HEIGHT + MARGIN;
  },
  describe: (solution, state) => {
    const d = surf(solution);
    const best = d.best ? `The maximum ρ = ${fmt(d.rho[d.best[0]][d.best[1]], RHO_DIGITS, NONE)} is at position ${d.best[0] * d.w + d.best[1] + 1}, centre pixel c = ${fmt(d.bestC, VALUE_DIGITS, NONE)}, r = ${fmt(d.bestR, VALUE_DIGITS, NONE)}.` : "No position has a ρ.";
    const [r, c] = selectedSurface(d, state);
    return `A ${d.template.length}×${d.template[0]?.length ?? 0} template over a ${d.search.length}×${d.search[0]?.length ?? 0} search array; the correlation surface has ${d.h}×${d.w} positions. ${best} Selected: ${d.h ? linesSurface(d, r, c).map((l) => l.text).join("; ") : "none"}.`;
  },
  draw: drawSurface,
  select: selectSurface,
  key: keySurface,
  status: (solution, state) => {
    const d = surf(solution);
    if (!d.h) return "";
    const [r, c] = selectedSurface(d, state);
    return linesSurface(d, r, c).map((l) => l.text).join("\n");
  },
};

// ---------------------------------------------------------------------------
// subpixel-1d: the parabola

function parabolaData(solution) {
  const res = solution.result ?? {};
  return {
    x: list(res.positions).filter(isNum),
    y: list(res.rho).filter(isNum),
    a: list(res.coefficients).map((v) => finite(v)),
    cMax: res.c_max,
    rhoMax: res.rho_max,
    printedC: res.c_max_printed_rho,
    extremum: res.extremum,
  };
}

function drawParabola(ctx, width, height, solution) {
  const d = parabolaData(solution);
  if (d.x.length !== 3 || d.a.length !== 3) return;
  const m = { left: 48, right: 16, top: 24, bottom: 40 };
  const marks = [...d.x, ...[d.cMax, d.printedC].filter(isNum)];
  const span = Math.max(...d.x) - Math.min(...d.x);
  const cLo = Math.min(...marks) - 0.35 * span;
  const cHi = Math.max(...marks) + 0.35 * span;
  const f = (c) => d.a[0] + d.a[1] * c + d.a[2] * c * c;
  const samples = Array.from({ length: 121 }, (_, i) => cLo + ((cHi - cLo) * i) / 120);
  const ys = [...samples.map(f), ...d.y, ...(isNum(d.rhoMax) ? [d.rhoMax] : [])];
  let [yLo, yHi] = range(ys);
  const pad = 0.08 * Math.max(yHi - yLo, 1e-6);
  yLo -= pad;
  yHi += pad;
  const X = (c) => m.left + ((c - cLo) / (cHi - cLo)) * (width - m.left - m.right);
  const Y = (r) => m.top + ((yHi - r) / (yHi - yLo)) * (height - m.top - m.bottom);
  // axes
  const labels = new Labels(ctx, width, height);
  line(ctx, m.left, height - m.bottom, width - m.right, height - m.bottom, { color: COLORS.ink });
  line(ctx, m.left, m.top, m.left, height - m.bottom, { color: COLORS.ink });
  labels.avoid(text(ctx, "c (column)", width - m.right, height - 8, { color: COLORS.muted, size: FONT_SIZE_SMALL, align: "right" }));
  labels.avoid(text(ctx, "ρ", m.left - 8, m.top - 10, { color: COLORS.muted, weight: "bold", align: "right" }));
  for (const v of niceTicks(yLo, yHi)) {
    line(ctx, m.left - 4, Y(v), m.left, Y(v), { color: COLORS.ink });
    labels.avoid(text(ctx, formatNumber(v, 3), m.left - 6, Y(v), { color: COLORS.muted, size: FONT_SIZE_SMALL, align: "right" }));
  }
  for (const c of d.x) {
    line(ctx, X(c), height - m.bottom, X(c), height - m.bottom + 4, { color: COLORS.ink });
    labels.avoid(text(ctx, formatNumber(c, 6), X(c), height - m.bottom + 6, { color: COLORS.muted, size: FONT_SIZE_SMALL, align: "center", baseline: "top" }));
  }
  // the curve
  ctx.save();
  ctx.strokeStyle = COLORS.pixelSystem;
  ctx.lineWidth = 2;
  ctx.beginPath();
  samples.forEach((c, i) => (i ? ctx.lineTo(X(c), Y(f(c))) : ctx.moveTo(X(c), Y(f(c)))));
  ctx.stroke();
  ctx.restore();
  // labels off the curve, the dots, the peak's line and each other
  labels.avoidPath(
    samples.map((c) => [X(c), Y(f(c))]),
    1.5,
  );
  labels.avoidLine(m.left, height - m.bottom, width - m.right, height - m.bottom, 1).avoidLine(m.left, m.top, m.left, height - m.bottom, 1);
  d.x.forEach((c, i) => {
    dot(ctx, X(c), Y(d.y[i]), 5, COLORS.ink);
    labels.avoidDot(X(c), Y(d.y[i]), 5);
  });
  if (isNum(d.printedC)) {
    line(ctx, X(d.printedC), m.top, X(d.printedC), height - m.bottom, { color: COLORS.muted, dash: DASH });
    labels.avoidLine(X(d.printedC), m.top, X(d.printedC), height - m.bottom, 1);
  }
  if (isNum(d.cMax)) {
    line(ctx, X(d.cMax), Y(d.rhoMax), X(d.cMax), height - m.bottom, { color: COLORS.highlight, dash: DASH, width: 1.5 });
    dot(ctx, X(d.cMax), Y(d.rhoMax), 5.5, COLORS.highlight);
    labels.avoidLine(X(d.cMax), Y(d.rhoMax), X(d.cMax), height - m.bottom, 1).avoidDot(X(d.cMax), Y(d.rhoMax), 5.5);
  }
  d.x.forEach((c, i) => {
    labels.add(`ρ = ${formatNumber(d.y[i], RHO_DIGITS)}`, X(c), Y(d.y[i]), { color: COLORS.ink, size: FONT_SIZE_SMALL, gap: 7, candidates: ["SE", "SW", "NE", "NW", "E", "W", "S", "N"], farther: 10 });
  });
  if (isNum(d.cMax)) labels.add(`peak c = ${formatNumber(d.cMax, 6)}`, X(d.cMax), Y(d.rhoMax), { color: COLORS.highlight, weight: "bold", gap: 8, candidates: ["NE", "N", "NW", "E", "W"], farther: 10 });
  if (isNum(d.printedC)) {
    labels.add(`peak from the printed ρ: ${formatNumber(d.printedC, 6)}`, X(d.printedC), height - m.bottom - 4, { color: COLORS.muted, size: FONT_SIZE_SMALL, gap: 4, candidates: ["NW", "NE"], farther: 16 });
  }
  labels.draw();
  if (!isNum(d.cMax)) {
    textBlock(ctx, [{ text: d.extremum === "minimum" ? "Opens upward: a minimum, no peak" : "A straight line: no peak", weight: "bold", color: COLORS.point }], m.left + 10, m.top);
  }
}

const subpixel1d = {
  caption: "The parabola ρ = a₀ + a₁c + a₂c² through the best ρ and its two neighbours; its maximum (orange) is the subpixel position of the match.",
  height: (width) => Math.min(360, Math.max(240, width * 0.62)),
  describe: (solution) => {
    const d = parabolaData(solution);
    const pts = d.x.map((c, i) => `(${fmt(c, VALUE_DIGITS, NONE)}, ${fmt(d.y[i], RHO_DIGITS, NONE)})`).join(", ");
    const peak = isNum(d.cMax) ? `its maximum is at c = ${fmt(d.cMax, VALUE_DIGITS, NONE)}, ρ = ${fmt(d.rhoMax, RHO_DIGITS, NONE)}` : "it has no maximum";
    return `A parabola through the points ${pts}; ${peak}.`;
  },
  draw: drawParabola,
};

// ---------------------------------------------------------------------------
// subpixel-2d: contours of the quadric

function quadricData(solution) {
  const res = solution.result ?? {};
  return {
    c: list(res.c).filter(isNum),
    r: list(res.r).filter(isNum),
    rho: matrix(res.rho),
    a: list(res.coefficients).map((v) => finite(v)),
    cMax: res.c_max,
    rMax: res.r_max,
    printed: isNum(res.c_max_printed_rho) ? [res.c_max_printed_rho, res.r_max_printed_rho] : null,
    extremum: res.extremum,
  };
}

/** f sampled on an (n+1)×(n+1) grid over [x0, x1]×[y0, y1]: { n, gx, gy, v } (v row by row, y outer). */
function sampleGrid(f, x0, x1, y0, y1, n) {
  const gx = new Float64Array(n + 1);
  const gy = new Float64Array(n + 1);
  for (let i = 0; i <= n; i += 1) gx[i] = x0 + ((x1 - x0) * i) / n;
  for (let j = 0; j <= n; j += 1) gy[j] = y0 + ((y1 - y0) * j) / n;
  const v = new Float64Array((n + 1) * (n + 1));
  for (let j = 0; j <= n; j += 1) for (let i = 0; i <= n; i += 1) v[j * (n + 1) + i] = f(gx[i], gy[j]);
  return { n, gx, gy, v };
}

/**
 * Marching squares on a sampled grid: calls segment(xa, ya, xb, yb) for each
 * segment of the level `level`, cell by cell (rows outer), edges in the order
 * bottom, right, top, left of the cell's corners.
 */
function isoSegments(grid, level, segment) {
  const { n, gx, gy, v } = grid;
  const xs = [0, 0, 0, 0];
  const ys = [0, 0, 0, 0];
  const fs = [0, 0, 0, 0];
  const px = [0, 0, 0, 0];
  const py = [0, 0, 0, 0];
  const lerp = (a, b, fa, fb) => a + ((b - a) * fa) / (fa - fb);
  for (let j = 0; j < n; j += 1) {
    for (let i = 0; i < n; i += 1) {
      xs[0] = gx[i];
      ys[0] = gy[j];
      fs[0] = v[j * (n + 1) + i] - level;
      xs[1] = gx[i + 1];
      ys[1] = gy[j];
      fs[1] = v[j * (n + 1) + i + 1] - level;
      xs[2] = gx[i + 1];
      ys[2] = gy[j + 1];
      fs[2] = v[(j + 1) * (n + 1) + i + 1] - level;
      xs[3] = gx[i];
      ys[3] = gy[j + 1];
      fs[3] = v[(j + 1) * (n + 1) + i] - level;
      let k = 0;
      for (let e = 0; e < 4; e += 1) {
        const b = (e + 1) % 4;
        if ((fs[e] < 0) !== (fs[b] < 0)) {
          px[k] = lerp(xs[e], xs[b], fs[e], fs[b]);
          py[k] = lerp(ys[e], ys[b], fs[e], fs[b]);
          k += 1;
        }
      }
      if (k === 2 || k === 4) segment(px[0], py[0], px[1], py[1]);
      if (k === 4) segment(px[2], py[2], px[3], py[3]);
    }
  }
}

function drawQuadric(ctx, width, height, solution) {
  const d = quadricData(solution);
  if (d.c.length !== 3 || d.r.length !== 3 || d.a.length !== 6) return;
  const sc = [...d.c].sort((p, q) => p - q);
  const sr = [...d.r].sort((p, q) => p - q);
  const dc = (sc[2] - sc[0]) / 2;
  const dr = (sr[2] - sr[0]) / 2;
  const c0 = sc[0] - dc / 2;
  const c1 = sc[2] + dc / 2;
  const r0 = sr[0] - dr / 2;
  const r1 = sr[2] + dr / 2;
  const m = { left: 40, right: 16, top: 30, bottom: 70 };
  const size = Math.min(width - m.left - m.right, height - m.top - m.bottom);
  const ox = m.left + (width - m.left - m.right - size) / 2;
  const X = (c) => ox + ((c - c0) / (c1 - c0)) * size;
  const Y = (r) => m.top + ((r - r0) / (r1 - r0)) * size; // r grows downward, as in the image
  const f = (c, r) => d.a[0] + d.a[1] * c + d.a[2] * r + d.a[3] * c * r + d.a[4] * c * c + d.a[5] * r * r;

  // the nine ρ as cells
  d.r.forEach((rv, i) =>
    d.c.forEach((cv, j) => {
      const v = d.rho[i]?.[j];
      const { fill, ink } = rhoShade(v);
      const w = (size / 3) * 0.98;
      ctx.fillStyle = fill;
      ctx.fillRect(X(cv) - w / 2, Y(rv) - w / 2, w, w);
      text(ctx, formatNumber(finite(v), RHO_DIGITS), X(cv), Y(rv) + w / 2 - 10, { color: ink, size: FONT_SIZE_SMALL, align: "center" });
    }),
  );
  // contours
  const vals = d.rho.flat().filter(isNum);
  const [lo, hi] = range(vals);
  const levels = 9;
  ctx.save();
  ctx.strokeStyle = COLORS.ink;
  ctx.lineWidth = 1;
  const grid = sampleGrid(f, c0, c1, r0, r1, 60); // once for every level
  const segment = (xa, ya, xb, yb) => {
    ctx.moveTo(X(xa), Y(ya));
    ctx.lineTo(X(xb), Y(yb));
  };
  for (let k = 1; k < levels; k += 1) {
    const level = lo + ((hi - lo) * k) / levels;
    ctx.globalAlpha = 0.35 + (0.6 * k) / levels;
    ctx.beginPath();
    isoSegments(grid, level, segment);
    ctx.stroke();
  }
  ctx.restore();
  // axes
  outline(ctx, X(c0), Y(r0), size, size, COLORS.grid, 1);
  d.c.forEach((cv) => text(ctx, `c = ${formatNumber(cv, 6)}`, X(cv), Y(r0) - 4, { color: COLORS.muted, size: FONT_SIZE_SMALL, align: "center", baseline: "bottom" }));
  d.r.forEach((rv) => text(ctx, `r = ${formatNumber(rv, 6)}`, X(c0) - 4, Y(rv), { color: COLORS.muted, size: FONT_SIZE_SMALL, align: "right" }));
  const cross = (c, r, color, s = 8) => {
    for (const [col, w] of [["#ffffff", 5], [color, 2.5]]) {
      line(ctx, X(c) - s, Y(r), X(c) + s, Y(r), { color: col, width: w });
      line(ctx, X(c), Y(r) - s, X(c), Y(r) + s, { color: col, width: w });
    }
  };
  const lines = [];
  if (d.printed && isNum(d.printed[0])) {
    cross(d.printed[0], d.printed[1], COLORS.muted, 5);
    lines.push({ text: `grey +: peak from the printed ρ (${fmt(d.printed[0], VALUE_DIGITS, NONE)}, ${fmt(d.printed[1], VALUE_DIGITS, NONE)})`, color: COLORS.muted });
  }
  if (isNum(d.cMax) && isNum(d.rMax)) {
    cross(d.cMax, d.rMax, COLORS.point);
    lines.unshift({ text: `peak (purple +): c = ${fmt(d.cMax, VALUE_DIGITS, NONE)}, r = ${fmt(d.rMax, VALUE_DIGITS, NONE)}`, weight: "bold", color: COLORS.point });
  } else {
    const what = d.extremum === "saddle" ? "a saddle" : d.extremum === "minimum" ? "a minimum" : "no single stationary point";
    lines.unshift({ text: `Not concave: the surface has ${what}, no peak`, weight: "bold", color: COLORS.point });
  }
  const box = blockSize(ctx, lines, { size: FONT_SIZE_SMALL });
  textBlock(ctx, lines, Math.max(MARGIN, (width - box.w) / 2), Y(r1) + 10, { size: FONT_SIZE_SMALL });
}

const subpixel2d = {
  caption: "The nine ρ around the best position (cells, r downward as in the image) and contours of the fitted surface ρ = a₀ + a₁c + a₂r + a₃cr + a₄c² + a₅r²; its maximum is the subpixel position of the match.",
  height: (width) => Math.min(520, width * 0.82 + 60),
  describe: (solution) => {
    const d = quadricData(solution);
    const peak = isNum(d.cMax) ? `The maximum is at c = ${fmt(d.cMax, VALUE_DIGITS, NONE)}, r = ${fmt(d.rMax, VALUE_DIGITS, NONE)}.` : `The fitted surface is not concave (${d.extremum}); there is no peak.`;
    return `Contours of the quadratic surface fitted to the 3×3 correlation coefficients at columns ${d.c.map((v) => fmt(v, VALUE_DIGITS, NONE)).join(", ")} and rows ${d.r.map((v) => fmt(v, VALUE_DIGITS, NONE)).join(", ")}. ${peak}`;
  },
  draw: drawQuadric,
};

// for the Data views (correlation.js)
export { ncc1d, ncc2d, nccSurface, subpixel1d, subpixel2d, oneD, twoD, surf, parabolaData, quadricData, selected1d, selectedSurface, lines1d, linesSurface, isNum, stepWith, RHO_DIGITS, VALUE_DIGITS, NONE };

export const figures = {
  "ncc-1d": ncc1d,
  "ncc-2d": ncc2d,
  "ncc-surface": nccSurface,
  "subpixel-1d": subpixel1d,
  "subpixel-2d": subpixel2d,
};
