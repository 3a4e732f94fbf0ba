// Figures of the "Interest operators" topic (seed 000, Examples 13–14; seed 003):
//   forstner-window: the window as a grid of numbers with the gradient arrow
//     at each interior pixel; N with its error ellipse beside the threshold T.
//   moravec-window: the four directional differences at each interior pixel.
//   forstner-image: the test pattern with the window, its error ellipse
//     (magnified), the candidates and the interest points; then the window
//     and N as above.

import { isMatrix, stepValue } from "../values.js";
import { matrixTable, seriesTable } from "./data-view.js";
import { COLORS, DASH, PALETTES, FONT_SIZE, FONT_SIZE_SMALL, GREY_LEGEND, LINE_HEIGHT, Labels, arrow, arrowStep, dot, finite, fmt, greyLegend, greyScale, greyScaleOf, line, text, textBlock, textWidth } from "./draw.js";

/** Layout constants (CSS px). */
const GRID = Object.freeze({ maxCell: 58, minCell: 22, margin: 14, legend: 26, greyLegend: GREY_LEGEND.height + 8 });
const ELLIPSE = Object.freeze({ height: 290, panelMin: 200, clip: 2.6, margin: 14 });
const MORAVEC = Object.freeze({ maxCell: 46, panelGap: 14, textLines: 6, minPanel: 200, compactPanel: 150, maxShown: 4, overviewMin: 26, overviewMax: 48, key: 20 });
const IMAGE = Object.freeze({ margin: 14, maxSide: 620, tRadiusCells: 1, clip: 3 });
/** The four Moravec directions, in the order of the core's `diffs`. */
const DIRECTIONS = Object.freeze([
  { name: "row", glyph: "→", from: [-1, 0], to: [1, 0], key: "pixelSystem" },
  { name: "column", glyph: "↓", from: [0, -1], to: [0, 1], key: "imageSystem" },
  { name: "main diagonal", glyph: "↘", from: [-1, -1], to: [1, 1], key: "green" },
  { name: "other diagonal", glyph: "↙", from: [1, -1], to: [-1, 1], key: "point" },
]);




/** The shared grey scale (draw.js: dark = low, as in an image) over a window's values. */
const windowScale = (win) => greyScaleOf(win, { name: "Window", format: (v) => fmt(v, 5) });

/**
 * The window grid with its numbers; arrows of (gx, gy) at the interior
 * pixels. Returns its grey scale (for the legend).
 */
function drawWindow(ctx, x0, y0, cell, win, gx, gy, arrowAt = () => true) {
  const scale = windowScale(win);
  const rows = win.length;
  const cols = win[0].length;
  for (let r = 0; r < rows; r++) {
    for (let c = 0; c < cols; c++) {
      const v = win[r][c];
      scale.cell(ctx, v, x0 + c * cell, y0 + r * cell, cell, cell);
      const interior = r > 0 && c > 0 && r < rows - 1 && c < cols - 1;
      text(ctx, fmt(v, 5), x0 + c * cell + 4, y0 + r * cell + 3, {
        size: cell < 34 ? 9.5 : FONT_SIZE_SMALL,
        baseline: "top",
        color: interior ? COLORS.ink : COLORS.muted,
        halo: true,
      });
    }
  }
  ctx.save();
  ctx.strokeStyle = COLORS.grid;
  for (let i = 0; i <= rows; i++) line(ctx, x0, y0 + i * cell, x0 + cols * cell, y0 + i * cell, { color: COLORS.grid });
  for (let i = 0; i <= cols; i++) line(ctx, x0 + i * cell, y0, x0 + i * cell, y0 + rows * cell, { color: COLORS.grid });
  ctx.strokeStyle = COLORS.frameStroke;
  ctx.lineWidth = 1.5;
  ctx.strokeRect(x0 + cell, y0 + cell, (cols - 2) * cell, (rows - 2) * cell);
  ctx.restore();
  if (!isMatrix(gx) || !isMatrix(gy)) return scale;
  const mags = gx.flatMap((row, r) => row.map((v, c) => Math.hypot(v, gy[r][c])));
  const maxMag = Math.max(...mags);
  if (!(maxMag > 0)) return scale;
  const reach = 0.46 * cell;
  gx.forEach((row, r) =>
    row.forEach((vx, c) => {
      if (!arrowAt(r, c)) return;
      const vy = gy[r][c];
      const cx = x0 + (c + 1.5) * cell;
      const cy = y0 + (r + 1.5) * cell + 4;
      const k = reach / maxMag;
      // on a white underlay: the arrows stay visible on dark (low) cells
      if (Math.hypot(vx, vy) * k < 3) {
        dot(ctx, cx, cy, 3.5, "#ffffff");
        dot(ctx, cx, cy, 2, PALETTES.light.pixelSystem);
        return;
      }
      arrow(ctx, cx, cy, cx + vx * k, cy + vy * k, { color: "#ffffff", width: 4.5, size: 9 });
      arrow(ctx, cx, cy, cx + vx * k, cy + vy * k, { color: PALETTES.light.pixelSystem, width: 2, size: 7 });
    }),
  );
  return scale;
}

/**
 * The gradient table of the solution ("Gradient table: central differences":
 * per interior pixel c, r, g, g′x, g′y, g′x·g′y, g′x², g′y²), its sums and
 * N, w, q: what the window's sums block and its motion show (nothing computed).
 */
function sumsOf(solution) {
  const table = stepValue(solution, "table");
  const rows = isMatrix(table) && table[0].length >= 8 ? table.map((t) => ({ c: t[0], r: t[1], g: t[2], gx: t[3], gy: t[4], gxgy: t[5], gx2: t[6], gy2: t[7] })) : [];
  const res = solution.result ?? {};
  const sum = { gx2: stepValue(solution, "sum_gx2"), gy2: stepValue(solution, "sum_gy2"), gxgy: stepValue(solution, "sum_gxgy") };
  return { rows, sum, n: res.n, det: res.det_n, trace: res.trace_n, w: res.w, q: res.q };
}

/** The sums block under the window: a header, the rows (at most SUMS.rows), "…", the Σ row and three lines for N, w and q. */
const SUMS = Object.freeze({ rows: 9, gap: 16, lines: 3 });
const sumsRowH = () => FONT_SIZE_SMALL * LINE_HEIGHT + 4;
function sumsHeight(solution) {
  const { rows } = sumsOf(solution);
  if (!rows.length) return 0;
  const shown = Math.min(rows.length, SUMS.rows) + (rows.length > SUMS.rows ? 1 : 0);
  return SUMS.gap + (shown + 2) * sumsRowH() + SUMS.lines * (FONT_SIZE * LINE_HEIGHT + 2) + 6;
}
const SUMS_HEAD = ["pixel", "g′x", "g′y", "g′x²", "g′y²", "g′x·g′y"];

