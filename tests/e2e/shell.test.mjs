// The site's shell and home (issue 29): the catalog a student starts from
// (pictures of the figures, a search, "Start here" in course order, practice
// and the lab at the top, compact on a phone), the Theme switch, the skip
// link, and where an example's figure sits on a phone.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import fs from "node:fs";
import path from "node:path";
import { DIST, TEST_TIMEOUT, open, settled, start, visit } from "./harness.mjs";
import { readDataBlock } from "../../scripts/site.mjs";

const PHONE = { viewport: { width: 390, height: 844 }, deviceScaleFactor: 2, isMobile: true, hasTouch: true };
/**
 * The home view's height at 390 px stays under this: it was 4,613 CSS px (about 9,200 device
 * pixels at 2×: 26 text links with their summaries, practice at the very end); 3,068 px now.
 */
const PHONE_HOME_MAX = 3300;
/** On a 390 px phone the figure starts at most this far below the inputs' end (it came after every step). */
const FIGURE_GAP_MAX = 40;
const THEME_KEY = "photogrammetry-playground:theme";

const data = readDataBlock(fs.readFileSync(path.join(DIST, "index.html"), "utf8"));
const READY = data.entries.filter((e) => e.status === "ready").map((e) => e.id);

let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

/** The ids of the catalog's cards a reader sees. */
function shownIds(page) {
  return page.evaluate(() => [...document.querySelectorAll("nav.catalog .catalog-item")].filter((li) => li.checkVisibility()).map((li) => li.dataset.id));
}

