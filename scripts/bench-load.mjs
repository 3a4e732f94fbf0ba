// The numbers that matter to a student opening an example (a benchmark, not a
// test; docs/BENCH-LOAD.md says how to read them). For every example of the
// catalog (its ids read from the page's own catalog, not from a list here):
//
//  1. bytes: the wasm, JS and CSS the browser requested before the page's
//     own first solution (its `solver-ready` mark: the critical path) and in
//     all after network idle, gzip -9 of the file in dist/ (fonts and HTML
//     apart; the build's saved solution, HTML, in a column of its own); what
//     the server really sent (resource timing's encodedBodySize) beside it;
//  2. navigation → `first-solution` (the first numbers on screen: the
//     build's saved solution, scripts/prerender.mjs, where the page shows
//     one, else the page's own) and → `solver-ready` (the page's own first
//     solution, its inputs live), cold (a new browser context each load,
//     service workers blocked), beside a FLOOR page from the same run (one tiny
//     ES module instantiating a hand-assembled 41-byte wasm and writing one
//     number), and their ratios. Each time is that of the frame the mark's
//     content is rendered in (the mark, then the next animation frame's
//     style, layout and paint: what the student sees), not of the mark itself,
//     which script sets before any of it; the marks are kept beside;
//  3. the same under a throttled phone profile (Chrome DevTools Protocol: CPU
//     4× slower, 1.6 Mbit/s down, 750 kbit/s up, 150 ms latency);
//  4. an input change → the figure redrawn (the page's `redraw` measure, see
//     inputChanged in www/app.js), median and worst of 15 changes, and → the
//     steps, result and notes updated too (its `settled` measure);
//  5. the image lab's size, and that no example requested any of it.
//
// The measurement depends on no file name: it sees what the browser requests.
//
//   node scripts/bench-load.mjs [--quick] [--example ID ...] [--runs 9]
//     [--throttled-runs 5] [--throttled topics|all|none] [--redraws 15]
//     [--no-redraw] [--json FILE]
import { launchChromium } from "./chromium.mjs";
import { recordRendered } from "./rendered-marks.mjs";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import zlib from "node:zlib";
import { startServer } from "./serve.mjs";

const AIM_KB = 150;
const AIM_RATIO = 2;
const AIM_THROTTLED_MS = 2500;
const AIM_REDRAW_MS = 16;

const args = process.argv.slice(2);
const arg = (name, dflt) => {
  const i = args.indexOf(name);
  return i >= 0 && i + 1 < args.length ? args[i + 1] : dflt;
};
const DIST = arg("--dist", "dist");
const argsAll = (name) => args.flatMap((a, i) => (a === name && i + 1 < args.length ? [args[i + 1]] : []));
const runs = Math.max(1, Number(arg("--runs", 9)));
const throttledRuns = Math.max(1, Number(arg("--throttled-runs", 5)));
const throttledSet = arg("--throttled", "topics"); // topics: the heaviest example of each topic
const redraws = Math.max(1, Number(arg("--redraws", 15)));
const doRedraw = !args.includes("--no-redraw");
const jsonFile = arg("--json", null);
const quick = args.includes("--quick");
const wanted = argsAll("--example");

if (!fs.existsSync(path.join(DIST, "index.html"))) {
  console.error("bench-load: dist/index.html is missing; run `SKIP_SETUP=1 bash scripts/build.sh` first");
  process.exit(1);
}

// ---------------------------------------------------------------------------
// The floor page: generated into a temp dir (never in dist/), served by the
// same server code (scripts/serve.mjs) in the same process.

// (module (func (export "add") (param i32 i32) (result i32) local.get 0 local.get 1 i32.add))
const ADD_WASM = Uint8Array.from([
  0x00, 0x61, 0x73, 0x6d, 0x01, 0x00, 0x00, 0x00, // magic, version
  0x01, 0x07, 0x01, 0x60, 0x02, 0x7f, 0x7f, 0x01, 0x7f, // type: (i32 i32) -> i32
  0x03, 0x02, 0x01, 0x00, // function 0 has type 0
  0x07, 0x07, 0x01, 0x03, 0x61, 0x64, 0x64, 0x00, 0x00, // export "add" = func 0
  0x0a, 0x09, 0x01, 0x07, 0x00, 0x20, 0x00, 0x20, 0x01, 0x6a, 0x0b, // local.get 0, local.get 1, i32.add
]);
const floorDir = fs.mkdtempSync(path.join(os.tmpdir(), "bench-floor-"));
fs.writeFileSync(path.join(floorDir, "add.wasm"), ADD_WASM);
fs.writeFileSync(
  path.join(floorDir, "floor.js"),
  `const { instance } = await WebAssembly.instantiateStreaming(fetch("./add.wasm"));
document.getElementById("out").textContent = String(instance.exports.add(40, 2));
performance.mark("first-solution");
`,
);
fs.writeFileSync(
  path.join(floorDir, "index.html"),
  `<!doctype html><html lang="en"><head><meta charset="utf-8"><meta name="viewport" content="width=device-width, initial-scale=1"><title>floor</title>
<script type="module" src="./floor.js"></script></head><body><p id="out">…</p></body></html>
`,
);

