// npm run bench -- ops: T1–T7 of ../shared/bench/TASKS.md through the lab's
// wasm exports (FastImage) and OpenCV.js (@techstark/opencv-js) in this same
// Node process, on the same bytes; optionally native OpenCV (one thread,
// opencv-python-headless in .venv-bench) in a child process on the same files,
// asked for each task right after Node timed it (interleaved, so the three
// columns of a row see the same machine load).
//   node scripts/bench-ops/bench.mjs [--json FILE] [--no-native]
// Timing rules of TASKS.md: BENCH_WARMUP (2) untimed calls, then
// n = clamp(floor(BENCH_BUDGET_S (1.5) / t_last_warmup), BENCH_MIN_REPS (5),
// BENCH_MAX_REPS (25)) timed calls; median, min, max of the wall-clock
// times. The CPU time of the same calls (process.cpuUsage, Python's
// process_time) is kept too: on a shared, loaded machine it is the figure
// least disturbed by other processes (see docs/BENCH-OPS.md).
// --json FILE: one object per task and size with the keys
// {task, size, ours_ms, opencvjs_ms, agree} and these extra keys:
// native_ms (native OpenCV wall-clock median, null without it), and
// ours_cpu_ms, opencvjs_cpu_ms, native_cpu_ms (CPU-time medians).
import fs from "node:fs";
import path from "node:path";
import crypto from "node:crypto";
import { createRequire } from "node:module";
import { spawn } from "node:child_process";
import { createInterface } from "node:readline";
import { fileURLToPath, pathToFileURL } from "node:url";

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.resolve(here, "../..");
const args = process.argv.slice(2);
const jsonOut = args.includes("--json") ? args[args.indexOf("--json") + 1] : null;
const env = (k, d) => (process.env[k] !== undefined ? Number(process.env[k]) : d);
const BUDGET = env("BENCH_BUDGET_S", 1.5), MINR = env("BENCH_MIN_REPS", 5), MAXR = env("BENCH_MAX_REPS", 25);
const WARM = env("BENCH_WARMUP", 2);
const SIZES = (process.env.BENCH_SIZES || "512,2048,4096").split(",").map(Number);
const ONLY = process.env.BENCH_TASKS ? process.env.BENCH_TASKS.split(",") : null;
const dataDir = path.join(root, "data");

// TASKS.md's reference hashes (first 16 hex digits)
const SHA = {
  "gray_512.u8": "296ff432d7c49bb2", "gray_2048.u8": "a965da9a264d699d", "gray_4096.u8": "2fa157367df5cba2",
  "bin_512.u8": "a1074ddab04e7a12", "bin_2048.u8": "7ec3f2755d1805e5", "bin_4096.u8": "7987cc9cb66ea914",
};
const manifest = JSON.parse(fs.readFileSync(path.join(dataDir, "manifest.json"), "utf8"));
const load = (name) => {
  const b = fs.readFileSync(path.join(dataDir, name));
  const h = crypto.createHash("sha256").update(b).digest("hex").slice(0, 16);
  if (SHA[name] && h !== SHA[name]) throw new Error(`${name}: SHA-256 ${h}…, TASKS.md says ${SHA[name]}…`);
  return new Uint8Array(b.buffer, b.byteOffset, b.length);
};

function time(fn) {
  let last = 0;
  for (let i = 0; i < WARM; i++) { const t0 = performance.now(); fn(); last = performance.now() - t0; }
  const n = Math.min(MAXR, Math.max(MINR, Math.floor((BUDGET * 1000) / Math.max(last, 1e-3))));
  const ts = [], cs = [];
  for (let i = 0; i < n; i++) {
    const c0 = process.cpuUsage(), t0 = performance.now();
    fn();
    ts.push(performance.now() - t0);
    const d = process.cpuUsage(c0);
    cs.push((d.user + d.system) / 1000);
  }
  ts.sort((a, b) => a - b);
  cs.sort((a, b) => a - b);
  return { median: ts[Math.floor(n / 2)], min: ts[0], max: ts[n - 1], n, cpu: cs[Math.floor(n / 2)] };
}

