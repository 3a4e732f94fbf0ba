// Shared look and drawing helpers for the figure modules. All sizes are CSS
// pixels: the canvas context is already scaled for the device pixel ratio.

import { formatNumber } from "../format.js";
import { GREY_WORDS, SIGNED_NEGATIVE, SIGNED_POSITIVE, rgbText } from "../colour-scales.js";
import { testData } from "../test-hooks.js";

export const FONT_FAMILY = 'system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, sans-serif';
export const FONT_SIZE = 13;
export const FONT_SIZE_SMALL = 11.5;
export const LINE_HEIGHT = 1.3;

/**
 * The figures' palettes: a light "paper" and a dark one for the dark theme
 * (contrast ≥ 4.5:1 on its background for the text colours). `COLORS` holds
 * the one in use: figures read it while they draw, and the plumbing
 * (index.js) switches it with usePalette before each drawing. Image greys do
 * not change with the theme (greyScale: dark = low in both).
 */
export const PALETTES = Object.freeze({
  light: Object.freeze({
    background: "#ffffff",
    ink: "#1b1f24",
    muted: "#57606a",
    grid: "#d0d7de",
    frameFill: "#eef3f9",
    frameStroke: "#3d4a5c",
    pixelSystem: "#1d5fbf", // pixel coordinates (c, r): blue
    imageSystem: "#b3400a", // image coordinates (x, y): orange-brown
    point: "#8f1d8f", // the point p
    ray: "#4a5361",
    highlight: "#d97706",
    highlightFill: "rgba(217, 119, 6, 0.28)",
    ground: "#6b4f2a",
    green: "#2f7d32",
    red: "#c62828",
    noValue: "#eceff2", // a cell without a value
    halo: "rgba(255, 255, 255, 0.88)",
  }),
  dark: Object.freeze({
    background: "#10151c",
    ink: "#e6edf3",
    muted: "#a3adb8",
    grid: "#3d444d",
    frameFill: "#1a2636",
    frameStroke: "#a9b8ca",
    pixelSystem: "#79b8ff",
    imageSystem: "#ff9a5c",
    point: "#e59be5",
    ray: "#a3adb8",
    highlight: "#f5a524",
    highlightFill: "rgba(245, 165, 36, 0.26)",
    ground: "#c9a36b",
    green: "#6fdd8b",
    red: "#ff8a80",
    noValue: "#2a313a",
    halo: "rgba(16, 21, 28, 0.86)",
  }),
});

/** The palette in use (a copy of one of PALETTES, switched by usePalette). */
export const COLORS = { ...PALETTES.light, theme: "light" };

/** Switches COLORS to the "light" or "dark" palette; returns the name in use. */
export function usePalette(name) {
  const theme = name === "dark" ? "dark" : "light";
  Object.assign(COLORS, PALETTES[theme], { theme });
  return theme;
}

/**
 * The page's theme: <html data-theme="dark|light"> (the theme switch or the
 * address's theme option), else the reader's system setting.
 */
export function pageTheme(doc = globalThis.document) {
  const set = doc?.documentElement?.getAttribute("data-theme");
  if (set === "dark" || set === "light") return set;
  return globalThis.matchMedia?.("(prefers-color-scheme: dark)").matches ? "dark" : "light";
}

export const ARROW_HEAD = 8; // length of an arrow head
export const DASH = Object.freeze([5, 4]);
export const DOTS = Object.freeze([2, 3]);
export const LABEL_PAD = 3; // padding of a text's halo box

/** A CSS font string. */
export function font(size = FONT_SIZE, weight = "normal", style = "normal") {
  return `${style} ${weight} ${size}px ${FONT_FAMILY}`;
}

export function line(ctx, x0, y0, x1, y1, { color = COLORS.ink, width = 1, dash = null } = {}) {
  ctx.save();
  ctx.strokeStyle = color;
  ctx.lineWidth = width;
  ctx.setLineDash(dash ? [...dash] : []);
  ctx.beginPath();
  ctx.moveTo(x0, y0);
  ctx.lineTo(x1, y1);
  ctx.stroke();
  ctx.restore();
}

function head(ctx, x0, y0, x1, y1, size) {
  const a = Math.atan2(y1 - y0, x1 - x0);
  const spread = Math.PI / 7;
  ctx.beginPath();
  ctx.moveTo(x1, y1);
  ctx.lineTo(x1 - size * Math.cos(a - spread), y1 - size * Math.sin(a - spread));
  ctx.lineTo(x1 - size * Math.cos(a + spread), y1 - size * Math.sin(a + spread));
  ctx.closePath();
  ctx.fill();
}

/** A line from (x0, y0) with an arrow head at (x1, y1); `both` puts one at each end. */
export function arrow(ctx, x0, y0, x1, y1, { color = COLORS.ink, width = 1.5, size = ARROW_HEAD, both = false } = {}) {
  ctx.save();
  ctx.strokeStyle = color;
  ctx.fillStyle = color;
  ctx.lineWidth = width;
  ctx.setLineDash([]);
  ctx.beginPath();
  ctx.moveTo(x0, y0);
  ctx.lineTo(x1, y1);
  ctx.stroke();
  head(ctx, x0, y0, x1, y1, size);
  if (both) head(ctx, x1, y1, x0, y0, size);
  ctx.restore();
}

