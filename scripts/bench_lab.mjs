// npm run bench -- --lab: the image lab's operators on a 2048 × 2048 image,
// milliseconds per call in Node and in Chromium's Web Worker (the lab's own
// worker.js, timed inside the worker), and the lab module's gzipped size.
// Benchmarks, not tests. BENCH_SIZE (default 2048) and BENCH_REPS (default 1
// timed call after one warm-up call on a 256 × 256 image) adjust it.
import fs from "node:fs";
import zlib from "node:zlib";
import { chromium } from "playwright-core";
import { startServer } from "./serve.mjs";

const N = Number(process.env.BENCH_SIZE || 2048);
const REPS = Number(process.env.BENCH_REPS || 1);

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
/** The operators, as [name, worker request type, arguments]. */
const OPS = [
  ["filter mean 3×3", "filter", { kernel: "mean", border: "replicate" }],
  ["filter Gaussian 5×5", "filter", { kernel: "gaussian-5", border: "replicate" }],
  ["filter median 3×3", "filter", { kernel: "median", border: "replicate" }],
  ["filter LoG 5×5", "filter", { kernel: "log", border: "replicate" }],
  ["edges Sobel (gx, gy, magnitude, direction)", "edges", { operator: "sobel", border: "replicate" }],
  ["Förstner w, q + points (5×5)", "forstner", { size: 5, sigmaN: 8, thresholdPx: 0.5, qMin: 0.5 }],
  ["Moravec map + points (4×4)", "moravec", { size: 4, threshold: 2000 }],
  ["NCC 21×21 over 121×121 + subpixel + LSM", "correlation", { template: [half - 10, half - 10, 21, 21], search: [half - 60, half - 60, 121, 121], model: "shift-radiometric", sameImage: true }],
  ["resample rotate 7°, scale 1.15 (nearest, bilinear, bicubic)", "resample", { kind: "rotate", params: [7, 1.15], width: N, height: N }],
  ["boundary: threshold 128, region at the centre, trace", "boundary", { threshold: 128, c: half, r: half }],
];

// ------------------------------------------------------------------ Node
// the build names files by their content: dist/assets.json maps logical names to them
const ASSETS = fs.existsSync("dist/assets.json") ? JSON.parse(fs.readFileSync("dist/assets.json", "utf8")) : {};
const built = (f) => ASSETS[f] ?? f;
// the build the worker loads where there is SIMD (pkg-simd), else the scalar one
const pkg = fs.existsSync(new URL("../dist/lab/pkg-simd/photogrammetry_lab.js", import.meta.url)) && process.env.BENCH_LAB_SCALAR !== "1" ? "pkg-simd" : "pkg";
const lab = await import(new URL(`../dist/${built(`lab/${pkg}/photogrammetry_lab.js`)}`, import.meta.url));
lab.initSync({ module: fs.readFileSync(new URL(`../dist/${built(`lab/${pkg}/photogrammetry_lab_bg.wasm`)}`, import.meta.url)) });
const call = (img, type, a) => {
  switch (type) {
    case "filter": return lab.run_filter(img, a.kernel, a.border);
    case "edges": return lab.run_edges(img, a.operator, a.border);
    case "forstner": return lab.run_forstner(img, a.size, a.sigmaN, a.thresholdPx, a.qMin);
    case "moravec": return lab.run_moravec(img, a.size, a.threshold);
    case "correlation": return lab.run_correlation(img, Float64Array.from(a.template), img, Float64Array.from(a.search), a.model);
    case "resample": return lab.run_resample(img, a.kind, Float64Array.from(a.params), a.width, a.height);
    case "boundary": return lab.run_boundary(img, a.threshold, a.c, a.r);
    default: throw new Error(type);
  }
};
const small = lab.image_from_u8(256, 256, image(256));
const big = lab.image_from_u8(N, N, image(N));
const node = {};
for (const [name, type, a] of OPS) {
  const scaled = structuredClone(a);
  if (type === "resample") Object.assign(scaled, { width: 256, height: 256 });
  if (type === "correlation") Object.assign(scaled, { template: [118, 118, 21, 21], search: [68, 68, 121, 121] });
  if (type === "boundary") Object.assign(scaled, { c: 128, r: 128 });
  call(small, type, scaled); // warm-up
  const ts = [];
  for (let i = 0; i < REPS; i++) {
    const t0 = performance.now();
    call(big, type, a);
    ts.push(performance.now() - t0);
  }
  node[name] = Math.min(...ts);
  console.error(`node: ${name}: ${node[name].toFixed(0)} ms`);
}

