// The colour conventions of every scale, figures and the lab alike (one
// place, so that the two cannot disagree):
//  - grey values: dark = low, light = high (an image's own convention);
//  - signed values: blue below zero, orange above, white (or the paper) at 0.
// figures/draw.js draws its grey scales and legends from these, figures/filters.js
// its signed kernels and outputs, lab/view.js its layers, lab/lab.js its legend.

/** Blue, for values below zero (RGB). */
export const SIGNED_NEGATIVE = Object.freeze([29, 95, 191]);
/** Orange, for values above zero (RGB). */
export const SIGNED_POSITIVE = Object.freeze([217, 119, 6]);
/** The signed scale in words. */
export const SIGNED_WORDS = "blue negative, orange positive";
/** The grey scale in words. */
export const GREY_WORDS = "dark = low";

/** "r, g, b" for a CSS rgb()/rgba(). */
export const rgbText = (c) => c.join(", ");
