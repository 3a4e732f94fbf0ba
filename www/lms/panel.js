// "Download for your LMS" on the worksheet page: a form for the package's
// settings (SCORM version, passing score, these variants or a new one per
// learner) and the button that makes the zip in the browser.

import { el } from "../dom.js";
import { lmsStyles } from "./styles.js";
import { buildPackage, fetchBytes, packageSettings, saveFile } from "./download.js";
import { MAX_VARIANTS_12 } from "./scorm.js";

let panels = 0;

/**
 * The panel. `items`: [{ entry, variant }] of the worksheet; `title`: the
 * worksheet's; `entries`: the catalog.
 */
export function lmsPanel({ items, title, entries }) {
  lmsStyles();
  const k = ++panels;
  const id = (name) => `lms${k}-${name}`;
  const version = el("select", { id: id("version") }, el("option", { value: "1.2" }, "SCORM 1.2 (Moodle, Canvas, Brightspace, Blackboard)"), el("option", { value: "2004" }, "SCORM 2004 4th edition"));
  const fixed = el("input", { type: "radio", name: id("which"), id: id("fixed"), value: "fixed", checked: true });
  const fresh = el("input", { type: "radio", name: id("which"), id: id("fresh"), value: "fresh" });
  const passing = el("input", { id: id("passing"), type: "number", min: "0", max: "100", step: "1", value: "", inputmode: "numeric", class: "lms-passing", "aria-describedby": id("passing-help") });
  const name = el("input", { id: id("title"), type: "text", value: title, class: "lms-title" });
  const button = el("button", { type: "button", class: "button" }, "Download for your LMS");
  const status = el("p", { class: "lms-download-status", role: "status" });
  const ids = [...new Set(items.map((x) => x.entry.id))];
  const perExample = Math.max(...ids.map((i) => items.filter((x) => x.entry.id === i).length));

  button.addEventListener("click", async () => {
    status.textContent = "";
    let settings;
    try {
      settings = packageSettings({
        scorm: version.value,
        title: name.value,
        passing: passing.value.trim() === "" ? null : Number(passing.value),
        items: fixed.checked ? items.map((x) => ({ id: x.entry.id, code: x.variant.code })) : null,
        fresh: fixed.checked ? null : { ids, n: perExample },
        site: new URL("index.html", location.href).href,
        entries,
      });
    } catch (e) {
      status.textContent = `Not made: ${e.message}`;
      return;
    }
    button.disabled = true;
    status.textContent = "Making the package…";
    try {
      const topics = [...new Set(ids.map((i) => entries.find((e) => e.id === i).module))];
      const stamp = new Date().toISOString().replace(/[-:T]/g, "").slice(0, 12);
      const zip = await buildPackage({ settings, topics, base: new URL(".", location.href).href, fetchBytes, identifier: `photogrammetry-playground-${ids.join("-").slice(0, 80)}-${stamp}` });
      const file = `${name.value.trim().replace(/[^A-Za-z0-9]+/g, "-").replace(/^-|-$/g, "").toLowerCase() || "practice"}-scorm${settings.scorm.replace(".", "")}.zip`;
      saveFile(zip, file);
      status.textContent = `Made ${file} (${Math.round(zip.length / 1024)} KB). Upload it to your LMS as a SCORM package; nothing was sent anywhere.`;
      status.dataset.bytes = String(zip.length);
    } catch (e) {
      status.textContent = `The package could not be made: ${e.message}`;
    } finally {
      button.disabled = false;
    }
  });

  return el(
    "section",
    { class: "panel lms-panel ws-screen-only", "aria-labelledby": id("h") },
    el("h3", { id: id("h") }, "Download for your LMS"),
    el("p", { class: "muted" }, "A SCORM package of this worksheet's practice: each box is checked as students type, and the score goes to your course's gradebook. It is made here in your browser; nothing is uploaded."),
    el("div", { class: "lms-field" }, el("label", { for: id("title") }, "Activity title"), name),
    el("div", { class: "lms-field" }, el("label", { for: id("version") }, "Format"), version),
    el(
      "fieldset",
      { class: "lms-field" },
      el("legend", {}, "Variants"),
      el("div", {}, fixed, el("label", { for: id("fixed") }, ` These ${items.length} variants, the same for every student`)),
      el("div", {}, fresh, el("label", { for: id("fresh") }, ` A new variant for each student (${perExample} of each example)`)),
    ),
    el("div", { class: "lms-field" }, el("label", { for: id("passing") }, "Passing score (%)"), passing, el("p", { id: id("passing-help"), class: "muted" }, `Optional: with one, the LMS records passed or failed; without, completed. SCORM 1.2 keeps up to ${MAX_VARIANTS_12} variants of each example.`)),
    el("div", { class: "actions" }, button),
    status,
  );
}
