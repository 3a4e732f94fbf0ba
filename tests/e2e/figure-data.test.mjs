// End-to-end (issue 32, item 1): every figure explorable without sight.
// For every example of the catalog (one page, hash navigation between them):
// each canvas has a name and a description (Chromium's accessibility tree
// over CDP: Accessibility.getFullAXTree) holding the result's key numbers as
// solve() in Node gives them, and a Data view (a disclosure button) whose
// tables have column and row headers; for some examples the tables' cells are
// compared with the solution's numbers. Then, by keyboard only (no mouse
// event): the NCC surface and the NCC 2-D pairs explored with the arrow keys
// (the live line reads the best ρ), and a shape drawn on the chain-code grid
// with the arrow keys and Enter (the chain code becomes the one solve() gives).

import assert from "node:assert/strict";
import { after, before, describe, test } from "node:test";
import { formatNumber } from "../../www/format.js";
import { CATALOG_IDS, TEST_TIMEOUT, nodeModule, open, parseShown, settled, start, visit } from "./harness.mjs";

let env;
let page;
let context;
let log;
let cdp;
let core;
const solutions = new Map();
const solution = (id) => {
  if (!solutions.has(id)) solutions.set(id, core.solve(id, {}));
  return solutions.get(id);
};
const stepOf = (s, key) => s.steps.find((st) => st.values && Object.hasOwn(st.values, key))?.values[key];
const f = formatNumber;

before(async () => {
  env = await start();
  ({ context, page, log } = await open(env.browser, { viewport: { width: 1280, height: 900 } }));
  cdp = await context.newCDPSession(page);
  core = await nodeModule("all");
});
after(async () => {
  await context?.close();
  await env?.close();
});

/** Shows example `id` by hash navigation (the first by loading the page) and waits for its figures. */
let loaded = false;
async function show(id) {
  if (!loaded) {
    assert.equal(await visit(page, env.url, "index.html", `#/${id}`), "ok", id);
    loaded = true;
  } else {
    await page.evaluate((h) => {
      for (const c of document.querySelectorAll(".figure-canvas")) c.dataset.old = "1";
      location.hash = h;
    }, `#/${id}`);
  }
  await page.waitForFunction(() => {
    const cs = [...document.querySelectorAll(".figure-canvas")];
    return cs.length > 0 && cs.every((c) => !c.dataset.old && c.getAttribute("aria-label") !== "Figure (not drawn yet)");
  });
  assert.equal(await settled(page), "ok", id);
}

/** Each canvas's name and description as the accessibility tree has them, beside its summary paragraph. */
async function axFigures() {
  const dom = await page.evaluate(() =>
    [...document.querySelectorAll(".figure-canvas")].map((c) => ({
      label: c.getAttribute("aria-label"),
      role: c.getAttribute("role"),
      summary: document.getElementById(c.getAttribute("aria-describedby")?.split(" ")[0] ?? "")?.textContent ?? "",
    })),
  );
  const { nodes } = await cdp.send("Accessibility.getFullAXTree");
  return dom.map((d) => {
    const node = nodes.find((n) => !n.ignored && n.name?.value === d.label && ["image", "img", "group"].includes(n.role?.value));
    return { ...d, axRole: node?.role?.value, name: node?.name?.value ?? "", description: node?.description?.value ?? "" };
  });
}

