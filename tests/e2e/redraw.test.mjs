// An input change redraws the figure in its own frame; the steps, result and
// notes follow after that frame (app.js inputChanged): until then their panels
// are marked busy (aria-busy, "updating") and the status is not "ok", and once
// in they are those of a cold load. A fast series of changes ends with the last
// one's steps, rendered once; an invalid input while they wait first shows the
// waiting solution whole; an embed host hears "solved" only with the steps in.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import { TEST_TIMEOUT, open, start, stepsHtml, visit, within } from "./harness.mjs";

/** A step's bound: a hang says which step and what the page was doing (within). */
const STEP = 25_000;

let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

/**
 * Puts window.__settle() (frames until the steps are in) and window.__find()
 * into the page; __find(): the first text input holding a number,
 * its seed text and up to 4 texts with that number changed that solve (each
 * tried, then the seed put back and settled), with the address each left
 * (the address follows a change once its steps are in).
 */
async function install(page) {
  await page.evaluate(`window.__settle = async () => {
    do await new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0)));
    while (document.body.dataset.status === "updating");
  };
  window.__find = async () => {
    const settle = window.__settle;
    const input = [...document.querySelectorAll(".input-form .field")]
      .filter((w) => !w.hidden && !w.classList.contains("field-choice") && !w.classList.contains("field-flag"))
      .map((w) => w.querySelector("input[type=text], textarea"))
      .find((i) => i && !i.disabled && /\\d/.test(i.value));
    const seed = input.value;
    const m = /-?\\d+(?:\\.\\d+)?/.exec(seed);
    const v = Number(m[0]);
    const near = /\\./.test(m[0]) ? [1.01, 1.02, 1.03, 1.04, 1.05, 0.99, 0.98].map((k) => String(Number((v * k).toPrecision(6)))) : [1, 2, 3, 4, 5, 6, 7, 8, -1, -2].map((k) => String(v + k));
    const texts = [];
    const hashes = [];
    for (const t of near) {
      if (texts.length === 4) break;
      input.value = seed.slice(0, m.index) + t + seed.slice(m.index + m[0].length);
      input.dispatchEvent(new Event("input", { bubbles: true }));
      await settle();
      if (document.body.dataset.status === "ok") {
        texts.push(input.value);
        hashes.push(location.hash);
      }
    }
    input.value = seed;
    input.dispatchEvent(new Event("input", { bubbles: true }));
    await settle();
    return { input, seed, texts, hashes };
  }`);
}

