// Figures of the "Filters and edges" topic (seed 000, Examples 15–16; seed 004):
//   filter-window: the window as a grid of numbers with the kernel laid over
//     the selected pixel, the kernel, the output grid, and the multiply-and-sum
//     of the selected pixel written row by row;
//   edge-window: the same for the two Prewitt/Sobel kernels, with Gx, Gy and
//     the magnitude as three output grids.
// Signed outputs are shaded on a diverging scale (blue below 0, orange above).
// Clicking a pixel of the window (or of an output grid) selects it; the arrow
// keys move the selection.

import { isMatrix, stepValue } from "../values.js";
import { matrixTable, seriesTable } from "./data-view.js";
import { COLORS, FONT_SIZE, FONT_SIZE_SMALL, GREY_LEGEND, GRID, LINE_HEIGHT, PLAIN_SHADE, arrowStep, cellAt, drawGrid, fmt, greyLegend, layoutSpec, outline, shader, signedLegend, signedMatrix, text, textBlock, textWidth, wrapWords } from "./draw.js";

// ---------------------------------------------------------------------------
// What the figures read from a solution

function filterData(solution) {
  const inp = solution.inputs ?? {};
  const res = solution.result ?? {};
  const window = inp.window;
  const output = res.output;
  if (!isMatrix(window) || !isMatrix(output)) return null;
  const numerators = stepValue(solution, "numerators");
  const divisor = stepValue(solution, "divisor");
  return {
    window,
    output,
    first: { c: res.output_first_c ?? 1, r: res.output_first_r ?? 1 },
    sel: { c: inp.select_c ?? 1, r: inp.select_r ?? 1 },
    kernels: isMatrix(numerators) ? [{ name: divisor && divisor !== 1 ? `Kernel: 1/${fmt(divisor)} ×` : "Kernel", m: numerators, divisor: divisor ?? 1 }] : [],
    median: inp.kernel === "median",
    neighbourhood: stepValue(solution, "neighbourhood"),
    sorted: stepValue(solution, "sorted"),
    selected: res.selected,
    outputs: [{ name: "Output g", m: output, value: res.selected }],
  };
}

function edgeData(solution) {
  const inp = solution.inputs ?? {};
  const res = solution.result ?? {};
  const window = inp.window;
  if (!isMatrix(window) || !isMatrix(res.gx) || !isMatrix(res.gy) || !isMatrix(res.magnitude)) return null;
  const sobel = inp.operator === "sobel";
  const kx = stepValue(solution, "kernel_x");
  const ky = stepValue(solution, "kernel_y");
  return {
    window,
    first: { c: res.output_first_c ?? 1, r: res.output_first_r ?? 1 },
    sel: { c: inp.select_c ?? 1, r: inp.select_r ?? 1 },
    kernels: isMatrix(kx) && isMatrix(ky)
      ? [
          { name: sobel ? "sk_x (→ Gx)" : "pk_x (→ Gx)", m: kx, divisor: 1, value: res.selected_gx, symbol: "Gx" },
          { name: sobel ? "sk_y (→ Gy)" : "pk_y (→ Gy)", m: ky, divisor: 1, value: res.selected_gy, symbol: "Gy" },
        ]
      : [],
    neighbourhood: stepValue(solution, "neighbourhood"),
    outputs: [
      { name: "Gx", m: res.gx, value: res.selected_gx },
      { name: "Gy", m: res.gy, value: res.selected_gy },
      { name: "|G| = √(Gx² + Gy²)", short: "|G|", m: res.magnitude, value: res.selected_magnitude, unsigned: true },
    ],
    magnitude: res.selected_magnitude,
  };
}

// ---------------------------------------------------------------------------
// The multiply-and-sum lines of the selected pixel

/** "1×10 + 2×13 + 1×3" for one kernel row over one neighbourhood row. */
function rowTerms(nums, vals) {
  const parts = [];
  nums.forEach((n, i) => {
    if (n === 0) return;
    const v = vals[i];
    const a = Math.abs(n);
    const body = `${a === 1 ? "" : `${fmt(a)}×`}${v < 0 ? `(${fmt(v)})` : fmt(v)}`;
    parts.push(parts.length === 0 ? (n < 0 ? `−${body}` : body) : `${n < 0 ? "− " : "+ "}${body}`);
  });
  return parts.length ? parts.join(" ") : "0";
}

