// Issue 32, items 2 and 3, for the page (docs/accessibility.md): axe-core
// with the WCAG 2.2 AA rule tags at 390 and 1280 px, light and dark (all four
// combinations) on every example, practice, a worksheet, the embed and its
// "Embed this" panel: zero violations of any impact. Lean where nothing is
// lost: one page a combination (two at work at once), examples reached by the
// address's hash; every rule in the light theme, the rules that depend on
// colours in the dark (the theme changes nothing else); the whole page
// (header, footer, KaTeX's visual copy of the formulas) on the first example
// and a handful of others, the example's own view (<main>) without KaTeX's
// aria-hidden copy on the rest. Target sizes at 390 px (24 × 24 or the
// spacing exception; the chain-code grid's cells too), reflow at 320 px, what
// the accessibility tree says for a power of ten, a result card and the
// answer line, and the keyboard alone: an input changed and the answer read
// in the live region, a practice box graded and its verdict read.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import { createRequire } from "node:module";
import { CATALOG_IDS, TEST_TIMEOUT, open, settled, start } from "./harness.mjs";

const AXE = createRequire(import.meta.url).resolve("axe-core/axe.min.js");
/** WCAG 2.0, 2.1 and 2.2, levels A and AA (axe-core's tags). */
const TAGS = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa", "wcag22aa"];
/**
 * The rules of those tags whose outcome depends on the colours (all the theme
 * changes): in the dark theme only these run on the examples; the others'
 * outcome is the light theme's (nothing but colours differs between them).
 */
const COLOUR_RULES = ["color-contrast", "link-in-text-block"];
const WAIT = 20_000;
const PRACTICE = "index.html#/gsd?practice=1K7Q2";
const WORKSHEET = "index.html#/practice?worksheet=gsd&n=2";
const EMBED = "embed.html#/gsd?dpi=1200";
/** Examples checked at the two other combinations too: a matrix, a grid, chain codes, a projection. */
const HANDFUL = ["gsd", "lsm-affine", "ncc-2d", "chain-code", "utm"];

let env;
let page;
let context;
before(async () => {
  env = await start();
  // bypassCSP: axe is injected as a script, which the page's CSP rightly refuses
  ({ context, page } = await open(env.browser, { bypassCSP: true }));
});
after(async () => {
  await context?.close();
  await env?.close();
});

/**
 * Opens `address` ("index.html#/gsd") on `p` (the shared page unless given):
 * a new hash on the same file is a route of the page already loaded
 * (hashchange), another file a load; waits until the page has settled and
 * its formulas are typeset.
 */
async function go(address, p = page) {
  const [file, hash = ""] = address.split("#");
  const here = await p.evaluate(() => location.pathname.split("/").pop()).catch(() => "");
  if (here === file && p.url() !== "about:blank") {
    await p.evaluate((h) => {
      if (location.hash === `#${h}`) return; // already there
      document.body.dataset.status = "routing";
      location.hash = h;
    }, hash);
  } else {
    await p.goto(`${env.url}${address}`);
  }
  await p.waitForFunction(
    () => !["routing", "loading", "updating"].includes(document.body.dataset.status) && document.documentElement.dataset.math !== "loading" && !document.querySelector("[aria-busy]"),
    null,
    { timeout: WAIT },
  );
  // the page marks scrolling formulas focusable when idle after a solve
  await idle(p);
  return p.evaluate(() => document.body.dataset.status);
}

const idle = (p) => p.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestIdleCallback(resolve, { timeout: 2000 }))));

async function look(width, scheme, p = page) {
  await p.setViewportSize({ width, height: 900 });
  await p.emulateMedia({ colorScheme: scheme, reducedMotion: "reduce" });
}

