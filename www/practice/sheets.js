// The practice overview (progress per topic, regraded from the stored texts)
// and the printable worksheet: N variants of an example or of every example
// of a topic, with the answer key on separate pages.

import { el } from "../dom.js";
import { messageOf } from "../core.js";
import { formulaSource, renderFormula } from "../math.js";
import { keyNumber, renderGivens } from "./common.js";
import { allProgress } from "./store.js";
import { siteTitle } from "../site.js";

/** The QR encoder (uqr, bundled by the build into vendor/): loaded only when a worksheet is made. */
const QR_URL = "../vendor/uqr.js";
const SVG_NS = "http://www.w3.org/2000/svg";

/**
 * The full address of a practice variant, for paper: the site's page (the
 * main page, also when the sheet is made inside an embed) with the variant's
 * hash: https://host/path/index.html#/gsd?practice=1K7Q2.
 */
export function practiceAddress(id, code, here = location.href) {
  const url = new URL(here);
  url.search = "";
  url.hash = `#/${encodeURIComponent(id)}?practice=${encodeURIComponent(code)}`;
  url.pathname = url.pathname.replace(/embed\.html$/, "index.html");
  return url.href;
}

/** A QR code of `text` as an SVG element (dark modules as one path; a quiet zone of 2). */
export function qrSvg(encode, text) {
  const { data, size } = encode(text, { ecc: "M", border: 2 });
  let d = "";
  data.forEach((row, y) => row.forEach((dark, x) => {
    if (dark) d += `M${x} ${y}h1v1h-1z`;
  }));
  const svg = document.createElementNS(SVG_NS, "svg");
  svg.setAttribute("viewBox", `0 0 ${size} ${size}`);
  svg.setAttribute("class", "ws-qr");
  svg.setAttribute("role", "img");
  svg.setAttribute("shape-rendering", "crispEdges");
  svg.setAttribute("aria-label", `QR code of ${text}`);
  const bg = document.createElementNS(SVG_NS, "rect");
  for (const [k, v] of Object.entries({ width: size, height: size, fill: "#fff" })) bg.setAttribute(k, String(v));
  const path = document.createElementNS(SVG_NS, "path");
  path.setAttribute("d", d);
  path.setAttribute("fill", "#000");
  svg.append(bg, path);
  return svg;
}

/** The QR encoder, or null when it cannot load (the sheet keeps its written addresses). */
export async function loadQr() {
  try {
    return (await import(QR_URL)).encode;
  } catch (e) {
    console.warn("The QR code library did not load; the worksheet prints the addresses only.", e);
    return null;
  }
}
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
  document.title = siteTitle("Practice");
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
  const steps = el("input", { id: "ws-steps", type: "checkbox", class: "ws-steps" });
  const make = el("button", { type: "button", class: "button" }, "Make worksheet");
  make.addEventListener("click", () => {
    const n = Math.min(MAX_VARIANTS, Math.max(1, Math.round(Number(count.value) || DEFAULT_VARIANTS)));
    location.hash = `#/practice?worksheet=${encodeURIComponent(select.value)}&n=${n}${steps.checked ? "&worked=1" : ""}`;
  });
  const maker = el(
    "section",
    { class: "panel worksheet-maker" },
    el("h3", {}, "Worksheet for a class"),
    el("p", { class: "muted" }, "Fresh variants of one example or of a whole topic, to print, with the answer key on separate pages, or as a package for your LMS's gradebook (on the worksheet's page)."),
    el("div", { class: "ws-row" }, el("label", { for: "ws-example" }, "Example"), select),
    el("div", { class: "ws-row" }, el("label", { for: "ws-n" }, "Variants"), count),
    el("div", { class: "ws-row ws-check" }, steps, el("label", { for: "ws-steps" }, "Answer key with the worked steps")),
    make,
  );
  const receipts = el(
    "section",
    { class: "panel receipt-check" },
    el("h3", {}, "Check a work receipt"),
    el("p", { class: "muted" }, "A student's receipt (Copy a work receipt, in practice) holds their answers as typed: open it to see them graded again, box by box."),
    el("a", { class: "button", href: "#/practice?receipt=" }, "Check a receipt"),
  );
  root.replaceChildren(
    el(
      "article",
      { class: "practice-overview" },
      el("div", { class: "crumbs" }, el("a", { href: "#/" }, "← Catalog")),
      el("header", { class: "example-head" }, el("h2", { tabindex: "-1" }, "Practice"), el("p", { class: "example-summary" }, "Every example with numbers you have not seen, checked box by box. Your answers stay in this browser.")),
      el("div", { class: "overview-grid" }, sections, maker, receipts),
    ),
  );
  setStatus("practice-overview");
}

