// "Download for your LMS": a SCORM package of a set of practice variants, made
// in the browser from the site's own files (dist/lms-files.json says which),
// nothing uploaded. The package's index.html is the site's page with the
// package's settings in a data block (#lms-package), which makes the page open
// as the package's practice (www/lms/launch.js) and talk to the LMS.

import { scormZip } from "./package.js";
import { MAX_VARIANTS_12 } from "./scorm.js";

/** The data block's id in the package's index.html. */
export const PACKAGE_BLOCK = "lms-package";

/**
 * The settings a package carries, checked: { scorm: "1.2"|"2004", title,
 * passing (0–100 or null), site (the playground's address, where receipts
 * are regraded), items: [{ id, code }] (fixed variants) or null with
 * `fresh: { ids, n }` (new variants at each learner's first launch) }.
 */
export function packageSettings({ scorm = "1.2", title, passing = null, items = null, fresh = null, site = null, entries }) {
  if (scorm !== "1.2" && scorm !== "2004") throw new Error(`scorm: "${scorm}" is not a SCORM version (1.2 or 2004)`);
  if (typeof title !== "string" || !title.trim()) throw new Error("title: give the activity a title");
  if (passing != null && !(Number.isFinite(passing) && passing >= 0 && passing <= 100)) throw new Error("passing: a percentage from 0 to 100, or none");
  const known = new Set(entries.filter((e) => e.practice).map((e) => e.id));
  const ids = items ? items.map((it) => it.id) : (fresh?.ids ?? []);
  if (!ids.length) throw new Error("items: the package needs at least one variant");
  for (const id of ids) if (!known.has(id)) throw new Error(`items: "${id}" is not an example with practice`);
  const perExample = items ? Math.max(...ids.map((id) => ids.filter((x) => x === id).length)) : fresh.n;
  if (scorm === "1.2" && perExample > MAX_VARIANTS_12) {
    throw new Error(`items: SCORM 1.2 keeps at most 4,096 characters of answers, enough for ${MAX_VARIANTS_12} variants an example; choose fewer variants, or SCORM 2004`);
  }
  return { scorm, title: title.trim(), passing, site, items: items ? items.map(({ id, code }) => ({ id, code })) : null, fresh: items ? null : { ids: [...fresh.ids], n: fresh.n } };
}

/** The package's index.html: the site's page with the settings block before </head>. */
export function launchPage(html, settings) {
  const json = JSON.stringify(settings).replace(/</g, "\\u003c");
  const block = `<script type="application/json" id="${PACKAGE_BLOCK}">${json}</script>\n`;
  if (!html.includes("</head>")) throw new Error("the site's index.html has no </head>");
  return html.replace("</head>", `${block}</head>`);
}

/**
 * Fetches the files the package needs from the site at `base` (the page's
 * folder URL) and returns the zip's bytes. `topics`: the topic modules of the
 * package's examples (catalog `module`); `fetchBytes(url)` → Uint8Array (the
 * page passes one around fetch; tests their own).
 */
export async function buildPackage({ settings, topics, base, fetchBytes, identifier }) {
  const list = JSON.parse(new TextDecoder().decode(await fetchBytes(new URL("lms-files.json", base).href)));
  const names = new Set(list.common);
  for (const t of topics) {
    if (!list.topics[t]) throw new Error(`topics: the site has no practice module "${t}"`);
    for (const f of list.topics[t]) names.add(f);
  }
  const files = {};
  await Promise.all(
    [...names].map(async (f) => {
      files[f] = await fetchBytes(new URL(f, base).href);
    }),
  );
  files[list.page] = launchPage(new TextDecoder().decode(files[list.page]), settings);
  return scormZip({ version: settings.scorm, identifier, title: settings.title, launch: list.page, passing: settings.passing, files });
}

/** fetch → bytes, with the URL in the error. */
export async function fetchBytes(url) {
  const r = await fetch(url, { cache: "no-cache" });
  if (!r.ok) throw new Error(`${url}: ${r.status} ${r.statusText}`);
  return new Uint8Array(await r.arrayBuffer());
}

/** Offers `bytes` as a file download named `name`. */
export function saveFile(bytes, name, type = "application/zip") {
  const url = URL.createObjectURL(new Blob([bytes], { type }));
  const a = document.createElement("a");
  a.href = url;
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 60_000);
}
