// The Sweep tool in Chromium (issue 34; www/sweep/, docs/embedding.md): opened
// with the keyboard only, the plotted series is solve() at every point (the
// core in Node says what each point must be); a sweep= link and an embed with
// sweep= draw the same series; the CSV carries the same numbers; the host page
// gets the series with the change event; axe-core finds no WCAG 2.2 AA
// violation on an open sweep at 390 and 1280 px; a wrong sweep= is named in
// words and the page keeps working. One browser, one page reused.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import fs from "node:fs";
import { createRequire } from "node:module";
import { TEST_TIMEOUT, nodeModule, open, start, startHost } from "./harness.mjs";
import { sweepValues } from "../../www/sweep/series.js";

const WAIT = 20_000;
const AXE = createRequire(import.meta.url).resolve("axe-core/axe.min.js");
const TAGS = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa", "wcag22aa"];
const LINK = "sweep=flying_height_m:500:3000:100&plot=gsd_cm";
/** Points the solver refuses: lsm-1d's patch does not fit the signal when it starts at c0 < 4 or c0 > 9. */
const GAPS = "sweep=c0:2:16:15";
/** Two units (cm, mm: a second axis). */
const AXES = "sweep=dpi:100:1200:12&plot=gsd_cm,pixel_size_mm";

let env;
let core;
let page;
let context;
before(async () => {
  env = await start();
  core = await nodeModule("all");
  ({ context, page } = await open(env.browser, { bypassCSP: true, acceptDownloads: true }));
});
after(async () => {
  await context?.close();
  await env?.close();
});

/** What uPlot was given (test-hooks.js: the section's data-plotted), once drawn. */
async function plotted(p = page) {
  const section = await p.waitForSelector(".sweep-section[data-plotted]", { timeout: WAIT });
  return JSON.parse(await section.getAttribute("data-plotted"));
}

/** The two-input table's cells, row by row (the row's value first). */
const tableCells = () => page.$$eval(".sweep-grid-table tbody tr", (trs) => trs.map((tr) => [...tr.cells].map((c) => c.textContent)));

async function go(hash) {
  await page.goto(`${env.url}index.html${hash}`);
  await page.waitForFunction(() => document.body.dataset.status === "ok", null, { timeout: WAIT });
}

/** Each plotted point against the core: solve(id, inputs with that value), a gap with its message where it throws. */
function assertSolved(id, data, inputs = {}) {
  assert.ok(data.xs.length >= 2);
  data.xs.forEach((x, i) => {
    let s = null;
    let message = null;
    try {
      s = core.solve(id, { ...inputs, [data.key]: x });
    } catch (e) {
      message = e.message;
    }
    assert.equal(data.errors[i], message, `${data.key} = ${x}`);
    for (const [k, ys] of Object.entries(data.ys)) assert.equal(ys[i], s ? s.result[k] : null, `${k} at ${data.key} = ${x}`);
  });
}

