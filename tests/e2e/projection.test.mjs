// UTM on the page: the checkpoint solved from a URL with degrees-minutes-
// seconds, the values and steps on the page, the three canvases drawn (the
// central meridian, the zone edges, the point, the curves: checked by their
// pixels), an error beside its field, the inverse from a band letter, and
// seed 004's facts with the printed numbers beside the exact ones.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import { TEST_TIMEOUT, cellText, exact, open, settled, start, visit } from "./harness.mjs";

let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

/** Per canvas: its label and how many pixels have each colour (within a tolerance). */
function canvases(page, colors) {
  return page.evaluate((wanted) => {
    const hex = (h) => [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16));
    return [...document.querySelectorAll(".figure-canvas")].map((c) => {
      const data = c.getContext("2d").getImageData(0, 0, c.width, c.height).data;
      const counts = Object.fromEntries(Object.keys(wanted).map((k) => [k, 0]));
      let ink = 0;
      for (let i = 0; i < data.length; i += 4) {
        const [r, g, b] = [data[i], data[i + 1], data[i + 2]];
        if (r < 240 || g < 240 || b < 240) ink += 1;
        for (const [name, h] of Object.entries(wanted)) {
          const [R, G, B] = hex(h);
          if (Math.abs(r - R) < 24 && Math.abs(g - G) < 24 && Math.abs(b - B) < 24) counts[name] += 1;
        }
      }
      return { label: c.getAttribute("aria-label"), ink, pixels: c.width * c.height, counts };
    });
  }, colors);
}

const COLORS = { meridian: "#1d5fbf", edge: "#b3400a", point: "#8f1d8f", curve: "#1b1f24" };

