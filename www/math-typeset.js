// The KaTeX side of math.js (issue 19): a formula's nodes, made from its plan
// (formula-plan.js: one group per relation of the step, items and terms
// from the step's parts), and fitted to their width after layout. Loaded
// with KaTeX (math.js startMath: script, stylesheet and this module in
// parallel), after the first numbers are on screen. Imports nothing of
// math.js: math.js loads this module and calls it.
//
// Fitting (after layout, and again when the width changes): a term wider
// than its line is laid out again from its plan — a matrix or table as
// blocks of columns captioned with its name ("A, columns 1–4 of 8", a table
// keeping its first column), a left-hand side parted from its first
// relation; what still cannot fit (one huge atom) becomes a labelled,
// focusable scroll region. A step without parts is one KaTeX block.

import { blockCaption, gridBlocks, gridColumns, gridTermTex, planFormula, shortGrid, tableRowLines } from "./formula-plan.js";

const KATEX_OPTIONS = Object.freeze({
  displayMode: false, // terms are inline boxes; \displaystyle keeps display-size fractions
  throwOnError: true,
  trust: false, // no \href, \url, \includegraphics, \htmlClass...
  strict: "ignore",
  maxSize: 20,
  maxExpand: 1000,
  output: "htmlAndMathml", // MathML for screen readers
});

/** Between boxes: a place to wrap that takes no room (KaTeX spaces the operators itself). */
const BREAK = "\u200b";

/** The source of each formula element (formula-plan.js formulaSource), to lay it out again. */
const sources = new WeakMap();
/** The plan of each term node ({ tex, apart } or a grid term) and whether it leads its group: what refit reads. */
const terms = new WeakMap();

function katexInto(node, tex) {
  globalThis.katex.render(`\\displaystyle ${tex}`, node, KATEX_OPTIONS);
}

/**
 * A formula's LaTeX as plain text, from KaTeX's own MathML (its annotation,
 * the LaTeX source, left out): "Q_{xx}" → "Qxx", "A^{\mathsf T}" → "AT".
 * @param {string} tex
 */
export function plainText(tex) {
  const box = document.createElement("span");
  globalThis.katex.render(tex, box, { ...KATEX_OPTIONS, output: "mathml", throwOnError: false });
  box.querySelectorAll("annotation").forEach((a) => a.remove());
  return box.textContent.replace(/\s+/g, " ").trim();
}

/**
 * One term as an inline box. Every term but a line's first is an operand
 * after something ("{}" before it gives a leading +, − or = its binary or
 * relation spacing).
 */
function termNode(term, first) {
  const node = document.createElement("span");
  node.className = "formula-term";
  const tex = term.grid ? gridTermTex(term) : term.tex;
  node.dataset.tex = tex;
  terms.set(node, { term, first });
  katexInto(node, first ? tex : `{}${tex}`);
  return node;
}

/**
 * A grid term of more than ROWS_MAX rows: its first rows, a row of dots and
 * a button that shows the rest. Returns null for smaller grids.
 */
function longGridNode(term, first) {
  const short = term.grid && shortGrid(term.grid);
  if (!short) return null;
  const wrap = document.createElement("span");
  wrap.className = "formula-long";
  const node = document.createElement("span");
  node.className = "formula-term";
  node.dataset.tex = gridTermTex(term, short.rows);
  // too wide, its first rows split into blocks of columns like any grid
  terms.set(node, { term: { ...term, grid: { ...term.grid, rows: short.rows } }, first });
  katexInto(node, first ? node.dataset.tex : `{}${node.dataset.tex}`);
  const more = document.createElement("button");
  more.type = "button";
  more.className = "button formula-more";
  more.textContent = `Show all ${short.count} rows`;
  more.addEventListener("click", () => {
    const full = termNode(term, first);
    wrap.replaceWith(full);
    const formula = full.closest(".formula");
    if (formula) fitAll([formula], { reset: false });
  });
  wrap.append(node, more);
  return wrap;
}

/** A line of terms that flow (as many on a line as fit, the next line indented). */
function lineNode(list, firstOfGroup) {
  const line = document.createElement("span");
  line.className = "formula-line";
  list.forEach((t, k) => {
    const first = firstOfGroup && k === 0;
    const node = longGridNode(t, first) ?? termNode(t, first);
    line.append(...(k ? [BREAK, node] : [node]));
  });
  return line;
}

