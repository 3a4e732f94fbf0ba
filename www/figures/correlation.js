// The correlation figures (drawn in correlation-draw.js) with their Data views (index.js:
// tables(solution, state)): every number read from the solution the figure
// is drawn from, formatted as the figure writes it. The registry loads the
// topic from here (index.js MODULES).

import { figures as drawn, ncc1d, ncc2d, nccSurface, subpixel1d, subpixel2d, deviations2d, isNum, lines1d, lines2d, linesSurface, oneD, parabolaData, quadricData, selected1d, selectedSurface, stepWith, surf, twoD, NONE, RHO_DIGITS, VALUE_DIGITS } from "./correlation-draw.js";
import { fmt } from "./draw.js";
import { columnsFrom, matrixTable, seriesTable } from "./data-view.js";

const rho = (v) => fmt(v, RHO_DIGITS, NONE);
const val = (v) => fmt(v, VALUE_DIGITS, NONE);
const mat = (v) => (Array.isArray(v) ? v.filter(Array.isArray) : []);

/** The lowest and highest finite entries of a matrix: { lo: [r, c, v], hi: [r, c, v] } (null when none). */
function extremes(m) {
  let lo = null;
  let hi = null;
  m.forEach((row, r) =>
    row.forEach((v, c) => {
      if (!isNum(v)) return;
      if (!lo || v < lo[2]) lo = [r, c, v];
      if (!hi || v > hi[2]) hi = [r, c, v];
    }),
  );
  return lo ? { lo, hi } : null;
}

function ncc1dTables(solution, state) {
  const d = oneD(solution);
  if (!d.rho.length) return { summary: "No positions.", tables: [] };
  const k = selected1d(d, state);
  const centres = Array.isArray(solution.result?.centres) ? solution.result.centres : [];
  const at = (i) => `position ${i + 1} (window centre at column ${centres[i] ?? "?"} of S)`;
  const ex = extremes([d.rho]);
  const summary = ex
    ? `ρ is highest, ${rho(ex.hi[2])}, at ${at(ex.hi[1])}, and lowest, ${rho(ex.lo[2])}, at ${at(ex.lo[1])}, of the ${d.rho.length} positions of the ${d.template.length}-value template along the ${d.search.length}-value search array. Selected: position ${k + 1}, ρ = ${rho(d.rho[k])}.`
    : `None of the ${d.rho.length} positions has a ρ.`;
  const rows = d.rho.map((r, i) => [String(i + 1), String(centres[i] ?? ""), val(d.means[i]), rho(r)]);
  const marks = d.rho.map((_, i) => [null, null, null, [i === d.best ? "best" : null, i === k ? "selected" : null].filter(Boolean).join(", ") || null]);
  const n = Math.max(d.search.length, d.template.length);
  return {
    summary,
    tables: [
      seriesTable("ρ at each position (the bars)", ["position", "window centre, column of S", "B̄, mean of the window", "ρ"], rows, marks),
      {
        caption: "The search array S and the template A",
        corner: "",
        columns: columnsFrom(n),
        rowHeaders: ["S", "A"],
        rows: [d.search, d.template].map((xs) => Array.from({ length: n }, (_, i) => (i < xs.length ? val(xs[i]) : ""))),
        marks: [Array.from({ length: n }, (_, i) => (i >= k && i < k + d.template.length ? "under the selected window" : null)), Array(n).fill(null)],
      },
    ],
  };
}

function ncc2dTables(solution, state) {
  const d = twoD(solution);
  const cols = d.a[0]?.length ?? 0;
  const total = d.a.length * cols;
  const sel = Number.isInteger(state?.i) && state.i < total ? state.i : null;
  const mark = (r, c) => (sel === r * cols + c ? "selected" : null);
  const steps = stepWith(solution, "da");
  const da = mat(steps.da);
  const db = mat(steps.db);
  const pairs = da.flatMap((row, r) => row.map((x, c) => [`row ${r + 1}, column ${c + 1}`, val(x), val(db[r]?.[c])]));
  return {
    summary: `ρ = ${rho(d.rho)} between the ${d.a.length} × ${cols} arrays A (mean Ā = ${val(d.ma)}) and B (mean B̄ = ${val(d.mb)}): Σ(A−Ā)(B−B̄) = ${val(d.res.sum_dadb)}, Σ(A−Ā)² = ${val(d.res.sum_da2)}, Σ(B−B̄)² = ${val(d.res.sum_db2)}.${sel === null ? "" : ` Selected: row ${Math.floor(sel / cols) + 1}, column ${(sel % cols) + 1}.`}`,
    tables: [
      matrixTable("A (grey values)", d.a, { format: val, mark }),
      matrixTable("B (grey values)", d.b, { format: val, mark }),
      seriesTable("The deviation pairs (the points of the scatter)", ["cell", "A − Ā", "B − B̄"], pairs, pairs.map((_, i) => [i === sel ? "selected" : null, null, null])),
    ],
  };
}

