// The built dist/ as a static host serves it (scripts/assets.mjs): .br and .gz
// beside every compressible file, content-hashed names that match their
// bytes, nothing referenced by a name that does not exist, and the server's
// encodings and cache rules.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import crypto from "node:crypto";
import fs from "node:fs";
import http from "node:http";
import path from "node:path";
import zlib from "node:zlib";
import { DIST } from "./harness.mjs";
import { startServer } from "../../scripts/serve.mjs";

const COMPRESSIBLE = /\.(m?js|wasm|css|json|html|svg|txt|map)$/;
const HASHED = /\.([0-9a-f]{8})\.[A-Za-z0-9]+$/;
/** Fixed public URLs: never hashed (scripts/assets.mjs STABLE). */
const STABLE = ["index.html", "embed.html", "sw.js", "embed.js", "pkg/photogrammetry_playground.js", "pkg/examples.js", "lab/pkg/photogrammetry_lab.js", "version.json"];

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

  test("hashed names match their content; the stable names are there unhashed; assets.json lists what exists", () => {
    const hashed = served.filter((f) => HASHED.test(f));
    assert.ok(hashed.length > 40, `${hashed.length} hashed files`);
    for (const f of hashed) {
      const digest = crypto.createHash("sha256").update(fs.readFileSync(path.join(DIST, f))).digest("hex").slice(0, 8);
      assert.equal(HASHED.exec(f)[1], digest, f);
    }
    for (const f of STABLE) assert.ok(onDisk.has(f), f);
    // a logical name left beside its hashed one is the same bytes (a module a stable
    // entry loads by a computed name keeps a copy: scripts/assets.mjs)
    const copy = (logical) => onDisk.has(logical) && assets[logical] && fs.readFileSync(path.join(DIST, logical)).equals(fs.readFileSync(path.join(DIST, assets[logical])));
    for (const [logical, name] of Object.entries(assets)) {
      assert.ok(onDisk.has(name), `${logical} → ${name}`);
      if (!STABLE.includes(logical) && onDisk.has(logical)) assert.ok(copy(logical), `${logical} is left under its logical name`);
    }
    // every JS, wasm and CSS file but the stable ones is hashed (KaTeX, the lab, practice, figures)
    const unhashed = served.filter((f) => /\.(m?js|wasm|css)$/.test(f) && !HASHED.test(f) && !STABLE.includes(f) && !copy(f));
    assert.deepEqual(unhashed, []);
    // fonts swap: text shows at once in a fallback font
    for (const f of served.filter((f) => f.endsWith(".css"))) {
      for (const face of read(f).match(/@font-face\s*\{[^}]*\}/g) ?? []) assert.match(face, /font-display:\s*swap/, `${f}: ${face.slice(0, 60)}`);
    }
  });

  test("nothing refers to a file that does not exist (HTML, import map, JS literals, CSS url())", () => {
    const missing = [];
    // relative to the file's folder, or (a string a module hands to the document) to the site's root
    const check = (from, ref, ok = (t) => onDisk.has(t)) => {
      const t = target(from, ref);
      if (t !== null && !ok(t) && !ok(target("index.html", ref))) missing.push(`${from}: ${ref}`);
    };
    const maps = new Map();
    for (const f of served.filter((f) => f.endsWith(".html"))) {
      const html = read(f);
      for (const m of html.matchAll(/\s(?:src|href)=["']([^"']+)["']/g)) check(f, m[1]);
      // a saved solution (scripts/prerender.mjs) is a fragment that goes into index.html: no head of its own
      if (f.startsWith("prerender/")) continue;
      const json = /<script type="importmap">([^<]*)<\/script>/.exec(html);
      assert.ok(json, `${f} has an import map`);
      const { imports } = JSON.parse(json[1]);
      for (const [logical, name] of Object.entries(imports)) {
        check(f, name);
        maps.set(target(f, logical), target(f, name));
      }
      // the CSP admits the import map and nothing else inline
      const csp = /script-src ([^;"]*)/.exec(html)[1];
      for (const m of html.matchAll(/<script(?: type="importmap")?>([^<]*)<\/script>/g)) {
        assert.ok(csp.includes(`'sha256-${crypto.createHash("sha256").update(m[1]).digest("base64")}'`), `${f}: inline script admitted by the CSP`);
      }
    }
    // workers and the stable entries run without the import map: their names must exist as written
    const noMap = new Set(STABLE);
    for (const f of served.filter((f) => /\.m?js$/.test(f))) {
      for (const m of read(f).matchAll(/new\s+Worker\s*\(\s*new\s+URL\s*\(\s*["'`]([^"'`]+)["'`]/g)) noMap.add(target(f, m[1]));
    }
    for (const f of served.filter((f) => /\.m?js$/.test(f))) {
      const source = read(f);
      // relative paths to a file of ours: "./x.js", "../x.css", 'x_bg.wasm' in new URL(…, import.meta.url)
      const refs = [
        // (not a key of the wasm's import object: { "./x_bg.js": import0 })
        ...[...source.matchAll(/["'`]((?:\.{1,2}\/)[\w@~.\/-]+\.(?:m?js|wasm|css|json|woff2?|png|jpe?g|svg))["'`](?!\s*:)/g)].map((m) => m[1]),
        ...[...source.matchAll(/new URL\(\s*["'`]([\w@~.\/-]+)["'`]\s*,\s*import\.meta\.url/g)].map((m) => m[1]),
      ];
      for (const ref of refs) check(f, ref, (t) => onDisk.has(t) || (!noMap.has(f) && maps.has(t) && onDisk.has(maps.get(t))));
    }
    for (const f of served.filter((f) => f.endsWith(".css"))) {
      for (const m of read(f).matchAll(/url\(\s*["']?([^"')\s]+)/g)) check(f, m[1]);
    }
    // the service worker's precache and lazy lists
    const build = JSON.parse(/^const BUILD = (.*);$/m.exec(read("sw.js"))[1]);
    for (const f of [...build.files, ...build.lazy]) if (f !== "./") check("sw.js", f);
    assert.deepEqual(missing, []);
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

  test("dist/_headers gives static hosts the same rules", () => {
    const rules = read("_headers");
    assert.match(rules, /^\/index\.html\n {2}Cache-Control: no-cache$/m);
    assert.match(rules, /^\/sw\.js\n {2}Cache-Control: no-cache$/m);
    // the saved solutions (HTML, not hashed): one rule for their folder
    assert.match(rules, /^\/prerender\/\*\n {2}Cache-Control: no-cache$/m);
    assert.doesNotMatch(rules, /^\/prerender\/[a-z]/m);
    const app = assets["app.js"];
    const covered = new RegExp(`^/(${app.replace(/\./g, "\\.")}|vendor/\\*)\\n {2}Cache-Control: public, max-age=31536000, immutable$`, "m");
    assert.match(rules, covered);
  });
});
