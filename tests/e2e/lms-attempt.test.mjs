// The attempt text (SCORM suspend data, work receipts) with the real core, in
// Node (no browser): every example's answers survive the round trip and are
// regraded to the same verdicts; an edited text earns only what its answers
// earn; the largest worksheet's attempt fits SCORM 1.2's 4,096 characters.

import test from "node:test";
import assert from "node:assert/strict";
import { nodeModule } from "./harness.mjs";
import { decodeAttempt, encodeAttempt, gradeAttempt } from "../../www/lms/attempt.js";
import { MAX_VARIANTS_12, SUSPEND_LIMIT_12, SUSPEND_LIMIT_2004 } from "../../www/lms/scorm.js";

const core = await nodeModule("all");
const entries = core.catalog().filter((e) => e.status === "ready" && e.practice);
/** The worksheet maker's largest: every example of a topic, this many variants each (www/practice/sheets.js MAX_VARIANTS). */
const MAX_VARIANTS = 20;

/** A student's typing of the expected value: 6 significant digits, a decimal comma now and then, the unit. */
function typed(box, k) {
  const x = box.expected;
  if (typeof x !== "number") return String(x);
  let t = Number(x.toPrecision(6)).toString();
  if (k % 3 === 1) t = t.replace(".", ",");
  return box.unit ? `${t} ${box.unit}` : t;
}

function answered(id, code) {
  const v = core.practice(id, code);
  const answers = {};
  v.boxes.forEach((b, k) => (answers[b.key] = typed(b, k)));
  return { id, code: v.code, answers };
}

test("every example's answers round-trip through the text and regrade to the core's own grade", () => {
  assert.ok(entries.length >= 26, `${entries.length} examples with practice`);
  const items = [];
  for (const e of entries) for (const code of ["10000", "1ZZZZ", "1K7Q2"]) items.push(answered(e.id, code));
  const back = decodeAttempt(encodeAttempt(items));
  assert.deepEqual(back, items);
  const g = gradeAttempt(core, back);
  let score = 0;
  let outOf = 0;
  for (const [k, it] of g.items.entries()) {
    assert.equal(it.error, null, `${it.id} ${it.code}`);
    const direct = core.grade(items[k].id, items[k].code, items[k].answers);
    assert.deepEqual(it.graded, direct, `${it.id} ${it.code}`);
    score += direct.score;
    outOf += direct.out_of;
  }
  assert.deepEqual([g.score, g.out_of], [score, outOf]);
  assert.ok(score > 0.9 * outOf, `the expected values typed to 6 digits earn most points: ${score} of ${outOf}`);
});

test("an edited text earns what its answers earn, not what it claims; an old code is refused by the core", () => {
  const item = answered("gsd", "1K7Q2");
  const honest = gradeAttempt(core, decodeAttempt(encodeAttempt([item])));
  const key = Object.keys(item.answers)[0];
  const edited = gradeAttempt(core, decodeAttempt(encodeAttempt([{ ...item, answers: { ...item.answers, [key]: "12345" }, score: 99 }])));
  assert.equal(edited.items[0].graded.boxes[key].verdict === "correct", false);
  assert.ok(edited.score < honest.score, `${edited.score} < ${honest.score}`);
  assert.deepEqual(edited.items[0].graded, core.grade("gsd", "1K7Q2", { ...item.answers, [key]: "12345" }));
  const old = gradeAttempt(core, [{ id: "gsd", code: "0K7Q2", answers: {} }]);
  assert.match(old.items[0].error, /version-0 code; this playground makes version-1 codes/);
  assert.deepEqual([old.score, old.out_of], [0, 0]);
});

/** The longest attempt text of a topic's examples × `variants` each, every box typed. */
function largest(variants) {
  const byTopic = new Map();
  for (const e of entries) byTopic.set(e.topic, [...(byTopic.get(e.topic) ?? []), e]);
  let top = null;
  for (const [topic, list] of byTopic) {
    const items = [];
    for (const e of list) for (let n = 0; n < variants; n++) items.push(answered(e.id, core.practice(e.id, null).code));
    const text = encodeAttempt(items);
    if (!top || text.length > top.length) top = { topic, length: text.length, variants: items.length, boxes: items.reduce((s, it) => s + Object.keys(it.answers).length, 0) };
  }
  return top;
}

test("the largest package's attempt (a topic's examples, every box typed) fits suspend_data: 10 variants each in SCORM 1.2, 20 in 2004", () => {
  const v12 = largest(MAX_VARIANTS_12);
  console.log(`SCORM 1.2, ${MAX_VARIANTS_12} variants an example: ${v12.topic}, ${v12.variants} variants, ${v12.boxes} boxes, ${v12.length} characters`);
  assert.ok(v12.length <= SUSPEND_LIMIT_12, `${v12.topic}: ${v12.length} characters`);
  const v04 = largest(MAX_VARIANTS);
  console.log(`SCORM 2004, ${MAX_VARIANTS} variants an example: ${v04.topic}, ${v04.variants} variants, ${v04.boxes} boxes, ${v04.length} characters`);
  assert.ok(v04.length <= SUSPEND_LIMIT_2004, `${v04.topic}: ${v04.length} characters`);
});