/** A circle's outline (a ring round a point). */
export function ring(ctx, x, y, r, color, width = 1.5) {
  ctx.save();
  ctx.strokeStyle = color;
  ctx.lineWidth = width;
  ctx.beginPath();
  ctx.arc(x, y, r, 0, 2 * Math.PI);
  ctx.stroke();
  ctx.restore();
}

export function dot(ctx, x, y, r, color) {
  ctx.save();
  ctx.fillStyle = color;
  ctx.beginPath();
  ctx.arc(x, y, r, 0, 2 * Math.PI);
  ctx.fill();
  ctx.restore();
}

/** Width of a text in the given font. */
export function measure(ctx, str, fontString = font()) {
  ctx.save();
  ctx.font = fontString;
  const w = ctx.measureText(str).width;
  ctx.restore();
  return w;
}

let scratch = null;
/** Width of a text without a visible canvas (for layouts computed before drawing). */
export function textWidth(str, size = FONT_SIZE, weight = "normal") {
  scratch ??= document.createElement("canvas").getContext("2d");
  scratch.font = font(size, weight);
  return scratch.measureText(str).width;
}

/** Splits `str` at spaces into lines no wider than `max` CSS px (a longer word keeps its own line). */
export function wrapWords(str, max, size = FONT_SIZE, weight = "normal") {
  const lines = [];
  let cur = "";
  for (const word of String(str).split(" ")) {
    const next = cur ? `${cur} ${word}` : word;
    if (cur && textWidth(next, size, weight) > max) {
      lines.push(cur);
      cur = word;
    } else {
      cur = next;
    }
  }
  if (cur) lines.push(cur);
  return lines;
}

/**
 * Writes one line of text; with `halo` a translucent white box behind it keeps
 * it readable over lines. Returns its box {x, y, w, h}.
 */
export function text(ctx, str, x, y, { color = COLORS.ink, size = FONT_SIZE, weight = "normal", style = "normal", align = "left", baseline = "middle", halo = false } = {}) {
  ctx.save();
  ctx.font = font(size, weight, style);
  ctx.textAlign = align;
  ctx.textBaseline = baseline;
  const w = ctx.measureText(str).width;
  const h = size * LINE_HEIGHT;
  const left = align === "center" ? x - w / 2 : align === "right" || align === "end" ? x - w : x;
  const top = baseline === "top" ? y : baseline === "bottom" || baseline === "alphabetic" ? y - h : y - h / 2;
  if (halo) {
    ctx.fillStyle = COLORS.halo;
    ctx.fillRect(left - LABEL_PAD, top - LABEL_PAD / 2, w + 2 * LABEL_PAD, h + LABEL_PAD);
  }
  ctx.fillStyle = color;
  ctx.fillText(str, x, y);
  ctx.restore();
  return { x: left, y: top, w, h };
}

/**
 * A block of lines [{ text, color, weight }] with its top-left corner at (x, y),
 * on a white box with a thin border. Returns the box.
 */
export function textBlock(ctx, lines, x, y, { size = FONT_SIZE, pad = 5, border = COLORS.grid } = {}) {
  const { w, h } = blockSize(ctx, lines, { size, pad });
  ctx.save();
  ctx.fillStyle = COLORS.halo;
  ctx.strokeStyle = border;
  ctx.lineWidth = 1;
  ctx.fillRect(x, y, w, h);
  ctx.strokeRect(x + 0.5, y + 0.5, w - 1, h - 1);
  ctx.restore();
  const lh = size * LINE_HEIGHT;
  lines.forEach((l, i) => {
    text(ctx, l.text, x + pad, y + pad + lh * i + lh / 2, { color: l.color ?? COLORS.ink, weight: l.weight ?? "normal", size });
  });
  return { x, y, w, h };
}

/** The size a textBlock would take. */
export function blockSize(ctx, lines, { size = FONT_SIZE, pad = 5 } = {}) {
  const widths = lines.map((l) => measure(ctx, l.text, font(size, l.weight ?? "normal")));
  return { w: Math.ceil(Math.max(0, ...widths) + 2 * pad), h: Math.ceil(lines.length * size * LINE_HEIGHT + 2 * pad) };
}

