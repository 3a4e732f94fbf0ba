// Practice scores in an LMS (issue 33), in Chromium: the worksheet page makes a
// SCORM package in the browser; the package is served on its own, with
// scorm-again (the LMS-side runtime on npm) as the LMS in the host page and the
// package's launch page in an iframe; answers go in as a student types them
// and the CMI holds the score, status and interactions; the attempt resumes in
// a new launch; the package without an LMS says so; a work receipt regrades.

import test, { after, before } from "node:test";
import assert from "node:assert/strict";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import { unzipSync, strFromU8 } from "fflate";
import { nodeModule, open, start } from "./harness.mjs";
import { startServer } from "../../scripts/serve.mjs";
import { percent } from "../../www/lms/scorm.js";
import { decodeAttempt } from "../../www/lms/attempt.js";
import { createRequire } from "node:module";

const AXE = createRequire(import.meta.url).resolve("axe-core/axe.min.js");
/** axe-core's WCAG 2.0–2.2 A and AA rules on the page as it is now: the violations, as lines. */
async function axe(page, where) {
  await page.addScriptTag({ path: AXE });
  const r = await page.evaluate(() => window.axe.run(document, { runOnly: { type: "tag", values: ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa", "wcag22aa"] }, resultTypes: ["violations"] }));
  return r.violations.map((v) => `${where}: ${v.id} ${v.nodes.slice(0, 3).map((n) => n.target.join(" ")).join(" | ")}`);
}

const WAIT = 60_000;
let env;
let core;
let host;
let dir;

before(async () => {
  env = await start();
  core = await nodeModule("all");
});
after(async () => {
  await host?.close();
  await env?.close();
  if (dir) fs.rmSync(dir, { recursive: true, force: true });
});

/** Makes a package on the worksheet page (its LMS panel) and returns { zip bytes, files }. */
async function makePackage({ scorm, passing, codes, fresh = false }) {
  const { context, page } = await open(env.browser, { acceptDownloads: true });
  try {
    await page.goto(`${env.url}index.html#/practice?worksheet=gsd&n=2&codes=${codes.join(",")}`);
    await page.waitForFunction(() => document.body.dataset.status === "worksheet", null, { timeout: WAIT });
    const panel = page.locator(".lms-panel");
    await panel.locator("select").selectOption(scorm);
    if (passing != null) await panel.locator("input.lms-passing").fill(String(passing));
    if (fresh) await panel.getByLabel(/A new variant for each student/).check();
    const [download] = await Promise.all([page.waitForEvent("download", { timeout: WAIT }), panel.getByRole("button", { name: "Download for your LMS" }).click()]);
    const file = path.join(dir, `pkg-${scorm}.zip`);
    await download.saveAs(file);
    await page.waitForFunction(() => /^Made /.test(document.querySelector(".lms-download-status")?.textContent ?? ""), null, { timeout: WAIT });
    return { name: download.suggestedFilename(), files: unzipSync(new Uint8Array(fs.readFileSync(file))) };
  } finally {
    await context.close();
  }
}

/** The host site: host.html (the LMS page with scorm-again), scorm-again.js, and the package under pkg12/ or pkg2004/. */
function writeHost(files, sub) {
  const root = path.join(dir, "host");
  for (const [name, bytes] of Object.entries(files)) {
    const target = path.join(root, sub, name);
    fs.mkdirSync(path.dirname(target), { recursive: true });
    fs.writeFileSync(target, bytes);
  }
  fs.copyFileSync("node_modules/scorm-again/dist/scorm-again.min.js", path.join(root, "scorm-again.js"));
  fs.writeFileSync(
    path.join(root, "host.html"),
    `<!doctype html><meta charset="utf-8"><title>LMS</title><script src="scorm-again.js"></script>
<script>
  const q = new URLSearchParams(location.search);
  const v2004 = q.get("v") === "2004";
  const api = v2004 ? new Scorm2004API({ autocommit: false, logLevel: 5 }) : new Scorm12API({ autocommit: false, logLevel: 5 });
  const saved = sessionStorage.getItem("cmi");
  if (saved) api.loadFromJSON(JSON.parse(saved).cmi);
  window[v2004 ? "API_1484_11" : "API"] = api;
  window.cmi = () => api.renderCommitCMI(true);
  window.keep = () => sessionStorage.setItem("cmi", JSON.stringify(api.renderCommitCMI(true)));
</script>
<iframe id="sco" src="${sub}/index.html" style="width:1200px;height:800px"></iframe>`,
  );
  return root;
}

/** The expected value of box `key` typed to 6 digits with its unit. */
function typed(box, factor = 1) {
  const t = Number((box.expected * factor).toPrecision(6)).toString();
  return box.unit ? `${t} ${box.unit}` : t;
}

test("a SCORM 1.2 package: made in the browser, every file listed, scores/status/interactions in scorm-again's CMI, resumed in a new launch", { timeout: 240_000 }, async () => {
  dir = fs.mkdtempSync(path.join(os.tmpdir(), "pp-lms-"));
  const codes = ["1K7Q2", "1ABCD"];
  const { name, files } = await makePackage({ scorm: "1.2", passing: 60, codes });
  assert.match(name, /^worksheet-.*-scorm12\.zip$/);
  const manifest = strFromU8(files["imsmanifest.xml"]);
  assert.match(manifest, /<schemaversion>1.2<\/schemaversion>/);
  assert.match(manifest, /<adlcp:masteryscore>60<\/adlcp:masteryscore>/);
  const listed = [...manifest.matchAll(/<file href="([^"]*)"\/>/g)].map((m) => m[1].replace(/&amp;/g, "&")).sort();
  assert.deepEqual(listed, Object.keys(files).filter((f) => f !== "imsmanifest.xml").sort(), "the manifest lists exactly the zip's files");
  assert.ok(listed.some((f) => /coordinates_practice_bg-.*\.wasm$/.test(f)), "the example's practice module is in");
  assert.ok(!listed.some((f) => /(correlation|matching|projection)_practice_bg|all_bg|photogrammetry_lab/.test(f)), "no other topic's module, no lab");

  const root = writeHost(files, "pkg12");
  host = await startServer({ dir: root, port: 0 });
  const { context, page, log } = await open(env.browser);
  const outside = [];
  context.on("request", (r) => {
    if (!r.url().startsWith(host.url)) outside.push(r.url());
  });
  const failed = [];
  context.on("response", (r) => {
    if (r.status() >= 400) failed.push(`${r.status()} ${r.url()}`);
  });
  await page.goto(`${host.url}host.html`);
  const frame = page.frameLocator("#sco");
  const sco = () => page.frame({ url: /pkg12\/index\.html/ });
  await page.waitForFunction(() => document.querySelector("#sco").contentDocument?.body?.dataset.status === "lms", null, { timeout: WAIT });
  assert.match(await frame.locator(".lms-status").textContent(), /Your score goes to your course \(SCORM 1\.2\)/);

  // variant 1: right, wrong, carried forward (gsd_mm consistent with the wrong scale number)
  const v = core.practice("gsd", codes[0]);
  const box = (key) => v.boxes.find((b) => b.key === key);
  const answers = { scale_denominator: typed(box("scale_denominator"), 1.1), pixel_size_mm: typed(box("pixel_size_mm")), gsd_mm: typed(box("gsd_mm"), 1.1) };
  const g = core.grade("gsd", v.code, answers);
  assert.deepEqual(
    [g.boxes.scale_denominator.verdict, g.boxes.pixel_size_mm.verdict, g.boxes.gsd_mm.verdict],
    ["wrong", "correct", "consistent"],
    "the answers typed are wrong, right and carried forward",
  );
  const item = frame.locator(`.lms-item[data-code="${v.code}"]`);
  for (const [key, text] of Object.entries(answers)) {
    const input = item.locator(`input[data-key="${key}"]`);
    await input.fill(text);
    await input.press("Tab");
  }
  const v2 = core.practice("gsd", codes[1]);
  const total = g.score + core.grade("gsd", v2.code, {}).score;
  const outOf = g.out_of + core.grade("gsd", v2.code, {}).out_of;
  await page.waitForFunction((want) => window.cmi().cmi.core.score.raw === want, percent(total, outOf), { timeout: WAIT });
  let cmi = (await page.evaluate(() => window.cmi())).cmi;
  assert.equal(cmi.core.score.raw, percent(total, outOf));
  assert.equal(cmi.core.score.min, "0");
  assert.equal(cmi.core.score.max, "100");
  assert.equal(cmi.core.lesson_status, "incomplete");
  const inter = Object.values(cmi.interactions);
  assert.deepEqual(
    inter.map((i) => [i.id, i.type, i.student_response, i.result]),
    [
      [`gsd_${v.code}_scale_denominator`, "numeric", answers.scale_denominator, "wrong"],
      [`gsd_${v.code}_pixel_size_mm`, "numeric", answers.pixel_size_mm, "correct"],
      [`gsd_${v.code}_gsd_mm`, "numeric", answers.gsd_mm, "correct"],
    ],
  );
  const saved = decodeAttempt(cmi.suspend_data);
  assert.deepEqual(saved.map((x) => x.code), [v.code, v2.code]);
  assert.deepEqual(saved[0].answers, answers);

  // the attempt is closed (the page goes away: pagehide), the CMI kept; a new launch resumes
  await sco().evaluate(() => (location.href = "about:blank"));
  await page.waitForFunction(() => window.cmi().cmi.core.exit === "suspend", null, { timeout: WAIT });
  await page.evaluate(() => window.keep());
  await page.reload();
  await page.waitForFunction(() => document.querySelector("#sco").contentDocument?.body?.dataset.status === "lms", null, { timeout: WAIT });
  assert.match(await frame.locator(".lms-status").textContent(), /Your earlier answers are back/);
  for (const [key, text] of Object.entries(answers)) assert.equal(await frame.locator(`.lms-item[data-code="${v.code}"] input[data-key="${key}"]`).inputValue(), text);
  assert.equal(await frame.locator(".practice-score").textContent(), `Score: ${Math.round(total * 100) / 100} of ${outOf}`);
  assert.deepEqual(outside, [], "nothing requested outside the LMS's site");
  assert.deepEqual(failed, [], "every file the package's page asked for is in it");
  assert.deepEqual(log.pageErrors, []);
  await context.close();
});

test("a SCORM 2004 package reports completion and success; without an LMS the package says scores are not sent; a receipt regrades", { timeout: 240_000 }, async () => {
  dir ??= fs.mkdtempSync(path.join(os.tmpdir(), "pp-lms-"));
  const codes = ["1QQQQ", "1WXYZ"];
  const { files } = await makePackage({ scorm: "2004", passing: 50, codes });
  assert.match(strFromU8(files["imsmanifest.xml"]), /<schemaversion>2004 4th Edition<\/schemaversion>/);
  const root = writeHost(files, "pkg2004");
  host ??= await startServer({ dir: root, port: 0 });
  const { context, page } = await open(env.browser, { bypassCSP: true });
  await page.goto(`${host.url}host.html?v=2004`);
  await page.waitForFunction(() => document.querySelector("#sco").contentDocument?.body?.dataset.status === "lms", null, { timeout: WAIT });
  const frame = page.frameLocator("#sco");
  // every box of both variants right
  for (const code of codes) {
    const v = core.practice("gsd", code);
    for (const b of v.boxes) {
      const input = frame.locator(`.lms-item[data-code="${v.code}"] input[data-key="${b.key}"]`);
      await input.fill(typed(b));
      await input.press("Tab");
    }
  }
  await page.waitForFunction(() => window.cmi().cmi.completion_status === "completed", null, { timeout: WAIT });
  const cmi = (await page.evaluate(() => window.cmi())).cmi;
  assert.equal(cmi.success_status, "passed");
  assert.equal(cmi.score.scaled, "1");
  assert.equal(cmi.score.raw, "100");
  const first = cmi.interactions[0];
  assert.equal(first.result, "correct");
  assert.ok(first.description.length > 0, "the box's label");

  // the same package opened with no LMS around it
  const alone = await context.newPage();
  await alone.goto(`${host.url}pkg2004/index.html`);
  await alone.waitForFunction(() => document.body.dataset.status === "lms", null, { timeout: WAIT });
  assert.match(await alone.locator(".lms-status").textContent(), /No course system \(LMS\) found: this is practice only, and scores are not being sent anywhere\./);
  const v = core.practice("gsd", codes[0]);
  const b0 = v.boxes[0];
  await alone.locator(`.lms-item[data-code="${v.code}"] input[data-key="${b0.key}"]`).fill(typed(b0));
  await alone.locator(`.lms-item[data-code="${v.code}"] input[data-key="${b0.key}"]`).press("Tab");
  await alone.waitForFunction(() => /^Score: 1 of /.test(document.querySelector(".practice-score")?.textContent ?? ""), null, { timeout: WAIT });
  const problems = await axe(alone, "the package's page");
  await context.close();

  // a receipt made by the practice page's button, regraded on the site: an edited answer earns what it earns
  const { context: c2, page: site } = await open(env.browser, { bypassCSP: true });
  await site.goto(`${env.url}index.html#/gsd?practice=${v.code}`);
  await site.waitForFunction(() => document.body.dataset.status === "practice", null, { timeout: WAIT });
  const answers = Object.fromEntries(v.boxes.map((b) => [b.key, typed(b)]));
  answers[v.boxes[1].key] = "12345";
  for (const [key, text] of Object.entries(answers)) {
    await site.locator(`input[data-key="${key}"]`).fill(text);
    await site.locator(`input[data-key="${key}"]`).press("Tab");
  }
  await site.getByRole("button", { name: "Copy a work receipt" }).click();
  await site.waitForFunction(() => document.querySelector(".receipt-text")?.value.startsWith("PGA1."), null, { timeout: WAIT });
  const text = await site.locator(".receipt-text").inputValue();
  assert.deepEqual(decodeAttempt(text), [{ id: "gsd", code: v.code, answers }]);
  assert.equal(await site.locator(".receipt-box svg.ws-qr").count(), 1, "a QR code of the address");
  await site.goto(await site.locator(".receipt-link").getAttribute("href"));
  await site.waitForFunction(() => document.body.dataset.status === "receipt" && document.querySelector(".receipt-score"), null, { timeout: WAIT });
  const g = core.grade("gsd", v.code, answers);
  assert.equal(await site.locator(".receipt-score").getAttribute("data-score"), String(g.score));
  for (const b of v.boxes) assert.equal(await site.locator(`.receipt-item tr[data-key="${b.key}"]`).getAttribute("data-verdict"), g.boxes[b.key].verdict, b.key);
  problems.push(...(await axe(site, "the receipt view")));
  // the same receipt with a box edited to the right value: graded to what the edit earns
  const fixed = { ...answers, [v.boxes[1].key]: typed(v.boxes[1]) };
  const { encodeAttempt } = await import("../../www/lms/attempt.js");
  await site.goto(`${env.url}index.html#/practice?receipt=${encodeAttempt([{ id: "gsd", code: v.code, answers: fixed }])}`);
  await site.waitForFunction((want) => document.querySelector(".receipt-score")?.dataset.score === want, String(core.grade("gsd", v.code, fixed).score), { timeout: WAIT });
  await site.goto(`${env.url}index.html#/practice?receipt=PGA1.garbled`);
  await site.waitForFunction(() => document.querySelector(".receipt-result .error-box"), null, { timeout: WAIT });
  assert.match(await site.locator(".receipt-result .error-box").textContent(), /damaged/);
  assert.deepEqual(problems, [], "WCAG 2.2 AA (axe-core)");
  await c2.close();
});

test("a package with a new variant per student draws the codes at the first launch and keeps them in suspend_data", { timeout: 240_000 }, async () => {
  dir ??= fs.mkdtempSync(path.join(os.tmpdir(), "pp-lms-"));
  const codes = ["1K7Q2", "1ABCD"];
  const { files } = await makePackage({ scorm: "1.2", passing: null, codes, fresh: true });
  const root = writeHost(files, "pkgfresh");
  host ??= await startServer({ dir: root, port: 0 });
  const { context, page } = await open(env.browser);
  await page.goto(`${host.url}host.html`);
  const ready = () => page.waitForFunction(() => document.querySelector("#sco").contentDocument?.body?.dataset.status === "lms", null, { timeout: WAIT });
  await ready();
  const frame = page.frameLocator("#sco");
  const drawn = await frame.locator(".lms-item").evaluateAll((xs) => xs.map((x) => x.dataset.code));
  assert.equal(drawn.length, 2, "as many variants as the worksheet had");
  assert.notDeepEqual(drawn, codes, "not the worksheet's codes");
  await page.waitForFunction(() => window.cmi().cmi.suspend_data !== "", null, { timeout: WAIT });
  assert.deepEqual(decodeAttempt((await page.evaluate(() => window.cmi())).cmi.suspend_data).map((x) => x.code), drawn);
  await page.frame({ url: /pkgfresh\/index\.html/ }).evaluate(() => (location.href = "about:blank"));
  await page.waitForFunction(() => window.cmi().cmi.core.exit === "suspend", null, { timeout: WAIT });
  await page.evaluate(() => window.keep());
  await page.reload();
  await ready();
  assert.deepEqual(await frame.locator(".lms-item").evaluateAll((xs) => xs.map((x) => x.dataset.code)), drawn, "the same variants in the next launch");
  await page.evaluate(() => sessionStorage.clear());
  await context.close();
});
