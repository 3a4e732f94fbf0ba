// End-to-end: a matrix too wide for a phone, shown as blocks of columns,
// keeps its name and its equation (issue 29, item 8). Each block is captioned
// with the matrix's name ("A, columns 1–4 of 6"); what the equation says
// around the matrix ("A X = L + V": X, "= L + V") comes after the whole
// matrix, never glued to its last block; an equation around a small matrix
// ("[a1 a2; a4 a5] = […]") wraps at its relation instead of splitting the
// matrix; nothing is cut. The layout comes from the steps' parts (grids as
// rows of cells, named by the core): www/formula-plan.js.

import assert from "node:assert/strict";
import { after, before, describe, test } from "node:test";
import { TEST_TIMEOUT, open, readSteps, start, visit } from "./harness.mjs";

/** Every split matrix of the page, and every formula term cut at its right edge. */
async function splits(page) {
  return page.evaluate(() => {
    const blocks = [...document.querySelectorAll(".steps .formula-blocks")].map((node) => {
      const own = [...node.children].filter((c) => c.classList.contains("formula-block"));
      const last = own.at(-1);
      const rest = [...node.children].find((c) => c.classList.contains("formula-blocks-rest"));
      // the first term after the whole matrix, in reading order (the rest line, or the next term of the line)
      const terms = [...node.closest(".formula").querySelectorAll(".formula-term")];
      const lastTerm = last.querySelector(".formula-term");
      const next = terms[terms.indexOf(lastTerm) + 1] ?? null;
      return {
        formula: node.closest(".formula").dataset.tex.slice(0, 80),
        // the caption as plain text (data-caption: its matrix name typeset, with MathML, in the caption itself)
        captions: own.map((b) => b.querySelector(".formula-block-caption").dataset.caption),
        firstTex: own[0].querySelector(".formula-term").dataset.tex,
        lastTex: lastTerm.dataset.tex,
        lastBottom: last.getBoundingClientRect().bottom,
        rest: rest ? { tex: rest.textContent ? [...rest.querySelectorAll(".formula-term")].map((t) => t.dataset.tex).join(" ") : "", top: rest.getBoundingClientRect().top } : null,
        next: next ? { tex: next.dataset.tex, top: next.getBoundingClientRect().top, after: Boolean(lastTerm.compareDocumentPosition(next) & Node.DOCUMENT_POSITION_FOLLOWING) } : null,
      };
    });
    const cut = [...document.querySelectorAll(".steps .formula-term")].filter((t) => t.clientWidth > 0 && t.scrollWidth > t.clientWidth + 1).map((t) => t.dataset.tex.slice(0, 60));
    return { blocks, cut };
  });
}

/** The matrix (a grid) and what may stand on its last block after it: nothing but punctuation. */
const ENDS_WITH_MATRIX = /\\end\{(?:[a-zA-Z]*matrix|array)\}\s*[,.;]?\s*$/;

function assertSplits({ blocks, cut }, where) {
  assert.deepEqual(cut, [], `${where}: formulas cut`);
  for (const b of blocks) {
    // a matrix's blocks carry its name (a table's keep its first column instead)
    const matrix = /\\begin\{[a-zA-Z]*matrix\}/.test(b.firstTex);
    for (const c of b.captions) assert.match(c, matrix ? /^[A-Za-z][A-Za-z0-9_ᵀ]*, columns? \d+(–\d+)? of \d+$/ : /^columns? \d+(–\d+)? of \d+$/, `${where}: a block of ${b.formula}: "${c}"`);
    assert.match(b.lastTex, ENDS_WITH_MATRIX, `${where}: the equation goes on right after the last block of ${b.formula}: ${b.lastTex.slice(-80)}`);
    if (b.next) {
      assert.ok(b.next.after, `${where}: ${b.next.tex} is not after the matrix in reading order`);
      assert.ok(b.next.top >= b.lastBottom - 2, `${where}: ${b.next.tex.slice(0, 40)} (top ${b.next.top}) sits beside the last block (bottom ${b.lastBottom}), not after the whole matrix`);
    }
  }
}

describe("split matrices keep their names and their equations (390 px)", { timeout: 6 * TEST_TIMEOUT }, () => {
  let env;
  before(async () => {
    env = await start();
  });
  after(async () => {
    await env?.close();
  });

  test("fiducial-similarity and fiducial-affine: A X = L + V reads on after the whole of A", { timeout: 2 * TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser, { viewport: { width: 390, height: 900 } });
    try {
      for (const id of ["fiducial-similarity", "fiducial-affine"]) {
        assert.equal(await visit(page, env.url, "index.html", `#/${id}`), "ok");
        await readSteps(page);
        const s = await splits(page);
        assertSplits(s, id);
        // the design-matrix step: "=" and L after the whole A (and X), never beside a block of A
        const order = await page.evaluate(() => {
          const f = [...document.querySelectorAll(".formula-substituted")].find((x) => x.dataset.tex.includes("+ V"));
          const terms = [...f.querySelectorAll(".formula-term")];
          const a = terms.filter((t) => /2699\.98/.test(t.dataset.tex) && !t.dataset.tex.trim().startsWith("="));
          const eq = terms.find((t) => t.dataset.tex.trim().startsWith("="));
          return { aBottom: Math.max(...a.map((t) => t.getBoundingClientRect().bottom)), eqTop: eq.getBoundingClientRect().top, eq: eq.dataset.tex.slice(0, 30), captions: [...f.querySelectorAll(".formula-block-caption")].map((c) => c.dataset.caption) };
        });
        assert.ok(order.eqTop >= order.aBottom - 2, `${id}: "${order.eq}" (top ${order.eqTop}) is beside A (bottom ${order.aBottom})`);
        if (id === "fiducial-affine") assert.deepEqual(order.captions.map((c) => c.split(",")[0]), order.captions.map(() => "A"), `A (8×6) in named blocks: ${order.captions}`);
      }
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("lsm-affine: [a1 a2; a4 a5] = […] wraps at its relation, the 2×2 matrix whole", { timeout: 2 * TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser, { viewport: { width: 390, height: 900 } });
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/lsm-affine"), "ok");
      await readSteps(page);
      const s = await splits(page);
      assertSplits(s, "lsm-affine");
      const first = await page.evaluate(() => {
        const f = document.querySelector("#step-1 .formula-substituted");
        const terms = [...f.querySelectorAll(".formula-term")];
        const lhs = terms.find((t) => t.dataset.tex.includes("a_1 & a_2"));
        const rhs = terms.find((t) => t.dataset.tex.trim().startsWith("="));
        return {
          split: f.querySelectorAll(".formula-block").length,
          lhs: lhs?.dataset.tex ?? null,
          rhsAfter: Boolean(lhs && rhs && lhs.compareDocumentPosition(rhs) & Node.DOCUMENT_POSITION_FOLLOWING),
        };
      });
      assert.equal(first.split, 0, "the 2×2 matrix is not split into columns");
      assert.match(first.lhs ?? "", /^\\begin\{bmatrix\} a_1 & a_2 \\\\ a_4 & a_5 \\end\{bmatrix\}$/);
      assert.ok(first.rhsAfter, "= […] follows the whole left-hand side");
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });
});
