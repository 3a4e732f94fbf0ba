// Correlation matching (seed 000, Examples 5–9) on the page: the seed
// solutions with their figures, selecting a position or a window in the
// figure (mouse and keyboard), chaining Examples 8 and 9 from the exact ρ,
// a 64×64 search array, and the documented answers for bad inputs.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import { TEST_TIMEOUT, exact, open, settled, start, visit, waitForExact } from "./harness.mjs";

let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

/** The example's canvases: size, ink and aria-label. */
function canvases(page) {
  return page.evaluate(() =>
    [...document.querySelectorAll(".figure-canvas")].map((c) => {
      const data = c.getContext("2d").getImageData(0, 0, c.width, c.height).data;
      let ink = 0;
      for (let i = 0; i < data.length; i += 4) if (data[i] < 240 || data[i + 1] < 240 || data[i + 2] < 240) ink += 1;
      return { ink, pixels: c.width * c.height, label: c.getAttribute("aria-label"), tabindex: c.getAttribute("tabindex"), clientWidth: c.clientWidth };
    }),
  );
}

const statusText = (page) => page.locator(".figure-status").innerText();

/** A JSON array stored in a result cell's data-value. */
async function exactList(page, key) {
  const cell = page.locator(`.result-table tr[data-key="${key}"] td.exact`);
  return JSON.parse(await cell.getAttribute("data-value"));
}

const EXAMPLES = {
  "ncc-1d": { describes: ["best match is position 5", "0.9766"], check: async (page) => assert.equal(await exact(page, "best"), 5) },
  "ncc-2d": { describes: ["0.7753", "58.7778"], check: async (page) => assert.ok(Math.abs((await exact(page, "rho")) - 0.775269268) < 1e-9) },
  "ncc-surface": {
    describes: ["position 10", "c = 3, r = 4", "0.9665"],
    check: async (page) => {
      assert.equal(await exact(page, "best_position"), 10);
      assert.equal(await exact(page, "best_c"), 3);
      assert.equal(await exact(page, "best_r"), 4);
    },
  },
  "subpixel-1d": { describes: ["c = 7.81818"], check: async (page) => assert.ok(Math.abs((await exact(page, "c_max")) - 86 / 11) < 1e-12) },
  "subpixel-2d": {
    describes: ["c = 3.0111", "r = 4.07599"],
    check: async (page) => {
      assert.ok(Math.abs((await exact(page, "c_max")) - 3.011096372) < 1e-8);
      assert.ok(Math.abs((await exact(page, "r_max")) - 4.075987003) < 1e-8);
    },
  },
};

