// The view options an address (or embed.js's data- attributes) may carry
// beside an example's inputs: validated like inputs, an unknown value ignored
// with a notice. Pure functions, no DOM: nothing read here becomes HTML.
//
//   theme=auto|light|dark        colours (auto: the reader's system setting)
//   show=figure,result           only these parts (inputs, steps, figure, result, notes, tools)
//   hide=inputs,notes            these parts not
//   steps=open|collapsed         every step open (default), or each step a fold
//   lock=true|false              inputs read-only (an exercise's fixed numbers)
//   step=3                       the step to start at: marked, and open when collapsed
//   host=https://course.example  the embedding page's origin: messages go only there
//   id=ex1                       echoed in every message to the host page
//   play=7 | play=auto           a moving figure (issue 34): open at frame 7, paused,
//                                or play from the first frame (paused at it under reduced motion)
//   sweep=key:from:to:steps      a sweep of one number input (issue 34; www/sweep/link.js)
//   plot=gsd_cm,pixel_size_mm    the results the sweep plots
//   grid=key:from:to:rows        the sweep's two-input table: a second input's rows (of plot='s first result)

import { parseGrid, parsePlot, parseSweep } from "./sweep/link.js";

export const PARTS = Object.freeze(["inputs", "steps", "figure", "result", "notes", "tools"]);
export const OPTION_KEYS = Object.freeze(["theme", "show", "hide", "steps", "lock", "step", "host", "id", "play", "sweep", "plot", "grid"]);
const THEMES = ["auto", "light", "dark"];
const MAX_QUOTED = 40;
const MAX_STEP = 1000;
/** The highest frame play= may name (a 64 × 64 search gives a few thousand positions). */
export const MAX_FRAME = 100000;

export function defaults() {
  return { theme: "auto", hide: [], steps: "open", lock: false, step: null, host: null, id: null, play: null, sweep: null, plot: null, grid: null };
}

function quote(text) {
  const t = String(text);
  return `“${t.length > MAX_QUOTED ? `${t.slice(0, MAX_QUOTED)}…` : t}”`;
}

function partList(key, value, notices) {
  const parts = [];
  for (const raw of value.split(/[\s,]+/).filter(Boolean)) {
    const p = raw.toLowerCase();
    if (PARTS.includes(p)) {
      if (!parts.includes(p)) parts.push(p);
    } else notices.push(`Ignored ${key}=${quote(raw)}: the parts are ${PARTS.join(", ")}.`);
  }
  return parts;
}

/** An origin "https://host[:port]" from a text, or null. */
export function parseOrigin(text) {
  let url;
  try {
    url = new URL(text);
  } catch {
    return null;
  }
  if (url.protocol !== "https:" && url.protocol !== "http:") return null;
  if (url.username || url.password) return null;
  return url.origin;
}

/**
 * Splits URL parameters into view options and the rest (the example's inputs
 * or unknown keys, which the page reports itself).
 * @param {Array<[string, string]>} params
 * @returns {{ options: object, entries: Array<[string, string]>, rest: Array<[string, string]>, notices: string[] }}
 *   entries: the valid options as written back into the address
 */
export function parseOptions(params) {
  const options = defaults();
  const entries = [];
  const rest = [];
  const notices = [];
  let show = null;
  const keep = (key, value) => {
    const i = entries.findIndex(([k]) => k === key);
    if (i >= 0) entries.splice(i, 1);
    entries.push([key, value]);
  };
  for (const [key, value] of params) {
    if (!OPTION_KEYS.includes(key)) {
      rest.push([key, value]);
      continue;
    }
    const v = value.trim();
    const bad = (expected) => notices.push(`Ignored the option ${key}=${quote(v)}: ${expected}.`);
    switch (key) {
      case "theme":
        if (THEMES.includes(v.toLowerCase())) {
          options.theme = v.toLowerCase();
          keep(key, options.theme);
        } else bad("use auto, light or dark");
        break;
      case "show":
      case "hide": {
        const parts = partList(key, v, notices);
        if (key === "show") show = parts.length ? parts : show;
        else options.hide = parts;
        if (parts.length) keep(key, parts.join(","));
        break;
      }
      case "steps":
        if (v === "open" || v === "collapsed") {
          options.steps = v;
          keep(key, v);
        } else bad("use open or collapsed");
        break;
      case "lock":
        if (["true", "1", "yes", ""].includes(v.toLowerCase())) {
          options.lock = true;
          keep(key, "true");
        } else if (["false", "0", "no"].includes(v.toLowerCase())) {
          options.lock = false;
        } else bad("use true or false");
        break;
      case "step":
        if (/^\d{1,4}$/.test(v) && Number(v) >= 1 && Number(v) <= MAX_STEP) {
          options.step = Number(v);
          keep(key, String(options.step));
        } else bad("give a step number, 1 or more");
        break;
      case "play":
        if (v.toLowerCase() === "auto") {
          options.play = { auto: true };
          keep(key, "auto");
        } else if (/^\d{1,6}$/.test(v) && Number(v) >= 1 && Number(v) <= MAX_FRAME) {
          options.play = { frame: Number(v) };
          keep(key, String(options.play.frame));
        } else bad(`give a frame number from 1 to ${MAX_FRAME} (opens paused there) or auto (plays from the first frame)`);
        break;
      case "sweep": {
        const read = parseSweep(v);
        if (read.spec) {
          options.sweep = read.spec;
          keep(key, v);
        } else bad(read.error);
        break;
      }
      case "grid": {
        const read = parseGrid(v);
        if (read.spec) {
          options.grid = read.spec;
          keep(key, v);
        } else bad(read.error);
        break;
      }
      case "plot": {
        const read = parsePlot(v);
        if (read.keys) {
          options.plot = read.keys;
          keep(key, read.keys.join(","));
        } else bad(read.error);
        break;
      }
      case "host": {
        const origin = parseOrigin(v);
        if (origin) {
          options.host = origin;
          keep(key, origin);
        } else bad("give the embedding page's origin, such as https://course.example.org");
        break;
      }
      case "id":
        if (/^[A-Za-z0-9_.:-]{1,64}$/.test(v)) {
          options.id = v;
          keep(key, v);
        } else bad("use up to 64 letters, digits, _ . : or -");
        break;
      default:
        rest.push([key, value]);
    }
  }
  if (show) options.hide = [...new Set([...options.hide, ...PARTS.filter((p) => !show.includes(p))])];
  return { options, entries, rest, notices };
}
