// Renders a Solution (docs/API.md) into plain DOM: the answer line, the
// steps, the result with the printed-vs-exact comparison, and the notes.
//
// The result is one table that becomes a card per quantity where its column
// is narrow (a container query in style.css), so the exact value, the
// printed value and the difference are always visible together; matrices
// are drawn as matrices.

import { el } from "./dom.js";
import { fitFormulaNodes, fitFormulas, formulaSource, renderFormula } from "./math.js";
import { isMatrix, stepValue } from "./values.js";
import { agreesWithPrinted, formatDecimals, formatDifference, formatExact, formatNumber, formatValue, spokenNumber } from "./format.js";

/** Note kinds with their own badge style; any other kind gets the neutral one. */
const NOTE_KINDS = ["erratum", "rounding", "convention", "warning"];
/** Note kinds that explain a printed value as another convention or a slip, not a difference. */
const EXPLAINING_KINDS = ["erratum", "convention"];
/**
 * Decimals a quantity in this unit deserves, beyond the usual significant
 * digits: eastings and northings to the millimetre, angles to about 0.1 mm on
 * the ground (1e-9 degree), so a surveyor sees every digit the core is sure of.
 */
const UNIT_DECIMALS = Object.freeze({ m: 3, "°": 9, km: 6 });

/** An exact value for its unit (see UNIT_DECIMALS), else as formatExact does. */
function formatFor(value, unit, printed) {
  const dec = UNIT_DECIMALS[unit];
  if (dec !== undefined && typeof value === "number" && Number.isFinite(value) && Math.abs(value) >= 1 && printed === undefined) {
    return formatDecimals(value, dec);
  }
  return formatExact(value, printed);
}

/** Significant digits of a printed value (the course notes print at most this many; derived ones are cut here). */
const PRINTED_DIGITS = 8;
/** Numbers of a vector shown in the answer line before "…". */
const ANSWER_VECTOR_MAX = 8;
/** Words for the comparison, used in the table head and the answer line. */
export const WORDS = Object.freeze({
  exact: "Exact",
  printed: "Course notes print",
  difference: "Difference (exact − printed)",
});

/** One step as a list item. */
function stepItem(step, k) {
  const item = el("li", { class: "step", id: `step-${k + 1}` }, el("h4", { class: "step-title" }, step.title ?? ""));
  if (step.text) item.append(el("p", { class: "step-text" }, step.text));
  if (step.formula) item.append(renderFormula(formulaSource(step, "symbolic"), "formula formula-symbolic"));
  if (step.substituted) item.append(renderFormula(formulaSource(step, "substituted"), "formula formula-substituted"));
  return item;
}

/** The steps as an ordered list. */
export function renderSteps(solution) {
  const list = el("ol", { class: "steps" });
  (solution.steps ?? []).forEach((step, k) => list.append(stepItem(step, k)));
  if (!list.childElementCount) list.append(el("li", { class: "step" }, "This solution has no steps."));
  return list;
}

/**
 * Marks the step a moving figure's frame belongs to (class step-playing; k is
 * the index in solution.steps, null for none): a class toggled, nothing built again.
 */
export function markStep(container, k) {
  const now = Number.isInteger(k) ? container.querySelector(`:scope > .steps > #step-${k + 1}`) : null;
  for (const item of container.querySelectorAll(":scope > .steps > .step-playing")) if (item !== now) item.classList.remove("step-playing");
  now?.classList.add("step-playing");
}

/** The steps each list of updateSteps shows, by list. */
const shownSteps = new WeakMap();

/**
 * What a step's item holds, in order: [class, text or TeX, formula source] of
 * its children (a formula is the same when its LaTeX, made by the core from
 * its parts, is).
 */
function stepParts(step) {
  const parts = [["step-title", step.title ?? ""]];
  if (step.text) parts.push(["step-text", step.text]);
  if (step.formula) parts.push(["formula formula-symbolic", String(step.formula), formulaSource(step, "symbolic")]);
  if (step.substituted) parts.push(["formula formula-substituted", String(step.substituted), formulaSource(step, "substituted")]);
  return parts;
}

/**
 * Shows `solution`'s steps in `container` as renderSteps and fitFormulas
 * would, fast after an input change: a list shown before is updated in place,
 * and only what changed is built again (a formula whose TeX is the same stays
 * as it was rendered and fitted, so KaTeX and the layout redo only the new
 * ones). Items another module reshaped (the embed's folded steps) are built
 * again whole.
 * @param {Element} container
 * @param {object} solution
 */
