// A sweep (issue 34; docs/sweeps.md): one numeric input of an example run over
// a range, every point solved by the core exactly as the page solves it —
// solve(id, inputs with that value) — and the chosen numeric results read off.
// The points are solved in one call of the core's solveSeries (the wasm export
// solve_series: the same solver per point, without building the steps, only
// the chosen results coming back). Pure functions, no DOM: the page
// (www/sweep/sweep.js) and Node's tests (tests/e2e/sweep-series.test.mjs, with
// the real core, point by point against solve) call the same code.
//
// The link's form (url.js carries it beside the inputs, embed-options.js
// checks its syntax): sweep=<field>:<from>:<to>:<steps>&plot=<key>,<key>
//   sweep=flying_height_m:500:3000:100&plot=gsd_cm  (link.js reads and writes it)

import { MAX_STEPS, MIN_STEPS, SWEEPABLE, tidy } from "./link.js";

export { formatSweep, MAX_PLOTTED, MAX_STEPS, MIN_STEPS, parsePlot, parseSweep, SWEEPABLE, tidy, valueText } from "./link.js";

/** The steps a new sweep takes when the range allows it. */
export const DEFAULT_STEPS = 50;

/** The number fields an entry can sweep, in form order. */
export function sweepableFields(entry) {
  return (entry?.inputs ?? []).filter((f) => SWEEPABLE.includes(f.kind));
}

/** Whether field `f` applies with these texts (its `when`; a missing controlling field counts as its default). */
export function fieldApplies(entry, f, texts = {}) {
  if (!f.when) return true;
  const ctl = (entry.inputs ?? []).find((g) => g.key === f.when.key);
  const value = Object.hasOwn(texts, f.when.key) ? texts[f.when.key] : (ctl?.default_text ?? String(ctl?.default ?? ""));
  return (f.when.values ?? []).map(String).includes(String(value));
}

/** The lowest / highest value a field takes (±Infinity when unbounded). */
function bounds(field) {
  return { lo: field.min ?? -Infinity, hi: field.max ?? Infinity, loOpen: Boolean(field.min_exclusive) };
}

/** A range `from`–`to` of field `field` clamped to its bounds (whole numbers for an integer), or null when nothing is left. */
function clampRange(field, from, to) {
  const { lo, hi, loOpen } = bounds(field);
  let a = from;
  let b = Math.min(to, hi);
  // an open minimum (> 0): start a small step above it
  if (a < lo || (loOpen && a <= lo)) a = loOpen ? lo + (b - lo) / DEFAULT_STEPS : lo;
  if (field.kind === "integer") {
    a = Math.ceil(a);
    b = Math.floor(b);
  }
  if (!(b > a)) return null;
  const span = field.kind === "integer" ? b - a + 1 : Infinity;
  return { from: tidy(a), to: tidy(b), steps: Math.max(MIN_STEPS, Math.min(DEFAULT_STEPS, span)) };
}

/**
 * Ranges around value `value`, widest first: half to twice it (±10 around
 * zero), ±10 %, ±5 and ±2 (whole steps for an integer), each within the
 * field's bounds.
 */
export function candidateRanges(field, value) {
  const v = Number.isFinite(value) ? value : Number.isFinite(field.default) ? field.default : 0;
  const a = Math.abs(v);
  const spans = [v === 0 ? [-10, 10] : [Math.min(v / 2, v * 2), Math.max(v / 2, v * 2)], [v - a / 10, v + a / 10], [v - 5, v + 5], [v - 2, v + 2]];
  const out = [];
  for (const [from, to] of spans) {
    const r = clampRange(field, from, to);
    if (r && !out.some((o) => o.from === r.from && o.to === r.to)) out.push(r);
  }
  if (!out.length) {
    // a bound right at the value: whatever the bounds allow
    const { lo, hi } = bounds(field);
    out.push(clampRange(field, Number.isFinite(lo) ? lo : v - 1, Number.isFinite(hi) ? hi : v + 1) ?? { from: v - 1, to: v + 1, steps: MIN_STEPS });
  }
  return out;
}

/** The first candidate range (defaultRange without a solver). */
export function defaultRange(field, value) {
  return candidateRanges(field, value)[0];
}

/** Points tried per candidate range by chooseRange. */
const PROBE = 11;

/**
 * A sensible range around the current value: the widest candidate range
 * (candidateRanges) on which at least half of a few probe points solve (a
 * window position, say, solves only near its value), else the one where
 * most do. `solveSeries` is the core's (see computeSeries); null takes the
 * first candidate (nothing to probe with).
 */
export function chooseRange(solveSeries, id, inputs, field, value) {
  const candidates = candidateRanges(field, value);
  if (!solveSeries) return candidates[0];
  let best = candidates[0];
  let bestCount = -1;
  for (const r of candidates) {
    const xs = sweepValues({ ...r, steps: PROBE }, field.kind === "integer");
    const ok = computeSeries(solveSeries, id, inputs, field.key, xs, []).points.filter((p) => !p.error).length;
    if (ok * 2 >= xs.length) return r;
    if (ok > bestCount) [best, bestCount] = [r, ok];
  }
  return best;
}

/**
 * The swept values: `steps` points from `from` to `to` (either way round),
 * evenly spaced; an integer field's rounded, repeats left out.
 */
