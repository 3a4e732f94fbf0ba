// One colour convention for every scale (issue 29, item 4): the lab's layers and
// legend use the same signed colours and grey words as the figures' kit.
import assert from "node:assert/strict";
import { test } from "node:test";
import { GREY_WORDS, SIGNED_NEGATIVE, SIGNED_POSITIVE, SIGNED_WORDS } from "../../www/colour-scales.js";
import { diverging } from "../../www/lab/view.js";
import { greyLegendText, greyScale } from "../../www/figures/draw.js";

test("the lab's diverging scale ends in the figures' signed colours, white at 0", () => {
  assert.deepEqual(diverging(-1), [...SIGNED_NEGATIVE]);
  assert.deepEqual(diverging(1), [...SIGNED_POSITIVE]);
  assert.deepEqual(diverging(0), [255, 255, 255]);
  // halfway is halfway to the end colour, and past the end is the end
  assert.deepEqual(diverging(-0.5), SIGNED_NEGATIVE.map((e) => Math.round(255 - 0.5 * (255 - e))));
  assert.deepEqual(diverging(7), [...SIGNED_POSITIVE]);
  assert.equal(SIGNED_WORDS, "blue negative, orange positive");
});

test("the figures' grey legend says the same words as the lab's", () => {
  const text = greyLegendText(greyScale(0, 255, { name: "g" }));
  assert.ok(text.endsWith(GREY_WORDS), text);
  assert.equal(GREY_WORDS, "dark = low");
});
