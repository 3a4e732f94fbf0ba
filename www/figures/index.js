// The figure registry and the canvas plumbing every figure shares.
//
// A figure module (one per topic) exports `figures`: an object mapping an
// example id to a figure spec, or to an array of specs (one canvas each):
//
//   export const figures = {
//     "<example id>": {
//       caption: "Side view of the camera …",          // shown under the canvas
//       height(width, solution) { return 300; },       // CSS px for a CSS width
//       describe(solution) { return "…"; },             // the canvas's aria-label
//       draw(ctx, width, height, solution) { … },       // ctx scaled to CSS px, cleared to COLORS.background
//     },
//   };
//
// and is named after its topic's module (the catalog's `module`: figures/<module>.js,
// listed in MODULES below).
//
// Optional: `slider(solution)` returns { label, min, max, value } (integers)
// or null; the panel then gets a labelled range input (keyboard-usable), and
// `draw`/`describe` receive its current value as a last argument `{ slider }`.
// The value is kept while it stays within a new solution's range.
//
// Optional: `interact`, to change inputs from the figure:
//
//   interact: {
//     hint: "Click a pixel to select it; arrow keys move the selection.",
//     pointer(x, y, width, height, solution) { return { select_c: "3" } | null; },
//     key(key, solution) { return { select_c: "4" } | null; },   // KeyboardEvent.key
//     drag: true,                                                  // also while the pointer moves pressed
//   }
//
// The returned texts are put into the form (as if typed) and the example is
// solved again; the canvas becomes focusable and the hint is shown below it.
//
// Optional: a view state (a selection the figure draws, e.g. one position of a
// correlation): a spec with `select(solution, { x, y, width, height }, state)`
// (a click, in CSS px of the canvas) and/or `key(solution, key, state)` (a
// KeyboardEvent.key on the focused canvas) returns the new selection state,
// or undefined to leave it; the canvas then takes the keyboard focus, and
// `draw(ctx, w, h, solution, state)`, `describe(solution, state)` and the
// optional `status(solution, state)` (a line of text under the canvas, read
// out by screen readers) receive it. The state lives as long as the example
// view; specs treat a state that no longer fits the solution as none.
//
// Optional, for figures whose items (points) can be picked, shared by all
// canvases of the example:
//
//     count(solution)                        // how many items there are
//     pick(x, y, width, height, solution)    // the item under (x, y), or null
//
// With them the canvas takes the focus (Tab); hovering an item, clicking it
// (pins it) or the arrow keys (Escape clears) select it, and every canvas of
// the example is redrawn with draw(ctx, width, height, solution, { selected })
// and describe(solution, { selected }) — so one figure can highlight what
// another shows. `selected` is the item's index or null.
//
// Optional: `actions: [{ label: "Circle", title, inputs(solution) { return { … }; } }]`,
// buttons under the canvas, each setting the input texts it returns (as if
// typed) and solving again.
//
// The page calls mountFigures(host, id, { onInputs })
// once per example view and .update(solution) after each successful solve;
// device-pixel-ratio scaling, resizing and errors are handled here.

import { COLORS, clearLabelBoxes, font, FONT_SIZE, pageTheme, usePalette } from "./draw.js";
import { testData } from "../test-hooks.js";

/** While the page prints, figures are drawn on the light paper whatever the theme. */
let printing = false;

/**
 * The figure module of each topic, by the topic's wasm module name (the
 * catalog's `module`: figures/<module>.js), loaded when an example of that
 * topic is first shown, so a page shows its first example without fetching
 * every topic's drawing code. The import paths are literal: the bundler
 * splits code at each, and names the chunks.
 */
const MODULES = Object.freeze({
  coordinates: () => import("./coordinates.js"),
  transformations: () => import("./transformations.js"),
  correlation: () => import("./correlation.js"),
  matching: () => import("./matching.js"),
  resampling: () => import("./resampling.js"),
  filters: () => import("./filters.js"),
  interest: () => import("./interest.js"),
  chains: () => import("./chains.js"),
  projection: () => import("./projection.js"),
});

