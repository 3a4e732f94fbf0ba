// Practice mode as a student and an instructor use it: a practice link, a
// known mistake named, an error carried forward accepted as consistent, the
// hint ladder, answers kept over a reload, a printed worksheet with its key,
// and answer events posted from an embed to its host page.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import { TEST_TIMEOUT, open, start } from "./harness.mjs";

const CODE = "1K7Q2";
const LINK = `#/gsd?practice=${CODE}`;
const WAIT = 15_000;

let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

/** Loads a practice page and waits for it to be ready. */
async function visitPractice(page, file, hash, status = "practice") {
  await page.goto(`${env.url}${file}${hash}`);
  await page.waitForFunction((s) => document.body.dataset.status === s, status, { timeout: WAIT });
}

/** The variant's inputs and exact results, from the page's own wasm module. */
async function variantOf(page, id, code) {
  return page.evaluate(
    async ([i, c]) => {
      const m = await import("./pkg/photogrammetry_playground.js");
      await m.default(); // the one-package API (a no-op when the page loaded it already)
      const p = m.practice(i, c);
      return { inputs: p.inputs, result: m.solve(i, p.inputs).result };
    },
    [id, code],
  );
}

function box(page, key) {
  return page.locator(`.answer[data-key="${key}"]`);
}

async function answer(page, key, text) {
  const input = box(page, key).locator("input");
  await input.fill(text);
  await input.press("Tab");
}

async function feedback(page, key) {
  return (await box(page, key).locator(".answer-feedback").innerText({ timeout: WAIT })).trim();
}

function noErrors(log) {
  assert.deepEqual(log.pageErrors, []);
  assert.deepEqual(log.consoleErrors, []);
}