// ---------------------------------------------------------------------------

const server = await startServer({ dir: DIST, port: 0 });
const floorServer = await startServer({ dir: floorDir, port: 0 });
const browser = await launchChromium();
const DESKTOP = { viewport: { width: 1280, height: 900 }, serviceWorkers: "block" };
const PHONE = { viewport: { width: 390, height: 844 }, deviceScaleFactor: 2, isMobile: true, hasTouch: true, serviceWorkers: "block" };
const THROTTLE = { cpu: 4, latency: 150, down: 1.6e6 / 8, up: 750e3 / 8 };

const kindOf = (p) => {
  if (/\.(woff2?|ttf|otf)$/.test(p)) return "font";
  if (/\.wasm$/.test(p)) return "wasm";
  if (/\.m?js$/.test(p)) return "js";
  if (/\.css$/.test(p)) return "css";
  if (/\.html?$/.test(p) || p.endsWith("/")) return "html";
  return "other";
};
/** The lab's built files (their logical names start with lab/ in the build's assets.json). */
const LAB_FILES = new Set(
  Object.entries(JSON.parse(fs.readFileSync(path.join(DIST, "assets.json"), "utf8")))
    .filter(([logical]) => logical.startsWith("lab/"))
    .map(([, built]) => built),
);
const gzCache = new Map();
/** gzip -9 and raw size of the dist/ file behind a URL path (null when dist/ has none). */
function distSize(pathname) {
  if (!gzCache.has(pathname)) {
    const file = path.join(DIST, pathname.endsWith("/") ? `${pathname}index.html` : pathname);
    let v = null;
    try {
      const raw = fs.readFileSync(file);
      v = { raw: raw.length, gz: zlib.gzipSync(raw, { level: 9 }).length };
    } catch {
      v = null;
    }
    gzCache.set(pathname, v);
  }
  return gzCache.get(pathname);
}

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  if (!s.length) return NaN;
  const m = Math.floor(s.length / 2);
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
};
const stats = (xs) => ({ median: median(xs), min: Math.min(...xs), max: Math.max(...xs), n: xs.length });

/** The marks whose frames are timed (scripts/rendered-marks.mjs tells when each is rendered). */
const MARKS = ["first-solution", "solver-ready"];
const signalOf = (name) => `bench: ${name}`;

/**
 * Resolves when the frame that shows the page's `first-solution` (or
 * `until`) mark has been rendered (recordRendered, scripts/rendered-marks.mjs:
 * the student sees the numbers then, not at the mark, which script sets
 * before the frame's layout and paint), told by a console message.
 * Not page.waitForFunction: that makes Playwright evaluate its own injected
 * script (≈ 100 KB of JS) in the page while it loads, 10–30 ms of the main
 * thread that a student's browser never spends, in the middle of every load
 * timed (the floor's included; see docs/BENCH-LOAD.md, "How it measures").
 */
async function markSignalled(page, name = "first-solution", timeout = 30000) {
  await page.addInitScript(recordRendered, MARKS);
  const message = new Promise((resolve) => {
    page.on("console", (m) => {
      if (m.text() === signalOf(name)) resolve();
    });
  });
  // A console message can be lost (seen once in a run of hundreds): after 5 s the page is
  // asked, every 0.5 s. The time taken is the mark's own, whenever it is noticed.
  let done = false;
  const asked = (async () => {
    const t0 = Date.now();
    for (let wait = 5000; !done; wait = 500) {
      await new Promise((r) => setTimeout(r, wait).unref());
      if (done) return;
      if (await page.evaluate((n) => window.__benchRendered?.[n] != null, name).catch(() => false)) return;
      if (Date.now() - t0 > timeout) {
        const state = await page
          .evaluate(() => ({ rendered: window.__benchRendered, marks: performance.getEntriesByType("mark").map((m) => m.name), visibility: document.visibilityState, status: document.body.dataset.status }))
          .catch(() => null);
        const what = `${page.url()} ${JSON.stringify(state)}`;
        if (state?.marks.includes(name)) {
          const why = state.rendered === undefined ? "the bench's init script did not run in this load" : "its frame not rendered";
          throw new FrameNotReported(`${name} set, ${why} within ${timeout} ms: ${what}`);
        }
        throw new Error(`no ${name} mark within ${timeout} ms: ${what}`);
      }
    }
  })();
  try {
    await Promise.race([message, asked]);
  } finally {
    done = true;
  }
}

