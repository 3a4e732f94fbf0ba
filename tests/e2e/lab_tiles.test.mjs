// The lab's engine in Chromium, on a page without the cross-origin isolation
// headers (as GitHub Pages and course platforms serve it): the image-wide
// operators run by bands of rows over a pool of workers (www/lab/tiles.js)
// with the single worker's numbers at every pixel, layers and photos are
// painted by the wasm (lab/src/paint.rs through web-sys) with the pixels the
// page's JavaScript painted before, and a lab visit fetches one of the two
// wasm builds (the SIMD one, JPEG its only decoder: the scalar build comes
// as the decoders when a photo of another format opens), within 350 KB gz.

import { test, before, after } from "node:test";
import assert from "node:assert/strict";
import fs from "node:fs";
import zlib from "node:zlib";
import { startServer } from "../../scripts/serve.mjs";
import { DIST, launchChromium, TEST_TIMEOUT } from "./harness.mjs";

let server, browser, context, page;
const errors = [];
before(async () => {
  server = await startServer({ dir: DIST, port: 0 });
  browser = await launchChromium();
  // one page for the whole file
  context = await browser.newContext({ serviceWorkers: "block" });
  page = await context.newPage();
  page.on("pageerror", (e) => errors.push(e.message));
  await page.goto(`${server.url}index.html`);
});
after(async () => {
  await context?.close().catch(() => {});
  await browser?.close().catch(() => {});
  await server?.close();
});

/**
 * A LabClient with a pool of `workers` (window.client) holding a random
 * 8-bit `w × h` image with flat runs, banded however small (minPixels 0).
 */
async function client(workers, [w, h]) {
  await page.evaluate(async ({ workers, w, h }) => {
    window.client?.close();
    const { LabClient } = await import("./lab/lab.js");
    const client = new LabClient({ onRestart: async () => {} }, { workers, minPixels: 0, minRows: 8 });
    const bytes = new Uint8Array(w * h);
    let s = 12345;
    for (let i = 0; i < bytes.length; i++) {
      s = (Math.imul(s, 1103515245) + 12345) >>> 0;
      // flat runs (ties for the suppression, zero gradients) and noise; a brighter disc (corners, edges)
      const [c, r] = [i % w, Math.floor(i / w)];
      const disc = (c - w / 2) ** 2 + (r - h / 3) ** 2 < (h / 5) ** 2 ? 80 : 0;
      bytes[i] = Math.min(255, (i % 7 < 2 ? 90 : s >>> 25) + disc);
    }
    await client.call("raw", { width: w, height: h, bytes: bytes.buffer }, [bytes.buffer]);
    window.client = client;
  }, { workers, w, h });
}

const CUSTOM = Array.from({ length: 15 }, (_, j) => Array.from({ length: 13 }, (_, i) => ((i * 7 + j * 3) % 11) - 5).join(" ")).join("\n");
const BORDERS = ["replicate", "reflect", "zero", "crop"];
/** Every request the pool runs by bands, with the parameters that change its halo. */
const REQUESTS = [
  ...["mean", "weighted-mean", "gaussian-3", "gaussian-5", "laplacian-4", "laplacian-8", "log", "sharpen", "high-pass", "median"].flatMap((kernel) =>
    BORDERS.map((border) => ["filter", { kernel, border }])),
  ...BORDERS.map((border) => ["filter", { kernel: "custom", border, custom: CUSTOM, divisor: 1 }]),
  ["filter", { kernel: "custom", border: "reflect", custom: Array(9).fill("1 1 1 1 1 1 1 1 1").join("\n"), divisor: 81 }],
  ...["sobel", "prewitt"].flatMap((operator) => BORDERS.map((border) => ["edges", { operator, border }])),
  ...[3, 5, 7, 9].map((size) => ["forstner", { size, sigmaN: 8, thresholdPx: 0.9, qMin: 0.5 }]),
  ["forstner", { size: 5, sigmaN: 8, thresholdPx: 3, qMin: 0 }],
  ...[3, 4, 8].map((size) => ["moravec", { size, threshold: 300 }]),
];

