// The figures' palettes (www/figures/draw.js): WCAG 2.2 contrast on their own
// background, light and dark — 4.5:1 for every colour the figures write text
// in (1.4.3), 3:1 for the marks and outlines that carry meaning (1.4.11).
// Canvas text is out of axe-core's reach; the palette is what decides it.
import test from "node:test";
import assert from "node:assert/strict";
import { PALETTES } from "../../www/figures/draw.js";

/** WCAG's relative luminance of "#rrggbb". */
function luminance(hex) {
  const [r, g, b] = [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16) / 255).map((c) => (c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4));
  return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}
function contrast(a, b) {
  const [hi, lo] = [luminance(a), luminance(b)].sort((x, y) => y - x);
  return (hi + 0.05) / (lo + 0.05);
}

/** Colours used for labels and values drawn as text. */
const TEXT = ["ink", "muted", "pixelSystem", "imageSystem", "point", "green", "red", "ground", "frameStroke", "ray"];
/** Colours of marks, outlines and legends' swatches. */
const MARKS = ["highlight"];

test("contrast is computed as WCAG defines it", () => {
  assert.equal(contrast("#000000", "#ffffff").toFixed(1), "21.0");
  assert.equal(contrast("#777777", "#ffffff").toFixed(2), "4.48");
});

for (const [theme, p] of Object.entries(PALETTES)) {
  test(`the ${theme} palette: text colours ≥ 4.5:1, marks ≥ 3:1 on its background`, () => {
    const low = [];
    for (const k of TEXT) if (p[k] && contrast(p[k], p.background) < 4.5) low.push(`${k} ${p[k]}: ${contrast(p[k], p.background).toFixed(2)}`);
    for (const k of MARKS) if (p[k] && contrast(p[k], p.background) < 3) low.push(`${k} ${p[k]}: ${contrast(p[k], p.background).toFixed(2)}`);
    for (const k of [...TEXT, ...MARKS]) assert.match(String(p[k]), /^#[0-9a-f]{6}$/i, `${theme}.${k} is a colour`);
    assert.deepEqual(low, []);
  });
}
