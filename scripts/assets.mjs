// The build's last step over dist/ (issue 19: everything on the critical path
// earns its bytes). Generic over whatever files the build put there:
//   node scripts/assets.mjs [dist]
//  1. HTML includes: `<!-- include: head.partial.html -->` is replaced by that
//     file (one source for the <head> of index.html and embed.html); every
//     *.partial.html is then removed.
//  2. Content-hashed names (`render.3f9a2c1b.js`) for JS, wasm, CSS, JSON,
//     fonts and images, except STABLE names (fixed public URLs) and files that
//     no literal names (fetched by a computed URL: they keep their name).
//     References are rewritten where no import map applies: string literals
//     in JS that name a file (`new URL("x_bg.wasm", import.meta.url)`,
//     `script.src = "./vendor/…"`), every import specifier of files that run
//     without the page's import map (workers, the stable entries third-party
//     pages import, what they import), url(…) in CSS, src/href in HTML.
//     Page modules keep their logical import specifiers: an import map in the
//     HTML maps each logical URL to its hashed one (dynamic import() with a
//     computed specifier included). Files are hashed leaves first; a cycle of
//     literal references fails the build.
//  3. The HTML: import map (its sha256 added to the CSP's script-src; a module
//     scripts/bundle.mjs put into the page's bundle maps to the bundle), small
//     classic scripts inlined (same), `<!-- modulepreload -->` replaced by
//     modulepreload links for the static import graph of the page's module
//     scripts, `<!-- catalog-data -->` by the catalog and each topic's files
//     (read by core.js and preload-route.js), every src/href rewritten.
//  0. Minified JS (terser: compress + mangle, one file at a time; the page's
//     modules are already one file, app.js, by scripts/bundle.mjs),
//     every .js/.mjs but vendor/ (minified by its authors) and sw.js (whose
//     precache list sw-manifest.mjs writes at a marker comment). It buys about
//     40 % of the gzipped JS on every critical path (docs/BENCH-LOAD.md,
//     "Measured"). Files with import/export statements are minified as ES
//     modules (top-level names mangled; exported names kept), the others as
//     classic scripts (their top-level names are globals, kept). CSS outside
//     vendor/ loses its comments and the white space around punctuation
//     (strings and url() untouched): about a fifth of its gzipped bytes.
//  4. dist/assets.json (logical → hashed), dist/_headers (cache rules for
//     Netlify / Cloudflare Pages), then scripts/sw-manifest.mjs (the service
//     worker's precache list of the final names), then .gz (zlib level 9)
//     and .br (brotli quality 11) beside every compressible file.
import crypto from "node:crypto";
import { spawnSync } from "node:child_process";
import fs from "node:fs";
import path from "node:path";
import zlib from "node:zlib";
import { fileURLToPath } from "node:url";
import { minify } from "terser";

/**
 * Names other sites or the browser reference by a fixed URL (never hashed):
 * the pages, the service worker (a worker keeps its URL), the course
 * authors' host script, the documented JS API entries (docs/API.md, README),
 * and the build's version file. Files this step writes are never hashed.
 */
export const STABLE = [
  "index.html", // the site's address
  "embed.html", // iframes of course pages (README, embed.js)
  "sw.js", // a service worker must keep its URL
  "embed.js", // <script src=".../embed.js"> on course pages (README)
  "pkg/photogrammetry_playground.js", // the JS API entry (docs/API.md, README)
  "pkg/examples.js", // the lighter JS API entry, one topic module per example (docs/API.md)
  "lab/pkg/photogrammetry_lab.js", // the lab module's API entry (docs/API.md)
  "version.json", // the build's version (sw-manifest.mjs)
  "assets.json", // this step's manifest
  "_headers", // read by the static host
];
const HASHED_EXT = /\.(m?js|wasm|css|json|woff2?|ttf|otf|eot|png|jpe?g|gif|webp|avif|svg|ico)$/i;
const COMPRESSIBLE = /\.(m?js|wasm|css|json|html|svg|txt|map)$/i;
const JS = /\.m?js$/i;
/**
 * An ES module: an import or export statement at the start of a line or after
 * `;` or `}` (minified code); a dynamic import() or import.meta alone is not one.
 */
