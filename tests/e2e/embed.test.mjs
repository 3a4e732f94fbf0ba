// Embedding in a course page, with the host page on ANOTHER origin (a second
// server on another port) than the playground: embed.js's script form and the
// plain iframe form take the content's height and follow it; a hidden tab;
// messages from a third frame ignored; events and getState/setState at the
// host; Canvas's lti.frameResize; keyboard in and out of the embed.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import { TEST_TIMEOUT, open, start, startHost } from "./harness.mjs";

const WAIT = 15_000;
/** gsd's result for a scan resolution (f = 152 mm, H = 1920 m): cm. */
const gsdCm = (dpi) => ((25.4 / dpi) * (1920 / 0.152)) / 10;

let env;
let host;
before(async () => {
  env = await start();
  const pg = env.url;
  const page = (body) => `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Course page</title></head><body style="margin:0;font-family:sans-serif">${body}</body></html>`;
  const record = `<script>
    window.events = [];
    for (const t of ["ready", "change", "error", "resize"])
      document.addEventListener("playground:" + t, (e) => window.events.push({ type: t, id: e.target.id, detail: e.detail }));
  </script>`;
  host = await startHost({
    "/script.html": page(`<h1>Week 3</h1><button id="before">before</button>
      ${record}<script src="${pg}embed.js" defer></script>
      <div id="a" data-playground="gsd?dpi=1200" data-id="a"></div>
      <button id="after">after</button>
      <iframe id="third" src="${pg}embed.html#/gsd?dpi=600&id=a" title="A third frame" style="width:300px;height:200px"></iframe>`),
    "/iframe.html": page(`<h1>Canvas-like host</h1>
      <iframe id="plain" src="${pg}embed.html#/gsd?dpi=1200" title="Ground sample distance" width="100%" height="300" style="border:0;display:block;width:100%;height:300px"></iframe>
      <script>
        window.lti = [];
        const frame = document.getElementById("plain");
        window.addEventListener("message", (e) => {
          if (e.source !== frame.contentWindow) return;
          let d = e.data;
          if (typeof d === "string") { try { d = JSON.parse(d); } catch { return; } }
          if (d && d.subject === "lti.frameResize") { window.lti.push(d); frame.style.height = d.height + "px"; }
        });
      </script>`),
    "/tabs.html": page(`${record}<script src="${pg}embed.js" defer></script>
      <button id="show">Tab 2</button>
      <div id="tab1"><p>First tab</p></div>
      <div id="tab2" hidden><div id="b" data-playground="gsd?dpi=900" data-id="b"></div></div>
      <script>document.getElementById("show").onclick = () => { tab1.hidden = true; tab2.hidden = false; };</script>`),
  });
});
after(async () => {
  await host?.close();
  await env?.close();
});

/** The playground frame made by embed.js (or the plain iframe) and its element on the host. */
async function embedFrame(page, selector) {
  const handle = await page.waitForSelector(selector, { state: "attached", timeout: WAIT });
  const frame = await handle.contentFrame();
  assert.ok(frame, `${selector} has a frame`);
  await frame.waitForFunction(() => document.body?.dataset.status === "ok", null, { timeout: WAIT });
  return { handle, frame };
}

/** Waits until the iframe's height is its content's height and nothing scrolls inside. */
async function fitsContent(page, selector, frame) {
  let last;
  for (let i = 0; i < 100; i++) {
    const outer = await page.$eval(selector, (f) => f.getBoundingClientRect().height);
    const inner = await frame.evaluate(() => ({
      content: Math.ceil(document.body.getBoundingClientRect().height),
      scroll: document.documentElement.scrollHeight,
      client: document.documentElement.clientHeight,
    }));
    last = { outer, ...inner };
    if (inner.content > 100 && Math.abs(outer - inner.content) <= 1 && inner.scroll <= inner.client) return last;
    await page.waitForTimeout(100);
  }
  assert.fail(`the frame did not take its content's height: ${JSON.stringify(last)}`);
}