/**
 * Every violation of the WCAG A/AA rules on the page as it is now, as readable
 * lines. `lean`: only the example's view (<main>: the header and footer are
 * the same on every example, checked whole once per width and theme) without
 * KaTeX's visual copy of each formula (.katex-html, hidden from assistive
 * technology; the MathML beside it is checked) — axe's time grows with its
 * boxes (62 s for ncc-1d on a loaded machine); a handful of examples are
 * checked whole at every width and theme (KaTeX's colours among them).
 */
async function violations(where, { lean = false, p = page, colours = false } = {}) {
  if (!(await p.evaluate(() => typeof window.axe === "object"))) await p.addScriptTag({ path: AXE });
  const runOnly = colours ? { type: "rule", values: COLOUR_RULES } : { type: "tag", values: TAGS };
  const result = await p.evaluate(
    ([runOnly, lean]) => window.axe.run(lean ? { include: [["main"]], exclude: [[".katex-html"]] } : document, { runOnly, resultTypes: ["violations"] }),
    [runOnly, lean],
  );
  return result.violations.map((v) => `${where}: ${v.id} (${v.impact}) ${v.nodes.slice(0, 3).map((n) => `${n.target.join(" ")} ${n.any[0]?.message ?? ""}`).join(" | ")}`);
}

async function openEmbedPanel() {
  await go("index.html#/gsd");
  await page.locator('[data-tool="embed"]').focus();
  await page.keyboard.press("Enter");
  await page.waitForSelector(".embed-panel");
  await idle(page);
}


// every example at both widths, light and dark (the four combinations): one page a combination
// (each in a context of its own), reused from example to example by the address's hash, two at work
// at once. (Not one page switched between the themes: a step off screen — content-visibility: auto —
// keeps the old theme's colours until it is rendered, and axe reads them.)
describe("axe-core, WCAG 2.2 AA tags: zero violations on every example", { timeout: TEST_TIMEOUT * 20, concurrency: 2 }, () => {
  test("the catalog names the examples", () => assert.ok(CATALOG_IDS.length >= 20, `examples: ${CATALOG_IDS.length}`));

  for (const [width, scheme] of [
    [1280, "light"],
    [390, "light"],
    [1280, "dark"],
    [390, "dark"],
  ]) {
    const colours = scheme === "dark";
    test(`every example at ${width} px, ${scheme} (${HANDFUL.join(", ")} and the first whole, the others their view without KaTeX's visual copy${colours ? "; the rules that depend on colours" : ""})`, async () => {
      const { context: own, page: p } = await open(env.browser, { bypassCSP: true });
      try {
        const problems = [];
        await look(width, scheme, p);
        for (const [k, id] of CATALOG_IDS.entries()) {
          assert.equal(await go(`index.html#/${id}`, p), "ok", id);
          problems.push(...(await violations(`${id} ${width} px ${scheme}`, { lean: k > 0 && !HANDFUL.includes(id), p, colours })));
        }
        assert.deepEqual(problems, []);
      } finally {
        await own.close();
      }
    });
  }
});

describe("axe-core, WCAG 2.2 AA tags: zero violations on practice, a worksheet, the embed and its panel", { timeout: TEST_TIMEOUT * 8 }, () => {
  for (const [width, scheme] of [
    [1280, "light"],
    [390, "dark"],
    [390, "light"],
    [1280, "dark"],
  ]) {
    test(`at ${width} px, ${scheme}`, async () => {
      await look(width, scheme);
      const problems = [];
      assert.equal(await go(PRACTICE), "practice");
      problems.push(...(await violations("practice")));
      assert.equal(await go(WORKSHEET), "worksheet");
      problems.push(...(await violations("worksheet")));
      await openEmbedPanel();
      problems.push(...(await violations("the Embed this panel")));
      assert.equal(await go(EMBED), "ok");
      problems.push(...(await violations("embed")));
      assert.deepEqual(problems, []);
    });
  }
});

/**
 * The interactive elements on screen whose box is under 24 × 24 px and that
 * the spacing exception does not cover (a 24 px circle on its centre meets
 * another target or its circle). Links inside running text are exempt.
 */