/** id → spec or [spec…], filled as topic modules load. */
const REGISTRY = {};
const loading = new Map();

/** Whether a module's figures still have to be fetched (the page then shows "loading"). */
export function figuresPending(module) {
  return Object.hasOwn(MODULES, module) && !loading.has(module);
}

/**
 * Loads the figures of the topic whose wasm module is `module` (the
 * catalog's `module`, once); resolves when its examples' figures are
 * registered. A module that fails to load leaves those examples without a
 * figure (the error is logged) and is tried again next time.
 */
export function loadFigures(module) {
  if (!Object.hasOwn(MODULES, module)) return Promise.resolve();
  if (!loading.has(module)) {
    const promise = MODULES[module]()
      .then((loaded) => {
        Object.assign(REGISTRY, loaded.figures);
      })
      .catch((e) => {
        loading.delete(module);
        console.warn(`the figures of "${module}" could not be loaded`, e);
      });
    loading.set(module, promise);
  }
  return loading.get(module);
}

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

function paint(panel, solution, shared = { selected: null }) {
  const { spec, canvas, figure } = panel;
  // the width the resize observer last saw (read while the layout was clean); reading
  // clientWidth here, after the steps were rewritten, would lay the whole page out again
  const width = panel.width ?? Math.floor(figure.clientWidth);
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
  // the page's theme: a dark paper in the dark theme (image greys keep dark = low)
  testData(canvas, "theme", usePalette(printing ? "light" : pageTheme()));
  ctx.fillStyle = COLORS.background;
  ctx.fillRect(0, 0, width, height);
  const state = { ...(panel.state ?? {}), selected: shared.selected, slider: panel.sliderValue ?? null };
  clearLabelBoxes(canvas);
  try {
    spec.draw(ctx, width, height, solution, state);
    // the legend of every grey scale drawn, in words
    const scales = (canvas.greyScales ?? []).map((g) => `${g.text}.`);
    canvas.setAttribute("aria-label", [spec.describe(solution, state), ...scales].join(" "));
    if (panel.status) panel.status.textContent = spec.status(solution, state) ?? "";
  } catch (e) {
    console.error("figure failed", e);
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.fillStyle = COLORS.background;
    ctx.fillRect(0, 0, width, height);
    ctx.fillStyle = COLORS.ink;
    ctx.font = font(FONT_SIZE);
    ctx.fillText("The figure could not be drawn for these values.", 10, 24);
    clearLabelBoxes(canvas);
    canvas.setAttribute("aria-label", "The figure could not be drawn for these values.");
  }
  panel.drawn = { width, dpr };
}

/** Wires a spec's optional `interact` hooks to its canvas (pointer and keyboard). */
function interactive(spec, canvas, figure, current, onInputs) {
  const { interact } = spec;
  canvas.tabIndex = 0;
  canvas.classList.add("figure-interactive");
  if (interact.hint) {
    const hint = document.createElement("p");
    hint.className = "figure-hint";
    hint.textContent = interact.hint;
    figure.append(hint);
  }
  const apply = (changes) => {
    if (changes && typeof changes === "object" && Object.keys(changes).length) onInputs(changes);
  };
  let pressed = false;
  let queued = null;
  const fromEvent = (e) => {
    const solution = current();
    if (!solution || typeof interact.pointer !== "function") return null;
    const box = canvas.getBoundingClientRect();
    try {
      return interact.pointer(e.clientX - box.left, e.clientY - box.top, box.width, box.height, solution);
    } catch (err) {
      console.error("figure interaction failed", err);
      return null;
    }
  };
  canvas.addEventListener("pointerdown", (e) => {
    if (e.button !== 0) return;
    pressed = true;
    if (interact.drag) canvas.setPointerCapture(e.pointerId);
    apply(fromEvent(e));
  });
  canvas.addEventListener("pointermove", (e) => {
    if (!pressed || !interact.drag) return;
    const first = queued === null;
    queued = e;
    if (first) {
      requestAnimationFrame(() => {
        const ev = queued;
        queued = null;
        if (ev) apply(fromEvent(ev));
      });
    }
  });
  const release = () => {
    pressed = false;
  };
  canvas.addEventListener("pointerup", release);
  canvas.addEventListener("pointercancel", release);
  canvas.addEventListener("keydown", (e) => {
    const solution = current();
    if (!solution || typeof interact.key !== "function") return;
    let changes = null;
    try {
      changes = interact.key(e.key, solution);
    } catch (err) {
      console.error("figure interaction failed", err);
    }
    if (changes) {
      e.preventDefault();
      apply(changes);
    }
  });
}

