/*! Photogrammetry Playground embed: <script src=".../embed.js" defer></script>
 * <div data-playground="gsd?dpi=1200" data-theme="auto"></div> becomes a titled,
 * lazy-loading iframe that takes its content's height. Every other data-
 * attribute (theme, hide, show, steps, lock, step, id, or an input) goes into
 * the link; the playground validates it and shows a notice for what it ignores.
 * Events: "playground:ready|change|error|resize" (CustomEvent, detail = the
 * message) on the placeholder; el.playground.getState(), .setState(inputs). */
(function () {
  "use strict";
  var NS = "photogrammetry-playground:";
  var MIN = 60, MAX = 20000;
  var script = document.currentScript;
  if (!script || window.PhotogrammetryPlayground) return;
  var base = new URL("embed.html", script.src);
  var origin = base.origin;
  var frames = [];
  var count = 0;

  function send(rec, event, extra) {
    var msg = { type: NS + event, version: 1, id: rec.id };
    for (var k in extra) msg[k] = extra[k];
    if (rec.frame.contentWindow) rec.frame.contentWindow.postMessage(msg, origin);
  }

  function mount(el) {
    if (el.playground) return el.playground;
    var spec = String(el.getAttribute("data-playground") || "").replace(/^[#/]+/, "");
    var q = spec.indexOf("?");
    var params = new URLSearchParams(q < 0 ? "" : spec.slice(q + 1));
    var id = el.getAttribute("data-id") || "playground-" + ++count;
    for (var i = 0; i < el.attributes.length; i++) {
      var a = el.attributes[i].name;
      if (a.indexOf("data-") === 0 && a !== "data-playground" && a !== "data-id" && a !== "data-title")
        params.set(a.slice(5), el.attributes[i].value);
    }
    params.set("id", id);
    if (/^https?:/.test(location.origin)) params.set("host", location.origin);
    var frame = document.createElement("iframe");
    frame.src = base.href + "#/" + (q < 0 ? spec : spec.slice(0, q)) + "?" + params.toString();
    frame.title = el.getAttribute("data-title") || "Worked example: " + (q < 0 ? spec : spec.slice(0, q)) + " (Photogrammetry Playground)";
    frame.loading = "lazy";
    frame.allow = "clipboard-write";
    frame.setAttribute("style", "display:block;width:100%;border:0;height:480px");
    var rec = { el: el, frame: frame, id: id, state: null, shown: false, title: !el.getAttribute("data-title") };
    el.textContent = "";
    el.appendChild(frame);
    frames.push(rec);
    var measure = function () {
      var visible = frame.offsetWidth > 0;
      if (visible && !rec.shown) send(rec, "measure", {});
      rec.shown = visible;
    };
    rec.measure = measure;
    if (window.ResizeObserver) new ResizeObserver(measure).observe(el);
    if (window.IntersectionObserver)
      new IntersectionObserver(function (es) {
        if (es[es.length - 1].isIntersecting) { rec.shown = false; measure(); }
      }).observe(frame);
    el.playground = rec.api = {
      iframe: frame,
      getState: function () { return rec.state && JSON.parse(JSON.stringify(rec.state)); },
      setState: function (inputs) { send(rec, "set-state", { inputs: inputs }); }
    };
    return rec.api;
  }

  window.addEventListener("message", function (e) {
    var d = e.data, rec = null;
    for (var i = 0; i < frames.length; i++) if (frames[i].frame.contentWindow === e.source) rec = frames[i];
    if (!rec || e.origin !== origin || !d || typeof d !== "object" || d.version !== 1 || d.id !== rec.id) return;
    if (typeof d.type !== "string" || d.type.indexOf(NS) !== 0) return;
    var ev = d.type.slice(NS.length);
    if (ev === "resize") {
      var h = Math.round(Number(d.height));
      if (!isFinite(h)) return;
      rec.frame.style.height = Math.min(Math.max(h, MIN), MAX) + "px";
    } else if (ev === "ready" || ev === "change") {
      rec.state = { example: d.example, inputs: d.inputs, texts: d.texts, result: d.result };
      if (rec.title && typeof d.title === "string") rec.frame.title = d.title.slice(0, 200) + " (Photogrammetry Playground)";
    } else if (ev !== "error") return;
    rec.el.dispatchEvent(new CustomEvent("playground:" + ev, { detail: d, bubbles: true }));
  });

  function scan(root) {
    var list = (root || document).querySelectorAll("[data-playground]");
    for (var i = 0; i < list.length; i++) mount(list[i]);
  }
  // a hidden tab, an accordion or <details> that opens: measure again
  document.addEventListener("visibilitychange", function () {
    if (!document.hidden) for (var i = 0; i < frames.length; i++) send(frames[i], "measure", {});
  });
  document.addEventListener("toggle", function () {
    for (var i = 0; i < frames.length; i++) { frames[i].shown = false; frames[i].measure(); }
  }, true);
  window.PhotogrammetryPlayground = { mount: mount, scan: scan };
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", function () { scan(); });
  else scan();
})();
