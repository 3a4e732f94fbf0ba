// Issue 30, item 4: layers that point one way.
//
// The page (www/**/*.js, not www/vendor): the import graph of its modules —
// static imports, `export … from` and dynamic import() — read by esbuild's
// own parser (a bundle with a metafile, nothing written), has no cycle.
//
// The Rust core crate (src/**/*.rs): a module's edges are its mentions of
// `crate::a::b…`, `super::…` and `self::…` paths in code (not comments,
// strings or #[cfg(test)] items). The layers, lowest first:
//   core      every module under src/ but examples/, practice/ and wasm.rs
//   examples  src/examples/**
//   practice  src/practice/**
//   wasm      src/wasm.rs
// No layer mentions a higher one, and no two sibling modules (children of
// the same parent, each with everything under it) mention each other, round
// a cycle of any length.
import { describe, it } from "node:test";
import assert from "node:assert/strict";
import fs from "node:fs";
import path from "node:path";
import { lexRust, read, ROOT, sourceFiles, withoutTestItems } from "./rules-lib.mjs";
import { site } from "./site.mjs";

/** The layers of the core crate, lowest first. */
export const LAYERS = ["core", "examples", "practice", "wasm"];

/** The strongly connected components of more than one node (Tarjan), each sorted. */
export function cycles(graph) {
  let index = 0;
  const stack = [];
  const on = new Set();
  const idx = new Map();
  const low = new Map();
  const out = [];
  const visit = (v) => {
    idx.set(v, index);
    low.set(v, index++);
    stack.push(v);
    on.add(v);
    for (const w of graph.get(v) ?? []) {
      if (!idx.has(w)) {
        visit(w);
        low.set(v, Math.min(low.get(v), low.get(w)));
      } else if (on.has(w)) low.set(v, Math.min(low.get(v), idx.get(w)));
    }
    if (low.get(v) === idx.get(v)) {
      const comp = [];
      let w;
      do {
        w = stack.pop();
        on.delete(w);
        comp.push(w);
      } while (w !== v);
      if (comp.length > 1) out.push(comp.sort());
    }
  };
  for (const v of [...graph.keys()].sort()) if (!idx.has(v)) visit(v);
  return out.sort((a, b) => a[0].localeCompare(b[0]));
}

/**
 * The page's import graph: file → Map(imported file → kinds), paths from
 * `base` (the repository root; a test's folder). Imports of files that do not
 * exist (pkg/*.js, made by the build), of vendor/ and outside `dir` are left out.
 */
