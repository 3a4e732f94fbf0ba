// Runs before the page paints (a classic script in <head>, inlined by the
// build, after preload-route.js so the example's requests start first):
//  - the theme becomes <html data-theme="light|dark"> (no attribute: the
//    system setting, prefers-color-scheme), so a dark page never flashes
//    white. theme.css reads it. On the site (index.html) the reader's own
//    choice (the header's Theme switch, shell.js, THEME_KEY) wins, else the
//    address's theme option; in the embed (embed.html) only the address's
//    option counts (the course author's choice: an embed has no switch).
//  - the remembered "Show API names" choice (app.js, API_NAMES_KEY) becomes
//    <html class="show-api">: read here, while the page waits for its files,
//    because a page's first localStorage read opens the storage (2–3 ms that
//    would otherwise fall between the solver's arrival and the first solution).
(function () {
  var root = document.documentElement;
  var m = /[?&]theme=(light|dark|auto)(?:&|$)/.exec(location.hash);
  var theme = m && m[1] !== "auto" ? m[1] : null;
  try {
    var chosen = /\/embed(\.html)?$/.test(location.pathname) ? null : localStorage.getItem("photogrammetry-playground:theme");
    if (chosen === "light" || chosen === "dark") theme = chosen;
    if (localStorage.getItem("photogrammetry-playground:show-api-names") === "1") root.classList.add("show-api");
  } catch (e) {
    // no storage (a sandboxed frame, private mode): the address or the system setting; names hidden
  }
  if (theme) root.setAttribute("data-theme", theme);
})();
