// The page as a whole: figures drawn sharp on canvases, no request leaving
// 127.0.0.1, the catalog and the embed view, keyboard use, and a phone's width.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import fs from "node:fs";
import { CATALOG_IDS, TEST_TIMEOUT, catalogMdIds, exact, open, quiet, settled, start, visit, waitForExact } from "./harness.mjs";

const EXAMPLES = {
  "pixel-to-photo": { describes: ["1600 columns", "8.255 mm"] },
  gsd: { describes: ["152 mm", "1920 m", "35.65 cm", "12632", "not to scale"] },
  "photo-to-pixel": { describes: ["1800 columns", "606.614"] },
};

let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

/** Canvas facts: size in CSS and device pixels, and how many pixels are not white. */
function canvasFacts(page) {
  return page.evaluate(() =>
    [...document.querySelectorAll(".figure-canvas")].map((c) => {
      const data = c.getContext("2d").getImageData(0, 0, c.width, c.height).data;
      let ink = 0;
      const colours = new Set();
      for (let i = 0; i < data.length; i += 4) {
        if (data[i] < 240 || data[i + 1] < 240 || data[i + 2] < 240) ink += 1;
        if (i % 64 === 0) colours.add((data[i] << 16) | (data[i + 1] << 8) | data[i + 2]);
      }
      return {
        width: c.width,
        height: c.height,
        clientWidth: c.clientWidth,
        clientHeight: c.clientHeight,
        ink,
        pixels: c.width * c.height,
        colours: colours.size,
        role: c.getAttribute("role"),
        label: c.getAttribute("aria-label"),
      };
    }),
  );
}

describe("figures", () => {
  test("each example draws a labelled canvas, scaled for devicePixelRatio 2, and redraws on resize", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser, { deviceScaleFactor: 2 });
    try {
      for (const [id, { describes }] of Object.entries(EXAMPLES)) {
        assert.equal(await visit(page, env.url, "index.html", `#/${id}`), "ok", id);
        const [fig] = await canvasFacts(page);
        assert.ok(fig, `${id}: a canvas`);
        assert.equal(fig.width, 2 * fig.clientWidth, `${id}: canvas.width = 2 × clientWidth`);
        assert.equal(fig.height, 2 * fig.clientHeight, `${id}: canvas.height = 2 × clientHeight`);
        assert.ok(fig.clientWidth > 200, `${id}: a useful size`);
        assert.ok(fig.ink > fig.pixels * 0.02, `${id}: drawn (${fig.ink} of ${fig.pixels} pixels not white)`);
        assert.ok(fig.colours > 8, `${id}: more than a flat fill`);
        assert.equal(fig.role, "img");
        for (const words of describes) assert.ok(fig.label.includes(words), `${id}: aria-label mentions ${words}: ${fig.label}`);
      }

      // narrower window: the canvas follows and stays sharp
      const before = (await canvasFacts(page))[0];
      await page.setViewportSize({ width: 700, height: 900 });
      await page.waitForFunction((w) => document.querySelector(".figure-canvas").clientWidth !== w, before.clientWidth);
      // redrawn at the new size (the canvas's pixels follow its width, then it is drawn in the same task)
      await page.waitForFunction(() => {
        const c = document.querySelector(".figure-canvas");
        return c.clientWidth > 0 && c.width === 2 * c.clientWidth;
      });
      const [narrow] = await canvasFacts(page);
      assert.equal(narrow.width, 2 * narrow.clientWidth);
      assert.ok(narrow.ink > narrow.pixels * 0.02);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("a point outside the image is still drawn, with the warning note", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page } = await open(env.browser);
    try {
      await visit(page, env.url, "index.html", "#/pixel-to-photo?dpi=600&columns=1600&rows=1400&c=3000&r=-200");
      assert.ok(Math.abs((await exact(page, "x_mm")) - 2200 * (25.4 / 600)) < 1e-9);
      assert.equal(await page.locator(".notes .badge-warning").count(), 1);
      const [fig] = await canvasFacts(page);
      assert.match(fig.label, /outside the image/);
      assert.ok(fig.ink > fig.pixels * 0.02);
    } finally {
      await context.close();
    }
  });
});

