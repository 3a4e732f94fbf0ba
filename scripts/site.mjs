// The static site from the staged sources (scripts/build.sh copies www/ and
// adds the generated wasm-bindgen packages and catalog.json), built by esbuild:
//   node scripts/site.mjs build STAGE DIST   bundle, split, minify, hash; the HTML
//   node scripts/site.mjs finish DIST        (after scripts/prerender.mjs) the service
//                                            worker's list, _headers, .gz/.br copies
//
// esbuild does the work: each page's module script and stylesheets are entry
// points, every import() a chunk of its own (topic modules, figures, KaTeX's
// typesetting, the lab, practice …), code two chunks share a shared chunk (one
// instance on the page), everything minified and named by its content under
// dist/assets/ (immutable), with the metafile as the manifest.
// What esbuild does not do, and this file does in a few lines each:
//  - `new URL("x", import.meta.url)` (wasm-bindgen's wasm, the lab's worker and
//    stylesheet, core.js's catalog.json: esbuild issue #795) becomes an import
//    of x that esbuild emits under a hashed name (a worker or a stylesheet is
//    built by esbuild first); a computed `new URL(`./dir/${…}`, …)` keeps
//    pointing at dir/, which is copied as it is (the lab's sample photos);
//  - the public entries keep their names (docs/API.md): pkg/examples.js,
//    pkg/photogrammetry_playground.js and lab/pkg/photogrammetry_lab.js
//    re-export their hashed builds;
//  - the HTML: its `<!-- include: x -->` partial, the hashed names, the small
//    classic scripts inlined (their sha256 in the CSP), modulepreload links for
//    the entry's chunks (from the metafile), and the catalog-data block;
//  - dist/assets.json (logical name → built file), the service worker's
//    precache list (www/sw.js), dist/_headers and the .gz/.br copies.
import * as esbuild from "esbuild";
import crypto from "node:crypto";
import fs from "node:fs";
import path from "node:path";
import zlib from "node:zlib";
import { fileURLToPath } from "node:url";
import { minify } from "terser";

/** Public URLs other sites import (docs/API.md): built, then re-exported under this name. */
export const STABLE_ENTRIES = ["pkg/examples.js", "pkg/photogrammetry_playground.js", "lab/pkg/photogrammetry_lab.js"];
/** Where every content-hashed file goes (one immutable folder). */
export const ASSETS = "assets";
/** Entries cached by the service worker when first used, not at install (the lab: about 1 MB; pkg/all: every example again). */
const LAZY_ENTRIES = ["lab/lab.js", "pkg/all.js"];
/** Classic scripts up to this size are inlined into the HTML (one request fewer before first paint). */
const INLINE_MAX = 4096;
export const IMMUTABLE = "public, max-age=31536000, immutable";
const COMPRESSIBLE = /\.(m?js|wasm|css|json|html|svg|txt|map)$/i;

const posix = (p) => p.split(path.sep).join("/");
function walk(dir, root = dir) {
  return fs.readdirSync(dir, { withFileTypes: true }).flatMap((d) => {
    const p = path.join(dir, d.name);
    return d.isDirectory() ? walk(p, root) : [posix(path.relative(root, p))];
  });
}
const sha256 = (text) => `'sha256-${crypto.createHash("sha256").update(text, "utf8").digest("base64")}'`;

/** The data block of a built page: its element, and its JSON as group 1. */
export const DATA_BLOCK = /<script type="application\/json" id="catalog-data">([\s\S]*?)<\/script>/;

/** The data block for `data` (scripts/prerender.mjs adds to it, the tests read it with DATA_BLOCK). */
export function dataBlock(data) {
  const json = JSON.stringify(data);
  if (/<\/script|<!--/i.test(json)) throw new Error("site: catalog-data: the data would end its script element");
  return `<script type="application/json" id="catalog-data">${json}</script>`;
}

/** The data of a built page's block (`html`: the page's text), or null when it has none. */
export function readDataBlock(html) {
  const m = DATA_BLOCK.exec(html);
  return m ? JSON.parse(m[1]) : null;
}

