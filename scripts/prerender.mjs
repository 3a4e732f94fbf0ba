// The top of every example's seed solution, as the page itself renders it,
// saved at build time (issue 19: the numbers on screen before the page's JS
// and wasm have run). Run by scripts/build.sh between the two steps of
// scripts/site.mjs (build, finish), on the built site:
//   node scripts/prerender.mjs [dist]
//
// For each ready example of the built catalog it opens index.html#/<id> and
// embed.html#/<id> in headless Chromium (the page served from dist/ by
// scripts/serve.mjs; KaTeX kept out; service workers blocked) and waits for
// the page's own first solution (the `solver-ready` mark of www/app.js). It
// saves the children of <main id="app"> down to the answer line (the
// heading, what the example is, its answer with the printed values beside),
// then "Loading the solver…", as dist/prerender/<id>.html and
// dist/prerender/embed/<id>.html; what belongs to one window only (inline
// sizes the page measured) is left out. The numbers are the page's own: the
// same wasm, parse, solve and render code computed them; nothing here
// formats a value.
//
// Each page's catalog-data block then says where its saved parts are and
// which ("prerendered": { folder, ids, options }), and www/preload-route.js
// fetches the example's for an address with no inputs (view options only:
// `options`, the keys of www/embed-options.js) and shows it, inert, until the
// page's own view replaces it.
//
// On index.html it also saves the catalog's picture of each example's figure
// (issue 29: its first canvas for the seed, 320 × 200 WebP, and a dark one
// when the figures draw one for <html data-theme="dark">) in
// dist/prerender/thumbs/, listed in that page's data block as
// "thumbs": { folder, ids, dark }; www/catalog.js shows them, loaded lazily,
// and the service worker caches them when first used (prerender/ is lazy).
//
// Without Chromium (/usr/bin/chromium, or CHROMIUM_PATH) the step says so and
// saves nothing: the page works as before, its first numbers later and its
// catalog without pictures.
import fs from "node:fs";
import path from "node:path";
import { fileURLToPath } from "node:url";
import { DATA_BLOCK, dataBlock, readDataBlock } from "./site.mjs";
import { CHROMIUM, launchChromium } from "./chromium.mjs";
import { startServer } from "./serve.mjs";
import { THUMB as SHOWN } from "../www/catalog.js";

/** The width the solutions are laid out at (the page's own CSS re-lays them at any other). */
const VIEWPORT = { width: 1280, height: 900 };

/**
 * Runs in the page: the children of #app as HTML, down to the answer line
 * (the example's heading, what it is, its answer with the printed values
 * beside), with "Loading the solver…" where the inputs, steps, figure, result
 * and notes come; no inline style, nothing the page set for this window only.
 *
 * Why not the whole solution: laying out and painting the whole saved page
 * (steps, tables, notes: 20–35 KB of HTML) competes with the page's own start
 * on the main thread: on this 2-core machine its own first solution came
 * 50–70 ms later (interleaved cold loads of the same build with and without;
 * docs/BENCH-LOAD.md, session 26), against about 10 ms for the answer line
 * alone. On a phone the answer line is the first screen anyway.
 */
function snapshot() {
  const app = document.getElementById("app").cloneNode(true);
  const article = app.querySelector("article.example");
  const layout = article.querySelector(":scope > .layout");
  while (layout.nextSibling) layout.nextSibling.remove();
  const loading = document.createElement("p");
  loading.className = "loading";
  loading.textContent = "Loading the solver…";
  layout.replaceWith(loading);
  // (the answer line keeps its tallest height with an inline min-height: not another window's)
  app.querySelectorAll("[style]").forEach((node) => node.removeAttribute("style"));
  // the print-only block names this server's address (the page's own view writes it with the reader's)
  app.querySelectorAll(".print-only").forEach((node) => node.remove());
  // its list is built when the drawer first opens; a closed drawer is saved closed
  app.querySelectorAll("details").forEach((d) => d.removeAttribute("open"));
  return app.innerHTML;
}

/**
 * The catalog's picture of an example's figure (issue 29, item 14): its first
 * canvas as the page drew it for the seed, scaled to fit THUMB (pixels: twice
 * the size catalog.js shows it at, SHOWN, for 2× screens) on the figure's own
 * background, as WebP. Null when the example has no figure.
 */
const THUMB = { width: 2 * SHOWN.width, height: 2 * SHOWN.height, quality: 0.8 };

/** Runs in the page: the picture of the figure on screen as a data: URL, or null. */
function thumbnail({ width, height, quality }) {
  const canvas = document.querySelector(".figure-section canvas.figure-canvas");
  if (!canvas || !canvas.width || !canvas.height) return null;
  const out = document.createElement("canvas");
  out.width = width;
  out.height = height;
  const ctx = out.getContext("2d");
  // the figure's own background (its top-left pixel) around it
  const [r, g, b] = canvas.getContext("2d").getImageData(0, 0, 1, 1).data;
  ctx.fillStyle = `rgb(${r} ${g} ${b})`;
  ctx.fillRect(0, 0, width, height);
  // the whole figure where it is about as wide as the picture; a tall one fills the width and
  // shows its top (a figure's title, scale and first rows are at its top)
  const scale = Math.max(Math.min(width / canvas.width, height / canvas.height), (0.75 * width) / canvas.width);
  const w = canvas.width * scale;
  const h = canvas.height * scale;
  ctx.imageSmoothingEnabled = true;
  ctx.imageSmoothingQuality = "high";
  ctx.drawImage(canvas, (width - w) / 2, h > height ? 0 : (height - h) / 2, w, h);
  return out.toDataURL("image/webp", quality);
}

/** Two frames: what a change of <html data-theme> makes the figures draw is on the canvas. */
function twoFrames() {
  return new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(() => resolve())));
}

