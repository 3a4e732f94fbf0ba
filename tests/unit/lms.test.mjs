// The LMS kit of www/lms/: the attempt text (suspend data and receipts), the
// SCORM runtime against scorm-again's LMS-side APIs, the manifest and the zip.
// (The attempt regraded by the real core: tests/e2e/lms-attempt.test.mjs.)

import test from "node:test";
import assert from "node:assert/strict";
import { Scorm12API, Scorm2004API } from "scorm-again";
import { unzipSync, strFromU8 } from "fflate";
import { AttemptError, decodeAttempt, encodeAttempt, MAX_TEXT } from "../../www/lms/attempt.js";
import { connect, findApi, interactionId, percent } from "../../www/lms/scorm.js";
import { manifestXml, xmlId } from "../../www/lms/manifest.js";
import { scormZip } from "../../www/lms/package.js";

const ITEMS = [
  { id: "gsd", code: "1K7Q2", answers: { scale_denominator: "12631,6", gsd_mm: "356 mm", gsd_cm: "" } },
  { id: "ncc-2d", code: "10000", answers: { "rho[2,1]": "−0.7012", note: "µm ° ü — 😀 & <x>" } },
  { id: "utm", code: "1ZZZZ", answers: {} },
];

test("an attempt's text round-trips ids, codes and the answers as typed (empty boxes left out)", () => {
  const text = encodeAttempt(ITEMS);
  assert.match(text, /^PGA1\.[A-Za-z0-9_-]+$/);
  const back = decodeAttempt(text);
  assert.deepEqual(back, [
    { id: "gsd", code: "1K7Q2", answers: { scale_denominator: "12631,6", gsd_mm: "356 mm" } },
    { id: "ncc-2d", code: "10000", answers: { "rho[2,1]": "−0.7012", note: "µm ° ü — 😀 & <x>" } },
    { id: "utm", code: "1ZZZZ", answers: {} },
  ]);
  // wrapped in an e-mail: whitespace anywhere is ignored
  assert.deepEqual(decodeAttempt(`  ${text.slice(0, 10)}\n ${text.slice(10)}\n`), back);
  // a long text is cut where the store cuts it
  const long = decodeAttempt(encodeAttempt([{ id: "gsd", code: "1K7Q2", answers: { a: "9".repeat(500) } }]));
  assert.equal(long[0].answers.a.length, MAX_TEXT);
});

test("a damaged, foreign or other-version text is refused with a message that says which", () => {
  const text = encodeAttempt(ITEMS);
  const refuse = (t, re) => assert.throws(() => decodeAttempt(t), (e) => e instanceof AttemptError && re.test(e.message), t.slice(0, 30));
  refuse("", /empty/);
  refuse("hello", /not a work receipt/);
  refuse(text.slice(0, text.length - 7), /damaged/);
  refuse(text.slice(0, 12) + (text[12] === "A" ? "B" : "A") + text.slice(13), /damaged/);
  refuse(text.replace(/^PGA1/, "PGA2"), /newer playground \(format 2\)/);
  refuse(text.replace(/^PGA1/, "PGA0"), /format \(0\) is no longer read/);
  // well-formed deflate of something that is not the list
  const notList = encodeAttempt([]).replace(/\..*/, ".") + "qwAAAA";
  assert.throws(() => decodeAttempt(notList), AttemptError);
  assert.throws(() => encodeAttempt([{ id: 3, code: "1K7Q2" }]), /items\[0\]: needs an example id/);
});

test("scores go to the LMS as 0–100 with at most two decimals; interaction ids are CMIIdentifiers", () => {
  assert.equal(percent(2, 3), "66.67");
  assert.equal(percent(3.5, 4), "87.5");
  assert.equal(percent(0, 0), "0");
  assert.equal(interactionId("ncc-2d", "1K7Q2", "rho[2,1]"), "ncc-2d_1K7Q2_rho-2-1-");
});

/** A window tree: the LMS's frame holds the API, the package runs two frames below. */
function frames(apiName, api) {
  const top = { [apiName]: api };
  top.parent = top;
  const middle = { parent: top };
  return { parent: middle, opener: null };
}

