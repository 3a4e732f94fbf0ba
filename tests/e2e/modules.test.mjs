// One wasm module per topic (web/<module>/), loaded on demand:
// - catalog.json, written natively by the build (examples/catalog_json.rs:
//   examples::catalog() through serde_json), is the catalog the wasm modules
//   report through serde-wasm-bindgen: pkg/all.js's catalog() and, entry by
//   entry, every topic module's own catalog() (two serialisers, two builds of
//   the same Rust entries: not the file compared with its own generator);
// - index.html and embed.html carry catalog.json (the page fetches no
//   catalog) and each topic's files under their built names;
// - every example solves from a cold load of its own address, with the
//   numbers of the Rust solver, having fetched only its own module before
//   the first solution, once, started from the address by preload-route.js
//   (the other topics follow when the page is idle);
// - an example's practice loads its topic's practice module (pkg/<module>_practice.js) only when it opens;
// - the one-package API (pkg/photogrammetry_playground.js) and the lighter
//   pkg/examples.js both solve an example of every topic in a blank page.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import fs from "node:fs";
import path from "node:path";
import { DIST, TEST_TIMEOUT, built, exact, nodeModule, open, start, visit } from "./harness.mjs";
import { readDataBlock } from "../../scripts/site.mjs";

// the build names files by their content (scripts/site.mjs): dist/assets.json maps
// a logical name to the file (harness.mjs `built`), and `logical` turns a requested path back
// (a shared chunk has no logical name: it keeps its own)
const LOGICAL = new Map(Object.entries(JSON.parse(fs.readFileSync(path.join(DIST, "assets.json"), "utf8"))).map(([l, b]) => [`/${b}`, `/${l}`]));
const logical = (p) => LOGICAL.get(p) ?? p;
const WASM = /_bg(-\w{8})?\.wasm$/;
const CATALOG = JSON.parse(fs.readFileSync(path.join(DIST, built("catalog.json")), "utf8"));
const MODULES = [...new Set(CATALOG.map((e) => e.module))];

const all = await nodeModule("all");

/** The seed's numeric answers of example `id`: [[key, value]]. */
function seedAnswers(id) {
  const s = all.solve(id, {});
  return s.answer.filter((k) => typeof s.result[k] === "number").map((k) => [k, s.result[k]]);
}

/** One example of each module: [module, id]. */
const ONE_PER_MODULE = MODULES.map((m) => [m, CATALOG.find((e) => e.module === m && e.status === "ready").id]);

let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

describe("the catalog as data", () => {
  test("index.html and embed.html carry catalog.json itself, and each topic's files under their built names", () => {
    for (const page of ["index.html", "embed.html"]) {
      const html = fs.readFileSync(path.join(DIST, page), "utf8");
      const data = readDataBlock(html);
      assert.ok(data, `${page} has the catalog-data block`);
      // the data block precedes every script (preload-route.js reads it)
      assert.equal(html.indexOf("<script"), html.indexOf('<script type="application/json" id="catalog-data">'), `${page}: the data block comes first`);
      assert.deepEqual(data.entries, CATALOG, page);
      assert.deepEqual(Object.keys(data.files).sort(), [...MODULES].sort(), page);
      for (const name of MODULES) {
        assert.deepEqual(data.files[name].slice(0, 3), [`pkg/${name}.js`, `pkg/${name}_bg.wasm`, `figures/${name}.js`].map((f) => `./${built(f)}`), `${page} ${name}`);
        for (const f of data.files[name]) assert.ok(fs.existsSync(path.join(DIST, f)), `${page}: ${f} exists`);
      }
    }
  });

  test("catalog.json (native serde_json) is the wasm's catalog(), every entry with its module (its fields come with the module)", () => {
    assert.deepEqual(CATALOG, all.catalog().map(({ inputs: _, ...entry }) => entry));
    for (const e of CATALOG) {
      assert.equal(typeof e.module, "string", e.id);
      assert.equal(typeof e.practice, "boolean", e.id);
    }
    assert.deepEqual(MODULES, ["coordinates", "transformations", "correlation", "matching", "resampling", "filters", "interest", "chains", "projection"]);
  });

  test("each topic module's own catalog() is its entries of catalog.json", async () => {
    for (const name of MODULES) {
      const m = await nodeModule(name);
      const expected = all.catalog().filter((e) => e.module === name);
      assert.deepEqual(m.catalog(), expected, name);
      const own = m.catalog().map(({ inputs: _, ...rest }) => rest);
      assert.deepEqual(own, CATALOG.filter((e) => e.module === name), name);
      // and it solves its own examples only
      const other = CATALOG.find((e) => e.module !== name);
      assert.throws(() => m.solve(other.id, {}), new RegExp(other.id), name);
    }
  });
});

