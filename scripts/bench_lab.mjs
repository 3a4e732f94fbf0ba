// npm run bench -- --lab: the image lab as a student meets it, on a 12 MP
// generated texture (4000 × 3000, BENCH_LAB_SIZE=WxH to change it), in
// Chromium, printed as one table:
//  - every lab operator through the lab's own client (www/lab/client.js:
//    the main worker, the pool's bands, tiles.js) with a pool of 1 worker
//    and of BENCH_LAB_WORKERS (default: the cores, at most 8): ms from the
//    request to the whole result on the page (painting not included),
//    beside the bench's fast path on the same image (the FastImage exports
//    of `npm run bench -- ops`, in Node, one call) where there is one;
//  - a 12 MP JPEG picked → photo on screen (decoded, painted, drawn);
//  - a slider or parameter change → its preview painted (the k × k mean's
//    size, the LoG's Run, the Förstner window, the edge operator, the
//    rotation's angle: the part of the output in view), the Förstner threshold →
//    its points drawn (raised: the kept map re-thresholded; lowered: the points
//    on screen that pass it, drawn at once);
//  - where an operator's call spends its time: the page's main thread busy
//    (its CPU profile over the calls) and the ms inside the workers (each
//    answer's `ms`, main worker and pool summed: the pool's bands are CPU
//    time that 2 cores share with the page) and Chromium's CPU time a call
//    (its processes' user + system time from /proc: what load does not
//    inflate as it does wall time), for each pool size;
//  - peak wasm memory of the main worker and of a pool worker;
//  - what a lab visit downloads (lab JS + wasm, gzip -9), against 350 KB.
// BENCH_LAB_COLOUR=1: the operators on the colour JPEG of the texture (its
// BT.601 greys, as a phone photo opens) instead of the 8-bit texture;
// BENCH_LAB_OPS=regex: only the operators whose names match (and nothing
// else, unless BENCH_LAB_REST=1: the photo on screen, the previews, the
// visit; BENCH_LAB_OPS='^$' BENCH_LAB_REST=1 runs those alone).
// Each result replaces the one before as on the page (client.release: its
// layers' buffers carry the next result's); BENCH_LAB_REUSE=0 keeps every
// result's layers fresh instead (the lab before the reuse).
// Benchmarks, not tests. Timing rules of ../shared/bench/TASKS.md: BENCH_WARMUP
// (1) untimed calls, then n = clamp(floor(BENCH_BUDGET_S (3) / t_last_warmup),
// BENCH_MIN_REPS (3), BENCH_MAX_REPS (15)) timed calls; the median.
import fs from "node:fs";
import path from "node:path";
import zlib from "node:zlib";
import { execFileSync } from "node:child_process";
import { pathToFileURL } from "node:url";
import { launchChromium } from "./chromium.mjs";
import { startServer } from "./serve.mjs";

const [W, H] = (process.env.BENCH_LAB_SIZE || "4000x3000").split("x").map(Number);
const env = (k, d) => (process.env[k] !== undefined ? Number(process.env[k]) : d);
const RULES = { budget: env("BENCH_BUDGET_S", 3), min: env("BENCH_MIN_REPS", 3), max: env("BENCH_MAX_REPS", 15), warm: env("BENCH_WARMUP", 1) };
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

/** A deterministic texture (as ../shared/bench/gen_images.py's): smooth ramps, blocks, discs, hash noise (0…255). */
function texture(w, h) {
  const out = new Uint8Array(w * h);
  for (let r = 0; r < h; r++) {
    for (let c = 0; c < w; c++) {
      let v = 70 + (70 * c) / w + (40 * r) / h + 25 * Math.sin(2 * Math.PI * ((1.5 * c) / w + (0.7 * r) / h));
      if (((c >> 6) + (r >> 6)) % 3 === 0) v += 50;
      const dx = (c % 128) - 64;
      const dy = (r % 128) - 64;
      if (dx * dx + dy * dy < 400) v -= 40;
      let x = Math.imul(c, 0x9e3779b1) ^ Math.imul(r, 0x85ebca77);
      x ^= x >>> 15;
      x = Math.imul(x, 0x2c1b3c6d);
      x ^= x >>> 12;
      v += ((x >>> 0) % 33) - 16;
      out[r * w + c] = Math.max(0, Math.min(255, Math.round(v)));
    }
  }
  return out;
}

