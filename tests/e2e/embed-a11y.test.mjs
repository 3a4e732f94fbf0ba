// Accessibility as a gate: axe-core (npm) on the catalog, every ready example
// and the embed, in dark mode and light: no serious or critical violation.
// Also: every figure canvas has a text alternative with numbers in it.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import { createRequire } from "node:module";
import { TEST_TIMEOUT, open, visit } from "./harness.mjs";

const AXE = createRequire(import.meta.url).resolve("axe-core/axe.min.js");

let env;
let ids = [];
before(async () => {
  const { start } = await import("./harness.mjs");
  env = await start();
  const { context, page } = await open(env.browser);
  await visit(page, env.url, "index.html", "#/");
  ids = await page.$$eval(".catalog-item.ready[data-id]", (items) => items.map((i) => i.dataset.id));
  await context.close();
});
after(async () => {
  await env?.close();
});

/** Serious and critical violations of the page as it is now, as readable lines. */
async function axeProblems(page) {
  // the page marks scrolling formulas focusable when idle after a solve: let it
  await page.evaluate(() => new Promise((resolve) => requestIdleCallback(resolve, { timeout: 2000 })));
  if (!(await page.evaluate(() => typeof window.axe === "object"))) await page.addScriptTag({ path: AXE });
  const result = await page.evaluate(() => window.axe.run(document, { resultTypes: ["violations"] }));
  return result.violations
    .filter((v) => v.impact === "serious" || v.impact === "critical")
    .map((v) => `${v.id} (${v.impact}): ${v.nodes.slice(0, 3).map((n) => n.target.join(" ")).join(" | ")}`);
}

describe("axe-core: no serious or critical violation", { timeout: TEST_TIMEOUT * 10 }, () => {
  test("the catalog has examples to check", () => {
    assert.ok(ids.length >= 20, `ready examples: ${ids.length}`);
  });

  for (const scheme of ["dark", "light"]) {
    test(`the catalog and the embed, ${scheme}`, async () => {
      // bypassCSP: axe is injected as an inline script, which the page's CSP rightly refuses
      const { context, page } = await open(env.browser, { colorScheme: scheme, bypassCSP: true });
      try {
        await visit(page, env.url, "index.html", "#/");
        assert.deepEqual(await axeProblems(page), [], "catalog");
        await visit(page, env.url, "embed.html", "#/gsd?dpi=1200");
        assert.deepEqual(await axeProblems(page), [], "embed");
        await visit(page, env.url, "embed.html", "#/lsm-1d?steps=collapsed&step=2&lock=true&theme=bogus");
        assert.deepEqual(await axeProblems(page), [], "embed with options and a notice");
        // the open "Embed this" panel
        await visit(page, env.url, "index.html", "#/gsd");
        await page.click('[data-tool="embed"]');
        await page.waitForSelector(".embed-panel");
        assert.deepEqual(await axeProblems(page), [], "Embed this panel");
      } finally {
        await context.close();
      }
    });
  }

  // (every example in dark, with all of WCAG 2.2 AA's rules: tests/e2e/a11y.test.mjs)
  test("an input error (the red message and border) in dark", async () => {
    const { context, page } = await open(env.browser, { colorScheme: "dark", bypassCSP: true });
    try {
      await visit(page, env.url, "index.html", "#/gsd?dpi=-5");
      assert.deepEqual(await axeProblems(page), []);
    } finally {
      await context.close();
    }
  });

  test("every figure canvas has a text alternative with numbers", async () => {
    const { context, page } = await open(env.browser);
    try {
      const missing = [];
      for (const id of ids) {
        await visit(page, env.url, "embed.html", `#/${id}`);
        const labels = await page.$$eval(".figure-canvas", (cs) => cs.map((c) => `${c.getAttribute("role")}|${c.getAttribute("aria-label") ?? ""}`));
        for (const l of labels) {
          const [role, label] = l.split("|");
          // a picture, or a figure the keyboard operates (docs/figures.md: role group, described as an interactive figure)
          if (!["img", "group"].includes(role) || label.length < 20 || !/\d/.test(label) || /not drawn yet/.test(label)) missing.push(`${id}: ${l.slice(0, 80)}`);
        }
      }
      assert.deepEqual(missing, []);
    } finally {
      await context.close();
    }
  });
});
