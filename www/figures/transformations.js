// Figures of the "Transformations" topic (seed 000 Example 4, seed 004
// Table 9.5.1): fiducial-similarity, fiducial-affine, transform-fit.
//   1. The control points in the source and the target system, each
//      labelled; in the target, the residual vectors (x̂ − x, ŷ − y) drawn
//      magnified, with a scale bar that states the magnification.
//   2. The rows of A, L and V, two per point. Hovering or selecting a point
//      in either canvas (or the arrow keys) highlights it in both.

import { formatNumber } from "../format.js";
import { stepValue } from "../values.js";
import { COLORS, FONT_SIZE_SMALL, Labels, arrow, dot, finite, line, ring, text, textWidth } from "./draw.js";

const PLOT = Object.freeze({
  sideBySide: 560, // at least this wide: source and target panels side by side
  gap: 20, // between the two panels
  pad: { left: 52, right: 16, top: 30, bottom: 44 }, // inside a panel, around the plot area
  margin: 0.1, // extra view around the points, a fraction of their span
  maxPlot: 380, // largest plot area side, side by side
  maxPlotStacked: 320, // largest plot area side, one panel above the other
  legend: 80, // room under the panels for the scale bar and legend
  ticks: 4, // about this many grid lines per axis
  pointRadius: 4,
  ringRadius: 9,
  hitRadius: 14, // a pointer this close to a point selects it
  arrowShare: 0.18, // the longest residual arrow spans this share of the plot
  labelGap: 7,
});

const TABLE = Object.freeze({
  rowHeight: 17,
  header: 24,
  pad: 8,
  cellPad: 14,
  digits: 5, // significant digits in the cells
  maxRows: 24, // rows shown at most (the selected point's rows are always shown)
});


function pairs(value) {
  return Array.isArray(value) ? value.filter((p) => Array.isArray(p) && p.length >= 2).map((p) => [finite(p[0]), finite(p[1])]) : [];
}

/** Everything the figures need, from any of the three solutions. */
function dataOf(solution) {
  const res = solution.result ?? {};
  const ex4 = solution.id !== "transform-fit";
  const source = pairs(stepValue(solution, "source"));
  const target = pairs(stepValue(solution, "target"));
  const residuals = pairs(res.point_residuals);
  const n = Math.min(source.length, target.length);
  return {
    ex4,
    n,
    source: source.slice(0, n),
    target: target.slice(0, n),
    residuals: residuals.slice(0, n),
    redundancy: finite(res.redundancy, 0),
    sigma0: typeof res.sigma0 === "number" ? res.sigma0 : null,
    unit: ex4 ? "mm" : "",
    sourceName: ex4 ? "Source: (x′, y′) = (c, −r), pixels" : "Source (u, v)",
    targetName: ex4 ? "Target: photo (x, y), mm" : "Target (x, y)",
    axes: ex4 ? ["x′", "y′", "x", "y"] : ["u", "v", "x", "y"],
    A: Array.isArray(stepValue(solution, "A")) ? stepValue(solution, "A") : [],
    L: Array.isArray(stepValue(solution, "L")) ? stepValue(solution, "L") : [],
    V: Array.isArray(stepValue(solution, "V")) ? stepValue(solution, "V") : [],
    names: Array.isArray(res.parameter_names) ? res.parameter_names.map(String) : [],
    model: typeof res.model === "string" ? res.model : ex4 ? (solution.id === "fiducial-affine" ? "affine" : "similarity") : "",
  };
}

/** 1, 2 or 5 times a power of ten, at most `x` (or at least, with `up`). */
function nice(x, up = false) {
  if (!(x > 0) || !Number.isFinite(x)) return 1;
  const p = 10 ** Math.floor(Math.log10(x));
  const steps = [1, 2, 5, 10];
  if (up) return p * steps.find((s) => s * p >= x * (1 - 1e-9));
  return p * [...steps].reverse().find((s) => s * p <= x * (1 + 1e-9));
}