describe("the catalog", () => {
  test("the search filters by title, topic, example number and names (GSD, Förstner), and the address keeps it", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html"), "home");
      assert.deepEqual((await shownIds(page)).sort(), [...READY].sort(), "every example before a search");
      const search = page.getByLabel("Find an example");
      const cases = [
        ["GSD", ["gsd"]],
        ["Förstner", ["forstner-image", "forstner-window"]],
        ["forstner", ["forstner-image", "forstner-window"]],
        ["6", ["ncc-2d"]],
        ["Example 4", ["fiducial-affine", "fiducial-similarity"]],
        ["map projection", ["utm", "utm-facts", "utm-inverse"]],
        ["sobel", ["edge-window"]],
      ];
      for (const [query, ids] of cases) {
        await search.fill(query);
        assert.deepEqual((await shownIds(page)).sort(), ids, `“${query}”`);
        assert.match(await page.locator("#catalog-search-status").innerText(), new RegExp(`^${ids.length} of ${data.entries.length} examples match`), query);
      }
      // a topic with nothing left is hidden with its heading
      await search.fill("GSD");
      const topics = await page.evaluate(() => [...document.querySelectorAll("nav.catalog .catalog-topic")].filter((s) => s.checkVisibility()).map((s) => s.dataset.topic));
      assert.deepEqual(topics, ["Coordinates"]);
      assert.equal(await page.evaluate(() => location.hash), "#/?q=GSD");
      // the address holds the search: a reload (or Back to it) shows the same list
      await page.reload();
      await settled(page);
      assert.equal(await page.getByLabel("Find an example").inputValue(), "GSD");
      assert.deepEqual(await shownIds(page), ["gsd"]);
      await page.getByLabel("Find an example").fill("no such thing");
      assert.deepEqual(await shownIds(page), []);
      assert.match(await page.locator("#catalog-search-status").innerText(), /^No example matches “no such thing”/);
      await page.getByLabel("Find an example").fill("");
      assert.equal((await shownIds(page)).length, READY.length);
      assert.equal(await page.evaluate(() => location.hash), "#/");
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("each example has a picture of its figure, drawn at build time, loaded lazily and shown", { timeout: TEST_TIMEOUT }, async () => {
    assert.ok(data.thumbs, "index.html's data block lists the pictures");
    assert.deepEqual([...data.thumbs.ids].sort(), [...READY].sort(), "a picture of every example's figure");
    for (const id of data.thumbs.ids) {
      const file = path.join(DIST, data.thumbs.folder, `${id}.webp`);
      const bytes = fs.readFileSync(file);
      assert.equal(bytes.subarray(8, 12).toString("latin1"), "WEBP", `${id}: a WebP file`);
      assert.ok(bytes.length < 30_000, `${id}: ${bytes.length} bytes`);
    }
    // cached by the offline copy when first used, not at install
    const sw = fs.readFileSync(path.join(DIST, "sw.js"), "utf8");
    const build = JSON.parse(/const BUILD = (\{.*\});/.exec(sw)[1]);
    assert.ok(build.lazy.includes("prerender/thumbs/gsd.webp"));
    assert.ok(!build.files.some((f) => f.startsWith("prerender/thumbs/")));

    const { context, page, log } = await open(env.browser, PHONE);
    try {
      assert.equal(await visit(page, env.url, "index.html"), "home");
      const imgs = await page.evaluate(() => [...document.querySelectorAll("nav.catalog img.thumb-light")].map((i) => ({ id: i.closest("li").dataset.id, loading: i.loading, w: i.getAttribute("width"), h: i.getAttribute("height"), alt: i.alt })));
      assert.deepEqual(imgs.map((i) => i.id).sort(), [...READY].sort());
      for (const i of imgs) assert.deepEqual([i.loading, i.w, i.h, i.alt], ["lazy", "160", "100", ""], i.id);
      // lazily: the pictures far below the first screen are not fetched with it
      await page.waitForLoadState("networkidle");
      const early = log.requests.filter((u) => u.includes("/prerender/thumbs/")).length;
      assert.ok(early > 0 && early < READY.length, `${early} pictures fetched with the first screen`);
      // scrolled through: every picture is there, decoded at its full size
      await page.evaluate(async () => {
        for (const li of document.querySelectorAll("nav.catalog .catalog-item")) {
          li.scrollIntoView();
          await new Promise((r) => requestAnimationFrame(r));
        }
      });
      await page.waitForFunction(() => [...document.querySelectorAll("nav.catalog img.thumb-light")].every((i) => i.complete && i.naturalWidth > 0), null, { timeout: 15_000 });
      const sizes = await page.evaluate(() => [...document.querySelectorAll("nav.catalog img.thumb-light")].map((i) => [i.naturalWidth, i.naturalHeight]));
      for (const s of sizes) assert.deepEqual(s, [320, 200]);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("at 390 px: practice, the lab, Start here and the search on the first screen; the whole catalog under the bound", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page } = await open(env.browser, PHONE);
    try {
      assert.equal(await visit(page, env.url, "index.html"), "home");
      const fold = 844;
      for (const sel of ['.home-go a[href="#/practice"]', '.home-go a[href="#/lab"]', ".start-here .course-path a", "#catalog-search"]) {
        const box = await page.locator(sel).first().boundingBox();
        assert.ok(box && box.y >= 0 && box.y + box.height <= fold, `${sel} above the fold: ${JSON.stringify(box)}`);
      }
      // touch targets
      for (const sel of [".home-go a", ".course-path a", "#catalog-search", "nav.catalog .catalog-item"]) {
        const h = await page.locator(sel).first().evaluate((n) => n.getBoundingClientRect().height);
        assert.ok(h >= 44, `${sel}: ${h} px tall`);
      }
      const height = await page.evaluate(() => document.documentElement.scrollHeight);
      assert.ok(height <= PHONE_HOME_MAX, `the home view is ${height} px tall at 390 px`);
      assert.equal(await page.evaluate(() => document.documentElement.scrollWidth), 390);
      // no placeholder-like lines
      const text = await page.locator("main").innerText();
      assert.doesNotMatch(text, /All \d+ examples are ready|Course notes 000/);
    } finally {
      await context.close();
    }
  });

  test("Start here: the worked examples in the course notes' order, Example 1 first", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html"), "home");
      const path_ = await page.evaluate(() => [...document.querySelectorAll(".course-path a")].map((a) => [a.querySelector(".path-n").textContent, a.getAttribute("href")]));
      assert.deepEqual(path_.slice(0, 7), [
        ["1", "#/pixel-to-photo"],
        ["2", "#/gsd"],
        ["3", "#/photo-to-pixel"],
        ["4(a)", "#/fiducial-similarity"],
        ["4(b)", "#/fiducial-affine"],
        ["5", "#/ncc-1d"],
        ["6", "#/ncc-2d"],
      ]);
      const numbers = path_.map(([n]) => parseInt(n, 10)).filter(Number.isFinite);
      assert.deepEqual(numbers, [...numbers].sort((a, b) => a - b), "in course order");
      await page.locator(".course-path a").first().click();
      await page.waitForSelector('article.example[data-id="pixel-to-photo"]');
      assert.equal(await settled(page), "ok");
    } finally {
      await context.close();
    }
  });
});

