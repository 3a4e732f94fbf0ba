// The top of the seed's solution saved by the build (scripts/prerender.mjs)
// and shown by preload-route.js before the page's JS and wasm have run
// (issue 19):
// - dist/prerender/<id>.html (index.html) and dist/prerender/embed/<id>.html
//   (embed.html) for every ready example, listed in each page's
//   catalog-data, with no script, no build-server address;
// - a cold load of #/<id> with no inputs (view options only) shows it,
//   inert, marked `first-solution`,
//   while the solver loads (its wasm held back here): the example's heading
//   and its answer line, reading exactly as the page's own view of the seed
//   does once the solver is in — the saved file is not a second renderer's
//   output but this page's;
// - the page's own view then replaces it, its inputs live (`solver-ready`);
// - an address with inputs, practice and home skip it; a move to another
//   example before the solver is in, and a solver that fails to load, end it.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import fs from "node:fs";
import path from "node:path";
import { DIST, TEST_TIMEOUT, open, settled, start } from "./harness.mjs";
import { OPTION_KEYS } from "../../www/embed-options.js";
import { readDataBlock } from "../../scripts/site.mjs";

const ASSETS = JSON.parse(fs.readFileSync(path.join(DIST, "assets.json"), "utf8"));
const CATALOG = JSON.parse(fs.readFileSync(path.join(DIST, ASSETS["catalog.json"] ?? "catalog.json"), "utf8"));
const READY = CATALOG.filter((e) => e.status === "ready").map((e) => e.id);
const dataOf = (page) => readDataBlock(fs.readFileSync(path.join(DIST, page), "utf8"));
const WASM = /_bg-\w{8}\.wasm$/;
const PARTS = [".crumbs", ".example-head", ".answer-line"];

let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

/**
 * Opens `file` + `hash` with every wasm request held until `release()`
 * (KaTeX kept out) and runs `fn({ page, log, release })`; the context is
 * closed afterwards, whatever `fn` does.
 */
