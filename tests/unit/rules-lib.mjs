// Shared by the rules-*.test.mjs files: the repository's source files and a
// small lexer for JS and Rust that tells code from comments, string literals
// and (JS) regular-expression literals. No build needed: these tests read the
// sources only.
import fs from "node:fs";
import path from "node:path";
import { fileURLToPath } from "node:url";

export const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), "../..");

/** Folders never walked: build output, dependencies, third-party code. */
const SKIP_DIRS = new Set(["node_modules", "target", "pkg", "pkg-simd", "vendor", ".git", ".venv-bench", "data"]);

/**
 * The files under `roots` (paths from the repository root) whose names end in
 * one of `exts`, as repository-relative paths with "/" separators, sorted.
 * Folders named `tests`, files named `tests.rs`, `*.test.*` files and
 * `dist*` folders are left out unless `withTests` is set.
 */
export function sourceFiles(roots, exts, { withTests = false } = {}) {
  const out = [];
  const walk = (rel) => {
    const abs = path.join(ROOT, rel);
    if (!fs.existsSync(abs)) return;
    const stat = fs.statSync(abs);
    if (stat.isFile()) {
      const name = path.basename(rel);
      if (!exts.some((e) => name.endsWith(e))) return;
      if (!withTests && (name === "tests.rs" || /\.test\.[cm]?js$/.test(name))) return;
      out.push(rel.split(path.sep).join("/"));
      return;
    }
    for (const entry of fs.readdirSync(abs, { withFileTypes: true })) {
      if (entry.isDirectory()) {
        if (SKIP_DIRS.has(entry.name) || entry.name.startsWith("dist")) continue;
        if (!withTests && entry.name === "tests") continue;
      }
      walk(path.join(rel, entry.name));
    }
  };
  roots.forEach(walk);
  return [...new Set(out)].sort();
}

export const read = (rel) => fs.readFileSync(path.join(ROOT, rel), "utf8");

const lineAt = (text, i) => {
  let n = 1;
  for (let k = 0; k < i; k++) if (text.charCodeAt(k) === 10) n++;
  return n;
};

/** Replaces text[a, b) by spaces, keeping newlines (so line numbers stay). */
function blank(chars, a, b) {
  for (let k = a; k < b; k++) if (chars[k] !== "\n") chars[k] = " ";
}

const REGEX_AFTER_WORD = new Set(["return", "typeof", "case", "do", "else", "in", "of", "new", "delete", "void", "throw", "yield", "await", "instanceof"]);

/**
 * Lexes JavaScript. Returns
 *   strings: [{ value, quote, line, start, end }]  (quote: ", ' or ` ; a template's
 *            literal parts, each a string of its own, `expr` true when it has ${…})
 *   regexes: [{ source, flags, line, start, end }]
 *   code:    the text with comments blanked out (strings and regexes kept)
 *   bare:    the text with comments and the insides of strings and regexes blanked
 */
