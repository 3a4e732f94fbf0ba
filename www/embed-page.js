// The page side of the view options (embed-options.js) and of embedding: the
// parts shown, locked inputs, folded steps, the theme, the height and events
// posted to the host page (embed-bridge.js), result changes announced to
// screen readers (the answer line's words, in the page's one polite live
// region, once typing settles and only when they changed), and the tools bar (exports, "Embed this").
//
// app.js calls: takeOptions(params) when it reads the address, optionEntries()
// when it writes it, onView(view, api) when an example is built, afterRoute()
// after each address change, onStatus(status, view) at each settled state.

import { el } from "./dom.js";
import { parseOptions, defaults } from "./embed-options.js";
import { configure, isFramed, listen, post, postCanvasResize } from "./embed-bridge.js";
import { toolsBar } from "./export.js";
import { formatValue } from "./format.js";
import { fitFormulas } from "./math.js";
import { spokenText } from "./render.js";

/** Wait after the last change before announcing the result (typing settles). */
const ANNOUNCE_DELAY_MS = 600;
/** Result keys read out in an announcement. */
const ANNOUNCE_KEYS = 6;

const embedded = document.body.dataset.mode === "embed";
let options = defaults();
let optionList = [];
let notices = [];
let current = null; // { view, api, notice, live, toolsHost }
let readySent = false;
let announceTimer = 0;
const openSteps = new Set();

/** The view options of the address; returns the other parameters (inputs, unknown keys). */
export function takeOptions(params) {
  const parsed = parseOptions(params);
  options = parsed.options;
  optionList = parsed.entries;
  notices = parsed.notices;
  configure({ id: options.id, host: options.host });
  applyTheme();
  return parsed.rest;
}

/** The valid options, to be written back into the address after the inputs. */
export function optionEntries() {
  return optionList;
}

/**
 * The frame a moving figure stopped at (0-based; null: every position shown),
 * written into the address as play=N (1-based) so a copied link opens there.
 */
export function setPlay(index) {
  optionList = optionList.filter(([k]) => k !== "play");
  if (Number.isInteger(index) && index >= 0) optionList.push(["play", String(index + 1)]);
}

/** The sweep's part of the address (sweep=key:from:to:steps&plot=a,b&grid=key:from:to:rows; www/sweep/): null removes it. */
export function setSweep(sweep, plot, grid = null) {
  optionList = optionList.filter(([k]) => k !== "sweep" && k !== "plot" && k !== "grid");
  if (sweep) optionList.push(["sweep", sweep]);
  if (sweep && plot) optionList.push(["plot", plot]);
  if (sweep && grid) optionList.push(["grid", grid]);
}

/** The sweep changed by its own controls (no input did): the host hears of it with the series. */
export function sweepChanged() {
  if (current?.view.lastGood && document.body.dataset.status === "ok") post("change", changePayload(current.view, current.view.lastGood));
}

/** The change event's data: the example, its inputs and results, and an open sweep's series (`sweep`). */
function changePayload(view, solution) {
  const payload = { example: view.id, title: view.entry.title, inputs: solution.inputs, texts: Object.fromEntries(view.form.entries()), result: solution.result };
  const sweep = view.sweep?.payload();
  if (sweep) payload.sweep = sweep;
  return payload;
}

/** The current options (for the tools and the embed panel). */
export function currentOptions() {
  return { ...options, hide: [...options.hide] };
}

function applyTheme() {
  const root = document.documentElement;
  if (options.theme === "auto") root.removeAttribute("data-theme");
  else root.setAttribute("data-theme", options.theme);
  window.dispatchEvent(new CustomEvent("playground-theme"));
}

/** Texts the form can take from a value the host sent (numbers, lists, rows). */
function asText(value) {
  if (Array.isArray(value)) return value.map((row) => (Array.isArray(row) ? row.join(" ") : String(row))).join(Array.isArray(value[0]) ? "\n" : ", ");
  return String(value);
}