describe("embedding on another origin", { timeout: TEST_TIMEOUT * 2 }, () => {
  test("the host and the playground are different origins", () => {
    assert.notEqual(new URL(host.url).origin, new URL(env.url).origin);
  });

  test("script form: a titled lazy iframe at the content's height that follows a taller content", async () => {
    const { context, page, log } = await open(env.browser, { viewport: { width: 390, height: 800 } });
    try {
      await page.goto(`${host.url}script.html`);
      const { frame } = await embedFrame(page, "#a iframe");
      const attrs = await page.$eval("#a iframe", (f) => ({ title: f.title, loading: f.loading, src: f.src }));
      assert.equal(attrs.loading, "lazy");
      assert.match(attrs.src, /embed\.html#\/gsd\?dpi=1200&.*id=a/);
      assert.match(attrs.src, new RegExp(`host=${encodeURIComponent(new URL(host.url).origin)}`));
      await page.waitForFunction(() => document.querySelector("#a iframe").title.startsWith("Ground sample distance"), null, { timeout: WAIT });
      const first = await fitsContent(page, "#a iframe", frame);
      // an invalid input adds its message and the stale banner: the content grows
      await frame.fill('[data-key="dpi"] input', "-5");
      await frame.waitForFunction(() => document.body?.dataset.status === "invalid", null, { timeout: WAIT });
      const taller = await fitsContent(page, "#a iframe", frame);
      assert.ok(taller.content > first.content + 20, `taller: ${first.content} → ${taller.content}`);
      // and shrinks back
      await frame.fill('[data-key="dpi"] input', "1200");
      await frame.waitForFunction(() => document.body?.dataset.status === "ok", null, { timeout: WAIT });
      const back = await fitsContent(page, "#a iframe", frame);
      assert.ok(Math.abs(back.content - first.content) <= 2, `back: ${back.content} vs ${first.content}`);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });

  test("iframe form: Canvas's lti.frameResize message sizes a plain iframe", async () => {
    const { context, page } = await open(env.browser, { viewport: { width: 1280, height: 700 } });
    try {
      await page.goto(`${host.url}iframe.html`);
      const { frame } = await embedFrame(page, "#plain");
      const fit = await fitsContent(page, "#plain", frame);
      const lti = await page.evaluate(() => window.lti);
      assert.ok(lti.length >= 1, "lti.frameResize was posted");
      const lastMsg = lti[lti.length - 1];
      assert.deepEqual(Object.keys(lastMsg).sort(), ["height", "subject"]);
      assert.equal(lastMsg.subject, "lti.frameResize");
      assert.equal(lastMsg.height, fit.content);
      await frame.fill('[data-key="dpi"] input', "abc");
      await frame.waitForFunction(() => document.body?.dataset.status === "invalid", null, { timeout: WAIT });
      const taller = await fitsContent(page, "#plain", frame);
      assert.ok(taller.content > fit.content, `taller: ${fit.content} → ${taller.content}`);
    } finally {
      await context.close();
    }
  });

  test("an embed in a hidden tab gets its height when the tab is shown", async () => {
    const { context, page } = await open(env.browser, { viewport: { width: 800, height: 800 } });
    try {
      await page.goto(`${host.url}tabs.html`);
      await page.waitForSelector("#b iframe", { state: "attached", timeout: WAIT });
      await page.click("#show");
      const { frame } = await embedFrame(page, "#b iframe");
      const fit = await fitsContent(page, "#b iframe", frame);
      assert.ok(fit.outer > 480, `more than the 480 px placeholder: ${fit.outer}`);
      // hidden again, changed from the host, shown: the new height follows
      await page.evaluate(() => {
        tab2.hidden = true;
        document.getElementById("b").playground.setState({ dpi: "x" });
      });
      await frame.waitForFunction(() => document.body?.dataset.status === "invalid", null, { timeout: WAIT });
      await page.evaluate(() => (tab2.hidden = false));
      const after = await fitsContent(page, "#b iframe", frame);
      assert.ok(after.content > fit.content, `${fit.content} → ${after.content}`);
    } finally {
      await context.close();
    }
  });

  test("messages from a third frame are ignored, even from the playground's own origin with the same id", async () => {
    const { context, page } = await open(env.browser);
    try {
      await page.goto(`${host.url}script.html`);
      const { frame } = await embedFrame(page, "#a iframe");
      const fit = await fitsContent(page, "#a iframe", frame);
      // the third frame is a real playground page (dpi 600, id "a") that embed.js did not make
      const third = await (await page.$("#third")).contentFrame();
      await third.waitForFunction(() => document.body?.dataset.status === "ok", null, { timeout: WAIT });
      // and it forges a resize and a change as well
      await third.evaluate(() => {
        const base = { version: 1, id: "a" };
        parent.postMessage({ ...base, type: "photogrammetry-playground:resize", height: 3333 }, "*");
        parent.postMessage({ ...base, type: "photogrammetry-playground:change", example: "gsd", inputs: { dpi: 600 } }, "*");
      });
      // the host page forges one too (right source origin? no: wrong source)
      await page.evaluate(() => window.postMessage({ version: 1, id: "a", type: "photogrammetry-playground:resize", height: 4444 }, "*"));
      // a real change in the real frame is a marker that every earlier message was handled
      await frame.fill('[data-key="dpi"] input', "1500");
      await page.waitForFunction(() => window.events.some((e) => e.type === "change" && e.detail.inputs?.dpi === 1500), null, { timeout: WAIT });
      const height = await page.$eval("#a iframe", (f) => f.getBoundingClientRect().height);
      assert.ok(Math.abs(height - fit.outer) <= 2, `height stayed ${fit.outer} (got ${height})`);
      const events = await page.evaluate(() => window.events);
      assert.ok(!events.some((e) => e.detail.inputs?.dpi === 600), "no event of the third frame");
      assert.ok(!events.some((e) => e.detail.height === 3333 || e.detail.height === 4444), "no forged resize");
      assert.equal(await page.evaluate(() => document.getElementById("a").playground.getState().inputs.dpi), 1500);
    } finally {
      await context.close();
    }
  });

  test("ready and change arrive at the host with the inputs and results; setState and getState", async () => {
    const { context, page } = await open(env.browser);
    try {
      await page.goto(`${host.url}script.html`);
      const { frame } = await embedFrame(page, "#a iframe");
      await page.waitForFunction(() => window.events.some((e) => e.type === "ready"), null, { timeout: WAIT });
      const ready = await page.evaluate(() => window.events.find((e) => e.type === "ready"));
      assert.equal(ready.id, "a");
      assert.equal(ready.detail.type, "photogrammetry-playground:ready");
      assert.equal(ready.detail.version, 1);
      assert.equal(ready.detail.id, "a");
      assert.equal(ready.detail.example, "gsd");
      assert.deepEqual(ready.detail.inputs, { dpi: 1200, focal_length_mm: 152, flying_height_m: 1920 });
      assert.ok(Math.abs(ready.detail.result.gsd_cm - gsdCm(1200)) < 1e-9);
      // the student types
      await frame.fill('[data-key="dpi"] input', "1500");
      await page.waitForFunction(() => window.events.some((e) => e.type === "change" && e.detail.inputs.dpi === 1500), null, { timeout: WAIT });
      const change = await page.evaluate(() => window.events.findLast((e) => e.type === "change"));
      assert.equal(change.detail.texts.dpi, "1500");
      assert.ok(Math.abs(change.detail.result.gsd_cm - gsdCm(1500)) < 1e-9);
      // the host sets the inputs; the embed solves and reports
      await page.evaluate(() => document.getElementById("a").playground.setState({ dpi: 2000, flying_height_m: "2400" }));
      await page.waitForFunction(() => document.getElementById("a").playground.getState()?.inputs.dpi === 2000, null, { timeout: WAIT });
      const state = await page.evaluate(() => document.getElementById("a").playground.getState());
      assert.equal(state.inputs.flying_height_m, 2400);
      assert.ok(Math.abs(state.result.gsd_cm - ((25.4 / 2000) * (2400 / 0.152)) / 10) < 1e-9);
      assert.equal(await frame.inputValue('[data-key="dpi"] input'), "2000");
      // an error is reported with the field
      await frame.fill('[data-key="dpi"] input', "-5");
      await page.waitForFunction(() => window.events.some((e) => e.type === "error"), null, { timeout: WAIT });
      const error = await page.evaluate(() => window.events.find((e) => e.type === "error"));
      assert.match(error.detail.errors.dpi, /greater than 0/);
    } finally {
      await context.close();
    }
  });

  test("keyboard: Tab moves into the embed and out of it again (no focus trap)", async () => {
    const { context, page } = await open(env.browser);
    try {
      await page.goto(`${host.url}script.html`);
      const { frame } = await embedFrame(page, "#a iframe");
      await page.focus("#before");
      await page.keyboard.press("Tab");
      assert.equal(await page.evaluate(() => document.activeElement.tagName), "IFRAME");
      assert.ok(await frame.evaluate(() => document.activeElement !== document.body), "focus is on a control in the embed");
      // from the last control of the embed, Tab leaves it for the host's next button
      await frame.evaluate(() => {
        const all = [...document.querySelectorAll("a[href], button, input, select, textarea, [tabindex]")].filter((e) => e.tabIndex >= 0 && !e.disabled && e.offsetParent !== null);
        all[all.length - 1].focus();
      });
      await page.keyboard.press("Tab");
      assert.equal(await page.evaluate(() => document.activeElement.id), "after");
      await page.keyboard.press("Shift+Tab");
      assert.equal(await page.evaluate(() => document.activeElement.tagName), "IFRAME");
    } finally {
      await context.close();
    }
  });
});
