// Practice mode on the page (docs/API.md, "practice" and "grade"):
//   #/<id>?practice=<code>   one variant: givens, answer boxes checked by the
//                            core, hints, progress kept in localStorage
//   #/<id>?practice          the stored variant of this example, or a new one
//   #/<id>?practice=new      a new variant
//   #/practice               the per-topic summary and the worksheet maker
//   #/practice?worksheet=<id>&n=4[&codes=…]   a printable worksheet with key
// Everything shown is text (textContent) or KaTeX; nothing from the URL or
// the student's boxes becomes HTML.

import { addStylesheet, el } from "../dom.js";
import { messageOf } from "../core.js";
import { formulaSource, renderFormula, texSource } from "../math.js";
import { renderGivens } from "./common.js";
import { postAnswer } from "./events.js";
import { loadProgress, saveProgress } from "./store.js";
import { showOverview, showWorksheet } from "./sheets.js";
import { siteTitle } from "../site.js";
import { testData } from "../test-hooks.js";

const STYLESHEET = new URL("./practice.css", import.meta.url).href; // (the build gives it its hashed name)
/** The rungs of a box's hint ladder. */
const RUNGS = ["A nudge", "The formula", "The formula with this variant's numbers", "The worked step"];
/** What each verdict says in the badge. */
const VERDICT_WORDS = {
  correct: "Correct",
  imprecise: "Too few digits",
  consistent: "Consistent",
  wrong: "Not yet",
  unreadable: "Cannot read",
  empty: "",
};

/**
 * The separate verdicts on a box's value, precision and unit (grade()'s
 * `value`, `precision`, `unit`), as short labelled lines: [class, text].
 */
export function verdictParts(r, unit) {
  const parts = [];
  if (r.value === "ok") parts.push(["value", "ok", "Value: right"]);
  if (r.value === "off") parts.push(["value", "bad", "Value: off"]);
  if (r.precision === "ok") parts.push(["precision", "ok", "Precision: enough digits"]);
  if (r.precision === "coarse") parts.push(["precision", "bad", "Precision: too few digits"]);
  if (unit && r.unit === "ok") parts.push(["unit", "ok", `Unit: ${unit}`]);
  if (unit && r.unit === "omitted") parts.push(["unit", "info", `Unit: none typed, taken as ${unit}`]);
  if (unit && r.unit === "wrong") parts.push(["unit", "bad", `Unit: wrong, this box is in ${unit}`]);
  return parts;
}

const PART_MARK = { ok: "✓", bad: "✗", info: "·" };

/**
 * A verdict as one sentence: the badge word, then the core's message without
 * the word again ("Correct." is one "Correct", not "Correct Correct."), so a
 * screen reader hears each verdict once. Returns [badge, rest].
 */
export function verdictSentence(verdict, message) {
  const word = VERDICT_WORDS[verdict] ?? verdict;
  const text = message ?? "";
  if (!word) return ["", text];
  if (text.toLowerCase().startsWith(word.toLowerCase())) {
    const rest = text.slice(word.length);
    return [word, rest === "." ? "" : rest];
  }
  return [word, text ? ` ${text}` : ""];
}

/** Adds the practice stylesheet once. */
function ensureStyles() {
  addStylesheet(STYLESHEET);
}

/**
 * Shows the practice route for `id` / `params`. Called by app.js's route()
 * when the hash is #/practice… or carries a `practice` parameter.
 */
export async function showPractice({ root, core, entries, id, params, mode, setStatus }) {
  ensureStyles();
  const get = (k) => params.find(([key]) => key === k)?.[1] ?? null;
  const ctx = { root, core, entries, mode, setStatus, params };
  if (id === "practice") {
    if (get("worksheet")) return showWorksheet(ctx, get("worksheet"), get("n"), get("codes"), get("worked"));
    return showOverview(ctx);
  }
  const entry = entries.find((e) => e.id === id);
  if (!entry || entry.status !== "ready") return message(ctx, "No practice here", `There is no ready example called “${id.slice(0, 40)}”.`);
  let code = get("practice") ?? "";
  const stored = loadProgress(id);
  if (code === "" && stored) code = stored.code;
  let variant;
  try {
    variant = core.practice(id, code === "" || code.toLowerCase() === "new" ? null : code);
  } catch (e) {
    return message(ctx, `Practice: ${entry.title}`, `This practice link does not work: ${messageOf(e)}`, id);
  }
  // The link names the variant; other options (an embed's id, host) stay.
  const query = params.map(([k, v]) => (k === "practice" ? `practice=${variant.code}` : `${encodeURIComponent(k)}=${encodeURIComponent(v)}`)).join("&");
  const hash = `#/${encodeURIComponent(id)}?${query}`;
  if (location.hash !== hash) history.replaceState(history.state, "", hash);
  const answers = stored && stored.code === variant.code ? stored.answers : {};
  buildVariant(ctx, entry, variant, answers);
}

