// The lab's operator families that work with positions: correlation and
// least-squares matching, resampling, boundaries, fiducials.

import { el } from "../dom.js";
import { Viewer, fmt } from "./view.js";
import * as X from "./explain.js";
import { needImage, number, runButton, select } from "./families.js";

function link(l, text) {
  return el("a", { href: `index.html${l.hash}`, "data-key": l.key }, text);
}

// ---------------------------------------------------------------- correlation + LSM

const correlation = {
  id: "correlation",
  title: "Correlation and least-squares matching",
  create(lab, box) {
    const [second, secondLabel] = select("lab-second", "Search in", [["same", "the same photo"], ["pair", "the other photo of the pair"]], "same");
    const [size, sizeLabel] = select("lab-template", "Template", [["11", "11×11"], ["15", "15×15"], ["21", "21×21"], ["31", "31×31"]], "21");
    const [reach, reachLabel] = number("lab-reach", "Search ± (px)", 30, { min: "1", max: "150", step: "1" });
    const [model, modelLabel] = select("lab-model", "LSM model", [["shift", "shift"], ["shift-radiometric", "shift + radiometric"], ["affine", "affine + radiometric"]], "shift-radiometric");
    box.append(secondLabel, " ", sizeLabel, " ", reachLabel, " ", modelLabel,
      el("p", { class: "muted" }, "Click the photo where the template should be (its centre), then drag the box (mouse or touch) or move it with the arrow keys on the box's handle below (Shift: 10 pixels a step); the matching runs again where it is dropped. The NCC surface over the search box appears as a heat map on the search photo below, with the best match, its subpixel peak (3×3 quadric, Example 9) and every LSM iteration's patch outline."));
    // the template box: its position, announced; a handle for the keyboard
    const handle = el("button", { type: "button", id: "lab-template-handle", class: "lab-handle", disabled: true, "aria-describedby": "lab-template-pos" }, "Template box: arrow keys move it");
    const readout = el("p", { id: "lab-template-pos", class: "lab-readout", "aria-live": "polite" }, "No template box yet: click the photo.");
    box.append(el("div", { class: "lab-template-bar" }, handle, " ", readout));
    const holder = el("div", { class: "lab-pair" });
    const fig = el("figure", {}, el("figcaption", { id: "lab-search-caption" }, "Search photo: NCC surface (blue −1 … red +1), best match (orange), LSM iterations (green to blue)."));
    holder.append(fig);
    lab.extra.append(holder);
    const viewerB = new Viewer(fig, {
      label: "The search photo with the NCC surface and the match",
      onPick: (c, r) => explainSurface(c, r),
    });
    let bImage = null;
    let last = null;
    const loadPair = async () => {
      const pairName = lab.source?.sample ? (lab.source.sample === "aero1.jpg" ? "aero3.jpg" : lab.source.sample === "aero3.jpg" ? "aero1.jpg" : null) : null;
      if (second.value !== "pair" || !pairName) {
        if (second.value === "pair") lab.say("Only the aerial photos come as a pair: searching the same photo.");
        bImage = lab.image;
        return "same";
      }
      const bytes = await (await fetch(new URL(`./samples/${pairName}`, import.meta.url))).arrayBuffer();
      const r = await lab.run("load", { slot: "b", name: pairName, bytes }, `Decoding ${pairName}`, [bytes]);
      if (!r) return null;
      bImage = { ...r, name: pairName };
      return "pair";
    };
    const explainSurface = async (c, r) => {
      if (!last) return;
      const l = last.layers[0];
      const i = (r - l.r0) * l.width + (c - l.c0);
      if (c < l.c0 || r < l.r0 || c >= l.c0 + l.width || r >= l.r0 + l.height || !Number.isFinite(l.data[i])) return;
      const half = (last.size - 1) / 2;
      const win = await lab.run("window", { slot: last.slot, c: c - half, r: r - half, w: last.size, h: last.size });
      if (!win) return;
      lab.showExplain(`ρ with the template centred on column ${c}, row ${r}:`, l.data[i], X.nccLink(last.template, win, last.size));
    };
    // where the box is (its centre), and the newest matching asked for
    let at = null;
    let matchGen = 0;
    let keyTimer = null;
    const boxShape = (c, r, n) => ({ kind: "rect", c0: c - (n - 1) / 2, r0: r - (n - 1) / 2, w: n, h: n, colour: "#ff8c00" });
    const announce = (moving) => {
      const n = Number(size.value);
      readout.textContent = at
        ? `Template ${n}×${n} centred on column ${at[0]}, row ${at[1]}${moving ? " (moving)" : ""}.`
        : "No template box yet: click the photo.";
      handle.disabled = !at;
      document.body.dataset.template = at ? at.join(",") : "";
    };
    /** The box's centre kept where the whole box fits in the photo. */
    const clampCentre = (c, r) => {
      const half = (Number(size.value) - 1) / 2;
      const img = lab.image;
      return [Math.min(Math.max(Math.round(c), half), img.width - 1 - half), Math.min(Math.max(Math.round(r), half), img.height - 1 - half)];
    };
    const moveTo = (c, r, moving) => {
      at = clampCentre(c, r);
      lab.viewer.setShapes([boxShape(at[0], at[1], Number(size.value))]);
      announce(moving);
    };
    let grab = null;
    lab.viewer.dragHandler = {
      start([x, y]) {
        if (!at) return false;
        const half = (Number(size.value) - 1) / 2 + 1;
        if (Math.abs(x - at[0]) > half || Math.abs(y - at[1]) > half) return false;
        grab = [x - at[0], y - at[1]];
        return true;
      },
      move([x, y]) {
        moveTo(x - grab[0], y - grab[1], true);
      },
      end(p) {
        if (p) moveTo(p[0] - grab[0], p[1] - grab[1], false);
        grab = null;
        announce(false);
        match(at[0], at[1]);
      },
    };
    handle.addEventListener("keydown", (ev) => {
      const d = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] }[ev.key];
      if (!at) return;
      if (ev.key === "Enter") {
        ev.preventDefault();
        clearTimeout(keyTimer);
        match(at[0], at[1]);
        return;
      }
      if (!d) return;
      ev.preventDefault();
      const step = ev.shiftKey ? 10 : 1;
      moveTo(at[0] + d[0] * step, at[1] + d[1] * step, true);
      // dropped when the keys rest: the matching runs again
      clearTimeout(keyTimer);
      keyTimer = setTimeout(() => {
        announce(false);
        match(at[0], at[1]);
      }, 400);
    });
    const match = async (c, r) => {
      if (!needImage(lab)) return;
      const gen = ++matchGen;
      const stale = () => gen !== matchGen;
      const n = Number(size.value);
      const half = (n - 1) / 2;
      const m = Number(reach.value);
      const t = [c - half, r - half, n, n];
      if (t[0] < 0 || t[1] < 0 || c + half >= lab.image.width || r + half >= lab.image.height) {
        lab.showError(`template: a ${n}×${n} box centred on column ${c}, row ${r} does not fit inside the photo; click further from the edge.`);
        return;
      }
      at = [c, r];
      announce(false);
      {
        const which = await loadPair();
        if (!which || stale()) return;
        const s0 = [Math.max(0, c - half - m), Math.max(0, r - half - m)];
        const s = [s0[0], s0[1], Math.min(bImage.width - s0[0], n + 2 * m), Math.min(bImage.height - s0[1], n + 2 * m)];
        lab.viewer.setShapes([{ kind: "rect", c0: t[0], r0: t[1], w: n, h: n, colour: "#ff8c00" }]);
        const res = await lab.run("correlation", { template: t, search: s, model: model.value, sameImage: which === "same" }, "Correlating");
        if (!res || stale()) return;
        const template = await lab.run("window", { c: t[0], r: t[1], w: n, h: n });
        if (stale()) return;
        last = { ...res, size: n, slot: which === "same" ? "a" : "b", template, model: model.value };
        viewerB.setImage(bImage);
        viewerB.setLayer(res.layers[0]);
        viewerB.setOpacity(0.75);
        const shapes = [{ kind: "rect", c0: s[0], r0: s[1], w: s[2], h: s[3], colour: "#888", width: 1 }];
        if (res.best) shapes.push({ kind: "rect", c0: res.best[0] - half, r0: res.best[1] - half, w: n, h: n, colour: "#ff8c00" });
        const lsm = res.lsm;
        if (lsm) {
          const [wc, wr] = lsm.window;
          const outline = (a) => [[-half, -half], [half, -half], [half, half], [-half, half]].map(([u, v]) => [a[0] * u + a[1] * v + a[2] + wc, a[3] * u + a[4] * v + a[5] + wr]);
          const its = lsm.iterations;
          its.forEach((a, k) => shapes.push({ kind: "poly", closed: true, points: outline(a), colour: `hsl(${140 + (80 * k) / Math.max(1, its.length - 1)}, 80%, 40%)`, width: 1.5 }));
        }
        viewerB.setShapes(shapes);
        if (res.best) viewerB.zoomTo(Math.max(2, 300 / (n + 2 * m)), res.best[0], res.best[1]);
        const rows = [];
        const links = [];
        if (res.best) {
          const bw = await lab.run("window", { slot: last.slot, c: res.best[0] - half, r: res.best[1] - half, w: n, h: n });
          const l = res.layers[0];
          const rho = l.data[(res.best[1] - l.r0) * l.width + (res.best[0] - l.c0)];
          rows.push(["Best whole-pixel match (template centre)", `c ${res.best[0]}, r ${res.best[1]}, ρ = ${fmt(rho, 6)}`]);
          if (bw) links.push(link(X.nccLink(template, bw, n), "ρ at the best match: ncc-2d"));
          document.body.dataset.rho = String(rho);
        }
        if (res.subpixel) {
          rows.push(["Subpixel peak (3×3 quadric)", `c ${fmt(res.subpixel[0], 7)}, r ${fmt(res.subpixel[1], 7)}`]);
          links.push(link(X.subpixelLink(res.best, res.around), "the subpixel peak: subpixel-2d"));
          document.body.dataset.subpixel = res.subpixel.join(",");
        }
        if (lsm) {
          const p = lsm.params;
          rows.push([`LSM (${model.value}), ${lsm.iterations.length} iterations, ${lsm.status}`,
            `c ${fmt(p[2] + lsm.window[0], 7)}, r ${fmt(p[5] + lsm.window[1], 7)}; gain ${fmt(p[6])}, offset ${fmt(p[7])}${model.value === "affine" ? `; [a1 a2; a4 a5] = [${fmt(p[0])} ${fmt(p[1])}; ${fmt(p[3])} ${fmt(p[4])}]` : ""}`]);
          // every model has its example: the shift models lsm-2d (shift
          // only: its radiometry off), affine + radiometric lsm-affine with
          // the given patches; the same window, start and core matching
          const sw = await lab.run("window", { slot: last.slot, c: lsm.window[0], r: lsm.window[1], w: lsm.window[2], h: lsm.window[3] });
          const start = [lsm.start[2], lsm.start[5]];
          const l = sw && (model.value === "affine" ? X.lsmAffineLink(template, n, sw, lsm.window[2], start) : X.lsmLink(template, n, sw, lsm.window[2], start, model.value));
          if (l) links.push(link(l, model.value === "affine" ? "the matching: lsm-affine" : "the matching: lsm-2d"));
          else if (sw) links.push(el("span", { class: "muted" }, `(the ${lsm.window[2]}×${lsm.window[3]} LSM window is too long for a link: a smaller template gives one)`));
          document.body.dataset.lsm = [...p, lsm.window[0], lsm.window[1]].join(",");
        }
        // a converged LSM is not yet a right match: say when it is doubtful and why (ops::doubts)
        const doubts = res.doubts ?? [];
        if (doubts.length) rows.push(["Doubtful", `${doubts.map((d) => d[0].toUpperCase() + d.slice(1)).join(". ")}.`]);
        document.body.dataset.doubts = String(doubts.length);
        lab.explain.replaceChildren(
          el("table", { class: "lab-table", id: "lab-match" }, rows.map(([k, v]) => el("tr", k === "Doubtful" ? { class: "lab-doubt", id: "lab-doubts" } : {}, el("th", {}, k), el("td", {}, v)))),
          el("p", {}, "Open the worked example with these numbers: ", links.flatMap((a, i) => (i ? [" · ", a] : [a]))),
        );
        if (stale()) return;
        lab.explain.hidden = false;
        document.body.dataset.matched = `${c},${r}`;
      }
    };
    return {
      destroy() {
        clearTimeout(keyTimer);
        lab.viewer.dragHandler = null;
        viewerB.destroy();
      },
      imageChanged() {
        at = null;
        announce(false);
      },
      pick(c, r) {
        if (!needImage(lab)) return;
        match(...clampCentre(c, r));
      },
    };
  },
};

