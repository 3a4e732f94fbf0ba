// The lab's view in Chromium: zoomed in far enough, the grey values are
// written into the pixels (the drawn text read back and checked against
// the photo); the keyboard (Ctrl+arrows) pans and fits; the inspector gives c, r, the
// grey value and, on the generated scanned frame, x and y in mm; the
// opacity slider blends the result over the photo; a signed layer (Sobel
// gx) gets the diverging legend with its range; and the engine line says
// which build runs on how many threads, on a plain and on a cross-origin
// isolated server.

import { test, before, after } from "node:test";
import assert from "node:assert/strict";
import { startServer } from "../../scripts/serve.mjs";
import { start, open, DIST, launchChromium, TEST_TIMEOUT } from "./harness.mjs";
import { idle, sample } from "./lab-harness.mjs";

let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

async function openLab(options, url = env.url, browser = env.browser) {
  const o = await open(browser, options);
  // every text written on the main view's canvas: [text, x, y, colour] (x, y in the canvas's current transform)
  await o.context.addInitScript(() => {
    const fill = CanvasRenderingContext2D.prototype.fillText;
    window.labTexts = [];
    CanvasRenderingContext2D.prototype.fillText = function (text, x, y, ...rest) {
      if (this.canvas.closest?.("#lab-stage")) window.labTexts.push([String(text), x, y, this.fillStyle]);
      return fill.call(this, text, x, y, ...rest);
    };
  });
  await o.page.goto(`${url}index.html#/lab`);
  await o.page.waitForSelector("#lab-sample");
  return o;
}

const view = (page) => page.evaluate(async () => (await import("./lab/lab.js")).viewForTests());
const greyBox = (page, box) => page.evaluate(async (b) => (await import("./lab/lab.js")).greyForTests(b), box);

/** Moves the mouse over image pixel (c, r) of the main view. */
async function hoverPixel(page, c, r) {
  await page.locator("#lab-stage .lab-canvas").scrollIntoViewIfNeeded();
  const g = await view(page);
  await page.mouse.move(g.left + ((c + 0.5) * g.zoom + g.ox) * (g.w / g.cw), g.top + ((r + 0.5) * g.zoom + g.oy) * (g.h / g.ch));
}

/** The main canvas's RGB at the centre of image pixel (c, r). */
async function canvasAt(page, c, r) {
  return page.evaluate(async ([c, r]) => {
    const g = (await import("./lab/lab.js")).viewForTests();
    const cv = document.querySelector("#lab-stage .lab-canvas");
    return Array.from(cv.getContext("2d").getImageData(Math.floor((c + 0.5) * g.zoom + g.ox), Math.floor((r + 0.5) * g.zoom + g.oy), 1, 1).data.slice(0, 3));
  }, [c, r]);
}

/** The image pixel under the canvas's centre. */
function centrePixel(g) {
  return [Math.floor((g.cw / 2 - g.ox) / g.zoom), Math.floor((g.ch / 2 - g.oy) / g.zoom)];
}

/** A number as the lab writes it for people: up to 5 significant digits. */
const fmt = (v) => (Number.isInteger(v) ? String(v) : String(Number(v.toPrecision(5))));

/** The texts written since the last call, as a map "c,r" → text (pixel labels sit at pixel centres c + 0.5, r + 0.5); `colours` the same for their colours. */
async function textsDrawn(page, colours = null) {
  const t = await page.evaluate(() => window.labTexts.splice(0));
  const out = new Map();
  for (const [text, x, y, colour] of t) {
    out.set(`${x - 0.5},${y - 0.5}`, text);
    colours?.set(`${x - 0.5},${y - 0.5}`, colour);
  }
  return out;
}

