// The Sweep tool of an example (issue 34; docs/sweeps.md): one number input
// run over a range, the chosen numeric results plotted against it. Loaded by
// app.js with import() only when a sweep opens (the button, or sweep= in the
// link): uPlot comes with it (chart.js), never on the first load.
//
// Every point is solve(id, inputs with that value) (series.js, the one path
// Node's tests check with the real core); the slider and a click on the chart
// put that value into the form, and the page's own recompute shows that
// point's whole solution. The link carries sweep=key:from:to:steps&plot=a,b.

import { addStylesheet, el, idPart } from "../dom.js";
import { download } from "../export.js";
import { testData } from "../test-hooks.js";
import { labelOf } from "../render.js";
import { dataView, num, renderData, seriesTable } from "../figures/data-view.js";
import { axesOf, colour, groupOf, makeChart, strokeOf } from "./chart.js";
import { gridFold } from "./grid.js";
import {
  checkPlot,
  checkSweep,
  chooseRange,
  computeSeries,
  readEnd as readTypedEnd,
  fieldApplies,
  formatSweep,
  MAX_PLOTTED,
  MAX_STEPS,
  MIN_STEPS,
  numericResultKeys,
  seriesCsv,
  sweepableFields,
  sweepValues,
  valueText,
} from "./series.js";

const STYLESHEET = new URL("./sweep.css", import.meta.url).href; // (the build gives it its hashed name)
const STATUS_MS = 4000;

const styles = () => addStylesheet(STYLESHEET);

const fieldText = (f) => `${f.label}${f.unit ? ` (${f.unit})` : ""}`;
/** "1200 m", "13.75°" (no space before a degree sign). */
const withUnit = (v, unit) => `${num(v)}${unit ? `${unit === "°" ? "" : " "}${unit}` : ""}`;

/**
 * Mounts the sweep panel in `host`.
 * @param {HTMLElement} host
 * @param {{ core, view, setInput: (key: string, text: string) => void, setLink: (sweep: string|null, plot: string|null, grid: string|null) => void,
 *           posted: () => void, hashFor: (key: string, text: string) => string }} api
 * @returns {{ open(options), changed(), payload(), destroy() }}
 */
