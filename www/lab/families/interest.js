// The interest family: Förstner (its map once per window size, then points
// for a live threshold from the kept map) and Moravec; a clicked pixel is
// explained by forstner-window or moravec-window.

import { el } from "../../dom.js";
import * as X from "../explain.js";
import { fmt } from "../view.js";
import { Live } from "../live.js";
import { testHook } from "../../test-hooks.js";
import { currentLayer, layerValue, needImage, number, runButton, select, showPixel } from "./common.js";

const ELLIPSE_MAGNIFY = 10;

const interest = {
  id: "interest",
  title: "Interest points (Förstner, Moravec)",
  create(lab, box) {
    const [op, opLabel] = select("lab-interest", "Interest operator", [["forstner", "Förstner"], ["moravec", "Moravec"]], "forstner");
    const [size, sizeLabel] = number("lab-window", "Window", 5, { min: "3", max: "15", step: "1" });
    const [sigma, sigmaLabel] = number("lab-sigma", "σn (grey values)", 8, { min: "0.01" });
    // the threshold is a live slider: it re-thresholds the kept map
    // its default is chosen for each photo (the strongest 0.1 % of w: ops::auto_threshold) until the student moves it
    const thr = el("input", { type: "range", id: "lab-threshold", min: "0.01", max: "3", step: "0.01", value: "0.5", "aria-describedby": "lab-threshold-out lab-threshold-rule" });
    const rule = el("p", { class: "muted", id: "lab-threshold-rule" });
    // while the photo's own T is used: its exact value (the slider shows its nearest step; the link leaves it out)
    let autoT = null;
    let thrSet = false;
    thr.addEventListener("change", () => {
      thrSet = true;
      autoT = null;
      delete thr.dataset.auto;
    });
    const thrOut = el("output", { id: "lab-threshold-out", for: "lab-threshold" }, "0.5 px");
    const thrLabel = el("label", { class: "lab-slider" }, "Threshold T ", thr, " ", thrOut);
    const [qmin, qLabel] = number("lab-qmin", "Roundness q ≥", 0.5, { min: "0", max: "1" });
    const [mthr, mthrLabel] = number("lab-mthreshold", "Moravec threshold", 2000, { min: "0" });
    const run = runButton();
    const note = el("p", { class: "muted" });
    const sync = () => {
      const f = op.value === "forstner";
      for (const l of [sigmaLabel, thrLabel, qLabel, rule]) l.hidden = !f;
      mthrLabel.hidden = f;
      if (!f && Number(size.value) === 5) size.value = "4";
      if (f && Number(size.value) === 4) size.value = "5";
      note.textContent = f
        ? `Lecture 21's rule: keep pixels whose error ellipse has λmax(Σuv) ≤ T² (and q ≥ the roundness), then the best in each window. Ellipses drawn ${ELLIPSE_MAGNIFY}× enlarged.`
        : "The worked examples' rule (Example 14): keep pixels whose mean of squared differences exceeds the threshold, then the largest in each window.";
    };
    op.addEventListener("change", sync);
    sync();
    box.append(opLabel, " ", sizeLabel, " ", sigmaLabel, " ", thrLabel, " ", qLabel, " ", mthrLabel, " ", run, note, rule);
    let used = null;
    const drawPoints = (p) => {
      // one batch (shapes.js pointShape: Förstner's error ellipses enlarged, Moravec's dots)
      const shapes = [{ kind: "points", p, ellipse: used.op === "forstner", magnify: ELLIPSE_MAGNIFY, colour: "#ff8c00" }];
      lab.viewer.setShapes(shapes);
      lab.explorer.setPoints(p, used.op);
      lab.say(`${p.length / 6} interest points found${used.op === "forstner" ? ` with T = ${fmt(used.thresholdPx, 3)} px` : ""}.`);
      testHook("points", String(p.length / 6));
    };
    // Förstner: the map once per window size (a new size cancels a running
    // map), then points for the current T, σn, q from the kept map
    const live = new Live(lab, "forstner");
    let mapSize = null;
    const params = () => ({ size: Number(size.value), sigmaN: Number(sigma.value), thresholdPx: autoT ?? Number(thr.value), qMin: Number(qmin.value), threshold: Number(mthr.value) });
    // the kept map's points on screen ({ sigmaN, qMin, thresholdPx, points }) and the newest request's arguments
    let onScreen = null;
    let newest = null;
    const points = () => {
      const args = params();
      newest = args;
      // T lowered, σn and q as they were: the points on screen with λmax(Σuv) ≤ T² are exactly the new ones,
      // drawn at once (seed 003's suppression keeps a candidate that beats every other in its window by a fixed
      // order; the dropped candidates beat no kept one); the kept map's answer follows and is the same
      const was = onScreen;
      if (was && was.sigmaN === args.sigmaN && was.qMin === args.qMin && args.thresholdPx <= was.thresholdPx) {
        const t2 = args.thresholdPx * args.thresholdPx;
        const [q, p] = [was.points, new Float64Array(was.points.length)];
        let n = 0;
        for (let i = 0; i < q.length; i += 6) if (q[i + 2] <= t2) for (let k = 0; k < 6; k++) p[n++] = q[i + k];
        onScreen = { ...args, points: p.subarray(0, n) };
        used = { op: "forstner", ...args, size: used?.size ?? Number(size.value) };
        drawPoints(onScreen.points);
        testHook("thresholdPreview", String(args.thresholdPx));
      }
      live.request({
        type: "forstnerPoints",
        args: { sigmaN: args.sigmaN, thresholdPx: args.thresholdPx, qMin: args.qMin },
        label: "Thresholding the kept map",
        apply(r) {
          // (an older T's answer while a newer one is on its way: the newer draws)
          if (args !== newest) return;
          const same = onScreen?.thresholdPx === args.thresholdPx && onScreen.sigmaN === args.sigmaN && onScreen.qMin === args.qMin
            && onScreen.points.length === r.points.length && onScreen.points.every((v, i) => Object.is(v, r.points[i]));
          testHook("thresholdSame", String(same));
          used = { op: "forstner", ...args, size: r.size };
          onScreen = { ...args, points: r.points };
          if (!same) drawPoints(r.points);
          testHook("threshold", String(r.thresholdPx));
          testHook("mapRuns", String(r.mapRuns));
          testHook("pointsMs", r.pointsMs.toFixed(1));
        },
      });
    };
    const maps = () => {
      const n = Number(size.value);
      mapSize = null;
      onScreen = null;
      live.request({
        type: "forstnerMaps",
        args: { size: n, sigmaN: Number(sigma.value) },
        label: `Förstner operator (${n}×${n} windows)`,
        cancel: true,
        apply(r) {
          mapSize = r.size;
          const a = r.auto;
          if (a && !thrSet) {
            autoT = a.thresholdPx;
            thr.value = String(autoT);
            thr.dataset.auto = "1";
            thrOut.textContent = `${fmt(autoT, 3)} px`;
          }
          auto = a;
          sayRule();
          used = { op: "forstner", ...params(), size: r.size };
          lab.setLayers(r.layers);
          testHook("mapRuns", String(r.mapRuns));
          points();
        },
      });
    };
    // the photo's own threshold (the map's `auto`), and the words on the T used
    let auto = null;
    const sayRule = () => {
      const a = auto;
      rule.textContent = !a
        ? "This photo has no textured pixel (every w is 0): no threshold can be chosen from it."
        : thrSet
          ? `T = ${thr.value} px as you set it. For this photo the lab would choose ${fmt(a.thresholdPx, 3)} px: w at least ${fmt(a.wMin, 4)}, the w of its strongest ${a.share * 100} % of pixels.`
          : `T = ${fmt(a.thresholdPx, 3)} px, chosen for this photo: its strongest ${a.share * 100} % of pixels have w ≥ ${fmt(a.wMin, 4)}, and T = σn/√w_min = ${fmt(Number(sigma.value), 4)}/√${fmt(a.wMin, 4)} keeps the pixels whose λmin(N) ≥ w_min (w ≤ λmin(N) ≤ 2w). A fixed T would keep the photo's texture as well; move the slider to choose your own.`;
    };
    const retune = (ev) => {
      if (ev?.target === thr) {
        // the student's T (moved, not yet let go) stays theirs: a new map keeps it
        thrSet = true;
        autoT = null;
        delete thr.dataset.auto;
        if (mapSize !== null) sayRule();
      }
      thrOut.textContent = autoT === null ? `${thr.value} px` : `${fmt(autoT, 3)} px`;
      if (op.value !== "forstner" || !lab.image) return;
      if (mapSize !== null && mapSize === Number(size.value)) points();
      // (while a map is computed, its points follow with the newest values)
    };
    for (const input of [thr, sigma, qmin]) input.addEventListener("input", retune);
    size.addEventListener("change", () => {
      if (op.value === "forstner" && lab.image && (mapSize !== null || live.busy)) maps();
    });
    run.addEventListener("click", async () => {
      if (!needImage(lab)) return;
      if (op.value === "forstner") {
        maps();
        return;
      }
      const args = params();
      const r = await lab.run(op.value, args, "Moravec operator");
      if (!r) return;
      used = { op: op.value, ...args };
      onScreen = null;
      lab.setLayers(r.layers);
      drawPoints(r.points);
    });
    return {
      imageChanged() {
        mapSize = null;
        onScreen = null;
        auto = null;
        thrSet = false;
        autoT = null;
        rule.textContent = "";
      },
      async pick(c, r) {
        const layer = currentLayer(lab);
        const v = layerValue(layer, c, r);
        if (!used || v === null) return;
        const n = used.size;
        const a = Math.floor((n - 1) / 2);
        const win = await lab.run("window", { c: c - a, r: r - a, w: n, h: n }, "Reading the window");
        if (!win) return;
        const link = used.op === "forstner"
          ? X.forstnerLink(win, n, used.sigmaN, used.thresholdPx, layer.name)
          : X.moravecLink(win, n);
        await showPixel(lab, `${layer.name} of the ${n}×${n} window at column ${c}, row ${r}:`, v, { op: used.op, args: { size: n }, layer: layer.name, c, r }, link);
      },
    };
  },
};

export default interest;
