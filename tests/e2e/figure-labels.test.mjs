// End-to-end: the labels that figures place with the shared helper
// (Labels in www/figures/draw.js) never overlap one another, stay inside
// their canvas and cover none of the marks the figure registered (dots,
// bars, arrows, lines, other texts), on a phone (390 px) and on a desktop
// (1280 px). The helper records the boxes it placed on the canvas as JSON in
// data-label-boxes ({ text, x, y, w, h, hits } in CSS px; hits = how many
// registered marks the box covers).

import assert from "node:assert/strict";
import { after, before, describe, test } from "node:test";
import { TEST_TIMEOUT, open, settled, start, visit } from "./harness.mjs";

const WIDTHS = [390, 1280];

/** The five figures of issue 13 and texts each must show. */
const FIGURES = {
  "ncc-1d": [/^best$/, /^0\.98$/, /^−0\.49$/, /^−0\.59$/],
  "ncc-2d": [/^product > 0$/, /^product < 0$/],
  resample: [/0\.426$/, /0\.334$/, /0\.134$/, /0\.106$/, /^I₁$/, /^I₂$/],
  "boundary-shape": [/^m ?= ?5\.488$/, /^D ?= ?11\.66$/, /^start$/],
  "moravec-window": [/^mean of the sums = 183$/, /^27$/, /^9$/, /^14$/, /^15$/],
};

/** Every figure canvas of the page with its size and the label boxes recorded on it. */
async function labelBoxes(page) {
  await page.waitForFunction(() => [...document.querySelectorAll(".figure-canvas")].some((c) => c.dataset.labelBoxes), null, { timeout: 15_000 });
  return page.evaluate(() =>
    [...document.querySelectorAll(".figure-canvas")].map((c) => ({
      w: c.clientWidth,
      h: c.clientHeight,
      label: c.getAttribute("aria-label") ?? "",
      boxes: JSON.parse(c.dataset.labelBoxes || "[]"),
    })),
  );
}

const EPS = 1e-6;
const intersect = (a, b) => a.x < b.x + b.w - EPS && b.x < a.x + a.w - EPS && a.y < b.y + b.h - EPS && b.y < a.y + a.h - EPS;

/**
 * Asserts the recorded boxes are disjoint and inside their canvas, and (with
 * `clear`) that each covers none of the figure's marks.
 */
function assertPlaced(canvases, where, { clear = true } = {}) {
  let count = 0;
  for (const { w, h, boxes } of canvases) {
    count += boxes.length;
    for (const b of boxes) {
      assert.ok(b.x >= -EPS && b.y >= -EPS && b.x + b.w <= w + EPS && b.y + b.h <= h + EPS, `${where}: "${b.text}" ${JSON.stringify(b)} is not inside the ${w}×${h} canvas`);
      if (clear) assert.equal(b.hits, 0, `${where}: "${b.text}" covers ${b.hits} mark(s) of the figure`);
    }
    for (let i = 0; i < boxes.length; i++) {
      for (let j = i + 1; j < boxes.length; j++) {
        assert.ok(!intersect(boxes[i], boxes[j]), `${where}: "${boxes[i].text}" and "${boxes[j].text}" overlap: ${JSON.stringify([boxes[i], boxes[j]])}`);
      }
    }
  }
  assert.ok(count > 0, `${where}: no labels recorded`);
  return canvases.flatMap((c) => c.boxes.map((b) => b.text));
}

let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

