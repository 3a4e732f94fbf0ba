// Figure of the "Resampling" topic (seed 000, Example 12; seed 004):
//   resample: the patch as a grid of numbers at its image columns and rows,
//     the fractional position (draggable), the nearest pixel, the four pixels
//     of the bilinear interpolation with their weights, I1 and I2 on the two
//     rows, and the sixteen pixels of the cubic convolution when they exist.

import { COLORS, FONT_SIZE_SMALL, LINE_HEIGHT, dot, line, text, textBlock, textWidth } from "./draw.js";
import { GRID, drawGrid, fmt, isMatrix, outline, stepValue } from "./filters.js";

const R = Object.freeze({
  maxCell: 84,
  minCell: 22,
  dot: 6,
  marker: 5,
  keyStep: 0.05, // px moved per arrow key press
  besideFrom: 64, // the value box goes beside the grid only if the cells stay this large
  valueDy: -0.24, // grey values sit above the pixel centre, which gets a dot
  key: 18, // room for the key line at the bottom
});

function data(solution) {
  const inp = solution.inputs ?? {};
  const res = solution.result ?? {};
  const patch = inp.patch;
  if (!isMatrix(patch)) return null;
  return {
    patch,
    fc: inp.first_c ?? 0,
    fr: inp.first_r ?? 0,
    c: inp.c,
    r: inp.r,
    res,
    bl: { c: stepValue(solution, "bilinear_c"), r: stepValue(solution, "bilinear_r"), w: stepValue(solution, "weights") },
    bc: { c: stepValue(solution, "bicubic_c"), r: stepValue(solution, "bicubic_r"), wc: stepValue(solution, "weights_c"), wr: stepValue(solution, "weights_r") },
  };
}

function valueLines(d) {
  const { res } = d;
  return [
    { text: `Position (c, r) = (${fmt(d.c, 7)}, ${fmt(d.r, 7)})`, weight: "bold" },
    { text: `Nearest pixel (${fmt(res.nearest_c)}, ${fmt(res.nearest_r)}): ${fmt(res.nearest)}`, color: COLORS.pixelSystem },
    { text: `dc = ${fmt(res.dc)}, dr = ${fmt(res.dr)}` },
    { text: `I₁ (row ${fmt(d.bl.r)}) = ${fmt(res.i1, 6)}`, color: COLORS.imageSystem },
    { text: `I₂ (row ${fmt((d.bl.r ?? 0) + 1)}) = ${fmt(res.i2, 6)}`, color: COLORS.imageSystem },
    { text: `Bilinear I = ${fmt(res.bilinear, 6)} ≈ ${fmt(res.bilinear_rounded)}`, weight: "bold", color: COLORS.highlight },
    res.bicubic === null || res.bicubic === undefined
      ? { text: "Bicubic: no 4×4 neighbourhood here", color: COLORS.muted }
      : { text: `Bicubic (4×4) = ${fmt(res.bicubic, 6)}`, weight: "bold", color: COLORS.point },
  ];
}

function layout(width, d) {
  const cols = d.patch[0].length;
  const rows = d.patch.length;
  const m = GRID.margin;
  const lines = valueLines(d);
  const pad = 5; // textBlock's padding
  const box = {
    w: Math.ceil(Math.max(...lines.map((l) => textWidth(l.text, FONT_SIZE_SMALL, l.weight ?? "normal"))) + 2 * pad),
    h: Math.ceil(lines.length * FONT_SIZE_SMALL * LINE_HEIGHT + 2 * pad),
  };
  const beside = width - 2 * m - GRID.axis - box.w - GRID.gap >= cols * R.besideFrom;
  const availW = beside ? width - 2 * m - GRID.axis - box.w - GRID.gap : width - 2 * m - GRID.axis;
  const cell = Math.max(R.minCell, Math.min(R.maxCell, Math.floor(availW / cols)));
  const x0 = m + GRID.axis + 8;
  const y0 = m + GRID.axis + 4;
  const gridH = rows * cell;
  const boxX = beside ? x0 + cols * cell + GRID.gap : m;
  const boxY = beside ? y0 : y0 + gridH + GRID.gap;
  const height = Math.max(y0 + gridH, boxY + box.h) + m + R.key;
  return { cell, x0, y0, cols, rows, lines, boxX, boxY, height };
}

