// Renders a Solution (docs/API.md) into plain DOM: steps, result table, notes.

import { el } from "./dom.js";
import { renderFormula } from "./math.js";
import { agreesWithPrinted, difference, formatNumber, formatValue } from "./format.js";

/** Significant digits of a printed-minus-exact difference. */
const DIFFERENCE_DIGITS = 4;
/** Note kinds with their own badge style; any other kind gets the neutral one. */
const NOTE_KINDS = ["erratum", "rounding", "convention", "warning"];

/** The steps as an ordered list. */
export function renderSteps(solution) {
  const list = el("ol", { class: "steps" });
  for (const step of solution.steps ?? []) {
    const item = el("li", { class: "step" }, el("h4", { class: "step-title" }, step.title ?? ""));
    if (step.text) item.append(el("p", { class: "step-text" }, step.text));
    if (step.formula) item.append(renderFormula(step.formula, "formula formula-symbolic"));
    if (step.substituted) item.append(renderFormula(step.substituted, "formula formula-substituted"));
    list.append(item);
  }
  if (!list.childElementCount) list.append(el("li", { class: "step" }, "This solution has no steps."));
  return list;
}

function signed(value) {
  if (typeof value === "number") {
    const s = formatNumber(value, DIFFERENCE_DIGITS);
    return value > 0 ? `+${s}` : s;
  }
  if (Array.isArray(value)) {
    if (value.length > 0 && value.every(Array.isArray)) return value.map(signed).join("\n");
    return `[${value.map(signed).join(", ")}]`;
  }
  return formatValue(value);
}

function valueCell(className, value) {
  const text = formatValue(value);
  const attrs = { class: className };
  if (typeof value === "number") attrs["data-value"] = String(value);
  if (Array.isArray(value)) attrs["data-value"] = JSON.stringify(value);
  const multiline = text.includes("\n");
  return el("td", attrs, el(multiline ? "pre" : "span", { class: "value" }, text));
}

/** The last step value named `key` (for textbook keys that are intermediates). */
function stepValue(solution, key) {
  let found;
  for (const step of solution.steps ?? []) {
    if (step.values && Object.hasOwn(step.values, key)) found = step.values[key];
  }
  return found;
}

/**
 * The result table: every result key with its exact value, and where the
 * seed prints the quantity (`textbook`), the printed value and the difference.
 */
export function renderResult(solution) {
  const result = solution.result ?? {};
  const textbook = solution.textbook ?? null;
  const rows = Object.keys(result).map((key) => ({ key, exact: result[key], intermediate: false }));
  if (textbook) {
    for (const key of Object.keys(textbook)) {
      if (!Object.hasOwn(result, key)) rows.push({ key, exact: stepValue(solution, key), intermediate: true });
    }
  }

  const head = [el("th", { scope: "col" }, "Quantity"), el("th", { scope: "col" }, "Exact")];
  if (textbook) head.push(el("th", { scope: "col" }, "Seed prints"), el("th", { scope: "col" }, "Difference"));
  const body = el("tbody");
  for (const row of rows) {
    const label = solution.labels && Object.hasOwn(solution.labels, row.key) ? solution.labels[row.key] : null;
    const name = el("th", { scope: "row" });
    if (label && label.label) {
      name.append(el("span", { class: "quantity-label" }, label.label + (label.unit ? ` (${label.unit})` : "")), el("br"));
    }
    name.append(el("code", {}, row.key));
    if (row.intermediate) name.append(el("span", { class: "intermediate" }, " (intermediate)"));
    const tr = el("tr", { "data-key": row.key }, name, valueCell("exact", row.exact));
    if (textbook) {
      if (Object.hasOwn(textbook, row.key) && row.exact === undefined) {
        tr.append(valueCell("printed", textbook[row.key]), el("td", { class: "diff" }, "—"));
      } else if (Object.hasOwn(textbook, row.key)) {
        const printed = textbook[row.key];
        const diff = difference(row.exact, printed);
        const agrees = agreesWithPrinted(row.exact, printed);
        const verdict = el(
          "span",
          {
            class: `verdict ${agrees ? "verdict-agrees" : "verdict-differs"}`,
            title: agrees ? "the exact value rounds to the printed one" : "more than the printed rounding: see the notes",
          },
          agrees ? "agrees" : "differs",
        );
        tr.append(
          valueCell("printed", printed),
          el("td", { class: "diff" }, el(diff !== null && Array.isArray(diff) && diff.every(Array.isArray) ? "pre" : "span", { class: "value" }, diff === null ? "—" : signed(diff)), " ", verdict),
        );
      } else {
        tr.append(el("td", { class: "printed" }, el("span", { class: "value muted" }, "not printed")), el("td", { class: "diff" }));
      }
    }
    body.append(tr);
  }
  const table = el("table", { class: "result-table" }, el("thead", {}, el("tr", {}, head)), body);
  const wrap = el("div", { class: "table-scroll", tabindex: "0", role: "region", "aria-label": "Result table" }, table);
  const parts = [wrap];
  if (textbook) {
    parts.push(el("p", { class: "hint" }, "Exact: computed without rounded intermediates. Difference: exact − printed; “agrees” when the exact value rounds to the printed one, “differs” otherwise (the notes say why)."));
  } else {
    parts.push(el("p", { class: "hint" }, "The seed prints its values only for its own inputs: “Reset to the seed’s values” compares with them."));
  }
  return parts;
}

/** The notes, each with its kind as a badge. */
export function renderNotes(solution) {
  const notes = solution.notes ?? [];
  if (!notes.length) return [el("p", { class: "muted" }, "No notes for these inputs.")];
  const list = el("ul", { class: "notes" });
  for (const note of notes) {
    const kind = NOTE_KINDS.includes(note.kind) ? note.kind : "other";
    list.append(
      el("li", { class: `note note-${kind}` }, el("span", { class: `badge badge-${kind}` }, String(note.kind ?? "note")), " ", el("span", { class: "note-text" }, note.text ?? "")),
    );
  }
  return [list];
}