/** Loads whose frame was never reported (see coldLoad), with what the page said. */
const retried = [];

/** A load whose mark was set but whose frame was not reported: coldLoad tries it again. */
class FrameNotReported extends Error {}

/**
 * One cold load (new context) of `url`: the time the frame of its
 * `first-solution` mark was rendered (ms: the first numbers on screen, the
 * build's saved solution where the page shows one) and, with `until:
 * "solver-ready"`, of the page's own first solution (ready: its inputs live;
 * the floor has no such mark); the marks' own times (mark, readyMark); and
 * the requests (resource timing).
 * A load whose bench init script did not run is loaded again (twice at most).
 */
async function coldLoad(url, options = {}) {
  for (let attempt = 1; ; attempt++) {
    try {
      return await coldLoadOnce(url, options);
    } catch (e) {
      // seen about once in 500 loads, and then the page had no window.__benchRendered: the
      // init script (Playwright's addInitScript) had not run in it. A harness hiccup, not the
      // page's: the load is timed again
      if (!(e instanceof FrameNotReported) || attempt >= 3) throw e;
      retried.push(e.message);
      process.stdout.write(`  (retried: ${e.message})\n`);
    }
  }
}

async function coldLoadOnce(url, { phone = false, throttle = false, details = false, until = "first-solution" } = {}) {
  const context = await browser.newContext(phone ? PHONE : DESKTOP);
  try {
    const page = await context.newPage();
    if (throttle) {
      const cdp = await page.context().newCDPSession(page);
      await cdp.send("Emulation.setCPUThrottlingRate", { rate: THROTTLE.cpu });
      await cdp.send("Network.enable");
      await cdp.send("Network.emulateNetworkConditions", {
        offline: false,
        latency: THROTTLE.latency,
        downloadThroughput: THROTTLE.down,
        uploadThroughput: THROTTLE.up,
      });
    }
    const requested = [];
    if (details) {
      await page.addInitScript(() => performance.setResourceTimingBufferSize(2000));
      page.on("request", (r) => requested.push(r.url()));
    }
    const marked = markSignalled(page, until);
    marked.catch(() => {}); // awaited below; a failed goto must not leave it unhandled
    await page.goto(url, { waitUntil: "commit" });
    await marked;
    const [mark, readyMark, ms, ready] = await page.evaluate(
      (names) => [...names.map((n) => performance.getEntriesByName(n)[0]?.startTime ?? null), ...names.map((n) => window.__benchRendered?.[n] ?? null)],
      MARKS,
    );
    const times = { ms, ready, mark, readyMark };
    if (!details) return times;
    await page.waitForLoadState("networkidle");
    const status = await page.evaluate(() => document.body.dataset.status);
    const resources = await page.evaluate(() =>
      performance.getEntriesByType("resource").map((e) => ({
        url: e.name,
        start: e.startTime,
        end: e.responseEnd,
        encoded: e.encodedBodySize,
        decoded: e.decodedBodySize,
      })),
    );
    return { ...times, status, resources, requested };
  } finally {
    await context.close();
  }
}

