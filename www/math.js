// KaTeX rendering that fits any width, with a plain-text fallback.
//
// The one place where formulas are broken into lines (issue 13): a formula
// never needs sideways scrolling, on a phone, at 1280 px or on paper.
//   1. splitFormula: top-level groups (at \quad, \qquad and ",\ " between
//      equations), each group a chain of pieces before its second, third…
//      relation ("a = b", "= c", "= 35.6 cm").
//   2. splitTerms: each piece into terms before a top-level binary + or −,
//      and at list separators (\; and ",\ " inside brackets); a gathered
//      block into its rows. The terms flow: as many on a line as fit, the
//      next line indented, the result after the last "=" on its own piece.
//   3. fitFormulas (after layout, and again when the width changes): a term
//      still wider than its line is laid out again: an aligned block as one
//      line per row, a matrix or table as blocks of columns ("columns 1–4 of
//      8", a table keeping its first column); what still cannot fit (one
//      huge atom) becomes a labelled, focusable scroll region.
// katex.render builds the DOM itself and escapes its input; when it fails
// on bad LaTeX the raw LaTeX is shown as text; when KaTeX did not load, the
// plain-text form (plainTex) stays.

// KaTeX is off the critical path (issue 19): the first numbers do not wait for
// it, nor share the network with it. A formula asked for before KaTeX has
// arrived is drawn at once as plain text (plainTex: the numbers readable, the
// room taken) and marked .formula-pending; the first such formula schedules
// KaTeX's load (script and stylesheet) for after the frame that paints those
// numbers (scheduleMath: no request starts before the page's first-solution
// mark), and when both are in every pending formula is typeset in place and
// fitted. <html data-math> says where that is: "loading" (from the
// scheduling on), "ready" or "failed" (then the plain text stays). whenMath()
// starts the load at once.
//
// The minified UMD build (76 KB gzipped) rather than katex.mjs (146 KB
// gzipped, not minified): loaded by a script element, it sets window.katex.
const KATEX_URL = "./vendor/katex/katex.min.js";
const KATEX_CSS = "./vendor/katex/katex.min.css";
const KATEX_OPTIONS = Object.freeze({
  displayMode: false, // terms are inline boxes; \displaystyle keeps display-size fractions
  throwOnError: true,
  trust: false, // no \href, \url, \includegraphics, \htmlClass...
  strict: "ignore",
  maxSize: 20,
  maxExpand: 1000,
  output: "htmlAndMathml", // MathML for screen readers
});

let katex = null;
let loadError = null;
let loading = null;
/** Formulas drawn before KaTeX arrived, typeset when it does (attached to the page or not). */
const pending = new Set();

function loadOne(tag, attrs, what) {
  return new Promise((resolve, reject) => {
    const node = document.createElement(tag);
    Object.assign(node, attrs);
    node.onload = resolve;
    node.onerror = () => reject(new Error(`${what} did not load`));
    document.head.append(node);
  });
}

/** Starts loading KaTeX once; resolves when it is in (or has failed: the page works without it). */
function startMath() {
  if (katex || loadError) return Promise.resolve();
  if (loading) return loading;
  if (typeof document === "undefined") return Promise.resolve();
  document.documentElement.dataset.math = "loading";
  loading = Promise.all([
    loadOne("link", { rel: "stylesheet", href: KATEX_CSS }, KATEX_CSS),
    loadOne("script", { src: KATEX_URL }, KATEX_URL),
  ])
    .then(() => {
      if (!window.katex) throw new Error("katex.min.js loaded but defined no katex");
      katex = window.katex;
    })
    .catch((e) => {
      loadError = e;
      console.warn("KaTeX did not load; formulas are shown as LaTeX source.", e);
    })
    .then(typesetPending);
  return loading;
}

/** After the next frame (the plain-text numbers painted), a hidden tab's timer failing that. */
const MATH_FALLBACK_MS = 250;
let scheduled = false;

/**
 * Starts loading KaTeX once the frame that paints the first formulas is
 * done: never inside the task that renders the first solution, so KaTeX's
 * bytes are not on its critical path. A tab without frames (hidden) starts
 * it by a timer instead. Idempotent, like startMath.
 */