/** In the page: each request by bands and on the one main worker (untiled), every layer value and point compared. */
async function compare(requests) {
  return page.evaluate(async (requests) => {
    const client = window.client;
    const out = { diffs: [], steps: [], bands: [], points: 0 };
    for (const [type, args] of requests) {
      const tag = `${type} ${JSON.stringify(args).slice(0, 70)}`;
      const steps = [];
      const bands = await client.call(type, args, [], (p) => steps.push(p.rows));
      const one = await client.call(type, { ...args, untiled: true });
      if (!bands.bands) out.diffs.push(`${tag}: did not run by bands`);
      out.bands.push(bands.bands?.bands ?? 0);
      out.steps.push(steps.length === (bands.bands?.bands ?? -1) && steps.every((r, i) => i === 0 || r !== steps[i - 1]));
      if (one.layers.length !== bands.layers.length) out.diffs.push(`${tag}: ${bands.layers.length} layers, not ${one.layers.length}`);
      one.layers.forEach((l, i) => {
        const b = bands.layers[i];
        for (const k of ["name", "width", "height", "c0", "r0", "signed"]) if (l[k] !== b[k]) out.diffs.push(`${tag} ${l.name}.${k}: ${b[k]}, not ${l[k]}`);
        let n = 0;
        for (let j = 0; j < l.data.length; j++) if (!Object.is(l.data[j], b.data[j])) n++;
        if (n || l.data.length !== b.data.length) out.diffs.push(`${tag} ${l.name}: ${n} pixels differ`);
      });
      if (one.points || bands.points) {
        const [p, q] = [Array.from(one.points ?? []), Array.from(bands.points ?? [])];
        if (p.length !== q.length || p.some((v, j) => !Object.is(v, q[j]))) out.diffs.push(`${tag}: points ${q.length / 6}, not the one call's ${p.length / 6} (or differ)`);
        out.points += p.length / 6;
      }
    }
    out.poolWorkers = client.tiles.workers.filter(Boolean).length;
    // bands' inputs cut into buffers the workers gave back (tiles.js rows)
    out.inputsReused = client.tiles.inputsReused;
    return out;
  }, requests);
}

test("without isolation headers, every banded operator over 3 workers equals the one worker at every pixel", { timeout: TEST_TIMEOUT * 4 }, async () => {
  assert.equal(await page.evaluate(() => crossOriginIsolated), false);
  await client(3, [301, 257]);
  const r = await compare(REQUESTS);
  assert.deepEqual(r.diffs, []);
  // several bands a worker (minRows 8, at least 2·halo + … rows each), progress after each band
  assert.ok(r.bands.every((n) => n >= 3), `bands: ${r.bands}`);
  assert.ok(r.steps.every(Boolean), "a progress message after each band, rows growing");
  assert.equal(r.poolWorkers, 3);
  assert.ok(r.points > 20, `${r.points} interest points compared`);
  // most bands' inputs were cut into a buffer a worker gave back (one of their size), with the same numbers
  const bands = r.bands.reduce((a, b) => a + b, 0);
  assert.ok(r.inputsReused > bands / 2, `${r.inputsReused} of ${bands} bands' inputs in a given-back buffer`);
  assert.deepEqual(errors, []);
});