function smallTargets() {
  const SELECTOR = 'a[href], button, input:not([type="hidden"]), select, textarea, summary, [tabindex]:not([tabindex="-1"]), [role="button"]';
  const all = [...document.querySelectorAll(SELECTOR)].filter((e) => {
    const r = e.getBoundingClientRect();
    const s = getComputedStyle(e);
    return r.width > 0 && r.height > 0 && s.visibility !== "hidden" && !e.closest("[hidden], [inert]") && r.bottom > 0;
  });
  const inText = (e) => e.tagName === "A" && getComputedStyle(e).display === "inline" && [...e.parentElement.childNodes].some((n) => n !== e && n.textContent.trim());
  const boxes = all.map((e) => ({ e, r: e.getBoundingClientRect() }));
  const small = (r) => r.width < 23.99 || r.height < 23.99;
  const centre = (r) => [r.left + r.width / 2, r.top + r.height / 2];
  const distToRect = ([x, y], r) => Math.hypot(Math.max(r.left - x, 0, x - r.right), Math.max(r.top - y, 0, y - r.bottom));
  const out = [];
  for (const { e, r } of boxes) {
    if (!small(r) || inText(e) || e.closest(".skip-link")) continue;
    const c = centre(r);
    const clash = boxes.find(({ e: o, r: q }) => o !== e && !o.contains(e) && !e.contains(o) && (distToRect(c, q) < 12 || (small(q) && Math.hypot(c[0] - centre(q)[0], c[1] - centre(q)[1]) < 24)));
    if (clash) out.push(`${e.tagName.toLowerCase()}.${e.className} "${(e.textContent || e.getAttribute("aria-label") || "").trim().slice(0, 30)}" ${Math.round(r.width)}×${Math.round(r.height)}`);
  }
  return out;
}

