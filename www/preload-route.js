// Runs while the page's <head> is parsed (a classic script, inlined by the
// build): the example in the address starts loading its own topic's wasm, its
// wasm-bindgen JS and its figures at once, in parallel with the page's modules,
// instead of after them (issue 19: the chain catalog → module → wasm was the
// first solution's critical path). The data block before it is written by the
// build (scripts/assets.mjs, from catalog.json and the hashed names):
//   {"entries": [catalog.json], "files": {"coordinates": ["./pkg/coordinates.<hash>.js", …]}}
// core.js and figures/index.js then import and fetch the same URLs, which the
// browser serves from these preloads. Home, the lab and practice preload nothing.
(function () {
  var data = document.getElementById("catalog-data");
  var m = /^#\/?([^?]*)(\?.*)?$/.exec(location.hash);
  if (!data || !m || /[?&]practice(?:[=&]|$)/.test(m[2] || "")) return;
  var page, id, files;
  try {
    page = JSON.parse(data.textContent);
    id = decodeURIComponent(m[1]).replace(/\/+$/, "");
  } catch (e) {
    return; // the page reports a bad address itself
  }
  page.entries.forEach(function (e) {
    if (e.id === id && e.status === "ready") files = page.files[e.module];
  });
  (files || []).forEach(function (href) {
    var link = document.createElement("link");
    if (/\.wasm$/.test(href)) {
      link.rel = "preload";
      link.as = "fetch";
      link.crossOrigin = "anonymous"; // wasm-bindgen's fetch(): same-origin credentials, cors mode
    } else {
      link.rel = "modulepreload";
    }
    link.href = href;
    document.head.appendChild(link);
  });
})();
