// The seed's solution saved by the build (scripts/prerender.mjs) and shown
// by preload-route.js before the page's JS and wasm have run (issue 19):
// - dist/prerender/<id>.html for every ready example, listed in index.html's
//   catalog-data (not embed.html's), with no script, no build-server address;
// - a cold load of a bare #/<id> shows it, inert, marked `first-solution`,
//   while the solver loads (its wasm held back here): the example's heading
//   and its answer line, reading exactly as the page's own view of the seed
//   does once the solver is in — the saved file is not a second renderer's
//   output but this page's;
// - the page's own view then replaces it, its inputs live (`solver-ready`);
// - a what-if address, embed.html, a move to another example before the
//   solver is in, and a solver that fails to load each end or skip it.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import fs from "node:fs";
import path from "node:path";
import { DIST, TEST_TIMEOUT, open, settled, start } from "./harness.mjs";

const ASSETS = JSON.parse(fs.readFileSync(path.join(DIST, "assets.json"), "utf8"));
const CATALOG = JSON.parse(fs.readFileSync(path.join(DIST, ASSETS["catalog.json"] ?? "catalog.json"), "utf8"));
const READY = CATALOG.filter((e) => e.status === "ready").map((e) => e.id);
const DATA = /<script type="application\/json" id="catalog-data">([\s\S]*?)<\/script>/;
const dataOf = (page) => JSON.parse(DATA.exec(fs.readFileSync(path.join(DIST, page), "utf8"))[1]);
const WASM = /_bg\.[0-9a-f]{8}\.wasm$/;
const PARTS = [".crumbs", ".example-head", ".answer-line"];

let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

/**
 * Opens `hash` with every wasm request held until `release()` (KaTeX kept
 * out). Returns the page, its log and release.
 */
async function held(hash, file = "index.html") {
  const { context, page, log } = await open(env.browser);
  const waiting = [];
  let released = false;
  await page.route(/\/vendor\/katex\//, (route) => route.abort());
  await page.route(WASM, (route) => (released ? route.continue() : waiting.push(route)));
  const release = async () => {
    released = true;
    for (const r of waiting.splice(0)) await r.continue();
  };
  await page.goto(`${env.url}${file}${hash}`);
  return { context, page, log, release };
}

/** The text of each saved part shown in #app (innerText: what a reader sees) and the answer line's markup. */
function partsText(page) {
  return page.evaluate((parts) => {
    const out = Object.fromEntries(parts.map((sel) => [sel, document.querySelector(`#app ${sel}`)?.innerText ?? null]));
    out.answerHtml = document.querySelector("#app .answer-line")?.innerHTML ?? null;
    return out;
  }, PARTS);
}

describe("the saved solutions in dist/", () => {
  test("one per ready example, listed in index.html's catalog-data only, no script, no build-server address", () => {
    const listed = dataOf("index.html").prerendered;
    assert.deepEqual([...listed].sort(), [...READY].sort());
    assert.equal(dataOf("embed.html").prerendered, undefined, "the embed has its own view options: no saved solution");
    for (const id of READY) {
      const file = path.join(DIST, "prerender", `${id}.html`);
      const html = fs.readFileSync(file, "utf8");
      assert.match(html, new RegExp(`^<article class="example" data-id="${id}">`), id);
      assert.doesNotMatch(html, /<script|\son\w+=|127\.0\.0\.1|localhost/i, id);
      assert.match(html, /class="answer-line"/, id);
      assert.ok(fs.existsSync(`${file}.gz`) && fs.existsSync(`${file}.br`), `${id}: .gz and .br`);
    }
    // cached by the offline copy when first used, not at install (sw-manifest.mjs)
    const sw = fs.readFileSync(path.join(DIST, "sw.js"), "utf8");
    const build = JSON.parse(/const BUILD = (\{.*\});/.exec(sw)[1]);
    assert.ok(build.lazy.includes("prerender/gsd.html"));
    assert.ok(!build.files.some((f) => f.startsWith("prerender/")));
  });
});

describe("a cold load of a bare #/<id>", () => {
  for (const id of READY) {
    test(`${id}: the saved solution is shown, inert, while the solver loads, and reads as the page's own view`, { timeout: TEST_TIMEOUT }, async () => {
      const { context, page, log, release } = await held(`#/${id}`);
      try {
        await page.waitForSelector(`#app[data-prerendered="${id}"] article.example[data-id="${id}"]`);
        const early = await page.evaluate(() => ({
          inert: document.getElementById("app").inert,
          marks: ["first-solution", "solver-ready"].map((n) => performance.getEntriesByName(n).length),
          status: document.body.dataset.status,
        }));
        assert.deepEqual(early, { inert: true, marks: [1, 0], status: "loading" });
        const saved = await partsText(page);
        assert.ok(saved[".answer-line"].trim().length > 0, `${id}: the answer line`);
        // the rest comes with the solver
        assert.equal(await page.locator("#app .layout").count(), 0);
        assert.equal(await page.locator("#app p.loading").innerText(), "Loading the solver…");
        await release();
        assert.equal(await settled(page), "ok");
        const own = await partsText(page);
        assert.deepEqual(own, saved, `${id}: the saved solution and the page's own view of the seed differ`);
        const after = await page.evaluate(() => ({
          prerendered: document.getElementById("app").hasAttribute("data-prerendered"),
          inert: document.getElementById("app").inert,
          marks: ["first-solution", "solver-ready"].map((n) => performance.getEntriesByName(n).length),
        }));
        assert.deepEqual(after, { prerendered: false, inert: false, marks: [1, 1] });
        assert.equal(log.requests.filter((u) => u.endsWith(`/prerender/${id}.html`)).length, 1);
        assert.deepEqual(log.pageErrors, []);
      } finally {
        await context.close();
      }
    });
  }

  test("it takes no click until the page's own view is in (inert); then the inputs are live", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, release } = await held("#/gsd");
    try {
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
    } finally {
      await context.close();
    }
  });
});

