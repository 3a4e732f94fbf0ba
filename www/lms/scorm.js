// The SCORM runtime of a practice package: finds the LMS's API object, resumes
// the attempt from cmi.suspend_data and reports each check (score, status, one
// interaction per box) — SCORM 1.2 (`API`) or SCORM 2004 4th edition
// (`API_1484_11`). Nothing else leaves the page: the only calls out are these
// to the API object the LMS put in a parent window (or the opener).
//
// Written against the two specifications' run-time data models; tested with
// scorm-again (the LMS-side runtime on npm) in tests/unit/lms-scorm.test.mjs
// and in the browser in tests/e2e/lms.test.mjs.

/** How many parent windows are searched (the ADL's reference script uses 7; LMS frames nest deeper). */
const MAX_PARENTS = 10;

/** SCORM 1.2's cmi.suspend_data holds at most 4,096 characters. */
export const SUSPEND_LIMIT_12 = 4096;
/** SCORM 2004's holds at least 64,000 (the LMS must keep that many). */
export const SUSPEND_LIMIT_2004 = 64000;
/**
 * Variants per example in a SCORM 1.2 package (the worksheet maker's 20 stay
 * for 2004 and print): 10 keeps the largest topic's attempt, every box typed,
 * inside 4,096 characters (tests/e2e/lms-attempt.test.mjs measures it).
 */
export const MAX_VARIANTS_12 = 10;

function findIn(win, name) {
  let w = win;
  for (let i = 0; w && i <= MAX_PARENTS; i++) {
    try {
      if (w[name]) return w[name];
    } catch {
      return null; // another origin: its properties cannot be read
    }
    if (!w.parent || w.parent === w) break;
    w = w.parent;
  }
  return null;
}

/**
 * The LMS's API, looked for in this window and its parents (bounded), then in
 * the opener and its parents: { version: "1.2" | "2004", api } or null. With
 * `prefer`, that version is looked for first; both are tried.
 */
export function findApi(win = globalThis.window, prefer = "1.2") {
  const names = prefer === "2004" ? [["2004", "API_1484_11"], ["1.2", "API"]] : [["1.2", "API"], ["2004", "API_1484_11"]];
  for (const start of [win, safeOpener(win)]) {
    if (!start) continue;
    for (const [version, name] of names) {
      const api = findIn(start, name);
      if (api) return { version, api };
    }
  }
  return null;
}

function safeOpener(win) {
  try {
    return win?.opener ?? null;
  } catch {
    return null;
  }
}

/** A score out of 100 with at most two decimals (SCORM 1.2's CMIDecimal, as LMSs store it). */
export function percent(score, outOf) {
  if (!(outOf > 0)) return "0";
  return String(Math.round((10000 * score) / outOf) / 100);
}

/** A CMIIdentifier: no spaces, at most 255 characters (SCORM 1.2 also forbids most punctuation). */
export function interactionId(exampleId, code, boxKey) {
  return `${exampleId}_${code}_${boxKey}`.replace(/[^A-Za-z0-9_-]/g, "-").slice(0, 255);
}

/**
 * A session with the LMS. `connect()` returns one, or null outside an LMS.
 * All calls are checked: `lastError` holds the LMS's last error text (the
 * page says scores could not be sent when it is set).
 */
export class ScormSession {
  constructor(version, api) {
    this.version = version;
    this.api = api;
    this.open = false;
    this.lastError = null;
    this.interactionsWritten = 0;
  }

  call(name12, name2004, ...args) {
    const name = this.version === "1.2" ? name12 : name2004;
    let out;
    try {
      out = this.api[name](...args);
    } catch (e) {
      this.lastError = `${name}: ${e?.message ?? e}`;
      return "";
    }
    const code = String(this.call0("LMSGetLastError", "GetLastError") ?? "0");
    if (code !== "0" && code !== "") {
      const text = this.call0("LMSGetErrorString", "GetErrorString", code);
      this.lastError = `${name}(${args.map(String).join(", ").slice(0, 80)}): error ${code} ${text ?? ""}`.trim();
    }
    return out;
  }

  call0(name12, name2004, ...args) {
    try {
      return this.api[this.version === "1.2" ? name12 : name2004](...args);
    } catch {
      return null;
    }
  }

  get(element) {
    return String(this.call("LMSGetValue", "GetValue", element) ?? "");
  }

  /** A value that may not be set yet (SCORM 2004 answers 403, "not initialized", for a first attempt): "" then, and no error kept. */
  peek(element) {
    const saved = this.lastError;
    const v = this.get(element);
    this.lastError = saved;
    return v;
  }

  set(element, value) {
    return String(this.call("LMSSetValue", "SetValue", element, String(value))) === "true";
  }