/** The lines of N, w and q (for frames: those reached; `upTo` 0: N, 1: and w, 2: and q). */
function sumsLines(t, upTo = 2, { short = false } = {}) {
  const n = isMatrix(t.n) ? t.n : null;
  const lines = [
    n ? `N = ${short ? "" : "[Σg′x²  Σg′x·g′y; Σg′x·g′y  Σg′y²] = "}[${fmt(n[0][0], 6)}  ${fmt(n[0][1], 6)}; ${fmt(n[1][0], 6)}  ${fmt(n[1][1], 6)}]` : "N: —",
    `w = det N / trace N = ${short ? "" : `${fmt(t.det, 8)} / ${fmt(t.trace, 6)} = `}${fmt(t.w)}`,
    `q = 4 det N / trace² N = ${short ? "" : `4 · ${fmt(t.det, 8)} / ${fmt(t.trace, 6)}² = `}${fmt(t.q)}`,
  ];
  return lines.slice(0, upTo + 1);
}

/**
 * Draws the sums block from y: the table of each interior pixel's terms (in
 * a frame: the rows up to its pixel, that row marked), the Σ row (the
 * solution's sums, from the sums frame on) and N, w, q (frame by frame).
 */
function drawSums(ctx, width, y, solution, frame) {
  const t = sumsOf(solution);
  if (!t.rows.length) return;
  const m = t.rows.length;
  const k = frame ? frame.k : m + 3; // the pixel (0…m−1), then m: sums, m+1: N, m+2: w, m+3: q
  const rh = sumsRowH();
  const left = GRID.margin;
  const avail = width - 2 * GRID.margin;
  const colW = Math.min(84, avail / SUMS_HEAD.length);
  const firstW = Math.max(colW, textWidth("P(c22, r22)", FONT_SIZE_SMALL) + 6);
  const restW = Math.min(84, (avail - firstW) / (SUMS_HEAD.length - 1));
  const xs = SUMS_HEAD.map((_, i) => (i === 0 ? left : left + firstW + (i - 1) * restW));
  const right = (i) => (i === 0 ? xs[0] : xs[i] + restW - 4);
  let yy = y + SUMS.gap + rh / 2;
  SUMS_HEAD.forEach((h, i) => text(ctx, h, right(i), yy, { size: FONT_SIZE_SMALL, weight: "bold", align: i ? "right" : "left", color: COLORS.muted }));
  line(ctx, left, yy + rh / 2, left + firstW + (SUMS_HEAD.length - 1) * restW, yy + rh / 2, { color: COLORS.grid });
  // the rows shown: the last SUMS.rows up to the frame's pixel (all of them if they fit)
  const lastRow = Math.min(k, m - 1);
  const from = m > SUMS.rows ? Math.max(0, Math.min(lastRow - SUMS.rows + 1, m - SUMS.rows)) : 0;
  if (m > SUMS.rows) {
    yy += rh;
    text(ctx, from > 0 ? `… ${from} row${from === 1 ? "" : "s"} above` : "", left, yy, { size: FONT_SIZE_SMALL, color: COLORS.muted });
  }
  for (let i = from; i < from + Math.min(m, SUMS.rows); i++) {
    yy += rh;
    if (i > k) continue;
    const row = t.rows[i];
    if (frame && i === k) {
      ctx.fillStyle = COLORS.highlightFill;
      ctx.fillRect(left - 4, yy - rh / 2, firstW + (SUMS_HEAD.length - 1) * restW + 4, rh);
    }
    [`P(c${row.c}, r${row.r})`, fmt(row.gx, 6), fmt(row.gy, 6), fmt(row.gx2, 6), fmt(row.gy2, 6), fmt(row.gxgy, 6)].forEach((v, j) =>
      text(ctx, v, right(j), yy, { size: FONT_SIZE_SMALL, align: j ? "right" : "left" }),
    );
  }
  yy += rh;
  line(ctx, left, yy - rh / 2, left + firstW + (SUMS_HEAD.length - 1) * restW, yy - rh / 2, { color: COLORS.grid });
  if (k >= m) {
    ["Σ", "", "", fmt(t.sum.gx2, 6), fmt(t.sum.gy2, 6), fmt(t.sum.gxgy, 6)].forEach((v, j) =>
      text(ctx, v, right(j), yy, { size: FONT_SIZE_SMALL, weight: "bold", align: j ? "right" : "left", color: frame?.k === m ? COLORS.highlight : COLORS.ink }),
    );
  }
  yy += rh / 2 + 4;
  if (k > m) {
    const lines = sumsLines(t, k - m - 1);
    const shortLines = sumsLines(t, k - m - 1, { short: true }); // a narrow canvas: without the substitution (the caption has it)
    lines.forEach((str, i) => {
      const weight = frame && i === lines.length - 1 ? "bold" : "normal";
      text(ctx, textWidth(str, FONT_SIZE_SMALL, weight) > avail ? shortLines[i] : str, left, yy + (i + 0.5) * (FONT_SIZE * LINE_HEIGHT + 2), { size: FONT_SIZE_SMALL, weight });
    });
  }
}

/**
 * The motion of the window (issue 34: "the window and its sums"): pixel by
 * pixel its gradient and the three terms (the solution's gradient table), then
 * the sums, N, w and q (the solution's steps).
 */
function windowFrames(solution) {
  const t = sumsOf(solution);
  const win = fromAny(solution);
  if (!t.rows.length || !isMatrix(win)) return [];
  const steps = solution.steps ?? [];
  const stepOf = (key) => {
    const i = steps.findIndex((x) => x.values && Object.hasOwn(x.values, key));
    return i >= 0 ? i : null;
  };
  const m = t.rows.length;
  const v = (c, r) => win[r - 1]?.[c - 1];
  const sub = (x) => (typeof x === "number" && x < 0 ? `(${fmt(x)})` : fmt(x));
  const pixels = t.rows.map((p, k) => ({
    k,
    c: p.c,
    r: p.r,
    step: stepOf("table"),
    caption: `Pixel ${k + 1} of ${m}: P(c${p.c}, r${p.r}) = ${fmt(p.g)}: g′x = (${fmt(v(p.c + 1, p.r))} − ${sub(v(p.c - 1, p.r))}) / 2 = ${fmt(p.gx, 6)}, g′y = (${fmt(v(p.c, p.r + 1))} − ${sub(v(p.c, p.r - 1))}) / 2 = ${fmt(p.gy, 6)}; g′x² = ${fmt(p.gx2, 6)}, g′y² = ${fmt(p.gy2, 6)}, g′x·g′y = ${fmt(p.gxgy, 6)}.`,
  }));
  const lines = sumsLines(t);
  return [
    ...pixels,
    { k: m, step: stepOf("sum_gx2"), caption: `The sums over the ${m} interior pixels: Σg′x² = ${fmt(t.sum.gx2, 6)}, Σg′y² = ${fmt(t.sum.gy2, 6)}, Σg′x·g′y = ${fmt(t.sum.gxgy, 6)}.` },
    { k: m + 1, step: stepOf("n"), caption: `${lines[0]}.` },
    { k: m + 2, step: stepOf("w"), caption: `${lines[1]}.` },
    { k: m + 3, step: stepOf("q"), caption: `${lines[2]}.` },
  ];
}
const fromAny = (solution) => (isMatrix(solution.result?.window) ? solution.result.window : solution.inputs?.window);