// ---------------------------------------------------------------- resampling

const resampling = {
  id: "resampling",
  title: "Resampling (rotate, scale, projective)",
  create(lab, box) {
    const [kind, kindLabel] = select("lab-warp", "Transformation", [["rotate", "rotate and scale"], ["projective", "projective, from 4 clicked points"]], "rotate");
    const [angle, angleLabel] = number("lab-angle", "Angle (°)", 10);
    const [scale, scaleLabel] = number("lab-scale", "Scale", 2, { min: "0.05" });
    const run = runButton();
    const hint = el("p", { class: "muted" });
    box.append(kindLabel, " ", angleLabel, " ", scaleLabel, " ", run, hint);
    const holder = el("div", { class: "lab-pair", id: "lab-methods" });
    lab.extra.append(holder);
    const views = [];
    let clicks = [];
    let used = null;
    const sync = () => {
      const rot = kind.value === "rotate";
      angleLabel.hidden = !rot;
      scaleLabel.hidden = !rot;
      run.hidden = !rot;
      clicks = [];
      hint.textContent = rot
        ? "Nearest neighbour, bilinear and bicubic (Lecture 7's cubic convolution) side by side on the same zoomed crop. Click a result pixel to see its 4×4 neighbourhood in the worked example."
        : "Click four points of a quadrilateral on the photo: top-left, top-right, bottom-right, bottom-left. They are mapped to a 256 × 256 square by the projective model of the 004 table.";
    };
    kind.addEventListener("change", sync);
    sync();
    const show = async (args) => {
      const r = await lab.run("resample", args, "Resampling");
      if (!r) return;
      used = args;
      holder.replaceChildren();
      views.splice(0).forEach((v) => v.destroy());
      const cc = Math.round(args.width / 2);
      const rr = Math.round(args.height / 2);
      r.layers.forEach((layer) => {
        const fig = el("figure", {}, el("figcaption", {}, layer.name));
        holder.append(fig);
        const v = new Viewer(fig, { label: `Resampled by ${layer.name}`, onPick: (c, rw) => explain(layer, c, rw) });
        v.setImage({ width: layer.width, height: layer.height, grey: layer.data });
        v.zoomTo(12, cc, rr);
        views.push(v);
      });
      lab.setLayers([]);
      document.body.dataset.resampled = r.layers.map((l) => l.name).join(",");
    };
    const explain = async (layer, c, r) => {
      const v = layer.data[r * layer.width + c];
      const pos = await lab.run("resamplePosition", { ...used, c, r });
      if (!pos) return;
      const [x, y] = pos;
      const fc = Math.floor(x) - 1;
      const fr = Math.floor(y) - 1;
      const patch = fc >= 0 && fr >= 0 ? await lab.run("window", { c: fc, r: fr, w: 4, h: 4 }) : null;
      lab.showExplain(`${layer.name} at output column ${c}, row ${r} (input position ${fmt(x, 7)}, ${fmt(y, 7)}):`, v,
        patch ? X.resampleLink(patch, fc, fr, x, y, layer.name) : null);
    };
    run.addEventListener("click", () => {
      if (!needImage(lab)) return;
      show({ kind: "rotate", params: [Number(angle.value), Number(scale.value)], width: lab.image.width, height: lab.image.height });
    });
    return {
      destroy() {
        views.forEach((v) => v.destroy());
      },
      pick(c, r, pos) {
        if (kind.value !== "projective") return;
        clicks.push(pos);
        // pos has pixel centres at integers, as the dots' c, r
        lab.viewer.setShapes(clicks.map(([x, y]) => ({ kind: "dot", c: x, r: y, size: 4 })));
        if (clicks.length === 4) {
          document.body.dataset.warpPoints = clicks.flat().join(",");
          show({ kind: "projective", params: clicks.flat(), width: 256, height: 256 });
          clicks = [];
        }
      },
    };
  },
};

