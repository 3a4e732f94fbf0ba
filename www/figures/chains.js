// Figures of the "Chain codes and boundaries" topic (seed 000, Examples
// 17–18, the exercise, the boundary descriptors): one drawing grid for
// chain-code, boundary-length and boundary-shape.
//
// The grid shows the pixels (c to the right, r downward), the coded path with
// an arrow and its code digit on every step, the start and end, where the
// path breaks or branches, and for a closed boundary the major axis, the
// minor axis and the basic rectangle. Below it: the code, the differential
// code, the length and the descriptors, as the core computed them.
//
// Interaction (the interact/actions hooks of index.js): with pixels given in
// order a click appends the pixel (a click on the last pixel takes it back, a
// click on the first closes the boundary; on the focused grid a code digit or
// an arrow key adds a step, Backspace takes one back); with regions a click
// toggles the pixel. Preset buttons load the seed's edges and a circle, a rectangle and
// an L-shape.

import { stepValue } from "../values.js";
import { COLORS, DASH, FONT_SIZE, FONT_SIZE_SMALL, LINE_HEIGHT, Labels, arrow, arrowStep, dot, finite, fmt, line, text, textWidth } from "./draw.js";

/** Layout (CSS px) and the smallest grid shown (cells). */
const LAYOUT = Object.freeze({ margin: 12, axis: 24, maxCell: 44, minCols: 13, minRows: 9, infoGap: 10, labelMinCell: 15, axisLabelMinPx: 18 });
/** Digits of numbers in the figure. */
const DIGITS = 5;
/** Colours beyond the shared palette, read from the palette in use when drawn (contrast ≥ 4.5:1 for text). */
const INK = Object.freeze({
  get path() {
    return COLORS.pixelSystem;
  },
  pathFill: "rgba(29, 95, 191, 0.16)",
  get region() {
    return COLORS.theme === "dark" ? "#2b3440" : "#e1e6ec";
  },
  otherRegion: "#8c959f",
  get broken() {
    return COLORS.red;
  },
  get start() {
    return COLORS.green;
  },
  get major() {
    return COLORS.highlight;
  },
  get minor() {
    return COLORS.point;
  },
  get rectangle() {
    return COLORS.imageSystem;
  },
});

/** The seed's edges and the preset shapes, as input data. */
const EX17 = [[1, 4], [2, 4], [3, 5], [4, 6], [5, 7], [5, 8], [6, 8], [7, 8], [8, 7], [8, 6], [7, 5], [6, 4], [7, 3], [8, 3], [9, 3], [10, 2], [11, 1]];
const EX18B = [[1, 1], [2, 1], [3, 2], [4, 3], [5, 4], [5, 5], [5, 6], [6, 7], [7, 7], [8, 6], [9, 5], [9, 4], [9, 3], [10, 2], [11, 1], [12, 1], [13, 2], [14, 2]];
const EX18A_CODE = "1 1 4 4 1 1 1 2 2 1 1 1 4 4 4 1 1 2 2 2 1 1 4";
const FIG_C_CODE = "441121141122233";

function filled(test, cols = LAYOUT.minCols, rows = LAYOUT.minRows) {
  const out = [];
  for (let r = 0; r < rows; r++) for (let c = 0; c < cols; c++) if (test(c, r)) out.push([c, r]);
  return out;
}
const SHAPES = Object.freeze({
  circle: () => filled((c, r) => (c - 7) ** 2 + (r - 4.5) ** 2 <= 4.2 ** 2),
  rectangle: () => filled((c, r) => c >= 3 && c <= 12 && r >= 2 && r <= 7),
  lShape: () => filled((c, r) => (c >= 3 && c <= 5 && r >= 1 && r <= 8) || (c >= 3 && c <= 11 && r >= 6 && r <= 8)),
});

const isPixel = (p) => Array.isArray(p) && p.length >= 2 && Number.isFinite(p[0]) && Number.isFinite(p[1]);
const pixelList = (v) => (Array.isArray(v) ? v.filter(isPixel) : []);
const pixelsText = (ps) => ps.map((p) => `${p[0]} ${p[1]}`).join("\n");
const same = (a, b) => a && b && a[0] === b[0] && a[1] === b[1];
const digits = (v) => (Array.isArray(v) ? v.join(" ") : "—");


/** How the edge was given: "pixels", "code" or "region" (boundary-shape: always region). */
function modeOf(solution) {
  const g = solution.inputs?.given;
  return g === "code" || g === "pixels" ? g : "region";
}

/** What the figure draws, read from the solution. */
function model(solution) {
  const res = solution.result ?? {};
  const mode = modeOf(solution);
  const path = pixelList(res.boundary ?? res.pixels);
  const raw = pixelList(solution.inputs?.pixels);
  const regions = Array.isArray(stepValue(solution, "boundaries")) ? stepValue(solution, "boundaries").map(pixelList) : [];
  return {
    mode,
    path,
    raw,
    regions,
    closed: res.closed === true,
    code: Array.isArray(res.code) ? res.code : null,
    breaks: Array.isArray(res.breaks) ? res.breaks : [],
    branches: Array.isArray(res.branches) ? res.branches : [],
    res,
    four: solution.inputs?.connectivity === "4",
  };
}

