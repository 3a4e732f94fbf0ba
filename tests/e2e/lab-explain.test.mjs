// "Explain this pixel" in Chromium, value against value: every match of the
// lab (shift, shift + radiometric, affine + radiometric) opens its worked
// example (subpixel-2d, lsm-2d, lsm-affine) and the example's result is the
// lab's number; an NCC surface pixel that is not the best opens ncc-2d with
// its ρ; a projective rectification from four clicked points is checked
// against a homography, bilinear and bicubic interpolation worked out here
// on the photo as the browser decodes it; an edge direction is atan2 of the
// gx and gy its example computes; after a trap the fresh worker's values
// are its examples' values.

import { test, before, after } from "node:test";
import assert from "node:assert/strict";
import { start, open, settled, TEST_TIMEOUT } from "./harness.mjs";
import { idle, sample, openLab as openLabIn } from "./lab-harness.mjs";

let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

/** Clicks the main canvas at image pixel (c, r) of the fitted image. */
async function clickPixel(page, c, r) {
  const sel = ".lab-canvas";
  const pos = await page.$eval(sel, (cv) => {
    const b = cv.getBoundingClientRect();
    return { w: b.width, h: b.height, cw: cv.width, ch: cv.height };
  });
  const info = await page.$eval("#lab-info", (e) => e.textContent);
  const [, w, h] = info.match(/(\d+) × (\d+) pixels/).map(Number);
  const zoom = Math.min(pos.cw / w, pos.ch / h);
  const x = ((c + 0.5) * zoom + (pos.cw - w * zoom) / 2) * (pos.w / pos.cw);
  const y = ((r + 0.5) * zoom + (pos.ch - h * zoom) / 2) * (pos.h / pos.ch);
  await page.click(sel, { position: { x, y } });
}

/**
 * Opens an example link (href relative to the lab page) in a second page of
 * the same context, so that the lab keeps its state, and reads result keys.
 */
async function results(context, base, href, keys) {
  const p = await context.newPage();
  try {
    await p.goto(new URL(href, base).href);
    assert.equal(await settled(p), "ok", `${href} did not solve`);
    const out = {};
    for (const k of keys) {
      const cell = p.locator(`.result-table tr[data-key="${k}"] td.exact`);
      const raw = await cell.getAttribute("data-value");
      // numbers carry their full precision in data-value; a word is its text
      out[k] = raw === null ? (await cell.innerText()).trim() : JSON.parse(raw);
    }
    return out;
  } finally {
    await p.close();
  }
}

const near = (a, b, tol = 1e-9) => Math.abs(a - b) <= tol;

/**
 * The example a link opens, in a second page: its answer line's item `key`
 * (the text shown and the number in it) and the result's exact value.
 */
async function answerOf(context, base, href, key) {
  const p = await context.newPage();
  try {
    await p.goto(new URL(href, base).href);
    assert.equal(await settled(p), "ok", `${href} did not solve`);
    const item = p.locator(`.answer-line .answer-item[data-key="${key}"]`);
    assert.equal(await item.count(), 1, `${href}: no ${key} in the answer line: ${await p.locator(".answer-line").innerText()}`);
    const text = (await item.locator("strong").innerText()).trim();
    const raw = await p.locator(`.result-table tr[data-key="${key}"] td.exact`).getAttribute("data-value");
    const exact = raw === null ? (await p.locator(`.result-table tr[data-key="${key}"] td.exact`).innerText()).trim() : JSON.parse(raw);
    return { text, exact, line: await p.locator(".answer-line").innerText() };
  } finally {
    await p.close();
  }
}

/** The answer line's number is `value` as shown: `value` rounded to the digits written. */
function showsValue(text, value, what) {
  const m = text.replace(/\u2212/g, "-").match(/^-?\d+(\.\d+)?(e-?\d+)?/);
  assert.ok(m, `${what}: no number in the answer "${text}"`);
  const decimals = (m[1] ?? ".").length - 1;
  assert.ok(Math.abs(Number(m[0]) - value) <= 0.5 * 10 ** -decimals * (1 + 1e-9) * (m[2] ? Math.abs(value) * 10 ** decimals : 1), `${what}: the answer line shows ${text}, the lab ${value}`);
}

