// npm run bench -- --lab: the image lab's operators on a 2048 × 2048 image,
// milliseconds per call in Node and in Chromium's Web Worker (the lab's own
// worker.js, timed inside the worker), and the lab module's gzipped size.
// Benchmarks, not tests. Timing rules of ../shared/bench/TASKS.md for every
// operator: BENCH_WARMUP (2) untimed calls on the same image (the second
// lets V8 tier the wasm up), then n = clamp(floor(BENCH_BUDGET_S (1.5) /
// t_last_warmup), BENCH_MIN_REPS (5), BENCH_MAX_REPS (25)) timed calls;
// median [min–max]. BENCH_SIZE (2048) sets the image side. Every operator
// family of the worker is timed: filters, edges, Förstner (whole, and the
// live threshold: the kept map, then points only), Moravec, correlation
// (+ LSM), resampling, boundary, fiducials (on the scanned frame).
import fs from "node:fs";
import zlib from "node:zlib";
import { launchChromium } from "./chromium.mjs";
import { startServer } from "./serve.mjs";

const N = Number(process.env.BENCH_SIZE || 2048);
const env = (k, d) => (process.env[k] !== undefined ? Number(process.env[k]) : d);
const RULES = { budget: env("BENCH_BUDGET_S", 1.5), min: env("BENCH_MIN_REPS", 5), max: env("BENCH_MAX_REPS", 25), warm: env("BENCH_WARMUP", 2) };
/** TASKS.md's rule: warm-ups, then n timed calls; median, min, max (ms). `run` returns the ms of one call. */
async function timed(run, rules) {
  let last = 0;
  for (let i = 0; i < rules.warm; i++) last = await run();
  const n = Math.min(rules.max, Math.max(rules.min, Math.floor((rules.budget * 1000) / Math.max(last, 1e-3))));
  const ts = [];
  for (let i = 0; i < n; i++) ts.push(await run());
  ts.sort((a, b) => a - b);
  return { median: ts[Math.floor(n / 2)], min: ts[0], max: ts[n - 1], n };
}

/** A deterministic test image: smooth ramps, blocks and discs, hash noise (0…255). */
function image(n) {
  const out = new Uint8Array(n * n);
  for (let r = 0; r < n; r++) {
    for (let c = 0; c < n; c++) {
      let v = 60 + (100 * c) / n + 40 * Math.sin(r / 37);
      if (((c >> 6) + (r >> 6)) % 3 === 0) v += 50;
      const dx = (c % 128) - 64;
      const dy = (r % 128) - 64;
      if (dx * dx + dy * dy < 400) v -= 40;
      let h = Math.imul(c, 0x9e3779b1) ^ Math.imul(r, 0x85ebca77);
      h ^= h >>> 15;
      h = Math.imul(h, 0x2c1b3c6d);
      h ^= h >>> 12;
      v += ((h >>> 0) % 33) - 16;
      out[r * n + c] = Math.max(0, Math.min(255, Math.round(v)));
    }
  }
  return out;
}