/** Canvas position of image pixel position (c, r). */
const at = (L, d, c, r) => [L.x0 + (c - d.fc + 0.5) * L.cell, L.y0 + (r - d.fr + 0.5) * L.cell];

function draw(ctx, width, d) {
  const L = layout(width, d);
  const shade = { fill: () => "rgba(87, 96, 106, 0.06)" };
  const g = drawGrid(ctx, d.patch, L.x0, L.y0, L.cell, { first: { c: d.fc, r: d.fr }, shade, valueDy: L.cell >= 40 ? R.valueDy : 0 });
  text(ctx, "c →", L.x0 + g.w + 4, L.y0 - GRID.axis / 2, { size: 10, color: COLORS.muted });
  text(ctx, "r ↓", L.x0 - 4, L.y0 - GRID.axis / 2, { size: 10, color: COLORS.muted, align: "right" });
  if (L.cell >= 40) {
    for (let r = 0; r < L.rows; r++) for (let c = 0; c < L.cols; c++) dot(ctx, L.x0 + (c + 0.5) * L.cell, L.y0 + (r + 0.5) * L.cell, 2, COLORS.muted);
  }
  const { res } = d;
  // the sixteen pixels of the cubic convolution
  if (Number.isFinite(d.bc.c) && res.bicubic !== null) {
    outline(ctx, g, d.bc.c - d.fc, d.bc.r - d.fr, 4, 4, { color: COLORS.point, width: 2, dash: [6, 4] });
    // each pixel's cubic weight f(row) · f(column), at the bottom of its cell
    if (Array.isArray(d.bc.wc) && Array.isArray(d.bc.wr) && L.cell >= 44) {
      d.bc.wr.forEach((wr, j) =>
        d.bc.wc.forEach((wc, i) => {
          const x = L.x0 + (d.bc.c - d.fc + i + 0.5) * L.cell;
          const y = L.y0 + (d.bc.r - d.fr + j + 1) * L.cell - 7;
          text(ctx, fmt(wr * wc, 2), x, y, { size: 9.5, align: "center", color: COLORS.point });
        }),
      );
    }
  }
  // the four pixels of the bilinear interpolation
  const bc = d.bl.c - d.fc;
  const br = d.bl.r - d.fr;
  if (Number.isFinite(bc) && Number.isFinite(br)) outline(ctx, g, bc, br, 2, 2, { fill: "rgba(217, 119, 6, 0.16)", width: 2 });
  // the nearest pixel
  if (Number.isFinite(res.nearest_c)) outline(ctx, g, res.nearest_c - d.fc, res.nearest_r - d.fr, 1, 1, { color: COLORS.pixelSystem, width: 2.5, dash: [3, 3] });
  const [px, py] = at(L, d, d.c, d.r);
  // weights: lines from the position to the four pixel centres
  const w = Array.isArray(d.bl.w) ? d.bl.w : [];
  const corners = [
    [d.bl.c, d.bl.r],
    [d.bl.c + 1, d.bl.r],
    [d.bl.c, d.bl.r + 1],
    [d.bl.c + 1, d.bl.r + 1],
  ];
  corners.forEach(([c, r], i) => {
    const [x, y] = at(L, d, c, r);
    line(ctx, px, py, x, y, { color: COLORS.highlight, width: 1 + 3 * (w[i] ?? 0) });
    if (L.cell >= 44) {
      text(ctx, `w=${fmt(w[i], 3)}`, x + (i % 2 ? 4 : -4), y + L.cell * 0.22, {
        size: 10,
        align: i % 2 ? "left" : "right",
        color: COLORS.highlight,
        halo: true,
        weight: "bold",
      });
    }
  });
  // I1 and I2 on the two rows, the final value between them
  const [ix, iy1] = at(L, d, d.c, d.bl.r);
  const [, iy2] = at(L, d, d.c, d.bl.r + 1);
  line(ctx, ix, iy1, ix, iy2, { color: COLORS.imageSystem, width: 1.5, dash: [4, 3] });
  for (const [y, name] of [
    [iy1, "I₁"],
    [iy2, "I₂"],
  ]) {
    ctx.save();
    ctx.fillStyle = COLORS.imageSystem;
    ctx.beginPath();
    ctx.moveTo(ix, y - R.marker);
    ctx.lineTo(ix + R.marker, y);
    ctx.lineTo(ix, y + R.marker);
    ctx.lineTo(ix - R.marker, y);
    ctx.closePath();
    ctx.fill();
    ctx.restore();
    text(ctx, name, ix + R.marker + 3, y + (name === "I₁" ? -8 : 8), { size: FONT_SIZE_SMALL, color: COLORS.imageSystem, weight: "bold", halo: true });
  }
  dot(ctx, px, py, R.dot, COLORS.highlight);
  dot(ctx, px, py, 2.5, COLORS.background);
  textBlock(ctx, L.lines, L.boxX, L.boxY, { size: FONT_SIZE_SMALL });
  // a small key to the marks
  const ky = L.height - R.key / 2 - 2;
  text(ctx, "orange: the 2×2 of bilinear · blue dashed: nearest · purple dashed: the 4×4 of bicubic", GRID.margin, ky, { size: 10, color: COLORS.muted });
}