/** A data: URL's bytes. */
function dataBytes(url) {
  const m = /^data:image\/webp;base64,(.*)$/.exec(url ?? "");
  if (!m) throw new Error("prerender: a figure's picture is not WebP (does this Chromium encode WebP?)");
  return Buffer.from(m[1], "base64");
}

/**
 * The two pages and where their saved parts go: the embed's differs (its
 * heading is the page's h1, no "← Catalog"), and is the same for any of its
 * view options (they show or hide the parts below the answer line).
 */
const PAGES = [
  { file: "index.html", folder: "prerender", thumbs: "prerender/thumbs" },
  { file: "embed.html", folder: "prerender/embed" },
];

export async function prerender(dist) {
  const pages = PAGES.map((p) => {
    const html = fs.readFileSync(path.join(dist, p.file), "utf8");
    const data = readDataBlock(html);
    if (!data) throw new Error(`prerender: ${p.file} has no catalog-data block (run scripts/site.mjs build first)`);
    return { ...p, html, data, saved: [], pictured: [], dark: [] };
  });
  const ids = pages[0].data.entries.filter((e) => e.status === "ready").map((e) => e.id);
  if (!fs.existsSync(CHROMIUM)) {
    console.log(`prerender: skipped: no Chromium at ${CHROMIUM} (the page shows its numbers when its solver is in)`);
    return [];
  }
  // the view options an address may carry beside an example's inputs (www/embed-options.js):
  // with only these, preload-route.js still shows the saved part
  const { OPTION_KEYS } = await import(new URL("../www/embed-options.js", import.meta.url).href);
  const server = await startServer({ dir: dist, port: 0 });
  const browser = await launchChromium();
  fs.rmSync(path.join(dist, "prerender"), { recursive: true, force: true });
  for (const p of pages) for (const f of [p.folder, p.thumbs].filter(Boolean)) fs.mkdirSync(path.join(dist, f), { recursive: true });
  try {
    for (const p of pages) {
      for (const id of ids) {
        const context = await browser.newContext({ viewport: VIEWPORT, serviceWorkers: "block", reducedMotion: "reduce" });
        try {
          const page = await context.newPage();
          const errors = [];
          page.on("pageerror", (e) => errors.push(e.message));
          await page.route(/\/vendor\/katex\//, (route) => route.abort());
          await page.goto(`${server.url}${p.file}#/${encodeURIComponent(id)}`);
          await page.waitForFunction(() => performance.getEntriesByName("solver-ready").length > 0 && document.body.dataset.status !== "loading", null, { timeout: 60_000 });
          const status = await page.evaluate(() => document.body.dataset.status);
          if (status !== "ok" || errors.length) throw new Error(`prerender: ${p.file}#/${id}: the page says ${status} ${errors.join("; ")}`);
          const saveHtml = await page.evaluate(snapshot);
          if (/<script|\son\w+=/i.test(saveHtml)) throw new Error(`prerender: ${p.file}#/${id}: the solution holds a script or an event handler`);
          if (saveHtml.includes(new URL(server.url).host)) throw new Error(`prerender: ${p.file}#/${id}: the solution names the build's own server (${server.url})`);
          fs.writeFileSync(path.join(dist, p.folder, `${id}.html`), saveHtml);
          p.saved.push(id);
          if (p.thumbs) {
            // the figure's picture for the catalog, and the dark one where the figures draw one
            // (they redraw when <html data-theme> changes; an identical picture is not kept)
            const light = await page.evaluate(thumbnail, THUMB);
            if (light) {
              fs.writeFileSync(path.join(dist, p.thumbs, `${id}.webp`), dataBytes(light));
              p.pictured.push(id);
              await page.evaluate(() => document.documentElement.setAttribute("data-theme", "dark"));
              await page.evaluate(twoFrames);
              const dark = await page.evaluate(thumbnail, THUMB);
              if (dark && dark !== light) {
                fs.writeFileSync(path.join(dist, p.thumbs, `${id}.dark.webp`), dataBytes(dark));
                p.dark.push(id);
              }
            }
          }
        } finally {
          await context.close();
        }
      }
    }
  } finally {
    await browser.close();
    await server.close();
  }
  let kb = 0;
  for (const p of pages) {
    const thumbs = p.thumbs ? { thumbs: { folder: `./${p.thumbs}/`, ids: p.pictured, dark: p.dark } } : {};
    const block = dataBlock({ ...p.data, prerendered: { folder: `./${p.folder}/`, ids: p.saved, options: OPTION_KEYS }, ...thumbs });
    fs.writeFileSync(path.join(dist, p.file), p.html.replace(DATA_BLOCK, () => block));
    kb += p.saved.reduce((s, id) => s + fs.statSync(path.join(dist, p.folder, `${id}.html`)).size, 0) / 1024;
  }
  console.log(`prerender: ${pages.map((p) => `${p.saved.length} answers for ${p.file} in ${p.folder}/`).join(", ")} (${kb.toFixed(0)} KB raw in all)`);
  for (const p of pages.filter((x) => x.thumbs)) {
    const bytes = fs.readdirSync(path.join(dist, p.thumbs)).reduce((sum, f) => sum + fs.statSync(path.join(dist, p.thumbs, f)).size, 0);
    console.log(`prerender: ${p.pictured.length} pictures of figures (${p.dark.length} dark) in ${p.thumbs}/, ${(bytes / 1024).toFixed(0)} KB, loaded lazily by the catalog`);
  }
  return pages.map((p) => p.saved);
}

if (process.argv[1] && fileURLToPath(import.meta.url) === path.resolve(process.argv[1])) {
  await prerender(path.resolve(process.argv[2] || "dist"));
}