const half = N / 2;
/** The operators, as [name, worker request type, arguments]; "frame" ones run on the scanned frame. */
const OPS = [
  ["filter mean 3×3", "filter", { kernel: "mean", border: "replicate" }],
  ["filter Gaussian 3×3", "filter", { kernel: "gaussian-3", border: "replicate" }],
  ["filter Gaussian 5×5", "filter", { kernel: "gaussian-5", border: "replicate" }],
  ["filter median 3×3", "filter", { kernel: "median", border: "replicate" }],
  ["filter LoG 5×5", "filter", { kernel: "log", border: "replicate" }],
  ["edges Sobel (gx, gy, magnitude, direction)", "edges", { operator: "sobel", border: "replicate" }],
  ["edges Prewitt (gx, gy, magnitude, direction)", "edges", { operator: "prewitt", border: "replicate" }],
  ["Förstner w, q + points (5×5)", "forstner", { size: 5, sigmaN: 8, thresholdPx: 0.5, qMin: 0.5 }],
  ["Förstner map kept (slider: once per size)", "forstnerMaps", { size: 5 }],
  ["Förstner points from the kept map (threshold slider)", "forstnerPoints", { sigmaN: 8, thresholdPx: 0.5, qMin: 0.5 }],
  ["Moravec map + points (4×4)", "moravec", { size: 4, threshold: 2000 }],
  ["NCC 21×21 over 121×121 + subpixel + LSM", "correlation", { template: [half - 10, half - 10, 21, 21], search: [half - 60, half - 60, 121, 121], model: "shift-radiometric", sameImage: true }],
  ["resample rotate 7°, scale 1.15 (nearest, bilinear, bicubic)", "resample", { kind: "rotate", params: [7, 1.15], width: N, height: N }],
  ["boundary: threshold 128, region at the centre, trace", "boundary", { threshold: 128, c: half, r: half }],
  ["fiducials: four marks + similarity and affine fits (scanned frame)", "fiducials", { frame: true }],
];

// ------------------------------------------------------------------ Node
// the build names files by their content: dist/assets.json maps logical names to them
const ASSETS = fs.existsSync("dist/assets.json") ? JSON.parse(fs.readFileSync("dist/assets.json", "utf8")) : {};
const built = (f) => ASSETS[f] ?? f;
// the build the worker loads where there is SIMD (pkg-simd), else the scalar one
// (looked up through assets.json: the built file names carry content hashes)
const hasSimd = fs.existsSync(new URL(`../dist/${built("lab/pkg-simd/photogrammetry_lab.js")}`, import.meta.url));
const pkg = hasSimd && process.env.BENCH_LAB_SCALAR !== "1" ? "pkg-simd" : "pkg";
const lab = await import(new URL(`../dist/${built(`lab/${pkg}/photogrammetry_lab.js`)}`, import.meta.url));
lab.initSync({ module: fs.readFileSync(new URL(`../dist/${built(`lab/${pkg}/photogrammetry_lab_bg.wasm`)}`, import.meta.url)) });
const frame = lab.scanned_frame();
const approx = Array.from(lab.scanned_frame_truth().marks, Math.round);
let kept = null;
const call = (img, type, a) => {
  switch (type) {
    case "filter": return lab.run_filter(img, a.kernel, a.border);
    case "edges": return lab.run_edges(img, a.operator, a.border);
    case "forstner": return lab.run_forstner(img, a.size, a.sigmaN, a.thresholdPx, a.qMin);
    case "forstnerMaps": kept?.free(); kept = lab.forstner_maps(img, a.size); return kept;
    case "forstnerPoints": return kept.points(a.sigmaN, a.thresholdPx, a.qMin);
    case "moravec": return lab.run_moravec(img, a.size, a.threshold);
    case "correlation": return lab.run_correlation(img, Float64Array.from(a.template), img, Float64Array.from(a.search), a.model);
    case "resample": return lab.run_resample(img, a.kind, Float64Array.from(a.params), a.width, a.height);
    case "boundary": return lab.run_boundary(img, a.threshold, a.c, a.r);
    case "fiducials": return lab.run_fiducials(frame, Float64Array.from(approx));
    default: throw new Error(type);
  }
};
const big = lab.image_from_u8(N, N, image(N));
const fmt = (t) => `${t.median.toFixed(t.median < 10 ? 1 : 0)} [${t.min.toFixed(t.min < 10 ? 1 : 0)}–${t.max.toFixed(t.max < 10 ? 1 : 0)}]`;
const node = {};
for (const [name, type, a] of OPS) {
  node[name] = await timed(() => {
    const t0 = performance.now();
    call(big, type, a);
    return performance.now() - t0;
  }, RULES);
  console.error(`node: ${name}: ${fmt(node[name])} ms (n = ${node[name].n})`);
}

