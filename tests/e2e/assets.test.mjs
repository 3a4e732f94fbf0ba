// The built dist/ as a static host serves it (scripts/site.mjs, esbuild):
// .br and .gz beside every compressible file, every module, chunk, wasm and
// stylesheet under a content-hashed name in assets/ (the public entries keep
// theirs and re-export their build), nothing referenced by a name that does
// not exist, and the server's encodings and cache rules.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import crypto from "node:crypto";
import fs from "node:fs";
import http from "node:http";
import path from "node:path";
import zlib from "node:zlib";
import { DIST } from "./harness.mjs";
import { startServer } from "../../scripts/serve.mjs";
import { ASSETS, STABLE_ENTRIES } from "../../scripts/site.mjs";

const COMPRESSIBLE = /\.(m?js|wasm|css|json|html|svg|txt|map)$/;
/** esbuild's content hash in a name: stem-XXXXXXXX.ext */
const HASHED = /-[A-Z2-7]{8}\.[A-Za-z0-9]+$/;
/** Fixed public URLs: never hashed (the pages, the worker, the host script, the JS API: docs/API.md). */
const STABLE = ["index.html", "embed.html", "sw.js", "embed.js", "version.json", ...STABLE_ENTRIES];

function walk(dir) {
  return fs.readdirSync(dir, { withFileTypes: true }).flatMap((d) => (d.isDirectory() ? walk(path.join(dir, d.name)) : [path.join(dir, d.name)]));
}
const files = fs.existsSync(DIST) ? walk(DIST).map((p) => path.relative(DIST, p).split(path.sep).join("/")) : [];
const served = files.filter((f) => !/\.(gz|br)$/.test(f));
const onDisk = new Set(files);
const assets = fs.existsSync(path.join(DIST, "assets.json")) ? JSON.parse(fs.readFileSync(path.join(DIST, "assets.json"), "utf8")) : {};
const read = (f) => fs.readFileSync(path.join(DIST, f), "utf8");

