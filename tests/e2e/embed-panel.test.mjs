// "Embed this" for an instructor: practice embeds offered beside the worked
// example (a fresh variant per student, or one variant for the class), what
// the panel refers to reachable from it, and the iframe form's height the one
// the preview measured.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import { TEST_TIMEOUT, open, start, visit } from "./harness.mjs";

const WAIT = 15_000;

let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

const snippet = (page, name) => page.inputValue(`[data-snippet="${name}"]`);
const heightOf = (iframe) => Number(/height="(\d+)"/.exec(iframe)[1]);

/** The preview's content height, as embed-page.js measures it, once the preview has reported it. */
async function measured(page, status) {
  const preview = await (await page.$(".embed-preview")).contentFrame();
  await preview.waitForFunction((s) => document.body.dataset.status === s, status, { timeout: WAIT });
  await page.waitForFunction(() => /measures \d+ px/.test(document.querySelector(".embed-height").textContent), null, { timeout: WAIT });
  // settled: the snippet's height stops changing
  let last = -1;
  for (let i = 0; i < 20; i++) {
    const h = heightOf(await snippet(page, "iframe"));
    const content = await preview.evaluate(() => Math.ceil(document.body.getBoundingClientRect().height));
    if (h === last && h === content) return { preview, content };
    last = h;
    await page.waitForTimeout(150);
  }
  return { preview, content: await preview.evaluate(() => Math.ceil(document.body.getBoundingClientRect().height)) };
}

describe("the embed panel", () => {
  test("writes the height it measured into the iframe form, not a rounded or default one", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      await visit(page, env.url, "index.html", "#/gsd");
      await page.click('[data-tool="embed"]');
      await page.waitForSelector(".embed-panel", { timeout: WAIT });
      const { content } = await measured(page, "ok");
      const iframe = await snippet(page, "iframe");
      assert.equal(heightOf(iframe), content);
      assert.ok(iframe.includes(`height:${content}px`), iframe);
      assert.match(await page.innerText(".embed-height"), new RegExp(`measures ${content} px.*height="${content}"`));
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("offers practice embeds: a fresh variant for each student, or one variant for the class", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      await visit(page, env.url, "index.html", "#/gsd?dpi=1200");
      await page.click('[data-tool="embed"]');
      await page.waitForSelector(".embed-panel", { timeout: WAIT });
      const labels = await page.locator("#embed-what option").allInnerTexts();
      assert.equal(labels.length, 3);
      assert.match(labels[1], /practice/i);
      await page.selectOption("#embed-what", "practice");
      await page.selectOption("#embed-theme", "dark");
      const script = await snippet(page, "script");
      assert.ok(script.includes('<div data-playground="gsd?practice" data-theme="dark"></div>'), script);
      let iframe = await snippet(page, "iframe");
      assert.ok(iframe.includes(`src="${env.url}embed.html#/gsd?practice&amp;theme=dark"`), iframe);
      assert.match(iframe, /title="Practice: Ground sample distance — Photogrammetry Playground"/);
      // the example's own options do not apply to practice
      assert.equal(await page.locator(".embed-example-options").evaluate((f) => f.disabled), true);
      // the preview is the practice page, and its measured height is written
      const { preview, content } = await measured(page, "practice");
      assert.equal(await preview.locator(".answer").count(), 4);
      assert.equal(heightOf(await snippet(page, "iframe")), content);
      // one variant for the whole class: its code in both forms
      await page.selectOption("#embed-what", "variant");
      await page.fill("#embed-code", "1k7q2");
      await page.waitForFunction(() => document.querySelector('[data-snippet="script"]').value.includes("practice=1K7Q2"), null, { timeout: WAIT });
      assert.ok((await snippet(page, "script")).includes('data-playground="gsd?practice=1K7Q2"'));
      iframe = await snippet(page, "iframe");
      assert.ok(iframe.includes(`embed.html#/gsd?practice=1K7Q2&amp;theme=dark`), iframe);
      const p2 = await (await page.$(".embed-preview")).contentFrame();
      await p2.waitForFunction(() => document.querySelector("article.practice")?.dataset.code === "1K7Q2", null, { timeout: WAIT });
      // and back to the worked example with its inputs
      await page.selectOption("#embed-what", "example");
      assert.ok((await snippet(page, "script")).includes('data-playground="gsd?dpi=1200&amp;'));
      assert.equal(await page.locator(".embed-example-options").evaluate((f) => f.disabled), false);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("links what it refers to: no bare \"see the README\"; the link opens how the script form talks to the page", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      await visit(page, env.url, "index.html", "#/gsd");
      await page.click('[data-tool="embed"]');
      await page.waitForSelector(".embed-panel", { timeout: WAIT });
      const text = await page.innerText(".embed-panel");
      assert.doesNotMatch(text, /README/);
      const link = page.locator(".embed-panel a.embed-howto-link");
      assert.equal(await link.getAttribute("href"), "#embed-howto");
      assert.equal(await page.locator("#embed-howto").evaluate((d) => d.open), false);
      const hash = await page.evaluate(() => location.hash);
      await link.click();
      assert.equal(await page.locator("#embed-howto").evaluate((d) => d.open), true);
      assert.equal(await page.evaluate(() => document.activeElement.matches("#embed-howto summary")), true);
      assert.equal(await page.evaluate(() => location.hash), hash, "the route stays");
      const howto = await page.innerText("#embed-howto");
      for (const s of ["playground:change", "getState()", "setState(", "photogrammetry-playground:answer", "data-id"]) assert.ok(howto.includes(s), s);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });
});
