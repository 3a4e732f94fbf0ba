// An input change updates the steps in place (render.js updateSteps: only the
// formulas that changed are rendered and fitted again). What it shows must be
// what a cold load of the same inputs shows, for every example: the steps'
// markup is compared, after a change and after the change back.
//
// Lean: two lanes of two pages each (each page in a context of its own, its
// HTTP cache warm after the first load), the examples shared between the
// lanes (node:test runs two at a time). A lane's first page goes from example
// to example by the address's hash (a route of the page already loaded, as a
// reader's link would); its second page is the cold load: about:blank, then
// the changed address loaded afresh (a new document: nothing of the first
// page's state).
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import { CATALOG_IDS, TEST_TIMEOUT, open, settled, start, stepsHtml, visit } from "./harness.mjs";

/** Pages at work at once: the page waits on frames most of the time, so two share two cores well. */
const LANES = 2;

let env;
const contexts = [];
const pageErrors = [];
const lanes = [];
const waiting = [];
before(async () => {
  env = await start();
  // a context for each page: in one context only the page opened last gets its frames at full
  // rate (the others' requestAnimationFrame runs about once a second in headless Chromium)
  const page = async () => {
    const { context, page: p } = await open(env.browser);
    contexts.push(context);
    p.on("pageerror", (e) => pageErrors.push(e.message));
    return p;
  };
  for (let i = 0; i < LANES; i++) lanes.push({ a: await page(), b: await page(), file: null });
});
after(async () => {
  for (const c of contexts) await c.close();
  await env?.close();
});

/** A free lane (waits for one), given back by `release`. */
async function lane() {
  const free = lanes.find((l) => !l.busy);
  if (free) {
    free.busy = true;
    return free;
  }
  return new Promise((resolve) => waiting.push(resolve));
}
function release(l) {
  const next = waiting.shift();
  if (next) next(l);
  else l.busy = false;
}

/**
 * Shows `file#hash` on the lane's first page: a route of the page already
 * there when it is the same file (the status set aside first, so that the
 * old "ok" is not taken for the new one), else a load.
 */
async function show(l, file, hash) {
  if (l.file !== file) {
    l.file = file;
    return visit(l.a, env.url, file, hash);
  }
  await l.a.evaluate((h) => {
    document.body.dataset.status = "routing";
    location.hash = h;
  }, hash);
  return settled(l.a);
}

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

describe("the steps after an input change are those of a cold load", { concurrency: LANES }, () => {
  for (const [file, id, options] of [...CATALOG_IDS.map((id) => ["index.html", id, ""]), ["embed.html", "gsd", "?steps=collapsed&step=2"]]) {
    test(`${file} ${id}${options}`, { timeout: TEST_TIMEOUT }, async () => {
      const l = await lane();
      try {
        assert.equal(await show(l, file, `#/${id}${options}`), "ok");
        const seedHash = await l.a.evaluate(() => location.hash);
        const seedHtml = await stepsHtml(l.a);
        const hash = await changeOne(l.a);
        assert.ok(hash, `${id}: a nearby value of some input solves`);
        assert.notEqual(hash, seedHash);
        const changed = await stepsHtml(l.a);
        // the same inputs, cold (the embed's options ride along in the address): a new document
        await l.b.goto("about:blank");
        assert.equal(await visit(l.b, env.url, file, hash), "ok");
        const cold = await stepsHtml(l.b);
        assert.equal(changed, cold, `${id}: the updated steps differ from a cold load of ${hash}`);
        // and back to the seed's values
        await l.a.evaluate(() => document.querySelector(".actions button").click());
        assert.equal(await settled(l.a), "ok");
        assert.equal(await stepsHtml(l.a), seedHtml, `${id}: back to the seed's values`);
        assert.deepEqual(pageErrors, []);
      } finally {
        release(l);
      }
    });
  }
});
