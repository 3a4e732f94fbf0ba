// The page's modules in one file (issue 19). Before this step the first
// solution waited for 14 small ES modules (app.js and its static imports);
// each module costs a request and its own compile/link before the page can run.
// Run by scripts/build.sh over dist/, before scripts/assets.mjs:
//   node scripts/bundle.mjs [dist]
//
// What it does (esbuild, bundling only: terser minifies later, assets.mjs hashes):
//  1. The module scripts of the pages (`<script type="module" src>` in dist/*.html:
//     app.js) are bundled with their whole static import graph into the
//     entry's own file. Dynamic import() stays a separate file (the topic
//     modules, their figures, KaTeX's typesetting, the lab, practice, …).
//  2. A module of that graph that some other file of dist/ also imports (the
//     lab imports dom.js, practice core.js and math.js, a topic's figures
//     draw.js and format.js, …) must still be ONE instance on the page (math.js
//     holds KaTeX's state, embed-bridge.js the host's origin): the bundle
//     re-exports its exports, and the page's import map (assets.mjs, from
//     dist/.bundle.json) points that module's name at the bundle. Its own file
//     stays for what runs without the import map (workers, the public API
//     entries). Two such modules exporting the same name fail the build.
//  3. Graph modules nothing else imports are removed from dist/.
// It writes dist/.bundle.json: { "app.js": ["core.js", "dom.js", …] } (entry →
// the modules it stands for), which assets.mjs reads and removes.
import * as esbuild from "esbuild";
import fs from "node:fs";
import path from "node:path";

const dist = path.resolve(process.argv[2] || "dist");
const posix = (p) => p.split(path.sep).join("/");
const relTo = (abs) => posix(path.relative(dist, abs));

function walk(dir) {
  return fs.readdirSync(dir, { withFileTypes: true }).flatMap((d) => {
    const p = path.join(dir, d.name);
    return d.isDirectory() ? walk(p) : [relTo(p)];
  });
}

/** Import specifiers of a module, static and dynamic, with esbuild's own parser. */
async function importsOf(file) {
  const result = await esbuild.build({
    entryPoints: [path.join(dist, file)],
    bundle: true,
    write: false,
    metafile: true,
    format: "esm",
    logLevel: "silent",
    plugins: [{ name: "list", setup: (b) => b.onResolve({ filter: /.*/ }, (a) => (a.kind === "entry-point" ? null : { path: a.path, external: true })) }],
  });
  const input = Object.values(result.metafile.inputs)[0];
  return (input?.imports ?? []).map((i) => ({ path: i.path, kind: i.kind }));
}

/** The names a module exports (esbuild's metafile of the module alone). */
async function exportsOf(file) {
  const result = await esbuild.build({ entryPoints: [path.join(dist, file)], bundle: false, write: false, metafile: true, format: "esm", logLevel: "silent" });
  return Object.values(result.metafile.outputs)[0].exports;
}

const html = walk(dist).filter((f) => f.endsWith(".html"));
const entries = [
  ...new Set(
    html.flatMap((f) =>
      [...fs.readFileSync(path.join(dist, f), "utf8").matchAll(/<script\b[^>]*type=["']module["'][^>]*\ssrc=["']([^"']+)["']/g)].map((m) => relTo(path.resolve(dist, path.dirname(f), m[1]))),
    ),
  ),
];
const jsFiles = walk(dist).filter((f) => /\.m?js$/.test(f) && !f.startsWith("vendor/"));
const manifest = {};

for (const entry of entries) {
  // the static graph, as esbuild sees it (dynamic imports and files outside dist/ stay out)
  const graph = new Set();
  const external = (a) => {
    const abs = path.resolve(a.resolveDir, a.path);
    // a dynamic import keeps its target a separate file, named from the bundle's directory
    let spec = posix(path.relative(path.dirname(path.join(dist, entry)), abs));
    if (!spec.startsWith(".")) spec = `./${spec}`;
    return { path: spec, external: true };
  };
  const collect = { name: "graph", setup: (b) => b.onResolve({ filter: /.*/ }, (a) => {
    if (a.kind === "entry-point") return null;
    if (a.kind === "dynamic-import") return external(a);
    graph.add(relTo(path.resolve(a.resolveDir, a.path)));
    return null;
  }) };
  await esbuild.build({ entryPoints: [path.join(dist, entry)], bundle: true, write: false, format: "esm", logLevel: "silent", plugins: [collect] });

  // graph modules that something outside the graph also imports (statically or not)
  const shared = new Set();
  for (const f of jsFiles) {
    if (f === entry || graph.has(f)) continue;
    for (const i of await importsOf(f)) {
      if (!i.path.startsWith(".")) continue;
      const target = relTo(path.resolve(dist, path.dirname(f), i.path));
      if (graph.has(target)) shared.add(target);
    }
  }
  for (const f of graph) {
    // a graph module imported dynamically by another graph module: also by its name
    for (const i of await importsOf(f)) {
      if (i.kind !== "dynamic-import" || !i.path.startsWith(".")) continue;
      const target = relTo(path.resolve(dist, path.dirname(f), i.path));
      if (graph.has(target) || target === entry) shared.add(target);
    }
  }

  const owner = new Map();
  const lines = [`export * from "./${path.basename(entry)}";`];
  for (const n of await exportsOf(entry)) owner.set(n, entry);
  for (const f of [...shared].sort()) {
    const names = await exportsOf(f);
    for (const n of names) {
      if (owner.has(n)) throw new Error(`bundle: ${owner.get(n)} and ${f} both export "${n}"; the bundle of ${entry} stands for both (rename one)`);
      owner.set(n, f);
    }
    let spec = posix(path.relative(path.dirname(entry), f));
    if (!spec.startsWith(".")) spec = `./${spec}`;
    if (names.length) lines.push(`export { ${names.join(", ")} } from "${spec}";`);
  }
  const result = await esbuild.build({
    stdin: { contents: lines.join("\n"), resolveDir: path.dirname(path.join(dist, entry)), sourcefile: `${entry} (bundle)`, loader: "js" },
    bundle: true,
    write: false,
    format: "esm",
    charset: "utf8",
    legalComments: "none",
    logLevel: "warning",
    plugins: [{ name: "split", setup: (b) => b.onResolve({ filter: /.*/ }, (a) => (a.kind === "dynamic-import" ? external(a) : null)) }],
  });
  fs.writeFileSync(path.join(dist, entry), result.outputFiles[0].text);
  for (const f of graph) if (!shared.has(f)) fs.rmSync(path.join(dist, f));
  manifest[entry] = [...shared].sort();
  console.log(`bundle: ${entry} = ${graph.size + 1} modules in one file (${(result.outputFiles[0].text.length / 1024).toFixed(0)} KB raw); it stands for ${shared.size} that other files import too (${[...shared].sort().join(", ")}); ${graph.size - shared.size} removed`);
}
fs.writeFileSync(path.join(dist, ".bundle.json"), `${JSON.stringify(manifest, null, 1)}\n`);