/** A plot area mapping the points' bounds into a rectangle, equal scale on both axes. */
function plotArea(points, x, y, w, h) {
  let [minX, maxX, minY, maxY] = [Infinity, -Infinity, Infinity, -Infinity];
  for (const [a, b] of points) {
    minX = Math.min(minX, a);
    maxX = Math.max(maxX, a);
    minY = Math.min(minY, b);
    maxY = Math.max(maxY, b);
  }
  if (!Number.isFinite(minX)) [minX, maxX, minY, maxY] = [0, 1, 0, 1];
  let spanX = maxX - minX;
  let spanY = maxY - minY;
  const span = Math.max(spanX, spanY) || 1;
  spanX = Math.max(spanX, span * 0.2);
  spanY = Math.max(spanY, span * 0.2);
  const cx = (minX + maxX) / 2;
  const cy = (minY + maxY) / 2;
  spanX *= 1 + 2 * PLOT.margin;
  spanY *= 1 + 2 * PLOT.margin;
  const scale = Math.min(w / spanX, h / spanY);
  const ox = x + w / 2;
  const oy = y + h / 2;
  return {
    x,
    y,
    w,
    h,
    scale,
    lo: [cx - w / 2 / scale, cy - h / 2 / scale],
    hi: [cx + w / 2 / scale, cy + h / 2 / scale],
    map: (a, b) => [ox + (a - cx) * scale, oy - (b - cy) * scale],
  };
}

/** The two panels' positions for a canvas `width` wide. */
function layout(width, d) {
  const side = width >= PLOT.sideBySide;
  const pw = side ? (width - PLOT.gap) / 2 : width;
  const plotW = Math.min(side ? PLOT.maxPlot : PLOT.maxPlotStacked, pw - PLOT.pad.left - PLOT.pad.right);
  const plotH = plotW;
  const ph = plotH + PLOT.pad.top + PLOT.pad.bottom;
  const boxes = side
    ? [
        { x: 0, y: 0 },
        { x: pw + PLOT.gap, y: 0 },
      ]
    : [
        { x: 0, y: 0 },
        { x: 0, y: ph },
      ];
  const panels = [d.source, d.target].map((pts, i) => {
    const b = boxes[i];
    const left = b.x + PLOT.pad.left + (pw - PLOT.pad.left - PLOT.pad.right - plotW) / 2;
    return { ...b, w: pw, h: ph, plot: plotArea(pts, left, b.y + PLOT.pad.top, plotW, plotH) };
  });
  const height = (side ? ph : 2 * ph) + PLOT.legend;
  return { panels, height };
}

/** Residual magnification and the scale bar length, or null when there is nothing to draw. */
function magnification(d, plot) {
  if (d.redundancy <= 0 || !d.residuals.length) return null;
  const longest = Math.max(...d.residuals.map(([a, b]) => Math.hypot(a, b)));
  if (!(longest > 0)) return null;
  const wanted = PLOT.arrowShare * Math.min(plot.w, plot.h);
  const k = nice(wanted / (longest * plot.scale));
  const bar = nice(longest);
  return { k, bar, longest, barPx: bar * k * plot.scale };
}

function gridAndTicks(ctx, plot, names) {
  const step = nice((plot.hi[0] - plot.lo[0]) / PLOT.ticks, true);
  ctx.save();
  ctx.beginPath();
  ctx.rect(plot.x, plot.y, plot.w, plot.h);
  ctx.clip();
  for (let a = Math.ceil(plot.lo[0] / step) * step; a <= plot.hi[0]; a += step) {
    const [px] = plot.map(a, 0);
    line(ctx, px, plot.y, px, plot.y + plot.h, { color: Math.abs(a) < step / 1e6 ? COLORS.muted : COLORS.grid });
  }
  for (let b = Math.ceil(plot.lo[1] / step) * step; b <= plot.hi[1]; b += step) {
    const [, py] = plot.map(0, b);
    line(ctx, plot.x, py, plot.x + plot.w, py, { color: Math.abs(b) < step / 1e6 ? COLORS.muted : COLORS.grid });
  }
  ctx.restore();
  ctx.save();
  ctx.strokeStyle = COLORS.frameStroke;
  ctx.strokeRect(plot.x + 0.5, plot.y + 0.5, plot.w - 1, plot.h - 1);
  ctx.restore();
  const first = Math.ceil(plot.lo[0] / step) * step;
  for (let a = first; a <= plot.hi[0]; a += 2 * step) {
    const [px] = plot.map(a, 0);
    text(ctx, formatNumber(Math.abs(a) < step / 1e6 ? 0 : a, 4), px, plot.y + plot.h + 4, { size: FONT_SIZE_SMALL, align: "center", baseline: "top", color: COLORS.muted });
  }
  const firstB = Math.ceil(plot.lo[1] / step) * step;
  for (let b = firstB; b <= plot.hi[1]; b += 2 * step) {
    const [, py] = plot.map(0, b);
    text(ctx, formatNumber(Math.abs(b) < step / 1e6 ? 0 : b, 4), plot.x - 4, py, { size: FONT_SIZE_SMALL, align: "right", color: COLORS.muted });
  }
  text(ctx, `${names[0]} →`, plot.x + plot.w / 2, plot.y + plot.h + 6 + FONT_SIZE_SMALL * 1.4, { size: FONT_SIZE_SMALL, align: "center", baseline: "top", color: COLORS.muted });
  ctx.save();
  ctx.translate(plot.x - 40, plot.y);
  ctx.rotate(-Math.PI / 2);
  text(ctx, `${names[1]} →`, 0, 0, { size: FONT_SIZE_SMALL, align: "right", color: COLORS.muted });
  ctx.restore();
}