describe("a practice variant", () => {
  test("opens from its link with its givens and boxes; the example page links to practice", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      await visitPractice(page, "index.html", LINK);
      assert.equal(await page.locator("#practice-title").innerText(), "Practice: Ground sample distance");
      assert.match(await page.locator(".example-meta").innerText(), new RegExp(`Variant ${CODE}`));
      const v = await variantOf(page, "gsd", CODE);
      const givens = await page.locator(".givens").innerText();
      assert.ok(givens.includes(`${v.inputs.dpi} dpi`), givens);
      assert.ok(givens.includes(`${v.inputs.flying_height_m} m`), givens);
      assert.deepEqual(await page.locator(".answer").evaluateAll((xs) => xs.map((x) => x.dataset.key)), ["scale_denominator", "pixel_size_mm", "gsd_mm", "gsd_cm"]);
      assert.match(await box(page, "gsd_cm").locator(".answer-tolerance").innerText(), /Tolerance ± 0\.2 %/);
      assert.equal((await page.locator(".practice-score").innerText()).trim(), "Score: 0 of 4");
      // the worked example has a Practice link to this mode
      await page.goto(`${env.url}index.html#/gsd`);
      await page.waitForFunction(() => document.body.dataset.status === "ok", null, { timeout: WAIT });
      await page.locator("a.practice-link").click();
      await page.waitForFunction(() => document.body.dataset.status === "practice", null, { timeout: WAIT });
      assert.match(page.url(), /#\/gsd\?practice=1[0-9A-Z]{4}$/);
      noErrors(log);
    } finally {
      await context.close();
    }
  });

  test("a known mistake is named; a right answer with a decimal comma is read and correct", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      await visitPractice(page, "index.html", LINK);
      const v = await variantOf(page, "gsd", CODE);
      // H / f with f left in millimetres
      await answer(page, "scale_denominator", String(v.inputs.flying_height_m / v.inputs.focal_length_mm));
      assert.equal(await box(page, "scale_denominator").getAttribute("data-verdict"), "wrong");
      assert.equal(await box(page, "scale_denominator").getAttribute("data-mistake"), "millimetres vs metres");
      assert.match(await feedback(page, "scale_denominator"), /millimetres vs metres/);
      const m = v.result.scale_denominator.toFixed(2);
      await answer(page, "scale_denominator", m.replace(".", ","));
      assert.equal(await box(page, "scale_denominator").getAttribute("data-verdict"), "correct");
      assert.equal(await box(page, "scale_denominator").locator(".answer-read").innerText(), `read as ${m}`);
      // a malformed entry is not counted as wrong
      await answer(page, "gsd_cm", "3..5");
      assert.equal(await box(page, "gsd_cm").getAttribute("data-verdict"), "unreadable");
      assert.match(await feedback(page, "gsd_cm"), /not counted as wrong/);
      assert.equal((await page.locator(".practice-score").innerText()).trim(), "Score: 1 of 4");
      noErrors(log);
    } finally {
      await context.close();
    }
  });

  test("an error carried forward is consistent with the earlier step, and a reload keeps the answers", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      await visitPractice(page, "index.html", LINK);
      const v = await variantOf(page, "gsd", CODE);
      const m = v.result.scale_denominator;
      const wrongP = 25 / v.inputs.dpi; // 25 instead of 25.4 mm per inch
      await answer(page, "scale_denominator", m.toFixed(3));
      await answer(page, "pixel_size_mm", wrongP.toFixed(6));
      await answer(page, "gsd_mm", (wrongP * m).toFixed(3));
      assert.equal(await box(page, "pixel_size_mm").getAttribute("data-verdict"), "wrong");
      assert.equal(await box(page, "gsd_mm").getAttribute("data-verdict"), "consistent");
      assert.match(await feedback(page, "gsd_mm"), /Consistent with your Pixel size \(step 2\)/);
      assert.equal((await page.locator(".practice-score").innerText()).trim(), "Score: 2 of 4");
      await page.reload();
      await page.waitForFunction(() => document.body.dataset.status === "practice", null, { timeout: WAIT });
      assert.equal(await box(page, "gsd_mm").locator("input").inputValue(), (wrongP * m).toFixed(3));
      assert.equal(await box(page, "gsd_mm").getAttribute("data-verdict"), "consistent");
      assert.equal((await page.locator(".practice-score").innerText()).trim(), "Score: 2 of 4");
      // the stored progress is the code and the raw texts only
      const stored = await page.evaluate(() => JSON.parse(localStorage.getItem("photogrammetry-playground:practice:v1")));
      assert.deepEqual(Object.keys(stored.gsd).sort(), ["answers", "code"]);
      assert.equal(stored.gsd.code, CODE);
      // the overview counts it under its topic
      await page.goto(`${env.url}index.html#/practice`);
      await page.waitForFunction(() => document.body.dataset.status === "practice-overview", null, { timeout: WAIT });
      const coords = await page.locator('.overview-topic[data-topic="Coordinates"]').innerText();
      assert.match(coords, /2 of 4 points/);
      assert.match(coords, new RegExp(`variant ${CODE}`));
      noErrors(log);
    } finally {
      await context.close();
    }
  });

  test("separate verdicts for the value, the precision and the unit", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      await visitPractice(page, "index.html", LINK);
      const v = await variantOf(page, "gsd", CODE);
      const parts = (key) => box(page, key).locator(".verdict-part").evaluateAll((xs) => xs.map((x) => [x.dataset.part, x.dataset.kind, x.textContent.replace(/^\S+\s/, "")]));
      // the right number in the wrong unit: value right, unit wrong
      await answer(page, "gsd_mm", `${v.result.gsd_mm.toFixed(3)} px`);
      assert.equal(await box(page, "gsd_mm").getAttribute("data-verdict"), "wrong");
      assert.deepEqual(await parts("gsd_mm"), [
        ["value", "ok", "Value: right"],
        ["unit", "bad", "Unit: wrong, this box is in mm"],
      ]);
      // the right number to too few digits (± 0.2 %): value right, precision coarse
      const x = v.result.gsd_cm;
      const allowed = 0.002 * x;
      const coarse = [1, 2, 3]
        .map((d) => x.toPrecision(d))
        .filter((t) => !t.includes("e"))
        .find((t) => {
          const halfUlp = 0.5 * 10 ** (Math.floor(Math.log10(Math.abs(Number(t)))) - (t.replace(/[^0-9]/g, "").replace(/^0+/, "").length - 1));
          return Math.abs(Number(t) - x) > allowed && halfUlp > allowed && halfUlp <= Math.max(10 * allowed, 0.005 * x);
        });
      assert.ok(coarse, `no coarse rounding of ${x}`);
      await answer(page, "gsd_cm", `${coarse} cm`);
      assert.equal(await box(page, "gsd_cm").getAttribute("data-verdict"), "imprecise");
      assert.deepEqual(await parts("gsd_cm"), [
        ["value", "ok", "Value: right"],
        ["precision", "bad", "Precision: too few digits"],
        ["unit", "ok", "Unit: cm"],
      ]);
      // a bare right number: all three fine, the unit taken as the box's
      await answer(page, "pixel_size_mm", String(v.result.pixel_size_mm));
      assert.deepEqual(await parts("pixel_size_mm"), [
        ["value", "ok", "Value: right"],
        ["precision", "ok", "Precision: enough digits"],
        ["unit", "info", "Unit: none typed, taken as mm"],
      ]);
      // a box without a unit has no unit line
      await answer(page, "scale_denominator", "1");
      assert.deepEqual(await parts("scale_denominator"), [["value", "bad", "Value: off"]]);
      noErrors(log);
    } finally {
      await context.close();
    }
  });

  test("a box shows how it was read before it is graded", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      await visitPractice(page, "index.html", LINK);
      const b = box(page, "gsd_mm");
      await b.locator("input").fill("1,25e2 mm");
      assert.equal(await b.locator(".answer-read").innerText(), "read as 125 mm");
      // not graded yet: no verdict, no feedback, no verdict lines
      assert.equal(await b.getAttribute("data-verdict"), "");
      assert.equal((await b.locator(".answer-feedback").innerText()).trim(), "");
      assert.equal(await b.locator(".verdict-part").count(), 0);
      await b.locator("input").fill("3/4");
      assert.equal(await b.locator(".answer-read").innerText(), "read as 0.75");
      await b.locator("input").press("Tab");
      assert.equal(await b.getAttribute("data-verdict"), "wrong");
      noErrors(log);
    } finally {
      await context.close();
    }
  });

  test("New variant: a new code in the link, empty boxes, the old variant's answers kept out", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      await visitPractice(page, "index.html", LINK);
      const v = await variantOf(page, "gsd", CODE);
      await answer(page, "scale_denominator", v.result.scale_denominator.toFixed(2));
      assert.equal(await box(page, "scale_denominator").getAttribute("data-verdict"), "correct");
      await page.getByRole("button", { name: "New variant" }).click();
      await page.waitForFunction((c) => document.querySelector("article.practice")?.dataset.code !== c, CODE, { timeout: WAIT });
      await page.waitForFunction(() => document.body.dataset.status === "practice", null, { timeout: WAIT });
      const code = await page.locator("article.practice").getAttribute("data-code");
      assert.match(code, /^1[0-9A-Z]{4}$/);
      assert.notEqual(code, CODE);
      assert.match(page.url(), new RegExp(`#/gsd\\?practice=${code}$`));
      assert.match(await page.locator(".example-meta").innerText(), new RegExp(`Variant ${code}`));
      assert.deepEqual(await page.locator(".answer input").evaluateAll((xs) => xs.map((x) => x.value)), ["", "", "", ""]);
      assert.equal(await page.locator(".answer[data-verdict=correct]").count(), 0);
      assert.equal((await page.locator(".practice-score").innerText()).trim(), "Score: 0 of 4");
      // its givens are the new variant's
      const w = await variantOf(page, "gsd", code);
      assert.ok((await page.locator(".givens").innerText()).includes(`${w.inputs.flying_height_m} m`));
      noErrors(log);
    } finally {
      await context.close();
    }
  });

  test("UTM: the zone and easting graded, the forgotten false easting named, the meridian carried from the student's zone", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      await visitPractice(page, "index.html", `#/utm?practice=${CODE}`);
      const v = await variantOf(page, "utm", CODE);
      assert.equal(await page.locator(".answer").count(), 12);
      // a zone off by one, then the central meridian that follows from it: consistent
      const zone = v.result.zone + 1;
      await answer(page, "zone", String(zone));
      assert.equal(await box(page, "zone").getAttribute("data-verdict"), "wrong");
      await answer(page, "central_meridian", String(6 * zone - 183));
      assert.equal(await box(page, "central_meridian").getAttribute("data-verdict"), "consistent");
      assert.match(await feedback(page, "central_meridian"), /Consistent with your Zone \(step 1\)/);
      // the right zone: correct
      await answer(page, "zone", String(v.result.zone));
      assert.equal(await box(page, "zone").getAttribute("data-verdict"), "correct");
      // the easting without its 500 000 m: named
      await answer(page, "easting", (v.result.easting - 500000).toFixed(3));
      assert.equal(await box(page, "easting").getAttribute("data-verdict"), "wrong");
      assert.equal(await box(page, "easting").getAttribute("data-mistake"), "false easting forgotten");
      // the easting to the centimetre (the box's tolerance), with a decimal comma
      await answer(page, "easting", v.result.easting.toFixed(2).replace(".", ","));
      assert.equal(await box(page, "easting").getAttribute("data-verdict"), "correct");
      assert.match(await box(page, "easting").innerText(), /Tolerance ± 0\.01 m/);
      noErrors(log);
    } finally {
      await context.close();
    }
  });

  test("the hint ladder: nudge, formula, numbers, worked step, and the page says what was revealed", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      await visitPractice(page, "index.html", LINK);
      const b = box(page, "gsd_mm");
      const button = b.locator(".hint-button");
      await button.click();
      assert.match(await b.locator('.hint[data-rung="1"]').innerText(), /pixel size times the scale number/);
      assert.match(await page.locator(".practice-revealed").innerText(), /a nudge \(1 of 4\)/);
      await button.click();
      // the formula is typeset when KaTeX has arrived (it loads after the first numbers)
      await b.locator('.hint[data-rung="2"] .katex').first().waitFor({ timeout: WAIT });
      await button.click();
      const numbers = await b.locator('.hint[data-rung="3"]').innerText();
      assert.ok(numbers.includes("?"), numbers);
      await button.click();
      assert.match(await b.locator('.hint[data-rung="4"] .hint-step-title').innerText(), /Ground sample distance/);
      assert.equal(await button.isDisabled(), true);
      assert.match(await page.locator(".practice-revealed").innerText(), /the worked step \(4 of 4\)/);
      noErrors(log);
    } finally {
      await context.close();
    }
  });
});