function sumLines(d) {
  // a motion frame at another pixel than the selected one: its output values (the solution writes out the selected pixel's sum only)
  if (d.frame && !d.frame.selected) return [{ text: d.frame.values, weight: "bold", color: COLORS.highlight }, { text: `The multiply-and-sum is written out at the selected pixel (row ${d.frame.sel.r}, column ${d.frame.sel.c}) and in the steps.`, color: COLORS.muted }];
  const nb = d.neighbourhood;
  const at = `row ${d.sel.r}, column ${d.sel.c}`;
  if (!Array.isArray(nb)) {
    return [{ text: `No output at ${at}: the kernel reaches outside the window.`, color: COLORS.muted }];
  }
  if (d.median) {
    const sorted = Array.isArray(d.sorted) ? d.sorted : [];
    const mid = Math.floor(sorted.length / 2);
    return [
      { text: `Median at ${at}: the ${sorted.length} values sorted`, weight: "bold" },
      { text: sorted.map((v, i) => (i === mid ? `[${fmt(v)}]` : fmt(v))).join("  ") },
      { text: `g = ${fmt(d.selected)}`, weight: "bold", color: COLORS.highlight },
    ];
  }
  const lines = [];
  for (const k of d.kernels) {
    const kw = k.m[0].length;
    const sym = k.symbol ?? "g";
    lines.push({ text: `${sym} at ${at}: weight × grey value, row by row`, weight: "bold" });
    let total = 0;
    k.m.forEach((row, j) => {
      if (row.every((n) => n === 0)) return; // as in the step: rows of zero weights left out
      const vals = nb.slice(j * kw, (j + 1) * kw);
      const s = row.reduce((acc, n, i) => acc + n * vals[i], 0);
      total += s;
      lines.push({ text: `  ${rowTerms(row, vals)}  = ${fmt(s, 6)}` });
    });
    const value = k.divisor !== 1 ? `${fmt(total, 6)} / ${fmt(k.divisor)} = ${fmt(k.value ?? d.selected, 6)}` : fmt(total, 6);
    lines.push({ text: `${sym} = ${value}`, weight: "bold", color: COLORS.highlight });
  }
  if (d.magnitude !== undefined && d.kernels.length === 2) {
    const sq = (v) => (v < 0 ? `(${fmt(v)})²` : `${fmt(v)}²`);
    lines.push({ text: `|G| = √(${sq(d.kernels[0].value)} + ${sq(d.kernels[1].value)}) = ${fmt(d.magnitude, 6)}`, weight: "bold", color: COLORS.highlight });
  }
  return lines;
}

// ---------------------------------------------------------------------------
// Layout: window and kernels in the first row, outputs in the second (or all
// stacked on a narrow canvas), the sum below.

