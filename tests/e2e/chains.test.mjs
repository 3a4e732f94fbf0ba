// Chain codes on the page: Example 17 and the exercise, Example 18 and the
// descriptors with the printed values beside the exact ones, and the drawing
// grid: clicks that take a pixel back, extend the path, break it, close it
// and toggle region pixels; the preset buttons.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import { TEST_TIMEOUT, cellText, exact, open, settled, start, visit } from "./harness.mjs";

let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

/** The figure canvas: its label and how much of it is not white. */
function figure(page) {
  return page.evaluate(() => {
    const c = document.querySelector(".figure-canvas");
    const data = c.getContext("2d").getImageData(0, 0, c.width, c.height).data;
    let ink = 0;
    for (let i = 0; i < data.length; i += 4) if (data[i] < 240 || data[i + 1] < 240 || data[i + 2] < 240) ink += 1;
    return { label: c.getAttribute("aria-label"), ink, pixels: c.width * c.height };
  });
}

/** Clicks grid cell [c, r] of the figure (its position from the figure's own layout for the current inputs). */
async function clickCell(page, id, pixel) {
  const point = await page.evaluate(
    async ([exampleId, p]) => {
      const { loadCore } = await import("./core.js");
      const fig = await import("./figures/chains.js");
      const core = await loadCore();
      const texts = {};
      for (const f of document.querySelectorAll(".input-form [name]")) texts[f.name] = f.value;
      const parsed = core.parseInputs(exampleId, texts);
      const solution = core.solve(exampleId, parsed.inputs);
      const canvas = document.querySelector(".figure-canvas");
      return fig.cellPoint(canvas.clientWidth, solution, p);
    },
    [id, pixel],
  );
  await page.locator(".figure-canvas").click({ position: { x: point[0], y: point[1] } });
  return settled(page);
}

const pixelsText = (page) => page.locator('textarea[name="pixels"]').inputValue();