/** The grid's extent in pixels: everything drawn, one spare cell around, at least the minimum grid. */
function extent(m) {
  const all = [...m.path, ...(m.mode === "code" ? [] : m.raw)];
  for (const b of m.breaks) if (b.length >= 5) all.push([b[1], b[2]], [b[3], b[4]]);
  // the basic rectangle may reach beyond the pixels
  for (const q of pixelList(m.res.basic_rectangle)) all.push([Math.floor(q[0]), Math.floor(q[1])], [Math.ceil(q[0]), Math.ceil(q[1])]);
  let c0 = 0;
  let r0 = 0;
  let c1 = LAYOUT.minCols - 1;
  let r1 = LAYOUT.minRows - 1;
  for (const [c, r] of all) {
    c0 = Math.min(c0, c - 1);
    r0 = Math.min(r0, r - 1);
    c1 = Math.max(c1, c + 1);
    r1 = Math.max(r1, r + 1);
  }
  if (c0 < 0 && all.every((p) => p[0] >= 0)) c0 = 0;
  if (r0 < 0 && all.every((p) => p[1] >= 0)) r0 = 0;
  return { c0, r0, cols: c1 - c0 + 1, rows: r1 - r0 + 1 };
}

/** Where the grid sits for a canvas width. */
function layout(width, m) {
  const e = extent(m);
  const avail = width - 2 * LAYOUT.margin - LAYOUT.axis;
  const cell = Math.max(2, Math.min(LAYOUT.maxCell, avail / e.cols));
  const left = LAYOUT.margin + LAYOUT.axis + Math.max(0, (avail - cell * e.cols) / 2);
  const top = LAYOUT.margin + LAYOUT.axis;
  return { ...e, cell, left, top, gridBottom: top + cell * e.rows };
}

const centre = (L, p) => [L.left + (p[0] - L.c0 + 0.5) * L.cell, L.top + (p[1] - L.r0 + 0.5) * L.cell];

/** The lines of text under the grid. */
function infoLines(solution, m) {
  const res = m.res;
  const lines = [];
  const what = m.mode === "region" ? `Traced outer boundary (${m.path.length} positions, clockwise from the top-most, left-most pixel)` : `${m.closed ? "Closed boundary" : "Open edge"} of ${m.path.length} pixel${m.path.length === 1 ? "" : "s"}`;
  lines.push({ text: what, weight: "bold" });
  if (m.code) {
    lines.push({ text: `Chain code: ${m.code.length ? digits(m.code) : "(empty)"}`, color: INK.path });
    if (Array.isArray(res.differential)) lines.push({ text: `Differential code: ${res.differential.length ? digits(res.differential) : "(empty)"}` });
  } else {
    lines.push({ text: "No chain code: the path breaks (red).", color: INK.broken, weight: "bold" });
  }
  if (typeof res.length === "number") {
    const counts = typeof res.horizontal === "number" ? ` (n_h = ${res.horizontal}, n_v = ${res.vertical}, n_d = ${res.diagonal})` : "";
    lines.push({ text: `Length L = ${fmt(res.length, DIGITS)} px${counts}` });
  }
  if (typeof res.diameter === "number") {
    lines.push({ text: `Diameter D = ${fmt(res.diameter, DIGITS)} px (major axis, orange)   minor axis m = ${fmt(res.minor_axis_length, DIGITS)} px (purple)`, color: COLORS.ink });
    lines.push({ text: `Eccentricity E = D / m = ${res.eccentricity == null ? "no value (m = 0)" : fmt(res.eccentricity, DIGITS)}   basic rectangle: dashed`, color: COLORS.ink });
  }
  for (const b of m.breaks.slice(0, 3)) {
    if (b.length >= 5) lines.push({ text: `Break: pixel ${b[0]} (${b[1]}, ${b[2]}) → pixel ${b[0] + 1} (${b[3]}, ${b[4]}) are not neighbours${m.four ? " (4-connectivity)" : ""}`, color: INK.broken });
  }
  for (const b of m.branches.slice(0, 3)) {
    if (b.length >= 4) lines.push({ text: `Branch: pixel ${b[0]} (${b[2]}, ${b[3]}) is pixel ${b[1]} again`, color: INK.broken });
  }
  if (m.regions.length > 1) lines.push({ text: `${m.regions.length} regions: the first is coded; the others' boundaries are grey.`, color: COLORS.muted });
  lines.push({ text: hint(m), color: COLORS.muted, size: FONT_SIZE_SMALL });
  return lines;
}