for (const id of ["ncc-1d", "lsm-affine"]) {
  describe(`${id}: the figure first, the steps right after`, () => {
    test("the figure is new in the change's frame, the steps busy until they are in, then those of a cold load", { timeout: 2 * TEST_TIMEOUT }, async () => {
      const a = await open(env.browser);
      const b = await open(env.browser);
      try {
        assert.equal(await visit(a.page, env.url, "index.html", `#/${id}`), "ok");
        await install(a.page);
        const seen = await within(a.page, STEP, `${id}: a change and its frame`, a.page.evaluate(async () => {
          const { input, texts, hashes } = await window.__find();
          const canvas = document.querySelector(".figure-section canvas");
          const panels = [".steps-panel", ".result-section", ".notes-section"].map((s) => document.querySelector(s));
          const before = { pixels: canvas.toDataURL(), steps: document.querySelector(".steps-body").innerHTML };
          input.value = texts[0];
          input.dispatchEvent(new Event("input", { bubbles: true }));
          const now = {
            pixels: canvas.toDataURL() !== before.pixels,
            stepsOld: document.querySelector(".steps-body").innerHTML === before.steps,
            busy: panels.map((p) => p.getAttribute("aria-busy") === "true" && p.classList.contains("updating")),
            status: document.body.dataset.status,
          };
          // the change's frame: the figure is painted, the steps are still waiting
          const frame = await new Promise((r) =>
            requestAnimationFrame(() => r({ pixels: canvas.toDataURL() !== before.pixels, busy: panels.map((p) => p.getAttribute("aria-busy") === "true"), status: document.body.dataset.status })),
          );
          return { now, frame, hash: hashes[0] };
        }), a.log);
        assert.deepEqual(seen.now, { pixels: true, stepsOld: true, busy: [true, true, true], status: "updating" });
        assert.deepEqual(seen.frame, { pixels: true, busy: [true, true, true], status: "updating" });
        const changed = await within(a.page, STEP, `${id}: the change's steps`, stepsHtml(a.page), a.log);
        assert.deepEqual(await a.page.evaluate(() => [...document.querySelectorAll(".panel[aria-busy], .panel.updating")].length), 0);
        assert.equal(await a.page.evaluate(() => location.hash), seen.hash, "the address follows the change once its steps are in");
        assert.equal(await within(b.page, STEP, `${id}: a cold load of ${seen.hash}`, visit(b.page, env.url, "index.html", seen.hash), b.log), "ok");
        assert.equal(changed, await within(b.page, STEP, `${id}: the cold load's steps`, stepsHtml(b.page), b.log), `${id}: the steps after the change differ from a cold load of ${seen.hash}`);
        assert.deepEqual(a.log.pageErrors, []);
      } finally {
        await a.context.close();
        await b.context.close();
      }
    });

    test("a fast series of changes ends with the last one's steps, rendered once", { timeout: 2 * TEST_TIMEOUT }, async () => {
      const a = await open(env.browser);
      const b = await open(env.browser);
      try {
        assert.equal(await visit(a.page, env.url, "index.html", `#/${id}`), "ok");
        await install(a.page);
        const found = await within(a.page, STEP, `${id}: finding four inputs that solve`, a.page.evaluate(async () => {
          const { input, texts } = await window.__find();
          window.__settled = 0;
          new PerformanceObserver((list) => (window.__settled += list.getEntriesByName("settled").length)).observe({ type: "measure" });
          for (const t of texts.slice(0, 4)) {
            input.value = t;
            input.dispatchEvent(new Event("input", { bubbles: true }));
          }
          return texts.length;
        }), a.log);
        assert.ok(found >= 2, `${id}: only ${found} nearby inputs solve`);
        const changed = await within(a.page, STEP, `${id}: the series' steps`, stepsHtml(a.page), a.log);
        // the settled measure comes a frame after the steps
        await within(a.page, STEP, `${id}: the "settled" measure`, a.page.waitForFunction(() => window.__settled > 0, null, { timeout: 0 }), a.log);
        // the address, written with the steps: the last change's
        const hash = await a.page.evaluate(() => location.hash);
        assert.equal(await a.page.evaluate(() => window.__settled), 1, "the steps were rendered once, for the last change");
        assert.equal(await within(b.page, STEP, `${id}: a cold load of ${hash}`, visit(b.page, env.url, "index.html", hash), b.log), "ok");
        assert.equal(changed, await within(b.page, STEP, `${id}: the cold load's steps`, stepsHtml(b.page), b.log), `${id}: the steps after the series differ from a cold load of ${hash}`);
        assert.deepEqual(a.log.pageErrors, []);
      } finally {
        await a.context.close();
        await b.context.close();
      }
    });
  });
}

test("an invalid input while the steps wait: the waiting solution is shown whole, then marked stale", { timeout: TEST_TIMEOUT }, async () => {
  const a = await open(env.browser);
  const b = await open(env.browser);
  try {
    assert.equal(await visit(a.page, env.url, "index.html", "#/ncc-1d"), "ok");
    await install(a.page);
    const seen = await a.page.evaluate(async () => {
      const { input, seed, texts, hashes } = await window.__find();
      input.value = texts[0];
      input.dispatchEvent(new Event("input", { bubbles: true }));
      const hash = hashes[0];
      input.value = `${seed}x`;
      input.dispatchEvent(new Event("input", { bubbles: true }));
      return { hash, status: document.body.dataset.status, busy: document.querySelectorAll(".panel[aria-busy]").length, banner: document.querySelector(".stale-banner").hidden };
    });
    assert.deepEqual({ status: seen.status, busy: seen.busy, banner: seen.banner }, { status: "invalid", busy: 0, banner: false });
    const shown = await a.page.evaluate(() => document.querySelector(".steps-body").innerHTML);
    assert.equal(await visit(b.page, env.url, "index.html", seen.hash), "ok");
    await b.page.evaluate(() => document.fonts.ready);
    assert.equal(shown, await b.page.evaluate(() => document.querySelector(".steps-body").innerHTML), "the steps are the last valid inputs' steps");
    assert.deepEqual(a.log.pageErrors, []);
  } finally {
    await a.context.close();
    await b.context.close();
  }
});

test("embed: the page says solved (and posts its change) only with the steps in", { timeout: TEST_TIMEOUT }, async () => {
  const a = await open(env.browser);
  try {
    assert.equal(await visit(a.page, env.url, "embed.html", "#/gsd"), "ok");
    await install(a.page);
    const seen = await a.page.evaluate(async () => {
      const { input, texts } = await window.__find();
      const events = [];
      window.addEventListener("playground-solved", () => events.push({ busy: document.querySelectorAll(".panel[aria-busy]").length, status: document.body.dataset.status }));
      input.value = texts[0];
      input.dispatchEvent(new Event("input", { bubbles: true }));
      const during = events.length;
      await new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0)));
      for (let i = 0; i < 50 && document.body.dataset.status === "updating"; i++) await new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0)));
      return { during, events };
    });
    assert.equal(seen.during, 0, "nothing said while the steps wait");
    assert.deepEqual(seen.events, [{ busy: 0, status: "ok" }]);
  } finally {
    await a.context.close();
  }
});

