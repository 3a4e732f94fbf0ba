// A formula's layout planned from a step's parts (www/formula-plan.js), in
// Node: the tests feed relations (data, as the core sends them), never LaTeX
// to be taken apart, and check the groups, lines and terms, and the blocks
// and captions of a matrix too wide for its line.
import { describe, it } from "node:test";
import assert from "node:assert/strict";
import fs from "node:fs";
import { blockCaption, gridBlocks, gridTermTex, gridTex, planFormula, shortGrid, tableRowLines } from "../../www/formula-plan.js";
import { formulaSource } from "../../www/math.js";

const t = (tex) => ({ tex });
const grid = (env, rows, name = null) => ({ grid: { env, rows, name } });
/** The terms' LaTeX of a plan: groups → items → terms (a grid as its lead and rows). */
const texts = (plan) => plan.groups.map((g) => g.items.map((item) => item.terms.map((x) => (x.grid ? `${x.lead}|${x.grid.rows.length}x${x.grid.rows[0].length}` : x.tex))));

const GSD = {
  key: "gsd_cm",
  lhs: [t(String.raw`\text{GSD}`)],
  op: "=",
  symbolic: [[t(String.raw`p \cdot m`)]],
  substituted: [[t(String.raw`0.028 \times 9047`)]],
  result: [[t(String.raw`255\,\text{mm}`)], [t(String.raw`25.5\,\text{cm}`)]],
};

describe("planFormula: one group per relation, breaks only between the core's pieces", () => {
  it("the left-hand side stays with its first relation; each further side starts an item", () => {
    const step = { formula: "x", substituted: "y", parts: [GSD] };
    assert.deepEqual(texts(planFormula(formulaSource(step, "symbolic"))), [[[String.raw`\text{GSD} = p \cdot m`]]]);
    const sub = planFormula(formulaSource(step, "substituted"));
    assert.deepEqual(texts(sub), [[[String.raw`\text{GSD} = 0.028 \times 9047`], [String.raw`= 255\,\text{mm}`], [String.raw`= 25.5\,\text{cm}`]]]);
    assert.deepEqual(
      sub.groups[0].items.map((i) => i.cont),
      [false, true, true],
    );
    assert.equal(sub.groups[0].key, "gsd_cm");
    // too wide, the left-hand side and its first relation may part
    assert.deepEqual(sub.groups[0].items[0].terms[0].apart, [String.raw`\text{GSD}`, String.raw`= 0.028 \times 9047`]);
  });

  it("the terms of a long sum are terms of one line; another relation sign is kept", () => {
    const r = { key: null, lhs: [t("Z")], op: String.raw`\approx`, symbolic: [[t("a_0"), t("+ a_1 x"), t("- a_2 y")]], substituted: [], result: [] };
    assert.deepEqual(texts(planFormula(formulaSource({ parts: [r] }, "symbolic"))), [[[String.raw`Z \approx a_0`, "+ a_1 x", "- a_2 y"]]]);
  });

  it("two relations are two groups; a relation with nothing on a side is left out of it", () => {
    const a = { key: "a", lhs: [t("a")], op: "=", symbolic: [[t("b + c")]], substituted: [[t("1 + 2")]], result: [[t("3")]] };
    const b = { key: "b", lhs: [t("d")], op: "<", symbolic: [], substituted: [], result: [[t("4")]] };
    const sym = planFormula(formulaSource({ parts: [a, b] }, "symbolic"));
    assert.deepEqual(texts(sym), [[["a = b + c"]]]);
    const sub = planFormula(formulaSource({ parts: [a, b] }, "substituted"));
    assert.deepEqual(texts(sub), [[["a = 1 + 2"], ["= 3"]], [["d < 4"]]]);
    assert.deepEqual(
      sub.groups.map((g) => g.key),
      ["a", "b"],
    );
  });

  it("a bare expression (no left-hand side) and practice's question (the result as ?)", () => {
    const r = { key: "k", lhs: [], op: "=", symbolic: [[t("x + y")]], substituted: [[t("1 + 2")]], result: [[t("3")]] };
    assert.deepEqual(texts(planFormula(formulaSource({ parts: [r] }, "symbolic"))), [[["x + y"]]]);
    assert.deepEqual(texts(planFormula({ tex: "", relations: [GSD], side: "question" })), [[[String.raw`\text{GSD} = 0.028 \times 9047`], [String.raw`= \;?`]]]);
  });

  it("a matrix is a term of its own, named by its grid or by the left-hand side it equals", () => {
    const n = { key: "N", lhs: [t("N")], op: "=", symbolic: [[t(String.raw`A^\mathsf{T} A`)]], substituted: [[grid("bmatrix", [["1", "2"], ["3", "4"]])]], result: [] };
    const plan = planFormula(formulaSource({ parts: [n] }, "substituted"));
    assert.deepEqual(texts(plan), [[["N =|2x2"]]]);
    assert.equal(plan.groups[0].items[0].terms[0].name, "N");
    // "A X = L + V": the matrices keep their own names, the equation flows on after them
    const axl = {
      key: null,
      lhs: [grid("bmatrix", [["1", "0"], ["0", "1"]], "A"), grid("bmatrix", [["a"], ["b"]], "X")],
      op: "=",
      symbolic: [],
      substituted: [[grid("bmatrix", [["5"], ["6"]], "L"), t("+ V")]],
      result: [],
    };
    const p2 = planFormula(formulaSource({ parts: [axl] }, "substituted"));
    assert.deepEqual(texts(p2), [[["|2x2", "|2x1", "=|2x1", "+ V"]]]);
    assert.deepEqual(
      p2.groups[0].items[0].terms.map((x) => x.name ?? null),
      ["A", "X", "L", null],
    );
  });

  it("a step without parts is one block, unsplit", () => {
    const step = { formula: String.raw`a = b,\quad c = d`, substituted: "", parts: [] };
    assert.deepEqual(planFormula(formulaSource(step, "symbolic")), { whole: String.raw`a = b,\quad c = d` });
  });
});

