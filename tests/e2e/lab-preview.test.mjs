// The lab's previews (www/lab/live.js) in Chromium, without timing: on a
// photo of a megapixel (1024², the smallest that gets previews), a slider
// change paints its preview before the whole result is shown — for the
// k × k mean and for the Förstner window, also while the old result's
// points are drawn (their shapes once took the page a second to stroke
// before each preview could be shown) — the whole result then equals the
// operator's numbers at sample pixels (a JavaScript reference), and a newer
// value still stops a running one, whose preview and result never show.
// The same for a new edge operator or border, and for a new rotation angle
// (the preview: the part of the OUTPUT in the three methods' views): the
// preview's numbers are the whole result's at the same pixels. A lower
// Förstner threshold draws the points on screen that pass it at once, and
// the kept map's answer is the same points; a higher one waits for it.

import { test, before, after } from "node:test";
import assert from "node:assert/strict";
import { start, TEST_TIMEOUT } from "./harness.mjs";
import { idle, openLab, forstner, sample } from "./lab-harness.mjs";

let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

const N = 1024;
const grey = (c, r) => (((c >> 5) + (r >> 5)) & 1 ? 190 : 60) + ((c * 7 + r * 13) % 17);
const at = (c, r) => grey(Math.min(N - 1, Math.max(0, c)), Math.min(N - 1, Math.max(0, r)));
const mean = (c, r, k) => {
  const h = (k - 1) / 2;
  let s = 0;
  for (let dr = -h; dr <= h; dr++) for (let dc = -h; dc <= h; dc++) s += at(c + dc, r + dr);
  return s / (k * k);
};

/**
 * The checkerboard `grey` opened as the photo, once the lab's start sample is
 * open (else that sample's load, still on its way, could land in the main
 * worker after it: the page would show the checkerboard and the previews be
 * made of the sample).
 */
async function openCheckerboard(page) {
  await page.waitForFunction(() => document.body.dataset.labRestored === "1" && document.body.dataset.lab === "idle", null, { timeout: 60_000 });
  await page.evaluate(async ([n, src]) => {
    const g = new Function(`return ${src}`)();
    const bytes = new Uint8Array(n * n);
    for (let r = 0; r < n; r++) for (let c = 0; c < n; c++) bytes[r * n + c] = g(c, r);
    await (await import("./lab/lab.js")).openRawForTests(n, n, bytes, "preview1024");
  }, [N, grey.toString()]);
  await page.waitForFunction(() => document.body.dataset.image === "preview1024");
  await idle(page);
}

/** The body's marks of previews and shown results, in the order they were set, from now on. */
async function watch(page) {
  await page.evaluate(() => {
    window.labEvents = [];
    if (window.labWatching) return;
    window.labWatching = true;
    const keys = ["filterPreview", "filterShown", "forstnerPreview", "mapRuns", "forstnerCancels", "edgesPreview", "edgesShown", "edgesCancels", "resamplePreview", "resampleShown", "resampleCancels", "thresholdPreview", "threshold", "thresholdSame", "points"];
    new MutationObserver((list) => {
      for (const m of list) {
        const key = m.attributeName.slice(5).replace(/-([a-z])/g, (_, ch) => ch.toUpperCase());
        if (keys.includes(key)) window.labEvents.push(`${key}=${document.body.dataset[key]}`);
      }
    }).observe(document.body, { attributes: true, attributeOldValue: true });
  });
}
/** Moves slider `selector` to `value` as a drag does (an "input" event). */
const slide = (page, selector, value) => page.evaluate(([selector, value]) => {
  const input = document.querySelector(selector);
  input.value = String(value);
  input.dispatchEvent(new Event("input", { bubbles: true }));
}, [selector, value]);
const events = (page) => page.evaluate(() => window.labEvents);
const layerAt = (page, name, pixels) => page.evaluate(async ([name, pixels]) => (await import("./lab/lab.js")).layerForTests(name, pixels), [name, pixels]);

/**
 * `changes` made while the first is computed (changeWhileRunning) on live
 * controller `name` (its test hooks: <name>Cancels, <name>Shown, <name>Live):
 * exactly one cancel, and only the newest, `shown`, drawn. The events seen.
 */