const [hc, hr] = [W >> 1, H >> 1];
const COLOUR = process.env.BENCH_LAB_COLOUR === "1";
const REUSE = process.env.BENCH_LAB_REUSE !== "0";
/** The operators, as [name, worker request type, arguments, the bench's fast path (FastImage) or null]; "frame" ones run on the scanned frame. */
const OPS = [
  ["filter mean 3×3", "filter", { kernel: "mean", border: "replicate" }, (f) => f.mean3("replicate")],
  ["filter Gaussian 3×3", "filter", { kernel: "gaussian-3", border: "replicate" }, (f) => f.gaussian(0.85, 1, "replicate")],
  ["filter Gaussian 5×5", "filter", { kernel: "gaussian-5", border: "replicate" }, (f) => f.gaussian(1.0, 2, "replicate")],
  ["filter median 3×3", "filter", { kernel: "median", border: "replicate" }, (f) => f.median3("replicate")],
  ["filter LoG 5×5", "filter", { kernel: "log", border: "replicate" }, null],
  ["filter custom 7×7 (k × k mean slider)", "filter", { kernel: "custom", border: "replicate", custom: Array(7).fill("1 1 1 1 1 1 1").join("\n"), divisor: 49 }, null],
  ["edges Sobel (gx, gy, magnitude, direction)", "edges", { operator: "sobel", border: "replicate" }, (f) => f.sobel("replicate")],
  ["edges Prewitt (gx, gy, magnitude, direction)", "edges", { operator: "prewitt", border: "replicate" }, null],
  ["Förstner w, q + points (5×5)", "forstner", { size: 5, sigmaN: 8, thresholdPx: 0.5, qMin: 0.5 }, (f) => f.forstner(5)],
  ["Förstner map kept (live threshold)", "forstnerMaps", { size: 5, sigmaN: 8 }, (f) => f.forstner(5)],
  ["Förstner points from the kept map", "forstnerPoints", { sigmaN: 8, thresholdPx: 0.5, qMin: 0.5 }, null],
  ["Moravec map + points (4×4)", "moravec", { size: 4, threshold: 2000 }, null],
  ["NCC 21×21 over 121×121 + subpixel + LSM", "correlation", { template: [hc - 10, hr - 10, 21, 21], search: [hc - 60, hr - 60, 121, 121], model: "shift-radiometric", sameImage: true }, null],
  ["resample rotate 7°, ×1.15 (nearest, bilinear, bicubic)", "resample", { kind: "rotate", params: [7, 1.15], width: W, height: H }, null],
  ["boundary: threshold 128, region at the centre, trace", "boundary", { threshold: 128, c: hc, r: hr }, null],
  ["fiducials: four marks + fits (scanned frame)", "fiducials", { frame: true }, null],
].filter(([name]) => !process.env.BENCH_LAB_OPS || new RegExp(process.env.BENCH_LAB_OPS).test(name));

/** The built site (BENCH_DIST: another build of it). */
const DIST = process.env.BENCH_DIST || "dist";
const ASSETS = JSON.parse(fs.readFileSync(path.join(DIST, "assets.json"), "utf8"));
const built = (f) => ASSETS[f] ?? f;
const bytes = texture(W, H);

