// The practice page of a SCORM package (www/lms/download.js made it): every
// variant of the package on one page, the boxes checked by the core as in
// practice mode (www/practice/view.js's boxes), the attempt resumed from the
// LMS's cmi.suspend_data and each check reported to it (www/lms/scorm.js).
// Outside an LMS the page still works as plain practice and says that scores
// are not being sent.

import { el } from "../dom.js";
import { lmsStyles } from "./styles.js";
import { siteTitle } from "../site.js";
import { renderGivens } from "../practice/common.js";
import { mountBoxes } from "../practice/view.js";
import { testHook } from "../test-hooks.js";
import { AttemptError, decodeAttempt, encodeAttempt } from "./attempt.js";
import { connect, interactionId } from "./scorm.js";
import { PACKAGE_BLOCK } from "./download.js";
import { receiptBox } from "./receipt-box.js";

/** The package's settings (its index.html's data block), or null on the site itself. */
export function packageSettings(doc = document) {
  const block = doc.getElementById(PACKAGE_BLOCK);
  if (!block) return null;
  try {
    return JSON.parse(block.textContent);
  } catch {
    return null;
  }
}

/** The attempt to show: the LMS's saved one when it fits the package, else the package's variants (or new ones). */
function startingItems(settings, saved) {
  const ids = new Set(settings.items ? settings.items.map((it) => it.id) : settings.fresh.ids);
  if (saved) {
    try {
      const items = decodeAttempt(saved);
      if (items.length && items.every((it) => ids.has(it.id))) return { items, resumed: true, note: null };
      return { items: null, resumed: false, note: "The saved attempt is for other examples than this package's; it starts afresh." };
    } catch (e) {
      if (!(e instanceof AttemptError)) throw e;
      return { items: null, resumed: false, note: `The saved attempt could not be read (${e.message}); it starts afresh.` };
    }
  }
  return { items: null, resumed: false, note: null };
}

export async function showLmsPractice({ root, core, entries, setStatus }, settings) {
  lmsStyles();
  document.title = siteTitle(settings.title);
  const session = connect(window, settings.scorm);
  const start = startingItems(settings, session?.suspendData() || null);
  const ids = [...new Set(settings.items ? settings.items.map((it) => it.id) : settings.fresh.ids)];
  await Promise.all(ids.map((id) => core.loadPractice(id)));
  let items = start.items;
  if (!items) {
    items = settings.items
      ? settings.items.map((it) => ({ id: it.id, code: it.code, answers: {} }))
      : settings.fresh.ids.flatMap((id) => Array.from({ length: settings.fresh.n }, () => ({ id, code: core.practice(id, null).code, answers: {} })));
  }
  const byId = new Map(entries.map((e) => [e.id, e]));

  const where = el("p", { class: "lms-status", role: "status" });
  const connected = session ? `Your score goes to your course (SCORM ${session.version}) after each box you check.${start.resumed ? " Your earlier answers are back." : ""}` : "";
  const score = el("p", { class: "practice-score", role: "status" });
  const sections = [];
  const mounted = items.map((it, k) => {
    const entry = byId.get(it.id);
    const variant = core.practice(it.id, it.code);
    const boxes = mountBoxes({ core, id: it.id, code: variant.code, variant, answers: it.answers, idPrefix: `v${k}-`, onChecked: (key, g) => checkedBox(k, key, g) });
    sections.push(
      el(
        "section",
        { class: "panel lms-item", "data-id": it.id, "data-code": variant.code, "aria-labelledby": `v${k}-h` },
        el("h3", { id: `v${k}-h` }, `${k + 1}. ${entry?.title ?? it.id} · variant ${variant.code}`),
        el("div", { class: "givens-panel" }, el("h4", {}, "Given"), renderGivens(entry, variant.inputs)),
        el("h4", {}, "Your answers"),
        boxes.element,
      ),
    );
    return { it, variant, boxes };
  });

  /** A box left: to the LMS as an interaction when its verdict is new (Enter then Tab grade twice). */
  const told = new Map();
  function checkedBox(k, key, g) {
    const r = g.boxes[key];
    const said = JSON.stringify([r?.verdict, mounted[k]?.boxes.texts()[key]]);
    if (!r || r.verdict === "empty" || told.get(`${k}/${key}`) === said) return report();
    told.set(`${k}/${key}`, said);
    report([{ k, key }]);
  }

  // the receipt's address is the playground's own (a package's page has no receipt view)
  const receipt = receiptBox(() => attempt(), { site: settings.site ?? location.href });

  function attempt() {
    return mounted.map(({ it, variant, boxes }) => ({ id: it.id, code: variant.code, answers: boxes.texts() }));
  }

  /**
   * Totals now; with `checked` ([{ k, key }]), those boxes go to the LMS as
   * interactions. Returns whether every box is answered.
   */
  function report(checked = []) {
    let total = 0;
    let outOf = 0;
    let answered = 0;
    let boxes = 0;
    for (const m of mounted) {
      const g = m.boxes.graded();
      total += g.score;
      outOf += g.out_of;
      boxes += Object.keys(g.boxes).length;
      answered += Object.values(g.boxes).filter((r) => r.verdict !== "empty").length;
    }
    const text = `Score: ${Math.round(total * 100) / 100} of ${outOf}`;
    if (score.textContent !== text) score.textContent = text;
    testHook("lmsScore", `${total}/${outOf}`);
    if (!session) return answered >= boxes;
    const sent = session.report({
      score: total,
      outOf,
      answered,
      total: boxes,
      passing: settings.passing,
      suspend: encodeAttempt(attempt()),
      boxes: checked.map(({ k, key }) => {
        const m = mounted[k];
        const r = m.boxes.graded().boxes[key];
        return { id: interactionId(m.it.id, m.variant.code, key), label: m.variant.boxes.find((b) => b.key === key)?.label ?? key, response: m.boxes.texts()[key] ?? "", verdict: r?.verdict ?? "empty" };
      }),
    });
    const text2 = sent && !session.lastError ? connected : `Your course did not take the score: ${session.lastError ?? "the LMS refused to save"}. Copy a work receipt to keep your answers.`;
    if (where.textContent !== text2) where.textContent = text2;
    return answered >= boxes;
  }

  where.textContent = session ? connected : "No course system (LMS) found: this is practice only, and scores are not being sent anywhere.";
  root.replaceChildren(
    el(
      "article",
      { class: "practice lms-practice" },
      el("header", { class: "example-head" }, el("h2", { id: "practice-title", tabindex: "-1" }, settings.title), where, start.note ? el("p", { class: "muted" }, start.note) : null),
      el("p", { class: "muted" }, "Work in order; each box is checked when you leave it (Tab or Enter). A decimal comma, 1.2e-3, 3/4 and a unit after the number are all read."),
      sections,
      score,
      el("div", { class: "actions" }, receipt.button),
      receipt.element,
    ),
  );
  report();
  if (session) {
    window.addEventListener("pagehide", () => {
      session.finish({ complete: report() });
    });
  }
  testHook("lms", session ? session.version : "none");
  setStatus("lms");
}
