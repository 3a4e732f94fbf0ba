// The lab's interactive pieces in Chromium: the custom kernel of the
// filters family (checked at its field, explained by filter-window with the
// same number), the template box dragged by mouse and touch and moved by
// the keyboard, the student's own fiducial measurements from clicks to
// residuals, the live sliders on a 2048² image (the newest value wins,
// whatever the machine's speed; the Förstner threshold re-uses the kept
// map), and Cancel during a long run (the photo and settings kept).

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

/** The page position of image position (x, y) in the main view (pixel centres at integers): relative to the canvas (x, y) and to the page. */
async function pagePos(page, x, y) {
  await page.locator("#lab-stage .lab-canvas").scrollIntoViewIfNeeded();
  const g = await page.evaluate(async () => (await import("./lab/lab.js")).viewForTests());
  const px = ((x + 0.5) * g.zoom + g.ox) * (g.w / g.cw);
  const py = ((y + 0.5) * g.zoom + g.oy) * (g.h / g.ch);
  return { x: px, y: py, pageX: g.left + px, pageY: g.top + py };
}

/** Clicks image position (x, y) of the main view (page coordinates: Playwright's element positions start inside the border). */
async function clickAt(page, x, y) {
  const p = await pagePos(page, x, y);
  await page.mouse.click(p.pageX, p.pageY);
}

/** Follows a link and reads the example's exact result `key` (indexed by `index`). */
async function followExplain(page, selector, key = null) {
  const a = page.locator(selector).first();
  key ??= await a.getAttribute("data-key");
  const index = (await a.getAttribute("data-index")) || "";
  const href = await a.getAttribute("href");
  await page.goto(new URL(href, page.url()).href);
  assert.equal(await settled(page), "ok", `${href} did not solve`);
  const raw = await page.locator(`.result-table tr[data-key="${key}"] td.exact`).getAttribute("data-value");
  let v = JSON.parse(raw);
  for (const i of index.split(",").filter(Boolean).map(Number)) v = v[i];
  return { v, key, href };
}

const labState = (page, c = 0, r = 0) => page.evaluate(async ([c, r]) => (await import("./lab/lab.js")).stateForTests(c, r), [c, r]);