export function updateSteps(container, solution) {
  const steps = solution.steps ?? [];
  const list = container.firstElementChild;
  const before = list && container.childElementCount === 1 ? shownSteps.get(list) : undefined;
  if (!before || !steps.length) {
    const fresh = renderSteps(solution);
    container.replaceChildren(fresh);
    fitFormulas(container);
    shownSteps.set(fresh, steps.map(stepParts));
    return;
  }
  const items = [...list.children];
  const fresh = []; // new formula elements, to fit once in the page
  const rebuilt = [];
  const now = steps.map((step, k) => {
    const parts = stepParts(step);
    const item = items[k];
    const old = before[k];
    const plain = item && old && item.childElementCount === old.length && [...item.children].every((c, i) => c.className === old[i][0]);
    if (!plain || old.length !== parts.length || parts.some(([cls], i) => cls !== old[i][0])) {
      const next = stepItem(step, k);
      if (item) item.replaceWith(next);
      else list.append(next);
      rebuilt.push(next);
      return parts;
    }
    parts.forEach(([cls, content, source], i) => {
      if (content === old[i][1]) return;
      const child = item.children[i];
      if (source) {
        const node = renderFormula(source, cls);
        child.replaceWith(node);
        fresh.push(node);
      } else {
        child.textContent = content;
      }
    });
    return parts;
  });
  for (const extra of items.slice(steps.length)) extra.remove();
  shownSteps.set(list, now);
  // only the new formulas (the kept ones are fitted already), all with one layout
  fitFormulaNodes([...rebuilt.flatMap((item) => [...item.querySelectorAll(".formula[data-tex]")]), ...fresh]);
}

/** The label of a key: { label, unit } from the solution, or the key itself. */
export function labelOf(solution, key) {
  const l = solution.labels && Object.hasOwn(solution.labels, key) ? solution.labels[key] : null;
  return { label: l?.label || key, unit: l?.unit || null };
}


/**
 * An element with `text` that reads well: a power of ten ("1.8 × 10⁻⁶") is
 * shown as written and said "1.8 times 10 to the minus 6" (style.css
 * .spoken: the shown text hidden from the accessibility tree, the words as
 * its alt text; copying and innerText keep the text shown).
 */
export function readable(tag, attrs, text) {
  const spoken = spokenNumber(text);
  if (spoken === null) return el(tag, attrs, text);
  return el(tag, { ...attrs, class: `${attrs.class ?? ""} spoken`.trim(), "data-spoken": spoken }, el("span", { "aria-hidden": "true" }, text));
}

/** The text of `node` as a screen reader gets it: .spoken parts as said, aria-hidden parts left out. */
export function spokenText(node) {
  if (node.nodeType === Node.TEXT_NODE) return node.nodeValue;
  if (node.nodeType !== Node.ELEMENT_NODE) return "";
  if (node.dataset.spoken !== undefined) return node.dataset.spoken;
  if (node.classList.contains("answer-sep")) return "; ";
  if (node.getAttribute("aria-hidden") === "true") return "";
  return [...node.childNodes].map(spokenText).join("");
}

/** A matrix larger than this (rows or columns) is shown in a scroll box of its own. */
const MATRIX_MAX_COLS = 8;
const MATRIX_MAX_ROWS = 12;

/** A value as DOM: a number, a bracketed vector that wraps, a matrix as a grid. */
export function valueNode(value, format = (v) => formatNumber(v)) {
  if (isMatrix(value)) {
    const cols = Math.max(...value.map((r) => r.length));
    const rows = value.map((row) => el("tr", {}, row.map((v) => readable("td", {}, typeof v === "number" ? format(v) : formatValue(v)))));
    // a table a screen reader can walk cell by cell ("row 2, column 3"), named by its size
    const table = el("table", { class: "matrix", "aria-label": `${value.length} × ${cols} matrix` }, el("tbody", {}, rows));
    if (cols <= MATRIX_MAX_COLS && value.length <= MATRIX_MAX_ROWS) return table;
    // a large what-if (a 64×64 search array): every number kept, in a box that scrolls
    return el("div", { class: "matrix-scroll", tabindex: "0", role: "region", "aria-label": `${value.length} × ${cols} matrix: scroll to see all of it` }, table);
  }
  if (Array.isArray(value)) {
    const items = value.map((v, i) => el("span", { class: "vector-item" }, readable("span", {}, typeof v === "number" ? format(v, i) : formatValue(v)), i < value.length - 1 ? "," : ""));
    return el("span", { class: "vector" }, items);
  }
  return readable("span", { class: "value" }, typeof value === "number" ? format(value) : formatValue(value));
}

function dataValue(value) {
  if (typeof value === "number") return String(value);
  if (Array.isArray(value)) return JSON.stringify(value);
  return null;
}

/** The element-wise map of a value (numbers and arrays of the same shape). */
function zipMap(a, b, f) {
  if (Array.isArray(a) && Array.isArray(b) && a.length === b.length) return a.map((x, i) => zipMap(x, b[i], f));
  return f(a, b);
}


