// Issue 29, item 6: the public API never traps on a wrong type. Every export
// of every wasm module of dist/pkg (each topic's, and all.js with practice
// and grade, which pkg/photogrammetry_playground.js re-exports) is called
// with every kind of JS value in every argument position, the other
// arguments valid. Each call either returns or throws an Error (never a
// WebAssembly.RuntimeError) whose message names the argument, and the module
// still solves its examples afterwards with the same numbers as before.
// pkg/examples.js (the lighter API) is stormed the same way in a blank page.
import { after, before, describe, test } from "node:test";
import assert from "node:assert/strict";
import fs from "node:fs";
import path from "node:path";
import { DIST, TEST_TIMEOUT, built, nodeModule, open, start } from "./harness.mjs";

const CATALOG = JSON.parse(fs.readFileSync(path.join(DIST, built("catalog.json")), "utf8"));
const MODULES = [...new Set(CATALOG.map((e) => e.module))];

/**
 * Every kind of JS value a caller might pass by mistake. A third element: a
 * field inside the value, which the message may name instead of the argument
 * (a Map is read as an object of fields: `dpi` is then an unknown field, or a bad value).
 */
function kinds() {
  return [
    ["a number", 5],
    ["NaN", NaN],
    ["an object", {}],
    ["an object with a wrong field type", { dpi: { nested: [1, 2] } }, "dpi"],
    ["an array", [1, 2, 3]],
    ["null", null],
    ["undefined", undefined],
    ["a boolean", true],
    ["a function", () => 1],
    ["a typed array", new Float64Array([1, 2, 3])],
    ["a Uint8Array", new Uint8Array([1, 2, 3])],
    ["a very long string", "x".repeat(1 << 20)],
    ["an empty string", ""],
    ["a BigInt", 10n],
    ["a symbol", Symbol("s")],
    ["a Map", new Map([["dpi", 1200]]), "dpi"],
  ];
}

/**
 * The parameters of each export, as docs/API.md names them (the built glue is
 * minified: its own names are gone); the test checks each function's length.
 */
const PARAMS = {
  catalog: [],
  solve: ["id", "inputs"],
  solve_series: ["id", "inputs", "key", "values", "plot"],
  read_count: ["text", "min", "max"],
  parse_inputs: ["id", "texts"],
  practice: ["id", "code"],
  grade: ["id", "code", "answers"],
};

/** The exported functions a course page calls (not init and not wasm-bindgen's internals). */
function publicExports(m) {
  return Object.keys(m)
    .filter((k) => typeof m[k] === "function" && !["default", "initSync"].includes(k) && !k.startsWith("__"))
    .sort();
}

/** Valid arguments of each export, for a module whose examples include `id`. */
function validArgs(id) {
  return {
    catalog: [],
    solve: [id, {}],
    solve_series: [id, {}, "dpi", [1200], []],
    read_count: ["5", 2, 500],
    parse_inputs: [id, {}],
    practice: [id, "1K7Q2"],
    grade: [id, "1K7Q2", {}],
  };
}

/**
 * Calls every export with every kind in every position; returns the calls that
 * trapped or threw something else than an Error naming the argument.
 */
function storm(m, id) {
  const bad = [];
  let calls = 0;
  const valid = validArgs(id);
  for (const name of publicExports(m)) {
    const params = PARAMS[name];
    assert.ok(params && valid[name], `${name}: an export this test does not know (add its parameters and valid arguments)`);
    assert.equal(m[name].length, params.length, `${name}: its number of parameters`);
    // catalog() takes no argument: a stray one is passed anyway
    const positions = params.length ? params : ["(none)"];
    positions.forEach((param, i) => {
      for (const [kind, value, field] of kinds()) {
        const args = [...valid[name]];
        args[i] = value;
        calls++;
        try {
          m[name](...args);
        } catch (e) {
          const what = `${name}(${param} = ${kind})`;
          if (!(e instanceof Error) || e instanceof WebAssembly.RuntimeError) {
            bad.push(`${what}: ${e?.constructor?.name}: ${e?.message ?? e}`);
          } else if (!new RegExp(`\\b${param}\\b`).test(e.message) && !(field && new RegExp(`\\b${field}\\b`).test(e.message))) {
            bad.push(`${what}: the message does not name ${param}: ${e.message.slice(0, 200)}`);
          } else if (e.message.length > 600) {
            bad.push(`${what}: a message of ${e.message.length} characters`);
          }
        }
      }
    });
  }
  return { bad, calls };
}

/** Every ready example of `module` solved with its seed inputs: { id: result }. */
function seedResults(m, ids) {
  return Object.fromEntries(ids.map((id) => [id, m.solve(id, {}).result]));
}