describe("a cold load of each example", () => {
  for (const entry of CATALOG.filter((e) => e.status === "ready")) {
    test(`${entry.id}: solves, fetching only pkg/${entry.module} before its first solution`, { timeout: TEST_TIMEOUT }, async () => {
      const { context, page, log } = await open(env.browser);
      try {
        assert.equal(await visit(page, env.url, "index.html", `#/${entry.id}`), "ok");
        const answers = seedAnswers(entry.id);
        for (const [key, value] of answers) {
          const shown = await exact(page, key);
          assert.ok(Math.abs(shown - value) <= 1e-9 * Math.max(1, Math.abs(value)), `${entry.id} ${key}: page ${shown}, Rust ${value}`);
        }
        assert.ok((await page.locator(".answer-line").innerText()).trim().length > 0, "the answer line is shown");
        const before = await page.evaluate(() => {
          const mark = performance.getEntriesByName("solver-ready")[0]; // the page's own first solution (app.js)
          return performance
            .getEntriesByType("resource")
            .filter((r) => r.startTime < mark.startTime)
            .map((r) => new URL(r.name).pathname);
        });
        const wasm = before.map(logical).filter((p) => p.startsWith("/pkg/"));
        assert.deepEqual(wasm.sort(), [`/pkg/${entry.module}.js`, `/pkg/${entry.module}_bg.wasm`].sort(), `${entry.id}: ${wasm.join(" ")}`);
        // the page has the catalog in its HTML (no request); preload-route.js started the
        // module's JS, wasm and figures from the address, each fetched once (the preloads are used)
        assert.ok(!before.map(logical).includes("/catalog.json"), "catalog.json is not fetched by the page");
        // (the figure modules; their stylesheet, figures.css, is added by the registry when it runs)
        const figures = before.map(logical).filter((p) => p.startsWith("/figures/") && p.endsWith(".js"));
        assert.equal(figures[0], `/figures/${entry.module}.js`, `${entry.id}: ${figures.join(" ")}`);
        const preloaded = (await page.evaluate(() => [...document.querySelectorAll('link[rel="modulepreload"], link[rel="preload"]')].map((l) => new URL(l.href).pathname))).map(logical);
        for (const f of [`/pkg/${entry.module}.js`, ...figures]) assert.ok(preloaded.includes(f), `${entry.id}: ${f} preloaded from the address`);
        for (const f of [`/pkg/${entry.module}.js`, `/pkg/${entry.module}_bg.wasm`, ...figures]) {
          assert.equal(log.requests.filter((u) => logical(new URL(u).pathname) === f).length, 1, `${entry.id}: ${f} requested once`);
        }
        // the wasm (fetched and compiled by preload-route.js) was requested before the page's own JS
        const order = before.map(logical);
        assert.ok(order.indexOf(`/pkg/${entry.module}_bg.wasm`) < order.indexOf("/app.js"), `${entry.id}: ${order.join(" ")}`);
        assert.deepEqual(log.pageErrors, []);
        assert.deepEqual(log.consoleErrors, []);
      } finally {
        await context.close();
      }
    });
  }

  test("the other topics' modules load when the page is idle; a switch then needs no fetch", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/gsd"), "ok");
      await page.waitForFunction(([n, re]) => performance.getEntriesByType("resource").filter((r) => new RegExp(re).test(r.name)).length >= n, [MODULES.length, WASM.source], { timeout: 15_000 });
      const wasm = log.requests.filter((u) => WASM.test(u)).map((u) => logical(new URL(u).pathname)).sort();
      assert.deepEqual(wasm, MODULES.map((m) => `/pkg/${m}_bg.wasm`).sort(), "every topic once, not all.js");
      const count = log.requests.length;
      await page.evaluate(() => {
        location.hash = "#/utm";
      });
      await page.waitForSelector('article.example[data-id="utm"]');
      const [[key, value]] = seedAnswers("utm").filter(([k]) => k === "easting");
      assert.ok(Math.abs((await exact(page, key)) - value) < 1e-6);
      assert.equal(log.requests.slice(count).filter((u) => logical(new URL(u).pathname).startsWith("/pkg/")).length, 0);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("before its first solution the page fetches its entry, the chunks the HTML preloads, the topic's module and figures: no other JS", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/gsd"), "ok");
      const js = await page.evaluate(() => {
        const mark = performance.getEntriesByName("solver-ready")[0]; // the page's own first solution (app.js)
        return performance
          .getEntriesByType("resource")
          .filter((r) => r.startTime < mark.startTime)
          .map((r) => new URL(r.name).pathname)
          .filter((p) => /\.js$/.test(p));
      });
      // the chunks app.js imports (if esbuild cut any) are preloaded by the HTML, and every one is used
      const html = fs.readFileSync(path.join(DIST, "index.html"), "utf8");
      const chunks = [...html.matchAll(/<link rel="modulepreload" href="\.\/([^"]+)">/g)].map((m) => `/${m[1]}`);
      for (const c of chunks) assert.ok(js.includes(c), `${c} preloaded but not used before the solution`);
      const own = js.filter((p) => !chunks.includes(p)).map(logical).sort();
      assert.deepEqual(own, ["/app.js", "/figures/coordinates.js", "/pkg/coordinates.js"], js.join(" "));
      for (const p of js) assert.match(p, /^\/assets\/[\w-]+-\w{8}\.js$/);
      // KaTeX's typesetting (math-typeset.js, a chunk of its own) works on the page's one math.js
      await page.waitForFunction(() => document.documentElement.dataset.math === "ready", null, { timeout: 15_000 });
      assert.ok((await page.locator(".steps-body .katex").count()) > 0, "formulas typeset");
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("an example's practice loads its topic's practice module when it opens, not pkg/all.js", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      await page.goto(`${env.url}index.html#/gsd?practice=1K7Q2`);
      await page.waitForFunction(() => document.body.dataset.status === "practice", null, { timeout: 15_000 });
      const pkg = log.requests.map((u) => logical(new URL(u).pathname)).filter((p) => p.startsWith("/pkg/"));
      const gsd = CATALOG.find((e) => e.id === "gsd").module;
      assert.deepEqual(pkg.sort(), [`/pkg/${gsd}_practice.js`, `/pkg/${gsd}_practice_bg.wasm`]);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });
});

describe("the public JS API in a blank page", () => {
  async function blankPage() {
    const opened = await open(env.browser);
    await opened.page.goto(`${env.url}version.json`);
    await opened.page.setContent("<!doctype html><title>A course page</title><p>blank</p>");
    return opened;
  }

  test("the one-package form: init(), then solve/parse_inputs/catalog/practice/grade synchronously", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await blankPage();
    try {
      const got = await page.evaluate(async (ids) => {
        const m = await import("/pkg/photogrammetry_playground.js");
        await m.default();
        const out = {};
        for (const id of ids) out[id] = m.solve(id, m.parse_inputs(id, {}).inputs).result;
        const p = m.practice("gsd", "1K7Q2");
        return { out, n: m.catalog().length, code: p.code, score: typeof m.grade("gsd", p.code, {}).out_of };
      }, ONE_PER_MODULE.map(([, id]) => id));
      assert.equal(got.n, CATALOG.length);
      assert.equal(got.code, "1K7Q2");
      assert.equal(got.score, "number");
      for (const [, id] of ONE_PER_MODULE) {
        for (const [key, value] of seedAnswers(id)) assert.equal(got.out[id][key], value, `${id} ${key}`);
      }
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("the lighter form: loadExample(id) fetches only that example's module", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await blankPage();
    try {
      for (const [name, id] of ONE_PER_MODULE) {
        const count = log.requests.length;
        const result = await page.evaluate(async (i) => {
          const { loadExample } = await import("/pkg/examples.js");
          const ex = await loadExample(i);
          return ex.solve(ex.parseInputs({}).inputs).result;
        }, id);
        for (const [key, value] of seedAnswers(id)) assert.equal(result[key], value, `${id} ${key}`);
        const wasm = log.requests.slice(count).filter((u) => WASM.test(u)).map((u) => logical(new URL(u).pathname));
        assert.deepEqual(wasm, [`/pkg/${name}_bg.wasm`], id);
      }
      const r = await page.evaluate(async () => {
        const { solve } = await import("/pkg/examples.js");
        return (await solve("gsd", { dpi: 1200 })).result.gsd_cm;
      });
      assert.ok(Math.abs(r - (((25.4 / 1200) * 1920000) / 152) / 10) < 1e-9);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });
});
