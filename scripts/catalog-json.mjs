// Writes dist/catalog.json, the catalog the page loads before any wasm:
//   node scripts/catalog-json.mjs [dist]
// The data is the Rust catalog itself (examples::catalog(), through the
// built pkg/all.js), so Rust stays the one source of truth: every entry,
// whether it has practice, and the module that solves it (examples::MODULES);
// not its fields, which come with its module. Fails when an entry's module was not built or the
// page's loader (core.js) does not list it.
import fs from "node:fs";
import path from "node:path";
import { pathToFileURL } from "node:url";

const dist = path.resolve(process.argv[2] || "dist");
const all = await import(pathToFileURL(path.join(dist, "pkg", "all.js")).href);
all.initSync({ module: fs.readFileSync(path.join(dist, "pkg", "all_bg.wasm")) });
const entries = all.catalog();

const core = fs.readFileSync(path.join(dist, "core.js"), "utf8");
for (const e of entries) {
  if (!e.module) throw new Error(`catalog-json: ${e.id} has no module (add its topic to examples::MODULES)`);
  for (const f of [`${e.module}.js`, `${e.module}_bg.wasm`]) {
    if (!fs.existsSync(path.join(dist, "pkg", f))) throw new Error(`catalog-json: ${e.id}'s module ${f} was not built (web/${e.module}/)`);
  }
  if (!core.includes(`import("./pkg/${e.module}.js")`)) throw new Error(`catalog-json: core.js does not load module ${e.module} (its MODULES table)`);
}
// Without the fields (`inputs`: three quarters of the bytes): each module's
// own catalog() brings those of its entries when it loads (www/core.js).
const out = path.join(dist, "catalog.json");
fs.writeFileSync(out, `${JSON.stringify(entries.map(({ inputs: _, ...entry }) => entry))}\n`);
const modules = new Set(entries.map((e) => e.module));
console.log(`catalog-json: ${entries.length} examples in ${modules.size} modules, ${fs.statSync(out).size} bytes`);