// ------------------------------------------------------------------ the bench's fast paths (Node)
// FastImage: the lab's +simd128 build with the `bench` feature, as `npm run bench -- ops` builds it
const pkg = path.resolve(process.env.BENCH_PKG || "target/bench-simd/pkg");
if (!fs.existsSync(path.join(pkg, "photogrammetry_lab.js")) || process.env.BENCH_LAB_REBUILD === "1") {
  console.error("bench lab: building the lab's FastImage (--features bench, +simd128, profile fast) for the fast-path column");
  execFileSync("cargo", ["build", "-p", "photogrammetry-lab", "--features", "bench", "--profile", "fast", "--target", "wasm32-unknown-unknown", "--target-dir", "target/bench-simd"], { stdio: "inherit", env: { ...process.env, RUSTFLAGS: "-C target-feature=+simd128" } });
  execFileSync("wasm-bindgen", ["--target", "web", "--no-typescript", "--out-dir", pkg, "target/bench-simd/wasm32-unknown-unknown/fast/photogrammetry_lab.wasm"], { stdio: "inherit" });
}
const fastMs = {};
{
  const lab = await import(pathToFileURL(path.join(pkg, "photogrammetry_lab.js")).href);
  lab.initSync({ module: fs.readFileSync(path.join(pkg, "photogrammetry_lab_bg.wasm")) });
  const img = new lab.FastImage(W, H, bytes);
  for (const [name, , , fast] of OPS) {
    if (!fast) continue;
    try {
      fastMs[name] = await timed(() => {
        const t0 = performance.now();
        fast(img);
        return performance.now() - t0;
      }, RULES);
    } catch (e) {
      fastMs[name] = null;
      console.error(`bench lab: fast path for ${name}: ${e.message}`);
    }
  }
  img.free();
}

