// Figure of the "Resampling" topic (seed 000, Example 12; seed 004):
//   resample: the patch as a grid of numbers at its image columns and rows,
//     the fractional position (draggable), the nearest pixel, the four pixels
//     of the bilinear interpolation with their weights, I1 and I2 on the two
//     rows, and the sixteen pixels of the cubic convolution when they exist.

import { isMatrix, stepValue } from "../values.js";
import { matrixTable, seriesTable } from "./data-view.js";
import { COLORS, FONT_SIZE_SMALL, GRID, LINE_HEIGHT, Labels, arrowStep, dot, drawGrid, fmt, layoutSpec, line, outline, text, textBlock, textWidth } from "./draw.js";

const R = Object.freeze({
  maxCell: 84,
  minCell: 22,
  dot: 6,
  marker: 5,
  keyStep: 0.05, // px moved per arrow key press
  besideFrom: 64, // the value box goes beside the grid only if the cells stay this large
  valueDy: -0.24, // grey values sit above the pixel centre, which gets a dot
  keySize: 10, // the key's text size
  keyLine: 14, // and line height
  cRoom: 26, // room right of the grid for "c →"
});

/** The key to the marks, in as many lines as the width needs. */
const KEY = ["orange: the 2×2 of bilinear with their weights w", "blue dashed: nearest", "purple dashed: the 4×4 of bicubic"];
function keyLines(width) {
  const avail = width - 2 * GRID.margin;
  const out = [];
  for (const part of KEY) {
    const last = out.length ? out[out.length - 1] : null;
    if (last !== null && textWidth(`${last} · ${part}`, R.keySize) <= avail) out[out.length - 1] = `${last} · ${part}`;
    else out.push(part);
  }
  return out;
}

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
    bc: { c: stepValue(solution, "bicubic_c"), r: stepValue(solution, "bicubic_r"), wc: stepValue(solution, "weights_c"), wr: stepValue(solution, "weights_r"), s: stepValue(solution, "s"), t: stepValue(solution, "t"), rows: stepValue(solution, "row_values") },
    x: stepValue(solution, "x"),
    y: stepValue(solution, "y"),
    corners: stepValue(solution, "corners"),
  };
}

/** Whether the cubic convolution was possible here (its 4×4 and row values are in the solution). */
const cubic = (d) => Number.isFinite(d.bc.c) && d.res.bicubic !== null && d.res.bicubic !== undefined && Array.isArray(d.bc.rows);

/**
 * The stages of the interpolation, in the solution's order (the motion's
 * frames; the value box's lines are reached stage by stage): the position,
 * the nearest pixel, the four pixels of bilinear with their weights, the
 * upper row, the lower row, between the rows; then, where the 4×4 exists,
 * the cubic weights, its four rows one by one and the column.
 */
const STAGE = Object.freeze({ position: 0, nearest: 1, four: 2, upper: 3, lower: 4, between: 5, cubicWeights: 6, row: 7, column: 11 });

