// The image lab by keyboard alone and without sight (issue 32): no mouse
// event at all. A small generated photo; Sobel run from the keyboard; the
// view's cell cursor moved by the arrow keys, its polite live region read
// and its numbers checked against the layer's value at that pixel; Enter
// explains that pixel; the Data view's tables equal the photo's and the
// layer's values around the cursor; the description names the layers'
// ranges; the view's buttons zoom and pan; a matching template placed and
// matched by keyboard. Then axe-core (WCAG 2.0/2.1/2.2 A and AA) at 390 and
// 1280 px, light and dark, with a result layer shown and the Data view open,
// and every control of the lab at least 24 × 24 CSS px at 390 px. One page.

import { test, before, after } from "node:test";
import assert from "node:assert/strict";
import { createRequire } from "node:module";
import { start, TEST_TIMEOUT } from "./harness.mjs";
import { idle, openLab, viewOf } from "./lab-harness.mjs";

const AXE = createRequire(import.meta.url).resolve("axe-core/axe.min.js");
const [W, H] = [96, 64];
/** The generated photo: a ramp with a bright disc (edges in every direction) and a little texture. */
const grey = (c, r) => Math.min(255, (c + r) + ((c - 60) ** 2 + (r - 30) ** 2 < 196 ? 120 : 0) + ((c * 7 + r * 13) % 11));
/** view.js's fmt: up to 5 significant digits. */
const fmt = (v) => (Number.isInteger(v) ? String(v) : String(Number(v.toPrecision(5))));

let env;
let page;
let log;
before(async () => {
  env = await start();
  // bypassCSP: axe is injected as an inline script, which the page's CSP rightly refuses
  ({ page, log } = await openLab(env, { bypassCSP: true }));
  await idle(page);
  await page.evaluate(async ([w, h, src]) => {
    const g = new Function("c", "r", `return (${src})(c, r)`);
    const bytes = new Uint8Array(w * h);
    for (let r = 0; r < h; r++) for (let c = 0; c < w; c++) bytes[r * w + c] = g(c, r);
    await (await import("./lab/lab.js")).openRawForTests(w, h, bytes, "ramp");
  }, [W, H, grey.toString()]);
  await page.waitForFunction(() => document.body.dataset.image === "ramp");
  await idle(page);
});
after(async () => {
  await env?.close();
});

const live = () => page.textContent("#lab-cursor-live");
const layer = (pixels) => page.evaluate(async (px) => (await import("./lab/lab.js")).layerForTests(null, px), pixels);
/** Chooses option `text` of select `id` by typing its first letters. */
async function choose(id, text, want) {
  await page.focus(id);
  await page.keyboard.type(text);
  assert.equal(await page.inputValue(id), want, id);
}