describe("correlation examples", () => {
  test("each seed example solves, shows the printed values and notes, and draws its figure", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      for (const [id, { describes, check }] of Object.entries(EXAMPLES)) {
        assert.equal(await visit(page, env.url, "index.html", `#/${id}`), "ok", id);
        await check(page);
        // the seed's printed values sit beside the exact ones, and every difference has a note
        assert.ok((await page.locator(".result-table td.printed").count()) > 0, `${id}: printed column`);
        const differs = await page.locator(".result-table .verdict-differs").count();
        const explained = await page.locator(".notes li.note-rounding, .notes li.note-erratum").count();
        assert.ok(differs === 0 || explained > 0, `${id}: ${differs} results differ from the printed ones, ${explained} rounding or erratum notes`);
        assert.ok((await page.locator(".notes li").count()) > 0, `${id}: notes`);
        const [fig] = await canvases(page);
        assert.ok(fig, `${id}: a canvas`);
        assert.ok(fig.ink > fig.pixels * 0.03, `${id}: drawn (${fig.ink} of ${fig.pixels})`);
        for (const words of describes) assert.ok(fig.label.includes(words), `${id}: aria-label mentions ${words}: ${fig.label}`);
        // KaTeX rendered every formula
        assert.equal(await page.locator(".steps-body .katex-error").count(), 0, `${id}: no KaTeX errors`);
      }
      assert.deepEqual(log.pageErrors, []);
      assert.deepEqual(log.consoleErrors, []);
    } finally {
      await context.close();
    }
  });

  test("ncc-1d: clicking a bar or pressing ← → shows that position's computation", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page } = await open(env.browser);
    try {
      await visit(page, env.url, "index.html", "#/ncc-1d");
      assert.match(await statusText(page), /^Position 5 \(best\): B5 = \[1, 3, 8, 8, 6, 1, 1\]/);
      assert.match(await statusText(page), /ρ5 = 74 \/ √\(89\.7143 × 64\) = 0\.9766/);
      const canvas = page.locator(".figure-canvas");
      assert.equal(await canvas.getAttribute("tabindex"), "0");
      // the bar of position 2 sits under the centre of window 2: search cell index 1 + 3.5
      const box = await canvas.boundingBox();
      const x = await page.evaluate(() => {
        // the search row spans the canvas minus margins; read the geometry the way the figure does
        const c = document.querySelector(".figure-canvas");
        const width = c.clientWidth;
        const n = 12;
        const cell = Math.min(40, (width - 24 - 30) / n);
        const x0 = 12 + 30 + (width - 24 - 30 - n * cell) / 2;
        return x0 + (1 + 3.5) * cell;
      });
      await page.mouse.click(box.x + x, box.y + box.height * 0.6);
      assert.match(await statusText(page), /^Position 2: B2 = \[2, 2, 1, 1, 3, 8, 8\]/);
      assert.match(await statusText(page), /= −0\.5877/);
      await canvas.focus();
      await page.keyboard.press("ArrowRight");
      assert.match(await statusText(page), /^Position 3:/);
      await page.keyboard.press("End");
      assert.match(await statusText(page), /^Position 6:/);
      assert.match((await canvases(page))[0].label, /Selected: Position 6/);
      await page.keyboard.press("Home");
      assert.match(await statusText(page), /^Position 1:/);
    } finally {
      await context.close();
    }
  });

  test("ncc-surface: a window picked on the heat map or with the arrow keys shows its sums", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page } = await open(env.browser);
    try {
      await visit(page, env.url, "index.html", "#/ncc-surface");
      assert.match(await statusText(page), /^Position 10 \(best\): rows 3–5, columns 2–4 of S/);
      assert.match(await statusText(page), /Σ\(T−T̄\)\(B−B̄\) = 737\.778/);
      const canvas = page.locator(".figure-canvas");
      await canvas.focus();
      await page.keyboard.press("ArrowUp");
      assert.match(await statusText(page), /^Position 6: rows 2–4, columns 2–4/);
      assert.match(await statusText(page), /ρ = 0\.2394/);
      await page.keyboard.press("ArrowRight");
      assert.match(await statusText(page), /^Position 7:/);
      await page.keyboard.press("ArrowRight");
      await page.keyboard.press("ArrowRight"); // stays in its row
      assert.match(await statusText(page), /^Position 8:/);
      // a click on a search-array pixel selects the window centred on it (top-left pixel → position 1)
      const box = await canvas.boundingBox();
      const geometry = await page.evaluate(() => {
        const width = document.querySelector(".figure-canvas").clientWidth;
        let cell = Math.min(36, (width - 36) / 9);
        const xs = 12 + Math.max(3 * cell, 80) + 12;
        cell = Math.min(cell, (width - 12 - xs) / 6);
        return { xs, y1: 12 + 18, cell };
      });
      await page.mouse.click(box.x + geometry.xs + geometry.cell / 2, box.y + geometry.y1 + geometry.cell / 2);
      assert.match(await statusText(page), /^Position 1:/);
      assert.match(await statusText(page), /ρ = −0\.3301/);
    } finally {
      await context.close();
    }
  });

  test("Examples 8 and 9 chain from the exact ρ of Examples 5 and 7 and show how far the peak moves", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      await visit(page, env.url, "index.html", "#/subpixel-1d");
      await page.getByLabel(/Take ρ from/).selectOption("exact");
      await waitForExact(page, "c_max", 47 / 6, 1e-12);
      assert.ok(Math.abs((await exact(page, "peak_shift")) - (47 / 6 - 86 / 11)) < 1e-12);
      assert.match(await page.evaluate(() => location.hash), /rho_from=exact/);
      assert.match((await canvases(page))[0].label, /c = 7\.83333/);
      assert.equal(await page.locator(".steps-body", { hasText: "How far the peak moves" }).count(), 1);

      await visit(page, env.url, "index.html", "#/subpixel-2d?rho_from=exact");
      await waitForExact(page, "c_max", 3.011087663, 1e-8);
      const shift = await exact(page, "peak_shift");
      assert.ok(shift > 1e-6 && shift < 2e-5, `shift ${shift}`);
      const rho = await exactList(page, "rho");
      assert.ok(Math.abs(rho[1][1] - 0.966489366) < 1e-8);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("a 64×64 search array solves at once and its surface is drawn", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      await visit(page, env.url, "index.html", "#/ncc-surface");
      let x = 7;
      const rows = [];
      for (let r = 0; r < 64; r += 1) {
        const row = [];
        for (let c = 0; c < 64; c += 1) {
          x = (x * 1103515245 + 12345) % 2147483648;
          row.push(Math.floor(x / 65536) % 256);
        }
        rows.push(row.join(" "));
      }
      const template = rows.slice(20, 25).map((r) => r.split(" ").slice(30, 35).join(" "));
      await page.getByLabel(/Template T/).fill(template.join("\n"));
      // pasted at once: one input event (Playwright's fill types a textarea's lines one by one)
      const search = page.getByLabel(/Search array S/);
      // (how fast is for `npm run bench`, not for a test)
      await search.evaluate((el, text) => {
        el.value = text;
        el.dispatchEvent(new Event("input", { bubbles: true }));
      }, rows.join("\n"));
      await waitForExact(page, "best_c", 33, 0);
      assert.equal(await exact(page, "best_r"), 23);
      assert.equal((await exactList(page, "rho")).length, 60);
      const [fig] = await canvases(page);
      assert.ok(fig.ink > fig.pixels * 0.05);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("bad inputs: a template that does not fit, ragged rows, flat windows, a saddle", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      await visit(page, env.url, "index.html", "#/ncc-1d");
      await page.getByLabel(/Search array/).fill("1 2 3");
      await page.waitForFunction(() => document.body.dataset.status === "error");
      assert.match(await page.locator(".error-box").innerText(), /template: has 7 values but the search array only 3: the template must fit/);
      await page.getByLabel(/Search array/).fill("1 2 2 1 1 3 8 8 6 1 1 1");
      await waitForExact(page, "best", 5, 0);

      await visit(page, env.url, "index.html", "#/ncc-2d");
      await page.getByLabel(/Array A/).fill("1 2 3; 4 5");
      await page.waitForFunction(() => document.body.dataset.status === "invalid");
      assert.match(await page.locator('.field[data-key="a"] .field-error').innerText(), /same length/);
      await page.getByLabel(/Array A/).fill("1 2 3; 4 5 6; 7 8 9");
      await page.getByLabel(/Array B/).fill("5 5 5; 5 5 5; 5 5 5");
      await page.waitForFunction(() => document.body.dataset.status === "ok");
      assert.equal(await page.locator('.result-table tr[data-key="rho"] td.exact').innerText(), "—");
      assert.match(await page.locator(".notes").innerText(), /B has no variance/);
      assert.match((await canvases(page))[0].label, /ρ = no value/);

      await visit(page, env.url, "index.html", `#/subpixel-2d?rho=${encodeURIComponent("0.5 0.9 0.5; 0.1 0.5 0.1; 0.5 0.9 0.5")}`);
      assert.equal(await settled(page), "ok");
      assert.equal(await page.locator('.result-table tr[data-key="c_max"] td.exact').innerText(), "—");
      assert.match(await page.locator(".notes").innerText(), /not concave/);
      assert.match((await canvases(page))[0].label, /not concave \(saddle\)/);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });
});