function message(ctx, title, text, id = null) {
  document.title = siteTitle(title);
  const back = id ? el("a", { href: `#/${encodeURIComponent(id)}` }, "← The worked example") : el("a", { href: "#/practice" }, "← All practice");
  ctx.root.replaceChildren(el("section", { class: "message" }, el("h2", {}, title), el("p", {}, text), el("p", {}, back)));
  ctx.setStatus("message");
}

function buildVariant(ctx, entry, variant, answers) {
  const { core, root, mode } = ctx;
  const id = entry.id;
  const code = variant.code;

  document.title = siteTitle(`Practice: ${entry.title}`);
  const score = el("p", { class: "practice-score", role: "status" });
  const saveNote = el("p", { class: "muted practice-save", hidden: true }, "Your answers cannot be kept in this browser (storage is off); they stay until you leave the page.");
  const copyStatus = el("span", { class: "copy-status", role: "status" });

  const newButton = el("button", { type: "button", class: "button" }, "New variant");
  newButton.addEventListener("click", () => {
    const others = ctx.params.filter(([k]) => k !== "practice").map(([k, v]) => `&${encodeURIComponent(k)}=${encodeURIComponent(v)}`);
    location.hash = `#/${encodeURIComponent(id)}?practice=new${others.join("")}`;
  });
  const copyButton = el("button", { type: "button", class: "button" }, "Copy link");
  copyButton.addEventListener("click", async () => {
    try {
      await navigator.clipboard.writeText(location.href);
      copyStatus.textContent = "Link copied: it opens this same variant.";
    } catch {
      copyStatus.textContent = `Link: ${location.href}`;
    }
  });
  // a work receipt: the answers as typed, which an instructor regrades (www/lms/receipt-box.js, loaded when pressed)
  const receiptButton = el("button", { type: "button", class: "button" }, "Copy a work receipt");
  const receiptSpot = el("div", { class: "receipt-spot" });
  receiptButton.addEventListener(
    "click",
    async () => {
      const { receiptBox } = await import("../lms/receipt-box.js");
      const box = receiptBox(() => [{ id, code, answers: boxes.texts() }]);
      receiptButton.replaceWith(box.button);
      receiptSpot.replaceChildren(box.element);
      box.button.click();
      box.button.focus();
    },
    { once: true },
  );
  const actions = el(
    "div",
    { class: "actions practice-actions" },
    newButton,
    copyButton,
    el("a", { class: "button", href: `#/practice?worksheet=${encodeURIComponent(id)}&n=4` }, "Worksheet"),
    receiptButton,
    el("a", { class: "button", href: `#/practice?worksheet=${encodeURIComponent(id)}&n=1&codes=${code}` }, "For your LMS"),
    copyStatus,
  );

  const boxes = mountBoxes({
    core,
    id,
    code,
    variant,
    answers,
    onGraded(g, t, changed) {
      // nothing typed in a variant never stored: nothing to keep
      const typed = Object.values(t).some((x) => x.trim());
      if ((typed || loadProgress(id)?.code === code) && !saveProgress(id, code, t)) saveNote.hidden = false;
      const scoreText = `Score: ${g.score} of ${g.out_of}`;
      if (score.textContent !== scoreText) score.textContent = scoreText;
      if (changed && mode === "embed") {
        const r = g.boxes[changed];
        postAnswer({ example: id, code, box: changed, verdict: r.verdict, score: g.score, outOf: g.out_of });
      }
    },
    onError(e) {
      score.textContent = `The answers could not be checked: ${messageOf(e)}`;
    },
  });

  const crumbs =
    mode === "embed"
      ? null
      : el("div", { class: "crumbs" }, el("a", { href: `#/${encodeURIComponent(id)}` }, "← The worked example"), " · ", el("a", { href: "#/practice" }, "All practice"));
  root.replaceChildren(
    el(
      "article",
      { class: "practice", "data-id": id, "data-code": code },
      crumbs,
      el(
        "header",
        { class: "example-head" },
        el("h2", { id: "practice-title", tabindex: "-1" }, `Practice: ${entry.title}`),
        el("p", { class: "example-meta" }, `Variant ${code} · ${entry.source ?? ""}`),
      ),
      actions,
      receiptSpot,
      el("div", { class: "practice-layout" },
        el("section", { class: "panel givens-panel", "aria-labelledby": "givens-h" }, el("h3", { id: "givens-h" }, "Given"), renderGivens(entry, variant.inputs)),
        el(
          "section",
          { class: "panel answers-panel", "aria-labelledby": "answers-h" },
          el("h3", { id: "answers-h" }, "Your answers"),
          el("p", { class: "muted" }, "Work in order; each box is checked when you leave it (Tab or Enter). A decimal comma, 1.2e-3, 3/4 and a unit after the number are all read. A later box is also checked against your own earlier answers."),
          boxes.element,
          score,
          boxes.revealed,
          saveNote,
        ),
      ),
    ),
  );

  ctx.setStatus("practice");
}

