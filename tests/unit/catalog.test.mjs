// The catalog's search and course order (www/catalog.js), in Node, over the
// sources as the Rust entries write them.
import { describe, it } from "node:test";
import assert from "node:assert/strict";
import { courseNumbers, coursePath, fold, matches, topicsInOrder } from "../../www/catalog.js";

const entry = (id, title, topic, source, summary = "") => ({ id, title, topic, source, summary, document: "", status: "ready" });
const ENTRIES = [
  entry("gsd", "Ground sample distance", "Coordinates", "Worked examples, Example 2"),
  entry("pixel-to-photo", "Pixel to image coordinates", "Coordinates", "Worked examples, Example 1"),
  entry("fiducial-affine", "Fiducials: affine transformation", "Transformations", "Worked examples, Example 4(b)"),
  entry("fiducial-similarity", "Fiducials: similarity transformation", "Transformations", "Worked examples, Example 4(a)"),
  entry("transform-fit", "2-D transformations by least squares", "Transformations", "Lecture 7: Image processing, Table 9.5.1"),
  entry("filter-window", "Filtering a window", "Filters and edges", "Worked examples, Examples 15–16; Lecture 7: Image processing"),
  entry("forstner-window", "Förstner operator", "Interest operators", "Worked examples, Example 13; Lecture 21: Image matching"),
  entry("forstner-image", "Förstner operator on a test pattern", "Interest operators", "Lecture 21: Image matching; Worked examples, Example 13", "a generated 64×64 pattern"),
  entry("boundary-shape", "Boundary descriptors", "Chain codes and boundaries", "Worked examples, boundary descriptors"),
];

describe("the search", () => {
  it("ignores case and accents", () => {
    assert.equal(fold("Förstner GSD"), "forstner gsd");
    assert.deepEqual(ENTRIES.filter((e) => matches(e, "FORSTNER")).map((e) => e.id), ["forstner-window", "forstner-image"]);
    assert.deepEqual(ENTRIES.filter((e) => matches(e, "gsd")).map((e) => e.id), ["gsd"]);
  });

  it("reads a number as an example or lecture number, not as digits anywhere", () => {
    assert.deepEqual(courseNumbers("Worked examples, Examples 15–16; Lecture 7: Image processing"), [15, 16, 7]);
    assert.deepEqual(courseNumbers("Worked examples, Example 4(a)"), [4]);
    assert.deepEqual(ENTRIES.filter((e) => matches(e, "16")).map((e) => e.id), ["filter-window"]);
    assert.deepEqual(ENTRIES.filter((e) => matches(e, "64")).map((e) => e.id), [], "not the 64×64 of a summary");
    assert.deepEqual(ENTRIES.filter((e) => matches(e, "lecture 21")).map((e) => e.id), ["forstner-window", "forstner-image"]);
  });

  it("needs every word; an empty search keeps everything", () => {
    assert.deepEqual(ENTRIES.filter((e) => matches(e, "fiducials affine")).map((e) => e.id), ["fiducial-affine"]);
    assert.equal(ENTRIES.filter((e) => matches(e, "  ")).length, ENTRIES.length);
  });
});

describe("Start here", () => {
  it("is the worked examples in the course notes' order, letters in order, unnumbered ones last", () => {
    assert.deepEqual(coursePath(ENTRIES).map((e) => e.id), ["pixel-to-photo", "gsd", "fiducial-similarity", "fiducial-affine", "forstner-window", "filter-window", "boundary-shape"]);
  });

  it("leaves out examples from the lectures and those not ready", () => {
    const path = coursePath([...ENTRIES, { ...entry("x", "X", "T", "Worked examples, Example 3"), status: "coming" }]).map((e) => e.id);
    assert.ok(!path.includes("transform-fit") && !path.includes("forstner-image") && !path.includes("x"));
  });

  it("topics keep the catalog's order", () => {
    assert.deepEqual(topicsInOrder(ENTRIES), ["Coordinates", "Transformations", "Filters and edges", "Interest operators", "Chain codes and boundaries"]);
  });
});
