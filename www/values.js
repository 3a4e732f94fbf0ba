// Reading a solution's values (docs/API.md), shared by the result table
// (render.js) and the figures: no DOM, no drawing.

/** The last step value named `key` (a textbook key that is an intermediate, a figure's input). */
export function stepValue(solution, key) {
  let found;
  for (const step of solution?.steps ?? []) {
    if (step.values && Object.hasOwn(step.values, key)) found = step.values[key];
  }
  return found;
}

/** Whether a value is a matrix: a non-empty list of rows, all lists of one length. */
export function isMatrix(m) {
  return Array.isArray(m) && m.length > 0 && m.every((r) => Array.isArray(r) && r.length === m[0].length);
}