/** Whether two boxes {x, y, w, h} overlap. */
export function overlaps(a, b) {
  return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

/** Whether box a lies inside box b. */
export function inside(a, b) {
  return a.x >= b.x && a.y >= b.y && a.x + a.w <= b.x + b.w && a.y + a.h <= b.y + b.h;
}

/** A finite number or the fallback. */
export function finite(value, fallback = 0) {
  return typeof value === "number" && Number.isFinite(value) ? value : fallback;
}

// ---------------------------------------------------------------------------
// Grey scales: one convention for every figure that maps numbers to greys,
// an image's: dark = low, light = high, in both themes. A scale stretches
// [lo, hi] over GREY_LEVELS (not quite black nor white, so a number stays
// readable on every cell: `ink(v)` is the colour to write it in); the test
// pattern's absolute 0…255 uses levels [0, 255]. Every scale drawn gets a
// legend (greyLegend): a small ramp between its low and high values, and
// "dark = low". The scales are recorded on the canvas (`canvas.greyScales`,
// and, under the tests (test-hooks.js), as JSON in its `data-grey-scales`: { name, lo, hi, text, legend: box,
// low, high: the lowest and highest valued cells drawn, {x, y, w, h, v} })
// for the tests and for the figure's accessible label (index.js).

/** Grey levels (0–255) of a stretched scale's low and high ends. */
export const GREY_LEVELS = Object.freeze([60, 245]);
/** Legend geometry (CSS px): the ramp's width, the legend's height. */
export const GREY_LEGEND = Object.freeze({ ramp: 44, height: 16, gap: 5 });
const INK_ON_LIGHT = "#1b1f24";
const INK_ON_DARK = "#ffffff";

/**
 * The grey scale for values in [lo, hi]; `name` says what it shades (the
 * legend's label), `levels` its [dark, light] grey levels, `format` writes
 * the legend's numbers.
 */
export function greyScale(lo, hi, { name = "grey value", levels = GREY_LEVELS, format = (v) => formatNumber(v, 4) } = {}) {
  const ok = Number.isFinite(lo) && Number.isFinite(hi);
  const low = ok ? Math.min(lo, hi) : 0;
  const high = ok ? Math.max(lo, hi) : 1;
  const [dark, light] = levels;
  const level = (v) => {
    const t = high > low ? (v - low) / (high - low) : 0.5;
    return Math.round(dark + (light - dark) * Math.min(1, Math.max(0, Number.isFinite(t) ? t : 0.5)));
  };
  return {
    name,
    lo: low,
    hi: high,
    levels,
    format,
    low: null,
    high: null,
    level,
    rgb: (v) => {
      const g = level(v);
      return [g, g, g];
    },
    fill: (v) => {
      const g = level(v);
      return `rgb(${g}, ${g}, ${g})`;
    },
    /** The colour of a number written on a cell of value v. */
    ink: (v) => (level(v) < 150 ? INK_ON_DARK : INK_ON_LIGHT),
    /** Records a cell of value v drawn at (x, y, w, h) (the lowest and highest are kept). */
    note(v, x, y, w, h) {
      if (!Number.isFinite(v)) return;
      if (!this.low || v < this.low.v) this.low = { x, y, w, h, v };
      if (!this.high || v > this.high.v) this.high = { x, y, w, h, v };
    },
    /** Fills a cell with v's grey and records it; returns the ink for a number on it. */
    cell(ctx, v, x, y, w, h) {
      ctx.fillStyle = this.fill(v);
      ctx.fillRect(x, y, w, h);
      this.note(v, x, y, w, h);
      return this.ink(v);
    },
  };
}

/** The grey scale over the finite values of a list or matrix. */
export function greyScaleOf(values, options = {}) {
  const xs = [values].flat(Infinity).filter((v) => typeof v === "number" && Number.isFinite(v));
  return greyScale(xs.length ? Math.min(...xs) : 0, xs.length ? Math.max(...xs) : 1, options);
}

/** A scale's legend in words (the figure's accessible label gets it too). */
export function greyLegendText(scale) {
  return `${scale.name}: grey from dark (${scale.format(scale.lo)}) to light (${scale.format(scale.hi)}), ${GREY_WORDS}`;
}

function legendParts(scale, label) {
  return { head: label ? `${label}: ` : "", lo: scale.format(scale.lo), hi: scale.format(scale.hi), tail: GREY_WORDS };
}

/** The width a legend takes (greyLegend's options). */
export function greyLegendWidth(scale, { label = scale.name, size = FONT_SIZE_SMALL, ramp = GREY_LEGEND.ramp } = {}) {
  const p = legendParts(scale, label);
  const g = GREY_LEGEND.gap;
  return textWidth(p.head, size) + textWidth(p.lo, size) + g + ramp + g + textWidth(p.hi, size) + 2 * g + textWidth(p.tail, size);
}

/**
 * Draws a scale's legend on one line from (x, y) (its top-left): "label: lo
 * [ramp] hi  dark = low"; within `maxWidth` the label, then the ramp's
 * length give way. Records the scale on the canvas. Returns its box.
 */
export function greyLegend(ctx, x, y, scale, { label = scale.name, size = FONT_SIZE_SMALL, maxWidth = Infinity } = {}) {
  let head = label;
  let ramp = GREY_LEGEND.ramp;
  if (greyLegendWidth(scale, { label: head, size, ramp }) > maxWidth) head = "";
  if (greyLegendWidth(scale, { label: head, size, ramp }) > maxWidth) ramp = Math.max(16, ramp - (greyLegendWidth(scale, { label: head, size, ramp }) - maxWidth));
  const p = legendParts(scale, head);
  const g = GREY_LEGEND.gap;
  const h = GREY_LEGEND.height;
  const cy = y + h / 2;
  let at = x;
  const put = (str) => {
    if (!str) return;
    const b = text(ctx, str, at, cy, { size, color: COLORS.muted });
    at = b.x + b.w;
  };
  put(p.head);
  put(p.lo);
  at += g;
  const gradient = ctx.createLinearGradient(at, 0, at + ramp, 0);
  gradient.addColorStop(0, scale.fill(scale.lo));
  gradient.addColorStop(1, scale.fill(scale.hi));
  ctx.save();
  ctx.fillStyle = gradient;
  ctx.fillRect(at, cy - 5, ramp, 10);
  ctx.strokeStyle = COLORS.muted;
  ctx.lineWidth = 1;
  ctx.strokeRect(at + 0.5, cy - 4.5, ramp - 1, 9);
  ctx.restore();
  at += ramp + g;
  put(p.hi);
  at += 2 * g;
  put(p.tail);
  const box = { x, y, w: at - x, h };
  recordGreyScale(ctx.canvas, scale, box);
  return box;
}

function recordGreyScale(canvas, scale, legend) {
  if (!canvas) return;
  const entry = { name: scale.name, lo: scale.lo, hi: scale.hi, text: greyLegendText(scale), legend, low: scale.low, high: scale.high };
  canvas.greyScales = [...(canvas.greyScales ?? []), entry];
  testData(canvas, "greyScales", JSON.stringify(canvas.greyScales));
}

// ---------------------------------------------------------------------------
// Label placement: a figure registers its labels (each with an anchor and a
// few candidate spots, best first) and the things a label must not cover
// (dots, bars, lines, arrows, other texts); `draw()` puts each label, in the
// order added, at its first candidate that stays inside the canvas and covers
// nothing, and writes it on a halo. When every candidate collides, the one
// that covers least is taken (inside the canvas if any is); an `optional`
// label is then left out instead. A label is never put over another label:
// one that fits nowhere else is left out (its figure's text alternative and
// the text beside the figure carry every number).
// Each candidate is also tried shifted into the canvas. A figure may place
// some labels (`place()`), register more marks and add more labels: marks
// registered later do not move labels already placed.
// The boxes placed are recorded on the canvas (`canvas.labelBoxes`, and as
// JSON in its `data-label-boxes` under the tests (test-hooks.js): { text, x, y, w, h, hits }, hits = how many
// registered marks the label covers) so tests can check that none overlap.

/** Unit offsets of the compass spots ("C" = centred on the anchor). */
const COMPASS = Object.freeze({
  C: [0, 0],
  N: [0, -1],
  NE: [1, -1],
  E: [1, 0],
  SE: [1, 1],
  S: [0, 1],
  SW: [-1, 1],
  W: [-1, 0],
  NW: [-1, -1],
});

/** Whether the segment (x0, y0)–(x1, y1) passes through box b (Liang–Barsky). */
export function segmentHitsBox(x0, y0, x1, y1, b) {
  let t0 = 0;
  let t1 = 1;
  const dx = x1 - x0;
  const dy = y1 - y0;
  const clip = (p, q) => {
    if (p === 0) return q >= 0;
    const r = q / p;
    if (p < 0) {
      if (r > t1) return false;
      if (r > t0) t0 = r;
    } else {
      if (r < t0) return false;
      if (r < t1) t1 = r;
    }
    return true;
  };
  return clip(-dx, x0 - b.x) && clip(dx, b.x + b.w - x0) && clip(-dy, y0 - b.y) && clip(dy, b.y + b.h - y0) && t0 <= t1;
}

function overlapArea(a, b) {
  const w = Math.min(a.x + a.w, b.x + b.w) - Math.max(a.x, b.x);
  const h = Math.min(a.y + a.h, b.y + b.h) - Math.max(a.y, b.y);
  return w > 0 && h > 0 ? w * h : 0;
}

const grow = (b, d) => ({ x: b.x - d, y: b.y - d, w: b.w + 2 * d, h: b.h + 2 * d });

/** Resets a canvas's record of placed labels and grey scales (the figure plumbing calls it before each drawing). */
export function clearLabelBoxes(canvas) {
  if (!canvas) return;
  canvas.labelBoxes = [];
  canvas.greyScales = [];
  testData(canvas, "labelBoxes", null);
  testData(canvas, "greyScales", null);
}

function recordLabelBoxes(canvas, boxes) {
  if (!canvas || !boxes.length) return;
  canvas.labelBoxes = [...(canvas.labelBoxes ?? []), ...boxes];
  testData(canvas, "labelBoxes", JSON.stringify(canvas.labelBoxes));
}

export class Labels {
  /**
   * @param ctx the figure's context (CSS px)
   * @param width, height the canvas size in CSS px (labels stay inside it)
   * @param options.margin free space kept along the canvas edges
   */
  constructor(ctx, width, height, { margin = 1 } = {}) {
    this.ctx = ctx;
    this.bounds = { x: margin, y: margin, w: width - 2 * margin, h: height - 2 * margin };
    this.obstacles = [];
    this.items = []; // added, not placed yet
    this.placed = [];
    this.drawn = 0; // how many of the placed ones are drawn
  }

  /** A copy with the same obstacles and labels (to try a placement without committing to it). */
  copy() {
    const c = new Labels(this.ctx, 0, 0);
    c.bounds = { ...this.bounds };
    c.obstacles = [...this.obstacles];
    c.items = [...this.items];
    c.placed = [...this.placed];
    c.drawn = this.drawn;
    return c;
  }

  /** A box {x, y, w, h} no label may cover (e.g. text() or textBlock()'s return value). */
  avoid(box, pad = 0) {
    if (box && [box.x, box.y, box.w, box.h].every(Number.isFinite)) this.obstacles.push({ box: grow(box, pad) });
    return this;
  }

  /** A rectangle given by its corner and size. */
  avoidRect(x, y, w, h, pad = 0) {
    return this.avoid({ x: Math.min(x, x + w), y: Math.min(y, y + h), w: Math.abs(w), h: Math.abs(h) }, pad);
  }

  /** A dot (or ring) of radius r, plus pad. */
  avoidDot(x, y, r, pad = 1) {
    if ([x, y, r].every(Number.isFinite)) this.obstacles.push({ circle: [x, y, r + pad] });
    return this;
  }

  /**
   * A line of the given half-width; `tag` names it for labels that may cover
   * it (their `ignore`), e.g. the arrow a digit belongs to.
   */
  avoidLine(x0, y0, x1, y1, halfWidth = 1.5, tag = null) {
    if ([x0, y0, x1, y1].every(Number.isFinite)) this.obstacles.push({ seg: [x0, y0, x1, y1], pad: halfWidth, tag });
    return this;
  }

  /** An arrow drawn by arrow(): its shaft and, at (x1, y1), its head. */
  avoidArrow(x0, y0, x1, y1, { width = 1.5, size = ARROW_HEAD, tag = null } = {}) {
    this.avoidLine(x0, y0, x1, y1, width / 2 + 0.5, tag);
    const len = Math.hypot(x1 - x0, y1 - y0) || 1;
    const hx = x1 - ((x1 - x0) / len) * size * 0.55;
    const hy = y1 - ((y1 - y0) / len) * size * 0.55;
    if ([hx, hy].every(Number.isFinite)) this.obstacles.push({ circle: [hx, hy, size * 0.55], tag });
    return this;
  }

  /** A polyline [[x, y], …]; `closed` joins the last point to the first. */
  avoidPath(points, halfWidth = 1.5, closed = false) {
    for (let i = 0; i + 1 < points.length; i++) this.avoidLine(...points[i], ...points[i + 1], halfWidth);
    if (closed && points.length > 2) this.avoidLine(...points[points.length - 1], ...points[0], halfWidth);
    return this;
  }

  /**
   * A label at anchor (x, y). Options: color, size, weight, style, halo (true);
   * `candidates`: compass spots ("NE", "S", …, "C") or objects { at, dx, dy } —
   * the spot plus an offset — or { cx, cy } (the label's centre), tried in order;
   * `gap`: the distance of a compass spot from the anchor; `farther`: also try
   * the compass spots this much farther out (after all the others); `along`: [x0, y0, x1, y1],
   * a line the label should sit beside (spots on both sides, from its middle out,
   * tried after `candidates`); `optional`: leave it out rather than cover something;
   * `shorter`: shorter forms of the text (strings, or { text, size } for a
   * smaller size too), tried (at every spot) when the text itself fits nowhere; `within`: a box it must stay in (default the canvas); `pad`: the halo's
   * margin beside the text (LABEL_PAD; half of it above and below); `ignore`:
   * the tag of lines it may cover.
   */
  add(str, x, y, options = {}) {
    this.items.push({ str: String(str), x, y, ...options });
    return this;
  }

  /** The box of a label of size (w, h) at a candidate spot. */
  static spot(c, x, y, w, h, gap) {
    if (typeof c === "object" && Number.isFinite(c.cx)) return { x: c.cx - w / 2, y: c.cy - h / 2, w, h };
    const name = typeof c === "string" ? c : c.at ?? "C";
    const [ux, uy] = COMPASS[name] ?? [0, 0];
    const g = ux && uy ? gap * 0.75 : gap;
    let cx = x + ux * (g + w / 2);
    let cy = y + uy * (g + h / 2);
    if (typeof c === "object") {
      cx += c.dx ?? 0;
      cy += c.dy ?? 0;
    }
    return { x: cx - w / 2, y: cy - h / 2, w, h };
  }

  /**
   * Spots beside a line: its middle first, then out towards its ends, either
   * side, then a little farther out, then beyond its ends.
   */
  static along([x0, y0, x1, y1], w, h, gap) {
    const len = Math.hypot(x1 - x0, y1 - y0) || 1;
    const ux = (x1 - x0) / len;
    const uy = (y1 - y0) / len;
    const nx = -uy;
    const ny = ux;
    // distance of a box's centre from the line so that the box just clears it
    const d = (w / 2) * Math.abs(nx) + (h / 2) * Math.abs(ny) + gap;
    const out = [];
    const box = (cx, cy) => ({ x: cx - w / 2, y: cy - h / 2, w, h });
    const e = (w / 2) * Math.abs(ux) + (h / 2) * Math.abs(uy) + gap;
    for (const far of [0, h, 2 * h]) {
      for (const t of [0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8, 0.1, 0.9, 0, 1]) {
        for (const side of [-1, 1]) out.push(box(x0 + (x1 - x0) * t + side * nx * (d + far), y0 + (y1 - y0) * t + side * ny * (d + far)));
      }
      // beyond either end, on the line's extension
      out.push(box(x1 + ux * (e + far), y1 + uy * (e + far)), box(x0 - ux * (e + far), y0 - uy * (e + far)));
    }
    return out;
  }

  /** How many obstacles box b covers (but those tagged `ignore`), and how much of the box ones. */
  cost(b, ignore = null) {
    let hits = 0;
    let area = 0;
    for (const o of this.obstacles) {
      if (ignore !== null && o.tag === ignore) continue;
      if (o.box) {
        const a = overlapArea(b, o.box);
        if (a > 0) {
          hits += 1;
          area += a;
        }
      } else if (o.circle) {
        const [cx, cy, r] = o.circle;
        const dx = cx - Math.min(Math.max(cx, b.x), b.x + b.w);
        const dy = cy - Math.min(Math.max(cy, b.y), b.y + b.h);
        if (dx * dx + dy * dy < r * r) {
          hits += 1;
          area += 4;
        }
      } else if (segmentHitsBox(...o.seg, grow(b, o.pad))) {
        hits += 1;
        area += 4;
      }
    }
    return { hits, area };
  }

  /**
   * Places the labels added since the last call (without drawing them); they
   * then count as obstacles for labels added later — so a figure can place
   * some labels, add more obstacles, and place others. Returns the labels
   * placed so far: [{ str, box, hits, …options }].
   */
  place() {
    const placed = this.placed;
    for (const item of this.items.splice(0)) {
      const pad = item.pad ?? LABEL_PAD;
      const gap = item.gap ?? 4;
      const within = item.within ?? this.bounds;
      let best = null;
      // the text, then its shorter (or smaller) forms, each at every spot
      const forms = [item.str, ...(item.shorter ?? [])].map((v) => (typeof v === "string" ? { text: v } : v));
      for (const form of forms) {
        const str = form.text;
        const size = form.size ?? item.size ?? FONT_SIZE;
        const f = font(size, item.weight ?? "normal", item.style ?? "normal");
        const h = size * LINE_HEIGHT + pad;
        const w = measure(this.ctx, str, f) + 2 * pad;
        const spots = item.candidates ?? (item.along ? [] : ["C"]);
        // with `farther`, the compass spots again, that much farther out
        const far = item.farther
          ? spots
              .map((c) => (typeof c === "string" ? { at: c } : c))
              .filter((c) => c.at && c.at !== "C")
              .map((c) => ({ ...c, dx: (c.dx ?? 0) + COMPASS[c.at][0] * item.farther, dy: (c.dy ?? 0) + COMPASS[c.at][1] * item.farther }))
          : [];
        const boxes = [...spots, ...far].map((c) => Labels.spot(c, item.x, item.y, w, h, gap));
        if (item.along) boxes.push(...Labels.along(item.along, w, h, gap));
        // the same spots shifted into the canvas, for labels near its edges
        const shifted = boxes.map((b) => ({
          ...b,
          x: Math.min(Math.max(b.x, within.x), within.x + within.w - b.w),
          y: Math.min(Math.max(b.y, within.y), within.y + within.h - b.h),
        }));
        for (const b of [...boxes, ...shifted]) {
          const out = !inside(b, within);
          const onLabel = placed.some((p) => overlaps(p.box, b));
          const { hits, area } = this.cost(b, item.ignore ?? null);
          const score = (out ? 1e9 : 0) + (onLabel ? 1e7 : 0) + hits * 1e4 + area;
          if (!best || score < best.score) best = { box: b, str, size, score, hits, out, onLabel };
          if (score === 0) break;
        }
        if (best.score === 0) break;
      }
      // never over another label: one that fits nowhere else is left out
      if (!best || best.onLabel || ((best.out || best.hits) && item.optional)) continue;
      const p = { ...item, str: best.str, size: best.size, box: best.box, hits: best.hits };
      placed.push(p);
      this.obstacles.push({ box: best.box });
    }
    return placed;
  }

  /** Places and draws every label not drawn yet; returns the placed labels. */
  draw() {
    const placed = this.place().slice(this.drawn);
    this.drawn = this.placed.length;
    for (const p of placed) {
      const { box } = p;
      const size = p.size ?? FONT_SIZE;
      // a label put farther from its line than beside it gets a dotted leader to it
      if (p.along) {
        const [x0, y0, x1, y1] = p.along;
        const bx = box.x + box.w / 2;
        const by = box.y + box.h / 2;
        const len2 = (x1 - x0) ** 2 + (y1 - y0) ** 2 || 1;
        const t = Math.min(1, Math.max(0, ((bx - x0) * (x1 - x0) + (by - y0) * (y1 - y0)) / len2));
        const [px, py] = [x0 + t * (x1 - x0), y0 + t * (y1 - y0)];
        const [qx, qy] = [Math.min(Math.max(px, box.x), box.x + box.w), Math.min(Math.max(py, box.y), box.y + box.h)];
        if (Math.hypot(px - qx, py - qy) > (p.gap ?? 4) + 6) line(this.ctx, qx, qy, px, py, { color: p.color ?? COLORS.ink, width: 1, dash: DOTS });
      }
      if (p.halo !== false) {
        this.ctx.save();
        this.ctx.fillStyle = COLORS.halo;
        this.ctx.fillRect(box.x, box.y, box.w, box.h);
        this.ctx.restore();
      }
      text(this.ctx, p.str, box.x + box.w / 2, box.y + box.h / 2, { color: p.color ?? COLORS.ink, size, weight: p.weight ?? "normal", style: p.style ?? "normal", align: "center" });
    }
    recordLabelBoxes(
      this.ctx.canvas,
      placed.map((p) => ({ text: p.str, x: p.box.x, y: p.box.y, w: p.box.w, h: p.box.h, hits: p.hits })),
    );
    return this.placed;
  }
}

/** A number in a figure: `digits` significant digits, `none` for anything that is not a finite number. */
export function fmt(v, digits = 4, none = "—") {
  return typeof v === "number" && Number.isFinite(v) ? formatNumber(v, digits) : none;
}

// ---------------------------------------------------------------------------
// Figure specs and keys

/**
 * A figure spec for the registry (index.js) whose canvas is laid out from
 * the solution's data: `data(solution)` (null when there is nothing to
 * draw), `layout(width, d)` (with its `height`) and `draw(ctx, width, d)`;
 * the other members (caption, describe, interact, …) are the spec's own.
 */
export function layoutSpec({ data, layout, draw, ...rest }) {
  return {
    ...rest,
    height(width, solution) {
      const d = data(solution);
      return d ? layout(width, d).height : 120;
    },
    draw(ctx, width, height, solution) {
      const d = data(solution);
      if (d) draw(ctx, width, d);
    },
  };
}

const ARROW_STEPS = Object.freeze({ ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] });

