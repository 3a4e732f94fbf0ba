// The service worker: the built site, cached on the first visit, so the
// playground works offline and an embed loads at once the second time.
// scripts/sw-manifest.mjs writes BUILD at build time (the version is a hash of
// every file, the file list is dist/), so each build is a new worker whose
// cache replaces the old one. Only our own files are cached; any other
// request (another origin, a file not in the build) goes to the network as
// if there were no worker.
//
// Updates: a new worker installs beside the old one and waits; the page
// offers "Reload" (sw-register.js), which tells it to take over. The old
// worker keeps serving its own, consistent set of files until then.

const BUILD = { version: "dev", files: [] }; // replaced by scripts/sw-manifest.mjs
// BUILD.files are cached at install; BUILD.lazy (the lab) when first fetched
const PREFIX = "photogrammetry-playground-";
const CACHE = `${PREFIX}${BUILD.version}`;
const SCOPE = new URL("./", self.location.href);
const FILES = new Set(BUILD.files.map((f) => new URL(f, SCOPE).pathname));
const LAZY = new Set((BUILD.lazy ?? []).map((f) => new URL(f, SCOPE).pathname));

self.addEventListener("install", (event) => {
  if (!BUILD.files.length) return; // an unbuilt copy caches nothing
  event.waitUntil(
    caches.open(CACHE).then((cache) => cache.addAll(BUILD.files.map((f) => new Request(new URL(f, SCOPE), { cache: "reload" })))),
  );
});

self.addEventListener("activate", (event) => {
  event.waitUntil(
    caches
      .keys()
      .then((keys) => Promise.all(keys.filter((k) => k.startsWith(PREFIX) && k !== CACHE).map((k) => caches.delete(k))))
      .then(() => self.clients.claim()),
  );
});

self.addEventListener("message", (event) => {
  if (event.data && event.data.type === "skip-waiting") self.skipWaiting();
});

self.addEventListener("fetch", (event) => {
  const request = event.request;
  if (request.method !== "GET") return;
  const url = new URL(request.url);
  if (url.origin !== SCOPE.origin) return;
  let path = url.pathname;
  if (path.endsWith("/")) path += "index.html";
  if (LAZY.has(path)) {
    event.respondWith(
      caches.open(CACHE).then((cache) =>
        cache.match(path).then(
          (hit) =>
            hit ||
            fetch(request).then((response) => {
              if (response.ok) cache.put(path, response.clone());
              return response;
            }),
        ),
      ),
    );
    return;
  }
  if (!FILES.has(path)) return;
  event.respondWith(
    caches
      .open(CACHE)
      .then((cache) => cache.match(path))
      .then((hit) => hit || fetch(request)),
  );
});
