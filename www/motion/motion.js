// Motion for the moving-window figures (issue 34, item 2): Play, Pause, Step
// back, Step forward, a scrub slider, the frame counter, a caption with this
// frame's numbers and a polite live region; the figure registry
// (www/figures/index.js) mounts it under a figure whose spec has `frames`.
//
// The frames are the spec's `frames(solution)`: a list of plain objects read
// from the solution the figure is drawn from (nothing is computed here):
//
//   { caption: "Position 7 (row 2, column 3): ρ = … = 0.2394",  // this frame's numbers, shown and read out
//     step: 3,                                                    // the index of its step in solution.steps (or null)
//     …anything the spec's draw reads from state.frame }
//
// The controller knows nothing of canvases: `show(index, { full })` asks the
// registry to draw frame `index` (`full: false` while playing, when only the
// canvas changes; `full: true` when it stops, so the canvas's name, status and
// Data view follow), `show(null)` the figure without frames (every position).
//
// Timing: requestAnimationFrame drives playback; a frame advances every
// 1000 / rate ms (rate: positions per second, 2, 5 or 10, chosen by the
// reader; 5 by default, slow enough to follow one position). With
// `prefers-reduced-motion: reduce` there is no Play button: the figure moves
// only when the reader steps or scrubs (Step forward is the one-frame Play; a
// Play that stepped would be a button named for something it does not do),
// and `play=auto` opens at the first frame, paused. The live region speaks
// on a step, a scrub and a pause, never frame by frame while playing.

import { addStylesheet, el, keepTallest, setText } from "../dom.js";

/** Positions per second the reader can choose, and the default. */
export const RATES = Object.freeze([2, 5, 10]);
export const DEFAULT_RATE = 5;

const REDUCE = "(prefers-reduced-motion: reduce)";

// the controls' rules, loaded once with the first motion
addStylesheet(new URL("./motion.css", import.meta.url).href);

let serial = 0;

/**
 * The controls of one figure's motion.
 * @param {{ noun?: string, show(index: number|null, how: { full: boolean }): void,
 *           onStep?(step: number|null): void, onPosition?(index: number|null): void }} options
 *   noun: what a frame is ("position", "move", "iteration"); onStep: the step of the
 *   frame shown (highlight it in the step list); onPosition: the frame the reader
 *   stopped at (for the link), null when the figure shows every position again;
 *   scrub: false leaves the slider out (the figure has its own, which the
 *   registry keeps in step); all: false leaves "Show all" out (a figure whose
 *   frames are states, such as iterations, not parts of one whole).
 */