export async function jsImportGraph(base = ROOT, dir = "www") {
  const esbuild = await import("esbuild");
  const entryPoints = (base === ROOT ? sourceFiles([dir], [".js"]) : fs.readdirSync(path.join(base, dir), { recursive: true }).filter((f) => f.endsWith(".js")).map((f) => path.join(dir, f))).map((f) => path.join(base, f));
  const external = {
    name: "external-missing",
    setup(build) {
      // what the build makes (pkg/*.js) or another host serves is not a source file
      build.onResolve({ filter: /.*/ }, (args) => {
        if (args.kind === "entry-point") return undefined;
        if (!/^\.{0,2}\//.test(args.path)) return { path: args.path, external: true };
        const target = path.resolve(args.resolveDir, args.path);
        if (!fs.existsSync(target)) return { path: args.path, external: true };
        if (!target.startsWith(path.join(base, dir) + path.sep) || target.includes(`${path.sep}vendor${path.sep}`)) return { path: args.path, external: true };
        return undefined;
      });
    },
  };
  const result = await esbuild.build({
    entryPoints,
    bundle: true,
    write: false,
    metafile: true,
    format: "esm",
    splitting: true,
    outdir: path.join(base, "target", "rules-layers"),
    absWorkingDir: base,
    logLevel: "silent",
    plugins: [external],
    loader: { ".css": "empty", ".html": "empty", ".json": "json" },
  });
  const graph = new Map();
  for (const [file, info] of Object.entries(result.metafile.inputs)) {
    const from = file.split(path.sep).join("/");
    const edges = new Map();
    for (const imp of info.imports) {
      if (imp.external) continue;
      const to = imp.path.split(path.sep).join("/");
      edges.set(to, [...(edges.get(to) ?? []), imp.kind]);
    }
    graph.set(from, edges);
  }
  return graph;
}

/** The module path (["examples", "projection"]) of a source file of the core crate. */
export function modulePath(file) {
  const parts = file.replace(/^src\//, "").replace(/\.rs$/, "").split("/");
  if (parts[parts.length - 1] === "mod") parts.pop();
  if (parts.length === 1 && parts[0] === "lib") return [];
  return parts;
}

/**
 * The core crate's module graph: { modules, edges: [{ from, to, line }] }, modules
 * as "a::b" strings ("" for the crate root), an edge for every path mention that
 * resolves to another module (the longest module prefix of the path).
 */
export function rustModuleGraph() {
  const files = sourceFiles(["src"], [".rs"]);
  const modules = new Map(files.map((f) => [modulePath(f).join("::"), f]));
  const resolve = (segments) => {
    for (let k = segments.length; k >= 0; k--) {
      const name = segments.slice(0, k).join("::");
      if (modules.has(name)) return name;
    }
    return "";
  };
  const edges = [];
  for (const file of files) {
    const here = modulePath(file);
    const text = withoutTestItems(lexRust(read(file)).bare);
    const add = (segments, index) => {
      const to = resolve(segments);
      const from = here.join("::");
      if (to !== from) edges.push({ from, to, file, line: text.slice(0, index).split("\n").length });
    };
    // paths: (crate|$crate|super|self)::ident::ident…, and grouped uses: crate::a::{b, c::d}
    const re = /(?<![\w$])(\$?crate|super|self)((?:\s*::\s*(?:super|[A-Za-z_]\w*))*)(\s*::\s*\{)?/g;
    let m;
    while ((m = re.exec(text))) {
      const head = m[1].replace("$", "");
      const rest = m[2].split("::").map((s) => s.trim()).filter(Boolean);
      if (head === "self" && !rest.length) continue;
      let base = head === "crate" ? [] : head === "super" ? here.slice(0, -1) : [...here];
      const segments = [...base];
      for (const s of rest) {
        if (s === "super") segments.pop();
        else segments.push(s);
      }
      if (m[3]) {
        // crate::a::{b, c::d, self}: one path per item (one level of braces)
        const open = m.index + m[0].length - 1;
        const close = text.indexOf("}", open);
        for (const item of text.slice(open + 1, close).split(",")) {
          const parts = item.trim().split(/\s*::\s*/).filter((p) => p && p !== "self" && p !== "{");
          add([...segments, ...parts.map((p) => p.replace(/[^\w].*$/, ""))], m.index);
        }
      } else if (head !== "self" || rest.length) add(segments, m.index);
    }
  }
  return { modules: [...modules.keys()], edges };
}

/** The layer of a module path string. */
export function layerOf(module) {
  const top = module.split("::")[0];
  if (top === "examples" || top === "practice" || top === "wasm") return top;
  return "core";
}

/** Mentions of a higher layer: ["src/x.rs:12 core → crate::examples (examples)", …]. */
export function layerViolations({ edges }) {
  const found = edges
    .filter((e) => e.to !== "" && LAYERS.indexOf(layerOf(e.to)) > LAYERS.indexOf(layerOf(e.from)))
    .map((e) => `${e.file}:${e.line} ${e.from || "crate"} (${layerOf(e.from)}) mentions ${e.to} (${layerOf(e.to)})`);
  return [...new Set(found)];
}

/**
 * Cycles among sibling modules: for every parent, its children (each standing
 * for itself and everything under it) and the edges between them.
 */
export function siblingCycles({ modules, edges }) {
  const parents = new Set(modules.map((m) => m.split("::").slice(0, -1).join("::")));
  const out = [];
  for (const parent of parents) {
    const depth = parent ? parent.split("::").length + 1 : 1;
    const inside = (m) => parent === "" || m === parent || m.startsWith(`${parent}::`);
    const child = (m) => (inside(m) && m.split("::").length >= depth && m !== parent ? m.split("::").slice(0, depth).join("::") : null);
    const graph = new Map();
    const where = new Map();
    for (const e of edges) {
      const a = child(e.from);
      const b = child(e.to);
      if (!a || !b || a === b) continue;
      if (!graph.has(a)) graph.set(a, new Set());
      graph.get(a).add(b);
      const key = `${a} → ${b}`;
      if (!where.has(key)) where.set(key, `${e.file}:${e.line}`);
    }
    for (const comp of cycles(new Map([...graph].map(([k, v]) => [k, [...v]])))) {
      const links = [...where].filter(([key]) => comp.includes(key.split(" → ")[0]) && comp.includes(key.split(" → ")[1])).map(([key, at]) => `${key} (${at})`);
      out.push(`${comp.join(" ↔ ")}: ${links.join("; ")}`);
    }
  }
  return out.sort();
}

/** The page's cycles, each with its edges: "a.js ↔ b.js: a.js → b.js (import-statement); …". */
export function jsCycles(graph) {
  const plain = new Map([...graph].map(([k, v]) => [k, [...v.keys()]]));
  return cycles(plain).map((comp) => {
    const links = comp.flatMap((a) => [...(graph.get(a) ?? new Map())].filter(([b]) => comp.includes(b)).map(([b, kinds]) => `${a} → ${b} (${[...new Set(kinds)].join(", ")})`));
    return `${comp.join(" ↔ ")}: ${links.join("; ")}`;
  });
}

describe("rules: layers point one way", () => {
  it("the graph readers see imports and paths (small cases)", () => {
    assert.deepEqual(cycles(new Map([["a", ["b"]], ["b", ["c"]], ["c", ["a"]], ["d", ["a"]]])), [["a", "b", "c"]]);
    assert.deepEqual(modulePath("src/examples/mod.rs"), ["examples"]);
    assert.deepEqual(modulePath("src/examples/chains/edge.rs"), ["examples", "chains", "edge"]);
    assert.equal(layerOf("examples::chains"), "examples");
    assert.equal(layerOf("projection::krueger"), "core");
    const edges = [
      { from: "coords", to: "examples::fields", file: "src/coords.rs", line: 3 },
      { from: "examples::projection", to: "examples::projection_facts", file: "src/examples/projection.rs", line: 8 },
      { from: "examples::projection_facts::geometry", to: "examples::projection", file: "src/examples/projection_facts/geometry.rs", line: 2 },
      { from: "examples::chains::edge", to: "examples::chains", file: "src/examples/chains/edge.rs", line: 1 },
      { from: "practice", to: "examples", file: "src/practice/mod.rs", line: 5 },
    ];
    assert.deepEqual(layerViolations({ edges }), ["src/coords.rs:3 coords (core) mentions examples::fields (examples)"]);
    const modules = ["", "coords", "examples", "examples::fields", "examples::projection", "examples::projection_facts", "examples::projection_facts::geometry", "examples::chains", "examples::chains::edge", "practice"];
    // a child using its parent (super::) is not a cycle; two siblings using each other are
    assert.deepEqual(siblingCycles({ modules, edges }), [
      "examples::projection ↔ examples::projection_facts: examples::projection → examples::projection_facts (src/examples/projection.rs:8); examples::projection_facts → examples::projection (src/examples/projection_facts/geometry.rs:2)",
    ]);
  });

  it("finds a cycle of imports in a small site, static or dynamic", async () => {
    const dir = site({
      "www/a.js": 'import { b } from "./b.js";\nexport const a = 1;',
      "www/b.js": 'export const b = 2;\nexport function later() { return import("./c.js"); }',
      "www/c.js": 'export * from "./a.js";\nimport "./pkg/made-by-the-build.js";',
      "www/d.js": 'import { a } from "./a.js";',
    });
    const graph = await jsImportGraph(dir, "www");
    assert.deepEqual(jsCycles(graph), ["www/a.js ↔ www/b.js ↔ www/c.js: www/a.js → www/b.js (import-statement); www/b.js → www/c.js (dynamic-import); www/c.js → www/a.js (import-statement)"]);
  });

  it("the page's modules import each other without a cycle", async () => {
    const graph = await jsImportGraph();
    assert.ok(graph.size > 40, `read ${graph.size} modules of www/`);
    assert.ok(graph.get("www/app.js")?.size > 3, "www/app.js imports other modules");
    const found = jsCycles(graph);
    assert.deepEqual(found, [], `cycles among www/ modules:\n${found.join("\n")}`);
  });

  it("the core crate's modules mention no higher layer", () => {
    const graph = rustModuleGraph();
    assert.ok(graph.edges.some((e) => e.from === "practice" && e.to === "solution"), "practice mentions crate::solution");
    const found = layerViolations(graph);
    assert.deepEqual(found, [], `lower layers mention higher ones (core → examples → practice → wasm):\n${found.join("\n")}`);
  });

  it("no two sibling modules of the core crate mention each other", () => {
    const found = siblingCycles(rustModuleGraph());
    assert.deepEqual(found, [], `cycles among sibling modules:\n${found.join("\n")}`);
  });
});