// ---- our wasm (the lab's exports)
const pkg = path.resolve(root, process.env.BENCH_PKG || "target/bench-simd/pkg");
const lab = await import(pathToFileURL(path.join(pkg, "photogrammetry_lab.js")).href);
const wasm = lab.initSync({ module: fs.readFileSync(path.join(pkg, "photogrammetry_lab_bg.wasm")) });
const f32view = (img, i) => new Float32Array(wasm.memory.buffer, img.out_ptr(i), img.out_len(i));
const u8view = (img) => new Uint8Array(wasm.memory.buffer, img.out_ptr(3), img.out_len(3));

// ---- OpenCV.js
const require = createRequire(path.join(here, "package.json"));
let cv = require("@techstark/opencv-js");
if (cv instanceof Promise) cv = await cv;
else if (!cv.Mat) await new Promise((r) => { cv.onRuntimeInitialized = r; });
const matU8 = (bytes, w, h) => { const m = new cv.Mat(h, w, cv.CV_8UC1); m.data.set(bytes); return m; };

// ---- comparisons
function floatAgree(a, b, tol) {
  let bad = 0, maxd = 0;
  for (let i = 0; i < a.length; i++) {
    const d = Math.abs(a[i] - b[i]);
    if (!(d <= tol * Math.max(1, Math.abs(b[i])))) bad++;
    if (d > maxd || Number.isNaN(d)) maxd = Number.isNaN(d) ? Infinity : d;
  }
  return { bad, maxd };
}

const tasks = [];
const task = (name, fn) => { if (!ONLY || ONLY.some((t) => name.startsWith(t))) tasks.push({ name, fn }); };