/** The bytes of one load: critical path (requested before the mark) and total. */
function bytesOf(load, origin) {
  const files = [];
  const seen = new Set();
  for (const r of load.resources) {
    const u = new URL(r.url);
    if (u.origin !== origin) continue;
    const key = u.pathname;
    if (seen.has(key)) continue;
    seen.add(key);
    const size = distSize(key);
    files.push({
      path: key,
      kind: kindOf(key),
      // what the page's own first solution needed (its solver: wasm, JS, CSS), requested before it
      critical: r.start < (load.readyMark ?? load.mark),
      start: r.start,
      gz: size ? size.gz : r.encoded,
      raw: size ? size.raw : r.decoded,
      sent: r.encoded,
      inDist: Boolean(size),
    });
  }
  // requests the page made that resource timing did not list (should be none)
  for (const url of load.requested) {
    const u = new URL(url);
    if (u.origin !== origin || seen.has(u.pathname) || u.pathname === "/" || kindOf(u.pathname) === "html") continue;
    seen.add(u.pathname);
    const size = distSize(u.pathname);
    files.push({ path: u.pathname, kind: kindOf(u.pathname), critical: false, start: NaN, gz: size?.gz ?? 0, raw: size?.raw ?? 0, sent: NaN, inDist: Boolean(size), untimed: true });
  }
  const sum = (f, field = "gz") => files.filter(f).reduce((s, x) => s + (Number.isFinite(x[field]) ? x[field] : 0), 0);
  const code = (x) => ["wasm", "js", "css"].includes(x.kind);
  return {
    files,
    critical: sum((x) => x.critical && code(x)),
    total: sum(code),
    criticalSent: sum((x) => x.critical && code(x), "sent"),
    totalSent: sum(code, "sent"),
    fonts: sum((x) => x.kind === "font"),
    // the build's saved solution (scripts/prerender.mjs), HTML
    saved: sum((x) => x.path.startsWith("/prerender/")),
    other: sum((x) => x.kind === "other"),
    lab: files.filter((x) => LAB_FILES.has(x.path.replace(/^\//, "")) || x.path.startsWith("/lab/")).map((x) => x.path),
  };
}

/** The examples in the page's own catalog (ready ones), with their topics. */
async function catalog() {
  const context = await browser.newContext(DESKTOP);
  try {
    const page = await context.newPage();
    await page.goto(`${server.url}#/`);
    await page.waitForFunction(() => document.body.dataset.status === "home", null, { timeout: 60000 });
    return await page.evaluate(() =>
      [...document.querySelectorAll("nav.catalog-detailed .catalog-item[data-status=ready]")].map((li) => ({
        id: li.dataset.id,
        topic: li.closest("section")?.querySelector("h2")?.textContent ?? "",
      })),
    );
  } finally {
    await context.close();
  }
}

/**
 * Input → redrawn figure: opens the example, finds a numeric input whose
 * nearby value solves, and alternates it with the seed's value `count` times,
 * reading the page's `redraw` measure after each change.
 */
async function redrawTimes(id, count) {
  const context = await browser.newContext(DESKTOP);
  try {
    const page = await context.newPage();
    await page.goto(`${server.url}#/${id}`);
    await page.waitForFunction(() => performance.getEntriesByName("first-solution").length > 0, null, { timeout: 60000 });
    await page.waitForLoadState("networkidle");
    await page.evaluate(() => document.fonts.ready);
    return await page.evaluate(async (count) => {
      const measures = [];
      const settles = [];
      new PerformanceObserver((list) => {
        measures.push(...list.getEntriesByName("redraw"));
        settles.push(...list.getEntriesByName("settled"));
      }).observe({ type: "measure" });
      const frame = () => new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0)));
      // one change: its "redraw" (the figure's frame) and "settled" (steps, result and notes too) measures
      const change = async (input, text) => {
        const before = measures.length;
        const beforeSettled = settles.length;
        input.value = text;
        input.dispatchEvent(new Event("input", { bubbles: true }));
        // (a page without the settled measure: given up a few frames after it stopped "updating")
        let after = 0;
        const waiting = () => measures.length === before || (settles.length === beforeSettled && (document.body.dataset.status === "updating" || after++ < 3));
        for (let i = 0; i < 100 && waiting(); i++) await frame();
        const m = measures[measures.length - 1];
        const s = settles.length > beforeSettled ? settles[settles.length - 1] : null;
        return measures.length > before
          ? { ms: m.duration, js: m.detail?.js, frame: m.detail?.frame, settled: s?.duration ?? null, rest: s?.detail?.rest ?? null, restFrame: s?.detail?.restFrame ?? null, wall: s?.detail?.wall ?? null, ok: document.body.dataset.status === "ok" }
          : null;
      };
      // the numeric inputs first (number, integer), then one number inside a vector, matrix or point list
      const rank = (w) => (w.classList.contains("field-number") || w.classList.contains("field-integer") ? 0 : 1);
      const fields = [...document.querySelectorAll(".input-form .field")]
        .filter((w) => !w.hidden && !w.classList.contains("field-choice") && !w.classList.contains("field-flag"))
        .sort((a, b) => rank(a) - rank(b))
        .map((w) => ({ key: w.dataset.key, input: w.querySelector("input[type=text], textarea") }))
        .filter((f) => f.input && !f.input.disabled && /\d/.test(f.input.value));
      const near = (token) => {
        const v = Number(token);
        if (/^-?\d+$/.test(token)) return [v + 1, v - 1, v + 2].map(String);
        if (v === 0) return ["0.1", "-0.1", "0.01"];
        return [v * 1.01, v * 0.99, v + 0.1, v - 0.1].map((x) => String(Number(x.toPrecision(6))));
      };
      /** Texts that differ from the seed's in one number (of the first few). */
      const nearby = (f) => {
        const text = f.input.value;
        const out = [];
        const tokens = [...text.matchAll(/-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?/g)].slice(0, 6);
        for (const m of tokens) for (const t of near(m[0])) out.push({ text: text.slice(0, m.index) + t + text.slice(m.index + m[0].length), from: m[0], to: t });
        return out;
      };
      const figure = Boolean(document.querySelector(".figure-section canvas"));
      for (const f of fields) {
        const seed = f.input.value;
        for (const { text, from, to } of nearby(f)) {
          const first = await change(f.input, text);
          if (!first || !first.ok) {
            await change(f.input, seed);
            continue;
          }
          const times = [first];
          for (let i = 1; i < count; i++) {
            await frame();
            times.push(await change(f.input, i % 2 ? seed : text));
          }
          await change(f.input, seed);
          return { field: f.key, values: [from, to], figure, times: times.filter(Boolean), allOk: times.every((t) => t && t.ok) };
        }
      }
      return { field: null, figure, times: [], reason: fields.length ? "no nearby value solved" : "no numeric input" };
    }, count);
  } finally {
    await context.close();
  }
}