function windowCell(width, win) {
  const cols = win[0].length;
  return Math.max(GRID.minCell, Math.min(GRID.maxCell, (width - 2 * GRID.margin) / cols));
}

/** The window's Data view: its grey values with each interior pixel's gradient in words; explorable. */
const windowTables = (source) => (solution) => {
  const { window: win, gx, gy } = source(solution);
  if (!isMatrix(win)) return { summary: "The window.", tables: [] };
  const hasG = isMatrix(gx) && isMatrix(gy);
  const t = sumsOf(solution);
  const mark = (r, c) => {
    const g = hasG && r > 0 && c > 0 ? gx[r - 1]?.[c - 1] : undefined;
    if (typeof g !== "number") return null;
    return `interior, gradient g′x = ${fmt(g)}, g′y = ${fmt(gy[r - 1][c - 1])}`;
  };
  return {
    summary: windowSpec(source).describe(solution),
    tables: [
      matrixTable("The window (grey values, c → r ↓ from 1; each interior pixel with its gradient)", win, {
        format: (v) => fmt(v, 5, "no value"),
        mark,
        explore: {
          rect(r, c, width) {
            const cell = windowCell(width, win);
            const x0 = Math.max(GRID.margin, (width - win[0].length * cell) / 2);
            return { x: x0 + c * cell, y: GRID.margin + r * cell, w: cell, h: cell };
          },
        },
      }),
      ...(t.rows.length
        ? [
            seriesTable(
              "The gradient table under the window: each interior pixel's gradient and terms, and their sums (the entries of N)",
              SUMS_HEAD,
              [...t.rows.map((p) => [`P(c${p.c}, r${p.r})`, fmt(p.gx, 6), fmt(p.gy, 6), fmt(p.gx2, 6), fmt(p.gy2, 6), fmt(p.gxgy, 6)]), ["Σ", "", "", fmt(t.sum.gx2, 6), fmt(t.sum.gy2, 6), fmt(t.sum.gxgy, 6)]],
            ),
          ]
        : []),
    ],
  };
};

const windowSpec = (source) => ({
  tables: windowTables(source),
  caption:
    "The window: grey values (dark = low, as in an image; see the legend), the interior framed; each blue arrow is the gradient (g′x, g′y) of an interior pixel by central differences, drawn to scale with the longest one.",
  height(width, solution) {
    const win = source(solution).window;
    if (!isMatrix(win)) return 120;
    return win.length * windowCell(width, win) + 2 * GRID.margin + GRID.greyLegend + GRID.legend + sumsHeight(solution);
  },
  describe(solution) {
    const { window: win, gx, gy } = source(solution);
    if (!isMatrix(win) || !isMatrix(gx)) return "The window.";
    let best = { m: -1 };
    gx.forEach((row, r) => row.forEach((v, c) => {
      const m = Math.hypot(v, gy[r][c]);
      if (m > best.m) best = { m, c: c + 2, r: r + 2, gx: v, gy: gy[r][c] };
    }));
    return `A ${win.length}×${win[0].length} window of grey values with the gradient arrows of its ${gx.length * gx[0].length} interior pixels; the longest is at P(c${best.c}, r${best.r}): g′x = ${fmt(best.gx)}, g′y = ${fmt(best.gy)}.`;
  },
  draw(ctx, width, height, solution, state) {
    const { window: win, gx, gy } = source(solution);
    if (!isMatrix(win)) return;
    const cell = windowCell(width, win);
    const x0 = Math.max(GRID.margin, (width - win[0].length * cell) / 2);
    const f = state?.frame ?? null;
    const rows = f ? sumsOf(solution).rows : [];
    // a frame of a pixel: the arrows so far (the gradient table's rows up to it)
    const done = new Set(rows.slice(0, f ? f.k + 1 : 0).map((p) => `${p.c},${p.r}`));
    const scale = drawWindow(ctx, x0, GRID.margin, cell, win, gx, gy, f ? (r, c) => done.has(`${c + 2},${r + 2}`) : undefined);
    if (f && f.c !== undefined) {
      // the pixel and the four neighbours of its central differences
      ctx.save();
      ctx.strokeStyle = COLORS.highlight;
      ctx.setLineDash([4, 3]);
      ctx.lineWidth = 2;
      for (const [dc, dr] of [[-1, 0], [1, 0], [0, -1], [0, 1]]) ctx.strokeRect(x0 + (f.c - 1 + dc) * cell + 2, GRID.margin + (f.r - 1 + dr) * cell + 2, cell - 4, cell - 4);
      ctx.setLineDash([]);
      ctx.lineWidth = 3;
      ctx.strokeRect(x0 + (f.c - 1) * cell + 1.5, GRID.margin + (f.r - 1) * cell + 1.5, cell - 3, cell - 3);
      ctx.restore();
    }
    const gridBottom = GRID.margin + win.length * cell;
    greyLegend(ctx, GRID.margin, gridBottom + 6, scale, { maxWidth: width - 2 * GRID.margin });
    text(ctx, "c →  r ↓  (from 1)   arrow = (g′x, g′y) at an interior pixel", GRID.margin, gridBottom + GRID.margin + GRID.greyLegend + GRID.legend / 2, {
      size: FONT_SIZE_SMALL,
      color: COLORS.muted,
    });
    drawSums(ctx, width, gridBottom + GRID.greyLegend + GRID.legend, solution, f);
  },
  // motion (issue 34; index.js `frames`): pixel by pixel its gradient and terms, then the sums, N, w and q
  frames: windowFrames,
  motion: { noun: "stage" },
});

/** The error ellipse (or its degenerate forms) centred at (cx, cy): `unit` CSS px per px of σ. */
function drawEllipse(ctx, cx, cy, unit, res, clipRadius) {
  const smax = res.sigma_max_px;
  const smin = res.sigma_min_px;
  const angle = (finite(res.weak_angle_deg) * Math.PI) / 180;
  ctx.save();
  ctx.beginPath();
  ctx.arc(cx, cy, clipRadius, 0, 2 * Math.PI);
  ctx.clip();
  ctx.strokeStyle = COLORS.imageSystem;
  ctx.fillStyle = "rgba(179, 64, 10, 0.16)";
  ctx.lineWidth = 2;
  if (typeof smin !== "number") {
    // N = 0: no direction is determined
    ctx.setLineDash([...DASH]);
    ctx.beginPath();
    ctx.arc(cx, cy, clipRadius - 2, 0, 2 * Math.PI);
    ctx.fill();
    ctx.stroke();
  } else {
    const a = typeof smax === "number" ? smax * unit : 4 * clipRadius; // ∞ along an edge
    const b = Math.max(smin * unit, 1.5);
    ctx.beginPath();
    ctx.ellipse(cx, cy, a, b, angle, 0, 2 * Math.PI);
    ctx.fill();
    ctx.stroke();
  }
  ctx.restore();
}

