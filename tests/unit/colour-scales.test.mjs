// One colour convention for every scale (issue 29, item 4): the lab's layers and
// legend use the same signed colours and grey words as the figures' kit. (The
// lab's layers are painted by its wasm from colour-scales.js's end colours:
// tests/e2e/lab_tiles.test.mjs checks the painted pixels, lab/src/paint.rs the rule.)
import assert from "node:assert/strict";
import { test } from "node:test";
import { GREY_WORDS, SIGNED_NEGATIVE, SIGNED_POSITIVE, SIGNED_WORDS } from "../../www/colour-scales.js";
import { greyLegendText, greyScale } from "../../www/figures/draw.js";

test("the figures' grey legend says the same words as the lab's", () => {
  const text = greyLegendText(greyScale(0, 255, { name: "g" }));
  assert.ok(text.endsWith(GREY_WORDS), text);
  assert.equal(GREY_WORDS, "dark = low");
});

test("the signed scale: blue below zero, orange above, in its words", () => {
  assert.equal(SIGNED_WORDS, "blue negative, orange positive");
  // blue: more blue than red; orange: more red than blue
  assert.ok(SIGNED_NEGATIVE[2] > SIGNED_NEGATIVE[0] && SIGNED_POSITIVE[0] > SIGNED_POSITIVE[2]);
});