function scheduleMath() {
  if (scheduled || katex || loadError || loading || typeof document === "undefined") return;
  scheduled = true;
  document.documentElement.dataset.math = "loading"; // on its way (tests wait for "ready")
  const go = () => void startMath();
  requestAnimationFrame(() => setTimeout(go, 0));
  setTimeout(go, MATH_FALLBACK_MS);
}

/**
 * Makes KaTeX available without holding anything up: resolves at once (the
 * formulas drawn meanwhile are typeset when it arrives). `whenMath()` waits.
 */
export async function loadMath() {}

/** Resolves when KaTeX has loaded (or failed), starting the load if needed. */
export function whenMath() {
  return startMath();
}

function typesetPending() {
  const nodes = [...pending];
  pending.clear();
  for (const node of nodes) {
    const fresh = renderFormula(node.dataset.tex, node.dataset.className);
    node.className = fresh.className;
    node.removeAttribute("aria-busy");
    delete node.dataset.className;
    node.replaceChildren(...fresh.childNodes);
  }
  // fitted after every formula is in: one layout, not one per formula
  for (const node of nodes) if (node.isConnected && katex) fitOne(node);
  document.documentElement.dataset.math = katex ? "ready" : "failed";
}

/** Greek letters and symbols plainTex writes as characters. */
const PLAIN_SYMBOLS = {
  cdot: "·", times: "×", approx: "≈", pm: "±", mp: "∓", le: "≤", leq: "≤", ge: "≥", geq: "≥", neq: "≠", ne: "≠",
  circ: "°", degree: "°", infty: "∞", sum: "Σ", prod: "Π", partial: "∂", to: "→", rightarrow: "→", lvert: "|", rvert: "|",
  alpha: "α", beta: "β", gamma: "γ", delta: "δ", epsilon: "ε", varepsilon: "ε", zeta: "ζ", eta: "η", theta: "θ",
  kappa: "κ", lambda: "λ", mu: "μ", nu: "ν", xi: "ξ", pi: "π", rho: "ρ", sigma: "σ", tau: "τ", phi: "φ",
  varphi: "φ", chi: "χ", psi: "ψ", omega: "ω", Gamma: "Γ", Delta: "Δ", Theta: "Θ", Lambda: "Λ", Sigma: "Σ",
  Phi: "Φ", Psi: "Ψ", Omega: "Ω", ldots: "…", cdots: "⋯", dots: "…", vdots: "⋮", quad: "  ", qquad: "   ",
};
const SUPERSCRIPTS = { 0: "⁰", 1: "¹", 2: "²", 3: "³", 4: "⁴", 5: "⁵", 6: "⁶", 7: "⁷", 8: "⁸", 9: "⁹", "-": "⁻", "+": "⁺" };

/** Combining marks for accents: \bar{A} → Ā (A + U+0304). */
const ACCENTS = { bar: "\u0304", overline: "\u0305", hat: "\u0302", tilde: "\u0303", vec: "\u20d7" };
const accented = (a, acc) => (/^[A-Za-z]$/.test(a) ? a + ACCENTS[acc] : `${a}${ACCENTS[acc]}`);

/**
 * A formula as plain text, shown until KaTeX has arrived (and kept if it cannot load): every number as
 * written, \frac{a}{b} as (a)/(b), \sqrt{x} as √(x), Greek letters and
 * operators as characters, matrices as [a b; c d].
 * @param {string} tex
 */
