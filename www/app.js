// Photogrammetry Playground: the page. One module for both views:
//   index.html  <body data-mode="full">   header, catalog, the chosen example
//   embed.html  <body data-mode="embed">  the chosen example only (for iframes)
//
// Flow on every edit: form texts -> parse_inputs(id, texts) -> errors beside
// their fields (the last good solution stays, marked stale) or
// solve(id, inputs) -> steps, result, notes, figure; the URL follows with
// history.replaceState. Nothing read from the URL is ever parsed as HTML.

import { loadCore, messageOf } from "./core.js";
import { keepFitted } from "./math.js";
import { buildHash, parseHash } from "./url.js";
import { el, keepTallest } from "./dom.js";
import { buildForm } from "./form.js";
import { markStep, renderAnswer, renderNotes, renderResult, updateSteps } from "./render.js";
import { figuresPending, hasFigure, loadFigures, mountFigures } from "./figures/index.js";
import { formatValue } from "./format.js";
import * as embedPage from "./embed-page.js";
import { mountShell, mountSkipLink } from "./shell.js";
import { SITE_TITLE, siteTitle } from "./site.js";
import { SWEEPABLE } from "./sweep/link.js";

/** Longest URL key quoted back in the "ignored" notice. */
const MAX_QUOTED_KEY = 40;
/** How long "Link copied" stays. */
const COPY_STATUS_MS = 4000;
/** Where the "Show API names" choice is remembered (theme-init.js reads it, before the page paints). */
const API_NAMES_KEY = "photogrammetry-playground:show-api-names";

const mode = document.body.dataset.mode === "embed" ? "embed" : "full";
const root = document.getElementById("app");
// the header's theme switch and the skip link (the embed: the skip link only)
if (mode === "full") mountShell();
else mountSkipLink();

let core = null;
let entries = [];
/** The example on screen: { id, entry, form, figure, parts, lastGood } */
let view = null;

function setStatus(status) {
  document.body.dataset.status = status;
  embedPage.onStatus(status, view);
}

function entryById(id) {
  return entries.find((e) => e.id === id) ?? null;
}

// ---------------------------------------------------------------------------
// The catalog (catalog.js: its own module, loaded for the home view and the
// "Other examples" list, not on an example's first load)

async function showHome(params = []) {
  destroyView();
  document.title = siteTitle();
  if (mode === "embed") {
    root.replaceChildren(
      el("p", { class: "notice" }, "No example chosen. Use an address such as embed.html#/gsd?dpi=1200 to embed one example."),
    );
    setStatus("home");
    return;
  }
  const hash = location.hash;
  if (!root.querySelector(".home")) setStatus("loading");
  const { homeView } = await import("./catalog.js");
  if (location.hash !== hash) return; // the reader moved on; that hashchange routes
  root.replaceChildren(homeView(entries, { query: params.find(([k]) => k === "q")?.[1] ?? "" }));
  setStatus("home");
}

/** The accessibility statement (#/accessibility, the footer's link): its own small module. */
async function showStatement(focus) {
  destroyView();
  const hash = location.hash;
  const { statementView } = await import("./accessibility.js");
  if (location.hash !== hash) return; // the reader moved on; that hashchange routes
  document.title = siteTitle("Accessibility");
  root.replaceChildren(statementView());
  endPrerendered();
  setStatus("message");
  if (focus) root.querySelector("#statement-title")?.focus();
}

function showMessage(title, message) {
  destroyView();
  document.title = siteTitle(title);
  const parts = [el("h2", {}, title), el("p", {}, message)];
  if (mode === "full") parts.push(el("p", {}, el("a", { href: "#/" }, "← All examples")));
  root.replaceChildren(el("section", { class: "message" }, parts));
  endPrerendered();
  setStatus("message");
}

// ---------------------------------------------------------------------------
// One example

function destroyView() {
  if (view?.figure) view.figure.destroy();
  if (view?.sweep) view.sweep.destroy();
  if (view?.stopFitting) view.stopFitting();
  if (view?.stopKeeping) view.stopKeeping();
  view = null;
}