// ------------------------------------------------------------------ Chromium
/** CPU ms (user + system) of this process's descendants (Chromium's processes), from /proc; NaN elsewhere. */
function chromiumCpuMs() {
  try {
    const stats = fs.readdirSync("/proc").filter((d) => /^\d+$/.test(d)).map((d) => {
      try {
        // fields after the command's closing parenthesis: state ppid … utime (14) stime (15)
        const f = fs.readFileSync(`/proc/${d}/stat`, "utf8").split(") ")[1].split(" ");
        return { pid: Number(d), ppid: Number(f[1]), ticks: Number(f[11]) + Number(f[12]) };
      } catch {
        return null;
      }
    }).filter(Boolean);
    const mine = new Set([process.pid]);
    for (let grew = true; grew;) {
      grew = false;
      for (const p of stats) if (!mine.has(p.pid) && mine.has(p.ppid)) grew = mine.add(p.pid) && true;
    }
    // (clock ticks of 10 ms: CLK_TCK 100)
    return stats.filter((p) => p.pid !== process.pid && mine.has(p.pid)).reduce((s, p) => s + p.ticks, 0) * 10;
  } catch {
    return NaN;
  }
}
const server = await startServer({ dir: DIST, port: 0 });
const browser = await launchChromium();
const chrome = {};
try {
  const context = await browser.newContext({ serviceWorkers: "block" });
  await context.addInitScript(() => {
    globalThis.__playgroundTest = true;
  });
  const page = await context.newPage();
  page.on("pageerror", (e) => console.error(`bench lab: page error: ${e.message}`));
  await page.goto(`${server.url}index.html`);
  const cores = await page.evaluate(() => navigator.hardwareConcurrency);
  const many = env("BENCH_LAB_WORKERS", Math.min(8, cores));
  chrome.cores = cores;
  chrome.counts = [...new Set([1, many])];
  chrome.ops = {};
  chrome.memory = {};
  await page.evaluate(({ W, H, bytes }) => {
    window.benchBytes = Uint8Array.from(atob(bytes), (ch) => ch.charCodeAt(0));
    window.benchSize = [W, H];
    // the texture as a colour JPEG (R = g, G = 255 − g, B = 3g mod 256): the photo a phone would give
    window.benchColourJpeg = async () => {
      const g = window.benchBytes;
      const rgba = new Uint8ClampedArray(W * H * 4);
      for (let i = 0; i < g.length; i++) {
        rgba[4 * i] = g[i];
        rgba[4 * i + 1] = 255 - g[i];
        rgba[4 * i + 2] = (g[i] * 3) & 255;
        rgba[4 * i + 3] = 255;
      }
      const cv = new OffscreenCanvas(W, H);
      cv.getContext("2d").putImageData(new ImageData(rgba, W, H), 0, 0);
      return new Uint8Array(await (await cv.convertToBlob({ type: "image/jpeg", quality: 0.9 })).arrayBuffer());
    };
  }, { W, H, bytes: Buffer.from(bytes).toString("base64") });
  // the page's main thread: its busy time (CPU profile samples not idle) over an operator's calls
  // and the CPU time of Chromium's processes (this process's descendants: /proc, Linux), read from the page around the calls
  await page.exposeFunction("benchCpuMs", () => chromiumCpuMs());
  const cdp = await context.newCDPSession(page);
  await cdp.send("Profiler.enable");
  await cdp.send("Profiler.setSamplingInterval", { interval: 250 });
  let profiled = null;
  cdp.on("Profiler.consoleProfileFinished", (ev) => (profiled = ev));
  const busy = ({ profile }) => {
    const idle = new Set(profile.nodes.filter((nd) => nd.callFrame.functionName === "(idle)").map((nd) => nd.id));
    return profile.samples.reduce((s, id, i) => s + (idle.has(id) ? 0 : profile.timeDeltas[i] ?? 0), 0) / 1000;
  };
  for (const n of chrome.counts) {
    console.error(`bench lab: ${n} worker${n > 1 ? "s" : ""} …`);
    chrome.ops[n] = {};
    for (const [name, type, a] of OPS) {
      profiled = null;
      const r = await page.evaluate(async ({ n, name, type, a, RULES, timedSrc, colour, reuse }) => {
        const timed = new Function(`return ${timedSrc}`)();
        if (!window.benchClient || window.benchClient.threads !== n) {
          window.benchClient?.close();
          const { LabClient } = await import("./lab/lab.js");
          window.benchClient = new LabClient({ onRestart: async () => {} }, { workers: n });
          window.benchLoaded = null;
        }
        const client = window.benchClient;
        const want = a.frame ? "frame" : "big";
        if (window.benchLoaded !== want) {
          if (want === "frame") await client.call("frame");
          else if (colour) {
            // the texture as a colour JPEG, opened as a photo is
            const b = await window.benchColourJpeg();
            await client.call("load", { name: "texture.jpg", bytes: b.buffer }, [b.buffer]);
          } else {
            const [w, h] = window.benchSize;
            const b = window.benchBytes.slice();
            await client.call("raw", { width: w, height: h, bytes: b.buffer }, [b.buffer]);
          }
          window.benchLoaded = want;
        }
        const args = a.frame ? { approx: window.benchApprox ??= Array.from((await client.call("frame")).truth.marks, Math.round) } : a;
        try {
          // the kept map first, for the points from it
          if (type === "forstnerPoints") await client.call("forstnerMaps", { size: 5, sigmaN: 8 });
          // ms inside the workers (main + pool) a call, from their answers (client.workerMs, tiles.workerMs)
          const inWorkers = [];
          // (the page's main thread profiled over the calls alone: console.profile, Profiler.consoleProfileFinished)
          console.profile("bench");
          const cpu0 = await window.benchCpuMs();
          const t = await timed(async () => {
            const w0 = client.workerMs + client.tiles.workerMs;
            const t0 = performance.now();
            const res = await client.call(type, args);
            const ms = performance.now() - t0;
            inWorkers.push(client.workerMs + client.tiles.workerMs - w0);
            // the page shows it in place of the one before (lab.js setLayers)
            if (reuse) client.release(window.benchLast?.layers);
            window.benchLast = res;
            return ms;
          }, RULES).finally(() => console.profileEnd("bench"));
          const cpu = (await window.benchCpuMs()) - cpu0;
          inWorkers.sort((x, y) => x - y);
          return { ...t, workers: inWorkers[inWorkers.length >> 1], calls: inWorkers.length, cpu: cpu / inWorkers.length };
        } catch (e) {
          return { error: e.message };
        }
      }, { n, name, type, a, RULES, timedSrc: timed.toString(), colour: COLOUR, reuse: REUSE });
      // (the event comes after the evaluate's answer at the latest a moment later)
      for (let i = 0; i < 50 && r.calls && !profiled; i++) await new Promise((res) => setTimeout(res, 20));
      if (r.calls && profiled) r.page = busy(profiled) / r.calls;
      chrome.ops[n][name] = r;
      console.error(`  ${name}: ${r.error ?? `${r.median.toFixed(0)} ms (n = ${r.n})`}`);
    }
    chrome.memory[n] = await page.evaluate(async () => {
      const client = window.benchClient;
      if (!client) return null;
      const main = (await client.call("memory")).bytes;
      const pool = await Promise.all(client.tiles.workers.filter(Boolean).map((w) => w.ask("memory", {}).then((m) => m.bytes)));
      return { main, pool: Math.max(0, ...pool), instances: 1 + pool.length };
    });
  }
  await page.evaluate(() => window.benchClient?.close());
  // (BENCH_LAB_OPS: the operators only)
  if (process.env.BENCH_LAB_OPS && process.env.BENCH_LAB_REST !== "1") throw Object.assign(new Error("operators only"), { opsOnly: true });

  // a 12 MP JPEG picked → on screen; slider → preview painted
  const jpeg = Buffer.from(await page.evaluate(async () => {
    const b = await window.benchColourJpeg();
    let s = "";
    for (let i = 0; i < b.length; i += 0x8000) s += String.fromCharCode(...b.subarray(i, i + 0x8000));
    return btoa(s);
  }), "base64");
  chrome.jpegBytes = jpeg.length;
  const shown = [];
  // slider or parameter change → its preview painted (live.js: previewMs), or, for the Förstner
  // threshold, → its points drawn (raised: the kept map's answer; lowered: the points on screen filtered)
  const PREVIEWS = [
    ["mean", "slider change → preview painted: k × k mean size"],
    ["log", "Run → preview painted: filter LoG 5×5"],
    ["forstner", "slider change → preview painted: Förstner window"],
    ["edges", "choice change → preview painted: edge operator"],
    ["resample", "angle change → preview painted: rotation (3 methods)"],
    ["threshold", "slider change → points drawn: Förstner threshold (kept map)"],
    ["thresholdDown", "slider lowered → points drawn: Förstner threshold (on screen)"],
  ];
  const previews = Object.fromEntries(PREVIEWS.map(([k]) => [k, []]));
  for (let run = 0; run < 3; run++) {
    const lab = await context.newPage();
    lab.on("pageerror", (e) => console.error(`bench lab: page error: ${e.message}`));
    await lab.setViewportSize({ width: 1280, height: 900 });
    await lab.goto(`${server.url}index.html#/lab`);
    await lab.waitForFunction(() => document.body.dataset.labRestored === "1" && document.body.dataset.lab === "idle", null, { timeout: 60_000 });
    await lab.evaluate(() => {
      const input = document.getElementById("lab-file");
      input.addEventListener("change", () => {
        window.benchT0 = performance.now();
      }, { capture: true });
      new MutationObserver(() => {
        if (document.body.dataset.image === "texture.jpg" && document.body.dataset.lab === "idle" && !window.benchShown) window.benchShown = performance.now();
      }).observe(document.body, { attributes: true });
    });
    await lab.setInputFiles("#lab-file", { name: "texture.jpg", mimeType: "image/jpeg", buffer: jpeg });
    await lab.waitForFunction(() => window.benchShown, null, { timeout: 120_000 });
    // one frame more: the drawn canvas on screen
    shown.push(await lab.evaluate(() => new Promise((res) => requestAnimationFrame(() => res(window.benchShown - window.benchT0)))));
    // `mark`: the body's mark that says it is on screen (previewMs: the page's own ms from the change)
    // (`type`: the event the change fires, else "input" for a range, "change" for the others)
    const previewOf = async (selector, value, mark = "previewMs", type = null) => lab.evaluate(async ({ selector, value, mark, type }) => {
      delete document.body.dataset[mark];
      const input = document.querySelector(selector);
      const t0 = performance.now();
      const seen = new Promise((res) => {
        const obs = new MutationObserver(() => {
          if (document.body.dataset[mark] === undefined) return;
          obs.disconnect();
          res(mark === "previewMs" ? Number(document.body.dataset.previewMs) : performance.now() - t0);
        });
        obs.observe(document.body, { attributes: true });
        setTimeout(() => res(NaN), 5000);
      });
      if (value === null) input.click();
      else {
        input.value = String(value);
        input.dispatchEvent(new Event(type ?? (input.type === "range" ? "input" : "change"), { bubbles: true }));
      }
      const ms = await seen;
      const { settledForTests } = await import("./lab/lab.js");
      await settledForTests();
      return ms;
    }, { selector, value, mark, type });
    await lab.selectOption("#lab-family", "filters");
    await lab.selectOption("#lab-kernel", "mean-k");
    for (const k of [5, 7, 9]) previews.mean.push(await previewOf("#lab-size", k));
    await lab.selectOption("#lab-kernel", "log");
    for (let i = 0; i < 2; i++) previews.log.push(await previewOf("#lab-run", null));
    await lab.selectOption("#lab-family", "interest");
    await lab.click("#lab-run");
    await lab.evaluate(async () => (await import("./lab/lab.js")).settledForTests());
    for (const s of [7, 5]) previews.forstner.push(await previewOf("#lab-window", s));
    for (const t of [0.3, 0.8]) previews.threshold.push(await previewOf("#lab-threshold", t, "threshold"));
    for (const t of [0.6, 0.4]) previews.thresholdDown.push(await previewOf("#lab-threshold", t, "thresholdPreview"));
    // edges and resampling: a Run, then a new choice / angle (recomputed live, its preview first)
    const settled = () => lab.evaluate(async () => (await import("./lab/lab.js")).settledForTests());
    await lab.selectOption("#lab-family", "edges");
    await lab.click("#lab-run");
    await settled();
    for (const o of ["prewitt", "sobel"]) previews.edges.push(await previewOf("#lab-operator", o));
    await lab.selectOption("#lab-family", "resampling");
    await lab.click("#lab-run");
    await settled();
    for (const a of [20, 30]) previews.resample.push(await previewOf("#lab-angle", a, "previewMs", "input"));
    await lab.close();
  }
  const med = (a) => [...a].sort((x, y) => x - y)[Math.floor(a.length / 2)];
  chrome.shown = med(shown);
  chrome.preview = PREVIEWS.map(([k, label]) => {
    const ok = previews[k].filter(Number.isFinite);
    return { label, ms: med(ok), n: `${ok.length} of ${previews[k].length}` };
  });

  // what a lab visit downloads
  const visit = await context.newPage();
  const fetched = [];
  visit.on("request", (req) => fetched.push(new URL(req.url()).pathname.slice(1)));
  await visit.goto(`${server.url}index.html`);
  await visit.waitForLoadState("networkidle");
  const before = fetched.length;
  await visit.goto(`${server.url}index.html#/lab`);
  await visit.waitForFunction(() => document.body.dataset.labRestored === "1" && document.body.dataset.lab === "idle", null, { timeout: 60_000 });
  await visit.waitForLoadState("networkidle");
  chrome.visit = [...new Set(fetched.slice(before))].filter((f) => /\.(js|wasm)$/.test(f));
  await context.close();
} catch (e) {
  if (!e.opsOnly) throw e;
} finally {
  await browser.close();
  await server.close();
}

