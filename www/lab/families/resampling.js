// The resampling family: rotate and scale (nearest, bilinear, bicubic side
// by side) or a projective warp from four clicked points; a result pixel is
// explained by the resample example with its 4×4 patch. A new angle or
// scale recomputes it live (live.js: a preview of the part of the output in
// the views first; they keep their zoom and place).

import { el } from "../../dom.js";
import { Viewer, fmt, paintOf } from "../view.js";
import { Live } from "../live.js";
import * as X from "../explain.js";
import { testHook } from "../../test-hooks.js";
import { needImage, number, runButton, select, showPixel } from "./common.js";

/** A preview target that has none. */
const NONE = { visible: () => null, setPreview() {} };

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
    // the result's layers by name (a view's pick explains the one it shows now)
    const shownLayers = new Map();
    // their grey stretch as painted (a preview is painted on it)
    const stretch = {};
    const same = (r) => views.length === r.layers.length && r.layers.every((l, i) => views[i].name === l.name && views[i].image?.width === l.width && views[i].image?.height === l.height);
    let drawn = 0;
    const draw = async (args, r) => {
      // painted before they replace the views' images (no blank frame between the preview and the result)
      const gen = ++drawn;
      const bitmaps = await Promise.all(r.layers.map((l) => paintOf({ data: l.data, width: l.width, signed: false })));
      if (gen !== drawn) return; // a newer result came meanwhile
      used = args;
      const keep = same(r);
      if (!keep) {
        holder.replaceChildren();
        views.splice(0).forEach((v) => v.destroy());
      }
      r.layers.forEach((layer, i) => {
        shownLayers.set(layer.name, layer);
        if (bitmaps[i]?.scale) stretch[layer.name] = [bitmaps[i].scale.lo, bitmaps[i].scale.hi];
        const img = { width: layer.width, height: layer.height, grey: layer.data, bitmap: bitmaps[i]?.bitmap };
        if (keep) {
          // the same output size: each view keeps its zoom and place
          const v = views[i];
          const { zoom, ox, oy } = v;
          v.setImage(img);
          Object.assign(v, { zoom, ox, oy, fitted: true, atFit: false });
          v.draw();
          return;
        }
        const fig = el("figure", {}, el("figcaption", {}, layer.name));
        holder.append(fig);
        const v = new Viewer(fig, { label: `Resampled by ${layer.name}`, onPick: (c, rw) => explain(shownLayers.get(layer.name), c, rw) });
        v.name = layer.name;
        v.setImage(img);
        // a preview is drawn as it will be (not see-through: the views show no photo under it)
        v.setOpacity(1);
        v.zoomTo(12, Math.round(args.width / 2), Math.round(args.height / 2));
        views.push(v);
      });
      lab.setLayers([]);
      testHook("resampled", r.layers.map((l) => l.name).join(","));
      testHook("resampleShown", args.params.join(","));
    };
    // where a preview goes: the part of the output in the views (their union), each method's into its view
    const target = {
      visible() {
        const boxes = views.map((v) => v.visible()).filter(Boolean);
        if (!boxes.length) return null;
        const c0 = Math.min(...boxes.map((b) => b[0]));
        const r0 = Math.min(...boxes.map((b) => b[1]));
        const c1 = Math.max(...boxes.map((b) => b[0] + b[2]));
        const r1 = Math.max(...boxes.map((b) => b[1] + b[3]));
        return [c0, r0, c1 - c0, r1 - r0];
      },
      setPreview(p) {
        for (const v of views) v.setPreview(p?.layers.find((l) => l.name === v.name) ?? null);
      },
      ranges: () => stretch,
    };
    const live = new Live(lab, "resample");
    const show = (args) => {
      // a preview only into views of the same output size (a projective warp's 256 × 256 has none: it is quick)
      const fits = views.length > 0 && views.every((v) => v.image?.width === args.width && v.image?.height === args.height);
      live.request({ type: "resample", args, label: "Resampling", cancel: true, target: fits ? target : NONE, rowWidth: args.width, apply: (r) => draw(args, r) });
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
    const rotate = () => {
      if (!needImage(lab)) return;
      show({ kind: "rotate", params: [Number(angle.value), Number(scale.value)], width: lab.image.width, height: lab.image.height });
    };
    run.addEventListener("click", rotate);
    // a new angle or scale, once a rotation is shown (or being computed): recomputed live
    for (const input of [angle, scale]) {
      input.addEventListener("input", () => {
        const n = Number(input.value);
        // (not while a number is half typed: "", "-", a scale of "0" before "0.5")
        if (input.value.trim() === "" || !Number.isFinite(n) || (input === scale && n <= 0)) return;
        if (kind.value === "rotate" && lab.image && (used?.kind === "rotate" || live.busy)) rotate();
      });
    }
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