describe("at 390 px and 320 px", { timeout: TEST_TIMEOUT * 4 }, () => {
  test("every interactive element is 24 × 24 px or spaced (2.5.8)", async () => {
    await look(390, "light");
    const problems = [];
    for (const address of ["index.html#/gsd", "index.html#/lsm-affine", "index.html#/ncc-2d", "index.html#/chain-code", "index.html#/fiducial-affine", PRACTICE, WORKSHEET, "embed.html#/gsd"]) {
      await go(address);
      for (const p of await page.evaluate(smallTargets)) problems.push(`${address}: ${p}`);
    }
    await openEmbedPanel();
    for (const p of await page.evaluate(smallTargets)) problems.push(`Embed this: ${p}`);
    assert.deepEqual(problems, []);
  });

  test("the chain-code drawing grid: every cell a 24 × 24 px target at 390 px, the grid scrolling in its own named region, its text wrapped to what is seen", async () => {
    await look(390, "light");
    assert.equal(await go("index.html#/chain-code"), "ok");
    const presets = await page.locator(".figure-actions button").allInnerTexts();
    assert.ok(presets.includes("Rectangle") && presets.length >= 6, presets.join(", "));
    for (const name of presets) {
      await page.locator(".figure-actions button", { hasText: name }).first().click();
      assert.equal(await settled(page), "ok", name);
      await idle(page); // the figure's paint of the new inputs (its resize observer's frame included)
      const grid = await page.evaluate(async () => {
        // the cells where the figure's own layout puts them for the inputs on the page (chains.js cellPoint)
        const { loadCore } = await import("./core.js");
        const fig = await import("./figures/chains.js");
        const core = await loadCore();
        const texts = {};
        for (const f of document.querySelectorAll(".input-form [name]")) texts[f.name] = f.value;
        const solution = core.solve("chain-code", core.parseInputs("chain-code", texts).inputs);
        const canvas = document.querySelector(".figure-canvas");
        const [p, q] = [fig.cellPoint(canvas.clientWidth, solution, [1, 1]), fig.cellPoint(canvas.clientWidth, solution, [2, 2])];
        // the text under the grid wraps to the panel's visible width: right of it, nothing but paper
        const room = canvas.closest(".figure-panel").clientWidth;
        const dpr = canvas.width / canvas.clientWidth;
        const [x0, y0] = [Math.ceil(room * dpr), Math.ceil(fig.infoTop(canvas.clientWidth, solution) * dpr)];
        let inked = 0;
        if (x0 < canvas.width && y0 < canvas.height) {
          const px = canvas.getContext("2d").getImageData(x0, y0, canvas.width - x0, canvas.height - y0).data;
          for (let i = 0; i < px.length; i += 4) if (px[i] !== px[0] || px[i + 1] !== px[1] || px[i + 2] !== px[2]) inked++;
        }
        // the box that scrolls when the canvas is wider than the page allows
        let box = canvas.parentElement;
        while (box && !/auto|scroll/.test(getComputedStyle(box).overflowX)) box = box.parentElement;
        const label = (e) => e && (e.getAttribute("aria-label") || e.querySelector(":scope > figcaption")?.textContent || "");
        return {
          cell: [q[0] - p[0], q[1] - p[1]],
          canvas: Math.round(canvas.getBoundingClientRect().width),
          wide: canvas.getBoundingClientRect().width > canvas.closest(".figure-panel").clientWidth + 1,
          page: document.documentElement.scrollWidth - document.documentElement.clientWidth,
          focusable: canvas.tabIndex === 0,
          inked,
          scroller: box ? { label: label(box), wider: box.scrollWidth > box.clientWidth + 1, inside: box.contains(canvas) } : null,
          // for a failure's message: the panel as it was
          panel: (({ className, clientWidth }) => ({ className, clientWidth, overflowX: getComputedStyle(canvas.closest(".figure-panel")).overflowX }))(canvas.closest(".figure-panel")),
        };
      });
      assert.ok(grid.cell[0] >= 24 && grid.cell[1] >= 24, `${name}: cells ${grid.cell.map((x) => x.toFixed(1)).join(" × ")} px`);
      assert.equal(grid.page, 0, `${name}: the page itself scrolls sideways`);
      assert.ok(grid.focusable, `${name}: the grid takes the keyboard's focus`);
      assert.equal(grid.inked, 0, `${name}: the text under a ${grid.canvas} px grid reaches past the panel's visible width`);
      if (grid.wide) {
        assert.ok(grid.scroller?.wider && grid.scroller.inside && grid.scroller.label.length > 10, `${name}: a grid ${grid.canvas} px wide needs a named scrolling region: ${JSON.stringify(grid.scroller)}; its panel ${JSON.stringify(grid.panel)}`);
        // the cell cursor's cell is scrolled into view as the keys move it (index.js keepInView)
        await page.focus(".figure-canvas");
        const scrolled = async (key) => {
          await page.keyboard.press(key);
          return page.evaluate(() => {
            const panel = document.querySelector(".figure-canvas").closest(".figure-panel");
            return { left: panel.scrollLeft, max: panel.scrollWidth - panel.clientWidth, line: panel.querySelector(".figure-cursor")?.textContent ?? "" };
          });
        };
        await scrolled("Home");
        const atEnd = await scrolled("End");
        assert.ok(atEnd.left > 0 && Math.abs(atEnd.left - atEnd.max) <= 1, `${name}: End puts the last column in view: ${JSON.stringify(atEnd)}`);
        assert.match(atEnd.line, /column/, `${name}: the cursor line reads the cell`);
        const atHome = await scrolled("Home");
        assert.equal(atHome.left, 0, `${name}: Home scrolls back to the first column`);
      }
    }
  });

  test("the page reflows at 320 px: nothing scrolls sideways but boxes of their own (1.4.10)", async () => {
    await look(320, "light");
    for (const address of ["index.html#/gsd", "index.html#/lsm-affine", PRACTICE, "embed.html#/utm"]) {
      await go(address);
      const { scroll, width } = await page.evaluate(() => ({ scroll: document.documentElement.scrollWidth, width: document.documentElement.clientWidth }));
      assert.ok(scroll <= width, `${address}: ${scroll} px wide in ${width}`);
    }
  });
});