/** Clicks (c, r), waits for the explanation: the lab's value and the link. */
async function explainAt(page, c, r) {
  await page.evaluate(() => document.getElementById("lab-explain").replaceChildren());
  await clickPixel(page, c, r);
  await page.waitForSelector("#lab-explain-link");
  const [pc, pr] = (await page.textContent("#lab-explain p")).match(/column (\d+), row (\d+)/).slice(1).map(Number);
  return {
    c: pc,
    r: pr,
    value: Number(await page.getAttribute("#lab-explain-value", "data-value")),
    // the layer's own value (f32) beside the exact one (issue 31, item 1)
    layer: Number(await page.getAttribute("#lab-layer-value", "data-value")),
    href: await page.getAttribute("#lab-explain-link", "href"),
    key: await page.getAttribute("#lab-explain-link", "data-key"),
  };
}

// Issue 29, item 1: every family's "Explain this pixel" opens its example
// with the clicked pixel selected, and the example's answer line (the line
// under its title) is the lab's number.

test("filters: the example selects the clicked pixel (the window's centre) and its answer line is the lab's value", { timeout: TEST_TIMEOUT * 2 }, async () => {
  const { page, log, context } = await openLab();
  await sample(page, "left01.jpg");
  await page.selectOption("#lab-family", "filters");
  for (const [kernel, side] of [["mean", 5], ["gaussian-5", 7], ["median", 5]]) {
    await page.selectOption("#lab-kernel", kernel);
    await page.click("#lab-run");
    await idle(page);
    const x = await explainAt(page, 320, 240);
    const q = new URLSearchParams(x.href.split("?")[1]);
    // the window of side k + 2 round the pixel: the pixel is its centre, (side + 1)/2 counted from 1
    assert.equal(q.get("select_c"), String((side + 1) / 2), x.href.slice(0, 60));
    assert.equal(q.get("select_r"), String((side + 1) / 2));
    assert.equal(x.key, "selected");
    const a = await answerOf(context, page.url(), x.href, "selected");
    assert.equal(a.exact, x.value, `${kernel} at (${x.c}, ${x.r}): the example's selected pixel ${a.exact}, the lab ${x.value}`);
    // the layer holds the exact value rounded to f32
    assert.equal(x.layer, Math.fround(x.value), `${kernel}: the layer's ${x.layer} beside the exact ${x.value}`);
    showsValue(a.text, x.value, `${kernel} at (${x.c}, ${x.r})`);
    assert.match(a.line, /^Output at the selected pixel = /);
  }
  // a custom kernel (3 rows × 5 columns): the window 5 × 7, its centre (4, 3)
  await page.selectOption("#lab-kernel", "custom");
  await page.fill("#lab-custom", "1 1 1 1 1\n1 2 3 2 1\n1 1 1 1 1");
  await page.click("#lab-run");
  await idle(page);
  const x = await explainAt(page, 100, 50);
  const q = new URLSearchParams(x.href.split("?")[1]);
  assert.deepEqual([q.get("select_c"), q.get("select_r")], ["4", "3"]);
  const a = await answerOf(context, page.url(), x.href, "selected");
  assert.ok(near(a.exact, x.value, 1e-12), `custom: ${a.exact} vs ${x.value}`);
  showsValue(a.text, x.value, "custom");
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("edges: gx, gy and the magnitude of the clicked pixel are the example's answer line", { timeout: TEST_TIMEOUT * 2 }, async () => {
  const { page, log, context } = await openLab();
  await sample(page, "left01.jpg");
  await page.selectOption("#lab-family", "edges");
  await page.selectOption("#lab-operator", "prewitt");
  await page.click("#lab-run");
  await idle(page);
  const names = await page.locator("#lab-layer option").allTextContents();
  for (const [layer, c, r] of [["magnitude", 320, 240], ["gx", 250, 170], ["gy", 0, 0]]) {
    await page.selectOption("#lab-layer", String(names.indexOf(layer)));
    const x = await explainAt(page, c, r);
    assert.equal(x.key, `selected_${layer}`);
    const q = new URLSearchParams(x.href.split("?")[1]);
    assert.deepEqual([q.get("select_c"), q.get("select_r")], ["3", "3"]);
    const a = await answerOf(context, page.url(), x.href, `selected_${layer}`);
    assert.equal(a.exact, x.value, `${layer} at (${x.c}, ${x.r})`);
    showsValue(a.text, x.value, `${layer} at (${x.c}, ${x.r})`);
  }
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("a colour photo: the filters' and edges' layers (fast, from its BT.601 greys) are the explained window's numbers", { timeout: TEST_TIMEOUT * 2 }, async () => {
  const { page, log, context } = await openLab();
  await sample(page, "aero1.jpg");
  assert.match(await page.textContent("#lab-info"), /colour/i);
  // the layer is the exact value rounded to f32, within half a step (and the reference's own f64 roundings)
  const f32near = (layer, exact, what) => assert.ok(Math.abs(layer - exact) <= Math.abs(exact) * 2 ** -24 * (1 + 1e-6) + 1e-9, `${what}: the layer's ${layer} beside the exact ${exact}`);
  await page.selectOption("#lab-family", "filters");
  for (const [kernel, side, taps] of [["gaussian-3", 5, [1, 2, 1, 2, 4, 2, 1, 2, 1].map((k) => k / 16)], ["median", 5, null]]) {
    await page.selectOption("#lab-kernel", kernel);
    await page.click("#lab-run");
    await idle(page);
    const x = await explainAt(page, 301, 203);
    const q = new URLSearchParams(x.href.split("?")[1]);
    // the explained window: the colour photo's greys (BT.601, three decimals at most), the ones the layer was made from
    const win = q.get("window").split(";").map((row) => row.split(",").map(Number));
    assert.equal(win.length, side);
    assert.ok(win.flat().some((v) => !Number.isInteger(v)) && win.flat().every((v) => Math.abs(v * 1000 - Math.round(v * 1000)) < 1e-6), q.get("window"));
    const inner = win.slice(1, 4).map((row) => row.slice(1, 4)).flat();
    const fromWindow = taps ? inner.reduce((s, v, i) => s + taps[i] * v, 0) : [...inner].sort((a, b) => a - b)[4];
    assert.ok(near(fromWindow, x.value, 1e-9), `${kernel}: the window's ${fromWindow} vs the lab's exact ${x.value}`);
    const a = await answerOf(context, page.url(), x.href, "selected");
    assert.equal(a.exact, x.value, `${kernel} at (${x.c}, ${x.r}): the example's ${a.exact}, the lab's ${x.value}`);
    f32near(x.layer, x.value, kernel);
  }
  await page.selectOption("#lab-family", "edges");
  await page.selectOption("#lab-operator", "sobel");
  await page.click("#lab-run");
  await idle(page);
  const names = await page.locator("#lab-layer option").allTextContents();
  await page.selectOption("#lab-layer", String(names.indexOf("magnitude")));
  const x = await explainAt(page, 250, 170);
  const a = await answerOf(context, page.url(), x.href, "selected_magnitude");
  assert.equal(a.exact, x.value, `magnitude at (${x.c}, ${x.r})`);
  f32near(x.layer, x.value, "magnitude");
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("interest operators: w and q of Förstner's window and Moravec's mean are the example's answer line", { timeout: TEST_TIMEOUT * 2 }, async () => {
  const { page, log, context } = await openLab();
  await sample(page, "left01.jpg");
  await page.selectOption("#lab-family", "interest");
  for (const [op, layer, key] of [["forstner", "w", "w"], ["forstner", "q", "q"], ["moravec", "moravec", "mean"]]) {
    await page.selectOption("#lab-interest", op);
    await page.click("#lab-run");
    await idle(page);
    await page.waitForFunction(() => document.body.dataset.forstnerLive !== "busy");
    await page.selectOption("#lab-layer", { label: layer });
    const x = await explainAt(page, 320, 240);
    const a = await answerOf(context, page.url(), x.href, key);
    assert.ok(near(a.exact, x.value, 1e-9 * Math.max(1, Math.abs(x.value))), `${op} ${layer}: ${a.exact} vs ${x.value}`);
    showsValue(a.text, x.value, `${op} ${layer}`);
  }
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("correlation: a surface pixel's ρ and the subpixel peak are their examples' answer lines", { timeout: TEST_TIMEOUT * 2 }, async () => {
  const { page, log, context } = await openLab();
  await sample(page, "aero1.jpg");
  await page.selectOption("#lab-family", "correlation");
  await page.selectOption("#lab-template", "15");
  await page.fill("#lab-reach", "10");
  await clickPixel(page, 300, 200);
  await page.waitForFunction(() => document.body.dataset.matched, null, { timeout: 30_000 });
  await idle(page);
  const sub = (await page.evaluate(() => document.body.dataset.subpixel)).split(",").map(Number);
  const href = await page.locator("#lab-explain a", { hasText: "subpixel-2d" }).getAttribute("href");
  const s = await answerOf(context, page.url(), href, "c_max");
  assert.ok(near(s.exact, sub[0]), `${s.exact} vs ${sub[0]}`);
  showsValue(s.text, sub[0], "c_max");
  const fig = page.locator(".lab-pair canvas").first();
  const box = await fig.boundingBox();
  await fig.click({ position: { x: box.width / 2 + 20, y: box.height / 2 + 15 } });
  await page.waitForSelector("#lab-explain-link");
  const rho = Number(await page.getAttribute("#lab-explain-value", "data-value"));
  const a = await answerOf(context, page.url(), await page.getAttribute("#lab-explain-link", "href"), "rho");
  assert.ok(near(a.exact, rho, 1e-12), `${a.exact} vs ${rho}`);
  showsValue(a.text, rho, "ρ");
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("resampling and boundaries: a rotated pixel's value and a region's chain code are their examples' answer lines", { timeout: TEST_TIMEOUT * 2 }, async () => {
  const { page, log, context } = await openLab();
  await sample(page, "camera.png");
  await page.selectOption("#lab-family", "resampling");
  await page.click("#lab-run");
  await page.waitForFunction(() => document.body.dataset.resampled === "nearest,bilinear,bicubic", null, { timeout: 30_000 });
  await idle(page);
  for (const [fig, method] of [[2, "bilinear"], [3, "bicubic"]]) {
    const canvas = page.locator(`#lab-methods figure:nth-child(${fig}) canvas`);
    const box = await canvas.boundingBox();
    await page.evaluate(() => document.getElementById("lab-explain").replaceChildren());
    await canvas.click({ position: { x: box.width / 2 + 13, y: box.height / 2 - 7 } });
    await page.waitForSelector("#lab-explain-link");
    const value = Number(await page.getAttribute("#lab-explain-value", "data-value"));
    const a = await answerOf(context, page.url(), await page.getAttribute("#lab-explain-link", "href"), method);
    assert.ok(near(a.exact, value, 1e-9), `${method}: ${a.exact} vs ${value}`);
    showsValue(a.text, value, method);
  }
  // boundaries: a fiducial's bright disc on the generated frame
  await sample(page, "frame");
  await page.selectOption("#lab-family", "boundaries");
  const truth = await page.evaluate(async () => (await import("./lab/lab.js")).truthForTests());
  await clickPixel(page, Math.round(truth.marks[0]), Math.round(truth.marks[1]));
  await page.waitForSelector("#lab-boundary");
  const code = await page.evaluate(() => document.body.dataset.code);
  const href = await page.locator("#lab-explain a").first().getAttribute("href");
  const a = await answerOf(context, page.url(), href, "code");
  assert.equal(String(a.exact).replace(/\D/g, ""), code);
  const shownDigits = a.text.replace(/\D/g, "");
  assert.ok(shownDigits.length > 0 && code.startsWith(shownDigits), `the answer line shows ${a.text.slice(0, 40)}; the lab's code ${code.slice(0, 20)}…`);
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("fiducials: the affine fitted to the lab's marks is Example 4's answer line", { timeout: TEST_TIMEOUT * 2 }, async () => {
  const { page, log, context } = await openLab();
  await sample(page, "frame");
  await page.selectOption("#lab-family", "fiducials");
  await page.click("#lab-run");
  await page.waitForSelector("#lab-fid-link");
  await idle(page);
  const lab = (await page.evaluate(() => document.body.dataset.fidAffine)).split(",").map(Number);
  const a = await answerOf(context, page.url(), await page.getAttribute("#lab-fid-link", "href"), "parameters");
  lab.forEach((v, k) => assert.ok(near(a.exact[k], v, 1e-9 * Math.max(1, Math.abs(v))), `a${k}: ${a.exact[k]} vs ${v}`));
  showsValue(a.text.replace(/^\[/, ""), lab[0], "the affine's first parameter");
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("every match explains: subpixel-2d, lsm-2d (shift, shift + radiometric), lsm-affine and a surface pixel give the lab's numbers", { timeout: TEST_TIMEOUT * 4 }, async () => {
  const { page, log, context } = await openLab();
  await sample(page, "aero1.jpg");
  await page.selectOption("#lab-family", "correlation");
  await page.selectOption("#lab-second", "pair");
  await page.selectOption("#lab-template", "21");
  await page.fill("#lab-reach", "30");
  for (const model of ["shift", "shift-radiometric", "affine"]) {
    await page.selectOption("#lab-model", model);
    await page.evaluate(() => delete document.body.dataset.matched);
    await clickPixel(page, 300, 200);
    await page.waitForFunction(() => document.body.dataset.matched, null, { timeout: 30_000 });
    await idle(page);
    const lsm = (await page.evaluate(() => document.body.dataset.lsm)).split(",").map(Number);
    const [p, wc, wr] = [lsm.slice(0, 8), lsm[8], lsm[9]];
    const sub = (await page.evaluate(() => document.body.dataset.subpixel)).split(",").map(Number);
    const hrefs = await page.locator("#lab-explain a").evaluateAll((as) => as.map((a) => a.getAttribute("href")));
    const find = (id) => {
      const h = hrefs.find((x) => x.includes(`#/${id}?`));
      assert.ok(h, `${model}: no ${id} link among ${hrefs.join(" ")}`);
      return h;
    };
    // the subpixel peak: the same quadric through the same 3×3 ρ
    const s = await results(context, page.url(), find("subpixel-2d"), ["c_max", "r_max"]);
    assert.ok(near(s.c_max, sub[0]) && near(s.r_max, sub[1]), `${model}: subpixel-2d ${s.c_max}, ${s.r_max} vs the lab's ${sub}`);
    if (model === "affine") {
      const href = find("lsm-affine");
      assert.ok(href.includes("pair=patches"), href.slice(0, 80));
      const r = await results(context, page.url(), href, ["parameters", "iterations", "status"]);
      // a1 a2 a4 a5 a7 a8 as they are; a3, a6 count from 1 in the window
      for (const k of [0, 1, 3, 4, 6, 7]) assert.ok(near(r.parameters[k], p[k]), `a${k + 1}: ${r.parameters[k]} vs ${p[k]}`);
      assert.ok(near(r.parameters[2] - 1 + wc, p[2] + wc) && near(r.parameters[5] - 1 + wr, p[5] + wr), `${r.parameters} vs ${p}`);
      assert.match(await page.textContent("#lab-match"), new RegExp(`LSM \\(affine\\), ${r.iterations} iterations, ${r.status}`));
    } else {
      const href = find("lsm-2d");
      assert.ok(href.includes(`radiometric=${model === "shift" ? "false" : "true"}`), href.slice(0, 80));
      const r = await results(context, page.url(), href, ["c", "r", "a", "b", "iterations", "status"]);
      // the lab's position in the photo: the window's origin plus the example's 1-based position less 1
      assert.ok(near(r.c - 1 + wc, p[2] + wc) && near(r.r - 1 + wr, p[5] + wr), `${model}: ${r.c}, ${r.r} vs ${p[2] + 1}, ${p[5] + 1}`);
      assert.ok(near(r.a, p[6]) && near(r.b, p[7]), `${model}: a ${r.a}, b ${r.b} vs ${p[6]}, ${p[7]}`);
      if (model === "shift") assert.deepEqual([r.a, r.b], [1, 0]);
      assert.match(await page.textContent("#lab-match"), new RegExp(`LSM \\(${model}\\), ${r.iterations} iterations, ${r.status}`));
    }
  }
  // a surface pixel that is not the best: click the search view off its centre (the best)
  const best = (await page.textContent("#lab-match")).match(/c (\d+), r (\d+), ρ/).slice(1).map(Number);
  const fig = page.locator(".lab-pair canvas").first();
  const box = await fig.boundingBox();
  await fig.click({ position: { x: box.width / 2 + 25, y: box.height / 2 - 18 } });
  await page.waitForSelector("#lab-explain-link");
  const text = await page.textContent("#lab-explain p");
  const [c, r] = text.match(/column (\d+), row (\d+)/).slice(1).map(Number);
  assert.ok(c !== best[0] || r !== best[1], `clicked the best position ${best}`);
  const rho = Number(await page.getAttribute("#lab-explain-value", "data-value"));
  assert.ok(rho < 1, `${rho}`);
  const href = await page.getAttribute("#lab-explain-link", "href");
  assert.ok(href.includes("#/ncc-2d?"), href.slice(0, 40));
  const n = await results(context, page.url(), href, ["rho"]);
  assert.ok(near(n.rho, rho, 1e-12), `ncc-2d ρ ${n.rho} vs the lab's ${rho} at (${c}, ${r})`);
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("projective rectification from four clicked points: output pixels against a homography and interpolations worked out here", { timeout: TEST_TIMEOUT * 2 }, async () => {
  const { page, log, context } = await openLab();
  await sample(page, "camera.png");
  await page.selectOption("#lab-family", "resampling");
  await page.selectOption("#lab-warp", "projective");
  for (const [c, r] of [[120, 90], [400, 110], [430, 420], [95, 390]]) await clickPixel(page, c, r);
  await page.waitForFunction(() => document.body.dataset.resampled === "nearest,bilinear,bicubic", null, { timeout: 30_000 });
  await idle(page);
  const clicked = (await page.evaluate(() => document.body.dataset.warpPoints)).split(",").map(Number);
  assert.equal(clicked.length, 8);
  // the clicks landed where they were aimed (within a pixel)
  [[120, 90], [400, 110], [430, 420], [95, 390]].forEach(([c, r], k) => assert.ok(Math.abs(clicked[2 * k] - c) < 1 && Math.abs(clicked[2 * k + 1] - r) < 1, `${clicked}`));
  for (const [fig, method] of [[1, "nearest"], [2, "bilinear"], [3, "bicubic"]]) {
    const canvas = page.locator(`#lab-methods figure:nth-child(${fig}) canvas`);
    const box = await canvas.boundingBox();
    for (const [dx, dy] of [[0, 0], [-40, 30], [55, -20]]) {
      await page.evaluate(() => document.getElementById("lab-explain").replaceChildren());
      await canvas.click({ position: { x: box.width / 2 + dx, y: box.height / 2 + dy } });
      await page.waitForSelector("#lab-explain-value");
      const text = await page.textContent("#lab-explain p");
      const [c, r] = text.match(/output column (\d+), row (\d+)/).slice(1).map(Number);
      const value = Number(await page.getAttribute("#lab-explain-value", "data-value"));
      // Independently, in the page: the photo decoded by the browser's own
      // PNG decoder (not the image crate), the projective map solved from the
      // four point pairs by Gaussian elimination (not transform.rs), and the
      // interpolation written out (nearest: floor(x + 0.5); bilinear; the
      // cubic convolution of seed 004, a = −1).
      const want = await page.evaluate(async ([pts, c, r, method]) => {
        const blob = await (await fetch("lab/samples/camera.png")).blob();
        const bmp = await createImageBitmap(blob, { colorSpaceConversion: "none", premultiplyAlpha: "none" });
        const cv = new OffscreenCanvas(bmp.width, bmp.height);
        const ctx = cv.getContext("2d");
        ctx.drawImage(bmp, 0, 0);
        const rgba = ctx.getImageData(0, 0, bmp.width, bmp.height).data;
        const W = bmp.width;
        const g = (x, y) => rgba[4 * (y * W + x)];
        const corners = [[0, 0], [255, 0], [255, 255], [0, 255]];
        const m = [];
        corners.forEach(([u, v], k) => {
          const [x, y] = [pts[2 * k], pts[2 * k + 1]];
          m.push([u, v, 1, 0, 0, 0, -x * u, -x * v, x]);
          m.push([0, 0, 0, u, v, 1, -y * u, -y * v, y]);
        });
        for (let k = 0; k < 8; k++) {
          let piv = k;
          for (let i = k + 1; i < 8; i++) if (Math.abs(m[i][k]) > Math.abs(m[piv][k])) piv = i;
          [m[k], m[piv]] = [m[piv], m[k]];
          for (let i = 0; i < 8; i++) {
            if (i === k) continue;
            const f = m[i][k] / m[k][k];
            for (let j = k; j < 9; j++) m[i][j] -= f * m[k][j];
          }
        }
        const h = m.map((row, k) => row[8] / row[k]);
        const den = h[6] * c + h[7] * r + 1;
        const x = (h[0] * c + h[1] * r + h[2]) / den;
        const y = (h[3] * c + h[4] * r + h[5]) / den;
        let v;
        if (method === "nearest") v = g(Math.floor(x + 0.5), Math.floor(y + 0.5));
        else if (method === "bilinear") {
          const [c0, r0] = [Math.floor(x), Math.floor(y)];
          const [dc, dr] = [x - c0, y - r0];
          v = (1 - dr) * ((1 - dc) * g(c0, r0) + dc * g(c0 + 1, r0)) + dr * ((1 - dc) * g(c0, r0 + 1) + dc * g(c0 + 1, r0 + 1));
        } else {
          const k = (t) => {
            t = Math.abs(t);
            return t < 1 ? 1 - 2 * t * t + t * t * t : t < 2 ? 4 - 8 * t + 5 * t * t - t * t * t : 0;
          };
          const [fx, fy] = [Math.floor(x), Math.floor(y)];
          v = 0;
          for (let j = -1; j <= 2; j++) for (let i = -1; i <= 2; i++) v += k(x - (fx + i)) * k(y - (fy + j)) * g(fx + i, fy + j);
        }
        return { x, y, v };
      }, [clicked, c, r, method]);
      const m = text.match(/input position ([\d.]+), ([\d.]+)/);
      assert.ok(Math.abs(Number(m[1]) - want.x) < 1e-3 && Math.abs(Number(m[2]) - want.y) < 1e-3, `${method} (${c}, ${r}): position ${m[1]}, ${m[2]} vs ${want.x}, ${want.y}`);
      assert.ok(Math.abs(value - want.v) < 1e-6, `${method} (${c}, ${r}): the lab ${value}, worked out here ${want.v}`);
    }
  }
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("an edge direction is atan2(gy, gx) of the gx and gy its edge-window computes", { timeout: TEST_TIMEOUT * 2 }, async () => {
  const { page, log, context } = await openLab();
  await sample(page, "camera.png");
  await page.selectOption("#lab-family", "edges");
  await page.selectOption("#lab-operator", "sobel");
  await page.click("#lab-run");
  await idle(page);
  const names = await page.locator("#lab-layer option").allTextContents();
  assert.deepEqual(names, ["gx", "gy", "magnitude", "direction"]);
  const read = async (layer, c, r) => {
    await page.selectOption("#lab-layer", String(names.indexOf(layer)));
    await page.evaluate(() => document.getElementById("lab-explain").replaceChildren());
    await clickPixel(page, c, r);
    await page.waitForSelector("#lab-explain-value");
    return Number(await page.getAttribute("#lab-explain-value", "data-value"));
  };
  for (const [c, r] of [[300, 300], [140, 260]]) {
    const dir = await read("direction", c, r);
    const gx = await read("gx", c, r);
    const href = await page.getAttribute("#lab-explain-link", "href");
    const e = await results(context, page.url(), href, ["gx", "gy"]);
    assert.equal(e.gx[1][1], gx);
    assert.equal(e.gx[1][1], (await results(context, page.url(), href, ["selected_gx"])).selected_gx, "the selected pixel is the window's centre");
    // the link explain.js builds for a direction pixel: the same window, gx and gy
    const link = await page.evaluate(async ([h]) => {
      const X = (await import("./lab/lab.js")).explain;
      const win = new URLSearchParams(h.split("?")[1]).get("window").split(";").flatMap((row) => row.split(",").map(Number));
      const l = X.edgeLink("sobel", win, "direction");
      return { same: `index.html${l.hash}` === h, derive: l.derive, dir: null };
    }, [href]);
    assert.ok(link.same, "a direction pixel links to the same edge-window");
    assert.deepEqual(link.derive.keys, ["selected_gx", "selected_gy"]);
    const want = (Math.atan2(e.gy[1][1], e.gx[1][1]) * 180) / Math.PI;
    assert.ok(near(dir, want, 1e-12), `(${c}, ${r}): the lab's direction ${dir}, atan2 of the example's gy ${e.gy[1][1]}, gx ${e.gx[1][1]}: ${want}`);
  }
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("after a trap the fresh worker's numbers are still its examples' numbers", { timeout: TEST_TIMEOUT * 2 }, async () => {
  const { page, context } = await openLab();
  await sample(page, "camera.png");
  await page.selectOption("#lab-family", "filters");
  await page.selectOption("#lab-kernel", "gaussian-3");
  await page.evaluate(async () => {
    const lab = await import("./lab/lab.js");
    return lab.trapForTests();
  });
  await page.waitForFunction(() => /stopped unexpectedly/.test(document.getElementById("lab-error").textContent));
  await idle(page);
  await page.click("#lab-run");
  await idle(page);
  assert.equal(await page.evaluate(() => document.body.dataset.layer), "gaussian-3");
  for (const [c, r] of [[200, 300], [10, 12], [500, 17]]) {
    await page.evaluate(() => document.getElementById("lab-explain").replaceChildren());
    await clickPixel(page, c, r);
    await page.waitForSelector("#lab-explain-value");
    // the pixel clicked (the fitted view may put the click a pixel away)
    const [pc, pr] = (await page.textContent("#lab-explain p")).match(/column (\d+), row (\d+):/).slice(1).map(Number);
    assert.ok(Math.abs(pc - c) <= 1 && Math.abs(pr - r) <= 1, `${pc}, ${pr}`);
    await page.waitForSelector("#lab-explain-link");
    const shown = Number(await page.getAttribute("#lab-explain-value", "data-value"));
    const href = await page.getAttribute("#lab-explain-link", "href");
    const e = await results(context, page.url(), href, ["output"]);
    assert.equal(e.output[1][1], shown, `(${c}, ${r})`);
  }
  await context.close();
});

/** A fresh page on the lab. */
function openLab(options) {
  return openLabIn(env, options);
}
