// Issue 30, item 1: one place per example. Every example id (read from the
// Rust descriptors in src/examples/) may be written as a string literal in at
// most MAX_FILES_PER_ID source files outside tests/ — its own file and, if it
// has one, its figure's. Every other list of examples is derived.
//
// Counted: a string literal whose whole text is the id ("gsd", 'gsd', a
// template `gsd` without ${…}) or a JS object key that is the id
// ({ gsd: … }), not in a comment, in *.rs, *.js, *.mjs and
// *.html files under src/, web/, www/ (not www/vendor), lab/, scripts/ and
// examples/; folders named tests, tests.rs files and #[cfg(test)] items are
// not source. A literal that only contains the id ("#/gsd?dpi=1200") is not
// counted.
import { describe, it } from "node:test";
import assert from "node:assert/strict";
import { exampleIds, idSpread, literalsOfJs, literalsOfRust, spreadTable } from "./rules-lib.mjs";

export { idSpread, spreadTable };

/** The target of issue 30; the lead sets it to what the session reached. */
export const MAX_FILES_PER_ID = 2;

describe("rules: one place per example id", () => {
  it("the descriptors name the examples, each id once", () => {
    const ids = exampleIds();
    assert.ok(ids.length >= 26, `expected at least the 26 examples of the catalog, read ${ids.length}: ${ids.map((r) => r.id).join(", ")}`);
    const seen = new Map();
    for (const { id, file } of ids) {
      assert.match(id, /^[a-z0-9]+(?:-[a-z0-9]+)*$/, `${file}: "${id}" is not an example id`);
      assert.ok(!seen.has(id), `${id} is declared in ${seen.get(id)} and ${file}`);
      seen.set(id, file);
    }
  });

  it("the measurement counts literals, not comments or longer strings", () => {
    assert.deepEqual(literalsOfJs(`// "gsd"\nconst a = "gsd", b = '#/gsd', c = \`gsd\`, d = \`\${x}gsd\`; /* 'gsd' */ const r = /"x"/;`), ["gsd", "#/gsd", "gsd"]);
    assert.deepEqual(literalsOfJs(`const f = { gsd: 1, "lsm-2d": 2 }; x ? a : b;`), ["lsm-2d", "gsd"]);
    const rust = [
      '/// "gsd" in a doc comment',
      'const ID: &str = "gsd"; // "utm"',
      "fn f<'a>(c: char) -> bool { c == '\"' || r#\"raw \"q\"\"#.is_empty() }",
      '#[cfg(test)]',
      'mod tests { const T: &str = "ncc-1d"; }',
      'const LAST: &str = "lsm-2d";',
    ].join("\n");
    assert.deepEqual(literalsOfRust(rust), ["gsd", 'raw "q"', "lsm-2d"]);
  });

  it(`every example id is a literal in at most ${MAX_FILES_PER_ID} source files outside tests/`, () => {
    const spread = idSpread();
    const over = spread.rows.filter((r) => r.count > MAX_FILES_PER_ID);
    assert.equal(over.length, 0, `${over.length} of ${spread.rows.length} ids are in more than ${MAX_FILES_PER_ID} files\n${spreadTable(spread)}`);
  });
});