describe("network", () => {
  test("no request leaves 127.0.0.1", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      await visit(page, env.url, "index.html");
      for (const id of Object.keys(EXAMPLES)) await visit(page, env.url, "index.html", `#/${id}`);
      await visit(page, env.url, "embed.html", "#/gsd?dpi=1200");
      await quiet(page);
      const origin = new URL(env.url).origin;
      assert.ok(log.requests.length > 3, "the page made its own requests");
      const outside = log.requests.filter((u) => !u.startsWith(`${origin}/`) && !u.startsWith("data:") && !u.startsWith("blob:"));
      assert.deepEqual(outside, []);
      // the wasm, KaTeX and its fonts came from here
      // (content-hashed names: name.<8 hex>.ext, scripts/site.mjs)
      assert.ok(log.requests.some((u) => /_bg(-\w{8})?\.wasm$/.test(u)));
      assert.ok(log.requests.some((u) => /\/vendor\/katex\/katex\.min(\.[0-9a-f]{8})?\.js$/.test(u)));
      assert.ok(log.requests.some((u) => u.includes("/vendor/katex/fonts/")));
      assert.deepEqual(log.consoleErrors, []);
    } finally {
      await context.close();
    }
  });
});

describe("numbers before formulas", () => {
  test("with KaTeX unreachable the first solution still shows every number, formulas as their LaTeX text", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page } = await open(env.browser);
    try {
      await page.route(/\/vendor\/katex\//, (route) => route.abort());
      assert.equal(await visit(page, env.url, "index.html", "#/gsd"), "ok");
      assert.equal(await page.evaluate(() => document.documentElement.dataset.math), "failed");
      assert.ok(await page.evaluate(() => performance.getEntriesByName("first-solution").length === 1));
      // the answer and the results are there; a formula is its LaTeX text (no home-made reader of it)
      assert.ok(Math.abs((await exact(page, "gsd_cm")) - 35.6491) < 1e-3);
      assert.match(await page.locator(".answer-line, .answer").first().innerText(), /35\.649/);
      assert.equal(await page.locator(".steps .katex").count(), 0);
      assert.equal(await page.locator(".steps .formula-pending, .steps [aria-busy]").count(), 0, "no formula left waiting");
      assert.match((await page.locator(".steps .formula-raw code").allInnerTexts()).join("\n"), /\\text\{GSD\}\s*=\s*p\s*\\cdot\s*m/);
    } finally {
      await context.close();
    }
  });
});