test("zoomed in, the grey values are written in the pixels; the keyboard pans and fits", { timeout: TEST_TIMEOUT * 2 }, async () => {
  const { page, log, context } = await openLab();
  await sample(page, "camera.png");
  const fit = await view(page);
  await textsDrawn(page);
  await page.focus("#lab-stage .lab-canvas");
  // one press at the fitted zoom: no values written yet
  await page.keyboard.press("+");
  assert.ok((await view(page)).zoom < 28);
  assert.equal((await textsDrawn(page)).size, 0, "values written at a small zoom");
  // zoom in until one image pixel is at least 28 canvas pixels
  let presses = 1;
  while ((await view(page)).zoom < 28) {
    await page.keyboard.press("+");
    presses++;
    assert.ok(presses < 40, "the zoom does not grow");
  }
  let g = await view(page);
  assert.ok(Math.abs(g.zoom - fit.zoom * 1.25 ** presses) < 1e-6 * g.zoom, `${g.zoom} after ${presses} presses from ${fit.zoom}`);
  await textsDrawn(page);
  await page.keyboard.press("Control+ArrowRight");
  const after = await view(page);
  // Ctrl+→ moves the view 40 canvas pixels (the image goes left), nothing else changes
  assert.equal(after.ox, g.ox - 40);
  assert.equal(after.oy, g.oy);
  assert.equal(after.zoom, g.zoom);
  g = after;
  const colours = new Map();
  const texts = await textsDrawn(page, colours);
  // every visible pixel carries its grey value (black on light grey, white on dark), and only those
  const [c0, r0] = [Math.floor(-g.ox / g.zoom), Math.floor(-g.oy / g.zoom)];
  const [c1, r1] = [Math.floor((g.cw - g.ox) / g.zoom), Math.floor((g.ch - g.oy) / g.zoom)];
  const grey = await greyBox(page, [c0, r0, c1 - c0 + 1, r1 - r0 + 1]);
  // the photo is drawn with its grey range stretched to 0…255
  const all = await greyBox(page, [0, 0, 512, 512]);
  const [glo, ghi] = all.reduce(([a, b], v) => [Math.min(a, v), Math.max(b, v)], [Infinity, -Infinity]);
  let written = 0;
  for (let r = r0; r <= r1; r++) {
    for (let c = c0; c <= c1; c++) {
      const want = String(grey[(r - r0) * (c1 - c0 + 1) + (c - c0)]);
      assert.equal(texts.get(`${c},${r}`), want, `pixel (${c}, ${r})`);
      const drawn = ((Number(want) - glo) / (ghi - glo)) * 255;
      assert.equal(colours.get(`${c},${r}`), drawn > 140 ? "#000000" : "#ffffff", `pixel (${c}, ${r}), grey ${want} drawn as ${drawn}`);
      written++;
    }
  }
  assert.ok(written >= 12, `${written} pixels in view`);
  assert.ok(texts.size <= written + 2 * (r1 - r0 + c1 - c0 + 4), `${texts.size} texts for ${written} pixels in view`);
  // Ctrl+↓ pans down, Ctrl+← and Ctrl+↑ back again, 0 fits the whole photo
  const [cc, cr] = centrePixel(g);
  await page.keyboard.press("Control+ArrowDown");
  assert.equal((await view(page)).oy, g.oy - 40);
  await page.keyboard.press("Control+ArrowDown");
  await page.keyboard.press("Control+ArrowDown");
  const down = centrePixel(await view(page));
  assert.deepEqual(down, [cc, Math.floor((g.ch / 2 - g.oy + 120) / g.zoom)]);
  assert.ok(down[1] > cr);
  await page.keyboard.press("Control+ArrowLeft");
  await page.keyboard.press("Control+ArrowUp");
  const moved = await view(page);
  assert.deepEqual([moved.ox, moved.oy], [g.ox + 40, g.oy - 80]);
  await page.keyboard.press("0");
  const back = await view(page);
  assert.deepEqual([back.zoom, back.ox, back.oy], [fit.zoom, fit.ox, fit.oy]);
  // the inspector follows the mouse: c, r and the grey value
  for (const [c, r] of [[0, 0], [511, 511], [123, 456]]) {
    await hoverPixel(page, c, r);
    const [v] = await greyBox(page, [c, r, 1, 1]);
    assert.equal(await page.textContent("#lab-inspector"), `c ${c}, r ${r} · grey ${v}`);
  }
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("the inspector on the scanned frame: c, r, grey and x, y in mm; at a fiducial, its calibrated position", { timeout: TEST_TIMEOUT }, async () => {
  const { page, log, context } = await openLab();
  await sample(page, "frame");
  const truth = await page.evaluate(async () => (await import("./lab/lab.js")).truthForTests());
  // lab/src/sample.rs scans the frame at 0.25 mm a pixel, 1000 × 1000 pixels, x right and y up from the centre
  assert.equal(truth.pixel_mm, 0.25);
  assert.match(await page.textContent("#lab-info"), /1000 × 1000 pixels/);
  const m = 499.5;
  for (const [c, r] of [[0, 0], [999, 0], [500, 500], [731, 212]]) {
    await hoverPixel(page, c, r);
    const [v] = await greyBox(page, [c, r, 1, 1]);
    assert.equal(await page.textContent("#lab-inspector"),
      `c ${c}, r ${r} · grey ${fmt(v)} · x ${fmt((c - m) * 0.25)} mm, y ${fmt((m - r) * 0.25)} mm (nominal)`);
  }
  // at fiducial 1 and 3 (Example 4: x = −113.002, y = 0.008; x = 0.008, y = 112.998 mm), the nominal
  // scale reads the calibrated position to within the frame's distortion (< 0.5 mm there)
  for (const [k, x, y] of [[0, -113.002, 0.008], [2, 0.008, 112.998]]) {
    const [c, r] = [Math.round(truth.marks[2 * k]), Math.round(truth.marks[2 * k + 1])];
    await hoverPixel(page, c, r);
    const text = await page.textContent("#lab-inspector");
    const [, xs, ys] = text.match(/x (-?[\d.]+) mm, y (-?[\d.]+) mm/);
    assert.ok(Math.abs(Number(xs) - x) < 0.5 && Math.abs(Number(ys) - y) < 0.5, `fiducial ${k + 1}: ${text}`);
    // the mark is a bright disc on the dark frame
    assert.ok(Number(text.match(/grey ([\d.]+)/)[1]) > 150, text);
  }
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("the opacity slider blends the result over the photo; Sobel gx gets the diverging legend with its range", { timeout: TEST_TIMEOUT * 2 }, async () => {
  const { page, log, context } = await openLab();
  await sample(page, "camera.png");
  const grey = await greyBox(page, [0, 0, 512, 512]);
  const g = (c, r) => grey[Math.min(511, Math.max(0, r)) * 512 + Math.min(511, Math.max(0, c))];
  // Sobel gx (top row minus bottom row), replicated edge, worked out here over the whole photo
  const gx = (c, r) => g(c - 1, r - 1) + 2 * g(c, r - 1) + g(c + 1, r - 1) - g(c - 1, r + 1) - 2 * g(c, r + 1) - g(c + 1, r + 1);
  let [lo, hi] = [Infinity, -Infinity];
  for (let r = 0; r < 512; r++) {
    for (let c = 0; c < 512; c++) {
      lo = Math.min(lo, gx(c, r));
      hi = Math.max(hi, gx(c, r));
    }
  }
  await page.selectOption("#lab-family", "edges");
  await page.selectOption("#lab-operator", "sobel");
  await page.click("#lab-run");
  await idle(page);
  await page.selectOption("#lab-layer", { label: "gx" });
  const mabs = Math.max(-lo, hi);
  assert.ok(lo < 0 && hi > 0, `gx from ${lo} to ${hi}`);
  assert.equal(await page.textContent("#lab-legend"),
    `gx: −${fmt(mabs)}0+${fmt(mabs)} (values from ${fmt(lo)} to ${fmt(hi)}; blue negative, orange positive)`);
  // blue to white left of 0, white to orange right of it
  assert.deepEqual(await page.$$eval("#lab-legend > span", (ss) => ss.map((s) => s.className || s.textContent)),
    ["lab-legend-name", "lab-legend-end", "lab-legend-bar negative", "lab-legend-end", "lab-legend-bar positive", "lab-legend-end", "muted"]);
  assert.equal(await page.textContent("#lab-legend .lab-legend-bar.negative + .lab-legend-end"), "0");
  // the magnitude is not signed: a grey legend from its smallest to its largest value
  await page.selectOption("#lab-layer", { label: "magnitude" });
  assert.match(await page.textContent("#lab-legend"), /^magnitude: 0[\d.]+ \(values from 0 to [\d.]+; dark = low\)$/);
  assert.equal(await page.locator("#lab-legend .lab-legend-bar.grey").count(), 1);
  await page.selectOption("#lab-layer", { label: "gx" });

  // the photo as drawn (its grey range stretched to 0…255) and gx's diverging colour
  let [glo, ghi] = [Infinity, -Infinity];
  for (const v of grey) [glo, ghi] = [Math.min(glo, v), Math.max(ghi, v)];
  const base = (c, r) => Math.round(((g(c, r) - glo) / (ghi - glo)) * 255);
  const colour = (v) => {
    const t = v / mabs;
    const end = t < 0 ? [29, 95, 191] : [217, 119, 6]; // blue and orange, as the figures draw signed values
    return end.map((e) => Math.round(255 - Math.abs(t) * (255 - e)));
  };
  const setOpacity = (v) => page.$eval("#lab-opacity", (i, v) => {
    i.value = String(v);
    i.dispatchEvent(new Event("input", { bubbles: true }));
  }, v);
  // pixels where gx is strongly negative, strongly positive and about 0
  const picks = [];
  for (let r = 1; r < 511 && picks.length < 3; r += 7) {
    for (let c = 1; c < 511; c += 5) {
      const v = gx(c, r);
      if ((picks.length === 0 && v < -0.5 * mabs) || (picks.length === 1 && v > 0.5 * mabs) || (picks.length === 2 && Math.abs(v) < 0.05 * mabs && g(c, r) < 120)) {
        picks.push([c, r]);
        break;
      }
    }
  }
  assert.equal(picks.length, 3, `pixels found: ${JSON.stringify(picks)}`);
  for (const opacity of [0, 0.3, 1]) {
    await setOpacity(opacity);
    for (const [c, r] of picks) {
      const b = base(c, r);
      const want = colour(gx(c, r)).map((l) => opacity * l + (1 - opacity) * b);
      const got = await canvasAt(page, c, r);
      assert.ok(got.every((x, k) => Math.abs(x - want[k]) <= 2), `opacity ${opacity} at (${c}, ${r}), gx ${gx(c, r)}: drawn ${got}, expected ${want.map(Math.round)}`);
    }
  }
  // the inspector gives the layer's value too
  await hoverPixel(page, ...picks[0]);
  assert.match(await page.textContent("#lab-inspector"), new RegExp(` · gx ${gx(...picks[0])}$`.replace("-", "\\-")));
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("many points: the small ones stamped (Förstner's ellipses, Moravec's dots), the ones out of view left out, the view as when every shape is stroked", { timeout: TEST_TIMEOUT * 2 }, async () => {
  const { page, log, context } = await openLab();
  await page.waitForFunction(() => document.body.dataset.labRestored === "1" && document.body.dataset.lab === "idle", null, { timeout: 60_000 });
  // a 3000 × 2000 board of 40-pixel squares: a few thousand corners, far enough apart on screen that their rings do not touch
  await page.evaluate(async () => {
    const [w, h] = [3000, 2000];
    const bytes = new Uint8Array(w * h);
    for (let r = 0; r < h; r++) for (let c = 0; c < w; c++) bytes[r * w + c] = ((Math.floor(c / 40) + Math.floor(r / 40)) & 1 ? 200 : 40) + ((c * 7 + r * 13) % 5);
    await (await import("./lab/lab.js")).openRawForTests(w, h, bytes, "board");
  });
  await page.waitForFunction(() => document.body.dataset.image === "board");
  await idle(page);
  await page.selectOption("#lab-family", "interest");
  await page.click("#lab-run");
  await page.waitForFunction(() => Number(document.body.dataset.points) > 0);
  await idle(page);
  // the view's shapes as drawn (the panel's cached canvas) against all of them stroked on a canvas of their own
  const compare = () => page.evaluate(async () => {
    const v = (await import("./lab/lab.js")).viewerForTests();
    v.draw();
    const cache = v.shapeCache.get(0).canvas;
    const [w, h] = [cache.width, cache.height];
    const drawn = cache.getContext("2d").getImageData(0, 0, w, h).data;
    const ref = new OffscreenCanvas(w, h).getContext("2d");
    ref.setTransform(v.zoom, 0, 0, v.zoom, v.ox, v.oy);
    v.drawShapes(ref);
    const stroked = ref.getImageData(0, 0, w, h).data;
    const near = (d, x, y) => {
      for (let j = Math.max(0, y - 1); j <= Math.min(h - 1, y + 1); j++) for (let i = Math.max(0, x - 1); i <= Math.min(w - 1, x + 1); i++) if (d[4 * (j * w + i) + 3] > 0) return true;
      return false;
    };
    // pixels at least half covered in one with nothing within a pixel in the other, and the colour of the covered ones
    // the points: one batch (interest.js), its ellipses' semi-axes σ × magnify
    const [batch] = v.shapes;
    const n = batch.p.length / 6;
    const stamped = Array.from({ length: n }, (_, i) => Math.max(batch.p[6 * i + 3], batch.p[6 * i + 4]) * batch.magnify * v.zoom <= 2).filter(Boolean).length;
    const out = { shapes: n, stamped, batches: v.shapes.length, kind: batch.kind, zoom: v.zoom, drawn: 0, stroked: 0, onlyDrawn: 0, onlyStroked: 0, colours: new Set() };
    for (let y = 0; y < h; y++) {
      for (let x = 0; x < w; x++) {
        const k = 4 * (y * w + x);
        if (drawn[k + 3] >= 128) {
          out.drawn++;
          if (!near(stroked, x, y)) out.onlyDrawn++;
          if (drawn[k + 3] === 255) out.colours.add(Array.from(drawn.slice(k, k + 3)).join(","));
        }
        if (stroked[k + 3] >= 128) {
          out.stroked++;
          if (!near(drawn, x, y)) out.onlyStroked++;
        }
      }
    }
    return { ...out, colours: [...out.colours] };
  });
  const fit = await compare();
  assert.ok(fit.kind === "points" && fit.batches === 1, `the points drawn as one batch: ${fit.batches} shapes, ${fit.kind}`);
  assert.ok(fit.shapes >= 1000 && fit.stamped === fit.shapes, `at the fit (zoom ${fit.zoom}), ${fit.stamped} of ${fit.shapes} points small enough to stamp`);
  for (const [what, c] of [["the fit", fit]]) {
    assert.ok(c.drawn > 0 && Math.abs(c.drawn - c.stroked) <= 0.1 * c.stroked, `${what}: ${c.drawn} pixels drawn, ${c.stroked} stroked`);
    assert.equal(c.onlyDrawn + c.onlyStroked, 0, `${what}: ${c.onlyDrawn} drawn pixels with none stroked within a pixel, ${c.onlyStroked} the other way`);
    assert.deepEqual(c.colours, ["255,140,0"]);
  }
  // zoomed in about a corner (1520, 1000): most points out of view, the ones in view stroked (larger than the least size)
  await page.evaluate(async () => {
    const v = (await import("./lab/lab.js")).viewerForTests();
    v.zoomAt(100, 1520 * v.zoom + v.ox, 1000 * v.zoom + v.oy);
  });
  const zoomed = await compare();
  assert.ok(zoomed.stamped < zoomed.shapes && zoomed.drawn > 0, `zoomed in (zoom ${zoomed.zoom}): ${zoomed.stamped} of ${zoomed.shapes} points small enough to stamp, ${zoomed.drawn} pixels drawn`);
  assert.ok(Math.abs(zoomed.drawn - zoomed.stroked) <= 0.02 * zoomed.stroked && zoomed.onlyDrawn + zoomed.onlyStroked === 0, `zoomed in: ${JSON.stringify(zoomed)}`);
  // Moravec's dots, at the fit: stamped, as they are stroked
  await page.evaluate(async () => (await import("./lab/lab.js")).viewerForTests().fit());
  await page.selectOption("#lab-interest", "moravec");
  await page.evaluate(() => delete document.body.dataset.points);
  await page.click("#lab-run");
  await page.waitForFunction(() => Number(document.body.dataset.points) > 0);
  await idle(page);
  const dots = await compare();
  assert.ok(dots.shapes >= 1000 && dots.drawn > 0 && Math.abs(dots.drawn - dots.stroked) <= 0.1 * dots.stroked, `Moravec's ${dots.shapes} dots: ${dots.drawn} pixels drawn, ${dots.stroked} stroked`);
  assert.equal(dots.onlyDrawn + dots.onlyStroked, 0, `Moravec's dots: ${JSON.stringify(dots)}`);
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("the engine line: the SIMD128 build on as many threads as cores (at most 8), with or without cross-origin isolation", { timeout: TEST_TIMEOUT * 2 }, async () => {
  const { page, log, context } = await openLab();
  await page.waitForFunction(() => !/starting/.test(document.getElementById("lab-engine").textContent));
  assert.equal(await page.evaluate(() => globalThis.crossOriginIsolated), false);
  const words = (n) => (n > 1 ? `Engine: fast (SIMD), ${n} threads.` : "Engine: fast (SIMD), 1 thread.");
  const n = Math.min(8, await page.evaluate(() => navigator.hardwareConcurrency));
  // in a student's words: no build details
  assert.equal(await page.textContent("#lab-engine"), words(n));
  assert.equal(await page.getAttribute("#lab-engine", "data-build"), "simd128");
  assert.equal(await page.getAttribute("#lab-engine", "data-threads"), String(n));
  // the line is the worker's own answer
  const engine = await page.evaluate(async () => {
    const { LabClient } = await import("./lab/lab.js");
    const c = new LabClient({ onRestart: async () => {} });
    const e = await c.call("engine");
    c.close();
    return e;
  });
  assert.deepEqual(engine, { build: "simd128", simd: true });
  assert.deepEqual(log.pageErrors, []);
  await context.close();

  const isolated = await startServer({ dir: DIST, port: 0, isolate: true });
  const browser = await launchChromium();
  try {
    const o = await openLab({}, isolated.url, browser);
    await o.page.waitForFunction(() => !/starting/.test(document.getElementById("lab-engine").textContent));
    assert.equal(await o.page.evaluate(() => globalThis.crossOriginIsolated), true);
    assert.equal(await o.page.textContent("#lab-engine"), words(n));
    assert.equal(await o.page.getAttribute("#lab-engine", "data-threads"), String(n));
    assert.deepEqual(o.log.pageErrors, []);
    await o.context.close();
  } finally {
    await browser.close().catch(() => {});
    await isolated.close();
  }
});
