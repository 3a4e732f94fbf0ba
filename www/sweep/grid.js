// Two inputs at once (docs/sweeps.md): one result over a grid of two number
// inputs, as a table whose cells are shaded by their value (a small heat map
// that is also the numbers). Every cell is solve(id, inputs with both values)
// (series.js computeGrid). Part of the sweep panel (sweep.js), loaded with it.
// While the table is shown, the link carries it: grid=<field>:<from>:<to>:<rows>,
// its result plot='s first (link.js parseGrid; restore() makes it on load).

import { el } from "../dom.js";
import { num } from "../figures/data-view.js";
import { SIGNED_NEGATIVE, rgbText } from "../colour-scales.js";
import { chooseRange, computeGrid, formatSweep, readEnd, sweepableFields, sweepValues } from "./series.js";
import { MAX_GRID_ROWS } from "./link.js";

/** Columns and rows of the table at most (a phone's width; a solve per cell). */
export const MAX_CELLS_SIDE = MAX_GRID_ROWS;
/** The strongest shade (alpha of the blue over the panel): the cell's text keeps its contrast. */
const MAX_ALPHA = 0.45;

const fieldText = (f) => `${f.label}${f.unit ? ` (${f.unit})` : ""}`;

/**
 * The "Two inputs at once" fold. `ctx`: { core, id, entry, prefix, first(): { field, range },
 * results(): [{ key, label, unit }], base(): { inputs } | { error },
 * made(resultKey | null): the table was made (its result) or put away: the link follows }.
 * @returns {{ element, refresh(), restore(spec): string|null, clear(), linkValue(): string|null }}
 */
