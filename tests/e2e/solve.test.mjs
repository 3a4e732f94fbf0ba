// The page solves: seed values with the printed ones beside them, edits that
// recompute and rewrite the URL, bad inputs that are reported beside their
// field, and URL text that never becomes markup.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import { TEST_TIMEOUT, cellText, exact, open, parseShown, quiet, settled, start, visit, waitForExact } from "./harness.mjs";

const GSD_SEED = "#/gsd?dpi=900&focal_length_mm=152&flying_height_m=1920";
// 25.4/900 mm × 1920 m / 152 mm, in cm; and at 1200 dpi
const GSD_CM_900 = (((25.4 / 900) * 1920000) / 152) / 10;
const GSD_CM_1200 = (((25.4 / 1200) * 1920000) / 152) / 10;

let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

describe("seed values", () => {
  test("gsd: exact 35.649 cm with the printed 35.37 beside it", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", GSD_SEED), "ok");
      const gsd = await exact(page, "gsd_cm");
      assert.ok(Math.abs(gsd - GSD_CM_900) < 1e-9, `gsd_cm = ${gsd}`);
      assert.ok(Math.abs(gsd - 35.649) < 1e-3);
      const shown = await cellText(page, "gsd_cm", "exact");
      assert.ok(shown.startsWith("35.649"), `shown exact: ${shown}`);
      assert.equal(parseShown(await cellText(page, "gsd_cm", "printed")), 35.37);
      const diff = parseShown((await cellText(page, "gsd_cm", "diff")).split(/\s/)[0]);
      assert.ok(Math.abs(diff - (GSD_CM_900 - 35.37)) < 1e-3, `difference ${diff}`);
      // every result key of CATALOG.md has a row
      for (const key of ["scale_denominator", "pixel_size_mm", "gsd_mm", "gsd_cm"]) {
        assert.equal(await page.locator(`.result-table tr[data-key="${key}"]`).count(), 1, key);
      }
      // steps rendered by KaTeX, not left as LaTeX
      assert.ok((await page.locator(".steps .step").count()) >= 3);
      assert.ok((await page.locator(".steps .katex").count()) >= 3);
      assert.equal(await page.locator(".formula-raw, .formula-error").count(), 0);
      // the notes carry their kind as a badge
      assert.ok((await page.locator(".notes .badge").count()) >= 1);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("pixel-to-photo: x_mm 8.255; photo-to-pixel: c and r", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/pixel-to-photo"), "ok");
      assert.ok(Math.abs((await exact(page, "x_mm")) - 8.255) < 1e-9);
      assert.equal(parseShown(await cellText(page, "x_mm", "exact")), 8.255);
      assert.equal(parseShown(await cellText(page, "x_mm", "printed")), 8.19);
      assert.ok(Math.abs((await exact(page, "y_mm")) - (220 * 25.4) / 600) < 1e-9);
      // the address now holds every input
      const hash = await page.evaluate(() => location.hash);
      assert.equal(hash, "#/pixel-to-photo?dpi=600&columns=1600&rows=1400&c=995&r=480");

      // hashchange switches the example
      await page.evaluate(() => {
        location.hash = "#/photo-to-pixel";
      });
      await page.waitForSelector('article.example[data-id="photo-to-pixel"]');
      await settled(page);
      const c = 900 + -12.42 / (25.4 / 600);
      const r = 750 + 25.36 / (25.4 / 600);
      await waitForExact(page, "c", c, 1e-9);
      assert.ok(Math.abs((await exact(page, "r")) - r) < 1e-9);
      assert.equal(await page.locator("h2#example-title").innerText(), "Image to pixel coordinates");
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });
});

describe("editing", () => {
  test("typing dpi 1200 recomputes and rewrites the URL without new history entries", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      await visit(page, env.url, "index.html", GSD_SEED);
      const historyBefore = await page.evaluate(() => history.length);
      const dpi = page.getByLabel(/Scan resolution/);
      await dpi.focus();
      await page.keyboard.press("ControlOrMeta+A");
      await page.keyboard.type("1200", { delay: 20 });
      await waitForExact(page, "gsd_cm", GSD_CM_1200, 1e-9);
      assert.ok(Math.abs((await exact(page, "gsd_cm")) - 26.737) < 1e-3);
      assert.ok((await cellText(page, "gsd_cm", "exact")).startsWith("26.73"));
      const hash = await page.evaluate(() => location.hash);
      assert.equal(hash, "#/gsd?dpi=1200&focal_length_mm=152&flying_height_m=1920");
      assert.equal(await page.evaluate(() => history.length), historyBefore, "replaceState, not pushState");
      // not the seed's inputs any more: no printed column
      assert.equal(await page.locator(".result-table td.printed").count(), 0);

      // a URL typed in (hashchange) restores its inputs into the form
      await page.evaluate(() => {
        location.hash = "#/gsd?dpi=600&focal_length_mm=152&flying_height_m=1920";
      });
      await waitForExact(page, "gsd_cm", (((25.4 / 600) * 1920000) / 152) / 10, 1e-9);
      assert.equal(await dpi.inputValue(), "600");

      // reloading keeps them
      await page.reload();
      await settled(page);
      assert.equal(await page.getByLabel(/Scan resolution/).inputValue(), "600");

      // reset brings the seed back, printed values included
      await page.getByRole("button", { name: /Reset to the worked example/ }).click();
      await waitForExact(page, "gsd_cm", GSD_CM_900, 1e-9);
      assert.equal(await page.evaluate(() => location.hash), GSD_SEED);
      assert.equal(parseShown(await cellText(page, "gsd_cm", "printed")), 35.37);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("copy link puts the current address on the clipboard", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page } = await open(env.browser);
    try {
      await context.grantPermissions(["clipboard-read", "clipboard-write"], { origin: env.url.replace(/\/$/, "") });
      await visit(page, env.url, "index.html", "#/gsd?dpi=1200");
      await page.getByRole("button", { name: "Copy link" }).click();
      const href = await page.evaluate(() => location.href);
      await page.waitForSelector(".copy-status:not(:empty)");
      const status = await page.locator(".copy-status").innerText();
      if (status.startsWith("Link copied")) {
        assert.equal(await page.evaluate(() => navigator.clipboard.readText()), href);
      } else {
        // no clipboard here: the link is offered to copy by hand
        assert.equal(await page.locator(".copy-field").inputValue(), href);
      }
      assert.ok(href.includes("#/gsd?dpi=1200&focal_length_mm=152&flying_height_m=1920"));
    } finally {
      await context.close();
    }
  });
});