const COMMON = { bundle: true, minify: true, legalComments: "none", charset: "utf8", logLevel: "warning", metafile: true, write: false };
const NAMES = { entryNames: `${ASSETS}/[name]-[hash]`, chunkNames: `${ASSETS}/[name]-[hash]`, assetNames: `${ASSETS}/[name]-[hash]` };
const LITERAL = /(new\s+(?:Shared)?Worker\s*\(\s*)?new\s+URL\(\s*(["'`])([^"'`$]+)\2\s*,\s*import\.meta\.url\s*\)/g;
const FOLDER = /new\s+URL\(\s*`(\.{1,2}\/(?:[^`$]*\/)?)(?=[^`]*\$\{)/g;

/**
 * esbuild plugin: `new URL("x", import.meta.url)` → an import of x that
 * esbuild emits as a hashed file (its path from the output file that uses it);
 * a worker or stylesheet is first built itself (bundled, minified), then
 * emitted the same way. `built` collects the outputs of those inner builds.
 */
function metaUrl(stage, dist, built) {
  const innerBuilds = new Map();
  return {
    name: "meta-url",
    setup(b) {
      b.onLoad({ filter: /\.m?js$/ }, async (args) => {
        if (!args.path.startsWith(stage)) return null;
        const source = await fs.promises.readFile(args.path, "utf8");
        if (!source.includes("import.meta.url")) return null;
        const head = [];
        let out = source.replace(LITERAL, (all, worker, q, ref) => {
          if (/^[a-z]+:|^\//i.test(ref)) return all;
          const kind = worker ? "worker" : ref.endsWith(".css") ? "css" : "file";
          const name = `__metaUrl${head.length}`;
          head.push(`import ${name} from ${JSON.stringify(`${ref}?${kind}`)};`);
          return `${worker ?? ""}new URL(${name}, import.meta.url)`;
        });
        // a computed name under a folder of the site: that folder, from dist/assets/ (copied as it is)
        out = out.replace(FOLDER, (all, dir) => {
          const abs = path.resolve(path.dirname(args.path), dir);
          if (!fs.existsSync(abs)) throw new Error(`site: ${posix(path.relative(stage, args.path))} names files under ${dir}, which is not a folder of the site`);
          return `new URL(\`../${posix(path.relative(stage, abs))}/`;
        });
        return { contents: head.join("\n") + (head.length ? "\n" : "") + out, loader: "js" };
      });
      b.onResolve({ filter: /\?(file|css|worker)$/ }, (args) => {
        const [ref, kind] = args.path.split("?");
        const abs = path.resolve(args.resolveDir, ref);
        if (!fs.existsSync(abs)) return { errors: [{ text: `new URL("${ref}", import.meta.url): ${posix(path.relative(stage, abs))} does not exist` }] };
        return { path: abs, namespace: "meta-url", pluginData: kind };
      });
      b.onLoad({ filter: /.*/, namespace: "meta-url" }, async (args) => {
        if (args.pluginData === "file") return { contents: await fs.promises.readFile(args.path), loader: "file" };
        if (!innerBuilds.has(args.path)) innerBuilds.set(args.path, innerBuild(args.path, args.pluginData === "worker"));
        return { contents: await innerBuilds.get(args.path), loader: "file", resolveDir: path.dirname(args.path) };
      });
    },
  };

  /** A worker or stylesheet built by esbuild (its chunks and files written): the entry's bytes. */
  async function innerBuild(file, js) {
    const inner = await esbuild.build({
      ...COMMON,
      ...NAMES,
      entryPoints: [file],
      outdir: dist,
      outbase: stage,
      ...(js ? { format: "esm", splitting: true, plugins: [metaUrl(stage, dist, built)] } : { loader: { ".woff2": "file" } }),
    });
    const entry = Object.entries(inner.metafile.outputs).find(([, o]) => o.entryPoint)[0];
    let text = null;
    for (const f of inner.outputFiles) {
      const bytes = await squeeze(f);
      if (path.resolve(entry) === f.path) text = bytes;
      else writeFile(f.path, bytes);
    }
    delete inner.metafile.outputs[entry]; // emitted by the outer build, under its own hash
    built.push(inner.metafile);
    return text;
  }
}

/**
 * esbuild plugin: the page's static graph in one file. A module outside that graph (a figure,
 * the lab, practice …) importing one of it imports it through `import "<entry>"; export * from
 * "<module>"`: every module of the graph then has the same importers, so esbuild splits it into
 * one shared chunk (the entry itself a stub) instead of a chunk per set of importers (11 files
 * on the first load's critical path, each a request and a compile).
 */