describe("figure labels", () => {
  for (const width of WIDTHS) {
    test(`the five figures at ${width} px: no label overlaps another, leaves the canvas or covers a mark`, { timeout: TEST_TIMEOUT * 2 }, async () => {
      const { context, page, log } = await open(env.browser, { viewport: { width, height: 900 } });
      try {
        for (const [id, expected] of Object.entries(FIGURES)) {
          assert.equal(await visit(page, env.url, "index.html", `#/${id}`), "ok", id);
          const canvases = await labelBoxes(page);
          const texts = assertPlaced(canvases, `${id} at ${width} px`);
          for (const re of expected) assert.ok(texts.some((t) => re.test(t)), `${id} at ${width} px: no label ${re} among ${JSON.stringify(texts)}`);
          // the text alternative keeps the numbers
          assert.ok(canvases.every((c) => /\d/.test(c.label)), `${id}: a canvas without numbers in its aria-label`);
        }
        assert.deepEqual(log.pageErrors, []);
        assert.deepEqual(log.consoleErrors, []);
      } finally {
        await context.close();
      }
    });

    test(`other states at ${width} px: every ρ position, other positions and patches, shapes, a large Moravec window`, { timeout: TEST_TIMEOUT * 3 }, async () => {
      const { context, page, log } = await open(env.browser, { viewport: { width, height: 900 } });
      try {
        // ncc-1d: each selected position
        assert.equal(await visit(page, env.url, "index.html", "#/ncc-1d"), "ok");
        const bars = page.locator(".figure-canvas").first();
        await bars.focus();
        await page.keyboard.press("Home");
        for (let k = 1; k <= 6; k++) {
          await page.waitForFunction((n) => (document.querySelector(".figure-status")?.textContent ?? "").startsWith(`Position ${n}`), k);
          assertPlaced(await labelBoxes(page), `ncc-1d position ${k} at ${width} px`);
          await page.keyboard.press("ArrowRight");
        }
        // ncc-2d: a selected pair
        assert.equal(await visit(page, env.url, "index.html", "#/ncc-2d"), "ok");
        await page.locator(".figure-canvas").first().focus();
        await page.keyboard.press("ArrowRight");
        assertPlaced(await labelBoxes(page), `ncc-2d with a pair selected at ${width} px`);
        // resample: positions all over the patch (on a pixel, on a cell's
        // corner, at the patch's edges: there a label may have to touch a
        // line, never another label), and the other patch (with bicubic)
        for (const [c, r, clear] of [
          [545, 817, true],
          [545.5, 817.5, true],
          [546.9, 818.1, true],
          [547.44, 817.24, true],
          [547.5, 819.5, true],
          [548, 820, true],
          [546.05, 819.95, false],
          [545.01, 819.99, false],
        ]) {
          assert.equal(await visit(page, env.url, "index.html", `#/resample?c=${c}&r=${r}`), "ok", `resample ${c}, ${r}`);
          assertPlaced(await labelBoxes(page), `resample at (${c}, ${r}), ${width} px`, { clear });
        }
        await page.getByRole("button", { name: "Example 12b" }).click();
        assert.equal(await settled(page), "ok");
        await page.waitForFunction(() => /c = 523\.72/.test(document.querySelector(".figure-canvas").getAttribute("aria-label")));
        assertPlaced(await labelBoxes(page), `resample, Example 12b at ${width} px`, { clear: false });
        // the boundary shapes (crowded: a digit may have to touch a line, never another label)
        assert.equal(await visit(page, env.url, "index.html", "#/boundary-shape"), "ok");
        for (const name of ["Circle", "Rectangle", "L-shape", "Example 17’s edge"]) {
          const before = await page.locator(".figure-canvas").getAttribute("aria-label");
          await page.getByRole("button", { name }).click();
          assert.equal(await settled(page), "ok", name);
          await page.waitForFunction((b) => document.querySelector(".figure-canvas").getAttribute("aria-label") !== b, before);
          assertPlaced(await labelBoxes(page), `boundary-shape, ${name} at ${width} px`, { clear: name === "Rectangle" });
        }
        // Moravec on an 8×8 window: the overview and one pixel
        assert.equal(await visit(page, env.url, "index.html", "#/moravec-window"), "ok");
        const rows = [];
        for (let r = 0; r < 8; r++) rows.push(Array.from({ length: 8 }, (_, c) => (r === 3 && c === 5 ? 90 : 10 + ((3 * r + 5 * c) % 7))).join(" "));
        await page.getByLabel(/Window of grey values/).fill(rows.join("\n"));
        await page.waitForFunction(() => document.querySelector(".figure-canvas").getAttribute("aria-label").startsWith("36 interior pixels"));
        assertPlaced(await labelBoxes(page), `moravec-window 8×8 at ${width} px`);
        assert.deepEqual(log.pageErrors, []);
        assert.deepEqual(log.consoleErrors, []);
      } finally {
        await context.close();
      }
    });
  }
});