export function sweepValues({ from, to, steps }, integer = false) {
  const n = Math.max(MIN_STEPS, Math.min(MAX_STEPS, Math.round(steps)));
  const out = [];
  for (let i = 0; i < n; i++) {
    let v = i === n - 1 ? to : from + ((to - from) * i) / (n - 1);
    v = integer ? Math.round(v) : tidy(v);
    if (!out.length || out[out.length - 1] !== v) out.push(v);
  }
  return out;
}

/** The result keys of a solution whose value is a number (or null/NaN: a number that has no value here). */
export function numericResultKeys(solution) {
  return Object.entries(solution?.result ?? {})
    .filter(([, v]) => typeof v === "number")
    .map(([k]) => k);
}

/**
 * One end of a range typed in a box, read by the core as input `key`'s own
 * box (`parseInputs`: its unit, a decimal comma, its bounds): { value }, or
 * { error } in the reader's words, named by the box (`name`: "From").
 */
export function readEnd(parseInputs, id, key, text, name) {
  let r;
  try {
    r = parseInputs(id, { [key]: text });
  } catch (e) {
    return { error: `“${name}”: ${messageOf(e)}` };
  }
  const v = r.inputs?.[key];
  if (typeof v === "number") return { value: v };
  const m = r.errors?.[key] ?? "not a number";
  return { error: `“${name}”: ${m.startsWith(`${key}: `) ? m.slice(key.length + 2) : m}` };
}

/** An error's message, whatever was thrown. */
function messageOf(e) {
  return e && typeof e.message === "string" ? e.message : String(e);
}

/**
 * Solves every point: solve(id, { ...inputs, [key]: x }) for each x of
 * `values`, and reads `plot`'s results off each solution — in one call of
 * `solveSeries` (the core's: www/core.js solveSeries, the wasm export
 * solve_series), which runs the same solver per point without building its
 * steps and returns { results: { k: [value…] }, errors: [message|null…] }.
 * A call that throws (an example whose module is not loaded, say) gives
 * every point its message, as solve would have at each.
 * @param {(id: string, inputs: object, key: string, values: number[], plot: string[]) =>
 *          { results: Record<string, any[]>, errors: (string|null)[] }} solveSeries
 * @returns {{ key, plot, xs: number[], ys: Record<string, (number|null)[]>,
 *             points: Array<{ x: number, error: string|null, result: object|null }> }}
 *   ys[k][i] is null where point i has no number: the solver's error (points[i].error), or a result without a value
 */
export function computeSeries(solveSeries, id, inputs, key, values, plot) {
  let out = null;
  let failed = null;
  try {
    out = solveSeries(id, inputs, key, [...values], [...plot]);
  } catch (e) {
    failed = messageOf(e);
  }
  const ys = Object.fromEntries(plot.map((k) => [k, []]));
  const points = values.map((x, i) => {
    const error = failed ?? out.errors[i] ?? null;
    const result = error ? null : Object.fromEntries(plot.map((k) => [k, out.results[k][i] ?? null]));
    for (const k of plot) {
      const y = result?.[k];
      ys[k].push(typeof y === "number" && Number.isFinite(y) ? y : null);
    }
    return { x, error, result };
  });
  return { key, plot: [...plot], xs: [...values], ys, points };
}

/**
 * One result over a grid of two inputs: values[i][j] = result `k` of
 * solve(id, { ...inputs, [keyY]: ys[i], [keyX]: xs[j] }) (null where it has
 * none), errors[i][j] the solver's message or null.
 */
export function computeGrid(solveSeries, id, inputs, keyX, xs, keyY, ys, k) {
  const rows = ys.map((y) => computeSeries(solveSeries, id, { ...inputs, [keyY]: y }, keyX, xs, [k]));
  return { keyX, keyY, k, xs: [...xs], ys: [...ys], values: rows.map((r) => r.ys[k]), errors: rows.map((r) => r.points.map((p) => p.error)) };
}

/** Why point i has no value for result k (the solver's message, or that the result has none there). */
export function gapReason(series, i, k) {
  const p = series.points[i];
  if (p.error) return p.error;
  if (series.ys[k]?.[i] === null) return `${k} has no value here`;
  return null;
}

/** A sweep spec against an example's fields: null when it fits, else a worded message. */
export function checkSweep(entry, spec) {
  const fields = sweepableFields(entry);
  const f = fields.find((g) => g.key === spec.key);
  if (!f) {
    const any = (entry.inputs ?? []).some((g) => g.key === spec.key);
    const which = fields.length ? `the number inputs here are ${fields.map((g) => g.key).join(", ")}` : "this example has no number input";
    return any ? `${spec.key} is not a number input; ${which}` : `this example has no input ${spec.key}; ${which}`;
  }
  return null;
}

/** Plot keys against a solution's numeric results: { keys, unknown }. */
export function checkPlot(solution, keys) {
  const numeric = numericResultKeys(solution);
  return { keys: keys.filter((k) => numeric.includes(k)), unknown: keys.filter((k) => !numeric.includes(k)) };
}

/** The series as CSV: the swept input, then each result (full precision), then the solver's message where a point has none. */
export function seriesCsv(series, { xLabel, labels = {} } = {}) {
  const head = [xLabel ?? series.key, ...series.plot.map((k) => labels[k] ?? k), "error"];
  const field = (s) => (/[",\n\r]/.test(s) ? `"${s.replace(/"/g, '""')}"` : s);
  const rows = series.xs.map((x, i) => [String(x), ...series.plot.map((k) => (series.ys[k][i] === null ? "" : String(series.ys[k][i]))), series.points[i].error ?? ""]);
  return `${[head, ...rows].map((r) => r.map(field).join(",")).join("\r\n")}\r\n`;
}