/**
 * #/practice?worksheet=<id or topic:Name>&n=N[&codes=…][&worked=1]: the
 * printable sheet; `worked=1` puts each solution's worked steps (formulas with
 * the variant's numbers) into the answer key, not only the final values.
 */
export async function showWorksheet({ root, core, entries, setStatus }, what, nText, codesText, workedText = null) {
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
  const withSteps = workedText === "1";
  const sheetHash = (steps) => `#/practice?worksheet=${encodeURIComponent(what)}&n=${n}&codes=${codes}${steps ? "&worked=1" : ""}`;
  const hash = sheetHash(withSteps);
  if (location.hash !== hash) history.replaceState(history.state, "", hash);
  const title = what.startsWith("topic:") ? `Worksheet: ${what.slice(6)}` : `Worksheet: ${chosen[0].title}`;
  document.title = siteTitle(title);

  const [encode, { lmsPanel }] = await Promise.all([loadQr(), import("../lms/panel.js")]);
  if (location.hash !== hash) return; // the reader moved on while the encoder loaded
  const exercises = items.map(({ entry, variant }, i) => {
    const address = practiceAddress(entry.id, variant.code);
    return el(
      "section",
      { class: "ws-exercise", "data-code": variant.code },
      el(
        "div",
        { class: "ws-online" },
        el("p", { class: "ws-address" }, `Variant ${variant.code} — check your answers online: `, el("a", { href: address, class: "ws-url" }, address)),
        encode ? qrSvg(encode, address) : null,
      ),
      el("h3", {}, `Exercise ${i + 1}: ${entry.title}`),
      renderGivens(entry, variant.inputs),
      el(
        "ol",
        { class: "ws-boxes" },
        variant.boxes.map((b) => el("li", {}, el("span", { class: "ws-label" }, `${b.label}${b.unit ? ` (${b.unit})` : ""}`), el("span", { class: "ws-line", "aria-hidden": "true" }), el("span", { class: "ws-tol muted" }, b.tolerance_text))),
      ),
    );
  });
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
        el("tbody", {}, variant.boxes.map((b) => el("tr", {}, el("th", { scope: "row" }, b.label), el("td", {}, `${keyNumber(b.expected, b.tolerance)}${b.unit ? ` ${b.unit}` : ""}`), el("td", { class: "muted" }, b.tolerance_text)))),
      ),
      withSteps ? workedSteps(solution) : null,
    );
  });
  const print = el("button", { type: "button", class: "button ws-print" }, "Print");
  print.addEventListener("click", () => window.print());
  const toggle = el("a", { class: "button ws-steps-toggle", href: sheetHash(!withSteps) }, withSteps ? "Key: final values only" : "Key with the worked steps");
  root.replaceChildren(
    el(
      "article",
      { class: "worksheet", "data-steps": withSteps ? "1" : "0" },
      el("div", { class: "crumbs ws-screen-only" }, el("a", { href: "#/practice" }, "← All practice"), " ", print, " ", toggle),
      el("header", { class: "ws-head" }, el("h2", {}, title), el("p", {}, "Name: ____________________   Date: __________"), el("p", { class: "muted" }, "Give each answer to the tolerance stated beside its line. Work each exercise in order; a later answer is marked against your own earlier ones.")),
      lmsPanel({ items, title, entries }),
      el("div", { class: "ws-exercises" }, exercises),
      el("section", { class: "ws-key" }, el("h2", {}, `Answer key — ${title.replace("Worksheet: ", "")}`), keys),
    ),
  );
  setStatus("worksheet");
}

/** A solution's worked steps for the answer key: title, text, the formula and the formula with the variant's numbers. */
function workedSteps(solution) {
  return el(
    "ol",
    { class: "ws-steps-list" },
    solution.steps.map((step) =>
      el(
        "li",
        { class: "ws-step" },
        el("h4", { class: "ws-step-title" }, step.title),
        step.text ? el("p", { class: "ws-step-text" }, step.text) : null,
        step.formula ? renderFormula(formulaSource(step, "symbolic"), "formula") : null,
        step.substituted ? renderFormula(formulaSource(step, "substituted"), "formula") : null,
      ),
    ),
  );
}
