// The Rust core, compiled to WebAssembly (docs/API.md is the contract).
//
// One small wasm module per topic (dist/pkg/<module>.js, built from web/<module>/):
// the page has the catalog (catalog.json, written by the build from the Rust
// entries, and copied into the HTML by the build) and loads only the module of
// the example on screen (preload-route.js starts its requests from the HTML); the others
// are loaded when the browser is idle after the first solution. An example's
// practice mode loads its topic's module with practice (pkg/<module>_practice.js,
// the same crate built with the drills and the practice and grade exports); the
// worksheets of several examples load pkg/all.js (every example and practice mode).
//
// Module URLs are literal strings (no template strings): a build step that
// renames files can rewrite them, and an import map applies to them too.

/**
 * The catalog: the Rust entries as JSON, with each entry's `module`, without
 * their `inputs` (the form's fields: most of the catalog's bytes), which come
 * with the entry's module (its own `catalog()`) when it loads.
 */
const CATALOG_URL = new URL("./catalog.json", import.meta.url);

/** Each module's wasm-bindgen package, imported on demand. */
const MODULES = Object.freeze({
  coordinates: () => import("./pkg/coordinates.js"),
  transformations: () => import("./pkg/transformations.js"),
  correlation: () => import("./pkg/correlation.js"),
  matching: () => import("./pkg/matching.js"),
  resampling: () => import("./pkg/resampling.js"),
  filters: () => import("./pkg/filters.js"),
  interest: () => import("./pkg/interest.js"),
  chains: () => import("./pkg/chains.js"),
  projection: () => import("./pkg/projection.js"),
  all: () => import("./pkg/all.js"),
  // each topic's module with its practice mode (practice, grade): loaded by #/<id>?practice
  coordinates_practice: () => import("./pkg/coordinates_practice.js"),
  transformations_practice: () => import("./pkg/transformations_practice.js"),
  correlation_practice: () => import("./pkg/correlation_practice.js"),
  matching_practice: () => import("./pkg/matching_practice.js"),
  resampling_practice: () => import("./pkg/resampling_practice.js"),
  filters_practice: () => import("./pkg/filters_practice.js"),
  interest_practice: () => import("./pkg/interest_practice.js"),
  chains_practice: () => import("./pkg/chains_practice.js"),
  projection_practice: () => import("./pkg/projection_practice.js"),
});

/** The module with practice mode of topic module `name`. */
const practiceOf = (name) => `${name}_practice`;

/**
 * The catalog's entries: from the page's own data block when it has one (the
 * build writes catalog.json into index.html and embed.html: no request), else
 * fetched (a course author's page importing pkg/examples.js).
 */
export async function loadCatalog() {
  const block = typeof document === "undefined" ? null : document.getElementById("catalog-data");
  if (block) {
    const entries = JSON.parse(block.textContent).entries;
    if (!Array.isArray(entries)) throw new Error("catalog-data: not a list of examples");
    return entries;
  }
  const response = await fetch(CATALOG_URL);
  if (!response.ok) throw new Error(`catalog.json: ${response.status} ${response.statusText}`);
  const entries = await response.json();
  if (!Array.isArray(entries)) throw new Error("catalog.json: not a list of examples");
  return entries;
}

/** Modules are loaded once per page, whichever loadCore() asked: name → Promise of the package. */
const pending = new Map();
/** name → the initialised package */
const ready = new Map();
/** The entry lists of every loadCore(), whose `inputs` a loaded module fills in. */
const catalogs = new Set();

/** Copies the fields of `mod`'s entries (its own catalog()) into `entries`. */
function fillInputs(entries, mod) {
  const own = new Map(mod.catalog().map((e) => [e.id, e.inputs]));
  for (const entry of entries) if (!entry.inputs && own.has(entry.id)) entry.inputs = own.get(entry.id);
}

/**
 * Initialises a topic's package: with the wasm preload-route.js already
 * fetched and compiled from the HTML when it is this module's, else by the
 * package's own fetch (also when that early compile failed).
 */
async function initModule(name, mod) {
  const early = globalThis.playgroundEarlyWasm;
  if (early && early.module === name) {
    globalThis.playgroundEarlyWasm = undefined;
    const compiled = await early.compiled.catch(() => null);
    if (compiled) {
      await mod.default({ module_or_path: compiled });
      return;
    }
  }
  await mod.default();
}

function loadModule(name) {
  if (!pending.has(name)) {
    const importer = MODULES[name];
    if (!importer) return Promise.reject(new Error(`catalog.json names a module “${name}” this page does not know`));
    const p = importer()
      .then(async (mod) => {
        await initModule(name, mod);
        for (const entries of catalogs) fillInputs(entries, mod);
        ready.set(name, mod);
        return mod;
      })
      .catch((e) => {
        pending.delete(name); // a later call tries again (a dropped connection)
        throw e;
      });
    pending.set(name, p);
  }
  return pending.get(name);
}

