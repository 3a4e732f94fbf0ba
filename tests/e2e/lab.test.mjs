// The image lab (#/lab) in Chromium: its module loads only when it opens,
// every sample opens and is drawn as its decoded grey, every file format
// opens (picked, dropped or pasted; 16-bit values kept), each operator
// family's layer equals the course's formulas worked out here at chosen
// pixels and is drawn in its legend's colours, a bad file is refused with
// its name and reason while the lab keeps working (banded runs equal one
// call: lab_tiles.test.mjs), a trapped worker is replaced with the image kept, an
// output pixel opens its worked example with the same number, and the
// fiducial workflow runs from the marks to the residuals.

import { test, before, after } from "node:test";
import assert from "node:assert/strict";
import fs from "node:fs";
import path from "node:path";
import zlib from "node:zlib";
import { start, open, settled, TEST_TIMEOUT } from "./harness.mjs";
import { idle, sample, forstner, openLab as openLabIn } from "./lab-harness.mjs";

const CORPUS = path.resolve("lab/tests/corpus");
let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

/** An 8-bit grey, non-interlaced PNG decoded by hand (chunks, zlib, the five row filters). */
function decodeGreyPng(buf) {
  let at = 8;
  let width = 0;
  let height = 0;
  const idat = [];
  while (at < buf.length) {
    const len = buf.readUInt32BE(at);
    const type = buf.toString("latin1", at + 4, at + 8);
    const body = buf.subarray(at + 8, at + 8 + len);
    if (type === "IHDR") {
      [width, height] = [body.readUInt32BE(0), body.readUInt32BE(4)];
      assert.deepEqual([body[8], body[9], body[12]], [8, 0, 0], "an 8-bit grey, non-interlaced PNG");
    }
    if (type === "IDAT") idat.push(body);
    at += 12 + len;
  }
  const raw = zlib.inflateSync(Buffer.concat(idat));
  const pixels = new Uint8Array(width * height);
  for (let r = 0; r < height; r++) {
    const f = raw[r * (width + 1)];
    for (let c = 0; c < width; c++) {
      const x = raw[r * (width + 1) + 1 + c];
      const a = c > 0 ? pixels[r * width + c - 1] : 0;
      const b = r > 0 ? pixels[(r - 1) * width + c] : 0;
      const cc = c > 0 && r > 0 ? pixels[(r - 1) * width + c - 1] : 0;
      const paeth = () => {
        const p = a + b - cc;
        const [pa, pb, pc] = [Math.abs(p - a), Math.abs(p - b), Math.abs(p - cc)];
        return pa <= pb && pa <= pc ? a : pb <= pc ? b : cc;
      };
      pixels[r * width + c] = (x + [0, a, b, (a + b) >> 1, f === 4 ? paeth() : 0][f]) & 255;
    }
  }
  return { width, height, pixels };
}

/** Mean |difference| of the main canvas's pixels between two grabs, and colour. */
async function canvasStats(page, selector = ".lab-canvas") {
  return page.$eval(selector, (cv) => {
    const d = cv.getContext("2d").getImageData(0, 0, cv.width, cv.height).data;
    let coloured = 0;
    let sum = 0;
    for (let i = 0; i < d.length; i += 4) {
      if (Math.abs(d[i] - d[i + 2]) > 40) coloured++;
      sum += d[i] + d[i + 1] + d[i + 2];
    }
    return { coloured, sum, n: d.length / 4 };
  });
}

/** Clicks image pixel (c, r) of the main view (page coordinates from the view's own geometry). */
async function clickPixel(page, c, r) {
  await page.locator("#lab-stage .lab-canvas").scrollIntoViewIfNeeded();
  const g = await page.evaluate(async () => (await import("./lab/lab.js")).viewForTests());
  await page.mouse.click(g.left + ((c + 0.5) * g.zoom + g.ox) * (g.w / g.cw), g.top + ((r + 0.5) * g.zoom + g.oy) * (g.h / g.ch));
}

/** Moves the mouse over image pixel (c, r) of the main view. */
async function hoverPixel(page, c, r) {
  await page.locator("#lab-stage .lab-canvas").scrollIntoViewIfNeeded();
  const g = await page.evaluate(async () => (await import("./lab/lab.js")).viewForTests());
  await page.mouse.move(g.left + ((c + 0.5) * g.zoom + g.ox) * (g.w / g.cw), g.top + ((r + 0.5) * g.zoom + g.oy) * (g.h / g.ch));
}

