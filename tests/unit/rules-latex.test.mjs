// Issue 30, item 2: formulas are data; no module parses LaTeX text back.
// LaTeX is written from a step's parts in one place; the page's line
// breaking, practice's hints and plain text read the parts. A LaTeX-reading
// routine is, concretely:
//
// JS (www/ but www/vendor, scripts/; *.js, *.mjs):
//   - a regular expression (a /…/ literal or new RegExp(…)) that matches a
//     LaTeX command or row break: a backslash followed by a letter, "(",
//     "[", a spacing character (, ; : ! space) or another backslash
//     (/\\frac/, /\\(begin|end)\{/, /\\[,;]/, /\\\\/); a lone /\\/ (escaping
//     a backslash of plain text on the way into LaTeX) is not reading LaTeX;
//   - a string search whose pattern is a string with a backslash in it:
//     .split(",\\ "), .indexOf("\\"), .startsWith("\\begin"), .includes(…),
//     .replace("\\,", …) and the like;
//   - a character compared with a backslash string: ch === "\\", case "\\":.
// Rust (src/, lab/src/, web/; not tests, tests.rs or #[cfg(test)] items):
//   - a function or closure with a string parameter named tex, latex,
//     formula or substituted (or ending in _tex) that scans it: chars(),
//     char_indices(), bytes(), find, rfind, split*, contains, starts_with,
//     ends_with, matches, strip_prefix/suffix, trim_*_matches, replace,
//     lines, or a slice of it;
//   - one of those scans applied to a step's LaTeX field (.formula,
//     .substituted, .tex, .latex);
//   - a function or closure that scans a string parameter, called in a
//     statement that reads a step's LaTeX field (practice's hint builder:
//     without_result(&st.substituted), gives_away(t)).
// Each finding names the file and line.
import { describe, it } from "node:test";
import assert from "node:assert/strict";
import { closingBrace, lexJs, lexRust, lineAt, read, sourceFiles, withoutTestItems } from "./rules-lib.mjs";

