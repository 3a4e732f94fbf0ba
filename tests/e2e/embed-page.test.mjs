// The embed page's options and what every example gets with them: themes
// (a background pixel checked), parts hidden or shown, locked inputs, folded
// steps and a start step, bad option values as a notice (never HTML), print,
// the exports, "Embed this", announcements, and the offline copy.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import fs from "node:fs";
import zlib from "node:zlib";
import { DIST, TEST_TIMEOUT, open, settled, start, visit } from "./harness.mjs";
import { startServer } from "../../scripts/serve.mjs";

const WAIT = 15_000;
const gsdCm = (dpi) => ((25.4 / dpi) * (1920 / 0.152)) / 10;

let env;
before(async () => {
  env = await start();
});
after(async () => {
  await env?.close();
});

/** The RGB of one screen pixel, from a 1×1 PNG screenshot (first pixel: no filter neighbours). */
async function pixel(page, x, y) {
  const png = await page.screenshot({ clip: { x, y, width: 1, height: 1 } });
  let offset = 8;
  const idat = [];
  let colorType = 2;
  while (offset < png.length) {
    const len = png.readUInt32BE(offset);
    const type = png.toString("ascii", offset + 4, offset + 8);
    if (type === "IHDR") colorType = png[offset + 8 + 9];
    if (type === "IDAT") idat.push(png.subarray(offset + 8, offset + 8 + len));
    offset += 12 + len;
  }
  const raw = zlib.inflateSync(Buffer.concat(idat));
  assert.ok(colorType === 2 || colorType === 6, `RGB(A) PNG, got colour type ${colorType}`);
  return [raw[1], raw[2], raw[3]];
}

const luminance = ([r, g, b]) => 0.2126 * r + 0.7152 * g + 0.0722 * b;