test("Sobel by keyboard: the cursor reads the pixel, Enter explains it, the Data view and the description hold its numbers", { timeout: TEST_TIMEOUT }, async () => {
  await choose("#lab-family", "Edges", "edges");
  await choose("#lab-operator", "S", "sobel");
  await page.focus("#lab-run");
  await page.keyboard.press("Enter");
  await page.waitForFunction(() => document.body.dataset.layer === "magnitude");
  await idle(page);
  // the cursor starts at the view's centre pixel when the view gets the focus
  const g = await viewOf(page);
  const start = [Math.round((g.cw / 2 - g.ox) / g.zoom - 0.5), Math.round((g.ch / 2 - g.oy) / g.zoom - 0.5)];
  await page.focus("#lab-stage .lab-canvas");
  for (let i = 0; i < 3; i++) await page.keyboard.press("ArrowRight");
  await page.keyboard.press("Shift+ArrowUp");
  await page.keyboard.press("ArrowLeft");
  const [c, r] = [start[0] + 2, start[1] - 10];
  const want = await layer([[c, r]]);
  assert.equal(want.values[0] !== null, true);
  assert.equal(await live(), `column ${c}, row ${r}, grey ${grey(c, r)}; magnitude ${fmt(want.values[0])}`);
  // the inspector says the same in its short words
  assert.equal(await page.textContent("#lab-inspector"), `c ${c}, r ${r} · grey ${grey(c, r)} · magnitude ${fmt(want.values[0])}`);
  // Home, End: the row's ends
  await page.keyboard.press("End");
  assert.match(await live(), new RegExp(`^column ${W - 1}, row ${r}, `));
  await page.keyboard.press("Home");
  assert.match(await live(), new RegExp(`^column 0, row ${r}, `));
  for (let i = 0; i < c; i++) await page.keyboard.press("ArrowRight");
  // Enter does what a click does: that pixel explained
  await page.keyboard.press("Enter");
  await page.waitForFunction((p) => document.body.dataset.picked === p, `${c},${r}`);
  await page.waitForSelector("#lab-explain-value");
  await idle(page);
  assert.match(await page.textContent("#lab-explain"), new RegExp(`magnitude at column ${c}, row ${r}:`));
  // the exact value (the reference function, f64) and beside it the layer's f32, the one the cursor read
  const exact = Number(await page.getAttribute("#lab-explain-value", "data-value"));
  assert.equal(Math.fround(exact), want.values[0]);
  if (await page.$("#lab-layer-value")) assert.equal(Number(await page.getAttribute("#lab-layer-value", "data-value")), want.values[0]);
  assert.ok(await page.$("#lab-explain-link"), "the link to the worked example");
  // the Data view, opened by keyboard: 7 × 7 around the cursor, headers, the cursor's cell in words
  await page.focus("#lab-data-toggle");
  await page.keyboard.press("Enter");
  assert.equal(await page.getAttribute("#lab-data-toggle", "aria-expanded"), "true");
  const table = (id) => page.$$eval(`${id} tr`, (rows) => rows.map((tr) => [...tr.children].map((x) => x.textContent)));
  const greyRows = await table("#lab-data-grey");
  const cols = Array.from({ length: 7 }, (_, k) => c - 3 + k);
  const rows = Array.from({ length: 7 }, (_, k) => r - 3 + k);
  assert.deepEqual(greyRows[0], ["row \\ column", ...cols.map(String)]);
  assert.deepEqual(greyRows.slice(1).map((x) => x[0]), rows.map(String));
  const pixels = rows.flatMap((y) => cols.map((x) => [x, y]));
  const lv = (await layer(pixels)).values;
  const layerRows = await table("#lab-data-layer");
  rows.forEach((y, i) => cols.forEach((x, k) => {
    const mark = x === c && y === r ? ", the cursor" : "";
    assert.equal(greyRows[i + 1][k + 1], `${grey(x, y)}${mark}`, `grey (${x}, ${y})`);
    assert.equal(layerRows[i + 1][k + 1], `${fmt(lv[i * 7 + k])}${mark}`, `magnitude (${x}, ${y})`);
  }));
  // the table follows the cursor
  await page.focus("#lab-stage .lab-canvas");
  await page.keyboard.press("ArrowDown");
  assert.equal((await table("#lab-data-grey")).slice(1).map((x) => x[0]).join(), rows.map((y) => String(y + 1)).join());
  // the description: the photo's size and range, the layer shown and the others with their ranges
  const desc = await page.textContent("#lab-view-desc");
  const all = await page.evaluate(async () => {
    const lab = await import("./lab/lab.js");
    return ["gx", "gy", "magnitude", "direction"].map((n) => lab.layerForTests(n));
  });
  const [glo, ghi] = [Math.min(...Array.from({ length: W * H }, (_, i) => grey(i % W, Math.floor(i / W)))), Math.max(...Array.from({ length: W * H }, (_, i) => grey(i % W, Math.floor(i / W))))];
  assert.match(desc, new RegExp(`^ramp: ${W} × ${H} pixels, grey values from ${glo} to ${ghi}\\. Result layer shown \\(over the photo at 70 % opacity\\): magnitude, ${W} × ${H} pixels, values from ${fmt(all[2].min)} to ${fmt(all[2].max)}\\.`));
  for (const l of all) assert.ok(desc.includes(`${l.name}, ${W} × ${H} pixels, values from ${fmt(l.min)} to ${fmt(l.max)}`), `${l.name} in: ${desc}`);
  assert.equal(await page.getAttribute("#lab-stage .lab-canvas", "aria-describedby"), "lab-view-desc");
  // the view's buttons: zoom in, pan, fit (no drag, no wheel)
  const fit = await viewOf(page);
  await page.focus("#lab-zoom-in");
  await page.keyboard.press("Enter");
  const zoomed = await viewOf(page);
  assert.ok(Math.abs(zoomed.zoom - fit.zoom * 1.25) < 1e-9 * zoomed.zoom);
  await page.focus("#lab-pan-right");
  await page.keyboard.press("Enter");
  assert.equal((await viewOf(page)).ox, zoomed.ox - 40 * (await page.evaluate(() => devicePixelRatio)));
  await page.focus("#lab-fit");
  await page.keyboard.press("Enter");
  assert.deepEqual(Object.values(await viewOf(page)).slice(0, 3), Object.values(fit).slice(0, 3));
  assert.deepEqual(log.pageErrors, []);
});