const ms = (t) => (!t ? "—" : t.error ? "error" : t.median.toFixed(t.median < 10 ? 1 : 0));
const [one, many] = [chrome.counts[0], chrome.counts.at(-1)];
console.log(`\nThe image lab on a ${W} × ${H} ${COLOUR ? "colour JPEG of the texture (its BT.601 greys; the fast path's column: the 8-bit texture)" : "texture"} (${((W * H) / 1e6).toFixed(1)} MP) in Chromium, ${chrome.cores} cores: ms from the request to the whole result on the page,`);
console.log(`${REUSE ? "each result replacing the one before (its layers reused)" : "every result's layers fresh (BENCH_LAB_REUSE=0)"}, median of n calls after ${RULES.warm} warm-up (n = clamp(${RULES.budget} s / last warm-up, ${RULES.min}, ${RULES.max})); the fast path: FastImage in Node, one call, same image`);
const cols = [["operator", 58], ["fast path", 10], [`1 worker`, 10], [`${many} workers`, 10], [`${many} vs 1`, 8], ["1 w / fast", 10]];
console.log(`  ${cols.map(([t, n], i) => (i ? t.padStart(n) : t.padEnd(n))).join(" ")}`);
for (const [name] of OPS) {
  const [f, a, b] = [fastMs[name], chrome.ops[one]?.[name], chrome.ops[many]?.[name]];
  const ratio = (x, y) => (x?.median && y?.median ? `${(x.median / y.median).toFixed(2)}×` : "—");
  console.log(`  ${name.padEnd(58)} ${ms(f).padStart(10)} ${ms(a).padStart(10)} ${ms(b).padStart(10)} ${ratio(a, b).padStart(8)} ${ratio(a, f).padStart(10)}`);
}
const num = (v, d = 0) => (Number.isFinite(v) ? v.toFixed(d) : "—");
if (chrome.preview) console.log(`  ${"12 MP colour JPEG picked → photo on screen".padEnd(58)} ${"".padStart(10)} ${num(chrome.shown).padStart(10)}   (median of 3; JPEG ${(chrome.jpegBytes / 1e6).toFixed(1)} MB)`);
for (const p of chrome.preview ?? []) console.log(`  ${p.label.padEnd(58)} ${"".padStart(10)} ${num(p.ms, 1).padStart(10)}   (median of ${p.n})`);
const mib = (b) => `${(b / 2 ** 20).toFixed(0)} MiB`;
for (const n of chrome.counts) {
  const m = chrome.memory[n];
  if (!m) continue;
  console.log(`  peak wasm memory, pool of ${n}: main worker ${mib(m.main)}, a pool worker ${mib(m.pool)} (${m.instances} instances)`);
}
// where the time of a call goes: the page's main thread busy (its CPU profile) and inside the workers (their answers' ms)
if (chrome.ops && Object.values(chrome.ops[one] ?? {}).some((t) => Number.isFinite(t?.cpu) || Number.isFinite(t?.workers))) {
  console.log(`  where a call's time goes, ms a call (median; the page's: mean), 1 worker and ${many}: the page's main thread busy (its CPU profile) / inside the workers (main + pool, summed) / Chromium's CPU time (all its processes, /proc: a mean)`);
  for (const [name] of OPS) {
    const part = (t) => (t?.calls ? `${num(t.page, 1)} / ${num(t.workers, 1)} / ${num(t.cpu, 0)}` : "—");
    console.log(`  ${name.padEnd(58)} ${"".padStart(10)} ${part(chrome.ops[one]?.[name]).padStart(24)} ${part(chrome.ops[many]?.[name]).padStart(24)}`);
  }
}
if (chrome.visit) {
  const gz = (f) => zlib.gzipSync(fs.readFileSync(path.join(DIST, f)), { level: 9 }).length;
  const total = chrome.visit.reduce((s, f) => s + gz(f), 0);
  console.log(`\nA lab visit (#/lab after the home page) fetched these JS and wasm files (gzip -9):`);
  for (const f of chrome.visit) console.log(`  ${(gz(f) / 1024).toFixed(1).padStart(7)} KiB  ${f}`);
  console.log(`  ${(total / 1024).toFixed(1).padStart(7)} KiB  in all (aim: ≤ 350 KB = ${(350000 / 1024).toFixed(1)} KiB)`);
  const wasm = chrome.visit.filter((f) => f.endsWith(".wasm"));
  console.log(`  lab wasm builds fetched: ${wasm.length} (${wasm.map((f) => (f === built("lab/pkg-simd/photogrammetry_lab_bg.wasm") ? "SIMD" : f === built("lab/pkg/photogrammetry_lab_bg.wasm") ? "scalar" : f)).join(", ")})`);
}