const ES_MODULE = /(?:^|[;}])[ \t]*(?:import\s*[\w{*"'`]|export\s*[\w{*])/m;
/** A hashed name: stem.<8 hex>.ext */
export const HASHED_NAME = /\.[0-9a-f]{8}\.[A-Za-z0-9]+$/;
/** Classic scripts up to this size are inlined into the HTML (one request fewer before first paint). */
const INLINE_MAX = 2048;
export const IMMUTABLE = "public, max-age=31536000, immutable";
export const REVALIDATE = "no-cache";

const posix = (p) => p.split(path.sep).join("/");

function walk(dir, root = dir) {
  return fs.readdirSync(dir, { withFileTypes: true }).flatMap((d) => {
    const p = path.join(dir, d.name);
    return d.isDirectory() ? walk(p, root) : [posix(path.relative(root, p))];
  });
}

/** The content hash of a name: the first 8 hex digits of its SHA-256. */
export function contentHash(bytes) {
  return crypto.createHash("sha256").update(bytes).digest("hex").slice(0, 8);
}

export function hashedName(file, bytes) {
  const dir = path.posix.dirname(file);
  const base = path.posix.basename(file);
  const dot = base.lastIndexOf(".");
  const name = `${base.slice(0, dot)}.${contentHash(bytes)}${base.slice(dot)}`;
  return dir === "." ? name : `${dir}/${name}`;
}

/**
 * Resolves a reference written in `from` (a dist-relative path) to a file of
 * `files`, or null: relative to the file's folder first (import specifiers,
 * `new URL(x, import.meta.url)`, CSS), else to the site's root (strings a
 * module hands to the document: `script.src = "./vendor/…"`).
 */
export function resolveRef(from, ref, files) {
  if (!ref || /^[a-z][a-z0-9+.-]*:/i.test(ref) || ref.startsWith("//") || ref.startsWith("#")) return null;
  const clean = ref.replace(/[?#].*$/, "");
  if (!clean || clean.endsWith("/")) return null;
  const dir = path.posix.dirname(from);
  const candidates = clean.startsWith("/") ? [clean.slice(1)] : [path.posix.join(dir, clean), path.posix.normalize(clean)];
  for (const c of candidates) if (!c.startsWith("..") && files.has(c)) return c;
  return null;
}

/** A quoted string that looks like a file path ("./a/b.js", 'x_bg.wasm', `../c.css`). */
const JS_LITERAL = /(["'`])((?:\.{1,2}\/|\/)?[\w@~.-]+(?:\/[\w@~.-]+)*\.[A-Za-z0-9]+)\1/g;
const IMPORT_BEFORE = /(?:\bfrom|\bimport|\bimport\s*\()\s*$/;
const WORKER_BEFORE = /\bnew\s+(?:Shared)?Worker\s*\(\s*(?:new\s+URL\s*\(\s*)?$/;

/** The references of a JS file: { start, end, ref, kind: "import" | "url", worker }. */
export function jsRefs(source) {
  const refs = [];
  for (const m of source.matchAll(JS_LITERAL)) {
    const before = source.slice(Math.max(0, m.index - 60), m.index);
    refs.push({
      start: m.index + 1,
      end: m.index + 1 + m[2].length,
      ref: m[2],
      kind: IMPORT_BEFORE.test(before) ? "import" : "url",
      worker: WORKER_BEFORE.test(before),
    });
  }
  return refs;
}

/** The url(…) and @import references of a CSS file. */
export function cssRefs(source) {
  const refs = [];
  const re = /url\(\s*(["']?)([^"')\s]+)\1\s*\)|@import\s+(["'])([^"']+)\3/g;
  for (const m of source.matchAll(re)) {
    const ref = m[2] ?? m[4];
    const start = m.index + m[0].indexOf(ref);
    refs.push({ start, end: start + ref.length, ref, kind: "url" });
  }
  return refs;
}

/** The src/href attributes of an HTML file. */
export function htmlRefs(source) {
  const refs = [];
  for (const m of source.matchAll(/\s(?:src|href)\s*=\s*(["'])([^"']+)\1/g)) {
    const start = m.index + m[0].lastIndexOf(m[2]);
    refs.push({ start, end: start + m[2].length, ref: m[2], kind: "url" });
  }
  return refs;
}

/**
 * Every @font-face shows text at once in a fallback font (font-display:
 * swap), and lists only the font files the build ships (KaTeX names .woff
 * and .ttf beside the .woff2 that every current browser takes).
 */
export function fontFaces(f, css, files) {
  return css.replace(/@font-face\s*\{[^}]*\}/g, (face) => {
    let out = /font-display\s*:/.test(face) ? face.replace(/font-display\s*:\s*[a-z]+/, "font-display:swap") : face.replace("{", "{font-display:swap;");
    out = out.replace(/(src\s*:\s*)([^;}]*)/, (all, head, list) => {
      const sources = list.split(/,(?=\s*(?:url|local)\()/);
      const kept = sources.filter((s) => {
        const m = /url\(\s*["']?([^"')\s]+)/.exec(s);
        return !m || resolveRef(f, m[1], files);
      });
      return head + (kept.length ? kept : sources).join(",");
    });
    return out;
  });
}

function rewrite(source, refs, replace) {
  let out = "";
  let at = 0;
  for (const r of [...refs].sort((a, b) => a.start - b.start)) {
    const next = replace(r);
    if (next === null) continue;
    out += source.slice(at, r.start) + next;
    at = r.end;
  }
  return out + source.slice(at);
}

/** `ref` with its last path segment replaced by the basename of `target`. */
function retarget(ref, target) {
  const m = /^(.*?)([^/?#]*)([?#].*)?$/.exec(ref);
  return m[1] + path.posix.basename(target) + (m[3] ?? "");
}

const sha256 = (text) => `'sha256-${crypto.createHash("sha256").update(text, "utf8").digest("base64")}'`;

/** Topological order (leaves first) of `nodes` under `edges` (node → targets); throws on a cycle. */
function leavesFirst(nodes, edges) {
  const order = [];
  const state = new Map();
  const visit = (n, trail) => {
    if (state.get(n) === 2) return;
    if (state.get(n) === 1) {
      const cycle = [...trail.slice(trail.indexOf(n)), n];
      throw new Error(`assets: a cycle of literal references cannot be content-hashed: ${cycle.join(" → ")}`);
    }
    state.set(n, 1);
    for (const t of edges.get(n) ?? []) visit(t, [...trail, n]);
    state.set(n, 2);
    order.push(n);
  };
  for (const n of nodes) visit(n, []);
  return order;
}

/** Replaces `<!-- include: x -->` in every HTML file, then removes the *.partial.html files. */
function includePartials(dist) {
  const files = walk(dist);
  for (const f of files.filter((f) => f.endsWith(".html") && !f.endsWith(".partial.html"))) {
    const file = path.join(dist, f);
    const source = fs.readFileSync(file, "utf8");
    const out = source.replace(/^([ \t]*)<!--\s*include:\s*(\S+)\s*-->[ \t]*\n?/gm, (all, indent, name) => {
      const part = path.join(path.dirname(file), name);
      if (!fs.existsSync(part)) throw new Error(`assets: ${f} includes ${name}, which does not exist`);
      return fs
        .readFileSync(part, "utf8")
        .split("\n")
        .map((l) => (l ? indent + l : l))
        .join("\n")
        .replace(/\n*$/, "\n");
    });
    if (out !== source) fs.writeFileSync(file, out);
  }
  for (const f of files.filter((f) => f.endsWith(".partial.html"))) fs.rmSync(path.join(dist, f));
}

export function hashAssets(dist) {
  // scripts/bundle.mjs: a bundle stands for the modules it re-exports (one instance on the page)
  const bundleFile = path.join(dist, ".bundle.json");
  const aliases = new Map();
  if (fs.existsSync(bundleFile)) {
    for (const [entry, names] of Object.entries(JSON.parse(fs.readFileSync(bundleFile, "utf8")))) for (const n of names) aliases.set(n, entry);
    fs.rmSync(bundleFile);
  }
  includePartials(dist);
  const all = walk(dist).filter((f) => !/\.(gz|br)$/.test(f));
  const files = new Set(all);
  const stable = new Set(STABLE.filter((f) => files.has(f)));
  const html = all.filter((f) => f.endsWith(".html"));
  const texts = new Map(); // file → source, for JS and CSS
  const refs = new Map(); // file → resolved references
  for (const f of all) {
    if (!JS.test(f) && !f.endsWith(".css")) continue;
    let source = fs.readFileSync(path.join(dist, f), "utf8");
    if (f.endsWith(".css")) source = fontFaces(f, source, files);
    texts.set(f, source);
    const found = (JS.test(f) ? jsRefs(source) : cssRefs(source))
      .map((r) => ({ ...r, target: resolveRef(f, r.ref, files) }))
      .filter((r) => r.target && r.target !== f);
    refs.set(f, found);
  }
  const htmlSources = new Map(html.map((f) => [f, fs.readFileSync(path.join(dist, f), "utf8")]));
  const named = new Set(); // files some literal, url() or attribute names
  for (const list of refs.values()) for (const r of list) named.add(r.target);
  for (const [f, s] of htmlSources) for (const r of htmlRefs(s)) {
    const t = resolveRef(f, r.ref, files);
    if (t) named.add(t);
  }
  // JS is reachable through the import map whatever the specifier; anything
  // else that nothing names is fetched by a computed URL and keeps its name
  const hashable = all.filter((f) => HASHED_EXT.test(f) && !stable.has(f) && !f.endsWith(".html") && (JS.test(f) || named.has(f)));
  const willHash = new Set(hashable);
  const keptNames = all.filter((f) => HASHED_EXT.test(f) && !stable.has(f) && !willHash.has(f) && !f.endsWith(".html"));

  // files that run without the page's import map: workers, the stable JS
  // entries (imported by other sites), and whatever they import
  const noMap = new Set();
  const queue = [...stable].filter((f) => JS.test(f));
  for (const list of refs.values()) for (const r of list) if (r.worker && JS.test(r.target)) queue.push(r.target);
  while (queue.length) {
    const f = queue.pop();
    if (noMap.has(f)) continue;
    noMap.add(f);
    for (const r of refs.get(f) ?? []) if (r.kind === "import") queue.push(r.target);
  }
  // such a file importing a computed specifier (a loader picking a module by
  // name) finds the modules of its folder under their logical names: those
  // keep a copy under that name beside the hashed one
  const keepLogical = new Set();
  for (const f of noMap) {
    if (!/\bimport\s*\(\s*(?:[^\s"'`)]|`[^`]*\$\{)/.test(texts.get(f) ?? "")) continue;
    const dir = path.posix.dirname(f);
    const near = all.filter((g) => JS.test(g) && (dir === "." ? !g.includes("/") : g.startsWith(`${dir}/`)) && !stable.has(g));
    for (const g of near) keepLogical.add(g);
    console.log(`assets: ${f} imports a computed specifier without the import map: ${near.length} modules of ${dir}/ keep a copy under their own name`);
  }
  const rewritten = (f, r) => willHash.has(r.target) && (r.kind === "url" || noMap.has(f));

  const edges = new Map();
  for (const [f, list] of refs) edges.set(f, [...new Set(list.filter((r) => rewritten(f, r)).map((r) => r.target))]);
  const order = leavesFirst([...texts.keys(), ...hashable], edges);

  const map = new Map(); // logical → hashed
  for (const f of order) {
    let bytes;
    if (texts.has(f)) {
      const out = rewrite(texts.get(f), refs.get(f), (r) => (rewritten(f, r) ? retarget(r.ref, map.get(r.target)) : null));
      bytes = Buffer.from(out, "utf8");
      if (stable.has(f) || !willHash.has(f)) fs.writeFileSync(path.join(dist, f), bytes);
    } else {
      bytes = fs.readFileSync(path.join(dist, f));
    }
    if (!willHash.has(f)) continue;
    const to = hashedName(f, bytes);
    fs.writeFileSync(path.join(dist, to), bytes);
    if (keepLogical.has(f)) fs.writeFileSync(path.join(dist, f), bytes);
    else fs.rmSync(path.join(dist, f));
    map.set(f, to);
  }
  // a stable ES module the page itself imports also gets a hashed copy: the
  // page's import map points at it (immutable), other sites keep the stable URL
  const pageNamed = new Set();
  for (const [f, list] of refs) if (!noMap.has(f)) for (const r of list) pageNamed.add(r.target);
  for (const s of htmlSources.values()) for (const r of htmlRefs(s)) pageNamed.add(resolveRef("index.html", r.ref, files));
  for (const f of stable) {
    if (!JS.test(f) || f === "sw.js" || !pageNamed.has(f)) continue;
    const bytes = fs.readFileSync(path.join(dist, f));
    if (!/^\s*(import|export)\b/m.test(bytes.toString("utf8"))) continue; // a classic script
    const to = hashedName(f, bytes);
    fs.writeFileSync(path.join(dist, to), bytes);
    map.set(f, to);
  }

  const now = new Set(walk(dist));
  for (const [f, source] of htmlSources) fs.writeFileSync(path.join(dist, f), buildHtml(dist, f, source, map, now, aliases));
  return { map, stable: [...stable], keptNames };
}

/** Whether a file is an ES module (classic scripts such as KaTeX's UMD build need no import map entry). */
function isModule(dist, file) {
  return JS.test(file) && ES_MODULE.test(fs.readFileSync(path.join(dist, file), "utf8"));
}

/** The static import graph of `entry` (logical names), entry excluded. */
function staticImports(dist, entry, map) {
  const seen = new Set();
  const queue = [entry];
  const files = new Set([...walk(dist), ...map.keys()]);
  while (queue.length) {
    const f = queue.pop();
    const onDisk = map.get(f) ?? f;
    if (!fs.existsSync(path.join(dist, onDisk))) continue;
    const source = fs.readFileSync(path.join(dist, onDisk), "utf8");
    // static imports only: `import … from "x"`, `import "x"`, `export … from "x"` (not import())
    for (const m of source.matchAll(/(?:^|[;\n}])\s*(?:import|export)\s*(?:[\w*{}\s,$]+?\s*from\s*)?(["'])([^"']+)\1/g)) {
      const t = resolveRef(f, m[2], files);
      if (t && !seen.has(t) && t !== entry) {
        seen.add(t);
        queue.push(t);
      }
    }
  }
  return [...seen];
}

/**
 * The page's data block (`<script type="application/json" id="catalog-data">`,
 * not executed: no CSP hash): `entries`, catalog.json itself (core.js reads it
 * here instead of fetching it: one request fewer before the first solution),
 * and `files`, each topic module's files under their hashed names — its
 * wasm-bindgen JS, its wasm and its figures (figures/<module>.js, when there
 * is one, and the modules it imports that are not in the page's bundle) —
 * which www/preload-route.js preloads for the example in the address.
 */
function catalogData(dist, map, rel, aliases) {
  const text = fs.readFileSync(path.join(dist, map.get("catalog.json") ?? "catalog.json"), "utf8");
  const entries = JSON.parse(text);
  const files = {};
  for (const e of entries) {
    if (!e.module || files[e.module]) continue;
    const wanted = [`pkg/${e.module}.js`, `pkg/${e.module}_bg.wasm`, `figures/${e.module}.js`];
    for (const w of wanted.slice(0, 2)) if (!map.has(w)) throw new Error(`assets: catalog-data: ${w} (module of ${e.id}) was not built`);
    // and what the figures import that the page's bundle is not (figures/resampling.js: figures/filters.js)
    if (map.has(wanted[2])) wanted.push(...staticImports(dist, wanted[2], map).filter((m) => !aliases.has(m) && m !== wanted[2]));
    files[e.module] = [...new Set(wanted)].filter((w) => map.has(w)).map(rel);
  }
  return dataBlock({ entries, files });
}

/** The data block of a built page: its element, and its JSON as group 1. */
export const DATA_BLOCK = /<script type="application\/json" id="catalog-data">([\s\S]*?)<\/script>/;

/** The data block for `data` (scripts/prerender.mjs adds to it, the tests read it with DATA_BLOCK). */
export function dataBlock(data) {
  const json = JSON.stringify(data);
  if (/<\/script|<!--/i.test(json)) throw new Error("assets: catalog-data: the data would end its script element");
  return `<script type="application/json" id="catalog-data">${json}</script>`;
}

/** The data of a built page's block (`html`: the page's text), or null when it has none. */
export function readDataBlock(html) {
  const m = DATA_BLOCK.exec(html);
  return m ? JSON.parse(m[1]) : null;
}

function buildHtml(dist, f, source, map, files, aliases = new Map()) {
  const rel = (logical) => {
    const hashed = map.get(logical) ?? logical;
    const from = path.posix.dirname(f);
    const r = path.posix.relative(from, hashed);
    return r.startsWith(".") ? r : `./${r}`;
  };
  const resolve = (ref) => resolveRef(f, ref, new Set([...files, ...map.keys()]));
  let out = source;
  // modulepreload links for the static graph of the module scripts (before rewriting)
  const entries = [...out.matchAll(/<script\b[^>]*type=["']module["'][^>]*\ssrc=["']([^"']+)["']/g)].map((m) => resolve(m[1])).filter(Boolean);
  out = out.replace(/^([ \t]*)<!--\s*modulepreload\s*-->[ \t]*\n/m, (all, indent) => {
    const listed = new Set([...out.matchAll(/rel=["']modulepreload["'][^>]*href=["']([^"']+)["']/g)].map((m) => resolve(m[1])));
    const graph = [...new Set(entries.flatMap((e) => staticImports(dist, e, map)))].filter((m) => !listed.has(m) && !entries.includes(m));
    return graph.map((m) => `${indent}<link rel="modulepreload" href="./${m}">\n`).join("");
  });
  out = out.replace(/^([ \t]*)<!--\s*catalog-data\s*-->[ \t]*\n/m, (all, indent) => `${indent}${catalogData(dist, map, rel, aliases)}\n`);
  // src/href → hashed names
  out = rewrite(out, htmlRefs(out), (r) => {
    const t = resolve(r.ref);
    if (!t) return null;
    if (!files.has(map.get(t) ?? t)) throw new Error(`assets: ${f} references ${r.ref}, which does not exist`);
    return map.has(t) ? retarget(r.ref, map.get(t)) : null;
  });
  const hashes = [];
  // small classic scripts inline
  out = out.replace(/<script src=["']([^"']+)["']><\/script>/g, (all, ref) => {
    const t = resolveRef(f, ref, files);
    if (!t || fs.statSync(path.join(dist, t)).size > INLINE_MAX) return all;
    // its leading comment lines stay in the file, not in every page
    const code = fs.readFileSync(path.join(dist, t), "utf8").replace(/^(\s*\/\/.*\n)+/, "").trim();
    if (code.includes("</script")) return all;
    hashes.push(sha256(code));
    return `<script>${code}</script>`;
  });
  // the import map, before any script: a module preloaded by preload-route.js must
  // resolve its imports (../format.js, ./draw.js) through it, whenever its response arrives
  const imports = {};
  for (const [logical, hashed] of [...map].sort()) if (isModule(dist, hashed) || logical.endsWith(".json")) imports[`./${logical}`] = rel(hashed);
  // a module bundled into the page's entry (scripts/bundle.mjs) is the bundle on the page
  for (const [logical, entry] of aliases) imports[`./${logical}`] = rel(map.get(entry) ?? entry);
  const json = JSON.stringify({ imports });
  hashes.push(sha256(json));
  if (!/<script\b[^>]*type=["']module["']/.test(out)) throw new Error(`assets: ${f} has no module script`);
  const first = /<script\b|<link\b[^>]*rel=["']modulepreload["']/.exec(out);
  const indent = /(?:^|\n)([ \t]*)$/.exec(out.slice(0, first.index));
  const tag = `<script type="importmap">${json}</script>`;
  out = out.slice(0, first.index) + (indent ? `${tag}\n${indent[1]}` : tag) + out.slice(first.index);
  // the CSP admits exactly these inline scripts
  let csp = false;
  out = out.replace(/(<meta http-equiv="Content-Security-Policy" content="[^"]*?script-src )([^;"]*)/i, (all, head, list) => {
    csp = true;
    return `${head}${list} ${hashes.join(" ")}`;
  });
  if (!csp && /Content-Security-Policy/i.test(out)) throw new Error(`assets: ${f}: no script-src in its CSP to admit the import map`);
  // the source's comments are for its readers, not for every first load
  return out.replace(/^[ \t]*<!--[\s\S]*?-->[ \t]*\n/gm, "");
}

/** dist/_headers: immutable for hashed names (a folder with nothing else: one rule), no-cache for the rest. */
export function headersFile(dist, map) {
  const hashed = new Set(map.values());
  const files = walk(dist).filter((f) => !/\.(gz|br)$/.test(f) && f !== "_headers");
  const dirs = new Set(files.map((f) => path.posix.dirname(f)).filter((d) => d !== "."));
  // the top-most folders whose every file is hashed
  const allHashed = [...dirs].filter((d) => files.filter((f) => f.startsWith(`${d}/`)).every((f) => hashed.has(f)));
  const folders = allHashed.filter((d) => !allHashed.some((o) => o !== d && d.startsWith(`${o}/`))).sort();
  // ... and those with none (prerender/: HTML, revalidated)
  const noneHashed = [...dirs].filter((d) => files.filter((f) => f.startsWith(`${d}/`)).every((f) => !hashed.has(f)));
  const plainFolders = noneHashed.filter((d) => !noneHashed.some((o) => o !== d && d.startsWith(`${o}/`))).sort();
  const inFolder = (f) => folders.some((d) => f.startsWith(`${d}/`));
  const inPlainFolder = (f) => plainFolders.some((d) => f.startsWith(`${d}/`));
  const lines = ["# Cache rules (scripts/assets.mjs): content-hashed names never change; everything else is revalidated.", ""];
  for (const d of folders) lines.push(`/${d}/*`, `  Cache-Control: ${IMMUTABLE}`);
  for (const f of [...hashed].filter((f) => !inFolder(f)).sort()) lines.push(`/${f}`, `  Cache-Control: ${IMMUTABLE}`);
  lines.push("/", `  Cache-Control: ${REVALIDATE}`);
  for (const d of plainFolders) lines.push(`/${d}/*`, `  Cache-Control: ${REVALIDATE}`);
  for (const f of files.filter((f) => !hashed.has(f) && !inFolder(f) && !inPlainFolder(f)).sort()) lines.push(`/${f}`, `  Cache-Control: ${REVALIDATE}`);
  const rules = lines.filter((l) => l.startsWith("/")).length;
  if (rules > 100) console.warn(`assets: _headers has ${rules} rules (Cloudflare Pages reads the first 100)`);
  fs.writeFileSync(path.join(dist, "_headers"), `${lines.join("\n")}\n`);
  return rules;
}

/** Not minified: code minified by its authors, and the service worker (sw-manifest.mjs writes into it at a comment). */
const NOT_MINIFIED = (f) => f.startsWith("vendor/") || f === "sw.js";

/** Strings and url(…) of a stylesheet, which minifyCss leaves as they are. */
const CSS_KEEP = /("(?:\\.|[^"\\])*"|'(?:\\.|[^'\\])*'|url\([^)]*\))/;

/** A stylesheet without comments and without the white space that separates nothing. */
export function minifyCss(css) {
  return css
    .replace(/\/\*[\s\S]*?\*\//g, "")
    .split(CSS_KEEP)
    .map((part, k) => (k % 2 ? part : part.replace(/\s+/g, " ").replace(/\s*([{};,>])\s*/g, "$1").replace(/:\s+/g, ":").replace(/;}/g, "}")))
    .join("")
    .trim();
}

/** Step 0: every JS (and CSS) file of dist/ minified in place; returns [files, bytes before, bytes after]. */
export async function minifyAll(dist) {
  let n = 0;
  let before = 0;
  let after = 0;
  for (const f of walk(dist)) {
    if (NOT_MINIFIED(f)) continue;
    const file = path.join(dist, f);
    if (/\.css$/i.test(f)) {
      const css = fs.readFileSync(file, "utf8");
      const out = `${minifyCss(css)}\n`;
      fs.writeFileSync(file, out);
      [n, before, after] = [n + 1, before + Buffer.byteLength(css), after + Buffer.byteLength(out)];
      continue;
    }
    if (!JS.test(f)) continue;
    const source = fs.readFileSync(file, "utf8");
    const module = ES_MODULE.test(source);
    let out;
    try {
      out = await minify(source, { module, ecma: 2020, compress: { passes: 2 }, mangle: true, format: { comments: false } });
    } catch (e) {
      throw new Error(`assets: ${f} could not be minified: ${e.message}${e.line ? ` (line ${e.line})` : ""}`);
    }
    fs.writeFileSync(file, `${out.code}\n`);
    n += 1;
    before += Buffer.byteLength(source);
    after += Buffer.byteLength(out.code) + 1;
  }
  return [n, before, after];
}

/** .gz and .br beside every compressible file. */
export function compressAll(dist) {
  let n = 0;
  for (const f of walk(dist)) {
    if (!COMPRESSIBLE.test(f)) continue;
    const file = path.join(dist, f);
    const bytes = fs.readFileSync(file);
    fs.writeFileSync(`${file}.gz`, zlib.gzipSync(bytes, { level: 9 }));
    fs.writeFileSync(
      `${file}.br`,
      zlib.brotliCompressSync(bytes, {
        params: {
          [zlib.constants.BROTLI_PARAM_QUALITY]: 11,
          [zlib.constants.BROTLI_PARAM_SIZE_HINT]: bytes.length,
          [zlib.constants.BROTLI_PARAM_MODE]: /\.wasm$/.test(f) ? zlib.constants.BROTLI_MODE_GENERIC : zlib.constants.BROTLI_MODE_TEXT,
        },
      }),
    );
    n += 1;
  }
  return n;
}

export { COMPRESSIBLE, HASHED_EXT };

if (process.argv[1] && fileURLToPath(import.meta.url) === path.resolve(process.argv[1])) {
  // two stages, so a step can run on the working site in between (scripts/build.sh:
  // scripts/prerender.mjs): `--stage names` minifies, hashes and writes the HTML;
  // `--stage finish` writes _headers, the service worker's list and the .gz/.br
  // copies of what is there then; no --stage does both
  const dist = path.resolve(process.argv.slice(2).find((a, i, all) => !a.startsWith("--") && all[i - 1] !== "--stage") || "dist");
  const stageAt = process.argv.indexOf("--stage");
  const stage = stageAt > 0 ? process.argv[stageAt + 1] : "all";
  if (!["names", "finish", "all"].includes(stage)) throw new Error(`assets: --stage names|finish, not ${stage}`);
  if (stage !== "finish") {
    const [minified, rawBefore, rawAfter] = await minifyAll(dist);
    console.log(`assets: ${minified} JS and CSS files minified (terser; minifyCss), ${(rawBefore / 1024).toFixed(0)} → ${(rawAfter / 1024).toFixed(0)} KB raw`);
    const { map, stable, keptNames } = hashAssets(dist);
    fs.writeFileSync(path.join(dist, "assets.json"), `${JSON.stringify(Object.fromEntries([...map].sort()), null, 1)}\n`);
    console.log(`assets: ${map.size} hashed names (dist/assets.json), ${stable.length} stable, ${keptNames.length} named only by computed URLs (kept: ${keptNames.join(", ") || "none"})`);
  }
  if (stage !== "names") {
    const map = new Map(Object.entries(JSON.parse(fs.readFileSync(path.join(dist, "assets.json"), "utf8"))));
    const rules = headersFile(dist, map);
    const sw = spawnSync(process.execPath, [path.join(path.dirname(fileURLToPath(import.meta.url)), "sw-manifest.mjs"), dist], { stdio: "inherit" });
    if (sw.status !== 0) process.exit(sw.status ?? 1);
    const n = compressAll(dist);
    console.log(`assets: _headers ${rules} rules; .gz + .br for ${n} files`);
  }
}
