// The KaTeX side of math.js (issue 19): typesetting a formula in its pieces
// and terms, and fitting it to its width after layout. Loaded with KaTeX
// (math.js startMath: script, stylesheet and this module in parallel), after
// the first numbers are on screen; until then math.js draws formulas as plain
// text. The page uses math.js (renderFormula, fitFormulas, keepFitted); the
// unit tests (tests/unit/math.test.mjs) read the splitting rules here.

import { plainTex, renderFormula } from "./math.js";

const KATEX_OPTIONS = Object.freeze({
  displayMode: false, // terms are inline boxes; \displaystyle keeps display-size fractions
  throwOnError: true,
  trust: false, // no \href, \url, \includegraphics, \htmlClass...
  strict: "ignore",
  maxSize: 20,
  maxExpand: 1000,
  output: "htmlAndMathml", // MathML for screen readers
});

// ---------------------------------------------------------------------------
// Scanning LaTeX at the top level

/** Spacing commands after which a formula may wrap ("x = 1,\quad y = 2"). */
const BREAK_COMMANDS = ["qquad", "quad"];
/** Relations before which a chain may wrap ("GSD = p·m = 356 mm = 35.6 cm"). */
const RELATION_COMMANDS = ["approx"];
/** Environments whose rows and columns the fitting may rearrange. */
const GRID_ENVS = ["bmatrix", "pmatrix", "vmatrix", "Bmatrix", "matrix", "array"];

/**
 * Walks `tex` and calls `visit(i, token, depth)` for every top-level token:
 * depth counts braces, \left…\right and \begin…\end; `paren` counts ( ) and
 * [ ] (plain delimiters) separately so sums inside parentheses stay whole.
 * Returns false when the braces do not balance.
 */
function scan(tex, visit) {
  let depth = 0;
  let paren = 0;
  let i = 0;
  while (i < tex.length) {
    const ch = tex[i];
    if (ch === "\\") {
      const m = /^\\([A-Za-z]+|.)/.exec(tex.slice(i));
      const name = m ? m[1] : "";
      const length = 1 + Math.max(name.length, 1);
      if (name === "left" || name === "begin") {
        if (depth === 0) visit(i, { cmd: name, length }, depth, paren);
        depth += 1;
      } else if (name === "right" || name === "end") {
        depth -= 1;
      } else if (depth === 0) {
        visit(i, { cmd: name, length }, depth, paren);
      }
      i += length;
      continue;
    }
    if (ch === "{") depth += 1;
    else if (ch === "}") depth -= 1;
    else if (depth === 0) {
      if (ch === "(" || ch === "[") paren += 1;
      else if (ch === ")" || ch === "]") paren = Math.max(0, paren - 1);
      visit(i, { ch }, depth, paren);
    }
    i += 1;
  }
  return depth === 0;
}

/**
 * Splits a formula where it may wrap, at the top level only:
 *   - into groups at "\quad"/"\qquad", and at ",\ " between equations
 *     (outside parentheses and brackets);
 *   - each group into pieces before its second, third… "=" or "\approx",
 *     the relation starting the next piece ("a = b = c" -> "a = b", "= c").
 * Returns [[tex]] when there is no such place.
 * @param {string} tex
 * @returns {string[][]}
 */
export function splitFormula(tex) {
  const groups = [];
  let pieces = [];
  let start = 0;
  const cut = (end) => {
    const piece = tex.slice(start, end).trim();
    if (piece) pieces.push(piece);
  };
  const endGroup = () => {
    if (pieces.length) groups.push(pieces);
    pieces = [];
  };
  const balanced = scan(tex, (i, t, depth, paren) => {
    if (t.cmd && BREAK_COMMANDS.includes(t.cmd)) {
      cut(i);
      endGroup();
      start = i + t.length;
    } else if (t.cmd && RELATION_COMMANDS.includes(t.cmd)) {
      cut(i);
      start = i;
    } else if (t.ch === "=") {
      cut(i);
      start = i;
    } else if (t.ch === "," && paren === 0 && /^,\\ /.test(tex.slice(i, i + 3))) {
      // "a_1 = …,\ a_2 = …": the comma ends one equation
      cut(i + 1);
      endGroup();
      start = i + 3;
    }
  });
  cut(tex.length);
  endGroup();
  if (!balanced || groups.length === 0) return [[tex]];
  // the left-hand side stays with the first relation: "GSD = a × b", "= 356 mm", …
  return groups.map((g) => (g.length > 1 && !/^(=|\\approx)/.test(g[0]) ? [`${g[0]} ${g[1]}`, ...g.slice(2)] : g));
}

