// The resampling family: rotate and scale (nearest, bilinear, bicubic side
// by side) or a projective warp from four clicked points; a result pixel is
// explained by the resample example with its 4×4 patch.

import { el } from "../../dom.js";
import { Viewer, fmt } from "../view.js";
import * as X from "../explain.js";
import { testHook } from "../../test-hooks.js";
import { needImage, number, runButton, select, showPixel } from "./common.js";

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
      testHook("resampled", r.layers.map((l) => l.name).join(","));
    };
    const explain = async (layer, c, r) => {
      const v = layer.data[r * layer.width + c];
      const pos = await lab.run("resamplePosition", { ...used, c, r });
      if (!pos) return;
      const [x, y] = pos;
      const fc = Math.floor(x) - 1;
      const fr = Math.floor(y) - 1;
      const patch = fc >= 0 && fr >= 0 ? await lab.run("window", { c: fc, r: fr, w: 4, h: 4 }) : null;
      await showPixel(lab, `${layer.name} at output column ${c}, row ${r} (input position ${fmt(x, 7)}, ${fmt(y, 7)}):`, v,
        { op: "resample", args: used, layer: layer.name, c, r }, patch ? X.resampleLink(patch, fc, fr, x, y, layer.name) : null);
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
          testHook("warpPoints", clicks.flat().join(","));
          show({ kind: "projective", params: clicks.flat(), width: 256, height: 256 });
          clicks = [];
        }
      },
    };
  },
};

export default resampling;