describe("every export of every module, called with every kind of JS value", () => {
  for (const name of [...MODULES, "all"]) {
    test(`pkg/${name}.js: an Error naming the argument, never a trap; the module still solves`, { timeout: TEST_TIMEOUT }, async () => {
      const m = await nodeModule(name);
      const ids = CATALOG.filter((e) => e.status === "ready" && (name === "all" || e.module === name)).map((e) => e.id);
      const before = seedResults(m, ids);
      const practice = name === "all" ? JSON.stringify([m.practice("gsd", "1K7Q2"), m.grade("gsd", "1K7Q2", { gsd_cm: "35.4" })]) : null;
      const { bad, calls } = storm(m, ids[0]);
      assert.ok(calls >= 16 * 4, `${name}: only ${calls} calls`);
      assert.deepEqual(bad, [], `${name}: ${bad.length} of ${calls} calls went wrong:\n${bad.slice(0, 30).join("\n")}`);
      // after the storm, the same numbers
      assert.deepEqual(seedResults(m, ids), before, `${name}: the seed's results after the storm`);
      if (practice) assert.equal(JSON.stringify([m.practice("gsd", "1K7Q2"), m.grade("gsd", "1K7Q2", { gsd_cm: "35.4" })]), practice);
    });
  }

  test("the messages: the argument, what it must be, what it got", async () => {
    const m = await nodeModule("all");
    const message = (f) => {
      try {
        f();
      } catch (e) {
        return e.message;
      }
      return "returned";
    };
    assert.equal(message(() => m.solve(5, {})), "id: must be a string naming an example, got a number");
    assert.equal(message(() => m.solve({}, {})), "id: must be a string naming an example, got an object");
    assert.equal(message(() => m.parse_inputs(5, {})), "id: must be a string naming an example, got a number");
    assert.equal(message(() => m.practice({}, "1K7Q2")), "id: must be a string naming an example, got an object");
    assert.equal(message(() => m.grade("gsd", {}, {})), 'code: must be a string like "1K7Q2" (a practice variant\'s code), got an object');
    assert.equal(message(() => m.grade("gsd", 5, {})), 'code: must be a string like "1K7Q2" (a practice variant\'s code), got a number');
    assert.equal(message(() => m.solve("gsd", [1])), "inputs: must be an object of fields like { dpi: 1200 }, got an array");
    assert.equal(message(() => m.solve("gsd", new Float64Array(2))), "inputs: must be an object of fields like { dpi: 1200 }, got a typed array");
    assert.equal(message(() => m.parse_inputs("gsd", "dpi=5")), "texts: must be an object of fields like { dpi: 1200 }, got a string");
    assert.equal(message(() => m.grade("gsd", "1K7Q2", () => 1)), "answers: must be an object of fields like { dpi: 1200 }, got a function");
    assert.equal(message(() => m.solve_series("gsd", {}, 5, [1], [])), "key: must be a string naming an input of the example, got a number");
    assert.equal(message(() => m.solve_series("gsd", {}, "dpi", new Float64Array(2), [])), "values: must be an array of numbers, got a typed array");
    assert.equal(message(() => m.solve_series("gsd", {}, "dpi", [1, "2"], [])), "values[1]: must be a number, got a string");
    assert.equal(message(() => m.solve_series("gsd", {}, "dpi", [1], ["gsd_cm", 3])), "plot[1]: must be a string, got a number");
    assert.equal(message(() => m.solve_series("gsd", {}, "dpi", Array(10001).fill(1), [])), "values: at most 10000 points, got 10001");
    assert.equal(message(() => m.read_count("800", 2, 500)), "text: must be at most 500 (got 800)");
    assert.equal(message(() => m.read_count(200, 2, 500)), "text: must be a string (a count typed in a box), got a number");
    assert.equal(m.read_count(" 2e2 ", 2, 500), 200);
    assert.equal(message(() => m.solve(null)), "id: must be a string naming an example, got null");
    assert.equal(message(() => m.solve()), "id: must be a string naming an example, got undefined");
    assert.match(message(() => m.solve("x".repeat(1 << 20), {})), /^unknown example id "x{24}…" \(see catalog\(\) for the ids\)$/);
  });
});

