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
// Optional: `minWidth(solution)`, the least canvas width (CSS px) the figure
// needs, e.g. for cells of at least 24 × 24 px to click (WCAG 2.5.8): on a
// narrower panel the canvas keeps that width and the panel scrolls sideways;
// `height(width, solution, room)` and `state.room` then give the panel's
// visible width, for text that should read without scrolling (chains.js).
//
// Optional: `tables(solution, state)`, the figure's numbers for readers who
// cannot see the canvas (issue 32; docs/figures.md), read from the same
// solution data the figure is drawn from (no number is computed for it):
//
//   tables(solution, state) {
//     return {
//       summary: "ρ is highest, 0.93, at row 3, column 4 of the 5 × 5 positions.",  // the canvas's description
//       tables: [{
//         caption: "ρ at every position",
//         corner: "",                                      // the top-left header (optional)
//         columns: ["column 1", …], rowHeaders: ["row 1", …],
//         rows: [["0.12", …], …],                          // texts, formatted as the figure writes them
//         marks: [[null, "best", …], …],                   // optional: words added to a cell ("best", "selected")
//         explore: { rect(r, c, width, height) { return { x, y, w, h }; } },  // optional: the cell on the canvas
//       }],
//       list: { caption: "The path, move by move", items: ["(1, 4) → (2, 4): east, code 1", …] },  // optional
//     };
//   }
//
// The summary becomes the canvas's accessible description (aria-describedby);
// a "Data" button under the canvas (a disclosure: aria-expanded, aria-controls)
// shows the summary, the tables (th scope=col/row headers) and the list; they
// print. A table with `explore` gives the focused canvas a cell cursor: the
// arrow keys (Home, End, PageUp, PageDown) move it where the figure's own key
// hooks leave the key alone, a polite live line reads the cell ("row 3,
// column 2, 87, inside the window"), and Enter or Space on it does what a
// click on the cell's centre does (the same pointer/select/pick path).
//
// Optional: motion (issue 34; docs/figures.md, "Motion"), for a figure of a
// moving window: `frames(solution)` returns the frames, each a plain object
// read from the solution (no number computed for it) with `caption` (this
// frame's numbers, in words) and `step` (the index of its step in
// solution.steps, highlighted in the step list, or null); `motion: { noun }`
// names a frame ("position", "move", "iteration"). The panel gets Play, Pause,
// Step back, Step forward, Show all and a slider (www/motion/motion.js), and
// `draw` receives `state.frame` (the frame shown, or null: the figure as it
// is without motion) and `state.frameIndex`. `frameAt(solution, state)`
// (optional) gives the frame of a selection the figure's own click or key
// made, so the motion follows it. A spec without `frames` is untouched.
//
// The page calls mountFigures(host, id, { onInputs })
// once per example view and .update(solution) after each successful solve;
// device-pixel-ratio scaling, resizing and errors are handled here.

import { COLORS, clearLabelBoxes, font, FONT_SIZE, pageTheme, usePalette } from "./draw.js";
import { addStylesheet, setText } from "../dom.js";
import { testData } from "../test-hooks.js";
import { cursorText, dataView, moveCursor, renderData } from "./data-view.js";

// the figures' own rules (the Data view, the cell cursor's line), loaded with the registry
addStylesheet(new URL("./figures.css", import.meta.url).href);

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

/** The frame the panel's motion shows, or null (none, or the figure without motion). */
function frameOf(panel) {
  const i = panel.motion?.index ?? null;
  return i === null ? null : panel.frames?.[i] ?? null;
}

