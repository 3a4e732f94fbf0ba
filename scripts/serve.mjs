// Serves a folder of static files on 127.0.0.1 with the right MIME types
// (application/wasm for .wasm). No dependencies. As a static host should:
// the build's .br / .gz copies when the request accepts them (Content-Encoding,
// Vary: Accept-Encoding), and long-lived caching for the content-hashed names
// (dist/assets/, as dist/_headers says), no-cache for everything else.
//   node scripts/serve.mjs [--dir dist] [--port 8080]   (PORT env also works)
// Also importable: const { url, close } = await startServer({ dir, port: 0 }).
// --isolate (or ISOLATE=1; startServer({ isolate: true })) adds the
// cross-origin isolation headers (COOP same-origin, COEP require-corp), under
// which the lab splits image-wide operators over several workers.
import http from "node:http";
import fs from "node:fs";
import path from "node:path";
import { fileURLToPath } from "node:url";

const TYPES = {
  ".html": "text/html; charset=utf-8",
  ".js": "text/javascript; charset=utf-8",
  ".mjs": "text/javascript; charset=utf-8",
  ".css": "text/css; charset=utf-8",
  ".json": "application/json; charset=utf-8",
  ".wasm": "application/wasm",
  ".svg": "image/svg+xml",
  ".png": "image/png",
  ".ico": "image/x-icon",
  ".woff2": "font/woff2",
  ".woff": "font/woff",
  ".ttf": "font/ttf",
  ".txt": "text/plain; charset=utf-8",
};

/** The build's precompressed copies, best first (scripts/site.mjs writes them). */
const ENCODINGS = [
  ["br", ".br"],
  ["gzip", ".gz"],
];

/** The encodings an Accept-Encoding header admits (q=0 refuses one). */
function accepted(header) {
  const ok = new Set();
  for (const part of String(header || "").split(",")) {
    const [name, ...params] = part.trim().toLowerCase().split(";");
    const q = params.map((p) => /^\s*q=([\d.]+)/.exec(p)).find(Boolean);
    if (name && !(q && Number(q[1]) === 0)) ok.add(name);
  }
  return ok;
}

/** The folder of content-hashed names (scripts/site.mjs ASSETS): cached for a year. */
const HASHED = "/assets/";

const ISOLATION = { "cross-origin-opener-policy": "same-origin", "cross-origin-embedder-policy": "require-corp" };

export function startServer({ dir = "dist", port = 8080, host = "127.0.0.1", isolate = false } = {}) {
  const root = path.resolve(dir);
  const server = http.createServer((req, res) => {
    let pathname;
    try {
      pathname = decodeURIComponent(new URL(req.url, "http://x").pathname);
    } catch {
      res.writeHead(400).end("bad request");
      return;
    }
    if (pathname.endsWith("/")) pathname += "index.html";
    const file = path.join(root, pathname);
    if (file !== root && !file.startsWith(root + path.sep)) {
      res.writeHead(403).end("forbidden");
      return;
    }
    const type = TYPES[path.extname(file).toLowerCase()] || "application/octet-stream";
    const headers = {
      "content-type": type,
      "cache-control": pathname.startsWith(HASHED) ? "public, max-age=31536000, immutable" : "no-cache",
    };
    const wanted = accepted(req.headers["accept-encoding"]);
    const copies = ENCODINGS.filter(([name, ext]) => fs.existsSync(file + ext));
    if (copies.length) headers.vary = "Accept-Encoding";
    const copy = copies.find(([name]) => wanted.has(name));
    fs.readFile(copy ? file + copy[1] : file, (err, data) => {
      if (err) {
        res.writeHead(404, { "content-type": "text/plain; charset=utf-8" }).end("not found");
        return;
      }
      if (copy) headers["content-encoding"] = copy[0];
      res.writeHead(200, isolate ? { ...headers, ...ISOLATION } : headers);
      res.end(data);
    });
  });
  return new Promise((resolve, reject) => {
    server.once("error", reject);
    server.listen(port, host, () => {
      const { port: p } = server.address();
      resolve({
        url: `http://${host}:${p}/`,
        port: p,
        close: () => new Promise((r) => server.close(() => r())),
      });
    });
  });
}

if (process.argv[1] && fileURLToPath(import.meta.url) === path.resolve(process.argv[1])) {
  const args = process.argv.slice(2);
  const arg = (name) => {
    const i = args.indexOf(name);
    return i >= 0 ? args[i + 1] : undefined;
  };
  const dir = arg("--dir") || "dist";
  const port = Number(arg("--port") || process.env.PORT || 8080);
  if (!fs.existsSync(path.join(dir, "index.html"))) {
    console.error(`serve: ${dir}/index.html is missing; run "npm run build" first`);
    process.exit(1);
  }
  const isolate = args.includes("--isolate") || process.env.ISOLATE === "1";
  startServer({ dir, port, isolate }).then(
    ({ url }) => console.log(`Photogrammetry Playground: ${url}${isolate ? " (cross-origin isolated)" : ""}  (Ctrl+C to stop)`),
    (e) => {
      console.error(`serve: cannot listen on port ${port}: ${e.message} (set PORT or --port)`);
      process.exit(1);
    },
  );
}
