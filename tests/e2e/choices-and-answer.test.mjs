// End-to-end (issue 29, item 9): a select box never cuts its option's text
// (every example, 390 and 1280 px: the chosen option's text, wrapped at the
// box's width, fits inside the box); an answer with no value says why
// (resample's bicubic value off the patch); and the answer line is greyed
// with the rest of a stale solution.

import assert from "node:assert/strict";
import { after, before, describe, test } from "node:test";
import { CATALOG_IDS, TEST_TIMEOUT, open, settled, start, visit } from "./harness.mjs";

/**
 * Each select of the form: its chosen option's text, and the height that text
 * takes wrapped at the width the box leaves it (a probe in the same font),
 * against the box's own height; and whether it is on one line at most.
 */
async function selectFits(page) {
  return page.evaluate(() =>
    [...document.querySelectorAll(".inputs .field select")].map((s) => {
      const cs = getComputedStyle(s);
      const text = s.selectedOptions[0]?.textContent ?? "";
      // the text's room: the box less its padding and the picker's arrow with the gap before it
      // (the arrow's own width where the browser says it, else 1.5em)
      const icon = parseFloat(getComputedStyle(s, "::picker-icon").width);
      const arrow = Number.isFinite(icon) ? icon + (parseFloat(cs.columnGap) || 0) : 1.5 * parseFloat(cs.fontSize);
      const room = s.clientWidth - parseFloat(cs.paddingLeft) - parseFloat(cs.paddingRight) - arrow;
      const probe = document.createElement("div");
      Object.assign(probe.style, { position: "absolute", visibility: "hidden", font: cs.font, lineHeight: cs.lineHeight, width: `${room}px`, whiteSpace: "normal", overflowWrap: "normal" });
      probe.textContent = text;
      document.body.append(probe);
      const need = probe.getBoundingClientRect().height;
      probe.style.width = "auto";
      probe.style.whiteSpace = "nowrap";
      const oneLine = probe.getBoundingClientRect().width <= room;
      probe.remove();
      const inner = s.clientHeight - parseFloat(cs.paddingTop) - parseFloat(cs.paddingBottom);
      return { name: s.name, text, room: Math.round(room), need: Math.round(need), inner: Math.round(inner), oneLine, overflow: s.scrollWidth > s.clientWidth + 1 };
    }),
  );
}

describe("choices, answers with no value, stale answers", { timeout: 20 * TEST_TIMEOUT }, () => {
  let env;
  before(async () => {
    env = await start();
  });
  after(async () => {
    await env?.close();
  });

  for (const width of [390, 1280]) {
    test(`no select cuts its option's text (every example, ${width} px)`, { timeout: 8 * TEST_TIMEOUT }, async () => {
      const { context, page, log } = await open(env.browser, { viewport: { width, height: 900 } });
      try {
        let checked = 0;
        const cut = [];
        for (const id of CATALOG_IDS) {
          await visit(page, env.url, "index.html", `#/${id}`);
          for (const s of await selectFits(page)) {
            checked += 1;
            // wrapped (where it does not fit one line), the text's lines fit in the box's height
            if (s.overflow || (!s.oneLine && s.inner + 1 < s.need)) cut.push(`${id}: ${s.name} "${s.text}" needs ${s.need} px of height at ${s.room} px, the box gives ${s.inner}`);
          }
        }
        assert.ok(checked >= 15, `selects checked: ${checked}`);
        assert.deepEqual(cut, []);
        // the long ones the issue named
        await visit(page, env.url, "index.html", "#/chain-code");
        const given = (await selectFits(page)).find((s) => s.name === "given");
        assert.match(given.text, /^Pixels in order \(an edge; repeat the first to close it\)$/);
        assert.equal(await page.locator('select[name="given"]').getAttribute("title"), given.text);
        assert.deepEqual(log.pageErrors, []);
      } finally {
        await context.close();
      }
    });
  }

  test("resample: the answer line says why there is no bicubic value", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser, { viewport: { width: 1280, height: 900 } });
    try {
      // a position whose 16 neighbours are not all in the 4×4 patch
      assert.equal(await visit(page, env.url, "index.html", "#/resample?c=545.3&r=817.24"), "ok");
      const item = page.locator('.answer-line .answer-item[data-key="bicubic"]');
      const text = (await item.innerText()).replace(/\s+/g, " ");
      assert.doesNotMatch(text, /= —/, text);
      assert.match(text, /= no value — .*16 pixels.*\(note \d+\)/, text);
      // the link goes to the note that says it
      const href = await item.locator("a.note-link").getAttribute("href");
      const note = await page.locator(href).innerText();
      assert.match(note, /No bicubic value here/);
      // a position with a value: the number, no reason
      // (the seed's own position has none either: its 4×4 patch ends a column short)
      assert.equal(await visit(page, env.url, "index.html", "#/resample?c=546.44&r=818.24"), "ok");
      const valued = await page.locator('.answer-line .answer-item[data-key="bicubic"]').innerText();
      assert.match(valued, /= \d+(\.\d+)?/, valued);
      assert.doesNotMatch(valued, /no value/);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("a stale solution greys its answer line like the rest", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser, { viewport: { width: 1280, height: 900 } });
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/gsd"), "ok");
      const opacity = (sel) => page.evaluate((s) => Number(getComputedStyle(document.querySelector(s)).opacity), sel);
      assert.equal(await opacity(".answer-line"), 1);
      await page.locator(".field input[type=text]").first().fill("abc");
      assert.equal(await settled(page), "invalid");
      const steps = await opacity(".steps-panel");
      assert.ok(steps < 1, `the steps are greyed (${steps})`);
      assert.equal(await opacity(".answer-line"), steps, "the answer line is greyed as the steps are");
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });
});
