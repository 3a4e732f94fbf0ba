// KaTeX rendering that fits any width, with a plain-text fallback (with
// math-typeset.js, which holds steps 1–3 below and is loaded with KaTeX).
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
// numbers (scheduleMath: no request starts before the page's own first
// solution, its solver-ready mark), and when both are in every pending formula
// is typeset in place and fitted. <html data-math> says where that is: "loading" (from the
// scheduling on), "ready" or "failed" (then the plain text stays). whenMath()
// starts the load at once.
//
// What only typeset formulas need (the splitting rules, pieces and terms as
// KaTeX boxes, fitting them after layout) is in math-typeset.js, loaded with
// KaTeX; this module keeps the plain-text path and the API.
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
  if (katex) typeset.fitAll(nodes.filter((node) => node.isConnected), { reset: false });
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
  if (katex) return typeset.typesetInto(el, String(tex));
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
