// Shared by the practice view and the worksheets: the givens of a variant as
// the student reads them, and a box's expected value in a solution.

import { el } from "../dom.js";

const MINUS = "\u2212";

/** A given exactly as generated (shortest round-trip form), with a real minus. */
export function givenNumber(x) {
  return typeof x === "number" ? String(x).replace("-", MINUS) : String(x);
}

function matrixTable(rows, columns = null) {
  const table = el("table", { class: "given-matrix" });
  if (columns) table.append(el("thead", {}, el("tr", {}, columns.map((c) => el("th", { scope: "col" }, c)))));
  const body = el("tbody");
  for (const row of rows) body.append(el("tr", {}, (Array.isArray(row) ? row : [row]).map((x) => el("td", {}, givenNumber(x)))));
  table.append(body);
  return table;
}

/** The givens of a variant as a definition list, labelled from the catalog's fields. */
export function renderGivens(entry, inputs) {
  const list = el("dl", { class: "givens" });
  for (const [key, value] of Object.entries(inputs)) {
    const field = entry.inputs.find((f) => f.key === key);
    const label = field?.label ?? key;
    let shown;
    if (Array.isArray(value) && value.length && value.every(Array.isArray)) {
      shown = matrixTable(value, field?.columns ?? null);
    } else if (Array.isArray(value)) {
      shown = el("span", { class: "given-vector" }, value.map(givenNumber).join(", "));
    } else if (field?.kind === "choice") {
      shown = el("span", {}, field.options?.find((o) => o.value === value)?.label ?? String(value));
    } else {
      shown = el("span", {}, givenNumber(value), field?.unit ? ` ${field.unit}` : "");
    }
    list.append(el("div", { class: "given" }, el("dt", {}, label), el("dd", {}, shown)));
  }
  return list;
}

/**
 * An expected value for the answer key: 7 significant digits, or more when
 * the box's tolerance (`{ atol, rtol }`) asks for them (a UTM easting to the
 * centimetre, ξ to 1e-9), so the key is never coarser than the tolerance.
 */
export function keyNumber(x, tolerance = null) {
  if (typeof x !== "number") return "—";
  if (Number.isInteger(x)) return givenNumber(x);
  let digits = 7;
  const allowed = tolerance ? (tolerance.atol ?? 0) + (tolerance.rtol ?? 0) * Math.abs(x) : 0;
  if (allowed > 0 && x !== 0) {
    // decimals to the tolerance's first digit: half a unit in the last place within it
    const decimals = Math.ceil(-Math.log10(allowed));
    digits = Math.min(15, Math.max(digits, Math.floor(Math.log10(Math.abs(x))) + 1 + decimals));
  }
  const s = Math.abs(x) >= 1e-4 && Math.abs(x) < 1e8 ? String(Number(x.toPrecision(digits))) : x.toExponential(digits - 1);
  return s.replace("-", MINUS);
}