function hint(m) {
  if (m.mode === "region") return "Click a cell to add or remove a pixel of the region; its outer boundary is traced again.";
  if (m.mode === "code") return "Click a cell to turn the code into pixels and extend the path.";
  return "Click a cell to extend the path; click the last pixel to take it back, the first to close the boundary. Keyboard: a code digit (or an arrow key) adds a step, Backspace takes one back.";
}

/** Splits lines that are wider than `width` at spaces. */
function wrap(lines, width) {
  const out = [];
  for (const l of lines) {
    const size = l.size ?? FONT_SIZE;
    const words = l.text.split(" ");
    let cur = "";
    for (const w of words) {
      const next = cur ? `${cur} ${w}` : w;
      if (cur && textWidth(next, size, l.weight ?? "normal") > width) {
        out.push({ ...l, text: cur });
        cur = w;
      } else {
        cur = next;
      }
    }
    out.push({ ...l, text: cur });
  }
  return out;
}

/** The lines under the grid, wrapped to the part of the canvas seen without scrolling (`room`, a phone's panel). */
function infoBlock(width, solution, m, room = width) {
  return wrap(infoLines(solution, m), Math.min(width, room) - 2 * LAYOUT.margin);
}

/** The pixel lattice of the chain figures: cell lines and the column/row numbers (no values: drawGrid draws grids of numbers). */
function drawLattice(ctx, L) {
  const { left, top, cell, cols, rows } = L;
  ctx.save();
  for (let i = 0; i <= cols; i++) line(ctx, left + i * cell, top, left + i * cell, top + rows * cell, { color: COLORS.grid });
  for (let j = 0; j <= rows; j++) line(ctx, left, top + j * cell, left + cols * cell, top + j * cell, { color: COLORS.grid });
  ctx.restore();
  const every = Math.max(1, Math.ceil(LAYOUT.axisLabelMinPx / cell));
  for (let i = 0; i < cols; i++) {
    const c = L.c0 + i;
    if (c % every === 0) text(ctx, String(c), left + (i + 0.5) * cell, top - 8, { size: FONT_SIZE_SMALL, color: COLORS.muted, align: "center" });
  }
  for (let j = 0; j < rows; j++) {
    const r = L.r0 + j;
    if (r % every === 0) text(ctx, String(r), left - 6, top + (j + 0.5) * cell, { size: FONT_SIZE_SMALL, color: COLORS.muted, align: "right" });
  }
  text(ctx, "c →", left - 4, LAYOUT.margin - 4, { size: FONT_SIZE_SMALL, color: COLORS.pixelSystem, baseline: "top", weight: "bold", align: "right" });
  text(ctx, "r ↓", left - 4, LAYOUT.margin + 9, { size: FONT_SIZE_SMALL, color: COLORS.pixelSystem, baseline: "top", weight: "bold", align: "right" });
}

function fillCells(ctx, L, pixels, color) {
  ctx.save();
  ctx.fillStyle = color;
  for (const p of pixels) {
    ctx.fillRect(L.left + (p[0] - L.c0) * L.cell + 1, L.top + (p[1] - L.r0) * L.cell + 1, L.cell - 2, L.cell - 2);
  }
  ctx.restore();
}

/**
 * The steps of the path as arrows with their digits (placed by `labels`:
 * left of the travel direction, else right of it); out-and-back steps are
 * kept apart by a sideways offset.
 */
function drawSteps(ctx, L, m, labels, upto = Infinity) {
  const n = m.path.length;
  if (n < 2 || !m.code) return;
  const steps = Math.min(m.code.length, upto + 1);
  const off = 0.14 * L.cell;
  const showDigits = L.cell >= LAYOUT.labelMinCell;
  const head = Math.max(4, Math.min(10, L.cell * 0.28));
  const width = L.cell >= 20 ? 2.2 : 1.3;
  for (let k = 0; k < steps; k++) {
    const a = m.path[k];
    const b = m.path[(k + 1) % n];
    if (!a || !b) continue;
    const [x0, y0] = centre(L, a);
    const [x1, y1] = centre(L, b);
    const len = Math.hypot(x1 - x0, y1 - y0) || 1;
    // the left of the travel direction (on the screen: (dy, -dx))
    const nx = (y1 - y0) / len;
    const ny = -(x1 - x0) / len;
    const shrink = 0.1 * L.cell;
    const ux = (x1 - x0) / len;
    const uy = (y1 - y0) / len;
    const ax0 = x0 + ux * shrink + nx * off;
    const ay0 = y0 + uy * shrink + ny * off;
    const ax1 = x1 - ux * shrink + nx * off;
    const ay1 = y1 - uy * shrink + ny * off;
    arrow(ctx, ax0, ay0, ax1, ay1, { color: INK.path, width, size: head });
    labels.avoidArrow(ax0, ay0, ax1, ay1, { width, size: head, tag: `step ${k}` });
    if (showDigits) {
      const mx = (ax0 + ax1) / 2;
      const my = (ay0 + ay1) / 2;
      // far enough from the arrow for the digit's box to clear it
      const size = L.cell >= 26 ? FONT_SIZE : FONT_SIZE_SMALL;
      const half = [textWidth(String(m.code[k]), size, "bold") / 2 + 1, (size * LINE_HEIGHT + 1) / 2];
      const d = Math.max(0.24 * L.cell, Math.abs(nx) * half[0] + Math.abs(ny) * half[1] + width / 2 + 1);
      const along = 0.22 * L.cell;
      const spot = (t, s = 0) => ({ cx: mx + nx * t + ux * s, cy: my + ny * t + uy * s });
      labels.add(String(m.code[k]), mx, my, {
        size,
        weight: "bold",
        color: INK.path,
        pad: 1,
        ignore: `step ${k}`,
        // left of the arrow, right of it, a little along it either way, farther out
        candidates: [spot(d), spot(-d), spot(d, -along), spot(d, along), spot(-d, -along), spot(-d, along), spot(1.6 * d), spot(-1.6 * d), spot(0), spot(2.4 * d), spot(-2.4 * d)],
      });
    }
  }
}

