// Checks dist/catalog.json, the catalog the page loads before any wasm:
//   node scripts/catalog-json.mjs [dist]
// The build writes it natively from the Rust entries (examples/catalog_json.rs:
// examples::catalog() through serde_json), so Rust stays the one source of
// truth. This step checks it, entry by entry, against the built wasm's own
// catalog() (pkg/all.js: the same entries through serde-wasm-bindgen, another
// serialiser), and that every entry's module was built and is listed by the
// page's loader (core.js). Fails the build on any difference.
import assert from "node:assert/strict";
import fs from "node:fs";
import path from "node:path";
import { pathToFileURL } from "node:url";

const dist = path.resolve(process.argv[2] || "dist");
const file = path.join(dist, "catalog.json");
const written = JSON.parse(fs.readFileSync(file, "utf8"));
const all = await import(pathToFileURL(path.join(dist, "pkg", "all.js")).href);
all.initSync({ module: fs.readFileSync(path.join(dist, "pkg", "all_bg.wasm")) });
// the fields (`inputs`) stay out of catalog.json: each module's own catalog() brings its entries' (www/core.js)
const wasm = all.catalog().map(({ inputs: _, ...entry }) => entry);

assert.equal(written.length, wasm.length, `catalog-json: catalog.json has ${written.length} entries, the wasm catalog ${wasm.length}`);
wasm.forEach((entry, k) => assert.deepEqual(written[k], entry, `catalog-json: entry ${k} (${entry.id}) differs between catalog.json and pkg/all.js's catalog()`));

const core = fs.readFileSync(path.join(dist, "core.js"), "utf8");
for (const e of written) {
  if (!e.module) throw new Error(`catalog-json: ${e.id} has no module (add its topic to examples::MODULES)`);
  for (const f of [`${e.module}.js`, `${e.module}_bg.wasm`]) {
    if (!fs.existsSync(path.join(dist, "pkg", f))) throw new Error(`catalog-json: ${e.id}'s module ${f} was not built (web/${e.module}/)`);
  }
  if (!core.includes(`import("./pkg/${e.module}.js")`)) throw new Error(`catalog-json: core.js does not load module ${e.module} (its MODULES table)`);
}
const modules = new Set(written.map((e) => e.module));
console.log(`catalog-json: ${written.length} examples in ${modules.size} modules, ${fs.statSync(file).size} bytes, the same as the wasm's catalog()`);