function showApiNames(on) {
  document.documentElement.classList.toggle("show-api", on);
  try {
    if (on) localStorage.setItem(API_NAMES_KEY, "1");
    else localStorage.removeItem(API_NAMES_KEY);
  } catch {
    // no storage (private mode): the choice lasts for this page only
  }
}

function buildView(entry) {
  destroyView();
  const id = entry.id;
  const v = { id, entry, lastGood: null, figure: null };

  // the embed has no site header: the example's title is its page heading
  const heading = el(mode === "embed" ? "h1" : "h2", { id: "example-title", tabindex: "-1" }, entry.title);
  const from = [entry.source, entry.document && entry.document !== entry.source ? entry.document : null].filter(Boolean).join(" — ");
  const meta = el("p", { class: "example-meta" }, `${from}${from && entry.topic ? " · " : ""}${entry.topic ?? ""}`);
  // not a live region itself: embed-page.js announces its words once typing settles (one region)
  const answerLine = el("p", { class: "answer-line", hidden: true });
  const summary = entry.summary ? el("p", { class: "example-summary" }, entry.summary) : null;
  const urlNotice = el("p", { class: "notice url-notice", role: "status", hidden: true });
  const errorBox = el("div", { class: "error-box", role: "alert", hidden: true });
  const staleBanner = el("p", { class: "stale-banner", role: "status", hidden: true });

  v.form = buildForm(entry, () => inputChanged());
  const copyStatus = el("span", { class: "copy-status", role: "status" });
  const resetButton = el("button", { type: "button", class: "button" }, "Reset to the worked example’s values");
  resetButton.addEventListener("click", () => {
    v.form.setAll({});
    urlNotice.hidden = true;
    recompute();
  });
  const copyButton = el("button", { type: "button", class: "button" }, "Copy link");
  copyButton.addEventListener("click", () => copyLink(copyStatus));
  const apiBox = el("input", { type: "checkbox", id: `api-names-${id}` });
  apiBox.checked = document.documentElement.classList.contains("show-api");
  apiBox.addEventListener("change", () => showApiNames(apiBox.checked));
  const apiToggle = el("label", { class: "api-toggle", for: `api-names-${id}`, title: "The names course authors use in links and in the JS API" }, apiBox, "Show API names");
  const actions = el("div", { class: "actions" }, resetButton, copyButton, apiToggle, copyStatus);
  // a sweep of a number input (www/sweep/: loaded when it opens; docs/embedding.md, sweep=)
  const sweepHost = el("div", { class: "sweep-host", hidden: true });
  const sweepButton = (entry.inputs ?? []).some((f) => SWEEPABLE.includes(f.kind)) ? el("button", { type: "button", class: "button keep-enabled sweep-open" }, "Sweep an input…") : null;
  if (sweepButton) {
    sweepButton.addEventListener("click", () => openSweep(v, { focus: true }));
    actions.append(sweepButton);
  }
  // practice mode (www/practice/): fresh numbers for this example
  if (entry.practice !== false) actions.append(el("a", { class: "button practice-link", href: `#/${encodeURIComponent(id)}?practice` }, "Practice"));
  // the same operator on a whole photo, in the image lab
  const family = mode === "full" ? labFamily(entry) : null;
  if (family) actions.append(el("a", { class: "button lab-try", href: `#/lab?family=${encodeURIComponent(family)}` }, "Try it on a photo"));
  if (mode === "embed") {
    const open = el("a", { class: "open-full", target: "_blank", rel: "noopener", href: "index.html" }, `Open in ${SITE_TITLE} ↗`);
    v.openLink = open;
    actions.append(open);
  }

  const inputs = el("section", { class: "panel inputs", "aria-labelledby": "inputs-h" }, el("h3", { id: "inputs-h" }, "Inputs"), v.form.element, actions);
  const stepsList = el("div", { class: "steps-body" });
  const steps = el("section", { class: "panel steps-panel", "aria-labelledby": "steps-h" }, el("h3", { id: "steps-h" }, "Solution, step by step"), stepsList);
  const figureHost = el("div", { class: "figure-host" });
  const figureSection = hasFigure(id) ? el("section", { class: "panel figure-section", "aria-labelledby": "figure-h" }, el("h3", { id: "figure-h" }, "Figure"), figureHost) : null;
  const resultBody = el("div", { class: "result-body" });
  const result = el("section", { class: "panel result-section", "aria-labelledby": "result-h" }, el("h3", { id: "result-h" }, "Result"), resultBody);
  const notesBody = el("div", { class: "notes-body" });
  const notes = el("section", { class: "panel notes-section", "aria-labelledby": "notes-h" }, el("h3", { id: "notes-h" }, "Notes"), notesBody);
  const side = el("div", { class: "side" }, result, notes);
  // the figure right after the inputs (style.css .layout: beside the steps on a wide screen)
  const solutionArea = el("div", { class: "layout" }, inputs, figureSection, steps, side);

  const children = [];
  if (mode === "full") {
    // its list is built when it is first opened (26 links the first solution need not wait for)
    const drawer = el("details", { class: "catalog-drawer" }, el("summary", {}, "Other examples"));
    drawer.addEventListener("toggle", async () => {
      if (!drawer.open || drawer.querySelector("nav")) return;
      const { catalogNav } = await import("./catalog.js");
      if (!drawer.querySelector("nav")) drawer.append(catalogNav(entries, { detailed: false, currentId: id }));
    });
    children.push(el("div", { class: "crumbs" }, el("a", { href: "#/" }, "← Catalog"), drawer));
  }
  children.push(el("header", { class: "example-head" }, heading, meta, summary), answerLine, urlNotice, errorBox, staleBanner, solutionArea, sweepHost);
  const article = el("article", { class: "example", "data-id": id }, children);
  root.replaceChildren(article);
  endPrerendered();
  if (figureSection) {
    // a figure may edit inputs (a click on a grid or a window, a key, a preset button)
    const onInputs = (texts) => {
      if (view !== v) return;
      v.form.set(texts);
      inputChanged();
    };
    // a moving figure (issue 34): its frame's step marked in the list, the frame it stops at in the link (play=)
    const onStep = (k) => {
      v.markedStep = k;
      markStep(stepsList, k);
    };
    const onPosition = (i) => {
      if (view !== v) return;
      embedPage.setPlay(i);
      writeUrl();
    };
    v.figure = mountFigures(figureHost, id, { onInputs, onStep, onPosition });
  }

  v.parts = { heading, answerLine, urlNotice, errorBox, staleBanner, stepsList, resultBody, notesBody, solutionArea, sweepHost, sweepButton };
  v.stopFitting = keepFitted(stepsList);
  // the answer line keeps its tallest height: the panels below stay put as it changes
  v.stopKeeping = keepTallest(answerLine);
  document.title = siteTitle(entry.title);
  view = v;
  // view options, embedding, exports (embed-page.js)
  embedPage.onView(v, {
    setTexts: (texts) => {
      if (view !== v) return;
      v.form.set(texts);
      recompute();
    },
  });
  return v;
}

