// KaTeX rendering with a plain-text fallback.
// katex.render builds the formula's DOM itself and escapes its input; when it
// fails (bad LaTeX, or KaTeX did not load) the raw LaTeX is shown as text.

// The minified UMD build (76 KB gzipped) rather than katex.mjs (146 KB
// gzipped, not minified): loaded by a script element, it sets window.katex.
const KATEX_URL = "./vendor/katex/katex.min.js";
const KATEX_OPTIONS = Object.freeze({
  displayMode: true,
  throwOnError: true,
  trust: false, // no \href, \url, \includegraphics, \htmlClass...
  strict: "ignore",
  maxSize: 20,
  maxExpand: 1000,
  output: "htmlAndMathml", // MathML for screen readers
});

let katex = null;
let loadError = null;

/** Loads KaTeX once; the page works without it (raw LaTeX shown). */
export async function loadMath() {
  if (katex || loadError) return;
  try {
    await new Promise((resolve, reject) => {
      const script = document.createElement("script");
      script.src = KATEX_URL;
      script.onload = resolve;
      script.onerror = () => reject(new Error(`${KATEX_URL} did not load`));
      document.head.append(script);
    });
    if (!window.katex) throw new Error("katex.min.js loaded but defined no katex");
    katex = window.katex;
  } catch (e) {
    loadError = e;
    console.warn("KaTeX did not load; formulas are shown as LaTeX source.", e);
  }
}

/** Spacing commands after which a formula may wrap ("x = 1,\quad y = 2"). */
const BREAK_COMMANDS = ["qquad", "quad"];
/** Relations before which a chain may wrap ("GSD = p·m = 356 mm = 35.6 cm"). */
const RELATION_COMMANDS = ["approx"];

/**
 * Splits a formula where it may wrap, at the top level only (outside braces,
 * \left…\right and environments):
 *   - into groups at "\quad"/"\qquad" ("x = …,\quad y = …" -> two groups);
 *   - each group into pieces before its second, third… "=" or "\approx", the
 *     relation starting the next piece ("a = b = c" -> "a = b", "= c").
 * Returns [[tex]] when there is no such place.
 * @param {string} tex
 * @returns {string[][]}
 */
export function splitFormula(tex) {
  const groups = [];
  let pieces = [];
  let depth = 0;
  let start = 0;
  let i = 0;
  const cut = (end) => {
    const piece = tex.slice(start, end).trim();
    if (piece) pieces.push(piece);
  };
  while (i < tex.length) {
    const ch = tex[i];
    if (ch === "\\") {
      const m = /^\\([A-Za-z]+|.)/.exec(tex.slice(i));
      const name = m ? m[1] : "";
      const length = 1 + Math.max(name.length, 1);
      if (name === "left" || name === "begin") depth += 1;
      else if (name === "right" || name === "end") depth -= 1;
      else if (depth === 0 && BREAK_COMMANDS.includes(name)) {
        cut(i);
        if (pieces.length) groups.push(pieces);
        pieces = [];
        start = i + length;
      } else if (depth === 0 && RELATION_COMMANDS.includes(name)) {
        cut(i);
        start = i;
      }
      i += length;
      continue;
    }
    if (ch === "{") depth += 1;
    else if (ch === "}") depth -= 1;
    else if (ch === "=" && depth === 0) {
      cut(i);
      start = i;
    }
    i += 1;
  }
  cut(tex.length);
  if (pieces.length) groups.push(pieces);
  if (depth !== 0 || groups.length === 0) return [[tex]];
  // the left-hand side stays with the first relation: "GSD = a × b", "= 356 mm", …
  return groups.map((g) => (g.length > 1 ? [`${g[0]} ${g[1]}`, ...g.slice(2)] : g));
}

function katexNode(tex, className) {
  const node = document.createElement("div");
  node.className = className;
  katex.render(tex, node, KATEX_OPTIONS);
  return node;
}

/** One group: its pieces, or the whole group when a piece cannot stand alone. */
function renderGroup(pieces) {
  const group = document.createElement("div");
  group.className = "formula-group";
  try {
    group.append(...pieces.map((piece, k) => katexNode(piece, k === 0 ? "formula-part" : "formula-part formula-cont")));
  } catch {
    group.replaceChildren(katexNode(pieces.join(" "), "formula-part"));
  }
  return group;
}

/**
 * Renders `tex` in display mode into a new element and returns it, split
 * (see splitFormula) into pieces that sit on one line when there is room and
 * wrap when there is not.
 * @param {string} tex
 * @param {string} className
 */
export function renderFormula(tex, className = "formula") {
  const el = document.createElement("div");
  el.className = className;
  if (katex) {
    try {
      try {
        el.replaceChildren(...splitFormula(String(tex)).map(renderGroup));
      } catch {
        // the pieces do not stand alone: the whole formula, unsplit
        el.replaceChildren(katexNode(String(tex), "formula-part"));
      }
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
  el.classList.add("formula-raw");
  const code = document.createElement("code");
  code.textContent = String(tex);
  el.append(code);
  return el;
}