/** After a backslash (as the regex source writes it: \\), what makes it a LaTeX command or row break. */
const COMMAND = /\\\\(?:[A-Za-z([]|[,;:! ]|\\\\)/;
const SEARCHES = "split|indexOf|lastIndexOf|includes|startsWith|endsWith|replace|replaceAll|match|matchAll|search";

/** The LaTeX-reading spots of one JS file: ["file:line what", …]. */
export function jsLatexReaders(file, text) {
  const found = [];
  const { regexes, code } = lexJs(text);
  const at = (i, what) => found.push(`${file}:${lineAt(text, i)} ${what.replace(/\s+/g, " ").slice(0, 90)}`);
  for (const r of regexes) if (COMMAND.test(r.source)) at(r.start, `regex /${r.source}/`);
  for (const m of code.matchAll(/new RegExp\(\s*(String\.raw\s*)?(["'`])((?:\\.|(?!\2).)*)\2/g)) {
    // in String.raw`…` a regex backslash is written \\ as in a /…/ literal; in "…" it is \\\\
    const source = m[1] ? m[3] : m[3].replace(/\\\\/g, "\\");
    if (COMMAND.test(source)) at(m.index, m[0]);
  }
  const search = new RegExp(String.raw`\.(?:${SEARCHES})\(\s*(["'\`])((?:\\.|(?!\1).)*)\1`, "g");
  for (const m of code.matchAll(search)) if (m[2].includes("\\\\")) at(m.index, m[0]);
  for (const m of code.matchAll(/(?:===|!==|==|!=)\s*(["'`])((?:\\.|(?!\1).)*)\1|\bcase\s*(["'`])((?:\\.|(?!\3).)*)\3\s*:/g))
    if ((m[2] ?? m[4]).includes("\\\\")) at(m.index, m[0]);
  return found;
}

const SCANS = String.raw`(?:chars|char_indices|bytes|find|rfind|split\w*|rsplit\w*|contains|starts_with|ends_with|matches|rmatches|match_indices|strip_prefix|strip_suffix|trim_start_matches|trim_end_matches|trim_matches|replace|replacen|lines)\s*\(`;
const TEX_NAME = /^(?:tex|latex|formula|substituted|\w+_tex)$/;
const TEX_FIELD = /\.\s*(?:formula|substituted|tex|latex)\b(?!\s*\()/; // a field, not a builder's .formula(…)
const STRING_TYPE = /^&\s*(?:'\w+\s+)?(?:mut\s+)?(?:str|String)\b|^String\b/;

/** The functions and closures of Rust code (comments and strings blanked): { name, params, body, start }. */
function rustCallables(bare) {
  const out = [];
  for (const m of bare.matchAll(/\bfn\s+(\w+)\s*(?:<[^>{]*>)?\s*\(([^)]*)\)[^{;]*\{/g)) {
    const open = m.index + m[0].length - 1;
    out.push({ name: m[1], params: m[2], body: bare.slice(open, closingBrace(bare, open)), start: m.index });
  }
  for (const m of bare.matchAll(/\blet\s+(\w+)\s*=\s*(?:move\s*)?\|([^|]*)\|/g)) {
    const from = m.index + m[0].length;
    let end = from;
    let level = 0;
    for (; end < bare.length; end++) {
      const c = bare[end];
      if ("({[".includes(c)) level++;
      else if (")}]".includes(c)) level--;
      else if (c === ";" && level <= 0) break;
    }
    out.push({ name: m[1], params: m[2], body: bare.slice(from, end), start: m.index });
  }
  return out;
}

/** The string parameters of a parameter list: names. */
function stringParams(params) {
  return params
    .split(",")
    .map((p) => /^\s*(?:mut\s+)?(\w+)\s*:\s*(.*)$/.exec(p))
    .filter((m) => m && STRING_TYPE.test(m[2].trim()))
    .map((m) => m[1]);
}

/** Where `body` scans `name` (name.find(…), name[..i], …): the offset in body, or -1. */
function scanOf(body, name) {
  const m = new RegExp(String.raw`\b${name}\s*(?:\.\s*${SCANS}|\[[^\]]*\.\.)`).exec(body);
  return m ? m.index : -1;
}

/** The LaTeX-reading spots of one Rust file: ["file:line what", …]. */
export function rustLatexReaders(file, text) {
  const found = new Set();
  const bare = withoutTestItems(lexRust(text).bare);
  const at = (i, what) => found.add(`${file}:${lineAt(text, i)} ${what}`);
  const scanners = [];
  for (const f of rustCallables(bare)) {
    for (const p of stringParams(f.params)) {
      const k = scanOf(f.body, p);
      if (k < 0) continue;
      const offset = f.start + bare.slice(f.start).indexOf(f.body) + k;
      scanners.push({ ...f, param: p, offset, named: TEX_NAME.test(p) });
      if (TEX_NAME.test(p)) at(offset, `${f.name} scans its LaTeX parameter ${p}`);
    }
  }
  for (const m of bare.matchAll(new RegExp(String.raw`\.\s*(?:formula|substituted|tex|latex)\s*\.\s*${SCANS}`, "g"))) at(m.index, `scans a step's LaTeX (${m[0].replace(/\s+/g, "")})`);
  for (const s of scanners) {
    for (const call of bare.matchAll(new RegExp(String.raw`(?<![\w.])${s.name}\s*\(`, "g"))) {
      if (call.index === s.start || bare.slice(s.start, s.start + 3) === "fn " && call.index === s.start + 3) continue;
      const from = bare.lastIndexOf(";", call.index) + 1;
      const to = bare.indexOf(";", call.index);
      if (TEX_FIELD.test(bare.slice(from, to < 0 ? bare.length : to))) {
        at(call.index, `${s.name}(…) reads a step's LaTeX`);
        if (!s.named) at(s.offset, `${s.name} scans ${s.param}, called on a step's LaTeX`);
      }
    }
  }
  return [...found];
}

/** Every LaTeX-reading spot in the sources. */
export function latexReaders() {
  const js = sourceFiles(["www", "scripts"], [".js", ".mjs"]).flatMap((f) => jsLatexReaders(f, read(f)));
  const rust = sourceFiles(["src", "lab/src", "web"], [".rs"]).flatMap((f) => rustLatexReaders(f, read(f)));
  return [...js, ...rust];
}

describe("rules: no module parses LaTeX text", () => {
  it("the detectors find the readers of a formula string (small cases)", () => {
    const js = String.raw`
      const groups = tex.split(",\\ ");              // 2: equations cut at ",\ "
      const frac = /\\frac\{([^{}]*)\}/;              // 3: a command
      if (ch === "\\") depth++;                      // 4: a character scanner
      const rows = body.replace(/\\\\/g, "; ");      // 5: row breaks
      const r = new RegExp(String.raw${"`"}\\sqrt${"`"}); // 6
      const esc = text.replace(/\\/g, "\\textbackslash{}"); // writing LaTeX: not reading
      const out = ${"`"}\\begin{array} ${"`"} + " \\\\ ";  // writing LaTeX: not reading
      // tex.split(",\\ ") in a comment is not code
    `;
    assert.deepEqual(
      jsLatexReaders("x.js", js).map((s) => s.split(" ")[0]),
      ["x.js:3", "x.js:5", "x.js:6", "x.js:2", "x.js:4"],
    );
    const rust = String.raw`
fn without_result(tex: &str) -> String {
    for (i, ch) in tex.char_indices() { let _ = (i, ch); }
    String::new()
}
fn hint(s: &Solution) -> String {
    let gives_away = |t: &str| t.contains("=");
    let first = s.steps[0].substituted.find('=');
    s.steps.iter().map(|st| without_result(&st.substituted)).find(|t| !gives_away(t)).unwrap_or_default()
}
fn label(unit: &str) -> String { if unit.contains('/') { format!("\\text{{{unit}}}") } else { unit.into() } }
#[cfg(test)]
mod tests { fn f(tex: &str) -> bool { tex.contains("x") } }
`;
    assert.deepEqual(rustLatexReaders("y.rs", rust).sort(), [
      "y.rs:3 without_result scans its LaTeX parameter tex",
      "y.rs:7 gives_away scans t, called on a step's LaTeX",
      "y.rs:8 scans a step's LaTeX (.substituted.find()",
      "y.rs:9 gives_away(…) reads a step's LaTeX",
      "y.rs:9 without_result(…) reads a step's LaTeX",
    ]);
  });

  it("no source file outside vendor and tests reads LaTeX text", () => {
    const found = latexReaders();
    assert.deepEqual(found, [], `LaTeX-reading routines (formulas should be read from the step's parts):\n${found.join("\n")}`);
  });
});