async function newestWins(page, name, changes, shown) {
  const hook = (k) => `${name}${k}`;
  const cancels0 = Number(await page.evaluate((k) => document.body.dataset[k] ?? 0, hook("Cancels")));
  await watch(page);
  await changeWhileRunning(page, changes);
  await page.waitForFunction(([s, l, want]) => document.body.dataset[s] === want && document.body.dataset[l] === "idle", [hook("Shown"), hook("Live"), shown], { timeout: 60_000 });
  await idle(page);
  const ev = await events(page);
  assert.equal(Number(await page.evaluate((k) => document.body.dataset[k], hook("Cancels"))) - cancels0, 1, `${ev}`);
  assert.deepEqual(ev.filter((e) => e.startsWith(`${hook("Shown")}=`)), [`${hook("Shown")}=${shown}`], `${ev}`);
  return ev;
}

test("a slider change paints its preview before the whole result (k × k mean, Förstner window); the result is the operator's; a newer value stops the running one", { timeout: TEST_TIMEOUT * 4 }, async () => {
  const { page, log, context } = await openLab(env);
  await openCheckerboard(page);

  // the k × k mean: 5 then 9, each a preview first, then the whole layer
  await page.selectOption("#lab-family", "filters");
  await page.selectOption("#lab-kernel", "mean-k");
  await page.selectOption("#lab-border", "replicate");
  for (const k of [5, 9]) {
    await watch(page);
    await slide(page, "#lab-size", k);
    await page.waitForFunction((k) => document.body.dataset.filterShown === `mean ${k}×${k}`, k, { timeout: 60_000 });
    await idle(page);
    const ev = await events(page);
    const p = ev.findIndex((e) => e.startsWith("filterPreview="));
    const shown = ev.indexOf(`filterShown=mean ${k}×${k}`);
    assert.ok(p >= 0 && p < shown, `mean ${k}: preview before the whole result: ${ev}`);
    // the preview's box: inside the photo, a part of it with the view's middle
    const [c, r, w, h] = ev[p].split("=")[1].split(",").map(Number);
    assert.ok(c >= 0 && r >= 0 && w > 0 && h > 0 && c + w <= N && r + h <= N && w * h <= 1 << 18, ev[p]);
    const pixels = [[0, 0], [511, 512], [1023, 700], [c, r]];
    const got = await layerAt(page, null, pixels);
    assert.equal(got.name, `mean ${k}×${k}`);
    pixels.forEach(([pc, pr], i) => assert.equal(got.values[i], Math.fround(mean(pc, pr, k)), `mean ${k} at (${pc}, ${pr})`));
  }

  // Förstner: Run (window 5), its points drawn; then window 7: its preview before the new map
  await page.selectOption("#lab-family", "interest");
  await page.selectOption("#lab-interest", "forstner");
  await page.click("#lab-run");
  await page.waitForFunction(() => document.body.dataset.threshold && document.body.dataset.forstnerLive === "idle", null, { timeout: 90_000 });
  await idle(page);
  const points = Number(await page.evaluate(() => document.body.dataset.points));
  assert.ok(points > 200, `${points} points on the checkerboard (the shapes drawn under the preview)`);
  const runs0 = Number(await page.evaluate(() => document.body.dataset.mapRuns));
  await watch(page);
  await page.fill("#lab-window", "7");
  await page.dispatchEvent("#lab-window", "change");
  await page.waitForFunction((r) => Number(document.body.dataset.mapRuns) > r && document.body.dataset.forstnerLive === "idle", runs0, { timeout: 90_000 });
  await idle(page);
  let ev = await events(page);
  const p = ev.findIndex((e) => e.startsWith("forstnerPreview="));
  const map = ev.findIndex((e) => e.startsWith("mapRuns="));
  assert.ok(p >= 0 && p < map, `Förstner window 7: preview before the new map: ${ev}`);
  const pixels = [[100, 100], [96, 96], [500, 330], [63, 64]];
  const w = await layerAt(page, "w", pixels);
  pixels.forEach(([c, r], i) => {
    const want = forstner(at, c, r, 7).w;
    assert.ok(Math.abs(w.values[i] - want) <= 1e-5 * Math.max(1, Math.abs(want)), `w (7×7) at (${c}, ${r}): ${w.values[i]} vs ${want}`);
  });

  // a newer window while the map of the one before is computed (at its first band's progress):
  // that one is stopped, and only the newest value's preview and map are shown
  const cancels0 = Number(await page.evaluate(() => document.body.dataset.forstnerCancels ?? 0));
  const runs1 = Number(await page.evaluate(() => document.body.dataset.mapRuns));
  await watch(page);
  await page.evaluate(async () => {
    const lab = await import("./lab/lab.js");
    const input = document.querySelector("#lab-window");
    for (const v of [9, 5]) {
      const running = v === 5 ? null : lab.progressForTests();
      input.value = String(v);
      input.dispatchEvent(new Event("change", { bubbles: true }));
      await running;
    }
  });
  await page.waitForFunction((r) => Number(document.body.dataset.mapRuns) > r && document.body.dataset.forstnerLive === "idle", runs1, { timeout: 90_000 });
  await idle(page);
  ev = await events(page);
  assert.equal(Number(await page.evaluate(() => document.body.dataset.forstnerCancels)) - cancels0, 1, `${ev}`);
  // (the map's result and its points both say how many maps were computed)
  assert.deepEqual([...new Set(ev.filter((e) => e.startsWith("mapRuns=")))], [`mapRuns=${runs1 + 1}`], `one map shown: ${ev}`);
  const last = ev.findLastIndex((e) => e.startsWith("forstnerPreview="));
  assert.ok(last >= 0 && last < ev.findIndex((e) => e.startsWith("mapRuns=")), `${ev}`);
  const w5 = await layerAt(page, "w", pixels);
  pixels.forEach(([c, r], i) => {
    const want = forstner(at, c, r, 5).w;
    assert.ok(Math.abs(w5.values[i] - want) <= 1e-5 * Math.max(1, Math.abs(want)), `w (5×5) at (${c}, ${r}): ${w5.values[i]} vs ${want}`);
  });
  assert.equal(await page.inputValue("#lab-window"), "5");
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

/** The previews drawn into the views of `selector` from now on (each view's setPreview recorded: { name, rect, values }). */
async function recordPreviews(page, selector) {
  await page.evaluate((selector) => {
    window.labPreviews = [];
    window.labDrawn = (canvas, [c, r, w, h]) => {
      const v = canvas.labViewer;
      const [x, y] = [Math.round((c + w / 2) * v.zoom + v.ox) - 8, Math.round((r + h / 2) * v.zoom + v.oy) - 8];
      const d = canvas.getContext("2d").getImageData(x, y, 16, 16).data;
      const sum = [0, 0, 0];
      for (let i = 0; i < d.length; i += 4) for (let k = 0; k < 3; k++) sum[k] += d[i + k];
      return sum.map((t) => t / 256);
    };
    for (const canvas of document.querySelectorAll(selector)) {
      const v = canvas.labViewer;
      v.setPreview = (p) => {
        Object.getPrototypeOf(v).setPreview.call(v, p);
        // and the view's mean colour over the preview box's middle (16 × 16 canvas pixels) as drawn with it
        if (p) window.labPreviews.push({ view: v.name ?? null, name: p.name, rect: p.rect, values: Array.from(p.values), drawn: window.labDrawn(canvas, p.rect) });
      };
    }
  }, selector);
}
const previews = (page) => page.evaluate(() => window.labPreviews);
/** Pixels of box [c, r, w, h]: its corners and middle. */
const inside = ([c, r, w, h]) => [[c, r], [c + w - 1, r], [c, r + h - 1], [c + w - 1, r + h - 1], [c + (w >> 1), r + (h >> 1)]];
/** Prewitt's and Sobel's magnitude at (c, r), replicated border (the course's kernels: gx top minus bottom, gy right minus left). */
const magnitude = (op, c, r) => {
  const m = op === "sobel" ? 2 : 1;
  const gx = at(c - 1, r - 1) + m * at(c, r - 1) + at(c + 1, r - 1) - at(c - 1, r + 1) - m * at(c, r + 1) - at(c + 1, r + 1);
  const gy = at(c + 1, r - 1) + m * at(c + 1, r) + at(c + 1, r + 1) - at(c - 1, r - 1) - m * at(c - 1, r) - at(c - 1, r + 1);
  return Math.hypot(gx, gy);
};

/** Changes the values of `changes` [[selector, value, event]] in turn, each after the one before has shown its first band's progress. */
async function changeWhileRunning(page, changes) {
  await page.evaluate(async (changes) => {
    const lab = await import("./lab/lab.js");
    for (const [i, [selector, value, type]] of changes.entries()) {
      const running = i === changes.length - 1 ? null : lab.progressForTests();
      const input = document.querySelector(selector);
      input.value = value;
      input.dispatchEvent(new Event(type, { bubbles: true }));
      await running;
    }
  }, changes);
}

test("a new edge operator or border, and a new rotation, paint their preview before the whole result, with its numbers; a newer choice stops the running one", { timeout: TEST_TIMEOUT * 4 }, async () => {
  const { page, log, context } = await openLab(env);
  await openCheckerboard(page);

  // edges: Run (Sobel), then Prewitt chosen: its preview (the magnitude shown) first, then the whole layers
  await page.selectOption("#lab-family", "edges");
  await page.selectOption("#lab-border", "replicate");
  await page.click("#lab-run");
  await page.waitForFunction(() => document.body.dataset.edgesShown === "sobel replicate", null, { timeout: 60_000 });
  await idle(page);
  await watch(page);
  await recordPreviews(page, ".lab-canvas");
  await page.selectOption("#lab-operator", "prewitt");
  await page.waitForFunction(() => document.body.dataset.edgesShown === "prewitt replicate" && document.body.dataset.edgesLive === "idle", null, { timeout: 60_000 });
  await idle(page);
  let ev = await events(page);
  let p = ev.findIndex((e) => e.startsWith("edgesPreview="));
  assert.ok(p >= 0 && p < ev.indexOf("edgesShown=prewitt replicate"), `Prewitt: preview before the whole result: ${ev}`);
  let [pv] = await previews(page);
  assert.equal(pv.name, "magnitude");
  assert.equal(ev[p], `edgesPreview=${pv.rect.join(",")}`);
  // drawn as the result then is (over the photo, not over the old layer: that drew it 14 grey levels darker here)
  const now = await page.evaluate((rect) => window.labDrawn(document.querySelector("#lab-stage .lab-canvas"), rect), pv.rect);
  assert.ok(now.every((x, k) => Math.abs(x - pv.drawn[k]) <= 4), `the preview drawn ${pv.drawn.map(Math.round)}, the result ${now.map(Math.round)}`);
  let pixels = inside(pv.rect);
  let got = await layerAt(page, "magnitude", pixels);
  pixels.forEach(([c, r], i) => {
    const [pc, pr] = [c - pv.rect[0], r - pv.rect[1]];
    assert.equal(pv.values[pr * pv.rect[2] + pc], got.values[i], `Prewitt magnitude at (${c}, ${r}): the preview's is the result's`);
    assert.ok(Math.abs(got.values[i] - magnitude("prewitt", c, r)) <= 1e-4, `Prewitt magnitude at (${c}, ${r}): ${got.values[i]} vs ${magnitude("prewitt", c, r)}`);
  });

  // Sobel while Prewitt's reflect border is being computed: that one is stopped, only Sobel's shows
  ev = await newestWins(page, "edges", [["#lab-border", "reflect", "change"], ["#lab-operator", "sobel", "change"]], "sobel reflect");
  assert.ok(ev.findLastIndex((e) => e.startsWith("edgesPreview=")) < ev.indexOf("edgesShown=sobel reflect"), `${ev}`);
  got = await layerAt(page, "magnitude", [[511, 512], [700, 300]]);
  [[511, 512], [700, 300]].forEach(([c, r], i) => assert.ok(Math.abs(got.values[i] - magnitude("sobel", c, r)) <= 1e-4, `Sobel at (${c}, ${r})`));

  // resampling: Run (10°, scale 2), then 20°: a preview of the part of the output in the three views, then the whole
  await page.selectOption("#lab-family", "resampling");
  await page.fill("#lab-angle", "10");
  await page.fill("#lab-scale", "2");
  await page.click("#lab-run");
  await page.waitForFunction(() => document.body.dataset.resampleShown === "10,2" && document.body.dataset.resampleLive === "idle", null, { timeout: 60_000 });
  await idle(page);
  await watch(page);
  await recordPreviews(page, "#lab-methods canvas");
  await page.fill("#lab-angle", "20");
  await page.waitForFunction(() => document.body.dataset.resampleShown === "20,2" && document.body.dataset.resampleLive === "idle", null, { timeout: 60_000 });
  await idle(page);
  ev = await events(page);
  p = ev.findIndex((e) => e.startsWith("resamplePreview="));
  assert.ok(p >= 0 && p < ev.indexOf("resampleShown=20,2"), `20°: preview before the whole result: ${ev}`);
  const pvs = await previews(page);
  assert.deepEqual(pvs.map((v) => v.view), ["nearest", "bilinear", "bicubic"]);
  const views = await page.$$eval("#lab-methods canvas", (cs) => cs.map((c) => ({ name: c.labViewer.name, box: c.labViewer.visible() })));
  for (const pv of pvs) {
    assert.equal(pv.name, pv.view);
    // the preview covers the part of the output in the view (the views keep their place)
    const box = views.find((v) => v.name === pv.view).box;
    assert.deepEqual(pv.rect, box, `${pv.view}: the preview is the part of the output in view`);
    const values = await page.$eval(`#lab-methods figure:nth-child(${pvs.indexOf(pv) + 1}) canvas`, (c, px) => px.map(([x, y]) => c.labViewer.image.grey[y * c.labViewer.image.width + x]), inside(pv.rect));
    inside(pv.rect).forEach(([c, r], i) => {
      const [pc, pr] = [c - pv.rect[0], r - pv.rect[1]];
      assert.equal(pv.values[pr * pv.rect[2] + pc], values[i], `${pv.view} at output (${c}, ${r}): the preview's is the result's`);
    });
  }

  // 30° while 40° is computed: 40° stopped, only 30° shown
  await newestWins(page, "resample", [["#lab-angle", "40", "input"], ["#lab-angle", "30", "input"]], "30,2");
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("a lower Förstner threshold draws the passing points on screen at once, the kept map's answer the same; a higher one waits for it; the newest T is shown", { timeout: TEST_TIMEOUT * 2 }, async () => {
  const { page, log, context } = await openLab(env);
  // a photo (its corners of every strength: a lower T keeps fewer)
  await page.waitForFunction(() => document.body.dataset.labRestored === "1" && document.body.dataset.lab === "idle", null, { timeout: 60_000 });
  await sample(page, "camera.png");
  await page.selectOption("#lab-family", "interest");
  await page.selectOption("#lab-interest", "forstner");
  await page.click("#lab-run");
  await page.waitForFunction(() => document.body.dataset.threshold && document.body.dataset.forstnerLive === "idle", null, { timeout: 90_000 });
  await idle(page);
  const t0 = Number(await page.evaluate(() => document.body.dataset.threshold));
  assert.match(await page.textContent("#lab-threshold-rule"), /^T = [\d.]+ px, chosen for this photo/);
  const n0 = Number(await page.evaluate(() => document.body.dataset.points));
  const settle = async (t) => {
    await page.waitForFunction((t) => document.body.dataset.threshold === t && document.body.dataset.forstnerLive === "idle", String(t), { timeout: 60_000 });
    await idle(page);
  };
  // lowered: drawn at once (before the kept map's answer), then the answer, the same points
  const low = Math.round(t0 * 70) / 100;
  await watch(page);
  await slide(page, "#lab-threshold", low);
  await settle(low);
  let ev = await events(page);
  const pre = ev.indexOf(`thresholdPreview=${low}`);
  assert.ok(pre >= 0 && pre < ev.indexOf(`threshold=${low}`), `T ${t0} -> ${low}: the points drawn before the kept map answers: ${ev}`);
  assert.ok(ev.includes("thresholdSame=true"), `the kept map's points are the ones drawn: ${ev}`);
  const n1 = Number(await page.evaluate(() => document.body.dataset.points));
  // the words under the slider follow it: the student's T, the photo's own beside it
  assert.match(await page.textContent("#lab-threshold-rule"), new RegExp(`^T = ${low} px as you set it\\. For this photo the lab would choose `));
  assert.ok(n1 > 0 && n1 < n0, `${n0} points at T ${t0}, ${n1} at ${low}`);
  // raised: no points to filter, the kept map's answer drawn
  const high = Math.round(t0 * 130) / 100;
  await watch(page);
  await slide(page, "#lab-threshold", high);
  await settle(high);
  ev = await events(page);
  assert.ok(!ev.some((e) => e.startsWith("thresholdPreview=")) && ev.includes("thresholdSame=false"), `T raised to ${high}: ${ev}`);
  const n2 = Number(await page.evaluate(() => document.body.dataset.points));
  assert.ok(n2 > n0, `${n0} points at T ${t0}, ${n2} at ${high}`);
  // lowered twice, the second while the first's answer is on its way: each drawn at once, the newest stays, and is the kept map's
  const [a, b] = [Math.round(t0 * 110) / 100, Math.round(t0 * 80) / 100];
  await watch(page);
  await slide(page, "#lab-threshold", a);
  await slide(page, "#lab-threshold", b);
  await settle(b);
  ev = await events(page);
  assert.deepEqual(ev.filter((e) => e.startsWith("thresholdPreview=")), [`thresholdPreview=${a}`, `thresholdPreview=${b}`], `T ${t0}, ${high} -> ${a}, ${b}: ${ev}`);
  assert.equal(ev.filter((e) => e.startsWith("threshold=")).at(-1), `threshold=${b}`, `${ev}`);
  assert.equal(ev.filter((e) => e.startsWith("thresholdSame=")).at(-1), "thresholdSame=true", `${ev}`);
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});
