// Measures the moving-window figures in motion (issue 34, "Measured"): for
// each example whose figure has frames (www/motion/motion.js), on the seed's
// inputs, the motion is played with a new frame on every animation frame
// (the hardest case: the page plays 2–10 positions per second) until at
// least --frames frames were drawn, and reports
//  - the frame time: the interval between consecutive animation frames while
//    playing (what the screen shows; 16.7 ms at 60 fps), median, 95th
//    percentile and worst, and the dropped frames (intervals over 1.5 × 16.7 ms);
//  - the drawing: the time the motion's draw of one frame took (the canvas,
//    the counter, the caption, the marked step), median and 95th percentile.
// A benchmark, not a test: it asserts nothing.
//   node scripts/bench-motion.mjs [--dist dist] [--frames 240] [--example ncc-surface]
import fs from "node:fs";
import { launchChromium } from "./chromium.mjs";
import { startServer } from "./serve.mjs";

const args = process.argv.slice(2);
const arg = (name, dflt) => {
  const i = args.indexOf(name);
  return i >= 0 ? args[i + 1] : dflt;
};
const dist = arg("--dist", "dist");
const want = Number(arg("--frames", 240));
// every example of the catalog; those whose figure does not move are skipped
const catalogFile = JSON.parse(fs.readFileSync(`${dist}/assets.json`, "utf8"))["catalog.json"] ?? "catalog.json";
const examples = arg("--example", null) ? [arg("--example")] : JSON.parse(fs.readFileSync(`${dist}/${catalogFile}`, "utf8")).map((e) => e.id);
const FRAME = 1000 / 60;

const pct = (xs, p) => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length ? s[Math.min(s.length - 1, Math.ceil((p / 100) * s.length) - 1)] : NaN;
};
const ms = (x) => (Number.isFinite(x) ? x.toFixed(2) : "—");

const server = await startServer({ dir: dist, port: 0 });
const browser = await launchChromium();
const page = await (await browser.newContext({ viewport: { width: 1280, height: 900 }, serviceWorkers: "block" })).newPage();
const rows = [];
try {
  for (const id of examples) {
    await page.goto("about:blank"); // a load of its own each (a hash change would keep the last status)
    await page.goto(`${server.url}index.html#/${id}`);
    await page.waitForFunction(() => ["ok", "error", "invalid", "message"].includes(document.body.dataset.status));
    if (!(await page.evaluate(() => document.querySelector(".figure-panel[data-moves]") !== null))) continue;
    await page.waitForSelector(".motion:not([hidden])");
    const r = await page.evaluate(async (want) => {
      const m = document.querySelector(".motion").motion;
      const frames = m.count;
      m.benchEveryFrame(true);
      m.benchTimes.length = 0;
      const intervals = [];
      let last = null;
      let recording = true;
      const watch = (t) => {
        if (!recording) return;
        if (m.playing && last !== null) intervals.push(t - last);
        last = m.playing ? t : null;
        requestAnimationFrame(watch);
      };
      requestAnimationFrame(watch);
      while (m.benchTimes.length < want) {
        m.play();
        await new Promise((resolve) => {
          const wait = () => (m.playing ? requestAnimationFrame(wait) : resolve());
          requestAnimationFrame(wait);
        });
      }
      recording = false;
      m.benchEveryFrame(false);
      return { frames, draws: [...m.benchTimes], intervals };
    }, want);
    rows.push({ id, ...r });
  }
} finally {
  await browser.close();
  await server.close();
}

console.log(`Motion, a new frame on every animation frame (${want}+ frames each; 60 fps = ${ms(FRAME)} ms):`);
console.log("| example | frames in the motion | frame time median / p95 / worst (ms) | dropped (> 25 ms) | drawing median / p95 (ms) |");
console.log("|---|---|---|---|---|");
for (const r of rows) {
  const dropped = r.intervals.filter((x) => x > 1.5 * FRAME).length;
  console.log(`| ${r.id} | ${r.frames} | ${ms(pct(r.intervals, 50))} / ${ms(pct(r.intervals, 95))} / ${ms(Math.max(...r.intervals))} | ${dropped} of ${r.intervals.length} | ${ms(pct(r.draws, 50))} / ${ms(pct(r.draws, 95))} |`);
}