// ------------------------------------------------------------------ Chromium worker
const server = await startServer({ dir: "dist", port: 0 });
const browser = await launchChromium();
const chrome = {};
try {
  const page = await (await browser.newContext()).newPage();
  await page.goto(`${server.url}index.html`);
  const bytesBig = Array.from(image(N));
  const result = await page.evaluate(async ({ OPS, N, RULES, bytesBig, approx, WORKER, timedSrc }) => {
    const timed = new Function(`return ${timedSrc}`)();
    const w = new Worker(WORKER, { type: "module" });
    let id = 0;
    const ask = (type, args, transfer = []) => new Promise((resolve, reject) => {
      const my = ++id;
      const on = (ev) => {
        if (ev.data.id !== my) return;
        w.removeEventListener("message", on);
        if (ev.data.ok) resolve(ev.data.ms);
        else reject(new Error(ev.data.error));
      };
      w.addEventListener("message", on);
      w.postMessage({ id: my, type, ...args }, transfer);
    });
    const out = {};
    let loaded = null;
    for (const [name, type, a] of OPS) {
      const want = a.frame ? "frame" : "big";
      if (loaded !== want) {
        if (want === "frame") await ask("frame", {});
        else {
          const b = Uint8Array.from(bytesBig);
          await ask("raw", { width: N, height: N, bytes: b.buffer }, [b.buffer]);
        }
        loaded = want;
      }
      // the worker times each call itself (ms inside the worker)
      out[name] = await timed(() => ask(type, a.frame ? { approx } : a), RULES);
    }
    out.engine = await new Promise((resolve) => {
      w.addEventListener("message", (ev) => ev.data.id === -1 && resolve(ev.data.ok ? ev.data.result.build : "unknown (no engine request)"));
      w.postMessage({ id: -1, type: "engine" });
    });
    w.terminate();
    return out;
  }, { OPS, N, RULES, bytesBig, approx, WORKER: `./${built("lab/worker.js")}`, timedSrc: timed.toString() });
  Object.assign(chrome, result);
} finally {
  await browser.close();
  await server.close();
}

console.log(`\nThe image lab's operators on a ${N} × ${N} image (ms per call: median [min–max] of n timed calls after ${RULES.warm} warm-ups, n = clamp(${RULES.budget} s / last warm-up, ${RULES.min}, ${RULES.max})):`);
console.log(`  Node: dist/lab/${pkg}; Chromium worker: the ${chrome.engine} build (timed inside the worker); fiducials on the scanned frame`);
console.log(`  ${"operator".padEnd(66)} ${"Node".padStart(16)} ${"Chromium worker".padStart(18)}`);
for (const [name] of OPS) console.log(`  ${name.padEnd(66)} ${fmt(node[name]).padStart(16)} ${fmt(chrome[name]).padStart(18)}`);

const gz = (f) => zlib.gzipSync(fs.readFileSync(f), { level: 9 }).length;
const files = [`dist/${built("lab/pkg/photogrammetry_lab_bg.wasm")}`, ...(fs.existsSync("dist/lab/pkg-simd") ? [`dist/${built("lab/pkg-simd/photogrammetry_lab_bg.wasm")}`] : []), "dist/lab/pkg/photogrammetry_lab.js", ...fs.readdirSync("dist/lab").filter((f) => /\.(js|css)$/.test(f)).map((f) => `dist/lab/${f}`)];
const total = files.filter((f) => !f.includes("pkg-simd")).reduce((s, f) => s + gz(f), 0);
console.log(`\nThe lab module, gzip -9 (loaded only when #/lab opens; one of the two wasm builds):`);
for (const f of files) console.log(`  ${(gz(f) / 1024).toFixed(1).padStart(7)} KiB  ${f}`);
console.log(`  ${(total / 1024).toFixed(1).padStart(7)} KiB  in all with the scalar wasm`);
