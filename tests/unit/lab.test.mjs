// The lab's pure helpers in Node: the k×k mean kernel, the fiducial residual
// arrows' scale, the link's state, and the explain links (their example found
// in the catalog by family and reading). (A custom kernel is checked by the
// lab's wasm module in its worker: tests/e2e/lab-interact.test.mjs.)

import { test } from "node:test";
import assert from "node:assert/strict";
import { meanKernel } from "../../www/lab/families/filters.js";
import { niceFloor, residualArrows } from "../../www/lab/families/fiducials.js";

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
  const { filterLink, customFilterLink, edgeLink, useCatalog, exampleFor } = await import("../../www/lab/explain.js");
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
  assert.equal(engineWords("scalar", 4), "standard (no SIMD), 4 threads");
  // the example a link opens is the catalog's: the entry whose lab family and readings name it
  useCatalog([]);
  assert.equal(filterLink("mean", Array(25).fill(1), 5), null);
  useCatalog([{ id: "ex-f", lab: "filters", explains: ["window"] }, { id: "ex-e", lab: "edges", explains: ["window"] }, { id: "gsd" }]);
  assert.deepEqual([exampleFor("filters", "window"), exampleFor("edges", "window"), exampleFor("filters", "rho")], ["ex-f", "ex-e", null]);
  assert.match(filterLink("mean", Array(25).fill(1), 5).hash, /^#\/ex-f\?/);
  assert.equal(edgeLink("sobel", Array(25).fill(1), "gx").id, "ex-e");
  // explain links select the window's centre: the lab's pixel
  const q = (l) => new URLSearchParams(l.hash.split("?")[1]);
  const f = filterLink("gaussian-5", Array(49).fill(1), 7);
  assert.deepEqual([q(f).get("select_c"), q(f).get("select_r"), f.key], ["4", "4", "selected"]);
  const cf = customFilterLink([[1, 1, 1, 1, 1]], 5, Array(21).fill(1), 7);
  assert.deepEqual([q(cf).get("select_c"), q(cf).get("select_r")], ["4", "2"]);
  const e = edgeLink("sobel", Array(25).fill(1), "direction");
  assert.deepEqual([q(e).get("select_c"), q(e).get("select_r"), e.key, e.derive.keys], ["3", "3", "selected_gx", ["selected_gx", "selected_gy"]]);
});
