// End-to-end (issue 34, item 2): the moving-window figures in motion
// (www/motion/motion.js, the specs' `frames`). One browser, one page, hash
// navigation; every number compared with solve() in Node.
//  - ncc-surface (the template moving over the search array): at every frame
//    the caption and the live region read that position's ρ, and the step it
//    belongs to is marked in the step list;
//  - ncc-1d: every position's ρ; the chain code: the follower's moves are the
//    solution's pixels and codes, move by move;
//  - filter-window, edge-window: every output pixel's values (the output
//    grids); moravec-window: every pixel's four differences and sum, the mean;
//    forstner-window: every pixel's gradient and terms (the gradient table),
//    then the sums, N, w and q; resample (a position with its 4×4): every
//    stage's numbers, bilinear then the cubic rows and column;
//  - keyboard only (focus and keys, no mouse event): Play, Pause, Step
//    forward and back, the slider (Home, End, arrows);
//  - play= in the link: opens at that frame, paused; a bad value is named;
//  - prefers-reduced-motion: reduce: no Play button, play=auto opens paused,
//    frames change only on a step;
//  - axe-core, WCAG 2.2 AA tags: no violation on a page with the controls.

import assert from "node:assert/strict";
import { createRequire } from "node:module";
import { after, before, describe, test } from "node:test";
import { TEST_TIMEOUT, nodeModule, open, settled, start } from "./harness.mjs";

const AXE = createRequire(import.meta.url).resolve("axe-core/axe.min.js");
const TAGS = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa", "wcag22aa"];

let env;
let page;
let context;
let log;
let core;

before(async () => {
  env = await start();
  ({ context, page, log } = await open(env.browser, { bypassCSP: true }));
  core = await nodeModule("all");
});
after(async () => {
  await context?.close();
  await env?.close();
});

let loaded = false;
/** Opens `#/<hash>` (the first by loading the page, then by hash navigation) and waits for the motion controls. */
async function show(hash) {
  if (!loaded) {
    await page.goto(`${env.url}index.html#/${hash}`);
    loaded = true;
  } else {
    await page.evaluate((h) => {
      // another example builds a new view (its own controls); the same one keeps them
      const id = h.slice(2).split("?")[0];
      if (document.querySelector("article.example")?.dataset.id !== id) for (const m of document.querySelectorAll(".motion")) m.dataset.old = "1";
      document.body.dataset.status = "routing";
      location.hash = h;
    }, `#/${hash}`);
  }
  assert.equal(await settled(page), "ok", hash);
  await page.waitForSelector(".motion:not([data-old]):not([hidden])");
}

/** The motion's state as the page shows it. */
const state = () =>
  page.evaluate(() => {
    const m = document.querySelector(".motion");
    return {
      frame: m.dataset.frame === "" ? null : Number(m.dataset.frame),
      playing: m.dataset.playing === "true",
      caption: m.querySelector(".motion-caption").textContent,
      live: m.querySelector(".motion-live").textContent,
      counter: m.querySelector(".motion-counter")?.textContent ?? null,
      slider: m.querySelector(".motion-slider")?.value ?? null,
      playHidden: m.querySelector(".motion-play").hidden,
      marked: [...document.querySelectorAll(".steps .step-playing")].map((s) => s.id),
      hash: location.hash,
      notice: document.querySelector(".options-notice")?.textContent ?? "",
    };
  });

/** Presses `key` on the control `selector` of the motion (focused by the keyboard's focus, not a click). */
async function press(selector, key = "Enter") {
  await page.locator(`.motion ${selector}`).focus();
  await page.keyboard.press(key);
}

/** A number as the page writes it ("−1.2345 × 10⁻⁶"). */
function readNumber(text) {
  const sup = { "⁻": "-", "⁰": "0", "¹": "1", "²": "2", "³": "3", "⁴": "4", "⁵": "5", "⁶": "6", "⁷": "7", "⁸": "8", "⁹": "9" };
  const [m, e] = text.replace(/−/g, "-").split(" × 10");
  return Number(m) * 10 ** Number([...(e ?? "0")].map((ch) => sup[ch] ?? ch).join(""));
}

/** The last number of a text ("… = −0.3301" → −0.3301). */
const lastNumber = (text) => Number(/(−|-)?\d+(\.\d+)?(?=[^\d]*$)/.exec(text)[0].replace("−", "-"));

