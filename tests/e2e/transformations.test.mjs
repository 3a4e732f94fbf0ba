// The transformation examples in the page: Example 4 with its printed values,
// the point table of transform-fit edited (parameters and residual vectors
// follow), the model and prepared point sets, picking a point in the figure,
// and bad point lists reported beside the field.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import { TEST_TIMEOUT, open, settled, start, visit } from "./harness.mjs";

let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

/** The exact value (JSON in data-value) of a result row. */
async function resultValue(page, key) {
  const cell = page.locator(`.result-table tr[data-key="${key}"] td.exact`);
  return JSON.parse(await cell.getAttribute("data-value"));
}

/** Pixels of the first figure canvas, to tell whether it changed. */
function canvasPixels(page, index = 0) {
  return page.evaluate((i) => {
    const c = document.querySelectorAll(".figure-canvas")[i];
    return c.toDataURL();
  }, index);
}

describe("transformations", () => {
  test("Example 4 (a) and (b): exact parameters, printed values, notes, two figures", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/fiducial-similarity"), "ok");
      const x = await resultValue(page, "parameters");
      assert.ok(Math.abs(x[0] - 0.0426001093) < 1e-9, `a = ${x[0]}`);
      assert.ok(Math.abs(x[2] + 115.0347815) < 1e-6, `c = ${x[2]}`);
      const v = await resultValue(page, "residuals");
      assert.equal(v.length, 8);
      assert.ok(Math.abs(v[4] + 0.0137517) < 1e-6);
      const printed = JSON.parse(await page.locator('.result-table tr[data-key="parameters"] td.printed').getAttribute("data-value"));
      assert.deepEqual(printed, [0.043, 0, -115.03, 115.04]);
      const notes = await page.locator(".notes").innerText();
      assert.ok(notes.includes("y′ = −r"), "the axis note");
      assert.ok(notes.includes("two decimals"), "the rounding note");
      assert.equal(await page.locator(".formula-raw, .formula-error").count(), 0, "every formula renders");
      const canvases = await page.locator(".figure-canvas").count();
      assert.equal(canvases, 2, "points and rows figures");
      const label = await page.locator(".figure-canvas").first().getAttribute("aria-label");
      assert.ok(label.includes("4 control points") && label.includes("similarity"), label);

      assert.equal(await visit(page, env.url, "index.html", "#/fiducial-affine"), "ok");
      const xa = await resultValue(page, "parameters");
      assert.ok(Math.abs(xa[4] - 0.0425999786) < 1e-9);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("transform-fit: editing a point changes the parameters and the residual vectors", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/transform-fit?model=affine"), "ok");
      const before = await resultValue(page, "parameters");
      const vBefore = await resultValue(page, "point_residuals");
      const figBefore = await canvasPixels(page);
      const area = page.locator('.field[data-key="points"] textarea');
      const text = await area.inputValue();
      const lines = text.split("\n");
      lines[3] = "2700.56, -5352.74, -0.016, -112.9"; // y of fiducial 4 moved by 0.1 mm
      lines.push("1000, -1000, -72.4, 72.4"); // and a fifth point added
      await area.fill(lines.join("\n"));
      await page.waitForFunction((b) => {
        const cell = document.querySelector('.result-table tr[data-key="parameters"] td.exact');
        return cell && cell.dataset.value !== JSON.stringify(b);
      }, before);
      assert.equal(await settled(page), "ok");
      const after = await resultValue(page, "parameters");
      assert.notDeepEqual(after, before);
      const vAfter = await resultValue(page, "point_residuals");
      assert.equal(vAfter.length, 5, "five points now");
      assert.ok(Math.abs(vAfter[3][1]) > Math.abs(vBefore[3][1]) + 0.01, `residual of point 4: ${vAfter[3][1]}`);
      assert.equal(await resultValue(page, "redundancy"), 4);
      assert.notEqual(await canvasPixels(page), figBefore, "the figure was redrawn");
      const hash = await page.evaluate(() => location.hash);
      assert.ok(hash.includes("points=") && hash.includes("1000"), hash);
      // removing points until too few: the message says how many more
      await area.fill(lines.slice(0, 2).join("\n"));
      assert.equal(await settled(page), "error");
      const message = await page.locator(".error-box").innerText();
      assert.ok(message.includes("needs at least 3 points; 2 given (1 more needed)"), message);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("the point table: change a cell, add a point, remove one; the text follows and the table follows the text", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/transform-fit?model=affine"), "ok");
      const table = page.locator('.field[data-key="points"] .points-table tbody');
      const area = page.locator('.field[data-key="points"] textarea');
      assert.equal(await table.locator("tr").count(), 4);
      const before = await resultValue(page, "parameters");
      // y of point 4 moved by 0.1 mm, in its cell
      const cell = page.getByLabel("Point 4, y");
      assert.equal(await cell.inputValue(), "-113");
      await cell.fill("-112.9");
      assert.equal(await settled(page), "ok");
      assert.equal((await area.inputValue()).split("\n")[3], "2700.56 -5352.74 -0.016 -112.9");
      assert.notDeepEqual(await resultValue(page, "parameters"), before);
      assert.match(await page.evaluate(() => location.hash), /112\.9/);
      // a new point: an empty row, then its four numbers
      await page.getByRole("button", { name: "+ Add point" }).click();
      assert.equal(await table.locator("tr").count(), 5);
      await page.getByLabel("Point 5, u").fill("1000");
      assert.equal(await settled(page), "invalid"); // a point with one number is not a point yet
      assert.equal(await page.locator('.field[data-key="points"] .field-error').innerText(), "point 5 has 1 number; each point needs 4");
      await page.getByLabel("Point 5, v").fill("-1000");
      await page.getByLabel("Point 5, x").fill("-72.4");
      await page.getByLabel("Point 5, y").fill("72.4");
      assert.equal(await settled(page), "ok");
      assert.equal(await resultValue(page, "redundancy"), 4);
      assert.equal((await area.inputValue()).split("\n").length, 5);
      // remove point 1: four points, renumbered
      await page.getByRole("button", { name: "Remove point 1" }).click();
      assert.equal(await settled(page), "ok");
      assert.equal(await table.locator("tr").count(), 4);
      assert.equal(await resultValue(page, "redundancy"), 2);
      assert.equal(await page.getByLabel("Point 1, u").inputValue(), "5353.12");
      // the text rebuilds the table
      await area.fill("0 0 0 0\n1 0 2 0\n0 1 0 2");
      assert.equal(await settled(page), "ok");
      assert.equal(await table.locator("tr").count(), 3);
      assert.equal(await page.getByLabel("Point 2, x").inputValue(), "2");
      assert.deepEqual(log.pageErrors, []);
      assert.deepEqual(log.consoleErrors, []);
    } finally {
      await context.close();
    }
  });

  test("models and prepared point sets; a bad row is reported beside the field", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/transform-fit?model=polynomial-3"), "error");
      assert.ok((await page.locator(".error-box").innerText()).includes("control-12"));
      await page.locator('.field[data-key="point_set"] select').selectOption("control-12");
      assert.equal(await settled(page), "ok");
      assert.equal(await resultValue(page, "redundancy"), 4);
      for (const model of ["helmert", "affine", "pseudo-affine", "projective", "conformal-2", "polynomial-2"]) {
        await page.locator('.field[data-key="model"] select').selectOption(model);
        await page.waitForFunction((m) => document.querySelector('.result-table tr[data-key="model"] td.exact')?.innerText.includes(m), model);
        assert.equal(await settled(page), "ok", model);
        if (model === "projective") {
          const notes = await page.locator(".notes").innerText();
          assert.ok(notes.includes("a7·u + a8·v + 1"), "the projective erratum");
        }
      }

      await page.locator('.field[data-key="point_set"] select').selectOption("table");
      await page.locator('.field[data-key="points"] textarea').fill("1 2 3 4\n5 6 7");
      assert.equal(await settled(page), "invalid");
      const err = await page.locator('.field[data-key="points"] .field-error').innerText();
      assert.equal(err, "point 2 has 3 numbers; each point needs 4");
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("picking a point with the keyboard highlights it in both figures", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/fiducial-similarity"), "ok");
      const rowsBefore = await canvasPixels(page, 1);
      const fig = page.locator(".figure-canvas").first();
      await fig.focus();
      await page.keyboard.press("ArrowRight");
      await page.keyboard.press("ArrowRight");
      const label = await fig.getAttribute("aria-label");
      assert.ok(label.includes("Point 2:") && label.includes("rows 3 and 4"), label);
      const rows = page.locator(".figure-canvas").nth(1);
      assert.ok((await rows.getAttribute("aria-label")).includes("Point 2: row 3 is [5353.1"), await rows.getAttribute("aria-label"));
      assert.notEqual(await canvasPixels(page, 1), rowsBefore, "the rows figure highlights");
      await page.keyboard.press("Escape");
      assert.ok(!(await fig.getAttribute("aria-label")).includes("Point 2:"));
      // hovering a point picks it too (its position from the figure's own layout), leaving lets it go
      await fig.scrollIntoViewIfNeeded();
      const box = await fig.boundingBox();
      const [px, py] = await page.evaluate(async () => {
        const { loadCore } = await import("./core.js");
        const { pointPosition } = await import("./figures/transformations.js");
        const core = await loadCore();
        const solution = core.solve("fiducial-similarity", {});
        return pointPosition(document.querySelector(".figure-canvas").clientWidth, solution, 2);
      });
      await page.mouse.move(box.x + px, box.y + py);
      await page.waitForFunction(() => document.querySelector(".figure-canvas").getAttribute("aria-label").includes("Point 3:"));
      assert.ok((await rows.getAttribute("aria-label")).includes("Point 3: row 5 is"), await rows.getAttribute("aria-label"));
      await page.mouse.move(2, 2);
      await page.waitForFunction(() => !document.querySelector(".figure-canvas").getAttribute("aria-label").includes("Point 3:"));
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });
});
