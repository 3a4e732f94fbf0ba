// The layout of a step's formula, planned from the step's structured parts
// (docs/API.md: step.parts, one relation per equation), in Node as in the
// page: no DOM, no KaTeX, and no reading of LaTeX. math-typeset.js makes the
// nodes from a plan and fits them to their width.
//
//   relation = { key, lhs: Form, op, symbolic: [Form], substituted: [Form], result: [Form] }
//   Form     = [Piece]   pieces a line may break between (the terms of a long sum)
//   Piece    = { tex } | { grid: { env, rows: [[cell tex]], name } }
//
// A formula is one of a step's sides (math.js formulaSource): "symbolic" (lhs op symbolic…),
// "substituted" (lhs op substituted… op result…) or "question" (lhs op
// substituted… op ?, practice's hint). Its plan: one group per relation,
// each group a chain of items ("GSD = p·m", "= 356 mm", "= 35.6 cm"), each
// item a line of terms that flow. LaTeX is only ever put together here (a
// grid's cells into a matrix), never taken apart.

/** The right-hand sides of a relation for a side of the formula. */
function sidesOf(r, side) {
  const substituted = r.substituted ?? [];
  if (side === "symbolic") return r.symbolic ?? [];
  if (side === "question") return substituted.length ? [...substituted, [{ tex: String.raw`\;?` }]] : [];
  return [...substituted, ...(r.result ?? [])];
}

/** Whether a relation shows in a side at all (as the core's LaTeX strings do). */
function shown(r, side, sides) {
  // as the core's LaTeX: a side is shown when it has something on the right
  // (a relation with symbols only has no numbers line)
  return sides.length > 0;
}

const isGrid = (piece) => Boolean(piece && piece.grid);
const joined = (...parts) => parts.filter((p) => p !== "").join(" ");

/**
 * A term of a line: { tex } (with `apart`: the two terms it may part into
 * when too wide, a left-hand side and its first relation), or a grid
 * { grid, lead, name } (`lead`: what stands before the matrix, "N =" or
 * "=", `name`: the matrix's name as LaTeX for its blocks' captions).
 */
function gridTerm(piece, lead, name) {
  return { grid: piece.grid, lead, name: piece.grid.name ?? name ?? null };
}

/** The terms of a side: `op` before its first piece. */
function sideTerms(form, op, name) {
  return form.map((piece, k) => {
    const lead = k === 0 ? op : "";
    if (isGrid(piece)) return gridTerm(piece, lead, form.length === 1 ? name : null);
    return { tex: joined(lead, piece.tex) };
  });
}

/**
 * The plan of one formula: { groups: [{ key, items: [{ cont, terms }] }] },
 * or { whole: tex } when the step has no parts (the core not converted yet:
 * one KaTeX block, unsplit).
 * @param {{ tex: string, relations: object[] | null, side: string }} source
 */
export function planFormula(source) {
  if (!source.relations) return { whole: source.tex };
  const groups = [];
  for (const r of source.relations) {
    const sides = sidesOf(r, source.side);
    if (!shown(r, source.side, sides)) continue;
    const lhs = r.lhs ?? [];
    const op = r.op || "=";
    // a one-piece left-hand side in words names the matrix it equals ("N = [...]")
    const lhsName = lhs.length === 1 && !isGrid(lhs[0]) ? lhs[0].tex : null;
    const items = [];
    sides.forEach((form, k) => {
      if (k > 0 || lhs.length === 0) {
        items.push({ cont: k > 0, terms: sideTerms(form, k > 0 ? op : "", lhsName) });
        return;
      }
      // the left-hand side stays with its first relation: "GSD = p·m" (parting only when too wide)
      const first = form[0];
      const rest = sideTerms(form.slice(1), "", null);
      const head = lhs.slice(0, -1).map((p) => (isGrid(p) ? gridTerm(p, "", null) : { tex: p.tex }));
      const last = lhs[lhs.length - 1];
      let glued;
      if (isGrid(last)) glued = [gridTerm(last, "", null), ...sideTerms(first ? [first] : [], op, null)];
      else if (!first) glued = [{ tex: last.tex }];
      else if (isGrid(first)) glued = [gridTerm(first, joined(last.tex, op), form.length === 1 ? lhsName : null)];
      else glued = [{ tex: joined(last.tex, op, first.tex), apart: [last.tex, joined(op, first.tex)] }];
      items.push({ cont: false, terms: [...head, ...glued, ...rest] });
    });
    if (!sides.length) items.push({ cont: false, terms: lhs.map((p) => (isGrid(p) ? gridTerm(p, "", null) : { tex: p.tex })) });
    groups.push({ key: r.key ?? null, items });
  }
  return { groups };
}