/** The lines of numbers beside the ellipse. */
function ellipseLines(solution) {
  const r = solution.result ?? {};
  const T = finite(solution.inputs?.threshold_px, 0.5);
  const n = isMatrix(r.n) ? r.n : [[0, 0], [0, 0]];
  const d = 6;
  return [
    { text: "N =", weight: "bold" },
    { text: `  [ ${fmt(n[0][0], d)}   ${fmt(n[0][1], d)} ]` },
    { text: `  [ ${fmt(n[1][0], d)}   ${fmt(n[1][1], d)} ]` },
    { text: `det N = ${fmt(r.det_n, 7)}` },
    { text: `trace N⁻¹ = ${typeof r.trace_n_inverse === "number" ? fmt(r.trace_n_inverse) : "∞"}` },
    { text: `w = det N / trace N = ${fmt(r.w)}` },
    { text: `q = 4 det N / trace² N = ${fmt(r.q)}` },
    { text: `λ(N) = ${fmt(r.lambda_max)}, ${fmt(r.lambda_min)}` },
    { text: `λmax(Σuv) = ${typeof r.lambda_max_shift === "number" ? fmt(r.lambda_max_shift) : "∞"} px² ${r.accepted ? "≤" : ">"} T² = ${fmt(T * T)}`, color: r.accepted ? COLORS.ink : COLORS.imageSystem },
    { text: `case: ${r.case}${r.accepted ? " (accepted)" : " (rejected)"}`, weight: "bold", color: r.accepted ? COLORS.green : COLORS.imageSystem },
  ];
}

/** Side by side when the canvas is wide enough, else the ellipse below the numbers. */
function ellipseLayout(width, solution) {
  const lines = ellipseLines(solution);
  const box = { w: Math.max(...lines.map((l) => textWidth(l.text, FONT_SIZE, l.weight ?? "normal"))) + 10, h: lines.length * FONT_SIZE * LINE_HEIGHT + 10 };
  const side = width - box.w - 3 * ELLIPSE.margin >= ELLIPSE.panelMin;
  const panel = side
    ? { x: box.w + 2 * ELLIPSE.margin, y: 0, w: width - box.w - 3 * ELLIPSE.margin, h: ELLIPSE.height }
    : { x: ELLIPSE.margin, y: box.h + ELLIPSE.margin, w: width - 2 * ELLIPSE.margin, h: ELLIPSE.height - 30 };
  return { lines, box, panel, height: side ? ELLIPSE.height : panel.y + panel.h };
}

const ellipseSpec = {
  tables(solution) {
    return {
      summary: `${ellipseSpec.describe(solution)} The figure draws the error ellipse beside the threshold circle; its numbers are these.`,
      tables: [seriesTable("N and the precision test (the lines beside the ellipse)", ["line"], ellipseLines(solution).filter((l) => l.text !== "N =").map((l) => [l.text.trim()]))],
    };
  },
  caption:
    "N and the precision test of Lecture 21: the error ellipse of the position (semi-axes σmax, σmin; orange) beside the threshold circle of radius T (dashed). Inside the circle: accepted. A long ellipse is an edge, a huge one a flat area.",
  height(width, solution) {
    return ellipseLayout(width, solution).height;
  },
  describe(solution) {
    const r = solution.result ?? {};
    const smax = typeof r.sigma_max_px === "number" ? `${fmt(r.sigma_max_px)} px` : "infinite";
    const T = finite(solution.inputs?.threshold_px, 0.5);
    return `N = [[${(r.n ?? []).flat().map((v) => fmt(v, 6)).join(", ")}]]; w = ${fmt(r.w)}, q = ${fmt(r.q)}. Error ellipse: σmax ${smax}, σmin ${fmt(r.sigma_min_px)} px against T = ${fmt(T)} px: ${r.accepted ? "accepted" : "not accepted"}, case ${r.case}.`;
  },
  draw(ctx, width, height, solution) {
    const r = solution.result ?? {};
    const T = finite(solution.inputs?.threshold_px, 0.5);
    const L = ellipseLayout(width, solution);
    textBlock(ctx, L.lines, ELLIPSE.margin, ELLIPSE.margin, { size: FONT_SIZE });
    const { panel } = L;
    const cx = panel.x + panel.w / 2;
    const cy = panel.y + panel.h / 2;
    const clipR = Math.max(20, Math.min(panel.w / 2, panel.h / 2 - 22));
    // the larger of T and σmax (up to the clip) fills the panel
    const smax = typeof r.sigma_max_px === "number" ? r.sigma_max_px : Infinity;
    const fit = Math.min(Math.max(T, smax), ELLIPSE.clip * T);
    const unit = (clipR - 6) / fit;
    drawEllipse(ctx, cx, cy, unit, r, clipR);
    ctx.save();
    ctx.strokeStyle = COLORS.ink;
    ctx.setLineDash([...DASH]);
    ctx.lineWidth = 1.2;
    ctx.beginPath();
    ctx.arc(cx, cy, T * unit, 0, 2 * Math.PI);
    ctx.stroke();
    ctx.restore();
    line(ctx, cx - 5, cy, cx + 5, cy, { color: COLORS.ink });
    line(ctx, cx, cy - 5, cx, cy + 5, { color: COLORS.ink });
    text(ctx, `dashed circle: T = ${fmt(T)} px`, cx, panel.y + 12, { align: "center", size: FONT_SIZE_SMALL, color: COLORS.ink, halo: true });
    const axes = typeof r.sigma_min_px !== "number"
      ? "no gradient: undetermined in every direction"
      : `σmax = ${typeof r.sigma_max_px === "number" ? fmt(r.sigma_max_px) : "∞"} px, σmin = ${fmt(r.sigma_min_px)} px`;
    text(ctx, axes, cx, panel.y + panel.h - 10, { align: "center", size: FONT_SIZE_SMALL, color: COLORS.imageSystem, halo: true });
  },
};

// ---------------------------------------------------------------------------
// Moravec: the four directional differences of each interior pixel