// Each task: (size, gray bytes, bin bytes, parameters) -> {ours: fn, cv: fn, agree: () => [bool, note], free}
task("T1_mean3", (n, g) => {
  const img = new lab.FastImage(n, n, g), src = matU8(g, n, n), dst = new cv.Mat();
  const k = new cv.Size(3, 3), anc = new cv.Point(-1, -1);
  return {
    ours: () => img.mean3("replicate"),
    cv: () => cv.boxFilter(src, dst, cv.CV_32F, k, anc, true, cv.BORDER_REPLICATE),
    agree: () => { const r = floatAgree(f32view(img, 0), dst.data32F, 1e-5); return [r.bad === 0, `max |Δ| ${r.maxd.toExponential(1)}`]; },
    free: () => { img.free(); src.delete(); dst.delete(); },
  };
});
task("T1_gauss5", (n, g) => {
  const img = new lab.FastImage(n, n, g), src = matU8(g, n, n), dst = new cv.Mat();
  const raw = [-2, -1, 0, 1, 2].map((i) => Math.exp(-i * i / 2)), s = raw.reduce((a, b) => a + b);
  const kern = cv.matFromArray(5, 1, cv.CV_32F, raw.map((v) => v / s));
  return {
    ours: () => img.gaussian(1.0, 2, "replicate"),
    cv: () => cv.sepFilter2D(src, dst, cv.CV_32F, kern, kern, new cv.Point(-1, -1), 0, cv.BORDER_REPLICATE),
    agree: () => { const r = floatAgree(f32view(img, 0), dst.data32F, 1e-5); return [r.bad === 0, `max |Δ| ${r.maxd.toExponential(1)}`]; },
    free: () => { img.free(); src.delete(); dst.delete(); kern.delete(); },
  };
});
task("T2_sobel", (n, g) => {
  const img = new lab.FastImage(n, n, g), src = matU8(g, n, n);
  const gx = new cv.Mat(), gy = new cv.Mat(), mag = new cv.Mat();
  return {
    ours: () => img.sobel("replicate"),
    cv: () => {
      cv.Sobel(src, gx, cv.CV_32F, 1, 0, 3, 1, 0, cv.BORDER_REPLICATE);
      cv.Sobel(src, gy, cv.CV_32F, 0, 1, 3, 1, 0, cv.BORDER_REPLICATE);
      cv.magnitude(gx, gy, mag);
    },
    agree: () => {
      const a = floatAgree(f32view(img, 0), gx.data32F, 0), b = floatAgree(f32view(img, 1), gy.data32F, 0);
      const m = floatAgree(f32view(img, 2), mag.data32F, 1e-5);
      return [a.bad + b.bad + m.bad === 0, `gx, gy equal: ${a.bad + b.bad === 0}; mag max |Δ| ${m.maxd.toExponential(1)}`];
    },
    free: () => { img.free(); for (const m of [src, gx, gy, mag]) m.delete(); },
  };
});
task("T3_foerstner", (n, g) => {
  const img = new lab.FastImage(n, n, g), src = matU8(g, n, n);
  const M = () => new cv.Mat();
  const [gx, gy, xx, yy, xy, sxx, syy, sxy, t1, t2, det, tr, w, q, tr2] = Array.from({ length: 15 }, M);
  const k = new cv.Size(5, 5), anc = new cv.Point(-1, -1);
  return {
    ours: () => img.forstner(5),
    cv: () => {
      cv.Sobel(src, gx, cv.CV_32F, 1, 0, 1, 0.5, 0, cv.BORDER_REPLICATE);
      cv.Sobel(src, gy, cv.CV_32F, 0, 1, 1, 0.5, 0, cv.BORDER_REPLICATE);
      cv.multiply(gx, gx, xx); cv.multiply(gy, gy, yy); cv.multiply(gx, gy, xy);
      cv.boxFilter(xx, sxx, -1, k, anc, false, cv.BORDER_REPLICATE);
      cv.boxFilter(yy, syy, -1, k, anc, false, cv.BORDER_REPLICATE);
      cv.boxFilter(xy, sxy, -1, k, anc, false, cv.BORDER_REPLICATE);
      cv.multiply(sxx, syy, t1); cv.multiply(sxy, sxy, t2); cv.subtract(t1, t2, det);
      cv.add(sxx, syy, tr);
      cv.divide(det, tr, w);
      cv.multiply(tr, tr, tr2); cv.divide(det, tr2, q, 4);
    },
    agree: () => {
      // OpenCV's det is f32 (cancellation on straight edges); ours exact
      const a = floatAgree(f32view(img, 0), w.data32F, 1e-3), b = floatAgree(f32view(img, 1), q.data32F, 1e-2);
      const frac = (a.bad + b.bad) / (2 * n * n);
      return [frac < 0.01, `w, q within 1e-3 / 1e-2: ${(100 * (1 - frac)).toFixed(2)}% of pixels`];
    },
    free: () => { img.free(); src.delete(); for (const m of [gx, gy, xx, yy, xy, sxx, syy, sxy, t1, t2, det, tr, w, q, tr2]) m.delete(); },
  };
});
task("T4_ncc", (n, g, _b, p) => {
  const [rx, ry, rw, rh] = p.t4_region, [tx, ty, tw, th] = p.t4_template;
  const cut = (x, y, w, h) => { const o = new Uint8Array(w * h); for (let r = 0; r < h; r++) o.set(g.subarray((y + r) * n + x, (y + r) * n + x + w), r * w); return o; };
  const sb = cut(rx, ry, rw, rh), tb = cut(tx, ty, tw, th);
  const img = new lab.FastImage(1, 1, new Uint8Array(1));
  const full = matU8(g, n, n), region = full.roi(new cv.Rect(rx, ry, rw, rh)), templ = full.roi(new cv.Rect(tx, ty, tw, th));
  const res = new cv.Mat(), mask = new cv.Mat();
  let ourPeak = [], cvPeak = null;
  return {
    ours: () => { ourPeak = img.zncc_bytes(sb, rw, rh, tb, tw, th); },
    cv: () => { cv.matchTemplate(region, templ, res, cv.TM_CCOEFF_NORMED, mask); cvPeak = cv.minMaxLoc(res, mask); },
    agree: () => {
      const r = floatAgree(f32view(img, 0), res.data32F, 1e-3);
      const [ex, ey] = p.t4_expected_peak_xy;
      const same = ourPeak[0] === ex && ourPeak[1] === ey && cvPeak.maxLoc.x === ex && cvPeak.maxLoc.y === ey;
      return [same && r.bad === 0, `peak (${ourPeak[0]}, ${ourPeak[1]}) ρ ${ourPeak[2]?.toFixed(4)}; map max |Δ| ${r.maxd.toExponential(1)}`];
    },
    free: () => { img.free(); for (const m of [templ, region, full, res, mask]) m.delete(); },
  };
});
for (const [name, method, flag] of [["T5_bilinear", "bilinear", "INTER_LINEAR"], ["T5_bicubic", "bicubic", "INTER_CUBIC"]]) {
  task(name, (n, g, _b, p) => {
    const m = p.t5_inverse_map.flat();
    const img = new lab.FastImage(n, n, g), src = matU8(g, n, n), dst = new cv.Mat();
    const M = cv.matFromArray(2, 3, cv.CV_64F, m), size = new cv.Size(n, n);
    return {
      // bicubic with OpenCV's kernel parameter a = −0.75 (the lab's default is seed 004's −1)
      ours: () => img.warp_affine(m, method, -0.75),
      cv: () => cv.warpAffine(src, dst, M, size, cv[flag] | cv.WARP_INVERSE_MAP, cv.BORDER_CONSTANT, new cv.Scalar(0)),
      agree: () => {
        // OpenCV rounds with 5-bit (bilinear) / 10-bit fixed-point weights and
        // blends the outer ring with the constant border: count pixels within 2
        const a = f32view(img, 0), b = dst.data;
        let within = 0;
        for (let i = 0; i < a.length; i++) if (Math.abs(Math.min(255, Math.max(0, Math.round(a[i]))) - b[i]) <= 2) within++;
        const frac = within / a.length;
        return [frac > 0.995, `${(100 * frac).toFixed(2)}% of pixels within 2 grey levels (u8)`];
      },
      free: () => { img.free(); src.delete(); dst.delete(); M.delete(); },
    };
  });
}
task("T6_median3", (n, g) => {
  const img = new lab.FastImage(n, n, g), src = matU8(g, n, n), dst = new cv.Mat();
  return {
    ours: () => img.median3("replicate"),
    cv: () => cv.medianBlur(src, dst, 3),
    agree: () => {
      const a = u8view(img), b = dst.data;
      let bad = 0;
      for (let i = 0; i < a.length; i++) if (a[i] !== b[i]) bad++;
      return [bad === 0, bad === 0 ? "equal" : `${bad} pixels differ`];
    },
    free: () => { img.free(); src.delete(); dst.delete(); },
  };
});
if (lab.FastImage.prototype.contours) {
  task("T7_contours", (n, _g, bin) => {
    const img = new lab.FastImage(n, n, bin), src = matU8(bin, n, n);
    let contours = new cv.MatVector(), hier = new cv.Mat();
    let ours = [];
    return {
      ours: () => { ours = img.contours(); },
      cv: () => { contours.delete(); hier.delete(); contours = new cv.MatVector(); hier = new cv.Mat(); cv.findContours(src, contours, hier, cv.RETR_LIST, cv.CHAIN_APPROX_NONE); },
      agree: () => {
        let pts = 0;
        const theirs = [];
        for (let i = 0; i < contours.size(); i++) {
          const c = contours.get(i); pts += c.rows;
          if (n <= 512) for (let k = 0; k < c.rows; k++) theirs.push(c.data32S[2 * k] * 65536 + c.data32S[2 * k + 1]);
          c.delete();
        }
        let ok = ours[0] === contours.size() && ours[1] === pts, lists = "";
        if (n <= 512) {
          // TASKS.md: at 512 the point lists too, compared as multisets
          const mine = [];
          for (let i = 0; i < ours[0]; i++) { const p = img.contour(i); for (let k = 0; k < p.length; k += 2) mine.push(p[k] * 65536 + p[k + 1]); }
          mine.sort((a, b) => a - b); theirs.sort((a, b) => a - b);
          const same = mine.length === theirs.length && mine.every((v, i) => v === theirs[i]);
          ok = ok && same; lists = same ? "; point multisets equal" : "; point multisets DIFFER";
        }
        return [ok, `ours ${ours[0]} contours / ${ours[1]} points, OpenCV.js ${contours.size()} / ${pts}${lists}`];
      },
      free: () => { img.free(); src.delete(); contours.delete(); hier.delete(); },
    };
  });
}

