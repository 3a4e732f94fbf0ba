// The practice overview (progress per topic, regraded from the stored texts)
// and the printable worksheet: N variants of an example or of every example
// of a topic, with the answer key on separate pages.

import { el } from "../dom.js";
import { messageOf } from "../core.js";
import { expectedValue, keyNumber, renderGivens } from "./common.js";
import { allProgress } from "./store.js";

const SITE_TITLE = "Photogrammetry Playground";
/** Worksheet sizes offered and allowed. */
const MAX_VARIANTS = 20;
const DEFAULT_VARIANTS = 4;

function practised(entries, core) {
  // An example has practice when the core makes a variant for it.
  return entries.filter((e) => {
    if (e.status !== "ready") return false;
    try {
      core.practice(e.id, "10000");
      return true;
    } catch {
      return false;
    }
  });
}

/** #/practice: progress per topic and the worksheet maker. */
export function showOverview({ root, core, entries, setStatus }) {
  document.title = `Practice — ${SITE_TITLE}`;
  const ready = practised(entries, core);
  const progress = allProgress();
  const topics = [...new Set(ready.map((e) => e.topic))];
  const sections = topics.map((topic) => {
    let points = 0;
    let total = 0;
    const rows = ready
      .filter((e) => e.topic === topic)
      .map((e) => {
        const p = progress[e.id];
        let status = "not started";
        if (p) {
          try {
            const g = core.grade(e.id, p.code, p.answers);
            points += g.score;
            total += g.out_of;
            const done = Object.values(g.boxes).filter((b) => b.verdict !== "empty").length;
            status = `${g.score} of ${g.out_of} points · ${done} boxes answered · variant ${p.code}`;
          } catch (err) {
            status = `stored answers could not be read (${messageOf(err)})`;
          }
        }
        return el(
          "li",
          { class: "overview-item", "data-id": e.id },
          el("a", { href: `#/${encodeURIComponent(e.id)}?practice` }, e.title),
          el("span", { class: "overview-status muted" }, status),
        );
      });
    const summary = total ? `${points} of ${total} points in the variants you started` : "nothing started yet";
    return el("section", { class: "panel overview-topic", "data-topic": topic }, el("h3", {}, topic), el("p", { class: "overview-summary" }, summary), el("ul", { class: "overview-list" }, rows));
  });

  const select = el("select", { id: "ws-example", class: "ws-select" });
  for (const topic of topics) {
    const group = el("optgroup", { label: topic });
    group.append(el("option", { value: `topic:${topic}` }, `Whole topic: ${topic}`));
    for (const e of ready.filter((x) => x.topic === topic)) group.append(el("option", { value: e.id }, e.title));
    select.append(group);
  }
  const count = el("input", { id: "ws-n", type: "number", min: "1", max: String(MAX_VARIANTS), value: String(DEFAULT_VARIANTS), class: "ws-count" });
  const make = el("button", { type: "button", class: "button" }, "Make worksheet");
  make.addEventListener("click", () => {
    const n = Math.min(MAX_VARIANTS, Math.max(1, Math.round(Number(count.value) || DEFAULT_VARIANTS)));
    location.hash = `#/practice?worksheet=${encodeURIComponent(select.value)}&n=${n}`;
  });
  const maker = el(
    "section",
    { class: "panel worksheet-maker" },
    el("h3", {}, "Worksheet for a class"),
    el("p", { class: "muted" }, "Fresh variants of one example or of a whole topic, to print, with the answer key on separate pages."),
    el("div", { class: "ws-row" }, el("label", { for: "ws-example" }, "Example"), select),
    el("div", { class: "ws-row" }, el("label", { for: "ws-n" }, "Variants"), count),
    make,
  );
  root.replaceChildren(
    el(
      "article",
      { class: "practice-overview" },
      el("div", { class: "crumbs" }, el("a", { href: "#/" }, "← Catalog")),
      el("header", { class: "example-head" }, el("h2", { tabindex: "-1" }, "Practice"), el("p", { class: "example-summary" }, "Every example with numbers you have not seen, checked box by box. Your answers stay in this browser.")),
      el("div", { class: "overview-grid" }, sections, maker),
    ),
  );
  setStatus("practice-overview");
}