/** Every interior pixel with its differences; `shown`: all of them for a small window, else the selected one (the largest sum by default). */
function moravecPixels(solution, state) {
  const rows = solution.result?.differences;
  const win = solution.inputs?.window;
  if (!isMatrix(rows) || !isMatrix(win)) return { all: [], shown: [], win: null, total: 0, selected: null };
  const all = rows.map((d) => ({ c: d[0], r: d[1], g: d[2], diffs: d.slice(3, 7), sum: d[7] }));
  const total = all.length;
  if (total <= MORAVEC.maxShown) return { all, shown: all, win, total, selected: null };
  const largest = all.reduce((a, b) => (b.sum > a.sum ? b : a));
  const at = state?.frame ?? state; // a motion frame is the selection
  const selected = all.find((p) => p.c === at?.c && p.r === at?.r) ?? largest;
  return { all, shown: [selected], win, total, selected };
}

/** The overview grid of a large window (every interior pixel with its sum; the selected one framed). */
function overviewLayout(width, win) {
  const cols = win[0].length;
  const cell = Math.max(MORAVEC.overviewMin, Math.min(MORAVEC.overviewMax, Math.floor((width - 2 * MORAVEC.panelGap) / cols)));
  return { cell, x0: Math.floor((width - cols * cell) / 2), y0: MORAVEC.panelGap + 18, h: win.length * cell + 18 + MORAVEC.panelGap };
}

/**
 * The panels of the shown pixels, as many per row as fit; on a narrow canvas
 * (where the named lines would put one panel per row) the compact form names
 * each direction by its arrow (→ ↓ ↘ ↙, with a key above the panels).
 */
function moravecLayout(width, count) {
  const fit = (minPanel) => Math.max(1, Math.min(count, Math.floor((width + MORAVEC.panelGap) / (minPanel + MORAVEC.panelGap))));
  const compact = count > 1 && fit(MORAVEC.minPanel) === 1 && fit(MORAVEC.compactPanel) > 1;
  const perRow = fit(compact ? MORAVEC.compactPanel : MORAVEC.minPanel);
  const panelW = (width - MORAVEC.panelGap * (perRow + 1)) / perRow;
  const cell = Math.min(MORAVEC.maxCell, (panelW - 20) / 3);
  const textH = MORAVEC.textLines * FONT_SIZE_SMALL * LINE_HEIGHT + 10;
  const panelH = 3 * cell + textH + 18;
  return { compact, perRow, panelW, cell, panelH, rows: Math.ceil(count / perRow), keyH: compact ? MORAVEC.key : 0 };
}

function drawOverview(ctx, width, m, scale) {
  const O = overviewLayout(width, m.win);
  const sums = new Map(m.all.map((p) => [`${p.c},${p.r}`, p.sum]));
  text(ctx, width < 520 ? "Click an interior pixel (Σ: its sum)." : "Click an interior pixel or use the arrow keys; Σ under a grey value is that pixel’s sum.", MORAVEC.panelGap, MORAVEC.panelGap, { size: FONT_SIZE_SMALL, color: COLORS.muted });
  m.win.forEach((row, r) =>
    row.forEach((v, c) => {
      const x = O.x0 + c * O.cell;
      const y = O.y0 + r * O.cell;
      scale.cell(ctx, v, x, y, O.cell, O.cell);
      ctx.strokeStyle = COLORS.grid;
      ctx.lineWidth = 1;
      ctx.strokeRect(x + 0.5, y + 0.5, O.cell - 1, O.cell - 1);
      text(ctx, fmt(v), x + 3, y + 3, { size: 9.5, baseline: "top", halo: true });
      const sum = sums.get(`${c + 1},${r + 1}`);
      if (sum !== undefined) text(ctx, `Σ ${fmt(sum)}`, x + 3, y + O.cell - 3, { size: 9, baseline: "bottom", color: COLORS.pixelSystem, halo: true });
    }),
  );
  const s = m.selected;
  ctx.strokeStyle = COLORS.highlight;
  ctx.lineWidth = 3;
  ctx.strokeRect(O.x0 + (s.c - 2) * O.cell + 1.5, O.y0 + (s.r - 2) * O.cell + 1.5, 3 * O.cell - 3, 3 * O.cell - 3);
  ctx.lineWidth = 2;
  ctx.strokeStyle = COLORS.frameStroke;
  ctx.strokeRect(O.x0 + (s.c - 1) * O.cell + 1, O.y0 + (s.r - 1) * O.cell + 1, O.cell - 2, O.cell - 2);
  return O.h;
}

