// The sweep's one computation path (issue 34; www/sweep/series.js) with the
// real core in Node: for every example with a number input, a sweep over its
// first number input that applies (a few points across the default range and
// one past the field's bounds) gives at each point exactly solve(id, inputs
// with that value); a point the solver refuses is a gap carrying the solver's
// message; the text the slider writes into the form reads back as the same number.

import assert from "node:assert/strict";
import { test } from "node:test";
import { nodeModule } from "./harness.mjs";
import { chooseRange, computeGrid, computeSeries, fieldApplies, numericResultKeys, seriesCsv, sweepableFields, sweepValues, valueText } from "../../www/sweep/series.js";

const core = await nodeModule("all");
const entries = core.catalog().filter((e) => e.status === "ready");
const seedTexts = (entry) => Object.fromEntries(entry.inputs.map((f) => [f.key, f.default_text ?? String(f.default)]));

/** A value the field refuses: past its max, else below its min (null when it has neither). */
function outside(field) {
  if (field.max != null && field.max < 1e6) return field.kind === "integer" ? field.max + 1 : field.max * 1.5 + 1;
  if (field.min != null && field.min > -1e6) return field.kind === "integer" ? field.min - 1 : field.min - 1;
  return null;
}

const swept = entries.filter((e) => sweepableFields(e).some((f) => fieldApplies(e, f, seedTexts(e))));

test("examples with a number input are found (the sweep has something to do)", () => {
  assert.ok(swept.length >= 12, `only ${swept.length} examples have a number input`);
  for (const id of ["gsd", "lsm-2d", "utm", "forstner-image"]) assert.ok(swept.some((e) => e.id === id), id);
});

for (const entry of swept) {
  test(`${entry.id}: every point of a sweep is solve(id, inputs with that value)`, () => {
    const texts = seedTexts(entry);
    const field = sweepableFields(entry).find((f) => fieldApplies(entry, f, texts));
    const { inputs, errors } = core.parse_inputs(entry.id, texts);
    assert.deepEqual(errors, {});
    const plot = numericResultKeys(core.solve(entry.id, inputs));
    assert.ok(plot.length > 0, "the seed solution has numeric results");
    const values = sweepValues({ ...chooseRange(core.solve_series, entry.id, inputs, field, field.default), steps: 5 }, field.kind === "integer");
    const bad = outside(field);
    if (bad !== null) values.push(bad);
    const series = computeSeries(core.solve_series, entry.id, inputs, field.key, values, plot);
    assert.deepEqual(series.xs, values);
    let refused = 0;
    values.forEach((x, i) => {
      // the form's text for x reads back as x (the slider's point is the plotted one)
      const back = core.parse_inputs(entry.id, { ...texts, [field.key]: valueText(x) });
      if (!Object.keys(back.errors).length) assert.equal(back.inputs[field.key], x, `${field.key}=${valueText(x)}`);
      let expected = null;
      let message = null;
      try {
        expected = core.solve(entry.id, { ...inputs, [field.key]: x });
      } catch (e) {
        message = e.message;
      }
      assert.equal(series.points[i].error, message, `point ${i} (${field.key} = ${x})`);
      for (const k of plot) {
        const y = expected?.result?.[k];
        assert.equal(series.ys[k][i], typeof y === "number" && Number.isFinite(y) ? y : null, `${k} at ${field.key} = ${x}`);
      }
      if (message) {
        refused++;
        for (const k of plot) assert.equal(series.ys[k][i], null, "an error is a gap");
      }
    });
    if (bad !== null) {
      assert.ok(series.points.at(-1).error, `${field.key} = ${bad} is refused`);
      assert.match(series.points.at(-1).error, new RegExp(`^${field.key}: `), "the message names the field");
    }
    assert.ok(refused < values.length, "some point solves");
    // the CSV carries the same numbers, at full precision
    const rows = seriesCsv(series).trim().split("\r\n").slice(1);
    rows.forEach((row, i) => {
      const cells = row.split(",");
      assert.equal(Number(cells[0]), values[i]);
      plot.forEach((k, j) => assert.equal(cells[1 + j] === "" ? null : Number(cells[1 + j]), series.ys[k][i]));
    });
  });
}

test("two inputs at once: every cell of a grid is solve(id, inputs with both values), a refused one null with its message", () => {
  const xs = [-100, 0, 600, 1200];
  const ys = [100, 152, 300];
  const grid = computeGrid(core.solve_series, "gsd", {}, "dpi", xs, "focal_length_mm", ys, "gsd_cm");
  ys.forEach((f, i) =>
    xs.forEach((d, j) => {
      let v = null;
      let message = null;
      try {
        v = core.solve("gsd", { dpi: d, focal_length_mm: f }).result.gsd_cm;
      } catch (e) {
        message = e.message;
      }
      assert.equal(grid.values[i][j], v, `dpi ${d}, f ${f}`);
      assert.equal(grid.errors[i][j], message);
    }),
  );
  assert.equal(grid.errors[0][0]?.startsWith("dpi: "), true);
  assert.equal(grid.values[1][2], core.solve("gsd", { dpi: 600 }).result.gsd_cm);
});