for (const version of ["1.2", "2004"]) {
  test(`SCORM ${version}: found through the parents, resumed from suspend_data, score, status and interactions written, exit suspend while incomplete`, () => {
    const api = version === "1.2" ? new Scorm12API({ autocommit: false, logLevel: 5 }) : new Scorm2004API({ autocommit: false, logLevel: 5 });
    const win = frames(version === "1.2" ? "API" : "API_1484_11", api);
    assert.equal(findApi(win)?.version, version);
    assert.equal(findApi({ parent: null, opener: win })?.version, version, "through the opener");
    assert.equal(findApi({ parent: null }), null);
    const s = connect(win);
    assert.ok(s.open, "initialised");
    assert.equal(s.suspendData(), "");
    const suspend = encodeAttempt(ITEMS);
    assert.ok(
      s.report({
        score: 1.5,
        outOf: 4,
        answered: 2,
        total: 4,
        passing: 80,
        suspend,
        boxes: [
          { id: interactionId("gsd", "1K7Q2", "gsd_mm"), label: "GSD in mm", response: "356 mm", verdict: "correct" },
          { id: interactionId("gsd", "1K7Q2", "scale_denominator"), label: "Scale number", response: "12631.6", verdict: "wrong" },
        ],
      }),
    );
    assert.equal(s.lastError, null);
    // what the LMS would store (scorm-again's commit body; 1.2's interactions are write-only through the API)
    let cmi = api.renderCommitCMI(true).cmi;
    if (version === "1.2") {
      assert.equal(cmi.core.score.raw, "37.5");
      assert.equal(cmi.core.score.max, "100");
      assert.equal(cmi.core.lesson_status, "incomplete");
      assert.equal(Object.keys(cmi.interactions).length, 2);
      assert.equal(cmi.interactions[0].id, "gsd_1K7Q2_gsd_mm");
      assert.equal(cmi.interactions[0].type, "numeric");
      assert.equal(cmi.interactions[0].student_response, "356 mm");
      assert.equal(cmi.interactions[0].result, "correct");
      assert.equal(cmi.interactions[1].result, "wrong");
    } else {
      assert.equal(cmi.score.raw, "37.5");
      assert.equal(cmi.score.scaled, "0.375");
      assert.equal(cmi.completion_status, "incomplete");
      assert.equal(cmi.success_status, "unknown");
      const [a, b] = [cmi.interactions[0], cmi.interactions[1]];
      assert.equal(a.type, "fill-in", "a response with a unit is not a SCORM 2004 number");
      assert.equal(a.learner_response, "356 mm");
      assert.equal(a.description, "GSD in mm");
      assert.equal(b.type, "numeric");
      assert.equal(b.learner_response, "12631.6");
      assert.equal(b.result, "incorrect");
    }
    assert.equal(cmi.suspend_data, suspend);
    assert.deepEqual(decodeAttempt(s.suspendData()), decodeAttempt(suspend));
    // every box answered, 3.5 of 4 = 87.5 ≥ 80: passed
    s.report({ score: 3.5, outOf: 4, answered: 4, total: 4, passing: 80, suspend, boxes: [] });
    cmi = api.renderCommitCMI(true).cmi;
    if (version === "1.2") assert.equal(cmi.core.lesson_status, "passed");
    else assert.deepEqual([cmi.completion_status, cmi.success_status], ["completed", "passed"]);
    s.report({ score: 2, outOf: 4, answered: 4, total: 4, passing: 80, suspend, boxes: [] });
    cmi = api.renderCommitCMI(true).cmi;
    if (version === "1.2") assert.equal(cmi.core.lesson_status, "failed");
    else assert.equal(cmi.success_status, "failed");
    s.report({ score: 2, outOf: 4, answered: 4, total: 4, passing: null, suspend, boxes: [] });
    cmi = api.renderCommitCMI(true).cmi;
    if (version === "1.2") assert.equal(cmi.core.lesson_status, "completed", "no passing score: completed");
    // answers too long for the LMS to keep: the score goes, the page is told why the answers cannot
    const before = cmi.suspend_data;
    s.report({ score: 2, outOf: 4, answered: 4, total: 4, suspend: "x".repeat(version === "1.2" ? 4097 : 64001), boxes: [] });
    assert.match(s.lastError, /^suspend_data: the answers take (4097|64001) characters, more than the (4096|64000) SCORM (1.2|2004) keeps/);
    assert.equal(api.renderCommitCMI(true).cmi.suspend_data, before);
    assert.ok(s.finish({ complete: false }));
    cmi = api.renderCommitCMI(true).cmi;
    assert.equal(version === "1.2" ? cmi.core.exit : cmi.exit, "suspend");
    assert.equal(s.open, false);
  });
}