const moravecSpec = {
  tables(solution, state) {
    const m = moravecPixels(solution, state);
    if (!m.win) return { summary: "No window.", tables: [] };
    const best = m.all.length ? m.all.reduce((a, b) => (b.sum > a.sum ? b : a)) : null;
    const sel = m.selected;
    const rows = m.all.map((p) => [`P(c${p.c}, r${p.r})`, fmt(p.g), ...p.diffs.map((v) => fmt(v)), fmt(p.sum)]);
    const marks = m.all.map((p) => [[best && p === best ? "largest sum" : null, sel && p === sel ? "selected" : null].filter(Boolean).join(", ") || null, null, null, null, null, null, null]);
    return {
      summary: `${m.total} interior pixels; the largest sum of squared differences, ${best ? fmt(best.sum) : "none"}, is at ${best ? `P(c${best.c}, r${best.r})` : "no pixel"}; the mean of the sums is ${fmt(solution.result?.mean)}.${sel ? ` Selected: P(c${sel.c}, r${sel.r}), sum ${fmt(sel.sum)}.` : ""}`,
      tables: [
        seriesTable("Each interior pixel: the four differences across it and the sum of their squares", ["pixel", "grey value", ...DIRECTIONS.map((d) => `${d.name} ${d.glyph}`), "sum of squares"], rows, marks),
        matrixTable("The window (grey values)", m.win, { format: (v) => fmt(v, 5, "no value"), mark: (r, c) => (sel && r === sel.r - 1 && c === sel.c - 1 ? "selected" : null) }),
      ],
    };
  },
  caption:
    "Moravec (worked examples, Example 14): at each interior pixel (framed), the four differences across it — along the row, the column and both diagonals, each arrow from the subtracted to the other neighbour — squared and summed. A window larger than 4×4 shows the selected pixel (orange 3×3 frame).",
  height(width, solution, state) {
    const m = moravecPixels(solution, state);
    const L = moravecLayout(width, Math.max(m.shown.length, 1));
    const top = m.selected ? overviewLayout(width, m.win).h : 0;
    return top + L.keyH + L.rows * (L.panelH + MORAVEC.panelGap) + MORAVEC.panelGap + 20 + GRID.greyLegend;
  },
  describe(solution, state) {
    const m = moravecPixels(solution, state);
    const parts = m.shown.map((p) => `P(c${p.c}, r${p.r}) = ${fmt(p.g)}: differences ${p.diffs.map((d) => fmt(d)).join(", ")}, sum ${fmt(p.sum)}`);
    const which = m.selected ? ` (the selected one shown; sums ${m.all.map((p) => fmt(p.sum)).join(", ")})` : "";
    return `${m.total} interior pixels${which}. ${parts.join("; ")}. Mean ${fmt(solution.result?.mean)}.`;
  },
  status(solution, state) {
    const m = moravecPixels(solution, state);
    if (!m.selected) return "";
    const p = m.selected;
    return `Selected P(c${p.c}, r${p.r}) = ${fmt(p.g)}: sum of the four squared differences ${fmt(p.sum)}.`;
  },
  select(solution, point, state) {
    const m = moravecPixels(solution, state);
    if (!m.selected) return undefined;
    const O = overviewLayout(point.width, m.win);
    const c = Math.floor((point.x - O.x0) / O.cell) + 1;
    const r = Math.floor((point.y - O.y0) / O.cell) + 1;
    return m.all.some((p) => p.c === c && p.r === r) ? { c, r } : undefined;
  },
  key(solution, key, state) {
    const m = moravecPixels(solution, state);
    if (!m.selected) return undefined;
    const step = arrowStep(key);
    if (!step) return undefined;
    const next = { c: m.selected.c + step[0], r: m.selected.r + step[1] };
    return m.all.some((p) => p.c === next.c && p.r === next.r) ? next : { c: m.selected.c, r: m.selected.r };
  },
  // motion (issue 34; index.js `frames`): pixel by pixel, its four differences and their sum (the solution's `differences`)
  frames(solution) {
    const { all } = moravecPixels(solution, null);
    const steps = solution.steps ?? [];
    const table = steps.findIndex((s) => s.values && Object.hasOwn(s.values, "sums"));
    const mean = steps.findIndex((s) => s.values && Object.hasOwn(s.values, "mean"));
    return all.map((p, k) => ({
      k,
      c: p.c,
      r: p.r,
      step: k === all.length - 1 && mean >= 0 ? mean : table >= 0 ? table : null,
      caption: `Pixel ${k + 1}: P(c${p.c}, r${p.r}) = ${fmt(p.g)}; the differences across it ${DIRECTIONS.map((d, i) => `${d.glyph} ${fmt(p.diffs[i])}`).join(", ")}; the sum of their squares ${fmt(p.sum)}.${k === all.length - 1 ? ` The mean of the ${all.length} sums: ${fmt(solution.result?.mean)}.` : ""}`,
    }));
  },
  motion: { noun: "pixel" },
  frameAt(solution, state) {
    const { all } = moravecPixels(solution, null);
    const i = all.findIndex((p) => p.c === state?.c && p.r === state?.r);
    return i >= 0 ? i : null;
  },
  draw(ctx, width, height, solution, state) {
    const m = moravecPixels(solution, state);
    const { shown, win, total } = m;
    if (!win) return;
    const L = moravecLayout(width, Math.max(shown.length, 1));
    const labels = new Labels(ctx, width, height);
    const scale = windowScale(win);
    let top = m.selected ? drawOverview(ctx, width, m, scale) : 0;
    if (L.compact) {
      // the key to the arrows of the compact lines
      let x = MORAVEC.panelGap;
      const y = top + MORAVEC.panelGap + L.keyH / 2 - 4;
      DIRECTIONS.forEach((dir) => {
        const b = text(ctx, `${dir.glyph} ${dir.name}`, x, y, { size: FONT_SIZE_SMALL, color: COLORS[dir.key] });
        labels.avoid(b);
        x = b.x + b.w + 10;
      });
      top += L.keyH;
    }
    const lh = FONT_SIZE_SMALL * LINE_HEIGHT;
    const f = state?.frame ?? null; // motion (a small window): the pixels up to the frame's
    shown.forEach((p, i) => {
      if (f && !m.selected && i > f.k) return;
      const px = MORAVEC.panelGap + (i % L.perRow) * (L.panelW + MORAVEC.panelGap);
      const py = top + MORAVEC.panelGap + Math.floor(i / L.perRow) * (L.panelH + MORAVEC.panelGap);
      const gx0 = px + (L.panelW - 3 * L.cell) / 2;
      const gy0 = py + 16;
      labels.avoid(text(ctx, `P(c${p.c}, r${p.r}) = ${fmt(p.g)}`, px + L.panelW / 2, py + 6, { align: "center", weight: "bold", size: FONT_SIZE_SMALL }));
      labels.avoidRect(gx0, gy0, 3 * L.cell, L.cell); // the grid's top row
      for (let dr = -1; dr <= 1; dr++) {
        for (let dc = -1; dc <= 1; dc++) {
          const v = win[p.r - 1 + dr]?.[p.c - 1 + dc];
          const x = gx0 + (dc + 1) * L.cell;
          const y = gy0 + (dr + 1) * L.cell;
          if (typeof v === "number") scale.cell(ctx, v, x, y, L.cell, L.cell);
          else {
            ctx.fillStyle = COLORS.background;
            ctx.fillRect(x, y, L.cell, L.cell);
          }
          ctx.strokeStyle = dr === 0 && dc === 0 ? COLORS.frameStroke : COLORS.grid;
          ctx.lineWidth = dr === 0 && dc === 0 ? 2 : 1;
          ctx.strokeRect(x + 0.5, y + 0.5, L.cell - 1, L.cell - 1);
          // the neighbours' values in their corners (no arrow reaches there)
          if (dr || dc) labels.avoid(text(ctx, fmt(v), x + 3, y + 3, { size: 9.5, baseline: "top", halo: true }));
        }
      }
      const centre = (d) => [gx0 + (d[0] + 1.5) * L.cell, gy0 + (d[1] + 1.5) * L.cell];
      const [cx, cy] = centre([0, 0]);
      DIRECTIONS.forEach((dir, k) => {
        const [x0, y0] = centre(dir.from);
        const [x1, y1] = centre(dir.to);
        const shrink = 0.28;
        const [ax0, ay0, ax1, ay1] = [x0 + (x1 - x0) * shrink, y0 + (y1 - y0) * shrink, x1 - (x1 - x0) * shrink, y1 - (y1 - y0) * shrink];
        arrow(ctx, ax0, ay0, ax1, ay1, { color: COLORS[dir.key], width: 2, size: 6 });
        // the label in the middle may cover where the arrows cross, not their ends
        labels.avoidDot(ax0, ay0, 2).avoidDot(ax1, ay1, 6);
        labels.avoidLine(ax0, ay0, ax1, ay1, 1, "crossing");
        const diff = p.diffs[k];
        const a = win[p.r - 1 + dir.to[1]]?.[p.c - 1 + dir.to[0]];
        const b = win[p.r - 1 + dir.from[1]]?.[p.c - 1 + dir.from[0]];
        const sub = typeof b === "number" && b < 0 ? `(${fmt(b)})` : fmt(b);
        const what = L.compact ? dir.glyph : `${dir.name}:`;
        labels.avoid(text(ctx, `${what} (${fmt(a)} − ${sub})² = ${fmt(diff * diff)}`, px + 8, gy0 + 3 * L.cell + 12 + k * lh, { size: FONT_SIZE_SMALL, color: COLORS[dir.key] }));
      });
      labels.avoid(text(ctx, `sum = ${fmt(p.sum)}`, px + 8, gy0 + 3 * L.cell + 14 + 4 * lh, { size: FONT_SIZE_SMALL, weight: "bold" }));
      // the centre pixel's value on top of the arrows' crossing (or in a corner)
      labels.add(fmt(win[p.r - 1]?.[p.c - 1]), cx, cy, {
        size: 10.5,
        weight: "bold",
        ignore: "crossing",
        candidates: ["C", { cx: cx - L.cell / 2 + 10, cy: cy - L.cell / 2 + 9 }],
      });
    });
    labels.avoid(greyLegend(ctx, MORAVEC.panelGap, height - 22 - GRID.greyLegend, scale, { maxWidth: width - 2 * MORAVEC.panelGap }));
    const note = m.selected ? ` (${total} pixels)` : "";
    if (!f || f.k === total - 1) labels.add(`mean of the sums = ${fmt(solution.result?.mean)}${note}`, MORAVEC.panelGap, height - 12, { weight: "bold", candidates: ["E"], gap: 0 });
    labels.draw();
  },
};

