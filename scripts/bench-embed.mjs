// Measures the embed as a course page meets it (a benchmark, not a test):
//  - the bytes embed.js adds to the host page, gzipped;
//  - the time from the iframe entering the viewport (an IntersectionObserver
//    on the host page) to the example solved on screen (the embed's `ready`
//    event at the host), cold (new browser context) and warm (the same
//    context again: HTTP cache and the service worker's copy);
//  - and to the first numbers in the frame (the frame rendered after its
//    `first-solution` mark, scripts/rendered-marks.mjs: the answer the build
//    saved, scripts/prerender.mjs, where it is shown), both on one clock
//    (each document's timeOrigin + its own time).
//   node scripts/bench-embed.mjs [--runs 5] [--example gsd]
import { launchChromium } from "./chromium.mjs";
import { recordRendered } from "./rendered-marks.mjs";
import fs from "node:fs";
import http from "node:http";
import zlib from "node:zlib";
import { startServer } from "./serve.mjs";

const args = process.argv.slice(2);
const arg = (name, dflt) => {
  const i = args.indexOf(name);
  return i >= 0 ? args[i + 1] : dflt;
};
const runs = Number(arg("--runs", 5));
// the catalog's first example unless one is named
const catalogFile = JSON.parse(fs.readFileSync("dist/assets.json", "utf8"))["catalog.json"] ?? "catalog.json";
const example = arg("--example", JSON.parse(fs.readFileSync(`dist/${catalogFile}`, "utf8"))[0].id);

const js = fs.readFileSync("dist/embed.js");
console.log(`embed.js: ${js.length} bytes, ${zlib.gzipSync(js, { level: 9 }).length} bytes gzipped (aim: under 3 KB)`);

const server = await startServer({ dir: "dist", port: 0 });
// the host page on another origin: the embed far below the fold, so lazy loading waits for the scroll
const hostPage = `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Course page</title></head><body>
<div style="height:6000px">Scroll down</div>
<script src="${server.url}embed.js" defer></script>
<div id="e" data-playground="${example}" data-id="e"></div>
<script>
  window.times = {};
  const start = () => {
    const frame = document.querySelector("#e iframe");
    if (!frame) return setTimeout(start, 10);
    new IntersectionObserver((es) => { if (es.some((e) => e.isIntersecting) && !times.enter) times.enter = performance.now(); }).observe(frame);
  };
  start();
  document.getElementById("e").addEventListener("playground:ready", () => (times.ready = performance.now()));
</script></body></html>`;
const host = http.createServer((req, res) => res.writeHead(200, { "content-type": "text/html; charset=utf-8" }).end(hostPage));
await new Promise((r) => host.listen(0, "127.0.0.1", r));
const hostUrl = `http://127.0.0.1:${host.address().port}/`;
const browser = await launchChromium();

async function once(page) {
  await page.goto(hostUrl);
  await page.waitForSelector("#e iframe", { state: "attached" });
  await page.waitForTimeout(300); // settled above the fold; the embed not loaded yet
  await page.evaluate(() => document.getElementById("e").scrollIntoView());
  await page.waitForFunction(() => window.times.ready > 0, null, { timeout: 20000 });
  const hostTimes = await page.evaluate(() => ({ origin: performance.timeOrigin, ...window.times }));
  const frame = await (await page.$("#e iframe")).contentFrame();
  // the frame in which the first numbers were rendered (scripts/rendered-marks.mjs), on the host's clock
  await frame.waitForFunction(() => window.__benchRendered?.["first-solution"] != null, null, { timeout: 20000 });
  const first = await frame.evaluate(() => performance.timeOrigin + window.__benchRendered["first-solution"]);
  const enter = hostTimes.origin + hostTimes.enter;
  return { ready: hostTimes.ready - hostTimes.enter, first: first - enter };
}

const cold = [];
const warm = [];
try {
  for (let i = 0; i < runs; i++) {
    const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
    await context.addInitScript(recordRendered, ["first-solution"]);
    const page = await context.newPage();
    cold.push(await once(page));
    // let the service worker finish its copy, then come back
    const frame = await (await page.$("#e iframe")).contentFrame();
    await frame.evaluate(() => navigator.serviceWorker?.ready);
    warm.push(await once(page));
    await context.close();
  }
} finally {
  await browser.close();
  await server.close();
  host.close();
}
const stat = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  return `median ${s[Math.floor(s.length / 2)].toFixed(0)} ms, min ${s[0].toFixed(0)} ms, max ${s[s.length - 1].toFixed(0)} ms`;
};
console.log(`iframe in the viewport → ${example}'s first numbers in the frame (the saved answer where shown; ${runs} runs):`);
console.log(`  cold (new context):          ${stat(cold.map((t) => t.first))}`);
console.log(`  second visit (cached + SW):  ${stat(warm.map((t) => t.first))}`);
console.log(`iframe in the viewport → ${example} solved on screen (the embed's ready event; ${runs} runs):`);
console.log(`  cold (new context):          ${stat(cold.map((t) => t.ready))}`);
console.log(`  second visit (cached + SW):  ${stat(warm.map((t) => t.ready))}`);