test("a custom kernel: checked at its field, run over the photo, explained by filter-window with the same number", { timeout: TEST_TIMEOUT * 2 }, async () => {
  const { page, log, context } = await openLab();
  await sample(page, "camera.png");
  await page.selectOption("#lab-family", "filters");
  await page.selectOption("#lab-kernel", "custom");
  assert.equal(await page.locator("#lab-custom").isVisible(), true);
  // every kind of wrong text the lab's wasm module refuses (ops::custom_kernel, asked in the
  // worker), said at its field in the module's words
  const big = Array.from({ length: 17 }, () => Array(17).fill(1).join(" ")).join("\n");
  const error = "#lab-custom-error";
  for (const [text, divisor, field, says] of [
    ["1 2 x", "", "lab-custom", 'Kernel: row 1: "x" is not a number'],
    ["1 2 1\n2 0x10 1\n1 2 1", "", "lab-custom", 'Kernel: row 2: "0x10" is not a number'],
    ["1 2 1\n2 4", "", "lab-custom", "Kernel: row 2 has 2 numbers but row 1 has 3; every row needs the same number"],
    ["1 1\n1 1", "", "lab-custom", "Kernel: is 2×2 (rows × columns); a kernel needs an odd number of rows and of columns, so that it has a centre pixel"],
    [big, "", "lab-custom", "Kernel: is 17×17 (rows × columns); at most 15×15 is allowed"],
    [" \n ; ", "", "lab-custom", "Kernel: is empty; type rows of numbers, e.g. 1 2 1 / 2 4 2 / 1 2 1 on three lines"],
    ["0 0 0", "", "lab-custom", "Kernel: all weights are 0: the result would be 0 everywhere"],
    ["-1 0 1", "", "lab-divisor", "Divisor: the weights sum to 0, so the kernel cannot be normalised; give a divisor (1 applies it as written)"],
    ["1 2 1", "0", "lab-divisor", "Divisor: must be a finite number other than 0"],
    ["1 2 1", "abc", "lab-divisor", "Divisor: must be a finite number other than 0"],
  ]) {
    await page.fill("#lab-custom", text);
    await page.fill("#lab-divisor", divisor);
    // the worker's answer to the newest text (the field's message waits for it)
    await page.waitForFunction(([sel, want]) => document.querySelector(sel).textContent === want, [error, says], { timeout: 10_000 }).catch(() => {});
    assert.equal(await page.textContent(error), says, JSON.stringify([text, divisor]));
    assert.equal(await page.locator(error).isVisible(), true);
    assert.equal(await page.getAttribute(`#${field}`, "aria-invalid"), "true");
    assert.equal(await page.getAttribute(field === "lab-custom" ? "#lab-divisor" : "#lab-custom", "aria-invalid"), "false");
    // Run refuses it: the field is focused, and no layer
    await page.focus("#lab-run");
    await page.click("#lab-run");
    await page.waitForFunction((id) => document.activeElement?.id === id, field);
    assert.equal(await page.evaluate(() => document.body.dataset.filterShown ?? null), null);
  }
  // a 3×5 (rows × columns) signed kernel with divisor 4
  await page.fill("#lab-custom", "1 2 3 2 1\n0 0 0 0 0\n-1 -2 -3 -2 -1");
  await page.fill("#lab-divisor", "4");
  await page.waitForSelector("#lab-custom-error", { state: "hidden" });
  assert.equal(await page.getAttribute("#lab-custom", "aria-invalid"), "false");
  await page.click("#lab-run");
  await page.waitForFunction(() => document.body.dataset.filterShown === "custom");
  await idle(page);
  assert.equal(await page.evaluate(() => document.body.dataset.layer), "custom");
  // the value at (200, 300) from the photo's grey values by hand
  const want = await page.evaluate(async () => {
    const lab = await import("./lab/lab.js");
    return lab.stateForTests(200, 300).value;
  });
  const grey = await page.evaluate(async () => {
    const s = await import("./lab/lab.js");
    return s.greyForTests([198, 299, 5, 3]);
  });
  const k = [[1, 2, 3, 2, 1], [0, 0, 0, 0, 0], [-1, -2, -3, -2, -1]];
  let sum = 0;
  for (let r = 0; r < 3; r++) for (let c = 0; c < 5; c++) sum += k[r][c] * grey[r * 5 + c];
  assert.ok(Math.abs(want - sum / 4) < 1e-9, `${want} vs ${sum / 4}`);
  await clickAt(page, 200, 300);
  await page.waitForSelector("#lab-explain-link");
  const shown = Number(await page.getAttribute("#lab-explain-value", "data-value"));
  assert.equal(shown, want);
  const { v, href } = await followExplain(page, "#lab-explain-link");
  assert.ok(href.includes("kernel=custom") && href.includes("custom_divisor=4"), href);
  assert.equal(v, shown, `${href}: the example gives ${v}, the lab showed ${shown}`);
  // normalised (no divisor): [1 2 1] / 4, explained the same way
  await page.goBack();
  await page.waitForSelector("#lab-sample");
  await sample(page, "camera.png");
  await page.selectOption("#lab-family", "filters");
  await page.selectOption("#lab-kernel", "custom");
  await page.fill("#lab-custom", "1, 2, 1");
  await page.fill("#lab-divisor", "");
  await page.click("#lab-run");
  await page.waitForFunction(() => document.body.dataset.filterShown === "custom");
  await idle(page);
  await clickAt(page, 100, 50);
  await page.waitForSelector("#lab-explain-link");
  const shown2 = Number(await page.getAttribute("#lab-explain-value", "data-value"));
  const g2 = await page.evaluate(async () => (await import("./lab/lab.js")).greyForTests([99, 50, 3, 1]));
  assert.ok(Math.abs(shown2 - (g2[0] + 2 * g2[1] + g2[2]) / 4) < 1e-12);
  const r2 = await followExplain(page, "#lab-explain-link");
  assert.equal(r2.v, shown2);
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("the template box is dragged by mouse and touch and moved by the keyboard; the matching runs again where it is dropped", { timeout: TEST_TIMEOUT * 2 }, async () => {
  const { page, log, context } = await openLab({ hasTouch: true });
  await sample(page, "aero1.jpg");
  await page.selectOption("#lab-family", "correlation");
  await page.selectOption("#lab-second", "same");
  await page.selectOption("#lab-template", "11");
  await page.fill("#lab-reach", "12");
  await clickAt(page, 300, 200);
  await page.waitForFunction(() => document.body.dataset.matched === "300,200");
  await idle(page);
  assert.match(await page.textContent("#lab-template-pos"), /centred on column 300, row 200/);
  // drag with the mouse: grab the box's centre, move by (+40, +30) image pixels
  const from = await pagePos(page, 300, 200);
  const to = await pagePos(page, 340, 230);
  await page.mouse.move(from.pageX, from.pageY);
  await page.mouse.down();
  for (let i = 1; i <= 5; i++) await page.mouse.move(from.pageX + ((to.pageX - from.pageX) * i) / 5, from.pageY + ((to.pageY - from.pageY) * i) / 5);
  assert.match(await page.textContent("#lab-template-pos"), /\(moving\)/);
  await page.mouse.up();
  await page.waitForFunction(() => document.body.dataset.matched && document.body.dataset.matched === document.body.dataset.template && document.body.dataset.matched !== "300,200");
  await idle(page);
  const [c1, r1] = (await page.evaluate(() => document.body.dataset.template)).split(",").map(Number);
  assert.ok(Math.abs(c1 - 340) <= 1 && Math.abs(r1 - 230) <= 1, `${c1}, ${r1}`);
  // the template found in its own photo where it was cut out: ρ = 1 at its centre
  assert.match(await page.textContent("#lab-match"), new RegExp(`c ${c1}, r ${r1}, ρ = 1(?![.\\d])`));
  // drag by touch (pointer events from touch input)
  const cdp = await context.newCDPSession(page);
  const a = await pagePos(page, c1, r1);
  const b = await pagePos(page, c1 - 50, r1 + 20);
  await cdp.send("Input.dispatchTouchEvent", { type: "touchStart", touchPoints: [{ x: a.pageX, y: a.pageY }] });
  for (let i = 1; i <= 5; i++) {
    await cdp.send("Input.dispatchTouchEvent", { type: "touchMove", touchPoints: [{ x: a.pageX + ((b.pageX - a.pageX) * i) / 5, y: a.pageY + ((b.pageY - a.pageY) * i) / 5 }] });
  }
  await cdp.send("Input.dispatchTouchEvent", { type: "touchEnd", touchPoints: [] });
  await page.waitForFunction((old) => document.body.dataset.matched === document.body.dataset.template && document.body.dataset.matched !== old, `${c1},${r1}`);
  await idle(page);
  const [c2, r2] = (await page.evaluate(() => document.body.dataset.template)).split(",").map(Number);
  assert.ok(Math.abs(c2 - (c1 - 50)) <= 1 && Math.abs(r2 - (r1 + 20)) <= 1, `${c2}, ${r2}`);
  // the keyboard: three steps right, one big step down (Shift: 10 pixels)
  await page.focus("#lab-template-handle");
  for (let i = 0; i < 3; i++) await page.keyboard.press("ArrowRight");
  await page.keyboard.press("Shift+ArrowDown");
  const want = `${c2 + 3},${r2 + 10}`;
  assert.match(await page.textContent("#lab-template-pos"), new RegExp(`column ${c2 + 3}, row ${r2 + 10}`));
  assert.equal(await page.getAttribute("#lab-template-pos", "aria-live"), "polite");
  await page.waitForFunction((w) => document.body.dataset.matched === w, want);
  await idle(page);
  assert.match(await page.textContent("#lab-match"), new RegExp(`c ${c2 + 3}, r ${r2 + 10}, ρ = 1(?![.\\d])`));
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("fiducials: the student clicks the four marks, refines them, redoes one, and the fits' residuals are drawn and checked", { timeout: TEST_TIMEOUT * 3 }, async () => {
  const { page, log, context } = await openLab();
  await sample(page, "frame");
  await page.selectOption("#lab-family", "fiducials");
  await page.waitForSelector("#lab-fid-start"); // (the family's module is loaded when chosen)
  const truth = await page.evaluate(async () => (await import("./lab/lab.js")).truthForTests());
  assert.equal(await page.evaluate(() => document.body.dataset.fidNext), "1");
  assert.match(await page.textContent("#lab-fid-prompt"), /Click fiducial 1 \(left/);
  // click each mark a little off its true centre; the refinement finds it
  const off = [[1.5, -1], [-1, 1.2], [0.8, 1.4], [-1.3, -0.7]];
  for (let k = 0; k < 4; k++) {
    await clickAt(page, truth.marks[2 * k] + off[k][0], truth.marks[2 * k + 1] + off[k][1]);
    await page.waitForFunction((n) => document.body.dataset.fidNext === n, k === 3 ? "done" : String(k + 2));
    if (k < 3) assert.match(await page.textContent("#lab-fid-prompt"), new RegExp(`Click fiducial ${k + 2} \\(`));
  }
  await page.waitForSelector("#lab-fid-fit");
  await idle(page);
  const errors = (await page.locator("#lab-fid-table td.lab-fid-error").allTextContents()).map(Number);
  assert.equal(errors.length, 4);
  for (const e of errors) assert.ok(e < 0.1, `refined mark ${e} px from the truth`);
  const moved = await page.locator("#lab-fid-table tr:nth-child(2) td:nth-child(4)").textContent();
  assert.match(moved, /^1\.[5-9]\d* px|^1\.[5-9] px/, moved);
  let res = JSON.parse(await page.evaluate(() => document.body.dataset.fidResiduals));
  // the affine model fits the frame's distortion: residuals of the measuring noise only;
  // the similarity cannot take the two scales 0.2 % apart and the shear: ~0.1 mm
  for (const v of res.affine) assert.ok(Math.abs(v) < 0.01, `affine residual ${v} mm`);
  const simMax = Math.max(...res.similarity.map(Math.abs));
  assert.ok(simMax > 0.05 && simMax < 0.3, `similarity residuals up to ${simMax} mm`);
  const A = (await page.evaluate(() => document.body.dataset.fidAffine)).split(",").map(Number);
  for (const i of [0, 1, 3, 4]) assert.ok(Math.abs(A[i] - truth.affine[i]) < 1e-4, `${A} vs ${truth.affine}`);
  assert.match(await page.textContent("#lab-fid-scale"), new RegExp(`drawn ${res.times}× enlarged; the yellow bar is [\\d.]+ µm`));
  assert.match(await page.textContent("#lab-fid-truth"), /from the true mark centres; your affine differs from the true one by at most [\d.]+ µm/);

  // redo mark 2 without refinement, 4 px to the right of the truth
  await page.uncheck("#lab-fid-refine");
  await page.click("#lab-fid-redo-2");
  assert.match(await page.textContent("#lab-fid-prompt"), /Click fiducial 2 \(right\) again/);
  const clickC = truth.marks[2] + 4;
  await clickAt(page, clickC, truth.marks[3]);
  await page.waitForFunction(() => document.body.dataset.fidNext === "done");
  await page.waitForFunction((old) => document.body.dataset.fidResiduals !== old, JSON.stringify(res));
  await idle(page);
  res = JSON.parse(await page.evaluate(() => document.body.dataset.fidResiduals));
  const err2 = Number(await page.locator("#lab-fid-table tr:nth-child(3) td.lab-fid-error").textContent());
  assert.ok(Math.abs(err2 - 4) < 1, `mark 2 clicked ${err2} px from the truth`);
  // 4 px = 1 mm along x at mark 2: the affine's residuals take up part of it
  const biggest = Math.max(...res.affine.map(Math.abs));
  assert.ok(biggest > 0.1 && biggest < 1, `largest affine residual ${biggest} mm`);
  // the arrows are drawn (red, the affine's) on the photo
  const red = await page.$eval(".lab-canvas", (cv) => {
    const d = cv.getContext("2d").getImageData(0, 0, cv.width, cv.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] > 180 && d[i + 1] < 90 && d[i + 2] < 90) n++;
    return n;
  });
  assert.ok(red > 20, `red arrow pixels: ${red}`);
  // Example 4 with these measurements gives the same residuals (the same core fit)
  const { v } = await followExplain(page, "#lab-fid-link", "point_residuals");
  const flat = v.flat();
  for (let i = 0; i < 8; i++) assert.ok(Math.abs(flat[i] - res.affine[i]) < 1e-12, `${flat} vs ${res.affine}`);

  // the keyboard alternative: the four true positions typed, no refinement: a perfect fit
  await page.goBack();
  await page.waitForSelector("#lab-sample");
  await sample(page, "frame");
  await page.selectOption("#lab-family", "fiducials");
  await page.waitForSelector("#lab-fid-start"); // (the family's module is loaded when chosen)
  await page.uncheck("#lab-fid-refine");
  const typed = [0, 1, 2, 3].map((k) => `${truth.marks[2 * k]}, ${truth.marks[2 * k + 1]}`).join("; ");
  await page.fill("#lab-fid-typed", typed);
  await page.click("#lab-fid-use");
  await page.waitForSelector("#lab-fid-fit");
  await idle(page);
  res = JSON.parse(await page.evaluate(() => document.body.dataset.fidResiduals));
  for (const x of res.affine) assert.ok(Math.abs(x) < 1e-9, `affine residual ${x} mm for the true positions`);
  await page.fill("#lab-fid-typed", "1, 2; 3");
  await page.click("#lab-fid-use");
  assert.match(await page.textContent("#lab-error"), /^positions: type four positions/);
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

/** A 2048² test image: 64-pixel checkerboard (50/200) with a texture. */
async function openBig(page, n = 2048) {
  await page.evaluate(async (n) => {
    const bytes = new Uint8Array(n * n);
    for (let r = 0; r < n; r++) for (let c = 0; c < n; c++) bytes[r * n + c] = (((c >> 6) + (r >> 6)) & 1 ? 200 : 50) + ((c * 7 + r * 13) % 17);
    await (await import("./lab/lab.js")).openRawForTests(n, n, bytes, `big${n}`);
  }, n);
  await page.waitForFunction((n) => document.body.dataset.image === `big${n}`, n);
  await idle(page);
}

const bigGrey = (c, r) => (((c >> 6) + (r >> 6)) & 1 ? 200 : 50) + ((c * 7 + r * 13) % 17);

/** The k×k mean of the big image (n × n) at (c, r), replicating the edge. */
function bigMean(c, r, k, n = 2048) {
  const h = (k - 1) / 2;
  let s = 0;
  for (let dr = -h; dr <= h; dr++) for (let dc = -h; dc <= h; dc++) s += bigGrey(Math.min(n - 1, Math.max(0, c + dc)), Math.min(n - 1, Math.max(0, r + dr)));
  return s / (k * k);
}

async function setRange(page, selector, values, gapMs) {
  await page.evaluate(async ([sel, vs, gap]) => {
    const input = document.querySelector(sel);
    for (const v of vs) {
      input.value = String(v);
      input.dispatchEvent(new Event("input", { bubbles: true }));
      await new Promise((res) => setTimeout(res, gap));
    }
  }, [selector, values, gapMs]);
}

test("live sliders on a 2048² image: the newest filter size wins (the running one is cancelled), the Förstner threshold re-uses the kept map", { timeout: TEST_TIMEOUT * 5 }, async () => {
  const { page, log, context } = await openLab();
  await openBig(page);
  await page.selectOption("#lab-family", "filters");
  await page.selectOption("#lab-kernel", "mean-k");
  await page.selectOption("#lab-border", "replicate");
  await setRange(page, "#lab-size", [5], 0);
  await page.waitForFunction(() => document.body.dataset.filterShown === "mean 5×5", null, { timeout: 60_000 });
  await idle(page);
  let s = await labState(page, 1000, 1000);
  // layers are f32: the exact mean rounded to f32 (docs/lab.md, fast image operators)
  assert.equal(s.value, Math.fround(bigMean(1000, 1000, 5)));
  // a drag: 7, 9, 11, 13, each next value given while the run before it is still running (at its
  // first progress message: rows are left to compute), however fast the machine. Each value is
  // asked for once; each run but the last is stopped by the next value; what is drawn only ever
  // grows (no older result after a newer one); the result layer never leaves the screen; and
  // the one drawn is the slider's final value.
  const filterSent0 = (await labState(page)).sent.filter;
  const cancels0 = Number(await page.evaluate(() => document.body.dataset.filterCancels ?? 0));
  await page.evaluate(() => {
    window.labShown = [];
    window.labBarHidden = 0;
    new MutationObserver(() => window.labShown.push(document.body.dataset.filterShown))
      .observe(document.body, { attributes: true, attributeFilter: ["data-filter-shown"] });
    new MutationObserver(() => {
      if (document.getElementById("lab-layerbar").hidden) window.labBarHidden++;
    }).observe(document.getElementById("lab-layerbar"), { attributes: true, attributeFilter: ["hidden"] });
  });
  await page.evaluate(async () => {
    const lab = await import("./lab/lab.js");
    const input = document.querySelector("#lab-size");
    for (const v of [7, 9, 11, 13]) {
      const running = v === 13 ? null : lab.progressForTests();
      input.value = String(v);
      input.dispatchEvent(new Event("input", { bubbles: true }));
      await running;
    }
  });
  await page.waitForFunction(() => document.body.dataset.filterShown === "mean 13×13", null, { timeout: 90_000 });
  await idle(page);
  const shown = await page.evaluate(() => window.labShown);
  const sizes = shown.map((t) => Number(t.match(/^mean (\d+)×/)[1]));
  assert.ok(sizes.every((k, i) => i === 0 || k > sizes[i - 1]) && sizes.at(-1) === 13, `drawn in this order: ${shown}`);
  assert.equal((await labState(page)).sent.filter - filterSent0, 4, "each slider value asked for once");
  const cancels = Number(await page.evaluate(() => document.body.dataset.filterCancels ?? 0)) - cancels0;
  assert.equal(cancels, 3, `${cancels} runs stopped, ${shown.length} drawn`);
  assert.deepEqual(shown, ["mean 13×13"]);
  assert.match(await page.textContent("#lab-notice"), /stopped for the newer setting/);
  assert.equal(await page.evaluate(() => window.labBarHidden), 0, "the result layer left the screen during the drag");
  console.log(`# ${cancels} filter runs cancelled by a newer value; the last restart (new worker, the 2048² photo back) took ${await page.evaluate(() => document.body.dataset.restartMs)} ms`);
  for (const [c, r] of [[1000, 1000], [3, 2], [2047, 640]]) {
    s = await labState(page, c, r);
    assert.equal(s.layer, "mean 13×13");
    assert.equal(s.value, Math.fround(bigMean(c, r, 13)), `(${c}, ${r}): ${s.value} vs ${bigMean(c, r, 13)}`);
  }
  assert.equal(await page.inputValue("#lab-size"), "13");
  assert.equal(await page.textContent("#lab-size-out"), "13×13");
  assert.equal(await page.locator("#lab-progress").isHidden(), true);

  // Förstner: the map once, then the threshold slider only re-thresholds it
  await page.selectOption("#lab-family", "interest");
  await page.selectOption("#lab-interest", "forstner");
  await page.click("#lab-run");
  await page.waitForFunction(() => document.body.dataset.threshold && document.body.dataset.forstnerLive === "idle", null, { timeout: 90_000 });
  await idle(page);
  const sent0 = (await labState(page)).sent;
  assert.equal(sent0.forstnerMaps, 1);
  const runs0 = await page.evaluate(() => document.body.dataset.mapRuns);
  await setRange(page, "#lab-threshold", [0.3, 0.6, 0.9, 1.2, 1.5], 10);
  await page.waitForFunction(() => document.body.dataset.threshold === "1.5" && document.body.dataset.forstnerLive === "idle", null, { timeout: 30_000 });
  const sent1 = (await labState(page)).sent;
  assert.equal(sent1.forstnerMaps, 1, "a threshold change asked for a new map");
  assert.equal(await page.evaluate(() => document.body.dataset.mapRuns), runs0, "the worker computed a map again");
  assert.ok(sent1.forstnerPoints - sent0.forstnerPoints >= 1 && sent1.forstnerPoints - sent0.forstnerPoints <= 5);
  const livePoints = Number(await page.evaluate(() => document.body.dataset.points));
  const pointsMs = Number(await page.evaluate(() => document.body.dataset.pointsMs));
  console.log(`# Förstner re-threshold of the kept 2048² map: ${pointsMs} ms in the worker; ${livePoints} points at T = 1.5 px`);
  // no later answer replaces it: every request has ended, none follows
  await page.evaluate(async () => (await import("./lab/lab.js")).settledForTests());
  assert.equal(await page.evaluate(() => document.body.dataset.threshold), "1.5");
  // the same points as a full run at T = 1.5 (map and points computed afresh)
  await page.click("#lab-run");
  await page.waitForFunction((r) => document.body.dataset.mapRuns !== r && document.body.dataset.forstnerLive === "idle", runs0, { timeout: 90_000 });
  await idle(page);
  assert.equal(Number(await page.evaluate(() => document.body.dataset.points)), livePoints);
  assert.ok(livePoints > 100, `${livePoints} points on the checkerboard`);
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("Cancel during a long run on a 4096² image: the photo and the settings are kept, and the lab works after", { timeout: TEST_TIMEOUT * 4 }, async () => {
  const { page, log, context } = await openLab();
  // 4096²: the 15×15 kernel runs on the fast path (exact integer sums), long enough for Cancel only at this size
  await openBig(page, 4096);
  assert.equal((await labState(page)).sent.raw, 1);
  await page.selectOption("#lab-family", "filters");
  await page.selectOption("#lab-kernel", "custom");
  await page.selectOption("#lab-border", "reflect");
  // a 15×15 kernel of unequal weights: 225 products a pixel over 16.8 million pixels
  const kernel = Array.from({ length: 15 }, (_, j) => Array.from({ length: 15 }, (_, i) => 1 + ((i * 3 + j * 5) % 7)).join(" ")).join("\n");
  await page.fill("#lab-custom", kernel);
  await page.fill("#lab-divisor", "");
  // Cancel pressed in the task that receives a progress message, once the progress line shows the
  // rows done (the pool runs it by bands of rows, tiles.js): the run is still running as far as
  // the page knows (a band a worker may have finished meanwhile is not yet received), so this
  // always cancels, however fast the machine
  const pressed = page.evaluate(async () => {
    const lab = await import("./lab/lab.js");
    for (;;) {
      const p = await lab.progressForTests();
      const cancel = document.getElementById("lab-cancel");
      const text = document.getElementById("lab-progress").textContent;
      if (cancel && /rows/.test(text)) {
        cancel.click();
        return { ...p, text };
      }
    }
  });
  await page.click("#lab-run");
  const at = await pressed;
  const [, rows, pct] = at.text.match(/^Filtering \(custom\)… rows (\d+) of 4096 \((\d+) %\), \d+\.\d s Cancel$/);
  assert.ok(Number(rows) >= 1 && Number(rows) < 4096 && Number(pct) === Math.round((100 * rows) / 4096), `${rows} rows, ${pct} %`);
  assert.ok(at.rows >= Number(rows) && at.of === 4096, JSON.stringify(at));
  await idle(page);
  assert.equal(await page.textContent("#lab-notice"), "Cancelled. The photo and the settings are kept.");
  assert.equal(await page.locator("#lab-error").isHidden(), true);
  assert.equal(await page.locator("#lab-progress").isHidden(), true);
  // nothing was drawn, the photo and every setting are as they were
  assert.equal(await page.evaluate(() => document.body.dataset.filterShown ?? null), null);
  assert.equal((await labState(page)).layer, null);
  assert.equal(await page.evaluate(() => document.body.dataset.image), "big4096");
  assert.match(await page.textContent("#lab-info"), /big4096: 4096 × 4096 pixels/);
  assert.equal(await page.inputValue("#lab-family"), "filters");
  assert.equal(await page.inputValue("#lab-kernel"), "custom");
  assert.equal(await page.inputValue("#lab-border"), "reflect");
  assert.equal(await page.inputValue("#lab-custom"), kernel);
  // only the pool's bands were stopped: the main worker kept the photo (no second "raw" request), and works on it
  assert.equal((await labState(page)).sent.raw, 1);
  await page.selectOption("#lab-kernel", "mean-k");
  await page.selectOption("#lab-border", "replicate");
  await setRange(page, "#lab-size", [3], 0);
  await page.waitForFunction(() => document.body.dataset.filterShown === "mean 3×3", null, { timeout: 60_000 });
  await idle(page);
  for (const [c, r] of [[0, 0], [1000, 1000], [4095, 4095], [64, 63]]) {
    const s = await labState(page, c, r);
    assert.equal(s.value, Math.fround(bigMean(c, r, 3, 4096)), `(${c}, ${r}): ${s.value} vs ${bigMean(c, r, 3, 4096)}`);
  }
  assert.match(await page.textContent("#lab-engine"), /^Engine: fast \(SIMD\)/);
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

/** A fresh page on the lab. */
function openLab(options) {
  return openLabIn(env, options);
}