function layout(width, d) {
  const m = GRID.margin;
  const top = GRID.title + GRID.axis;
  const first = [{ kind: "window", item: null, mat: d.window }, ...d.kernels.map((k) => ({ kind: "kernel", item: k, mat: k.m }))];
  if (d.median) first.push({ kind: "median", item: null, mat: [[1, 1, 1], [1, 1, 1], [1, 1, 1]] });
  const second = d.outputs.map((o) => ({ kind: "output", item: o, mat: o.m }));
  const colsOf = (row) => row.reduce((a, p) => a + p.mat[0].length, 0);
  const sumSize = FONT_SIZE_SMALL;
  // the sum's lines, each wrapped (indented) where it is wider than the canvas
  const maxW = width - 2 * m - 12;
  const lines = sumLines(d).flatMap((l) => {
    if (textWidth(l.text, sumSize, l.weight ?? "normal") <= maxW) return [l];
    return wrapWords(l.text.trim(), maxW - textWidth("    ", sumSize), sumSize, l.weight ?? "normal").map((t, i) => ({ ...l, text: i ? `    ${t}` : t }));
  });
  const sumH = lines.length * sumSize * LINE_HEIGHT + 10;
  // a legend line for each grey scale (the window, each unsigned output) and one for the diverging scale
  const greys = [d.window, ...d.outputs.map((o) => o.m)].filter((mat) => !signedMatrix(mat)).length;
  const signed = [d.window, ...d.kernels.map((k) => k.m), ...d.outputs.map((o) => o.m)].some(signedMatrix);
  const legendH = (greys + (signed ? 1 : 0)) * GRID.legendLine + 4;
  const fixed = 2 * m + GRID.sumGap + sumH + legendH;
  // the largest cell that fits the width and keeps the figure within its height
  const cellFor = (rows) => {
    const byWidth = Math.min(...rows.map((row) => Math.floor((width - 2 * m - GRID.axis - (row.length - 1) * GRID.gap) / colsOf(row))));
    const cellRows = rows.reduce((a, row) => a + Math.max(...row.map((p) => p.mat.length)), 0);
    const byHeight = Math.floor((GRID.maxHeight - fixed - rows.length * (top + GRID.gap)) / cellRows);
    return Math.min(byWidth, byHeight);
  };
  // the arrangement with the largest cells: all in one row, two rows, or one panel per row
  const options = [[[...first, ...second]], [first, second]];
  if (first.length > 1) options.push([first.slice(0, 1), first.slice(1), second]);
  if (second.length > 1) {
    options.push([first, ...second.map((p) => [p])]);
    if (first.length > 1) options.push([first.slice(0, 1), first.slice(1), ...second.map((p) => [p])]);
  }
  if (second.length > 2) options.push([first, second.slice(0, 2), second.slice(2)]);
  options.push([...first, ...second].map((p) => [p]));
  const pick = (least) => options.find((o) => cellFor(o) >= least);
  const best = () => options.reduce((a, o) => (cellFor(o) > cellFor(a) ? o : a));
  const rows = pick(GRID.comfortable) ?? pick(GRID.readable) ?? best();
  let cell = cellFor(rows);
  cell = Math.max(GRID.minCell, Math.min(GRID.maxCell, cell));
  const panels = [];
  let y = m + top;
  for (const row of rows) {
    let x = m + GRID.axis;
    let rowH = 0;
    for (const p of row) {
      panels.push({ ...p, x, y });
      x += p.mat[0].length * cell + GRID.gap;
      rowH = Math.max(rowH, p.mat.length * cell);
    }
    y += rowH + GRID.gap + top;
  }
  const gridsBottom = y - GRID.gap - top;
  const height = gridsBottom + GRID.sumGap + sumH + legendH + m;
  return { cell, panels, gridsBottom, lines, sumSize, height, legendTop: gridsBottom + GRID.sumGap + sumH + 6 };
}

/** A panel's title, or its short form where the title would leave the canvas. */
function fitTitle(p, width) {
  const { name, short } = p.item;
  return short && p.x + textWidth(name, FONT_SIZE, "bold") > width - 4 ? short : name;
}

