// Photos as they are taken (issue 31, item 4), in Chromium, on one page:
// JPEGs with each EXIF orientation 1–8 shown upright (the size Chromium
// itself gives them, the info line says what was done); WebP, BMP and GIF
// open; a HEIC and an AVIF are refused with the way to a JPEG and the lab
// keeps working; a 12 MP JPEG opens as it is and Förstner runs over it end
// to end; a 48 MP portrait JPEG is offered reduced 2× and opens at
// 3024 × 4032 when accepted. The large
// JPEGs are made here by Chromium's encoder (nothing big in git).

import { test, before, after } from "node:test";
import assert from "node:assert/strict";
import fs from "node:fs";
import path from "node:path";
import { start, TEST_TIMEOUT } from "./harness.mjs";
import { idle, openLab, pixelPos, clickPixel, forstner } from "./lab-harness.mjs";

const CORPUS = path.resolve("lab/tests/corpus");
let env;
let page;
let log;
before(async () => {
  env = await start();
  ({ page, log } = await openLab(env));
  await page.waitForFunction(() => document.body.dataset.image === "left01.jpg", null, { timeout: 30_000 });
  await idle(page);
});
after(async () => {
  await env?.close();
});

/** Picks corpus file `name` with the lab's file input and waits for it on the stage. */
async function pick(name) {
  await page.setInputFiles("#lab-file", path.join(CORPUS, name));
  await page.waitForFunction((n) => document.body.dataset.image === n, name, { timeout: 30_000 });
  await idle(page);
  return page.textContent("#lab-info");
}

const grey = (box) => page.evaluate(async (b) => (await import("./lab/lab.js")).greyForTests(b), box);
const layerAt = (name, pixels) => page.evaluate(async ([n, p]) => (await import("./lab/lab.js")).layerForTests(n, p), [name, pixels]);

/** The orientation JPEGs' stored pixels (lab/tests/decode.rs block6): 24 × 16 in six flat 8×8 blocks. */
const block6 = (x, y) => 20 + 40 * (Math.floor(x / 8) + 3 * Math.floor(y / 8));
/** Where stored pixel (x, y) lands upright under EXIF orientation o (24 × 16 stored). */
function lands(o, x, y) {
  const [w, h] = [24, 16];
  return [null, [x, y], [w - 1 - x, y], [w - 1 - x, h - 1 - y], [x, h - 1 - y], [y, x], [h - 1 - y, x], [h - 1 - y, w - 1 - x], [y, w - 1 - x]][o];
}
const WORDS = [null, null, "mirrored left to right", "turned 180°", "mirrored top to bottom", "turned 90° clockwise and mirrored left to right",
  "turned 90° clockwise", "turned 90° counter-clockwise and mirrored left to right", "turned 90° counter-clockwise"];

test("a JPEG with each EXIF orientation 1–8 is upright, as Chromium shows it, and the info line says what was done", { timeout: TEST_TIMEOUT * 2 }, async () => {
  for (let o = 1; o <= 8; o++) {
    const name = `orient_${o}.jpg`;
    const info = await pick(name);
    const [w, h] = o >= 5 ? [16, 24] : [24, 16];
    assert.ok(info.includes(`${name}: ${w} × ${h} pixels, JPEG`), info);
    if (WORDS[o]) assert.ok(info.includes(`; ${WORDS[o]} by its EXIF orientation (${o})`), info);
    else assert.doesNotMatch(info, /EXIF/);
    // every stored pixel where the orientation puts it
    const g = await grey([0, 0, w, h]);
    for (let y = 0; y < 16; y++) {
      for (let x = 0; x < 24; x++) {
        const [u, v] = lands(o, x, y);
        assert.equal(g[v * w + u], block6(x, y), `${name}: stored (${x}, ${y}) at (${u}, ${v})`);
      }
    }
    // Chromium's own decoder, which applies the orientation as the browser shows the photo: same size, same corner
    const shown = await page.evaluate(async (bytes) => {
      const bmp = await createImageBitmap(new Blob([new Uint8Array(bytes)], { type: "image/jpeg" }));
      const c = new OffscreenCanvas(bmp.width, bmp.height);
      const g2 = c.getContext("2d");
      g2.drawImage(bmp, 0, 0);
      return { w: bmp.width, h: bmp.height, topLeft: g2.getImageData(0, 0, 1, 1).data[0], bottomRight: g2.getImageData(bmp.width - 1, bmp.height - 1, 1, 1).data[0] };
    }, [...fs.readFileSync(path.join(CORPUS, name))]);
    assert.deepEqual([shown.w, shown.h], [w, h], name);
    assert.ok(Math.abs(shown.topLeft - g[0]) <= 2 && Math.abs(shown.bottomRight - g[w * h - 1]) <= 2, `${name}: Chromium ${shown.topLeft}, ${shown.bottomRight}; lab ${g[0]}, ${g[w * h - 1]}`);
  }
  assert.deepEqual(log.pageErrors, []);
});