// ---------------------------------------------------------------- boundaries

const MAX_LINK_PIXELS = 1500;

const boundaries = {
  id: "boundaries",
  title: "Boundaries (threshold, region, chain code)",
  create(lab, box) {
    const [thr, thrLabel] = number("lab-bthreshold", "Threshold", 128);
    box.append(thrLabel, el("p", { class: "muted" }, "Click a pixel: its region (the connected pixels on the same side of the threshold, 8-connected) is traced clockwise from its top-most, left-most pixel; the chain code counts 1 = east, counter-clockwise to 8 = south-east."));
    return {
      async pick(c, r) {
        if (!needImage(lab)) return;
        const res = await lab.run("boundary", { threshold: Number(thr.value), c, r }, "Tracing");
        if (!res) return;
        lab.setLayers(res.layers);
        const pts = [];
        for (let i = 0; i < res.pixels.length; i += 2) pts.push([res.pixels[i], res.pixels[i + 1]]);
        lab.viewer.setShapes([{ kind: "poly", closed: true, points: pts, colour: "#ff8c00", width: 2 }]);
        const code = res.code.length > 160 ? `${res.code.slice(0, 160)}… (${res.code.length} digits)` : res.code;
        const sh = res.shape;
        const rows = [
          ["Region", `${res.area} pixels; boundary of ${pts.length} pixels`],
          ["Chain code", code || "(a single pixel: no steps)"],
          ["Length", `${res.horizontal} horizontal + ${res.vertical} vertical + ${res.diagonal}·√2 diagonal = ${fmt(res.length, 7)} px`],
        ];
        if (sh) rows.push(["Shape", `diameter ${fmt(sh.diameter)} px, minor axis ${fmt(sh.minor_axis_length)} px, eccentricity ${fmt(sh.eccentricity)}`]);
        else rows.push(["Shape", "not computed: the boundary is longer than 4000 pixels (the diameter compares every pair of boundary pixels)"]);
        const closed = res.pixels.length >= 2 ? [...res.pixels, res.pixels[0], res.pixels[1]] : [];
        lab.explain.replaceChildren(
          el("table", { class: "lab-table", id: "lab-boundary" }, rows.map(([k, v]) => el("tr", {}, el("th", {}, k), el("td", { class: k === "Chain code" ? "lab-code" : "" }, v)))),
          pts.length > 1 && pts.length <= MAX_LINK_PIXELS
            ? el("p", {}, link(X.chainLink(closed), "Explain: open chain-code with these boundary pixels →"))
            : el("p", { class: "muted" }, `The boundary has ${pts.length} pixels; the worked example takes at most ${MAX_LINK_PIXELS} here.`),
        );
        lab.explain.hidden = false;
        document.body.dataset.code = res.code;
      },
    };
  },
};

// ---------------------------------------------------------------- fiducials

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

const fiducials = {
  id: "fiducials",
  title: "Fiducials (Example 4 on the scanned frame)",
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
      document.body.dataset.fidNext = next === null ? "done" : String(next + 1);
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
          document.body.dataset.fidNext = String(k + 1);
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
        el("p", {}, el("a", { href: `index.html#/fiducial-affine?points=${q}`, id: "lab-fid-link" }, "Open Example 4 (affine) with your measurements →"), " · ",
          el("a", { href: `index.html#/fiducial-similarity?points=${q}`, id: "lab-fid-link-similarity" }, "similarity →")),
      );
      lab.explain.hidden = false;
      document.body.dataset.fidResiduals = JSON.stringify({ similarity: sim, affine: aff, times });
      document.body.dataset.fidAffine = A.join(",");
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
      document.body.dataset.fiducials = Array.from(res.affine.params).join(",");
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

export const MORE_FAMILIES = [correlation, resampling, boundaries, fiducials];