function drawFigure(ctx, width, d) {
  const L = layout(width, d);
  const sel = { c: d.sel.c - 1, r: d.sel.r - 1 };
  const geo = {};
  let signed = false;
  const greys = []; // the grey scales drawn, for their legends
  L.panels.forEach((p) => {
    if (p.kind === "window") {
      const kw = d.kernels[0]?.m[0].length ?? 3;
      const kh = d.kernels[0]?.m.length ?? 3;
      const shade = shader(p.mat, "Window f");
      const g = drawGrid(ctx, p.mat, p.x, p.y, L.cell, { title: "Window f", first: { c: 1, r: 1 }, shade });
      if (shade.scale) greys.push(shade.scale);
      signed = signed || shade.signed;
      geo.window = g;
      const c0 = sel.c - Math.floor(kw / 2);
      const r0 = sel.r - Math.floor(kh / 2);
      // the kernel's footprint, cut to the window (the border policy supplies the rest)
      const fc0 = Math.max(c0, 0);
      const fr0 = Math.max(r0, 0);
      const fc1 = Math.min(c0 + kw, g.cols);
      const fr1 = Math.min(r0 + kh, g.rows);
      if (fc1 > fc0 && fr1 > fr0) outline(ctx, g, fc0, fr0, fc1 - fc0, fr1 - fr0, { fill: COLORS.highlightFill, dash: fc0 !== c0 || fr0 !== r0 || fc1 !== c0 + kw || fr1 !== r0 + kh ? [6, 3] : null });
      outline(ctx, g, sel.c, sel.r, 1, 1, { width: 1.5 });
      if (d.kernels.length === 1 && L.cell >= GRID.weightFrom) {
        d.kernels[0].m.forEach((row, j) =>
          row.forEach((n, i) => {
            const cc = c0 + i;
            const rr = r0 + j;
            if (cc < 0 || rr < 0 || cc >= g.cols || rr >= g.rows) return;
            text(ctx, `×${fmt(n)}`, g.x0 + (cc + 1) * g.cell - 3, g.y0 + rr * g.cell + 7, { align: "right", size: 9.5, color: COLORS.highlight, weight: "bold" });
          }),
        );
      }
    } else if (p.kind === "kernel") {
      // weights, not grey values: shaded only on the diverging scale when some are negative
      const shade = signedMatrix(p.mat) ? shader(p.mat) : PLAIN_SHADE;
      drawGrid(ctx, p.mat, p.x, p.y, L.cell, { title: fitTitle(p, width), shade });
      signed = signed || shade.signed;
    } else if (p.kind === "median") {
      const blank = p.mat.map((r) => r.map(() => NaN));
      const g = drawGrid(ctx, blank, p.x, p.y, L.cell, { title: "Median 3×3" });
      text(ctx, "middle of 9", g.x0 + g.w / 2, g.y0 + g.h / 2, { align: "center", size: FONT_SIZE_SMALL, color: COLORS.muted, halo: true });
    } else {
      const i = d.outputs.indexOf(p.item);
      const shade = shader(p.mat, p.item.short ?? p.item.name);
      if (shade.signed) signed = true;
      if (shade.scale) greys.push(shade.scale);
      const g = drawGrid(ctx, p.mat, p.x, p.y, L.cell, { title: fitTitle(p, width), first: d.first, shade });
      geo[`output${i}`] = g;
      // motion: the outputs after the frame's pixel are not computed yet
      ctx.fillStyle = COLORS.background;
      for (let k = d.frame ? d.frame.index + 1 : g.rows * g.cols; k < g.rows * g.cols; k++) ctx.fillRect(g.x0 + (k % g.cols) * g.cell + 1, g.y0 + Math.floor(k / g.cols) * g.cell + 1, g.cell - 2, g.cell - 2);
      const oc = sel.c - (d.first.c - 1);
      const or = sel.r - (d.first.r - 1);
      if (oc >= 0 && or >= 0 && oc < g.cols && or < g.rows) outline(ctx, g, oc, or, 1, 1);
    }
  });
  const y = L.gridsBottom + GRID.sumGap;
  textBlock(ctx, L.lines, GRID.margin, y, { size: L.sumSize });
  // the legends, one a line: each grey scale's, then the diverging scale's
  let ly = L.legendTop;
  for (const scale of greys) {
    greyLegend(ctx, GRID.margin, ly, scale, { maxWidth: width - 2 * GRID.margin });
    ly += GRID.legendLine;
  }
  if (signed) signedLegend(ctx, GRID.margin, ly + GREY_LEGEND.height / 2);
  return { L, geo };
}

// ---------------------------------------------------------------------------
// Interaction: click a pixel of the window or of an output; arrows move it.

function selectionInteract(dataOf) {
  return {
    hint: "Click a pixel of the window (or of an output grid) to write out its sum; with the figure focused, the arrow keys move the selection.",
    pointer(x, y, width, height, solution) {
      const d = dataOf(solution);
      if (!d) return null;
      const L = layout(width, d);
      for (const p of L.panels) {
        if (p.kind !== "window" && p.kind !== "output") continue;
        const g = { x0: p.x, y0: p.y, cell: L.cell, cols: p.mat[0].length, rows: p.mat.length };
        const hit = cellAt(g, x, y);
        if (!hit) continue;
        const off = p.kind === "output" ? { c: d.first.c - 1, r: d.first.r - 1 } : { c: 0, r: 0 };
        return { select_c: String(hit.c + 1 + off.c), select_r: String(hit.r + 1 + off.r) };
      }
      return null;
    },
    key(key, solution) {
      const d = dataOf(solution);
      if (!d) return null;
      const step = arrowStep(key);
      if (!step) return null;
      const [dc, dr] = step;
      const c = Math.min(Math.max(d.sel.c + dc, 1), d.window[0].length);
      const r = Math.min(Math.max(d.sel.r + dr, 1), d.window.length);
      return c === d.sel.c && r === d.sel.r ? null : { select_c: String(c), select_r: String(r) };
    },
  };
}