/** The value box's lines; in a frame (`stage`), a line not reached yet keeps its place, muted, with "…". */
function valueLines(d, stage = null) {
  const { res } = d;
  const lines = [
    [STAGE.position, { text: `Position (c, r) = (${fmt(d.c, 7)}, ${fmt(d.r, 7)})`, weight: "bold" }, "Position (c, r)"],
    [STAGE.nearest, { text: `Nearest pixel (${fmt(res.nearest_c)}, ${fmt(res.nearest_r)}): ${fmt(res.nearest)}`, color: COLORS.pixelSystem }, "Nearest pixel"],
    [STAGE.four, { text: `dc = ${fmt(res.dc)}, dr = ${fmt(res.dr)}` }, "dc, dr"],
    [STAGE.upper, { text: `I₁ (row ${fmt(d.bl.r)}) = ${fmt(res.i1, 6)}`, color: COLORS.imageSystem }, "I₁"],
    [STAGE.lower, { text: `I₂ (row ${fmt((d.bl.r ?? 0) + 1)}) = ${fmt(res.i2, 6)}`, color: COLORS.imageSystem }, "I₂"],
    [STAGE.between, { text: `Bilinear I = ${fmt(res.bilinear, 6)} ≈ ${fmt(res.bilinear_rounded)}`, weight: "bold", color: COLORS.highlight }, "Bilinear I"],
  ];
  if (cubic(d)) {
    // the rows of the 4×4 weighted along the columns: reached one by one
    const reached = stage === null ? 4 : Math.max(0, Math.min(4, stage - STAGE.row + 1));
    const rows = d.bc.rows.map((v, j) => (j < reached ? fmt(v, 6) : "…")).join(", ");
    lines.push([STAGE.row, { text: `Rows P·w_c = ${rows}`, color: COLORS.point }, "Rows P·w_c"]);
    lines.push([STAGE.column, { text: `Bicubic (4×4) = ${fmt(res.bicubic, 6)}`, weight: "bold", color: COLORS.point }, "Bicubic (4×4)"]);
  } else lines.push([STAGE.column, { text: "Bicubic: no 4×4 neighbourhood here", color: COLORS.muted }, "Bicubic"]);
  return lines.map(([at, line, name]) => (stage === null || at <= stage ? line : { text: `${name} …`, color: COLORS.muted }));
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
  const x0 = m + GRID.axis + 8;
  // the grid, then the value box beside it (if the cells stay large) or "c →"
  const beside = width - x0 - m - box.w - GRID.gap >= cols * R.besideFrom;
  const availW = width - x0 - m - (beside ? box.w + GRID.gap : R.cRoom);
  const cell = Math.max(R.minCell, Math.min(R.maxCell, Math.floor(availW / cols)));
  const y0 = m + GRID.axis + 4;
  const gridH = rows * cell;
  const boxX = beside ? x0 + cols * cell + GRID.gap : m;
  const boxY = beside ? y0 : y0 + gridH + GRID.gap;
  const key = keyLines(width);
  const keyTop = Math.max(y0 + gridH, boxY + box.h) + m;
  const height = keyTop + key.length * R.keyLine + 4;
  return { cell, x0, y0, cols, rows, lines, boxX, boxY, key, keyTop, height };
}

/** Canvas position of image pixel position (c, r). */
const at = (L, d, c, r) => [L.x0 + (c - d.fc + 0.5) * L.cell, L.y0 + (r - d.fr + 0.5) * L.cell];

/** The four sides of a rectangle, as label obstacles. */
function avoidFrame(labels, g, c, r, w, h, halfWidth) {
  const x = g.x0 + c * g.cell;
  const y = g.y0 + r * g.cell;
  const X = x + w * g.cell;
  const Y = y + h * g.cell;
  labels.avoidPath(
    [
      [x, y],
      [X, y],
      [X, Y],
      [x, Y],
    ],
    halfWidth,
    true,
  );
}