function drawPanel(ctx, panel, title, pts, color, selected, labelled, labels) {
  text(ctx, title, panel.plot.x, panel.y + 12, { weight: "bold", color });
  pts.forEach(([a, b], i) => {
    const [px, py] = panel.plot.map(a, b);
    if (i === selected) {
      ring(ctx, px, py, PLOT.ringRadius, COLORS.highlight, 3);
    }
    dot(ctx, px, py, PLOT.pointRadius, color);
    labels.avoidDot(px, py, i === selected ? PLOT.ringRadius + 1.5 : PLOT.pointRadius, 1);
  });
  // each point's number beside it (above right first), off the points, the
  // residual arrows and the other numbers, inside the plot
  if (labelled) {
    const within = { x: panel.plot.x + 1, y: panel.plot.y + 1, w: panel.plot.w - 2, h: panel.plot.h - 2 };
    pts.forEach(([a, b], i) => {
      const [px, py] = panel.plot.map(a, b);
      const r = i === selected ? PLOT.ringRadius : PLOT.pointRadius;
      labels.add(String(i + 1), px, py, { size: FONT_SIZE_SMALL, weight: i === selected ? "bold" : "normal", gap: r + 1, candidates: ["NE", "NW", "SE", "SW", "E", "W", "N", "S"], farther: 6, within });
    });
  }
}

function drawPoints(ctx, width, height, solution, state) {
  const d = dataOf(solution);
  const { panels } = layout(width, d);
  const selected = Number.isInteger(state?.selected) && state.selected < d.n ? state.selected : null;
  const [src, tgt] = panels;
  gridAndTicks(ctx, src.plot, d.axes.slice(0, 2));
  gridAndTicks(ctx, tgt.plot, d.axes.slice(2, 4));
  const labels = new Labels(ctx, width, height);
  drawPanel(ctx, src, d.sourceName, d.source, COLORS.pixelSystem, selected, true, labels);

  const mag = magnification(d, tgt.plot);
  if (mag) {
    ctx.save();
    ctx.beginPath();
    ctx.rect(tgt.x, tgt.y, tgt.w, tgt.h); // an arrow may leave the plot, never the panel
    ctx.clip();
    d.target.forEach(([a, b], i) => {
      const [vx, vy] = d.residuals[i] ?? [0, 0];
      const [x0, y0] = tgt.plot.map(a, b);
      const [x1, y1] = tgt.plot.map(a + mag.k * vx, b + mag.k * vy);
      if (Math.hypot(x1 - x0, y1 - y0) > 1) {
        const width = i === selected ? 2.5 : 1.8;
        arrow(ctx, x0, y0, x1, y1, { color: i === selected ? COLORS.highlight : COLORS.point, width, size: 7 });
        labels.avoidArrow(x0, y0, x1, y1, { width, size: 7 });
      }
    });
    ctx.restore();
  }
  drawPanel(ctx, tgt, d.targetName, d.target, COLORS.imageSystem, selected, true, labels);
  labels.draw();

  // the scale bar and what the arrows are
  const y = height - PLOT.legend + 14;
  const x = tgt.plot.x;
  if (mag) {
    arrow(ctx, x, y, x + mag.barPx, y, { color: COLORS.point, width: 1.8, size: 7 });
    line(ctx, x, y - 5, x, y + 5, { color: COLORS.point });
    const unit = d.unit ? ` ${d.unit}` : "";
    text(ctx, `= ${formatNumber(mag.bar, 3)}${unit} of residual (x̂ − x, ŷ − y)`, x + mag.barPx + 8, y, { size: FONT_SIZE_SMALL });
    text(ctx, `Residual vectors drawn ${formatNumber(mag.k, 3)} × magnified.`, x, y + 16, { size: FONT_SIZE_SMALL, weight: "bold", color: COLORS.point });
  } else {
    text(ctx, d.redundancy <= 0 ? "No redundancy (r = 0): the fit passes through every point, there are no residuals to draw." : "All residuals are zero.", x, y, { size: FONT_SIZE_SMALL, color: COLORS.muted });
  }
  const hint = selected === null ? "Point at, click or use the arrow keys on a figure to pick a point." : pickedLine(d, selected);
  wrapText(ctx, hint, TABLE.pad, y + 34, width - 2 * TABLE.pad, { size: FONT_SIZE_SMALL, color: selected === null ? COLORS.muted : COLORS.ink });
}