// ---------------------------------------------------------------------------
// Grids: matrices and tables from their cells

/** Columns of a grid (its widest row). */
export function gridColumns(grid) {
  return Math.max(0, ...grid.rows.map((r) => r.length));
}

/** A grid's rows as LaTeX in its environment (an array right-aligned, as the core writes it). */
export function gridTex(grid, rows = grid.rows) {
  const cols = Math.max(1, ...rows.map((r) => r.length));
  const spec = grid.env === "array" ? `{${"r".repeat(cols)}}` : "";
  const body = rows.map((r) => r.join(" & ")).join(" \\\\ ");
  return `\\begin{${grid.env}}${spec} ${body} \\end{${grid.env}}`;
}

/** A grid term as LaTeX: what leads it, then the matrix. */
export function gridTermTex(term, rows) {
  return joined(term.lead ?? "", gridTex(term.grid, rows));
}

function range(a, b) {
  return Array.from({ length: Math.max(0, b - a) }, (_, k) => a + k);
}

/**
 * A grid as blocks of at most `per` columns (a table, env "array", keeps its
 * first column in every block): [{ rows, from, to, of }], columns counted
 * from 1.
 */
export function gridBlocks(grid, per) {
  const ncols = gridColumns(grid);
  const table = grid.env === "array";
  const first = table ? 1 : 0;
  const blocks = [];
  for (let from = first; from < ncols; from += Math.max(1, per)) {
    const to = Math.min(ncols, from + Math.max(1, per));
    const cols = table ? [0, ...range(from, to)] : range(from, to);
    blocks.push({ rows: grid.rows.map((r) => cols.map((c) => r[c] ?? "")), from: from + 1, to, of: ncols });
  }
  return blocks;
}

/** A block's caption after the matrix's name (plain text): "columns 1–3 of 4". */
export function blockCaption(name, b) {
  const cols = b.from === b.to ? `column ${b.from} of ${b.of}` : `columns ${b.from}–${b.to} of ${b.of}`;
  return name ? `${name}, ${cols}` : cols;
}

/** Rows of a matrix or table shown before "Show all n rows", and the most shown whole. */
export const ROWS_SHOWN = 8;
export const ROWS_MAX = 12;

/**
 * A grid of more than ROWS_MAX rows (a table's header row not counted): its
 * first ROWS_SHOWN rows and a row of dots, with the count of all rows; null
 * for a smaller grid.
 */
export function shortGrid(grid) {
  const header = grid.env === "array" ? 1 : 0;
  const count = grid.rows.length - header;
  if (count <= ROWS_MAX) return null;
  const dots = Array.from({ length: gridColumns(grid) }, () => String.raw`\vdots`);
  return { rows: [...grid.rows.slice(0, header + ROWS_SHOWN), dots], count };
}

/** A table as one line of terms per data row: its first cell, then "header = cell" for the others. */
export function tableRowLines(grid) {
  const [head = [], ...data] = grid.rows;
  return data.map((row) => [`${row[0] ?? ""}{:}`, ...row.slice(1).map((cell, j) => `${head[j + 1] ?? ""} = ${cell}${j < row.length - 2 ? "," : ""}`)]);
}