describe("where no saved solution is shown", () => {
  test("a what-if address, and embed.html, do not fetch one", { timeout: TEST_TIMEOUT }, async () => {
    for (const [file, hash] of [
      ["index.html", "#/gsd?flying_height_m=2400"],
      ["embed.html", "#/gsd"],
      ["index.html", "#/"],
    ]) {
      const { context, page, log } = await open(env.browser);
      try {
        await page.goto(`${env.url}${file}${hash}`);
        assert.ok(["ok", "home"].includes(await settled(page)), `${file}${hash}`);
        assert.deepEqual(log.requests.filter((u) => u.includes("/prerender/")), [], `${file}${hash}`);
        assert.equal(await page.evaluate(() => document.getElementById("app")?.inert ?? false), false);
      } finally {
        await context.close();
      }
    }
  });

  test("a move to another example before the solver is in replaces it with that example, live", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, release } = await held("#/gsd");
    try {
      await page.waitForSelector('#app[data-prerendered="gsd"]');
      await page.evaluate(() => {
        location.hash = "#/utm";
      });
      await release();
      assert.equal(await settled(page), "ok");
      await page.waitForSelector('article.example[data-id="utm"]');
      assert.deepEqual(await page.evaluate(() => [document.getElementById("app").inert, document.getElementById("app").hasAttribute("data-prerendered"), document.querySelectorAll("article.example").length]), [false, false, 1]);
    } finally {
      await context.close();
    }
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
      assert.deepEqual(await page.evaluate(() => [document.getElementById("app").inert, document.getElementById("app").hasAttribute("data-prerendered"), Boolean(document.querySelector("article.example"))]), [false, false, false]);
      await page.getByRole("link", { name: "← All examples" }).click();
      assert.equal(await settled(page), "home");
    } finally {
      await context.close();
    }
  });
});
