// The fiducials family: Example 4 on the generated scanned frame: the
// student clicks (or types) the four marks, each refined by NCC and LSM, the
// similarity and affine transformations fitted, residuals drawn as arrows,
// compared with the frame's known truth.

import { el } from "../../dom.js";
import { fmt } from "../view.js";
import { exampleFor } from "../explain.js";
import { testHook } from "../../test-hooks.js";
import { runButton } from "./common.js";

/** Where each of Example 4's fiducials sits on the frame (its calibrated x, y). */
export const MARK_NAMES = ["left", "right", "top", "bottom"];

/** The largest "nice" number (1, 2, 5 × 10ⁿ) not above `v`. */
export function niceFloor(v) {
  const e = 10 ** Math.floor(Math.log10(v));
  const m = v / e;
  return (m >= 5 ? 5 : m >= 2 ? 2 : 1) * e;
}

/**
 * Residual arrows: `v` (mm, [vx, vy]×4, x right, y up) at the marks
 * ([c, r]×4) enlarged so that the largest is about `reach` image pixels.
 * Returns the enlargement, the arrows, and a scale bar of a nice length.
 */
export function residualArrows(marks, sets, pixelMm, reach = 120) {
  const biggest = Math.max(1e-9, ...sets.flatMap(({ v }) => v.map(Math.abs)));
  const times = niceFloor((reach * pixelMm) / biggest);
  const arrows = [];
  for (const { v, colour } of sets) {
    for (let k = 0; k < 4; k++) {
      const [c, r] = [marks[2 * k], marks[2 * k + 1]];
      arrows.push({ kind: "arrow", from: [c, r], to: [c + (v[2 * k] * times) / pixelMm, r - (v[2 * k + 1] * times) / pixelMm], colour, width: 2 });
    }
  }
  // a bar of a nice residual (mm) about reach/2 pixels long once enlarged
  const barMm = niceFloor((reach / 2) * pixelMm / times);
  return { times, arrows, barMm, barPx: (barMm * times) / pixelMm };
}

/** µm for people. */
function um(mm) {
  return fmt(mm * 1000, 3);
}

