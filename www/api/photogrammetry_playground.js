// The one-package API of earlier versions, kept for course pages that use it
// (docs/API.md, "The one-package form"). Hand-written, not generated: it is
// pkg/all.js, the module with every example and practice mode (about 310 KB
// gzipped), under the old name:
//
//   import init, { catalog, solve, parse_inputs, practice, grade } from "./pkg/photogrammetry_playground.js";
//   await init();
//   solve("gsd", { dpi: 1200 });
//
// The lighter form loads only the example's own module (docs/API.md,
// "Loading one example"):
//
//   import { loadExample } from "./pkg/examples.js";
//   const gsd = await loadExample("gsd");
//   gsd.solve({ dpi: 1200 });
//
// The module URL below is a literal: a build step that renames files rewrites it.
import init, { initSync } from "./all.js";

export { catalog, solve, parse_inputs, practice, grade } from "./all.js";
export { initSync };
export default init;
