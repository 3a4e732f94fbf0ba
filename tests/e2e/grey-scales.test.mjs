// End-to-end: one grey convention in every figure (issue 29, items 4 and 15).
// Every figure that maps numbers to greys does it through draw.js's
// greyScale, an image's convention: dark = low, light = high; each scale has
// a legend (a small ramp with its low and high values and "dark = low"),
// also in the canvas's accessible label. The kit records each scale drawn on
// its canvas (data-grey-scales: { name, lo, hi, text, legend, low, high },
// low/high = the lowest and highest valued cells drawn, in CSS px); these
// tests read the canvas pixels of those two cells and check that the low one
// is the darker — in the light theme, in the dark theme (system setting or
// <html data-theme="dark">), where the paper turns dark and the greys keep
// their meaning.

import assert from "node:assert/strict";
import { after, before, describe, test } from "node:test";
import { TEST_TIMEOUT, open, start, visit } from "./harness.mjs";

/** Every example whose figure shades numbers as greys. */
const GREY_FIGURES = ["ncc-1d", "ncc-2d", "ncc-surface", "filter-window", "edge-window", "forstner-window", "moravec-window", "forstner-image", "lsm-2d", "lsm-affine"];

/** Relative luminance (WCAG) of [r, g, b] in 0–255. */
function luminance([r, g, b]) {
  const lin = (c) => {
    const s = c / 255;
    return s <= 0.03928 ? s / 12.92 : ((s + 0.055) / 1.055) ** 2.4;
  };
  return 0.2126 * lin(r) + 0.7152 * lin(g) + 0.0722 * lin(b);
}
const contrast = (a, b) => (Math.max(a, b) + 0.05) / (Math.min(a, b) + 0.05);

/**
 * For every figure canvas: its recorded grey scales, the commonest colour of
 * the pixels of each scale's lowest and highest cell (the fill, not the
 * number written on it), the colour of its top-left corner (the paper), its
 * theme, its aria-label, and the luminances of the pixels in each legend's box.
 */
async function readFigures(page) {
  await page.waitForFunction(() => document.querySelector(".figure-canvas[data-grey-scales]"), null, { timeout: 15_000 });
  // the figure redrawn for a theme change happens at once; one frame for the paint
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0))));
  return page.evaluate(() => {
    const out = [];
    for (const canvas of document.querySelectorAll(".figure-canvas")) {
      const k = canvas.width / canvas.clientWidth;
      const ctx = canvas.getContext("2d");
      const commonest = (box) => {
        const x = Math.round(box.x * k);
        const y = Math.round(box.y * k);
        const w = Math.max(1, Math.round(box.w * k));
        const h = Math.max(1, Math.round(box.h * k));
        const data = ctx.getImageData(x, y, w, h).data;
        const counts = new Map();
        for (let i = 0; i < data.length; i += 4) {
          const key = `${data[i]},${data[i + 1]},${data[i + 2]}`;
          counts.set(key, (counts.get(key) ?? 0) + 1);
        }
        return [...counts].sort((a, b) => b[1] - a[1])[0][0].split(",").map(Number);
      };
      const pixels = (box) => {
        const data = ctx.getImageData(Math.round(box.x * k), Math.round(box.y * k), Math.max(1, Math.round(box.w * k)), Math.max(1, Math.round(box.h * k))).data;
        const rgb = [];
        for (let i = 0; i < data.length; i += 4) rgb.push([data[i], data[i + 1], data[i + 2]]);
        return rgb;
      };
      const scales = JSON.parse(canvas.dataset.greyScales || "[]").map((s) => ({
        ...s,
        lowRgb: s.low ? commonest(s.low) : null,
        highRgb: s.high ? commonest(s.high) : null,
        legendPixels: pixels(s.legend),
      }));
      out.push({
        w: canvas.clientWidth,
        h: canvas.clientHeight,
        theme: canvas.dataset.theme,
        label: canvas.getAttribute("aria-label") ?? "",
        paper: [...ctx.getImageData(1, 1, 1, 1).data.slice(0, 3)],
        scales,
      });
    }
    return out;
  });
}

/** Asserts every recorded scale: its low cell darker than its high one, its legend inside the canvas and in the label. */
function assertScales(figures, where) {
  const scales = figures.flatMap((f) => f.scales.map((s) => ({ ...s, f })));
  assert.ok(scales.length > 0, `${where}: no grey scale recorded`);
  for (const s of scales) {
    assert.ok(s.low && s.high, `${where}: scale "${s.name}" recorded no cells`);
    if (s.hi > s.lo) {
      const lo = luminance(s.lowRgb);
      const hi = luminance(s.highRgb);
      assert.ok(lo < hi, `${where}: scale "${s.name}": the lowest cell (${s.low.v}, rgb ${s.lowRgb}) is not darker than the highest (${s.high.v}, rgb ${s.highRgb})`);
    }
    const b = s.legend;
    assert.ok(b.x >= 0 && b.y >= 0 && b.x + b.w <= s.f.w + 0.5 && b.y + b.h <= s.f.h + 0.5, `${where}: the legend of "${s.name}" ${JSON.stringify(b)} leaves the ${s.f.w}×${s.f.h} canvas`);
    assert.match(s.text, /dark = low/);
    assert.ok(s.f.label.includes(s.text), `${where}: the figure's label does not give the legend of "${s.name}": ${s.f.label}`);
  }
  return scales;
}