function showGeneralError(message) {
  const box = view.parts.errorBox;
  box.replaceChildren(el("strong", {}, "Cannot solve: "), el("span", { class: "error-message" }, message));
  box.hidden = false;
}

function clearGeneralError() {
  view.parts.errorBox.hidden = true;
  view.parts.errorBox.replaceChildren();
}

function markStale(reason) {
  const { staleBanner, solutionArea, stepsList, answerLine } = view.parts;
  solutionArea.classList.toggle("stale", Boolean(view.lastGood));
  answerLine.classList.toggle("stale", Boolean(view.lastGood));
  solutionArea.classList.toggle("no-solution", !view.lastGood);
  if (!view.lastGood) stepsList.replaceChildren(el("p", { class: "muted" }, "No solution yet: the steps appear as soon as every input is valid."));
  if (view.lastGood) {
    const fields = new Map((view.entry.inputs ?? []).map((f) => [f.key, f]));
    const used = Object.entries(view.lastGood.inputs ?? {})
      .map(([k, val]) => {
        const f = fields.get(k);
        const shown = f?.kind === "choice" ? (f.options ?? []).find((o) => String(o.value) === String(val))?.label ?? formatValue(val) : formatValue(val).replace(/\n/g, "; ");
        return `${f?.label ?? k} = ${shown}${f?.unit ? ` ${f.unit}` : ""}`;
      })
      .join(", ");
    staleBanner.textContent = `${reason} The solution below is still the one for the last valid inputs (${used}).`;
  } else {
    staleBanner.textContent = reason;
  }
  staleBanner.hidden = false;
}