export function createMotion({ noun = "position", show, onStep = () => {}, onPosition = () => {}, scrub = true, all: showAll = true }) {
  const id = `motion-${++serial}`;
  let frames = [];
  /** The frame shown, or null: the figure as it is without motion (the final state). */
  let index = null;
  let playing = false;
  let rate = DEFAULT_RATE;
  let raf = 0;
  let last = 0;
  /** For `npm run bench -- motion`: a frame on every animation frame. */
  let everyFrame = false;
  const reduce = typeof matchMedia === "function" ? matchMedia(REDUCE) : { matches: false, addEventListener() {}, removeEventListener() {} };

  const button = (label, cls) => el("button", { type: "button", class: `button motion-${cls}` }, label);
  const play = button("▶ Play", "play");
  const back = button("◀ Step back", "back");
  const forward = button("Step forward ▶", "forward");
  const all = button("Show all", "all");
  const slider = el("input", { type: "range", min: "1", max: "1", step: "1", value: "1", id: `${id}-slider`, class: "motion-slider" });
  const counter = el("span", { class: "motion-counter", id: `${id}-counter` });
  // without a scrub of its own the figure's slider (above) names the frame: no counter
  const sliderLabel = scrub ? el("label", { for: `${id}-slider`, class: "motion-slider-label" }, counter, slider) : null;
  const speed = el("select", { id: `${id}-speed`, class: "motion-speed" }, ...RATES.map((r) => el("option", { value: String(r) }, `${r} per second`)));
  speed.value = String(rate);
  const speedLabel = el("label", { for: `${id}-speed`, class: "motion-speed-label" }, "Speed ", speed);
  const note = el("p", { class: "motion-note", hidden: true }, "Animation is off (your system asks for reduced motion): use Step forward, Step back or the slider.");
  const caption = el("p", { class: "motion-caption", id: `${id}-caption` });
  const live = el("p", { class: "visually-hidden motion-live", "aria-live": "polite", "aria-atomic": "true" });
  const bar = el("div", { class: "motion-bar", role: "group", "aria-label": "Motion" }, play, back, forward, showAll ? all : null, speedLabel);
  const element = el("div", { class: "motion", "data-motion": "" }, bar, sliderLabel, caption, note, live);
  slider.setAttribute("aria-describedby", caption.id);
  // the caption keeps its tallest height: a shorter frame's caption does not move the page below (a repaint of it all)
  const stopTallest = keepTallest(caption);

  const shownIndex = () => (index === null ? frames.length - 1 : index);
  const position = (i) => `${noun} ${i + 1} of ${frames.length}`;

  /** The controls' texts and states (no drawing). */
  function sync() {
    const n = frames.length;
    element.hidden = n < 2;
    const i = Math.max(0, shownIndex());
    slider.max = String(Math.max(1, n));
    slider.value = String(i + 1);
    slider.setAttribute("aria-valuetext", index === null ? `all ${n} ${noun}s` : position(i));
    // each frame: the text nodes' data, not new nodes (dom.js setText: a new node costs a style recalculation of the page)
    setText(counter, index === null ? `All ${n} ${noun}s` : position(i)[0].toUpperCase() + position(i).slice(1));
    setText(caption, index === null ? `Press Play or Step forward to follow the ${noun}s one by one.` : frames[i]?.caption ?? "");
    setText(play, playing ? "❚❚ Pause" : "▶ Play");
    play.setAttribute("aria-pressed", String(playing));
    play.hidden = reduce.matches;
    note.hidden = !reduce.matches;
    back.disabled = index === 0;
    forward.disabled = index !== null && index >= n - 1;
    all.disabled = index === null;
    element.dataset.frame = index === null ? "" : String(index + 1);
    element.dataset.playing = String(playing);
  }

  function announce() {
    live.textContent = index === null ? `All ${frames.length} ${noun}s shown.` : `${position(index)}. ${frames[index]?.caption ?? ""}`;
  }

  function draw(full) {
    show(index, { full });
    onStep(index === null ? null : frames[index]?.step ?? null);
    sync();
  }

  /** Shows frame i (null: all); `speak` announces it; `full` redraws the figure's words too. */
  function goTo(i, { speak = true, full = true } = {}) {
    index = i === null || !frames.length ? null : Math.min(Math.max(0, i), frames.length - 1);
    draw(full);
    if (speak) announce();
    if (!playing) onPosition(index);
  }

  function tick(now) {
    raf = 0;
    if (!playing) return;
    if (everyFrame || now - last >= 1000 / rate) {
      last = now;
      if (index === null || index >= frames.length - 1) {
        stop();
        return;
      }
      index += 1;
      if (everyFrame) {
        const t0 = performance.now();
        draw(false);
        api.benchTimes.push(performance.now() - t0);
      } else draw(false);
    }
    raf = requestAnimationFrame(tick);
  }

  function start() {
    if (reduce.matches || frames.length < 2) return;
    if (index === null || index >= frames.length - 1) index = 0;
    playing = true;
    last = performance.now();
    draw(false);
    live.textContent = `Playing from ${position(index)}.`;
    if (!raf) raf = requestAnimationFrame(tick);
  }

  function stop({ speak = true } = {}) {
    const was = playing;
    playing = false;
    if (raf) cancelAnimationFrame(raf);
    raf = 0;
    draw(true);
    if (was && speak) live.textContent = `Paused at ${position(index ?? frames.length - 1)}. ${index === null ? "" : frames[index]?.caption ?? ""}`;
    onPosition(index);
  }

  play.addEventListener("click", () => (playing ? stop() : start()));
  back.addEventListener("click", () => {
    if (playing) stop({ speak: false });
    goTo(index === null ? frames.length - 1 : index - 1);
  });
  forward.addEventListener("click", () => {
    if (playing) stop({ speak: false });
    goTo(index === null ? 0 : index + 1);
  });
  all.addEventListener("click", () => {
    if (playing) stop({ speak: false });
    goTo(null);
  });
  slider.addEventListener("input", () => {
    if (playing) stop({ speak: false });
    goTo(Number(slider.value) - 1);
  });
  speed.addEventListener("change", () => {
    if (RATES.includes(Number(speed.value))) rate = Number(speed.value);
  });
  const onReduce = () => {
    if (reduce.matches && playing) stop();
    else sync();
  };
  reduce.addEventListener("change", onReduce);
  sync();

  const api = {
    element,
    /** For `npm run bench -- motion`: the time each frame's drawing took (ms), with benchEveryFrame. */
    benchTimes: [],
    /** The frames of a new solution: the frame shown stays (clamped), drawn by the caller's paint. */
    setFrames(next) {
      frames = Array.isArray(next) ? next : [];
      if (index !== null) index = frames.length ? Math.min(index, frames.length - 1) : null;
      if (frames.length < 2 && playing) {
        playing = false;
        if (raf) cancelAnimationFrame(raf);
        raf = 0;
      }
      onStep(index === null ? null : frames[index]?.step ?? null);
      sync();
    },
    /** How many frames there are. */
    get count() {
      return frames.length;
    },
    /** The frame shown (0-based) or null. */
    get index() {
      return index;
    },
    get playing() {
      return playing;
    },
    /** A start from the link (`play=`): { frame } (1-based, paused) or { auto: true }. */
    open(request) {
      if (!request || frames.length < 2) return;
      if (request.auto) {
        if (reduce.matches) goTo(0);
        else start();
      } else if (Number.isInteger(request.frame)) goTo(request.frame - 1, { speak: false });
    },
    /** Shows frame i paused, as a step would (the figure's own selection moved it). */
    goTo(i) {
      if (playing) stop({ speak: false });
      goTo(i);
    },
    /** For `npm run bench -- motion`: advance on every animation frame. */
    benchEveryFrame(on) {
      everyFrame = Boolean(on);
    },
    play: start,
    pause: stop,
    destroy() {
      playing = false;
      if (raf) cancelAnimationFrame(raf);
      raf = 0;
      reduce.removeEventListener("change", onReduce);
      stopTallest();
      element.remove();
    },
  };
  // (the bench reaches the controller from the page: scripts/bench-motion.mjs)
  element.motion = api;
  return api;
}