/** One relation: its items ("GSD = p·m", "= 356 mm", …), each a piece that may wrap. */
function groupNode(group) {
  const node = document.createElement("div");
  node.className = "formula-group";
  if (group.key) node.dataset.key = group.key;
  group.items.forEach((item, k) => {
    const piece = document.createElement("span");
    piece.className = item.cont ? "formula-piece formula-cont" : "formula-piece";
    piece.append(lineNode(item.terms, k === 0));
    node.append(...(k ? [BREAK, piece] : [piece]));
  });
  return node;
}

/**
 * The formula of `source` (formula-plan.js formulaSource) typeset into `el`
 * (renderFormula once KaTeX is in): one group per relation, or one block
 * when the step has no parts; the LaTeX text itself when KaTeX rejects it.
 * @param {Element} el
 * @param {{ tex: string, relations: object[] | null, side: string }} source
 */
export function typesetInto(el, source) {
  sources.set(el, source);
  el.setAttribute("data-tex", source.tex);
  try {
    const plan = planFormula(source);
    const groups = plan.whole !== undefined ? [{ key: null, items: [{ cont: false, terms: [{ tex: plan.whole }] }] }] : plan.groups;
    el.replaceChildren(...groups.flatMap((g, k) => (k ? [" ", groupNode(g)] : [groupNode(g)])));
    return el;
  } catch (e) {
    el.replaceChildren();
    el.classList.add("formula-error");
    const code = document.createElement("code");
    code.textContent = source.tex;
    const why = document.createElement("span");
    why.className = "formula-error-why";
    why.textContent = `(formula could not be rendered: ${e && e.message ? e.message : e})`;
    el.append(code, why);
    return el;
  }
}

// ---------------------------------------------------------------------------
// Fitting after layout

/** Whether a term is wider than the line it sits on. */
function tooWide(term) {
  return term.clientWidth > 0 && term.scrollWidth > term.clientWidth + 1;
}

/**
 * The first rearrangement of a wide term (a write, no layout read), from
 * its plan: a grid as blocks of columns, a first guess from the widths read
 * before (`room`, `wide`): returns { node, grid, per } (fitAll tries fewer
 * columns while a block is still too wide); a left-hand side parted from its
 * first relation: { node }; null when nothing can be rearranged.
 */
function refit(node, room, wide) {
  const planned = terms.get(node);
  if (!planned) return null;
  const { term, first } = planned;
  if (term.grid) {
    const n = gridColumns(term.grid) - (term.grid.env === "array" ? 1 : 0);
    if (n < 2) return null;
    // a first guess from the widths, then fewer columns a block until every block fits
    const per = Math.max(1, Math.min(n - 1, Math.floor((n * room) / wide)));
    const blocks = blocksNode(term, per, first);
    node.replaceWith(blocks);
    return { node: blocks, plan: term, per, first };
  }
  if (term.apart) {
    const line = lineNode(term.apart.map((tex) => ({ tex })), first);
    line.classList.add("formula-refit");
    node.replaceWith(line);
    return { node: line };
  }
  return null;
}

/** A table as one line per data row: "key: header = cell, …". */
function rowLinesNode(term) {
  const node = document.createElement("span");
  node.className = "formula-piece formula-rows formula-refit";
  tableRowLines(term.grid).forEach((line, k) => node.append(...(k ? [" ", lineNode(line.map((tex) => ({ tex })), true)] : [lineNode(line.map((tex) => ({ tex })), true)])));
  return node;
}

/** A matrix's name as plain text ("A", "Qxx") for its blocks' captions. */
function nameText(name) {
  if (!name) return null;
  try {
    return plainText(name);
  } catch {
    return null;
  }
}

/**
 * A grid as blocks of `per` columns, each captioned with the matrix's name
 * ("A, columns 1–2 of 4"; data-caption holds the caption as plain text, the
 * name typeset in it): what leads the matrix ("N =") on its first block;
 * what follows the matrix in the equation comes after the whole of it (the
 * blocks are a block of their own).
 */