/** The step `[dc, dr]` of an arrow key (rows count downward), or null for any other key. */
export function arrowStep(key) {
  return Object.hasOwn(ARROW_STEPS, key) ? ARROW_STEPS[key] : null;
}

// ---------------------------------------------------------------------------
// Grids of numbers: shaded cells with their values (filters, resampling, matching)

/** Layout of grids of numbers (CSS px): the filter and resampling figures. */
export const GRID = Object.freeze({
  margin: 14,
  gap: 22, // between panels
  title: 22, // room for a panel title above a grid
  axis: 16, // room for the column/row numbers
  maxCell: 54,
  minCell: 14,
  numbersFrom: 20, // below this cell size the numbers are left out
  weightFrom: 40, // below this the kernel weights in the window's cells are left out
  sumGap: 12,
  legendLine: GREY_LEGEND.height + 4, // below the sum, one line for each colour legend
  maxHeight: 900, // the figure registry's largest canvas height
  comfortable: 44, // the first arrangement (fewest rows) whose cells are this large is taken,
  readable: 34, // else the first with cells this large, else one panel per row
});
/** Significant digits in the grids. */
const GRID_DIGITS = 4;
/** Strongest shade of a grid cell (alpha). */
const MAX_ALPHA = 0.5;
/** Diverging scale colours: below and above zero. */
const NEGATIVE = rgbText(SIGNED_NEGATIVE);
const POSITIVE = rgbText(SIGNED_POSITIVE);