test("a matching template placed by keyboard: the cursor, Enter, the matching runs there", { timeout: TEST_TIMEOUT }, async () => {
  await choose("#lab-family", "Corr", "correlation");
  await choose("#lab-template", "15", "15");
  assert.match(await page.textContent("#lab-template-pos"), /No template box yet/);
  await page.focus("#lab-stage .lab-canvas");
  // from the image's first pixel: 40 right, 30 down (a 15 × 15 box fits there)
  await page.keyboard.press("Control+Home");
  for (let i = 0; i < 4; i++) await page.keyboard.press("Shift+ArrowRight");
  for (let i = 0; i < 3; i++) await page.keyboard.press("Shift+ArrowDown");
  assert.match(await live(), /^column 40, row 30, grey /);
  await page.keyboard.press("Enter");
  await page.waitForFunction(() => document.body.dataset.matched === "40,30");
  await idle(page);
  assert.equal(await page.textContent("#lab-template-pos"), "Template 15×15 centred on column 40, row 30.");
  // the same photo: the best match is the template's own place, ρ = 1
  assert.match(await page.textContent("#lab-match"), /c 40, r 30, ρ = 1(?![\d.])/);
  // the search photo's Data view: its description, and its grey values and ρ around the best match
  await page.focus("#lab-search-data-toggle");
  await page.keyboard.press("Enter");
  assert.equal(await page.getAttribute("#lab-search-data-toggle", "aria-expanded"), "true");
  assert.match(await page.textContent("#lab-search-data-desc"), /^ramp: 96 × 64 pixels; the search box is columns 3 to 77, rows 0 to 63\..* ρ from [-−\d.]+ to 1\. The best match is at column 40, row 30, ρ = 1\.$/);
  const around = (id) => page.$$eval(`${id} tr`, (trs) => trs.map((tr) => [...tr.children].map((c) => c.textContent)));
  const greyRows = await around("#lab-search-data-grey");
  assert.deepEqual(greyRows[0].slice(1), ["37", "38", "39", "40", "41", "42", "43"]);
  assert.deepEqual(greyRows.slice(1).map((row) => row.slice(1).map((t) => t.replace(", the cursor", ""))), [27, 28, 29, 30, 31, 32, 33].map((r) => [37, 38, 39, 40, 41, 42, 43].map((c) => fmt(grey(c, r)))));
  assert.equal((await around("#lab-search-data-layer"))[4][4], "1, the cursor");
  // the search photo's own cursor moves the tables
  await page.focus(".lab-pair .lab-canvas");
  await page.keyboard.press("ArrowRight");
  await page.waitForFunction(() => {
    const at = /^column (\d+), row (\d+)/.exec(document.querySelector(".lab-pair .lab-cursor-live")?.textContent ?? "");
    return at && document.querySelector("#lab-search-data-grey caption")?.textContent.includes(`the cursor (column ${at[1]}, row ${at[2]})`);
  });
  assert.deepEqual(await page.getAttribute(".lab-pair .lab-canvas", "aria-describedby"), "lab-search-data-desc");
  assert.deepEqual((await axe())[0], [], "the lab with the search photo's Data view open");
  // and moved by its handle's keys, matched again where it rests
  await page.focus("#lab-template-handle");
  await page.keyboard.press("ArrowLeft");
  await page.keyboard.press("Enter");
  await page.waitForFunction(() => document.body.dataset.matched === "39,30");
  await idle(page);
  assert.deepEqual(log.pageErrors, []);
});

test("interest points: the description counts them and names the most precise with their coordinates", { timeout: TEST_TIMEOUT }, async () => {
  await choose("#lab-family", "Int", "interest");
  await page.evaluate(() => delete document.body.dataset.points);
  await page.focus("#lab-run");
  await page.keyboard.press("Enter");
  await page.waitForFunction(() => document.body.dataset.points !== undefined);
  await idle(page);
  const n = Number(await page.evaluate(() => document.body.dataset.points));
  assert.ok(n >= 2, `${n} points`);
  const desc = await page.textContent("#lab-view-desc");
  assert.match(desc, new RegExp(`${n} interest points found; the most precise \\(smallest error ellipse\\): `));
  // each point named is one drawn (an ellipse at its c, r), at most five of them
  // (the points are one batch of [c, r, score, σmax, σmin, angle] each: shapes.js pointShape)
  const drawn = new Set(await page.$eval("#lab-stage .lab-canvas", (cv) => cv.labViewer.shapes.flatMap((s) => (s.kind === "points"
    ? Array.from({ length: s.p.length / 6 }, (_, i) => `${s.p[6 * i]},${s.p[6 * i + 1]}`)
    : [`${s.c},${s.r}`]))));
  const named = [...desc.matchAll(/column ([\d.]+), row ([\d.]+) \(σmax ([\d.]+) px\)/g)];
  assert.equal(named.length, Math.min(5, n));
  for (const [, c, r] of named) assert.ok(drawn.has(`${c},${r}`), `${c},${r} is a point drawn`);
  // the most precise first
  const sigmas = named.map((m) => Number(m[3]));
  assert.deepEqual(sigmas, [...sigmas].sort((a, b) => a - b));
});