/** Text on up to two lines of at most `maxWidth`. */
function wrapText(ctx, str, x, y, maxWidth, options) {
  const words = str.split(" ");
  let first = "";
  let k = 0;
  while (k < words.length && textWidth(`${first} ${words[k]}`.trim(), options.size) <= maxWidth) {
    first = `${first} ${words[k]}`.trim();
    k += 1;
  }
  text(ctx, first, x, y, options);
  if (k < words.length) text(ctx, words.slice(k).join(" "), x, y + options.size * 1.35, options);
}

function pickedLine(d, i) {
  const [u, v] = d.source[i];
  const [x, y] = d.target[i];
  const [vx, vy] = d.residuals[i] ?? [0, 0];
  const f = (z) => formatNumber(z, 6);
  const unit = d.unit ? ` ${d.unit}` : "";
  return `Point ${i + 1}: (${d.axes[0]}, ${d.axes[1]}) = (${f(u)}, ${f(v)}) → (x, y) = (${f(x)}, ${f(y)}); residuals ${f(vx)}, ${f(vy)}${unit} (rows ${2 * i + 1} and ${2 * i + 2} of A and V)`;
}

/** Where point `i` is drawn in the source panel (CSS px of a canvas `width` wide); for tests and tools. */
export function pointPosition(width, solution, i) {
  const d = dataOf(solution);
  const [a, b] = d.source[i];
  return layout(width, d).panels[0].plot.map(a, b);
}

function pickPoint(px, py, width, solution) {
  const d = dataOf(solution);
  const { panels } = layout(width, d);
  let best = null;
  let bestDist = PLOT.hitRadius;
  [d.source, d.target].forEach((pts, k) => {
    pts.forEach(([a, b], i) => {
      const [qx, qy] = panels[k].plot.map(a, b);
      const dist = Math.hypot(qx - px, qy - py);
      if (dist < bestDist) {
        bestDist = dist;
        best = i;
      }
    });
  });
  return best;
}

function describePoints(solution, state) {
  const d = dataOf(solution);
  const unit = d.unit ? ` ${d.unit}` : "";
  const longest = d.residuals.length ? Math.max(...d.residuals.map(([a, b]) => Math.hypot(a, b))) : 0;
  const parts = [
    `${d.n} control points of the ${d.model} transformation, in the source system and in the target system.`,
    d.redundancy > 0 ? `Residual vectors drawn magnified; the longest is ${formatNumber(longest, 3)}${unit}.` : "No redundancy: no residuals.",
  ];
  if (Number.isInteger(state?.selected) && state.selected < d.n) parts.push(pickedLine(d, state.selected));
  return parts.join(" ");
}

// ---------------------------------------------------------------------------
// The rows of A, L and V

/** Which rows to show: the first ones, and the selected point's rows if they are further down. */
function shownRows(d, selected) {
  const total = d.A.length;
  if (total <= TABLE.maxRows) return [...Array(total).keys()];
  const rows = [...Array(TABLE.maxRows - 3).keys()];
  if (selected !== null && 2 * selected + 1 >= rows.length) rows.push(-1, 2 * selected, 2 * selected + 1);
  else rows.push(-1);
  return rows;
}

