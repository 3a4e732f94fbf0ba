// Loading one example at a time (docs/API.md, "Loading one example"): the
// catalog first, then only the module of the example asked for (a topic's,
// about 70–110 KB gzipped) instead of every example at once.
//
//   import { loadExample, catalog } from "./pkg/examples.js";
//   const gsd = await loadExample("gsd");
//   gsd.solve({ dpi: 1200 });            // synchronous from here on
//   gsd.parseInputs({ dpi: "1200" });
//   await solve("gsd", { dpi: 1200 });   // or in one step
//
// The module URL below is a literal: a build step that renames files rewrites it.
import { loadCore } from "../core.js";

let core = null;

function theCore() {
  core ??= loadCore().catch((e) => {
    core = null; // a later call tries again
    throw e;
  });
  return core;
}

/**
 * Every worked example (catalog.json; no module is loaded): each entry's
 * `inputs` (its fields) appear once its example is loaded.
 */
export async function catalog() {
  return (await theCore()).catalog();
}

/** What kind of JS value `v` is, as the wasm exports' messages say it (src/wasm.rs, js_kind). */
function kindOf(v) {
  if (v === null) return "null";
  if (Array.isArray(v)) return "an array";
  if (ArrayBuffer.isView(v)) return "a typed array";
  const t = typeof v;
  if (t === "undefined") return t;
  return { number: "a number", boolean: "a boolean", function: "a function", bigint: "a BigInt", symbol: "a symbol" }[t] ?? "an object";
}

/** An id that is not a string never reaches the catalog's lookup (a Symbol cannot even be quoted). */
function checkId(id) {
  if (typeof id !== "string") throw new Error(`id: must be a string naming an example, got ${kindOf(id)}`);
}

/**
 * Loads example `id`'s module once; its `solve(inputs)` and
 * `parseInputs(texts)` are then synchronous.
 */
export async function loadExample(id) {
  checkId(id);
  const c = await theCore();
  await c.load(id);
  const entry = c.catalog().find((e) => e.id === id);
  return Object.freeze({
    id,
    entry,
    solve: (inputs) => c.solve(id, inputs),
    parseInputs: (texts) => c.parseInputs(id, texts),
  });
}

/** Solves example `id` with `inputs`, loading its module first if needed. */
export async function solve(id, inputs) {
  return (await loadExample(id)).solve(inputs);
}

/** Parses form texts for example `id`, loading its module first if needed. */
export async function parseInputs(id, texts) {
  return (await loadExample(id)).parseInputs(texts);
}
