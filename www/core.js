// The Rust core, compiled to WebAssembly (docs/API.md is the contract).

const CORE_URL = "./pkg/photogrammetry_playground.js";

/**
 * Loads and initialises the wasm package.
 * @returns {Promise<{ catalog: () => any[], parseInputs: (id: string, texts: object) => { inputs: object, errors: object }, solve: (id: string, inputs: object) => any }>}
 */
export async function loadCore() {
  const mod = await import(CORE_URL);
  await mod.default();
  return {
    catalog: () => mod.catalog(),
    parseInputs: (id, texts) => mod.parse_inputs(id, texts),
    solve: (id, inputs) => mod.solve(id, inputs),
    practice: (id, code) => mod.practice(id, code ?? undefined),
    grade: (id, code, answers) => mod.grade(id, code, answers),
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