/** Violations of the WCAG 2.0–2.2 A/AA rules: [inside the lab, elsewhere on the page]. */
async function axe() {
  if (!(await page.evaluate(() => typeof window.axe === "object"))) await page.addScriptTag({ path: AXE });
  // each violating node by whether it is inside the lab's section (#lab) or the page around it
  const nodes = await page.evaluate(async () => {
    const res = await window.axe.run(document, { runOnly: { type: "tag", values: ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa", "wcag22aa"] }, resultTypes: ["violations"] });
    return res.violations.flatMap((v) => v.nodes.map((n) => ({
      line: `${v.id} (${v.impact}): ${n.target.join(" ")}`,
      inLab: Boolean(n.target.length === 1 && document.querySelector(n.target[0])?.closest("#lab")),
    })));
  });
  const lines = (inLab) => nodes.filter((n) => n.inLab === inLab).map((n) => n.line);
  return [lines(true), lines(false)];
}

test("axe-core at 390 and 1280 px, light and dark, with a layer shown and the Data view open; controls at least 24 × 24 px at 390 px", { timeout: TEST_TIMEOUT }, async () => {
  await choose("#lab-family", "Edges", "edges");
  await page.focus("#lab-run");
  await page.keyboard.press("Enter");
  await page.waitForFunction(() => document.body.dataset.layer === "magnitude");
  await idle(page);
  if ((await page.getAttribute("#lab-data-toggle", "aria-expanded")) !== "true") {
    await page.focus("#lab-data-toggle");
    await page.keyboard.press("Enter");
  }
  await page.focus("#lab-stage .lab-canvas");
  await page.keyboard.press("ArrowUp");
  const shell = new Set();
  for (const width of [390, 1280]) {
    await page.setViewportSize({ width, height: 844 });
    for (const scheme of ["light", "dark"]) {
      await page.emulateMedia({ colorScheme: scheme });
      const [lab, other] = await axe();
      assert.deepEqual(lab, [], `${width} px, ${scheme}`);
      for (const o of other) shell.add(o);
    }
  }
  // target size (WCAG 2.5.8) at 390 px: every control of the lab at least 24 × 24 CSS px, in every family
  await page.setViewportSize({ width: 390, height: 844 });
  for (const family of await page.$$eval("#lab-family option", (os) => os.map((o) => o.value))) {
    await page.selectOption("#lab-family", family);
    // (a family loaded when chosen, fiducials: its controls once its module is in)
    await page.waitForFunction(() => document.querySelector("#lab-family-box").childElementCount > 0);
    const small = await page.$$eval("#lab button, #lab select, #lab input, #lab textarea, #lab canvas, #lab [tabindex]", (els) => els
      .filter((e) => e.getClientRects().length && !e.closest("[hidden]"))
      .map((e) => [e.id || e.textContent.trim().slice(0, 20) || e.tagName, e.getBoundingClientRect()])
      .filter(([, b]) => b.width < 24 || b.height < 24)
      .map(([n, b]) => `${n} ${b.width.toFixed(1)} × ${b.height.toFixed(1)}`));
    assert.deepEqual(small, [], family);
  }
  // prefers-reduced-motion: the progress spinner stands still (zoom and pan are never animated)
  const spin = () => page.evaluate(() => {
    const s = document.createElement("span");
    s.className = "lab-spinner";
    document.querySelector("#lab").append(s);
    const name = getComputedStyle(s).animationName;
    s.remove();
    return name;
  });
  await page.emulateMedia({ reducedMotion: "reduce" });
  assert.equal(await spin(), "none");
  await page.emulateMedia({ reducedMotion: "no-preference" });
  assert.equal(await spin(), "lab-spin");
  if (shell.size) console.log(`outside the lab (the page shell): ${[...shell].join("; ")}`);
  assert.deepEqual(log.pageErrors, []);
});