test("the manifest names every file once, with SCORM 1.2's and 2004's namespaces and required elements", () => {
  const files = ["index.html", "assets/app-X.js", "assets/a&b.css"];
  const m12 = manifestXml({ version: "1.2", identifier: "pp gsd 1", title: "Practice: GSD & scale", launch: "index.html", files, passing: 80 });
  assert.match(m12, /^<\?xml version="1.0" encoding="UTF-8"\?>\n<manifest identifier="pp_gsd_1" version="1.0" xmlns="http:\/\/www.imsproject.org\/xsd\/imscp_rootv1p1p2" xmlns:adlcp="http:\/\/www.adlnet.org\/xsd\/adlcp_rootv1p2"/);
  assert.match(m12, /<schema>ADL SCORM<\/schema>\s*<schemaversion>1.2<\/schemaversion>/);
  assert.match(m12, /<organizations default="org">\s*<organization identifier="org">\s*<title>Practice: GSD &amp; scale<\/title>\s*<item identifier="item" identifierref="sco" isvisible="true">/);
  assert.match(m12, /<adlcp:masteryscore>80<\/adlcp:masteryscore>/);
  assert.match(m12, /<resource identifier="sco" type="webcontent" adlcp:scormtype="sco" href="index.html">/);
  assert.deepEqual([...m12.matchAll(/<file href="([^"]*)"\/>/g)].map((x) => x[1]), ["index.html", "assets/app-X.js", "assets/a&amp;b.css"]);
  const m04 = manifestXml({ version: "2004", identifier: "x", title: "T", launch: "index.html", files, passing: 75 });
  assert.match(m04, /xmlns="http:\/\/www.imsglobal.org\/xsd\/imscp_v1p1"/);
  for (const ns of ["adlcp_v1p3", "adlseq_v1p3", "adlnav_v1p3"]) assert.ok(m04.includes(`http://www.adlnet.org/xsd/${ns}`), ns);
  assert.match(m04, /<schemaversion>2004 4th Edition<\/schemaversion>/);
  assert.match(m04, /adlcp:scormType="sco"/);
  assert.match(m04, /<imsss:minNormalizedMeasure>0.75<\/imsss:minNormalizedMeasure>/);
  // tags balanced (a well-formedness check without an XML library: every element closed in order)
  for (const m of [m12, m04]) {
    const stack = [];
    for (const [, close, name, self] of m.replace(/<\?xml[^>]*\?>/, "").matchAll(/<(\/?)([A-Za-z:]+)[^>]*?(\/?)>/g)) {
      if (self) continue;
      if (close) assert.equal(stack.pop(), name);
      else stack.push(name);
    }
    assert.deepEqual(stack, []);
  }
  assert.throws(() => manifestXml({ version: "2.0", identifier: "x", title: "t", launch: "index.html", files }), /version: "2.0"/);
  assert.throws(() => manifestXml({ version: "1.2", identifier: "x", title: "t", launch: "start.html", files }), /launch: "start.html"/);
  assert.equal(xmlId("9-gsd"), "_9-gsd");
});

test("the zip holds exactly the files the manifest lists, plus the manifest", () => {
  const zip = scormZip({ identifier: "p", title: "t", launch: "index.html", files: { "index.html": "<!doctype html>", "assets/x.js": new Uint8Array([1, 2, 3]), "fonts/k.woff2": new Uint8Array(100) } });
  const out = unzipSync(zip);
  const listed = [...strFromU8(out["imsmanifest.xml"]).matchAll(/<file href="([^"]*)"\/>/g)].map((x) => x[1]);
  assert.deepEqual(Object.keys(out).sort(), ["assets/x.js", "fonts/k.woff2", "imsmanifest.xml", "index.html"]);
  assert.deepEqual(listed.sort(), ["assets/x.js", "fonts/k.woff2", "index.html"]);
  assert.deepEqual([...out["assets/x.js"]], [1, 2, 3]);
  assert.throws(() => scormZip({ identifier: "p", title: "t", launch: "index.html", files: { "index.html": "", "../x": "" } }), /"..\/x" is not a relative path/);
});
