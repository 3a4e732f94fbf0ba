// Shared set-up of the end-to-end tests: the built page (dist/, from
// `npm run build`) served on 127.0.0.1, and headless Chromium.
// Not a test file itself (node --test runs only *.test.mjs here).

import assert from "node:assert/strict";
import fs from "node:fs";
import path from "node:path";
import { pathToFileURL } from "node:url";
import { launchChromium } from "../../scripts/chromium.mjs";
import { startServer } from "../../scripts/serve.mjs";

/** The built site; E2E_DIST points elsewhere (e.g. a hand-assembled copy). */
export const DIST = process.env.E2E_DIST || "dist";
export { launchChromium };
/** Statuses the page sets on <body data-status> once it has settled. */
const SETTLED = ["ok", "invalid", "error", "home", "message", "fatal"];
export const TEST_TIMEOUT = 60_000;
const WAIT = 15_000;

/** A built file's name (content-hashed: dist/assets.json) from its logical name ("pkg/all.js"). */
export function built(file) {
  assets ??= JSON.parse(fs.readFileSync(path.join(DIST, "assets.json"), "utf8"));
  return assets[file] ?? file;
}
let assets = null;

/** A wasm module of dist/pkg ("all", "coordinates" …) or another folder ("lab/pkg"), initialised in Node: its exports. */
export async function nodeModule(name, dir = "pkg") {
  const m = await import(pathToFileURL(path.resolve(DIST, built(`${dir}/${name}.js`))).href);
  m.initSync({ module: fs.readFileSync(path.resolve(DIST, built(`${dir}/${name}_bg.wasm`))) });
  return m;
}

/** Starts the server and the browser; `close()` stops both. */
export async function start() {
  assert.ok(
    fs.existsSync(path.join(DIST, "index.html")) && fs.existsSync(path.join(DIST, "pkg")),
    `${DIST}/ is not built: run "npm run build" first`,
  );
  const server = await startServer({ dir: DIST, port: 0 });
  let browser;
  try {
    browser = await launchChromium();
  } catch (e) {
    await server.close();
    throw e;
  }
  return {
    url: server.url,
    browser,
    async close() {
      await browser.close().catch(() => {});
      await server.close();
    },
  };
}

/**
 * A fresh context and page that record every request, page error, console
 * error and dialog.
 */
export async function open(browser, options = {}) {
  // service workers blocked unless a test asks for them (`serviceWorkers: "allow"`):
  // no precache traffic in the request logs, no copy of an earlier build
  const context = await browser.newContext({ viewport: { width: 1280, height: 900 }, serviceWorkers: "block", ...options });
  // the page's test-only hooks (www/test-hooks.js) on, for every page of this context
  await context.addInitScript(() => {
    globalThis.__playgroundTest = true;
  });
  const page = await context.newPage();
  // (open: the requests not yet finished, for pageState's failure messages)
  const log = { requests: [], pageErrors: [], consoleErrors: [], dialogs: [], open: new Set() };
  context.on("request", (r) => {
    log.requests.push(r.url());
    log.open.add(r);
  });
  context.on("requestfinished", (r) => log.open.delete(r));
  context.on("requestfailed", (r) => log.open.delete(r));
  page.on("pageerror", (e) => log.pageErrors.push(e.message));
  page.on("console", (m) => {
    if (m.type() === "error") log.consoleErrors.push(m.text());
  });
  page.on("dialog", (d) => {
    log.dialogs.push(d.message());
    d.dismiss().catch(() => {});
  });
  return { context, page, log };
}

/** Waits until the page has settled after a load or an edit. */
export async function settled(page) {
  // the status (an input change says "updating" until its steps, result and notes are in: app.js
  // inputChanged), no panel busy, and the formulas typeset once KaTeX has arrived (math.js: <html data-math>)
  await page.waitForFunction(
    (states) => states.includes(document.body.dataset.status) && !document.querySelector(".panel[aria-busy]") && document.documentElement.dataset.math !== "loading",
    SETTLED,
    { timeout: WAIT },
  );
  return page.evaluate(() => document.body.dataset.status);
}

/**
 * What the page is doing, for a failure message: its status, busy panels,
 * formulas, fonts, visibility and the requests still open (`log` from open()).
 * Bounded: a page whose main thread does not answer within 5 s says so.
 */
export async function pageState(page, log = null) {
  const state = page
    .evaluate(() => ({
      status: document.body.dataset.status,
      busy: document.querySelectorAll(".panel[aria-busy]").length,
      math: document.documentElement.dataset.math ?? null,
      fonts: document.fonts.status,
      visibility: document.visibilityState,
      hash: location.hash.slice(0, 120),
    }))
    .catch((e) => ({ evaluate: e.message.split("\n")[0] }));
  const timer = new Promise((r) => setTimeout(() => r({ evaluate: "no answer within 5 s (main thread busy or hung)" }), 5000).unref());
  const s = await Promise.race([state, timer]);
  if (log?.open) s.openRequests = [...log.open].slice(0, 5).map((r) => r.url().slice(-60));
  return JSON.stringify(s);
}

/**
 * `promise` (a step of a test on `page`), or an error after `ms` that names
 * the step and the page's state (pageState): a wait that hangs says where,
 * instead of the test's timeout saying only that it ran out.
 */
export async function within(page, ms, what, promise, log = null) {
  let timer;
  const late = new Promise((_, reject) => {
    timer = setTimeout(() => {
      pageState(page, log).then((s) => reject(new Error(`${what}: not done after ${ms} ms; the page: ${s}`)));
    }, ms);
  });
  try {
    return await Promise.race([promise, late]);
  } finally {
    clearTimeout(timer);
  }
}

