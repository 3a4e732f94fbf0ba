// Shared look and drawing helpers for the figure modules. All sizes are CSS
// pixels: the canvas context is already scaled for the device pixel ratio.

export const FONT_FAMILY = 'system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, sans-serif';
export const FONT_SIZE = 13;
export const FONT_SIZE_SMALL = 11.5;
export const LINE_HEIGHT = 1.3;

/** One palette for every figure (contrast ≥ 4.5:1 on white for the text colours). */
export const COLORS = Object.freeze({
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
  halo: "rgba(255, 255, 255, 0.88)",
});

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
