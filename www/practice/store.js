// Practice progress in localStorage: per example, the variant code and the raw
// texts of the answer boxes, nothing else (grades are recomputed on load).

const KEY = "photogrammetry-playground:practice:v1";
/** Longest answer text kept (a box holds one number). */
const MAX_TEXT = 200;

function readAll() {
  try {
    const data = JSON.parse(localStorage.getItem(KEY) ?? "{}");
    return data && typeof data === "object" && !Array.isArray(data) ? data : {};
  } catch {
    return {};
  }
}

function writeAll(data) {
  try {
    localStorage.setItem(KEY, JSON.stringify(data));
    return true;
  } catch {
    return false; // private mode, quota: practice still works, it just is not kept
  }
}

/** The stored progress of example `id`: { code, answers: { key: text } } or null. */
export function loadProgress(id) {
  const p = readAll()[id];
  if (!p || typeof p.code !== "string") return null;
  const answers = {};
  if (p.answers && typeof p.answers === "object") {
    for (const [k, v] of Object.entries(p.answers)) if (typeof v === "string") answers[k] = v.slice(0, MAX_TEXT);
  }
  return { code: p.code, answers };
}

/** Keeps the variant code and the answer texts of example `id`. */
export function saveProgress(id, code, answers) {
  const all = readAll();
  const kept = {};
  for (const [k, v] of Object.entries(answers)) if (v) kept[k] = String(v).slice(0, MAX_TEXT);
  all[id] = { code, answers: kept };
  return writeAll(all);
}

/** Every stored example id with its progress. */
export function allProgress() {
  const out = {};
  for (const id of Object.keys(readAll())) {
    const p = loadProgress(id);
    if (p) out[id] = p;
  }
  return out;
}