describe("grids: blocks of columns with captions, long ones shortened", () => {
  const a = { env: "bmatrix", rows: [["1", "2", "3", "4", "5"], ["6", "7", "8", "9", "10"]], name: "A" };
  it("a matrix in blocks of at most `per` columns, every cell once", () => {
    const blocks = gridBlocks(a, 2);
    assert.deepEqual(
      blocks.map((b) => [b.from, b.to, b.of]),
      [
        [1, 2, 5],
        [3, 4, 5],
        [5, 5, 5],
      ],
    );
    assert.deepEqual(blocks[1].rows, [["3", "4"], ["8", "9"]]);
    assert.deepEqual(
      blocks.map((b) => blockCaption("A", b)),
      ["A, columns 1–2 of 5", "A, columns 3–4 of 5", "A, column 5 of 5"],
    );
    assert.equal(blockCaption(null, blocks[0]), "columns 1–2 of 5");
  });
  it("a table keeps its first column in every block", () => {
    const table = { env: "array", rows: [["", "x", "y", "z"], ["p", "1", "2", "3"]], name: null };
    const blocks = gridBlocks(table, 2);
    assert.deepEqual(
      blocks.map((b) => b.rows),
      [
        [["", "x", "y"], ["p", "1", "2"]],
        [["", "z"], ["p", "3"]],
      ],
    );
    assert.deepEqual(
      blocks.map((b) => [b.from, b.to, b.of]),
      [
        [2, 3, 4],
        [4, 4, 4],
      ],
    );
    assert.deepEqual(tableRowLines(table), [["p{:}", "x = 1,", "y = 2,", "z = 3"]]);
  });
  it("the matrix's LaTeX is put together from its cells (never read back)", () => {
    assert.equal(gridTex(a, [["1"], ["6"]]), String.raw`\begin{bmatrix} 1 \\ 6 \end{bmatrix}`);
    assert.equal(gridTex({ env: "array", rows: [["a", "b"]] }), String.raw`\begin{array}{rr} a & b \end{array}`);
    assert.equal(gridTermTex({ grid: a, lead: "N =" }, [["1"]]), String.raw`N = \begin{bmatrix} 1 \end{bmatrix}`);
  });
  it("more than 12 rows: the first 8 and a row of dots, with the count", () => {
    const tall = { env: "bmatrix", rows: Array.from({ length: 20 }, (_, i) => [String(i), "0"]) };
    const short = shortGrid(tall);
    assert.equal(short.count, 20);
    assert.equal(short.rows.length, 9);
    assert.deepEqual(short.rows[8], [String.raw`\vdots`, String.raw`\vdots`]);
    assert.equal(shortGrid(a), null);
  });
});

describe("no LaTeX reader in www/", () => {
  it("the formula modules take no LaTeX apart (no \\begin / \\frac / \\\\ patterns matched against formulas)", () => {
    for (const file of ["www/formula-plan.js", "www/math-typeset.js", "www/math.js"]) {
      const code = fs.readFileSync(new URL(`../../${file}`, import.meta.url), "utf8");
      // a regular expression literal or RegExp that looks for LaTeX commands or environments
      assert.doesNotMatch(code, /\/[^/\n]*\\\\(begin|end|frac|sqrt|left|right|text|quad|approx)[^/\n]*\/[gimsuy]*[.)]/, file);
      assert.doesNotMatch(code, /new RegExp\([^)]*\\\\/, file);
      assert.doesNotMatch(code, /\b(splitFormula|splitTerms|findGrid|plainTex|skeleton|gridNames)\b/, file);
    }
  });
});
