// The build's assets step (scripts/assets.mjs) on a small made-up site.
import { describe, it } from "node:test";
import assert from "node:assert/strict";
import crypto from "node:crypto";
import fs from "node:fs";
import path from "node:path";
import { contentHash, dataBlock, fontFaces, hashAssets, headersFile, jsRefs, minifyAll, minifyCss, readDataBlock } from "../../scripts/assets.mjs";
import { site } from "./site.mjs";

const read = (dir, name) => fs.readFileSync(path.join(dir, name), "utf8");
const CSP = `<meta http-equiv="Content-Security-Policy" content="default-src 'self'; script-src 'self'; style-src 'self'">`;

describe("assets.mjs: hashed names, references, the import map", () => {
  const dir = site({
    "head.partial.html": `${CSP}\n<link rel="stylesheet" href="./s.css">\n<!-- a comment for the source's readers -->\n<!-- modulepreload -->\n<script type="module" src="./app.js"></script>\n`,
    "index.html": "<!doctype html>\n<head>\n  <!-- include: head.partial.html -->\n</head>\n<body></body>\n",
    "app.js": 'import { b } from "./b.js";\nexport const a = b + import("./lazy.js");\n',
    "b.js": 'export const b = new URL("./w.wasm", import.meta.url).href;\nexport const w = new Worker(new URL("./worker.js", import.meta.url), { type: "module" });\n',
    "lazy.js": "export const z = 3;\n",
    "worker.js": 'import { x } from "./lib.js";\npostMessage(x);\n',
    "lib.js": "export const x = 1;\n",
    "w.wasm": "\0asm-one",
    "s.css": '@font-face{font-family:F;src:url(f.woff2) format("woff2"),url(f.ttf) format("truetype")}',
    "f.woff2": "font bytes",
    "samples/a.png": "named by no literal",
    "pkg/photogrammetry_playground.js": "export default 1;\nconst u = new URL('w2.wasm', import.meta.url);\n",
    "pkg/w2.wasm": "\0asm-two",
  });
  const { map } = hashAssets(dir);
  const html = read(dir, "index.html");

  it("names every file by its content, and the name is the hash of the bytes on disk", () => {
    for (const logical of ["app.js", "b.js", "lazy.js", "worker.js", "lib.js", "w.wasm", "s.css", "f.woff2", "pkg/w2.wasm"]) {
      const hashed = map.get(logical);
      assert.ok(hashed, logical);
      assert.match(hashed, /\.[0-9a-f]{8}\.[a-z0-9]+$/);
      assert.ok(!fs.existsSync(path.join(dir, logical)), `${logical} is gone`);
      assert.equal(hashed.split(".").at(-2), contentHash(fs.readFileSync(path.join(dir, hashed))));
    }
  });
  it("keeps stable names and files that only a computed URL can name; the stable entry points at the hashed wasm", () => {
    assert.ok(fs.existsSync(path.join(dir, "samples/a.png")));
    assert.ok(!map.has("samples/a.png"));
    assert.ok(!map.has("pkg/photogrammetry_playground.js"), "no page imports it: no hashed copy");
    assert.match(read(dir, "pkg/photogrammetry_playground.js"), new RegExp(`new URL\\('${path.basename(map.get("pkg/w2.wasm")).replace(/\./g, "\\.")}'`));
  });
  it("rewrites literals where no import map applies: new URL, the worker and what the worker imports", () => {
    const b = read(dir, map.get("b.js"));
    assert.ok(b.includes(`new URL("./${map.get("w.wasm")}"`), b);
    assert.ok(b.includes(`new URL("./${map.get("worker.js")}"`), b);
    assert.ok(read(dir, map.get("worker.js")).includes(`from "./${map.get("lib.js")}"`));
    // a page module keeps its logical specifiers: the import map maps them
    const app = read(dir, map.get("app.js"));
    assert.ok(app.includes('from "./b.js"') && app.includes('import("./lazy.js")'));
  });
  it("the HTML: the shared head included, import map admitted by the CSP, generated modulepreloads, hashed src/href", () => {
    assert.ok(!fs.existsSync(path.join(dir, "head.partial.html")));
    assert.ok(!html.includes("<!--"), "comments dropped");
    const json = /<script type="importmap">(.*?)<\/script>/.exec(html)[1];
    const { imports } = JSON.parse(json);
    assert.equal(imports["./b.js"], `./${map.get("b.js")}`);
    assert.equal(imports["./lazy.js"], `./${map.get("lazy.js")}`);
    const digest = crypto.createHash("sha256").update(json).digest("base64");
    assert.ok(html.includes(`script-src 'self' 'sha256-${digest}'`), html);
    assert.ok(html.indexOf("importmap") < html.indexOf("modulepreload"), "the map comes before any module loads");
    assert.ok(html.includes(`<link rel="modulepreload" href="./${map.get("b.js")}">`));
    assert.ok(html.includes(`<script type="module" src="./${map.get("app.js")}">`));
    assert.ok(html.includes(`href="./${map.get("s.css")}"`));
  });
  it("CSS: fonts swap, url() hashed, sources the build does not ship dropped", () => {
    const css = read(dir, map.get("s.css"));
    assert.ok(css.includes("font-display:swap"));
    assert.ok(css.includes(`url(${path.basename(map.get("f.woff2"))})`));
    assert.ok(!css.includes(".ttf"));
  });
  it("a stable entry that imports by a computed name still finds its folder's modules under their own names", () => {
    const loader = site({
      "index.html": `<head>${CSP}<script type="module" src="./app.js"></script></head>`,
      "app.js": 'import("./pkg/photogrammetry_playground.js");\n',
      "pkg/photogrammetry_playground.js": "export const load = (topic) => import(`./${topic}.js`);\n",
      "pkg/coordinates.js": "export const x = new URL('coordinates_bg.wasm', import.meta.url);\n",
      "pkg/coordinates_bg.wasm": "\0asm",
    });
    const { map } = hashAssets(loader);
    const hashed = map.get("pkg/coordinates.js");
    assert.ok(hashed && fs.existsSync(path.join(loader, hashed)));
    assert.equal(read(loader, "pkg/coordinates.js"), read(loader, hashed), "the logical copy is the hashed file's bytes");
    assert.ok(read(loader, hashed).includes(path.basename(map.get("pkg/coordinates_bg.wasm"))));
    // the page's own import map points at the hashed copies, the stable entry included
    const { imports } = JSON.parse(/<script type="importmap">(.*?)<\/script>/.exec(read(loader, "index.html"))[1]);
    assert.equal(imports["./pkg/coordinates.js"], `./${hashed}`);
    assert.equal(imports["./pkg/photogrammetry_playground.js"], `./${map.get("pkg/photogrammetry_playground.js")}`);
  });
  it("fails loudly on a cycle of literal references", () => {
    const cyclic = site({
      "index.html": `<head>${CSP}<script type="module" src="./c1.js"></script></head>`,
      "c1.js": 'export const u = new URL("./c2.js", import.meta.url);\n',
      "c2.js": 'export const u = new URL("./c1.js", import.meta.url);\n',
    });
    assert.throws(() => hashAssets(cyclic), /cycle of literal references.*c1\.js.*c2\.js/);
  });
});