describe("chain codes", () => {
  test("Example 17, the exercise and figure c on the page", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/chain-code"), "ok");
      let fig = await figure(page);
      assert.ok(fig.ink > fig.pixels * 0.03, "the grid is drawn");
      assert.match(fig.label, /open edge of 17 pixels from \(1, 4\)/);
      assert.match(fig.label, /Chain code 1 8 8 8 7 1 1 2 3 4 4 2 1 1 2 2; differential code 7 0 0 7 2 0 1 1 1 0 6 7 0 1 0\./);
      assert.match(await cellText(page, "code", "diff"), /agrees/);
      assert.match(await cellText(page, "differential", "diff"), /agrees/);
      assert.equal(await page.locator(".formula-raw, .formula-error").count(), 0);
      const notes = await page.locator(".notes .note").allInnerTexts();
      assert.ok(notes.some((n) => /rebuilt from the printed code/.test(n)));
      // the exercise, from its preset button
      await page.getByRole("button", { name: "Exercise: from the right end" }).click();
      assert.equal(await settled(page), "ok");
      fig = await figure(page);
      assert.match(fig.label, /Chain code 6 6 5 5 6 8 8 7 6 5 5 3 4 4 4 5; differential code 0 7 0 1 2 0 7 7 7 0 6 1 0 0 1\./);
      assert.match(page.url(), /from=end/);
      // figure c: a 4-connectivity code
      await page.getByRole("button", { name: "Figure c (4-connected)" }).click();
      assert.equal(await settled(page), "ok");
      fig = await figure(page);
      assert.match(fig.label, /Chain code 4 4 1 1 2 1 1 4 1 1 2 2 2 3 3;/);
      assert.deepEqual(log.pageErrors, []);
      assert.deepEqual(log.consoleErrors, []);
    } finally {
      await context.close();
    }
  });

  test("the drawing grid: take back, extend, break, close", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/chain-code"), "ok");
      // a click on the last pixel takes it back
      assert.equal(await clickCell(page, "chain-code", [11, 1]), "ok");
      assert.equal((await pixelsText(page)).split("\n").length, 16);
      assert.match((await figure(page)).label, /Chain code 1 8 8 8 7 1 1 2 3 4 4 2 1 1 2;/);
      // a click on a neighbour extends the path by one digit
      assert.equal(await clickCell(page, "chain-code", [11, 2]), "ok");
      assert.match((await figure(page)).label, /Chain code 1 8 8 8 7 1 1 2 3 4 4 2 1 1 2 1;/);
      // a click two cells away breaks it: pointed out, no code
      assert.equal(await clickCell(page, "chain-code", [11, 4]), "ok");
      let fig = await figure(page);
      assert.match(fig.label, /No chain code: the path breaks\. Break between pixel 17 \(11, 2\) and pixel 18 \(11, 4\)\./);
      const notes = await page.locator(".notes .note").allInnerTexts();
      assert.ok(notes.some((n) => /pixel 17 \(11, 2\) and pixel 18 \(11, 4\) are not neighbours/.test(n)));
      // take it back again and start over from one pixel, then draw a closed square
      await page.getByRole("button", { name: "Start again" }).click();
      assert.equal(await settled(page), "ok");
      assert.equal(await pixelsText(page), "1 4");
      for (const p of [[2, 4], [2, 5], [1, 5]]) assert.equal(await clickCell(page, "chain-code", p), "ok");
      assert.equal(await clickCell(page, "chain-code", [1, 4]), "ok"); // the first pixel closes it
      fig = await figure(page);
      assert.match(fig.label, /a closed boundary of 4 pixels/);
      assert.match(fig.label, /Chain code 1 7 5 3; differential code 6 6 6 6\./);
      assert.match(fig.label, /Diameter 1\.4142 px, minor axis 1\.4142 px, eccentricity 1\./);
      assert.ok(Math.abs((await exact(page, "eccentricity")) - 1) < 1e-12);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("drawing by keyboard: digits and arrows add a step, Backspace takes one back", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/chain-code"), "ok");
      await page.getByRole("button", { name: "Start again" }).click();
      assert.equal(await settled(page), "ok");
      assert.equal(await pixelsText(page), "1 4");
      const canvas = page.locator(".figure-canvas");
      await canvas.focus();
      // digit 1 = east, 8 = south-east, then the arrow up (north = 3)
      for (const key of ["1", "8", "ArrowUp"]) {
        await page.keyboard.press(key);
        assert.equal(await settled(page), "ok");
      }
      assert.equal(await pixelsText(page), "1 4\n2 4\n3 5\n3 4");
      assert.match((await figure(page)).label, /Chain code 1 8 3;/);
      assert.match(page.url(), /pixels=/);
      await page.keyboard.press("Backspace");
      assert.equal(await settled(page), "ok");
      assert.equal(await pixelsText(page), "1 4\n2 4\n3 5");
      assert.match((await figure(page)).label, /Chain code 1 8;/);
      // a key that is no direction changes nothing
      await page.keyboard.press("9");
      assert.equal(await settled(page), "ok");
      assert.equal(await pixelsText(page), "1 4\n2 4\n3 5");
      assert.deepEqual(log.pageErrors, []);
      assert.deepEqual(log.consoleErrors, []);
    } finally {
      await context.close();
    }
  });

  test("a path that goes back over itself is marked as a branch; the circle and the seed's edge presets", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/chain-code"), "ok");
      // a T drawn by going out along the arm and back: pixel 4 repeats pixel 2
      await page.locator('textarea[name="pixels"]').fill("1 1\n2 1\n3 1\n2 1\n2 2");
      assert.equal(await settled(page), "ok");
      const fig = await figure(page);
      assert.match(fig.label, /Branch: pixel 4 \(2, 1\) repeats pixel 2\./);
      const notes = await page.locator(".notes .note").allInnerTexts();
      assert.ok(notes.some((n) => /pixel 4 \(2, 1\) is pixel 2 again/.test(n)), notes.join("\n"));
      // the presets
      await page.getByRole("button", { name: "Circle" }).click();
      assert.equal(await settled(page), "ok");
      let label = (await figure(page)).label;
      assert.match(label, /outer boundary of the first, 22 positions/);
      // a digitised circle: diameter and minor axis nearly equal
      const ecc = Number(/eccentricity ([\d.]+)\.$/.exec(label)?.[1]);
      assert.ok(ecc >= 1 && ecc < 1.1, label);
      await page.getByRole("button", { name: "Example 17 (the worked example’s edge)" }).click();
      assert.equal(await settled(page), "ok");
      label = (await figure(page)).label;
      assert.match(label, /Chain code 1 8 8 8 7 1 1 2 3 4 4 2 1 1 2 2;/);
      assert.deepEqual(log.pageErrors, []);
      assert.deepEqual(log.consoleErrors, []);
    } finally {
      await context.close();
    }
  });

  test("Example 18 lengths and the descriptors of drawn regions", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/boundary-length"), "ok");
      assert.ok(Math.abs((await exact(page, "length")) - (8 + 9 * Math.SQRT2)) < 1e-12);
      assert.match(await cellText(page, "length", "printed"), /20\.7/);
      assert.match(await cellText(page, "length", "diff"), /agrees/);
      await page.getByRole("button", { name: "Example 18 (a)" }).click();
      assert.equal(await settled(page), "ok");
      assert.equal(await exact(page, "length"), 23);
      assert.equal(await exact(page, "pixel_count"), 24);
      assert.match(await cellText(page, "length", "diff"), /agrees/);
      // a rectangle region: its traced boundary and the descriptors drawn
      await page.getByRole("button", { name: "Rectangle" }).click();
      assert.equal(await settled(page), "ok");
      assert.equal(await exact(page, "length"), 2 * 9 + 2 * 5);
      assert.match((await figure(page)).label, /Diameter 10\.296 px/);

      assert.equal(await visit(page, env.url, "index.html", "#/boundary-shape"), "ok");
      assert.ok(Math.abs((await exact(page, "eccentricity")) - 2.125) < 1e-12);
      let fig = await figure(page);
      assert.ok(fig.ink > fig.pixels * 0.05);
      assert.match(fig.label, /Diameter 11\.662 px, minor axis 5\.488 px, eccentricity 2\.125\./);
      // a click outside the region adds a separate one-pixel region
      assert.equal(await clickCell(page, "boundary-shape", [0, 0]), "ok");
      assert.equal(await exact(page, "regions"), 2);
      const notes = await page.locator(".notes .note").allInnerTexts();
      assert.ok(notes.some((n) => /2 separate regions/.test(n)));
      // clicking it again removes it
      assert.equal(await clickCell(page, "boundary-shape", [0, 0]), "ok");
      assert.equal(await exact(page, "regions"), 1);
      await page.getByRole("button", { name: "L-shape" }).click();
      assert.equal(await settled(page), "ok");
      fig = await figure(page);
      assert.match(fig.label, /outer boundary of the first, 29 positions from \(3, 1\)/);
      assert.deepEqual(log.pageErrors, []);
      assert.deepEqual(log.consoleErrors, []);
    } finally {
      await context.close();
    }
  });
});