/**
 * Loads the catalog; modules follow on demand. After `await core.load(id)`,
 * `parseInputs(id, …)` and `solve(id, …)` are synchronous (the page redraws on
 * every input change) and entry `id` of `catalog()` has its `inputs`;
 * `await core.loadPractice()` before `practice`/`grade` (every entry then has
 * its `inputs`).
 * @returns {Promise<{
 *   catalog: () => any[],
 *   load: (id: string) => Promise<void>,
 *   loaded: (id: string) => boolean,
 *   parseInputs: (id: string, texts: object) => { inputs: object, errors: object },
 *   solve: (id: string, inputs: object) => any,
 *   solveSeries: (id: string, inputs: object, key: string, values: number[], plot: string[]) => { results: object, errors: (string|null)[] },
 *   readCount: (id: string, text: string, min: number, max: number) => number,
 *   loadPractice: () => Promise<void>,
 *   practice: (id: string, code?: string | null) => any,
 *   grade: (id: string, code: string, answers: object) => any,
 *   prefetch: () => void,
 *   modulesLoaded: () => string[],
 * }>}
 */
export async function loadCore() {
  const entries = await loadCatalog();
  const moduleById = new Map(entries.map((e) => [e.id, e.module]));
  for (const mod of ready.values()) fillInputs(entries, mod);
  catalogs.add(entries);

  function moduleOf(id) {
    const name = moduleById.get(id);
    if (!name) throw new Error(`No such example: “${id}”`);
    return name;
  }

  /** The initialised package that solves `id` (its topic's, with or without practice, or the whole one). */
  function packageFor(id) {
    const name = moduleById.get(id);
    const mod = ready.get(name) ?? ready.get(practiceOf(name)) ?? ready.get("all");
    if (mod) return mod;
    moduleOf(id); // an unknown id says so
    throw new Error(`${id}: its module is not loaded yet (await core.load("${id}") first)`);
  }

  function practicePackage(id) {
    const mod = ready.get(practiceOf(moduleById.get(id))) ?? ready.get("all");
    if (!mod) throw new Error(`practice mode of ${id} is not loaded yet (await core.loadPractice("${id}") first)`);
    return mod;
  }

  let prefetching = false;
  /** Loads every other topic's module, one per idle moment (never on Save-Data). */
  function prefetch() {
    if (prefetching || navigator.connection?.saveData) return;
    prefetching = true;
    const idle = globalThis.requestIdleCallback ?? ((f) => setTimeout(f, 200));
    const names = [...new Set(entries.map((e) => e.module))].filter((n) => n && MODULES[n]);
    const tried = new Set();
    const next = () => {
      const name = names.find((n) => !pending.has(n) && !tried.has(n));
      if (!name) return;
      tried.add(name); // once: a failed module is loaded again only when its example opens
      idle(() => loadModule(name).then(next, next), { timeout: 5000 });
    };
    next();
  }

  return {
    // the same entry objects every time: an entry's `inputs` appear when its module loads
    catalog: () => entries,
    load: async (id) => {
      if (ready.has("all")) return;
      await loadModule(moduleOf(id));
    },
    loaded: (id) => ready.has(moduleById.get(id)) || ready.has(practiceOf(moduleById.get(id))) || ready.has("all"),
    parseInputs: (id, texts) => packageFor(id).parse_inputs(id, texts),
    solve: (id, inputs) => packageFor(id).solve(id, inputs),
    /**
     * A sweep's series in one call (docs/API.md, solve_series): `id` solved with
     * `inputs` and `key` set to each of `values`; `{ results: { k: [value…] },
     * errors: [message|null…] }` for the results `plot`, each point solve()'s.
     */
    solveSeries: (id, inputs, key, values, plot) => packageFor(id).solve_series(id, inputs, key, values, plot),
    /** A count typed in a box (a sweep's steps): a whole number from `min` to `max`, read by example `id`'s module; throws in the core's words. */
    readCount: (id, text, min, max) => packageFor(id).read_count(text, min, max),
    /** Practice mode of example `id` (its topic's practice module), or of every example (no id: worksheets). */
    loadPractice: async (id) => {
      if (ready.has("all")) return;
      await loadModule(id ? practiceOf(moduleOf(id)) : "all");
    },
    practice: (id, code) => practicePackage(id).practice(id, code ?? undefined),
    grade: (id, code, answers) => practicePackage(id).grade(id, code, answers),
    prefetch,
    modulesLoaded: () => [...ready.keys()],
  };
}

/** An error's message, whatever was thrown. */
export function messageOf(e) {
  if (e && typeof e.message === "string") return e.message;
  if (typeof e === "string") return e;
  try {
    return JSON.stringify(e);
  } catch {
    return String(e);
  }
}