/**
 * A variant's answer boxes, checked by the core as the student leaves each
 * one: the list (labels, tolerance, "read as", verdict lines, hint ladder) and
 * the line of hints revealed. The practice view and an LMS package's page
 * (www/lms/launch.js, several variants on one page: `idPrefix` keeps their
 * element ids apart) both use it. `onGraded(graded, texts, changedKey)` after
 * every grading, `onChecked(key, graded)` when a box was left.
 * Returns { element, revealed, regrade(changedKey), texts(), graded() }.
 */
export function mountBoxes({ core, id, code, variant, answers, idPrefix = "", onGraded = () => {}, onChecked = () => {}, onError = () => {} }) {
  ensureStyles();
  let solution = null;
  const worked = () => (solution ??= core.solve(id, variant.inputs));
  const hintsShown = {};
  const checked = new Set(Object.keys(answers).filter((k) => answers[k]));
  const revealed = el("p", { class: "practice-revealed muted" });
  let last = null;
  const boxes = variant.boxes.map((b, k) => buildBox(b, k));
  const element = el("ol", { class: "answer-list" }, boxes.map((b) => b.item));

  function buildBox(b, k) {
    const inputId = `${idPrefix}answer-${k}`;
    const input = el("input", {
      id: inputId,
      class: "answer-input",
      type: "text",
      inputmode: "decimal",
      autocomplete: "off",
      spellcheck: "false",
      "data-key": b.key,
      "aria-describedby": `${inputId}-tol ${inputId}-fb`,
    });
    input.value = answers[b.key] ?? "";
    const readAs = el("span", { class: "answer-read" });
    const feedback = el("p", { class: "answer-feedback", id: `${inputId}-fb`, "aria-live": "polite" });
    const parts = el("ul", { class: "verdict-parts", "aria-label": "Value, precision and unit" });
    const hintButton = el("button", { type: "button", class: "button hint-button" }, "Hint");
    const hintBody = el("div", { class: "hint-body" });
    const item = el(
      "li",
      { class: "answer", "data-key": b.key },
      el("label", { for: inputId, class: "answer-label" }, b.label),
      el("div", { class: "answer-row" }, input, b.unit ? el("span", { class: "answer-unit" }, b.unit) : null, readAs),
      el("p", { class: "answer-tolerance muted", id: `${inputId}-tol` }, `Tolerance ${b.tolerance_text}`),
      feedback,
      parts,
      el("div", { class: "hints" }, hintButton, hintBody),
    );
    // While typing only "read as" follows; the verdicts (live regions) wait
    // for the box to be left, so a screen reader is not told each keystroke.
    input.addEventListener("input", () => regrade(null, { verdicts: false }));
    input.addEventListener("change", () => {
      checked.add(b.key);
      regrade(b.key);
    });
    input.addEventListener("keydown", (ev) => {
      if (ev.key === "Enter") {
        checked.add(b.key);
        regrade(b.key);
      }
    });
    hintButton.addEventListener("click", () => {
      const n = (hintsShown[b.key] ?? 0) + 1;
      hintsShown[b.key] = n;
      showHint(b, n, hintBody);
      hintButton.textContent = n >= RUNGS.length ? "All hints shown" : `Next hint (${n + 1} of ${RUNGS.length})`;
      hintButton.disabled = n >= RUNGS.length;
      showRevealed();
    });
    return { b, input, readAs, feedback, parts, item };
  }

  /**
   * A hint's formula: laid out from the relation it comes from when the core
   * sends it (hints.relation: the symbolic side, or the numbers with the
   * result as ?), else the core's LaTeX as one block.
   */
  function hintSource(h, side, tex) {
    return h.relation ? { tex, relations: [h.relation], side } : texSource(tex);
  }

  function showHint(b, n, body) {
    const h = b.hints;
    const rung = RUNGS[n - 1];
    const part = el("div", { class: "hint", "data-rung": String(n) }, el("p", { class: "hint-rung" }, `${n}. ${rung}`));
    if (n === 1) part.append(el("p", {}, h.nudge || "Look at what the givens say about this value."));
    if (n === 2) part.append(h.formula ? renderFormula(hintSource(h, "symbolic", h.formula), "formula") : el("p", {}, "This value is read off the worked step."));
    if (n === 3) part.append(h.numbers ? renderFormula(hintSource(h, "question", h.numbers), "formula") : el("p", {}, "The step below has the numbers."));
    if (n === 4) {
      try {
        const step = worked().steps[h.step];
        part.append(el("h4", { class: "hint-step-title" }, step.title));
        if (step.text) part.append(el("p", {}, step.text));
        if (step.formula) part.append(renderFormula(formulaSource(step, "symbolic"), "formula"));
        if (step.substituted) part.append(renderFormula(formulaSource(step, "substituted"), "formula"));
      } catch (e) {
        part.append(el("p", {}, `The worked step could not be shown: ${messageOf(e)}`));
      }
    }
    body.append(part);
  }

  function showRevealed() {
    const used = Object.entries(hintsShown).filter(([, n]) => n > 0);
    if (!used.length) {
      revealed.textContent = "No hints used. Hints are free in practice; the page says what you revealed.";
      return;
    }
    const label = (key) => variant.boxes.find((b) => b.key === key)?.label ?? key;
    revealed.textContent = `Revealed: ${used.map(([k, n]) => `${label(k)} — ${RUNGS[n - 1].toLowerCase()} (${n} of ${RUNGS.length})`).join("; ")}.`;
  }

  function texts() {
    const out = {};
    for (const b of boxes) out[b.b.key] = b.input.value;
    return out;
  }

  /**
   * Grades every box; `changed` is the box just left (for the host page).
   * A box's feedback (an aria-live region) is rewritten only when its verdict
   * or message changed: Enter and then Tab grade twice, and an unchanged
   * region rewritten would be announced again.
   */
  function regrade(changed, { verdicts = true } = {}) {
    const t = texts();
    let g;
    try {
      g = core.grade(id, code, t);
    } catch (e) {
      onError(e);
      return;
    }
    last = g;
    for (const b of boxes) {
      const r = g.boxes[b.b.key];
      const text = b.input.value.trim();
      b.readAs.textContent = r.read && text ? `read as ${r.read}` : "";
      if (!verdicts) continue;
      const show = checked.has(b.b.key) && r.verdict !== "empty";
      const said = show ? JSON.stringify([r.verdict, r.message, r.value, r.precision, r.unit]) : "";
      if (said === b.said) continue;
      b.said = said;
      b.item.dataset.verdict = show ? r.verdict : "";
      b.feedback.replaceChildren();
      b.parts.replaceChildren();
      if (show) {
        for (const [part, kind, text] of verdictParts(r, b.b.unit)) {
          b.parts.append(el("li", { class: `verdict-part part-${kind}`, "data-part": part, "data-kind": kind }, el("span", { class: "part-mark", "aria-hidden": "true" }, PART_MARK[kind]), " ", text));
        }
        const [word, rest] = verdictSentence(r.verdict, r.message);
        testData(b.item, "mistake", r.mistake || null);
        b.feedback.append(el("span", { class: `verdict verdict-${r.verdict}` }, word), rest);
      } else {
        testData(b.item, "mistake", null);
      }
    }
    onGraded(g, t, changed);
    if (changed) onChecked(changed, g);
  }

  regrade(null, { verdicts: true });
  showRevealed();
  return {
    element,
    revealed,
    regrade,
    texts,
    graded: () => last ?? core.grade(id, code, texts()),
  };
}