describe("the theme switch", () => {
  /** The page's colours and its theme attribute. */
  const look = (page) =>
    page.evaluate(() => ({
      theme: document.documentElement.getAttribute("data-theme"),
      bg: getComputedStyle(document.body).backgroundColor,
      ink: getComputedStyle(document.body).color,
      choice: document.getElementById("theme-choice")?.value ?? null,
    }));

  test("Dark and Light set <html data-theme>, are remembered across a reload and Back/Forward; System follows the system", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page } = await open(env.browser, { colorScheme: "light" });
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/gsd"), "ok");
      const light = await look(page);
      assert.deepEqual([light.theme, light.choice, light.bg], [null, "system", "rgb(255, 255, 255)"]);
      await page.locator("#theme-choice").selectOption("dark");
      const dark = await look(page);
      assert.equal(dark.theme, "dark");
      assert.equal(dark.bg, "rgb(13, 17, 23)");
      assert.notEqual(dark.ink, light.ink);
      assert.equal(await page.evaluate((k) => localStorage.getItem(k), THEME_KEY), "dark");
      // a reload: dark before the page's modules run (theme-init.js), the switch says so
      await page.reload();
      await settled(page);
      assert.deepEqual(await look(page), { ...dark, choice: "dark" });
      // other views and Back/Forward keep it (each route applies the address's view options)
      await page.goto(`${env.url}index.html#/`);
      await settled(page);
      await page.goto(`${env.url}index.html#/ncc-2d?theme=light`);
      await settled(page);
      assert.equal((await look(page)).theme, "dark", "the reader's choice wins over a link's theme on the site");
      await page.goBack();
      await settled(page);
      await page.goBack();
      await settled(page);
      assert.deepEqual(await look(page), { ...dark, choice: "dark" });
      await page.goForward();
      await settled(page);
      assert.equal((await look(page)).theme, "dark");
      // Light, then System (the system here is light; then dark)
      await page.locator("#theme-choice").selectOption("light");
      assert.equal((await look(page)).theme, "light");
      await page.locator("#theme-choice").selectOption("system");
      assert.equal((await look(page)).theme, null);
      assert.equal(await page.evaluate((k) => localStorage.getItem(k), THEME_KEY), null);
      await page.emulateMedia({ colorScheme: "dark" });
      assert.equal((await look(page)).bg, "rgb(13, 17, 23)");
    } finally {
      await context.close();
    }
  });

  test("the embed follows its own theme option, not the site's switch", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page } = await open(env.browser, { colorScheme: "light" });
    try {
      await visit(page, env.url, "index.html", "#/gsd");
      await page.locator("#theme-choice").selectOption("dark");
      assert.equal(await visit(page, env.url, "embed.html", "#/gsd?theme=light"), "ok");
      assert.equal(await page.evaluate(() => document.documentElement.getAttribute("data-theme")), "light");
      assert.equal(await visit(page, env.url, "embed.html", "#/gsd"), "ok");
      assert.equal(await page.evaluate(() => document.documentElement.getAttribute("data-theme")), null);
      assert.equal(await page.locator("#theme-choice").count(), 0);
    } finally {
      await context.close();
    }
  });
});