/** An open path without code (it breaks): plain lines where consecutive pixels are neighbours. */
function drawBrokenPath(ctx, L, m) {
  const ps = m.raw;
  for (let k = 0; k + 1 < ps.length; k++) {
    const [x0, y0] = centre(L, ps[k]);
    const [x1, y1] = centre(L, ps[k + 1]);
    const gap = m.breaks.some((b) => b[0] === k + 1);
    if (!gap) line(ctx, x0, y0, x1, y1, { color: INK.path, width: 2 });
  }
}

function drawProblems(ctx, L, m, labels) {
  for (const b of m.breaks) {
    if (b.length < 5) continue;
    const [x0, y0] = centre(L, [b[1], b[2]]);
    const [x1, y1] = centre(L, [b[3], b[4]]);
    line(ctx, x0, y0, x1, y1, { color: INK.broken, width: 2, dash: DASH });
    const mx = (x0 + x1) / 2;
    const my = (y0 + y1) / 2;
    labels.avoid(text(ctx, "✕", mx, my, { color: INK.broken, weight: "bold", align: "center" }));
    labels.avoidLine(x0, y0, x1, y1, 1);
    labels.add(`break ${b[0]}→${b[0] + 1}`, mx, my, { color: INK.broken, weight: "bold", size: FONT_SIZE_SMALL, gap: 8, candidates: ["S", "N", "E", "W", "SE", "NE", "SW", "NW"] });
  }
  for (const b of m.branches) {
    if (b.length < 4) continue;
    const [x, y] = centre(L, [b[2], b[3]]);
    ctx.save();
    ctx.strokeStyle = INK.broken;
    ctx.lineWidth = 2.5;
    ctx.beginPath();
    ctx.arc(x, y, Math.max(6, 0.48 * L.cell), 0, 2 * Math.PI);
    ctx.stroke();
    ctx.restore();
    const ring = Math.max(6, 0.48 * L.cell);
    labels.avoidDot(x, y, ring, 1.5);
    labels.add(`branch: pixel ${b[0]} = pixel ${b[1]}`, x, y, { color: INK.broken, weight: "bold", size: FONT_SIZE_SMALL, gap: ring + 3, candidates: ["N", "S", "NE", "SE", "NW", "SW", "E", "W"] });
  }
}

/** The start ring and the end dot: [x, y, radius] each (the end null for a closed path). */
function endMarks(L, m) {
  const ps = m.code ? m.path : m.raw;
  if (!ps.length) return null;
  const r = Math.max(4, 0.34 * L.cell);
  const end = !m.closed && ps.length > 1 ? [...centre(L, ps[ps.length - 1]), Math.max(3, 0.18 * L.cell)] : null;
  return { start: [...centre(L, ps[0]), r], end };
}

function drawEnds(ctx, L, m, labels) {
  const marks = endMarks(L, m);
  if (!marks) return;
  const [sx, sy, r] = marks.start;
  ctx.save();
  ctx.strokeStyle = INK.start;
  ctx.lineWidth = 2.5;
  ctx.beginPath();
  ctx.arc(sx, sy, r, 0, 2 * Math.PI);
  ctx.stroke();
  ctx.restore();
  const spots = ["S", "N", "SW", "SE", "NW", "NE", "W", "E"];
  labels.add("start", sx, sy, { color: INK.start, weight: "bold", size: FONT_SIZE_SMALL, gap: r + 3, candidates: spots });
  if (marks.end) {
    const [ex, ey, er] = marks.end;
    dot(ctx, ex, ey, er, COLORS.ink);
    labels.add("end", ex, ey, { color: COLORS.ink, weight: "bold", size: FONT_SIZE_SMALL, gap: er + 3, candidates: spots });
  }
}

