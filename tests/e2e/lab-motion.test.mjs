// End-to-end (issue 34, item 2, last sentence): motion in the lab, for the
// clicked pixel's window of the photo (www/lab/motion.js). One browser page,
// bundled samples. For the filters (a mean over the chessboard), Moravec and
// the chain code (a fiducial's disc on the scanned frame): "Watch it move"
// opens the explaining example's figure in the lab, moved frame by frame with
// the keyboard only; each frame's caption is compared with solve(id, the
// inputs of the explain link) in Node, the window outlined on the photo with
// where the lab read it, and the frame of the explained pixel (the last
// frame for Moravec and the chain code) with the lab's own value. Escape
// closes it; axe-core (WCAG 2.2 AA) with the motion open at 1280 and 390 px;
// screenshots of both widths in target/screenshots/.

import assert from "node:assert/strict";
import fs from "node:fs";
import { createRequire } from "node:module";
import { after, before, test } from "node:test";
import { TEST_TIMEOUT, nodeModule, start } from "./harness.mjs";
import { clickPixel, idle, openLab, sample, viewOf } from "./lab-harness.mjs";
import { parseHash } from "../../www/url.js";
import { formatNumber } from "../../www/format.js";

const AXE = createRequire(import.meta.url).resolve("axe-core/axe.min.js");
const SHOTS = "target/screenshots";

let env;
let page;
let context;
let log;
let core;

before(async () => {
  env = await start();
  ({ page, context, log } = await openLab(env, { bypassCSP: true, viewport: { width: 1280, height: 900 } }));
  core = await nodeModule("all");
});
after(async () => {
  await context?.close();
  await env?.close();
});

/** solve(id, inputs) in Node with the texts the lab's explain link carries. */
function solveLink(href) {
  const { id, params } = parseHash(href.slice(href.indexOf("#")));
  const parsed = core.parse_inputs(id, Object.fromEntries(params));
  assert.deepEqual(parsed.errors, {}, `${href}: the link's inputs are read without errors`);
  return { id, inputs: parsed.inputs, solution: core.solve(id, parsed.inputs) };
}

/** Waits for the offer of the explanation whose link is `selector`, opens the motion by the keyboard, and pauses it at frame 1 with the slider's Home. */
async function openMotion(selector) {
  await page.waitForSelector(selector);
  const href = await page.getAttribute(selector, "href");
  await page.waitForFunction((h) => {
    const a = document.getElementById("lab-motion-link");
    return a && !document.getElementById("lab-motion-offer").hidden && a.getAttribute("href") === `${h}&play=auto`;
  }, href);
  await page.focus("#lab-motion-open");
  await page.keyboard.press("Enter");
  await page.waitForSelector("#lab-motion:not([hidden]) .motion:not([hidden])");
  assert.equal(await page.getAttribute("#lab-motion-open", "aria-expanded"), "true");
  // it plays; the focus goes to the motion's controls; the slider (the keyboard's scrub) stops it, End then Home: frame 1
  await page.waitForFunction(() => document.activeElement?.closest("#lab-motion .motion-bar") !== null);
  const opened = await page.evaluate(() => {
    const m = document.querySelector("#lab-motion .motion");
    return { frame: m.dataset.frame, playing: m.dataset.playing === "true", playHidden: m.querySelector(".motion-play").hidden, focus: document.activeElement.className };
  });
  await page.focus("#lab-motion .motion-slider");
  await page.keyboard.press("End");
  await page.keyboard.press("Home");
  await page.waitForFunction(() => document.querySelector("#lab-motion .motion").dataset.frame === "1" && document.querySelector("#lab-motion .motion").dataset.playing === "false");
  return { href, opened, ...solveLink(href) };
}

/** The frame shown: its number, caption, the motion's frame count and the outlined window(s) on the photo. */
const shown = () =>
  page.evaluate(() => {
    const m = document.querySelector("#lab-motion .motion");
    const slider = m.querySelector(".motion-slider");
    return {
      frame: Number(m.dataset.frame),
      count: Number(slider.max),
      playing: m.dataset.playing === "true",
      caption: m.querySelector(".motion-caption").textContent,
      boxes: (document.getElementById("lab-motion-host").dataset.window || "").split(" ").filter(Boolean).map((b) => b.split(",").map(Number)),
    };
  });

/** Next frame by the keyboard (the slider's ArrowRight), waited for. */
async function next(frame) {
  await page.keyboard.press("ArrowRight");
  await page.waitForFunction((f) => document.querySelector("#lab-motion .motion").dataset.frame === String(f), frame + 1);
  return shown();
}

/** A number as the figures write it (figures/draw.js fmt: formatNumber with `digits` significant digits). */
const NUM = "(−?\\d+(?:\\.\\d+)?(?:e[+−-]?\\d+)?)";
/** The caption's text `shown` is solve()'s `value` as the figure writes it. */
const shows = (shown, value, digits, what) => assert.equal(shown, formatNumber(value, digits), `${what}: solve() gives ${value}`);
const labValue = async () => Number(await page.getAttribute("#lab-explain-value", "data-value"));