function draw(ctx, width, d, frame = null) {
  const L = layout(width, d);
  // a frame of the motion shows the marks of its stage (the position always); without one, every mark
  const stage = frame ? frame.stage : null;
  const upTo = (k) => stage === null || stage >= k;
  const only = (from, to) => stage === null || (stage >= from && stage <= to);
  const labels = new Labels(ctx, width, L.height);
  const shade = { fill: () => "rgba(87, 96, 106, 0.06)" };
  const g = drawGrid(ctx, d.patch, L.x0, L.y0, L.cell, { first: { c: d.fc, r: d.fr }, shade, valueDy: L.cell >= 40 ? R.valueDy : 0 });
  g.texts.forEach((b) => labels.avoid(b));
  labels.avoid(text(ctx, "c →", L.x0 + g.w + 4, L.y0 - GRID.axis / 2, { size: 10, color: COLORS.muted }));
  labels.avoid(text(ctx, "r ↓", L.x0 - 4, L.y0 - GRID.axis / 2, { size: 10, color: COLORS.muted, align: "right" }));
  if (L.cell >= 40) {
    for (let r = 0; r < L.rows; r++) {
      for (let c = 0; c < L.cols; c++) {
        dot(ctx, L.x0 + (c + 0.5) * L.cell, L.y0 + (r + 0.5) * L.cell, 2, COLORS.muted);
        labels.avoidDot(L.x0 + (c + 0.5) * L.cell, L.y0 + (r + 0.5) * L.cell, 2);
      }
    }
  }
  const { res } = d;
  // the sixteen pixels of the cubic convolution
  if (Number.isFinite(d.bc.c) && res.bicubic !== null && upTo(STAGE.cubicWeights)) {
    // a row's frame: that row of the 4×4, the rows before it done
    if (stage !== null && stage >= STAGE.row && stage < STAGE.column) {
      const j = stage - STAGE.row;
      outline(ctx, g, d.bc.c - d.fc, d.bc.r - d.fr + j, 4, 1, { fill: COLORS.highlightFill, color: COLORS.point, width: 2.5 });
    }
    outline(ctx, g, d.bc.c - d.fc, d.bc.r - d.fr, 4, 4, { color: COLORS.point, width: stage === STAGE.column ? 3 : 2, dash: stage === STAGE.column ? null : [6, 4] });
    avoidFrame(labels, g, d.bc.c - d.fc, d.bc.r - d.fr, 4, 4, 1);
    // each pixel's cubic weight f(row) · f(column), at the bottom of its cell
    if (Array.isArray(d.bc.wc) && Array.isArray(d.bc.wr) && L.cell >= 44) {
      d.bc.wr.forEach((wr, j) =>
        d.bc.wc.forEach((wc, i) => {
          const x = L.x0 + (d.bc.c - d.fc + i + 0.5) * L.cell;
          const y = L.y0 + (d.bc.r - d.fr + j + 1) * L.cell - 7;
          labels.avoid(text(ctx, fmt(wr * wc, 2), x, y, { size: 9.5, align: "center", color: COLORS.point }));
        }),
      );
    }
  }
  // the four pixels of the bilinear interpolation
  const bc = d.bl.c - d.fc;
  const br = d.bl.r - d.fr;
  if (Number.isFinite(bc) && Number.isFinite(br) && only(STAGE.four, STAGE.between)) {
    outline(ctx, g, bc, br, 2, 2, { fill: "rgba(217, 119, 6, 0.16)", width: 2 });
    avoidFrame(labels, g, bc, br, 2, 2, 1);
    // a row's frame of bilinear: its two pixels
    if (stage === STAGE.upper || stage === STAGE.lower) outline(ctx, g, bc, br + (stage === STAGE.lower ? 1 : 0), 2, 1, { color: COLORS.imageSystem, width: 3 });
  }
  // the nearest pixel
  if (Number.isFinite(res.nearest_c) && only(STAGE.nearest, STAGE.between)) {
    outline(ctx, g, res.nearest_c - d.fc, res.nearest_r - d.fr, 1, 1, { color: COLORS.pixelSystem, width: 2.5, dash: [3, 3] });
    avoidFrame(labels, g, res.nearest_c - d.fc, res.nearest_r - d.fr, 1, 1, 1.5);
  }
  const [px, py] = at(L, d, d.c, d.r);
  // weights: lines from the position to the four pixel centres, each labelled
  // beside its pixel's centre (outwards from the position first)
  const w = Array.isArray(d.bl.w) ? d.bl.w : [];
  // below the centre, lower down (clear of a weight line), then outwards
  const below = [0, 0.12, 0.22, 0.3].map((f) => ({ at: "S", dy: f * L.cell }));
  const corners = [
    [d.bl.c, d.bl.r, [...below, "W", "SW", "NW", "SE"]],
    [d.bl.c + 1, d.bl.r, [...below, "E", "SE", "NE", "SW"]],
    [d.bl.c, d.bl.r + 1, [...below, "W", "SW", "NW", "SE"]],
    [d.bl.c + 1, d.bl.r + 1, [...below, "E", "SE", "NE", "SW"]],
  ];
  const weightLabels = [];
  corners.forEach(([c, r, spots], i) => {
    if (!only(STAGE.four, STAGE.between)) return;
    const [x, y] = at(L, d, c, r);
    const lw = 1 + 3 * (w[i] ?? 0);
    line(ctx, px, py, x, y, { color: COLORS.highlight, width: lw });
    labels.avoidLine(px, py, x, y, lw / 2 + 1);
    if (L.cell >= 44) weightLabels.push([`w=${fmt(w[i], 3)}`, x, y, spots, fmt(w[i], 3)]);
  });
  // I1 and I2 on the two rows, the final value between them
  const [ix, iy1] = at(L, d, d.c, d.bl.r);
  const [, iy2] = at(L, d, d.c, d.bl.r + 1);
  // I₁ from the upper row's frame, I₂ from the lower's, the line between them at "between"
  const marks = [iy1, iy2].filter((_, i) => only(STAGE.upper + i, STAGE.between));
  if (only(STAGE.between, STAGE.between)) {
    line(ctx, ix, iy1, ix, iy2, { color: COLORS.imageSystem, width: 1.5, dash: [4, 3] });
    labels.avoidLine(ix, iy1, ix, iy2, 1);
  }
  for (const y of marks) {
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
    labels.avoidDot(ix, y, R.marker);
  }
  dot(ctx, px, py, R.dot, COLORS.highlight);
  dot(ctx, px, py, 2.5, COLORS.background);
  labels.avoidDot(px, py, R.dot, 2);
  labels.avoid(textBlock(ctx, stage === null ? L.lines : valueLines(d, stage), L.boxX, L.boxY, { size: FONT_SIZE_SMALL }));
  // a small key to the marks
  L.key.forEach((k, i) => labels.avoid(text(ctx, k, GRID.margin, L.keyTop + (i + 0.5) * R.keyLine, { size: R.keySize, color: COLORS.muted })));
  const iStyle = { size: FONT_SIZE_SMALL, color: COLORS.imageSystem, weight: "bold", gap: R.marker + 2 };
  const withLabels = (short) => {
    const all = labels.copy();
    for (const [str, x, y, spots, number] of weightLabels) all.add(short ? number : str, x, y, { size: 10, weight: "bold", color: COLORS.highlight, gap: 3, pad: 1.5, candidates: spots, farther: R.dot + 3, shorter: short ? [{ text: number, size: 9 }] : [] });
    if (marks.includes(iy1)) all.add("I₁", ix, iy1, { ...iStyle, candidates: ["NE", "NW", "E", "W", "N", "SE", "SW"], farther: R.dot + 3 });
    if (marks.includes(iy2)) all.add("I₂", ix, iy2, { ...iStyle, candidates: ["SE", "SW", "E", "W", "S", "NE", "NW"], farther: R.dot + 3 });
    return all;
  };
  // the weights as "w=0.426" where they all fit, else all as plain numbers
  const full = withLabels(false);
  if (full.place().every((p) => p.hits === 0)) full.draw();
  else withLabels(true).draw();
}