// ---------------------------------------------------------------------------

const results = {};
let floorDesktop = [];
let floorMarks = [];
let floorThrottled = [];
let examples = [];
let lab = null;
const t0 = Date.now();
try {
  const all = await catalog();
  if (!all.length) throw new Error("the page's catalog lists no ready example");
  // --quick: the catalog's first example and the first of its last topic
  // (the lightest module and, since the topics grew in that order, a heavy one)
  if (quick && !wanted.length) wanted.push(all[0].id, all.find((e) => e.topic === all.at(-1).topic).id);
  const unknown = wanted.filter((id) => !all.some((e) => e.id === id));
  if (unknown.length) throw new Error(`not in the page's catalog: ${unknown.join(", ")} (it has ${all.map((e) => e.id).join(", ")})`);
  examples = wanted.length ? wanted.map((id) => all.find((e) => e.id === id)) : all;
  for (const e of examples) results[e.id] = { id: e.id, topic: e.topic, nav: [], ready: [], navMark: [], readyMark: [] };
  const origin = new URL(server.url).origin;
  console.log(`bench-load: ${examples.length} example(s), ${runs} cold loads each (+ floor), throttled: ${throttledSet}, redraw: ${doRedraw ? redraws : "off"}`);

  // 1 + 2: cold loads, round-robin over the examples, a floor load every 3 examples
  for (let round = 0; round < runs; round++) {
    for (let i = 0; i < examples.length; i++) {
      if (i % 3 === 0) {
        const f = await coldLoad(floorServer.url);
        floorDesktop.push(f.ms);
        floorMarks.push(f.mark);
      }
      const { id } = examples[i];
      const load = await coldLoad(`${server.url}#/${id}`, { details: round === 0, until: "solver-ready" });
      results[id].nav.push(load.ms);
      results[id].ready.push(load.ready);
      results[id].navMark.push(load.mark);
      results[id].readyMark.push(load.readyMark);
      if (round === 0) {
        results[id].status = load.status;
        results[id].bytes = bytesOf(load, origin);
      }
    }
    process.stdout.write(`  round ${round + 1}/${runs} done (${((Date.now() - t0) / 1000).toFixed(0)} s)\n`);
  }

  // 3: throttled phone profile
  if (throttledSet !== "none") {
    let set = examples;
    if (throttledSet === "topics") {
      const byTopic = new Map();
      for (const e of examples) {
        const cur = byTopic.get(e.topic);
        if (!cur || results[e.id].bytes.critical > results[cur.id].bytes.critical) byTopic.set(e.topic, e);
      }
      set = [...byTopic.values()];
    }
    for (let round = 0; round < throttledRuns; round++) {
      floorThrottled.push((await coldLoad(floorServer.url, { phone: true, throttle: true })).ms);
      for (const { id } of set) {
        const load = await coldLoad(`${server.url}#/${id}`, { phone: true, throttle: true, until: "solver-ready" });
        (results[id].throttled ??= []).push(load.ms);
        (results[id].throttledReady ??= []).push(load.ready);
      }
      process.stdout.write(`  throttled round ${round + 1}/${throttledRuns} done (${((Date.now() - t0) / 1000).toFixed(0)} s)\n`);
    }
  }

  // 4: input → redrawn figure
  if (doRedraw) {
    for (const { id } of examples) results[id].redraw = await redrawTimes(id, redraws);
    process.stdout.write(`  redraws done (${((Date.now() - t0) / 1000).toFixed(0)} s)\n`);
  }

  // 5: what a lab visit downloads (#/lab opened after the home page, as a student
  // comes to it: the lab's own JS, CSS and the one wasm build its worker picks),
  // and that no example requested any lab file (the build's logical names, assets.json).
  {
    const context = await browser.newContext(DESKTOP);
    try {
      const page = await context.newPage();
      await page.addInitScript(() => {
        globalThis.__playgroundTest = true;
      });
      const requested = [];
      page.on("request", (r) => requested.push(new URL(r.url()).pathname));
      await page.goto(`${server.url}#/`);
      await page.waitForLoadState("networkidle");
      const home = new Set(requested);
      await page.goto(`${server.url}#/lab`);
      await page.waitForFunction(() => document.body.dataset.labRestored === "1" && document.body.dataset.lab === "idle", null, { timeout: 60000 });
      await page.waitForLoadState("networkidle");
      const visit = [...new Set(requested)].filter((p) => !home.has(p) && ["js", "wasm", "css"].includes(kindOf(p)));
      const sizes = visit.map((p) => ({ path: p, ...(distSize(p) ?? { raw: 0, gz: 0 }) }));
      const photos = fs.readdirSync(path.join(DIST, "lab", "samples")).map((f) => fs.statSync(path.join(DIST, "lab", "samples", f)).size);
      lab = {
        module_gz: sizes.reduce((s, f) => s + f.gz, 0),
        module_raw: sizes.reduce((s, f) => s + f.raw, 0),
        wasm: sizes.filter((f) => f.path.endsWith(".wasm")).map((f) => f.path),
        photos_raw: photos.reduce((s, n) => s + n, 0),
        photos: photos.length,
        files: sizes.length,
        requested_by: Object.values(results).filter((r) => r.bytes?.lab.length).map((r) => r.id),
      };
    } finally {
      await context.close();
    }
  }
} finally {
  await browser.close();
  await server.close();
  await floorServer.close();
  fs.rmSync(floorDir, { recursive: true, force: true });
}

