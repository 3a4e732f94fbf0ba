// The lab's engine in Chromium: the worker loads the SIMD128 build (every
// current browser validates SIMD), and on a cross-origin isolated page
// (serve.mjs `isolate`) filters and edges run over row tiles on several
// workers (www/lab/tiles.js) with the single worker's numbers at every
// pixel; without the isolation headers the lab stays on one worker.

import { test, before, after } from "node:test";
import assert from "node:assert/strict";
import { startServer } from "../../scripts/serve.mjs";
import { DIST, launchChromium, TEST_TIMEOUT } from "./harness.mjs";

let isolated, plain, browser;
before(async () => {
  isolated = await startServer({ dir: DIST, port: 0, isolate: true });
  plain = await startServer({ dir: DIST, port: 0 });
  browser = await launchChromium();
});
after(async () => {
  await browser?.close().catch(() => {});
  await isolated?.close();
  await plain?.close();
});

/** Opens the page with a fresh LabClient (`window.client`) holding a random 8-bit image, then `body(arg)` in the page. */
async function withClient(url, body, arg) {
  const context = await browser.newContext({ serviceWorkers: "block" });
  const page = await context.newPage();
  const errors = [];
  page.on("pageerror", (e) => errors.push(e.message));
  await page.goto(`${url}index.html`);
  await page.evaluate(async () => {
    const { LabClient } = await import("./lab/lab.js");
    const client = new LabClient({ onRestart: async () => {} });
    const [w, h] = [301, 257];
    const bytes = new Uint8Array(w * h);
    let s = 12345;
    for (let i = 0; i < bytes.length; i++) {
      s = (Math.imul(s, 1103515245) + 12345) >>> 0;
      // flat runs and noise
      bytes[i] = i % 7 < 2 ? 90 : s >>> 24;
    }
    await client.call("raw", { width: w, height: h, bytes: bytes.buffer }, [bytes.buffer]);
    window.client = client;
  });
  const out = await page.evaluate(body, arg);
  await page.evaluate(() => window.client.close());
  await context.close();
  assert.deepEqual(errors, []);
  return out;
}

const REQUESTS = [
  ...["mean", "gaussian-5", "median", "laplacian-8", "log", "weighted-mean"].flatMap((kernel) =>
    ["replicate", "reflect", "zero", "crop"].map((border) => ["filter", { kernel, border }])),
  ...["sobel", "prewitt"].flatMap((operator) => ["replicate", "crop"].map((border) => ["edges", { operator, border }])),
];

test("cross-origin isolated: tiled filters and edges equal the single worker at every pixel", { timeout: TEST_TIMEOUT * 3 }, async () => {
  const r = await withClient(isolated.url, async (requests) => {
    const client = window.client;
    const report = { isolated: crossOriginIsolated, threads: client.threads, engine: await client.call("engine"), diffs: [] };
    for (const [type, args] of requests) {
      const tiled = await client.call(type, args);
      const single = await client.call(type, { ...args, untiled: true });
      const tag = `${type} ${JSON.stringify(args)}`;
      if (tiled.layers.length !== single.layers.length) report.diffs.push(`${tag}: ${tiled.layers.length} layers`);
      single.layers.forEach((s, i) => {
        const t = tiled.layers[i];
        for (const k of ["name", "width", "height", "c0", "r0", "signed"]) if (t[k] !== s[k]) report.diffs.push(`${tag} ${s.name}.${k}: ${t[k]} vs ${s[k]}`);
        let bad = 0;
        for (let j = 0; j < s.data.length; j++) if (!Object.is(t.data[j], s.data[j])) bad++;
        if (bad || t.data.length !== s.data.length) report.diffs.push(`${tag} ${s.name}: ${bad} pixels differ`);
      });
    }
    report.tileWorkers = client.tiles ? client.tiles.workers.length : 0;
    return report;
  }, REQUESTS);
  assert.equal(r.isolated, true, "the isolation headers make the page cross-origin isolated");
  assert.ok(r.threads >= 2, `several workers (${r.threads})`);
  assert.equal(r.tileWorkers, r.threads, "the tiles ran on their own workers");
  assert.deepEqual(r.diffs, []);
  assert.deepEqual(r.engine, { build: "simd128", simd: true });
});

test("without the isolation headers the lab stays on one worker", { timeout: TEST_TIMEOUT }, async () => {
  const r = await withClient(plain.url, async () => {
    const client = window.client;
    const layers = (await client.call("filter", { kernel: "mean", border: "replicate" })).layers;
    return { isolated: crossOriginIsolated, threads: client.threads, tiles: client.tiles === null, height: layers[0].height };
  });
  assert.equal(r.isolated, false);
  assert.equal(r.threads, 1);
  assert.equal(r.tiles, true, "no tiles");
  assert.equal(r.height, 257);
});
