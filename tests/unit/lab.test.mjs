// The lab's pure helpers in Node: the custom kernel's parser (the same rules
// and messages as lab/src/ops.rs's custom_kernel), the k×k mean kernel, and
// the fiducial residual arrows' scale.

import { test } from "node:test";
import assert from "node:assert/strict";
import { parseKernel, meanKernel, MAX_KERNEL } from "../../www/lab/families.js";
import { niceFloor, residualArrows } from "../../www/lab/families2.js";

test("a custom kernel is parsed with the Rust side's rules and messages", () => {
  assert.deepEqual(parseKernel("1, 2, 1; 2 4 2\n 1 2 1 "), { rows: [[1, 2, 1], [2, 4, 2], [1, 2, 1]], divisor: 16, width: 3, height: 3, normalised: true });
  assert.equal(parseKernel("-1 0 1", "2").divisor, 2);
  assert.equal(parseKernel("1e1 -.5 +3").rows[0][1], -0.5);
  const big = Array.from({ length: MAX_KERNEL + 2 }, () => "1 ".repeat(MAX_KERNEL + 2)).join("\n");
  for (const [text, d, field, says] of [
    ["1 2 x", "", "custom_kernel", 'row 1: "x" is not a number'],
    ["1 2 0x10", "", "custom_kernel", 'row 1: "0x10" is not a number'],
    ["1 2 1\n2 4", "", "custom_kernel", "row 2 has 2 numbers but row 1 has 3; every row needs the same number"],
    ["1 1\n1 1", "", "custom_kernel", "is 2×2 (rows × columns); a kernel needs an odd number of rows and of columns, so that it has a centre pixel"],
    [big, "", "custom_kernel", "is 17×17 (rows × columns); at most 15×15 is allowed"],
    [" \n ", "", "custom_kernel", "is empty; type rows of numbers, e.g. 1 2 1 / 2 4 2 / 1 2 1 on three lines"],
    ["0 0 0", "", "custom_kernel", "all weights are 0: the result would be 0 everywhere"],
    ["-1 0 1", "", "custom_divisor", "the weights sum to 0, so the kernel cannot be normalised; give a divisor (1 applies it as written)"],
    ["1 2 1", "0", "custom_divisor", "must be a finite number other than 0"],
    ["1 2 1", "abc", "custom_divisor", "must be a finite number other than 0"],
  ]) {
    assert.deepEqual(parseKernel(text, d), { field, error: says }, text);
  }
});

test("the k×k mean kernel, and the residual arrows' nice scale", () => {
  assert.deepEqual(meanKernel(3), { rows: [[1, 1, 1], [1, 1, 1], [1, 1, 1]], divisor: 9, width: 3, height: 3 });
  assert.deepEqual([niceFloor(7.3), niceFloor(0.031), niceFloor(2), niceFloor(199)], [5, 0.02, 2, 100]);
  // residuals up to 0.2 mm, 0.25 mm pixels, reach 120 px: 150× → 100×; bar 0.1 mm = 40 px
  const r = residualArrows([100, 100, 200, 100, 150, 50, 150, 150], [{ v: [0.2, 0, 0, -0.1, 0, 0, 0, 0], colour: "red" }], 0.25);
  assert.equal(r.times, 100);
  assert.deepEqual(r.arrows[0].to, [180, 100]);
  assert.deepEqual(r.arrows[1].to, [200, 140]); // y up: a negative vy points down the rows
  assert.equal(r.barMm, 0.1);
  assert.equal(r.barPx, 40);
});

test("the lab's link: its state's entries in a fixed order, samples by name, the start sample, the engine's words", async () => {
  const { stateEntries, sampleOf, startSample, engineWords } = await import("../../www/lab/lab.js");
  const { filterLink, customFilterLink, edgeLink } = await import("../../www/lab/explain.js");
  assert.deepEqual(stateEntries({ sample: "chessboard", family: "filters", controls: [["kernel", "mean"], ["border", "replicate"]], run: true, layer: "mean", mode: "over", opacity: "0.7", pick: [320, 240], view: { zoom: 3.14159, c: 320.4, r: 239.6 } }), [
    ["sample", "chessboard"], ["family", "filters"], ["kernel", "mean"], ["border", "replicate"], ["run", "1"], ["layer", "mean"], ["c", "320"], ["r", "240"], ["zoom", "3.142"], ["vc", "320"], ["vr", "240"],
  ]);
  // the student's photo: named "yours" (its bytes never go into a link); a view left fitted and defaults are left out
  assert.deepEqual(stateEntries({ sample: null, photo: true, family: "edges", controls: [], run: false, layer: null, mode: "beside", opacity: "0.4", pick: null, view: null }), [
    ["photo", "yours"], ["family", "edges"], ["mode", "beside"], ["opacity", "0.4"],
  ]);
  assert.equal(sampleOf("chessboard").id, "left01.jpg");
  assert.equal(sampleOf("camera.png").key, "cameraman");
  assert.equal(sampleOf("<script>"), null);
  assert.deepEqual(["filters", "correlation", "fiducials"].map(startSample), ["left01.jpg", "aero1.jpg", "frame"]);
  assert.equal(engineWords("simd128", 1), "fast (SIMD), 1 thread");
  assert.equal(engineWords("scalar", 4), "standard (no SIMD), 4 threads for filters and edges");
  // explain links select the window's centre: the lab's pixel
  const q = (l) => new URLSearchParams(l.hash.split("?")[1]);
  const f = filterLink("gaussian-5", Array(49).fill(1), 7);
  assert.deepEqual([q(f).get("select_c"), q(f).get("select_r"), f.key], ["4", "4", "selected"]);
  const cf = customFilterLink([[1, 1, 1, 1, 1]], 5, Array(21).fill(1), 7);
  assert.deepEqual([q(cf).get("select_c"), q(cf).get("select_r")], ["4", "2"]);
  const e = edgeLink("sobel", Array(25).fill(1), "direction");
  assert.deepEqual([q(e).get("select_c"), q(e).get("select_r"), e.key, e.derive.keys], ["3", "3", "selected_gx", ["selected_gx", "selected_gy"]]);
});