function tableLayout(width, d, selected) {
  const f = (z) => formatNumber(finite(z), TABLE.digits);
  const cols = [];
  const widthOf = (header, values) => Math.max(textWidth(header, FONT_SIZE_SMALL, "bold"), ...values.map((v) => textWidth(v, FONT_SIZE_SMALL))) + TABLE.cellPad;
  cols.push({ header: "point", cell: (r) => (r % 2 === 0 ? String(r / 2 + 1) : ""), w: widthOf("point", ["00"]) });
  cols.push({ header: "row", cell: (r) => `${r + 1} (${r % 2 === 0 ? "x" : "y"})`, w: widthOf("row", ["00 (x)"]) });
  const tail = [
    { header: "L", cell: (r) => f(d.L[r]), w: widthOf("L", d.L.map(f)) },
    { header: "V", cell: (r) => f(d.V[r]), w: widthOf("V", d.V.map(f)), strong: true },
  ];
  const fixed = cols.reduce((s, c) => s + c.w, 0) + tail.reduce((s, c) => s + c.w, 0) + 2 * TABLE.pad;
  const u = d.A[0]?.length ?? 0;
  const aCols = [];
  let used = fixed;
  for (let j = 0; j < u; j += 1) {
    const name = d.names[j] ?? `x${j + 1}`;
    const w = widthOf(`A: ${name}`, d.A.map((row) => f(row[j])));
    const more = j < u - 1 ? textWidth(`… ${u - j} more`, FONT_SIZE_SMALL) + TABLE.cellPad : 0;
    if (used + w + more > width) {
      aCols.push({ header: `… ${u - j} more`, cell: () => "…", w: more });
      break;
    }
    aCols.push({ header: j === 0 ? `A: ${name}` : name, cell: (r) => f(d.A[r]?.[j]), w });
    used += w;
  }
  const all = [...cols, ...aCols, ...tail];
  let x = TABLE.pad;
  for (const c of all) {
    c.x = x;
    x += c.w;
  }
  const rows = shownRows(d, selected);
  return { cols: all, rows, height: TABLE.header + rows.length * TABLE.rowHeight + 2 * TABLE.pad };
}

function drawRows(ctx, width, height, solution, state) {
  const d = dataOf(solution);
  const selected = Number.isInteger(state?.selected) && state.selected < d.n ? state.selected : null;
  const { cols, rows } = tableLayout(width, d, selected);
  const top = TABLE.pad;
  for (const c of cols) {
    text(ctx, c.header, c.x + c.w - TABLE.cellPad / 2, top + TABLE.header / 2, { size: FONT_SIZE_SMALL, weight: "bold", align: "right" });
  }
  line(ctx, TABLE.pad, top + TABLE.header - 2, cols.at(-1).x + cols.at(-1).w, top + TABLE.header - 2, { color: COLORS.frameStroke });
  rows.forEach((r, k) => {
    const y = top + TABLE.header + k * TABLE.rowHeight;
    if (r < 0) {
      text(ctx, "⋮", cols[1].x + cols[1].w / 2, y + TABLE.rowHeight / 2, { size: FONT_SIZE_SMALL, color: COLORS.muted });
      return;
    }
    const point = Math.floor(r / 2);
    if (point === selected) {
      ctx.save();
      ctx.fillStyle = COLORS.highlightFill;
      ctx.fillRect(TABLE.pad, y, cols.at(-1).x + cols.at(-1).w - TABLE.pad, TABLE.rowHeight);
      ctx.restore();
    } else if (point % 2 === 1) {
      ctx.save();
      ctx.fillStyle = COLORS.frameFill;
      ctx.fillRect(TABLE.pad, y, cols.at(-1).x + cols.at(-1).w - TABLE.pad, TABLE.rowHeight);
      ctx.restore();
    }
    for (const c of cols) {
      text(ctx, c.cell(r), c.x + c.w - TABLE.cellPad / 2, y + TABLE.rowHeight / 2, {
        size: FONT_SIZE_SMALL,
        align: "right",
        weight: c.strong || point === selected ? "bold" : "normal",
        color: c.strong ? COLORS.point : COLORS.ink,
      });
    }
  });
  void height;
}

function pickRow(px, py, width, solution) {
  const d = dataOf(solution);
  const { rows } = tableLayout(width, d, null);
  const k = Math.floor((py - TABLE.pad - TABLE.header) / TABLE.rowHeight);
  if (k < 0 || k >= rows.length || rows[k] < 0) return null;
  return Math.floor(rows[k] / 2);
}