test("leaving the seed's values shortens the answer line, and nothing below it moves; a new width starts afresh", { timeout: TEST_TIMEOUT }, async () => {
  const a = await open(env.browser);
  try {
    assert.equal(await visit(a.page, env.url, "index.html", "#/ncc-1d"), "ok");
    await install(a.page);
    const seen = await a.page.evaluate(async () => {
      const { input, seed, texts } = await window.__find();
      const line = document.querySelector(".answer-line");
      const top = () => Math.round(document.querySelector(".layout").getBoundingClientRect().top);
      const natural = () => {
        const kept = line.style.minHeight;
        line.style.minHeight = "";
        const h = line.offsetHeight;
        line.style.minHeight = kept;
        return h;
      };
      const type = async (text) => {
        input.value = text;
        input.dispatchEvent(new Event("input", { bubbles: true }));
        await window.__settle();
      };
      const at = (label) => ({ label, printed: /course notes print/.test(line.textContent), height: line.offsetHeight, natural: natural(), top: top() });
      const out = [at("seed")];
      await type(texts[0]);
      out.push(at("changed"));
      await type(seed);
      out.push(at("seed again"));
      await type(texts[0]);
      return out;
    });
    const [s, c, s2] = seen;
    assert.deepEqual([s.printed, c.printed, s2.printed], [true, false, true], "the printed value is shown with the seed's inputs only");
    assert.ok(c.natural < s.natural, `the line without the printed value is shorter (${c.natural} < ${s.natural} px): else this test shows nothing`);
    assert.deepEqual(
      seen.map((x) => [x.height, x.top]),
      seen.map(() => [s.height, s.top]),
      "the answer line keeps its height and the panels below stay put",
    );
    // a phone: the room kept at 1280 px goes; the line is its own height at the new width
    await a.page.setViewportSize({ width: 390, height: 844 });
    await a.page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    const phone = await a.page.evaluate(() => {
      const line = document.querySelector(".answer-line");
      const kept = line.offsetHeight;
      line.style.minHeight = "";
      return { kept, natural: line.offsetHeight };
    });
    assert.equal(phone.kept, phone.natural, "at a new width the answer line keeps no extra room");
    assert.deepEqual(a.log.pageErrors, []);
  } finally {
    await a.context.close();
  }
});

test("a valid change rewrites nothing in the form: no field's error, aria-invalid or class is touched", { timeout: TEST_TIMEOUT }, async () => {
  const a = await open(env.browser);
  try {
    assert.equal(await visit(a.page, env.url, "index.html", "#/lsm-2d"), "ok");
    await install(a.page);
    const seen = await a.page.evaluate(async () => {
      const { input, texts } = await window.__find();
      const form = document.querySelector(".input-form");
      const changes = [];
      const note = (list) => {
        for (const m of list) if (m.target !== input) changes.push(`${m.type} ${m.attributeName ?? ""} on ${m.target.id || m.target.className || m.target.nodeName}`);
      };
      const observer = new MutationObserver(note);
      observer.observe(form, { attributes: true, childList: true, subtree: true, characterData: true });
      input.value = texts[0];
      input.dispatchEvent(new Event("input", { bubbles: true }));
      await new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0)));
      note(observer.takeRecords());
      const valid = [...changes];
      // an invalid text: its field says so, and only its field
      input.value = "x";
      input.dispatchEvent(new Event("input", { bubbles: true }));
      const marked = [...form.querySelectorAll("[aria-invalid=true]")].map((n) => n === input);
      const errors = [...form.querySelectorAll(".field-error")].filter((p) => !p.hidden).length;
      observer.disconnect();
      return { changes: valid, fields: form.querySelectorAll(".field").length, marked, errors };
    });
    assert.ok(seen.fields > 3, "lsm-2d has several fields");
    assert.deepEqual(seen.changes, [], "nothing in the form changed but the input typed in");
    assert.deepEqual(seen.marked, [true], "the invalid field alone is marked");
    assert.equal(seen.errors, 1);
    assert.deepEqual(a.log.pageErrors, []);
  } finally {
    await a.context.close();
  }
});