export function mountSweep(host, api) {
  styles();
  const { core, view } = api;
  const { entry, id } = view;
  const prefix = `sweep-${idPart(id)}`;
  const state = { field: null, range: null, plot: [], series: null, base: null, idx: null, chart: null, chartKeys: "", labels: null, cost: 0, settle: 0 };

  const heading = el("h3", { id: `${prefix}-h`, tabindex: "-1" }, "Sweep an input");
  const intro = el("p", { class: "sweep-intro" }, "Solve this example over a range of one input and plot the results against it. Each point is the example solved with that value; move the slider or click the chart to see that point’s whole solution above.");
  const fieldSelect = el("select", { id: `${prefix}-field` });
  // the ends are read as the form's own box is (the core's one reader: units, a decimal comma, ×10^)
  const fromInput = el("input", { id: `${prefix}-from`, type: "text", inputmode: "decimal", autocomplete: "off", spellcheck: "false" });
  const toInput = el("input", { id: `${prefix}-to`, type: "text", inputmode: "decimal", autocomplete: "off", spellcheck: "false" });
  // the count too: the core's reader (a whole number, 2–500, refused in its words)
  const stepsInput = el("input", { id: `${prefix}-steps`, type: "text", inputmode: "numeric", autocomplete: "off", spellcheck: "false" });
  const labelled = (input, text) => el("div", { class: "sweep-control" }, el("label", { for: input.id }, text), input);
  const plotBox = el("fieldset", { class: "sweep-plot" }, el("legend", {}, "Plot"));
  const message = el("p", { class: "sweep-message", role: "status" });
  const chartHost = el("div", { class: "sweep-chart" });
  const legend = el("ul", { class: "sweep-legend" });
  const frame = el("div", { class: "sweep-frame", tabindex: "0", role: "group", "aria-roledescription": "interactive chart" }, chartHost);
  const data = dataView(frame);
  data.keys.textContent = "Arrow keys: move along the points (Home, End: the ends); Enter: show that point’s solution.";
  const slider = el("input", { id: `${prefix}-slider`, type: "range", min: "0", max: "1", step: "1", value: "0" });
  const sliderValue = el("output", { for: slider.id, class: "sweep-slider-value" });
  const pointLink = el("a", { class: "sweep-point-link" }, "Link to this point");
  const scrub = el("div", { class: "sweep-scrub" }, el("label", { for: slider.id }, "Solution shown at"), slider, sliderValue, pointLink);
  const errorsBox = el("div", { class: "sweep-errors" });
  const status = el("p", { class: "tools-status", role: "status" });
  const csvButton = el("button", { type: "button", class: "button keep-enabled", "data-tool": "sweep-csv" }, "Series (CSV)");
  const pngButton = el("button", { type: "button", class: "button keep-enabled", "data-tool": "sweep-png" }, "Chart (PNG)");
  const closeButton = el("button", { type: "button", class: "button keep-enabled" }, "Close the sweep");
  // two inputs at once: the sweep's input and a second one, one result, as a shaded table (grid.js)
  const grid = gridFold({
    core,
    id,
    entry,
    prefix,
    first: () => ({ field: state.field, range: state.range }),
    results: () => plotted().shown,
    base: () => {
      const b = baseInputs();
      return b.error ? b : { inputs: { ...b.inputs, [state.field.key]: currentValue() ?? state.field.default } };
    },
    // the table of result `key` was made (or closed: null): the link carries it, with its result first in plot=
    made: (key) => {
      if (key && state.plot[0] !== key && state.plot.includes(key)) {
        state.plot = [key, ...state.plot.filter((k) => k !== key)];
        buildPlotChoices();
        run({ own: true });
      } else writeLink();
    },
  });
  const section = el(
    "section",
    { class: "panel sweep-section", "aria-labelledby": heading.id, "data-sweep": "" },
    heading,
    intro,
    el("div", { class: "sweep-controls" }, labelled(fieldSelect, "Input"), labelled(fromInput, "From"), labelled(toInput, "To"), labelled(stepsInput, "Steps")),
    plotBox,
    message,
    frame,
    legend,
    data.cursorLine,
    scrub,
    data.bar,
    data.body,
    errorsBox,
    el("div", { class: "tools" }, csvButton, pngButton, closeButton),
    grid.element,
    status,
  );
  // the sweep's controls stay usable in a locked embed: they change no input of the exercise
  for (const c of [fieldSelect, fromInput, toInput, stepsInput]) c.classList.add("keep-enabled");
  host.replaceChildren(section);
  host.hidden = false;

  const fields = sweepableFields(entry);
  for (const f of fields) fieldSelect.append(el("option", { value: f.key }, fieldText(f)));

  let statusTimer = 0;
  const say = (text) => {
    clearTimeout(statusTimer);
    status.textContent = text;
    statusTimer = setTimeout(() => (status.textContent = ""), STATUS_MS);
  };

  /** The labels and units of results (from a solution: they do not change with the inputs). */
  function labels() {
    if (!state.labels) {
      let s = view.lastGood;
      if (!s) {
        try {
          s = core.solve(id, {});
        } catch {
          s = null;
        }
      }
      state.labels = s;
    }
    return state.labels;
  }

  const resultInfo = (k) => labelOf(labels() ?? {}, k);

  /** The form's inputs as the core reads them, or an error message. */
  function baseInputs() {
    const texts = view.form.texts();
    let parsed;
    try {
      parsed = core.parseInputs(id, texts);
    } catch (e) {
      return { error: e.message };
    }
    const errs = Object.entries(parsed.errors ?? {}).filter(([k]) => k !== state.field?.key);
    if (errs.length) return { error: `Fix the inputs above first: ${errs.map(([k, m]) => (m.startsWith(`${k}: `) ? m : `${k}: ${m}`)).join("; ")}` };
    const inputs = { ...(parsed.inputs ?? {}) };
    delete inputs[state.field.key];
    return { inputs, texts };
  }

  /** The swept input's value in the form, as the core reads it (null when it does not read). */
  function currentValue() {
    const key = state.field.key;
    try {
      const v = core.parseInputs(id, { [key]: view.form.texts()[key] }).inputs?.[key];
      return typeof v === "number" ? v : null;
    } catch {
      return null;
    }
  }

  function buildPlotChoices() {
    const keys = numericResultKeys(labels());
    plotBox.replaceChildren(el("legend", {}, `Plot (up to ${MAX_PLOTTED} results)`));
    for (const k of keys) {
      const { label, unit } = resultInfo(k);
      const box = el("input", { type: "checkbox", id: `${prefix}-plot-${idPart(k)}`, value: k, class: "keep-enabled" });
      box.checked = state.plot.includes(k);
      box.addEventListener("change", () => {
        const chosen = [...plotBox.querySelectorAll("input:checked")].map((b) => b.value);
        if (chosen.length > MAX_PLOTTED) {
          box.checked = false;
          say(`At most ${MAX_PLOTTED} results at once: clear one first.`);
          return;
        }
        state.plot = chosen;
        run({ own: true });
      });
      plotBox.append(el("label", { for: box.id, class: "sweep-plot-choice" }, box, ` ${label}${unit ? ` (${unit})` : ""}`, el("code", { class: "field-key" }, k)));
    }
  }

  /** The results plotted first: the example's answer where it is a number, else the first numeric result. */
  function defaultPlot() {
    const s = labels();
    const keys = numericResultKeys(s);
    const answer = (s?.answer ?? []).filter((k) => keys.includes(k));
    return answer.length ? answer.slice(0, MAX_PLOTTED) : keys.slice(0, 1);
  }

  function setField(key, range = null) {
    state.field = fields.find((f) => f.key === key) ?? fields[0];
    fieldSelect.value = state.field.key;
    if (range) state.range = range;
    else {
      const base = baseInputs();
      const value = currentValue() ?? state.field.default;
      state.range = base.error ? chooseRange(null, id, {}, state.field, value) : chooseRange(core.solveSeries, id, base.inputs, state.field, value);
    }
    fromInput.value = valueText(state.range.from);
    toInput.value = valueText(state.range.to);
    stepsInput.value = String(state.range.steps);
  }

  /** Reads the range controls: a range, or a worded message. */
  function readRange() {
    const from = readEnd(fromInput.value, "From");
    if (from.error) return from;
    const to = readEnd(toInput.value, "To");
    if (to.error) return to;
    const steps = readCount(stepsInput.value, "Steps", MIN_STEPS, MAX_STEPS);
    if (steps.error) return steps;
    if (from.value === to.value) return { error: "“From” and “To” are the same value: a sweep needs a range." };
    return { range: { from: from.value, to: to.value, steps: steps.value } };
  }

  /** A count typed in a box, read by the core (a whole number from `min` to `max`), or the core's words. */
  function readCount(text, name, min, max) {
    try {
      return { value: core.readCount(id, text, min, max) };
    } catch (e) {
      return { error: `“${name}”: ${e.message.replace(/^text: /, "")}.` };
    }
  }

  /** One end of the range, read by the core as the swept input's own box (its unit, bounds and message). */
  function readEnd(text, name) {
    return readTypedEnd(core.parseInputs, id, state.field.key, text, name);
  }

  function writeLink() {
    api.setLink(formatSweep({ key: state.field.key, ...state.range }), state.plot.join(","), grid.linkValue());
  }

  /** The plotted results that fit two axes; a third unit is left out with a message. */
  function plotted() {
    const series = state.plot.map((k) => ({ key: k, ...resultInfo(k) }));
    const units = axesOf(series);
    return { shown: series.filter((s) => units.includes(s.unit ?? "")), left: series.filter((s) => !units.includes(s.unit ?? "")) };
  }

  function ensureChart(shown) {
    const keys = `${state.field.key}|${shown.map((s) => `${s.key}:${groupOf(s)}`).join(",")}`;
    if (state.chart && state.chartKeys === keys) return;
    state.chart?.destroy();
    chartHost.replaceChildren();
    state.chartKeys = keys;
    state.chart = makeChart(chartHost, {
      x: { label: state.field.label, unit: state.field.unit, seed: state.field.default },
      series: shown,
      onCursor: (i) => {
        if (i !== null && state.idx !== i && !state.keyboard) readout(i, false);
      },
      onPick: (i) => pick(i),
    });
    const units = axesOf(shown);
    legend.replaceChildren(
      ...shown.map((s, i) => {
        const swatch = el("span", { class: "sweep-swatch", "aria-hidden": "true" });
        swatch.style.borderTopColor = colour(strokeOf(i).color);
        swatch.style.borderTopStyle = strokeOf(i).dash.length ? "dashed" : "solid";
        const side = units.length > 1 ? (units.indexOf(groupOf(s)) === 0 ? ", left axis" : ", right axis") : "";
        return el("li", {}, swatch, `${s.label}${s.unit ? ` (${s.unit})` : ""}${side}`);
      }),
      el("li", { class: "sweep-legend-mark" }, el("span", { class: "sweep-swatch sweep-swatch-seed", "aria-hidden": "true" }), `worked example: ${state.field.label} = ${withUnit(state.field.default, state.field.unit)}`),
    );
  }

  /** The words for point i: "Flying height H = 1200 m: GSD = 23.4 cm" or its solver's message. */
  function pointText(i) {
    const s = state.series;
    const x = s.xs[i];
    const head = `${state.field.label} = ${withUnit(x, state.field.unit)}`;
    const p = s.points[i];
    if (p.error) return `${head}: no solution — ${p.error}`;
    const parts = plotted().shown.map(({ key, label, unit }) => (s.ys[key][i] === null ? `${label}: no value` : `${label} = ${withUnit(s.ys[key][i], unit)}`));
    return `${head}: ${parts.join("; ")}`;
  }

  function readout(i, announce) {
    if (!state.series || i === null || i >= state.series.xs.length) return;
    state.idx = i;
    // the live line speaks for the keyboard; a pointer's hover writes the same words
    data.cursorLine.setAttribute("aria-live", announce ? "polite" : "off");
    data.cursorLine.textContent = pointText(i);
  }

  /** Point i's value into the form: the page solves it (its whole solution above). */
  function pick(i) {
    if (!state.series || i == null) return;
    // a locked embed (lock=true): the exercise's inputs stay; the chart is still read point by point
    if (document.body.classList.contains("locked")) {
      say("The inputs of this exercise are fixed: the chart and its table show every point.");
      slider.value = String(nearestIndex(currentValue()));
      return;
    }
    slider.value = String(i);
    showSlider(i);
    api.setInput(state.field.key, valueText(state.series.xs[i]));
    state.chart?.setCurrent(state.series.xs[i]);
  }

  /** The slider at point i; its words say `value` (the form's, when it lies between two points). */
  function showSlider(i, value = null) {
    const x = value ?? state.series.xs[i];
    sliderValue.textContent = withUnit(x, state.field.unit);
    slider.setAttribute("aria-valuetext", `${state.field.label} ${withUnit(x, state.field.unit)}`);
    pointLink.href = api.hashFor(state.field.key, valueText(x));
  }

  function nearestIndex(value) {
    const xs = state.series?.xs ?? [];
    if (value === null || !xs.length) return 0;
    let best = 0;
    xs.forEach((x, i) => {
      if (Math.abs(x - value) < Math.abs(xs[best] - value)) best = i;
    });
    return best;
  }

  function tables() {
    const s = state.series;
    const { shown } = plotted();
    const columns = [fieldText(state.field), ...shown.map(({ label, unit }) => `${label}${unit ? ` (${unit})` : ""}`)];
    const rows = s.xs.map((x, i) => [num(x, 10), ...shown.map(({ key }) => (s.ys[key][i] === null ? "no value" : num(s.ys[key][i], 10)))]);
    const marks = s.xs.map((x, i) => [s.points[i].error ? "no solution" : x === state.field.default ? "worked example" : null, ...shown.map(() => null)]);
    return { tables: [seriesTable(`The series: ${columns.slice(1).join(", ")} against ${columns[0]}`, columns, rows, marks)] };
  }

  /** The Data table (figures' data view); its scrolling box reachable by keyboard. */
  function showData() {
    renderData(data.body, tables());
    for (const wrap of data.body.querySelectorAll(".figure-table-wrap")) scrollable(wrap, "The series as a table: scroll to see all of it");
  }

  function renderErrors() {
    const s = state.series;
    const bad = s.points.map((p, i) => [i, p]).filter(([, p]) => p.error);
    if (!bad.length) {
      errorsBox.replaceChildren();
      return;
    }
    const t = el(
      "table",
      { class: "figure-table sweep-error-table" },
      el("caption", { class: "visually-hidden" }, "Points without a solution"),
      el("thead", {}, el("tr", {}, el("th", { scope: "col" }, fieldText(state.field)), el("th", { scope: "col" }, "The solver’s message"))),
      el("tbody", {}, ...bad.map(([, p]) => el("tr", {}, el("td", {}, num(p.x, 10)), el("td", { class: "figure-text" }, p.error)))),
    );
    // a long list folds (a phone would scroll through it); a few are shown at once
    const fold = el("details", { class: "sweep-errors-fold" }, el("summary", {}, `${bad.length} of ${s.xs.length} points have no solution (gaps in the lines, × on the chart): the solver’s messages`), el("div", { class: "figure-table-wrap" }, t));
    fold.open = bad.length <= 5;
    errorsBox.replaceChildren(fold);
    scrollable(fold.querySelector(".figure-table-wrap"), "Points without a solution: scroll to see all of it");
  }

  /**
   * Computes the series and draws it. `own`: a change of the sweep's own
   * controls (the link follows and the host hears of it); else an input of
   * the page changed (only the inputs other than the swept one matter).
   */
  function run({ own = false } = {}) {
    if (!state.field) return;
    const base = baseInputs();
    if (base.error) {
      message.textContent = base.error;
      return;
    }
    const r = readRange();
    if (r.error) {
      message.textContent = r.error;
      return;
    }
    const key = JSON.stringify([state.field.key, r.range, state.plot, base.inputs]);
    if (!own && key === state.base && state.series) {
      // only the swept input moved (the slider): the curve stands, its marks follow
      const v = currentValue();
      state.chart?.setCurrent(v);
      if (v !== null && v !== state.series.xs[Number(slider.value)]) {
        slider.value = String(nearestIndex(v));
        showSlider(Number(slider.value), v);
      }
      return;
    }
    state.range = r.range;
    state.base = key;
    if (own) writeLink();
    const t0 = performance.now();
    const { shown, left } = plotted();
    const notes = [];
    if (!state.plot.length) notes.push("Choose a result to plot.");
    if (left.length) notes.push(`Not plotted: ${left.map((s) => s.label).join(", ")} (a third unit: two axes at most).`);
    const values = sweepValues(r.range, state.field.kind === "integer");
    state.series = computeSeries(core.solveSeries, id, base.inputs, state.field.key, values, shown.map((s) => s.key));
    const compute = performance.now() - t0;
    state.cost = compute;
    splitBySize(shown, state.series);
    ensureChart(shown);
    const errors = state.series.points.map((p) => p.error);
    const v = currentValue();
    state.chart.setData(state.series.xs, state.series.ys, errors, v);
    // what uPlot was given, for the e2e tests (test-hooks.js: nothing on a student's page)
    testData(section, "plotted", JSON.stringify({ key: state.field.key, xs: state.series.xs, ys: Object.fromEntries(shown.map((x) => [x.key, state.series.ys[x.key]])), errors }));
    const bad = errors.filter(Boolean).length;
    message.textContent = [...notes, bad ? `${bad} of ${values.length} points have no solution: see the list below the chart.` : ""].filter(Boolean).join(" ");
    slider.max = String(values.length - 1);
    const i = nearestIndex(v);
    slider.value = String(i);
    showSlider(i, v);
    data.summary.textContent = `A line chart of ${shown.map((s) => s.label).join(" and ") || "nothing yet"} against ${state.field.label} from ${withUnit(values[0], state.field.unit)} to ${withUnit(values.at(-1), state.field.unit)}, ${values.length} points${bad ? `, ${bad} without a solution` : ""}. The worked example’s value is ${withUnit(state.field.default, state.field.unit)}.`;
    frame.setAttribute("aria-label", `Sweep chart: ${shown.map((s) => s.label).join(", ")} against ${state.field.label}`);
    if (data.open) showData();
    renderErrors();
    grid.refresh();
    if (state.idx !== null && state.idx >= values.length) state.idx = null;
    const js = performance.now() - t0;
    // for `npm run bench -- sweep`: the series and its chart, after the frame that paints them
    const start = own ? t0 : (api.changeStart?.() ?? t0);
    requestAnimationFrame(() =>
      setTimeout(() => {
        performance.clearMeasures("sweep");
        performance.measure("sweep", { start, end: performance.now(), detail: { points: values.length, compute, js } });
      }, 0),
    );
    if (own) api.posted();
  }

  // ---- events
  fieldSelect.addEventListener("change", () => {
    setField(fieldSelect.value);
    state.idx = null;
    run({ own: true });
  });
  for (const input of [fromInput, toInput, stepsInput]) input.addEventListener("change", () => run({ own: true }));
  slider.addEventListener("input", () => {
    const i = Number(slider.value);
    readout(i, false);
    state.chart?.select(i);
    pick(i);
  });
  frame.addEventListener("keydown", (e) => {
    if (!state.series || e.altKey || e.ctrlKey || e.metaKey) return;
    const n = state.series.xs.length;
    const cur = state.idx ?? nearestIndex(currentValue());
    let next;
    if (e.key === "ArrowRight" || e.key === "ArrowUp") next = Math.min(n - 1, cur + (state.idx === null ? 0 : 1));
    else if (e.key === "ArrowLeft" || e.key === "ArrowDown") next = Math.max(0, cur - (state.idx === null ? 0 : 1));
    else if (e.key === "Home") next = 0;
    else if (e.key === "End") next = n - 1;
    else if (e.key === "PageUp") next = Math.min(n - 1, cur + 10);
    else if (e.key === "PageDown") next = Math.max(0, cur - 10);
    else if ((e.key === "Enter" || e.key === " ") && state.idx !== null) {
      e.preventDefault();
      pick(state.idx);
      say(`Showing the solution at ${state.field.label} = ${withUnit(state.series.xs[state.idx], state.field.unit)}.`);
      return;
    } else return;
    e.preventDefault();
    state.keyboard = true;
    state.chart?.select(next);
    state.keyboard = false;
    readout(next, true);
  });
  frame.addEventListener("blur", () => state.chart?.select(null));
  data.toggle.addEventListener("click", () => {
    data.open = !data.open;
    data.toggle.setAttribute("aria-expanded", String(data.open));
    data.body.hidden = !data.open;
    if (data.open && state.series) showData();
  });
  csvButton.addEventListener("click", () => {
    if (!state.series) return say("Nothing to export yet.");
    const labelsByKey = Object.fromEntries(state.series.plot.map((k) => [k, `${k}${resultInfo(k).unit ? ` (${resultInfo(k).unit})` : ""}`]));
    const xLabel = `${state.field.key}${state.field.unit ? ` (${state.field.unit})` : ""}`;
    download(new Blob([seriesCsv(state.series, { xLabel, labels: labelsByKey })], { type: "text/csv" }), `${id}-sweep-${state.field.key}.csv`);
    say("Series downloaded.");
  });
  pngButton.addEventListener("click", () => {
    const canvas = state.chart?.canvas();
    if (!canvas) return say("Nothing to export yet.");
    const out = document.createElement("canvas");
    out.width = canvas.width;
    out.height = canvas.height;
    const ctx = out.getContext("2d");
    ctx.fillStyle = colour("background");
    ctx.fillRect(0, 0, out.width, out.height);
    ctx.drawImage(canvas, 0, 0);
    out.toBlob((blob) => {
      if (!blob) return say("The chart could not be saved.");
      download(blob, `${id}-sweep-${state.field.key}.png`);
      say("Chart downloaded.");
    }, "image/png");
  });
  closeButton.addEventListener("click", () => api.close());
  const retheme = () => state.chart && (state.chart.theme(), state.series && state.chart.setData(state.series.xs, state.series.ys, state.series.points.map((p) => p.error), currentValue()));
  const themeObserver = new MutationObserver(retheme);
  themeObserver.observe(document.documentElement, { attributes: true, attributeFilter: ["data-theme"] });
  const scheme = window.matchMedia("(prefers-color-scheme: dark)");
  scheme.addEventListener("change", retheme);

  return {
    /** Opens (or re-aims) the sweep: a spec from the link (checked here against the example), the results to plot. */
    open({ spec = null, plot = null, grid: gridSpec = null, focus = false } = {}) {
      const notes = [];
      const texts = view.form.texts();
      let field = fields.find((f) => fieldApplies(entry, f, texts)) ?? fields[0];
      let range = null;
      if (spec) {
        const wrong = checkSweep(entry, spec);
        if (wrong) notes.push(`Ignored sweep=${spec.key}:…: ${wrong}.`);
        else {
          field = fields.find((f) => f.key === spec.key);
          range = { from: spec.from, to: spec.to, steps: spec.steps };
        }
      }
      state.plot = [];
      setField(field.key, range);
      const numeric = numericResultKeys(labels());
      if (plot) {
        const { keys, unknown } = checkPlot(labels(), plot);
        if (unknown.length) notes.push(`Ignored plot=${unknown.join(",")}: ${unknown.length === 1 ? "it is not a numeric result" : "they are not numeric results"} of this example (${numeric.join(", ")}).`);
        state.plot = keys;
      }
      if (!state.plot.length) state.plot = defaultPlot();
      buildPlotChoices();
      run({ own: true });
      // grid= from the link: the table of plot='s first result, made now (none without it)
      const wrong = gridSpec ? grid.restore(gridSpec) : (grid.clear(), null);
      if (wrong) {
        grid.clear();
        notes.push(`Ignored grid=${gridSpec.key}:…: ${wrong}.`);
      } else if (gridSpec) writeLink();
      if (notes.length) message.textContent = `${notes.join(" ")} ${message.textContent}`.trim();
      if (focus) heading.focus();
    },
    /** An input of the page changed (app.js recompute): the series follows. */
    changed({ defer = false } = {}) {
      if (!state.field) return;
      clearTimeout(state.settle);
      // while a student types, a slow series (LSM, UTM: 200 solutions) waits until the typing settles
      if (defer && state.cost > SLOW_SERIES_MS) {
        section.classList.add("sweep-updating");
        state.settle = setTimeout(() => {
          section.classList.remove("sweep-updating");
          run();
          api.posted();
        }, SETTLE_MS);
        return;
      }
      run();
    },
    /** The series for the host page's change event (embed-page.js). */
    payload() {
      const s = state.series;
      if (!s) return null;
      return { input: s.key, from: state.range.from, to: state.range.to, steps: state.range.steps, plot: [...s.plot], xs: [...s.xs], ys: Object.fromEntries(s.plot.map((k) => [k, [...s.ys[k]]])), errors: s.points.map((p) => p.error) };
    },
    /** The sweep as the link writes it: { sweep: "key:from:to:steps", plot: "a,b" } (the embed panel's snippets). */
    linkEntries: () => (state.field && state.range ? { sweep: formatSweep({ key: state.field.key, ...state.range }), plot: state.plot.join(",") || null, grid: grid.linkValue() } : {}),
    destroy() {
      clearTimeout(state.settle);
      themeObserver.disconnect();
      scheme.removeEventListener("change", retheme);
      state.chart?.destroy();
      host.replaceChildren();
      host.hidden = true;
    },
  };
}