function onePageChunk(entry, graph) {
  return {
    name: "one-page-chunk",
    setup(b) {
      b.onResolve({ filter: /^\.\.?\// }, (args) => {
        if (args.namespace !== "file" || graph.has(args.importer) || !/^(import-statement|dynamic-import)$/.test(args.kind)) return null;
        const target = path.resolve(args.resolveDir, args.path);
        // (one per importer: shared by two, it would be an empty chunk of its own)
        return graph.has(target) && target !== entry ? { path: `${target}?from=${args.importer}`, namespace: "page", pluginData: target } : null;
      });
      // the page's modules by name (see buildSite: `import("./core.js")` from a course page or a test)
      b.onResolve({ filter: /^page-module:/ }, (args) => ({ path: args.path.slice("page-module:".length), namespace: "page", pluginData: args.path.slice("page-module:".length) }));
      b.onLoad({ filter: /.*/, namespace: "page" }, (args) => ({
        contents: `import ${JSON.stringify(entry)};\nexport * from ${JSON.stringify(args.pluginData)};\n`,
        resolveDir: path.dirname(args.pluginData),
        loader: "js",
      }));
    },
  };
}

/** The modules `entry` imports statically (absolute paths, `entry` included). */
async function staticModules(entry) {
  const external = { name: "dynamic", setup: (b) => b.onResolve({ filter: /.*/ }, (a) => (a.kind === "dynamic-import" ? { path: a.path, external: true } : null)) };
  const r = await esbuild.build({ entryPoints: [entry], bundle: true, write: false, metafile: true, format: "esm", logLevel: "silent", plugins: [external] });
  return new Set(Object.keys(r.metafile.inputs).map((i) => path.resolve(i)));
}

/**
 * esbuild's JS output, compressed further by terser (two passes): about 4 % fewer gzipped
 * bytes than esbuild's own minifier (ncc-1d's page chunk: 27.5 → 26.3 KB gz), which alone
 * made the first load's JS bigger than the build before it. Names stay esbuild's (a hash
 * of what terser reads: the same esbuild output always gives the same bytes).
 */
async function squeeze(file) {
  if (!file.path.endsWith(".js")) return file.contents;
  const out = await minify(file.text, { module: true, ecma: 2020, compress: { passes: 2 }, mangle: true, format: { comments: false } });
  return Buffer.from(`${out.code}\n`);
}

function writeFile(file, bytes) {
  fs.mkdirSync(path.dirname(file), { recursive: true });
  fs.writeFileSync(file, bytes);
}

/** `<!-- include: x -->` → the file x beside the page (one <head> for index.html and embed.html). */
function includePartials(file) {
  return fs.readFileSync(file, "utf8").replace(/^([ \t]*)<!--\s*include:\s*(\S+)\s*-->[ \t]*\n?/gm, (all, indent, name) => {
    const part = path.join(path.dirname(file), name);
    if (!fs.existsSync(part)) throw new Error(`site: ${path.basename(file)} includes ${name}, which does not exist`);
    return fs.readFileSync(part, "utf8").replace(/\n*$/, "\n").replace(/^(?=.)/gm, indent);
  });
}

/** What a page loads: module scripts, stylesheets and classic scripts, as site paths. */
function pageRefs(html) {
  const all = (re) => [...html.matchAll(re)].map((m) => m[1].replace(/^\.\//, ""));
  return {
    modules: all(/<script\b[^>]*type="module"[^>]*\ssrc="([^"]+)"/g),
    styles: all(/<link rel="stylesheet" href="([^"]+)"/g),
    classic: all(/<script src="([^"]+)"><\/script>/g),
  };
}

/** Every output of the build (outer and inner) by its dist path: { imports, exports, entryPoint, inputs }. */
function outputsOf(metafiles, dist) {
  const rel = (p) => posix(path.relative(dist, path.resolve(p)));
  const outputs = new Map();
  for (const meta of metafiles) {
    for (const [file, o] of Object.entries(meta.outputs)) outputs.set(rel(file), { ...o, imports: o.imports.map((i) => ({ ...i, path: rel(i.path) })) });
  }
  return outputs;
}