describe("bad inputs", () => {
  test("dpi = -5 and dpi = abc are reported beside the field; fixing it brings the result back", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      await visit(page, env.url, "index.html", GSD_SEED);
      const dpi = page.getByLabel(/Scan resolution/);
      const dpiId = await dpi.getAttribute("id");
      const error = page.locator(`#${dpiId}-error`);

      for (const [text, pattern] of [
        ["-5", /greater than 0/],
        ["abc", /not a number/],
      ]) {
        await dpi.fill(text);
        await page.waitForFunction(() => document.body.dataset.status === "invalid");
        assert.match(await error.innerText(), pattern);
        assert.equal(await error.isVisible(), true);
        assert.equal(await dpi.getAttribute("aria-invalid"), "true");
        assert.ok((await dpi.getAttribute("aria-describedby")).split(" ").includes(`${dpiId}-error`));
        // the error sits in the dpi field's own box
        assert.equal(await page.locator('.field[data-key="dpi"] .field-error').innerText(), await error.innerText());
        // the last good solution stays, marked stale
        assert.equal(await page.locator(".layout.stale").count(), 1);
        assert.equal(await page.locator(".stale-banner").isVisible(), true);
        assert.ok(Math.abs((await exact(page, "gsd_cm")) - GSD_CM_900) < 1e-9);
        assert.ok((await page.evaluate(() => location.hash)).includes(`dpi=${encodeURIComponent(text)}`));
      }

      await dpi.fill("1200");
      await waitForExact(page, "gsd_cm", GSD_CM_1200, 1e-9);
      assert.equal(await page.evaluate(() => document.body.dataset.status), "ok");
      assert.equal(await error.isVisible(), false);
      assert.equal(await dpi.getAttribute("aria-invalid"), null);
      assert.equal(await page.locator(".layout.stale").count(), 0);
      assert.equal(await page.locator(".stale-banner").isVisible(), false);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("a bad value in the URL is reported the same way", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/gsd?dpi=0"), "invalid");
      assert.match(await page.locator('.field[data-key="dpi"] .field-error').innerText(), /greater than 0/);
      // no solution yet to keep: none shown, and the page still works
      assert.equal(await page.locator(".result-table").count(), 0);
      await page.getByLabel(/Scan resolution/).fill("900");
      await waitForExact(page, "gsd_cm", GSD_CM_900, 1e-9);
    } finally {
      await context.close();
    }
  });

  test("markup in URL values, keys and ids never becomes an element", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      // short enough to survive any shortening for display (a cut tag would be harmless anyway)
      const evil = "<img src=x onerror=window.__pwned=1>";
      const e = encodeURIComponent(evil);
      const alerting = encodeURIComponent("<img src=x onerror=alert(1)>");
      const script = encodeURIComponent("<script>window.__pwned=2</script>");
      const status = await visit(page, env.url, "index.html", `#/gsd?dpi=${e}&${e}=1&${script}=${script}&focal_length_mm=152`);
      assert.equal(status, "invalid");
      // the value reached the input as text and the core's message beside it
      assert.equal(await page.getByLabel(/Scan resolution/).inputValue(), evil);
      assert.match(await page.locator('.field[data-key="dpi"] .field-error').innerText(), /not a number/);
      // the unknown keys are dropped with a notice that quotes them as text
      const notice = await page.locator(".url-notice").innerText();
      assert.match(notice, /Ignored unknown URL parameters/);
      assert.ok(notice.includes("<img src=x"), notice);
      const keys = await page.evaluate(() => [...new URLSearchParams(location.hash.split("?")[1])].map(([k]) => k));
      assert.deepEqual(keys, ["dpi", "focal_length_mm", "flying_height_m"], "unknown keys dropped from the URL");
      assert.equal(await page.locator("img").count(), 0);
      assert.equal(await page.locator("#app script").count(), 0);

      // an id with markup
      await page.goto(`${env.url}index.html#/${e}?x=${e}`);
      assert.equal(await settled(page), "message");
      assert.equal(await page.locator("img").count(), 0);
      await page.goto(`${env.url}index.html#/${alerting}`);
      assert.equal(await settled(page), "message");
      assert.match(await page.locator("#app").innerText(), /No such example/);
      assert.equal(await page.locator("img").count(), 0);

      // and in the embed view
      await visit(page, env.url, "embed.html", `#/pixel-to-photo?c=${e}&${e}=${e}&${alerting}=${alerting}`);
      assert.equal(await page.locator("img").count(), 0);

      // a payload that ran (a script, an image's onerror after its request failed) would have by now
      await quiet(page);
      assert.equal(await page.evaluate(() => window.__pwned), undefined);
      assert.deepEqual(log.dialogs, []);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });
});