describe("verdicts", () => {
  test("a mean to the course's one decimal is correct; too few digits has its own verdict and colour; a sign flip on ρ is not about an axis; each verdict is announced once", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      await visitPractice(page, "index.html", `#/ncc-2d?practice=${CODE}`);
      const v = await variantOf(page, "ncc-2d", CODE);
      // every live region's changes, counted per box, from here on
      await page.evaluate(() => {
        window.liveChanges = {};
        for (const f of document.querySelectorAll(".answer-feedback")) {
          const key = f.closest(".answer").dataset.key;
          window.liveChanges[key] = 0;
          new MutationObserver(() => window.liveChanges[key]++).observe(f, { childList: true, subtree: true, characterData: true });
        }
      });
      const changes = (key) => page.evaluate((k) => window.liveChanges[k], key);
      // the notes print Ā = 58.5: one decimal, with a decimal comma, is enough
      const mean = v.result.mean_a.toFixed(1).replace(".", ",");
      const input = box(page, "mean_a").locator("input");
      await input.fill(mean);
      await input.press("Enter"); // graded on Enter …
      await input.press("Tab"); // … and again on leaving: said once
      assert.equal(await box(page, "mean_a").getAttribute("data-verdict"), "correct");
      const parts = await box(page, "mean_a").locator(".verdict-part").evaluateAll((xs) => xs.map((x) => [x.dataset.part, x.dataset.kind]));
      assert.deepEqual(parts, [["value", "ok"], ["precision", "ok"]]);
      assert.equal(await box(page, "mean_a").locator(".answer-tolerance").innerText(), "Tolerance ± 0.01 (or 1 decimal, as the course notes print it)");
      assert.match(await feedback(page, "mean_a"), /^Correct to 1 decimal, as the course notes print it\.$/);
      const said = await feedback(page, "mean_a");
      assert.equal(said.match(/Correct/g)?.length, 1, said);
      assert.equal(await changes("mean_a"), 1);
      // another box answered: the first box's region is left alone
      await answer(page, "mean_b", v.result.mean_b.toFixed(2));
      assert.equal(await box(page, "mean_b").getAttribute("data-verdict"), "correct");
      assert.equal(await changes("mean_a"), 1);
      assert.equal(await changes("mean_b"), 1);
      // ρ to two digits (the box asks ± 0.001): right, but too few digits
      const rho = v.result.rho;
      const two = rho.toPrecision(2);
      assert.ok(Math.abs(Number(two) - rho) > 0.001, `${two} vs ${rho}`);
      await answer(page, "rho", two);
      const r = box(page, "rho");
      assert.equal(await r.getAttribute("data-verdict"), "imprecise");
      const text = await feedback(page, "rho");
      assert.match(text, /^Too few digits\s*Right, but give at least 3 significant digits: this box asks for ± 0\.001\.$/);
      assert.equal(await r.locator(".verdict").getAttribute("class"), "verdict verdict-imprecise");
      assert.equal((await page.locator(".practice-score").innerText()).trim(), "Score: 2.5 of 6");
      // its own colour: neither correct's green nor wrong's red
      const colours = await page.evaluate(() => {
        const css = getComputedStyle(document.documentElement);
        const probe = (c) => {
          const s = document.createElement("span");
          s.style.color = `var(${c})`;
          document.body.append(s);
          const out = getComputedStyle(s).color;
          s.remove();
          return out;
        };
        return { ok: probe("--ok"), error: probe("--error"), badge: getComputedStyle(document.querySelector('.answer[data-key="rho"] .verdict')).color, border: getComputedStyle(document.querySelector('.answer[data-key="rho"]')).borderTopColor, partial: css.getPropertyValue("--partial").trim() };
      });
      assert.ok(colours.partial, "a --partial colour");
      for (const c of [colours.badge, colours.border]) {
        assert.notEqual(c, colours.ok);
        assert.notEqual(c, colours.error);
      }
      // a sign flip on ρ: named, about the deviations, not an axis
      await answer(page, "rho", (-rho).toFixed(4));
      assert.equal(await r.getAttribute("data-mistake"), "sign flipped");
      const flip = await feedback(page, "rho");
      assert.doesNotMatch(flip, /axis/);
      assert.match(flip, /mean/);
      // a negative mean is just wrong: no "sign flipped"
      await answer(page, "mean_b", (-v.result.mean_b).toFixed(2));
      assert.equal(await box(page, "mean_b").getAttribute("data-verdict"), "wrong");
      assert.equal(await box(page, "mean_b").getAttribute("data-mistake"), null);
      noErrors(log);
    } finally {
      await context.close();
    }
  });
});