/**
 * Scrolls to every step as a reader going down the page would, twice (the second
 * time with the fonts the first asked for), and back to the top. A step off
 * screen is not rendered (content-visibility: auto): its formulas are fitted,
 * and its layout and innerText are there, once it has been.
 */
export async function readSteps(page) {
  for (let pass = 0; pass < 2; pass++) {
    const asked = await page.evaluate(async () => {
      const frame = () => new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0)));
      // a font the steps asked for while read: the second pass reads them with it
      let loading = document.fonts.status === "loading";
      const mark = () => (loading = true);
      document.fonts.addEventListener("loading", mark);
      for (const step of document.querySelectorAll(".steps-body .step")) {
        step.scrollIntoView({ block: "start" });
        // the step rendered (a frame), its formulas fitted (the next)
        await frame();
        await frame();
      }
      window.scrollTo(0, 0);
      await document.fonts.ready;
      await frame();
      document.fonts.removeEventListener("loading", mark);
      return loading;
    });
    // no font asked for (all there from an earlier view of the same document): a second pass would read the same
    if (!asked) break;
  }
}

/**
 * The steps' markup once the page has settled with "ok" (an input change's steps
 * in), the network is idle, the fonts are in and the formulas fitted (a frame),
 * every step read (readSteps).
 */
export async function stepsHtml(page) {
  const status = await settled(page);
  if (status !== "ok") throw new Error(`stepsHtml: the page says "${status}", not "ok"`);
  await page.waitForLoadState("networkidle");
  await readSteps(page);
  return page.evaluate(() => document.querySelector(".steps-body").innerHTML);
}

/**
 * Waits until nothing more can happen on its own: no request in flight (the
 * network idle), the fonts in, and a frame drawn after them (what a late
 * script, image error handler, font or layout change would have shown is
 * there by then). For "nothing happened" checks, instead of a fixed sleep.
 */
export async function quiet(page) {
  await page.waitForLoadState("networkidle");
  await page.evaluate(() => document.fonts.ready.then(() => new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0)))));
}

/** Loads `file#hash` and waits for the page to settle. */
export async function visit(page, base, file, hash = "") {
  await page.goto(`${base}${file}${hash}`);
  return settled(page);
}

/** The full-precision exact value of a result row (its data-value). */
export async function exact(page, key) {
  const cell = page.locator(`.result-table tr[data-key="${key}"] td.exact`);
  return Number(await cell.getAttribute("data-value", { timeout: WAIT }));
}

/** The text of a result cell ("exact", "printed", "diff"). */
export async function cellText(page, key, column) {
  return (await page.locator(`.result-table tr[data-key="${key}"] td.${column}`).innerText({ timeout: WAIT })).trim();
}

/** A number as the page writes it (format.js formatNumber: a real minus sign, maybe a "+", "1.8777 × 10⁻⁶"). */
export function parseShown(text) {
  const power = (sup) => [...sup].map((c) => "-0123456789"["⁻⁰¹²³⁴⁵⁶⁷⁸⁹".indexOf(c)]).join("");
  return Number(
    text
      .replace(/\u2212/g, "-")
      .replace(/ × 10([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)/, (_, sup) => `e${power(sup)}`)
      .replace(/^\+/, "")
      .trim(),
  );
}

/** Waits until a result's exact value is within `tol` of `expected`. */
export async function waitForExact(page, key, expected, tol = 1e-3) {
  await page.waitForFunction(
    ([k, e, t]) => {
      const cell = document.querySelector(`.result-table tr[data-key="${k}"] td.exact`);
      return cell && Math.abs(Number(cell.dataset.value) - e) <= t;
    },
    [key, expected, tol],
    { timeout: WAIT },
  );
}

/**
 * The built catalog (dist's catalog.json, by its hashed name in assets.json):
 * every example's entry, in catalog order (topics in page order). [] when
 * the site is not built (start() says so).
 */
export function builtCatalog() {
  for (const name of [() => built("catalog.json"), () => "catalog.json"]) {
    try {
      const data = JSON.parse(fs.readFileSync(path.join(DIST, name()), "utf8"));
      const entries = Array.isArray(data) ? data : data.entries;
      if (Array.isArray(entries)) return entries;
    } catch {
      // not built, or by another name: the next way
    }
  }
  return [];
}

/** The ids of every example, from the built catalog (the core's descriptors: no list kept here). */
export const CATALOG_IDS = Object.freeze(builtCatalog().map((e) => e.id));

/** The ids in ../shared/CATALOG.md (first column of its tables), or null when absent. */
export function catalogMdIds() {
  const file = path.resolve("..", "shared", "CATALOG.md");
  if (!fs.existsSync(file)) return null;
  const ids = [];
  for (const line of fs.readFileSync(file, "utf8").split("\n")) {
    const m = /^\|\s*`([a-z0-9-]+)`\s*\|/.exec(line);
    if (m) ids.push(m[1]);
  }
  return ids;
}

/** A second server, on another port (another origin), for host pages: path → HTML. */
export async function startHost(pages) {
  const http = await import("node:http");
  const server = http.createServer((req, res) => {
    const url = new URL(req.url, "http://x");
    const body = Object.hasOwn(pages, url.pathname) ? pages[url.pathname] : null;
    if (body === null) {
      res.writeHead(404, { "content-type": "text/plain" }).end("not found");
      return;
    }
    res.writeHead(200, { "content-type": "text/html; charset=utf-8", "cache-control": "no-store" }).end(body);
  });
  await new Promise((resolve) => server.listen(0, "127.0.0.1", resolve));
  return {
    url: `http://127.0.0.1:${server.address().port}/`,
    close: () => new Promise((r) => server.close(() => r())),
  };
}