describe("the skip link", () => {
  test("Tab reaches “Skip to the example” first, shown; Enter moves the focus into <main> and leaves the address", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page } = await open(env.browser);
    try {
      for (const hash of ["", "#/ncc-2d"]) {
        await page.goto("about:blank"); // a fresh load: the focus at the document's start
        await visit(page, env.url, "index.html", hash);
        const before_ = await page.evaluate(() => location.hash);
        const hidden = await page.locator("a.skip-link").boundingBox();
        assert.ok(hidden.y + hidden.height <= 0, "out of sight until focused");
        await page.keyboard.press("Tab");
        const focused = await page.evaluate(() => ({ cls: document.activeElement.className, text: document.activeElement.textContent }));
        assert.deepEqual(focused, { cls: "skip-link", text: "Skip to the example" });
        const shown = await page.locator("a.skip-link").boundingBox();
        assert.ok(shown.y >= 0 && shown.height > 20, `visible on focus: ${JSON.stringify(shown)}`);
        await page.keyboard.press("Enter");
        assert.equal(await page.evaluate(() => document.activeElement.id), "app");
        assert.equal(await page.evaluate(() => location.hash), before_);
        // the next Tab goes on inside main
        await page.keyboard.press("Tab");
        assert.ok(await page.evaluate(() => document.getElementById("app").contains(document.activeElement)));
      }
    } finally {
      await context.close();
    }
  });
});

describe("the figure on a phone", () => {
  const IDS = ["ncc-2d", "gsd", "filter-window", "forstner-window", "resample", "chain-code", "lsm-affine"];

  /** The boxes of an example's parts (page coordinates). */
  const boxes = (page) =>
    page.evaluate(() => {
      const box = (sel) => {
        const n = document.querySelector(sel);
        if (!n) return null;
        const r = n.getBoundingClientRect();
        return { x: r.x, y: r.y + scrollY, w: r.width, h: r.height, bottom: r.bottom + scrollY, right: r.right };
      };
      return { inputs: box(".inputs"), figure: box(".figure-section"), steps: box(".steps-panel"), result: box(".result-section") };
    });

  test(`390 px: the figure right after the inputs (≤ ${FIGURE_GAP_MAX} px), before the steps, nothing overlapping`, { timeout: TEST_TIMEOUT * 2 }, async () => {
    const { context, page } = await open(env.browser, PHONE);
    try {
      for (const id of IDS) {
        assert.equal(await visit(page, env.url, "index.html", `#/${id}`), "ok", id);
        const b = await boxes(page);
        const gap = b.figure.y - b.inputs.bottom;
        assert.ok(gap >= 0 && gap <= FIGURE_GAP_MAX, `${id}: the figure starts ${gap} px below the inputs`);
        assert.ok(b.steps.y >= b.figure.bottom, `${id}: the steps below the figure`);
        assert.ok(b.result.y >= b.steps.bottom, `${id}: the result below the steps`);
      }
    } finally {
      await context.close();
    }
  });

  test("1280 px: inputs | steps | figure above the result, as before", { timeout: TEST_TIMEOUT * 2 }, async () => {
    const { context, page } = await open(env.browser);
    try {
      for (const id of IDS) {
        assert.equal(await visit(page, env.url, "index.html", `#/${id}`), "ok", id);
        const b = await boxes(page);
        assert.ok(b.inputs.right <= b.steps.x && b.steps.right <= b.figure.x, `${id}: three columns`);
        assert.ok(Math.abs(b.figure.y - b.steps.y) <= 1, `${id}: the figure at the top of its column`);
        const gap = b.result.y - b.figure.bottom;
        assert.ok(gap >= 0 && gap <= 20, `${id}: the result ${gap} px below the figure`);
        assert.ok(Math.abs(b.result.x - b.figure.x) <= 1, `${id}: the result in the figure's column`);
      }
    } finally {
      await context.close();
    }
  });
});