/** The Data view (index.js tables()): the patch with the pixels the methods use named in its cells, the values box. */
function tables(solution) {
  const d = data(solution);
  if (!d) return { summary: "The patch and the position.", tables: [] };
  const { res } = d;
  const w = Array.isArray(d.bl.w) ? d.bl.w : [];
  const corners = [[d.bl.c, d.bl.r], [d.bl.c + 1, d.bl.r], [d.bl.c, d.bl.r + 1], [d.bl.c + 1, d.bl.r + 1]];
  const hasCubic = Number.isFinite(d.bc.c) && res.bicubic !== null && res.bicubic !== undefined;
  const mark = (j, i) => {
    const c = d.fc + i;
    const r = d.fr + j;
    const words = [];
    if (c === res.nearest_c && r === res.nearest_r) words.push("nearest");
    corners.forEach(([cc, rr], k) => {
      if (cc === c && rr === r) words.push(`bilinear, w = ${fmt(w[k], 3)}`);
    });
    if (hasCubic && c >= d.bc.c && c < d.bc.c + 4 && r >= d.bc.r && r < d.bc.r + 4) words.push("in the 4×4 of bicubic");
    return words.join(", ");
  };
  return {
    summary: `The position c = ${fmt(d.c, 7)}, r = ${fmt(d.r, 7)} lies between columns ${fmt(d.bl.c)}–${fmt(d.bl.c + 1)} and rows ${fmt(d.bl.r)}–${fmt(d.bl.r + 1)} of the ${d.patch.length}×${d.patch[0].length} patch. Nearest pixel (${fmt(res.nearest_c)}, ${fmt(res.nearest_r)}) = ${fmt(res.nearest)}; bilinear: I₁ = ${fmt(res.i1, 6)}, I₂ = ${fmt(res.i2, 6)}, I = ${fmt(res.bilinear, 6)}; bicubic ${hasCubic ? fmt(res.bicubic, 6) : "not available here"}.`,
    tables: [
      matrixTable("The patch (grey values at image columns and rows)", d.patch, { format: (v) => fmt(v, 6, "no value"), first: { c: d.fc, r: d.fr }, mark }),
      seriesTable("The values (the box beside the patch)", ["value"], valueLines(d).map((l) => [l.text])),
    ],
  };
}

