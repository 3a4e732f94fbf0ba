// Least-squares matching on the page: the three examples draw their figures,
// the iteration slider steps through the record, every end status shows,
// and a bad input is reported without breaking the page.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import { TEST_TIMEOUT, open, start, visit } from "./harness.mjs";

let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

function canvases(page) {
  return page.evaluate(() =>
    [...document.querySelectorAll(".figure-canvas")].map((c) => {
      const data = c.getContext("2d").getImageData(0, 0, c.width, c.height).data;
      let ink = 0;
      for (let i = 0; i < data.length; i += 4) if (data[i] < 240 || data[i + 1] < 240 || data[i + 2] < 240) ink += 1;
      return { ink, pixels: c.width * c.height, label: c.getAttribute("aria-label") };
    }),
  );
}

describe("least-squares matching", () => {
  test("each example draws two labelled figures", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      const expect = {
        "lsm-1d": ["iteration 1 of 13", "c = 7.77"],
        "lsm-2d": ["3×3 pixel grids", "iteration 1 of 11", "converged"],
        "lsm-affine": ["21×21 pixel grids", "a7 (gain) ends at 1.2"],
      };
      for (const [id, words] of Object.entries(expect)) {
        assert.equal(await visit(page, env.url, "index.html", `#/${id}`), "ok", id);
        const figs = await canvases(page);
        assert.equal(figs.length, 2, id);
        for (const f of figs) assert.ok(f.ink > f.pixels * 0.02, `${id}: drawn`);
        const labels = figs.map((f) => f.label).join(" | ");
        for (const w of words) assert.ok(labels.includes(w), `${id}: ${w} in ${labels}`);
      }
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("the slider steps through the iterations, by keyboard too", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/lsm-1d"), "ok");
      const slider = page.locator(".figure-slider input").first();
      assert.equal(await slider.getAttribute("max"), "13");
      await slider.focus();
      await page.keyboard.press("ArrowRight");
      await page.keyboard.press("ArrowRight");
      const [fig] = await canvases(page);
      assert.ok(fig.label.includes("iteration 3 of 13"), fig.label);
      assert.ok(fig.label.includes("c = 7.8073"), fig.label);
      assert.ok((await page.locator(".figure-slider span").first().textContent()).includes("Iteration 3 of 13"));
      // a new solution keeps a valid slider position and takes the new range
      assert.equal(await visit(page, env.url, "index.html", "#/lsm-1d?radiometric=true"), "ok");
      assert.equal(await page.locator(".figure-slider input").first().getAttribute("max"), "7");
    } finally {
      await context.close();
    }
  });

  test("not converged, left window and degenerate runs say so", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      const cases = [
        ["#/lsm-2d?gradients=patch-edge&max_iterations=30", "Not converged within the limit of 30"],
        ["#/lsm-affine?shift_c=6&shift_r=0", "outside the search window"],
        ["#/lsm-1d?search=5,5,5,5,5,5,5,5,5,5,5,5", "flat"],
      ];
      for (const [hash, words] of cases) {
        assert.equal(await visit(page, env.url, "index.html", hash), "ok", hash);
        const body = await page.locator("main").textContent();
        assert.ok(body.includes(words), `${hash}: ${words}`);
      }
      // a bad input: the field's message, and the page keeps working
      const st = await visit(page, env.url, "index.html", "#/lsm-2d?gradients=sobel");
      assert.equal(st, "invalid");
      assert.ok((await page.locator("main").textContent()).includes("is not one of the choices"));
      assert.equal(await visit(page, env.url, "index.html", "#/lsm-2d"), "ok");
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });
});
