// Runs while the page's <head> is parsed (a classic script, inlined by the
// build): the example in the address starts loading its own topic's wasm (and
// compiling it), its wasm-bindgen JS and its figures at once, in parallel with
// the page's modules, instead of after them (issue 19: the chain catalog →
// module → wasm was the first solution's critical path). The data block before it is written by the
// build (scripts/assets.mjs, from catalog.json and the hashed names):
//   {"entries": [catalog.json], "files": {"coordinates": ["./pkg/coordinates.<hash>.js", …]}}
// core.js and figures/index.js then import the same URLs, which the browser
// serves from these preloads, and core.js takes the compiled wasm from
// window.playgroundEarlyWasm. Home, the lab and practice preload nothing.
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
  var name;
  page.entries.forEach(function (e) {
    if (e.id === id && e.status === "ready") name = e.module;
  });
  files = name ? page.files[name] : [];
  // The top of the seed's solution as the page rendered it at build time
  // (scripts/prerender.mjs: the heading and the answer line with the printed
  // values, then "Loading the solver…"; each page's own, listed in its data
  // block as { folder, ids, options }), for an address with no inputs (view
  // options only): shown, inert, as soon as it and the <main> are here, and
  // marked as the first solution on screen; app.js's own view replaces it
  // (the whole solution, its inputs live) as soon as the solver is in.
  var saved = page.prerendered;
  var onlyOptions = function (query) {
    try {
      return query
        .slice(1)
        .split("&")
        .every(function (kv) {
          return !kv || saved.options.indexOf(decodeURIComponent(kv.split("=")[0])) >= 0;
        });
    } catch (e) {
      return false; // a malformed address: the page says so itself
    }
  };
  if (name && saved && saved.ids.indexOf(id) >= 0 && onlyOptions(m[2] || "")) {
    var hash = location.hash;
    var html = null;
    var show = function () {
      var app = document.getElementById("app");
      if (html === null || !app || location.hash !== hash || !app.querySelector(":scope > p.loading")) return;
      app.innerHTML = html; // the build's own HTML (no script in it: prerender.mjs checks)
      app.inert = true;
      app.setAttribute("data-prerendered", id);
      performance.mark("first-solution");
    };
    fetch(saved.folder + encodeURIComponent(id) + ".html")
      .then(function (r) {
        return r.ok ? r.text() : null;
      })
      .then(function (text) {
        html = text;
        if (document.readyState !== "loading") show();
      })
      ["catch"](function () {}); // nothing shown early: the page's own view comes as before
    document.addEventListener("readystatechange", show, { once: true });
  }
  files.forEach(function (href) {
    if (/\.wasm$/.test(href)) {
      // fetched and compiled while the page's JS loads; core.js hands the compiled
      // module to the topic's init (which would otherwise fetch it itself)
      if (typeof WebAssembly === "object" && WebAssembly.compileStreaming) {
        var compiled = WebAssembly.compileStreaming(fetch(href));
        compiled["catch"](function () {}); // a failure: core.js lets init fetch it again
        window.playgroundEarlyWasm = { module: name, compiled: compiled };
      }
      return;
    }
    var link = document.createElement("link");
    link.rel = "modulepreload";
    link.href = href;
    document.head.appendChild(link);
  });
})();
