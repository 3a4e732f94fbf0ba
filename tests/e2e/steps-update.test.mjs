// An input change updates the steps in place (render.js updateSteps: only the
// formulas that changed are rendered and fitted again). What it shows must be
// what a cold load of the same inputs shows, for every example: the steps'
// markup is compared, after a change and after the change back.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import { CATALOG_IDS, TEST_TIMEOUT, open, settled, start, stepsHtml, visit } from "./harness.mjs";

let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

/**
 * Changes one number of the first input that has one (a nearby value that
 * still solves); returns the new address, or null when none solves.
 */
async function changeOne(page) {
  return page.evaluate(async () => {
    // a frame, and then until the steps, result and notes are in (app.js inputChanged: "updating")
    const settle = async () => {
      do await new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0)));
      while (document.body.dataset.status === "updating");
    };
    const inputs = [...document.querySelectorAll(".input-form .field")]
      .filter((w) => !w.hidden && !w.classList.contains("field-choice") && !w.classList.contains("field-flag"))
      .map((w) => w.querySelector("input[type=text], textarea"))
      .filter((i) => i && !i.disabled && /\d/.test(i.value));
    for (const input of inputs) {
      const seed = input.value;
      const m = /-?\d+(?:\.\d+)?/.exec(seed);
      const v = Number(m[0]);
      const near = /\./.test(m[0]) ? [v * 1.01, v * 0.99].map((x) => String(Number(x.toPrecision(6)))) : [v + 1, v - 1].map(String);
      for (const t of near) {
        input.value = seed.slice(0, m.index) + t + seed.slice(m.index + m[0].length);
        input.dispatchEvent(new Event("input", { bubbles: true }));
        await settle();
        if (document.body.dataset.status === "ok") return location.hash;
      }
      input.value = seed;
      input.dispatchEvent(new Event("input", { bubbles: true }));
      await settle();
    }
    return null;
  });
}

describe("the steps after an input change are those of a cold load", () => {
  for (const [file, id, options] of [...CATALOG_IDS.map((id) => ["index.html", id, ""]), ["embed.html", "gsd", "?steps=collapsed&step=2"]]) {
    test(`${file} ${id}${options}`, { timeout: TEST_TIMEOUT }, async () => {
      const a = await open(env.browser);
      const b = await open(env.browser);
      try {
        assert.equal(await visit(a.page, env.url, file, `#/${id}${options}`), "ok");
        const seedHash = await a.page.evaluate(() => location.hash);
        const seedHtml = await stepsHtml(a.page);
        const hash = await changeOne(a.page);
        assert.ok(hash, `${id}: a nearby value of some input solves`);
        assert.notEqual(hash, seedHash);
        const changed = await stepsHtml(a.page);
        // the same inputs, cold (the embed's options ride along in the address)
        assert.equal(await visit(b.page, env.url, file, hash), "ok");
        const cold = await stepsHtml(b.page);
        assert.equal(changed, cold, `${id}: the updated steps differ from a cold load of ${hash}`);
        // and back to the seed's values
        await a.page.evaluate(() => document.querySelector(".actions button").click());
        assert.equal(await settled(a.page), "ok");
        assert.equal(await stepsHtml(a.page), seedHtml, `${id}: back to the seed's values`);
        assert.deepEqual(a.log.pageErrors, []);
      } finally {
        await a.context.close();
        await b.context.close();
      }
    });
  }
});