function clearStale() {
  view.parts.solutionArea.classList.remove("stale", "no-solution");
  view.parts.answerLine.classList.remove("stale");
  view.parts.staleBanner.hidden = true;
  view.parts.staleBanner.textContent = "";
}

/**
 * The part of an input change a student sees move at once: the answer line
 * and the figure (they are drawn in the same frame as the change).
 */
function renderQuick(solution) {
  const { answerLine } = view.parts;
  answerLine.replaceChildren(...renderAnswer(solution));
  answerLine.hidden = !answerLine.childElementCount;
  answerLine.classList.remove("stale");
  if (view.figure) view.figure.update(solution);
}

/** The steps, result and notes: after the figure on an input change, at once otherwise. */
function renderRest(solution) {
  const { stepsList, resultBody, notesBody } = view.parts;
  updateSteps(stepsList, solution); // in place: only the formulas that changed are rendered and fitted again
  if (Number.isInteger(view.markedStep)) markStep(stepsList, view.markedStep); // a moving figure's step, on a rebuilt item too
  resultBody.replaceChildren(...renderResult(solution));
  notesBody.replaceChildren(...renderNotes(solution));
}

function renderSolution(solution) {
  renderQuick(solution);
  renderRest(solution);
  // for `npm run bench`: navigation to the first solution on screen (the build's
  // saved one, preload-route.js, marks it first when it is shown), and to the
  // page's own, its inputs live
  if (!performance.getEntriesByName("solver-ready").length) {
    if (!performance.getEntriesByName("first-solution").length) performance.mark("first-solution");
    performance.mark("solver-ready");
    core.prefetch(); // the other topics' modules, when the browser is idle
  }
}

/**
 * The build's saved solution (preload-route.js shows it, inert, in #app
 * while the solver loads) ends when the page shows its own view; where the
 * address asks for something else, "Loading…" takes its place at once.
 */
function endPrerendered({ loading = false } = {}) {
  if (!root.hasAttribute("data-prerendered")) return;
  if (loading) root.replaceChildren(el("p", { class: "loading" }, "Loading the solver…"));
  root.removeAttribute("data-prerendered");
  root.inert = false;
}

/**
 * An input change's deferred part: { view, solution } whose answer line and
 * figure are on screen while its steps, result and notes are not yet (they
 * are marked busy). One at most: a newer change replaces it.
 */
let pendingRest = null;

/** The panels that wait for a pending rest (steps, result, notes). */
function restPanels() {
  const { stepsList, resultBody, notesBody } = view.parts;
  return [stepsList, resultBody, notesBody].map((n) => n.parentElement);
}

function markUpdating(on) {
  for (const panel of restPanels()) {
    panel.classList.toggle("updating", on);
    if (on) panel.setAttribute("aria-busy", "true");
    else panel.removeAttribute("aria-busy");
  }
}

/**
 * Renders the pending steps, result and notes (if any, and still of this
 * view); the solution is then the last good one and the status "ok" (left to
 * the caller with `quiet`: an input that cannot be solved follows).
 * Returns whether there was one.
 */