/** The notes as numbered items: [{ n, note, kind }]. */
function numberedNotes(solution) {
  return (solution.notes ?? []).map((note, i) => ({ n: i + 1, note, kind: NOTE_KINDS.includes(note.kind) ? note.kind : "other" }));
}

function notesAbout(solution, key) {
  return numberedNotes(solution).filter(({ note }) => Array.isArray(note.keys) && note.keys.includes(key));
}

function noteLink({ n, kind }) {
  return el("a", { class: `note-link note-link-${kind}`, href: `#note-${n}`, "data-note": String(n) }, `note ${n}`);
}

/** The comparison of one quantity: { agrees, explained, diffText }. */
export function compare(solution, key, exact, printed) {
  const agrees = agreesWithPrinted(exact, printed);
  const explaining = notesAbout(solution, key).filter(({ kind }) => EXPLAINING_KINDS.includes(kind));
  return { agrees, explained: !agrees && explaining.length > 0, explaining };
}

function diffCell(solution, key, exact, printed) {
  const td = el("td", { class: "diff", "data-label": WORDS.difference });
  if (exact === undefined || exact === null) {
    td.append(el("span", { class: "value muted" }, "—"));
    return td;
  }
  const { agrees, explained, explaining } = compare(solution, key, exact, printed);
  if (explained) {
    // a sign slip or another convention: not a difference to report as a number
    const kind = explaining[0].kind;
    td.append(el("span", { class: `verdict verdict-${kind}` }, kind === "erratum" ? "erratum" : "other convention"), " — see ", ...explaining.flatMap((x, i) => (i ? [", ", noteLink(x)] : [noteLink(x)])));
    return td;
  }
  const diff = zipMap(exact, printed, (e, p) => formatDifference(e, p));
  const shown = agrees ? null : isMatrix(diff) ? valueNode(diff, (v) => v) : Array.isArray(diff) ? valueNode(diff, (v) => v) : readable("span", { class: "value" }, diff ?? "—");
  if (shown) td.append(shown, " ");
  td.append(
    el(
      "span",
      {
        class: `verdict ${agrees ? "verdict-agrees" : "verdict-differs"}`,
        title: agrees ? "the exact value rounds to the printed one" : "more than the printed rounding: see the notes",
      },
      agrees ? "agrees" : "differs",
    ),
  );
  const others = notesAbout(solution, key);
  if (!agrees && others.length) td.append(" — see ", ...others.flatMap((x, i) => (i ? [", ", noteLink(x)] : [noteLink(x)])));
  return td;
}

/**
 * The result: every result key with its exact value, and where the course
 * notes print the quantity (`textbook`), the printed value and exact −
 * printed. Returns DOM nodes.
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

  const head = [el("th", { scope: "col" }, "Quantity"), el("th", { scope: "col" }, WORDS.exact)];
  if (textbook) head.push(el("th", { scope: "col" }, WORDS.printed), el("th", { scope: "col" }, WORDS.difference));
  const body = el("tbody");
  for (const row of rows) {
    const { label, unit } = labelOf(solution, row.key);
    const name = el("th", { scope: "row" }, el("span", { class: "quantity-label" }, label + (unit ? ` (${unit})` : "")));
    name.append(" ", el("code", { class: "api-name", title: "name in the API and the URL" }, row.key));
    if (row.intermediate) name.append(el("span", { class: "intermediate" }, " (intermediate)"));
    const printed = textbook && Object.hasOwn(textbook, row.key) ? textbook[row.key] : undefined;
    const exactCell = el("td", { class: "exact", "data-label": WORDS.exact }, valueNode(row.exact, (v) => formatFor(v, unit, typeof printed === "number" ? printed : undefined)));
    const dv = dataValue(row.exact);
    if (dv !== null) exactCell.dataset.value = dv;
    const tr = el("tr", { "data-key": row.key }, name, exactCell);
    if (textbook) {
      if (printed !== undefined) {
        const p = el("td", { class: "printed", "data-label": WORDS.printed }, valueNode(printed, (v) => formatNumber(v, PRINTED_DIGITS)));
        const pv = dataValue(printed);
        if (pv !== null) p.dataset.value = pv;
        tr.append(p, diffCell(solution, row.key, row.exact, printed));
      } else {
        tr.append(el("td", { class: "printed not-printed", "data-label": WORDS.printed }, el("span", { class: "value muted" }, "not printed")), el("td", { class: "diff empty", "data-label": WORDS.difference }));
      }
    }
    body.append(tr);
  }
  const table = el("table", { class: "result-table" }, el("thead", {}, el("tr", {}, head)), body);
  const parts = [el("div", { class: "result-wrap" }, table)];
  if (textbook) {
    parts.push(
      el(
        "p",
        { class: "hint" },
        "Exact: computed here without rounding any intermediate value. Course notes print: the value printed in the worked example. Difference: exact − printed; “agrees” when the exact value rounds to the printed one, “differs” otherwise (a note says why).",
      ),
    );
  } else {
    parts.push(el("p", { class: "hint" }, "The course notes print values only for their own inputs: “Reset to the worked example’s values” compares with them."));
  }
  return parts;
}

/**
 * The one-line answer near the top: "Ground sample distance = 35.649 cm; the
 * course notes print 35.37 cm." from `solution.answer` (or the first result).
 */
