// Resampling, filters and edges on the page: Examples 12a, 15 and 16 with the
// printed values beside the exact ones, the figures drawn and described, the
// figures' interaction (select a pixel, drag the position), and bad inputs
// reported beside the field.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import { TEST_TIMEOUT, exact, open, settled, start, visit } from "./harness.mjs";

let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

/** Each figure canvas: its label and how many pixels are not white. */
function canvases(page) {
  return page.evaluate(() =>
    [...document.querySelectorAll(".figure-canvas")].map((c) => {
      const data = c.getContext("2d").getImageData(0, 0, c.width, c.height).data;
      let ink = 0;
      for (let i = 0; i < data.length; i += 4) if (data[i] < 240 || data[i + 1] < 240 || data[i + 2] < 240) ink += 1;
      return { label: c.getAttribute("aria-label"), ink, pixels: c.width * c.height };
    }),
  );
}

const inputValue = (page, key) => page.locator(`[name="${key}"]`).inputValue();

describe("resampling, filters and edges", () => {
  test("Example 12a: nearest and bilinear beside the printed values; drag the position", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/resample"), "ok");
      assert.equal(await exact(page, "nearest"), 72);
      assert.ok(Math.abs((await exact(page, "bilinear")) - 75.3584) < 1e-9);
      const printed = page.locator('.result-table tr[data-key="bilinear"] td.printed');
      assert.equal(Number(await printed.getAttribute("data-value")), 75.35);
      const notes = await page.locator(".notes .note").allInnerTexts();
      assert.ok(notes.some((n) => /cut off, not rounded/.test(n)));
      assert.ok(notes.some((n) => /No bicubic value/.test(n)));
      assert.equal(await page.locator(".formula-raw, .formula-error").count(), 0);
      const [fig] = await canvases(page);
      assert.ok(fig.ink > fig.pixels * 0.05, "the patch is drawn");
      assert.match(fig.label, /4×4 patch; position c = 547\.44, r = 817\.24/);
      // drag the position into the middle of the patch: bicubic appears
      const canvas = page.locator(".figure-canvas");
      const box = await canvas.boundingBox();
      await page.mouse.move(box.x + box.width * 0.3, box.y + box.height * 0.3);
      await page.mouse.down();
      await page.mouse.move(box.x + box.width * 0.32, box.y + box.height * 0.32);
      await page.mouse.up();
      await settled(page);
      assert.notEqual(await inputValue(page, "c"), "547.44");
      assert.match(page.url(), /[?&]c=/);
      // the keyboard moves it too
      const before = Number(await inputValue(page, "c"));
      await canvas.focus();
      await page.keyboard.press("ArrowRight");
      await settled(page);
      assert.ok(Math.abs(Number(await inputValue(page, "c")) - (before + 0.05)) < 1e-9);
      assert.deepEqual(log.pageErrors, []);
      assert.deepEqual(log.consoleErrors, []);
    } finally {
      await context.close();
    }
  });

  test("Example 15: the mean with its slips; a click selects another pixel", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/filter-window"), "ok");
      assert.ok(Math.abs((await exact(page, "selected")) - 102 / 9) < 1e-12);
      const notes = await page.locator(".notes .note").allInnerTexts();
      assert.ok(notes.some((n) => /erratum/i.test(n) && /copied as 1/.test(n)));
      assert.ok(notes.some((n) => /rounding/i.test(n) && /cut the means off/.test(n)));
      assert.match(await page.locator('.result-table tr[data-key="output"] td.printed').innerText(), /12\.9/);
      assert.equal(await page.locator(".formula-raw, .formula-error").count(), 0);
      const [fig] = await canvases(page);
      assert.match(fig.label, /Selected pixel row 2, column 2: output 11\.3333/);
      // keyboard: down twice selects (r4, c2), the slipped pixel
      await page.locator(".figure-canvas").focus();
      await page.keyboard.press("ArrowDown");
      await settled(page);
      await page.keyboard.press("ArrowDown");
      await settled(page);
      assert.equal(await inputValue(page, "select_r"), "4");
      assert.ok(Math.abs((await exact(page, "selected")) - 125 / 9) < 1e-12);
      const printed = page.locator('.result-table tr[data-key="selected"] td.printed');
      assert.equal(Number(await printed.getAttribute("data-value")), 12.88);
      // a click on the window's top-right area selects a pixel in column 4 or 5
      const box = await page.locator(".figure-canvas").boundingBox();
      await page.mouse.click(box.x + 270, box.y + 70);
      await settled(page);
      assert.ok(["4", "5"].includes(await inputValue(page, "select_c")), await inputValue(page, "select_c"));
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("the preset buttons load the seeds' other windows and patches", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/resample"), "ok");
      await page.getByRole("button", { name: "Example 12b" }).click();
      assert.equal(await settled(page), "ok");
      assert.ok(Math.abs((await exact(page, "bilinear")) - 56.2336) < 1e-9);
      const printed = page.locator('.result-table tr[data-key="bilinear"] td.printed');
      assert.equal(Number(await printed.getAttribute("data-value")), 56.234);
      assert.match(page.url(), /first_c=523/);
      await page.getByRole("button", { name: "Example 12a" }).click();
      assert.equal(await settled(page), "ok");
      assert.ok(Math.abs((await exact(page, "bilinear")) - 75.3584) < 1e-9);
      assert.equal(Number(await printed.getAttribute("data-value")), 75.35);

      assert.equal(await visit(page, env.url, "index.html", "#/filter-window"), "ok");
      await page.getByRole("button", { name: "Example 16: Laplacian" }).click();
      assert.equal(await settled(page), "ok");
      assert.equal(await exact(page, "selected"), 1 + 9 + 2 + 9 + 8 + 1 + 8 + 1 - 8 * 9);
      assert.equal(await exact(page, "kernel_sum"), 0);
      assert.match(await page.locator('.result-table tr[data-key="output"] td.diff').innerText(), /agrees/);
      await page.getByRole("button", { name: "Lecture 7: mean (33)" }).click();
      assert.equal(await settled(page), "ok");
      assert.ok(Math.abs((await exact(page, "selected")) - 300 / 9) < 1e-12);
      assert.equal(Number(await page.locator('.result-table tr[data-key="selected"] td.printed').getAttribute("data-value")), 33);
      await page.getByRole("button", { name: "Example 15: Gaussian" }).click();
      assert.equal(await settled(page), "ok");
      assert.equal(await page.locator('[name="kernel"]').inputValue(), "gaussian-3");
      // the seed's printed values appear only when the window is exactly the seed's
      // (the Rust constant): the preset's copy of it is right
      assert.ok((await page.locator(".result-table .verdict").count()) > 0, "Example 15 preset compared with the seed");

      assert.equal(await visit(page, env.url, "index.html", "#/edge-window"), "ok");
      await page.getByRole("button", { name: "Example 15: Sobel" }).click();
      assert.equal(await settled(page), "ok");
      assert.equal(await page.locator('[name="operator"]').inputValue(), "sobel");
      assert.ok((await page.locator(".result-table .verdict").count()) > 0, "Example 15 Sobel preset compared with the seed");
      assert.deepEqual(log.pageErrors, []);
      assert.deepEqual(log.consoleErrors, []);
    } finally {
      await context.close();
    }
  });

  test("Example 16 and the edge operators; a bad custom kernel is reported beside its field", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      const w = encodeURIComponent("1 2 1 1 1; 1 1 9 2 1; 1 9 9 8 1; 1 1 8 1 2; 2 1 1 1 1");
      assert.equal(await visit(page, env.url, "index.html", `#/filter-window?window=${w}&kernel=laplacian-8`), "ok");
      assert.equal(await exact(page, "selected"), 25);
      assert.equal(await exact(page, "kernel_sum"), 0);
      assert.equal(await visit(page, env.url, "index.html", "#/edge-window?operator=sobel"), "ok");
      assert.equal(await exact(page, "selected_gx"), -25);
      assert.ok(Math.abs((await exact(page, "selected_magnitude")) - Math.hypot(25, 11)) < 1e-12);
      const [fig] = await canvases(page);
      assert.ok(fig.ink > fig.pixels * 0.05);
      assert.match(fig.label, /Gx = −25, Gy = −11/);
      assert.equal(await visit(page, env.url, "index.html", "#/filter-window?kernel=custom&custom_kernel=1%201%3B%201%201"), "error");
      assert.match(await page.locator(".error-box").innerText(), /custom_kernel: is 2×2; a kernel needs an odd number/);
      assert.equal(await visit(page, env.url, "index.html", "#/filter-window?window=1%202%3B%203"), "invalid");
      assert.match(await page.locator('.field[data-key="window"]').innerText(), /same length/);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });
});
