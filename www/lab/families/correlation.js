// The correlation family: a template box dragged over the photo, its NCC
// surface over a search box (the same photo or the other of the aerial
// pair), the subpixel peak and least-squares matching, each with its worked
// example.

import { el } from "../../dom.js";
import { Viewer, fmt } from "../view.js";
import * as X from "../explain.js";
import { aroundTables, viewData } from "../explore.js";
import { testHook } from "../../test-hooks.js";
import { link, needImage, number, select, showPixel } from "./common.js";

const correlation = {
  id: "correlation",
  title: "Correlation and least-squares matching",
  create(lab, box) {
    const [second, secondLabel] = select("lab-second", "Search in", [["same", "the same photo"], ["pair", "the other photo of the pair"]], "same");
    const [size, sizeLabel] = select("lab-template", "Template", [["11", "11×11"], ["15", "15×15"], ["21", "21×21"], ["31", "31×31"]], "21");
    const [reach, reachLabel] = number("lab-reach", "Search ± (px)", 30, { min: "1", max: "150", step: "1" });
    const [model, modelLabel] = select("lab-model", "LSM model", [["shift", "shift"], ["shift-radiometric", "shift + radiometric"], ["affine", "affine + radiometric"]], "shift-radiometric");
    box.append(secondLabel, " ", sizeLabel, " ", reachLabel, " ", modelLabel,
      el("p", { class: "muted" }, "Click the photo where the template should be (its centre) — or, on the keyboard, focus the photo, move its cursor with the arrow keys and press Enter — then drag the box (mouse or touch) or move it with the arrow keys on the box's handle below (Shift: 10 pixels a step); the matching runs again where it is dropped. The NCC surface over the search box appears as a heat map on the search photo below, with the best match, its subpixel peak (3×3 quadric, Example 9) and every LSM iteration's patch outline."));
    // the template box: its position, announced; a handle for the keyboard
    const handle = el("button", { type: "button", id: "lab-template-handle", class: "lab-handle", disabled: true, "aria-describedby": "lab-template-pos" }, "Template box: arrow keys move it");
    const readout = el("p", { id: "lab-template-pos", class: "lab-readout", "aria-live": "polite" }, "No template box yet: click the photo, or press Enter on its cursor.");
    box.append(el("div", { class: "lab-template-bar" }, handle, " ", readout));
    const holder = el("div", { class: "lab-pair" });
    const fig = el("figure", {}, el("figcaption", { id: "lab-search-caption" }, "Search photo: NCC surface (blue −1 … red +1), best match (orange), LSM iterations (green to blue)."));
    holder.append(fig);
    lab.extra.append(holder);
    const viewerB = new Viewer(fig, {
      label: "The search photo with the NCC surface and the match",
      onPick: (c, r) => explainSurface(c, r),
      onCursor: () => data.update(),
      describedBy: "lab-search-data-desc",
    });
    let bImage = null;
    let last = null;
    // the search photo's Data view: its grey values and ρ around its cursor (the best match until it moves)
    const data = viewData("lab-search-data", "Data: the search photo", () =>
      bImage && last ? aroundTables("lab-search-data", bImage, last.layers[0], viewerB.cursor ?? last.best ?? viewerB.centrePixel()) : []);
    holder.append(el("div", { class: "lab-viewbar" }, data.button), data.panel);
    const loadPair = async () => {
      const pairName = lab.source?.sample ? (lab.source.sample === "aero1.jpg" ? "aero3.jpg" : lab.source.sample === "aero3.jpg" ? "aero1.jpg" : null) : null;
      if (second.value !== "pair" || !pairName) {
        if (second.value === "pair") lab.say("Only the aerial photos come as a pair: searching the same photo.");
        bImage = lab.image;
        return "same";
      }
      const bytes = await (await fetch(new URL(`../samples/${pairName}`, import.meta.url))).arrayBuffer();
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
      await showPixel(lab, `ρ with the template centred on column ${c}, row ${r}:`, l.data[i], { op: "correlation", args: last.args, layer: l.name, c, r }, X.nccLink(last.template, win, last.size));
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
        : "No template box yet: click the photo, or press Enter on its cursor.";
      handle.disabled = !at;
      testHook("template", at ? at.join(",") : "");
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
        const args = { template: t, search: s, model: model.value, sameImage: which === "same" };
        const res = await lab.run("correlation", args, "Correlating");
        if (!res || stale()) return;
        const template = await lab.run("window", { c: t[0], r: t[1], w: n, h: n });
        if (stale()) return;
        last = { ...res, size: n, slot: which === "same" ? "a" : "b", template, model: model.value, args };
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
        viewerB.cursor = null;
        data.desc.textContent = searchWords(bImage, res.layers[0], res.best, s);
        data.update();
        const rows = [];
        const links = [];
        if (res.best) {
          const bw = await lab.run("window", { slot: last.slot, c: res.best[0] - half, r: res.best[1] - half, w: n, h: n });
          const l = res.layers[0];
          const rho = l.data[(res.best[1] - l.r0) * l.width + (res.best[0] - l.c0)];
          rows.push(["Best whole-pixel match (template centre)", `c ${res.best[0]}, r ${res.best[1]}, ρ = ${fmt(rho, 6)}`]);
          const nl = bw && X.nccLink(template, bw, n);
          if (nl) links.push(link(nl, `ρ at the best match: ${nl.id}`));
          testHook("rho", String(rho));
        }
        if (res.subpixel) {
          rows.push(["Subpixel peak (3×3 quadric)", `c ${fmt(res.subpixel[0], 7)}, r ${fmt(res.subpixel[1], 7)}`]);
          const sl = X.subpixelLink(res.best, res.around);
          if (sl) links.push(link(sl, `the subpixel peak: ${sl.id}`));
          testHook("subpixel", res.subpixel.join(","));
        }
        if (lsm) {
          const p = lsm.params;
          rows.push([`LSM (${model.value}), ${lsm.iterations.length} iterations, ${lsm.status}`,
            `c ${fmt(p[2] + lsm.window[0], 7)}, r ${fmt(p[5] + lsm.window[1], 7)}; gain ${fmt(p[6])}, offset ${fmt(p[7])}${model.value === "affine" ? `; [a1 a2; a4 a5] = [${fmt(p[0])} ${fmt(p[1])}; ${fmt(p[3])} ${fmt(p[4])}]` : ""}`]);
          // every model has its example: the shift models the "lsm" reading's
          // (shift only: its radiometry off), affine + radiometric the
          // "affine-lsm" reading's with the given patches; the same window,
          // start and core matching
          const sw = await lab.run("window", { slot: last.slot, c: lsm.window[0], r: lsm.window[1], w: lsm.window[2], h: lsm.window[3] });
          const start = [lsm.start[2], lsm.start[5]];
          const l = sw && (model.value === "affine" ? X.lsmAffineLink(template, n, sw, lsm.window[2], start) : X.lsmLink(template, n, sw, lsm.window[2], start, model.value));
          if (l) links.push(link(l, `the matching: ${l.id}`));
          else if (sw) links.push(el("span", { class: "muted" }, `(the ${lsm.window[2]}×${lsm.window[3]} LSM window is too long for a link: a smaller template gives one)`));
          testHook("lsm", [...p, lsm.window[0], lsm.window[1]].join(","));
        }
        // a converged LSM is not yet a right match: say when it is doubtful and why (ops::doubts)
        const doubts = res.doubts ?? [];
        if (doubts.length) rows.push(["Doubtful", `${doubts.map((d) => d[0].toUpperCase() + d.slice(1)).join(". ")}.`]);
        testHook("doubts", String(doubts.length));
        lab.explain.replaceChildren(
          el("table", { class: "lab-table", id: "lab-match" }, rows.map(([k, v]) => el("tr", k === "Doubtful" ? { class: "lab-doubt", id: "lab-doubts" } : {}, el("th", {}, k), el("td", {}, v)))),
          el("p", {}, "Open the worked example with these numbers: ", links.flatMap((a, i) => (i ? [" · ", a] : [a]))),
        );
        if (stale()) return;
        lab.explain.hidden = false;
        testHook("matched", `${c},${r}`);
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

/** The search photo in words: its size, the search box, the range of ρ over it and the best match. */
function searchWords(img, layer, best, [c0, r0, w, h]) {
  let [lo, hi] = [Infinity, -Infinity];
  for (const v of layer.data) {
    if (v < lo) lo = v;
    if (v > hi) hi = v;
  }
  const rho = best ? layer.data[(best[1] - layer.r0) * layer.width + (best[0] - layer.c0)] : null;
  return [
    `${img.name}: ${img.width} × ${img.height} pixels; the search box is columns ${c0} to ${c0 + w - 1}, rows ${r0} to ${r0 + h - 1}.`,
    `The NCC surface (the template centred on each pixel) covers columns ${layer.c0} to ${layer.c0 + layer.width - 1}, rows ${layer.r0} to ${layer.r0 + layer.height - 1}${Number.isFinite(lo) ? `, ρ from ${fmt(lo, 4)} to ${fmt(hi, 4)}` : ""}.`,
    best ? `The best match is at column ${best[0]}, row ${best[1]}, ρ = ${fmt(rho, 6)}.` : "No best match.",
  ].join(" ");
}

export default correlation;