describe("the image lab's module (lab/pkg, run in its worker)", () => {
  /**
   * The lab's exports that take a string, with valid arguments and the name of
   * each string position (the others take numbers, arrays or a LabImage, which
   * the glue converts or checks itself): [call, arguments, { position: name }].
   */
  function stringCalls(lab) {
    const img = lab.image_from_u8(8, 8, Uint8Array.from({ length: 64 }, (_, i) => (i * 37) % 256));
    const rect = (w) => Float64Array.of(0, 0, w, w);
    return [
      ["decode_image", (...a) => lab.decode_image(...a), ["x.png", new Uint8Array(0)], { 0: "name" }],
      ["run_filter", (...a) => lab.run_filter(...a), [img, "mean", "crop", undefined, undefined], { 1: "kernel", 2: "border", 3: "custom_kernel" }],
      ["check_custom_kernel", (...a) => lab.check_custom_kernel(...a), ["1 2 1", undefined], { 0: "custom_kernel" }],
      ["run_edges", (...a) => lab.run_edges(...a), [img, "sobel", "crop"], { 1: "operator", 2: "border" }],
      ["run_correlation", (...a) => lab.run_correlation(...a), [img, rect(3), img, rect(7), "shift"], { 4: "model" }],
      ["run_resample", (...a) => lab.run_resample(...a), [img, "rotate", Float64Array.of(0, 1), 4, 3], { 1: "kind" }],
      ["resample_position", (...a) => lab.resample_position(...a), [img, "rotate", Float64Array.of(0, 1), 4, 3, 1, 1], { 1: "kind" }],
      ["LabImage.neighbourhood", (...a) => img.neighbourhood(...a), [4, 4, 3, 3, "crop"], { 4: "border" }],
    ];
  }

  test("every string argument of the lab: an Error naming it, never a trap; the lab still filters", { timeout: TEST_TIMEOUT }, async () => {
    const lab = await nodeModule("photogrammetry_lab", "lab/pkg");
    const mean = () => {
      const img = lab.image_from_u8(8, 8, Uint8Array.from({ length: 64 }, (_, i) => (i * 37) % 256));
      return [...lab.run_filter(img, "mean", "crop", undefined, undefined)[0].data];
    };
    const before = mean();
    const bad = [];
    let calls = 0;
    for (const [name, call, valid, strings] of stringCalls(lab)) {
      for (const [i, param] of Object.entries(strings)) {
        for (const [kind, value] of kinds()) {
          const args = [...valid];
          args[Number(i)] = value;
          calls++;
          try {
            call(...args);
          } catch (e) {
            const what = `${name}(${param} = ${kind})`;
            if (!(e instanceof Error) || e instanceof WebAssembly.RuntimeError) bad.push(`${what}: ${e?.constructor?.name}: ${e?.message ?? e}`);
            // a string of the right type but no valid content is the operation's own error
            else if (typeof value !== "string" && !new RegExp(`\\b${param}\\b`).test(e.message)) bad.push(`${what}: ${e.message.slice(0, 200)}`);
          }
        }
      }
    }
    assert.ok(calls >= 11 * 16, `only ${calls} calls`);
    assert.deepEqual(bad, [], `${bad.length} of ${calls} calls went wrong:\n${bad.slice(0, 30).join("\n")}`);
    assert.deepEqual(mean(), before, "the mean filter after the storm");
  });
});

describe("pkg/examples.js in a blank page", () => {
  let env;
  before(async () => {
    env = await start();
  });
  after(async () => {
    await env?.close();
  });

  test("loadExample, solve and parseInputs with every kind of value: an Error naming the argument", { timeout: TEST_TIMEOUT }, async () => {
    const { context, page, log } = await open(env.browser);
    try {
      await page.goto(`${env.url}version.json`);
      await page.setContent("<!doctype html><title>A course page</title><p>blank</p>");
      const got = await page.evaluate(async () => {
        const api = await import("/pkg/examples.js");
        const values = [5, NaN, {}, [1, 2], null, undefined, true, () => 1, new Float64Array(2), "x".repeat(1 << 20), "", 10n, Symbol("s")];
        const bad = [];
        const check = async (what, param, f) => {
          try {
            await f();
          } catch (e) {
            if (!(e instanceof Error) || e instanceof WebAssembly.RuntimeError) bad.push(`${what}: ${e?.constructor?.name}: ${e?.message}`);
            else if (!new RegExp(`\\b${param}\\b|example`).test(e.message)) bad.push(`${what}: ${e.message.slice(0, 200)}`);
          }
        };
        const gsd = await api.loadExample("gsd");
        const before = gsd.solve({}).result.gsd_cm;
        for (const [i, v] of values.entries()) {
          await check(`loadExample(#${i})`, "id", () => api.loadExample(v));
          await check(`solve(#${i}, {})`, "id", () => api.solve(v, {}));
          await check(`parseInputs(#${i}, {})`, "id", () => api.parseInputs(v, {}));
          await check(`solve("gsd", #${i})`, "inputs", () => api.solve("gsd", v));
          await check(`parseInputs("gsd", #${i})`, "texts", () => api.parseInputs("gsd", v));
          await check(`gsd.solve(#${i})`, "inputs", () => gsd.solve(v));
          await check(`gsd.parseInputs(#${i})`, "texts", () => gsd.parseInputs(v));
        }
        return { bad, before, after: (await api.solve("gsd", {})).result.gsd_cm };
      });
      assert.deepEqual(got.bad, []);
      assert.equal(got.after, got.before);
      assert.deepEqual(log.pageErrors, []);
    } finally {
      await context.close();
    }
  });
});