export function lexJs(text) {
  const strings = [];
  const regexes = [];
  const code = [...text];
  const bare = [...text];
  let i = 0;
  let prev = ""; // the last significant character of code (or a word)
  const stack = []; // open template literals: brace depth at their ${
  let depth = 0;
  const n = text.length;
  const readTemplate = (from, tail) => {
    // from: index just after the opening ` or (tail) the closing } of a ${…}
    let k = from;
    let value = "";
    while (k < n) {
      const c = text[k];
      if (c === "\\") {
        value += text.slice(k, k + 2);
        k += 2;
      } else if (c === "`") {
        strings.push({ value, quote: "`", line: lineAt(text, from), start: from, end: k, expr: tail });
        blank(bare, from, k);
        return { end: k + 1, open: false };
      } else if (c === "$" && text[k + 1] === "{") {
        strings.push({ value, quote: "`", line: lineAt(text, from), start: from, end: k, expr: true });
        blank(bare, from, k);
        return { end: k + 2, open: true };
      } else {
        value += c;
        k++;
      }
    }
    return { end: n, open: false };
  };
  while (i < n) {
    const c = text[i];
    const d = text[i + 1];
    if (c === "/" && d === "/") {
      const e = text.indexOf("\n", i);
      const end = e < 0 ? n : e;
      blank(code, i, end);
      blank(bare, i, end);
      i = end;
    } else if (c === "/" && d === "*") {
      const e = text.indexOf("*/", i + 2);
      const end = e < 0 ? n : e + 2;
      blank(code, i, end);
      blank(bare, i, end);
      i = end;
    } else if (c === '"' || c === "'") {
      let k = i + 1;
      while (k < n && text[k] !== c && text[k] !== "\n") k += text[k] === "\\" ? 2 : 1;
      strings.push({ value: text.slice(i + 1, k), quote: c, line: lineAt(text, i), start: i + 1, end: k });
      blank(bare, i + 1, k);
      i = k + 1;
      prev = "a";
    } else if (c === "`") {
      const t = readTemplate(i + 1, false);
      if (t.open) stack.push(depth);
      i = t.end;
      prev = "a";
    } else if (c === "}" && stack.length && stack[stack.length - 1] === depth) {
      stack.pop();
      const t = readTemplate(i + 1, true);
      if (t.open) stack.push(depth);
      i = t.end;
      prev = "a";
    } else if (c === "/" && (prev === "" || /[(,=:[!&|?{};+\-*%<>~^]/.test(prev) || REGEX_AFTER_WORD.has(prev))) {
      let k = i + 1;
      let cls = false;
      while (k < n && text[k] !== "\n") {
        if (text[k] === "\\") k += 2;
        else if (text[k] === "[") (cls = true), k++;
        else if (text[k] === "]") (cls = false), k++;
        else if (text[k] === "/" && !cls) break;
        else k++;
      }
      let f = k + 1;
      while (f < n && /[a-z]/.test(text[f])) f++;
      regexes.push({ source: text.slice(i + 1, k), flags: text.slice(k + 1, f), line: lineAt(text, i), start: i + 1, end: k });
      blank(bare, i + 1, k);
      i = f;
      prev = "a";
    } else if (/[A-Za-z_$0-9]/.test(c)) {
      let k = i;
      while (k < n && /[A-Za-z_$0-9]/.test(text[k])) k++;
      const word = text.slice(i, k);
      prev = REGEX_AFTER_WORD.has(word) ? word : "a";
      i = k;
    } else {
      if (c === "{") depth++;
      else if (c === "}") depth--;
      if (!/\s/.test(c)) prev = c === ")" || c === "]" ? "a" : c;
      i++;
    }
  }
  return { strings, regexes, code: code.join(""), bare: bare.join("") };
}

/**
 * Lexes Rust. Returns
 *   strings: [{ value, line, start, end }]  ("…", b"…", r#"…"#; char literals are not strings)
 *   code:    the text with comments blanked out
 *   bare:    the text with comments and the insides of string and char literals blanked
 */
export function lexRust(text) {
  const strings = [];
  const code = [...text];
  const bare = [...text];
  const n = text.length;
  let i = 0;
  while (i < n) {
    const c = text[i];
    const d = text[i + 1];
    if (c === "/" && d === "/") {
      const e = text.indexOf("\n", i);
      const end = e < 0 ? n : e;
      blank(code, i, end);
      blank(bare, i, end);
      i = end;
    } else if (c === "/" && d === "*") {
      let k = i + 2;
      let level = 1;
      while (k < n && level > 0) {
        if (text[k] === "/" && text[k + 1] === "*") (level++, (k += 2));
        else if (text[k] === "*" && text[k + 1] === "/") (level--, (k += 2));
        else k++;
      }
      blank(code, i, k);
      blank(bare, i, k);
      i = k;
    } else if ((c === "r" || (c === "b" && d === "r")) && /^b?r#*"/.test(text.slice(i, i + 40)) && !/[A-Za-z0-9_]/.test(text[i - 1] ?? "")) {
      const m = /^b?r(#*)"/.exec(text.slice(i, i + 40));
      const close = `"${m[1]}`;
      const from = i + m[0].length;
      const e = text.indexOf(close, from);
      const end = e < 0 ? n : e;
      strings.push({ value: text.slice(from, end), line: lineAt(text, from), start: from, end });
      blank(bare, from, end);
      i = end + close.length;
    } else if (c === '"') {
      let k = i + 1;
      while (k < n && text[k] !== '"') k += text[k] === "\\" ? 2 : 1;
      strings.push({ value: text.slice(i + 1, k), line: lineAt(text, i), start: i + 1, end: k });
      blank(bare, i + 1, k);
      i = k + 1;
    } else if (c === "'") {
      // a char literal ('x', '\n', '\u{1F600}', 'é') or a lifetime / label ('a)
      let end = -1;
      if (d === "\\") end = text.indexOf("'", i + 3);
      else {
        const cp = text.codePointAt(i + 1);
        const w = cp > 0xffff ? 2 : 1;
        if (text[i + 1 + w] === "'") end = i + 1 + w;
      }
      if (end > 0) {
        blank(bare, i + 1, end);
        i = end + 1;
      } else i++;
    } else i++;
  }
  return { strings, code: code.join(""), bare: bare.join("") };
}

/** The index just after the brace that closes the one at `open` (in comment- and string-free text). */
export function closingBrace(bare, open) {
  let level = 0;
  for (let k = open; k < bare.length; k++) {
    if (bare[k] === "{") level++;
    else if (bare[k] === "}" && --level === 0) return k + 1;
  }
  return bare.length;
}

/** Blanks `#[cfg(test)]` items (a `mod … { … }` block or one item up to `;`) in comment- and string-free Rust. */
export function withoutTestItems(bare) {
  const chars = [...bare];
  const re = /#\[cfg\(test\)\]/g;
  let m;
  while ((m = re.exec(bare))) {
    const semi = bare.indexOf(";", m.index);
    const brace = bare.indexOf("{", m.index);
    const end = brace >= 0 && (semi < 0 || brace < semi) ? closingBrace(bare, brace) : semi + 1;
    blank(chars, m.index, end);
    re.lastIndex = end;
  }
  return chars.join("");
}

export { lineAt };

// ---- issue 30, item 1: where example ids are written (rules-ids.test.mjs) ----

export const SOURCE_ROOTS = ["src", "web", "www", "lab", "scripts", "examples"];
const SOURCE_EXTS = [".rs", ".js", ".mjs", ".html"];

/**
 * The example ids of the Rust descriptors: the `id: "…"` of each
 * `Entry { … }` or `Example { … }` value under src/examples/ (the field at
 * the value's own level, not a nested one), in file order.
 */
export function exampleIds() {
  const ids = [];
  for (const file of sourceFiles(["src/examples"], [".rs"])) {
    const text = read(file);
    const { code, bare } = lexRust(text);
    const scan = withoutTestItems(bare);
    const re = /\b(?:Entry|Example)\s*\{/g;
    let m;
    while ((m = re.exec(scan))) {
      const open = m.index + m[0].length - 1;
      const close = closingBrace(scan, open);
      let level = 0;
      for (let k = open; k < close; k++) {
        if (scan[k] === "{") level++;
        else if (scan[k] === "}") level--;
        else if (level === 1 && /^\bid\s*:\s*"/.test(scan.slice(k, k + 40)) && !/[\w.]/.test(scan[k - 1])) {
          const lit = /^id\s*:\s*"([^"]*)"/.exec(code.slice(k, k + 200));
          if (lit) ids.push({ id: lit[1], file });
          break;
        }
      }
    }
  }
  return ids;
}

/** The string literals (their whole text) of one source file, outside comments and test items. */
export function literalsOf(file) {
  const text = read(file);
  if (file.endsWith(".rs")) return literalsOfRust(text);
  if (file.endsWith(".html")) {
    const out = [];
    const noComments = text.replace(/<!--[\s\S]*?-->/g, (c) => c.replace(/[^\n]/g, " "));
    const outside = noComments.replace(/(<script\b[^>]*>)([\s\S]*?)(<\/script>)/gi, (all, a, body, b) => {
      out.push(...literalsOfJs(body));
      return a + body.replace(/[^\n]/g, " ") + b;
    });
    for (const m of outside.matchAll(/=\s*(["'])([^"'<>\n]*)\1/g)) out.push(m[2]);
    return out;
  }
  return literalsOfJs(text);
}

/** The string literals of Rust `text`, outside comments and #[cfg(test)] items. */
export function literalsOfRust(text) {
  const { strings, bare } = lexRust(text);
  const live = withoutTestItems(bare);
  return strings.filter((s) => live[s.start - 1] === '"').map((s) => s.value);
}

/**
 * The literals of JS `text`: its strings (a template only when it has no
 * ${…}) and, since `{ gsd: figure }` names an example as surely as
 * `{ "gsd": figure }`, its unquoted object keys.
 */
export function literalsOfJs(text) {
  const { strings, bare } = lexJs(text);
  const keys = [...bare.matchAll(/[{,]\s*([A-Za-z_$][\w$]*)\s*:(?!:)/g)].map((m) => m[1]);
  return [...strings.filter((s) => s.quote !== "`" || !s.expr).map((s) => s.value), ...keys];
}

/**
 * The spread of each example id: { id, count, files } (files: where it is a
 * literal), plus the mean and the largest count over all examples.
 */
/**
 * The same word with another meaning: where an id is also the name of
 * something else, the files that use it in that sense (each with why).
 */
export const OTHER_MEANINGS = Object.freeze({
  resample: {
    why: "the lab worker's operation (run_resample), not the worked example",
    files: ["www/lab/families/resampling.js", "scripts/bench_lab.mjs", "www/lab/tiles.js", "lab/src/wasm/run.rs"],
  },
});

export function idSpread() {
  const ids = exampleIds();
  const files = sourceFiles(SOURCE_ROOTS, SOURCE_EXTS);
  const where = new Map(ids.map(({ id }) => [id, new Set()]));
  for (const file of files) {
    const literals = new Set(literalsOf(file));
    for (const [id, set] of where) {
      if (literals.has(id) && !OTHER_MEANINGS[id]?.files.includes(file)) set.add(file);
    }
  }
  const rows = [...where].map(([id, set]) => ({ id, count: set.size, files: [...set].sort() }));
  const mean = rows.reduce((s, r) => s + r.count, 0) / Math.max(1, rows.length);
  const max = Math.max(0, ...rows.map((r) => r.count));
  return { rows, mean, max };
}

/** The spread as a table, worst first. */
export function spreadTable({ rows, mean, max }) {
  const lines = [...rows]
    .sort((a, b) => b.count - a.count || a.id.localeCompare(b.id))
    .map((r) => `  ${r.id}: ${r.count}  ${r.files.join(", ")}`);
  return `example ids as literals in source files (mean ${mean.toFixed(1)}, max ${max}):\n${lines.join("\n")}`;
}