describe("worksheets", () => {
  test("N variants with an answer key on separate pages, printable", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      await visitPractice(page, "index.html", "#/practice?worksheet=gsd&n=3", "worksheet");
      assert.equal(await page.locator(".ws-exercise").count(), 3);
      assert.equal(await page.locator(".ws-key-item").count(), 3);
      // the codes are kept in the link, so the sheet is the same after a reload
      const codes = await page.locator(".ws-exercise").evaluateAll((xs) => xs.map((x) => x.dataset.code));
      assert.match(page.url(), new RegExp(`codes=${codes.join(",")}$`));
      // the key holds the solver's value for the first exercise's GSD
      const v = await variantOf(page, "gsd", codes[0]);
      const firstKey = await page.locator(".ws-key-item").first().innerText();
      const cm = Number(v.result.gsd_cm.toPrecision(7));
      assert.ok(firstKey.includes(String(cm)), `${cm} in ${firstKey}`);
      await page.emulateMedia({ media: "print" });
      assert.equal(await page.locator(".ws-key").evaluate((k) => getComputedStyle(k).breakBefore), "page");
      // the links, buttons and the LMS panel are for the screen only
      assert.deepEqual(await page.locator(".ws-screen-only").evaluateAll((xs) => xs.filter((x) => getComputedStyle(x).display !== "none").length), 0);
      assert.equal(await page.locator(".ws-screen-only").count(), 2);
      const pdf = await page.pdf({ format: "A4" });
      const pages = (pdf.toString("latin1").match(/\/Type\s*\/Page[^s]/g) ?? []).length;
      assert.ok(pages >= 2, `the printed sheet has ${pages} page(s)`);
      await page.reload();
      await page.waitForFunction(() => document.body.dataset.status === "worksheet", null, { timeout: WAIT });
      assert.deepEqual(await page.locator(".ws-exercise").evaluateAll((xs) => xs.map((x) => x.dataset.code)), codes);
      noErrors(log);
    } finally {
      await context.close();
    }
  });

  test("each exercise prints its full address and a QR code of it; the key can carry the worked steps", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      // a worked example's page never loads the QR encoder
      await page.goto(`${env.url}index.html#/gsd`);
      await page.waitForFunction(() => document.body.dataset.status === "ok", null, { timeout: WAIT });
      assert.equal(await page.evaluate(() => performance.getEntriesByType("resource").some((e) => /uqr/.test(e.name))), false);
      // the maker's option
      await page.goto(`${env.url}index.html#/practice`);
      await page.waitForFunction(() => document.body.dataset.status === "practice-overview", null, { timeout: WAIT });
      await page.selectOption("#ws-example", "gsd");
      await page.fill("#ws-n", "2");
      await page.check("#ws-steps");
      await page.getByRole("button", { name: "Make worksheet" }).click();
      await page.waitForFunction(() => document.body.dataset.status === "worksheet", null, { timeout: WAIT });
      assert.match(page.url(), /&worked=1$/);
      const sheet = await page.locator(".ws-exercise").evaluateAll((xs) =>
        xs.map((x) => ({ code: x.dataset.code, text: x.innerText, href: x.querySelector("a.ws-url")?.href, url: x.querySelector("a.ws-url")?.textContent, d: x.querySelector("svg.ws-qr path")?.getAttribute("d"), label: x.querySelector("svg.ws-qr")?.getAttribute("aria-label") })),
      );
      assert.equal(sheet.length, 2);
      for (const x of sheet) {
        const address = `${env.url}index.html#/gsd?practice=${x.code}`;
        assert.equal(x.url, address);
        assert.equal(x.href, address);
        assert.doesNotMatch(x.text, /online: #\//);
        assert.equal(x.label, `QR code of ${address}`);
        // the QR code is the address's: the same modules as the encoder gives for it
        const d = await page.evaluate(async (a) => {
          const { encode } = await import("./vendor/uqr.js");
          const { data } = encode(a, { ecc: "M", border: 2 });
          let out = "";
          data.forEach((row, y) => row.forEach((dark, xx) => { if (dark) out += `M${xx} ${y}h1v1h-1z`; }));
          return out;
        }, address);
        assert.ok(d.length > 1000);
        assert.equal(x.d, d);
      }
      // the key: the final values and each solution's worked steps, with the variant's numbers
      const v = await variantOf(page, "gsd", sheet[0].code);
      const steps = await page.evaluate(async ([i]) => {
        const m = await import("./pkg/photogrammetry_playground.js");
        await m.default();
        return m.solve("gsd", i).steps.map((s) => s.title);
      }, [v.inputs]);
      const key = page.locator(".ws-key-item").first();
      assert.deepEqual(await key.locator(".ws-step-title").allInnerTexts(), steps);
      await key.locator(".ws-step .katex").first().waitFor({ timeout: WAIT });
      assert.ok((await key.innerText()).includes(String(v.inputs.dpi)), "the substituted formulas carry the variant's dpi");
      // on paper: the address and the QR code print, the screen buttons do not
      await page.emulateMedia({ media: "print" });
      assert.equal(await page.locator("svg.ws-qr").first().isVisible(), true);
      assert.equal(await page.locator("a.ws-url").first().isVisible(), true);
      assert.equal(await page.locator(".ws-steps-toggle").isVisible(), false);
      const box = await page.locator("svg.ws-qr").first().boundingBox();
      assert.ok(box.width >= 90 && Math.abs(box.width - box.height) < 1, `QR ${box.width}×${box.height} px`);
      await page.emulateMedia({ media: "screen" });
      // the key without steps: one click
      await page.locator(".ws-steps-toggle").click();
      await page.waitForFunction(() => document.querySelector(".worksheet")?.dataset.steps === "0", null, { timeout: WAIT });
      assert.equal(await page.locator(".ws-step").count(), 0);
      assert.doesNotMatch(page.url(), /worked=1/);
      noErrors(log);
    } finally {
      await context.close();
    }
  });
});