// ---------------------------------------------------------------------------
// 6: one table

const KB = (n) => (Number.isFinite(n) ? (n / 1024).toFixed(1) : "–");
const MS = (n) => (Number.isFinite(n) ? n.toFixed(0) : "–");
const floor = stats(floorDesktop);
const floorMark = stats(floorMarks);
const floorT = floorThrottled.length ? stats(floorThrottled) : null;
const rows = examples.map(({ id, topic }) => {
  const r = results[id];
  const nav = stats(r.nav);
  const ready = stats(r.ready);
  const th = r.throttled ? stats(r.throttled) : null;
  const thReady = r.throttledReady ? stats(r.throttledReady) : null;
  const rd = r.redraw?.times?.length ? { ...stats(r.redraw.times.map((t) => t.ms)), js: median(r.redraw.times.map((t) => t.js)), frame: median(r.redraw.times.map((t) => t.frame)) } : null;
  const settledTimes = (r.redraw?.times ?? []).filter((t) => Number.isFinite(t.settled));
  const st = settledTimes.length
    ? { ...stats(settledTimes.map((t) => t.settled)), rest: median(settledTimes.map((t) => t.rest)), rest_frame: median(settledTimes.map((t) => t.restFrame)), wall: median(settledTimes.map((t) => t.wall)) }
    : null;
  return {
    id,
    topic,
    status: r.status,
    critical_gz: r.bytes.critical,
    total_gz: r.bytes.total,
    critical_sent: r.bytes.criticalSent,
    total_sent: r.bytes.totalSent,
    fonts_gz: r.bytes.fonts,
    saved_gz: r.bytes.saved,
    other_gz: r.bytes.other,
    lab_files: r.bytes.lab,
    nav_ms: nav,
    ratio: nav.median / floor.median,
    ready_ms: ready,
    ratio_ready: ready.median / floor.median,
    // the marks' own times (set by script, before their frame is rendered)
    nav_mark_ms: stats(r.navMark),
    ready_mark_ms: stats(r.readyMark),
    throttled_ms: th,
    throttled_ready_ms: thReady,
    redraw_ms: rd,
    settled_ms: st,
    redraw_field: r.redraw?.field ?? null,
    redraw_values: r.redraw?.values ?? null,
    redraw_note: r.redraw ? (r.redraw.reason ?? (r.redraw.figure ? "" : "no figure")) : "",
    files: r.bytes.files,
  };
});

