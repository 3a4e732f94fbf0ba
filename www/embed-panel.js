// "Embed this": both snippets for the current inputs and options (the worked
// example, or its practice mode), copy buttons, a live preview whose measured
// height the iframe form takes, how the script form talks to the course page,
// and notes for the usual course platforms. The panel is plain content under
// the tools (no dialog, so no focus trap).

import { el } from "./dom.js";
import { NAMESPACE, VERSION } from "./embed-bridge.js";
import { PARTS } from "./embed-options.js";
import { buildHash } from "./url.js";
import { siteTitle } from "./site.js";

const DEFAULT_HEIGHT = 900;
const PREVIEW_ID = "embed-preview";
/** A practice code as practice() writes it (a version digit and four Crockford letters). */
const CODE_RE = /^[0-9][0-9A-HJKMNP-TV-Z]{4}$/;

/** The query of an embed: the example with its inputs, or its practice mode (a variant code, or a fresh one). */
function embedQuery(id, texts, options) {
  if (!options.practice) return texts;
  return [["practice", options.code && CODE_RE.test(options.code) ? options.code : ""]];
}

let panel = null;

/**
 * The snippets for an example, its input texts and options ({ theme, hide[],
 * steps, lock, step, practice, code }); `height` is the preview's measured
 * height, written as it is into the iframe form.
 */
