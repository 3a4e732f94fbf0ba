// The Data view of a figure (issue 32; docs/figures.md): the elements under a
// canvas that carry its numbers for readers who cannot see it, built from the
// spec's tables(solution, state) (index.js describes the shape):
//   - the summary: the canvas's accessible description (aria-describedby),
//     shown first in the Data view;
//   - a "Data" disclosure button (aria-expanded, aria-controls) that shows the
//     tables (real <table>s: th scope=col/row headers, marks in words inside the
//     cells) and the ordered list (a path, move by move); they print;
//   - the cell cursor's line (polite live region) for tables with `explore`.
// And the helpers for text: a table cell's words, moving the cursor, numbers
// (fmt, as the figures write them), grids of numbers as tables.

import { fmt } from "./draw.js";

let next = 0;

/** The elements of a panel's Data view (not in the page yet); `canvas` gets its description and keyboard help. */
export function dataView(canvas) {
  const id = `figure-data-${++next}`;
  const summary = el("p", "figure-summary");
  summary.id = `${id}-summary`;
  const body = el("div", "figure-data");
  body.id = id;
  body.hidden = true;
  body.append(summary, el("div", "figure-data-tables"));
  const toggle = el("button", "button figure-data-toggle", "Data");
  toggle.type = "button";
  toggle.setAttribute("aria-expanded", "false");
  toggle.setAttribute("aria-controls", id);
  const keys = el("span", "figure-keys");
  keys.id = `${id}-keys`;
  const bar = el("div", "figure-data-bar");
  bar.append(toggle, keys);
  const cursorLine = el("p", "figure-cursor");
  cursorLine.setAttribute("aria-live", "polite");
  canvas.setAttribute("aria-describedby", `${summary.id} ${keys.id}`);
  return { open: false, toggle, body, summary, bar, keys, cursorLine };
}

function el(tag, className, text) {
  const e = document.createElement(tag);
  if (className) e.className = className;
  if (text !== undefined) e.textContent = text;
  return e;
}

/** Fills the open Data view's tables and list from `data` (a spec's tables(): summary, tables, list). */
export function renderData(body, data) {
  const host = body.querySelector(".figure-data-tables");
  const parts = [];
  for (const t of data?.tables ?? []) parts.push(table(t));
  if (data?.list?.items?.length) {
    if (data.list.caption) parts.push(el("p", "figure-list-caption", data.list.caption));
    const ol = el("ol", "figure-list");
    for (const item of data.list.items) ol.append(el("li", null, item));
    parts.push(ol);
  }
  host.replaceChildren(...parts);
}