/** Whether a matrix has a negative value (it is then shaded on the diverging scale). */
export const signedMatrix = (m) => m.flat().some((v) => Number.isFinite(v) && v < 0);

/**
 * A shading function for a matrix: diverging (blue < 0 < orange) when it has
 * a negative value, else the shared grey scale (draw.js: dark = low, as in an
 * image; `scale` records the cells for its legend), named `name`.
 */
export function shader(m, name = "grey value") {
  const flat = m.flat().filter(Number.isFinite);
  if (signedMatrix(m)) {
    const max = Math.max(...flat.map(Math.abs)) || 1;
    return { signed: true, fill: (v) => `rgba(${v < 0 ? NEGATIVE : POSITIVE}, ${(MAX_ALPHA * Math.abs(v)) / max})` };
  }
  const scale = greyScaleOf(flat, { name, format: (v) => fmt(v) });
  return { signed: false, fill: scale.fill, ink: scale.ink, scale };
}

/** No shading (a kernel's weights are not grey values). */
export const PLAIN_SHADE = Object.freeze({ signed: false, fill: () => COLORS.background });

/**
 * A grid of numbers with its top-left at (x0, y0): shaded cells (`shade`:
 * { fill(v), ink(v)?, scale? }, a grey or a signed scale by default), thin
 * lines (`lines`), the numbers where a cell is `numbersFrom` px or more,
 * optional column/row numbers (`first` = the number of the first column/row,
 * null for none). Returns its geometry.
 */
