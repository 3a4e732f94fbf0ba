// Registers the service worker (sw.js) after the page has loaded, and offers a
// reload when a new build is waiting (never swaps files under a running page).

import { el } from "./dom.js";

function offer(worker) {
  if (document.querySelector(".update-notice")) return;
  const button = el("button", { type: "button", class: "button" }, "Reload");
  const notice = el("div", { class: "update-notice", role: "status" }, "A new version of the playground is ready. ", button);
  button.addEventListener("click", () => {
    button.disabled = true;
    let reloading = false;
    navigator.serviceWorker.addEventListener("controllerchange", () => {
      if (reloading) return;
      reloading = true;
      location.reload();
    });
    worker.postMessage({ type: "skip-waiting" });
  });
  document.body.append(notice);
  // a class, not `html:has(.update-notice)`: a :has() over the document makes
  // every text change anywhere recalculate the document's style (2 ms a frame
  // of a figure's motion, docs/figures.md)
  document.documentElement.classList.add("has-update-notice");
}

function watch(registration) {
  if (!registration) return; // registration refused (a browser that blocks workers)
  if (registration.waiting && navigator.serviceWorker.controller) offer(registration.waiting);
  registration.addEventListener("updatefound", () => {
    const worker = registration.installing;
    if (!worker) return;
    worker.addEventListener("statechange", () => {
      if (worker.state === "installed" && navigator.serviceWorker.controller) offer(worker);
    });
  });
}

if ("serviceWorker" in navigator && (location.protocol === "https:" || location.hostname === "127.0.0.1" || location.hostname === "localhost")) {
  const register = () =>
    navigator.serviceWorker.register("./sw.js").then(watch, (e) => console.warn("offline copy not available:", e && e.message ? e.message : e));
  if (document.readyState === "complete") register();
  else window.addEventListener("load", register, { once: true });
}
