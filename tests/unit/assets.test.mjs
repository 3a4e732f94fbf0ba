// The build's esbuild step (scripts/site.mjs) on a small made-up site.
import { describe, it } from "node:test";
import assert from "node:assert/strict";
import crypto from "node:crypto";
import fs from "node:fs";
import path from "node:path";
import { pathToFileURL } from "node:url";
import { buildSite, dataBlock, finishSite, readDataBlock } from "../../scripts/site.mjs";
import { site } from "./site.mjs";

const read = (dir, name) => fs.readFileSync(path.join(dir, name), "utf8");
const CSP = `<meta http-equiv="Content-Security-Policy" content="default-src 'self'; script-src 'self'; style-src 'self'">`;
const HASHED = /^assets\/[\w-]+-[A-Z2-7]{8}\.\w+$/;

describe("site.mjs: esbuild's bundle of a small site", async () => {
  const stage = site({
    "head.partial.html": `${CSP}\n<!-- catalog-data -->\n<script src="./early.js"></script>\n<link rel="stylesheet" href="./s.css">\n<!-- a comment for the source's readers -->\n<!-- modulepreload -->\n<script type="module" src="./app.js"></script>\n`,
    "index.html": "<!doctype html>\n<head>\n  <!-- include: head.partial.html -->\n</head>\n<body></body>\n",
    "early.js": "// a classic script, inlined\nvar early = document.getElementById('catalog-data');\n",
    "app.js": 'import { shared } from "./shared.js";\nexport const topic = () => import("./pkg/t.js");\nexport const fig = () => import("./figures/t.js");\nexport const lab = () => import("./lab/lab.js");\nglobalThis.appResult = shared(21);\n',
    "shared.js": "let calls = 0;\nexport function shared(x) { calls += 1; return 2 * x; }\nexport const count = () => calls;\n",
    "pkg/t.js": "import { count } from '../shared.js';\nexport function wasmUrl() { return new URL('t_bg.wasm', import.meta.url); }\nexport const seen = () => count();\n",
    "pkg/t_bg.wasm": "\0asm-one",
    "figures/t.js": "export const figure = 1;\n",
    // a public entry (STABLE_ENTRIES: docs/API.md)
    "pkg/examples.js": "export { wasmUrl } from '../pkg/t.js';\nexport default 7;\n",
    "lab/lab.js": 'export const worker = () => new Worker(new URL("./worker.js", import.meta.url), { type: "module" });\nexport const css = new URL("./lab.css", import.meta.url).href;\nexport const photo = (n) => new URL(`./samples/${n}`, import.meta.url).href;\n',
    "lab/worker.js": 'import("./helper.js").then((m) => postMessage(m.x));\n',
    "lab/helper.js": "export const x = 1;\n",
    "lab/lab.css": ".lab  {  color : red ; }\n",
    "lab/samples/a.png": "a photo",
    "s.css": ".a  { color: blue }\n",
    "catalog.json": JSON.stringify([{ id: "t1", module: "t", status: "ready" }]),
    "sw.js": 'const BUILD = { version: "dev", files: [] }; // replaced\n',
    "embed.js": "var  spaced = 1;\n",
    "vendor/v.js": "var  keep = 1 ;  // as shipped\n",
  });
  const dist = site({});
  await buildSite(stage, dist);
  finishSite(stage, dist);
  const assets = JSON.parse(read(dist, "assets.json"));
  const html = read(dist, "index.html");

  it("names every module, chunk and emitted file by its content under assets/, and lists them in assets.json", () => {
    for (const logical of ["app.js", "pkg/t.js", "pkg/t_bg.wasm", "figures/t.js", "lab/lab.js", "lab/worker.js", "lab/lab.css", "s.css"]) {
      assert.match(assets[logical] ?? "", HASHED, logical);
      assert.ok(fs.existsSync(path.join(dist, assets[logical])), logical);
    }
    assert.equal(read(dist, assets["pkg/t_bg.wasm"]), "\0asm-one");
    assert.equal(read(dist, assets["lab/lab.css"]).trim(), ".lab{color:red}");
  });

  it("runs: one instance of a shared module, new URL(…, import.meta.url) pointing at the hashed file, the public entry re-exporting its build", async () => {
    const app = await import(pathToFileURL(path.join(dist, assets["app.js"])).href);
    assert.equal(globalThis.appResult, 42);
    const t = await app.topic();
    assert.equal(t.seen(), 1, "pkg/t.js sees the count app.js's call made");
    assert.equal(t.wasmUrl().href, pathToFileURL(path.join(dist, assets["pkg/t_bg.wasm"])).href);
    const lab = await app.lab();
    assert.equal(lab.css, pathToFileURL(path.join(dist, assets["lab/lab.css"])).href);
    assert.equal(lab.photo("a.png"), pathToFileURL(path.join(dist, "lab/samples/a.png")).href);
    assert.equal(read(dist, "lab/samples/a.png"), "a photo");
    // a page module by its own name (a course page, a test): the page's instance
    const byName = await import(pathToFileURL(path.join(dist, "shared.js")).href);
    assert.equal(byName.count(), 1, "shared.js by its name counts app.js's call");
    assert.match(read(dist, "shared.js"), /^export \* from "\.\/assets\/[\w-]+\.js";\n$/);
    const entry = await import(pathToFileURL(path.join(dist, "pkg/examples.js")).href);
    assert.equal(entry.default, 7);
    assert.equal(entry.wasmUrl().href, t.wasmUrl().href);
    assert.match(read(dist, "pkg/examples.js"), /^export \* from "\.\.\/assets\/examples-[A-Z2-7]{8}\.js";\nexport \{ default \} from/);
  });

  it("builds the worker with its own chunks, next to the page's", () => {
    const worker = read(dist, assets["lab/worker.js"]);
    const chunk = /import\("\.\/(helper-[A-Z2-7]{8}\.js)"\)/.exec(worker);
    assert.ok(chunk, worker);
    assert.ok(fs.existsSync(path.join(dist, "assets", chunk[1])));
  });

  it("the HTML: the shared head included, hashed names, the classic script inlined and admitted by the CSP, the catalog data", () => {
    assert.ok(!html.includes("<!--"), "comments dropped");
    assert.ok(!html.includes("importmap"));
    assert.ok(html.includes(`<script type="module" src="./${assets["app.js"]}">`));
    assert.ok(html.includes(`<link rel="stylesheet" href="./${assets["s.css"]}">`));
    const inline = /<script>([^<]*)<\/script>/.exec(html)[1];
    assert.ok(inline.includes("catalog-data") && !inline.includes("a classic script"), inline);
    const digest = crypto.createHash("sha256").update(inline).digest("base64");
    assert.ok(html.includes(`script-src 'self' 'sha256-${digest}'`), html);
    // the chunk app.js shares with the topic module is preloaded; the lazy ones are not
    const preloads = [...html.matchAll(/<link rel="modulepreload" href="\.\/([^"]+)">/g)].map((m) => m[1]);
    assert.equal(preloads.length, 1);
    // (shared.js, with app.js: the chunk the topic module imports too)
    assert.ok(read(dist, assets["pkg/t.js"]).includes(`"./${path.basename(preloads[0])}"`), preloads[0]);
    const data = readDataBlock(html);
    assert.deepEqual(data.entries, [{ id: "t1", module: "t", status: "ready" }]);
    assert.deepEqual(data.files.t, [`./${assets["pkg/t.js"]}`, `./${assets["pkg/t_bg.wasm"]}`, `./${assets["figures/t.js"]}`]);
    assert.ok(!fs.existsSync(path.join(dist, "head.partial.html")));
  });

  it("classic scripts at fixed URLs, vendor/ as shipped; the worker's list; _headers by folder", () => {
    assert.equal(read(dist, "embed.js").trim(), "var spaced=1;");
    assert.equal(read(dist, "vendor/v.js"), "var  keep = 1 ;  // as shipped\n");
    const build = JSON.parse(/^const BUILD = (.*);$/m.exec(read(dist, "sw.js"))[1]);
    assert.match(build.version, /^[0-9a-f]{16}$/);
    for (const f of ["index.html", assets["app.js"], assets["pkg/t_bg.wasm"], assets["figures/t.js"]]) assert.ok(build.files.includes(f), f);
    for (const f of [assets["lab/lab.js"], assets["lab/worker.js"], assets["lab/lab.css"], "lab/samples/a.png"]) assert.ok(build.lazy.includes(f), f);
    const rules = read(dist, "_headers");
    assert.match(rules, /^\/assets\/\*\n {2}Cache-Control: public, max-age=31536000, immutable$/m);
    assert.match(rules, /^\/index\.html\n {2}Cache-Control: no-cache$/m);
    assert.match(rules, /^\/lab\/\*\n {2}Cache-Control: no-cache$/m);
    assert.ok(fs.existsSync(path.join(dist, `${assets["app.js"]}.br`)) && fs.existsSync(path.join(dist, "index.html.gz")));
  });

  it("fails with a clear message on a new URL to a file that does not exist", async () => {
    const bad = site({ ...Object.fromEntries(["index.html", "head.partial.html", "s.css", "catalog.json", "sw.js", "embed.js", "early.js"].map((f) => [f, read(stage, f)])), "app.js": 'export const u = new URL("./missing.wasm", import.meta.url);\n' });
    await assert.rejects(buildSite(bad, site({})), /missing\.wasm.*does not exist/s);
  });
});

describe("site.mjs: the page's data block", () => {
  it("writes data that reads back the same, inside a page, and refuses what would end its element", () => {
    const data = { entries: [{ id: "gsd" }], prerendered: { folder: "./prerender/", ids: ["gsd"], options: ["theme"] } };
    const page = `<head>${dataBlock(data)}<script type="module"></script></head>`;
    assert.deepEqual(readDataBlock(page), data);
    assert.equal(readDataBlock("<head></head>"), null);
    assert.throws(() => dataBlock({ title: "</script><script>x()" }), /would end its script element/);
  });
});