export function drawGrid(
  ctx,
  m,
  x0,
  y0,
  cell,
  { title = null, first = null, shade = shader(m), digits = cell >= GRID.comfortable ? GRID_DIGITS : GRID_DIGITS - 1, muted = null, valueDy = 0, numbersFrom = GRID.numbersFrom, lines = true } = {},
) {
  const rows = m.length;
  const cols = m[0].length;
  const texts = []; // the boxes of the numbers written (for label placement)
  if (title) texts.push(text(ctx, title, x0, y0 - GRID.title / 2 - GRID.axis, { weight: "bold", size: FONT_SIZE }));
  for (let r = 0; r < rows; r++) {
    for (let c = 0; c < cols; c++) {
      const v = m[r][c];
      ctx.fillStyle = Number.isFinite(v) ? shade.fill(v) : COLORS.background;
      ctx.fillRect(x0 + c * cell, y0 + r * cell, cell, cell);
      shade.scale?.note(v, x0 + c * cell, y0 + r * cell, cell, cell);
      if (cell >= numbersFrom && Number.isFinite(v)) {
        const size = cell < 30 ? 9.5 : cell < 40 ? FONT_SIZE_SMALL : FONT_SIZE;
        texts.push(
          text(ctx, fmt(v, digits), x0 + (c + 0.5) * cell, y0 + (r + 0.5 + valueDy) * cell, {
            align: "center",
            size,
            color: muted && muted(c, r) ? COLORS.muted : shade.ink ? shade.ink(v) : COLORS.ink,
          }),
        );
      }
    }
  }
  if (lines) {
    for (let i = 0; i <= rows; i++) line(ctx, x0, y0 + i * cell, x0 + cols * cell, y0 + i * cell, { color: COLORS.grid });
    for (let i = 0; i <= cols; i++) line(ctx, x0 + i * cell, y0, x0 + i * cell, y0 + rows * cell, { color: COLORS.grid });
  }
  if (first) {
    const step = Math.max(1, Math.ceil(28 / cell));
    for (let c = 0; c < cols; c += step) {
      texts.push(text(ctx, String(first.c + c), x0 + (c + 0.5) * cell, y0 - GRID.axis / 2, { align: "center", size: 10, color: COLORS.muted }));
    }
    for (let r = 0; r < rows; r += step) {
      texts.push(text(ctx, String(first.r + r), x0 - 4, y0 + (r + 0.5) * cell, { align: "right", size: 10, color: COLORS.muted }));
    }
  }
  return { x0, y0, cell, rows, cols, w: cols * cell, h: rows * cell, texts };
}