/** Tokens after which a + or − is a sign, not an operation. */
const SIGN_CONTEXT = /(^|[=<>(,[&+\-]|\\cdot|\\times|\\approx|\\quad|\\;|\\ |\\left.?)\s*$/;

/**
 * Splits a piece into terms that may flow onto several lines: before each
 * top-level binary + or − (outside parentheses), and after each list
 * separator (\; anywhere at the top level, ",\ " inside brackets, where it
 * separates the items of a list). A piece that is exactly a `gathered` block
 * gives one line per row. Returns { lines: [[term…]…] } where every line
 * starts on a line of its own.
 * @param {string} piece
 */
export function splitTerms(piece) {
  const gathered = /^\\begin\{gathered\}([\s\S]*)\\end\{gathered\}(\s*[,.;]?)$/.exec(piece.trim());
  if (gathered && splitTop(gathered[1], "\\\\").length > 1) {
    const rows = splitTop(gathered[1], "\\\\").map((r) => r.trim()).filter(Boolean);
    if (gathered[2].trim()) rows[rows.length - 1] += gathered[2].trim();
    return { lines: rows.map((row) => termsOf(row)) };
  }
  return { lines: [termsOf(piece)] };
}

function termsOf(piece) {
  const terms = [];
  let seenRelation = false;
  let start = 0;
  const cut = (end) => {
    const t = piece.slice(start, end).trim();
    if (t) terms.push(t);
  };
  const balanced = scan(piece, (i, t, depth, paren) => {
    if ((t.ch === "+" || t.ch === "-") && paren === 0) {
      if (!SIGN_CONTEXT.test(piece.slice(0, i))) {
        cut(i);
        start = i;
      }
    } else if ((t.ch === "=" || (t.cmd && RELATION_COMMANDS.includes(t.cmd))) && paren === 0) {
      // a second relation inside a row of a block ("σa = 0.00996 √… = 1.9 × 10⁻⁶"); the
      // left-hand side stays with the first one, as in splitFormula
      if (seenRelation && i > start) {
        cut(i);
        start = i;
      }
      seenRelation = true;
    } else if (t.cmd === "," && paren === 0 && i > start && /^\\,\s*\\(sqrt|frac|tfrac|dfrac|left|bigl|Bigl)/.test(piece.slice(i))) {
      // factors set apart by a thin space ("√a\,√b"): a place to break (not "6\,367", a digit group)
      cut(i);
      start = i + t.length;
    } else if ((t.cmd === "times" || t.cmd === "cdot") && paren === 0 && i > start) {
      // a long product: "= 0.9996 × 6 367 449.1 × 0.0254…" may break before each ×
      cut(i);
      start = i;
    } else if (t.cmd === ";" && paren === 0) {
      cut(i);
      start = i + t.length;
      seenRelation = false;
    } else if (t.ch === "," && /^,\\ /.test(piece.slice(i, i + 3)) && (paren === 0 || (paren === 1 && bracketOpen(piece.slice(0, i))))) {
      // ",\ " between the items of a list, or between equations in a row
      cut(i + 1);
      start = i + 3;
      seenRelation = false;
    }
  });
  cut(piece.length);
  if (!balanced || terms.length === 0) return [piece];
  return terms;
}

/** Whether the innermost open plain delimiter before the end of `s` is "[". */
function bracketOpen(s) {
  const stack = [];
  scan(s, (i, t) => {
    if (t.ch === "(" || t.ch === "[") stack.push(t.ch);
    else if (t.ch === ")" || t.ch === "]") stack.pop();
  });
  return stack[stack.length - 1] === "[";
}

/** Splits at a top-level separator ("\\\\" for rows, "&" for cells). */
function splitTop(tex, sep) {
  const parts = [];
  let start = 0;
  scan(tex, (i, t) => {
    if (sep === "\\\\" && t.cmd === "\\") {
      parts.push(tex.slice(start, i));
      start = i + 2;
    } else if (sep === "&" && t.ch === "&") {
      parts.push(tex.slice(start, i));
      start = i + 1;
    }
  });
  parts.push(tex.slice(start));
  return parts;
}

/**
 * The first top-level grid environment of a term: { before, env, spec, body,
 * after } or null. `before` keeps any "N = " or size command ahead of it.
 */
export function findGrid(term) {
  const m = /\\begin\{([A-Za-z]+)\}/.exec(term);
  if (!m || !GRID_ENVS.includes(m[1])) return null;
  const env = m[1];
  let i = m.index + m[0].length;
  let spec = "";
  if (env === "array") {
    const s = /^\s*\{([^{}]*)\}/.exec(term.slice(i));
    if (!s) return null;
    spec = s[1];
    i += s[0].length;
  }
  // the matching \end{env}
  const re = /\\(begin|end)\{([A-Za-z]+)\}/g;
  re.lastIndex = i;
  let level = 1;
  let r;
  while ((r = re.exec(term))) {
    if (r[2] !== env) continue;
    level += r[1] === "begin" ? 1 : -1;
    if (level === 0) {
      return { before: term.slice(0, m.index), env, spec, body: term.slice(i, r.index), after: term.slice(r.index + r[0].length) };
    }
  }
  return null;
}

/** The rows of a grid body as cells; a leading \hline is kept apart. */
function gridRows(body) {
  return splitTop(body, "\\\\")
    .map((row) => {
      const h = /^\s*((?:\\hline\s*)*)([\s\S]*)$/.exec(row);
      return { hline: h[1].trim(), cells: splitTop(h[2], "&").map((c) => c.trim()) };
    })
    .filter((row) => row.cells.some((c) => c.length) || row.hline);
}

/** Column letters of an array spec ("c|rr|rr" -> ["c","r","r","r","r"]). */
function specColumns(spec) {
  return [...spec.replace(/[^lcr]/g, "")];
}

/**
 * A grid environment as blocks of at most `per` columns each (a table keeps
 * its first column in every block). Returns [{ tex, from, to, of }].
 */
export function gridBlocks(grid, per) {
  const rows = gridRows(grid.body);
  const ncols = Math.max(...rows.map((r) => r.cells.length));
  const isTable = grid.env === "array";
  const first = isTable ? 1 : 0;
  const letters = isTable ? specColumns(grid.spec) : [];
  const blocks = [];
  for (let from = first; from < ncols; from += per) {
    const to = Math.min(ncols, from + per);
    const cols = isTable ? [0, ...range(from, to)] : range(from, to);
    const body = rows
      .map((r) => `${r.hline ? `${r.hline} ` : ""}${cols.map((c) => r.cells[c] ?? "").join(" & ")}`)
      .join(" \\\\ ");
    let tex;
    if (isTable) {
      const spec = `${letters[0] ?? "l"}|${cols.slice(1).map((c) => letters[c] ?? "r").join("")}`;
      tex = `\\begin{array}{${spec}} ${body} \\end{array}`;
    } else {
      tex = `\\begin{${grid.env}} ${body} \\end{${grid.env}}`;
    }
    blocks.push({ tex, from: from + 1, to, of: ncols });
  }
  return blocks;
}

function range(a, b) {
  return Array.from({ length: b - a }, (_, k) => a + k);
}

// ---------------------------------------------------------------------------
// A split matrix keeps its name, and the equation around it reads on after
// the whole matrix (issue 29): "A, columns 1–2 of 4", "A, columns 3–4 of 4",
// then "A X = L" with the name standing for the matrix shown above.

/** A matrix's name: a letter with an optional subscript and transpose (A, N, Q_{xx}, A^\mathsf{T}). */
const SYMBOL = /^[A-Za-z](?:_\{[^{}]*\}|_[A-Za-z0-9])?(?:\^\{?\\mathsf\{T\}\}?)?$/;
/** What may stand before a matrix on its first block: a size, "N =" (its name), or a relation ("= "). */
const LEAD = /^\s*((?:\\(?:small|footnotesize|scriptsize)\s*)?)(?:([A-Za-z](?:_\{[^{}]*\}|_[A-Za-z0-9])?(?:\^\{?\\mathsf\{T\}\}?)?)\s*=|=|\\approx)?\s*$/;
/** What may follow a matrix on its last block: a comma or a full stop. */
const TRAIL = /^\s*[,.;]?\s*$/;

/**
 * A formula's top level with each grid replaced by "@k@": its operands and
 * the operators between them (=, +, −, \cdot, \times and the thin space of
 * a product), for matching a substituted formula to its symbolic form.
 */
function skeleton(tex) {
  let flat = "";
  let rest = tex;
  let k = 0;
  let g;
  while ((g = findGrid(rest))) {
    flat += `${g.before}@${k++}@`;
    rest = g.after;
  }
  flat += rest;
  const ops = [];
  const operands = [];
  let start = 0;
  scan(flat, (i, t, depth, paren) => {
    if (paren) return;
    const op = t.ch === "=" || t.ch === "+" || t.ch === "-" ? t.ch : ["cdot", "times", ","].includes(t.cmd) ? t.cmd : null;
    if (op === null) return;
    operands.push(flat.slice(start, i).trim());
    ops.push(op);
    start = i + (t.length ?? 1);
  });
  operands.push(flat.slice(start).trim());
  return { ops, operands };
}

/**
 * The names of the matrices of `substituted` (in their order), read from
 * the symbolic formula where both have the same operators
 * ("A\,X = L + V" names the three matrices of "[…]\,[…] = […] + V" A, X
 * and L); null where there is no name.
 * @param {string} symbolic
 * @param {string} substituted
 * @returns {(string | null)[]}
 */
export function gridNames(symbolic, substituted) {
  const b = skeleton(String(substituted ?? ""));
  const names = [];
  const a = symbolic ? skeleton(String(symbolic)) : null;
  const same = a && a.ops.join(" ") === b.ops.join(" ");
  b.operands.forEach((o, i) => {
    const m = /^@(\d+)@$/.exec(o);
    if (m) names[Number(m[1])] = same && SYMBOL.test(a.operands[i]) ? a.operands[i] : null;
  });
  // grids inside an operand ("s[…][…]") have no name of their own
  const count = (String(substituted ?? "").match(/\\begin\{/g) ?? []).length;
  return Array.from({ length: Math.max(names.length, 0) }, (_, k) => names[k] ?? null).slice(0, count);
}

/**
 * How a grid split into blocks sits in its term. A grid with only a size,
 * "N =" or a relation before it and only punctuation after keeps them on
 * its first and last blocks (`lead`, `trail`); otherwise the blocks carry
 * just the size and the term is written again after the whole matrix
 * (`rest`), the matrix's name (or "[matrix above]") standing for it.
 * `name` (LaTeX): "N" of "N = […]", else `known` (from the symbolic
 * formula: gridNames), else null.
 * @returns {{ size: string, lead: string, trail: string, name: string | null, rest: string | null }}
 */
export function gridContext(grid, known = null) {
  const size = /^\s*(\\(?:small|footnotesize|scriptsize)\s*)?/.exec(grid.before)[1] ?? "";
  const lead = LEAD.exec(grid.before);
  if (lead && TRAIL.test(grid.after)) return { size, lead: grid.before, trail: grid.after, name: lead[2] ?? known, rest: null };
  const stand = known ?? String.raw`\left[\,\text{matrix above}\,\right]`;
  const before = grid.before.slice(grid.before.indexOf(size) + size.length);
  return { size, lead: size, trail: "", name: known, rest: `${size}${before}${stand}${grid.after}`.trim() };
}

/** A matrix's name as plain text: "Aᵀ", "Q_xx". */
function matrixName(name) {
  return plainTex(name).replace(/\^\(?T\)?$/, "ᵀ").replace(/_\((\w+)\)/, "_$1");
}

/** A block's caption: "A, columns 1–3 of 4" (plain text). */
export function blockCaption(name, b) {
  const cols = b.from === b.to ? `column ${b.from} of ${b.of}` : `columns ${b.from}–${b.to} of ${b.of}`;
  return name ? `${matrixName(name)}, ${cols}` : cols;
}

// ---------------------------------------------------------------------------
// Rendering

/** Between boxes: a place to wrap that takes no room (KaTeX spaces the operators itself). */
const BREAK = "\u200b";

function katexInto(node, tex) {
  globalThis.katex.render(`\\displaystyle ${tex}`, node, KATEX_OPTIONS);
}

/** One term as an inline box; `lead` gives a leading + or − its binary spacing. */
function termNode(tex, first = false) {
  const node = document.createElement("span");
  node.className = "formula-term";
  node.dataset.tex = tex;
  // a continuation's + or − is an operation (a line's first − is a sign); a relation always is one
  const lead = (!first && /^[+\-]/.test(tex)) || /^=|^\\(approx|cdot|times)/.test(tex) ? "{}" : "";
  katexInto(node, lead + tex);
  return node;
}

/** Rows of a matrix or table shown before "Show all n rows". */
const ROWS_SHOWN = 8;
const ROWS_MAX = 12;

/**
 * A term holding a grid of more than ROWS_MAX rows: its first rows, a row of
 * dots and a button that shows the rest. Returns null for smaller terms.
 */
function longGridNode(tex) {
  const grid = findGrid(tex);
  if (!grid) return null;
  const rows = gridRows(grid.body);
  const header = grid.env === "array" ? 1 : 0;
  if (rows.length - header <= ROWS_MAX) return null;
  const ncols = Math.max(...rows.map((r) => r.cells.length));
  const dots = Array.from({ length: ncols }, () => "\\vdots").join(" & ");
  const kept = rows.slice(0, header + ROWS_SHOWN).map((r) => `${r.hline ? `${r.hline} ` : ""}${r.cells.join(" & ")}`);
  const spec = grid.env === "array" ? `{${grid.spec}}` : "";
  const short = `${grid.before}\\begin{${grid.env}}${spec} ${[...kept, dots].join(" \\\\ ")} \\end{${grid.env}}${grid.after}`;
  const wrap = document.createElement("span");
  wrap.className = "formula-long";
  const term = termNode(short);
  const more = document.createElement("button");
  more.type = "button";
  more.className = "button formula-more";
  more.textContent = `Show all ${rows.length - header} rows`;
  more.addEventListener("click", () => {
    const full = termNode(tex);
    wrap.replaceWith(full);
    const formula = full.closest(".formula");
    if (formula) fitOne(formula);
  });
  wrap.append(term, more);
  return wrap;
}

function lineNode(terms) {
  const line = document.createElement("span");
  line.className = "formula-line";
  terms.forEach((t, k) => {
    const node = longGridNode(t) ?? termNode(t, k === 0);
    line.append(...(k ? [BREAK, node] : [node]));
  });
  return line;
}

function pieceNode(piece, k) {
  const node = document.createElement("span");
  node.className = k === 0 ? "formula-piece" : "formula-piece formula-cont";
  const { lines } = splitTerms(piece);
  if (lines.length > 1) node.classList.add("formula-rows");
  lines.forEach((l, k) => node.append(...(k ? [" ", lineNode(l)] : [lineNode(l)])));
  return node;
}

/** One group: its pieces, or the whole group when a piece cannot stand alone. */
function groupNode(pieces) {
  const group = document.createElement("div");
  group.className = "formula-group";
  try {
    pieces.forEach((p, k) => group.append(...(k ? [BREAK, pieceNode(p, k)] : [pieceNode(p, k)])));
  } catch {
    group.replaceChildren(pieceNodeWhole(pieces.join(" ")));
  }
  return group;
}

function pieceNodeWhole(tex) {
  const node = document.createElement("span");
  node.className = "formula-piece";
  const line = document.createElement("span");
  line.className = "formula-line";
  line.append(termNode(tex));
  node.append(line);
  return node;
}


/** The formula `tex` typeset into `el` (renderFormula once KaTeX is in). */
export function typesetInto(el, tex) {
  try {
    try {
      splitFormula(tex).forEach((g, k) => el.append(...(k ? [" ", groupNode(g)] : [groupNode(g)])));
    } catch {
      // the pieces do not stand alone: the whole formula, unsplit
      el.replaceChildren(groupNodeWhole(tex));
    }
    el.setAttribute("data-tex", tex);
    return el;
  } catch (e) {
    el.replaceChildren();
    el.classList.add("formula-error");
    const code = document.createElement("code");
    code.textContent = tex;
    const why = document.createElement("span");
    why.className = "formula-error-why";
    why.textContent = `(formula could not be rendered: ${e && e.message ? e.message : e})`;
    el.append(code, why);
    return el;
  }
}

function groupNodeWhole(tex) {
  const group = document.createElement("div");
  group.className = "formula-group";
  group.append(pieceNodeWhole(tex));
  return group;
}

// ---------------------------------------------------------------------------
// Fitting after layout

/** Whether a term is wider than the line it sits on. */
function tooWide(term) {
  return term.clientWidth > 0 && term.scrollWidth > term.clientWidth + 1;
}

/**
 * The first rearrangement of a wide term (a write, no layout read): aligned
 * rows; a long left-hand side parted from its first relation; for a grid,
 * blocks of columns, a first guess from the widths read before (`room`,
 * `wide`): returns { node, grid, per } for a grid (fitAll tries fewer
 * columns while a block is still too wide), { node } otherwise, or null when
 * nothing can be rearranged.
 */
function refit(term, room, wide) {
  const tex = term.dataset.tex;
  const aligned = /^(\\(?:small|footnotesize|scriptsize)\s*)?\\begin\{aligned\}([\s\S]*)\\end\{aligned\}(\s*[,.;]?)$/.exec(tex.trim());
  if (aligned) {
    const size = aligned[1] ? `${aligned[1].trim()} ` : "";
    const rows = splitTop(aligned[2], "\\\\").map((r) => r.replace(/&/g, "").trim()).filter(Boolean).map((r) => size + r);
    const rowsNode = document.createElement("span");
    rowsNode.className = "formula-piece formula-rows formula-refit";
    rows.forEach((row, k) => rowsNode.append(...(k ? [" ", lineNode(termsOf(row))] : [lineNode(termsOf(row))])));
    term.replaceWith(rowsNode);
    return { node: rowsNode };
  }
  const found = findGrid(tex);
  // an equation around a matrix ("[…] = s[…]", "[…]\,[…] = […]") first parts at its
  // relation: the matrix may then fit whole; one that does not is split below
  const grid = found && { ...found, context: gridContext(found, knownName(term, found)) };
  if (grid && !(grid.context.rest !== null && firstRelation(tex) > 0)) {
    const rows = gridRows(grid.body);
    const ncols = Math.max(...rows.map((r) => r.cells.length));
    const first = grid.env === "array" ? 1 : 0;
    const n = ncols - first;
    // a first guess from the widths, then fewer columns a block until every block fits
    const per = Math.max(1, Math.min(n - 1, Math.floor((n * room) / wide)));
    const node = blocksNode(grid, per);
    term.replaceWith(node);
    return { node, grid, per };
  }
  // a long left-hand side and its first relation: they may part
  const at = firstRelation(tex);
  if (at > 0) {
    const line = lineNode([tex.slice(0, at).trim(), ...termsOf(tex.slice(at).trim())]);
    line.classList.add("formula-refit");
    term.replaceWith(line);
    return { node: line };
  }
  return null;
}

/** The name of a term's matrix from the symbolic formula of its step (gridNames), or null. */
function knownName(term, grid) {
  const formula = term.closest(".formula");
  if (!formula) return null;
  const full = formula.dataset.tex ?? "";
  const prev = formula.previousElementSibling;
  const symbolic = prev?.classList.contains("formula-symbolic") ? prev.dataset.tex : null;
  if (!symbolic) return null;
  const grids = [];
  let rest = full;
  let g;
  while ((g = findGrid(rest))) {
    grids.push(g);
    rest = g.after;
  }
  const k = grids.findIndex((x) => x.env === grid.env && x.body === grid.body);
  return k >= 0 ? (gridNames(symbolic, full)[k] ?? null) : null;
}

/** Where the first top-level relation ("=", \approx) of a term stands, or -1. */
function firstRelation(tex) {
  let at = -1;
  scan(tex, (i, t, depth, paren) => {
    if (at < 0 && paren === 0 && (t.ch === "=" || (t.cmd && RELATION_COMMANDS.includes(t.cmd)))) at = i;
  });
  return at;
}

/** A table as one line per data row: its first cell, then "header = cell" for the others. */
function rowLinesNode(grid) {
  const rows = gridRows(grid.body);
  const [head, ...data] = rows;
  const node = document.createElement("span");
  node.className = "formula-piece formula-rows formula-refit";
  data.forEach((row, k) => {
    const terms = [`${row.cells[0]}{:}`];
    row.cells.slice(1).forEach((cell, j) => terms.push(`${head.cells[j + 1] ?? ""} = ${cell}${j < row.cells.length - 2 ? "," : ""}`));
    node.append(...(k ? [" ", lineNode(terms)] : [lineNode(terms)]));
  });
  return node;
}

/**
 * A grid as blocks of `per` columns, each captioned with the matrix's name
 * ("A, columns 1–2 of 4"); what its term says around the matrix
 * (grid.context, gridContext) follows the whole matrix, on a line of its own.
 */
function blocksNode(grid, per) {
  const { size = "", lead = grid.before, trail = grid.after, name = null, rest = null } = grid.context ?? {};
  const node = document.createElement("span");
  node.className = "formula-piece formula-rows formula-refit formula-blocks";
  if (name) node.dataset.matrix = matrixName(name);
  const blocks = gridBlocks(grid, per);
  blocks.forEach((b, k) => {
    const block = document.createElement("span");
    block.className = "formula-block";
    const caption = document.createElement("span");
    caption.className = "formula-block-caption";
    caption.textContent = blockCaption(name, b);
    const before = k === 0 ? lead : size;
    const after = k === blocks.length - 1 ? trail : "";
    block.append(caption, termNode(`${before}${b.tex}${after}`));
    node.append(block);
  });
  if (rest) {
    // the equation, after the whole matrix
    const line = lineNode(termsOf(rest));
    line.classList.add("formula-blocks-rest");
    node.append(line);
  }
  return node;
}

/** How many times the parts of a rearranged term are rearranged again. */
const REFIT_DEPTH = 3;

/** refit, or null when the rearrangement fails (KaTeX cannot read it: the term stays whole, scrolling). */
function tryRefit(term, room, width) {
  try {
    return refit(term, room, width);
  } catch (e) {
    console.warn("formula could not be rearranged", e);
    return null;
  }
}

/** The last resort for an atom that cannot be broken: a labelled scroll region. */
function scrollable(term) {
  term.classList.add("formula-scroll");
  term.setAttribute("tabindex", "0");
  term.setAttribute("role", "region");
  term.setAttribute("aria-label", "Wide formula: scroll sideways to see all of it");
}

/**
 * Lays the formulas below `root` out again for the width they have now:
 * every refitted term starts from its original rendering, so a wider screen
 * gets whole matrices back.
 * @param {Element} root
 */
export function fitFormulas(root, { all = false } = {}) {
  fitAll([...root.querySelectorAll(".formula[data-tex]")], { all });
}

/** Fits one formula's terms as they are now (no new start: a grid shown whole stays whole). */
export function fitOne(formula) {
  fitAll([formula], { reset: false });
}

// Steps have content-visibility: auto (style.css): a step off screen is not
// laid out, and reading a width inside it would lay it out (Chromium) just to
// fit it. Its formulas wait instead, and are fitted when the browser renders
// the step (contentvisibilityautostatechange, skipped false): scrolled to,
// found, focused, or printed (keepFitted renders every step before print).

/** The elements with content-visibility: auto that hold formulas. */
const LAZY = ".steps > .step";
/** Formulas waiting for their step to be rendered: step → Map(formula → reset). */
const waiting = new WeakMap();

function fitLater(step, formula, reset) {
  let list = waiting.get(step);
  if (!list) waiting.set(step, (list = new Map()));
  list.set(formula, reset || list.get(formula) === true);
}

/** Fits what waits in `step`, rendered now; a formula replaced since was fitted as the new one. */
function fitWaiting(step) {
  const list = waiting.get(step);
  if (!list) return;
  waiting.delete(step);
  const live = [...list].filter(([formula]) => formula.isConnected && step.contains(formula));
  fitAll(live.filter(([, reset]) => reset).map(([formula]) => formula));
  fitAll(live.filter(([, reset]) => !reset).map(([formula]) => formula), { reset: false });
}

if (typeof document !== "undefined") {
  // the event does not bubble: caught on its way down. Fitted at once; the steps rendered
  // together share a layout (a fitting that rearranged nothing leaves none to redo)
  document.addEventListener(
    "contentvisibilityautostatechange",
    (event) => {
      if (!event.skipped) fitWaiting(event.target);
    },
    true,
  );
}

/**
 * Fits `formulas` (elements .formula[data-tex]) to their lines, reading the
 * layout in as few passes as it can: all the writes of a pass, then all the
 * reads, so the page is laid out once per pass (usually one, a second when a
 * term was rearranged), not once per formula. A term wider than its line is
 * rearranged (refit); a grid gets fewer columns a block while a block is
 * still too wide; what still cannot fit scrolls (scrollable). With `reset`
 * a formula rearranged before starts again from its rendering. With `all`
 * every formula is read, those in steps off screen too (print: rendered
 * by then, the browser has not yet said so).
 * @param {Element[]} formulas
 * @param {{ reset?: boolean }} [options]
 */
export function fitAll(formulas, { reset = true, all = false } = {}) {
  // only what is rendered: a formula in a step off screen waits for the step (fitLater)
  const shown = formulas.filter((formula) => {
    if (all || !formula.checkVisibility || formula.checkVisibility({ contentVisibilityAuto: true })) return true;
    // not rendered: skipped (its step off screen) or hidden (a closed fold, display: none;
    // no width to fit to). Not told apart: checkVisibility() without the option would lay
    // a skipped step out. A step's formulas wait for it to be rendered.
    const step = formula.closest(LAZY);
    if (step) fitLater(step, formula, reset);
    return false;
  });
  // writes: a formula rearranged before starts again from its rendering
  const list = shown.map((formula) => {
    if (!reset || !formula.querySelector(".formula-refit, .formula-scroll")) return formula;
    const fresh = renderFormula(formula.dataset.tex, formula.className);
    formula.replaceWith(fresh);
    return fresh;
  });
  // reads (one layout): the terms wider than their line, with their widths
  const wide = [];
  for (const formula of list) {
    if (formula.clientWidth === 0) continue; // not laid out (hidden)
    for (const term of formula.querySelectorAll(".formula-term")) {
      if (tooWide(term)) wide.push({ term, room: term.clientWidth, width: term.scrollWidth });
    }
  }
  if (!wide.length) return;
  // writes: the first rearrangement of each
  let jobs = wide.map(({ term, room, width }) => ({ term, depth: 0, ...(tryRefit(term, room, width) ?? { node: null }) }));
  const stuck = [];
  while (jobs.length) {
    // reads: which new terms are still too wide (with their widths)
    const next = [];
    const still = jobs.map((job) =>
      job.node ? [...job.node.querySelectorAll(".formula-term")].filter(tooWide).map((term) => ({ term, room: term.clientWidth, width: term.scrollWidth })) : [{ term: job.term }],
    );
    // writes: a grid with blocks still too wide tries fewer columns; a term around it (or a
    // part of an equation) still too wide is rearranged in its turn, a few levels deep; the rest is done
    jobs.forEach((job, k) => {
      if (!still[k].length) return;
      if (!job.node) {
        stuck.push(...still[k].map((w) => w.term));
        return;
      }
      const ownBlock = (w) => job.grid && w.term.parentElement?.classList.contains("formula-block") && w.term.parentElement.parentElement === job.node;
      const blocks = still[k].filter(ownBlock);
      if (!blocks.length) {
        for (const w of still[k]) {
          const again = (job.depth ?? 0) < REFIT_DEPTH ? tryRefit(w.term, w.room, w.width) : null;
          if (again?.node) next.push({ term: w.term, ...again, depth: (job.depth ?? 0) + 1 });
          else stuck.push(w.term);
        }
        return;
      }
      try {
        if (job.per === 1) {
          if (job.grid.env !== "array") {
            stuck.push(...blocks.map((w) => w.term));
            return;
          }
          // a table too wide even one column at a time: one line per row, "key: header = cell"
          const lines = rowLinesNode(job.grid);
          job.node.replaceWith(lines);
          next.push({ term: job.term, node: lines, depth: job.depth });
          return;
        }
        const per = Math.max(1, Math.min(job.per - 1, Math.floor(job.per * 0.8)));
        const node = blocksNode(job.grid, per);
        job.node.replaceWith(node);
        next.push({ ...job, node, per });
      } catch (e) {
        console.warn("formula could not be rearranged", e);
        stuck.push(...blocks.map((w) => w.term));
      }
    });
    jobs = next;
  }
  stuck.forEach(scrollable);
}