/** The Data view (index.js tables()): the window (the selected pixel and the kernel's footprint in words), kernels, outputs, the sum. */
const tablesOf = (dataOf, what) => (solution) => {
  const d = dataOf(solution);
  if (!d) return { summary: `The window and its ${what}.`, tables: [] };
  const kw = d.kernels[0]?.m[0].length ?? 3;
  const kh = d.kernels[0]?.m.length ?? 3;
  const c0 = d.sel.c - 1 - Math.floor(kw / 2);
  const r0 = d.sel.r - 1 - Math.floor(kh / 2);
  const inWindow = (r, c) => [r === d.sel.r - 1 && c === d.sel.c - 1 ? "selected" : null, r >= r0 && r < r0 + kh && c >= c0 && c < c0 + kw ? "under the kernel" : null].filter(Boolean).join(", ");
  const atSel = (r, c) => (r + d.first.r === d.sel.r && c + d.first.c === d.sel.c ? "selected" : null);
  const values = d.outputs.map((o) => `${o.short ?? o.name} = ${fmt(o.value, 6)}`).join(", ");
  const outputs = d.outputs.map((o) => matrixTable(`${o.name} (output, at the window's columns and rows)`, o.m, { format: (v) => fmt(v, 6, "no value"), first: d.first, mark: atSel }));
  return {
    summary: `A ${d.window.length}×${d.window[0].length} window; the selected pixel is at row ${d.sel.r}, column ${d.sel.c}: ${values}. Outputs cover columns ${d.first.c}–${d.first.c + d.outputs[0].m[0].length - 1} and rows ${d.first.r}–${d.first.r + d.outputs[0].m.length - 1}.`,
    tables: [
      matrixTable("Window f (grey values)", d.window, { format: (v) => fmt(v, 6, "no value"), mark: inWindow }),
      ...d.kernels.map((k) => matrixTable(k.name, k.m, { format: (v) => fmt(v, 6, "no value"), first: { c: 1, r: 1 } })),
      ...outputs,
      seriesTable("The selected pixel's sum, as written under the grids", ["line"], sumLines(d).map((l) => [l.text.trim()])),
    ],
  };
};

const filterSpec = layoutSpec({
  tables: tablesOf(filterData, "filtered output"),
  caption:
    "The window with the kernel laid over the selected pixel (orange frame, the kernel's weights in the corners of its cells), the kernel, and the output grid (shaded on a diverging scale, blue below 0 and orange above, when it has negative values; otherwise in grey, dark = low as in an image, with its legend). Below: the selected pixel's multiply-and-sum, one line per kernel row.",
  data: filterData,
  layout,
  draw: drawFigure,
  describe(solution) {
    const d = filterData(solution);
    if (!d) return "The window and its filtered output.";
    const k = d.median ? "the 3×3 median" : `a ${d.kernels[0]?.m.length}×${d.kernels[0]?.m[0].length} kernel`;
    return `A ${d.window.length}×${d.window[0].length} window filtered with ${k}; output ${d.output.length}×${d.output[0].length}. Selected pixel row ${d.sel.r}, column ${d.sel.c}: output ${fmt(d.selected, 6)}.`;
  },
  interact: selectionInteract(filterData),
});

const edgeSpec = layoutSpec({
  tables: tablesOf(edgeData, "edge responses"),
  caption:
    "The window with the 3×3 neighbourhood of the selected pixel framed in orange, the two kernels, then Gx, Gy (diverging scale: blue below 0, orange above) and the edge magnitude (grey, dark = low as in an image, with its legend). Below: the selected pixel's sums, one line per kernel row, and its magnitude.",
  data: edgeData,
  layout,
  draw: drawFigure,
  describe(solution) {
    const d = edgeData(solution);
    if (!d) return "The window and its edge responses.";
    return `A ${d.window.length}×${d.window[0].length} window with its edge responses Gx, Gy and magnitude. Selected pixel row ${d.sel.r}, column ${d.sel.c}: Gx = ${fmt(d.kernels[0]?.value)}, Gy = ${fmt(d.kernels[1]?.value)}, magnitude ${fmt(d.magnitude, 6)}.`;
  },
  interact: selectionInteract(edgeData),
});

