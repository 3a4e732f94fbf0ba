// Runs before the page paints (a classic script in <head>, inlined by the
// build, after preload-route.js so the example's requests start first):
//  - the theme option of the address (theme=light|dark) becomes
//    <html data-theme>, so a dark embed never flashes white. theme.css reads
//    it; without it the system setting rules.
//  - the remembered "Show API names" choice (app.js, API_NAMES_KEY) becomes
//    <html class="show-api">: read here, while the page waits for its files,
//    because a page's first localStorage read opens the storage (2–3 ms that
//    would otherwise fall between the solver's arrival and the first solution).
(function () {
  var m = /[?&]theme=(light|dark|auto)(?:&|$)/.exec(location.hash);
  if (m && m[1] !== "auto") document.documentElement.setAttribute("data-theme", m[1]);
  try {
    if (localStorage.getItem("photogrammetry-playground:show-api-names") === "1") document.documentElement.classList.add("show-api");
  } catch (e) {
    // no storage (a sandboxed frame, private mode): names hidden
  }
})();
