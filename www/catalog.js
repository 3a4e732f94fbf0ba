// The catalog: the home view (#/) and the "Other examples" list of an
// example's page. Built from the catalog's entries (the Rust descriptors, via
// catalog.json): nothing here knows an example by name.
//
// The home view, top to bottom (a student on a phone sees the first three at
// once): where to go (practice, the image lab), "Start here" (the worked
// examples in the course notes' order, Example 1 first), a search box, and
// every example by topic, each with a small picture of its figure. The
// pictures are the page's own figures, drawn at build time
// (scripts/prerender.mjs: listed in the page's data block as `thumbs`) and
// loaded lazily; without them (a copy of www/ served as it is) the cards keep
// their shape.

import { el } from "./dom.js";
import { buildHash } from "./url.js";

/** The size a figure's picture is shown at (CSS px; the files have twice as many pixels). */
export const THUMB = Object.freeze({ width: 160, height: 100 });

/**
 * The topics of `entries` in page order: the catalog's own (the Rust entries
 * come grouped by topic in src/examples/mod.rs TOPICS order).
 */
export function topicsInOrder(entries) {
  return [...new Set(entries.map((e) => e.topic))];
}

/** The build's pictures of the figures ({ folder, ids, dark }), or null. */
function thumbsData() {
  try {
    const block = document.getElementById("catalog-data");
    const thumbs = block ? JSON.parse(block.textContent).thumbs : null;
    return thumbs && Array.isArray(thumbs.ids) ? thumbs : null;
  } catch {
    return null;
  }
}

/** A text as the search compares it: lower case, without accents ("Förstner" → "forstner"). */
export function fold(text) {
  return String(text ?? "")
    .normalize("NFD")
    .replace(/[\u0300-\u036f]/g, "")
    .toLowerCase();
}

/**
 * The numbers the course gives an example by, from its source: the worked
 * examples' ("Examples 15–16" → 15, 16; "Example 4(a)" → 4) and the
 * lectures' ("Lecture 21" → 21).
 */
export function courseNumbers(source) {
  const out = [];
  for (const m of String(source ?? "").matchAll(/\b(?:Examples?|Lecture)\s+(\d+)(?:\s*[–-]\s*(\d+))?/g)) {
    const from = Number(m[1]);
    const to = m[2] ? Number(m[2]) : from;
    for (let n = from; n <= to && n - from < 50; n++) out.push(n);
  }
  return out;
}

/**
 * The worked example an entry is, in the course notes' order: its first
 * example number and letter (Example 4(b) → [4, "b"]) when its source starts
 * with the worked examples, else null.
 */
export function workedExample(entry) {
  const m = /^Worked examples, (?:Examples? (\d+)(?:\((\w)\))?)?/.exec(entry.source ?? "");
  if (!m) return null;
  return m[1] ? [Number(m[1]), m[2] ?? ""] : [Infinity, ""];
}

/** The worked examples in the course notes' order (ready ones; those with no number last, in catalog order). */
export function coursePath(entries) {
  return entries
    .map((e, i) => ({ e, i, at: workedExample(e) }))
    .filter((x) => x.at && x.e.status === "ready")
    .sort((a, b) => a.at[0] - b.at[0] || a.at[1].localeCompare(b.at[1]) || a.i - b.i)
    .map((x) => x.e);
}

/**
 * Whether `entry` matches the query: every word of it is in the entry's id,
 * title, topic, source, course document or summary (case and accents
 * ignored), a number being one of the example's course numbers.
 */
export function matches(entry, query) {
  const words = fold(query).split(/[\s,;]+/).filter(Boolean);
  if (!words.length) return true;
  const hay = fold([entry.id, entry.title, entry.topic, entry.source, entry.document, entry.summary].join(" \n "));
  const numbers = courseNumbers(entry.source);
  return words.every((w) => (/^\d+$/.test(w) ? numbers.includes(Number(w)) : hay.includes(w)));
}

/** The pictures of an example's figure, light and dark (the theme shows one), or a blank of their size. */
function thumbOf(id, thumbs) {
  if (!thumbs || !thumbs.ids.includes(id)) return el("span", { class: "thumb thumb-none", "aria-hidden": "true" });
  const img = (file, cls) =>
    el("img", { class: `thumb ${cls}`, src: `${thumbs.folder}${file}`, alt: "", width: THUMB.width, height: THUMB.height, loading: "lazy", decoding: "async" });
  const light = img(`${encodeURIComponent(id)}.webp`, "thumb-light");
  if (!(thumbs.dark ?? []).includes(id)) return light;
  return [light, img(`${encodeURIComponent(id)}.dark.webp`, "thumb-dark")];
}

/**
 * The examples by topic: `detailed` (the home view: cards with a picture, the
 * source and the summary) or compact (the "Other examples" list), the example
 * on screen marked.
 */