/** Logical (site) name → built file: entries, chunks of an import(), emitted files. */
function manifestOf(outputs, stage) {
  const map = {};
  for (const [file, o] of outputs) {
    // an entry or import() target, or a file esbuild emitted (wasm, fonts, a worker, catalog.json)
    const inputs = Object.keys(o.inputs);
    const source = o.entryPoint ?? (inputs.length === 1 && (!file.endsWith(".js") || inputs[0].startsWith("meta-url:")) ? inputs[0] : null);
    if (!source) continue;
    const logical = posix(path.relative(stage, path.resolve(source.replace(/^[a-z-]+:/, ""))));
    if (!logical.startsWith("..")) map[logical] ??= file;
  }
  return map;
}

/** The static imports of `file` (built names), transitively, `file` excluded. */
function staticGraph(outputs, file) {
  const seen = new Set();
  const queue = [file];
  while (queue.length) {
    for (const i of outputs.get(queue.pop())?.imports ?? []) {
      if (i.kind !== "import-statement" || seen.has(i.path)) continue;
      seen.add(i.path);
      queue.push(i.path);
    }
  }
  return seen;
}

export async function buildSite(stage, dist) {
  stage = path.resolve(stage);
  dist = path.resolve(dist);
  const pages = fs.readdirSync(stage).filter((f) => f.endsWith(".html") && !f.endsWith(".partial.html"));
  const html = new Map(pages.map((p) => [p, includePartials(path.join(stage, p))]));
  const refs = new Map([...html].map(([p, h]) => [p, pageRefs(h)]));
  const entries = [...new Set([...refs.values()].flatMap((r) => [...r.modules, ...r.styles]))];
  const stable = STABLE_ENTRIES.filter((f) => fs.existsSync(path.join(stage, f)));
  const modules = [...new Set([...refs.values()].flatMap((r) => r.modules))];
  if (modules.length !== 1) throw new Error(`site: the pages load ${modules.length} module scripts (${modules.join(", ")}); one is their entry`);
  const entry = path.join(stage, modules[0]);
  const inner = [];
  const options = { ...COMMON, ...NAMES, outdir: dist, outbase: stage, format: "esm", splitting: true, loader: { ".woff2": "file", ".wasm": "file" } };
  // the pages (each of the page's own modules also by its name, through an entry that re-exports
  // it: see "modules by name" below), then apart (they must not import the page's entry) the public entries
  const graph = await staticModules(entry);
  const named = [...graph].filter((f) => f !== entry && f.startsWith(stage + path.sep) && /\.m?js$/.test(f));
  const entryPoints = [...entries.map((f) => path.join(stage, f)), ...named.map((f) => ({ in: `page-module:${f}`, out: posix(path.relative(stage, f)).replace(/\.m?js$/, "") }))];
  const page = await esbuild.build({ ...options, entryPoints, plugins: [onePageChunk(entry, graph), metaUrl(stage, dist, inner)] });
  const api = await esbuild.build({ ...options, entryPoints: stable.map((f) => path.join(stage, f)), plugins: [metaUrl(stage, dist, inner)] });
  for (const f of [...page.outputFiles, ...api.outputFiles]) writeFile(f.path, await squeeze(f));
  const outputs = outputsOf([page.metafile, api.metafile, ...inner], dist);
  const map = manifestOf(outputs, stage);
  // the entry is a stub importing the one chunk that holds the page's code: the page loads that chunk
  const stub = outputs.get(map[modules[0]]);
  if (stub.imports.length === 1 && stub.exports.length === 0 && stub.bytes < 64) {
    fs.rmSync(path.join(dist, map[modules[0]]));
    outputs.delete(map[modules[0]]);
    map[modules[0]] = stub.imports[0].path;
  }

  /** dist/<logical>: a module re-exporting its build (the same module instance), under a fixed name. */
  const reexport = (logical) => {
    const spec = JSON.stringify(posix(path.relative(path.dirname(logical), map[logical])).replace(/^(?!\.)/, "./"));
    const lines = [`export * from ${spec};`];
    if (outputs.get(map[logical]).exports.includes("default")) lines.push(`export { default } from ${spec};`);
    writeFile(path.join(dist, logical), `${lines.join("\n")}\n`);
  };
  // the public entries under their own names
  for (const f of stable) {
    reexport(f);
    delete map[f];
  }

  // classic scripts at fixed URLs: the service worker (its list is written by `finish`) and
  // the course pages' embed.js (minified)
  fs.copyFileSync(path.join(stage, "sw.js"), path.join(dist, "sw.js"));
  const embed = await esbuild.transform(fs.readFileSync(path.join(stage, "embed.js"), "utf8"), { minify: true, legalComments: "none", charset: "utf8" });
  fs.writeFileSync(path.join(dist, "embed.js"), embed.code);
  // modules by name: a page module or an import() target at its own path, re-exporting its
  // build (one instance with the page's): what course pages and the tests import by name
  // (`import("./figures/chains.js")`, `import("./lab/lab.js")`); the page itself never loads these
  const byName = [];
  for (const [logical, built] of Object.entries(map)) {
    if (!/\.m?js$/.test(logical) || logical === modules[0] || stable.includes(logical) || !outputs.get(built)?.exports.length) continue;
    byName.push(logical);
    reexport(logical);
  }

  // files no module imports (the lab's sample photos, vendor/: minified by their authors) as they are
  const used = new Set(Object.keys(map));
  for (const o of outputs.values()) for (const i of Object.keys(o.inputs)) used.add(posix(path.relative(stage, path.resolve(i.replace(/^[a-z-]+:/, "")).replace(/\?.*$/, ""))));
  for (const f of walk(stage)) {
    if (f.endsWith(".css") && !used.has(f) && !f.startsWith("vendor/")) {
      throw new Error(`site: ${f} is loaded by nothing the build sees: name it in a page's <link> or by new URL("…", import.meta.url) in the module that loads it`);
    }
    if (used.has(f) || (/\.(m?js|html|json)$/.test(f) && !f.startsWith("vendor/"))) continue;
    let bytes = fs.readFileSync(path.join(stage, f));
    // KaTeX's fonts: text shows at once in a fallback font; only the woff2 files are shipped
    if (f.endsWith(".css")) bytes = String(bytes).replace(/font-display:\s*block/g, "font-display:swap").replace(/,\s*url\([^)]*\.(?:woff|ttf)\)\s*format\("[a-z]+"\)/g, "");
    writeFile(path.join(dist, f), bytes);
  }

  const catalog = JSON.parse(fs.readFileSync(path.join(stage, "catalog.json"), "utf8"));
  for (const [page, source] of html) fs.writeFileSync(path.join(dist, page), await pageHtml(page, source, refs.get(page), { stage, map, outputs, catalog }));

  // what the service worker caches when first used: whatever only a lazy entry leads to
  const eager = new Set();
  const queue = [...refs.values()].flatMap((r) => [...r.modules, ...r.styles]).map((f) => map[f]);
  const lazyRoots = new Set(LAZY_ENTRIES.map((f) => map[f]).filter(Boolean));
  while (queue.length) {
    const f = queue.pop();
    if (eager.has(f) || lazyRoots.has(f)) continue;
    eager.add(f);
    for (const i of outputs.get(f)?.imports ?? []) queue.push(i.path);
  }
  const lazy = [...[...outputs.keys()].filter((f) => !eager.has(f)), ...byName];
  fs.writeFileSync(path.join(dist, "lms-files.json"), `${JSON.stringify(lmsFiles(dist, map, outputs))}\n`);

  fs.writeFileSync(path.join(dist, "assets.json"), `${JSON.stringify(Object.fromEntries(Object.entries(map).sort()), null, 1)}\n`);
  fs.writeFileSync(path.join(stage, "lazy.json"), `${JSON.stringify(lazy.sort())}\n`);
  console.log(`site: esbuild: ${entries.length} page entries + ${stable.length} public ones → ${outputs.size} files in ${ASSETS}/ (${inner.length} built apart: workers, stylesheets)`);
}