/** A relative reference from `from` as a dist path, or null when it is not one (an address, a data: URL). */
function target(from, ref) {
  if (/^[a-z][a-z0-9+.-]*:|^\/\/|^#/i.test(ref)) return null;
  const clean = ref.replace(/[?#].*$/, "");
  return path.posix.normalize(path.posix.join(clean.startsWith("/") ? "" : path.posix.dirname(from), clean.replace(/^\//, "")));
}

describe("the built dist/", () => {
  test("has .br and .gz beside every compressible file, each decompressing to its bytes", () => {
    const compressible = served.filter((f) => COMPRESSIBLE.test(f));
    assert.ok(compressible.length > 40, `${compressible.length} compressible files`);
    for (const f of compressible) {
      const bytes = fs.readFileSync(path.join(DIST, f));
      assert.ok(onDisk.has(`${f}.gz`) && onDisk.has(`${f}.br`), f);
      assert.ok(zlib.gunzipSync(fs.readFileSync(path.join(DIST, `${f}.gz`))).equals(bytes), `${f}.gz`);
      assert.ok(zlib.brotliDecompressSync(fs.readFileSync(path.join(DIST, `${f}.br`))).equals(bytes), `${f}.br`);
    }
  });

  test("every module, chunk, wasm and stylesheet is in assets/ under a hashed name; the stable names re-export their build", () => {
    const hashed = served.filter((f) => f.startsWith(`${ASSETS}/`));
    assert.ok(hashed.length > 40, `${hashed.length} hashed files`);
    for (const f of hashed) assert.match(f, HASHED);
    // two different files never share a name, and one content is one file
    const digests = new Map();
    for (const f of hashed) {
      const d = crypto.createHash("sha256").update(fs.readFileSync(path.join(DIST, f))).digest("hex");
      assert.ok(!digests.has(d), `${f} and ${digests.get(d)} are the same bytes`);
      digests.set(d, f);
    }
    for (const f of STABLE) assert.ok(onDisk.has(f), f);
    for (const f of STABLE_ENTRIES) {
      const lines = read(f).trim().split("\n");
      assert.ok(lines.length <= 2 && lines.every((l) => /^export (\*|\{ default \}) from "\.\.?\/[\w./-]+";$/.test(l)), `${f}: ${lines.join(" ")}`);
    }
    for (const [logical, name] of Object.entries(assets)) assert.ok(onDisk.has(name) && name.startsWith(`${ASSETS}/`), `${logical} → ${name}`);
    for (const f of ["app.js", "style.css", "pkg/all.js", "pkg/all_bg.wasm", "pkg/coordinates_bg.wasm", "lab/lab.js", "lab/worker.js", "catalog.json"]) assert.ok(assets[f], f);
    // outside assets/: the stable names, the saved answers, the lab's photos, vendor/ (KaTeX and
    // uqr as their authors built them: math.js and practice/sheets.js name them by a fixed URL),
    // and the page's modules by name (one-line re-exports of their builds, never loaded by the page)
    const byName = (f) => /^export \* from "(\.\.\/)*(\.\/)?assets\/([\w-]+\.js)";\n(export \{ default \} from "(\.\.\/)*(\.\/)?assets\/\3";\n)?$/.test(read(f));
    const elsewhere = served.filter((f) => /\.(m?js|wasm|css)$/.test(f) && !f.startsWith(`${ASSETS}/`) && !STABLE.includes(f) && !f.startsWith("vendor/") && !byName(f));
    assert.deepEqual(elsewhere, []);
    for (const f of ["core.js", "lab/lab.js", "figures/chains.js"]) assert.ok(onDisk.has(f) && byName(f), f);
    // fonts swap: text shows at once in a fallback font
    for (const f of served.filter((f) => f.endsWith(".css"))) {
      for (const face of read(f).match(/@font-face\s*\{[^}]*\}/g) ?? []) assert.match(face, /font-display:\s*swap/, `${f}: ${face.slice(0, 60)}`);
    }
  });

  test("nothing refers to a file that does not exist (HTML, JS imports and literals, CSS url(), the service worker's list)", () => {
    const missing = [];
    // relative to the file's folder, or (a string a module hands to the document) to the site's root
    const check = (from, ref) => {
      const t = target(from, ref);
      if (t !== null && !onDisk.has(t) && !onDisk.has(target("index.html", ref))) missing.push(`${from}: ${ref}`);
    };
    for (const f of served.filter((f) => f.endsWith(".html"))) {
      const html = read(f);
      for (const m of html.matchAll(/\s(?:src|href)=["']([^"']+)["']/g)) check(f, m[1]);
      // a saved solution (scripts/prerender.mjs) is a fragment that goes into index.html: no head of its own
      if (f.startsWith("prerender/")) continue;
      assert.doesNotMatch(html, /type="importmap"/, `${f}: no import map (chunks name each other)`);
      // the CSP admits the inline scripts and nothing else inline
      const csp = /script-src ([^;"]*)/.exec(html)[1];
      const inline = [...html.matchAll(/<script>([^<]*)<\/script>/g)];
      assert.ok(inline.length >= 1, `${f}: the small classic scripts are inlined`);
      for (const m of inline) assert.ok(csp.includes(`'sha256-${crypto.createHash("sha256").update(m[1]).digest("base64")}'`), `${f}: inline script admitted by the CSP`);
    }
    for (const f of served.filter((f) => /\.m?js$/.test(f) && !f.startsWith("vendor/"))) {
      const source = read(f);
      // relative paths to a file of ours: import specifiers, the names esbuild wrote for emitted files
      // (not a key of the wasm's import object: { "./x_bg.js": import0 })
      const refs = [...source.matchAll(/["'`]((?:\.{1,2}\/)[\w@~.\/-]+\.(?:m?js|wasm|css|json|woff2?|png|jpe?g|svg))["'`](?!\s*:)/g)].map((m) => m[1]);
      for (const ref of refs) check(f, ref);
    }
    for (const f of served.filter((f) => f.endsWith(".css"))) {
      for (const m of read(f).matchAll(/url\(\s*["']?([^"')\s]+)/g)) check(f, m[1]);
    }
    // the service worker's precache and lazy lists
    const build = JSON.parse(/^const BUILD = (.*);$/m.exec(read("sw.js"))[1]);
    for (const f of [...build.files, ...build.lazy]) if (f !== "./") check("sw.js", f);
    assert.deepEqual(missing, []);
  });

  test("the service worker caches the page and every topic at install, the lab and pkg/all when first used", () => {
    const build = JSON.parse(/^const BUILD = (.*);$/m.exec(read("sw.js"))[1]);
    for (const f of ["app.js", "style.css", "pkg/coordinates.js", "pkg/coordinates_bg.wasm", "figures/coordinates.js", "catalog.json"]) assert.ok(build.files.includes(assets[f]), f);
    for (const f of ["pkg/all.js", "pkg/all_bg.wasm", "lab/lab.js", "lab/worker.js", "lab/pkg/photogrammetry_lab_bg.wasm"]) assert.ok(build.lazy.includes(assets[f]) && !build.files.includes(assets[f]), f);
    assert.ok(build.lazy.some((f) => f.startsWith("prerender/")));
    // every served file is in one list or the other (but the worker itself, the host's rules, the manifest and the version)
    const listed = new Set([...build.files, ...build.lazy]);
    assert.deepEqual(served.filter((f) => !listed.has(f) && !["sw.js", "_headers", "assets.json", "version.json"].includes(f)), []);
  });
});

describe("scripts/serve.mjs as a static host", () => {
  let server;
  before(async () => {
    server = await startServer({ dir: DIST, port: 0 });
  });
  after(() => server.close());
  const get = (p, encoding) =>
    new Promise((resolve, reject) => {
      http.get(new URL(p, server.url), { headers: encoding === undefined ? {} : { "accept-encoding": encoding } }, (res) => {
        const chunks = [];
        res.on("data", (c) => chunks.push(c));
        res.on("end", () => resolve({ headers: res.headers, body: Buffer.concat(chunks) }));
      }).on("error", reject);
    });

  test("sends .br or .gz as the request allows, with Vary; long caching for hashed names only", async () => {
    const wasm = assets["pkg/coordinates_bg.wasm"];
    const bytes = fs.readFileSync(path.join(DIST, wasm));
    const br = await get(wasm, "gzip, deflate, br");
    assert.equal(br.headers["content-encoding"], "br");
    assert.equal(br.headers.vary, "Accept-Encoding");
    assert.equal(br.headers["content-type"], "application/wasm");
    assert.equal(br.headers["cache-control"], "public, max-age=31536000, immutable");
    assert.ok(zlib.brotliDecompressSync(br.body).equals(bytes));
    const gz = await get(wasm, "gzip");
    assert.equal(gz.headers["content-encoding"], "gzip");
    assert.ok(zlib.gunzipSync(gz.body).equals(bytes));
    const plain = await get(wasm, "identity");
    assert.equal(plain.headers["content-encoding"], undefined);
    assert.ok(plain.body.equals(bytes));
    for (const stable of ["", "index.html", "embed.html", "sw.js", "embed.js", "pkg/photogrammetry_playground.js"]) {
      assert.equal((await get(stable, "br")).headers["cache-control"], "no-cache", stable || "/");
    }
  });

  test("dist/_headers gives static hosts the same rules, one per top-level file or folder", () => {
    const rules = read("_headers");
    assert.match(rules, /^\/assets\/\*\n {2}Cache-Control: public, max-age=31536000, immutable$/m);
    for (const p of ["/", "/index.html", "/embed.html", "/sw.js", "/embed.js", "/pkg/*", "/prerender/*", "/vendor/*", "/lab/*"]) {
      assert.match(rules, new RegExp(`^${p.replace(/[.*]/g, "\\$&")}\\n {2}Cache-Control: no-cache$`, "m"), p);
    }
    // no rule that matches assets/ too (a host applies every rule that matches: two Cache-Control values)
    assert.doesNotMatch(rules, /^\/\*$/m);
    assert.equal(rules.match(/^\//gm).length, fs.readdirSync(DIST).filter((f) => !/\.(gz|br)$/.test(f) && f !== "_headers").length + 1);
  });
});