/** The key numbers of each example's result, as its figures' descriptions must state them. */
const KEY = {
  "pixel-to-photo": (s) => [f(s.result.x_mm, 5), f(s.result.y_mm, 5)],
  "photo-to-pixel": (s) => [f(s.result.c, 6), f(s.result.r, 6)],
  gsd: (s) => [`GSD = ${f(s.result.gsd_cm, 4)} cm`],
  "fiducial-similarity": (s) => [`${s.result.point_residuals.length} control points`],
  "fiducial-affine": (s) => [`${s.result.point_residuals.length} control points`],
  "transform-fit": (s) => [`${s.result.point_residuals.length} control points`],
  "ncc-1d": (s) => [`ρ is highest, ${f(s.result.rho[s.result.best - 1], 4)}, at position ${s.result.best}`],
  "ncc-2d": (s) => [`ρ = ${f(s.result.rho, 4)}`],
  "ncc-surface": (s) => [`ρ is highest, ${f(s.result.rho[s.result.best_row - 1][s.result.best_col - 1], 4)}, at row ${s.result.best_row}, column ${s.result.best_col}`],
  "subpixel-1d": (s) => [`c = ${f(s.result.c_max, 6)}`],
  "subpixel-2d": (s) => [`c = ${f(s.result.c_max, 6)}, r = ${f(s.result.r_max, 6)}`],
  "lsm-1d": (s) => [`c ends at ${f(s.result.c, 5)}`],
  "lsm-2d": (s) => [`c ends at ${f(s.result.c, 5)}`, `r ends at ${f(s.result.r, 5)}`],
  "lsm-affine": (s) => [`a3 (shift c) ends at ${f(s.result.parameters[2], 5)}`],
  resample: (s) => [`I = ${f(s.result.bilinear, 6)}`],
  "filter-window": (s) => [`g = ${f(s.result.selected, 6)}`],
  "edge-window": (s) => [`|G| = ${f(s.result.selected_magnitude, 6)}`],
  "forstner-window": (s) => [`w = ${f(s.result.w, 4)}`],
  "moravec-window": (s) => [`mean of the sums is ${f(s.result.mean, 4)}`],
  "forstner-image": (s) => [`w = ${f(s.result.w, 4)}`, `${s.result.points.length} interest points`],
  "chain-code": (s) => [`Chain code ${s.result.code.join(" ")}`, `Length ${f(s.result.length, 5)} px`],
  "boundary-length": (s) => [`Length ${f(s.result.length, 5)} px`],
  "boundary-shape": (s) => [`Diameter ${f(s.result.diameter, 5)} px`, `Chain code ${s.result.code.join(" ")}`],
  utm: (s) => [`easting ${f(s.result.easting / 1000, 9)} km`],
  "utm-inverse": (s) => [`zone ${s.inputs.zone}`, `easting ${f(s.inputs.easting / 1000, 9)} km`],
  "utm-facts": (s) => [`${f(s.result.central_scale_factor, 6)} on the central meridian`],
};

/** The cells of the Data views' tables (opened first): per table its caption, headers and cell texts (value, mark). */
async function openTables() {
  await page.evaluate(() => {
    for (const b of document.querySelectorAll(".figure-data-toggle")) if (b.getAttribute("aria-expanded") !== "true") b.click();
  });
  return page.evaluate(() =>
    [...document.querySelectorAll(".figure-panel")].map((panel) => ({
      toggle: (() => {
        const b = panel.querySelector(".figure-data-toggle");
        return b && { expanded: b.getAttribute("aria-expanded"), controls: b.getAttribute("aria-controls"), hidden: document.getElementById(b.getAttribute("aria-controls"))?.hidden };
      })(),
      tables: [...panel.querySelectorAll(".figure-table")].map((t) => ({
        caption: t.caption?.textContent ?? "",
        cols: [...t.querySelectorAll("thead th")].map((th) => [th.scope, th.textContent]),
        rowHeads: [...t.querySelectorAll("tbody th")].map((th) => [th.scope, th.textContent]),
        cells: [...t.querySelectorAll("tbody tr")].map((tr) => [...tr.querySelectorAll("td")].map((td) => [td.querySelector(".figure-value").textContent, td.querySelector(".figure-mark")?.textContent.replace(/^, /, "") ?? null])),
      })),
      list: [...panel.querySelectorAll(".figure-list li")].map((li) => li.textContent),
    })),
  );
}

const values = (t) => t.cells.map((row) => row.map(([v]) => v));