export function renderAnswer(solution) {
  const result = solution.result ?? {};
  const keys = (Array.isArray(solution.answer) && solution.answer.length ? solution.answer : Object.keys(result).slice(0, 1)).filter((k) => Object.hasOwn(result, k));
  const textbook = solution.textbook ?? {};
  const parts = keys.map((key) => {
    const { label, unit } = labelOf(solution, key);
    const exact = result[key];
    const printed = Object.hasOwn(textbook, key) ? textbook[key] : undefined;
    const u = unit ? ` ${unit}` : "";
    if (exact === null || exact === undefined) {
      // no value: say why, from the note about it (e.g. resample's bicubic value off the patch)
      return el("span", { class: "answer-item", "data-key": key }, el("span", { class: "answer-label" }, label), " = ", el("strong", {}, "no value"), ...noValueReason(solution, key));
    }
    const span = el("span", { class: "answer-item", "data-key": key }, el("span", { class: "answer-label" }, label), " = ", readable("strong", {}, `${answerText(exact, printed, unit)}${u}`));
    if (printed !== undefined) {
      const { agrees, explained } = compare(solution, key, exact, printed);
      span.append(`; the course notes print ${answerText(printed)}${u}`, el("span", { class: "muted" }, agrees ? " (agrees)" : explained ? " (an erratum: see the notes)" : " (see the notes)"));
    }
    return span;
  });
  // the dot is for the eye; a screen reader hears a pause (style.css .answer-sep::after)
  return parts.flatMap((p, i) => (i ? [el("span", { class: "answer-sep" }, el("span", { "aria-hidden": "true" }, " · ")), p] : [p]));
}

/**
 * Why a result has no value, for the answer line: the first sentence of the
 * note about it (a warning first) and a link to that note; a plain word when
 * no note says.
 */
function noValueReason(solution, key) {
  const about = notesAbout(solution, key);
  const note = about.find(({ kind }) => kind === "warning") ?? about[0];
  if (!note) return [el("span", { class: "answer-why" }, " (these inputs give none)")];
  // "No bicubic value here: Lecture 7's … (7 missing). The lecture's …" → its first sentence, without the "No … here:"
  const text = String(note.note.text ?? "");
  const first = (/^[\s\S]*?[.!?](?=\s|$)/.exec(text)?.[0] ?? text).replace(/^No [^:.]{0,60}:\s*/, "");
  const why = first ? first.charAt(0).toUpperCase() + first.slice(1) : "See the note.";
  return [el("span", { class: "answer-why" }, ` — ${why} (`, noteLink(note), ")")];
}

function answerText(value, printed, unit = null) {
  if (isMatrix(value)) return `${value.length} × ${value[0].length} matrix (in the result below)`;
  if (Array.isArray(value)) {
    const shown = value.slice(0, ANSWER_VECTOR_MAX).map((v, i) => (typeof v === "number" ? formatExact(v, Array.isArray(printed) ? printed[i] : undefined) : formatValue(v)));
    return `[${shown.join(", ")}${value.length > ANSWER_VECTOR_MAX ? ", …" : ""}]`;
  }
  return typeof value === "number" ? formatFor(value, unit, typeof printed === "number" ? printed : undefined) : formatValue(value);
}

/** The notes, numbered, each with its kind as a badge and the quantities it concerns. */
export function renderNotes(solution) {
  const notes = numberedNotes(solution);
  if (!notes.length) return [el("p", { class: "muted" }, "No notes for these inputs.")];
  const list = el("ol", { class: "notes" });
  for (const { n, note, kind } of notes) {
    const about = Array.isArray(note.keys) && note.keys.length ? el("span", { class: "note-about" }, ` (about: ${note.keys.map((k) => labelOf(solution, k).label).join(", ")})`) : null;
    list.append(
      el("li", { class: `note note-${kind}`, id: `note-${n}`, tabindex: "-1" }, el("span", { class: `badge badge-${kind}` }, String(note.kind ?? "note")), " ", el("span", { class: "note-text" }, note.text ?? ""), about),
    );
  }
  return [list];
}
