// Where formulas may break (www/math.js), in Node: the splitting is pure
// string work; the page lays the pieces out and fits them to the width.
import { describe, it } from "node:test";
import assert from "node:assert/strict";
import { blockCaption, findGrid, gridBlocks, gridContext, gridNames, splitFormula, splitTerms } from "../../www/math-typeset.js"; // loaded with KaTeX (www/math.js)

describe("splitFormula: groups and relation chains", () => {
  it("the left-hand side stays with the first relation; the result is a piece of its own", () => {
    assert.deepEqual(splitFormula(String.raw`\text{GSD} = p \cdot m = 356\ \text{mm} = 35.6\ \text{cm}`), [
      [String.raw`\text{GSD} = p \cdot m`, String.raw`= 356\ \text{mm}`, String.raw`= 35.6\ \text{cm}`],
    ]);
  });
  it("\\quad and ',\\ ' between equations start groups; a comma inside parentheses does not", () => {
    const g = splitFormula(String.raw`a_1 = b_1 - b_3,\ a_2 = b_2,\quad P = (1,\ 2)`);
    assert.equal(g.length, 3);
    assert.deepEqual(g[2], [String.raw`P = (1,\ 2)`]);
  });
  it("unbalanced braces leave the formula whole", () => {
    assert.deepEqual(splitFormula("x = {a"), [["x = {a"]]);
  });
});

describe("splitTerms: sums, lists and rows", () => {
  it("a written-out sum breaks before each binary + or −, not inside parentheses, not at a sign", () => {
    const { lines } = splitTerms("= (48 - 58.7)(52 - 59.1) + (50 - 58.7)(37 - 59.1) - 3 = 1149.2");
    assert.deepEqual(lines, [["= (48 - 58.7)(52 - 59.1)", "+ (50 - 58.7)(37 - 59.1)", "- 3", "= 1149.2"]]);
    assert.deepEqual(splitTerms("-113.002 + v_{1}").lines, [["-113.002", "+ v_{1}"]]);
    assert.deepEqual(splitTerms("= -0.5").lines, [["= -0.5"]]);
  });
  it("the items of a bracketed list and \\; sequences", () => {
    assert.deepEqual(splitTerms(String.raw`V = [-0.01,\ 0.03,\ -0.02]`).lines, [[String.raw`V = [-0.01,`, "0.03,", "-0.02]"]]);
    assert.deepEqual(splitTerms(String.raw`d = 7\;0\;(-1)`).lines, [["d = 7", "0", "(-1)"]]);
  });
  it("a gathered block gives one line per row; a second relation in a row may break", () => {
    const { lines } = splitTerms(String.raw`\begin{gathered}\sigma_a = 0.0099 \sqrt{0.1} = 0.003 \\ \Delta(1) = (1,0),\ \Delta(2) = (1,-1)\end{gathered}`);
    assert.deepEqual(lines, [[String.raw`\sigma_a = 0.0099 \sqrt{0.1}`, "= 0.003"], [String.raw`\Delta(1) = (1,0),`, String.raw`\Delta(2) = (1,-1)`]]);
  });
  it("a long product breaks before each × or ·", () => {
    assert.deepEqual(splitTerms(String.raw`= 0.9996 \times 6\,367\,449.1 \times 0.0254`).lines, [["= 0.9996", String.raw`\times 6\,367\,449.1`, String.raw`\times 0.0254`]]);
  });
  it("factors set apart by a thin space break; digit groups do not", () => {
    assert.deepEqual(splitTerms(String.raw`= \sqrt{a}\,\sqrt{b} \times 6\,367`).lines, [[String.raw`= \sqrt{a}`, String.raw`\sqrt{b}`, String.raw`\times 6\,367`]]);
  });
  it("nothing breaks inside a fraction or a root", () => {
    assert.deepEqual(splitTerms(String.raw`\rho = \frac{a + b}{\sqrt{c + d}}`).lines, [[String.raw`\rho = \frac{a + b}{\sqrt{c + d}}`]]);
  });
});