/** Follows the explain link and reads the example's exact result. */
async function followExplain(page, selector = "#lab-explain-link") {
  const a = page.locator(selector).first();
  const key = await a.getAttribute("data-key");
  const index = (await a.getAttribute("data-index")) || "";
  const href = await a.getAttribute("href");
  await page.goto(new URL(href, page.url()).href);
  assert.equal(await settled(page), "ok", `${href} did not solve`);
  const raw = await page.locator(`.result-table tr[data-key="${key}"] td.exact`).getAttribute("data-value");
  let v = JSON.parse(raw);
  for (const i of index.split(",").filter(Boolean).map(Number)) v = v[i];
  return { v, key, href };
}

test("the lab loads its own module only when it opens, and every sample opens", { timeout: TEST_TIMEOUT * 3 }, async () => {
  const { page, log, context } = await open(env.browser);
  await page.goto(`${env.url}index.html#/`);
  await settled(page);
  assert.ok(!log.requests.some((u) => u.includes("photogrammetry_lab")), "the lab's wasm was fetched before the lab opened");
  await page.click('a[href="#/lab"]');
  await page.waitForSelector("#lab-sample");
  for (const [id, w, h] of [["aero1.jpg", 0, 0], ["aero3.jpg", 0, 0], ["left01.jpg", 640, 480], ["camera.png", 512, 512], ["brick.png", 512, 512], ["frame", 1000, 1000]]) {
    await sample(page, id);
    const info = await page.textContent("#lab-info");
    if (w) assert.match(info, new RegExp(`${w} × ${h} pixels`), info);
    // the photo is drawn: at a few pixels the canvas shows the decoded grey, stretched from its range to 0…255
    const { g, w: iw, h: ih } = await greyOf(page);
    let [glo, ghi] = [Infinity, -Infinity];
    for (let r = 0; r < ih; r++) for (let c = 0; c < iw; c++) [glo, ghi] = [Math.min(glo, g(c, r)), Math.max(ghi, g(c, r))];
    // (a view smaller than the photo samples one of the pixels about (c, r))
    const { zoom } = await page.evaluate(async () => (await import("./lab/lab.js")).viewForTests());
    const near = zoom >= 1 ? [[0, 0]] : [-1, 0, 1].flatMap((dr) => [-1, 0, 1].map((dc) => [dc, dr]));
    for (const [c, r] of [[0, 0], [iw - 1, ih - 1], [iw >> 1, ih >> 2], [iw >> 2, (3 * ih) >> 2]]) {
      const wants = near.map(([dc, dr]) => Math.round(((g(c + dc, r + dr) - glo) / (ghi - glo)) * 255));
      const rgb = await canvasAt(page, c, r);
      assert.ok(rgb[0] === rgb[1] && rgb[1] === rgb[2] && wants.some((want) => Math.abs(rgb[0] - want) <= 1), `${id} at (${c}, ${r}), zoom ${zoom}: drawn ${rgb}, grey stretched ${wants}`);
    }
    // the PNG samples: the lab's grey values are the file's own, decoded here by zlib
    if (id.endsWith(".png")) {
      const png = decodeGreyPng(fs.readFileSync(path.resolve("www/lab/samples", id)));
      assert.deepEqual([png.width, png.height], [iw, ih]);
      for (let r = 0; r < ih; r += 7) for (let c = 0; c < iw; c += 3) assert.equal(g(c, r), png.pixels[r * iw + c], `${id} (${c}, ${r})`);
    }
    // OpenCV's photos link their licence's full text (kept beside them)
    const licence = page.locator("#lab-sample-licence");
    if (/^(aero|left)/.test(id)) {
      const text = await page.evaluate(async (href) => (await fetch(href)).text(), await licence.getAttribute("href"));
      assert.match(text, /Apache License\s+Version 2\.0, January 2004/);
    } else assert.equal(await licence.count(), 0, id);
  }
  assert.ok(log.requests.some((u) => /photogrammetry_lab_bg(-\w{8})?\.wasm$/.test(u)));
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("an example with an operator of the lab links to it, its family chosen", { timeout: TEST_TIMEOUT }, async () => {
  const { page, log, context } = await open(env.browser);
  for (const [id, family] of [["forstner-window", "interest"], ["filter-window", "filters"], ["chain-code", "boundaries"], ["ncc-2d", "correlation"]]) {
    await page.goto(`${env.url}index.html#/${id}`);
    await settled(page);
    await page.getByRole("link", { name: "Try it on a photo" }).click();
    await page.waitForSelector("#lab-family");
    assert.equal(await page.inputValue("#lab-family"), family, id);
  }
  // an example the lab has no operator for has no such link
  await page.goto(`${env.url}index.html#/gsd`);
  await settled(page);
  assert.equal(await page.getByRole("link", { name: "Try it on a photo" }).count(), 0);
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("files of each format open; a bad file says its name and why, and the lab keeps working", { timeout: TEST_TIMEOUT * 2 }, async () => {
  const { page, log, context } = await openLab();
  for (const [file, w, h, kind] of [["grey8.png", 4, 3, "PNG, grey, 8-bit"], ["grey16.png", 4, 3, "PNG, grey, 16-bit"], ["rgb8.png", 4, 3, "PNG, colour"],
    ["blocks.jpg", 16, 8, "JPEG, grey"], ["colour.jpg", 8, 8, "JPEG, colour"], ["grey8_strips.tif", 4, 3, "TIFF, grey, 8-bit"],
    ["grey16_strips.tif", 4, 3, "TIFF, grey, 16-bit"], ["rgb8_tiles.tif", 4, 3, "TIFF, colour"], ["rgb16_strips.tif", 4, 3, "TIFF, colour"]]) {
    await page.setInputFiles("#lab-file", path.join(CORPUS, file));
    await page.waitForFunction((f) => document.body.dataset.image === f, file);
    const info = await page.textContent("#lab-info");
    assert.ok(info.includes(`${w} × ${h} pixels`) && info.includes(kind), info);
  }
  // the 16-bit value is kept: hover the last pixel of grey16.png, whose value make_corpus.py
  // writes as 1000·c + 20000·r + 7 = 43007 at (3, 2) (more than 8 bits can hold)
  await page.setInputFiles("#lab-file", path.join(CORPUS, "grey16.png"));
  await page.waitForFunction(() => document.body.dataset.image === "grey16.png");
  await idle(page);
  for (const [c, r] of [[3, 2], [0, 0], [1, 2]]) {
    await hoverPixel(page, c, r);
    assert.equal(await page.textContent("#lab-inspector"), `c ${c}, r ${r} · grey ${1000 * c + 20000 * r + 7}`);
  }
  for (const [file, says] of [["truncated.png", "PNG"], ["bad_crc.png", "damaged"], ["zero_width.png", "PNG"], ["huge_header.png", "too large"],
    ["bomb.png", "megapixels"], ["missing_tag.tif", "TIFF"], ["text.png", "not a PNG, JPEG or TIFF"], ["empty.png", "empty"], ["truncated.jpg", "cut short"]]) {
    await page.setInputFiles("#lab-file", path.join(CORPUS, file));
    // wait for this file's message: the previous file's is still on screen until the worker answers
    await page.waitForFunction((f) => {
      const e = document.getElementById("lab-error");
      return !e.hidden && e.textContent.startsWith(`${f}: `);
    }, file);
    const msg = await page.textContent("#lab-error");
    assert.ok(msg.startsWith(`${file}: `) && msg.includes(says), msg);
    // still the last good image
    assert.equal(await page.evaluate(() => document.body.dataset.image), "grey16.png");
  }
  // and the lab still works on it
  await page.selectOption("#lab-family", "filters");
  await page.selectOption("#lab-kernel", "mean");
  await page.click("#lab-run");
  await idle(page);
  assert.equal(await page.evaluate(() => document.body.dataset.layer), "mean");
  assert.equal(await page.locator("#lab-error").isHidden(), true);
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("a file dropped on the lab or pasted into it opens, its pixels decoded", { timeout: TEST_TIMEOUT }, async () => {
  const { page, log, context } = await openLab();
  const file = async (name, type) => ({ name, type, bytes: [...fs.readFileSync(path.join(CORPUS, name))] });
  // drop: a drop event on the lab carrying a DataTransfer with the file
  await page.evaluate(({ name, type, bytes }) => {
    const dt = new DataTransfer();
    dt.items.add(new File([new Uint8Array(bytes)], name, { type }));
    const lab = document.getElementById("lab");
    lab.dispatchEvent(new DragEvent("dragover", { dataTransfer: dt, bubbles: true, cancelable: true }));
    lab.dispatchEvent(new DragEvent("drop", { dataTransfer: dt, bubbles: true, cancelable: true }));
  }, await file("grey8_strips.tif", "image/tiff"));
  await page.waitForFunction(() => document.body.dataset.image === "grey8_strips.tif");
  await idle(page);
  assert.match(await page.textContent("#lab-info"), /4 × 3 pixels, TIFF, grey, 8-bit/);
  assert.equal(await page.evaluate(() => document.getElementById("lab").classList.contains("lab-drop")), false);
  // grey8 in make_corpus.py: 10·c + 40·r
  const grey8 = (c, r) => 10 * c + 40 * r;
  assert.deepEqual(await page.evaluate(async () => (await import("./lab/lab.js")).greyForTests([0, 0, 4, 3])),
    [0, 1, 2].flatMap((r) => [0, 1, 2, 3].map((c) => grey8(c, r))));
  // paste: a paste event whose clipboard holds the file
  await page.evaluate(({ name, type, bytes }) => {
    const dt = new DataTransfer();
    dt.items.add(new File([new Uint8Array(bytes)], name, { type }));
    document.dispatchEvent(new ClipboardEvent("paste", { clipboardData: dt, bubbles: true, cancelable: true }));
  }, await file("grey16.png", "image/png"));
  await page.waitForFunction(() => document.body.dataset.image === "grey16.png");
  await idle(page);
  assert.deepEqual(await page.evaluate(async () => (await import("./lab/lab.js")).greyForTests([0, 0, 4, 3])),
    [0, 1, 2].flatMap((r) => [0, 1, 2, 3].map((c) => 1000 * c + 20000 * r + 7)));
  assert.equal(await page.locator("#lab-error").isHidden(), true);
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

// ------------------------------------------------------------------ the values of each family, worked out here

/** The photo's grey values as a function g(c, r), the edge replicated (the lab's default border). */
async function greyOf(page) {
  const info = await page.$eval("#lab-info", (e) => e.textContent);
  const [, w, h] = info.match(/(\d+) × (\d+) pixels/).map(Number);
  const grey = await page.evaluate(async ([w, h]) => (await import("./lab/lab.js")).greyForTests([0, 0, w, h]), [w, h]);
  const g = (c, r) => grey[Math.min(h - 1, Math.max(0, r)) * w + Math.min(w - 1, Math.max(0, c))];
  return { g, w, h };
}

/** Σ k[j][i] · g(c + i − a, r + j − a) / d: a kernel applied as written (no flip), centred. */
function correlate(g, k, d, c, r) {
  const a = (k.length - 1) / 2;
  let s = 0;
  for (let j = 0; j < k.length; j++) for (let i = 0; i < k.length; i++) s += k[j][i] * g(c + i - a, r + j - a);
  return s / d;
}

const KERNELS = {
  mean: [[[1, 1, 1], [1, 1, 1], [1, 1, 1]], 9],
  "gaussian-5": [[[1, 4, 6, 4, 1], [4, 16, 24, 16, 4], [6, 24, 36, 24, 6], [4, 16, 24, 16, 4], [1, 4, 6, 4, 1]], 256],
  "laplacian-8": [[[1, 1, 1], [1, -8, 1], [1, 1, 1]], 1],
  sharpen: [[[1, -8, 1], [-8, 37, -8], [1, -8, 1]], 9],
};
// the course's edge kernels (seed 000): gx = top row minus bottom row, gy = right column minus left
const EDGE = {
  sobel: { gx: [[1, 2, 1], [0, 0, 0], [-1, -2, -1]], gy: [[-1, 0, 1], [-2, 0, 2], [-1, 0, 1]] },
  prewitt: { gx: [[1, 1, 1], [0, 0, 0], [-1, -1, -1]], gy: [[-1, 0, 1], [-1, 0, 1], [-1, 0, 1]] },
};

function median3(g, c, r) {
  const v = [];
  for (let j = -1; j <= 1; j++) for (let i = -1; i <= 1; i++) v.push(g(c + i, r + j));
  return v.sort((a, b) => a - b)[4];
}

/** Moravec's mean of the four squared directional differences over the interior of the size×size window anchored at (c, r) (Example 14). */
function moravec(g, c, r, size) {
  const a = Math.floor((size - 1) / 2);
  let s = 0;
  let n = 0;
  for (let y = r - a + 1; y <= r - a + size - 2; y++) {
    for (let x = c - a + 1; x <= c - a + size - 2; x++) {
      s += (g(x + 1, y) - g(x - 1, y)) ** 2 + (g(x, y + 1) - g(x, y - 1)) ** 2 + (g(x + 1, y + 1) - g(x - 1, y - 1)) ** 2 + (g(x - 1, y + 1) - g(x + 1, y - 1)) ** 2;
      n++;
    }
  }
  return s / n;
}

/** The colour the lab's legend promises for v: grey from black (min) to white (max); signed: blue (−m) – white (0) – red (+m), m = max |v|. */
function colourOf(v, { signed, min, max }) {
  if (!signed) {
    const g = Math.round(((v - min) / (max > min ? max - min : 1)) * 255);
    return [g, g, g];
  }
  const t = v / (Math.max(Math.abs(min), Math.abs(max)) || 1);
  const end = t < 0 ? [29, 95, 191] : [217, 119, 6];
  const u = Math.min(1, Math.abs(t));
  return end.map((e) => Math.round(255 - u * (255 - e)));
}

/** The main canvas's RGB at the centre of image pixel (c, r). */
async function canvasAt(page, c, r) {
  return page.evaluate(async ([c, r]) => {
    const g = (await import("./lab/lab.js")).viewForTests();
    const cv = document.querySelector("#lab-stage .lab-canvas");
    const x = Math.floor((c + 0.5) * g.zoom + g.ox);
    const y = Math.floor((r + 0.5) * g.zoom + g.oy);
    return Array.from(cv.getContext("2d").getImageData(x, y, 1, 1).data.slice(0, 3));
  }, [c, r]);
}

const layerAt = (page, name, pixels) => page.evaluate(async ([n, p]) => (await import("./lab/lab.js")).layerForTests(n, p), [name, pixels]);

const close = (a, b, tol = 1e-4) => Math.abs(a - b) <= tol * Math.max(1, Math.abs(b));

test("each operator family: the layer's values at chosen pixels equal the course's formulas worked out here, drawn in the legend's colours", { timeout: TEST_TIMEOUT * 4 }, async () => {
  const { page, log, context } = await openLab();
  await sample(page, "camera.png");
  const { g } = await greyOf(page);
  // corners and edges (the replicated border) and the inside
  const pixels = [[0, 0], [511, 511], [0, 300], [511, 7], [200, 300], [250, 150], [300, 300], [100, 420], [37, 481], [401, 66]];
  const inner = pixels.filter(([c, r]) => c >= 8 && r >= 8 && c < 504 && r < 504);
  const g3 = (k) => (c, r) => correlate(g, ...KERNELS[k], c, r);
  const runs = [
    ["filters", { "#lab-kernel": "mean" }, { mean: g3("mean") }, pixels],
    ["filters", { "#lab-kernel": "gaussian-5" }, { "gaussian-5": g3("gaussian-5") }, pixels],
    ["filters", { "#lab-kernel": "laplacian-8" }, { "laplacian-8": g3("laplacian-8") }, pixels],
    ["filters", { "#lab-kernel": "sharpen" }, { sharpen: g3("sharpen") }, pixels],
    ["filters", { "#lab-kernel": "median" }, { median: (c, r) => median3(g, c, r) }, pixels],
    ...["sobel", "prewitt"].map((op) => ["edges", { "#lab-operator": op }, {
      gx: (c, r) => correlate(g, EDGE[op].gx, 1, c, r),
      gy: (c, r) => correlate(g, EDGE[op].gy, 1, c, r),
      magnitude: (c, r) => Math.hypot(correlate(g, EDGE[op].gx, 1, c, r), correlate(g, EDGE[op].gy, 1, c, r)),
      direction: (c, r) => (Math.atan2(correlate(g, EDGE[op].gy, 1, c, r), correlate(g, EDGE[op].gx, 1, c, r)) * 180) / Math.PI,
    }, pixels]),
    ["interest", { "#lab-interest": "forstner" }, { w: (c, r) => forstner(g, c, r, 5).w, q: (c, r) => forstner(g, c, r, 5).q }, inner],
    ["interest", { "#lab-interest": "moravec" }, { moravec: (c, r) => moravec(g, c, r, 4) }, inner],
  ];
  for (const [family, setup, want, at] of runs) {
    await page.selectOption("#lab-family", family);
    for (const [sel, v] of Object.entries(setup)) await page.selectOption(sel, v);
    await page.click("#lab-run");
    await idle(page);
    if (family === "interest") await page.waitForFunction(() => document.body.dataset.forstnerLive !== "busy");
    const what = `${family} ${Object.values(setup).join(" ")}`;
    for (const [name, f] of Object.entries(want)) {
      const got = await layerAt(page, name, at);
      assert.ok(got, `${what}: no layer ${name}`);
      at.forEach(([c, r], i) => {
        const v = got.values[i];
        assert.ok(v !== null && close(v, f(c, r)), `${what} ${name} at (${c}, ${r}): the lab ${v}, worked out here ${f(c, r)}`);
      });
    }
    // the shown layer's pixels are drawn in the legend's colours (opacity 1: the layer alone; the
    // interest families' points are drawn on top, so their colours are not read)
    if (family === "interest") continue;
    await page.$eval("#lab-opacity", (i) => {
      i.value = "1";
      i.dispatchEvent(new Event("input", { bubbles: true }));
    });
    for (const name of family === "edges" ? ["gx", "magnitude"] : Object.keys(want)) {
      await page.selectOption("#lab-layer", { label: name });
      const got = await layerAt(page, name, pixels);
      const legend = await page.textContent("#lab-legend");
      if (got.signed) {
        const m = Math.max(Math.abs(got.min), Math.abs(got.max));
        assert.ok(legend.includes(`−${Number(m.toPrecision(5))}`) && legend.includes("blue negative, orange positive"), `${name}: ${legend}`);
      }
      for (const [i, [c, r]] of pixels.entries()) {
        const rgb = await canvasAt(page, c, r);
        const exp = colourOf(got.values[i], got);
        assert.ok(rgb.every((x, k) => Math.abs(x - exp[k]) <= 2), `${what} ${name} ${got.values[i]} at (${c}, ${r}) drawn ${rgb}, the legend says ${exp}`);
      }
    }
    await page.$eval("#lab-opacity", (i) => {
      i.value = "0.7";
      i.dispatchEvent(new Event("input", { bubbles: true }));
    });
  }
  // the signed layers were signed, the others not
  assert.equal((await layerAt(page, "moravec", [])).signed, false);
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("a clicked pixel of each family opens its worked example with the same number (Prewitt's gx and gy too)", { timeout: TEST_TIMEOUT * 5 }, async () => {
  const { page, log, context } = await openLab();
  const checks = [
    // family, set-up, layer to show, pixel
    ["filters", async () => page.selectOption("#lab-kernel", "gaussian-5"), "gaussian-5", [200, 300]],
    ["filters", async () => page.selectOption("#lab-kernel", "median"), "median", [250, 150]],
    ["edges", async () => page.selectOption("#lab-operator", "sobel"), "magnitude", [300, 300]],
    ["edges", async () => page.selectOption("#lab-operator", "prewitt"), "gx", [300, 300]],
    ["edges", async () => page.selectOption("#lab-operator", "prewitt"), "gy", [120, 222]],
    ["edges", async () => page.selectOption("#lab-operator", "sobel"), "direction", [310, 290]],
    ["interest", async () => page.selectOption("#lab-interest", "forstner"), "w", [260, 120]],
    ["interest", async () => page.selectOption("#lab-interest", "moravec"), "moravec", [100, 420]],
  ];
  for (const [family, setup, layer, [c, r]] of checks) {
    await page.goto(`${env.url}index.html#/lab`);
    await page.waitForSelector("#lab-sample");
    await sample(page, "camera.png");
    await page.selectOption("#lab-family", family);
    await setup();
    await page.click("#lab-run");
    await idle(page);
    if (family === "interest") await page.waitForFunction(() => document.body.dataset.forstnerLive !== "busy");
    await page.selectOption("#lab-layer", { label: layer });
    assert.equal(await page.evaluate(() => document.body.dataset.layer), layer);
    const inLab = (await layerAt(page, layer, [[c, r]])).values[0];
    await clickPixel(page, c, r);
    await page.waitForSelector("#lab-explain-link");
    assert.match(await page.textContent("#lab-explain"), new RegExp(`at column ${c}, row ${r}:`));
    // the exact value (the example's number), the layer's own f32 value beside it: the exact one
    // rounded to f32 (the direction: within 1e-4°, docs/lab.md)
    const shown = Number(await page.getAttribute("#lab-explain-value", "data-value"));
    assert.equal(Number(await page.getAttribute("#lab-layer-value", "data-value")), inLab, `${family}/${layer}: the layer's value beside`);
    if (layer === "direction") assert.ok(Math.abs(shown - inLab) <= 1e-4, `direction at (${c}, ${r}): ${shown} vs ${inLab}`);
    else assert.equal(Math.fround(shown), inLab, `${family}/${layer}: the explained value is the layer's at (${c}, ${r}), rounded to f32`);
    if (layer === "direction") {
      // edge-window has no direction result: the link opens the same window, and the lab says how the layer follows
      assert.match(await page.textContent("#lab-explain"), /atan2\(Gy, Gx\) in degrees/);
      const { v: gx, href } = await followExplain(page);
      assert.match(href, /#\/edge-window.*operator=sobel/, href);
      const gy = JSON.parse(await page.locator('.result-table tr[data-key="selected_gy"] td.exact').getAttribute("data-value"));
      const want = (Math.atan2(gy, gx) * 180) / Math.PI;
      assert.ok(Math.abs(want - shown) < 1e-9, `${href}: atan2 of the example's gy ${gy}, gx ${gx} is ${want}; the lab showed ${shown}`);
      continue;
    }
    const { v, href } = await followExplain(page);
    if (family === "edges") assert.match(href, new RegExp(`#/edge-window.*operator=${layer === "magnitude" ? "sobel" : "prewitt"}`), href);
    assert.equal(v, shown, `${href}: the example gives ${v}, the lab showed ${shown}`);
  }
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("correlation: NCC surface, subpixel and LSM on the aerial pair, each explained by its example", { timeout: TEST_TIMEOUT * 2 }, async () => {
  const { page, log, context } = await openLab();
  await sample(page, "aero1.jpg");
  // the correlation family's module comes when the family is chosen, not with the lab
  const correlationModule = () => log.requests.filter((u) => /\/correlation(-\w{8})?\.js$/.test(u)).length;
  assert.equal(correlationModule(), 0, "the correlation family was fetched before it was chosen");
  await page.selectOption("#lab-family", "correlation");
  await page.selectOption("#lab-second", "same");
  assert.equal(correlationModule(), 1);
  await page.selectOption("#lab-template", "11");
  await page.fill("#lab-reach", "12");
  await clickPixel(page, 300, 200);
  await page.waitForSelector("#lab-match");
  await idle(page);
  const table = await page.textContent("#lab-match");
  // the template found in its own photo: ρ = 1 where it was cut out
  assert.match(table, /c \d+, r \d+, ρ = 1(?![.\d])/, table);
  const search = await canvasStats(page, ".lab-pair canvas");
  assert.ok(search.coloured > 100, "the NCC surface is drawn in colour");
  const rho = Number(await page.evaluate(() => document.body.dataset.rho));
  const links = await page.locator("#lab-explain a").evaluateAll((as) => as.map((a) => a.getAttribute("href")));
  assert.ok(links.some((h) => h.includes("#/ncc-2d")) && links.some((h) => h.includes("#/subpixel-2d")) && links.some((h) => h.includes("#/lsm-2d")), links.join(" "));
  const { v } = await followExplain(page, '#lab-explain a[href*="ncc-2d"]');
  assert.ok(Math.abs(v - rho) < 1e-12, `${v} vs ${rho}`);
  // the pair: search aero3 for the same template
  await page.goBack();
  await page.waitForSelector("#lab-sample");
  await sample(page, "aero1.jpg");
  await page.selectOption("#lab-family", "correlation");
  await page.selectOption("#lab-second", "pair");
  await page.selectOption("#lab-model", "affine");
  await clickPixel(page, 300, 200);
  await page.waitForSelector("#lab-match");
  await idle(page);
  assert.match(await page.textContent("#lab-match"), /LSM \(affine\), \d+ iterations/);
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("resampling side by side, boundaries with chain code, and the fiducial workflow", { timeout: TEST_TIMEOUT * 3 }, async () => {
  const { page, log, context } = await openLab();
  await sample(page, "brick.png");
  await page.selectOption("#lab-family", "resampling");
  await page.click("#lab-run");
  await idle(page);
  assert.equal(await page.evaluate(() => document.body.dataset.resampled), "nearest,bilinear,bicubic");
  const views = await page.locator("#lab-methods canvas").count();
  assert.equal(views, 3);
  const [n, b] = [await canvasStats(page, "#lab-methods figure:nth-child(1) canvas"), await canvasStats(page, "#lab-methods figure:nth-child(2) canvas")];
  assert.notEqual(n.sum, b.sum, "nearest and bilinear look different on the zoomed crop");
  // the same crop in the three: each view has the output's centre pixel at its own centre
  const centres = await page.$$eval("#lab-methods canvas", (cs) => cs.map((c) => c.labViewer.toImage(c.width / 2, c.height / 2).map((v) => Math.round(v * 100) / 100)));
  // brick.png is 512 × 512, and so is the output: its centre pixel is (256, 256)
  for (const xy of centres) assert.deepEqual(xy, [256, 256], `view centres ${JSON.stringify(centres)}`);
  // explain a bilinear pixel
  const bilinear = page.locator("#lab-methods figure:nth-child(2) canvas");
  const box = await bilinear.boundingBox();
  await bilinear.click({ position: { x: box.width / 2, y: box.height / 2 } });
  await page.waitForSelector("#lab-explain-link");
  const shown = Number(await page.getAttribute("#lab-explain-value", "data-value"));
  const r1 = await followExplain(page);
  assert.equal(r1.key, "bilinear");
  assert.ok(Math.abs(r1.v - shown) < 1e-9, `${r1.v} vs ${shown}`);

  // boundaries on the generated frame: a fiducial's disc is a bright region
  await page.goto(`${env.url}index.html#/lab`);
  await page.waitForSelector("#lab-sample");
  await sample(page, "frame");
  // the fiducials family's module comes when the family is chosen, not with the lab
  const fiducialsModule = () => log.requests.filter((u) => /\/fiducials(-\w{8})?\.js$/.test(u)).length;
  assert.equal(fiducialsModule(), 0, "the fiducials family was fetched before it was chosen");
  await page.selectOption("#lab-family", "fiducials");
  await page.waitForSelector("#lab-fid-start");
  assert.equal(fiducialsModule(), 1);
  // the lab measures the four marks itself (the student's own clicks: lab-interact.test.mjs)
  await page.click("#lab-run");
  await page.waitForSelector("#lab-fid-fit");
  await idle(page);
  const params = (await page.evaluate(() => document.body.dataset.fiducials)).split(",").map(Number);
  const truth = [0.2502, 0.0004, 0.12 - 0.2502 * 499.5 + 0.0004 * 499.5, -0.0003, 0.2497, 0.08 + 0.0003 * 499.5 + 0.2497 * 499.5];
  for (const i of [0, 1, 3, 4]) assert.ok(Math.abs(params[i] - truth[i]) < 1e-4, `${params} vs ${truth}`);
  for (const i of [2, 5]) assert.ok(Math.abs(params[i] - truth[i]) < 0.03, `${params} vs ${truth}`);
  const rows = await page.locator("#lab-fid-table tr").count();
  assert.equal(rows, 5);
  await page.click("#lab-fid-link");
  assert.equal(await settled(page), "ok");
  const fitted = JSON.parse(await page.locator('.result-table tr[data-key="parameters"] td.exact').getAttribute("data-value"));
  for (let i = 0; i < 6; i++) assert.ok(Math.abs(fitted[i] - params[i]) < 1e-9, `${fitted} vs ${params}`);

  await page.goto(`${env.url}index.html#/lab`);
  await page.waitForSelector("#lab-sample");
  await sample(page, "frame");
  await page.selectOption("#lab-family", "boundaries");
  await page.fill("#lab-bthreshold", "128");
  // the first mark's true centre is near (48.7, 500.1)
  await clickPixel(page, 49, 500);
  await page.waitForSelector("#lab-boundary");
  await idle(page);
  const code = await page.evaluate(() => document.body.dataset.code);
  assert.ok(code.length > 20 && /^[1-8]+$/.test(code), code);
  const r2 = await followExplain(page, '#lab-explain a[href*="chain-code"]');
  assert.equal(r2.v.join(""), code);
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("a trap in the worker is recovered: a fresh worker, the image and settings kept", { timeout: TEST_TIMEOUT }, async () => {
  const { page, context } = await openLab();
  await sample(page, "camera.png");
  await page.selectOption("#lab-family", "filters");
  await page.selectOption("#lab-kernel", "sharpen");
  // the test hook: make the worker's wasm execute `unreachable`
  await page.evaluate(async () => {
    const lab = await import("./lab/lab.js");
    return lab.trapForTests();
  });
  await page.waitForFunction(() => /stopped unexpectedly/.test(document.getElementById("lab-error").textContent));
  await idle(page);
  assert.equal(await page.inputValue("#lab-kernel"), "sharpen");
  await page.click("#lab-run");
  await idle(page);
  assert.equal(await page.evaluate(() => document.body.dataset.layer), "sharpen");
  assert.equal(await page.evaluate(() => document.body.dataset.image), "camera.png");
  await context.close();
});

/** A fresh page on the lab. */
function openLab(options) {
  return openLabIn(env, options);
}
