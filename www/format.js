// Number formatting for people: the result cards, the answer line and the
// figures. No floating-point noise (0.30000000000000004 is 0.3), no
// e-notation (a tiny value is written 1.8777 × 10⁻⁶), integers in full, a
// real minus sign; differences in one direction, exact − printed.

/** Significant digits shown for an exact (unrounded) value. */
export const EXACT_SIGNIFICANT_DIGITS = 6;
/** Significant digits every value is first rounded to: below this is binary noise. */
const NOISE_DIGITS = 12;
/** Beyond these magnitudes a number is written with a power of ten. */
const POWER_ABOVE = 1e9;
const POWER_BELOW = 1e-4;
const MINUS = "\u2212";
const SUPERSCRIPT = { "-": "⁻", 0: "⁰", 1: "¹", 2: "²", 3: "³", 4: "⁴", 5: "⁵", 6: "⁶", 7: "⁷", 8: "⁸", 9: "⁹" };

function trimZeros(s) {
  // "35.6490" -> "35.649", "12.000" -> "12"
  return s.includes(".") ? s.replace(/0+$/, "").replace(/\.$/, "") : s;
}

/** `value` with the binary noise beyond 12 significant digits removed. */
export function denoise(value) {
  if (typeof value !== "number" || !Number.isFinite(value) || value === 0) return value;
  return Number(value.toPrecision(NOISE_DIGITS));
}

/** Fixed-point text of |v| with `digits` significant digits, never e-notation. */
function fixed(abs, digits) {
  const magnitude = Math.floor(Math.log10(abs));
  const decimals = Math.max(0, digits - 1 - magnitude);
  return trimZeros(abs.toFixed(Math.min(decimals, 100)));
}

/**
 * A number with at most `digits` significant digits, trailing zeros dropped,
 * and a real minus sign. Integers are written in full; very large or very
 * small values as "m × 10ⁿ".
 */
export function formatNumber(value, digits = EXACT_SIGNIFICANT_DIGITS) {
  if (typeof value !== "number") return String(value);
  if (Number.isNaN(value)) return "NaN";
  if (!Number.isFinite(value)) return value > 0 ? "∞" : `${MINUS}∞`;
  value = denoise(value);
  if (Object.is(value, -0) || value === 0) return "0";
  const abs = Math.abs(value);
  let s;
  if (Number.isInteger(value) && abs < POWER_ABOVE) {
    s = String(abs);
  } else if (abs >= POWER_ABOVE || abs < POWER_BELOW) {
    const [m, e] = abs.toExponential(digits - 1).split("e");
    s = `${trimZeros(m)} × 10${[...String(Number(e))].map((c) => SUPERSCRIPT[c]).join("")}`;
  } else {
    s = fixed(abs, digits);
    if (s === "0") s = fixed(abs, digits + 1);
  }
  return value < 0 ? MINUS + s : s;
}

const FROM_SUPERSCRIPT = Object.fromEntries(Object.entries(SUPERSCRIPT).map(([k, v]) => [v, k]));

/**
 * How a screen reader should say a text with powers of ten written as
 * formatNumber writes them: "1.87772 × 10⁻⁶" → "1.87772 times 10 to the
 * minus 6" (superscript characters are read as "superscript minus", or not
 * at all). null when the text has none (it reads as shown).
 */
export function spokenNumber(text) {
  const said = String(text).replace(/ × 10([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)/g, (_, sup) => {
    const e = [...sup].map((c) => FROM_SUPERSCRIPT[c]).join("");
    return ` times 10 to the ${e.startsWith("-") ? `minus ${e.slice(1)}` : e}`;
  });
  return said === String(text) ? null : said;
}

/** A number with exactly as many decimals as needed up to `decimals` (never e-notation). */
export function formatDecimals(value, decimals) {
  if (typeof value !== "number" || !Number.isFinite(value)) return formatNumber(value);
  const s = trimZeros(Math.abs(denoise(value)).toFixed(Math.max(0, Math.min(decimals, 20))));
  return s === "0" ? "0" : (value < 0 ? MINUS : "") + s;
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
 * An exact value shown beside a printed one: at least the usual significant
 * digits, and two decimals more than the print, so the comparison is visible.
 */
export function formatExact(value, printed) {
  if (typeof value !== "number") return formatValue(value);
  const d = printedDecimals(typeof printed === "number" ? printed : NaN);
  if (d === null || !Number.isFinite(value) || value === 0) return formatNumber(value);
  const abs = Math.abs(value);
  if (abs >= POWER_ABOVE || abs < POWER_BELOW) return formatNumber(value);
  const sig = Math.max(EXACT_SIGNIFICANT_DIGITS, Math.floor(Math.log10(abs)) + 1 + d + 2);
  return formatNumber(value, Math.min(sig, 15));
}

/**
 * Any result value as text: numbers, vectors "[1, 2]", matrices one row per
 * line, strings, booleans ("yes"/"no"), null ("—").
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
  if (typeof exact === "number" && typeof printed === "number") return denoise(exact - printed);
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

/**
 * exact − printed as people write it: "0" when the exact value rounds to the
 * printed one (the difference is only the printing), otherwise with a sign
 * and one decimal more than the print carries (at least two significant
 * digits). Non-numbers give null.
 */
export function formatDifference(exact, printed) {
  if (typeof exact !== "number" || typeof printed !== "number") return null;
  if (agreesWithPrinted(exact, printed)) return "0";
  const d = denoise(exact - printed);
  const decimals = printedDecimals(printed) ?? 3;
  const abs = Math.abs(d);
  // one decimal more than the print, at least the first significant digit, at most four of them
  const lead = abs > 0 ? Math.floor(Math.log10(abs)) : 0;
  const needed = Math.min(Math.max(decimals + 1, 1 - lead), 3 - lead);
  const s = formatDecimals(d, needed);
  return d > 0 ? `+${s}` : s;
}
