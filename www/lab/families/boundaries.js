// The boundaries family: a clicked pixel's region (threshold, 8-connected)
// traced, its chain code, length and shape; linked to chain-code.

import { el } from "../../dom.js";
import { fmt } from "../view.js";
import * as X from "../explain.js";
import { testHook } from "../../test-hooks.js";
import { link, needImage, number } from "./common.js";

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
        const linked = pts.length > 1 && pts.length <= MAX_LINK_PIXELS;
        const l = linked ? X.chainLink(closed) : null;
        lab.explain.replaceChildren(
          el("table", { class: "lab-table", id: "lab-boundary" }, rows.map(([k, v]) => el("tr", {}, el("th", {}, k), el("td", { class: k === "Chain code" ? "lab-code" : "" }, v)))),
          linked
            ? (l ? el("p", {}, link(l, `Explain: open ${l.id} with these boundary pixels →`)) : "")
            : el("p", { class: "muted" }, `The boundary has ${pts.length} pixels; the worked example takes at most ${MAX_LINK_PIXELS} here.`),
        );
        lab.explain.hidden = false;
        testHook("code", res.code);
      },
    };
  },
};

export default boundaries;
