// Interest operators on the page: Examples 13 and 14 with the printed values
// beside the exact ones, the figures drawn and described, the test-pattern
// mode answering a moved window, and bad windows reported beside the field.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import { TEST_TIMEOUT, cellText, exact, open, start, visit } from "./harness.mjs";

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

async function waitForCell(page, key, textValue) {
  await page.waitForFunction(
    ([k, t]) => document.querySelector(`.result-table tr[data-key="${k}"] td.exact`)?.innerText.trim() === t,
    [key, textValue],
    { timeout: 15_000 },
  );
}

/** Where window pixel (c, r) is drawn in the Moravec overview, from the figure's own layout for the current window. */
function moravecCell(page, c, r) {
  return page.evaluate(
    async ([cc, rr]) => {
      const { loadCore } = await import("./core.js");
      const { moravecPoint } = await import("./figures/interest.js");
      const core = await loadCore();
      const texts = { window: document.querySelector('.field[data-key="window"] textarea').value };
      const solution = core.solve("moravec-window", core.parseInputs("moravec-window", texts).inputs);
      return moravecPoint(document.querySelector(".figure-canvas").clientWidth, solution, cc, rr);
    },
    [c, r],
  );
}

describe("interest operators", () => {
  test("Example 13: exact N, det N, trace N⁻¹ beside the printed ones; the two figures", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/forstner-window"), "ok");
      assert.equal(await exact(page, "det_n"), 8914.4375);
      const printed = page.locator('.result-table tr[data-key="det_n"] td.printed');
      assert.equal(Number(await printed.getAttribute("data-value")), 8891.9375);
      // the printed det N follows the slip in its table (−22.25 copied as −22.75): an erratum, not a rounding
      assert.match(await cellText(page, "det_n", "diff"), /erratum/);
      assert.ok(Math.abs((await exact(page, "trace_n_inverse")) - 196.75 / 8914.4375) < 1e-15);
      assert.match(await cellText(page, "trace_n_inverse", "diff"), /agrees/);
      assert.match(await cellText(page, "n", "printed"), /22\.75/);
      assert.equal(await cellText(page, "case", "exact"), "corner");
      assert.equal(await cellText(page, "accepted", "exact"), "yes");
      // the notes: the slip in N and the backwards rule
      const notes = await page.locator(".notes .note").allInnerTexts();
      assert.ok(notes.some((n) => /erratum/i.test(n) && /22\.75 off the diagonal/.test(n)));
      assert.ok(notes.some((n) => /erratum/i.test(n) && /backwards/.test(n)));
      // the steps rendered by KaTeX, the seed's table included
      assert.ok((await page.locator(".steps .step").count()) >= 10);
      assert.equal(await page.locator(".formula-raw, .formula-error").count(), 0);
      const figs = await canvases(page);
      assert.equal(figs.length, 2);
      for (const f of figs) assert.ok(f.ink > f.pixels * 0.02, `drawn: ${f.label}`);
      assert.match(figs[0].label, /5×5 window/);
      assert.match(figs[0].label, /P\(c3, r3\)/);
      assert.match(figs[1].label, /case corner/);
      assert.match(figs[1].label, /accepted/);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("Example 14: the Moravec sums and the mean 183 agree with the seed", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/moravec-window"), "ok");
      assert.equal(await exact(page, "mean"), 183);
      assert.match(await cellText(page, "mean", "diff"), /agrees/);
      assert.match(await cellText(page, "sums", "diff"), /agrees/);
      const [fig] = await canvases(page);
      assert.ok(fig.ink > fig.pixels * 0.02);
      for (const words of ["P(c2, r2) = 27", "sum 47", "sum 361", "sum 153", "sum 171", "Mean 183"]) assert.ok(fig.label.includes(words), `${words}: ${fig.label}`);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("the test pattern: the window moves, the case follows; the interest points stay", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/forstner-image"), "ok");
      assert.equal(await cellText(page, "case", "exact"), "corner");
      let figs = await canvases(page);
      assert.equal(figs.length, 3);
      for (const f of figs) assert.ok(f.ink > f.pixels * 0.02, `drawn: ${f.label}`);
      assert.match(figs[0].label, /14 interest points after suppression: \(9, 9\), \(24, 9\)/);
      assert.match(figs[0].label, /Reference windows: flat background \(34, 16\) flat, vertical edge \(47, 14\) edge, checkerboard corner \(47, 47\) corner\./);
      // move the window onto the square's top edge, then into the flat background
      await page.getByLabel(/column c/).fill("16");
      await waitForCell(page, "case", "edge");
      assert.ok((await exact(page, "q")) < 0.1);
      assert.match(await page.evaluate(() => location.hash), /c=16/);
      await page.getByLabel(/column c/).fill("35");
      await page.getByLabel(/row r/).fill("12");
      await waitForCell(page, "case", "flat");
      figs = await canvases(page);
      assert.match(figs[0].label, /window at \(c, r\) = \(35, 12\): case flat/);
      assert.match(figs[0].label, /14 interest points/);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("the window moves on the pattern by a click and by the arrow keys", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/forstner-image"), "ok");
      const canvas = page.locator(".figure-canvas").first();
      await canvas.scrollIntoViewIfNeeded();
      const [x, y] = await page.evaluate(async () => {
        const { loadCore } = await import("./core.js");
        const { patternPoint } = await import("./figures/interest.js");
        const core = await loadCore();
        return patternPoint(document.querySelector(".figure-canvas").clientWidth, core.solve("forstner-image", {}), 16, 9);
      });
      await canvas.click({ position: { x, y } });
      await waitForCell(page, "case", "edge");
      assert.equal(await page.getByLabel(/column c/).inputValue(), "16");
      assert.equal(await page.getByLabel(/row r/).inputValue(), "9");
      assert.match(await page.evaluate(() => location.hash), /c=16/);
      // the canvas keeps the focus: the arrow keys move the window by one pixel
      await page.keyboard.press("ArrowRight");
      await page.waitForFunction(() => document.querySelector('.field[data-key="c"] input').value === "17");
      await page.keyboard.press("ArrowDown");
      await page.waitForFunction(() => document.querySelector('.field[data-key="r"] input').value === "10");
      const [fig] = await canvases(page);
      await page.waitForFunction(() => document.querySelector(".figure-canvas").getAttribute("aria-label").includes("(c, r) = (17, 10)"));
      assert.ok(fig.ink > fig.pixels * 0.02);
      // the window stops at the border: c cannot go below half the window + 1
      await page.getByLabel(/column c/).fill("3");
      await page.waitForFunction(() => document.querySelector(".figure-canvas").getAttribute("aria-label").includes("(c, r) = (3, 10)"));
      await canvas.focus();
      await page.keyboard.press("ArrowLeft");
      assert.equal(await page.getByLabel(/column c/).inputValue(), "3");
      assert.deepEqual(log.pageErrors, []);
      assert.deepEqual(log.consoleErrors, []);
    } finally {
      await context.close();
    }
  });

  test("Moravec on an 8×8 window: click or arrow to any interior pixel and see its differences", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/moravec-window"), "ok");
      const rows = [];
      for (let r = 0; r < 8; r++) rows.push(Array.from({ length: 8 }, (_, c) => (r === 3 && c === 5 ? 90 : 10 + ((3 * r + 5 * c) % 7))).join(" "));
      await page.getByLabel(/Window of grey values/).fill(rows.join("\n"));
      await page.waitForFunction(() => document.querySelector(".figure-canvas").getAttribute("aria-label").startsWith("36 interior pixels"));
      const status = page.locator(".figure-status");
      // by default the pixel of the largest sum: one of the bright pixel's neighbours
      assert.match(await status.innerText(), /^Selected P\(c\d, r\d\)/);
      const canvas = page.locator(".figure-canvas").first();
      await canvas.scrollIntoViewIfNeeded();
      const [x, y] = await moravecCell(page, 2, 2);
      await canvas.click({ position: { x, y } });
      assert.match(await status.innerText(), /^Selected P\(c2, r2\) = 11: sum of the four squared differences/);
      assert.match(await canvas.getAttribute("aria-label"), /P\(c2, r2\) = 11: differences/);
      await page.keyboard.press("ArrowRight");
      await page.keyboard.press("ArrowDown");
      assert.match(await status.innerText(), /^Selected P\(c3, r3\)/);
      // an edge pixel is not interior: a click there keeps the selection
      const [x0, y0] = await moravecCell(page, 1, 1);
      await canvas.click({ position: { x: x0, y: y0 } });
      assert.match(await status.innerText(), /^Selected P\(c3, r3\)/);
      assert.deepEqual(log.pageErrors, []);
      assert.deepEqual(log.consoleErrors, []);
    } finally {
      await context.close();
    }
  });

  test("a window too small, ragged or off the image is reported beside its field", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/forstner-window"), "ok");
      const win = page.getByLabel(/Window of grey values/);
      const fieldError = page.locator('.field[data-key="window"] .field-error');
      const general = page.locator(".error-message");
      // text that cannot be read: beside the field
      for (const [textValue, pattern] of [
        ["1 2 3; 4 5; 6 7 8", /same length/],
        ["1 2 3; 4 x 6; 7 8 9", /not a number/],
      ]) {
        await win.fill(textValue);
        await page.waitForFunction(() => document.body.dataset.status === "invalid");
        assert.match(await fieldError.innerText(), pattern);
      }
      // a readable window the operator cannot use: the message names the field
      await win.fill("1 2; 3 4");
      await page.waitForFunction(() => document.body.dataset.status === "error");
      assert.match(await general.innerText(), /^window: is 2×2; the window needs at least 3×3/);
      await win.fill("1 1 1; 1 1 1; 1 1 1");
      await waitForCell(page, "case", "flat");
      assert.equal(await cellText(page, "q", "exact"), "—");

      assert.equal(await visit(page, env.url, "index.html", "#/forstner-image?c=2"), "error");
      assert.match(await general.innerText(), /^c: must be between 3 and 62/);
      await page.getByLabel(/column c/).fill("9");
      await waitForCell(page, "case", "corner");
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });
});