export function plainTex(tex) {
  let s = String(tex);
  const arg = String.raw`\{([^{}]*)\}`;
  for (let k = 0; k < 8; k++) {
    const before = s;
    s = s
      .replace(new RegExp(String.raw`\\[dt]?frac\s*${arg}\s*${arg}`, "g"), (m, a, b) => `${/^[\w.]+$/.test(a) ? a : `(${a})`}/${/^[\w.]+$/.test(b) ? b : `(${b})`}`)
      .replace(new RegExp(String.raw`\\sqrt\s*(?:\[([^\]]*)\])?\s*${arg}`, "g"), (m, n, a) => `${n ? SUPERSCRIPTS[n] ?? n : ""}√(${a})`)
      .replace(new RegExp(String.raw`\\(bar|overline|hat|tilde|vec)\s*${arg}`, "g"), (m, acc, a) => accented(a, acc))
      .replace(/\\(bar|hat|tilde|vec)\s+([A-Za-z])/g, (m, acc, a) => accented(a, acc))
      .replace(new RegExp(String.raw`\\(?:text|mathrm|mathbf|mathit|operatorname|boldsymbol|mathsf|textbf|textit)\s*${arg}`, "g"), "$1")
      .replace(new RegExp(String.raw`\^${arg}`, "g"), (m, a) => ([...a].every((c) => SUPERSCRIPTS[c]) ? [...a].map((c) => SUPERSCRIPTS[c]).join("") : `^(${a})`))
      .replace(new RegExp(String.raw`_${arg}`, "g"), (m, a) => (a.length > 1 ? `_(${a})` : `_${a}`));
    if (s === before) break;
  }
  return s
    .replace(/\\begin\{[a-z]*matrix\}([\s\S]*?)\\end\{[a-z]*matrix\}/g, (m, body) => `[${body.replace(/\s*&\s*/g, " ").replace(/\s*\\\\\s*/g, "; ").trim()}]`)
    .replace(/\\(begin|end)\{[A-Za-z*]+\}(\{[^{}]*\})?/g, " ")
    .replace(/\^([0-9])/g, (m, d) => SUPERSCRIPTS[d])
    .replace(/\\\\/g, "; ")
    .replace(/&/g, " ")
    .replace(/\\(left|right|big|Big|bigl|bigr|Bigl|Bigr|displaystyle|small|footnotesize|scriptsize|hline)\b/g, "")
    .replace(/\\([A-Za-z]+)/g, (m, name) => PLAIN_SYMBOLS[name] ?? name)
    .replace(/\\[,;:! ]/g, " ")
    .replace(/\\([{}%$#_])/g, "$1")
    .replace(/[{}]/g, "")
    .replace(/\s+/g, " ")
    .trim();
}

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
// Rendering

/** Between boxes: a place to wrap that takes no room (KaTeX spaces the operators itself). */
const BREAK = "\u200b";

function katexInto(node, tex) {
  katex.render(`\\displaystyle ${tex}`, node, KATEX_OPTIONS);
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

/**
 * Renders `tex` into a new element and returns it, split (see splitFormula,
 * splitTerms) into pieces that sit on one line when there is room and wrap
 * when there is not. Call fitFormulas on an ancestor once it is in the page.
 * @param {string} tex
 * @param {string} className
 */
export function renderFormula(tex, className = "formula") {
  const el = document.createElement("div");
  el.className = className;
  if (katex) {
    try {
      try {
        splitFormula(String(tex)).forEach((g, k) => el.append(...(k ? [" ", groupNode(g)] : [groupNode(g)])));
      } catch {
        // the pieces do not stand alone: the whole formula, unsplit
        el.replaceChildren(groupNodeWhole(String(tex)));
      }
      el.setAttribute("data-tex", String(tex));
      return el;
    } catch (e) {
      el.replaceChildren();
      el.classList.add("formula-error");
      const code = document.createElement("code");
      code.textContent = String(tex);
      const why = document.createElement("span");
      why.className = "formula-error-why";
      why.textContent = `(formula could not be rendered: ${e && e.message ? e.message : e})`;
      el.append(code, why);
      return el;
    }
  }
  if (!loadError) {
    // KaTeX is on its way: the numbers now, typeset when it is in
    el.classList.add("formula-pending");
    el.dataset.tex = String(tex);
    el.dataset.className = className;
    el.setAttribute("aria-busy", "true");
    const text = document.createElement("span");
    text.className = "formula-plain";
    text.textContent = plainTex(tex);
    el.append(text);
    pending.add(el);
    scheduleMath();
    return el;
  }
  // KaTeX could not be loaded: the plain text stays (readable numbers, not LaTeX source)
  el.classList.add("formula-raw");
  el.dataset.tex = String(tex);
  const text = document.createElement("span");
  text.className = "formula-plain";
  text.textContent = plainTex(tex);
  el.append(text);
  return el;
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

/** The alternatives of a wide term: aligned rows, or blocks of columns. */
function refit(term) {
  const tex = term.dataset.tex;
  const aligned = /^(\\(?:small|footnotesize|scriptsize)\s*)?\\begin\{aligned\}([\s\S]*)\\end\{aligned\}(\s*[,.;]?)$/.exec(tex.trim());
  if (aligned) {
    const size = aligned[1] ? `${aligned[1].trim()} ` : "";
    const rows = splitTop(aligned[2], "\\\\").map((r) => r.replace(/&/g, "").trim()).filter(Boolean).map((r) => size + r);
    const rowsNode = document.createElement("span");
    rowsNode.className = "formula-piece formula-rows formula-refit";
    rows.forEach((row, k) => rowsNode.append(...(k ? [" ", lineNode(termsOf(row))] : [lineNode(termsOf(row))])));
    term.replaceWith(rowsNode);
    return rowsNode;
  }
  const grid = findGrid(tex);
  if (grid) {
    const rows = gridRows(grid.body);
    const ncols = Math.max(...rows.map((r) => r.cells.length));
    const first = grid.env === "array" ? 1 : 0;
    const n = ncols - first;
    // a first guess from the widths, then fewer columns a block until every block fits
    const room = term.clientWidth;
    let per = Math.max(1, Math.min(n - 1, Math.floor((n * room) / term.scrollWidth)));
    for (;;) {
      const node = blocksNode(grid, per);
      term.replaceWith(node);
      if (![...node.querySelectorAll(".formula-term")].some(tooWide)) return node;
      if (per === 1) {
        if (grid.env !== "array") return node;
        // a table too wide even one column at a time: one line per row, "key: header = cell"
        const lines = rowLinesNode(grid);
        node.replaceWith(lines);
        return lines;
      }
      node.replaceWith(term);
      per = Math.max(1, Math.min(per - 1, Math.floor(per * 0.8)));
    }
  }
  // a long left-hand side and its first relation: they may part
  const at = firstRelation(tex);
  if (at > 0) {
    const line = lineNode([tex.slice(0, at).trim(), ...termsOf(tex.slice(at).trim())]);
    line.classList.add("formula-refit");
    term.replaceWith(line);
    return line;
  }
  return null;
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

function blocksNode(grid, per) {
  const node = document.createElement("span");
  node.className = "formula-piece formula-rows formula-refit formula-blocks";
  const blocks = gridBlocks(grid, per);
  blocks.forEach((b, k) => {
    const block = document.createElement("span");
    block.className = "formula-block";
    const caption = document.createElement("span");
    caption.className = "formula-block-caption";
    caption.textContent = b.from === b.to ? `column ${b.from} of ${b.of}` : `columns ${b.from}–${b.to} of ${b.of}`;
    const before = k === 0 ? grid.before : "";
    const after = k === blocks.length - 1 ? grid.after : "";
    block.append(caption, termNode(`${before}${b.tex}${after}`));
    node.append(block);
  });
  return node;
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
export function fitFormulas(root) {
  if (!katex || !root) return;
  for (const formula of root.querySelectorAll(".formula[data-tex]")) {
    if (formula.querySelector(".formula-refit, .formula-scroll")) {
      const fresh = renderFormula(formula.dataset.tex, formula.className);
      formula.replaceWith(fresh);
      fitOne(fresh);
    } else {
      fitOne(formula);
    }
  }
}

function fitOne(formula) {
  if (formula.clientWidth === 0) return; // not laid out (hidden)
  for (const term of [...formula.querySelectorAll(".formula-term")]) {
    if (!tooWide(term)) continue;
    let node = null;
    try {
      node = refit(term);
    } catch (e) {
      // a rearrangement KaTeX cannot read: the term stays whole, scrolling
      console.warn("formula could not be rearranged", e);
    }
    const still = node ? [...node.querySelectorAll(".formula-term")].filter(tooWide) : [term];
    still.forEach(scrollable);
  }
}

/**
 * Keeps the formulas below `root` fitted as its width changes (a phone
 * turned, a window resized, the print layout). Returns a stop function.
 */
export function keepFitted(root) {
  let width = root.clientWidth;
  let frame = 0;
  const observer = new ResizeObserver(() => {
    if (root.clientWidth === width) return;
    width = root.clientWidth;
    cancelAnimationFrame(frame);
    frame = requestAnimationFrame(() => fitFormulas(root));
  });
  observer.observe(root);
  const again = () => fitFormulas(root);
  window.addEventListener("beforeprint", again);
  // KaTeX's fonts arrive after the first layout and make every formula wider
  document.fonts?.addEventListener?.("loadingdone", again);
  document.fonts?.ready?.then(again);
  return () => {
    observer.disconnect();
    window.removeEventListener("beforeprint", again);
    document.fonts?.removeEventListener?.("loadingdone", again);
  };
}