function finishRest({ quiet = false } = {}) {
  if (view?.urlPending) writeUrl();
  const job = pendingRest;
  pendingRest = null;
  if (!job || job.view !== view) return false;
  try {
    renderRest(job.solution);
  } catch (e) {
    console.error(e);
    markUpdating(false);
    showGeneralError(`The page could not show this solution: ${messageOf(e)}`);
    if (!quiet) setStatus("error");
    return true;
  }
  markUpdating(false);
  view.lastGood = job.solution;
  clearStale();
  if (!quiet) setStatus("ok");
  return true;
}

/** Runs `fn(frameStart)` in a task queued by the next animation frame (after it has been rendered). */
function afterFrame(fn) {
  requestAnimationFrame(() => {
    const frameStart = performance.now();
    const channel = new MessageChannel();
    channel.port1.onmessage = () => {
      channel.port1.close();
      fn(frameStart);
    };
    channel.port2.postMessage(null);
  });
}

/** The latest input change (its times, for the measures). */
let latestChange = null;

/**
 * An input typed or dragged (the form, an interactive figure): solves and
 * draws the answer line and the figure now; the steps, result and notes
 * follow once that frame is rendered, unless a newer change came meanwhile
 * (its own frame brings them then: fast typing or a drag does no wasted work).
 *
 * For `npm run bench`, two measures (only the latest of each is kept):
 *  - "redraw": the synchronous work of the change (parse, solve, answer line,
 *    figure) plus the next frame's rendering (from the animation frame's start
 *    until a task queued in it runs); the wait for the frame is left out.
 *    detail: { js, frame } in ms.
 *  - "settled": that, plus the deferred steps, result and notes and the
 *    rendering of their frame, the waits for frames left out likewise.
 *    detail: { js, frame, rest, restFrame, wall } (wall: input to settled
 *    with the waits). An invalid or unsolvable input has nothing deferred:
 *    its rest is 0.
 */
function inputChanged() {
  const start = performance.now();
  const change = { start };
  latestChange = change;
  recompute({ defer: true });
  const js = performance.now() - start;
  afterFrame((frameStart) => {
    const frame = performance.now() - frameStart;
    performance.clearMeasures("redraw");
    performance.measure("redraw", { start, duration: js + frame, detail: { js, frame } });
    if (latestChange !== change) return; // a newer change's frame finishes it
    const restStart = performance.now();
    finishRest();
    const rest = performance.now() - restStart;
    afterFrame((restFrameStart) => {
      if (latestChange !== change) return;
      const restFrame = performance.now() - restFrameStart;
      performance.clearMeasures("settled");
      performance.measure("settled", { start, duration: js + frame + rest + restFrame, detail: { js, frame, rest, restFrame, wall: performance.now() - start } });
    });
  });
}

function writeUrl() {
  view.urlPending = false;
  const hash = buildHash(view.id, [...view.form.entries(), ...embedPage.optionEntries()]);
  if (location.hash !== hash) history.replaceState(history.state, "", hash);
  if (view.openLink) view.openLink.setAttribute("href", `index.html${hash}`);
}

/** Opens the sweep tool of view `v` (its module and uPlot load now): `spec`, `plot` from the link. */
async function openSweep(v, options = {}) {
  let mountSweep;
  try {
    ({ mountSweep } = await import("./sweep/sweep.js"));
  } catch (e) {
    showGeneralError(`The sweep could not be loaded: ${messageOf(e)}`);
    return;
  }
  if (view !== v) return;
  v.sweep ??= mountSweep(v.parts.sweepHost, {
    core,
    view: v,
    setInput: (key, text) => {
      if (view !== v) return;
      v.form.set({ [key]: text });
      inputChanged();
    },
    setLink: (sweep, plot, grid) => {
      embedPage.setSweep(sweep, plot, grid);
      if (view === v) writeUrl();
    },
    posted: () => embedPage.sweepChanged(),
    hashFor: (key, text) => buildHash(v.id, [...v.form.entries().map(([k, t]) => [k, k === key ? text : t]), ...embedPage.optionEntries()]),
    changeStart: () => latestChange?.start,
    close: () => {
      closeSweep(v);
      v.parts.sweepButton?.focus();
    },
  });
  v.sweep.open(options);
}

