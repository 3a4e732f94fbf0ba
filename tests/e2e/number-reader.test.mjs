// Issue 29, item 2: one number reader. An example page reads what a
// practice box reads (src/practice/read.rs): a decimal comma, powers of ten,
// fractions and a unit where the field has one. The value is the one practice
// would read (grade's `read`, from the same core), the address keeps the text
// as typed and stays a what-if link that opens the same solution.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import { TEST_TIMEOUT, exact, nodeModule, open, settled, start, visit, waitForExact } from "./harness.mjs";

const all = await nodeModule("all");

let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

/** The number a practice box reads from `text` (grade's `read`, "1200" or "26.7 cm"). */
function practiceReads(text) {
  const p = all.practice("gsd", "1K7Q2");
  const key = p.boxes[0].key;
  const read = all.grade("gsd", p.code, { [key]: text }).boxes[key].read;
  assert.ok(read, `practice reads "${text}"`);
  return read;
}

describe("an example page reads numbers as practice does", () => {
  test("gsd with 1,2e3 dpi, 15,2 cm and 3/2 km: the solution of 1200 dpi, 152 mm, 1500 m; the link reopens it", { timeout: TEST_TIMEOUT }, async () => {
    // the practice reader, on the same texts (without the field's unit)
    assert.equal(practiceReads("1,2e3"), "1200");
    assert.equal(practiceReads("3/2"), "1.5");
    assert.equal(practiceReads("0,5"), "0.5");
    const want = all.solve("gsd", { dpi: 1200, focal_length_mm: 152, flying_height_m: 1500 }).result.gsd_cm;
    const { context, page, log } = await open(env.browser);
    try {
      await visit(page, env.url, "index.html", "#/gsd");
      await page.getByLabel(/Scan resolution/).fill("1,2e3");
      await page.getByLabel(/Focal length/).fill("15,2 cm");
      await page.getByLabel(/Flying height/).fill("3/2 km");
      await waitForExact(page, "gsd_cm", want, 1e-9);
      assert.equal(await settled(page), "ok");
      assert.equal(await exact(page, "gsd_cm"), want);
      assert.equal(await page.locator(".field-error:visible").count(), 0);
      const hash = await page.evaluate(() => location.hash);
      assert.equal(hash, "#/gsd?dpi=1,2e3&focal_length_mm=15,2+cm&flying_height_m=3%2F2+km");

      // the what-if link opens the same solution, with the texts as typed
      const again = await open(env.browser);
      try {
        assert.equal(await visit(again.page, env.url, "index.html", hash), "ok");
        assert.equal(await exact(again.page, "gsd_cm"), want);
        assert.equal(await again.page.getByLabel(/Scan resolution/).inputValue(), "1,2e3");
      } finally {
        await again.context.close();
      }
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("a decimal comma in a list, and an ambiguous one said so beside its field", { timeout: TEST_TIMEOUT }, async () => {
    const seed = all.solve("subpixel-1d", { rho_from: "printed" });
    const key = seed.answer[0];
    const { context, page, log } = await open(env.browser);
    try {
      await visit(page, env.url, "index.html", "#/subpixel-1d?rho_from=printed");
      const rho = page.locator('.field[data-key="rho"]').locator("input, textarea");
      assert.equal(await rho.inputValue(), "0.69, 0.97, 0.37");
      // numbers separated by spaces: the commas are decimal commas
      await rho.fill("0,69 0,97 0,37");
      assert.equal(await settled(page), "ok");
      assert.equal(await exact(page, key), seed.result[key]);
      // commas that separate and a comma between digits: refused, and the message says why
      await rho.fill("0,69, 0,97, 0,37");
      await page.waitForFunction(() => document.body.dataset.status === "invalid");
      const message = await page.locator('.field[data-key="rho"] .field-error').innerText();
      assert.match(message, /^"0,69, 0,97, 0,37" is ambiguous: .*decimal comma.*separate the numbers with spaces only \(0,5 1,5\)/);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });
});
