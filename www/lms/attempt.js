// A practice attempt as text: the example ids, variant codes and the answers
// exactly as typed — nothing derived (no value, no verdict, no score). It is
// what a SCORM package keeps in `cmi.suspend_data` and what a student's work
// receipt holds; both are regraded by the core on reading, so an edited text
// can only earn what its answers earn.
//
//   text    = "PGA" VERSION "." base64url(deflate-raw(utf-8(JSON)))
//   JSON    = [[id, code, [[box key, text], …]], …]   (boxes left empty are left out)
//
// deflate (fflate, the page's one compression library) keeps a worksheet of
// 20 variants of a topic's examples inside SCORM 1.2's 4,096 characters
// (tests/unit/lms-attempt.test.mjs measures the largest); base64url keeps it
// safe in a URL, an LMS's database and a QR code.

import { deflateSync, inflateSync, strFromU8, strToU8 } from "fflate";

/** The attempt text's own format version (the codes carry the generators' version). */
export const ATTEMPT_VERSION = 1;
const PREFIX = "PGA";
/** Longest answer text kept (a box holds one number; as store.js keeps it). */
export const MAX_TEXT = 200;
/** At most this many variants in one attempt (a worksheet's largest is well below). */
export const MAX_ITEMS = 400;

/** A reason the text could not be read: `.field` says which part. */
export class AttemptError extends Error {
  constructor(message) {
    super(message);
    this.name = "AttemptError";
  }
}

function toBase64Url(bytes) {
  let bin = "";
  for (let i = 0; i < bytes.length; i += 0x8000) bin += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(bin).replace(/\+/g, "-").replace(/\//g, "_").replace(/=+$/, "");
}

function fromBase64Url(text) {
  const b64 = text.replace(/-/g, "+").replace(/_/g, "/");
  const bin = atob(b64 + "=".repeat((4 - (b64.length % 4)) % 4));
  const out = new Uint8Array(bin.length);
  for (let i = 0; i < bin.length; i++) out[i] = bin.charCodeAt(i);
  return out;
}

/**
 * The attempt as text. `items`: [{ id, code, answers: { key: text } }]; empty
 * answers are left out, texts cut at MAX_TEXT characters.
 */
export function encodeAttempt(items) {
  if (!Array.isArray(items)) throw new AttemptError("items: must be a list of { id, code, answers }");
  if (items.length > MAX_ITEMS) throw new AttemptError(`items: at most ${MAX_ITEMS} variants in one attempt, not ${items.length}`);
  const rows = items.map((it, k) => {
    if (!it || typeof it.id !== "string" || typeof it.code !== "string") throw new AttemptError(`items[${k}]: needs an example id and a variant code (strings)`);
    const answers = Object.entries(it.answers ?? {})
      .filter(([, v]) => typeof v === "string" && v.trim() !== "")
      .map(([key, v]) => [key, v.slice(0, MAX_TEXT)]);
    return [it.id, it.code, answers];
  });
  return `${PREFIX}${ATTEMPT_VERSION}.${toBase64Url(deflateSync(strToU8(JSON.stringify(rows)), { level: 9 }))}`;
}

/**
 * Reads an attempt text back: [{ id, code, answers }]. Whitespace (a receipt
 * copied from an e-mail, wrapped) is ignored. Throws AttemptError with what is
 * wrong: not a receipt, another version, damaged.
 */
export function decodeAttempt(text) {
  if (typeof text !== "string" || !text.trim()) throw new AttemptError("The receipt is empty: paste the whole text, which starts with PGA1.");
  const t = text.replace(/\s+/g, "");
  const m = /^PGA(\d+)\.([A-Za-z0-9_-]+)$/.exec(t);
  if (!m) throw new AttemptError("This is not a work receipt: a receipt starts with PGA1. and holds only letters, digits, - and _.");
  const version = Number(m[1]);
  if (version !== ATTEMPT_VERSION) {
    throw new AttemptError(
      version > ATTEMPT_VERSION
        ? `This receipt was made by a newer playground (format ${version}); this one reads format ${ATTEMPT_VERSION}.`
        : `This receipt's format (${version}) is no longer read; this playground reads format ${ATTEMPT_VERSION}.`,
    );
  }
  let rows;
  try {
    rows = JSON.parse(strFromU8(inflateSync(fromBase64Url(m[2]))));
  } catch {
    throw new AttemptError("This receipt is damaged (part of it is missing or changed): copy it again, whole.");
  }
  const bad = () => new AttemptError("This receipt is damaged: its contents are not a list of examples, codes and answers.");
  if (!Array.isArray(rows) || rows.length > MAX_ITEMS) throw bad();
  return rows.map((row) => {
    if (!Array.isArray(row) || row.length !== 3 || typeof row[0] !== "string" || typeof row[1] !== "string" || !Array.isArray(row[2])) throw bad();
    const answers = {};
    for (const pair of row[2]) {
      if (!Array.isArray(pair) || pair.length !== 2 || typeof pair[0] !== "string" || typeof pair[1] !== "string") throw bad();
      answers[pair[0]] = pair[1].slice(0, MAX_TEXT);
    }
    return { id: row[0], code: row[1], answers };
  });
}

/**
 * Grades every variant of an attempt with the core (`core.practice` for the
 * boxes, `core.grade` for the verdicts): the score is computed here, never
 * read. Returns { items: [{ id, code, answers, variant, graded, error }],
 * score, out_of }; a variant whose code the core refuses (an old generator
 * version, an unknown example) has `error` (its message) and counts its
 * boxes as 0 when known, else nothing.
 */
export function gradeAttempt(core, items) {
  let score = 0;
  let outOf = 0;
  const graded = items.map((it) => {
    try {
      const variant = core.practice(it.id, it.code);
      const g = core.grade(it.id, variant.code, it.answers);
      score += g.score;
      outOf += g.out_of;
      return { ...it, variant, graded: g, error: null };
    } catch (e) {
      return { ...it, variant: null, graded: null, error: e?.message ?? String(e) };
    }
  });
  return { items: graded, score, out_of: outOf };
}