export function catalogNav(entries, { detailed, currentId = null, thumbs = null }) {
  const nav = el("nav", { class: `catalog ${detailed ? "catalog-detailed" : "catalog-compact"}`, "aria-label": "All examples" });
  for (const topic of topicsInOrder(entries)) {
    const headingId = `topic-${topic.replace(/[^A-Za-z0-9]+/g, "-").toLowerCase()}${detailed ? "" : "-menu"}`;
    const list = el("ul", { class: "catalog-list", "aria-labelledby": headingId });
    for (const e of entries.filter((x) => x.topic === topic)) {
      const ready = e.status === "ready";
      const item = el("li", { class: `catalog-item ${ready ? "ready" : "coming"}`, "data-id": e.id, "data-status": e.status });
      if (ready && detailed) {
        item.append(el("a", { class: "catalog-card", href: `#/${encodeURIComponent(e.id)}` }, thumbOf(e.id, thumbs), el("span", { class: "catalog-title" }, e.title)));
      } else if (ready) {
        item.append(el("a", { href: `#/${encodeURIComponent(e.id)}`, "aria-current": e.id === currentId ? "page" : null }, e.title));
      } else {
        if (detailed) item.append(el("span", { class: "thumb thumb-none", "aria-hidden": "true" }));
        item.append(el("span", { class: "coming-title" }, e.title), " ", el("span", { class: "badge badge-coming" }, "coming"));
      }
      if (detailed) {
        item.append(el("span", { class: "catalog-source" }, e.source ?? ""));
        if (e.summary) item.append(el("p", { class: "catalog-summary" }, e.summary));
      }
      list.append(item);
    }
    nav.append(el("section", { class: "catalog-topic", "data-topic": topic }, el(detailed ? "h2" : "h3", { id: headingId }, topic), list));
  }
  return nav;
}

/** "Start here": the worked examples in the course notes' order, as a numbered path. */
function startHere(entries) {
  const path = coursePath(entries);
  if (!path.length) return null;
  const steps = path.map((e) => {
    const at = workedExample(e);
    const n = Number.isFinite(at[0]) ? `${at[0]}${at[1] ? `(${at[1]})` : ""}` : "•";
    return el("li", {}, el("a", { href: `#/${encodeURIComponent(e.id)}` }, el("span", { class: "path-n", "aria-hidden": "true" }, n), el("span", { class: "path-title" }, e.title)));
  });
  return el(
    "nav",
    { class: "start-here", "aria-labelledby": "start-here-h" },
    el("h2", { id: "start-here-h" }, "Start here"),
    el("p", { class: "start-here-text" }, "The worked examples in the order of the course notes, Example 1 first:"),
    el("ol", { class: "course-path" }, steps),
  );
}

/**
 * The home view: where to go, "Start here", the search and the examples.
 * `query` is the search the address holds (#/?q=…); the address follows the
 * search box (history.replaceState: Back leaves the catalog as it was).
 */
export function homeView(entries, { query = "" } = {}) {
  const thumbs = thumbsData();
  const ready = entries.filter((e) => e.status === "ready");
  const coming = entries.length - ready.length;
  const go = el(
    "nav",
    { class: "home-go", "aria-label": "Practice and the image lab" },
    el("a", { class: "go-card", href: "#/practice" }, el("strong", {}, "Practice"), el("span", {}, "Every example with fresh numbers, checked step by step")),
    el("a", { class: "go-card", href: "#/lab" }, el("strong", {}, "Image lab"), el("span", {}, "These operators on real photos; open the example behind any pixel")),
  );
  const box = el("input", {
    type: "search",
    id: "catalog-search",
    class: "catalog-search-box",
    autocomplete: "off",
    spellcheck: "false",
    placeholder: "GSD, Förstner, Example 6, matching…",
    "aria-describedby": "catalog-search-status",
  });
  box.value = query;
  const status = el("p", { class: "catalog-search-status", id: "catalog-search-status", role: "status" });
  const nav = catalogNav(entries, { detailed: true, thumbs });
  const filter = () => {
    const q = box.value.trim();
    let shown = 0;
    for (const item of nav.querySelectorAll(".catalog-item")) {
      const entry = entries.find((e) => e.id === item.dataset.id);
      const ok = entry ? matches(entry, q) : true;
      item.hidden = !ok;
      if (ok) shown++;
    }
    for (const section of nav.querySelectorAll(".catalog-topic")) section.hidden = !section.querySelector(".catalog-item:not([hidden])");
    status.textContent = !q
      ? `${ready.length} worked examples${coming ? `, ${coming} more coming` : ""}, by topic.`
      : shown
        ? `${shown} of ${entries.length} examples match “${q}”.`
        : `No example matches “${q}”. Try a title, a topic, an example number (6) or a name such as GSD or Förstner.`;
    return q;
  };
  box.addEventListener("input", () => {
    const q = filter();
    const hash = buildHash("", q ? [["q", q]] : []);
    if (location.hash !== hash && !(hash === "#/" && !location.hash)) history.replaceState(history.state, "", hash);
  });
  filter();
  const search = el(
    "div",
    { class: "catalog-search", role: "search" },
    el("label", { for: "catalog-search" }, "Find an example"),
    box,
    status,
  );
  return el(
    "section",
    { class: "home" },
    el("p", { class: "intro" }, "Worked examples of digital photogrammetry and image processing, solved step by step. Change any input and the whole solution follows; the address holds the inputs, so a what-if is a link."),
    go,
    startHere(entries),
    search,
    nav,
  );
}
