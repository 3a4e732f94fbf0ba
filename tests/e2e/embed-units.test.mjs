// The pure parts of embedding and export, in Node (no browser): view options
// parsed and validated, CSV and LaTeX built from a solution.
import { describe, test } from "node:test";
import assert from "node:assert/strict";
import { parseOptions, parseOrigin } from "../../www/embed-options.js";
import { solutionCsv, solutionTex, texText } from "../../www/export.js";

describe("view options", () => {
  test("valid options are taken, written back in a fixed form, inputs left alone", () => {
    const r = parseOptions([["dpi", "1200"], ["theme", "Dark"], ["hide", "notes, inputs,notes"], ["steps", "collapsed"], ["lock", ""], ["step", "2"], ["host", "https://course.example.org/page?x=1"], ["id", "ex-1"]]);
    assert.deepEqual(r.rest, [["dpi", "1200"]]);
    assert.deepEqual(r.notices, []);
    assert.deepEqual(r.options, { theme: "dark", hide: ["notes", "inputs"], steps: "collapsed", lock: true, step: 2, host: "https://course.example.org", id: "ex-1", play: null, sweep: null, plot: null, grid: null });
    assert.deepEqual(r.entries, [["theme", "dark"], ["hide", "notes,inputs"], ["steps", "collapsed"], ["lock", "true"], ["step", "2"], ["host", "https://course.example.org"], ["id", "ex-1"]]);
  });

  test("play: a frame (paused there) or auto; anything else named in a notice", () => {
    assert.deepEqual(parseOptions([["play", "7"]]).options.play, { frame: 7 });
    assert.deepEqual(parseOptions([["play", " AUTO "]]).entries, [["play", "auto"]]);
    for (const bad of ["0", "-3", "seven", "1.5", "1000001"]) {
      const r = parseOptions([["play", bad]]);
      assert.equal(r.options.play, null, bad);
      assert.match(r.notices[0], /play=“.*”: give a frame number from 1 to 100000 \(opens paused there\) or auto/, bad);
    }
  });

  test("grid: the sweep's two-input table, key:from:to:rows (2–11), read like sweep=; anything else named in a notice", () => {
    const r = parseOptions([["grid", "focal_length_mm:100:3e2:5"]]);
    assert.deepEqual(r.options.grid, { key: "focal_length_mm", from: 100, to: 300, steps: 5 });
    assert.deepEqual(r.entries, [["grid", "focal_length_mm:100:3e2:5"]]);
    for (const [bad, why] of [
      ["focal_length_mm:100:300:12", /the rows must be a whole number from 2 to 11/],
      ["focal_length_mm:100:300", /it has 3 parts; write it as field:from:to:rows/],
      ["focal_length_mm:100:x:5", /“to” is not a number/],
      ["focal_length_mm:100:100:5", /“from” and “to” are the same value: a table needs a range/],
      ["f<b>:1:2:3", /the field name must be letters, digits and _/],
    ]) {
      const b = parseOptions([["grid", bad]]);
      assert.equal(b.options.grid, null, bad);
      assert.match(b.notices[0], why, bad);
    }
  });

  test("show keeps only the parts named; hide adds to it", () => {
    const r = parseOptions([["show", "figure,result"], ["hide", "figure"]]);
    assert.deepEqual([...r.options.hide].sort(), ["figure", "inputs", "notes", "steps", "tools"]);
  });

  test("bad values are ignored with a notice each; the defaults stay", () => {
    const r = parseOptions([["theme", "purple"], ["steps", "half"], ["lock", "maybe"], ["step", "-1"], ["step", "1e3"], ["host", "ftp://x.org"], ["id", "a b"], ["hide", "wings,steps"]]);
    assert.equal(r.options.theme, "auto");
    assert.equal(r.options.steps, "open");
    assert.equal(r.options.lock, false);
    assert.equal(r.options.step, null);
    assert.equal(r.options.host, null);
    assert.equal(r.options.id, null);
    assert.deepEqual(r.options.hide, ["steps"]);
    assert.equal(r.notices.length, 8);
    assert.match(r.notices[0], /theme=“purple”: use auto, light or dark/);
    assert.match(r.notices.at(-1), /hide=“wings”/);
    // a long value is quoted shortened
    const long = parseOptions([["theme", "x".repeat(500)]]);
    assert.ok(long.notices[0].length < 120, long.notices[0]);
  });

  test("origins: http(s) only, no credentials, the path dropped", () => {
    assert.equal(parseOrigin("https://a.example:8443/x"), "https://a.example:8443");
    assert.equal(parseOrigin("javascript:alert(1)"), null);
    assert.equal(parseOrigin("https://user:pw@a.example"), null);
    assert.equal(parseOrigin("null"), null);
  });
});

const SOLUTION = {
  id: "gsd",
  title: "Ground sample distance",
  inputs: { dpi: 900, focal_length_mm: 152, flying_height_m: 1920 },
  steps: [{ title: "Pixel size", text: "25.4 mm per inch; 100% & more_", formula: "p = \\frac{25.4}{dpi}", substituted: "p = \\frac{25.4}{900} = 0.02822222", values: {} }],
  result: { gsd_cm: 35.6491228, parameters: [1.5, -2], n: [[1, 2], [3, 4]], ok: true },
  textbook: { gsd_cm: 35.65 },
  notes: [{ kind: "rounding", text: "rounded to 4 digits" }],
  labels: { gsd_cm: { label: "Ground sample distance", unit: "cm" } },
};

describe("exports", () => {
  test("CSV: one row per number, lists indexed from 1, the printed value beside", () => {
    const rows = solutionCsv(SOLUTION).trimEnd().split("\r\n");
    assert.deepEqual(rows, [
      "section,key,label,unit,value,printed",
      "input,dpi,,,900,",
      "input,focal_length_mm,,,152,",
      "input,flying_height_m,,,1920,",
      "result,gsd_cm,Ground sample distance,cm,35.6491228,35.65",
      "result,parameters[1],,,1.5,",
      "result,parameters[2],,,-2,",
      "result,n[1][1],,,1,",
      "result,n[1][2],,,2,",
      "result,n[2][1],,,3,",
      "result,n[2][2],,,4,",
      "result,ok,,,true,",
    ]);
  });

  test("LaTeX: escaped text, the formulas as they are, results with the printed values", () => {
    assert.equal(texText("100% & a_b {x} $ # ~ ^ \\"), "100\\% \\& a\\_b \\{x\\} \\$ \\# \\~{} \\^{} \\textbackslash{}");
    const tex = solutionTex(SOLUTION, "https://x/#/gsd");
    assert.ok(tex.includes("\\subsection*{Ground sample distance}"));
    assert.ok(tex.includes("\\paragraph{1. Pixel size}"));
    assert.ok(tex.includes("25.4 mm per inch; 100\\% \\& more\\_"));
    assert.ok(tex.includes("\\[\np = \\frac{25.4}{900} = 0.02822222\n\\]"));
    assert.ok(tex.includes("\\item Ground sample distance (cm), \\texttt{gsd\\_cm} = 35.6491228 (the seed prints 35.65)"));
    assert.ok(tex.includes("\\texttt{n} = $\\begin{bmatrix}1 & 2 \\\\ 3 & 4\\end{bmatrix}$"));
    assert.ok(tex.includes("\\item \\textit{rounding:} rounded to 4 digits"));
  });
});