const toCanvas = (L, p) => [L.left + (p[0] - L.c0 + 0.5) * L.cell, L.top + (p[1] - L.r0 + 0.5) * L.cell];

/** Draws the axes and the basic rectangle; returns the axes' labels [text, line, colour]. */
function drawShape(ctx, L, res, labels) {
  if (typeof res.diameter !== "number") return [];
  const axisLabels = [];
  const rect = pixelList(res.basic_rectangle);
  if (rect.length === 4) {
    ctx.save();
    ctx.strokeStyle = INK.rectangle;
    ctx.lineWidth = 1.6;
    ctx.setLineDash([...DASH]);
    ctx.beginPath();
    rect.forEach((p, i) => {
      const [x, y] = toCanvas(L, p);
      if (i === 0) ctx.moveTo(x, y);
      else ctx.lineTo(x, y);
    });
    ctx.closePath();
    ctx.stroke();
    ctx.restore();
    labels.avoidPath(
      rect.map((p) => toCanvas(L, p)),
      1,
      true,
    );
  }
  const major = pixelList(res.major_axis);
  if (major.length === 2) {
    const [x0, y0] = toCanvas(L, major[0]);
    const [x1, y1] = toCanvas(L, major[1]);
    line(ctx, x0, y0, x1, y1, { color: INK.major, width: 3 });
    dot(ctx, x0, y0, 4, INK.major);
    dot(ctx, x1, y1, 4, INK.major);
    labels.avoidLine(x0, y0, x1, y1, 2).avoidDot(x0, y0, 4).avoidDot(x1, y1, 4);
    axisLabels.push([`D = ${fmt(res.diameter, 4)}`, [x0, y0, x1, y1], COLORS.theme === "dark" ? COLORS.highlight : "#9a4a00"]);
  }
  const minor = pixelList(res.minor_axis);
  if (minor.length === 2 && finite(res.minor_axis_length) > 0) {
    const [x0, y0] = toCanvas(L, minor[0]);
    const [x1, y1] = toCanvas(L, minor[1]);
    line(ctx, x0, y0, x1, y1, { color: INK.minor, width: 2.5 });
    labels.avoidLine(x0, y0, x1, y1, 2);
    axisLabels.push([`m = ${fmt(res.minor_axis_length, 4)}`, [x0, y0, x1, y1], INK.minor]);
  }
  return axisLabels;
}

function figureHeight(width, solution, room = width) {
  const m = model(solution);
  const L = layout(width, m);
  const lines = infoBlock(width, solution, m, room);
  const lh = FONT_SIZE * LINE_HEIGHT;
  return L.gridBottom + LAYOUT.infoGap + 14 + lines.length * lh + LAYOUT.margin;
}

function drawFigure(ctx, width, height, solution, state) {
  const m = model(solution);
  const f = state?.frame ?? null; // motion: the moves up to the frame's, the follower where it has got to
  const L = layout(width, m);
  drawLattice(ctx, L);
  if (m.mode === "region") {
    fillCells(ctx, L, m.raw, INK.region);
    ctx.save();
    for (const b of m.regions.slice(1)) {
      for (let k = 0; k < b.length; k++) {
        const [x0, y0] = centre(L, b[k]);
        const [x1, y1] = centre(L, b[(k + 1) % b.length]);
        line(ctx, x0, y0, x1, y1, { color: INK.otherRegion, width: 1.5, dash: DASH });
      }
    }
    ctx.restore();
  }
  fillCells(ctx, L, m.code ? m.path : m.raw, INK.pathFill);
  // every label stays on the grid and off the arrows, the axes and each other
  const labels = new Labels(ctx, width, height);
  labels.bounds = { x: L.left, y: L.top, w: L.cell * L.cols, h: L.cell * L.rows };
  const marks = endMarks(L, m);
  if (marks) labels.avoidDot(...marks.start, 1.5);
  if (marks?.end) labels.avoidDot(...marks.end, 1.5);
  if (m.code) drawSteps(ctx, L, m, labels, f ? f.k : Infinity);
  else drawBrokenPath(ctx, L, m);
  if (f) {
    // the follower: a ring on the pixel the move reached
    const [x, y] = centre(L, f.to);
    const ring = Math.max(6, 0.42 * L.cell);
    for (const [color, w] of [["#ffffff", 5], [COLORS.point, 3]]) {
      ctx.save();
      ctx.strokeStyle = color;
      ctx.lineWidth = w;
      ctx.beginPath();
      ctx.arc(x, y, ring, 0, 2 * Math.PI);
      ctx.stroke();
      ctx.restore();
    }
    labels.avoidDot(x, y, ring, 2);
  }
  // the digits belong to the path: placed before the shape's lines (which they may touch)
  labels.place();
  const axisLabels = drawShape(ctx, L, m.res, labels);
  drawEnds(ctx, L, m, labels);
  drawProblems(ctx, L, m, labels);
  // each axis named beside it, as near its middle as the path allows
  for (const [str, along, color] of axisLabels) {
    labels.add(str, (along[0] + along[2]) / 2, (along[1] + along[3]) / 2, { color, weight: "bold", size: L.cell >= 26 ? FONT_SIZE : FONT_SIZE_SMALL, gap: 3, along, shorter: [str.replace(/ = /, "=")] });
  }
  labels.draw();
  const lh = FONT_SIZE * LINE_HEIGHT;
  let y = L.gridBottom + LAYOUT.infoGap + 14 + lh / 2;
  for (const l of infoBlock(width, solution, m, state?.room ?? width)) {
    text(ctx, l.text, LAYOUT.margin, y, { color: l.color ?? COLORS.ink, weight: l.weight ?? "normal", size: l.size ?? FONT_SIZE });
    y += lh;
  }
}