// ---- native OpenCV (optional): one child process serving one task at a time
let askNative = async () => undefined;
const py = path.join(root, ".venv-bench/bin/python");
if (!args.includes("--no-native") && fs.existsSync(py)) {
  const child = spawn(py, [path.join(here, "native.py"), dataDir, "--serve"], { stdio: ["pipe", "pipe", "inherit"] });
  const lines = createInterface({ input: child.stdout });
  const pending = [];
  lines.on("line", (l) => pending.shift()?.(JSON.parse(l)));
  child.on("exit", () => { for (const r of pending.splice(0)) r(undefined); askNative = async () => undefined; });
  askNative = (t, n) => new Promise((resolve) => { pending.push((v) => resolve(v ?? undefined)); child.stdin.write(`${t} ${n}\n`); });
  process.on("exit", () => child.kill());
}

const rows = [];
const fmt = (t) => (t === undefined ? "-" : t.median.toFixed(t.median < 10 ? 2 : 1));
console.log(`\nT1–T7 (../shared/bench/TASKS.md), ms per call: median [min–max] of n timed calls after ${WARM} warm-ups`);
console.log(`ours = lab wasm (${path.relative(root, pkg)}) in Node ${process.version}; OpenCV.js ${require("@techstark/opencv-js/package.json").version}; native = opencv-python one thread`);
const head = ["task", "size", "ours ms", "OpenCV.js ms", "ours/cv.js", "native ms", "ours/native", "CPU ms ours / cv.js / native", "agree"];
console.log(head.join(" | "));
for (const n of SIZES) {
  const p = manifest.sizes[String(n)];
  const g = load(p.gray), b = load(p.binary);
  for (const t of tasks) {
    const job = t.fn(n, g, b, p);
    const ours = time(job.ours);
    const cvt = time(job.cv);
    const [agree, note] = job.agree();
    job.free();
    const nat = await askNative(t.name, n);
    const ratio = ours.median / cvt.median;
    const row = { task: t.name, size: n, ours_ms: +ours.median.toFixed(3), opencvjs_ms: +cvt.median.toFixed(3), agree,
      ours_min: +ours.min.toFixed(3), ours_max: +ours.max.toFixed(3), opencvjs_min: +cvt.min.toFixed(3), opencvjs_max: +cvt.max.toFixed(3),
      native_ms: nat ? +nat.median.toFixed(3) : null, ours_cpu_ms: +ours.cpu.toFixed(3), opencvjs_cpu_ms: +cvt.cpu.toFixed(3),
      native_cpu_ms: nat ? +nat.cpu_median.toFixed(3) : null, note };
    rows.push(row);
    console.log([t.name, n, `${fmt(ours)} [${ours.min.toFixed(1)}–${ours.max.toFixed(1)}]`, `${fmt(cvt)} [${cvt.min.toFixed(1)}–${cvt.max.toFixed(1)}]`,
      ratio.toFixed(2), nat ? fmt(nat) : "-", nat ? (ours.median / nat.median).toFixed(2) : "-",
      `${ours.cpu.toFixed(1)} / ${cvt.cpu.toFixed(1)} / ${nat ? nat.cpu_median.toFixed(1) : "-"}`, `${agree ? "yes" : "NO"} (${note})`].join(" | "));
  }
}
if (jsonOut) {
  fs.writeFileSync(jsonOut, JSON.stringify(rows.map(({ task, size, ours_ms, opencvjs_ms, agree, native_ms, ours_cpu_ms, opencvjs_cpu_ms, native_cpu_ms }) =>
    ({ task, size, ours_ms, opencvjs_ms, agree, native_ms, ours_cpu_ms, opencvjs_cpu_ms, native_cpu_ms })), null, 1));
  console.log(`wrote ${jsonOut}`);
}
process.exit(0);