/**
 * What a practice package for an LMS (www/lms/, issue 33) copies from the site:
 * `common`, the page and every file it may load but the examples' wasm modules
 * and the lab (its JS chunks, stylesheets, KaTeX and its fonts, the QR code
 * maker), and for each topic module its practice build (`topics[module]`: the
 * wasm-bindgen JS and wasm). Written to dist/lms-files.json (a fixed name, read
 * when an instructor downloads a package).
 */
function lmsFiles(dist, map, outputs) {
  // everything the page's modules lead to (static and dynamic imports), stopping at the lab and
  // the wasm-bindgen modules (pkg/<topic>.js, pkg/all.js …): a package carries only its topics' own
  const reach = (roots, stop = new Set()) => {
    const seen = new Set();
    const queue = roots.filter(Boolean);
    while (queue.length) {
      const f = queue.pop();
      if (seen.has(f) || stop.has(f)) continue;
      seen.add(f);
      for (const i of outputs.get(f)?.imports ?? []) queue.push(i.path);
    }
    return seen;
  };
  const topicsOf = Object.keys(map).flatMap((l) => /^pkg\/([a-z]+)_practice\.js$/.exec(l)?.[1] ?? []);
  const isModule = (l) => l.startsWith("pkg/") || l.startsWith("lab/");
  const stop = new Set(Object.entries(map).filter(([l]) => isModule(l)).map(([, b]) => b));
  const pageRoots = Object.entries(map).filter(([l]) => !isModule(l)).map(([, b]) => b);
  const page = [...reach(pageRoots, stop)].filter((f) => !f.endsWith(".wasm"));
  const vendor = walk(path.join(dist, "vendor")).map((f) => `vendor/${f}`).filter((f) => !/\.(gz|br)$/.test(f));
  const topics = {};
  for (const t of topicsOf) topics[t] = [...reach([map[`pkg/${t}_practice.js`]])].filter((f) => !page.includes(f)).sort();
  return { page: "index.html", common: ["index.html", ...page.sort(), ...vendor.sort()], topics };
}

