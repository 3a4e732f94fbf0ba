// The lab's previews (www/lab/live.js) in Chromium, without timing: on a
// photo of a megapixel (1024², the smallest that gets previews), a slider
// change paints its preview before the whole result is shown — for the
// k × k mean and for the Förstner window, also while the old result's
// points are drawn (their shapes once took the page a second to stroke
// before each preview could be shown) — the whole result then equals the
// operator's numbers at sample pixels (a JavaScript reference), and a newer
// value still stops a running one, whose preview and result never show.

import { test, before, after } from "node:test";
import assert from "node:assert/strict";
import { start, TEST_TIMEOUT } from "./harness.mjs";
import { idle, openLab, forstner } from "./lab-harness.mjs";

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

/** The body's marks of previews and shown results, in the order they were set, from now on. */
async function watch(page) {
  await page.evaluate(() => {
    window.labEvents = [];
    if (window.labWatching) return;
    window.labWatching = true;
    const keys = ["filterPreview", "filterShown", "forstnerPreview", "mapRuns", "forstnerCancels"];
    new MutationObserver((list) => {
      for (const m of list) {
        const key = m.attributeName.slice(5).replace(/-([a-z])/g, (_, ch) => ch.toUpperCase());
        if (keys.includes(key)) window.labEvents.push(`${key}=${document.body.dataset[key]}`);
      }
    }).observe(document.body, { attributes: true, attributeOldValue: true });
  });
}
const events = (page) => page.evaluate(() => window.labEvents);
const layerAt = (page, name, pixels) => page.evaluate(async ([name, pixels]) => (await import("./lab/lab.js")).layerForTests(name, pixels), [name, pixels]);

test("a slider change paints its preview before the whole result (k × k mean, Förstner window); the result is the operator's; a newer value stops the running one", { timeout: TEST_TIMEOUT * 4 }, async () => {
  const { page, log, context } = await openLab(env);
  await page.evaluate(async ([n, src]) => {
    const g = new Function(`return ${src}`)();
    const bytes = new Uint8Array(n * n);
    for (let r = 0; r < n; r++) for (let c = 0; c < n; c++) bytes[r * n + c] = g(c, r);
    await (await import("./lab/lab.js")).openRawForTests(n, n, bytes, "preview1024");
  }, [N, grey.toString()]);
  await page.waitForFunction(() => document.body.dataset.image === "preview1024");
  await idle(page);

  // the k × k mean: 5 then 9, each a preview first, then the whole layer
  await page.selectOption("#lab-family", "filters");
  await page.selectOption("#lab-kernel", "mean-k");
  await page.selectOption("#lab-border", "replicate");
  for (const k of [5, 9]) {
    await watch(page);
    await page.evaluate((k) => {
      const input = document.querySelector("#lab-size");
      input.value = String(k);
      input.dispatchEvent(new Event("input", { bubbles: true }));
    }, k);
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