export function gridFold(ctx) {
  const { core, id, entry, prefix } = ctx;
  const fields = sweepableFields(entry);
  const second = el("select", { id: `${prefix}-grid-field`, class: "keep-enabled" });
  // the ends are read as the second input's own box (the core's reader: a unit, a decimal comma; its bounds)
  const textBox = (name) => el("input", { id: `${prefix}-grid-${name}`, type: "text", inputmode: "decimal", autocomplete: "off", spellcheck: "false", class: "keep-enabled" });
  const from = textBox("from");
  const to = textBox("to");
  // a count: read by the core as the sweep's Steps (a whole number, 2–11, refused in its words)
  const steps = el("input", { id: `${prefix}-grid-steps`, type: "text", inputmode: "numeric", autocomplete: "off", spellcheck: "false", value: "6", class: "keep-enabled" });
  const result = el("select", { id: `${prefix}-grid-result`, class: "keep-enabled" });
  const make = el("button", { type: "button", class: "button keep-enabled", "data-tool": "sweep-grid" }, "Make the table");
  const message = el("p", { class: "sweep-message", role: "status" });
  const out = el("div", { class: "sweep-grid-out" });
  const labelled = (input, text) => el("div", { class: "sweep-control" }, el("label", { for: input.id }, text), input);
  const fold = el(
    "details",
    { class: "sweep-grid" },
    el("summary", {}, "Two inputs at once (a table)"),
    el("p", { class: "sweep-intro" }, `One result over the sweep’s input (columns, at most ${MAX_CELLS_SIDE} of its points) and a second input (rows); the stronger the blue, the higher the value.`),
    el("div", { class: "sweep-controls" }, labelled(second, "Second input"), labelled(from, "From"), labelled(to, "To"), labelled(steps, "Rows"), labelled(result, "Result")),
    el("div", { class: "tools" }, make),
    message,
    out,
  );

  /** The choices follow the sweep (its input is not a second one; its results are the table's). */
  function refresh() {
    const { field } = ctx.first();
    const keep = second.value;
    second.replaceChildren(...fields.filter((f) => f.key !== field.key).map((f) => el("option", { value: f.key }, fieldText(f))));
    if ([...second.options].some((o) => o.value === keep)) second.value = keep;
    const keepResult = result.value;
    result.replaceChildren(...ctx.results().map((r) => el("option", { value: r.key }, `${r.label}${r.unit ? ` (${r.unit})` : ""}`)));
    if ([...result.options].some((o) => o.value === keepResult)) result.value = keepResult;
    fold.hidden = !second.options.length || !result.options.length;
    if (!fold.hidden && keep !== second.value) aim();
    // a table whose input became the sweep's, or whose result is no longer plotted, is gone
    if (shown && (shown.key !== second.value || shown.result !== result.value || fold.hidden)) {
      shown = null;
      out.replaceChildren();
      message.textContent = "";
    }
  }

  /** A range around the second input's value (as the sweep's own). */
  function aim() {
    const f = fields.find((g) => g.key === second.value);
    const base = ctx.base();
    if (!f || base.error) return;
    const r = chooseRange(core.solveSeries, id, base.inputs, f, base.inputs[f.key] ?? f.default);
    from.value = String(r.from);
    to.value = String(r.to);
    steps.value = String(Math.min(6, f.kind === "integer" ? r.to - r.from + 1 : 6));
  }
  second.addEventListener("change", aim);

  /** The table on screen: { key, from, to, steps, result } (what the link carries), or null. */
  let shown = null;

  make.addEventListener("click", () => {
    makeTable();
    ctx.made(shown?.result ?? null);
  });
  // a folded table leaves the link; unfolded again, it is back
  fold.addEventListener("toggle", () => ctx.made(fold.open ? (shown?.result ?? null) : null));

  /** Makes the table from the controls; false (with the reason shown) when they cannot be read. */
  function makeTable() {
    const base = ctx.base();
    if (base.error) return fail(base.error);
    const f2 = fields.find((g) => g.key === second.value);
    const r = ctx.results().find((x) => x.key === result.value);
    let n;
    try {
      n = core.readCount(id, steps.value, 2, MAX_CELLS_SIDE);
    } catch (e) {
      return fail(`“Rows”: ${e.message.replace(/^text: /, "")}.`);
    }
    if (!f2 || !r) return fail("Choose a second input and a result.");
    const a = readEnd(core.parseInputs, id, f2.key, from.value, "From");
    if (a.error) return fail(a.error);
    const b = readEnd(core.parseInputs, id, f2.key, to.value, "To");
    if (b.error) return fail(b.error);
    if (a.value === b.value) return fail("“From” and “To” are the same value: the table needs a range.");
    const { field, range } = ctx.first();
    const xs = sweepValues({ ...range, steps: Math.min(range.steps, MAX_CELLS_SIDE) }, field.kind === "integer");
    const ys = sweepValues({ from: a.value, to: b.value, steps: n }, f2.kind === "integer");
    const inputs = { ...base.inputs };
    delete inputs[f2.key];
    const grid = computeGrid(core.solveSeries, id, inputs, field.key, xs, f2.key, ys, r.key);
    out.replaceChildren(table(grid, field, f2, r));
    const bad = grid.errors.flat().filter(Boolean).length;
    message.textContent = `${ys.length} × ${xs.length} solutions${bad ? `, ${bad} without a solution (their cells say so; the message is in each cell’s title and in the Data table of the sweep)` : ""}.`;
    shown = { key: f2.key, from: a.value, to: b.value, steps: n, result: r.key };
    return true;
  }

  function fail(text) {
    message.textContent = text;
    shown = null;
    out.replaceChildren();
    return false;
  }

  /**
   * The table from a link's grid= ({ key, from, to, steps }: link.js parseGrid), of
   * the sweep's first plotted result, opened and made: null, or why it cannot be.
   */
  function restore(spec) {
    const f = fields.find((g) => g.key === spec.key);
    if (!f) return `this example has no number input ${spec.key}`;
    if (f.key === ctx.first().field.key) return `${spec.key} is the sweep’s own input; the table needs a second one`;
    if (fold.hidden || ![...second.options].some((o) => o.value === f.key)) return `${spec.key} cannot be the table’s second input here`;
    const r = ctx.results()[0];
    if (!r) return "there is no plotted result to put in the table";
    second.value = f.key;
    from.value = String(spec.from);
    to.value = String(spec.to);
    steps.value = String(spec.steps);
    result.value = r.key;
    fold.open = true;
    return makeTable() ? null : message.textContent;
  }

  /** No table (a link without grid=, or a wrong one): folded and empty. */
  function clear() {
    fail("");
    fold.open = false;
  }

  /** grid=… for the link while the table is shown (null otherwise). */
  const linkValue = () => (shown && fold.open ? formatSweep(shown) : null);

  function table(grid, fx, fy, r) {
    const vals = grid.values.flat().filter((v) => v !== null);
    const lo = Math.min(...vals);
    const hi = Math.max(...vals);
    const shade = (v) => (hi > lo ? (MAX_ALPHA * (v - lo)) / (hi - lo) : MAX_ALPHA / 2);
    const caption = `${r.label}${r.unit ? ` (${r.unit})` : ""}: ${fieldText(fy)} down, ${fieldText(fx)} across`;
    const t = el(
      "table",
      { class: "figure-table sweep-grid-table", id: `${prefix}-grid-table` },
      el("caption", { class: "visually-hidden" }, caption),
      el("thead", {}, el("tr", {}, el("th", { scope: "col", title: `${fieldText(fy)} down, ${fieldText(fx)} across` }, `${fy.unit || fy.label} ↓ ${fx.unit || fx.label} →`), ...grid.xs.map((x) => el("th", { scope: "col" }, num(x))))),
      el(
        "tbody",
        {},
        ...grid.ys.map((y, i) =>
          el(
            "tr",
            {},
            el("th", { scope: "row" }, num(y)),
            ...grid.xs.map((x, j) => {
              const v = grid.values[i][j];
              const err = grid.errors[i][j];
              const td = el("td", err ? { class: "figure-text", title: err } : {}, v === null ? (err ? "no solution" : "no value") : num(v));
              if (v !== null) td.style.backgroundColor = `rgba(${rgbText(SIGNED_NEGATIVE)}, ${shade(v).toFixed(3)})`;
              return td;
            }),
          ),
        ),
      ),
    );
    // the caption's words above the scrolling box (a wide table's own caption would scroll away with it)
    const wrap = el("div", { class: "figure-table-wrap", tabindex: "0", role: "region", "aria-label": `${caption}: scroll to see all of it` }, t);
    return el("div", {}, el("p", { class: "figure-table-title", "aria-hidden": "true" }, caption), wrap);
  }

  return { element: fold, refresh, restore, clear, linkValue };
}