function describe(solution) {
  const m = model(solution);
  const res = m.res;
  const parts = [];
  const first = (m.code ? m.path : m.raw)[0];
  parts.push(
    m.mode === "region"
      ? `A pixel grid with ${m.raw.length} region pixel${m.raw.length === 1 ? "" : "s"} in ${Math.max(1, m.regions.length)} region${m.regions.length > 1 ? "s" : ""}; the outer boundary of the first, ${m.path.length} positions from (${first?.[0]}, ${first?.[1]}), traced clockwise.`
      : `A pixel grid with ${m.closed ? "a closed boundary" : "an open edge"} of ${m.path.length} pixels from (${first?.[0]}, ${first?.[1]}).`,
  );
  if (m.code) parts.push(`Chain code ${m.code.length ? digits(m.code) : "empty"}; differential code ${Array.isArray(res.differential) && res.differential.length ? digits(res.differential) : "empty"}.`);
  else parts.push("No chain code: the path breaks.");
  if (typeof res.length === "number") parts.push(`Length ${fmt(res.length, DIGITS)} px.`);
  if (typeof res.diameter === "number") parts.push(`Diameter ${fmt(res.diameter, DIGITS)} px, minor axis ${fmt(res.minor_axis_length, DIGITS)} px, eccentricity ${res.eccentricity == null ? "no value" : fmt(res.eccentricity, DIGITS)}.`);
  for (const b of m.breaks.slice(0, 3)) parts.push(`Break between pixel ${b[0]} (${b[1]}, ${b[2]}) and pixel ${b[0] + 1} (${b[3]}, ${b[4]}).`);
  for (const b of m.branches.slice(0, 3)) parts.push(`Branch: pixel ${b[0]} (${b[2]}, ${b[3]}) repeats pixel ${b[1]}.`);
  return parts.join(" ");
}

/** The grid cell under (x, y), or null outside the grid. */
function cellAt(x, y, width, m) {
  const L = layout(width, m);
  const i = Math.floor((x - L.left) / L.cell);
  const j = Math.floor((y - L.top) / L.cell);
  if (i < 0 || j < 0 || i >= L.cols || j >= L.rows) return null;
  return [L.c0 + i, L.r0 + j];
}

/** The centre of grid cell `pixel` [c, r] in CSS px on a canvas `width` wide (the inverse of a click; for tests). */
export function cellPoint(width, solution, pixel) {
  return centre(layout(width, model(solution)), pixel);
}

/** Where the lines of text under the grid begin, in CSS px on a canvas `width` wide (for tests). */
export function infoTop(width, solution) {
  return layout(width, model(solution)).gridBottom + LAYOUT.infoGap;
}

/** A click: extend or take back the path, close it, or toggle a region pixel. */
function onPointer(x, y, width, height, solution) {
  const m = model(solution);
  const p = cellAt(x, y, width, m);
  if (!p) return null;
  if (m.mode === "region") {
    const has = m.raw.some((q) => same(q, p));
    const next = has ? m.raw.filter((q) => !same(q, p)) : [...m.raw, p];
    if (!next.length) return null; // keep at least one pixel
    return { pixels: pixelsText(next) };
  }
  let path;
  const changes = {};
  if (m.mode === "code") {
    path = [...m.path];
    if (m.closed && path.length) path.push(path[0]);
    changes.given = "pixels";
    changes.from = "start";
  } else {
    path = [...m.raw];
  }
  const last = path[path.length - 1];
  if (same(last, p) && path.length > 1) path.pop();
  else if (same(path[0], p) && path.length >= 3) path.push(p);
  else if (!(same(last, p) && path.length === 1)) path.push(p);
  changes.pixels = pixelsText(path);
  return changes;
}