test("a boundary's layer is carried by the released layer of the one before (no fresh pages): the same pixels as a fresh one", { timeout: TEST_TIMEOUT * 2 }, async () => {
  await client(2, [301, 257]);
  const r = await page.evaluate(async () => {
    const client = window.client;
    const tiles = client.tiles;
    const out = { diffs: [], free: [] };
    const args = [{ threshold: 100, c: 150, r: 85 }, { threshold: 60, c: 20, r: 20 }, { threshold: 100, c: 150, r: 85 }];
    // fresh answers first (nothing released: no spare), kept as copies
    const fresh = [];
    for (const a of args) {
      const res = await client.call("boundary", a);
      fresh.push({ data: res.layers[0].data.slice(), pixels: Array.from(res.pixels), code: res.code });
    }
    let last = await client.call("boundary", args[0]);
    for (const [i, a] of args.entries()) {
      // the page shows the next result in place of the last (lab.js setLayers)
      client.release(last.layers);
      out.free.push(tiles.free.length);
      const res = await client.call("boundary", a);
      out.free.push(tiles.free.length);
      if ("spare" in res) out.diffs.push(`${i}: the answer kept its spare buffers`);
      const [l, f] = [res.layers[0].data, fresh[i].data];
      let n = 0;
      for (let j = 0; j < f.length; j++) if (!Object.is(l[j], f[j])) n++;
      if (n || l.length !== f.length) out.diffs.push(`${i}: ${n} pixels differ (${l.length} of ${f.length})`);
      if (JSON.stringify(Array.from(res.pixels)) !== JSON.stringify(fresh[i].pixels) || res.code !== fresh[i].code) out.diffs.push(`${i}: the boundary differs`);
      last = res;
    }
    return out;
  });
  assert.deepEqual(r.diffs, []);
  // the released layer went to the main worker with the request (1 → 0 free) and its answer's is released in turn
  assert.deepEqual(r.free, [1, 0, 1, 0, 1, 0]);
  assert.deepEqual(errors, []);
});

test("Förstner's kept map by bands: its layers, the photo's own threshold and the points of every threshold equal the one worker's", { timeout: TEST_TIMEOUT * 2 }, async () => {
  await client(3, [301, 257]);
  const r = await page.evaluate(async () => {
    const client = window.client;
    const out = { diffs: [], points: [] };
    for (const [size, sigmaN, qMin] of [[5, 8, 0.5], [7, 3, 0], [3, 8, 0.7]]) {
      const tag = `size ${size}, σn ${sigmaN}, q ${qMin}`;
      const bands = await client.call("forstnerMaps", { size, sigmaN });
      if (!bands.bands) out.diffs.push(`${tag}: did not run by bands`);
      // thresholds below and above the first (the kept suppression serves T up to twice it, then is redone)
      const ts = [bands.auto?.thresholdPx ?? 0.5, 0.3, 0.9, 2.5, 0.05];
      const banded = [];
      for (const t of ts) banded.push(await client.call("forstnerPoints", { sigmaN, thresholdPx: t, qMin }));
      const one = await client.call("forstnerMaps", { size, sigmaN, untiled: true });
      if (JSON.stringify(one.auto) !== JSON.stringify(bands.auto)) out.diffs.push(`${tag}: threshold ${JSON.stringify(bands.auto)}, not ${JSON.stringify(one.auto)}`);
      one.layers.forEach((l, i) => {
        const b = bands.layers[i];
        for (const k of ["name", "width", "height", "c0", "r0", "signed"]) if (l[k] !== b[k]) out.diffs.push(`${tag} ${l.name}.${k}`);
        let n = 0;
        for (let j = 0; j < l.data.length; j++) if (!Object.is(l.data[j], b.data[j])) n++;
        if (n) out.diffs.push(`${tag} ${l.name}: ${n} pixels differ`);
      });
      for (const [i, t] of ts.entries()) {
        const p = await client.call("forstnerPoints", { sigmaN, thresholdPx: t, qMin, untiled: true });
        const [a, b] = [Array.from(p.points), Array.from(banded[i].points)];
        if (a.length !== b.length || a.some((v, j) => !Object.is(v, b[j]))) out.diffs.push(`${tag}, T ${t}: ${b.length / 6} points, not ${a.length / 6} (or differ)`);
        out.points.push(a.length / 6);
      }
    }
    return out;
  });
  assert.deepEqual(r.diffs, []);
  assert.ok(r.points.some((n) => n > 10) && r.points.some((n) => n < r.points[0]), `points: ${r.points}`);
  assert.deepEqual(errors, []);
});