/** A page of dist/: hashed names, inline classic scripts, modulepreloads, the catalog-data block, the CSP. */
async function pageHtml(page, source, refs, { stage, map, outputs, catalog }) {
  const built = (f) => {
    if (!map[f]) throw new Error(`site: ${page} loads ${f}, which the build did not make`);
    return `./${map[f]}`;
  };
  const hashes = [];
  let out = source;
  for (const f of refs.classic) {
    const code = (await esbuild.transform(fs.readFileSync(path.join(stage, f), "utf8"), { minify: true, legalComments: "none", charset: "utf8" })).code.trim();
    if (code.length > INLINE_MAX || code.includes("</script")) throw new Error(`site: ${page}: ${f} is too big to inline (${code.length} bytes; make it a module)`);
    hashes.push(sha256(code));
    out = out.replace(`<script src="./${f}"></script>`, () => `<script>${code}</script>`);
  }
  for (const f of [...refs.styles, ...refs.modules]) out = out.replace(new RegExp(`(href|src)="\\./${f.replace(/\./g, "\\.")}"`), (all, attr) => `${attr}="${built(f)}"`);
  // every chunk the page's modules import statically, fetched at once instead of one after the other
  const preload = [...new Set(refs.modules.flatMap((m) => [...staticGraph(outputs, map[m])]))];
  out = out.replace(/^([ \t]*)<!--\s*modulepreload\s*-->[ \t]*\n/m, (all, indent) => preload.map((f) => `${indent}<link rel="modulepreload" href="./${f}">\n`).join(""));
  // the catalog, and each topic's files (its wasm-bindgen JS and wasm, its figures and what
  // they import that the page has not), which www/preload-route.js starts for the address's example
  const pageStatic = new Set(refs.modules.flatMap((m) => [map[m], ...staticGraph(outputs, map[m])]));
  const files = {};
  for (const e of catalog) {
    if (!e.module || files[e.module]) continue;
    const own = [`pkg/${e.module}.js`, `pkg/${e.module}_bg.wasm`].map(built);
    const figures = map[`figures/${e.module}.js`];
    const more = figures ? [figures, ...staticGraph(outputs, figures)].filter((f) => !pageStatic.has(f)).map((f) => `./${f}`) : [];
    files[e.module] = [...own, ...more];
  }
  out = out.replace(/^([ \t]*)<!--\s*catalog-data\s*-->[ \t]*\n/m, (all, indent) => `${indent}${dataBlock({ entries: catalog, files })}\n`);
  let csp = false;
  out = out.replace(/(<meta http-equiv="Content-Security-Policy" content="[^"]*?script-src )([^;"]*)/i, (all, head, list) => {
    csp = true;
    return `${head}${list} ${hashes.join(" ")}`;
  });
  if (hashes.length && !csp) throw new Error(`site: ${page}: no script-src in its CSP to admit its inline scripts`);
  // the source's comments are for its readers, not for every first load
  return out.replace(/^[ \t]*<!--[\s\S]*?-->[ \t]*\n/gm, "");
}

