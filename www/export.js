// Exports of one example: the figure as PNG, the numbers as JSON and CSV, the
// whole solution as a LaTeX fragment (an instructor's answer key). Pure
// builders (solutionJson, solutionCsv, solutionTex) plus the tools bar.

import { el } from "./dom.js";
import { SITE_TITLE as SITE } from "./site.js";

const STATUS_MS = 4000;

/** A file name from an example id. */
function fileName(id, ext) {
  return `${String(id).replace(/[^A-Za-z0-9_-]/g, "_")}.${ext}`;
}

/** The solution with its link, as JSON (NaN and infinities become null). */
export function solutionJson(solution, link) {
  const { id, title, inputs, result, textbook, notes, labels } = solution;
  const steps = (solution.steps ?? []).map((s) => ({ title: s.title, text: s.text, formula: s.formula, substituted: s.substituted, values: s.values }));
  return `${JSON.stringify({ generator: SITE, link, id, title, inputs, result, textbook: textbook ?? null, labels: labels ?? {}, notes, steps }, null, 2)}\n`;
}

function csvField(value) {
  const s = value === null || value === undefined ? "" : String(value);
  return /[",\n\r]/.test(s) ? `"${s.replace(/"/g, '""')}"` : s;
}

/** [[suffix, number]] for a value: "" for a number, "[2]" or "[1][3]" for list items. */
function flatten(value, suffix = "") {
  if (Array.isArray(value)) return value.flatMap((v, i) => flatten(v, `${suffix}[${i + 1}]`));
  return [[suffix, value]];
}

/**
 * One row per number: section (input, result), key with its 1-based index,
 * label, unit, exact value, the seed's printed value.
 */
export function solutionCsv(solution) {
  const rows = [["section", "key", "label", "unit", "value", "printed"]];
  const labels = solution.labels ?? {};
  const textbook = solution.textbook ?? {};
  const plain = (v) => (typeof v === "boolean" ? String(v) : v);
  for (const [key, value] of Object.entries(solution.inputs ?? {})) {
    for (const [suffix, v] of flatten(value)) rows.push(["input", key + suffix, "", "", plain(v), ""]);
  }
  for (const [key, value] of Object.entries(solution.result ?? {})) {
    const printed = Object.hasOwn(textbook, key) ? new Map(flatten(textbook[key])) : new Map();
    for (const [suffix, v] of flatten(value)) {
      rows.push(["result", key + suffix, labels[key]?.label ?? "", labels[key]?.unit ?? "", plain(v), printed.get(suffix) ?? ""]);
    }
  }
  return `${rows.map((r) => r.map(csvField).join(",")).join("\r\n")}\r\n`;
}

/** Text for LaTeX's text mode. */
export function texText(text) {
  return String(text ?? "")
    .replace(/\\/g, "\u0000")
    .replace(/([{}$&#%_])/g, "\\$1")
    .replace(/\^/g, "\\^{}")
    .replace(/~/g, "\\~{}")
    .replace(/\u0000/g, "\\textbackslash{}");
}

function texValue(value) {
  if (value === null || value === undefined) return "--";
  if (typeof value === "number") return Number.isFinite(value) ? String(Number(value.toPrecision(10))) : "--";
  if (typeof value === "boolean") return value ? "yes" : "no";
  if (Array.isArray(value)) {
    if (value.every(Array.isArray)) return `$\\begin{bmatrix}${value.map((r) => r.map(texValue).join(" & ")).join(" \\\\ ")}\\end{bmatrix}$`;
    return `[${value.map(texValue).join(", ")}]`;
  }
  return texText(value);
}

/** The whole solution as a LaTeX fragment (needs amsmath; UTF-8 text). */
export function solutionTex(solution, link) {
  const lines = [
    `% ${solution.title}: the solution step by step, from the ${SITE}.`,
    `% ${link}`,
    "% A fragment: \\input it into a document that loads amsmath and amssymb;",
    "% the text is UTF-8 (Greek letters): compile with LuaLaTeX or XeLaTeX.",
    `\\subsection*{${texText(solution.title)}}`,
    "",
    "\\paragraph{Inputs}",
    "\\begin{itemize}",
    ...Object.entries(solution.inputs ?? {}).map(([k, v]) => `  \\item \\texttt{${texText(k)}} = ${texValue(v)}`),
    "\\end{itemize}",
    "",
  ];
  (solution.steps ?? []).forEach((step, i) => {
    lines.push(`\\paragraph{${i + 1}. ${texText(step.title)}}`);
    if (step.text) lines.push(texText(step.text));
    if (step.formula) lines.push("\\[", step.formula, "\\]");
    if (step.substituted) lines.push("\\[", step.substituted, "\\]");
    lines.push("");
  });
  const labels = solution.labels ?? {};
  const textbook = solution.textbook ?? null;
  lines.push("\\paragraph{Result}", "\\begin{itemize}");
  for (const [k, v] of Object.entries(solution.result ?? {})) {
    const label = labels[k]?.label ? `${texText(labels[k].label)}${labels[k].unit ? ` (${texText(labels[k].unit)})` : ""}, ` : "";
    const printed = textbook && Object.hasOwn(textbook, k) ? ` (the seed prints ${texValue(textbook[k])})` : "";
    lines.push(`  \\item ${label}\\texttt{${texText(k)}} = ${texValue(v)}${printed}`);
  }
  lines.push("\\end{itemize}");
  if ((solution.notes ?? []).length) {
    lines.push("", "\\paragraph{Notes}", "\\begin{itemize}");
    for (const n of solution.notes) lines.push(`  \\item \\textit{${texText(n.kind)}:} ${texText(n.text)}`);
    lines.push("\\end{itemize}");
  }
  return `${lines.join("\n")}\n`;
}

/** The example's canvases stacked into one PNG (a white margin between them), or null. */
export function figurePng(root) {
  const canvases = [...root.querySelectorAll(".figure-host canvas")].filter((c) => c.width > 0 && c.height > 0);
  if (!canvases.length) return Promise.resolve(null);
  const gap = Math.round(8 * (window.devicePixelRatio || 1));
  const out = document.createElement("canvas");
  out.width = Math.max(...canvases.map((c) => c.width));
  out.height = canvases.reduce((h, c) => h + c.height, 0) + gap * (canvases.length - 1);
  const ctx = out.getContext("2d");
  ctx.fillStyle = "#ffffff";
  ctx.fillRect(0, 0, out.width, out.height);
  let y = 0;
  for (const c of canvases) {
    ctx.drawImage(c, 0, y);
    y += c.height + gap;
  }
  return new Promise((resolve) => out.toBlob(resolve, "image/png"));
}

/** Saves `blob` as a file called `name` (a link clicked for the reader). */
export function download(blob, name) {
  const url = URL.createObjectURL(blob);
  const a = el("a", { href: url, download: name, hidden: true });
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

/**
 * The tools under an example: downloads, copy LaTeX, and (in the full page)
 * "Embed this". `view.lastGood` is the solution exported.
 */
export function toolsBar(view, { embedded }) {
  const status = el("p", { class: "tools-status", role: "status" });
  let timer = 0;
  const say = (text) => {
    clearTimeout(timer);
    status.textContent = text;
    timer = setTimeout(() => (status.textContent = ""), STATUS_MS);
  };
  const link = () => location.href;
  const need = () => {
    if (!view.lastGood) say("Nothing to export yet: no valid solution.");
    return view.lastGood;
  };
  const button = (label, action, attrs = {}) => {
    const b = el("button", { type: "button", class: "button keep-enabled", ...attrs }, label);
    b.addEventListener("click", action);
    return b;
  };
  const bar = el("div", { class: "tools" });
  if (!embedded) {
    const embedButton = button("Embed this…", async () => {
      const { toggleEmbedPanel } = await import("./embed-panel.js");
      toggleEmbedPanel(view, embedButton, bar);
    }, { "aria-expanded": "false", "data-tool": "embed" });
    bar.append(embedButton);
  }
  bar.append(
    button("Figure (PNG)", async () => {
      if (!need()) return;
      const blob = await figurePng(view.parts.solutionArea);
      if (blob) {
        download(blob, fileName(view.id, "png"));
        say("Figure downloaded.");
      } else say("This example has no figure to download.");
    }, { "data-tool": "png" }),
    button("Numbers (JSON)", () => {
      const s = need();
      if (s) download(new Blob([solutionJson(s, link())], { type: "application/json" }), fileName(view.id, "json"));
    }, { "data-tool": "json" }),
    button("Numbers (CSV)", () => {
      const s = need();
      if (s) download(new Blob([solutionCsv(s)], { type: "text/csv" }), fileName(view.id, "csv"));
    }, { "data-tool": "csv" }),
    button("LaTeX (.tex)", () => {
      const s = need();
      if (s) download(new Blob([solutionTex(s, link())], { type: "application/x-tex" }), fileName(view.id, "tex"));
    }, { "data-tool": "tex" }),
    button("Copy LaTeX", async () => {
      const s = need();
      if (!s) return;
      try {
        await navigator.clipboard.writeText(solutionTex(s, link()));
        say("The solution is copied as LaTeX.");
      } catch {
        say("The clipboard is not available here: use “LaTeX (.tex)” to download it.");
      }
    }, { "data-tool": "copy-tex" }),
  );
  return el("div", {}, bar, status);
}