describe("grey scales: dark = low, with a legend, in both themes", { timeout: 20 * TEST_TIMEOUT }, () => {
  let env;
  before(async () => {
    env = await start();
  });
  after(async () => {
    await env?.close();
  });

  for (const width of [390, 1280]) {
    test(`every grey figure at ${width} px: the low cell is the darker, the legend is drawn and in the label`, { timeout: 10 * TEST_TIMEOUT }, async () => {
      const { context, page, log } = await open(env.browser, { viewport: { width, height: 900 }, colorScheme: "light" });
      try {
        for (const id of GREY_FIGURES) {
          assert.equal(await visit(page, env.url, "index.html", `#/${id}`), "ok", id);
          const figures = await readFigures(page);
          assert.ok(figures.every((f) => f.theme === "light"), `${id}: drawn in the ${figures.map((f) => f.theme)} theme`);
          const scales = assertScales(figures, `${id} at ${width} px`);
          // the light paper
          assert.ok(figures.every((f) => luminance(f.paper) > 0.9), `${id}: paper ${figures.map((f) => f.paper)}`);
          if (id === "forstner-window") assert.ok(scales.some((s) => s.name === "Window" && s.lo === 3 && s.hi === 24), `forstner-window: ${JSON.stringify(scales.map((s) => [s.name, s.lo, s.hi]))}`);
        }
        assert.deepEqual(log.pageErrors, []);
      } finally {
        await context.close();
      }
    });
  }

  test("dark theme from the system setting: dark paper, readable legend, the same grey order", { timeout: 5 * TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser, { viewport: { width: 390, height: 900 }, colorScheme: "dark" });
    try {
      for (const id of ["ncc-2d", "filter-window", "forstner-window", "lsm-affine", "gsd", "chain-code"]) {
        assert.equal(await visit(page, env.url, "index.html", `#/${id}`), "ok", id);
        if (!GREY_FIGURES.includes(id)) {
          await page.waitForFunction(() => document.querySelector(".figure-canvas")?.dataset.theme, null, { timeout: 15_000 });
          const paper = await page.evaluate(() => {
            const c = document.querySelector(".figure-canvas");
            return { theme: c.dataset.theme, rgb: [...c.getContext("2d").getImageData(1, 1, 1, 1).data.slice(0, 3)] };
          });
          assert.equal(paper.theme, "dark", id);
          assert.ok(luminance(paper.rgb) < 0.05, `${id}: paper ${paper.rgb} is not dark`);
          continue;
        }
        const figures = await readFigures(page);
        assert.ok(figures.every((f) => f.theme === "dark"), `${id}: drawn in the ${figures.map((f) => f.theme)} theme`);
        for (const f of figures) assert.ok(luminance(f.paper) < 0.05, `${id}: paper ${f.paper} is not dark`);
        const scales = assertScales(figures, `${id} (dark)`);
        // the legend's text: its brightest pixels against the dark paper
        for (const s of scales) {
          const paper = luminance(s.f.paper);
          const lum = s.legendPixels.map(luminance).sort((a, b) => a - b);
          // the legend's text (its ramp aside: the brightest 2 % of the box include the text's stems)
          const bright = lum[Math.floor(lum.length * 0.98)];
          assert.ok(contrast(bright, paper) >= 4.5, `${id}: legend "${s.name}" text contrast ${contrast(bright, paper).toFixed(2)} on the dark paper`);
        }
      }
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("the theme switch (<html data-theme>) redraws the figure dark and back", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser, { viewport: { width: 1280, height: 900 }, colorScheme: "light" });
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/ncc-2d"), "ok");
      let figures = await readFigures(page);
      assert.ok(luminance(figures[0].paper) > 0.9);
      const lightOrder = figures[0].scales.map((s) => luminance(s.lowRgb) < luminance(s.highRgb));
      await page.evaluate(() => document.documentElement.setAttribute("data-theme", "dark"));
      await page.waitForFunction(() => document.querySelector(".figure-canvas").dataset.theme === "dark", null, { timeout: 5000 });
      figures = await readFigures(page);
      assert.ok(luminance(figures[0].paper) < 0.05, `paper ${figures[0].paper}`);
      assertScales(figures, "ncc-2d, data-theme=dark");
      assert.deepEqual(
        figures[0].scales.map((s) => luminance(s.lowRgb) < luminance(s.highRgb)),
        lightOrder,
      );
      // the canvas's own background (before it is drawn) is dark too
      assert.equal(await page.evaluate(() => getComputedStyle(document.querySelector(".figure-canvas")).backgroundColor), "rgb(16, 21, 28)");
      // print: the light paper whatever the theme, the dark one again afterwards
      await page.evaluate(() => window.dispatchEvent(new Event("beforeprint")));
      assert.equal(await page.evaluate(() => document.querySelector(".figure-canvas").dataset.theme), "light");
      await page.evaluate(() => window.dispatchEvent(new Event("afterprint")));
      assert.equal(await page.evaluate(() => document.querySelector(".figure-canvas").dataset.theme), "dark");
      await page.evaluate(() => document.documentElement.setAttribute("data-theme", "light"));
      await page.waitForFunction(() => document.querySelector(".figure-canvas").dataset.theme === "light", null, { timeout: 5000 });
      figures = await readFigures(page);
      assert.ok(luminance(figures[0].paper) > 0.9);
      // an embed with theme=dark: its figure on the dark paper, the greys in the same order
      assert.equal(await visit(page, env.url, "embed.html", "#/filter-window?theme=dark"), "ok");
      figures = await readFigures(page);
      assert.ok(figures.length > 0 && figures.every((f) => f.theme === "dark" && luminance(f.paper) < 0.05), `embed: ${figures.map((f) => [f.theme, f.paper])}`);
      assertScales(figures, "embed filter-window, theme=dark");
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });
});