function surfaceTables(solution, state) {
  const d = surf(solution);
  if (!d.h) return { summary: "No positions.", tables: [] };
  const [r, c] = selectedSurface(d, state);
  const th = d.template.length;
  const tw = d.template[0]?.length ?? 0;
  const ex = extremes(d.rho);
  const place = ([rr, cc]) => `row ${rr + 1}, column ${cc + 1} (position ${rr * d.w + cc + 1})`;
  const best = d.best ? `ρ is highest, ${rho(d.rho[d.best[0]]?.[d.best[1]])}, at ${place(d.best)} of the ${d.h} × ${d.w} search positions; the window's centre pixel is c = ${val(d.bestC)}, r = ${val(d.bestR)}.` : "No position has a ρ.";
  const low = ex ? ` Lowest: ${rho(ex.lo[2])} at ${place(ex.lo)}.` : "";
  const rhoMarks = (rr, cc) => [d.best && d.best[0] === rr && d.best[1] === cc ? "best" : null, rr === r && cc === c ? "selected" : null].filter(Boolean).join(", ");
  const inWindow = (rr, cc) => (rr >= r && rr < r + th && cc >= c && cc < c + tw ? "inside the selected window" : null);
  return {
    summary: `${best}${low} Selected: ${place([r, c])}, ρ = ${rho(d.rho[r]?.[c])}.`,
    tables: [
      matrixTable("ρ at every position (the heat map)", d.rho, {
        format: rho,
        mark: rhoMarks,
      }),
      matrixTable("Template T", d.template, { format: val }),
      matrixTable("Search array S", d.search, { format: val, mark: inWindow }),
    ],
  };
}

function parabolaTables(solution) {
  const d = parabolaData(solution);
  const pts = d.x.map((c, i) => `(${val(c)}, ${rho(d.y[i])})`).join(", ");
  const peak = isNum(d.cMax) ? `The parabola's maximum is at c = ${val(d.cMax)}, ρ = ${rho(d.rhoMax)}` : `The parabola has no maximum (${d.extremum ?? "a straight line"})`;
  const rows = d.x.map((c, i) => ["measured", val(c), rho(d.y[i])]);
  if (isNum(d.cMax)) rows.push(["peak of the parabola", val(d.cMax), rho(d.rhoMax)]);
  if (isNum(d.printedC)) rows.push(["peak from the printed ρ", val(d.printedC), ""]);
  return {
    summary: `${peak}; it passes through the three points ${pts}; coefficients a₀, a₁, a₂ = ${d.a.map(val).join(", ")}.`,
    tables: [seriesTable("The points and the peak", ["point", "c (column)", "ρ"], rows)],
  };
}

function quadricTables(solution) {
  const d = quadricData(solution);
  const ex = extremes(d.rho);
  const peak = isNum(d.cMax) ? `The fitted surface's maximum is at c = ${val(d.cMax)}, r = ${val(d.rMax)}` : `The fitted surface is not concave (${d.extremum}): no peak`;
  const hi = ex ? `; the highest of the nine ρ, ${rho(ex.hi[2])}, is at c = ${val(d.c[ex.hi[1]])}, r = ${val(d.r[ex.hi[0]])}` : "";
  return {
    summary: `${peak}${hi}.`,
    tables: [
      {
        caption: "The nine ρ (r downward, as in the image)",
        corner: "",
        columns: d.c.map((v) => `c = ${val(v)}`),
        rowHeaders: d.r.map((v) => `r = ${val(v)}`),
        rows: d.rho.map((row) => row.map(rho)),
        marks: ex ? d.rho.map((row, rr) => row.map((_, cc) => (rr === ex.hi[0] && cc === ex.hi[1] ? "highest" : null))) : undefined,
      },
      seriesTable("The fitted surface ρ = a₀ + a₁c + a₂r + a₃cr + a₄c² + a₅r²", ["coefficient", "value"], d.a.map((v, i) => [`a${"₀₁₂₃₄₅"[i]}`, val(v)])),
    ],
  };
}