export function onView(view, api) {
  const article = view.parts.solutionArea.closest("article") ?? view.parts.solutionArea.parentElement;
  const notice = el("p", { class: "notice options-notice", role: "status", hidden: true });
  view.parts.urlNotice.after(notice);
  // printed instead of the form: the inputs as text and the link
  const printInputs = el("pre", { class: "print-inputs" });
  const printLink = el("p", { class: "print-link" });
  const printBlock = el("section", { class: "print-only print-block", "aria-hidden": "true" }, el("h3", {}, "Inputs"), printInputs, printLink);
  view.parts.solutionArea.before(printBlock);
  const live = el("p", { class: "visually-hidden result-announcer", "aria-live": "polite", "aria-atomic": "true" });
  const toolsHost = el("section", { class: "panel tools-section", "aria-labelledby": "tools-h" }, el("h3", { id: "tools-h" }, embedded ? "Export" : "Share and export"));
  toolsHost.append(toolsBar(view, { embedded, options: currentOptions }));
  article.append(toolsHost);
  article.prepend(live); // (at the end its absolute box would hang below the content)
  openSteps.clear();
  current = { view, api, notice, live, toolsHost, printInputs, printLink, lastAnnounced: null };
  // a locked example: the figure edits no input (its view selections stay)
  for (const type of ["pointerdown", "keydown"]) {
    article.addEventListener(
      type,
      (e) => {
        if (!options.lock || !e.target.closest?.(".figure-interactive, .figure-actions")) return;
        if (type === "keydown" && (e.key === "Tab" || e.key === "Escape")) return;
        e.stopPropagation();
      },
      true,
    );
  }
}

/** After each address change: the options that do not depend on a solution. */
export function afterRoute() {
  if (!current) return;
  const { view, notice } = current;
  notice.textContent = notices.join(" ");
  notice.hidden = notices.length === 0;
  document.body.dataset.hide = options.hide.join(" ");
  if (!options.hide.length) delete document.body.dataset.hide;
  document.body.classList.toggle("locked", options.lock);
  // embed.js resizes the frame to the content: no scrollbar flashes meanwhile
  document.documentElement.classList.toggle("framed-auto", embedded && isFramed() && options.host !== null);
  lockInputs(view, options.lock);
  shapeSteps();
}

function lockInputs(view, locked) {
  const form = view.parts.solutionArea.querySelector(".inputs");
  if (!form) return;
  for (const c of form.querySelectorAll("input, textarea")) c.readOnly = locked;
  for (const c of form.querySelectorAll("select, input[type=checkbox], input[type=radio], button")) {
    if (c.classList.contains("keep-enabled")) continue;
    c.disabled = locked;
  }
  form.toggleAttribute("data-locked", locked);
  let note = form.querySelector(".locked-note");
  if (locked && !note) {
    note = el("p", { class: "locked-note" }, "The inputs of this exercise are fixed.");
    form.querySelector("h3")?.after(note);
  } else if (!locked && note) note.remove();
}

/** Folds the steps (steps=collapsed) and marks the start step (step=k). */
function shapeSteps() {
  if (!current) return;
  const items = [...current.view.parts.stepsList.querySelectorAll(".step")];
  items.forEach((item, i) => {
    const k = i + 1;
    const start = options.step === k;
    item.classList.toggle("step-start", start);
    if (start) item.setAttribute("aria-current", "step");
    else item.removeAttribute("aria-current");
    const folded = item.querySelector(":scope > details.step-fold");
    if (options.steps === "collapsed" && !folded) {
      const title = item.querySelector(":scope > .step-title");
      if (!title) return;
      const fold = el("details", { class: "step-fold" }, el("summary", {}, title));
      fold.append(...[...item.childNodes]);
      item.append(fold);
      if (openSteps.has(k) || (start && !openSteps.size)) fold.open = true;
      fold.addEventListener("toggle", () => {
        if (fold.open) openSteps.add(k);
        else openSteps.delete(k);
        if (fold.open) fitFormulas(fold); // a folded step had no width to fit its formulas to
      });
    }
  });
}

