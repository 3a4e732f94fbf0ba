// The edges family: Prewitt and Sobel over the whole photo (gx, gy,
// magnitude, direction); a clicked pixel is explained by edge-window.

import { el } from "../../dom.js";
import * as X from "../explain.js";
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
    run.addEventListener("click", async () => {
      if (!needImage(lab)) return;
      const args = { operator: op.value, border: border.value };
      const r = await lab.run("edges", args, "Finding edges");
      if (!r) return;
      used = args;
      lab.setLayers(r.layers, 2);
    });
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