test("resampling by bands of output rows equals the one worker at every pixel", { timeout: TEST_TIMEOUT * 2 }, async () => {
  await client(2, [301, 257]);
  const r = await page.evaluate(async () => {
    const client = window.client;
    const diffs = [];
    const requests = [
      { kind: "rotate", params: [7, 1.15], width: 301, height: 257 },
      { kind: "rotate", params: [-33, 0.6], width: 180, height: 333 },
      { kind: "projective", params: [20, 10, 280, 30, 290, 240, 5, 220], width: 200, height: 150 },
    ];
    let bandsRun = 0;
    for (const args of requests) {
      const bands = await client.call("resample", args);
      const one = await client.call("resample", { ...args, untiled: true });
      bandsRun += bands.bands?.bands ?? 0;
      one.layers.forEach((l, i) => {
        const b = bands.layers[i];
        for (const k of ["name", "width", "height", "c0", "r0"]) if (l[k] !== b[k]) diffs.push(`${args.kind} ${l.name}.${k}: ${b[k]}, not ${l[k]}`);
        let n = 0;
        for (let j = 0; j < l.data.length; j++) if (!Object.is(l.data[j], b.data[j])) n++;
        if (n) diffs.push(`${args.kind} ${JSON.stringify(args.params)} ${l.name}: ${n} pixels differ`);
      });
    }
    return { diffs, bandsRun };
  });
  assert.deepEqual(r.diffs, []);
  assert.ok(r.bandsRun >= 6, `${r.bandsRun} bands`);
  assert.deepEqual(errors, []);
});

test("a colour photo (its BT.601 greys are not 8-bit) runs by bands of its grey values, equal to the one worker at every pixel", { timeout: TEST_TIMEOUT * 2 }, async () => {
  await client(2, [8, 8]);
  // a colour PNG made here (lossless), opened as the photo
  await page.evaluate(async () => {
    const [w, h] = [203, 151];
    const cv = new OffscreenCanvas(w, h);
    const ctx = cv.getContext("2d");
    const img = ctx.createImageData(w, h);
    let s = 7;
    for (let i = 0; i < w * h; i++) {
      s = (Math.imul(s, 1103515245) + 12345) >>> 0;
      const [c, r] = [i % w, Math.floor(i / w)];
      const v = ((c >> 4) + (r >> 4)) % 2 ? 180 : 60;
      img.data.set([v + (s >>> 28), (s >>> 24) & 255, 255 - v, 255], 4 * i);
    }
    ctx.putImageData(img, 0, 0);
    const bytes = await (await cv.convertToBlob({ type: "image/png" })).arrayBuffer();
    const r = await window.client.call("load", { name: "colour.png", bytes }, [bytes]);
    if (r.colour !== "colour" || r.bytes) throw new Error(`not a colour photo of fractional greys: ${r.colour}, ${Boolean(r.bytes)}`);
    // its levels (n = 299R+587G+114B over 1000) found once, what the bands are cut from
    if (!(r.levels instanceof Float32Array) || r.scale !== 1000 || r.levels.length !== w * h) throw new Error(`no levels: ${r.scale}`);
    if (r.levels.some((n, i) => n / 1000 !== r.grey[i])) throw new Error("levels that do not give the greys back");
  });
  const some = REQUESTS.filter(([type, a]) => (type === "filter" && ["custom", "median", "gaussian-5", "laplacian-8"].includes(a.kernel)) || type === "edges" || (type === "forstner" && a.size !== 9) || (type === "moravec" && a.size === 4));
  const r = await compare(some);
  assert.deepEqual(r.diffs, []);
  assert.ok(r.points > 5, `${r.points} points`);
  // bands of levels (4 bytes a pixel) cut into buffers the workers gave back too
  assert.ok(r.inputsReused > 0, `${r.inputsReused} bands' inputs in a given-back buffer`);
  const rs = await page.evaluate(async () => {
    const args = { kind: "rotate", params: [11, 0.9], width: 180, height: 140 };
    const [b, one] = [await window.client.call("resample", args), await window.client.call("resample", { ...args, untiled: true })];
    let n = 0;
    one.layers.forEach((l, i) => l.data.forEach((v, j) => (n += Object.is(v, b.layers[i].data[j]) ? 0 : 1)));
    return { n, bands: b.bands?.bands ?? 0 };
  });
  assert.equal(rs.n, 0, "resampled pixels differ");
  assert.ok(rs.bands >= 2);
  // Förstner's kept map: its layers, the photo's own threshold (the reference route's w_min) and points
  const fk = await page.evaluate(async () => {
    const client = window.client;
    const diffs = [];
    const bands = await client.call("forstnerMaps", { size: 5, sigmaN: 4 });
    const t = bands.auto?.thresholdPx;
    const bp = await client.call("forstnerPoints", { sigmaN: 4, thresholdPx: t ?? 1, qMin: 0.5 });
    const one = await client.call("forstnerMaps", { size: 5, sigmaN: 4, untiled: true });
    const op = await client.call("forstnerPoints", { sigmaN: 4, thresholdPx: t ?? 1, qMin: 0.5, untiled: true });
    if (!bands.bands) diffs.push("did not run by bands");
    if (JSON.stringify(bands.auto) !== JSON.stringify(one.auto)) diffs.push(`threshold ${JSON.stringify(bands.auto)}, not ${JSON.stringify(one.auto)}`);
    one.layers.forEach((l, i) => l.data.forEach((v, j) => Object.is(v, bands.layers[i].data[j]) || diffs.push(`${l.name} ${j}`)));
    if (JSON.stringify(Array.from(bp.points)) !== JSON.stringify(Array.from(op.points))) diffs.push(`points ${bp.points.length / 6}, not ${op.points.length / 6}`);
    return { diffs: diffs.slice(0, 5), auto: one.auto, points: op.points.length / 6 };
  });
  assert.deepEqual(fk.diffs, []);
  assert.ok(fk.auto && fk.points > 0, JSON.stringify(fk));
  assert.deepEqual(errors, []);
});