async function held(hash, file, fn) {
  const { context, page, log } = await open(env.browser);
  try {
    const waiting = [];
    let released = false;
    await page.route(/\/vendor\/katex\//, (route) => route.abort());
    await page.route(WASM, (route) => (released ? route.continue() : waiting.push(route)));
    const release = async () => {
      released = true;
      for (const r of waiting.splice(0)) await r.continue();
    };
    await page.goto(`${env.url}${file}${hash}`);
    return await fn({ page, log, release });
  } finally {
    await context.close();
  }
}

/** <main id="app">'s state: saved part or not, inert or not, the two marks (how many), the examples in it, the status. */
function appState(page) {
  return page.evaluate(() => {
    const app = document.getElementById("app");
    return {
      prerendered: app.getAttribute("data-prerendered"),
      inert: app.inert,
      marks: ["first-solution", "solver-ready"].map((n) => performance.getEntriesByName(n).length),
      examples: [...app.querySelectorAll("article.example")].map((a) => a.dataset.id),
      status: document.body.dataset.status,
    };
  });
}

/** The text of each saved part shown in #app (innerText: what a reader sees) and the answer line's markup. */
function partsText(page) {
  return page.evaluate((parts) => {
    const out = Object.fromEntries(parts.map((sel) => [sel, document.querySelector(`#app ${sel}`)?.innerText ?? null]));
    out.answerHtml = document.querySelector("#app .answer-line")?.innerHTML ?? null;
    return out;
  }, PARTS);
}

/** Each page, where its saved parts are, and an address with view options only. */
const PAGES = [
  { file: "index.html", folder: "./prerender/", options: "", heading: "h2" },
  { file: "embed.html", folder: "./prerender/embed/", options: "?id=e1&theme=dark&steps=collapsed", heading: "h1" },
];

describe("the saved solutions in dist/", () => {
  test("one per ready example and page, listed in the page's catalog-data, no script, no build-server address", () => {
    for (const p of PAGES) {
      const saved = dataOf(p.file).prerendered;
      assert.equal(saved.folder, p.folder);
      assert.deepEqual([...saved.ids].sort(), [...READY].sort(), p.file);
      assert.deepEqual(saved.options, [...OPTION_KEYS], `${p.file}: the view options of www/embed-options.js`);
      for (const id of READY) {
        const file = path.join(DIST, p.folder, `${id}.html`);
        const html = fs.readFileSync(file, "utf8");
        assert.match(html, new RegExp(`^<article class="example" data-id="${id}">`), id);
        assert.match(html, new RegExp(`<${p.heading} id="example-title"`), `${p.file} ${id}: the page's own heading`);
        assert.equal(html.includes('class="crumbs"'), p.file === "index.html", `${p.file} ${id}: crumbs on the full page only`);
        assert.doesNotMatch(html, /<script|\son\w+=|127\.0\.0\.1|localhost/i, id);
        assert.match(html, /class="answer-line"/, id);
        assert.ok(fs.existsSync(`${file}.gz`) && fs.existsSync(`${file}.br`), `${id}: .gz and .br`);
      }
    }
    // cached by the offline copy when first used, not at install (sw-manifest.mjs)
    const sw = fs.readFileSync(path.join(DIST, "sw.js"), "utf8");
    const build = JSON.parse(/const BUILD = (\{.*\});/.exec(sw)[1]);
    assert.ok(build.lazy.includes("prerender/gsd.html") && build.lazy.includes("prerender/embed/gsd.html"));
    assert.ok(!build.files.some((f) => f.startsWith("prerender/")));
  });
});

describe("a cold load of #/<id> with no inputs", () => {
  for (const p of PAGES) {
    for (const id of READY) {
      test(`${p.file}#/${id}${p.options}: the saved part is shown, inert, while the solver loads, and reads as the page's own view`, { timeout: TEST_TIMEOUT }, async () => {
        await held(`#/${id}${p.options}`, p.file, async ({ page, log, release }) => {
          await page.waitForSelector(`#app[data-prerendered="${id}"] article.example[data-id="${id}"]`);
          assert.deepEqual(await appState(page), { prerendered: id, inert: true, marks: [1, 0], examples: [id], status: "loading" });
          const saved = await partsText(page);
          assert.ok(saved[".answer-line"].trim().length > 0, `${id}: the answer line`);
          // the rest comes with the solver
          assert.equal(await page.locator("#app .layout").count(), 0);
          assert.equal(await page.locator("#app p.loading").innerText(), "Loading the solver…");
          await release();
          assert.equal(await settled(page), "ok");
          const own = await partsText(page);
          assert.deepEqual(own, saved, `${id}: the saved part and the page's own view of the seed differ`);
          assert.deepEqual(await appState(page), { prerendered: null, inert: false, marks: [1, 1], examples: [id], status: "ok" });
          assert.equal(log.requests.filter((u) => u.endsWith(`${p.folder.slice(1)}${id}.html`)).length, 1);
          assert.deepEqual(log.pageErrors, []);
        });
      });
    }
  }

  test("it takes no click until the page's own view is in (inert); then the inputs are live", { timeout: TEST_TIMEOUT }, async () => {
    await held("#/gsd", "index.html", async ({ page, release }) => {
      await page.waitForSelector('#app[data-prerendered="gsd"]');
      // "← Catalog" in the saved part: a click does not follow it
      const link = await page.locator("#app .crumbs a").boundingBox();
      await page.mouse.click(link.x + 5, link.y + 5);
      assert.equal(await page.evaluate(() => location.hash), "#/gsd");
      await release();
      assert.equal(await settled(page), "ok");
      const input = '#app .field[data-key="flying_height_m"] input';
      assert.equal(await page.locator(input).inputValue(), "1920");
      await page.locator(input).fill("2400");
      await page.waitForFunction(() => /44\.56/.test(document.querySelector(".answer-line").innerText));
      await page.locator("#app .crumbs a").click();
      assert.equal(await settled(page), "home");
    });
  });
});

describe("where no saved solution is shown", () => {
  test("an address with inputs, practice and home do not fetch one", { timeout: TEST_TIMEOUT }, async () => {
    for (const [file, hash] of [
      ["index.html", "#/gsd?flying_height_m=2400"],
      ["embed.html", "#/gsd?id=e1&flying_height_m=2400"],
      ["index.html", "#/gsd?practice"],
      ["index.html", "#/"],
    ]) {
      const { context, page, log } = await open(env.browser);
      try {
        await page.goto(`${env.url}${file}${hash}`);
        await page.waitForFunction(() => ["ok", "home", "practice"].includes(document.body.dataset.status), null, { timeout: 15_000 });
        // (the catalog's pictures of the figures, prerender/thumbs/, are not saved solutions)
        assert.deepEqual(log.requests.filter((u) => u.includes("/prerender/") && !u.includes("/prerender/thumbs/")), [], `${file}${hash}`);
        const state = await appState(page);
        assert.deepEqual([state.prerendered, state.inert], [null, false], `${file}${hash}`);
      } finally {
        await context.close();
      }
    }
  });

  test("a move to another example before the solver is in replaces it with that example, live", { timeout: TEST_TIMEOUT }, async () => {
    await held("#/gsd", "index.html", async ({ page, release }) => {
      await page.waitForSelector('#app[data-prerendered="gsd"]');
      await page.evaluate(() => {
        location.hash = "#/utm";
      });
      await release();
      assert.equal(await settled(page), "ok");
      await page.waitForSelector('article.example[data-id="utm"]');
      assert.deepEqual(await appState(page), { prerendered: null, inert: false, marks: [1, 1], examples: ["utm"], status: "ok" });
    });
  });

  test("a solver that cannot load replaces it with the page's message, which takes clicks", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page } = await open(env.browser);
    try {
      // held until the saved solution is shown, then refused (and so is the page's second try)
      const waiting = [];
      let refuse = false;
      await page.route(WASM, (route) => (refuse ? route.abort() : waiting.push(route)));
      await page.goto(`${env.url}index.html#/gsd`);
      await page.waitForSelector('#app[data-prerendered="gsd"]');
      refuse = true;
      for (const r of waiting.splice(0)) await r.abort();
      assert.equal(await settled(page), "message");
      assert.deepEqual(await appState(page), { prerendered: null, inert: false, marks: [1, 0], examples: [], status: "message" });
      await page.getByRole("link", { name: "← All examples" }).click();
      assert.equal(await settled(page), "home");
    } finally {
      await context.close();
    }
  });
});