// the throttled column says which examples it ran: by default the heaviest critical path of each topic ("–": not run)
const throttledHead = { topics: "throttled ms (heaviest of its topic)", all: "throttled ms (every example)", none: "throttled ms (not run)" }[throttledSet] ?? "throttled ms";
const head = ["example", "crit KB gz", "total KB gz", "sent KB", "saved KB gz", "numbers ms med (min–max)", "× floor", "solver ms med", "× floor", `${throttledHead}: numbers/solver`, "redraw med/worst ms", "settled med/worst ms", "input"];
const lines = rows.map((r) => [
  r.id,
  KB(r.critical_gz),
  KB(r.total_gz),
  `${KB(r.critical_sent)}/${KB(r.total_sent)}`,
  r.saved_gz ? KB(r.saved_gz) : "–",
  `${MS(r.nav_ms.median)} (${MS(r.nav_ms.min)}–${MS(r.nav_ms.max)})`,
  r.ratio.toFixed(2),
  MS(r.ready_ms.median),
  r.ratio_ready.toFixed(2),
  r.throttled_ms ? `${MS(r.throttled_ms.median)}/${MS(r.throttled_ready_ms.median)}` : "–",
  r.redraw_ms ? `${r.redraw_ms.median.toFixed(1)}/${r.redraw_ms.max.toFixed(1)}` : r.redraw_note ? "n/a" : "",
  r.settled_ms ? `${r.settled_ms.median.toFixed(1)}/${r.settled_ms.max.toFixed(1)}` : r.redraw_note ? "n/a" : "",
  r.redraw_field ? `${r.redraw_field} ${r.redraw_values.join("↔")}${r.redraw_note ? ` (${r.redraw_note})` : ""}` : r.redraw_note,
]);
const widths = head.map((h, i) => Math.max(h.length, ...lines.map((l) => String(l[i]).length)));
const fmt = (cells) => cells.map((c, i) => (i === 0 || i === cells.length - 1 ? String(c).padEnd(widths[i]) : String(c).padStart(widths[i]))).join(" | ");
console.log(`\n${fmt(head)}\n${widths.map((w) => "-".repeat(w)).join("-|-")}`);
for (const l of lines) console.log(fmt(l));

