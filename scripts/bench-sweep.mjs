// npm run bench -- sweep (scripts/bench.sh): the Sweep tool (issue 34; www/sweep/)
// in headless Chromium. For every example of the catalog with a number input
// (ids from the built catalog, none written here): the sweep opened on its
// first number input, 200 points over the default range; then a change of the
// range (the sweep's "To" box, alternately nudged) a few times, each timed from
// the change to the chart painted — the page's `sweep` measure (www/sweep/
// sweep.js: its start, then the frame after the chart's data was set) — median
// and worst; beside it the same module's solve() called 200 times on the seed's
// inputs in the page (what the 200 crossings of the JS↔wasm boundary and the
// solving cost without any drawing). A benchmark: it asserts nothing.
//
//   node scripts/bench-sweep.mjs [--dist dist] [--points 200] [--runs 7] [--example gsd] [--json FILE]
import fs from "node:fs";
import os from "node:os";
import { launchChromium } from "./chromium.mjs";
import { startServer } from "./serve.mjs";

const args = process.argv.slice(2);
const arg = (name, dflt) => {
  const i = args.indexOf(name);
  return i >= 0 && i + 1 < args.length ? args[i + 1] : dflt;
};
const dist = arg("--dist", "dist");
const points = Number(arg("--points", 200));
const runs = Math.max(1, Number(arg("--runs", 7)));
const jsonFile = arg("--json", null);
const catalogFile = JSON.parse(fs.readFileSync(`${dist}/assets.json`, "utf8"))["catalog.json"] ?? "catalog.json";
const catalog = JSON.parse(fs.readFileSync(`${dist}/${catalogFile}`, "utf8"));
const examples = arg("--example", null) ? catalog.filter((e) => e.id === arg("--example")) : catalog.filter((e) => e.status === "ready");
/** Aims (issue 34): 200 points in 100 ms, 250 ms for the LSM and UTM families (their modules: matching, projection). */
const aimOf = (e) => (e.module === "matching" || e.module === "projection" ? 250 : 100);

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length ? (s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2) : NaN;
};
const ms = (x) => (Number.isFinite(x) ? x.toFixed(1) : "—");

const server = await startServer({ dir: dist, port: 0 });
const browser = await launchChromium();
const page = await (await browser.newContext({ viewport: { width: 1280, height: 900 }, serviceWorkers: "block" })).newPage();
const rows = [];
try {
  for (const entry of examples) {
    await page.goto("about:blank");
    await page.goto(`${server.url}index.html#/${entry.id}`);
    await page.waitForFunction(() => ["ok", "error", "invalid", "message"].includes(document.body.dataset.status));
    if (!(await page.$(".sweep-open"))) continue; // no number input
    await page.click(".sweep-open");
    await page.waitForSelector(".sweep-section canvas");
    // 200 points over the default range
    const measure = (action) =>
      page.evaluate(async ([act, n]) => {
        performance.clearMeasures("sweep");
        const steps = document.querySelector(".sweep-section input[id$=-steps]");
        const to = document.querySelector(".sweep-section input[id$=-to]");
        // the ends are text boxes the core reads (the page writes them as plain numbers)
        const from = Number(document.querySelector(".sweep-section input[id$=-from]").value);
        if (act === "steps") steps.value = String(n);
        // (whole-number ends move by 1: an integer input's box refuses a fraction)
        else if (/^-?\d+$/.test(to.value)) to.value = String(Number(to.value) + (act === "up" ? 1 : -1));
        else to.value = String(Number(to.value) + (act === "up" ? 1 : -1) * Math.abs(Number(to.value) - from) * 1e-6);
        (act === "steps" ? steps : to).dispatchEvent(new Event("change"));
        for (let i = 0; i < 200 && !performance.getEntriesByName("sweep").length; i++) await new Promise((r) => setTimeout(r, 10));
        const m = performance.getEntriesByName("sweep")[0];
        return m ? { duration: m.duration, compute: m.detail.compute, js: m.detail.js, points: m.detail.points } : null;
      }, [action, points]);
    const first = await measure("steps");
    const times = [];
    const computes = [];
    const js = [];
    for (let i = 0; i < runs; i++) {
      const m = await measure(i % 2 ? "down" : "up");
      if (m) {
        times.push(m.duration);
        computes.push(m.compute);
        js.push(m.js);
      }
    }
    const field = await page.$eval(".sweep-section select", (s) => s.value);
    // the same module's solve, 200 times on the seed's inputs (no drawing)
    const solve200 = await page.evaluate(async ([id, n]) => {
      const { loadExample } = await import("./pkg/examples.js");
      const ex = await loadExample(id);
      ex.solve({});
      const t = performance.now();
      for (let i = 0; i < n; i++) ex.solve({});
      const solve = performance.now() - t;
      // a light crossing of the boundary (texts in, a small object out): its floor
      const u = performance.now();
      for (let i = 0; i < n; i++) ex.parseInputs({});
      return { solve, parse: performance.now() - u };
    }, [entry.id, points]);
    const gaps = await page.$eval(".sweep-section", (s) => Number(s.querySelector(".sweep-errors-fold summary")?.textContent.match(/^\d+/)?.[0] ?? 0));
    rows.push({ id: entry.id, field, points: first?.points ?? null, median: median(times), worst: Math.max(...times), compute: median(computes), js: median(js), solve200: solve200.solve, parse200: solve200.parse, gaps, aim: aimOf(entry) });
    console.error(`${entry.id}: ${ms(median(times))} ms`);
  }
} finally {
  await browser.close();
  await server.close();
}

const load = os.loadavg().map((x) => x.toFixed(2)).join(", ");
console.log(`\nSweep of ${points} points, change → chart painted (${runs} changes each), Chromium headless, 1280 px; load average ${load} on ${os.cpus().length} cores\n`);
console.log("| example | swept input | points | median ms | worst ms | series ms (median) | all JS ms (median) | solve() × 200 ms | parseInputs() × 200 ms | points without a solution | aim ms |");
console.log("|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|");
for (const r of rows) console.log(`| ${r.id} | ${r.field} | ${r.points} | ${ms(r.median)} | ${ms(r.worst)} | ${ms(r.compute)} | ${ms(r.js)} | ${ms(r.solve200)} | ${ms(r.parse200)} | ${r.gaps ?? "—"} | ${r.median <= r.aim ? "" : "over "}${r.aim} |`);
if (jsonFile) fs.writeFileSync(jsonFile, `${JSON.stringify({ points, runs, load, rows }, null, 2)}\n`);