/** Every number in the solution (inputs, result, the steps' values), sorted: what a table may show. */
function numbersOf(s) {
  const out = [];
  const walk = (v) => {
    if (typeof v === "number" && Number.isFinite(v)) out.push(v);
    else if (Array.isArray(v)) v.forEach(walk);
    else if (v && typeof v === "object") Object.values(v).forEach(walk);
  };
  walk(s.inputs);
  walk(s.result);
  for (const st of s.steps ?? []) walk(st.values);
  return out.sort((a, b) => a - b);
}

/**
 * The cells of every table that are one number, each read back (parseShown:
 * the real minus sign, a power of ten) and found in the solution to the
 * digits it shows (half a unit of its last digit): a table cell is a number
 * of the solution, not one the figure computed or mistyped.
 */
function strayCells(panels, s) {
  const have = numbersOf(s);
  const near = (x, tol) => {
    let lo = 0;
    let hi = have.length;
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (have[mid] < x - tol) lo = mid + 1;
      else hi = mid;
    }
    return lo < have.length && have[lo] <= x + tol;
  };
  const stray = [];
  let read = 0;
  for (const t of panels.flatMap((p) => p.tables)) {
    t.cells.forEach((row, r) =>
      row.forEach(([text], c) => {
        const x = parseShown(text);
        // a row's number in the first column (point 1, 2 …) is not a value
        if (!Number.isFinite(x) || !/\d/.test(text) || (c === 0 && text === String(r + 1))) return;
        read++;
        // half a unit of the last digit shown (of the mantissa for a power of ten)
        const [mantissa, power = ""] = text.replace(/\u2212/g, "-").split(" × 10");
        const decimals = (mantissa.split(".")[1] ?? "").length;
        const exponent = Math.log10(parseShown(`1 × 10${power}`) || 1);
        const tol = 0.5001 * 10 ** (Math.round(exponent) - decimals);
        if (!near(x, tol)) stray.push(`"${t.caption}" row ${r + 1} column ${c + 1}: ${text}`);
      }),
    );
  }
  return { read, stray };
}
const table = (panels, re) => panels.flatMap((p) => p.tables).find((t) => re.test(t.caption));

/** Tables whose cells must equal the solution's numbers, as the figures format them. */
const CELLS = {
  "ncc-2d": (panels, s) => {
    assert.deepEqual(values(table(panels, /^A /)), s.inputs.a.map((row) => row.map((v) => f(v, 6))));
    assert.deepEqual(values(table(panels, /^B /)), s.inputs.b.map((row) => row.map((v) => f(v, 6))));
    const da = stepOf(s, "da").flat();
    const db = stepOf(s, "db").flat();
    assert.deepEqual(values(table(panels, /deviation pairs/)).map((r) => r.slice(1)), da.map((x, i) => [f(x, 6), f(db[i], 6)]));
  },
  "ncc-surface": (panels, s) => {
    const t = table(panels, /^ρ at every position/);
    assert.deepEqual(values(t), s.result.rho.map((row) => row.map((v) => f(v, 4))));
    assert.match(t.cells[s.result.best_row - 1][s.result.best_col - 1][1], /best/);
    assert.deepEqual(t.rowHeads[0], ["row", "row 1"]);
    assert.deepEqual(t.cols[1], ["col", "column 1"]);
  },
  "filter-window": (panels, s) => {
    const t = table(panels, /^Output g/);
    assert.deepEqual(values(t), s.result.output.map((row) => row.map((v) => f(v, 6))));
    assert.ok(t.cells.flat().some(([, m]) => m === "selected"));
  },
  resample: (panels, s) => {
    const t = table(panels, /^The patch/);
    assert.deepEqual(values(t), s.inputs.patch.map((row) => row.map((v) => f(v, 6))));
    const w = stepOf(s, "weights");
    assert.ok(t.cells.flat().some(([, m]) => m?.includes(`bilinear, w = ${f(w[0], 3)}`)));
  },
  "chain-code": (panels, s) => {
    const list = panels.flatMap((p) => p.list);
    assert.equal(list.length, s.result.code.length);
    const [c, r] = s.result.pixels[0];
    assert.match(list[0], new RegExp(`^\\(${c}, ${r}\\) → .*: code ${s.result.code[0]}, `));
  },
  "lsm-2d": (panels, s) => {
    const t = table(panels, /^Each parameter/);
    const c = t.cells[t.rowHeads.findIndex(([, h]) => h === "c")];
    assert.equal(c[c.length - 1][0], f(s.result.c, 5));
  },
};

