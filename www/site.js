// The site's name, for titles, exports and the embed's frame.

export const SITE_TITLE = "Photogrammetry Playground";

/** A page title: "What — Photogrammetry Playground" (the site's name alone without `what`). */
export function siteTitle(what = "") {
  return what ? `${what} — ${SITE_TITLE}` : SITE_TITLE;
}