export function snippets({ base, id, title, texts, options, height = DEFAULT_HEIGHT }) {
  const embedJs = new URL("embed.js", base).href;
  const own = embedQuery(id, texts, options);
  // "gsd?dpi=1200", "gsd?practice" (a fresh variant for each reader), "gsd?practice=1K7Q2"
  const query = buildHash(id, own).slice(2).replace(/practice=$/, "practice");
  const attrs = [];
  const params = [];
  if (options.theme && options.theme !== "auto") {
    attrs.push(`data-theme="${options.theme}"`);
    params.push(["theme", options.theme]);
  }
  if (options.practice) {
    // practice has its own page: the example's parts, folds and lock do not apply
  } else if (options.hide?.length) {
    attrs.push(`data-hide="${options.hide.join(",")}"`);
    params.push(["hide", options.hide.join(",")]);
  }
  if (!options.practice && options.steps === "collapsed") {
    attrs.push('data-steps="collapsed"');
    params.push(["steps", "collapsed"]);
  }
  if (!options.practice && options.lock) {
    attrs.push('data-lock="true"');
    params.push(["lock", "true"]);
  }
  if (!options.practice && options.step) {
    attrs.push(`data-step="${options.step}"`);
    params.push(["step", String(options.step)]);
  }
  // an open sweep (www/sweep/): the embed opens with the same plot
  if (!options.practice && options.sweep) {
    attrs.push(`data-sweep="${options.sweep}"`);
    params.push(["sweep", options.sweep]);
    if (options.plot) {
      attrs.push(`data-plot="${options.plot}"`);
      params.push(["plot", options.plot]);
    }
    if (options.grid) {
      attrs.push(`data-grid="${options.grid}"`);
      params.push(["grid", options.grid]);
    }
  }
  const attrText = (s) => s.replace(/&/g, "&amp;").replace(/"/g, "&quot;").replace(/</g, "&lt;");
  const script = `<script src="${attrText(embedJs)}" defer></script>\n<div data-playground="${attrText(query)}"${attrs.length ? ` ${attrs.join(" ")}` : ""}></div>`;
  const src = new URL(`embed.html${buildHash(id, [...own, ...params]).replace(/practice=(&|$)/, "practice$1")}`, base).href;
  const h = Math.round(height);
  const frameTitle = siteTitle(options.practice ? `Practice: ${title}` : title);
  const iframe = `<iframe src="${attrText(src)}" title="${attrText(frameTitle)}" loading="lazy" allow="clipboard-write" width="100%" height="${h}" style="width:100%;height:${h}px;border:0"></iframe>`;
  return { script, iframe, src, height: h };
}

const NOTES = [
  ["Moodle", "In a Page or a Label, switch the Atto/TinyMCE editor to HTML and paste the iframe form (Moodle strips scripts for most roles). It keeps the height above: pick one that fits the example."],
  ["Canvas", "In the Rich Content Editor choose HTML Editor and paste the iframe form. Canvas listens for the embed's lti.frameResize message, so the frame grows and shrinks with the content."],
  ["WordPress", "Administrators can paste the script form into a Custom HTML block; editors and authors cannot save scripts, so use the iframe form there."],
  ["Quarto / Jupyter Book", "Paste either form into a raw HTML block (```{=html} in Quarto, a {raw} html cell or a .. raw:: html directive in Jupyter Book); the script form sizes itself."],
];

function copyField(label, name, rows) {
  const area = el("textarea", { class: "snippet", readonly: true, rows: String(rows), "aria-label": label, "data-snippet": name });
  const status = el("span", { class: "snippet-status", role: "status" });
  const copy = el("button", { type: "button", class: "button", "data-copy": name }, `Copy ${label.toLowerCase()}`);
  copy.addEventListener("click", async () => {
    try {
      await navigator.clipboard.writeText(area.value);
      status.textContent = "Copied.";
    } catch {
      area.focus();
      area.select();
      status.textContent = "Selected: press Ctrl+C (⌘C) to copy.";
    }
  });
  return { area, block: el("div", { class: "snippet-block" }, el("h4", {}, label), area, el("div", { class: "snippet-actions" }, copy, status)) };
}

function optionControls(state, onChange) {
  const what = el(
    "select",
    { id: "embed-what" },
    el("option", { value: "example" }, "the worked example, these inputs"),
    el("option", { value: "practice" }, "practice: own numbers per student"),
    el("option", { value: "variant" }, "practice: one variant for the class"),
  );
  what.value = state.practice ? (state.code ? "variant" : "practice") : "example";
  const code = el("input", { id: "embed-code", type: "text", class: "embed-code", autocomplete: "off", spellcheck: "false", maxlength: "5", placeholder: "1K7Q2", value: state.code ?? "", "aria-describedby": "embed-code-help" });
  const codeRow = el(
    "div",
    { class: "embed-code-row", hidden: what.value !== "variant" },
    el("label", { for: "embed-code" }, "Variant code "),
    code,
    el("span", { id: "embed-code-help", class: "muted" }, " the code a practice page shows (“Variant 1K7Q2”)"),
  );
  const exampleOnly = el("fieldset", { class: "embed-example-options", disabled: state.practice }, el("legend", {}, "The example's options"));
  const sync = () => {
    const kind = what.value;
    codeRow.hidden = kind !== "variant";
    exampleOnly.disabled = kind !== "example";
    const c = code.value.trim().toUpperCase();
    onChange({ practice: kind !== "example", code: kind === "variant" && CODE_RE.test(c) ? c : null });
  };
  what.addEventListener("change", sync);
  code.addEventListener("input", () => {
    if (code.value.trim().length === 5 || code.value.trim() === "") sync();
  });
  const theme = el("select", { id: "embed-theme" }, ["auto", "light", "dark"].map((t) => el("option", { value: t }, t)));
  theme.value = state.theme;
  theme.addEventListener("change", () => onChange({ theme: theme.value }));
  const parts = el("fieldset", { class: "embed-parts" }, el("legend", {}, "Parts shown"));
  for (const p of PARTS) {
    const box = el("input", { type: "checkbox", value: p, checked: !state.hide.includes(p) });
    box.addEventListener("change", () => onChange({ hide: PARTS.filter((q) => !parts.querySelector(`input[value="${q}"]`).checked) }));
    parts.append(el("label", { class: "embed-check" }, box, ` ${p}`));
  }
  const collapsed = el("input", { type: "checkbox", id: "embed-collapsed", checked: state.steps === "collapsed" });
  collapsed.addEventListener("change", () => onChange({ steps: collapsed.checked ? "collapsed" : "open" }));
  const lock = el("input", { type: "checkbox", id: "embed-lock", checked: state.lock });
  lock.addEventListener("change", () => onChange({ lock: lock.checked }));
  const step = el("input", { type: "number", id: "embed-step", min: "1", step: "1", inputmode: "numeric", value: state.step ?? "" });
  step.addEventListener("change", () => {
    const n = Number(step.value);
    onChange({ step: Number.isInteger(n) && n >= 1 ? n : null });
  });
  exampleOnly.append(
    parts,
    el("label", { class: "embed-check" }, collapsed, " steps folded"),
    el("label", { class: "embed-check" }, lock, " inputs locked"),
    el("label", { for: "embed-step" }, "Start at step "),
    step,
  );
  return el(
    "div",
    { class: "embed-options" },
    el("div", { class: "embed-what-row" }, el("label", { for: "embed-what" }, "Embed "), what),
    codeRow,
    el("label", { for: "embed-theme" }, "Theme "),
    theme,
    exampleOnly,
  );
}

/** How the script form talks to the course page: the events and the state calls (README, "Events and state"). */
function howTo() {
  const code = (text) => el("code", {}, text);
  return el(
    "details",
    { class: "embed-howto", id: "embed-howto" },
    el("summary", {}, "How the script form talks to your page"),
    el(
      "ul",
      {},
      el("li", {}, "It sizes its frame to the content, also when a hidden tab, accordion or ", code("<details>"), " opens."),
      el("li", {}, "It dispatches ", code("playground:ready"), ", ", code("playground:change"), " (", code("detail.example"), ", ", code("inputs"), ", ", code("texts"), ", ", code("result"), "), ", code("playground:error"), " and ", code("playground:resize"), " on the placeholder element."),
      el("li", {}, code("el.playground.getState()"), " returns the inputs and the result; ", code("el.playground.setState({ dpi: 600 })"), " solves with new inputs."),
      el("li", {}, "A practice embed posts ", code("photogrammetry-playground:answer"), " (", code("box"), ", ", code("verdict"), ", ", code("score"), ", ", code("out_of"), ") each time a student checks a box."),
      el("li", {}, code("data-id"), " names the embed in every event; the other ", code("data-"), " attributes are the options above or inputs (", code('data-dpi="1200"'), ")."),
    ),
  );
}

/** Opens or closes the panel under `bar` for the view on screen. */
export function toggleEmbedPanel(view, button, bar) {
  if (panel && panel.view === view && panel.node.isConnected) {
    panel.close();
    return;
  }
  panel?.close();
  const state = { theme: "auto", hide: [], steps: "open", lock: false, step: null, practice: false, code: null, height: DEFAULT_HEIGHT, measured: false };
  const base = new URL(".", location.href.split("#")[0]).href;
  const script = copyField("Script form", "script", 4);
  const iframe = copyField("Iframe form", "iframe", 5);
  // not lazy: the preview is what measures the height the iframe form writes
  const preview = el("iframe", { class: "embed-preview", title: `Preview of the embedded ${view.entry.title}` });
  const heightNote = el("p", { class: "muted embed-height" });
  const refresh = ({ reload = true } = {}) => {
    // the sweep open on the page, as its link writes it (sweep=…&plot=…)
    const sweep = view.sweep?.linkEntries() ?? {};
    const s = snippets({ base, id: view.id, title: view.entry.title, texts: view.form.entries(), options: { ...state, sweep: sweep.sweep ?? null, plot: sweep.plot ?? null, grid: sweep.grid ?? null }, height: state.height });
    script.area.value = s.script;
    iframe.area.value = s.iframe;
    heightNote.textContent = state.measured
      ? `The preview below measures ${s.height} px at this width; the iframe form writes height="${s.height}" (a narrower column is taller: where the host cannot resize the frame, check it there).`
      : `Measuring the preview… until it reports, the iframe form writes ${s.height} px.`;
    if (reload) {
      state.measured = false;
      preview.src = `${s.src}${s.src.includes("?") ? "&" : "?"}id=${PREVIEW_ID}`;
    }
  };
  const onMessage = (e) => {
    if (e.source !== preview.contentWindow || e.origin !== location.origin) return;
    const d = e.data;
    if (!d || d.type !== `${NAMESPACE}:resize` || d.version !== VERSION || d.id !== PREVIEW_ID) return;
    const h = Number(d.height);
    if (!Number.isFinite(h)) return;
    state.height = Math.min(Math.max(Math.round(h), 100), 20000);
    state.measured = true;
    preview.style.height = `${state.height}px`;
    refresh({ reload: false });
  };
  window.addEventListener("message", onMessage);
  const onSolved = () => refresh();
  window.addEventListener("playground-solved", onSolved);
  const notes = el("ul", { class: "embed-notes" }, NOTES.map(([name, text]) => el("li", {}, el("strong", {}, `${name}: `), text)));
  const doc = howTo();
  // the page routes on its hash: the link opens the section below and moves there itself
  const howToLink = el("a", { href: "#embed-howto", class: "embed-howto-link" }, "how it talks to your page");
  howToLink.addEventListener("click", (e) => {
    e.preventDefault();
    doc.open = true;
    doc.scrollIntoView({ block: "start" });
    doc.querySelector("summary").focus();
  });
  const node = el(
    "section",
    { class: "embed-panel", "aria-labelledby": "embed-h" },
    el("h4", { id: "embed-h" }, "Embed this example in a course page"),
    el("p", {}, "The script form sizes itself and tells your page about changes (", howToLink, "); the iframe form works where scripts are stripped."),
    optionControls(state, (changes) => {
      Object.assign(state, changes);
      refresh();
    }),
    script.block,
    iframe.block,
    doc,
    el("h4", {}, "Platforms"),
    notes,
    el("h4", {}, "Live preview"),
    heightNote,
    // the preview scrolls inside the panel: reachable by keyboard, and named
    el("div", { class: "embed-preview-box", tabindex: "0", role: "region", "aria-label": "Live preview of the embed (scrolls)" }, preview),
  );
  bar.after(node);
  refresh();
  button.setAttribute("aria-expanded", "true");
  panel = {
    view,
    node,
    close() {
      window.removeEventListener("message", onMessage);
      window.removeEventListener("playground-solved", onSolved);
      node.remove();
      button.setAttribute("aria-expanded", "false");
      panel = null;
    },
  };
}