// ---------------------------------------------------------------------------
// Motion (issue 34; index.js `frames`): the template moving position by position,
// ρ filling in, the best so far held. Every number is the solution's.

/** The index in solution.steps of the first step whose values satisfy `test`, or null. */
function stepIndex(solution, test) {
  const i = (solution.steps ?? []).findIndex((s) => s.values && test(s.values));
  return i >= 0 ? i : null;
}

/** For each position in order, the best (highest finite ρ) among it and those before it (null before any). */
function bestSoFar(rhos) {
  let best = null;
  return rhos.map((r, i) => {
    if (isNum(r) && (best === null || r > rhos[best])) best = i;
    return best;
  });
}

function ncc1dFrames(solution) {
  const d = oneD(solution);
  const held = bestSoFar(d.rho);
  const all = stepIndex(solution, (v) => Array.isArray(v.rho));
  return d.rho.map((_, k) => ({
    k,
    best: held[k],
    // the position's own step ("Sub-window k", shown for short arrays), else the step with every ρ
    step: stepIndex(solution, (v) => v.k === k + 1 && Object.hasOwn(v, "rho")) ?? all,
    get caption() {
      const [where, , , value] = lines1d(d, k);
      return `${where.text}. ${value.text}`;
    },
  }));
}

function surfaceFrames(solution) {
  const d = surf(solution);
  const order = d.rho.flatMap((row) => row);
  const held = bestSoFar(order);
  const all = stepIndex(solution, (v) => Array.isArray(v.rho));
  const inFull = stepIndex(solution, (v) => Object.hasOwn(v, "window") && Object.hasOwn(v, "position"));
  return order.map((_, index) => {
    const r = Math.floor(index / d.w);
    const c = index % d.w;
    const isBest = d.best && d.best[0] === r && d.best[1] === c;
    return {
      index,
      r,
      c,
      best: held[index] === null ? null : [Math.floor(held[index] / d.w), held[index] % d.w],
      // the best window's own step writes its numbers term by term
      step: isBest && inFull !== null ? inFull : all,
      get caption() {
        const [where, means, , value] = linesSurface(d, r, c);
        const v = d.rho[r]?.[c];
        const formula = isNum(v) ? `ρ = Σ(T−T̄)(B−B̄) / √(Σ(T−T̄)² Σ(B−B̄)²) = ${val(d.sumDadb[r]?.[c])} / √(${val(d.sumDa2)} × ${val(d.sumDb2[r]?.[c])}) = ${rho(v)}` : value.text;
        return `${where.text}. ${means.text}. ${formula}`;
      },
    };
  });
}

/** What each drawn spec gains here, by the spec (the ids are written once, in correlation.js). */
const ADDED = new Map([
  [ncc1d, { tables: ncc1dTables, frames: ncc1dFrames, motion: { noun: "position" }, frameAt: (solution, state) => selected1d(oneD(solution), state) }],
  [
    ncc2d,
    {
      tables: ncc2dTables,
      // the selected pair's product, read out when the arrow keys move it (it is drawn on the canvas too)
      status(solution, state) {
        const d = twoD(solution);
        const total = d.a.length * (d.a[0]?.length ?? 0);
        const sel = Number.isInteger(state?.i) && state.i < total ? state.i : null;
        // nothing selected: the canvas's ρ line alone would only repeat the figure
        if (sel === null) return "";
        const [rho, pair] = lines2d(d, sel, deviations2d(d));
        return `${pair.text}\n${rho.text}`;
      },
    },
  ],
  [
    nccSurface,
    {
      tables: surfaceTables,
      frames: surfaceFrames,
      motion: { noun: "position" },
      frameAt(solution, state) {
        const d = surf(solution);
        const [r, c] = selectedSurface(d, state);
        return r * d.w + c;
      },
    },
  ],
  [subpixel1d, { tables: parabolaTables }],
  [subpixel2d, { tables: quadricTables }],
]);

export const figures = Object.fromEntries(Object.entries(drawn).map(([id, spec]) => [id, { ...spec, ...ADDED.get(spec) }]));