describe("catalog and embed", () => {
  test("the catalog lists every example of CATALOG.md, grouped by topic, coming ones marked", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html"), "home");
      const items = await page.evaluate(() =>
        [...document.querySelectorAll("nav.catalog .catalog-item")].map((li) => ({
          id: li.dataset.id,
          status: li.dataset.status,
          href: li.querySelector("a")?.getAttribute("href") ?? null,
          badge: li.querySelector(".badge-coming")?.textContent ?? null,
          topic: li.closest(".catalog-topic").querySelector("h2").textContent,
        })),
      );
      const ids = items.map((i) => i.id);
      // the home view lists the built catalog, in its order
      assert.ok(CATALOG_IDS.length > 20, `the built catalog has ${CATALOG_IDS.length} examples`);
      assert.deepEqual(ids, [...CATALOG_IDS]);
      // every example of the shared catalog is there; one beyond it is documented in docs/API.md
      const md = catalogMdIds();
      if (md) for (const id of md) assert.ok(ids.includes(id), `${id} (CATALOG.md) is not on the page`);
      const api = fs.readFileSync("docs/API.md", "utf8");
      for (const id of ids.filter((x) => md && !md.includes(x))) assert.ok(api.includes(`\`${id}\``), `${id}: beyond CATALOG.md and not in docs/API.md`);
      for (const item of items) {
        if (item.status === "ready") {
          assert.equal(item.href, `#/${item.id}`, item.id);
          assert.equal(item.badge, null, item.id);
        } else {
          assert.equal(item.status, "coming", item.id);
          assert.equal(item.href, null, `${item.id}: not a link`);
          assert.equal(item.badge, "coming", item.id);
        }
      }
      for (const id of Object.keys(EXAMPLES)) assert.equal(items.find((i) => i.id === id).status, "ready", id);
      const topics = [...new Set(items.map((i) => i.topic))];
      assert.deepEqual(topics, [
        "Coordinates",
        "Transformations",
        "Correlation",
        "Least-squares matching",
        "Resampling",
        "Filters and edges",
        "Interest operators",
        "Chain codes and boundaries",
        "Map projection",
      ]);
    } finally {
      await context.close();
    }
  });

  test("embed.html shows one example without the catalog or the header", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser, { viewport: { width: 800, height: 700 } });
    try {
      assert.equal(await visit(page, env.url, "embed.html", "#/gsd?dpi=1200"), "ok");
      await waitForExact(page, "gsd_cm", (((25.4 / 1200) * 1920000) / 152) / 10, 1e-9);
      assert.equal(await page.locator("article.example").count(), 1);
      assert.equal(await page.locator("nav.catalog").count(), 0);
      assert.equal(await page.locator(".site-header").count(), 0);
      assert.equal(await page.locator(".figure-canvas").count(), 1);
      const open_ = page.locator("a.open-full");
      assert.match(await open_.getAttribute("href"), /^index\.html#\/gsd\?dpi=1200&/);
      // editing works there too
      await page.getByLabel(/Scan resolution/).fill("900");
      await waitForExact(page, "gsd_cm", (((25.4 / 900) * 1920000) / 152) / 10, 1e-9);
      assert.match(await page.evaluate(() => location.pathname), /embed\.html$/);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("an example's \"Other examples\" drawer: its list built when first opened, the example on screen marked, its links work", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/ncc-1d"), "ok");
      const drawer = page.locator("details.catalog-drawer");
      assert.equal(await drawer.locator("nav").count(), 0, "not built before it is opened");
      await drawer.locator("summary").click();
      const nav = drawer.locator("nav.catalog-compact");
      await nav.waitFor(); // (catalog.js is loaded when the list is first wanted)
      assert.equal(await nav.count(), 1);
      const home = await page.evaluate(() => JSON.parse(document.getElementById("catalog-data").textContent).entries.filter((e) => e.status === "ready").length);
      assert.equal(await nav.locator(".catalog-item.ready a").count(), home, "every ready example");
      assert.equal(await nav.locator('a[aria-current="page"]').getAttribute("href"), "#/ncc-1d");
      // closed and opened again: the one list, not a second
      await drawer.locator("summary").click();
      await drawer.locator("summary").click();
      assert.equal(await drawer.locator("nav").count(), 1);
      await nav.locator('a[href="#/gsd"]').click();
      await page.waitForSelector('article.example[data-id="gsd"]');
      await settled(page);
      assert.ok(await exact(page, "gsd_cm"));
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("keyboard: a catalog link opens its example; Tab walks the labelled inputs", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page } = await open(env.browser);
    try {
      await visit(page, env.url, "index.html");
      const link = page.locator('nav.catalog a[href="#/gsd"]');
      await link.focus();
      // a visible focus indicator
      const outline = await link.evaluate((a) => getComputedStyle(a).outlineStyle);
      assert.notEqual(outline, "none");
      await page.keyboard.press("Enter");
      await page.waitForSelector('article.example[data-id="gsd"]');
      await settled(page);
      assert.ok(await exact(page, "gsd_cm"));
      // every input has a label tied to it
      const unlabeled = await page.evaluate(() =>
        [...document.querySelectorAll(".input-form input, .input-form select, .input-form textarea")].filter((i) => !i.labels || i.labels.length === 0).map((i) => i.id),
      );
      assert.deepEqual(unlabeled, []);
      // Tab from the first field reaches the next one
      await page.getByLabel(/Scan resolution/).focus();
      await page.keyboard.press("Tab");
      assert.equal(await page.evaluate(() => document.activeElement.name), "focal_length_mm");
      await page.keyboard.press("Tab");
      assert.equal(await page.evaluate(() => document.activeElement.name), "flying_height_m");
      await page.keyboard.press("Tab");
      assert.match(await page.evaluate(() => document.activeElement.textContent), /Reset to the worked example/);
    } finally {
      await context.close();
    }
  });
});

describe("phone", () => {
  test("375 px wide: one column, no horizontal scroll", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page } = await open(env.browser, { viewport: { width: 375, height: 800 }, deviceScaleFactor: 2, isMobile: true, hasTouch: true });
    try {
      const pages = [
        ["index.html", ""],
        ...Object.keys(EXAMPLES).map((id) => ["index.html", `#/${id}`]),
        ["index.html", "#/gsd?dpi=abc"],
        ["embed.html", "#/photo-to-pixel"],
      ];
      for (const [file, hash] of pages) {
        await visit(page, env.url, file, hash);
        await quiet(page);
        const width = await page.evaluate(() => document.documentElement.scrollWidth);
        assert.ok(width <= 375, `${file}${hash}: scrollWidth ${width}`);
        if (hash.startsWith("#/") && !hash.includes("abc")) {
          // single column: the steps sit below the inputs, not beside them
          const [inputs, steps] = await Promise.all([page.locator(".inputs").boundingBox(), page.locator(".steps-panel").boundingBox()]);
          assert.ok(steps.y >= inputs.y + inputs.height, `${hash}: steps below the inputs`);
          const [fig] = await canvasFacts(page);
          assert.ok(fig.clientWidth <= 375 && fig.width === 2 * fig.clientWidth);
        }
      }
    } finally {
      await context.close();
    }
  });
});
