// Measures the page as a student's browser meets it (benchmarks, not tests):
//  - the bytes it loads for a first example, gzipped (wasm, JS, CSS; KaTeX
//    fonts counted apart), as a static host with gzip would send them;
//  - the time from navigation to the first solved example on screen (the
//    page's `first-solution` performance mark), median of several cold loads.
//   node scripts/bench.mjs [--runs 7] [--example gsd]
import { chromium } from "playwright-core";
import fs from "node:fs";
import path from "node:path";
import zlib from "node:zlib";
import { startServer } from "./serve.mjs";

const args = process.argv.slice(2);
if (args.includes("--lab")) {
  // the image lab's mode: scripts/bench_lab.mjs
  await import("./bench_lab.mjs");
  process.exit(0);
}
const arg = (name, dflt) => {
  const i = args.indexOf(name);
  return i >= 0 ? args[i + 1] : dflt;
};
const runs = Number(arg("--runs", 7));
const example = arg("--example", "gsd");

const server = await startServer({ dir: "dist", port: 0 });
const browser = await chromium.launch({
  executablePath: "/usr/bin/chromium",
  args: ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
    "--disable-background-networking", "--disable-component-update", "--disable-sync"],
});

const kindOf = (p) => {
  if (/\.(woff2?|ttf)$/.test(p)) return "font";
  if (p.endsWith(".wasm")) return "wasm";
  if (/\.m?js$/.test(p)) return "js";
  if (p.endsWith(".css")) return "css";
  if (p.endsWith(".html") || p.endsWith("/")) return "html";
  return "other";
};

const times = [];
let loaded = null;
try {
  for (let i = 0; i < runs; i++) {
    const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
    const page = await context.newPage();
    const urls = new Set();
    page.on("requestfinished", (r) => urls.add(new URL(r.url()).pathname));
    await page.goto(`${server.url}#/${example}`);
    await page.waitForFunction(() => performance.getEntriesByName("first-solution").length > 0, null, { timeout: 20000 });
    await page.waitForLoadState("networkidle");
    const ms = await page.evaluate(() => performance.getEntriesByName("first-solution")[0].startTime);
    times.push(ms);
    if (!loaded) loaded = [...urls];
    await context.close();
  }
} finally {
  await browser.close();
  await server.close();
}

const rows = loaded.map((p) => {
  const file = path.join("dist", p.endsWith("/") ? p + "index.html" : p);
  const raw = fs.readFileSync(file);
  return { path: p, kind: kindOf(p), raw: raw.length, gz: zlib.gzipSync(raw, { level: 9 }).length };
}).sort((a, b) => b.gz - a.gz);

const kb = (n) => (n / 1024).toFixed(1).padStart(7) + " KiB";
console.log(`\nWhat the page loads for #/${example} (gzip -9 as a static host would send it):`);
for (const r of rows) console.log(`  ${kb(r.gz)}  (raw ${kb(r.raw)})  ${r.kind.padEnd(5)} ${r.path}`);
const sum = (f) => rows.filter(f).reduce((s, r) => s + r.gz, 0);
const budget = sum((r) => ["wasm", "js", "css"].includes(r.kind));
console.log(`  wasm + JS + CSS: ${kb(budget)}   (aim: 150 KB)`);
console.log(`  fonts apart:     ${kb(sum((r) => r.kind === "font"))}`);
console.log(`  html:            ${kb(sum((r) => r.kind === "html"))}`);
console.log(`  image lab files loaded: ${rows.filter((r) => r.path.includes("/lab/")).length} (the lab loads only when #/lab opens)`);
times.sort((a, b) => a - b);
const median = times[Math.floor(times.length / 2)];
console.log(`\nNavigation to the first solved example (${runs} cold loads, new browser context each):`);
console.log(`  median ${median.toFixed(0)} ms, min ${times[0].toFixed(0)} ms, max ${times[times.length - 1].toFixed(0)} ms   (aim: 300 ms)`);