/** `light`: a frame while playing: only the canvas changes (its words follow when it stops). */
function paint(panel, solution, shared = { selected: null }, light = false) {
  const { spec, canvas, figure } = panel;
  // the width the resize observer last saw (read while the layout was clean); reading
  // clientWidth here, after the steps were rewritten, would lay the whole page out again
  const room = panel.width ?? Math.floor(figure.clientWidth);
  if (!solution || room <= 0) return;
  // a figure whose targets would be smaller than 24 × 24 px (WCAG 2.5.8) asks for a wider canvas: the panel scrolls
  let width = room;
  const dpr = window.devicePixelRatio || 1;
  let height;
  // a frame while playing keeps the canvas's size (the solution and the width are the same)
  const kept = light && panel.size?.room === room && panel.size.solution === solution ? panel.size : null;
  if (kept) ({ width, height } = kept);
  else {
    try {
      if (typeof spec.minWidth === "function") width = Math.max(room, Math.ceil(spec.minWidth(solution)));
    } catch {
      width = room;
    }
    figure.classList.toggle("figure-wide", width > room);
    try {
      // `room`: the panel's visible width (a wide canvas's text wraps to what is seen without scrolling)
      height = Math.round(Math.min(MAX_HEIGHT, Math.max(MIN_HEIGHT, spec.height(width, solution, room))));
    } catch {
      height = MIN_HEIGHT;
    }
    panel.size = { room, solution, width, height };
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
  const frame = frameOf(panel);
  const state = { ...(panel.state ?? {}), selected: shared.selected, slider: panel.sliderValue ?? null, frame, frameIndex: frame ? panel.motion.index : null, room };
  clearLabelBoxes(canvas);
  try {
    spec.draw(ctx, width, height, solution, state);
    if (light) {
      panel.drawn = { width: room, dpr };
      return;
    }
    // the legend of every grey scale drawn, in words
    const scales = (canvas.greyScales ?? []).map((g) => `${g.text}.`);
    canvas.setAttribute("aria-label", [spec.describe(solution, state), ...scales].join(" "));
    if (panel.status) {
      panel.status.textContent = spec.status(solution, state) ?? "";
      // a motion frame's caption (and its live line) says it: the selection's line would say it twice
      panel.status.hidden = frame !== null;
    }
    showData(panel, solution, state, width, height, ctx);
    operable(canvas);
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
  panel.drawn = { width: room, dpr };
}

/**
 * A canvas the keyboard can operate (focusable) is a group with its own role
 * description, not a picture (docs/figures.md); a static one stays an image.
 */
function operable(canvas) {
  const role = canvas.tabIndex >= 0 ? "group" : "img";
  if (canvas.getAttribute("role") === role) return;
  canvas.setAttribute("role", role);
  if (role === "group") canvas.setAttribute("aria-roledescription", "interactive figure");
  else canvas.removeAttribute("aria-roledescription");
}

/**
 * The spec's tables(solution, state): the canvas's description (the summary),
 * the Data view when it is open, and the cell cursor (drawn on the canvas
 * while it has the focus, its cell read out in the panel's cursor line).
 */
function showData(panel, solution, state, width, height, ctx) {
  if (!panel.data) return;
  let data = null;
  try {
    data = panel.spec.tables(solution, state);
  } catch (e) {
    console.error("figure data failed", e);
  }
  panel.tables = data;
  panel.data.summary.textContent = data?.summary ?? "";
  if (panel.data.open) renderData(panel.data.body, data);
  const grid = (data?.tables ?? []).find((t) => t.explore);
  panel.grid = grid ?? null;
  const name = (grid?.caption ?? "the grid").replace(/\s*\(.*$/, "");
  const keys = grid ? `Keyboard: on the focused figure the arrow keys move a cell cursor over “${name}”, read out below${panel.clicks.length ? "; Enter or Space does what a click on the cell does" : ""}.` : "";
  if (panel.data.keys.textContent !== keys) panel.data.keys.textContent = keys;
  if (grid && panel.canvas.tabIndex < 0) panel.canvas.tabIndex = 0;
  if (!grid || !panel.cursor) {
    if (panel.data.cursorLine.textContent) panel.data.cursorLine.textContent = "";
    return;
  }
  const rows = grid.rows.length;
  const cols = grid.rows[0]?.length ?? 0;
  if (!rows || !cols) {
    panel.cursor = null;
    panel.data.cursorLine.textContent = "";
    return;
  }
  // the cursor stays on its row and column (by their headers: a grid may grow or shift when a click changes it)
  const at = (headers, key, i, n) => {
    const k = key === undefined ? -1 : (headers ?? []).indexOf(key);
    return k >= 0 ? k : Math.min(i, n - 1);
  };
  const r = at(grid.rowHeaders, panel.cursor.rowKey, panel.cursor.r, rows);
  const c = at(grid.columns, panel.cursor.colKey, panel.cursor.c, cols);
  panel.cursor = { r, c, rowKey: grid.rowHeaders?.[r], colKey: grid.columns?.[c] };
  const words = cursorText(grid, panel.cursor);
  if (panel.data.cursorLine.textContent !== words) panel.data.cursorLine.textContent = words;
  if (document.activeElement !== panel.canvas) return;
  const box = grid.explore.rect(panel.cursor.r, panel.cursor.c, width, height);
  if (!box) return;
  keepInView(panel.figure, panel.canvas, box);
  ctx.save();
  for (const [color, lw, dash] of [["#ffffff", 5, []], [COLORS.ink, 2.5, [5, 3]]]) {
    ctx.strokeStyle = color;
    ctx.lineWidth = lw;
    ctx.setLineDash(dash);
    ctx.strokeRect(box.x, box.y, box.w, box.h);
  }
  ctx.restore();
}

/**
 * A grid wider than its panel scrolls inside it (figures.css .figure-wide, a phone): the
 * cursor's cell is scrolled into view, with a cell's margin, as the arrow keys move it.
 */
function keepInView(scroller, canvas, box) {
  if (scroller.scrollWidth <= scroller.clientWidth) return;
  // the canvas's left edge in the panel's scrolled content
  const x0 = canvas.getBoundingClientRect().left - scroller.getBoundingClientRect().left - scroller.clientLeft + scroller.scrollLeft;
  const left = x0 + box.x - box.w;
  const right = x0 + box.x + 2 * box.w;
  const max = scroller.scrollWidth - scroller.clientWidth;
  // near an end, the whole way (the row labels left of the first column come with it)
  if (left < scroller.scrollLeft) scroller.scrollLeft = left < 2 * box.w ? 0 : left;
  else if (right > scroller.scrollLeft + scroller.clientWidth) scroller.scrollLeft = right - scroller.clientWidth > max - 2 * box.w ? max : right - scroller.clientWidth;
}

/** Wires a spec's optional `interact` hooks to its canvas (pointer and keyboard); returns its click at a point. */
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
  const pointerAt = (x, y, width, height) => {
    const solution = current();
    if (!solution || typeof interact.pointer !== "function") return null;
    try {
      return interact.pointer(x, y, width, height, solution);
    } catch (err) {
      console.error("figure interaction failed", err);
      return null;
    }
  };
  const fromEvent = (e) => {
    const box = canvas.getBoundingClientRect();
    return pointerAt(e.clientX - box.left, e.clientY - box.top, box.width, box.height);
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
  return (x, y, width, height) => apply(pointerAt(x, y, width, height));
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
export function mountFigures(host, id, { onInputs = null, onStep = null, onPosition = null } = {}) {
  const specs = specsFor(id);
  if (!specs.length) return null;
  let solution = null;
  let destroyed = false;
  /** A start the link asked for (play=), kept until the motion and a solution are there. */
  let playRequest = null;
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
    const data = typeof spec.tables === "function" ? dataView(canvas) : null;
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
    if (data) figure.append(data.cursorLine, data.bar, data.body);
    host.append(figure);
    const panel = { spec, canvas, figure, drawn: null, slider: null, sliderValue: null, state: null, status: null, data, cursor: null, grid: null, clicks: [] };
    if (data) {
      data.toggle.addEventListener("click", () => {
        data.open = !data.open;
        data.toggle.setAttribute("aria-expanded", String(data.open));
        data.body.hidden = !data.open;
        if (data.open) renderData(data.body, panel.tables);
      });
    }
    if (spec.interact && onInputs) panel.clicks.push(interactive(spec, canvas, figure, () => solution, onInputs));
    if (typeof spec.slider === "function") {
      const label = document.createElement("label");
      label.className = "figure-slider";
      const name = document.createElement("span");
      const input = document.createElement("input");
      input.type = "range";
      input.step = "1";
      input.addEventListener("input", () => {
        // a moving figure's own slider is its scrub (frame k is slider value k + 1)
        if (panel.motion?.index !== null && panel.motion?.index !== undefined) {
          panel.motion.goTo(Number(input.value) - Number(input.min));
          return;
        }
        panel.sliderValue = Number(input.value);
        name.textContent = panel.sliderText(panel.sliderValue);
        paint(panel, panel.solution, shared);
      });
      label.append(name, input);
      canvas.after(label);
      panel.slider = { label, name, input };
    }
    if (typeof spec.frames === "function") {
      panel.frames = [];
      figure.dataset.moves = ""; // a figure that moves (its controls come with their module)
      // the controls' module is loaded with the first figure that moves (www/motion/motion.js)
      panel.motionReady = import("../motion/motion.js").then(({ createMotion }) => {
        if (destroyed) return;
        panel.motion = createMotion({
          noun: spec.motion?.noun ?? "position",
          // a figure with its own slider (the LSM iterations): that slider scrubs, and follows the frame
          scrub: !panel.slider,
          all: spec.motion?.all !== false,
          show: (i, how) => {
            if (panel.slider && i !== null && panel.frames[i]?.slider !== undefined) {
              panel.sliderValue = panel.frames[i].slider;
              panel.slider.input.value = String(panel.sliderValue);
              setText(panel.slider.name, panel.sliderText?.(panel.sliderValue) ?? ""); // a frame: the text node's data (dom.js)
            }
            paint(panel, solution, shared, !how.full);
          },
          onStep: (k) => onStep?.(k),
          onPosition: (i) => onPosition?.(i),
        });
        (panel.slider?.label ?? canvas).after(panel.motion.element);
        if (solution) panel.motion.setFrames(panel.frames);
        openRequested();
      });
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
    // a selection made on a moving figure: the motion goes to its frame (or shows every position)
    if (panel.motion && panel.motion.index !== null) {
      let at = null;
      try {
        at = typeof panel.spec.frameAt === "function" ? panel.spec.frameAt(solution, next) : null;
      } catch {
        at = null;
      }
      panel.motion.goTo(Number.isInteger(at) ? at : null);
      return true;
    }
    paint(panel, solution, shared);
    return true;
  };
  const moving = () => panels.find((p) => p.motion);
  // a key or click moves on from the frame shown (its position is the selection then)
  const withFrame = (panel) => (frameOf(panel) ? { ...(panel.state ?? {}), frame: frameOf(panel) } : panel.state);
  function openRequested() {
    const p = moving();
    if (!playRequest || !p || !solution) return;
    const request = playRequest;
    playRequest = null;
    p.motion.open(request);
  }
  for (const panel of panels) {
    const { spec, canvas } = panel;
    if (typeof spec.select === "function") {
      const selectAt = (x, y, width, height) => {
        if (solution) interact(panel, spec.select(solution, { x, y, width, height }, withFrame(panel)));
      };
      canvas.addEventListener("click", (e) => {
        const box = canvas.getBoundingClientRect();
        selectAt(e.clientX - box.left, e.clientY - box.top, box.width, box.height);
      });
      panel.clicks.push(selectAt);
    }
    if (typeof spec.key === "function") {
      canvas.tabIndex = 0;
      canvas.addEventListener("keydown", (e) => {
        if (!solution || e.altKey || e.ctrlKey || e.metaKey) return;
        if (interact(panel, spec.key(solution, e.key, withFrame(panel)))) e.preventDefault();
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
    const pickAt = (i) => {
      if (i === null || (shared.pinned && i === shared.selected)) select(null, false);
      else select(i, true);
    };
    canvas.addEventListener("click", (e) => pickAt(hit(e)));
    p.clicks.push((x, y, width, height) => pickAt(solution ? spec.pick(x, y, width, height, solution) : null));
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
  for (const p of panels) {
    if (!p.data) continue;
    const { canvas } = p;
    canvas.addEventListener("keydown", (e) => {
      if (e.defaultPrevented || e.altKey || e.ctrlKey || e.metaKey || !solution || !p.grid) return;
      if (e.key === "Enter" || e.key === " ") {
        if (!p.cursor || !p.clicks.length) return;
        e.preventDefault();
        const box = p.grid.explore.rect(p.cursor.r, p.cursor.c, canvas.clientWidth, canvas.clientHeight);
        if (box) for (const click of p.clicks) click(box.x + box.w / 2, box.y + box.h / 2, canvas.clientWidth, canvas.clientHeight);
        return;
      }
      const next = moveCursor(p.grid, p.cursor, e.key);
      if (!next) return;
      e.preventDefault();
      p.cursor = { ...next, rowKey: p.grid.rowHeaders?.[next.r], colKey: p.grid.columns?.[next.c] };
      paint(p, solution, shared);
    });
    // the cursor is drawn while the canvas has the focus
    canvas.addEventListener("focus", () => p.cursor && paint(p, solution, shared));
    canvas.addEventListener("blur", () => p.cursor && paint(p, solution, shared));
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
    // the Data views print open (figures.css): their tables are filled now
    for (const p of panels) if (p.data && !p.data.open) renderData(p.data.body, p.tables);
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
      for (const p of panels) {
        if (typeof p.spec.frames !== "function") continue;
        try {
          p.frames = p.spec.frames(next) ?? [];
        } catch (e) {
          console.error("figure frames failed", e);
          p.frames = [];
        }
        p.motion?.setFrames(p.frames);
      }
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
      openRequested();
    },
    redraw,
    /** Whether a figure of the example moves (has frames). */
    hasMotion: panels.some((p) => typeof p.spec.frames === "function"),
    /** Opens the motion as the link asks (play=): { frame } (1-based, paused) or { auto: true }. */
    play(request) {
      playRequest = request ?? null;
      openRequested();
    },
    /** The motion controllers (for `npm run bench -- motion`). */
    motions: () => panels.map((p) => p.motion).filter(Boolean),
    /** The frame a moving figure shows (its spec's frame object), or null (the lab outlines it on the photo). */
    frame: () => (moving() ? frameOf(moving()) : null),
    destroy() {
      destroyed = true;
      panels.forEach((p) => p.motion?.destroy());
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
