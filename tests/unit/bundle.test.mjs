// scripts/bundle.mjs on a small made-up site: the page's entry and its static
// imports become one file; a module something else also imports stays (and is
// re-exported, for the import map to point at the bundle); dynamic imports stay
// files, named from the bundle's folder; a name exported by two such modules
// stops the build. Then scripts/assets.mjs maps those names to the bundle.
import { describe, it } from "node:test";
import assert from "node:assert/strict";
import { spawnSync } from "node:child_process";
import fs from "node:fs";
import path from "node:path";
import { fileURLToPath, pathToFileURL } from "node:url";
import { hashAssets } from "../../scripts/assets.mjs";
import { site } from "./site.mjs";

const BUNDLE = path.join(path.dirname(fileURLToPath(import.meta.url)), "../../scripts/bundle.mjs");
const run = (dir) => spawnSync(process.execPath, [BUNDLE, dir], { encoding: "utf8" });
const HTML = `<!doctype html><head><meta http-equiv="Content-Security-Policy" content="script-src 'self'"><script type="module" src="./app.js"></script></head><body></body>`;

describe("bundle.mjs", () => {
  const files = {
    "index.html": HTML,
    "app.js": `import { twice } from "./lib/private.js";\nimport { shared } from "./shared.js";\nexport const loadLazy = () => import("./lib/lazy.js");\nglobalThis.appResult = twice(shared());\n`,
    "lib/private.js": `export function twice(x) { return 2 * x; }\n`,
    "shared.js": `let calls = 0;\nexport function shared() { calls += 1; return 21; }\nexport function count() { return calls; }\n`,
    "lib/lazy.js": `import { count } from "../shared.js";\nexport const seen = () => count();\n`,
  };

  it("puts the entry's static graph into the entry, keeps what others import, and the names for the import map", async () => {
    const dir = site(files);
    const r = run(dir);
    assert.equal(r.status, 0, r.stderr);
    assert.ok(!fs.existsSync(path.join(dir, "lib/private.js")), "a module only the entry imports is gone");
    assert.ok(fs.existsSync(path.join(dir, "shared.js")), "a module the lazy one imports stays");
    assert.deepEqual(JSON.parse(fs.readFileSync(path.join(dir, ".bundle.json"), "utf8")), { "app.js": ["shared.js"] });
    const app = fs.readFileSync(path.join(dir, "app.js"), "utf8");
    assert.match(app, /import\("\.\/lib\/lazy\.js"\)/, "the dynamic import, named from the bundle's folder");
    assert.doesNotMatch(app, /^import .* from/m, "no static import left");
    // the bundle runs and re-exports the shared module's names (one instance: the same `calls`)
    const mod = await import(pathToFileURL(path.join(dir, "app.js")).href);
    assert.equal(globalThis.appResult, 42);
    assert.equal(mod.count(), 1);
    assert.equal(typeof mod.shared, "function");
    // assets.mjs: the page's import map sends shared.js to the bundle, and .bundle.json is not shipped
    const { map } = hashAssets(dir);
    const html = fs.readFileSync(path.join(dir, "index.html"), "utf8");
    const { imports } = JSON.parse(/<script type="importmap">([^<]*)<\/script>/.exec(html)[1]);
    assert.equal(imports["./shared.js"], `./${map.get("app.js")}`);
    assert.equal(imports["./app.js"], `./${map.get("app.js")}`);
    assert.ok(!fs.existsSync(path.join(dir, ".bundle.json")));
  });

  it("stops when two modules it stands for export the same name", () => {
    const dir = site({ ...files, "lib/lazy.js": `import { count } from "../shared.js";\nimport { twice } from "./private.js";\nexport const seen = () => twice(count());\n`, "lib/private.js": `export function twice(x) { return 2 * x; }\nexport function count() { return 0; }\n` });
    const r = run(dir);
    assert.notEqual(r.status, 0);
    assert.match(r.stderr, /both export "count"/);
  });
});