function closeSweep(v) {
  v.sweep?.destroy();
  v.sweep = null;
  embedPage.setSweep(null);
  if (view === v) writeUrl();
}

/**
 * An open sweep follows the inputs: before the page solves when the solution
 * is shown at once (the host's change event then carries the new series),
 * after it on an input change (the figure first; the event waits for the steps).
 */
function recompute({ defer = false } = {}) {
  if (!defer) view?.sweep?.changed();
  recomputeSolution({ defer });
  if (defer) view?.sweep?.changed({ defer });
}

/**
 * Reads the form, parses, solves, renders; the URL follows. With `defer`
 * (an input change) a solution's steps, result and notes wait for
 * finishRest (the status says "updating" meanwhile); an input that cannot be
 * solved first shows the pending solution whole, so what the stale banner
 * calls "the last valid inputs" is what the steps show.
 */
function recomputeSolution({ defer = false } = {}) {
  if (!view) return;
  const id = view.id;
  const texts = view.form.texts();
  // the address follows the inputs; after an input change it waits with the steps (finishRest,
  // whatever the change turns out to be): history.replaceState costs 0.5–4 ms of the frame
  if (defer && view.lastGood) view.urlPending = true;
  else writeUrl();
  let parsed;
  try {
    parsed = core.parseInputs(id, texts); // plain objects (src/wasm.rs: json_compatible)
  } catch (e) {
    finishRest({ quiet: true });
    view.form.showErrors({});
    showGeneralError(messageOf(e));
    markStale("The inputs could not be read.");
    setStatus("error");
    return;
  }
  const errors = parsed?.errors ?? {};
  if (Object.keys(errors).length) finishRest({ quiet: true });
  const rest = view.form.showErrors(errors);
  if (Object.keys(errors).length) {
    const others = Object.entries(rest);
    if (others.length) showGeneralError(others.map(([k, m]) => `${k}: ${m}`).join("; "));
    else clearGeneralError();
    const n = Object.keys(errors).length;
    markStale(n === 1 ? "One input is not valid (see the message beside it)." : `${n} inputs are not valid (see the messages beside them).`);
    setStatus("invalid");
    return;
  }
  let solution;
  try {
    solution = core.solve(id, parsed.inputs ?? {});
  } catch (e) {
    finishRest({ quiet: true });
    const message = messageOf(e);
    // "c: 560 is outside the patch …": the field it names is marked too
    const named = /^([A-Za-z0-9_]+): /.exec(message);
    if (named && view.form.has(named[1])) view.form.showErrors({ [named[1]]: message });
    showGeneralError(message);
    markStale("These inputs cannot be solved.");
    setStatus("error");
    return;
  }
  clearGeneralError();
  if (defer && view.lastGood) {
    // the figure in this frame; the steps, result and notes after it (finishRest)
    try {
      renderQuick(solution);
    } catch (e) {
      console.error(e);
      finishRest({ quiet: true });
      showGeneralError(`The page could not show this solution: ${messageOf(e)}`);
      setStatus("error");
      return;
    }
    if (!pendingRest) markUpdating(true);
    pendingRest = { view, solution };
    setStatus("updating");
    return;
  }
  pendingRest = null;
  markUpdating(false);
  try {
    renderSolution(solution);
  } catch (e) {
    console.error(e);
    showGeneralError(`The page could not show this solution: ${messageOf(e)}`);
    setStatus("error");
    return;
  }
  view.lastGood = solution;
  clearStale();
  setStatus("ok");
}