/** Escape in the panel closes it: the focus is back on the button, the outline gone. */
async function escape() {
  await page.keyboard.press("Escape");
  await page.waitForSelector("#lab-motion", { state: "hidden" });
  assert.equal(await page.evaluate(() => document.activeElement?.id), "lab-motion-open");
  assert.equal(await page.getAttribute("#lab-motion-host", "data-window"), "");
}

test("filters: the kernel moves over the clicked pixel's window of the photo; every frame is solve()'s output there", { timeout: TEST_TIMEOUT }, async () => {
  await sample(page, "left01.jpg");
  await page.selectOption("#lab-family", "filters");
  await page.click("#lab-run");
  await idle(page);
  const pick = [300, 200];
  await clickPixel(page, ...pick);
  // the offer fetches no topic wasm: the filters' module comes when the motion is asked for
  await page.waitForSelector("#lab-motion-offer:not([hidden])");
  assert.deepEqual(log.requests.filter((u) => /filters_bg[^/]*\.wasm/.test(u)), []);
  const { id, inputs, solution } = await openMotion("#lab-explain-link");
  assert.equal(id, "filter-window");
  assert.equal(log.requests.filter((u) => /filters_bg[^/]*\.wasm/.test(u)).length, 1);
  const out = solution.result.output;
  const [fc, fr] = [solution.result.output_first_c, solution.result.output_first_r];
  const side = inputs.window.length;
  const o = [pick[0] - (side - 1) / 2, pick[1] - (side - 1) / 2];
  // the fitted photo is zoomed in about the window: at least 72 CSS px across
  const g = await viewOf(page);
  assert.ok((side * g.zoom * g.w) / g.cw >= 71.9, `the window is ${(side * g.zoom * g.w) / g.cw} CSS px across`);
  let f = await shown();
  assert.equal(f.count, out.length * out[0].length);
  for (let k = 0; k < f.count; k++) {
    if (k) f = await next(k);
    const [r, c] = [fr + Math.floor(k / out[0].length), fc + (k % out[0].length)];
    const m = f.caption.match(new RegExp(`at row (\\d+), column (\\d+): [^=]+= ${NUM}`));
    assert.ok(m, f.caption);
    assert.deepEqual([Number(m[1]), Number(m[2])], [r, c], `frame ${k + 1}: the output pixel, row by row`);
    shows(m[3], out[r - fr][c - fc], 6, `frame ${k + 1}`);
    // the photo outlines the window and, inside it, the kernel's footprint over this output pixel
    assert.deepEqual(f.boxes[0], [o[0], o[1], side, side]);
    assert.deepEqual(f.boxes[1], [o[0] + c - 1 - (fc - 1), o[1] + r - 1 - (fr - 1), 2 * fc - 1, 2 * fr - 1]);
    // the explained pixel (the window's centre) is the lab's value
    if (r === inputs.select_r && c === inputs.select_c) shows(m[3], await labValue(), 6, "the explained pixel against the lab's value");
  }
  await escape();
  // open again (Enter on the button), then a new click: the open motion follows it, the new pixel's window outlined
  await page.keyboard.press("Enter");
  await page.waitForSelector("#lab-motion:not([hidden])");
  const old = await page.getAttribute("#lab-motion-link", "href");
  await clickPixel(page, 305, 203);
  await page.waitForFunction((h) => {
    const a = document.getElementById("lab-motion-link");
    return a.getAttribute("href") !== h && !document.getElementById("lab-motion").hidden && (document.getElementById("lab-motion-host").dataset.window || "").startsWith(`${305 - 2},${203 - 2},5,5`);
  }, old);
  assert.equal(await page.getAttribute("#lab-motion-open", "aria-expanded"), "true");
  await page.focus("#lab-motion-close");
  await page.keyboard.press("Enter");
  await page.waitForSelector("#lab-motion", { state: "hidden" });
  assert.deepEqual(log.pageErrors, []);
});