// ---------------------------------------------------------------------------
// The test pattern: window, ellipse, candidates, interest points

function imageLayout(width, img) {
  const side = img.length;
  const avail = Math.min(width - 2 * IMAGE.margin, IMAGE.maxSide);
  const cell = Math.max(2, Math.floor(avail / side));
  return { cell, side, x0: Math.floor((width - side * cell) / 2), y0: IMAGE.margin };
}

/** Splits `str` at " · " and spaces into lines no wider than `max` CSS px. */
function wrap(str, max, size, weight) {
  const lines = [];
  let cur = "";
  for (const word of str.split(" ")) {
    const next = cur ? `${cur} ${word}` : word;
    if (cur && textWidth(next, size, weight) > max) {
      lines.push(cur.replace(/ ·$/, ""));
      cur = word === "·" ? "" : word;
    } else {
      cur = next;
    }
  }
  if (cur) lines.push(cur);
  return lines;
}

/** The legend under the pattern, wrapped to the canvas width. */
function legendLines(width, solution, magnification) {
  const r = solution.result ?? {};
  const inp = solution.inputs ?? {};
  const pts = Array.isArray(r.points) ? r.points : [];
  const size = finite(inp.window_size, 5);
  const T = finite(inp.threshold_px, 0.5);
  const max = width - 2 * IMAGE.margin;
  const parts = [
    [`window (${inp.c}, ${inp.r}), ${size}×${size}: ${r.case} · w = ${fmt(r.w)} · q = ${fmt(r.q)}`, { size: FONT_SIZE, weight: "bold" }],
    [`${r.candidates} pixels pass the threshold (orange dots) · ${pts.length} interest points (purple rings)`, { size: FONT_SIZE_SMALL }],
    [`ellipse magnified ×${fmt(magnification, 3)}: the dashed circle is T = ${fmt(T)} px · c → 1…64, r ↓ 1…64`, { size: FONT_SIZE_SMALL, color: COLORS.muted }],
  ];
  return parts.flatMap(([str, style]) => wrap(str, max, style.size, style.weight).map((t) => ({ text: t, style })));
}