/** Outlines cells [c, c+w) × [r, r+h) of a grid. */
export function outline(ctx, g, c, r, w, h, { color = COLORS.highlight, width = 2.5, dash = null, fill = null } = {}) {
  ctx.save();
  if (fill) {
    ctx.fillStyle = fill;
    ctx.fillRect(g.x0 + c * g.cell, g.y0 + r * g.cell, w * g.cell, h * g.cell);
  }
  ctx.strokeStyle = color;
  ctx.lineWidth = width;
  ctx.setLineDash(dash ? [...dash] : []);
  ctx.strokeRect(g.x0 + c * g.cell, g.y0 + r * g.cell, w * g.cell, h * g.cell);
  ctx.restore();
}

/** The cell of grid `g` under (x, y), or null. */
export function cellAt(g, x, y) {
  if (!g) return null;
  const c = Math.floor((x - g.x0) / g.cell);
  const r = Math.floor((y - g.y0) / g.cell);
  return c >= 0 && r >= 0 && c < g.cols && r < g.rows ? { c, r } : null;
}

/** The colour legend of the diverging scale; (x, y) its left end, vertically centred. */
export function signedLegend(ctx, x, y) {
  const sw = 12;
  ctx.fillStyle = `rgba(${NEGATIVE}, ${MAX_ALPHA})`;
  ctx.fillRect(x, y - sw / 2, sw, sw);
  let b = text(ctx, "below 0", x + sw + 4, y, { size: FONT_SIZE_SMALL, color: COLORS.muted });
  const x2 = b.x + b.w + 12;
  ctx.fillStyle = `rgba(${POSITIVE}, ${MAX_ALPHA})`;
  ctx.fillRect(x2, y - sw / 2, sw, sw);
  text(ctx, "above 0", x2 + sw + 4, y, { size: FONT_SIZE_SMALL, color: COLORS.muted });
}