describe("figure data", () => {
  test("every example: each figure has a name and a description with the result's key numbers, and a Data view of tables", { timeout: TEST_TIMEOUT * 3 }, async () => {
    assert.ok(CATALOG_IDS.length >= 26);
    const cellsRead = [];
    const strays = [];
    for (const id of CATALOG_IDS) {
      await show(id);
      const s = solution(id);
      const figs = await axFigures();
      assert.ok(figs.length > 0, id);
      for (const fig of figs) {
        assert.ok(fig.name.length > 10, `${id}: a figure without a name`);
        assert.ok(fig.summary.length > 20 && /\d/.test(fig.summary), `${id}: a figure without a summary: ${fig.summary}`);
        assert.ok(fig.description.startsWith(fig.summary), `${id}: the description is not the summary: ${fig.description}`);
        assert.equal(fig.axRole, fig.role === "group" ? "group" : "image", `${id}: role ${fig.role} read as ${fig.axRole}`);
      }
      const text = figs.map((fig) => fig.description).join(" ");
      for (const want of (KEY[id] ?? (() => assert.fail(`${id}: no key numbers listed`)))(s)) assert.ok(text.includes(want), `${id}: "${want}" is not in the figures' descriptions: ${text}`);
      const panels = await openTables();
      for (const p of panels) {
        assert.deepEqual([p.toggle?.expanded, p.toggle?.hidden], ["true", false], `${id}: the Data view does not open`);
        assert.ok(p.tables.length > 0, `${id}: a figure without a table`);
        for (const t of p.tables) {
          assert.ok(t.caption && t.cols.length && t.cols.every(([scope]) => scope === "col"), `${id}: "${t.caption}" lacks column headers`);
          assert.ok(t.rowHeads.every(([scope]) => scope === "row"), `${id}: "${t.caption}"`);
          assert.ok(t.cells.length > 0 && t.cells.every((row) => row.length === t.cols.length - (t.rowHeads.length ? 1 : 0)), `${id}: "${t.caption}" has rows of the wrong length`);
        }
      }
      CELLS[id]?.(panels, s);
      const { read, stray } = strayCells(panels, s);
      cellsRead.push([id, read]);
      strays.push(...stray.map((x) => `${id}: ${x}`));
    }
    assert.deepEqual(strays, [], "table cells not in the solution");
    // most examples' tables hold numbers (a few figures are schematic: their tables are words)
    const withNumbers = cellsRead.filter(([, n]) => n > 0).map(([id]) => id);
    assert.ok(withNumbers.length >= 20, `tables with numbers: ${withNumbers.join(", ")}`);
    assert.deepEqual(log.pageErrors, []);
    assert.deepEqual(log.consoleErrors, []);
  });

  test("keyboard only: the NCC surface and pairs explored with the arrow keys, the live line reads the selection and the best ρ", { timeout: TEST_TIMEOUT }, async () => {
    await show("ncc-surface");
    const s = solution("ncc-surface");
    const status = page.locator(".figure-status").first();
    assert.equal(await status.getAttribute("aria-live"), "polite");
    await page.locator(".figure-canvas").first().focus();
    await page.keyboard.press("Home");
    await page.waitForFunction(() => document.querySelector(".figure-status").textContent.startsWith("Position 1:"));
    for (let k = 1; k < s.result.best_row; k++) await page.keyboard.press("ArrowDown");
    for (let k = 1; k < s.result.best_col; k++) await page.keyboard.press("ArrowRight");
    const best = f(s.result.rho[s.result.best_row - 1][s.result.best_col - 1], 4);
    await page.waitForFunction((p) => document.querySelector(".figure-status").textContent.startsWith(`Position ${p} (best)`), s.result.best_position);
    assert.match(await status.textContent(), new RegExp(`ρ = ${best}$`));

    // ncc-2d: the pair with the largest product of deviations (the arrow keys move the selection)
    await show("ncc-2d");
    const t = solution("ncc-2d");
    const da = stepOf(t, "da");
    const db = stepOf(t, "db");
    const cols = da[0].length;
    let top = 0;
    da.flat().forEach((x, i) => {
      if (x * db.flat()[i] > da.flat()[top] * db.flat()[top]) top = i;
    });
    const line = page.locator(".figure-status").first();
    assert.equal(await line.getAttribute("aria-live"), "polite");
    await page.locator(".figure-canvas").first().focus();
    await page.keyboard.press("ArrowRight"); // selects the first pair
    for (let k = 0; k < Math.floor(top / cols); k++) await page.keyboard.press("ArrowDown");
    for (let k = 0; k < top % cols; k++) await page.keyboard.press("ArrowRight");
    const r = Math.floor(top / cols) + 1;
    const c = (top % cols) + 1;
    await page.waitForFunction((w) => document.querySelector(".figure-status").textContent.includes(w), `Selected (row ${r}, column ${c})`);
    const said = await line.textContent();
    assert.match(said, new RegExp(`^Selected \\(row ${r}, column ${c}\\): .*\\nρ = .* = ${f(t.result.rho, 4)}$`));
    assert.ok(said.includes(`(${f(da[r - 1][c - 1], 5)}) × (${f(db[r - 1][c - 1], 5)})`), said);
    assert.deepEqual(log.pageErrors, []);
  });

  test("keyboard only: a shape drawn on the chain-code grid with the arrow keys and Enter gives the chain code solve() gives", { timeout: TEST_TIMEOUT }, async () => {
    await show("chain-code");
    // the Rectangle preset, by keyboard
    await page.getByRole("button", { name: "Rectangle" }).focus();
    await page.keyboard.press("Enter");
    await page.waitForFunction(() => document.querySelector(".figure-summary").textContent.includes("A pixel grid with 60 region pixels"));
    assert.equal(await settled(page), "ok");
    const canvas = page.locator(".figure-canvas").first();
    assert.equal(await canvas.getAttribute("role"), "group");
    assert.equal(await canvas.getAttribute("aria-roledescription"), "interactive figure");
    await canvas.focus();
    // the cursor starts on the start pixel, (3, 2): up one is (3, 1), outside the rectangle
    const cursor = page.locator(".figure-cursor").first();
    assert.equal(await cursor.getAttribute("aria-live"), "polite");
    await page.keyboard.press("ArrowRight"); // the first key puts the cursor on the first marked cell
    assert.equal(await cursor.textContent(), "row 2, column 3, region pixel, boundary 1, start");
    await page.keyboard.press("ArrowUp");
    assert.equal(await cursor.textContent(), "row 1, column 3, empty");
    const before = await page.locator(".figure-summary").first().textContent();
    await page.keyboard.press("Enter");
    await page.waitForFunction((b) => document.querySelector(".figure-summary").textContent !== b, before);
    assert.equal(await settled(page), "ok");
    await page.waitForFunction(() => /region pixel/.test(document.querySelector(".figure-cursor").textContent));
    assert.match(await cursor.textContent(), /^row 1, column 3, region pixel, boundary 1, start$/);
    // what the core says for the rectangle and the new pixel
    const px = [];
    for (let r = 2; r <= 7; r++) for (let c = 3; c <= 12; c++) px.push([c, r]);
    const want = core.solve("chain-code", { given: "region", pixels: [...px, [3, 1]], connectivity: "8", from: "start" }).result.code;
    const summary = await page.locator(".figure-summary").first().textContent();
    assert.ok(summary.includes(`Chain code ${want.join(" ")};`), summary);
    // Space toggles it back
    await page.keyboard.press(" ");
    await page.waitForFunction(() => /^row 1, column 3, empty$/.test(document.querySelector(".figure-cursor").textContent));
    assert.deepEqual(log.pageErrors, []);
  });
});