/** A box that may scroll sideways, reachable and named for the keyboard (as render.js's wide matrices). */
function scrollable(node, label) {
  node.setAttribute("tabindex", "0");
  node.setAttribute("role", "region");
  node.setAttribute("aria-label", label);
}

/** A series that took longer than this waits for typing to settle (SETTLE_MS after the last key). */
const SLOW_SERIES_MS = 40;
const SETTLE_MS = 250;

/** How far apart (a factor) two results of one unit may be and still share an axis. */
const SHARED_AXIS_RATIO = 10;

/**
 * Results that all have one unit but sizes far apart (Förstner's weight in
 * thousands beside its roundness below 1) get the right axis for the later
 * ones (their `group`), so that none is drawn flat along zero.
 */
function splitBySize(shown, series) {
  for (const s of shown) delete s.group;
  if (shown.length < 2 || axesOf(shown).length > 1) return;
  const size = (s) => Math.max(0, ...series.ys[s.key].filter((v) => v !== null).map(Math.abs));
  const first = size(shown[0]);
  for (const s of shown.slice(1)) {
    const m = size(s);
    if (first > 0 && m > 0 && (first / m > SHARED_AXIS_RATIO || m / first > SHARED_AXIS_RATIO)) s.group = `${s.unit ?? ""}\u0000right`;
  }
}