function describeRows(solution, state) {
  const d = dataOf(solution);
  const parts = [`The design matrix A (${d.A.length} rows, ${d.A[0]?.length ?? 0} columns), the observations L and the residuals V, two rows per point: its x equation, then its y equation.`];
  if (Number.isInteger(state?.selected) && state.selected < d.n) {
    const i = state.selected;
    const f = (z) => formatNumber(finite(z), TABLE.digits);
    parts.push(`Point ${i + 1}: row ${2 * i + 1} is [${(d.A[2 * i] ?? []).map(f).join(", ")}], L = ${f(d.L[2 * i])}, v = ${f(d.V[2 * i])}; row ${2 * i + 2} is [${(d.A[2 * i + 1] ?? []).map(f).join(", ")}], L = ${f(d.L[2 * i + 1])}, v = ${f(d.V[2 * i + 1])}.`);
  }
  return parts.join(" ");
}

// ---------------------------------------------------------------------------
// The Data views (index.js tables()) and the picked point's status line

const isPicked = (d, state) => Number.isInteger(state?.selected) && state.selected < d.n;

function pointsTables(solution, state) {
  const d = dataOf(solution);
  const f = (z) => formatNumber(finite(z), 6);
  const unit = d.unit ? ` (${d.unit})` : "";
  return {
    summary: describePoints(solution, state),
    tables: [
      {
        caption: `The control points: source, target and residual (fitted minus given)${unit}`,
        columns: ["point", d.axes[0], d.axes[1], "x", "y", "residual x", "residual y"],
        rows: d.source.map(([u, v], i) => [String(i + 1), f(u), f(v), f(d.target[i][0]), f(d.target[i][1]), d.residuals[i] ? f(d.residuals[i][0]) : "", d.residuals[i] ? f(d.residuals[i][1]) : ""]),
        marks: d.source.map((_, i) => [isPicked(d, state) && i === state.selected ? "picked" : null, null, null, null, null, null, null]),
      },
    ],
  };
}

function rowsTables(solution, state) {
  const d = dataOf(solution);
  const f = (z) => formatNumber(finite(z), TABLE.digits);
  const u = d.A[0]?.length ?? 0;
  return {
    summary: describeRows(solution, state),
    tables: [
      {
        caption: "Every row of A with its observation L and residual V (two per point: x, then y)",
        corner: "row",
        columns: [...Array.from({ length: u }, (_, j) => `A: ${d.names[j] ?? `x${j + 1}`}`), "L", "V"],
        rowHeaders: d.A.map((_, r) => `row ${r + 1}, point ${Math.floor(r / 2) + 1} ${r % 2 === 0 ? "x" : "y"}`),
        rows: d.A.map((row, r) => [...row.map(f), f(d.L[r]), f(d.V[r])]),
        marks: d.A.map((row, r) => [...row.map(() => null), null, isPicked(d, state) && Math.floor(r / 2) === state.selected ? "picked point" : null]),
      },
    ],
  };
}

const pointsFigure = {
  tables: pointsTables,
  // the picked point in words, read out when the arrow keys pick another
  status: (solution, state) => {
    const d = dataOf(solution);
    return isPicked(d, state) ? pickedLine(d, state.selected) : "";
  },
  caption: "The control points in both systems, numbered; in the target, each point's residual vector (fitted minus given) drawn magnified — the scale bar says by how much. Point at a point, click it, or focus the figure and use the arrow keys to pick one: it is marked here and its rows light up in the table below.",
  height(width, solution) {
    return layout(width, dataOf(solution)).height;
  },
  describe: describePoints,
  draw: drawPoints,
  count: (solution) => dataOf(solution).n,
  pick: (x, y, width, _height, solution) => pickPoint(x, y, width, solution),
};

const rowsFigure = {
  tables: rowsTables,
  caption: "The rows of A with their observations L and residuals V = A·X − L, two per point (its x equation, then its y equation); the picked point's rows are highlighted.",
  height(width, solution) {
    const d = dataOf(solution);
    return tableLayout(width, d, null).height;
  },
  describe: describeRows,
  draw: drawRows,
  count: (solution) => dataOf(solution).n,
  pick: (x, y, width, _height, solution) => pickRow(x, y, width, solution),
};

export const figures = {
  "fiducial-similarity": [pointsFigure, rowsFigure],
  "fiducial-affine": [pointsFigure, rowsFigure],
  "transform-fit": [pointsFigure, rowsFigure],
};
