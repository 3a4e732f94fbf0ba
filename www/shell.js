// The site's shell around the views (index.html): the header's Theme switch
// and the "Skip to the example" link (index.html and embed.html: mountSkipLink).
//
// Theme: the reader's choice (System, Light or Dark) is remembered under
// THEME_KEY and becomes <html data-theme="light|dark"> (System: no
// attribute, the system's prefers-color-scheme rules). theme-init.js applies
// it before the first paint; here the switch sets it, and it is applied
// again whenever something else set the theme: embed-page.js applies the
// address's theme option at every route (Back/Forward included) and says so
// with a "playground-theme" event; another tab may change the choice (a
// "storage" event); a page restored from the back-forward cache may be
// behind (pageshow). On the site the reader's Light or Dark wins over the
// address's option; the embed has no switch and follows its address alone.
// The figures redraw themselves when data-theme changes (www/figures/).

/** Where the reader's theme choice is kept (theme-init.js reads the same key, before the page paints). */
export const THEME_KEY = "photogrammetry-playground:theme";
const CHOICES = ["system", "light", "dark"];

/** The remembered choice: "system", "light" or "dark". */
export function storedTheme() {
  try {
    const v = localStorage.getItem(THEME_KEY);
    return CHOICES.includes(v) ? v : "system";
  } catch {
    return "system"; // no storage (private mode): the system setting
  }
}

/**
 * Shows `choice`: Light or Dark as such; System as the address's theme option
 * when it has one (a link's), else the system setting (no attribute).
 */
function applyChoice(choice) {
  const root = document.documentElement;
  const address = /[?&]theme=(light|dark)(?:&|$)/.exec(location.hash);
  const theme = choice === "light" || choice === "dark" ? choice : address ? address[1] : null;
  if (theme) root.setAttribute("data-theme", theme);
  else root.removeAttribute("data-theme");
}

/**
 * Wires the header's switch (a <select> with the values of CHOICES) and the
 * skip link. Called once, on the site's page only (the embed: mountSkipLink).
 */
export function mountShell() {
  const select = document.getElementById("theme-choice");
  if (select) {
    const sync = () => {
      select.value = storedTheme();
      applyChoice(select.value);
    };
    sync();
    select.addEventListener("change", () => {
      const choice = CHOICES.includes(select.value) ? select.value : "system";
      try {
        if (choice === "system") localStorage.removeItem(THEME_KEY);
        else localStorage.setItem(THEME_KEY, choice);
      } catch {
        // no storage: the choice lasts for this page only
      }
      applyChoice(choice);
    });
    // embed-page.js has just applied the address's option (a route, Back/Forward): the choice wins
    window.addEventListener("playground-theme", () => {
      if (storedTheme() !== "system") applyChoice(storedTheme());
    });
    // another tab changed the choice; a page restored from the back-forward cache
    window.addEventListener("storage", (e) => {
      if (e.key === THEME_KEY || e.key === null) sync();
    });
    window.addEventListener("pageshow", (e) => {
      if (e.persisted) sync();
    });
  }
  mountSkipLink();
}

/** The skip link: focuses <main> without touching the address (a hash is a route here). */
export function mountSkipLink() {
  document.addEventListener("click", (e) => {
    const link = e.target instanceof Element ? e.target.closest("a.skip-link") : null;
    if (!link) return;
    e.preventDefault();
    const main = document.querySelector("main");
    if (!main) return;
    if (!main.hasAttribute("tabindex")) main.setAttribute("tabindex", "-1");
    main.focus();
    main.scrollIntoView({ block: "start" });
  });
}