describe("grids: matrices and tables in blocks of columns", () => {
  const matrix = String.raw`N = \begin{bmatrix} 1 & 2 & 3 \\ 4 & 5 & 6 \end{bmatrix},`;
  it("findGrid keeps what stands before and after", () => {
    const g = findGrid(matrix);
    assert.equal(g.before, "N = ");
    assert.equal(g.after, ",");
    assert.equal(g.env, "bmatrix");
  });
  it("a matrix in blocks of two columns: every number kept once", () => {
    const blocks = gridBlocks(findGrid(matrix), 2);
    assert.deepEqual(
      blocks.map((b) => [b.from, b.to, b.of]),
      [
        [1, 2, 3],
        [3, 3, 3],
      ],
    );
    assert.match(blocks[0].tex, /1 & 2 \\\\ 4 & 5/);
    assert.match(blocks[1].tex, /3 \\\\ 6/);
  });
  it("a table keeps its first column and its rules in every block", () => {
    const table = String.raw`\begin{array}{c|rr|rr} k & a & b & c & d \\ \hline 1 & 10 & 20 & 30 & 40 \end{array}`;
    const blocks = gridBlocks(findGrid(table), 2);
    assert.equal(blocks.length, 2);
    assert.match(blocks[1].tex, /^\\begin\{array\}\{c\|rr\} k & c & d \\\\ \\hline 1 & 30 & 40/);
  });
});

describe("a split matrix keeps its name and its equation (issue 29)", () => {
  const substituted = String.raw`\begin{bmatrix} 48.15 & 2699.98 & 1 & 0 \\ -2699.98 & 48.15 & 0 & 1 \end{bmatrix}\,\begin{bmatrix} a \\ b \\ c \\ d \end{bmatrix} = \begin{bmatrix} -113.002 \\ 0.008 \end{bmatrix} + V`;
  it("gridNames reads the matrices' names from the symbolic formula with the same operators", () => {
    assert.deepEqual(gridNames(String.raw`A\,X = L + V`, substituted), ["A", "X", "L"]);
    // another shape: no names
    assert.deepEqual(gridNames(String.raw`A\,X = L`, substituted), [null, null, null]);
    assert.deepEqual(gridNames(String.raw`N = A^\mathsf{T} A`, String.raw`N = \begin{bmatrix} 1 & 2 \end{bmatrix}`), [null]);
  });
  it("N = […], the name before the matrix and punctuation after stay on its first and last blocks", () => {
    const c = gridContext(findGrid(String.raw`\small N = \begin{bmatrix} 1 & 2 & 3 \end{bmatrix},`));
    assert.deepEqual(c, { size: String.raw`\small `, lead: String.raw`\small N = `, trail: ",", name: "N", rest: null });
  });
  it("A X: the blocks are A alone, and the product is written again after the whole matrix", () => {
    const term = String.raw`\begin{bmatrix} 1 & 2 \end{bmatrix}\,\begin{bmatrix} a \\ b \end{bmatrix}`;
    const c = gridContext(findGrid(term), "A");
    assert.equal(c.lead, "");
    assert.equal(c.trail, "");
    assert.equal(c.rest, String.raw`A\,\begin{bmatrix} a \\ b \end{bmatrix}`);
    // without a name, a word stands for the matrix
    assert.match(gridContext(findGrid(term), null).rest, /^\\left\[\\,\\text\{matrix above\}/);
  });
  it("each block's caption names the matrix", () => {
    assert.equal(blockCaption("A", { from: 1, to: 3, of: 4 }), "A, columns 1–3 of 4");
    assert.equal(blockCaption(String.raw`A^\mathsf{T}`, { from: 4, to: 4, of: 4 }), "Aᵀ, column 4 of 4");
    assert.equal(blockCaption(null, { from: 2, to: 3, of: 5 }), "columns 2–3 of 5");
  });
});
