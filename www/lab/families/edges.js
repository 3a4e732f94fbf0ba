// The edges family: Prewitt and Sobel over the whole photo (gx, gy,
// magnitude, direction); a clicked pixel is explained by edge-window. A new
// operator or border recomputes the shown edges live (live.js: a preview of
// the part in view first).

import { el } from "../../dom.js";
import * as X from "../explain.js";
import { Live } from "../live.js";
import { testHook } from "../../test-hooks.js";
import { BORDERS, currentLayer, layerValue, needImage, runButton, select, showPixel } from "./common.js";

const edges = {
  id: "edges",
  title: "Edges (Prewitt, Sobel)",
  create(lab, box) {
    const [op, opLabel] = select("lab-operator", "Edge operator", [["prewitt", "Prewitt"], ["sobel", "Sobel"]], "sobel");
    const [border, borderLabel] = select("lab-border", "Border", BORDERS, "replicate");
    const run = runButton();
    box.append(opLabel, " ", borderLabel, " ", run,
      el("p", { class: "muted" }, "gx = top row minus bottom row, gy = right column minus left (the course's kernels, applied as written); direction = atan2(gy, gx) in degrees."));
    let used = null;
    // a new operator or border, once edges are shown (or being found): the
    // newest choice wins, its preview first (live.js)
    const live = new Live(lab, "edges");
    const go = () => {
      if (!needImage(lab)) return;
      const args = { operator: op.value, border: border.value };
      live.request({
        type: "edges",
        args,
        label: "Finding edges",
        cancel: true,
        layer: "magnitude",
        apply(r) {
          used = args;
          const shown = lab.layers[Number(lab.layerSelect.value)]?.name;
          const i = r.layers.findIndex((l) => l.name === shown);
          lab.setLayers(r.layers, i >= 0 ? i : 2);
          testHook("edgesShown", `${args.operator} ${args.border}`);
        },
      });
    };
    run.addEventListener("click", go);
    for (const s of [op, border]) {
      s.addEventListener("change", () => {
        if (lab.image && (used || live.busy)) go();
      });
    }
    return {
      async pick(c, r) {
        const layer = currentLayer(lab);
        const v = layerValue(layer, c, r);
        if (!used || v === null) return;
        let link = null;
        {
          const win = await lab.run("neighbourhood", { c, r, w: 5, h: 5, border: used.border }, "Reading the window");
          if (win) link = X.edgeLink(used.operator, win, layer.name);
        }
        await showPixel(lab, `${used.operator} ${layer.name} at column ${c}, row ${r}:`, v, { op: "edges", args: used, layer: layer.name, c, r }, link);
      },
    };
  },
};

export default edges;
