// Work receipts: a student copies a short text (or shows its QR code) holding
// the example ids, variant codes and answers as typed; an instructor opens
// #/practice?receipt=<text> (or pastes it into the box there) and sees the
// attempt regraded box by box by the core — the same verdicts, named mistakes
// and carried-forward reasoning the student saw. The score is recomputed,
// never read from the receipt.

import { el } from "../dom.js";
import { lmsStyles } from "./styles.js";
import { siteTitle } from "../site.js";
import { verdictParts, verdictSentence } from "../practice/view.js";
import { decodeAttempt, gradeAttempt } from "./attempt.js";

/** "3.5" / "2" — a score with its half points. */
const points = (x) => String(Math.round(x * 100) / 100);

/**
 * The receipt view: the paste box, and when `text` is given, its attempt
 * regraded. `ctx`: { root, core, entries, setStatus } as the practice views.
 */
export async function showReceipt(ctx, text) {
  lmsStyles();
  const { root, core, entries, setStatus } = ctx;
  document.title = siteTitle("Check a work receipt");
  const box = el("textarea", { id: "receipt-text", rows: "3", spellcheck: "false", autocomplete: "off", "aria-describedby": "receipt-help" });
  box.value = text ?? "";
  const check = el("button", { type: "button", class: "button" }, "Check");
  check.addEventListener("click", () => {
    location.hash = `#/practice?receipt=${box.value.replace(/\s+/g, "")}`;
  });
  const result = el("div", { class: "receipt-result", "aria-live": "polite" });
  root.replaceChildren(
    el(
      "article",
      { class: "practice receipt" },
      el("div", { class: "crumbs" }, el("a", { href: "#/practice" }, "← All practice")),
      el("h2", { id: "receipt-title", tabindex: "-1" }, "Check a work receipt"),
      el("label", { for: "receipt-text" }, "The receipt (it starts with PGA1.)"),
      box,
      el("p", { id: "receipt-help", class: "muted" }, "Every answer is graded again here, as the student's page graded it; the score is computed from the answers, not read from the receipt."),
      el("div", { class: "actions" }, check),
      result,
    ),
  );
  if (!text) {
    setStatus("receipt");
    return;
  }
  let items;
  try {
    items = decodeAttempt(text);
  } catch (e) {
    result.append(el("p", { class: "error-box", role: "alert" }, e.message));
    setStatus("receipt");
    return;
  }
  // each topic's practice module (a receipt's examples may come from several)
  const byId = new Map(entries.map((e) => [e.id, e]));
  await Promise.all([...new Set(items.map((it) => it.id).filter((id) => byId.has(id)))].map((id) => core.loadPractice(id)));
  const g = gradeAttempt(core, items);
  result.append(el("p", { class: "receipt-score", "data-score": String(g.score), "data-out-of": String(g.out_of) }, `Score: ${points(g.score)} of ${g.out_of} (recomputed from the answers)`));
  for (const it of g.items) result.append(attemptSection(it, byId.get(it.id)));
  setStatus("receipt");
}

function attemptSection(it, entry) {
  const title = entry ? entry.title : it.id;
  const head = el("h3", {}, `${title} · variant ${it.code}`);
  if (it.error) return el("section", { class: "panel receipt-item", "data-id": it.id }, head, el("p", { class: "error-box" }, `Not graded: ${it.error}`));
  const rows = it.variant.boxes.map((b) => {
    const r = it.graded.boxes[b.key];
    const typed = it.answers[b.key] ?? "";
    const [word, rest] = verdictSentence(r.verdict, r.message);
    const parts = verdictParts(r, b.unit).map(([, , t]) => t);
    return el(
      "tr",
      { "data-key": b.key, "data-verdict": r.verdict },
      el("th", { scope: "row" }, b.label),
      el("td", {}, typed || el("span", { class: "muted" }, "(empty)")),
      el("td", {}, r.verdict === "empty" ? "" : [el("strong", {}, word), rest, parts.length ? el("br") : null, parts.join(" · ")]),
      el("td", { class: "num" }, points(r.points)),
    );
  });
  const table = el(
    "table",
    { class: "receipt-table" },
    el("caption", {}, `Score for this variant: ${points(it.graded.score)} of ${it.graded.out_of}`),
    el("thead", {}, el("tr", {}, el("th", { scope: "col" }, "Box"), el("th", { scope: "col" }, "Answer as typed"), el("th", { scope: "col" }, "Verdict"), el("th", { scope: "col" }, "Points"))),
    el("tbody", {}, rows),
  );
  return el("section", { class: "panel receipt-item", "data-id": it.id }, head, el("div", { class: "table-scroll", tabindex: "0", role: "region", "aria-label": `${title}: answers and verdicts` }, table));
}
