// The README and docs/*.md link only to what exists: every relative link
// ([text](path), ![alt](path), [name]: path, <img src="…">, <a href="…">)
// outside code names a file or folder of the repository, and a #fragment
// names a heading of the Markdown file it points to (GitHub's anchors).
import { describe, it } from "node:test";
import assert from "node:assert/strict";
import fs from "node:fs";
import path from "node:path";
import { read, ROOT } from "./rules-lib.mjs";

/** README.md and docs/**.md, repository-relative. */
export function markdownFiles() {
  const out = ["README.md"];
  const walk = (rel) => {
    for (const e of fs.readdirSync(path.join(ROOT, rel), { withFileTypes: true })) {
      const p = `${rel}/${e.name}`;
      if (e.isDirectory()) walk(p);
      else if (e.name.endsWith(".md")) out.push(p);
    }
  };
  walk("docs");
  return out.sort();
}

/** Markdown without fenced code blocks (kept line for line). */
function withoutFences(text) {
  return text.replace(/^(```|~~~)[^\n]*\n[\s\S]*?^\1[^\n]*$/gm, (m) => m.replace(/[^\n]/g, " "));
}

/** Markdown without fenced code blocks and inline code (kept line for line). */
function withoutCode(text) {
  return withoutFences(text).replace(/(`+)[^`\n][\s\S]*?\1/g, (m) => m.replace(/[^\n]/g, " "));
}

/** The links of a Markdown text: [{ target, line }]. */
export function linksOf(text) {
  const body = withoutCode(text);
  const out = [];
  const add = (target, index) => out.push({ target: target.trim().replace(/^<|>$/g, ""), line: body.slice(0, index).split("\n").length });
  for (const m of body.matchAll(/!?\[(?:[^\]\\]|\\.)*\]\(\s*(<[^>]*>|[^)\s]+)(?:\s+"[^"]*")?\s*\)/g)) add(m[1], m.index);
  for (const m of body.matchAll(/^\s{0,3}\[[^\]]+\]:\s*(\S+)/gm)) add(m[1], m.index);
  for (const m of body.matchAll(/<(?:img|a|source)\b[^>]*?\b(?:src|href)\s*=\s*"([^"]+)"/gi)) add(m[1], m.index);
  return out;
}

/** GitHub's anchor for a heading text. */
export function slug(heading) {
  return heading
    .trim()
    .toLowerCase()
    .replace(/<[^>]+>/g, "")
    .replace(/[`*~]/g, "")
    .replace(/\[([^\]]*)\]\([^)]*\)/g, "$1")
    .replace(/[^\p{L}\p{N}\s_-]/gu, "")
    .replace(/\s/g, "-");
}

/** The anchors of a Markdown file's headings (a repeated heading gets -1, -2 …). */
export function anchorsOf(text) {
  const seen = new Map();
  const out = new Set();
  for (const m of withoutFences(text).matchAll(/^#{1,6}\s+(.+?)\s*#*\s*$/gm)) {
    const base = slug(m[1]);
    const n = seen.get(base) ?? 0;
    seen.set(base, n + 1);
    out.add(n ? `${base}-${n}` : base);
  }
  return out;
}

/** The links that do not resolve: ["file:line target (why)", …]. */
export function brokenLinks(files = markdownFiles()) {
  const broken = [];
  for (const file of files) {
    const text = read(file);
    for (const { target, line } of linksOf(text)) {
      if (/^[a-z][a-z0-9+.-]*:/i.test(target) || target.startsWith("//")) continue; // https:, mailto:, …
      const [rawPath, fragment] = target.split("#");
      const rel = decodeURIComponent(rawPath);
      const abs = rel ? path.resolve(ROOT, path.dirname(file), rel) : path.join(ROOT, file);
      if (!abs.startsWith(ROOT + path.sep) && abs !== ROOT) {
        broken.push(`${file}:${line} ${target} (outside the repository)`);
      } else if (!fs.existsSync(abs)) {
        broken.push(`${file}:${line} ${target} (no such file)`);
      } else if (fragment && abs.endsWith(".md") && !anchorsOf(fs.readFileSync(abs, "utf8")).has(fragment)) {
        broken.push(`${file}:${line} ${target} (no heading #${fragment})`);
      }
    }
  }
  return broken;
}

describe("rules: the docs' links resolve", () => {
  it("reads links and anchors as GitHub does (small cases)", () => {
    const md = "# The JS API\n## `solve(id)` → Solution\nSee [a](docs/a.md#x) and ![p](img/p.png \"t\").\n`[not](a link)`\n```\n[nor](this)\n```\n[ref]: ./b.md\n<img src=\"c.png\" alt=\"\">\n## The lab (`scripts/bench_lab.mjs`)";
    assert.deepEqual(
      linksOf(md).map((l) => `${l.line} ${l.target}`),
      ["3 docs/a.md#x", "3 img/p.png", "8 ./b.md", "9 c.png"],
    );
    assert.deepEqual([...anchorsOf(md)], ["the-js-api", "solveid--solution", "the-lab-scriptsbench_labmjs"]);
  });

  it("README.md and docs/*.md link only to files and headings that exist", () => {
    const files = markdownFiles();
    assert.ok(files.includes("README.md") && files.length > 3, `read ${files.join(", ")}`);
    const broken = brokenLinks(files);
    assert.deepEqual(broken, [], `links that do not resolve:\n${broken.join("\n")}`);
  });
});