/** Steps of the chain-code digits, [dc, dr] (r downward): 8-connectivity 1 = east counter-clockwise; 4-connectivity 1 east, 2 north, 3 west, 4 south. */
const STEPS8 = [[1, 0], [1, -1], [0, -1], [-1, -1], [-1, 0], [-1, 1], [0, 1], [1, 1]];
const STEPS4 = [[1, 0], [0, -1], [-1, 0], [0, 1]];

/** A key on the focused grid: a code digit or an arrow adds a step to the path, Backspace takes the last one back. */
function onKey(key, solution) {
  const m = model(solution);
  if (m.mode === "region") return null;
  let path = m.mode === "code" ? [...m.path] : [...m.raw];
  if (m.mode === "code" && m.closed && path.length) path.push(path[0]);
  if (!path.length) return null;
  const changes = m.mode === "code" ? { given: "pixels", from: "start" } : {};
  if (key === "Backspace") {
    if (path.length < 2) return null;
    path = path.slice(0, -1);
  } else {
    const steps = m.four ? STEPS4 : STEPS8;
    const digit = /^[1-8]$/.test(key) ? Number(key) : 0;
    const step = digit >= 1 && digit <= steps.length ? steps[digit - 1] : arrowStep(key);
    if (!step) return null;
    const [c, r] = path[path.length - 1];
    path.push([c + step[0], r + step[1]]);
  }
  changes.pixels = pixelsText(path);
  return changes;
}

const region = (pixels, extra = {}) => ({ given: "region", pixels: pixelsText(pixels), connectivity: "8", ...extra });
const clear = {
  label: "Start again",
  title: "Keep only the first pixel",
  inputs(solution) {
    const m = model(solution);
    const first = (m.mode === "region" ? m.raw : m.code ? m.path : m.raw)[0] ?? [2, 2];
    return m.mode === "region" ? { pixels: pixelsText([first]) } : { given: "pixels", pixels: pixelsText([first]), from: "start" };
  },
};
const shapePresets = (extra = {}) => [
  { label: "Circle", inputs: () => region(SHAPES.circle(), extra) },
  { label: "Rectangle", inputs: () => region(SHAPES.rectangle(), extra) },
  { label: "L-shape", inputs: () => region(SHAPES.lShape(), extra) },
];

const CAPTION =
  "The pixel grid: c to the right, r downward. Blue arrows are the steps of the chain code, each labelled with its digit (1 = east, counter-clockwise to 8 = south-east); the green ring is the start. Red marks where a path breaks or branches. For a closed boundary: major axis (orange), minor axis (purple), basic rectangle (dashed).";

/** Direction words of the code digits (8-connectivity: 1 = east, counter-clockwise; 4-connectivity: 1 east, 2 north, 3 west, 4 south). */
const WORDS8 = ["east", "north-east", "north", "north-west", "west", "south-west", "south", "south-east"];
const WORDS4 = ["east", "north", "west", "south"];

/**
 * The Data view (index.js tables()): the grid as a table (a cell's pixel, its
 * place on the path, start and end in words), the path move by move, the
 * numbers under the grid; the grid is explorable (Enter toggles a cell as a click does).
 */
function tables(solution) {
  const m = model(solution);
  const res = m.res;
  const shown = m.code ? m.path : m.raw;
  const e = extent(m);
  const where = new Map();
  const note = (p, word) => {
    const k = `${p[0]},${p[1]}`;
    where.set(k, [...(where.get(k) ?? []), word]);
  };
  if (m.mode === "region") for (const p of m.raw) note(p, "region pixel");
  shown.forEach((p, i) => note(p, m.mode === "region" ? `boundary ${i + 1}` : `pixel ${i + 1}`));
  const first = shown[0];
  const last = shown[shown.length - 1];
  const rows = [];
  const marks = [];
  for (let j = 0; j < e.rows; j++) {
    const r = e.r0 + j;
    rows.push(Array.from({ length: e.cols }, (_, i) => (where.get(`${e.c0 + i},${r}`) ?? []).join(", ")));
    marks.push(Array.from({ length: e.cols }, (_, i) => {
      const p = [e.c0 + i, r];
      const words = [same(p, first) ? "start" : null, !m.closed && shown.length > 1 && same(p, last) ? "end" : null].filter(Boolean);
      return words.join(", ") || null;
    }));
  }
  const words = m.four ? WORDS4 : WORDS8;
  const path = m.closed && m.path.length ? [...m.path, m.path[0]] : m.path;
  const moves = m.code ? m.code.map((d, i) => `(${path[i]?.[0]}, ${path[i]?.[1]}) → (${path[i + 1]?.[0]}, ${path[i + 1]?.[1]}): code ${d}, ${words[d - 1] ?? "?"}`) : [];
  const numbers = [
    ["chain code", m.code ? digits(m.code) || "empty" : "none (the path breaks)"],
    ["differential code", Array.isArray(res.differential) ? digits(res.differential) || "empty" : "none"],
  ];
  if (typeof res.length === "number") numbers.push(["length L (px)", fmt(res.length, DIGITS)]);
  if (typeof res.diameter === "number") numbers.push(["diameter D (px)", fmt(res.diameter, DIGITS)], ["minor axis m (px)", fmt(res.minor_axis_length, DIGITS)], ["eccentricity E", res.eccentricity == null ? "no value" : fmt(res.eccentricity, DIGITS)]);
  for (const b of m.breaks.slice(0, 3)) if (b.length >= 5) numbers.push(["break", `pixel ${b[0]} (${b[1]}, ${b[2]}) → pixel ${b[0] + 1} (${b[3]}, ${b[4]})`]);
  return {
    summary: `${describe(solution)} ${first ? `It starts at column ${first[0]}, row ${first[1]}${!m.closed && last && shown.length > 1 ? ` and ends at column ${last[0]}, row ${last[1]}` : ""}` : "No pixels"}; the grid shows columns ${e.c0}–${e.c0 + e.cols - 1} and rows ${e.r0}–${e.r0 + e.rows - 1}.`,
    tables: [
      {
        caption: "The pixel grid (c to the right, r downward)",
        corner: "",
        columns: Array.from({ length: e.cols }, (_, i) => `column ${e.c0 + i}`),
        rowHeaders: Array.from({ length: e.rows }, (_, j) => `row ${e.r0 + j}`),
        rows,
        marks,
        // a region's cells are toggled from the cursor (Enter or Space); with pixels in order the arrow keys add steps
        ...(m.mode === "region"
          ? {
              explore: {
                rect(j, i, width) {
                  const L = layout(width, m);
                  return { x: L.left + i * L.cell, y: L.top + j * L.cell, w: L.cell, h: L.cell };
                },
              },
            }
          : {}),
      },
      { caption: "The numbers under the grid", columns: ["what", "value"], rows: numbers },
    ],
    list: moves.length ? { caption: `The path, move by move (${m.four ? "4" : "8"}-connectivity codes)`, items: moves } : null,
  };
}