describe("the sweep", { timeout: TEST_TIMEOUT * 4 }, () => {
  let gridLink = null;
  let linkFromUi = null;
  let fromUi = null;

  test("opened with the keyboard only: the plotted series is solve() at each point; arrows read a point, Enter shows its solution", async () => {
    await go("#/gsd");
    let found = false;
    for (let i = 0; i < 80 && !found; i++) {
      await page.keyboard.press("Tab");
      found = await page.evaluate(() => document.activeElement?.classList.contains("sweep-open"));
    }
    assert.ok(found, "the Sweep button is reached with Tab");
    await page.keyboard.press("Enter");
    fromUi = await plotted();
    assert.equal(await page.evaluate(() => document.activeElement?.textContent), "Sweep an input");
    assert.equal(fromUi.key, "dpi", "the first number input");
    assert.deepEqual(Object.keys(fromUi.ys), ["gsd_cm"], "the example's answer is plotted first");
    assertSolved("gsd", fromUi);
    assert.match(page.url(), /sweep=dpi:450:1800:50&plot=gsd_cm/);
    linkFromUi = new URL(page.url()).hash;

    // the chart: arrows move a point cursor read out in a live line
    await page.focus(".sweep-frame");
    for (const key of ["Home", "ArrowRight", "ArrowRight"]) await page.keyboard.press(key);
    const line = page.locator(".sweep-section .figure-cursor");
    const x = fromUi.xs[2];
    assert.equal(await line.getAttribute("aria-live"), "polite");
    assert.match(await line.textContent(), new RegExp(`^Scan resolution = ${String(x).slice(0, 5)}`));
    // Enter: that point's value in the form, and the page solves it
    await page.keyboard.press("Enter");
    await page.waitForFunction((v) => document.querySelector("[data-key=dpi] input")?.value === v && document.body.dataset.status === "ok", String(x), { timeout: WAIT });
    assert.equal(Number(await page.inputValue("[data-key=dpi] input")), x);

    // the Data table holds the same series
    await page.click(".sweep-section .figure-data-toggle");
    const rows = await page.$$eval(".sweep-section .figure-data tbody tr", (trs) => trs.map((tr) => [...tr.cells].map((c) => c.querySelector(".figure-value").textContent)));
    assert.equal(rows.length, fromUi.xs.length);
    rows.forEach(([cx, cy], i) => {
      assert.ok(Math.abs(Number(cx.replace("−", "-")) - fromUi.xs[i]) <= 1e-9 * Math.abs(fromUi.xs[i]), `x ${cx}`);
      assert.ok(Math.abs(Number(cy.replace("−", "-")) - fromUi.ys.gsd_cm[i]) <= 1e-9 * Math.abs(fromUi.ys.gsd_cm[i]), `y ${cy}`);
    });

    // the CSV: the same numbers, at full precision
    const [download] = await Promise.all([page.waitForEvent("download"), page.click('[data-tool="sweep-csv"]')]);
    const csv = fs.readFileSync(await download.path(), "utf8").trim().split("\r\n");
    assert.equal(csv[0], "dpi (dpi),gsd_cm (cm),error");
    csv.slice(1).forEach((row, i) => {
      const [cx, cy, err] = row.split(",");
      assert.equal(Number(cx), fromUi.xs[i]);
      assert.equal(Number(cy), fromUi.ys.gsd_cm[i]);
      assert.equal(err, "");
    });
  });

  test("the sweep's link and a sweep= link draw the same series as solve()", async () => {
    assert.ok(linkFromUi, "the first test ran");
    await go(linkFromUi.replace(/dpi=[^&]*/, "dpi=900"));
    assert.deepEqual(await plotted(), fromUi);
    await go(`#/gsd?${LINK}`);
    const data = await plotted();
    assert.equal(data.key, "flying_height_m");
    assert.equal(data.xs.length, 100);
    assert.equal(data.xs[0], 500);
    assert.equal(data.xs.at(-1), 3000);
    assertSolved("gsd", data);
  });

  test("errors are gaps with the solver's message; an end outside the input's bounds is refused in the reader's words; two units get two axes; axe: no WCAG 2.2 AA violation at 1280 and 390 px", async () => {
    for (const width of [1280, 390]) {
      await page.setViewportSize({ width, height: 900 });
      await go(`#/lsm-1d?${GAPS}`);
      const gaps = await plotted();
      assertSolved("lsm-1d", gaps);
      const refused = gaps.errors.filter(Boolean);
      assert.equal(refused.length, 9, "c0 = 2, 3 and 10…16 do not fit");
      assert.match(refused[0], /^c0: the patch does not fit/);
      assert.match(await page.textContent(".sweep-errors-fold summary"), /^9 of 15 points have no solution/);
      // the last point is refused: its message is read on the keyboard's cursor
      await page.focus(".sweep-frame");
      await page.keyboard.press("End");
      assert.match(await page.textContent(".sweep-section .figure-cursor"), /no solution — c0: /);

      // the range's ends are read by the core's reader, as the input's own box: units, a comma, its bounds
      await go(`#/gsd?${AXES}`);
      const data = await plotted();
      assertSolved("gsd", data);
      assert.deepEqual(data.errors.filter(Boolean), []);
      assert.equal(await page.locator(".sweep-legend li").count(), 3, "two results and the worked example");
      assert.match(await page.textContent(".sweep-legend"), /left axis.*right axis/);
      await page.fill("[id$=-from]", "-200");
      await page.press("[id$=-from]", "Enter");
      await page.waitForFunction(() => /“From”: must be greater than 0/.test(document.querySelector(".sweep-message")?.textContent), null, { timeout: WAIT });
      await page.fill("[id$=-from]", "150,5");
      // the Steps box too: the core's reader (a whole number, 2–500), its words
      await page.fill("[id$=-steps]", "800");
      await page.press("[id$=-steps]", "Enter");
      await page.waitForFunction(() => /“Steps”: must be at most 500 \(got 800\)/.test(document.querySelector(".sweep-message")?.textContent), null, { timeout: WAIT });
      await page.fill("[id$=-steps]", "1,2e1");
      await page.press("[id$=-steps]", "Tab");
      await page.waitForFunction(() => JSON.parse(document.querySelector(".sweep-section").dataset.plotted).xs[0] === 150.5, null, { timeout: WAIT });
      assertSolved("gsd", await plotted());
      // two inputs at once: dpi (columns) × focal length (rows), gsd_cm in each cell
      if (!(await page.$eval(".sweep-grid", (d) => d.open))) await page.click(".sweep-grid summary");
      await page.selectOption("[id$=-grid-field]", "focal_length_mm");
      await page.selectOption("[id$=-grid-result]", "gsd_cm");
      // its ends too are read as the second input's own box: its bounds, in the reader's words
      await page.fill("[id$=-grid-from]", "-5");
      await page.click("[data-tool=sweep-grid]");
      assert.match(await page.textContent(".sweep-grid .sweep-message"), /^“From”: must be greater than 0/);
      await page.fill("[id$=-grid-from]", "100");
      await page.fill("[id$=-grid-to]", "200");
      await page.fill("[id$=-grid-steps]", "3");
      await page.click("[data-tool=sweep-grid]");
      const cells = await tableCells();
      assert.equal(cells.length, 3);
      // the table is in the link, its result first in plot=
      await page.waitForFunction(() => /[?&]grid=focal_length_mm:100:200:3(&|$)/.test(location.hash), null, { timeout: WAIT });
      assert.match(page.url(), /plot=gsd_cm,pixel_size_mm/);
      if (width === 390) gridLink = new URL(page.url()).hash;
      // the columns: 11 points over the sweep's range (grid.js MAX_CELLS_SIDE)
      const xs = sweepValues({ from: 150.5, to: 1200, steps: 11 });
      const heads = await page.$$eval(".sweep-grid-table thead th", (ths) => ths.slice(1).map((th) => Number(th.textContent.replace("−", "-"))));
      heads.forEach((h, j) => assert.ok(Math.abs(h - xs[j]) <= 1e-5 * Math.abs(xs[j]), `column ${j}: ${h} vs ${xs[j]}`));
      cells.forEach(([f, ...row], i) => {
        assert.equal(Number(f), [100, 150, 200][i]);
        row.forEach((text, j) => {
          const v = core.solve("gsd", { dpi: xs[j], focal_length_mm: Number(f) }).result.gsd_cm;
          assert.ok(Math.abs(Number(text) - v) <= 1e-5 * Math.abs(v), `${text} vs ${v}`);
        });
      });
      await page.addScriptTag({ path: AXE });
      const result = await page.evaluate((tags) => window.axe.run({ include: [[".sweep-section"]] }, { runOnly: { type: "tag", values: tags }, resultTypes: ["violations"] }), TAGS);
      assert.deepEqual(
        result.violations.map((v) => `${width}px: ${v.id} ${v.nodes.map((n) => n.target.join(" ")).join(" | ")}`),
        [],
      );
    }
    await page.setViewportSize({ width: 1280, height: 900 });
  });

  test("a grid= link opens the same table; folding the table takes it out of the link; a wrong grid= is named", async () => {
    assert.ok(gridLink, "the table was made");
    const made = await tableCells();
    await go(gridLink);
    await plotted();
    await page.waitForSelector(".sweep-grid[open] .sweep-grid-table", { timeout: WAIT });
    assert.deepEqual(await tableCells(), made);
    assert.equal(await page.inputValue("[id$=-grid-field]"), "focal_length_mm");
    assert.equal(await page.inputValue("[id$=-grid-result]"), "gsd_cm");
    await page.click(".sweep-grid summary");
    await page.waitForFunction(() => !/grid=/.test(location.hash) && /sweep=dpi:/.test(location.hash), null, { timeout: WAIT });
    await go(gridLink.replace(/grid=[^&]*/, "grid=dpi:1:2:3"));
    await plotted();
    assert.match(await page.textContent(".sweep-message"), /Ignored grid=dpi:…: dpi is the sweep’s own input/);
    assert.equal(await page.locator(".sweep-grid-table").count(), 0);
    await go(gridLink.replace(/grid=[^&]*/, "grid=focal_length_mm:100:200:<i>12</i>"));
    assert.match(await page.textContent(".options-notice"), /Ignored the option grid=“focal_length_mm:100:200:<i>12<\/i>”: the rows must be a whole number from 2 to 11/);
    assert.equal(await page.locator(".options-notice i").count(), 0);
  });

  test("a wrong sweep= is named in words (never HTML) and the page keeps working", async () => {
    await go("#/gsd?sweep=flying_height_m:500:<b>x</b>:100");
    assert.match(await page.textContent(".options-notice"), /Ignored the option sweep=“flying_height_m:500:<b>x<\/b>:100”: “to” is not a number/);
    assert.equal(await page.locator(".options-notice b").count(), 0);
    assert.equal(await page.locator(".sweep-section").count(), 0);
    await go("#/gsd?sweep=height:1:2:5&plot=gsd_cm,nope");
    await plotted();
    const message = await page.textContent(".sweep-message");
    assert.match(message, /Ignored sweep=height:…: this example has no input height; the number inputs here are dpi, focal_length_mm, flying_height_m\./);
    assert.match(message, /Ignored plot=nope: it is not a numeric result/);
    await page.fill("[data-key=dpi] input", "1200");
    await page.waitForFunction(() => document.body.dataset.status === "ok" && document.querySelector(".answer-line")?.textContent.includes("26.7"), null, { timeout: WAIT });
  });

  test("an embed with sweep= (and grid=) draws the same series and table, and the host page gets the series with the change event", async () => {
    const link = await (async () => {
      await go(`#/gsd?${LINK}&grid=dpi:600:1200:3`);
      return plotted();
    })();
    await page.waitForSelector(".sweep-grid-table", { timeout: WAIT });
    const table = await tableCells();
    assert.equal(table.length, 3);
    const host = await startHost({
      "/course.html": `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Course</title></head><body>
        <script>window.events = []; document.addEventListener("playground:change", (e) => window.events.push(e.detail));</script>
        <script src="${env.url}embed.js" defer></script>
        <div id="a" data-playground="gsd?${LINK}" data-grid="dpi:600:1200:3" data-id="a"></div></body></html>`,
    });
    try {
      const p = await context.newPage();
      await p.goto(`${host.url}course.html`);
      await p.waitForFunction(() => window.events.some((d) => d.sweep), null, { timeout: WAIT });
      const frame = await (await p.waitForSelector("#a iframe")).contentFrame();
      assert.deepEqual(await plotted(frame), link);
      await frame.waitForSelector(".sweep-grid-table", { timeout: WAIT });
      assert.deepEqual(await frame.$$eval(".sweep-grid-table tbody tr", (trs) => trs.map((tr) => [...tr.cells].map((c) => c.textContent))), table);
      const sweep = await p.evaluate(() => window.events.findLast((d) => d.sweep).sweep);
      assert.equal(sweep.input, "flying_height_m");
      assert.deepEqual(sweep.xs, link.xs);
      assert.deepEqual(sweep.ys, link.ys);
      assert.deepEqual(sweep.plot, ["gsd_cm"]);
      await p.close();
    } finally {
      await host.close();
    }
  });
});