/** Marks that single a cell out (drawn with a frame); other marks are notes (words only). */
const HIGHLIGHT = /\b(best|selected|start|end|picked|highest|largest|nearest|lowest)\b/;
/** A number as the figures write it (a real minus, digits, a power of ten): right-aligned; other texts left. */
const NUMERIC = /^[−+-]?[\d.,\s]*\d( × 10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?$/;

function table(t) {
  const wrap = el("div", "figure-table-wrap");
  const tab = el("table", "figure-table");
  const parts = [];
  if (t.caption) {
    // the caption is the table's name for screen readers; the same words are shown above the
    // scrolling box (a wide table's own caption would scroll away with it)
    const shown = el("p", "figure-table-title", t.caption);
    shown.setAttribute("aria-hidden", "true");
    parts.push(shown);
    tab.append(el("caption", "visually-hidden", t.caption));
  }
  const head = el("tr");
  if (t.rowHeaders) {
    const corner = el("th", null, t.corner ?? "");
    corner.scope = "col";
    head.append(corner);
  }
  for (const c of t.columns ?? []) {
    const th = el("th", null, c);
    th.scope = "col";
    head.append(th);
  }
  const thead = el("thead");
  thead.append(head);
  const tbody = el("tbody");
  t.rows.forEach((row, r) => {
    const tr = el("tr");
    if (t.rowHeaders) {
      const th = el("th", null, t.rowHeaders[r] ?? "");
      th.scope = "row";
      tr.append(th);
    }
    row.forEach((v, c) => {
      const td = el("td");
      td.append(el("span", "figure-value", v));
      if (v && !NUMERIC.test(v)) td.classList.add("figure-text");
      const mark = t.marks?.[r]?.[c];
      if (mark) {
        if (HIGHLIGHT.test(mark)) td.classList.add("figure-marked");
        const words = el("span", "figure-mark");
        // read as "0.9665, best"; shown on a line of its own under the value
        words.append(el("span", "visually-hidden", ", "), mark);
        td.append(words);
      }
      tr.append(td);
    });
    tbody.append(tr);
  });
  tab.append(thead, tbody);
  wrap.append(tab);
  parts.push(wrap);
  const box = el("div", "figure-table-box");
  box.append(...parts);
  return box;
}

/** What the cursor line reads for cell (r, c) of an explorable table: "row 3, column 2, 87, inside the window". */
export function cursorText(t, { r, c }) {
  const value = t.rows[r]?.[c] ?? "";
  const mark = t.marks?.[r]?.[c];
  const where = [t.rowHeaders?.[r] ?? `row ${r + 1}`, t.columns?.[c] ?? `column ${c + 1}`];
  return [...where, value === "" ? "empty" : value, ...(mark ? [mark] : [])].join(", ");
}

/** The cursor after `key` (arrows, Home, End, PageUp, PageDown), or null for any other key; no cursor yet starts at the first marked cell. */
export function moveCursor(t, cursor, key) {
  const rows = t.rows.length;
  const cols = t.rows[0]?.length ?? 0;
  if (!rows || !cols) return null;
  if (!cursor) {
    if (!["ArrowLeft", "ArrowRight", "ArrowUp", "ArrowDown", "Home", "End", "PageUp", "PageDown"].includes(key)) return null;
    for (let r = 0; r < rows; r++) for (let c = 0; c < cols; c++) if (t.marks?.[r]?.[c]) return { r, c };
    return { r: 0, c: 0 };
  }
  const clamp = (v, n) => Math.max(0, Math.min(n - 1, v));
  const { r, c } = cursor;
  switch (key) {
    case "ArrowLeft":
      return { r, c: clamp(c - 1, cols) };
    case "ArrowRight":
      return { r, c: clamp(c + 1, cols) };
    case "ArrowUp":
      return { r: clamp(r - 1, rows), c };
    case "ArrowDown":
      return { r: clamp(r + 1, rows), c };
    case "Home":
      return { r, c: 0 };
    case "End":
      return { r, c: cols - 1 };
    case "PageUp":
      return { r: 0, c };
    case "PageDown":
      return { r: rows - 1, c };
    default:
      return null;
  }
}

// ---------------------------------------------------------------------------
// Helpers for the topic modules' tables()

/** A number as the figures write it (draw.js fmt: significant digits, a real minus sign), "no value" when it is not one. */
export const num = (v, digits = 6) => fmt(v, digits, "no value");

/** "column 1" … for n columns from `first`. */
export const columnsFrom = (n, first = 1, word = "column") => Array.from({ length: n }, (_, i) => `${word} ${first + i}`);

/**
 * A matrix as a table: `format(v)` the cell texts, `first` the numbers of the
 * first column and row ({ c, r }), `mark(r, c)` words for a cell (or null),
 * `explore` the figure's cell rectangles (index.js).
 */
export function matrixTable(caption, m, { format = (v) => num(v), first = { c: 1, r: 1 }, mark = null, explore = null, corner = "" } = {}) {
  const rows = Array.isArray(m) ? m.filter(Array.isArray) : [];
  const cols = rows[0]?.length ?? 0;
  const t = {
    caption,
    corner,
    columns: columnsFrom(cols, first.c),
    rowHeaders: columnsFrom(rows.length, first.r, "row"),
    rows: rows.map((row) => row.map((v) => format(v))),
  };
  if (mark) t.marks = rows.map((row, r) => row.map((_, c) => mark(r, c) || null));
  if (explore) t.explore = explore;
  return t;
}

/** A plotted series or a list of records as a table: `columns` its headers, `rows` its texts (no row headers). */
export const seriesTable = (caption, columns, rows, marks = null) => ({ caption, columns, rows, ...(marks ? { marks } : {}) });
