// The sweep's part of an address (issue 34; docs/sweeps.md): read and written
// here, checked for syntax only (embed-options.js calls it when it reads the
// link; www/sweep/series.js checks the names against the example). Small and
// without imports: it is on the page's first load.
//
//   sweep=<field>:<from>:<to>:<steps>   e.g. sweep=flying_height_m:500:3000:100
//   plot=<result>,<result>              e.g. plot=gsd_cm
//   grid=<field>:<from>:<to>:<rows>     the two-input table: a second input's rows
//                                       (2–11) beside the sweep, of plot='s first result

/** Field kinds a sweep can run over (an angle is a number of degrees). */
export const SWEEPABLE = Object.freeze(["number", "integer", "angle"]);
/** Points of a sweep: at least two, at most this many (the slider's stops; a solve each). */
export const MIN_STEPS = 2;
export const MAX_STEPS = 500;
/** Rows of the two-input table at most (and its columns: the sweep's points, at most this many). */
export const MAX_GRID_ROWS = 11;
/** Results plotted at once. */
export const MAX_PLOTTED = 4;
/** Significant digits of a swept value: the text the form gets reads back as the same number. */
const DIGITS = 12;
/** A number as the link writes it: plain decimal or exponent notation, nothing else. */
const LINK_NUMBER = /^[-+]?(\d+\.?\d*|\.\d+)(e[-+]?\d+)?$/i;
/** A field key or a result key in the link. */
const KEY = /^[A-Za-z][A-Za-z0-9_]{0,63}$/;

/** A value rounded to DIGITS significant digits (0.1 + 0.2 is 0.3 here). */
export function tidy(v) {
  return v === 0 ? 0 : Number(v.toPrecision(DIGITS));
}

/** A swept value as the form's text (JS's shortest form: the core reads back the same double). */
export function valueText(v) {
  return String(tidy(v));
}

/** The link's value for a sweep: "key:from:to:steps". */
export function formatSweep({ key, from, to, steps }) {
  return `${key}:${valueText(from)}:${valueText(to)}:${Math.round(steps)}`;
}

/**
 * Reads a link's sweep value (syntax only; the example's fields are checked by checkSweep).
 * @returns {{ spec: { key, from, to, steps } } | { error: string }}  error: a worded message
 */
export function parseSweep(text) {
  return parseRange(text, { usage: "write it as field:from:to:steps, e.g. sweep=flying_height_m:500:3000:100", what: "a sweep", count: "steps", max: MAX_STEPS });
}

/**
 * Reads a link's grid value: the two-input table's second input and its rows
 * (syntax only; grid.js checks the field against the example and the sweep).
 * @returns {{ spec: { key, from, to, steps } } | { error: string }}
 */
export function parseGrid(text) {
  return parseRange(text, { usage: "write it as field:from:to:rows, e.g. grid=focal_length_mm:100:300:5", what: "a table", count: "rows", max: MAX_GRID_ROWS });
}

/** "key:from:to:count" read: a key, two different plain numbers, a whole count from MIN_STEPS to `max`. */
function parseRange(text, { usage, what, count, max }) {
  const parts = String(text).trim().split(":");
  if (parts.length !== 4) return { error: `it has ${parts.length} part${parts.length === 1 ? "" : "s"}; ${usage}` };
  const [key, a, b, n] = parts.map((p) => p.trim());
  if (!KEY.test(key)) return { error: `the field name must be letters, digits and _ (${usage})` };
  if (!LINK_NUMBER.test(a) || !Number.isFinite(Number(a))) return { error: `“from” is not a number; ${usage}` };
  if (!LINK_NUMBER.test(b) || !Number.isFinite(Number(b))) return { error: `“to” is not a number; ${usage}` };
  if (Number(a) === Number(b)) return { error: `“from” and “to” are the same value: ${what} needs a range` };
  if (!/^\d{1,4}$/.test(n) || Number(n) < MIN_STEPS || Number(n) > max) return { error: `the ${count} must be a whole number from ${MIN_STEPS} to ${max}` };
  return { spec: { key, from: Number(a), to: Number(b), steps: Number(n) } };
}

/** Reads a link's plot value: result keys separated by commas (each checked against a solution by checkPlot). */
export function parsePlot(text) {
  const keys = String(text)
    .split(",")
    .map((k) => k.trim())
    .filter(Boolean);
  if (!keys.length) return { error: "name one or more results, e.g. plot=gsd_cm" };
  const bad = keys.find((k) => !KEY.test(k));
  if (bad !== undefined) return { error: "result names are letters, digits and _, separated by commas" };
  if (keys.length > MAX_PLOTTED) return { error: `at most ${MAX_PLOTTED} results at once` };
  return { keys: [...new Set(keys)] };
}