test("bands equal the one worker on a tall thin and a wide flat image (bands of a few rows, halos over several bands)", { timeout: TEST_TIMEOUT * 2 }, async () => {
  const some = REQUESTS.filter(([type, a]) => (type === "filter" && ["custom", "median", "log"].includes(a.kernel) && a.border !== "zero") || type === "forstner" || (type === "moravec" && a.size === 8));
  for (const size of [[23, 400], [517, 40]]) {
    await client(2, size);
    const r = await compare(some);
    assert.deepEqual(r.diffs, [], `${size.join(" × ")}`);
  }
  assert.deepEqual(errors, []);
});

test("a cancel stops the bands, not the main worker: the photo stays, and the next run is whole", { timeout: TEST_TIMEOUT * 2 }, async () => {
  await client(2, [640, 600]);
  const r = await page.evaluate(async (custom) => {
    const client = window.client;
    const args = { kernel: "custom", border: "reflect", custom, divisor: 1 };
    let cancelled = null;
    const running = client.call("filter", args, [], () => {
      // at the first band done: the others are still to come
      if (!cancelled) cancelled = client.cancel() ?? true;
    }).then(() => "finished", (e) => (e.cancelled ? "cancelled" : e.message));
    const outcome = await running;
    const after = await client.call("filter", args);
    const one = await client.call("filter", { ...args, untiled: true });
    let differ = 0;
    for (let j = 0; j < one.layers[0].data.length; j++) if (!Object.is(one.layers[0].data[j], after.layers[0].data[j])) differ++;
    return { outcome, sent: client.sent, differ, height: after.layers[0].height, busy: client.busy };
  }, CUSTOM);
  assert.equal(r.outcome, "cancelled");
  assert.equal(r.sent.raw, 1, "the photo never had to be sent again");
  assert.equal(r.differ, 0);
  assert.equal(r.height, 600);
  assert.equal(r.busy, false);
  assert.deepEqual(errors, []);
});