// ------------------------------------------------------------------ Chromium worker
const server = await startServer({ dir: "dist", port: 0 });
const browser = await chromium.launch({
  executablePath: "/usr/bin/chromium",
  args: ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking", "--disable-component-update", "--disable-sync"],
});
const chrome = {};
try {
  const page = await (await browser.newContext()).newPage();
  await page.goto(`${server.url}index.html`);
  const bytesSmall = Array.from(image(256));
  const bytesBig = Array.from(image(N));
  const result = await page.evaluate(async ({ OPS, N, REPS, bytesSmall, bytesBig, WORKER }) => {
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
    for (const [name, type, a] of OPS) {
      const s = Uint8Array.from(bytesSmall);
      await ask("raw", { width: 256, height: 256, bytes: s.buffer }, [s.buffer]);
      const scaled = structuredClone(a);
      if (type === "resample") Object.assign(scaled, { width: 256, height: 256 });
      if (type === "correlation") Object.assign(scaled, { template: [118, 118, 21, 21], search: [68, 68, 121, 121] });
      if (type === "boundary") Object.assign(scaled, { c: 128, r: 128 });
      await ask(type, scaled);
      const b = Uint8Array.from(bytesBig);
      await ask("raw", { width: N, height: N, bytes: b.buffer }, [b.buffer]);
      const ts = [];
      for (let i = 0; i < REPS; i++) ts.push(await ask(type, a));
      out[name] = Math.min(...ts);
    }
    out.engine = await new Promise((resolve) => {
      w.addEventListener("message", (ev) => ev.data.id === -1 && resolve(ev.data.ok ? ev.data.result.build : "unknown (no engine request)"));
      w.postMessage({ id: -1, type: "engine" });
    });
    w.terminate();
    return out;
  }, { OPS, N, REPS, bytesSmall, bytesBig, WORKER: `./${built("lab/worker.js")}` });
  Object.assign(chrome, result);
} finally {
  await browser.close();
  await server.close();
}

console.log(`\nThe image lab's operators on a ${N} × ${N} image (ms, best of ${REPS} after a warm-up on 256 × 256):`);
console.log(`  Node: dist/lab/${pkg}; Chromium worker: the ${chrome.engine} build`);
console.log(`  ${"operator".padEnd(62)} ${"Node".padStart(9)} ${"Chromium worker".padStart(16)}`);
for (const [name] of OPS) console.log(`  ${name.padEnd(62)} ${node[name].toFixed(0).padStart(9)} ${chrome[name].toFixed(0).padStart(16)}`);

const gz = (f) => zlib.gzipSync(fs.readFileSync(f), { level: 9 }).length;
const files = [`dist/${built("lab/pkg/photogrammetry_lab_bg.wasm")}`, ...(fs.existsSync("dist/lab/pkg-simd") ? [`dist/${built("lab/pkg-simd/photogrammetry_lab_bg.wasm")}`] : []), "dist/lab/pkg/photogrammetry_lab.js", ...fs.readdirSync("dist/lab").filter((f) => /\.(js|css)$/.test(f)).map((f) => `dist/lab/${f}`)];
const total = files.filter((f) => !f.includes("pkg-simd")).reduce((s, f) => s + gz(f), 0);
console.log(`\nThe lab module, gzip -9 (loaded only when #/lab opens; one of the two wasm builds):`);
for (const f of files) console.log(`  ${(gz(f) / 1024).toFixed(1).padStart(7)} KiB  ${f}`);
console.log(`  ${(total / 1024).toFixed(1).padStart(7)} KiB  in all with the scalar wasm`);
