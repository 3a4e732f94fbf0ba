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
      el("p", { class: "muted" }, "Click the photo where the template should be (its centre). The NCC surface over the search box appears as a heat map on the search photo below, with the best match, its subpixel peak (3×3 quadric, Example 9) and every LSM iteration's patch outline."));
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
    return {
      destroy() {
        viewerB.destroy();
      },
      async pick(c, r) {
        if (!needImage(lab)) return;
        const n = Number(size.value);
        const half = (n - 1) / 2;
        const m = Number(reach.value);
        const t = [c - half, r - half, n, n];
        if (t[0] < 0 || t[1] < 0 || c + half >= lab.image.width || r + half >= lab.image.height) {
          lab.showError(`template: a ${n}×${n} box centred on column ${c}, row ${r} does not fit inside the photo; click further from the edge.`);
          return;
        }
        const which = await loadPair();
        if (!which) return;
        const s0 = [Math.max(0, c - half - m), Math.max(0, r - half - m)];
        const s = [s0[0], s0[1], Math.min(bImage.width - s0[0], n + 2 * m), Math.min(bImage.height - s0[1], n + 2 * m)];
        lab.viewer.setShapes([{ kind: "rect", c0: t[0], r0: t[1], w: n, h: n, colour: "#ff8c00" }]);
        const res = await lab.run("correlation", { template: t, search: s, model: model.value, sameImage: which === "same" }, "Correlating");
        if (!res) return;
        const template = await lab.run("window", { c: t[0], r: t[1], w: n, h: n });
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
        }
        if (lsm) {
          const p = lsm.params;
          rows.push([`LSM (${model.value}), ${lsm.iterations.length} iterations, ${lsm.status}`,
            `c ${fmt(p[2] + lsm.window[0], 7)}, r ${fmt(p[5] + lsm.window[1], 7)}; gain ${fmt(p[6])}, offset ${fmt(p[7])}${model.value === "affine" ? `; [a1 a2; a4 a5] = [${fmt(p[0])} ${fmt(p[1])}; ${fmt(p[3])} ${fmt(p[4])}]` : ""}`]);
          if (model.value === "shift-radiometric" && lsm.window[2] <= 64 && lsm.window[3] <= 64) {
            const sw = await lab.run("window", { slot: last.slot, c: lsm.window[0], r: lsm.window[1], w: lsm.window[2], h: lsm.window[3] });
            if (sw) links.push(link(X.lsmLink(template, n, sw, lsm.window[2], [lsm.start[2], lsm.start[5]]), "the matching: lsm-2d"));
          }
        }
        lab.explain.replaceChildren(
          el("table", { class: "lab-table", id: "lab-match" }, rows.map(([k, v]) => el("tr", {}, el("th", {}, k), el("td", {}, v)))),
          el("p", {}, "Open the worked example with these numbers: ", links.flatMap((a, i) => (i ? [" · ", a] : [a]))),
        );
        lab.explain.hidden = false;
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
        lab.viewer.setShapes(clicks.map(([x, y]) => ({ kind: "dot", c: x - 0.5, r: y - 0.5, size: 4 })));
        if (clicks.length === 4) {
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

const fiducials = {
  id: "fiducials",
  title: "Fiducials (Example 4 on the scanned frame)",
  create(lab, box) {
    const run = runButton("Measure the four marks and fit");
    box.append(run, el("p", { class: "muted" }, "On the generated scanned frame: each mark is found by NCC with a template of the mark near its nominal position, refined by LSM (shift + radiometric); then Example 4's similarity and affine transformations are fitted to the four measurements. The true affine is known, so the fit can be checked."));
    run.addEventListener("click", async () => {
      if (lab.image?.truth === undefined) {
        await lab.openSample("frame");
        lab.sampleSelect.value = "frame";
      }
      const truth = lab.image?.truth;
      if (!truth) return;
      const res = await lab.run("fiducials", { approx: Array.from(truth.nominal) }, "Measuring the marks");
      if (!res) return;
      const m = res.marks;
      const rows = [];
      const shapes = [];
      const points = [];
      const cal = truth.calibrated;
      const affRes = res.affine.residuals;
      for (let k = 0; k < 4; k++) {
        const [c, r] = [m[4 * k], m[4 * k + 1]];
        const [tc, tr] = [truth.marks[2 * k], truth.marks[2 * k + 1]];
        rows.push([k + 1, fmt(truth.nominal[2 * k], 6), fmt(truth.nominal[2 * k + 1], 6), fmt(c, 7), fmt(r, 7), fmt(tc, 7), fmt(tr, 7),
          fmt(Math.hypot(c - tc, r - tr), 2), fmt(affRes[2 * k] * 1000, 3), fmt(affRes[2 * k + 1] * 1000, 3)]);
        shapes.push({ kind: "rect", c0: c - 10.5, r0: r - 10.5, w: 21, h: 21, colour: "#ff8c00" });
        // residual vectors, 2000× enlarged (x to the right, y up)
        shapes.push({ kind: "line", from: [c, r], to: [c + affRes[2 * k] * 2000 / truth.pixel_mm, r - affRes[2 * k + 1] * 2000 / truth.pixel_mm], colour: "#d62728", width: 2 });
        points.push([c, r, cal[2 * k], cal[2 * k + 1]]);
      }
      lab.viewer.setShapes(shapes);
      const head = ["mark", "nominal c", "nominal r", "measured c", "measured r", "true c", "true r", "error (px)", "affine vx (µm)", "affine vy (µm)"];
      const params = (p) => Array.from(p).map((v) => fmt(v, 7)).join(", ");
      const pts = points.map((p) => p.join(",")).join(";");
      lab.explain.replaceChildren(
        el("table", { class: "lab-table", id: "lab-fiducials" }, el("tr", {}, head.map((h) => el("th", {}, h))), rows.map((row) => el("tr", {}, row.map((v) => el("td", {}, String(v)))))),
        el("p", {}, `Similarity [a, b, c, d]: ${params(res.similarity.params)}; σ0 = ${fmt(res.similarity.sigma0 ?? NaN)} mm.`),
        el("p", {}, `Affine [a, b, e, c, d, f]: ${params(res.affine.params)}; σ0 = ${fmt(res.affine.sigma0 ?? NaN)} mm.`),
        el("p", {}, `True affine: ${params(truth.affine)}. Residual vectors are drawn 2000× enlarged in red.`),
        el("p", {}, el("a", { href: `index.html#/fiducial-affine?points=${encodeURIComponent(pts).replace(/%2C/g, ",").replace(/%3B/g, ";")}`, id: "lab-fiducial-link" }, "Open Example 4 (affine) with these measurements →"), " · ",
          el("a", { href: `index.html#/fiducial-similarity?points=${encodeURIComponent(pts).replace(/%2C/g, ",").replace(/%3B/g, ";")}` }, "similarity →")),
      );
      lab.explain.hidden = false;
      document.body.dataset.fiducials = Array.from(res.affine.params).join(",");
    });
    return {};
  },
};

export const MORE_FAMILIES = [correlation, resampling, boundaries, fiducials];