test("layers and photos are painted by the wasm (web-sys ImageData) with the pixels of the page's old JavaScript painting", { timeout: TEST_TIMEOUT * 2 }, async () => {
  const toml = fs.readFileSync(new URL("../../lab/Cargo.toml", import.meta.url), "utf8");
  assert.match(toml, /^web-sys = \{ version = "0\.3", features = \["ImageData"\] \}$/m);
  await client(2, [64, 48]);
  // layers as the operators give them: grey (0 … 255, halves, a flat one), signed with NaN and ±∞, f32, two of over a megapixel (painted
  // part by part) and two of over 2 MP (painted by bands on the pool's workers)
  const specs = [
    { w: 97, h: 61, signed: false, kind: "grey", type: "Float64Array" },
    { w: 50, h: 40, signed: false, kind: "halves", type: "Float64Array" },
    { w: 33, h: 17, signed: false, kind: "flat", type: "Float64Array" },
    { w: 89, h: 73, signed: true, kind: "signed", type: "Float64Array" },
    { w: 64, h: 64, signed: true, kind: "signed", type: "Float32Array" },
    { w: 71, h: 3, signed: true, kind: "nan", type: "Float64Array" },
    { w: 71, h: 5, signed: false, kind: "nan", type: "Float32Array" },
    { w: 1201, h: 1003, signed: false, kind: "grey", type: "Float32Array" },
    { w: 1100, h: 1000, signed: true, kind: "signed", type: "Float64Array" },
    // over 2 MP: painted by bands on both workers
    { w: 2101, h: 1103, signed: false, kind: "grey", type: "Float32Array" },
    { w: 1500, h: 1500, signed: true, kind: "nan", type: "Float32Array" },
  ];
  const r = await page.evaluate(async (specs) => {
    const { SIGNED_NEGATIVE, SIGNED_POSITIVE } = await import("./colour-scales.js");
    // the page's painting before the wasm (view.js's scaleOf and paint): the reference
    const reference = (data, signed) => {
      let [lo, hi] = [Infinity, -Infinity];
      for (const v of data) if (Number.isFinite(v)) [lo, hi] = [Math.min(lo, v), Math.max(hi, v)];
      if (!(lo <= hi)) [lo, hi] = [0, 0];
      const m = Math.max(Math.abs(lo), Math.abs(hi)) || 1;
      const s = signed ? { lo: -m, hi: m, min: lo, max: hi } : { lo, hi: hi > lo ? hi : lo + 1, min: lo, max: hi };
      const out = new Uint8ClampedArray(data.length * 4);
      for (let i = 0; i < data.length; i++) {
        const v = data[i];
        if (!Number.isFinite(v)) continue;
        let rgb;
        if (signed) {
          const u = Math.max(-1, Math.min(1, v / s.hi));
          const end = u < 0 ? SIGNED_NEGATIVE : SIGNED_POSITIVE;
          rgb = end.map((e) => Math.round(255 - Math.abs(u) * (255 - e)));
        } else {
          const g = Math.round(((v - s.lo) / (s.hi - s.lo)) * 255);
          rgb = [g, g, g];
        }
        out.set([...rgb, 255], i * 4);
      }
      return { scale: s, rgba: out };
    };
    let seed = 99;
    const rnd = () => ((seed = (Math.imul(seed, 1103515245) + 12345) >>> 0) / 2 ** 32);
    const layers = specs.map(({ w, h, signed, kind, type }) => {
      const data = new globalThis[type](w * h);
      for (let i = 0; i < data.length; i++) {
        const x = rnd();
        data[i] = kind === "flat" ? 7 : kind === "halves" ? (i % 3) * 0.5 : kind === "nan" && x < 0.3 ? [NaN, Infinity, -Infinity][i % 3] : signed ? (x - 0.4) * 1e3 : x * 255 + 3;
      }
      return { data, width: w, height: h, signed };
    });
    // all at once: several paintings interleave in each worker (each one's pixels must be its own)
    const paintings = await Promise.all(layers.map((l) => window.client.paint(l)));
    const report = [];
    for (const [i, { w, h, signed, kind, type }] of specs.entries()) {
      const { data } = layers[i];
      const p = paintings[i];
      const ctx = new OffscreenCanvas(w, h).getContext("2d");
      ctx.drawImage(p.bitmap, 0, 0);
      const got = ctx.getImageData(0, 0, w, h).data;
      const want = reference(data, signed);
      let bad = 0;
      let first = null;
      for (let j = 0; j < got.length; j++) {
        if (got[j] !== want.rgba[j]) {
          bad++;
          first ??= `pixel ${j >> 2} (${data[j >> 2]}): ${got.slice(j & ~3, (j & ~3) + 4)}, not ${want.rgba.slice(j & ~3, (j & ~3) + 4)}`;
        }
      }
      report.push({ tag: `${kind} ${type} ${w} × ${h}`, size: [p.bitmap.width, p.bitmap.height], scale: p.scale, want: { ...want.scale, signed }, bad, first });
    }
    return report;
  }, specs);
  for (const [i, x] of r.entries()) {
    assert.deepEqual(x.size, [specs[i].w, specs[i].h], x.tag);
    assert.deepEqual(x.scale, x.want, `${x.tag}: the scale`);
    assert.equal(x.bad, 0, `${x.tag}: ${x.bad} bytes differ (${x.first})`);
  }
  // the ends of the signed scale are colour-scales.js's, white at 0
  const ends = await page.evaluate(async () => {
    const p = await window.client.paint({ data: Float64Array.from([-2, 0, 2]), width: 3, height: 1, signed: true });
    const ctx = new OffscreenCanvas(3, 1).getContext("2d");
    ctx.drawImage(p.bitmap, 0, 0);
    const { SIGNED_NEGATIVE, SIGNED_POSITIVE } = await import("./colour-scales.js");
    return { got: Array.from(ctx.getImageData(0, 0, 3, 1).data), want: [...SIGNED_NEGATIVE, 255, 255, 255, 255, 255, ...SIGNED_POSITIVE, 255] };
  });
  assert.deepEqual(ends.got, ends.want);
  assert.deepEqual(errors, []);
});