const maxBy = (f) => rows.reduce((best, r) => (f(r) > f(best) ? r : best), rows[0]);
const maxBytes = maxBy((r) => r.critical_gz);
const maxTotal = maxBy((r) => r.total_gz);
const maxRatio = maxBy((r) => r.ratio);
const maxReady = maxBy((r) => r.ratio_ready);
const withT = rows.filter((r) => r.throttled_ms);
const maxT = withT.length ? withT.reduce((b, r) => (r.throttled_ms.median > b.throttled_ms.median ? r : b)) : null;
const maxTR = withT.length ? withT.reduce((b, r) => (r.throttled_ready_ms.median > b.throttled_ready_ms.median ? r : b)) : null;
const withR = rows.filter((r) => r.redraw_ms);
const maxR = withR.length ? withR.reduce((b, r) => (r.redraw_ms.median > b.redraw_ms.median ? r : b)) : null;
const worstR = withR.length ? withR.reduce((b, r) => (r.redraw_ms.max > b.redraw_ms.max ? r : b)) : null;
const withS = rows.filter((r) => r.settled_ms);
const maxS = withS.length ? withS.reduce((b, r) => (r.settled_ms.median > b.settled_ms.median ? r : b)) : null;
const worstS = withS.length ? withS.reduce((b, r) => (r.settled_ms.max > b.settled_ms.max ? r : b)) : null;
const verdict = (ok) => (ok ? "meets the aim" : "OVER the aim");
const notOk = rows.filter((r) => r.status !== "ok").map((r) => `${r.id} (${r.status})`);
const summary = [
  `floor page: median ${MS(floor.median)} ms (min ${MS(floor.min)}, max ${MS(floor.max)}, ${floor.n} cold loads)${floorT ? `; throttled median ${MS(floorT.median)} ms (${floorT.n} loads) — the throttling applies: ${(floorT.median / floor.median).toFixed(1)}× the desktop floor` : ""}`,
  `largest critical path: ${maxBytes.id} ${KB(maxBytes.critical_gz)} KB gz vs aim ${AIM_KB} KB — ${verdict(maxBytes.critical_gz <= AIM_KB * 1024)}; largest total after network idle: ${maxTotal.id} ${KB(maxTotal.total_gz)} KB gz (fonts apart: ${KB(maxTotal.fonts_gz)} KB)`,
  `mark → its frame rendered (medians): floor ${MS(floorMark.median)} → ${MS(floor.median)} ms; first numbers ${MS(Math.min(...rows.map((r) => r.nav_ms.median - r.nav_mark_ms.median)))}–${MS(Math.max(...rows.map((r) => r.nav_ms.median - r.nav_mark_ms.median)))} ms after their mark, the page's own solution ${MS(Math.min(...rows.map((r) => r.ready_ms.median - r.ready_mark_ms.median)))}–${MS(Math.max(...rows.map((r) => r.ready_ms.median - r.ready_mark_ms.median)))} ms after its own (the times above are the rendered frames)`,
  `largest ratio to floor, the first numbers on screen (the build's saved solution where there is one): ${maxRatio.id} ${maxRatio.ratio.toFixed(2)}× (${MS(maxRatio.nav_ms.median)} ms) vs aim ${AIM_RATIO}× — ${verdict(maxRatio.ratio <= AIM_RATIO)}`,
  `largest ratio to floor, the page's own first solution (its inputs live): ${maxReady.id} ${maxReady.ratio_ready.toFixed(2)}× (${MS(maxReady.ready_ms.median)} ms) vs aim ${AIM_RATIO}× — ${verdict(maxReady.ratio_ready <= AIM_RATIO)}`,
  maxT ? `slowest throttled (${throttledSet === "topics" ? "the heaviest example of each topic" : "every example"}, ${throttledRuns} loads each), first numbers: ${maxT.id} ${MS(maxT.throttled_ms.median)} ms vs aim ${AIM_THROTTLED_MS} ms — ${verdict(maxT.throttled_ms.median <= AIM_THROTTLED_MS)}; the page's own solution: ${maxTR.id} ${MS(maxTR.throttled_ready_ms.median)} ms — ${verdict(maxTR.throttled_ready_ms.median <= AIM_THROTTLED_MS)}` : "throttled: not run",
  maxR ? `slowest redraw (median): ${maxR.id} ${maxR.redraw_ms.median.toFixed(1)} ms (JS ${maxR.redraw_ms.js.toFixed(1)} + frame ${maxR.redraw_ms.frame.toFixed(1)}); worst single: ${worstR.id} ${worstR.redraw_ms.max.toFixed(1)} ms; aim ${AIM_REDRAW_MS} ms — ${withR.filter((r) => r.redraw_ms.median > AIM_REDRAW_MS).length} example(s) over it by median, ${withR.filter((r) => r.redraw_ms.max > AIM_REDRAW_MS).length} by worst` : "redraw: not run",
  maxS
    ? `slowest settled (median; the steps, result and notes updated too): ${maxS.id} ${maxS.settled_ms.median.toFixed(1)} ms (redraw ${maxS.redraw_ms.median.toFixed(1)} + rest ${maxS.settled_ms.rest.toFixed(1)} + its frame ${maxS.settled_ms.rest_frame.toFixed(1)}; input to settled, the waits for frames included: ${maxS.settled_ms.wall.toFixed(1)}); worst single: ${worstS.id} ${worstS.settled_ms.max.toFixed(1)} ms`
    : "settled: not run",
  lab ? `image lab: a #/lab visit downloads ${KB(lab.module_gz)} KB gz of JS, CSS and wasm (${lab.files} files, raw ${KB(lab.module_raw)} KB; wasm: ${lab.wasm.join(", ")}), sample photos ${KB(lab.photos_raw)} KB (${lab.photos} files, not compressible); lab files requested by an example: ${lab.requested_by.length ? `YES — ${lab.requested_by.join(", ")}` : "none (off every example's critical path)"}` : "image lab: not measured",
  notOk.length ? `NOT SOLVED on the first load: ${notOk.join(", ")}` : `every example reached status "ok"`,
  `untimed requests (not in resource timing): ${rows.flatMap((r) => r.files.filter((f) => f.untimed).map((f) => `${r.id}:${f.path}`)).join(", ") || "none"}; files not in dist/: ${[...new Set(rows.flatMap((r) => r.files.filter((f) => !f.inDist).map((f) => f.path)))].join(", ") || "none"}`,
  `loads tried again (a mark's frame not reported): ${retried.length ? `${retried.length} — ${retried.join("; ")}` : "none"}`,
  `machine load: ${os.loadavg().map((x) => x.toFixed(2)).join(" ")} (1/5/15 min), ${os.cpus().length} cores; run took ${((Date.now() - t0) / 1000).toFixed(0)} s`,
];
console.log("");
for (const s of summary) console.log(s);
// what the heaviest critical path holds, largest first
console.log(`\nThe critical path of ${maxBytes.id} (gzip -9 of the dist/ file; fonts and HTML apart):`);
for (const f of maxBytes.files.filter((x) => x.critical && ["wasm", "js", "css"].includes(x.kind)).sort((a, b) => b.gz - a.gz)) {
  console.log(`  ${KB(f.gz).padStart(7)} KB  (raw ${KB(f.raw).padStart(7)} KB)  ${f.kind.padEnd(4)} ${f.path}`);
}

if (jsonFile) {
  fs.writeFileSync(
    jsonFile,
    JSON.stringify({ date: new Date().toISOString(), runs, throttled_runs: throttledRuns, throttled_set: throttledSet, throttle: THROTTLE, floor_ms: floor, floor_mark_ms: floorMark, floor_throttled_ms: floorT, retried, lab, examples: rows, summary }, null, 1),
  );
  console.log(`written: ${jsonFile}`);
}