// ---------------------------------------------------------------------------
// Motion (issue 34; index.js `frames`): the kernel moving over the window, one
// output pixel a frame, each output value appearing; the values are the
// solution's output grids (the selected pixel's sum is written out as before).

function moving(spec, dataOf, noun) {
  const index = (solution) => (solution.steps ?? []).findIndex((s) => s.values && Object.hasOwn(s.values, "neighbourhood"));
  const last = (solution) => (solution.steps ?? []).findLastIndex((s) => s.values && Object.hasOwn(s.values, "output_first_c"));
  spec.frames = (solution) => {
    const d = dataOf(solution);
    if (!d) return [];
    const out = d.outputs[0].m;
    const cols = out[0].length;
    const kh = d.kernels[0]?.m.length ?? 3;
    const kw = d.kernels[0]?.m[0].length ?? 3;
    return out.flatMap((row, r) =>
      row.map((_, c) => {
        const at = { c: d.first.c + c, r: d.first.r + r };
        const selected = at.c === d.sel.c && at.r === d.sel.r;
        const values = d.outputs.map((o) => `${o.short ?? o.name.replace(/^Output /, "")} = ${fmt(o.m[r]?.[c], 6, "no value")}`).join(", ");
        const k = r * cols + c;
        return {
          index: k,
          ...at,
          selected,
          sel: d.sel,
          values: `At row ${at.r}, column ${at.c}: ${values}`,
          step: selected && index(solution) >= 0 ? index(solution) : last(solution) >= 0 ? last(solution) : null,
          caption: `${noun[0].toUpperCase()}${noun.slice(1)} ${k + 1}: the kernel over rows ${at.r - Math.floor(kh / 2)}–${at.r - Math.floor(kh / 2) + kh - 1}, columns ${at.c - Math.floor(kw / 2)}–${at.c - Math.floor(kw / 2) + kw - 1} of the window; at row ${at.r}, column ${at.c}: ${values}.`,
        };
      }),
    );
  };
  spec.motion = { noun };
  const draw = spec.draw;
  spec.draw = (ctx, width, height, solution, state) => {
    const f = state?.frame;
    if (!f) return draw(ctx, width, height, solution);
    const d = dataOf(solution);
    if (d) drawFigure(ctx, width, { ...d, sel: { c: f.c, r: f.r }, frame: f });
  };
}
moving(filterSpec, filterData, "output pixel");
moving(edgeSpec, edgeData, "output pixel");

// Preset buttons: the seeds' windows with their kernels (the help texts list them too).
const grid = (rows) => rows.map((r) => r.join(" ")).join("\n");
const EXAMPLE_15 = [[10, 13, 3, 11, 13], [11, 15, 10, 9, 9], [9, 24, 7, 8, 10], [10, 13, 14, 15, 13], [13, 18, 17, 19, 21]];
const EXAMPLE_16 = [[1, 2, 1, 1, 1], [1, 1, 9, 2, 1], [1, 9, 9, 8, 1], [1, 1, 8, 1, 2], [2, 1, 1, 1, 1]];
const SEED_004 = [[5, 6, 7, 8, 9], [11, 10, 20, 30, 9], [31, 50, 60, 70, 9], [40, 30, 20, 10, 9], [58, 95, 105, 106, 98]];
const seed15 = { window: grid(EXAMPLE_15), select_c: "2", select_r: "2", border: "crop" };
filterSpec.actions = [
  { label: "Example 15: mean", inputs: () => ({ ...seed15, kernel: "mean" }) },
  { label: "Example 15: Gaussian", inputs: () => ({ ...seed15, kernel: "gaussian-3" }) },
  { label: "Example 16: Laplacian", inputs: () => ({ window: grid(EXAMPLE_16), kernel: "laplacian-8", select_c: "3", select_r: "3", border: "crop" }) },
  { label: "Lecture 7: mean (33)", inputs: () => ({ window: grid(SEED_004), kernel: "mean", select_c: "3", select_r: "3", border: "crop" }) },
];
edgeSpec.actions = [
  { label: "Example 15: Prewitt", inputs: () => ({ ...seed15, operator: "prewitt" }) },
  { label: "Example 15: Sobel", inputs: () => ({ ...seed15, operator: "sobel" }) },
];

export const figures = {
  "filter-window": filterSpec,
  "edge-window": edgeSpec,
};