/**
 * The accessibility tree's nodes (CDP) whose DOM node matches `selector`, with
 * their subtree's text; asked again when the page replaced a node meanwhile
 * (a formula fitted after its step was rendered).
 */
async function axText(selector, tries = 3) {
  try {
    return await axTextOnce(selector);
  } catch (e) {
    if (tries <= 1 || !/Could not find node/.test(e.message)) throw e;
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0))));
    return axText(selector, tries - 1);
  }
}

async function axTextOnce(selector) {
  const cdp = await context.newCDPSession(page);
  try {
    const { nodes } = await cdp.send("Accessibility.getFullAXTree");
    const byId = new Map(nodes.map((n) => [n.nodeId, n]));
    const { root } = await cdp.send("DOM.getDocument", { depth: -1 });
    const { nodeIds } = await cdp.send("DOM.querySelectorAll", { nodeId: root.nodeId, selector });
    const out = [];
    for (const nodeId of nodeIds) {
      const { node } = await cdp.send("DOM.describeNode", { nodeId });
      const ax = nodes.find((n) => n.backendDOMNodeId === node.backendNodeId);
      if (!ax) continue;
      const texts = [];
      const walk = (n) => {
        if (!n.ignored && n.role?.value === "StaticText") texts.push(n.name?.value ?? "");
        for (const c of n.childIds ?? []) if (byId.has(c)) walk(byId.get(c));
      };
      walk(ax);
      out.push({ role: ax.role?.value, name: ax.name?.value ?? "", text: texts.join("") });
    }
    return out;
  } finally {
    await cdp.detach();
  }
}

describe("what a screen reader gets (the accessibility tree over CDP)", { timeout: TEST_TIMEOUT * 2 }, () => {
  test("powers of ten in words, a card's cell without its visual label, a matrix as a table, the answer line without dots", async () => {
    await look(390, "light");
    assert.equal(await go("index.html#/lsm-affine"), "ok");
    const cells = await axText('.result-table td.exact');
    const sci = cells.find((c) => /× 10/.test(c.text) || /times 10/.test(c.text));
    assert.ok(sci, JSON.stringify(cells));
    assert.match(sci.text, /\d times 10 to the minus \d/);
    assert.doesNotMatch(sci.text, /[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]/);
    // the card's "Exact" label is drawn for the eye only: the column header names the cell
    for (const c of cells) assert.doesNotMatch(c.name, /^Exact/, c.name);
    // what is shown and copied is unchanged
    assert.match(await page.locator(".result-table td.exact").allInnerTexts().then((t) => t.join(" ")), /\d × 10⁻[⁰¹²³⁴⁵⁶⁷⁸⁹]/);
    // the substituted formulas are MathML, the KaTeX boxes hidden: no text twice
    // (a step off screen is not rendered: content-visibility, style.css)
    await page.locator(".steps .formula math").first().scrollIntoViewIfNeeded();
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(() => setTimeout(r, 0)))));
    const formula = (await axText(".steps .formula:has(math)"))[0];
    assert.ok(formula.text.length > 0);
    assert.equal(await page.locator(".steps .katex-html:not([aria-hidden='true'])").count(), 0);
    assert.ok((await page.locator(".steps .formula math").count()) > 0);

    assert.equal(await go("index.html#/utm"), "ok");
    const answer = (await axText(".answer-line"))[0];
    assert.doesNotMatch(answer.text, /·/, answer.text);
    assert.match(answer.text, /Easting E = [\d.]+ m; Northing N = /, answer.text);
  });
});