test("a lab visit fetches one lab wasm (the SIMD build, JPEG its only decoder) and at most 350 KB gz of lab JS and wasm; a PNG then brings the decoders", { timeout: TEST_TIMEOUT }, async () => {
  const ctx = await browser.newContext({ serviceWorkers: "block" });
  await ctx.addInitScript(() => {
    globalThis.__playgroundTest = true;
  });
  const p = await ctx.newPage();
  const fetched = [];
  p.on("request", (req) => fetched.push(new URL(req.url()).pathname.slice(1)));
  await p.goto(`${server.url}index.html`);
  await p.waitForLoadState("networkidle");
  const home = fetched.length;
  await p.goto(`${server.url}index.html#/lab`);
  await p.waitForFunction(() => document.body.dataset.labRestored === "1" && document.body.dataset.lab === "idle" && /threads?\.$/.test(document.getElementById("lab-engine").textContent), null, { timeout: 30_000 });
  const cores = await p.evaluate(() => navigator.hardwareConcurrency);
  const engine = await p.textContent("#lab-engine");
  const visit = [...new Set(fetched.slice(home))].filter((f) => /\.(js|wasm)$/.test(f));
  // a PNG sample: the scalar build comes as the decoders
  await p.selectOption("#lab-sample", "camera.png");
  await p.click("#lab-open-sample");
  await p.waitForFunction(() => (document.body.dataset.image || "").startsWith("camera.png") && document.body.dataset.lab === "idle", null, { timeout: 30_000 });
  const info = await p.textContent("#lab-info");
  const after = [...new Set(fetched)];
  await ctx.close();
  const assets = JSON.parse(fs.readFileSync(`${DIST}/assets.json`, "utf8"));
  const [simd, scalar] = ["lab/pkg-simd/photogrammetry_lab_bg.wasm", "lab/pkg/photogrammetry_lab_bg.wasm"].map((f) => assets[f]);
  assert.equal(engine, `Engine: fast (SIMD), ${Math.min(8, cores)} thread${Math.min(8, cores) > 1 ? "s" : ""}.`);
  assert.deepEqual(visit.filter((f) => f.endsWith(".wasm")), [simd], "the visit fetches the SIMD build only");
  const gz = (f) => zlib.gzipSync(fs.readFileSync(`${DIST}/${f}`), { level: 9 }).length;
  const bytes = visit.reduce((s, f) => s + gz(f), 0);
  assert.ok(bytes <= 350_000, `a lab visit: ${bytes} B gz of JS and wasm (${visit.join(", ")})`);
  assert.match(info, /^camera\.png: 512 × 512 pixels, PNG, grey, 8-bit/);
  assert.ok(after.includes(scalar), "the PNG was decoded by the scalar build");
});
