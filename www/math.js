// KaTeX rendering that fits any width: the page's one entry to formulas
// (renderFormula, fitFormulas, keepFitted). A formula comes from a step's
// parts (formula-plan.js plans its lines: one group per relation, breaks
// only between the pieces the core gave); math-typeset.js makes the nodes
// with KaTeX and fits them after layout (a matrix too wide in blocks of
// columns, captioned with its name). A step without parts is one block.
//
// KaTeX is off the critical path (issue 19): the first numbers (answer line,
// result table) do not wait for it, nor share the network with it. A formula
// asked for before KaTeX has arrived takes its room, empty and aria-busy
// (.formula-pending); the first such formula schedules KaTeX's load (script,
// stylesheet and math-typeset.js) for after the frame that paints the
// numbers (scheduleMath), and when they are in every pending formula is
// typeset in place and fitted. <html data-math> says where that is:
// "loading" (from the scheduling on), "ready" or "failed" (then each formula
// shows its LaTeX text). math-typeset.js never imports this module.
//
// The minified UMD build (76 KB gzipped) rather than katex.mjs (146 KB
// gzipped, not minified): loaded by a script element, it sets window.katex.
const KATEX_URL = "./vendor/katex/katex.min.js";
const KATEX_CSS = "./vendor/katex/katex.min.css";

let katex = null;
/** math-typeset.js (typesetting and fitting), loaded with KaTeX. */
let typeset = null;
let loadError = null;
let loading = null;
/** Formulas drawn before KaTeX arrived, typeset when it does (attached to the page or not): element → source. */
const pending = new Map();

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
    import("./math-typeset.js"),
  ])
    .then(([, , mod]) => {
      if (!window.katex) throw new Error("katex.min.js loaded but defined no katex");
      typeset = mod;
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

function typesetPending() {
  const list = [...pending];
  pending.clear();
  for (const [node, source] of list) {
    node.classList.remove("formula-pending");
    node.removeAttribute("aria-busy");
    if (katex) typeset.typesetInto(node, source);
    else rawInto(node, source.tex);
  }
  // fitted after every formula is in: one layout, not one per formula
  if (katex) typeset.fitAll(list.map(([node]) => node).filter((node) => node.isConnected), { reset: false });
  document.documentElement.dataset.math = katex ? "ready" : "failed";
}

/** A step's LaTeX string of each side (made by the core from the parts). */
const SIDES = Object.freeze({ symbolic: "formula", substituted: "substituted" });

/**
 * The source of one formula of a step: its LaTeX string (the identity the
 * page compares, and the text shown when KaTeX cannot load) and, when the
 * step has them, its relations (step.parts).
 * @param {{ formula?: string, substituted?: string, parts?: object[] }} step
 * @param {"symbolic" | "substituted"} side
 */
export function formulaSource(step, side) {
  const tex = String(step?.[SIDES[side]] ?? "");
  const relations = Array.isArray(step?.parts) && step.parts.length ? step.parts : null;
  return { tex, relations, side };
}

/** A formula that is only a LaTeX string (a practice hint the core writes whole): one block. */
export function texSource(tex) {
  return { tex: String(tex), relations: null, side: "substituted" };
}

/**
 * The formula of `source` (formula-plan.js formulaSource: a step's side, its
 * parts and its LaTeX string) in a new element: typeset now when KaTeX is in,
 * else pending (typeset when it arrives), or its LaTeX text when KaTeX could
 * not load. Call fitFormulas on an ancestor once it is in the page.
 * @param {{ tex: string, relations: object[] | null, side: string }} source
 * @param {string} className
 */
export function renderFormula(source, className = "formula") {
  const el = document.createElement("div");
  el.className = className;
  if (katex) return typeset.typesetInto(el, source);
  el.dataset.tex = source.tex;
  if (!loadError) {
    // KaTeX is on its way: the room now, the formula when it is in
    el.classList.add("formula-pending");
    el.setAttribute("aria-busy", "true");
    pending.set(el, source);
    scheduleMath();
    return el;
  }
  // KaTeX could not be loaded: the LaTeX text
  rawInto(el, source.tex);
  return el;
}

function rawInto(el, tex) {
  el.classList.add("formula-raw");
  const code = document.createElement("code");
  code.textContent = tex;
  el.replaceChildren(code);
}

/**
 * Lays the formulas below `root` out again for the width they have now:
 * every refitted term starts from its original rendering, so a wider screen
 * gets whole matrices back. Nothing to do before KaTeX is in. Formulas in
 * steps off screen are fitted when they are rendered; `all` fits them now
 * (print).
 * @param {Element} root
 * @param {{ all?: boolean }} [options]
 */
export function fitFormulas(root, { all = false } = {}) {
  if (!katex || !root) return;
  typeset.fitFormulas(root, { all });
}

/**
 * Fits the formulas `nodes` (rendered by renderFormula, in the page) to the
 * width they have now, reading the layout once for all of them rather than
 * once each (math-typeset.js fitAll). Nothing to do before KaTeX is in.
 * @param {Element[]} nodes
 */
export function fitFormulaNodes(nodes) {
  if (!katex || !nodes.length) return;
  typeset.fitAll(nodes);
}

/**
 * Keeps the formulas below `root` fitted as its width changes (a phone
 * turned, a window resized, the print layout). Returns a stop function.
 */
export function keepFitted(root) {
  // the width the observer reports (its first report is the starting width): reading
  // root.clientWidth here, while the view is being built, would lay the page out once more
  let width = null;
  let frame = 0;
  const observer = new ResizeObserver((entries) => {
    const now = entries[entries.length - 1].contentRect.width;
    const first = width === null;
    if (now === width) return;
    width = now;
    if (first) return;
    cancelAnimationFrame(frame);
    frame = requestAnimationFrame(() => fitFormulas(root));
  });
  observer.observe(root);
  let stopped = false;
  const again = () => {
    if (!stopped) fitFormulas(root);
  };
  // print: every step rendered (content-visibility: visible, style.css) and fitted, not
  // only those that were on screen; back to rendering what is on screen afterwards
  const printing = () => {
    document.documentElement.classList.add("printing");
    if (!stopped) fitFormulas(root, { all: true });
  };
  const printed = () => document.documentElement.classList.remove("printing");
  window.addEventListener("beforeprint", printing);
  window.addEventListener("afterprint", printed);
  // KaTeX's fonts arrive after the first layout and make every formula wider
  document.fonts?.addEventListener?.("loadingdone", again);
  // after the first frame: reading document.fonts.ready recalculates the style of the
  // whole page, which the view being built would pay for twice
  requestAnimationFrame(() => setTimeout(() => document.fonts?.ready?.then(again), 0));
  return () => {
    stopped = true;
    observer.disconnect();
    window.removeEventListener("beforeprint", printing);
    window.removeEventListener("afterprint", printed);
    document.fonts?.removeEventListener?.("loadingdone", again);
  };
}