describe("assets.mjs: finding references", () => {
  it("tells import specifiers from other literals, and sees workers", () => {
    const refs = jsRefs('import a from "./a.js";\nconst u = new URL("./b.wasm", import.meta.url);\nnew Worker(new URL("./w.js", import.meta.url));\nawait import("./c.js");\nconst s = "not a path.js here";');
    assert.deepEqual(
      refs.map((r) => [r.ref, r.kind, r.worker]),
      [
        ["./a.js", "import", false],
        ["./b.wasm", "url", false],
        ["./w.js", "url", true],
        ["./c.js", "import", false],
      ],
    );
  });
  it("font-display: block becomes swap; a face without one gets it", () => {
    const files = new Set(["x.woff2"]);
    assert.equal(fontFaces("a.css", "@font-face{font-display:block;src:url(x.woff2)}", files), "@font-face{font-display:swap;src:url(x.woff2)}");
    assert.equal(fontFaces("a.css", "@font-face{src:url(x.woff2)}", files), "@font-face{font-display:swap;src:url(x.woff2)}");
  });
});

describe("step 0: minified JS and CSS", () => {
  it("CSS loses comments and idle white space; strings, url() and descendant spaces stay", () => {
    const css = `/* note */\n.a > .b ,\n.c :is(.d) {\n  content: "▸ ; , x" ;\n  background: url( "x y.png" ) ;\n  margin: 0 auto;\n}\n@media (min-width: 600px) { .e { color: red; } }\n`;
    assert.equal(minifyCss(css), `.a>.b,.c :is(.d){content:"▸ ; , x";background:url( "x y.png" );margin:0 auto}@media (min-width:600px){.e{color:red}}`);
  });
  it("a module keeps its exports and imports, a classic script its globals; vendor/ and sw.js are left alone", async () => {
    const source = {
      "m.js": `import { helper } from "./h.js";\nconst longLocalName = helper(2);\nexport function twice(value) { return longLocalName * value; }\n`,
      "classic.js": `var pageGlobal = 1;\nfunction setup(argument) { return argument + pageGlobal; }\n`,
      "vendor/v.js": "var  keep = 1 ;  // as shipped\n",
      "sw.js": "// PRECACHE-MARKER\nself.x = 1;\n",
      "s.css": ".a { color: red; }\n",
    };
    const dir = site(source);
    const [n, before, after] = await minifyAll(dir);
    assert.equal(n, 3);
    assert.ok(after < before, `${after} < ${before}`);
    const m = read(dir, "m.js");
    assert.match(m, /import\{helper as \w+\}from"\.\/h\.js"/);
    assert.match(m, /export\{\w+ as twice\}|export function twice/);
    assert.doesNotMatch(m, /longLocalName/);
    assert.match(read(dir, "classic.js"), /var pageGlobal=1;function setup\(/);
    assert.equal(read(dir, "vendor/v.js"), source["vendor/v.js"]);
    assert.equal(read(dir, "sw.js"), source["sw.js"]);
    assert.equal(read(dir, "s.css"), ".a{color:red}\n");
  });
});

describe("assets.mjs: the page's data block, and cache rules by folder", () => {
  it("writes data that reads back the same, inside a page, and refuses what would end its element", () => {
    const data = { entries: [{ id: "gsd" }], prerendered: { folder: "./prerender/", ids: ["gsd"], options: ["theme"] } };
    const page = `<head>${dataBlock(data)}<script type="importmap">{}</script></head>`;
    assert.deepEqual(readDataBlock(page), data);
    assert.equal(readDataBlock("<head></head>"), null);
    assert.throws(() => dataBlock({ title: "</script><script>x()" }), /would end its script element/);
  });

  it("gives a folder with no hashed file one no-cache rule, and one with only hashed files one immutable rule", () => {
    const dir = site({ "index.html": "", "prerender/gsd.html": "", "prerender/embed/gsd.html": "", "pkg/a.12345678.js": "", "b.js": "" });
    headersFile(dir, new Map([["pkg/a.js", "pkg/a.12345678.js"]]));
    const text = read(dir, "_headers");
    assert.match(text, /^\/prerender\/\*\n {2}Cache-Control: no-cache$/m);
    assert.doesNotMatch(text, /^\/prerender\/(gsd|embed)/m);
    assert.match(text, /^\/pkg\/\*\n {2}Cache-Control: public, max-age=31536000, immutable$/m);
    assert.match(text, /^\/b\.js\n {2}Cache-Control: no-cache$/m);
  });
});