async function copyLink(status) {
  const url = location.href;
  clearTimeout(copyLink.timer);
  try {
    await navigator.clipboard.writeText(url);
    status.textContent = "Link copied.";
  } catch {
    // no clipboard (permissions, insecure context): show the link to copy by hand
    const field = el("input", { type: "text", readonly: true, class: "copy-field", "aria-label": "Link to these inputs" });
    field.value = url;
    status.replaceChildren("Copy this link: ", field);
    field.focus();
    field.select();
    return;
  }
  copyLink.timer = setTimeout(() => {
    status.textContent = "";
  }, COPY_STATUS_MS);
}

function quoteKey(key) {
  const k = key.length > MAX_QUOTED_KEY ? `${key.slice(0, MAX_QUOTED_KEY)}…` : key;
  return `“${k}”`;
}

// ---------------------------------------------------------------------------
// The image lab (#/lab): its own module and wasm, loaded only when it opens

let labModule = null;

/** The lab family an example opens in: the catalog's `lab` (from the core's descriptors). */
function labFamily(entry) {
  return entry.lab ?? null;
}

async function showLab(params = []) {
  destroyView();
  setStatus("loading");
  try {
    labModule = await import("./lab/lab.js");
  } catch (e) {
    showMessage("The image lab could not be loaded", messageOf(e));
    return;
  }
  // the lab's whole state is in its link (family, photo, controls, pixel, view): lab.js reads it
  const family = params.find(([k]) => k === "family")?.[1] ?? null;
  labModule.openLab(root, { family, params });
}

// ---------------------------------------------------------------------------
// Routing

/** A SCORM package's page (its index.html carries #lms-package, www/lms/download.js): its practice only. */
const lmsPackage = document.getElementById("lms-package") !== null;

async function showLmsPackage() {
  destroyView();
  setStatus("loading");
  const { packageSettings, showLmsPractice } = await import("./lms/launch.js");
  await showLmsPractice({ root, core, entries, setStatus }, packageSettings());
}

async function route({ focus = false } = {}) {
  if (lmsPackage) return showLmsPackage();
  const hash = location.hash;
  const { id, params: allParams } = parseHash(hash);
  const params = embedPage.takeOptions(allParams); // theme, hide, lock …: embed-options.js
  // the saved part is the seed's: another example, or any input in the address, replaces it
  // (view options do not: preload-route.js shows it with them)
  if (root.dataset.prerendered !== id || params.length) endPrerendered({ loading: true });
  if (id !== "lab") labModule?.closeLab();
  if (id === "lab" && mode === "full") {
    await showLab(params);
    return;
  }
  if (!id) {
    await showHome(params);
    return;
  }
  if (id === "accessibility") {
    await showStatement(focus);
    return;
  }
  if (id === "practice" && params.some(([key]) => key === "receipt")) {
    // a work receipt, regraded (www/lms/receipt.js loads the practice of the receipt's topics)
    destroyView();
    setStatus("loading");
    const { showReceipt } = await import("./lms/receipt.js");
    if (location.hash !== hash) return;
    await showReceipt({ root, core, entries, setStatus }, params.find(([key]) => key === "receipt")[1]);
    return;
  }
  if (id === "practice" || params.some(([key]) => key === "practice")) {
    destroyView();
    setStatus("loading");
    // practice mode: the example's topic module with practice (every example's for the worksheets)
    const [{ showPractice }] = await Promise.all([import("./practice/view.js"), core.loadPractice(id === "practice" ? null : id)]);
    if (location.hash !== hash) return; // the reader moved on; that hashchange routes
    await showPractice({ root, core, entries, id, params, mode, setStatus });
    return;
  }
  const entry = entryById(id);
  if (!entry) {
    showMessage("No such example", `There is no example called “${id.length > MAX_QUOTED_KEY ? `${id.slice(0, MAX_QUOTED_KEY)}…` : id}”.`);
    return;
  }
  if (entry.status !== "ready") {
    showMessage(entry.title, `This example (${entry.source ?? entry.topic}) is coming: it is not built yet.`);
    return;
  }
  if (!(view && view.id === id)) {
    if (figuresPending(entry.module) || !core.loaded(id)) setStatus("loading");
    // the example's own wasm module and its figures, in parallel
    await Promise.all([core.load(id), loadFigures(entry.module)]);
    if (location.hash !== hash) return; // the reader moved on; that hashchange routes
  }
  const v = view && view.id === id ? view : buildView(entry);
  const texts = {};
  const dropped = [];
  for (const [key, value] of params) {
    if (v.form.has(key)) texts[key] = value;
    else if (!dropped.includes(key)) dropped.push(key);
  }
  v.form.setAll(texts);
  const notice = v.parts.urlNotice;
  if (dropped.length) {
    notice.textContent = `Ignored ${dropped.length === 1 ? "an unknown URL parameter" : "unknown URL parameters"}: ${dropped.map(quoteKey).join(", ")}. This example takes ${v.form.keys().join(", ")}.`;
    notice.hidden = false;
  } else {
    notice.hidden = true;
    notice.textContent = "";
  }
  recompute();
  // play= in the address: the moving figure opens at that frame (or plays)
  const play = embedPage.currentOptions().play;
  if (play && v.figure?.hasMotion) v.figure.play(play);
  else if (play) {
    notice.textContent = `${notice.textContent} Ignored the option play: the figure of this example does not move.`.trim();
    notice.hidden = false;
  }
  // sweep= / plot= in the address: the sweep opens with them
  const { sweep, plot, grid } = embedPage.currentOptions();
  if (sweep || plot || grid) openSweep(v, { spec: sweep, plot, grid });
  else if (v.sweep) closeSweep(v);
  embedPage.afterRoute();
  if (focus) v.parts.heading.focus({ preventScroll: false });
}