test("WebP, BMP and GIF open; a HEIC and an AVIF are refused with the way to a JPEG, and the lab keeps working", { timeout: TEST_TIMEOUT * 2 }, async () => {
  // grey8 (10·c + 40·r) and rgb8's luma (make_corpus.py)
  const rgb8 = (c, r) => (299 * 50 * c + 587 * 60 * r + 114 * (200 - 30 * c)) / 1000;
  for (const [name, kind, want] of [["rgb8.webp", "WebP, colour", rgb8], ["rgb8.bmp", "BMP, colour", rgb8], ["grey8.gif", "GIF", (c, r) => 10 * c + 40 * r]]) {
    const info = await pick(name);
    assert.ok(info.includes(`${name}: 4 × 3 pixels, ${kind}`), info);
    assert.deepEqual(await grey([0, 0, 4, 3]), [0, 1, 2].flatMap((r) => [0, 1, 2, 3].map((c) => want(c, r))), name);
  }
  // a lossy WebP from Chromium's encoder, dropped on the lab: left half dark, right half light
  await page.evaluate(async () => {
    const c = new OffscreenCanvas(64, 48);
    const g = c.getContext("2d");
    g.fillStyle = "#202020";
    g.fillRect(0, 0, 32, 48);
    g.fillStyle = "#e0e0e0";
    g.fillRect(32, 0, 32, 48);
    const dt = new DataTransfer();
    dt.items.add(new File([await c.convertToBlob({ type: "image/webp", quality: 0.9 })], "chromium.webp", { type: "image/webp" }));
    document.getElementById("lab").dispatchEvent(new DragEvent("drop", { dataTransfer: dt, bubbles: true, cancelable: true }));
  });
  await page.waitForFunction(() => document.body.dataset.image === "chromium.webp");
  await idle(page);
  assert.match(await page.textContent("#lab-info"), /chromium\.webp: 64 × 48 pixels, WebP/);
  const [dark, light] = [(await grey([8, 20, 1, 1]))[0], (await grey([56, 20, 1, 1]))[0]];
  assert.ok(Math.abs(dark - 32) <= 4 && Math.abs(light - 224) <= 4, `${dark}, ${light}`);
  // refused by their signature, with what they are and how to get a JPEG
  for (const [name, says] of [["iphone.heic", /^iphone\.heic: is a HEIC\/HEIF photo \(the iPhone's default format\).*Settings → Camera → Formats → Most Compatible.*export it as JPEG/],
    ["photo.avif", /^photo\.avif: is an AVIF image, which the lab does not decode\. Save or export it as JPEG or PNG/],
    ["canon.cr3", /^canon\.cr3: is a camera RAW file \(Canon CR3\).*Export it as a JPEG from the camera's app/]]) {
    await page.setInputFiles("#lab-file", path.join(CORPUS, name));
    await page.waitForFunction((n) => {
      const e = document.getElementById("lab-error");
      return !e.hidden && e.textContent.startsWith(`${n}: `);
    }, name);
    assert.match(await page.textContent("#lab-error"), says);
    assert.equal(await page.evaluate(() => document.body.dataset.image), "chromium.webp");
  }
  // and the lab still works on the photo it had
  await page.selectOption("#lab-family", "filters");
  await page.selectOption("#lab-kernel", "mean");
  await page.click("#lab-run");
  await idle(page);
  assert.equal(await page.evaluate(() => document.body.dataset.layer), "mean");
  assert.deepEqual(log.pageErrors, []);
});

/**
 * A `w × h` JPEG made in the page by Chromium's encoder (texture: a gradient
 * and small tiles; the left third flat black, for a known value), with
 * EXIF `orientation` when given, dropped on the lab as `name`.
 */
async function dropJpeg(name, w, h, orientation = 0) {
  await page.evaluate(async ([name, w, h, o]) => {
    const c = new OffscreenCanvas(w, h);
    const g = c.getContext("2d");
    const grad = g.createLinearGradient(0, 0, w, h);
    grad.addColorStop(0, "#304050");
    grad.addColorStop(1, "#f0d0a0");
    g.fillStyle = grad;
    g.fillRect(0, 0, w, h);
    for (let y = 0; y < h; y += 64) {
      for (let x = (y / 64) % 2 ? 0 : 64; x < w; x += 128) {
        g.fillStyle = "#fff";
        g.fillRect(x, y, 32, 32);
      }
    }
    g.fillStyle = "#000";
    g.fillRect(0, 0, Math.floor(w / 3), h);
    let bytes = new Uint8Array(await (await c.convertToBlob({ type: "image/jpeg", quality: 0.9 })).arrayBuffer());
    if (o) {
      // an APP1 EXIF segment with only Orientation (big-endian TIFF, one IFD entry) after SOI
      const app1 = [0xff, 0xe1, 0, 34, ..."Exif\0\0MM\0\x2a\0\0\0\x08\0\x01".split("").map((ch) => ch.charCodeAt(0)),
        0x01, 0x12, 0, 3, 0, 0, 0, 1, 0, o, 0, 0, 0, 0, 0, 0];
      bytes = new Uint8Array([...bytes.subarray(0, 2), ...app1, ...bytes.subarray(2)]);
    }
    const dt = new DataTransfer();
    dt.items.add(new File([bytes], name, { type: "image/jpeg" }));
    document.getElementById("lab").dispatchEvent(new DragEvent("drop", { dataTransfer: dt, bubbles: true, cancelable: true }));
  }, [name, w, h, orientation]);
}

/**
 * Förstner over the whole open 12 MP colour photo as a student runs it (the
 * map by bands, the photo's own threshold, its points): w and q at a white
 * square's corners as Example 13 works them out here from the photo's
 * greys, points found, and a clicked pixel explained with the layer's number.
 */
async function forstnerEndToEnd() {
  await page.evaluate(() => delete document.body.dataset.points);
  await page.selectOption("#lab-family", "interest");
  await page.selectOption("#lab-interest", "forstner");
  await page.click("#lab-run");
  await page.waitForFunction(() => document.body.dataset.points !== undefined && document.body.dataset.forstnerLive !== "busy", null, { timeout: 120_000 });
  await idle(page);
  assert.ok(Number(await page.evaluate(() => document.body.dataset.points)) > 0, "points found");
  // dropJpeg's white 32 × 32 squares: rows of 64, every 128 columns, from column 64 on even rows
  const worked = async (c, r) => {
    const box = await grey([c - 3, r - 3, 7, 7]);
    return forstner((x, y) => box[(y - r + 3) * 7 + (x - c + 3)], c, r, 5);
  };
  const at = [[2112, 1024], [2143, 1024], [2112, 1055], [2143, 1055], [3167, 2079]];
  const got = { w: await layerAt("w", at), q: await layerAt("q", at) };
  for (const [i, [c, r]] of at.entries()) {
    const want = await worked(c, r);
    for (const k of ["w", "q"]) {
      assert.ok(Number.isFinite(want[k]) && want.w > 0, `(${c}, ${r}): a corner has texture (${k} ${want[k]})`);
      const v = got[k].values[i];
      assert.ok(v !== null && Math.abs(v - want[k]) <= 1e-5 * Math.max(1, Math.abs(want[k])), `${k} at (${c}, ${r}): the lab ${v}, worked out here ${want[k]}`);
    }
  }
  // a click at a corner explains the clicked pixel's w: the layer's number, the exact one beside it
  await page.selectOption("#lab-layer", { label: "w" });
  await clickPixel(page, 2112, 1024);
  await page.waitForSelector("#lab-explain-link", { timeout: 30_000 });
  const [, c, r] = (await page.textContent("#lab-explain")).match(/at column (\d+), row (\d+):/).map(Number);
  const shown = Number(await page.getAttribute("#lab-explain-value", "data-value"));
  assert.equal(Math.fround(shown), (await layerAt("w", [[c, r]])).values[0], `the explained w at (${c}, ${r}) is the layer's`);
  const want = (await worked(c, r)).w;
  assert.ok(Math.abs(shown - want) <= 1e-9 * Math.max(1, want), `explained w at (${c}, ${r}): ${shown}, worked out here ${want}`);
  await page.selectOption("#lab-family", "filters");
}

/** The spread of the stage's grey values (0: nothing drawn). */
const stageSpread = () => page.$eval("#lab-stage .lab-canvas", (cv) => {
  const d = cv.getContext("2d").getImageData(0, 0, cv.width, cv.height).data;
  let [lo, hi] = [255, 0];
  for (let i = 0; i < d.length; i += 4 * 97) [lo, hi] = [Math.min(lo, d[i]), Math.max(hi, d[i])];
  return hi - lo;
});

test("a 12 MP phone JPEG opens as it is and Förstner runs over it end to end; a 48 MP portrait JPEG is offered reduced 2× and opens when accepted", { timeout: TEST_TIMEOUT * 4 }, async () => {
  await dropJpeg("phone-12mp.jpg", 4000, 3000);
  await page.waitForFunction(() => document.body.dataset.image === "phone-12mp.jpg", null, { timeout: 60_000 });
  await idle(page);
  const info = await page.textContent("#lab-info");
  assert.ok(info.startsWith("phone-12mp.jpg: 4000 × 3000 pixels, JPEG, colour"), info);
  assert.doesNotMatch(info, /reduced/);
  assert.equal(await page.locator("#lab-offer").count(), 0);
  assert.ok((await stageSpread()) > 150, "the stage shows the photo");
  await forstnerEndToEnd();
  // 8064 × 6048 stored, EXIF 6: a portrait 6048 × 8064 (48.8 million pixels)
  await dropJpeg("camera-48mp.jpg", 8064, 6048, 6);
  await page.waitForSelector("#lab-offer", { timeout: 60_000 });
  const offer = await page.textContent("#lab-offer");
  assert.ok(offer.includes("camera-48mp.jpg is 6048 × 8064 pixels (48.8 megapixels), turned 90° clockwise by its EXIF orientation (6)"), offer);
  assert.ok(offer.includes("reduced 2× (area average of 2 × 2 pixels) from 6048 × 8064 to 3024 × 4032 pixels to fit the lab's working size of 16 megapixels; 1 lab pixel = 2 × 2 photo pixels"), offer);
  // offered, not opened: the 12 MP photo is still the lab's
  assert.equal(await page.evaluate(() => document.body.dataset.image), "phone-12mp.jpg");
  await page.click("#lab-offer-open");
  await page.waitForFunction(() => document.body.dataset.image === "camera-48mp.jpg", null, { timeout: 120_000 });
  await idle(page);
  const opened = await page.textContent("#lab-info");
  assert.ok(opened.startsWith("camera-48mp.jpg: 3024 × 4032 pixels, JPEG"), opened);
  assert.ok(opened.includes("turned 90° clockwise by its EXIF orientation (6); reduced 2× (area average of 2 × 2 pixels)"), opened);
  assert.ok(opened.includes("1 lab pixel = 2 × 2 photo pixels"), opened);
  assert.equal(await page.locator("#lab-offer").count(), 0);
  assert.ok((await stageSpread()) > 150, "the stage shows the photo");
  // upright: the stored left third (black) is the top third now; a lab pixel there averages black photo pixels
  const [top, bottom] = [(await grey([1500, 200, 1, 1]))[0], (await grey([1500, 3800, 1, 1]))[0]];
  assert.ok(top <= 8 && bottom > 60, `top ${top}, bottom ${bottom}`);
  // the inspector gives the photo's own pixels of the lab pixel under the pointer
  const p = await pixelPos(page, 1000, 2000);
  await page.mouse.move(p.x, p.y);
  await page.waitForFunction(() => /photo pixels/.test(document.getElementById("lab-inspector").textContent));
  const said = await page.textContent("#lab-inspector");
  const [, c, r] = said.match(/^c (\d+), r (\d+)/).map(Number);
  assert.ok(said.includes(`photo pixels c ${2 * c}…${2 * c + 1}, r ${2 * r}…${2 * r + 1}`), said);
  assert.deepEqual(log.pageErrors, []);
});