const spec = {
  caption:
    "The patch at its image columns and rows (grey values above the pixel centres), the position (orange dot), the nearest pixel (blue dashed), the four pixels of the bilinear interpolation with their weights w (line width), I₁ and I₂ on the two rows, and the sixteen pixels of the cubic convolution when the patch holds them (purple dashed, each pixel's weight f(t)·f(s) at the bottom of its cell; some are negative).",
  height(width, solution) {
    const d = data(solution);
    return d ? layout(width, d).height : 120;
  },
  describe(solution) {
    const d = data(solution);
    if (!d) return "The patch and the position.";
    const { res } = d;
    return `A ${d.patch.length}×${d.patch[0].length} patch; position c = ${fmt(d.c, 7)}, r = ${fmt(d.r, 7)}. Nearest pixel (${fmt(res.nearest_c)}, ${fmt(res.nearest_r)}) = ${fmt(res.nearest)}; I1 = ${fmt(res.i1, 6)}, I2 = ${fmt(res.i2, 6)}, bilinear ${fmt(res.bilinear, 6)}; bicubic ${res.bicubic == null ? "not available" : fmt(res.bicubic, 6)}.`;
  },
  draw(ctx, width, height, solution) {
    const d = data(solution);
    if (d) draw(ctx, width, d);
  },
  interact: {
    hint: "Drag the position over the patch (or click); with the figure focused, the arrow keys move it by 0.05 pixel.",
    drag: true,
    pointer(x, y, width, height, solution) {
      const d = data(solution);
      if (!d) return null;
      const L = layout(width, d);
      const clamp = (v, lo, hi) => Math.min(Math.max(v, lo), hi);
      const c = clamp(d.fc + (x - L.x0) / L.cell - 0.5, d.fc, d.fc + L.cols - 1);
      const r = clamp(d.fr + (y - L.y0) / L.cell - 0.5, d.fr, d.fr + L.rows - 1);
      return { c: c.toFixed(2), r: r.toFixed(2) };
    },
    key(key, solution) {
      const d = data(solution);
      if (!d) return null;
      const moves = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] };
      if (!Object.hasOwn(moves, key)) return null;
      const [dc, dr] = moves[key];
      const cols = d.patch[0].length;
      const rows = d.patch.length;
      const c = Math.min(Math.max(d.c + dc * R.keyStep, d.fc), d.fc + cols - 1);
      const r = Math.min(Math.max(d.r + dr * R.keyStep, d.fr), d.fr + rows - 1);
      return { c: String(Math.round(c * 100) / 100), r: String(Math.round(r * 100) / 100) };
    },
  },
};

// Preset buttons: the seed's two patches with their positions (the help text lists them too).
const grid = (rows) => rows.map((r) => r.join(" ")).join("\n");
spec.actions = [
  {
    label: "Example 12a",
    inputs: () => ({ patch: grid([[68, 64, 72, 79], [64, 71, 78, 74], [61, 65, 71, 78], [63, 56, 62, 68]]), first_c: "545", first_r: "817", c: "547.44", r: "817.24" }),
  },
  {
    label: "Example 12b",
    inputs: () => ({ patch: grid([[58, 54, 66, 64], [54, 62, 67, 59], [52, 57, 60, 54], [53, 46, 52, 48]]), first_c: "523", first_r: "835", c: "523.72", r: "835.24" }),
  },
];

export const figures = {
  resample: spec,
};