async function main() {
  setStatus("loading");
  // (the HTML says "Loading the solver…" already: writing it again would lay the page out once more)
  // (nor over the build's saved solution, which preload-route.js may have shown)
  if (!root.querySelector(":scope > p.loading") && !root.hasAttribute("data-prerendered")) root.replaceChildren(el("p", { class: "loading" }, "Loading the solver…"));
  // the example in the address starts loading its module as soon as the catalog names it
  // (and its figures: both were preloaded from the HTML by preload-route.js)
  const early = loadCore().then((c) => {
    const { id, params } = parseHash(location.hash);
    if (!lmsPackage && !params.some(([key]) => key === "practice")) {
      c.load(id).catch(() => {}); // route() reports errors
      const module = c.catalog().find((e) => e.id === id)?.module;
      if (module) loadFigures(module);
    }
    return c;
  });
  const [coreResult] = await Promise.allSettled([early]);
  if (coreResult.status !== "fulfilled") {
    root.replaceChildren(
      el(
        "div",
        { class: "error-box", role: "alert" },
        el("strong", {}, "The solver could not be loaded. "),
        `(${messageOf(coreResult.reason)}) The page needs the WebAssembly build: run “npm run build” and serve the dist/ folder.`,
      ),
    );
    endPrerendered();
    setStatus("fatal");
    return;
  }
  core = coreResult.value;
  try {
    entries = core.catalog(); // plain JSON; an entry's inputs arrive with its module (core.load)
  } catch (e) {
    root.replaceChildren(el("div", { class: "error-box", role: "alert" }, `The catalog could not be read: ${messageOf(e)}`));
    endPrerendered();
    setStatus("fatal");
    return;
  }
  const go = (options) =>
    route(options).catch((e) => {
      console.error(e);
      showMessage("Something went wrong", `The example could not be shown: ${messageOf(e)}`);
    });
  // (a SCORM package's page keeps its one view: no routes, no offline copy of its own)
  if (!lmsPackage) window.addEventListener("hashchange", () => go({ focus: true }));
  // the offline copy's service worker: after the first view (not on its critical path)
  go().then(() => (lmsPackage ? null : import("./sw-register.js")));
}

main();
