// Writes the build's version and file list into dist/sw.js (see www/sw.js):
//   node scripts/sw-manifest.mjs [dist]
// Run by scripts/assets.mjs after it has given the files their hashed names,
// so the precache list holds the names the page asks for.
// The version is a hash of every file's path and bytes, so any change to the
// site makes a new service worker, and an unchanged rebuild keeps the old one.
import crypto from "node:crypto";
import fs from "node:fs";
import path from "node:path";

const dist = path.resolve(process.argv[2] || "dist");
const sw = path.join(dist, "sw.js");

function walk(dir) {
  return fs.readdirSync(dir, { withFileTypes: true }).flatMap((d) => {
    const p = path.join(dir, d.name);
    return d.isDirectory() ? walk(p) : [p];
  });
}

const files = walk(dist)
  .map((p) => path.relative(dist, p).split(path.sep).join("/"))
  // not the worker itself, nor the precompressed copies and the host's rules (scripts/assets.mjs)
  .filter((f) => f !== "sw.js" && f !== "_headers" && f !== "assets.json" && !/\.(gz|br)$/.test(f))
  .sort();
const hash = crypto.createHash("sha256");
for (const f of files) {
  hash.update(f);
  hash.update("\0");
  hash.update(fs.readFileSync(path.join(dist, f)));
}
const version = hash.digest("hex").slice(0, 16);
const source = fs.readFileSync(sw, "utf8");
const marker = /^const BUILD = \{ version: "dev", files: \[\] \};.*$/m;
if (!marker.test(source)) throw new Error("sw-manifest: the BUILD line of sw.js is missing");
// Cached at install: the page and every topic's module (pkg/<topic>*: any
// example works offline after the first visit). Cached when first used, not on
// every first visit: the lab (its wasm and sample photos, about 1 MB),
// pkg/all* (every example again plus practice, about 310 KB gzipped; loaded
// by practice mode and the one-package API), and the seed answers the build
// saved (prerender/: 52 files, about 33 KB gzipped in all, each shown only
// while its example's module loads, which the offline copy serves at once).
const lazy = (f) => f.startsWith("lab/") || f.startsWith("prerender/") || /^pkg\/all(_bg)?(\.[0-9a-f]{8})?\.(wasm|js)$/.test(f);
const line = `const BUILD = ${JSON.stringify({ version, files: ["./", ...files.filter((f) => !lazy(f))], lazy: files.filter(lazy) })};`;
fs.writeFileSync(sw, source.replace(marker, () => line));
fs.writeFileSync(path.join(dist, "version.json"), `${JSON.stringify({ version, files: files.length })}\n`);
console.log(`sw-manifest: version ${version}, ${files.length} files`);
