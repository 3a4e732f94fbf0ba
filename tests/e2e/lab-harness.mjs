// Shared steps of the image lab's end-to-end tests (lab*.test.mjs).
// Not a test file itself (node --test runs only *.test.mjs here).

import { open } from "./harness.mjs";

/** A fresh page on the lab (`#/lab`), its sample menu ready. */
export async function openLab(env, options) {
  const o = await open(env.browser, options);
  await o.page.goto(`${env.url}index.html#/lab`);
  await o.page.waitForSelector("#lab-sample");
  return o;
}

/** Waits until the lab has no request running. */
export async function idle(page) {
  await page.waitForFunction(() => document.body.dataset.lab === "idle", null, { timeout: 60_000 });
}

/** Opens bundled sample `id` (a file name, or "frame") and waits for that photo. */
export async function sample(page, id) {
  await page.selectOption("#lab-sample", id);
  // the body's marks outlive a lab left for an example and opened again: wait for this photo's own
  await page.evaluate(() => delete document.body.dataset.image);
  await page.click("#lab-open-sample");
  await idle(page);
  await page.waitForFunction((want) => (document.body.dataset.image || "").startsWith(want), id === "frame" ? "scanned frame" : id);
}

/** The main view's geometry (lab.js's viewForTests). */
export function viewOf(page) {
  return page.evaluate(async () => (await import("./lab/lab.js")).viewForTests());
}

/** Page coordinates of image pixel (c, r)'s centre in the main view. */
export async function pixelPos(page, c, r) {
  await page.locator("#lab-stage .lab-canvas").scrollIntoViewIfNeeded();
  const g = await viewOf(page);
  return { x: g.left + ((c + 0.5) * g.zoom + g.ox) * (g.w / g.cw), y: g.top + ((r + 0.5) * g.zoom + g.oy) * (g.h / g.ch) };
}

/** Clicks image pixel (c, r) of the main view with the mouse. */
export async function clickPixel(page, c, r) {
  const p = await pixelPos(page, c, r);
  await page.mouse.click(p.x, p.y);
}

/** Förstner's w and q of the size×size window centred on (c, r): central differences over its interior (Example 13). */
export function forstner(g, c, r, size) {
  const a = (size - 1) / 2;
  let [xx, xy, yy] = [0, 0, 0];
  for (let y = r - a + 1; y <= r + a - 1; y++) {
    for (let x = c - a + 1; x <= c + a - 1; x++) {
      const gx = (g(x + 1, y) - g(x - 1, y)) / 2;
      const gy = (g(x, y + 1) - g(x, y - 1)) / 2;
      xx += gx * gx;
      xy += gx * gy;
      yy += gy * gy;
    }
  }
  const det = xx * yy - xy * xy;
  const tr = xx + yy;
  return { w: det / tr, q: (4 * det) / (tr * tr) };
}