/** (its id and title are in lab.js's FAMILIES: this module is loaded when the family is chosen) */
const fiducials = {
  create(lab, box) {
    const start = el("button", { type: "button", class: "lab-run", id: "lab-fid-start" }, "Measure the four marks yourself");
    const refine = el("input", { type: "checkbox", id: "lab-fid-refine", checked: true });
    const typed = el("input", { type: "text", id: "lab-fid-typed", size: "40", placeholder: "c, r; c, r; c, r; c, r", "aria-describedby": "lab-fid-typed-help" });
    const use = el("button", { type: "button", id: "lab-fid-use" }, "Use these positions");
    const auto = runButton("Or let the lab measure all four");
    const prompt = el("p", { class: "lab-prompt", id: "lab-fid-prompt", "aria-live": "polite" }, "Open the generated scanned frame and press “Measure the four marks yourself”.");
    const marksBox = el("div", { id: "lab-fid-marks" });
    box.append(start, " ", el("label", {}, refine, " refine each click (the mark's template matched by NCC within ±12 px, then LSM)"),
      prompt,
      el("p", { class: "lab-typed" }, el("label", {}, "Or type the four positions (column, row) ", typed), " ", use,
        el("span", { class: "muted", id: "lab-fid-typed-help" }, ` In the order ${MARK_NAMES.map((n, i) => `${i + 1} ${n}`).join(", ")}.`)),
      marksBox,
      el("p", { class: "muted" }, "Example 4's similarity and affine transformations are then fitted to your measurements (pixel column c and row r, with x′ = c, y′ = −r, to the calibrated x, y in mm), and their residuals drawn as arrows. The frame was generated at a known affine distortion, so your fit is compared to the truth. ", auto));
    /** The student's marks: { clicked: [x, y], measured: [c, r], moved, ncc } by index. */
    let marks = [null, null, null, null];
    let next = null;
    const ensureFrame = async () => {
      if (lab.image?.truth === undefined) {
        await lab.openSample("frame");
        lab.sampleSelect.value = "frame";
      }
      return lab.image?.truth ?? null;
    };
    const ask = () => {
      next = marks.findIndex((m) => !m);
      if (next < 0) next = null;
      prompt.textContent = next === null
        ? "All four marks measured. Redo one by its button, or start again."
        : `Click fiducial ${next + 1} (${MARK_NAMES[next]}: the bright dot in the middle of the frame's ${MARK_NAMES[next]} side). Zoom in (wheel, + or pinch) to click it precisely.`;
      testHook("fidNext", next === null ? "done" : String(next + 1));
    };
    const shapesOf = (extra = []) => {
      const shapes = [];
      marks.forEach((m, k) => {
        if (!m) return;
        shapes.push({ kind: "cross", c: m.clicked[0], r: m.clicked[1], size: 7, colour: "#0b7285", width: 1.5 });
        shapes.push({ kind: "dot", c: m.measured[0], r: m.measured[1], size: 2.5, colour: "#ff8c00" });
        shapes.push({ kind: "text", c: m.measured[0] + 14, r: m.measured[1] - 14, text: String(k + 1), colour: "#0b7285" });
      });
      return [...shapes, ...extra];
    };
    const table = () => {
      const truth = lab.image.truth;
      const head = ["mark", "clicked c, r", "measured c, r", "refinement moved it by", "true c, r", "error (px)", ""];
      const rows = marks.map((m, k) => {
        const redo = el("button", { type: "button", id: `lab-fid-redo-${k + 1}`, disabled: !m }, `Redo ${k + 1}`);
        redo.addEventListener("click", () => {
          marks[k] = null;
          next = k;
          prompt.textContent = `Click fiducial ${k + 1} (${MARK_NAMES[k]}) again.`;
          testHook("fidNext", String(k + 1));
          lab.viewer.setShapes(shapesOf());
          table();
          lab.explain.hidden = true;
        });
        const [tc, tr] = [truth.marks[2 * k], truth.marks[2 * k + 1]];
        return el("tr", {},
          el("td", {}, `${k + 1} (${MARK_NAMES[k]})`),
          el("td", {}, m ? `${fmt(m.clicked[0], 6)}, ${fmt(m.clicked[1], 6)}` : "–"),
          el("td", {}, m ? `${fmt(m.measured[0], 7)}, ${fmt(m.measured[1], 7)}` : "–"),
          el("td", {}, m ? (m.refined ? `${fmt(m.moved, 3)} px (Δc ${fmt(m.measured[0] - m.clicked[0], 3)}, Δr ${fmt(m.measured[1] - m.clicked[1], 3)}; ρ = ${fmt(m.ncc, 4)})` : "not refined") : "–"),
          el("td", {}, `${fmt(tc, 7)}, ${fmt(tr, 7)}`),
          el("td", { class: "lab-fid-error" }, m ? fmt(Math.hypot(m.measured[0] - tc, m.measured[1] - tr), 3) : "–"),
          el("td", {}, redo));
      });
      marksBox.replaceChildren(el("table", { class: "lab-table", id: "lab-fid-table" }, el("tr", {}, head.map((h) => el("th", {}, h))), rows));
    };
    const setMark = async (k, x, y) => {
      let m = { clicked: [x, y], measured: [x, y], refined: false, moved: 0, ncc: null };
      if (refine.checked) {
        const r = await lab.run("refineMark", { c: x, r: y }, `Refining fiducial ${k + 1}`);
        if (!r) return;
        m = { ...m, measured: [r[0], r[1]], refined: true, moved: Math.hypot(r[0] - x, r[1] - y), ncc: r[2] };
        if (m.moved > 8) lab.say(`Fiducial ${k + 1}: the refinement moved your click by ${fmt(m.moved, 3)} px — check that it found the mark, or redo it.`);
      }
      marks[k] = m;
      ask();
      lab.viewer.setShapes(shapesOf());
      table();
      if (next === null) await fit();
    };
    const fit = async () => {
      const truth = lab.image.truth;
      const measured = marks.flatMap((m) => m.measured);
      const res = await lab.run("fitMarks", { measured }, "Fitting Example 4");
      if (!res) return;
      const sim = Array.from(res.similarity.residuals);
      const aff = Array.from(res.affine.residuals);
      const { times, arrows, barMm, barPx } = residualArrows(measured, [{ v: sim, colour: "#1f77b4" }, { v: aff, colour: "#d62728" }], truth.pixel_mm);
      const y0 = lab.image.height - 40;
      const bar = [
        { kind: "line", from: [30, y0], to: [30 + barPx, y0], colour: "#ffd43b", width: 4 },
        { kind: "text", c: 30, r: y0 - 18, text: `${um(barMm)} µm (arrows × ${times})`, colour: "#ffd43b", halo: "#000" },
      ];
      lab.viewer.setShapes(shapesOf([...arrows, ...bar]));
      // the fitted affine against the truth: the largest difference of the two maps over the frame's corners
      const A = Array.from(res.affine.params);
      const T = Array.from(truth.affine);
      const apply = (p, c, r) => [p[0] * c + p[1] * -r + p[2], p[3] * c + p[4] * -r + p[5]];
      const corners = [[0, 0], [lab.image.width - 1, 0], [0, lab.image.height - 1], [lab.image.width - 1, lab.image.height - 1]];
      const worst = Math.max(...corners.map(([c, r]) => {
        const [a, b] = [apply(A, c, r), apply(T, c, r)];
        return Math.hypot(a[0] - b[0], a[1] - b[1]);
      }));
      const errors = marks.map((m, k) => Math.hypot(m.measured[0] - truth.marks[2 * k], m.measured[1] - truth.marks[2 * k + 1]));
      const rms = Math.sqrt(errors.reduce((a, e) => a + e * e, 0) / 4);
      const pts = marks.map((m, k) => [m.measured[0], m.measured[1], truth.calibrated[2 * k], truth.calibrated[2 * k + 1]].join(",")).join(";");
      const q = encodeURIComponent(pts).replace(/%2C/g, ",").replace(/%3B/g, ";");
      const params = (p) => Array.from(p).map((v) => fmt(v, 7)).join(", ");
      lab.explain.replaceChildren(
        el("table", { class: "lab-table", id: "lab-fid-fit" },
          el("tr", {}, ["mark", "similarity vx, vy (µm)", "affine vx, vy (µm)"].map((h) => el("th", {}, h))),
          [0, 1, 2, 3].map((k) => el("tr", {}, el("td", {}, `${k + 1} (${MARK_NAMES[k]})`),
            el("td", {}, `${um(sim[2 * k])}, ${um(sim[2 * k + 1])}`), el("td", {}, `${um(aff[2 * k])}, ${um(aff[2 * k + 1])}`)))),
        el("p", { id: "lab-fid-scale" }, `Residual arrows (blue: similarity, red: affine) are drawn ${times}× enlarged; the yellow bar is ${um(barMm)} µm.`),
        el("p", {}, `Similarity [a, b, c, d]: ${params(res.similarity.params)}; σ0 = ${fmt(res.similarity.sigma0 ?? NaN)} mm.`),
        el("p", {}, `Affine [a, b, e, c, d, f]: ${params(A)}; σ0 = ${fmt(res.affine.sigma0 ?? NaN)} mm.`),
        el("p", { id: "lab-fid-truth" }, `The truth of the generated frame: affine ${params(T)}. Your marks are ${fmt(rms, 3)} px (RMS) from the true mark centres; your affine differs from the true one by at most ${um(worst)} µm over the frame (corners).`),
        el("p", {}, el("a", { href: `index.html#/${exampleFor("fiducials", "affine")}?points=${q}`, id: "lab-fid-link" }, "Open Example 4 (affine) with your measurements →"), " · ",
          el("a", { href: `index.html#/${exampleFor("fiducials", "similarity")}?points=${q}`, id: "lab-fid-link-similarity" }, "similarity →")),
      );
      lab.explain.hidden = false;
      testHook("fidResiduals", JSON.stringify({ similarity: sim, affine: aff, times }));
      testHook("fidAffine", A.join(","));
    };
    start.addEventListener("click", async () => {
      if (!(await ensureFrame())) return;
      marks = [null, null, null, null];
      lab.clearResult();
      ask();
      table();
      lab.canvasFocus?.();
    });
    use.addEventListener("click", async () => {
      const truth = await ensureFrame();
      if (!truth) return;
      const nums = typed.value.split(/[;,\s]+/).filter(Boolean).map(Number);
      if (nums.length !== 8 || nums.some((v) => !Number.isFinite(v))) {
        lab.showError("positions: type four positions as c, r; c, r; c, r; c, r (eight numbers)");
        typed.setAttribute("aria-invalid", "true");
        typed.focus();
        return;
      }
      typed.setAttribute("aria-invalid", "false");
      lab.clearError();
      marks = [null, null, null, null];
      for (let k = 0; k < 4; k++) await setMark(k, nums[2 * k], nums[2 * k + 1]);
    });
    auto.addEventListener("click", async () => {
      const truth = await ensureFrame();
      if (!truth) return;
      const res = await lab.run("fiducials", { approx: Array.from(truth.nominal) }, "Measuring the marks");
      if (!res) return;
      const m = res.marks;
      marks = [0, 1, 2, 3].map((k) => ({ clicked: [truth.nominal[2 * k], truth.nominal[2 * k + 1]], measured: [m[4 * k], m[4 * k + 1]], refined: true, moved: Math.hypot(m[4 * k] - truth.nominal[2 * k], m[4 * k + 1] - truth.nominal[2 * k + 1]), ncc: m[4 * k + 2] }));
      ask();
      table();
      await fit();
      testHook("fiducials", Array.from(res.affine.params).join(","));
    });
    if (lab.image?.truth) {
      ask();
      table();
    }
    return {
      imageChanged() {
        marks = [null, null, null, null];
        next = null;
        marksBox.replaceChildren();
        if (lab.image?.truth) {
          ask();
          table();
        }
      },
      async pick(c, r, pos) {
        if (!lab.image?.truth || next === null) return;
        await setMark(next, pos[0], pos[1]);
      },
    };
  },
};

export default fiducials;
