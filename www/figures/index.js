// The figure registry and the canvas plumbing every figure shares.
//
// A figure module (one per topic) exports `figures`: an object mapping an
// example id to a figure spec, or to an array of specs (one canvas each):
//
//   export const figures = {
//     "gsd": {
//       caption: "Side view of the camera …",          // shown under the canvas
//       height(width, solution) { return 300; },       // CSS px for a CSS width
//       describe(solution) { return "…"; },             // the canvas's aria-label
//       draw(ctx, width, height, solution) { … },       // ctx scaled to CSS px, cleared white
//     },
//   };
//
// Two optional members let a figure edit the inputs (the page then sets those
// fields' texts and solves again, as if typed):
//
//     onPointer(x, y, width, height, solution) { return { pixels: "1 4; 2 4" }; }
//       a click or tap at (x, y) CSS px on the canvas; returns { key: text }
//       for the fields to change, or null for none;
//     actions: [{ label: "Circle", inputs(solution) { return { … }; } }]
//       buttons under the canvas, each setting the fields it returns.
//
// The figure is registered with one line below. The page calls mountFigures(host, id)
// once per example view and .update(solution) after each successful solve;
// device-pixel-ratio scaling, resizing and errors are handled here.

import { figures as coordinates } from "./coordinates.js";
import { figures as interest } from "./interest.js";
import { figures as chains } from "./chains.js";
import { COLORS, font, FONT_SIZE } from "./draw.js";

const REGISTRY = Object.freeze({
  ...coordinates,
  ...interest,
  ...chains,
});

/** Heights are kept within these bounds (CSS px). */
const MIN_HEIGHT = 120;
const MAX_HEIGHT = 900;

function specsFor(id) {
  const entry = Object.hasOwn(REGISTRY, id) ? REGISTRY[id] : null;
  if (!entry) return [];
  return Array.isArray(entry) ? entry : [entry];
}

/** Whether an example has a figure. */
export function hasFigure(id) {
  return specsFor(id).length > 0;
}

function paint(panel, solution) {
  const { spec, canvas, figure } = panel;
  const width = Math.floor(figure.clientWidth);
  if (!solution || width <= 0) return;
  const dpr = window.devicePixelRatio || 1;
  let height;
  try {
    height = Math.round(Math.min(MAX_HEIGHT, Math.max(MIN_HEIGHT, spec.height(width, solution))));
  } catch {
    height = MIN_HEIGHT;
  }
  canvas.style.width = `${width}px`;
  canvas.style.height = `${height}px`;
  const bw = Math.round(width * dpr);
  const bh = Math.round(height * dpr);
  if (canvas.width !== bw) canvas.width = bw;
  if (canvas.height !== bh) canvas.height = bh;
  const ctx = canvas.getContext("2d");
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.fillStyle = COLORS.background;
  ctx.fillRect(0, 0, width, height);
  try {
    spec.draw(ctx, width, height, solution);
    canvas.setAttribute("aria-label", spec.describe(solution));
  } catch (e) {
    console.error("figure failed", e);
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.fillStyle = COLORS.background;
    ctx.fillRect(0, 0, width, height);
    ctx.fillStyle = COLORS.ink;
    ctx.font = font(FONT_SIZE);
    ctx.fillText("The figure could not be drawn for these values.", 10, 24);
    canvas.setAttribute("aria-label", "The figure could not be drawn for these values.");
  }
  panel.drawn = { width, dpr };
}

/**
 * Puts the example's canvases into `host`.
 * @returns {{ update(solution): void, redraw(): void, destroy(): void } | null}
 */
export function mountFigures(host, id, { setInputs = null } = {}) {
  const specs = specsFor(id);
  if (!specs.length) return null;
  let solution = null;
  const edit = (texts) => {
    if (setInputs && texts && typeof texts === "object") setInputs(texts);
  };
  const panels = specs.map((spec) => {
    const canvas = document.createElement("canvas");
    canvas.className = "figure-canvas";
    canvas.setAttribute("role", "img");
    canvas.setAttribute("aria-label", "Figure (not drawn yet)");
    const figure = document.createElement("figure");
    figure.className = "figure-panel";
    figure.append(canvas);
    if (typeof spec.onPointer === "function" && setInputs) {
      canvas.classList.add("figure-interactive");
      canvas.addEventListener("click", (e) => {
        if (!solution) return;
        const box = canvas.getBoundingClientRect();
        try {
          edit(spec.onPointer(e.clientX - box.left, e.clientY - box.top, box.width, box.height, solution));
        } catch (err) {
          console.error("figure pointer failed", err);
        }
      });
    }
    if (Array.isArray(spec.actions) && spec.actions.length && setInputs) {
      const bar = document.createElement("div");
      bar.className = "figure-actions";
      for (const action of spec.actions) {
        const button = document.createElement("button");
        button.type = "button";
        button.className = "button";
        button.textContent = action.label;
        if (action.title) button.title = action.title;
        button.addEventListener("click", () => {
          try {
            edit(action.inputs(solution));
          } catch (err) {
            console.error("figure action failed", err);
          }
        });
        bar.append(button);
      }
      figure.append(bar);
    }
    if (spec.caption) {
      const caption = document.createElement("figcaption");
      caption.textContent = spec.caption;
      figure.append(caption);
    }
    host.append(figure);
    return { spec, canvas, figure, drawn: null };
  });

  const redraw = () => panels.forEach((p) => paint(p, solution));
  const onResize = () => {
    // repaint only when the width or the pixel ratio changed (the height follows the width)
    const dpr = window.devicePixelRatio || 1;
    for (const p of panels) {
      const w = Math.floor(p.figure.clientWidth);
      if (!p.drawn || p.drawn.width !== w || p.drawn.dpr !== dpr) paint(p, solution);
    }
  };
  const observer = new ResizeObserver(onResize);
  panels.forEach((p) => observer.observe(p.figure));

  // a zoom or a move to another screen changes devicePixelRatio
  let media = null;
  const watchRatio = () => {
    media = window.matchMedia(`(resolution: ${window.devicePixelRatio || 1}dppx)`);
    media.addEventListener("change", onRatio, { once: true });
  };
  const onRatio = () => {
    onResize();
    watchRatio();
  };
  watchRatio();

  return {
    update(next) {
      solution = next;
      redraw();
    },
    redraw,
    destroy() {
      observer.disconnect();
      if (media) media.removeEventListener("change", onRatio);
      panels.forEach((p) => p.figure.remove());
    },
  };
}