function blocksNode(term, per, first) {
  const node = document.createElement("span");
  node.className = "formula-piece formula-rows formula-refit formula-blocks";
  const name = term.grid.env === "array" ? null : term.name;
  const plain = nameText(name);
  if (plain) node.dataset.matrix = plain;
  gridBlocks(term.grid, per).forEach((b, k) => {
    const block = document.createElement("span");
    block.className = "formula-block";
    const caption = document.createElement("span");
    caption.className = "formula-block-caption";
    caption.dataset.caption = blockCaption(plain, b);
    if (plain) {
      const typeset = document.createElement("span");
      typeset.className = "formula-block-name";
      globalThis.katex.render(name, typeset, KATEX_OPTIONS);
      caption.append(typeset, blockCaption("", b).replace(/^/, ", "));
    } else {
      caption.textContent = blockCaption(null, b);
    }
    const part = { grid: { ...term.grid, rows: b.rows }, lead: k === 0 ? term.lead : "", name: term.name };
    const tex = gridTermTex(part);
    const box = document.createElement("span");
    box.className = "formula-term";
    box.dataset.tex = tex;
    katexInto(box, first && k === 0 ? tex : `{}${tex}`);
    block.append(caption, box);
    node.append(block);
  });
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

/** A formula laid out afresh from its source (a rearranged one, for a new width). */
function fresh(formula) {
  const source = sources.get(formula);
  if (!source) return formula;
  const node = document.createElement("div");
  node.className = formula.className;
  typesetInto(node, source);
  formula.replaceWith(node);
  return node;
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
 * @param {{ reset?: boolean, all?: boolean }} [options]
 */
export function fitAll(formulas, { reset = true, all = false } = {}) {
  // only what is rendered: a formula in a step off screen waits for the step (fitLater)
  const shownNow = formulas.filter((formula) => {
    if (all || !formula.checkVisibility || formula.checkVisibility({ contentVisibilityAuto: true })) return true;
    // not rendered: skipped (its step off screen) or hidden (a closed fold, display: none;
    // no width to fit to). Not told apart: checkVisibility() without the option would lay
    // a skipped step out. A step's formulas wait for it to be rendered.
    const step = formula.closest(LAZY);
    if (step) fitLater(step, formula, reset);
    return false;
  });
  // writes: a formula rearranged before starts again from its rendering
  const list = shownNow.map((formula) => (reset && formula.querySelector(".formula-refit, .formula-scroll") ? fresh(formula) : formula));
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
    // writes: a grid with blocks still too wide tries fewer columns; a part of an
    // equation still too wide is rearranged in its turn, a few levels deep; the rest is done
    jobs.forEach((job, k) => {
      if (!still[k].length) return;
      if (!job.node) {
        stuck.push(...still[k].map((w) => w.term));
        return;
      }
      if (!job.per) {
        for (const w of still[k]) {
          const again = (job.depth ?? 0) < REFIT_DEPTH ? tryRefit(w.term, w.room, w.width) : null;
          if (again?.node) next.push({ ...again, term: w.term, depth: (job.depth ?? 0) + 1 });
          else stuck.push(w.term);
        }
        return;
      }
      try {
        if (job.per === 1) {
          if (job.plan.grid.env !== "array") {
            stuck.push(...still[k].map((w) => w.term));
            return;
          }
          // a table too wide even one column at a time: one line per row, "key: header = cell"
          const lines = rowLinesNode(job.plan);
          job.node.replaceWith(lines);
          next.push({ term: job.term, node: lines, depth: job.depth });
          return;
        }
        const per = Math.max(1, Math.min(job.per - 1, Math.floor(job.per * 0.8)));
        const node = blocksNode(job.plan, per, job.first);
        job.node.replaceWith(node);
        next.push({ ...job, node, per });
      } catch (e) {
        console.warn("formula could not be rearranged", e);
        stuck.push(...still[k].map((w) => w.term));
      }
    });
    jobs = next;
  }
  stuck.forEach(shrinkOrScroll);
}

/** The smallest font size a term that cannot be rearranged is shrunk to before it scrolls. */
const MIN_SHRINK = 0.7;

/**
 * A term nothing can rearrange (one piece: a fraction, a long product): a
 * little too wide, it is set a little smaller to fit its line; much too wide,
 * it scrolls (read, then write: a few terms at most).
 */
function shrinkOrScroll(term) {
  const room = term.clientWidth;
  const width = term.scrollWidth;
  if (room > 0 && width > room && room / width >= MIN_SHRINK) {
    term.style.fontSize = `${Math.floor((room / width) * 980) / 10}%`;
    term.classList.add("formula-refit"); // a later fit starts again from the rendering
    return;
  }
  scrollable(term);
}