describe("embedded", () => {
  test("an answer in an embedded practice question is posted to the host page", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      await page.goto(`${env.url}index.html#/`);
      const src = `${env.url}embed.html#/gsd?practice=${CODE}&id=quiz-7`;
      await page.evaluate((s) => {
        window.answers = [];
        window.addEventListener("message", (e) => window.answers.push(e.data));
        const f = document.createElement("iframe");
        f.src = s;
        f.width = "800";
        f.height = "700";
        document.body.append(f);
      }, src);
      const frame = page.frameLocator("iframe");
      await frame.locator('.answer[data-key="gsd_cm"] input').waitFor({ timeout: WAIT });
      const v = await variantOf(page, "gsd", CODE);
      await frame.locator('.answer[data-key="gsd_cm"] input').fill(v.result.gsd_cm.toFixed(3));
      await frame.locator('.answer[data-key="gsd_cm"] input').press("Tab");
      await page.waitForFunction(() => window.answers.some((a) => a?.type === "photogrammetry-playground:answer"), null, { timeout: WAIT });
      const msg = await page.evaluate(() => window.answers.find((a) => a?.type === "photogrammetry-playground:answer"));
      assert.deepEqual(msg, {
        type: "photogrammetry-playground:answer",
        version: 1,
        id: "quiz-7",
        example: "gsd",
        code: CODE,
        box: "gsd_cm",
        verdict: "correct",
        score: 1,
        out_of: 4,
      });
      noErrors(log);
    } finally {
      await context.close();
    }
  });
});