/**
 * dist/_headers (Netlify, Cloudflare Pages): immutable for assets/, no-cache for the
 * rest, one rule per top-level file or folder (a host applies every rule that matches).
 */
function headersFile(dist) {
  const lines = ["# Cache rules (scripts/site.mjs): assets/ holds content-hashed names only; everything else is revalidated.", ""];
  lines.push(`/${ASSETS}/*`, `  Cache-Control: ${IMMUTABLE}`, "/", "  Cache-Control: no-cache");
  for (const d of fs.readdirSync(dist, { withFileTypes: true }).sort((a, b) => a.name.localeCompare(b.name))) {
    if (d.name === ASSETS || d.name === "_headers" || /\.(gz|br)$/.test(d.name)) continue;
    lines.push(d.isDirectory() ? `/${d.name}/*` : `/${d.name}`, "  Cache-Control: no-cache");
  }
  fs.writeFileSync(path.join(dist, "_headers"), `${lines.join("\n")}\n`);
}

/**
 * The service worker's list (www/sw.js, its BUILD line): the version (a hash of
 * every file's path and bytes: any change makes a new worker), the files cached
 * at install and those cached when first used (the lab, pkg/all, the saved answers).
 */
function serviceWorker(dist, lazyOutputs) {
  const files = walk(dist)
    .filter((f) => f !== "sw.js" && f !== "_headers" && f !== "assets.json" && !/\.(gz|br)$/.test(f))
    .sort();
  const hash = crypto.createHash("sha256");
  for (const f of files) hash.update(f).update("\0").update(fs.readFileSync(path.join(dist, f)));
  const version = hash.digest("hex").slice(0, 16);
  const lazySet = new Set(lazyOutputs);
  const isLazy = (f) => lazySet.has(f) || f.startsWith("lab/") || f.startsWith("prerender/");
  const file = path.join(dist, "sw.js");
  const source = fs.readFileSync(file, "utf8");
  const marker = /^const BUILD = \{ version: "dev", files: \[\] \};.*$/m;
  if (!marker.test(source)) throw new Error("site: the BUILD line of sw.js is missing");
  const line = `const BUILD = ${JSON.stringify({ version, files: ["./", ...files.filter((f) => !isLazy(f))], lazy: files.filter(isLazy) })};`;
  fs.writeFileSync(file, source.replace(marker, () => line));
  fs.writeFileSync(path.join(dist, "version.json"), `${JSON.stringify({ version, files: files.length })}\n`);
  return { version, files: files.length };
}

/** .gz and .br beside every compressible file. */
function compressAll(dist) {
  let n = 0;
  for (const f of walk(dist).filter((f) => COMPRESSIBLE.test(f))) {
    const file = path.join(dist, f);
    const bytes = fs.readFileSync(file);
    fs.writeFileSync(`${file}.gz`, zlib.gzipSync(bytes, { level: 9 }));
    const mode = f.endsWith(".wasm") ? zlib.constants.BROTLI_MODE_GENERIC : zlib.constants.BROTLI_MODE_TEXT;
    const params = { [zlib.constants.BROTLI_PARAM_QUALITY]: 11, [zlib.constants.BROTLI_PARAM_SIZE_HINT]: bytes.length, [zlib.constants.BROTLI_PARAM_MODE]: mode };
    fs.writeFileSync(`${file}.br`, zlib.brotliCompressSync(bytes, { params }));
    n += 1;
  }
  return n;
}

export function finishSite(stage, dist) {
  const { version, files } = serviceWorker(dist, JSON.parse(fs.readFileSync(path.join(stage, "lazy.json"), "utf8")));
  headersFile(dist);
  const n = compressAll(dist);
  console.log(`site: service worker ${version} (${files} files); _headers; .gz + .br for ${n} files`);
}

if (process.argv[1] && fileURLToPath(import.meta.url) === path.resolve(process.argv[1])) {
  const [command, stage, dist] = process.argv.slice(2);
  if (command === "build" && stage && dist) await buildSite(stage, dist);
  else if (command === "finish" && stage && dist) finishSite(stage, dist);
  else throw new Error("usage: node scripts/site.mjs build|finish STAGE DIST");
}