describe("the keyboard alone", { timeout: TEST_TIMEOUT * 2 }, () => {
  /** Presses Tab until `selector` has the focus (at most `max` times). */
  async function tabTo(selector, max = 60) {
    for (let i = 0; i < max; i++) {
      await page.keyboard.press("Tab");
      if (await page.evaluate((s) => document.activeElement?.matches(s), selector)) return;
    }
    assert.fail(`Tab never reached ${selector}`);
  }

  test("the skip link first, on the site and the embed; Enter moves into <main>", async () => {
    await look(1280, "light");
    for (const address of ["index.html#/gsd", "embed.html#/gsd"]) {
      await page.goto("about:blank");
      await go(address);
      await page.keyboard.press("Tab");
      assert.deepEqual(await page.evaluate(() => [document.activeElement.className, document.activeElement.textContent]), ["skip-link", "Skip to the example"], address);
      const box = await page.locator(".skip-link").boundingBox();
      assert.ok(box.y >= 0 && box.height >= 24, `shown on focus: ${JSON.stringify(box)}`);
      await page.keyboard.press("Enter");
      assert.equal(await page.evaluate(() => document.activeElement.tagName), "MAIN", address);
    }
    // one <main>; every <nav> named
    assert.equal(await page.locator("main").count(), 1);
  });

  test("#/gsd: a changed input's answer is read in the one live region", async () => {
    await look(1280, "light");
    await page.goto("about:blank");
    await go("index.html#/gsd");
    const live = () =>
      page.evaluate(() =>
        [...document.querySelectorAll("[aria-live], [role=status], [role=alert]")]
          .filter((e) => (e.getAttribute("aria-live") ?? "polite") !== "off" && /Ground sample distance/.test(e.textContent))
          .map((e) => ({ cls: e.className, text: e.textContent })),
      );
    await tabTo('[data-key="dpi"] input');
    await page.keyboard.press("Control+A");
    await page.keyboard.type("1500");
    await page.waitForFunction(() => /21\.3895/.test(document.querySelector(".result-announcer")?.textContent ?? ""), null, { timeout: WAIT });
    const regions = await live();
    assert.equal(regions.length, 1, JSON.stringify(regions));
    assert.match(regions[0].text, /^Ground sample distance = 21\.3895\d* cm/);
    // the visible answer line says the same and is not a second live region
    assert.match(await page.locator(".answer-line").innerText(), /Ground sample distance = 21\.3895/);
  });

  test("practice: an answer typed, Enter, the verdict read in its box's live region", async () => {
    await page.goto("about:blank");
    assert.equal(await go(PRACTICE), "practice");
    const want = await page.evaluate(async () => {
      const m = await import("./pkg/photogrammetry_playground.js");
      await m.default();
      const p = m.practice("gsd", "1K7Q2");
      return m.solve("gsd", p.inputs).result.scale_denominator;
    });
    await tabTo('.answer[data-key="scale_denominator"] input');
    await page.keyboard.type(String(Math.round(want)));
    await page.keyboard.press("Enter");
    const feedback = page.locator('.answer[data-key="scale_denominator"] .answer-feedback');
    assert.equal(await feedback.getAttribute("aria-live"), "polite");
    await page.waitForFunction(() => /\S/.test(document.querySelector('.answer[data-key="scale_denominator"] .answer-feedback').textContent), null, { timeout: WAIT });
    assert.match(await feedback.innerText(), /^Correct/);
    // a wrong one next, the same way
    await page.keyboard.press("Tab");
    await tabTo('.answer[data-key="pixel_size_mm"] input');
    await page.keyboard.type("5");
    await page.keyboard.press("Enter");
    await page.waitForFunction(() => /\S/.test(document.querySelector('.answer[data-key="pixel_size_mm"] .answer-feedback').textContent), null, { timeout: WAIT });
    assert.match(await page.locator('.answer[data-key="pixel_size_mm"] .answer-feedback').innerText(), /^Not yet/);
  });
});