/**
 * Motion (issue 34; index.js `frames`): the follower walking the boundary,
 * one move (one code digit) a frame; pixels and codes are the solution's.
 */
function frames(solution) {
  const m = model(solution);
  if (!m.code || m.path.length < 2) return [];
  const path = m.closed ? [...m.path, m.path[0]] : m.path;
  const words = m.four ? WORDS4 : WORDS8;
  const step = (solution.steps ?? []).findIndex((s) => s.values && Array.isArray(s.values.code));
  return m.code.map((code, k) => {
    const from = path[k];
    const to = path[k + 1] ?? from;
    return {
      k,
      from,
      to,
      code,
      step: step >= 0 ? step : null,
      caption: `Move ${k + 1}: from column ${from[0]}, row ${from[1]} to column ${to[0]}, row ${to[1]}, ${words[code - 1] ?? "?"}: code ${code}. The code so far: ${m.code.slice(0, k + 1).join(" ")}.`,
    };
  });
}

/** The smallest cell a pointer should have to hit (CSS px; WCAG 2.5.8). */
const TARGET = 24;

/** The canvas width that gives every cell of the grid TARGET px (the registry lets the panel scroll when it is narrower). */
const minWidth = (solution) => 2 * LAYOUT.margin + LAYOUT.axis + extent(model(solution)).cols * TARGET;

const base = { caption: CAPTION, height: figureHeight, minWidth, describe, draw: drawFigure, tables, frames, motion: { noun: "move" }, interact: { pointer: onPointer, key: onKey } };

export const figures = {
  "chain-code": {
    ...base,
    actions: [
      { label: "Example 17 (the worked example’s edge)", inputs: () => ({ given: "pixels", pixels: pixelsText(EX17), connectivity: "8", from: "start" }) },
      { label: "Exercise: from the right end", inputs: () => ({ given: "pixels", pixels: pixelsText(EX17), connectivity: "8", from: "end" }) },
      { label: "Figure c (4-connected)", inputs: () => ({ given: "code", code: FIG_C_CODE, start: "1 4", connectivity: "4", from: "start" }) },
      ...shapePresets({ from: "start" }),
      clear,
    ],
  },
  "boundary-length": {
    ...base,
    actions: [
      { label: "Example 18 (b)", inputs: () => ({ given: "pixels", pixels: pixelsText(EX18B), connectivity: "8" }) },
      { label: "Example 18 (a)", inputs: () => ({ given: "code", code: EX18A_CODE, start: "1 1", connectivity: "4" }) },
      { label: "Example 17’s edge", inputs: () => ({ given: "pixels", pixels: pixelsText(EX17), connectivity: "8" }) },
      ...shapePresets(),
      clear,
    ],
  },
  "boundary-shape": {
    ...base,
    actions: [
      ...shapePresets(),
      { label: "Example 17’s edge", inputs: () => ({ pixels: pixelsText(EX17), connectivity: "8" }) },
      clear,
    ],
  },
};