const spec = layoutSpec({
  tables,
  caption:
    "The patch at its image columns and rows (grey values above the pixel centres), the position (orange dot), the nearest pixel (blue dashed), the four pixels of the bilinear interpolation with their weights w (line width), I₁ and I₂ on the two rows, and the sixteen pixels of the cubic convolution when the patch holds them (purple dashed, each pixel's weight f(t)·f(s) at the bottom of its cell; some are negative).",
  data,
  layout,
  draw,
  describe(solution) {
    const d = data(solution);
    if (!d) return "The patch and the position.";
    const { res } = d;
    return `A ${d.patch.length}×${d.patch[0].length} patch; position c = ${fmt(d.c, 7)}, r = ${fmt(d.r, 7)}. Nearest pixel (${fmt(res.nearest_c)}, ${fmt(res.nearest_r)}) = ${fmt(res.nearest)}; I1 = ${fmt(res.i1, 6)}, I2 = ${fmt(res.i2, 6)}, bilinear ${fmt(res.bilinear, 6)}; bicubic ${res.bicubic == null ? "not available" : fmt(res.bicubic, 6)}.`;
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
      const step = arrowStep(key);
      if (!step) return null;
      const [dc, dr] = step;
      const cols = d.patch[0].length;
      const rows = d.patch.length;
      const c = Math.min(Math.max(d.c + dc * R.keyStep, d.fc), d.fc + cols - 1);
      const r = Math.min(Math.max(d.r + dr * R.keyStep, d.fr), d.fr + rows - 1);
      return { c: String(Math.round(c * 100) / 100), r: String(Math.round(r * 100) / 100) };
    },
  },
});

