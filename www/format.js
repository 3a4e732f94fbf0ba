// Number formatting for the result table and the figures.

/** Significant digits shown for an exact (unrounded) value. */
export const EXACT_SIGNIFICANT_DIGITS = 6;
/** Beyond these magnitudes a number is written with an exponent. */
const EXPONENT_ABOVE = 1e9;
const EXPONENT_BELOW = 1e-5;
const MINUS = "\u2212";

function trimZeros(s) {
  // "35.6490" -> "35.649", "12.000" -> "12", "1.500e+3" -> "1.5e+3"
  return s.replace(/(\.\d*?)0+(?=$|e)/, "$1").replace(/\.(?=$|e)/, "");
}

/**
 * A number with at most `digits` significant digits, trailing zeros dropped,
 * and a real minus sign. Integers are written in full.
 */
export function formatNumber(value, digits = EXACT_SIGNIFICANT_DIGITS) {
  if (typeof value !== "number") return String(value);
  if (Number.isNaN(value)) return "NaN";
  if (!Number.isFinite(value)) return value > 0 ? "∞" : `${MINUS}∞`;
  if (Object.is(value, -0)) value = 0;
  const abs = Math.abs(value);
  let s;
  if (Number.isInteger(value) && abs < EXPONENT_ABOVE) {
    s = String(abs);
  } else if (abs !== 0 && (abs >= EXPONENT_ABOVE || abs < EXPONENT_BELOW)) {
    s = trimZeros(abs.toExponential(digits - 1)).replace("e+", "e");
  } else {
    s = trimZeros(abs.toPrecision(digits));
    if (s.includes("e")) s = trimZeros(abs.toFixed(Math.max(0, digits - 1)));
  }
  return value < 0 ? MINUS + s : s;
}

/** The number of decimals a printed number carries (12632 -> 0, 35.37 -> 2, 0.042 -> 3). */
export function printedDecimals(value) {
  if (typeof value !== "number" || !Number.isFinite(value)) return null;
  const s = String(Math.abs(value));
  const m = /^(\d+)(?:\.(\d+))?(?:e([-+]\d+))?$/.exec(s);
  if (!m) return null;
  const frac = m[2] ? m[2].length : 0;
  const exp = m[3] ? Number(m[3]) : 0;
  return Math.max(0, frac - exp);
}

/**
 * Any result value as text: numbers, vectors "[1, 2]", matrices "[[1, 2]; [3, 4]]",
 * strings, booleans, null.
 */
export function formatValue(value, digits = EXACT_SIGNIFICANT_DIGITS) {
  if (value === null || value === undefined) return "—";
  if (typeof value === "number") return formatNumber(value, digits);
  if (typeof value === "boolean") return value ? "yes" : "no";
  if (typeof value === "string") return value;
  if (Array.isArray(value)) {
    if (value.length > 0 && value.every(Array.isArray)) {
      return value.map((row) => formatValue(row, digits)).join("\n");
    }
    return `[${value.map((v) => formatValue(v, digits)).join(", ")}]`;
  }
  try {
    return JSON.stringify(value);
  } catch {
    return String(value);
  }
}

/**
 * exact − printed, for numbers and for arrays of the same shape.
 * Returns null when the two cannot be compared.
 */
export function difference(exact, printed) {
  if (typeof exact === "number" && typeof printed === "number") return exact - printed;
  if (Array.isArray(exact) && Array.isArray(printed) && exact.length === printed.length) {
    const out = exact.map((e, i) => difference(e, printed[i]));
    return out.some((d) => d === null) ? null : out;
  }
  return null;
}

/**
 * Whether the exact value rounds to the printed one at the printed number of
 * decimals (so the difference is only the printing). Arrays: every element.
 */
export function agreesWithPrinted(exact, printed) {
  if (typeof exact === "number" && typeof printed === "number") {
    const d = printedDecimals(printed);
    if (d === null) return false;
    const half = 0.5 * 10 ** -d;
    // a small tolerance for binary floating point at the rounding boundary
    return Math.abs(exact - printed) <= half * (1 + 1e-9);
  }
  if (Array.isArray(exact) && Array.isArray(printed) && exact.length === printed.length) {
    return exact.every((e, i) => agreesWithPrinted(e, printed[i]));
  }
  if (typeof exact === typeof printed) return exact === printed;
  return false;
}