/** Sets a panel's range input from the spec's slider(solution). */
function syncSlider(panel, solution) {
  panel.solution = solution;
  if (!panel.slider) return;
  let spec = null;
  try {
    spec = solution ? panel.spec.slider(solution) : null;
  } catch {
    spec = null;
  }
  const { label, name, input } = panel.slider;
  if (!spec || !(spec.max > spec.min)) {
    label.hidden = true;
    panel.sliderValue = spec ? spec.value : null;
    return;
  }
  label.hidden = false;
  input.min = String(spec.min);
  input.max = String(spec.max);
  const keep = panel.sliderValue;
  const value = Number.isInteger(keep) && keep >= spec.min && keep <= spec.max ? keep : spec.value;
  input.value = String(value);
  panel.sliderValue = value;
  panel.sliderText = (v) => `${spec.label} ${v} of ${spec.max}`;
  name.textContent = panel.sliderText(value);
  input.setAttribute("aria-label", spec.label);
}

/**
 * Puts the example's canvases into `host`; `onInputs(texts)` (optional) takes
 * input changes from interactive figures.
 * @returns {{ update(solution): void, redraw(): void, destroy(): void } | null}
 */
export function mountFigures(host, id, { onInputs = null } = {}) {
  const specs = specsFor(id);
  if (!specs.length) return null;
  let solution = null;
  const shared = { selected: null, pinned: false };
  const edit = (texts) => {
    if (onInputs && texts && typeof texts === "object" && Object.keys(texts).length) onInputs(texts);
  };
  const panels = specs.map((spec) => {
    const canvas = document.createElement("canvas");
    canvas.className = "figure-canvas";
    canvas.setAttribute("role", "img");
    canvas.setAttribute("aria-label", "Figure (not drawn yet)");
    const figure = document.createElement("figure");
    figure.className = "figure-panel";
    figure.append(canvas);
    if (Array.isArray(spec.actions) && spec.actions.length && onInputs) {
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
    const panel = { spec, canvas, figure, drawn: null, slider: null, sliderValue: null, state: null, status: null };
    if (spec.interact && onInputs) interactive(spec, canvas, figure, () => solution, onInputs);
    if (typeof spec.slider === "function") {
      const label = document.createElement("label");
      label.className = "figure-slider";
      const name = document.createElement("span");
      const input = document.createElement("input");
      input.type = "range";
      input.step = "1";
      input.addEventListener("input", () => {
        panel.sliderValue = Number(input.value);
        name.textContent = panel.sliderText(panel.sliderValue);
        paint(panel, panel.solution, shared);
      });
      label.append(name, input);
      canvas.after(label);
      panel.slider = { label, name, input };
    }
    if (typeof spec.status === "function") {
      panel.status = document.createElement("p");
      panel.status.className = "figure-status";
      panel.status.setAttribute("aria-live", "polite");
      figure.insertBefore(panel.status, canvas.nextSibling);
    }
    return panel;
  });

  const interact = (panel, next) => {
    if (next === undefined) return false;
    panel.state = next;
    paint(panel, solution, shared);
    return true;
  };
  for (const panel of panels) {
    const { spec, canvas } = panel;
    if (typeof spec.select === "function") {
      canvas.addEventListener("click", (e) => {
        if (!solution) return;
        const box = canvas.getBoundingClientRect();
        const point = { x: e.clientX - box.left, y: e.clientY - box.top, width: box.width, height: box.height };
        interact(panel, spec.select(solution, point, panel.state));
      });
    }
    if (typeof spec.key === "function") {
      canvas.tabIndex = 0;
      canvas.addEventListener("keydown", (e) => {
        if (!solution || e.altKey || e.ctrlKey || e.metaKey) return;
        if (interact(panel, spec.key(solution, e.key, panel.state))) e.preventDefault();
      });
    }
  }
  const redraw = () => panels.forEach((p) => paint(p, solution, shared));
  const select = (index, pinned) => {
    if (index === shared.selected && pinned === shared.pinned) return;
    shared.selected = index;
    shared.pinned = pinned;
    redraw();
  };
  for (const p of panels) {
    const { spec, canvas } = p;
    if (typeof spec.pick !== "function" || typeof spec.count !== "function") continue;
    canvas.tabIndex = 0;
    const hit = (e) => (solution ? spec.pick(e.offsetX, e.offsetY, canvas.clientWidth, canvas.clientHeight, solution) : null);
    canvas.addEventListener("pointermove", (e) => {
      if (!shared.pinned) select(hit(e), false);
    });
    canvas.addEventListener("pointerleave", () => {
      if (!shared.pinned) select(null, false);
    });
    canvas.addEventListener("click", (e) => {
      const i = hit(e);
      if (i === null || (shared.pinned && i === shared.selected)) select(null, false);
      else select(i, true);
    });
    canvas.addEventListener("keydown", (e) => {
      const n = solution ? spec.count(solution) : 0;
      if (!n) return;
      const cur = shared.selected;
      let next;
      if (e.key === "ArrowRight" || e.key === "ArrowDown") next = cur === null ? 0 : (cur + 1) % n;
      else if (e.key === "ArrowLeft" || e.key === "ArrowUp") next = cur === null ? n - 1 : (cur - 1 + n) % n;
      else if (e.key === "Escape") next = null;
      else return;
      e.preventDefault();
      select(next, next !== null);
    });
  }
  const onResize = () => {
    // repaint only when the width or the pixel ratio changed (the height follows the width)
    const dpr = window.devicePixelRatio || 1;
    for (const p of panels) {
      const w = Math.floor(p.figure.clientWidth);
      p.width = w;
      if (!p.drawn || p.drawn.width !== w || p.drawn.dpr !== dpr) paint(p, solution, shared);
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

  // the theme switch (<html data-theme>), the system setting, and print (light paper) redraw
  const themeObserver = new MutationObserver(redraw);
  themeObserver.observe(document.documentElement, { attributes: true, attributeFilter: ["data-theme"] });
  const scheme = window.matchMedia("(prefers-color-scheme: dark)");
  scheme.addEventListener("change", redraw);
  const beforePrint = () => {
    printing = true;
    redraw();
  };
  const afterPrint = () => {
    printing = false;
    redraw();
  };
  window.addEventListener("beforeprint", beforePrint);
  window.addEventListener("afterprint", afterPrint);

  return {
    update(next) {
      solution = next;
      panels.forEach((p) => syncSlider(p, next));
      const counts = panels
        .filter((p) => typeof p.spec.count === "function")
        .map((p) => {
          try {
            return p.spec.count(next);
          } catch {
            return 0;
          }
        });
      if (shared.selected !== null && !counts.some((n) => shared.selected < n)) {
        shared.selected = null;
        shared.pinned = false;
      }
      redraw();
    },
    redraw,
    destroy() {
      observer.disconnect();
      themeObserver.disconnect();
      scheme.removeEventListener("change", redraw);
      window.removeEventListener("beforeprint", beforePrint);
      window.removeEventListener("afterprint", afterPrint);
      if (media) media.removeEventListener("change", onRatio);
      panels.forEach((p) => p.figure.remove());
    },
  };
}