test("Moravec: pixel by pixel the four differences and their sum; the last frame's mean is the lab's value", { timeout: TEST_TIMEOUT }, async () => {
  await page.selectOption("#lab-family", "interest");
  await page.selectOption("#lab-interest", "moravec");
  await page.click("#lab-run");
  await idle(page);
  await page.selectOption("#lab-layer", { label: "moravec" });
  const pick = [250, 190];
  // the whole photo again (the view's 0 key)
  await page.focus("#lab-stage .lab-canvas");
  await page.keyboard.press("0");
  const before = await page.getAttribute("#lab-motion-link", "href").catch(() => null);
  await clickPixel(page, ...pick);
  await page.waitForFunction((b) => document.getElementById("lab-explain-link")?.getAttribute("href") !== b && document.getElementById("lab-explain-link")?.getAttribute("href")?.includes("moravec"), before?.replace("&play=auto", ""));
  const { id, inputs, solution } = await openMotion("#lab-explain-link");
  assert.equal(id, "moravec-window");
  const rows = solution.result.differences;
  const n = inputs.window.length;
  const a = Math.floor((n - 1) / 2);
  let f = await shown();
  assert.equal(f.count, rows.length);
  for (let k = 0; k < rows.length; k++) {
    if (k) f = await next(k);
    const [c, r, g] = rows[k];
    const m = f.caption.match(new RegExp(`^Pixel (\\d+): P\\(c(\\d+), r(\\d+)\\) = ${NUM}.*the sum of their squares ${NUM}`));
    assert.ok(m, f.caption);
    assert.deepEqual(m.slice(1, 4).map(Number), [k + 1, c, r]);
    shows(m[4], g, 4, `pixel ${k + 1}'s grey value`);
    shows(m[5], rows[k].at(-1), 4, `pixel ${k + 1}'s sum of squares`);
    assert.deepEqual(f.boxes, [[pick[0] - a, pick[1] - a, n, n], [pick[0] - a + c - 2, pick[1] - a + r - 2, 3, 3]]);
  }
  const mean = f.caption.match(new RegExp(`The mean of the (\\d+) sums: ${NUM}`));
  assert.ok(mean, f.caption);
  assert.equal(Number(mean[1]), rows.length);
  shows(mean[2], solution.result.mean, 4, "the mean");
  shows(mean[2], await labValue(), 4, "the mean against the lab's value");
  // axe with the motion open, at 1280 and at 390 px; screenshots of both
  fs.mkdirSync(SHOTS, { recursive: true });
  for (const width of [1280, 390]) {
    await page.setViewportSize({ width, height: 900 });
    await page.locator("#lab-motion").scrollIntoViewIfNeeded();
    const sideways = await page.evaluate(() => document.documentElement.scrollWidth - document.documentElement.clientWidth);
    assert.ok(sideways <= 0, `${width} px: the page scrolls ${sideways} px sideways`);
    assert.deepEqual(await axe(), [], `axe at ${width} px with the motion open`);
    await page.screenshot({ path: `${SHOTS}/lab-motion-${width}.png` });
  }
  await page.setViewportSize({ width: 1280, height: 900 });
  await page.focus("#lab-motion .motion-slider");
  await escape();
  assert.deepEqual(log.pageErrors, []);
});

test("chain code: the follower walks the traced boundary of the photo; the last frame's code is the lab's", { timeout: TEST_TIMEOUT }, async () => {
  // with reduced motion asked for, it opens at the first move, paused, without a Play button (motion.js)
  await page.emulateMedia({ reducedMotion: "reduce" });
  await sample(page, "frame");
  await page.selectOption("#lab-family", "boundaries");
  const truth = await page.evaluate(async () => (await import("./lab/lab.js")).truthForTests());
  await clickPixel(page, Math.round(truth.marks[0]), Math.round(truth.marks[1]));
  await page.waitForSelector("#lab-boundary");
  const { id, solution, opened } = await openMotion("#lab-explain a");
  assert.equal(id, "chain-code");
  assert.deepEqual(opened, { frame: "1", playing: false, playHidden: true, focus: "button motion-forward" });
  const { code, pixels } = solution.result;
  const path = [...pixels, pixels[0]];
  let f = await shown();
  assert.equal(f.count, code.length);
  const check = (k) => {
    const m = f.caption.match(/^Move (\d+): from column (\d+), row (\d+) to column (\d+), row (\d+), .*: code (\d)\./);
    assert.ok(m, f.caption);
    assert.deepEqual(m.slice(1).map(Number), [k + 1, ...path[k], ...path[k + 1], code[k]]);
    assert.deepEqual(f.boxes, [[...path[k + 1], 1, 1]], `move ${k + 1}: the pixel reached, on the photo`);
  };
  for (let k = 0; k < 4; k++) {
    if (k) f = await next(k);
    check(k);
  }
  await page.keyboard.press("End");
  await page.waitForFunction((n) => document.querySelector("#lab-motion .motion").dataset.frame === String(n), code.length);
  f = await shown();
  check(code.length - 1);
  assert.equal(f.caption.match(/The code so far: ([\d ]+)\./)[1].replace(/ /g, ""), await page.evaluate(() => document.body.dataset.code));
  await escape();
  await page.emulateMedia({ reducedMotion: "no-preference" });
  assert.deepEqual(log.pageErrors, []);
});

/** WCAG 2.0–2.2 A/AA violations on the page. */
async function axe() {
  if (!(await page.evaluate(() => typeof window.axe === "object"))) await page.addScriptTag({ path: AXE });
  return page.evaluate(async () => {
    const res = await window.axe.run(document, { runOnly: { type: "tag", values: ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa", "wcag22aa"] }, resultTypes: ["violations"] });
    return res.violations.flatMap((v) => v.nodes.map((n) => `${v.id}: ${n.target.join(" ")}`));
  });
}