const imageSpec = {
  tables(solution) {
    const r = solution.result ?? {};
    const inp = solution.inputs ?? {};
    const pts = Array.isArray(r.points) ? r.points : [];
    const refs = stepValue(solution, "references");
    return {
      summary: `${imageSpec.describe(solution)} The 64×64 pattern's grey values are 0 and 255 (its picture is not repeated as a table); the interest points and the windows are listed here.`,
      tables: [
        seriesTable("The interest points after suppression (purple rings)", ["point", "c", "r"], pts.map((p, i) => [String(i + 1), fmt(p[0]), fmt(p[1])])),
        seriesTable(
          "The windows and their cases",
          ["window", "c", "r", "case"],
          [[`selected ${inp.window_size}×${inp.window_size} window (orange)`, fmt(inp.c), fmt(inp.r), String(r.case ?? "")], ...(Array.isArray(refs) ? refs.map((x) => [`reference: ${x.place}`, fmt(x.c), fmt(x.r), String(x.case)]) : [])],
        ),
      ],
    };
  },
  caption:
    "The 64×64 test pattern with the window (orange square) and its error ellipse, magnified so that the dashed circle is T; small orange dots pass the threshold, purple rings are the interest points left after non-maximum suppression. Three fixed windows (dotted) show Lecture 21's three cases with their ellipses at the same magnification: flat (a dashed disc, no direction determined or both axes long), edge (long along the edge), corner (small).",
  height(width, solution) {
    const img = stepValue(solution, "image");
    if (!isMatrix(img)) return 120;
    const L = imageLayout(width, img);
    return L.side * L.cell + 2 * IMAGE.margin + 14 + legendLines(width, solution, 1).length * (FONT_SIZE * LINE_HEIGHT + 2) + GRID.greyLegend;
  },
  describe(solution) {
    const r = solution.result ?? {};
    const inp = solution.inputs ?? {};
    const pts = Array.isArray(r.points) ? r.points : [];
    const refs = stepValue(solution, "references");
    const cases = Array.isArray(refs) ? ` Reference windows: ${refs.map((x) => `${x.place} (${x.c}, ${x.r}) ${x.case}`).join(", ")}.` : "";
    return `Test pattern 64×64; ${inp.window_size}×${inp.window_size} window at (c, r) = (${inp.c}, ${inp.r}): case ${r.case}, w = ${fmt(r.w)}, q = ${fmt(r.q)}. ${r.candidates} pixels pass the threshold, ${pts.length} interest points after suppression: ${pts.map((p) => `(${p[0]}, ${p[1]})`).join(", ")}.${cases}`;
  },
  draw(ctx, width, height, solution) {
    const img = stepValue(solution, "image");
    if (!isMatrix(img)) return;
    const r = solution.result ?? {};
    const inp = solution.inputs ?? {};
    const L = imageLayout(width, img);
    const X = (c) => L.x0 + c * L.cell; // c zero-based, left edge of the pixel
    const Y = (rr) => L.y0 + rr * L.cell;
    // grey values 0…255 as they are (the shared scale with levels 0 and 255: dark = low)
    const scale = greyScale(0, 255, { name: "Pattern", levels: [0, 255], format: (v) => String(v) });
    let shade = -1; // the pattern is mostly flat: set (and parse) a colour only when it changes
    for (let rr = 0; rr < L.side; rr++) {
      for (let c = 0; c < L.side; c++) {
        const g = Math.max(0, Math.min(255, Math.round(img[rr][c])));
        if (g !== shade) {
          ctx.fillStyle = scale.fill(g);
          shade = g;
        }
        ctx.fillRect(X(c), Y(rr), L.cell + 0.5, L.cell + 0.5);
        scale.note(g, X(c), Y(rr), L.cell, L.cell);
      }
    }
    const cands = stepValue(solution, "candidates");
    if (isMatrix(cands)) for (const p of cands) dot(ctx, X(p[0] - 0.5), Y(p[1] - 0.5), Math.max(1.2, L.cell * 0.16), COLORS.highlight);
    const pts = Array.isArray(r.points) ? r.points : [];
    const labels = new Labels(ctx, width, height);
    for (const p of pts) {
      labels.avoidDot(X(p[0] - 0.5), Y(p[1] - 0.5), Math.max(4, L.cell * 0.9), 2);
      ctx.save();
      ctx.strokeStyle = "#ffffff";
      ctx.lineWidth = 4;
      ctx.beginPath();
      ctx.arc(X(p[0] - 0.5), Y(p[1] - 0.5), Math.max(4, L.cell * 0.9), 0, 2 * Math.PI);
      ctx.stroke();
      ctx.strokeStyle = COLORS.point;
      ctx.lineWidth = 2;
      ctx.stroke();
      ctx.restore();
    }
    // the window and its magnified ellipse
    const size = finite(inp.window_size, 5);
    const half = Math.floor(size / 2);
    const c0 = finite(inp.c, 1) - 1;
    const r0 = finite(inp.r, 1) - 1;
    ctx.save();
    ctx.strokeStyle = "#ffffff";
    ctx.lineWidth = 4;
    ctx.strokeRect(X(c0 - half), Y(r0 - half), size * L.cell, size * L.cell);
    ctx.strokeStyle = COLORS.highlight;
    ctx.lineWidth = 2;
    ctx.strokeRect(X(c0 - half), Y(r0 - half), size * L.cell, size * L.cell);
    ctx.restore();
    labels.avoidRect(X(c0 - half), Y(r0 - half), size * L.cell, size * L.cell, 2);
    const T = finite(inp.threshold_px, 0.5);
    const cx = X(c0 + 0.5);
    const cy = Y(r0 + 0.5);
    const rT = (half + IMAGE.tRadiusCells) * L.cell;
    // seed 003's three cases at fixed places, with the same magnification
    const refs = stepValue(solution, "references");
    for (const ref of Array.isArray(refs) ? refs : []) {
      const rx = X(ref.c - 0.5);
      const ry = Y(ref.r - 0.5);
      ctx.save();
      ctx.strokeStyle = "#ffffff";
      ctx.lineWidth = 1;
      ctx.setLineDash([3, 3]);
      ctx.strokeRect(X(ref.c - 1 - half), Y(ref.r - 1 - half), size * L.cell, size * L.cell);
      ctx.restore();
      drawEllipse(ctx, rx, ry, rT / T, ref, rT * IMAGE.clip * 0.7);
      labels.avoidDot(rx, ry, rT * IMAGE.clip * 0.7, 0); // the ellipse at most (it is clipped there)
      // the case's name beside its window (above first), off the interest points and the other names
      labels.add(ref.case, rx, ry, { size: FONT_SIZE_SMALL, weight: "bold", gap: (size * L.cell) / 2 + 2, candidates: ["N", "S", "W", "E", "NW", "NE", "SW", "SE"], farther: rT * IMAGE.clip * 0.7 - (size * L.cell) / 2, within: { x: X(0), y: Y(0), w: L.side * L.cell, h: L.side * L.cell } });
    }
    drawEllipse(ctx, cx, cy, rT / T, r, rT * IMAGE.clip);
    ctx.save();
    ctx.strokeStyle = "#ffffff";
    ctx.setLineDash([...DASH]);
    ctx.lineWidth = 1.5;
    ctx.beginPath();
    ctx.arc(cx, cy, rT, 0, 2 * Math.PI);
    ctx.stroke();
    ctx.restore();
    labels.avoidDot(cx, cy, rT, 1);
    labels.draw();
    const magnification = rT / T / L.cell;
    let y = L.y0 + L.side * L.cell + 14;
    const lh = FONT_SIZE * LINE_HEIGHT + 2;
    for (const line of legendLines(width, solution, magnification)) {
      text(ctx, line.text, IMAGE.margin, y, line.style);
      y += lh;
    }
    greyLegend(ctx, IMAGE.margin, y - lh / 2 + 4, scale, { maxWidth: width - 2 * IMAGE.margin });
  },
};

/** The centre of pattern pixel (c, r), counted from 1, in CSS px of a canvas `width` wide; for tests and tools. */
export function patternPoint(width, solution, c, r) {
  const L = imageLayout(width, stepValue(solution, "image"));
  return [L.x0 + (c - 0.5) * L.cell, L.y0 + (r - 0.5) * L.cell];
}

/** The centre of window pixel (c, r) in the Moravec overview grid (shown for windows larger than 4×4). */
export function moravecPoint(width, solution, c, r) {
  const O = overviewLayout(width, solution.inputs.window);
  return [O.x0 + (c - 0.5) * O.cell, O.y0 + (r - 0.5) * O.cell];
}

/** Moves the window on the pattern: a click (or a drag) centres it on a pixel, the arrow keys move it by one. */
function moveWindow(solution, c, r) {
  const img = stepValue(solution, "image");
  const size = finite(solution.inputs?.window_size, 5);
  if (!isMatrix(img)) return null;
  const half = Math.floor(size / 2);
  const clamp = (v) => Math.max(half + 1, Math.min(img.length - half, Math.round(v)));
  const next = { c: clamp(c), r: clamp(r) };
  return next.c === solution.inputs?.c && next.r === solution.inputs?.r ? null : { c: String(next.c), r: String(next.r) };
}

imageSpec.interact = {
  hint: "Click or drag on the pattern to move the window there; with the pattern focused, the arrow keys move it by one pixel.",
  drag: true,
  pointer(x, y, width, height, solution) {
    const img = stepValue(solution, "image");
    if (!isMatrix(img)) return null;
    const L = imageLayout(width, img);
    const c = Math.floor((x - L.x0) / L.cell) + 1;
    const r = Math.floor((y - L.y0) / L.cell) + 1;
    if (c < 1 || r < 1 || c > L.side || r > L.side) return null;
    return moveWindow(solution, c, r);
  },
  key(key, solution) {
    const step = arrowStep(key);
    if (!step) return null;
    return moveWindow(solution, finite(solution.inputs?.c, 1) + step[0], finite(solution.inputs?.r, 1) + step[1]);
  },
};

const fromResult = (solution) => ({ window: solution.inputs?.window, gx: solution.result?.gx, gy: solution.result?.gy });
const fromImage = (solution) => ({ window: solution.result?.window, gx: solution.result?.gx, gy: solution.result?.gy });

export const figures = {
  "forstner-window": [windowSpec(fromResult), ellipseSpec],
  "moravec-window": moravecSpec,
  "forstner-image": [imageSpec, windowSpec(fromImage), ellipseSpec],
};