describe("the embed page's options", { timeout: TEST_TIMEOUT * 2 }, () => {
  test("theme=dark and prefers-color-scheme: dark both give the dark page; theme=light wins over the system", async () => {
    const cases = [
      { hash: "#/gsd?theme=dark", scheme: "light", dark: true },
      { hash: "#/gsd", scheme: "dark", dark: true },
      { hash: "#/gsd?theme=light", scheme: "dark", dark: false },
      { hash: "#/gsd", scheme: "light", dark: false },
    ];
    for (const c of cases) {
      const { context, page, log } = await open(env.browser, { colorScheme: c.scheme });
      try {
        assert.equal(await visit(page, env.url, "embed.html", c.hash), "ok");
        const bg = await pixel(page, 2, 2);
        if (c.dark) assert.ok(luminance(bg) < 40, `${c.hash} (${c.scheme}): dark background, got ${bg}`);
        else assert.ok(luminance(bg) > 240, `${c.hash} (${c.scheme}): light background, got ${bg}`);
        // the text is readable on it: ink of the title against the background
        const ink = await page.$eval("#example-title", (h) => getComputedStyle(h).color);
        const [r, g, b] = ink.match(/\d+/g).map(Number);
        assert.ok(Math.abs(luminance([r, g, b]) - luminance(bg)) > 150, `${c.hash}: ink ${ink} on ${bg}`);
        // the option stays in the address when the page rewrites it
        if (c.hash.includes("theme")) assert.match(await page.evaluate(() => location.hash), /theme=/);
        assert.deepEqual(log.pageErrors, []);
      } finally {
        await context.close();
      }
    }
  });

  test("hide and show choose the parts; lock makes the inputs read-only", async () => {
    const { context, page } = await open(env.browser);
    try {
      await visit(page, env.url, "embed.html", "#/gsd?dpi=1200&hide=inputs,notes");
      assert.equal(await page.isVisible(".inputs"), false);
      assert.equal(await page.isVisible(".notes-section"), false);
      assert.equal(await page.isVisible(".result-section"), true);
      assert.equal(await page.isVisible(".steps-panel"), true);
      // the parts left take the embed's whole width (a column of 0 px once wrote the result letter by letter)
      for (const sel of [".result-section", ".steps-panel", ".figure-section"]) {
        const w = await page.$eval(sel, (e) => e.getBoundingClientRect().width);
        assert.ok(w > 900, `${sel}: ${w} px wide in a 1280 px embed`);
      }
      await visit(page, env.url, "embed.html", "#/gsd?dpi=1200&show=figure,result");
      for (const [sel, shown] of [[".inputs", false], [".steps-panel", false], [".notes-section", false], [".tools-section", false], [".figure-section", true], [".result-section", true]]) {
        assert.equal(await page.isVisible(sel), shown, `${sel} ${shown ? "shown" : "hidden"}`);
      }
      await page.goto(`${env.url}embed.html#/gsd?dpi=1200&lock=true`);
      await page.reload();
      await settled(page);
      const input = page.locator('[data-key="dpi"] input');
      assert.equal(await input.evaluate((i) => i.readOnly), true);
      await input.focus();
      await page.keyboard.type("99");
      assert.equal(await input.inputValue(), "1200");
      assert.match(await page.textContent(".locked-note"), /fixed/);
      assert.ok(Math.abs(Number(await page.getAttribute('tr[data-key="gsd_cm"] td.exact', "data-value")) - gsdCm(1200)) < 1e-9);
    } finally {
      await context.close();
    }
  });

  test("bad option values show a notice, as text; the example still solves", async () => {
    const { context, page } = await open(env.browser);
    try {
      const hash = `#/gsd?theme=purple&hide=wings&steps=sideways&step=0&host=${encodeURIComponent("javascript:alert(1)")}&id=${encodeURIComponent("<img src=x onerror=alert(1)>")}`;
      assert.equal(await visit(page, env.url, "embed.html", hash), "ok");
      const notice = await page.textContent(".options-notice");
      for (const part of ["theme=“purple”", "hide=“wings”", "steps=“sideways”", "step=“0”", "host=“javascript:alert(1)”", "id=“<img src=x onerror=alert(1)>”"]) {
        assert.ok(notice.includes(part), `notice names ${part}: ${notice}`);
      }
      assert.equal(await page.$$eval(".options-notice *", (n) => n.length), 0, "the notice is text only");
      assert.equal(await page.$$eval("img", (n) => n.length), 0);
      assert.equal(await page.isVisible(".options-notice"), true);
      // an unknown option is an unknown parameter, named by the page's own notice
      await visit(page, env.url, "embed.html", "#/gsd?colour=red");
      assert.match(await page.textContent(".url-notice"), /“colour”/);
    } finally {
      await context.close();
    }
  });

  test("steps=collapsed folds each step; step=2 opens the second and marks it", async () => {
    const { context, page } = await open(env.browser);
    try {
      await visit(page, env.url, "embed.html", "#/gsd?steps=collapsed&step=2");
      const folds = await page.$$eval(".step-fold", (d) => d.map((x) => x.open));
      assert.deepEqual(folds, [false, true, false]);
      assert.equal(await page.getAttribute(".step:nth-child(2)", "aria-current"), "step");
      // a fold stays open across a new solution
      await page.click(".step:nth-child(3) summary");
      await page.fill('[data-key="dpi"] input', "1000");
      await page.waitForFunction(() => document.querySelector('tr[data-key="dpi"]') === null && document.body.dataset.status === "ok");
      await page.waitForFunction(() => [...document.querySelectorAll(".step-fold")].map((d) => d.open).join() === "false,true,true", null, { timeout: WAIT });
    } finally {
      await context.close();
    }
  });

  test("print: every step open, the link and the inputs printed, no buttons, the figure as an image", async () => {
    const { context, page } = await open(env.browser);
    try {
      await visit(page, env.url, "embed.html", "#/gsd?dpi=1200&steps=collapsed");
      await page.emulateMedia({ media: "print" });
      const formulas = await page.$$eval(".step .formula-substituted", (f) => f.map((x) => x.getBoundingClientRect().height > 0 && getComputedStyle(x).visibility !== "hidden"));
      assert.equal(formulas.length, 3);
      assert.ok(formulas.every(Boolean), `every step's formula is laid out in print: ${formulas}`);
      assert.ok((await page.innerText(".steps-panel")).includes("0.02116667"), "the substituted numbers print");
      const buttons = await page.$$eval("button", (b) => b.filter((x) => x.getBoundingClientRect().width > 0).length);
      assert.equal(buttons, 0, "no button prints");
      assert.match(await page.innerText(".print-inputs"), /Scan resolution \(dpi\) = 1200/);
      assert.match(await page.innerText(".print-link"), /embed\.html#\/gsd\?dpi=1200/);
      assert.equal(await page.isVisible(".figure-canvas"), true);
      const pdf = await page.pdf({ format: "A4" });
      assert.ok(pdf.length > 10_000, "a PDF with content");
    } finally {
      await context.close();
    }
  });
});

describe("exports and Embed this", { timeout: TEST_TIMEOUT * 2 }, () => {
  test("figure PNG, numbers JSON and CSV, LaTeX download and copy, with the numbers", async () => {
    const { context, page } = await open(env.browser, { acceptDownloads: true });
    try {
      await context.grantPermissions(["clipboard-read", "clipboard-write"], { origin: new URL(env.url).origin });
      await visit(page, env.url, "index.html", "#/gsd?dpi=1200");
      const get = async (tool) => {
        const [download] = await Promise.all([page.waitForEvent("download"), page.click(`[data-tool="${tool}"]`)]);
        return { name: download.suggestedFilename(), bytes: fs.readFileSync(await download.path()) };
      };
      const png = await get("png");
      assert.equal(png.name, "gsd.png");
      assert.deepEqual([...png.bytes.subarray(0, 8)], [137, 80, 78, 71, 13, 10, 26, 10]);
      assert.ok(png.bytes.readUInt32BE(16) >= 300 && png.bytes.readUInt32BE(20) >= 200, "a figure-sized PNG");
      const json = JSON.parse((await get("json")).bytes.toString("utf8"));
      assert.equal(json.id, "gsd");
      assert.equal(json.inputs.dpi, 1200);
      assert.ok(Math.abs(json.result.gsd_cm - gsdCm(1200)) < 1e-12);
      assert.equal(json.steps.length, 3);
      assert.match(json.link, /#\/gsd\?dpi=1200/);
      const csv = (await get("csv")).bytes.toString("utf8").split("\r\n");
      assert.equal(csv[0], "section,key,label,unit,value,printed");
      assert.ok(csv.includes("input,dpi,,,1200,"));
      const row = csv.find((l) => l.startsWith("result,gsd_cm,"));
      assert.ok(row, "a gsd_cm row");
      assert.ok(Math.abs(Number(row.split(",")[4]) - gsdCm(1200)) < 1e-12, row);
      const tex = (await get("tex")).bytes.toString("utf8");
      assert.match(tex, /\\subsection\*\{Ground sample distance\}/);
      assert.match(tex, /\\texttt\{dpi\} = 1200/);
      assert.ok(tex.includes("1200"), "the substituted formula");
      assert.ok(tex.includes("26.73684211"), tex.slice(-600));
      await page.click('[data-tool="copy-tex"]');
      await page.waitForFunction(() => /copied/.test(document.querySelector(".tools-status").textContent), null, { timeout: WAIT });
      assert.equal(await page.evaluate(() => navigator.clipboard.readText()), tex);
      // seed inputs: the CSV carries the printed value beside the exact one
      await visit(page, env.url, "index.html", "#/gsd");
      await page.reload();
      await settled(page);
      const seed = (await get("csv")).bytes.toString("utf8").split("\r\n").find((l) => l.startsWith("result,gsd_cm,"));
      assert.match(seed, /,35\.\d+$/);
    } finally {
      await context.close();
    }
  });

  test("Embed this: both snippets with the inputs and options, copy, and a live preview that sizes itself", async () => {
    const { context, page } = await open(env.browser);
    try {
      await context.grantPermissions(["clipboard-read", "clipboard-write"], { origin: new URL(env.url).origin });
      await visit(page, env.url, "index.html", "#/gsd?dpi=1200");
      await page.click('[data-tool="embed"]');
      await page.waitForSelector(".embed-panel", { timeout: WAIT }); // its module loads on the first click
      assert.equal(await page.getAttribute('[data-tool="embed"]', "aria-expanded"), "true");
      const script = await page.inputValue('[data-snippet="script"]');
      assert.ok(script.includes(`<script src="${env.url}embed.js" defer></script>`), script);
      assert.ok(script.includes('data-playground="gsd?dpi=1200&amp;focal_length_mm=152&amp;flying_height_m=1920"'), script);
      await page.selectOption("#embed-theme", "dark");
      await page.check("#embed-lock");
      let iframe = await page.inputValue('[data-snippet="iframe"]');
      assert.ok(iframe.includes(`src="${env.url}embed.html#/gsd?dpi=1200&amp;focal_length_mm=152&amp;flying_height_m=1920&amp;theme=dark&amp;lock=true"`), iframe);
      assert.match(iframe, /title="Ground sample distance — Photogrammetry Playground"/);
      assert.ok((await page.inputValue('[data-snippet="script"]')).includes('data-theme="dark" data-lock="true"'));
      // the preview reports its height; the iframe snippet takes it as measured
      const preview = await (await page.$(".embed-preview")).contentFrame();
      await preview.waitForFunction(() => document.body.dataset.status === "ok", null, { timeout: WAIT });
      await page.waitForFunction(() => /height="\d+"/.test(document.querySelector('[data-snippet="iframe"]').value) && !document.querySelector('[data-snippet="iframe"]').value.includes('height="900"'), null, { timeout: WAIT });
      const content = await preview.evaluate(() => Math.ceil(document.body.getBoundingClientRect().height));
      iframe = await page.inputValue('[data-snippet="iframe"]');
      assert.equal(Number(/height="(\d+)"/.exec(iframe)[1]), content);
      assert.equal(await preview.evaluate(() => document.documentElement.dataset.theme), "dark");
      // the snippets follow an edit of the inputs
      await page.fill('[data-key="dpi"] input', "1500");
      await page.waitForFunction(() => document.querySelector('[data-snippet="script"]').value.includes("dpi=1500"), null, { timeout: WAIT });
      await page.click('[data-copy="script"]');
      assert.match(await page.evaluate(() => navigator.clipboard.readText()), /data-playground="gsd\?dpi=1500/);
      // the notes for the platforms
      const notes = await page.innerText(".embed-notes");
      for (const p of ["Moodle", "Canvas", "WordPress", "Quarto"]) assert.ok(notes.includes(p), p);
    } finally {
      await context.close();
    }
  });

  test("a new result is announced politely to screen readers", async () => {
    const { context, page } = await open(env.browser);
    try {
      await visit(page, env.url, "embed.html", "#/gsd?dpi=1200");
      assert.equal(await page.getAttribute(".result-announcer", "aria-live"), "polite");
      await page.fill('[data-key="dpi"] input', "1500");
      await page.waitForFunction(() => /Ground sample distance \(cm\)|gsd_cm|Ground sample distance/.test(document.querySelector(".result-announcer").textContent), null, { timeout: WAIT });
      const text = await page.textContent(".result-announcer");
      assert.ok(text.includes("21.3895"), text);
    } finally {
      await context.close();
    }
  });
});

describe("offline after the first visit", { timeout: TEST_TIMEOUT * 2 }, () => {
  test("the build stamps the service worker with its version and file list", () => {
    const sw = fs.readFileSync(`${DIST}/sw.js`, "utf8");
    const version = JSON.parse(fs.readFileSync(`${DIST}/version.json`, "utf8")).version;
    const build = JSON.parse(/^const BUILD = (.*);$/m.exec(sw)[1]);
    assert.equal(build.version, version);
    assert.match(version, /^[0-9a-f]{16}$/);
    // the names the page asks for: content-hashed where scripts/site.mjs hashed them
    const hashed = JSON.parse(fs.readFileSync(`${DIST}/assets.json`, "utf8"));
    for (const f of ["index.html", "embed.html", "embed.js", "catalog.json", "pkg/coordinates_bg.wasm", "pkg/projection_bg.wasm", "vendor/katex/katex.min.js"]) {
      assert.ok(build.files.includes(hashed[f] ?? f), f);
    }
    // practice's module (every example again) is cached when first used
    const all = hashed["pkg/all_bg.wasm"] ?? "pkg/all_bg.wasm";
    assert.ok(!build.files.includes(all) && build.lazy.includes(all), "pkg/all_bg.wasm lazy");
    assert.ok(!build.files.some((f) => /\.(gz|br)$/.test(f)), "no precompressed copies in the precache list");
    assert.ok(!build.files.includes("sw.js"));
  });

  test("the service worker serves the page with the server stopped, and caches only our files", async () => {
    const server = await startServer({ dir: DIST, port: 0 });
    let stopped = false;
    const { context, page, log } = await open(env.browser, { serviceWorkers: "allow" });
    try {
      assert.equal(await visit(page, server.url, "embed.html", "#/gsd?dpi=1200"), "ok");
      await page.evaluate(() => navigator.serviceWorker.ready);
      await page.waitForFunction(() => navigator.serviceWorker.controller !== null, null, { timeout: WAIT });
      const cached = await page.evaluate(async () => {
        const names = await caches.keys();
        const urls = [];
        for (const n of names) for (const r of await (await caches.open(n)).keys()) urls.push(r.url);
        return { names, urls };
      });
      assert.equal(cached.names.length, 1);
      assert.ok(cached.urls.every((u) => u.startsWith(server.url)), "only our own origin");
      assert.ok(cached.urls.some((u) => /_bg(-\w{8})?\.wasm$/.test(u)));
      await server.close();
      stopped = true;
      await page.goto(`${server.url}embed.html#/gsd?dpi=1500`);
      assert.equal(await settled(page), "ok");
      assert.ok(Math.abs(Number(await page.getAttribute('tr[data-key="gsd_cm"] td.exact', "data-value")) - gsdCm(1500)) < 1e-9);
      // another example's figures, loaded on demand, come from the cache too
      await page.goto(`${server.url}index.html#/ncc-1d`);
      assert.equal(await settled(page), "ok");
      assert.ok(await page.isVisible(".figure-canvas"));
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
      if (!stopped) await server.close();
    }
  });
});