// motion (issue 34, "resampling: the neighbourhood and weights as the point
// moves"): the solution holds one position, so its frames are the stages of
// the interpolation at it (STAGE): the nearest pixel, bilinear's four pixels
// and weights, the upper row, the lower row, between them; then the 4×4 of
// the cubic convolution, its rows one by one and the column. Every number is
// the solution's (its steps' values); the substitutions are written out.
const withFrame = spec.draw;
spec.draw = (ctx, width, height, solution, state) => {
  const d = state?.frame ? data(solution) : null;
  if (d) draw(ctx, width, d, state.frame);
  else withFrame(ctx, width, height, solution);
};
spec.motion = { noun: "stage" };
spec.frames = (solution) => {
  const d = data(solution);
  if (!d) return [];
  const steps = solution.steps ?? [];
  const stepOf = (key) => {
    const i = steps.findIndex((x) => x.values && Object.hasOwn(x.values, key));
    return i >= 0 ? i : null;
  };
  const { res, bl, bc } = d;
  const k = Array.isArray(d.corners) ? d.corners : [];
  const w = Array.isArray(bl.w) ? bl.w : [];
  const list = [
    { stage: STAGE.position, step: stepOf("x"), caption: `Position (c, r) = (${fmt(d.c, 7)}, ${fmt(d.r, 7)}): in the patch x = c − ${fmt(d.fc)} = ${fmt(d.x)}, y = r − ${fmt(d.fr)} = ${fmt(d.y)}.` },
    { stage: STAGE.nearest, step: stepOf("nearest"), caption: `Nearest neighbour: pixel (${fmt(res.nearest_c)}, ${fmt(res.nearest_r)}) = ${fmt(res.nearest)}.` },
    {
      stage: STAGE.four,
      step: stepOf("corners"),
      caption: `Bilinear: the four pixels of columns ${fmt(bl.c)}–${fmt(bl.c + 1)}, rows ${fmt(bl.r)}–${fmt(bl.r + 1)}: ${k.map((v) => fmt(v)).join(", ")}; dc = ${fmt(res.dc)}, dr = ${fmt(res.dr)}; their weights (1 − dc)(1 − dr), dc(1 − dr), (1 − dc)dr, dc·dr = ${w.map((v) => fmt(v)).join(", ")}.`,
    },
    { stage: STAGE.upper, step: stepOf("i1"), caption: `Along the upper row ${fmt(bl.r)}: I₁ = (1 − dc)·${fmt(k[0])} + dc·${fmt(k[1])} = ${fmt(res.i1, 6)}.` },
    { stage: STAGE.lower, step: stepOf("i2"), caption: `Along the lower row ${fmt(bl.r + 1)}: I₂ = (1 − dc)·${fmt(k[2])} + dc·${fmt(k[3])} = ${fmt(res.i2, 6)}.` },
    { stage: STAGE.between, step: stepOf("bilinear"), caption: `Between the rows: I = (1 − dr)·I₁ + dr·I₂ = ${fmt(res.bilinear, 6)} ≈ ${fmt(res.bilinear_rounded)}.` },
  ];
  if (!cubic(d)) return list;
  const P = stepValue(solution, "neighbourhood");
  const vec = (v) => `[${(Array.isArray(v) ? v : []).map((x) => fmt(x)).join(", ")}]`;
  list.push({
    stage: STAGE.cubicWeights,
    step: stepOf("weights_c"),
    caption: `Bicubic: the 4×4 from column ${fmt(bc.c)}, row ${fmt(bc.r)}; s = ${fmt(bc.s)}, t = ${fmt(bc.t)}; the weights along the columns w_c = ${vec(bc.wc)}, along the rows w_r = ${vec(bc.wr)}.`,
  });
  bc.rows.forEach((v, j) =>
    list.push({ stage: STAGE.row + j, step: stepOf("row_values"), caption: `Bicubic, row ${fmt(bc.r + j)}: ${vec(isMatrix(P) ? P[j] : [])} · w_c = ${fmt(v, 6)}.` }),
  );
  list.push({ stage: STAGE.column, step: stepOf("bicubic"), caption: `Bicubic, the column: w_r · [${bc.rows.map((v) => fmt(v, 6)).join(", ")}] = ${fmt(res.bicubic, 6)}.` });
  return list;
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