describe("map projection", () => {
  test("55°N 12°E on GRS 80 in zone 32, from a URL in degrees, minutes and seconds", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      const hash = `#/utm?latitude=${encodeURIComponent("55°00'00\"N")}&longitude=${encodeURIComponent("12 0 0 E")}&ellipsoid=grs80&zone=32`;
      assert.equal(await visit(page, env.url, "index.html", hash), "ok");
      assert.equal(await page.inputValue('input[name="latitude"]'), "55°00'00\"N");
      // the published checkpoint: E 691 875.632 m, N 6 098 907.825 m
      assert.ok(Math.abs((await exact(page, "easting")) - 691875.632) < 5e-4);
      assert.ok(Math.abs((await exact(page, "northing")) - 6098907.825) < 5e-4);
      assert.equal(await cellText(page, "zone", "exact"), "32");
      assert.equal(await cellText(page, "band", "exact"), "U");
      assert.equal(await cellText(page, "utm_text", "exact"), "32U 691\u2009875.632 m E, 6\u2009098\u2009907.825 m N");
      assert.equal(await cellText(page, "zone_rule", "exact"), "forced");
      // the steps with their formulas rendered
      // textContent: a step off screen is not rendered (content-visibility: auto), its innerText empty
      const steps = await page.locator(".steps .step-title").allTextContents();
      assert.ok(steps.includes("Krüger's series") && steps.includes("Easting and northing"), steps.join(" | "));
      assert.ok((await page.locator(".steps .katex").count()) > 20);
      assert.equal(await page.locator(".formula-error").count(), 0, "every formula renders");
      // three canvases, each drawn and labelled
      const figs = await canvases(page, COLORS);
      assert.equal(figs.length, 3);
      const [map, k, diff] = figs;
      assert.match(map.label, /UTM zone 32: the central meridian 9°E/);
      assert.ok(map.counts.meridian > 300, `central meridian pixels ${map.counts.meridian}`);
      assert.ok(map.counts.edge > 150, `zone edge pixels ${map.counts.edge}`);
      assert.ok(map.counts.point > 30, `point pixels ${map.counts.point}`);
      assert.match(k.label, /scale factor k across the zone: 0\.9996 on the central meridian/);
      assert.ok(k.counts.curve > 200 && k.counts.point > 30);
      assert.match(diff.label, /Log plot of the classical series' error/);
      assert.ok(diff.counts.edge > 200, "the classical-minus-exact curve");
      // the point is on the zone edge: 3° from the central meridian
      assert.match(map.label, /easting 691\.875632 km, northing 6098\.907825 km/);
      assert.deepEqual(log.pageErrors, []);
      assert.deepEqual(log.consoleErrors, []);
    } finally {
      await context.close();
    }
  });

  test("a latitude out of range: the message beside the field; beyond 84°N: UPS", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser, { viewport: { width: 390, height: 844 } });
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/utm"), "ok");
      const easting = await exact(page, "easting");
      assert.ok(Math.abs(easting - 662176.290477) < 1e-6, String(easting));
      await page.fill('input[name="latitude"]', "95");
      assert.equal(await settled(page), "invalid");
      const err = page.locator('.field[data-key="latitude"] .field-error');
      assert.equal((await err.innerText()).trim(), "must be between −90° and 90° (got 95°)");
      assert.equal(await page.getAttribute('input[name="latitude"]', "aria-invalid"), "true");
      await page.fill('input[name="latitude"]', "55 61");
      assert.equal(await settled(page), "invalid");
      assert.match(await err.innerText(), /minutes must be less than 60/);
      await page.fill('input[name="latitude"]', "85");
      assert.equal(await settled(page), "error");
      assert.match(await page.locator(".error-box").innerText(), /latitude: UTM covers 80°S to 84°N only .*UPS/);
      await page.fill('input[name="latitude"]', "-33 52");
      assert.equal(await settled(page), "ok");
      assert.equal(await cellText(page, "hemisphere", "exact"), "south");
      assert.match(page.url(), /latitude=-33(%20|\+)52/);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("the inverse from a band letter, and a band that does not fit", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/utm-inverse?zone=32&hemisphere=U&easting=691875.632139661&northing=6098907.825005013&ellipsoid=grs80"), "ok");
      assert.ok(Math.abs((await exact(page, "latitude")) - 55) < 1e-9);
      assert.ok(Math.abs((await exact(page, "longitude")) - 12) < 1e-9);
      assert.equal(await cellText(page, "latitude_dms", "exact"), "55°00′00.00000″ N");
      assert.equal(await page.locator(".formula-error").count(), 0, "every formula renders");
      const figs = await canvases(page, COLORS);
      assert.equal(figs.length, 2);
      assert.ok(figs[0].counts.point > 30 && figs[0].counts.meridian > 300);
      await page.selectOption('select[name="hemisphere"]', "T");
      assert.equal(await settled(page), "ok");
      assert.match(await page.locator(".notes").innerText(), /in band U, not in band T/);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("seed 004's facts: the printed numbers beside the exact ones", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      assert.equal(await visit(page, env.url, "index.html", "#/utm-facts"), "ok");
      assert.ok(Math.abs((await exact(page, "k1_distance_km")) - 179.754) < 1e-3);
      assert.equal(await cellText(page, "k1_distance_km", "printed"), "90");
      assert.equal(await page.locator(".formula-error").count(), 0, "every formula renders");
      // each printed slip is shown as the erratum its note explains, not as a numeric difference
      assert.match(await cellText(page, "k1_distance_km", "diff"), /erratum/);
      assert.match(await cellText(page, "latitude_max", "diff"), /erratum/);
      assert.match(await cellText(page, "zones_thailand", "diff"), /erratum/);
      assert.match(await cellText(page, "zones_pakistan", "diff"), /agrees/);
      assert.match(await cellText(page, "central_scale_factor", "diff"), /agrees/);
      const notes = await page.locator(".notes").innerText();
      assert.match(notes, /It is 1 at 179\.8 km/);
      assert.match(notes, /northern limit is 84°N/);
      const [k] = await canvases(page, { ...COLORS, seed: "#8f1d8f" });
      assert.ok(k.counts.curve > 200 && k.counts.seed > 50, "the k curve and the seed's 90 km lines");
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });
});