describe("motion", { timeout: TEST_TIMEOUT * 2 }, () => {
  test("ncc-surface: every frame reads that position's ρ, its step marked; keyboard only", async () => {
    const s = core.solve("ncc-surface", {});
    const rho = s.result.rho;
    const w = rho[0].length;
    const n = rho.length * w;
    const surfaceStep = s.steps.findIndex((st) => Array.isArray(st.values?.rho));
    const fullStep = s.steps.findIndex((st) => st.values && "window" in st.values);
    await show("ncc-surface");
    let st = await state();
    assert.equal(st.frame, null, "without play= the figure shows every position");
    assert.match(st.counter, new RegExp(`All ${n} positions`));
    for (let i = 0; i < n; i++) {
      await press(".motion-forward");
      st = await state();
      const [r, c] = [Math.floor(i / w), i % w];
      assert.equal(st.frame, i + 1);
      assert.equal(st.counter, `Position ${i + 1} of ${n}`);
      assert.match(st.caption, new RegExp(`^Position ${i + 1}\\b`));
      assert.match(st.caption, new RegExp(`rows ${r + 1}–${r + s.inputs.template.length}, columns ${c + 1}–`));
      assert.ok(Math.abs(lastNumber(st.caption) - rho[r][c]) <= 0.5e-4, `position ${i + 1}: ${st.caption} vs ${rho[r][c]}`);
      assert.ok(st.live.startsWith(`position ${i + 1} of ${n}.`), st.live);
      assert.ok(st.live.endsWith(st.caption), "the live region reads the caption");
      const best = s.result.best_row === r + 1 && s.result.best_col === c + 1;
      assert.deepEqual(st.marked, [`step-${(best ? fullStep : surfaceStep) + 1}`], `position ${i + 1}'s step`);
      assert.match(st.hash, new RegExp(`[?&]play=${i + 1}(&|$)`), "the link follows the frame");
    }
    // the slider, by keyboard
    await press(".motion-slider", "Home");
    st = await state();
    assert.equal(st.frame, 1);
    assert.equal(lastNumber(st.caption).toFixed(4), rho[0][0].toFixed(4));
    await press(".motion-slider", "ArrowRight");
    assert.equal((await state()).frame, 2);
    await press(".motion-slider", "End");
    assert.equal((await state()).frame, n);
    await press(".motion-back");
    assert.equal((await state()).frame, n - 1);
    // Play from the first frame, then Pause
    await press(".motion-slider", "Home");
    await press(".motion-play");
    await page.waitForFunction(() => Number(document.querySelector(".motion").dataset.frame) >= 3);
    assert.equal((await state()).playing, true);
    await page.keyboard.press("Enter"); // the focus stays on the button, now "Pause"
    st = await state();
    assert.equal(st.playing, false);
    assert.ok(st.frame >= 3, "it moved");
    assert.match(st.live, new RegExp(`^Paused at position ${st.frame} of ${n}\\.`));
    assert.match(st.hash, new RegExp(`[?&]play=${st.frame}(&|$)`));
    // Show all: no frame, no marked step, no play= in the link
    await press(".motion-all");
    st = await state();
    assert.equal(st.frame, null);
    assert.deepEqual(st.marked, []);
    assert.doesNotMatch(st.hash, /play=/);
  });

  test("ncc-1d: every position's ρ", async () => {
    const s = core.solve("ncc-1d", {});
    await show("ncc-1d");
    await press(".motion-slider", "Home");
    for (let k = 0; k < s.result.rho.length; k++) {
      if (k) await page.keyboard.press("ArrowRight");
      const st = await state();
      assert.equal(st.frame, k + 1);
      assert.ok(Math.abs(lastNumber(st.caption) - s.result.rho[k]) <= 0.5e-4, st.caption);
      // "Sub-window k" is that position's step
      assert.deepEqual(st.marked, [`step-${s.steps.findIndex((x) => x.values?.k === k + 1) + 1}`]);
    }
  });

  test("chain-code: the follower's moves are the solution's pixels and codes", async () => {
    const s = core.solve("chain-code", {});
    const { code, pixels } = s.result;
    await show("chain-code");
    await press(".motion-slider", "Home");
    for (let k = 0; k < code.length; k++) {
      if (k) await page.keyboard.press("ArrowRight");
      const st = await state();
      assert.equal(st.counter, `Move ${k + 1} of ${code.length}`);
      const m = /^Move (\d+): from column (-?\d+), row (-?\d+) to column (-?\d+), row (-?\d+), [a-z-]+: code (\d)\./.exec(st.caption);
      assert.ok(m, st.caption);
      const [, no, c0, r0, c1, r1, digit] = m.map(Number);
      assert.equal(no, k + 1);
      assert.deepEqual([c0, r0], pixels[k]);
      assert.deepEqual([c1, r1], pixels[k + 1]);
      assert.equal(digit, code[k]);
      assert.ok(st.caption.endsWith(`The code so far: ${code.slice(0, k + 1).join(" ")}.`));
    }
  });

  test("lsm-2d: frame k shows iteration k's numbers, the figure's iteration slider with it", async () => {
    const s = core.solve("lsm-2d", {});
    const v = s.steps.find((x) => x.title === "Every iteration").values;
    const n = v.sigma0.length;
    await show("lsm-2d");
    for (let k = 0; k < n; k++) {
      await press(".motion-forward");
      const st = await state();
      assert.equal(st.frame, k + 1);
      // the figure's own iteration slider is the scrub: it follows, and names the frame
      assert.equal(await page.locator(".figure-slider span").first().textContent(), `Iteration ${k + 1} of ${n}`);
      const num = (key) => readNumber(new RegExp(`(?:^|[ (])${key} = (−?[\\d.]+(?: × 10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?)`).exec(st.caption)?.[1] ?? "");
      for (const key of ["c", "r", "a", "b", "dc", "dr", "da", "db"]) {
        assert.ok(Math.abs(num(key) - v[key][k]) <= 1e-4 * Math.max(1, Math.abs(v[key][k])), `iteration ${k + 1}: ${key} in “${st.caption}” vs ${v[key][k]}`);
      }
      assert.ok(Math.abs(lastNumber(st.caption) - v.sigma0[k]) <= 1e-4 * Math.max(1, v.sigma0[k]), st.caption);
      assert.equal(await page.locator(".figure-slider input").first().inputValue(), String(k + 1));
      assert.deepEqual(st.marked, [`step-${s.steps.findIndex((x) => x.title === "Every iteration") + 1}`]);
    }
    // that slider scrubs the motion
    await page.locator(".figure-slider input").first().focus();
    await page.keyboard.press("Home");
    const st = await state();
    assert.equal(st.frame, 1);
    assert.match(st.caption, new RegExp(`^Iteration 1 of ${n}:`));
  });

  /** Steps through every frame by the slider's keys (Home, then →), giving each frame's state to `check`. */
  async function everyFrame(count, check) {
    await press(".motion-slider", "Home");
    for (let k = 0; k < count; k++) {
      if (k) await page.keyboard.press("ArrowRight");
      const st = await state();
      assert.equal(st.frame, k + 1);
      await check(k, st);
    }
  }
  const NUM = "(−?\\d+(?:\\.\\d+)?(?: × 10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?)";
  /** The number after `label` (a regular expression's source) in `text`. */
  const after = (text, label) => {
    const m = new RegExp(`${label}${NUM}`).exec(text);
    assert.ok(m, `${label} in “${text}”`);
    return readNumber(m[1]);
  };
  const near = (a, b, what) => assert.ok(Math.abs(a - b) <= 0.5e-4 * Math.max(1, Math.abs(b)), `${what}: ${a} vs ${b}`);

  for (const [id, grids] of [
    ["filter-window", (s) => [["g", s.result.output]]],
    ["edge-window", (s) => [["Gx", s.result.gx], ["Gy", s.result.gy], ["\\|G\\|", s.result.magnitude]]],
  ]) {
    test(`${id}: every output pixel's values are the solution's output grids`, async () => {
      const s = core.solve(id, {});
      const g = grids(s);
      const rows = g[0][1].length;
      const cols = g[0][1][0].length;
      await show(id);
      await everyFrame(rows * cols, async (k, st) => {
        const [r, c] = [Math.floor(k / cols), k % cols];
        const at = { c: s.result.output_first_c + c, r: s.result.output_first_r + r };
        assert.match(st.caption, new RegExp(`^Output pixel ${k + 1}: the kernel over rows ${at.r - 1}–${at.r + 1}, columns ${at.c - 1}–${at.c + 1} of the window; at row ${at.r}, column ${at.c}: `));
        for (const [name, m] of g) near(after(st.caption, `${name} = `), m[r][c], `${id} frame ${k + 1} ${name}`);
      });
    });
  }

  test("moravec-window: pixel by pixel its four differences and their sum, then the mean", async () => {
    const s = core.solve("moravec-window", {});
    const rows = s.result.differences;
    await show("moravec-window");
    await everyFrame(rows.length, async (k, st) => {
      const [c, r, g, d1, d2, d3, d4, sum] = rows[k];
      assert.match(st.caption, new RegExp(`^Pixel ${k + 1}: P\\(c${c}, r${r}\\) = `));
      near(after(st.caption, "\\) = "), g, "grey value");
      [["→ ", d1], ["↓ ", d2], ["↘ ", d3], ["↙ ", d4]].forEach(([glyph, v]) => near(after(st.caption, glyph), v, `pixel ${k + 1} ${glyph}`));
      near(after(st.caption, "the sum of their squares "), sum, `pixel ${k + 1} sum`);
      if (k === rows.length - 1) near(after(st.caption, `The mean of the ${rows.length} sums: `), s.result.mean, "mean");
      else assert.doesNotMatch(st.caption, /mean/);
    });
  });

  test("forstner-window: pixel by pixel the gradient table's terms, then the sums, N, w and q", async () => {
    const s = core.solve("forstner-window", {});
    const table = s.steps.find((x) => x.values?.table).values.table;
    const sums = s.steps.find((x) => x.values && "sum_gx2" in x.values).values;
    const m = table.length;
    const stepOf = (key) => `step-${s.steps.findIndex((x) => x.values && key in x.values) + 1}`;
    await show("forstner-window");
    await everyFrame(m + 4, async (k, st) => {
      if (k < m) {
        const [c, r, g, gx, gy, gxgy, gx2, gy2] = table[k];
        assert.match(st.caption, new RegExp(`^Pixel ${k + 1} of ${m}: P\\(c${c}, r${r}\\) = `));
        near(after(st.caption, "\\) = "), g, "grey value");
        near(after(st.caption, "g′x = \\([^)]*\\) / 2 = "), gx, `pixel ${k + 1} g′x`);
        near(after(st.caption, "g′y = \\([^)]*\\) / 2 = "), gy, `pixel ${k + 1} g′y`);
        near(after(st.caption, "g′x² = "), gx2, `pixel ${k + 1} g′x²`);
        near(after(st.caption, "g′y² = "), gy2, `pixel ${k + 1} g′y²`);
        near(after(st.caption, "g′x·g′y = "), gxgy, `pixel ${k + 1} g′x·g′y`);
        assert.deepEqual(st.marked, [stepOf("table")]);
      } else if (k === m) {
        near(after(st.caption, "Σg′x² = "), sums.sum_gx2, "Σg′x²");
        near(after(st.caption, "Σg′y² = "), sums.sum_gy2, "Σg′y²");
        near(after(st.caption, "Σg′x·g′y = "), sums.sum_gxgy, "Σg′x·g′y");
        assert.deepEqual(st.marked, [stepOf("sum_gx2")]);
      } else if (k === m + 1) {
        const n = /= \[(\S+)  (\S+); (\S+)  (\S+)\]\.$/.exec(st.caption);
        assert.ok(n, st.caption);
        n.slice(1).forEach((v, i) => near(readNumber(v), s.result.n[i >> 1][i & 1], `N ${i}`));
        assert.deepEqual(st.marked, [stepOf("n")]);
      } else if (k === m + 2) {
        assert.match(st.caption, /^w = det N \/ trace N = /);
        near(lastNumber(st.caption), s.result.w, "w");
        assert.deepEqual(st.marked, [stepOf("w")]);
      } else {
        assert.match(st.caption, /^q = 4 det N \/ trace² N = /);
        near(lastNumber(st.caption), s.result.q, "q");
        assert.deepEqual(st.marked, [stepOf("q")]);
      }
    });
  });

  test("resample: the stages at the position, bilinear then the 4×4's rows and column", async () => {
    const inputs = { c: 546.44, r: 818.24 };
    const s = core.solve("resample", inputs);
    const v = (key) => s.steps.find((x) => x.values && key in x.values).values[key];
    const res = s.result;
    assert.equal(typeof res.bicubic, "number", "this position has its 4×4");
    await show(`resample?c=${inputs.c}&r=${inputs.r}`);
    const rows = v("row_values");
    const weights = v("weights");
    const corners = v("corners");
    await everyFrame(12, async (k, st) => {
      const cap = st.caption;
      if (k === 0) [["x = c − \\S+ = ", v("x")], ["y = r − \\S+ = ", v("y")]].forEach(([l, x]) => near(after(cap, l), x, l));
      if (k === 1) {
        assert.ok(cap.includes(`pixel (${res.nearest_c}, ${res.nearest_r})`), cap);
        near(lastNumber(cap), res.nearest, "nearest");
      }
      if (k === 2) {
        const w = cap.split("dc·dr = ")[1].replace(/\.$/, "").split(", ").map(readNumber);
        assert.equal(w.length, 4);
        w.forEach((x, i) => near(x, weights[i], `weight ${i}`));
        assert.ok(cap.includes(`: ${corners.join(", ")};`), cap);
      }
      if (k === 3) near(lastNumber(cap), res.i1, "I₁");
      if (k === 4) near(lastNumber(cap), res.i2, "I₂");
      if (k === 5) near(after(cap, "I = \\(1 − dr\\)·I₁ \\+ dr·I₂ = "), res.bilinear, "bilinear");
      if (k === 6) v("weights_c").forEach((x, i) => near(readNumber(/w_c = \[([^\]]+)\]/.exec(cap)[1].split(", ")[i]), x, `w_c ${i}`));
      if (k >= 7 && k <= 10) {
        assert.ok(cap.startsWith(`Bicubic, row ${v("bicubic_r") + k - 7}: [${v("neighbourhood")[k - 7].join(", ")}] · w_c = `), cap);
        near(lastNumber(cap), rows[k - 7], `row ${k - 7}`);
      }
      if (k === 11) near(lastNumber(cap), res.bicubic, "bicubic");
    });
    assert.equal((await state()).counter, "Stage 12 of 12");
  });

  test("play= opens at a frame, paused; a bad value is named", async () => {
    await show("ncc-surface?play=7");
    let st = await state();
    assert.equal(st.frame, 7);
    assert.equal(st.playing, false);
    assert.match(st.hash, /[?&]play=7(&|$)/);
    await show("ncc-surface?play=seven");
    st = await state();
    assert.match(st.notice, /play=“seven”: give a frame number from 1 to \d+ \(opens paused there\) or auto/);
    // a frame past the last: the last
    await show("ncc-1d?play=99");
    assert.equal((await state()).frame, 6);
  });

  test("axe-core, WCAG 2.2 AA: no violation with the motion controls", async () => {
    await show("ncc-surface?play=5");
    await page.addScriptTag({ path: AXE });
    const result = await page.evaluate((tags) => window.axe.run({ include: [".figure-section", ".steps-panel"], exclude: [".katex-html"] }, { runOnly: { type: "tag", values: tags }, resultTypes: ["violations"] }), TAGS);
    assert.deepEqual(
      result.violations.map((v) => `${v.id}: ${v.nodes.map((x) => x.target.join(" ")).join(", ")}`),
      [],
    );
  });

  test("prefers-reduced-motion: reduce: no Play, play=auto opens paused, frames change only on a step", async () => {
    await page.emulateMedia({ reducedMotion: "reduce" });
    await show("ncc-surface?play=auto");
    let st = await state();
    assert.equal(st.playHidden, true, "no Play button");
    assert.equal(st.frame, 1, "play=auto opens at the first frame");
    assert.equal(st.playing, false, "and does not play");
    await press(".motion-forward");
    st = await state();
    assert.equal(st.frame, 2);
    assert.equal(st.playing, false);
    await page.emulateMedia({ reducedMotion: "no-preference" });
    // Play comes back with the setting (its change event)
    await page.waitForFunction(() => document.querySelector(".motion-play").hidden === false);
    assert.deepEqual(log.pageErrors, []);
    assert.deepEqual(log.consoleErrors, []);
  });
});