function resultSummary(solution) {
  const labels = solution.labels ?? {};
  return Object.entries(solution.result ?? {})
    .filter(([, v]) => typeof v === "number" || typeof v === "string" || v === null)
    .slice(0, ANNOUNCE_KEYS)
    .map(([k, v]) => `${labels[k]?.label ?? k} ${formatValue(v)}${labels[k]?.unit ? ` ${labels[k].unit}` : ""}`)
    .join(", ");
}

function announce(text) {
  clearTimeout(announceTimer);
  announceTimer = setTimeout(() => {
    if (current && current.lastAnnounced !== text) {
      current.lastAnnounced = text;
      current.live.textContent = text;
    }
  }, ANNOUNCE_DELAY_MS);
}

function visibleErrors() {
  const errors = {};
  for (const p of document.querySelectorAll(".field-error:not([hidden])")) {
    const field = p.closest("[data-key]")?.dataset.key ?? p.id;
    errors[field] = p.textContent.trim();
  }
  return errors;
}

/** Each settled state: folds, announcements, events to the host. */
export function onStatus(status, view) {
  if (!current || view !== current.view) {
    scheduleMeasure(); // a message page ("no such example") has a height too
    return;
  }
  const labels = new Map((view.entry.inputs ?? []).map((f) => [f.key, f]));
  current.printInputs.textContent = view.form
    .entries()
    .map(([k, v]) => `${labels.get(k)?.label ?? k}${labels.get(k)?.unit ? ` (${labels.get(k).unit})` : ""} = ${v.replace(/\n/g, "; ")}`)
    .join("\n");
  current.printLink.textContent = `Link: ${location.href}`;
  if (status === "ok" && view.lastGood) {
    shapeSteps();
    const solution = view.lastGood;
    // the answer line as a screen reader reads it (powers of ten in words), else the first results
    const said = spokenText(view.parts.answerLine).replace(/\s+/g, " ").trim() || resultSummary(solution);
    if (current.lastAnnounced === null) current.lastAnnounced = said;
    else announce(said);
    const payload = changePayload(view, solution);
    if (!readySent) {
      readySent = true;
      post("ready", payload);
    }
    post("change", payload);
    window.dispatchEvent(new CustomEvent("playground-solved"));
  } else if (status === "invalid" || status === "error") {
    const box = view.parts.errorBox;
    const message = box && !box.hidden ? box.textContent.trim() : "";
    const errors = visibleErrors();
    const text = message || Object.values(errors).join("; ") || "The inputs are not valid.";
    announce(`Not solved: ${text}`);
    if (!readySent) {
      readySent = true;
      post("ready", { example: view.id, title: view.entry.title, inputs: null, texts: Object.fromEntries(view.form.entries()), result: null });
    }
    post("error", { example: view.id, message: text, errors });
  }
  scheduleMeasure();
}

// ---------------------------------------------------------------------------
// The height, for embed.js and Canvas: measured, never derived from the frame

let lastHeight = 0;
let measureQueued = false;

/** The content's height in CSS px (the document's box, not the frame's viewport). */
export function contentHeight() {
  return Math.ceil(document.body.getBoundingClientRect().height);
}

function sendHeight(force = false) {
  const h = contentHeight();
  if (h <= 0 || (!force && h === lastHeight)) return;
  lastHeight = h;
  post("resize", { height: h });
  postCanvasResize(h);
}

function scheduleMeasure(force = false) {
  if (!embedded || !isFramed() || measureQueued) return;
  measureQueued = true;
  requestAnimationFrame(() => {
    measureQueued = false;
    sendHeight(force);
  });
}

if (embedded && isFramed()) {
  document.documentElement.classList.add("framed");
  new ResizeObserver(() => scheduleMeasure()).observe(document.body);
  document.addEventListener("visibilitychange", () => scheduleMeasure(true));
  listen((event, data) => {
    if (event === "measure") scheduleMeasure(true);
    else if (event === "set-state" && current && data.inputs && typeof data.inputs === "object") {
      const texts = {};
      for (const [k, v] of Object.entries(data.inputs)) if (current.view.form.has(k)) texts[k] = asText(v);
      current.api.setTexts(texts);
    }
  });
}