  initialize() {
    this.open = String(this.call("LMSInitialize", "Initialize", "")) === "true";
    if (this.open) this.interactionsWritten = Number(this.peek("cmi.interactions._count")) || 0;
    return this.open;
  }

  /**
   * The passing percentage the LMS holds (1.2: cmi.student_data.mastery_score,
   * from the manifest's adlcp:masteryscore; 2004: cmi.scaled_passing_score),
   * or null when it has none.
   */
  passing() {
    if (!this.open) return null;
    const text = this.peek(this.version === "1.2" ? "cmi.student_data.mastery_score" : "cmi.scaled_passing_score");
    const x = text.trim() === "" ? NaN : Number(text);
    if (!Number.isFinite(x)) return null;
    return this.version === "1.2" ? x : 100 * x;
  }

  /** The saved attempt text (cmi.suspend_data), or "" for a first attempt. */
  suspendData() {
    return this.open ? this.peek("cmi.suspend_data") : "";
  }

  /**
   * Reports a graded attempt: score (0–100), status against `passing` (a
   * percentage, or null: then completed once every box was answered), the
   * attempt text for resuming, and interactions for the boxes checked since
   * the last report (`boxes`: [{ id, label, response, verdict }]).
   */
  report({ score, outOf, answered, total, passing = null, suspend, boxes = [] }) {
    if (!this.open) return false;
    this.lastError = null; // this report's errors only
    passing ??= this.passing();
    const raw = percent(score, outOf);
    const complete = answered >= total;
    const passed = passing == null ? null : Number(raw) >= passing;
    if (this.version === "1.2") {
      this.set("cmi.core.score.min", "0");
      this.set("cmi.core.score.max", "100");
      this.set("cmi.core.score.raw", raw);
      this.set("cmi.core.lesson_status", !complete ? "incomplete" : passed == null ? "completed" : passed ? "passed" : "failed");
    } else {
      this.set("cmi.score.min", "0");
      this.set("cmi.score.max", "100");
      this.set("cmi.score.raw", raw);
      this.set("cmi.score.scaled", String(Math.round((10000 * (outOf > 0 ? score / outOf : 0))) / 10000));
      this.set("cmi.completion_status", complete ? "completed" : "incomplete");
      this.set("cmi.success_status", passed == null || !complete ? "unknown" : passed ? "passed" : "failed");
    }
    const limit = this.version === "1.2" ? SUSPEND_LIMIT_12 : SUSPEND_LIMIT_2004;
    if (suspend != null && suspend.length > limit) {
      this.lastError = `suspend_data: the answers take ${suspend.length} characters, more than the ${limit} SCORM ${this.version} keeps; the score is sent, the answers cannot be resumed`;
    } else if (suspend != null) this.set("cmi.suspend_data", suspend);
    for (const b of boxes) this.interaction(b);
    return String(this.call("LMSCommit", "Commit", "")) === "true";
  }

  /**
   * One cmi.interactions.n for a checked box (n counts up: interactions are a
   * journal). The response goes as typed: SCORM 1.2 as a numeric interaction
   * (its student_response is kept as text by the LMSs); SCORM 2004's numeric
   * response must be a plain number, so a text with a unit goes as fill-in.
   */
  interaction({ id, label, response, verdict }) {
    const n = this.interactionsWritten++;
    const p = `cmi.interactions.${n}.`;
    const text = String(response ?? "").trim();
    const result = verdict === "correct" || verdict === "consistent" ? "correct" : verdict === "empty" ? "neutral" : "wrong";
    this.set(`${p}id`, id);
    if (this.version === "1.2") {
      this.set(`${p}type`, "numeric");
      this.set(`${p}student_response`, text.slice(0, 255));
      this.set(`${p}result`, result);
    } else {
      const plain = /^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/.test(text);
      this.set(`${p}type`, plain ? "numeric" : "fill-in");
      this.set(`${p}description`, String(label).slice(0, 250));
      this.set(`${p}learner_response`, text.slice(0, 250));
      this.set(`${p}result`, result === "wrong" ? "incorrect" : result);
    }
  }

  /** Closes the session: exit "suspend" while incomplete (the LMS keeps the attempt), then finish/terminate. */
  finish({ complete }) {
    if (!this.open) return false;
    this.set(this.version === "1.2" ? "cmi.core.exit" : "cmi.exit", complete ? "" : "suspend");
    this.call("LMSCommit", "Commit", "");
    const ok = String(this.call("LMSFinish", "Terminate", "")) === "true";
    this.open = false;
    return ok;
  }
}

/** A session with the LMS that launched this page, initialised; null when there is none. */
export function connect(win = globalThis.window, prefer = "1.2") {
  const found = findApi(win, prefer);
  if (!found) return null;
  const s = new ScormSession(found.version, found.api);
  s.initialize();
  return s;
}