/** #/practice?worksheet=<id or topic:Name>&n=N[&codes=…]: the printable sheet. */
export function showWorksheet({ root, core, entries, setStatus }, what, nText, codesText) {
  const ready = practised(entries, core);
  const chosen = what.startsWith("topic:") ? ready.filter((e) => e.topic === what.slice(6)) : ready.filter((e) => e.id === what);
  if (!chosen.length) {
    root.replaceChildren(el("section", { class: "message" }, el("h2", {}, "No worksheet"), el("p", {}, `Nothing to practise called “${what.slice(0, 60)}”.`), el("p", {}, el("a", { href: "#/practice" }, "← All practice"))));
    setStatus("message");
    return;
  }
  const n = Math.min(MAX_VARIANTS, Math.max(1, Math.round(Number(nText) || DEFAULT_VARIANTS)));
  // The codes make the sheet the same on reload and in print: kept in the URL.
  const given = (codesText ?? "").split(",").filter(Boolean);
  const items = [];
  let k = 0;
  for (const entry of chosen) {
    for (let i = 0; i < n; i++) {
      let variant;
      try {
        variant = core.practice(entry.id, given[k] ?? null);
      } catch {
        variant = core.practice(entry.id, null);
      }
      items.push({ entry, variant });
      k++;
    }
  }
  const codes = items.map((x) => x.variant.code).join(",");
  const hash = `#/practice?worksheet=${encodeURIComponent(what)}&n=${n}&codes=${codes}`;
  if (location.hash !== hash) history.replaceState(history.state, "", hash);
  const title = what.startsWith("topic:") ? `Worksheet: ${what.slice(6)}` : `Worksheet: ${chosen[0].title}`;
  document.title = `${title} — ${SITE_TITLE}`;

  const exercises = items.map(({ entry, variant }, i) =>
    el(
      "section",
      { class: "ws-exercise", "data-code": variant.code },
      el("h3", {}, `Exercise ${i + 1}: ${entry.title}`),
      el("p", { class: "muted" }, `Variant ${variant.code} — online: #/${entry.id}?practice=${variant.code}`),
      renderGivens(entry, variant.inputs),
      el(
        "ol",
        { class: "ws-boxes" },
        variant.boxes.map((b) => el("li", {}, el("span", { class: "ws-label" }, `${b.label}${b.unit ? ` (${b.unit})` : ""}`), el("span", { class: "ws-line", "aria-hidden": "true" }), el("span", { class: "ws-tol muted" }, b.tolerance_text))),
      ),
    ),
  );
  const keys = items.map(({ entry, variant }, i) => {
    let solution = null;
    try {
      solution = core.solve(entry.id, variant.inputs);
    } catch (e) {
      return el("section", { class: "ws-key-item" }, el("h3", {}, `Exercise ${i + 1}`), el("p", {}, messageOf(e)));
    }
    return el(
      "section",
      { class: "ws-key-item" },
      el("h3", {}, `Exercise ${i + 1}: ${entry.title} (variant ${variant.code})`),
      el(
        "table",
        { class: "ws-key-table" },
        el("tbody", {}, variant.boxes.map((b) => el("tr", {}, el("th", { scope: "row" }, b.label), el("td", {}, `${keyNumber(expectedValue(solution, b.key), b.tolerance)}${b.unit ? ` ${b.unit}` : ""}`), el("td", { class: "muted" }, b.tolerance_text)))),
      ),
    );
  });
  const print = el("button", { type: "button", class: "button ws-print" }, "Print");
  print.addEventListener("click", () => window.print());
  root.replaceChildren(
    el(
      "article",
      { class: "worksheet" },
      el("div", { class: "crumbs ws-screen-only" }, el("a", { href: "#/practice" }, "← All practice"), " ", print),
      el("header", { class: "ws-head" }, el("h2", {}, title), el("p", {}, "Name: ____________________   Date: __________"), el("p", { class: "muted" }, "Give each answer to the tolerance stated beside its line. Work each exercise in order; a later answer is marked against your own earlier ones.")),
      el("div", { class: "ws-exercises" }, exercises),
      el("section", { class: "ws-key" }, el("h2", {}, `Answer key — ${title.replace("Worksheet: ", "")}`), keys),
    ),
  );
  setStatus("worksheet");
}
