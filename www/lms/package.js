// A SCORM package as a zip, made in the browser (fflate's zipSync; nothing is
// uploaded): the given files plus the imsmanifest.xml that lists them all.

import { strToU8, zipSync } from "fflate";
import { manifestXml } from "./manifest.js";

/**
 * The zip's bytes. `files`: { "relative/path": Uint8Array | string }, the
 * launch page among them; the manifest is written from exactly these paths.
 */
export function scormZip({ version = "1.2", identifier, title, launch, passing = null, files }) {
  const paths = Object.keys(files).sort();
  for (const p of paths) {
    if (!p || p.startsWith("/") || p.split("/").some((part) => part === ".." || part === "." || part === "")) throw new Error(`files: "${p}" is not a relative path inside the package`);
    if (p === "imsmanifest.xml") throw new Error("files: the manifest is written by scormZip, not given");
  }
  const entries = { "imsmanifest.xml": strToU8(manifestXml({ version, identifier, title, launch, files: paths, passing })) };
  // files that are compressed already (woff2 fonts, PNG, JPEG) are stored, the rest deflated
  for (const p of paths) {
    const data = typeof files[p] === "string" ? strToU8(files[p]) : files[p];
    entries[p] = /\.(woff2?|png|jpe?g|gif|webp|zip)$/i.test(p) ? [data, { level: 0 }] : data;
  }
  return zipSync(entries, { level: 9, mtime: new Date("2026-01-01T00:00:00Z") });
}
