// Figures of the "Coordinates" topic (seed 000, Examples 1–3):
//   pixel-to-photo, photo-to-pixel: the image frame to scale with both
//     coordinate systems and the point p;
//   gsd: a side view of the camera (not to scale) with one pixel and its
//     ground footprint.

import { seriesTable } from "./data-view.js";
import { formatNumber } from "../format.js";
import {
  arrow,
  blockSize,
  COLORS,
  DASH,
  dot,
  DOTS,
  finite,
  FONT_SIZE,
  FONT_SIZE_SMALL,
  inside,
  line,
  LINE_HEIGHT,
  overlaps,
  ring,
  text,
  textBlock,
  textWidth,
} from "./draw.js";

const MM_PER_INCH = 25.4;

// ---------------------------------------------------------------------------
// The image frame: pixel (c, r) and image (x, y) coordinate systems

const FRAME = Object.freeze({
  margin: { left: 28, right: 28, top: 40, bottom: 34 }, // at least; widened to fit the labels
  axisOverhang: 22, // how far the axis arrows reach past the frame
  axisNameGap: 4, // between an arrow tip and the axis name
  tick: 5, // tick mark length
  labelGap: 8, // gap between a marker and its label
  pointRadius: 4.5,
  centreRadius: 5,
  outsidePad: 0.05, // extra view around a point outside the frame, fraction of the frame size
  maxHeightPerWidth: 1.3, // a tall frame is drawn smaller rather than taller than this
  maxHeight: 560,
});

/** Axis names ("c (px)") are a little smaller than the other labels. */
const AXIS_NAME_SIZE = 12;
/** Digits in the figure labels. */
const PX_DIGITS = 6;
const MM_DIGITS = 5;
const MM_TICK_DIGITS = 4;
/** Farther vertical distances tried for a label that would cover another one. */
const LABEL_STEPS = [0, 14, 28];
/** Space kept between a label and the canvas edge. */
const LABEL_ROOM = 6;

/** A marked span (a pixel on the image plane, its footprint on the ground): a highlighted bar 10 px high centred on (cx, y). */
function markedSpan(ctx, cx, y, half) {
  ctx.save();
  ctx.fillStyle = COLORS.highlightFill;
  ctx.strokeStyle = COLORS.highlight;
  ctx.lineWidth = 1.5;
  ctx.fillRect(cx - half, y - 5, 2 * half, 10);
  ctx.strokeRect(cx - half, y - 5, 2 * half, 10);
  ctx.restore();
}

/** The numbers a frame figure needs, from either example's solution. */
function frameData(solution, id) {
  const inp = solution.inputs ?? {};
  const res = solution.result ?? {};
  const columns = finite(inp.columns, 1);
  const rows = finite(inp.rows, 1);
  const p = finite(res.pixel_size_mm, MM_PER_INCH / finite(inp.dpi, MM_PER_INCH));
  const c0 = finite(res.c0, columns / 2);
  const r0 = finite(res.r0, rows / 2);
  let c;
  let r;
  let x;
  let y;
  if (id === "pixel-to-photo") {
    c = finite(inp.c);
    r = finite(inp.r);
    x = finite(res.x_mm, (c - c0) * p);
    y = finite(res.y_mm, -(r - r0) * p);
  } else {
    x = finite(inp.x_mm);
    y = finite(inp.y_mm);
    c = finite(res.c, c0 + x / p);
    r = finite(res.r, r0 - y / p);
  }
  const outside = c < 0 || c > columns || r < 0 || r > rows;
  return { columns, rows, p, c0, r0, c, r, x, y, outside };
}

/** Margins wide enough for the tick labels left of the frame and the axis names right of it. */
function frameMargins(d) {
  const tickW = (v, digits) => textWidth(formatNumber(v, digits), FONT_SIZE_SMALL);
  const halfW = (d.columns / 2) * d.p;
  const left = Math.max(tickW(-halfW, MM_TICK_DIGITS), tickW(d.rows, PX_DIGITS) + FRAME.tick) + LABEL_ROOM;
  const names = Math.max(textWidth("x (mm)", AXIS_NAME_SIZE, "bold"), textWidth("c (px)", AXIS_NAME_SIZE, "bold"));
  const right = Math.max(FRAME.axisOverhang + FRAME.axisNameGap + names, tickW(halfW, MM_TICK_DIGITS)) + LABEL_ROOM;
  const m = FRAME.margin;
  return { left: Math.max(m.left, Math.ceil(left)), right: Math.max(m.right, Math.ceil(right)), top: m.top, bottom: m.bottom };
}

/** Where the frame goes on a canvas of the given width (and height, if fixed). */
function frameLayout(d, width, height = null) {
  const m = frameMargins(d);
  const padC = d.outside ? FRAME.outsidePad * Math.max(d.columns, d.rows) : 0;
  const cMin = Math.min(0, d.c - (d.c < 0 ? padC : 0));
  const cMax = Math.max(d.columns, d.c + (d.c > d.columns ? padC : 0));
  const rMin = Math.min(0, d.r - (d.r < 0 ? padC : 0));
  const rMax = Math.max(d.rows, d.r + (d.r > d.rows ? padC : 0));
  const spanC = Math.max(cMax - cMin, 1e-9);
  const spanR = Math.max(rMax - rMin, 1e-9);
  const availW = Math.max(width - m.left - m.right, 10);
  let s = availW / spanC;
  const maxH = Math.min(FRAME.maxHeight, width * FRAME.maxHeightPerWidth);
  let h = m.top + m.bottom + spanR * s;
  if (h > maxH) {
    h = maxH;
    s = (maxH - m.top - m.bottom) / spanR;
  }
  if (height !== null) {
    s = Math.min(s, Math.max(height - m.top - m.bottom, 10) / spanR);
    h = height;
  }
  const ox = m.left + (availW - spanC * s) / 2;
  const oy = m.top;
  return {
    height: h,
    X: (c) => ox + (c - cMin) * s,
    Y: (r) => oy + (r - rMin) * s,
  };
}

/** The first candidate box that fits the canvas and avoids the obstacles (or the least bad one). */
function place(candidates, bounds, obstacles) {
  let best = null;
  let bestScore = Infinity;
  for (const box of candidates) {
    const score = (inside(box, bounds) ? 0 : 10) + obstacles.filter((o) => overlaps(box, o)).length;
    if (score < bestScore) {
      best = box;
      bestScore = score;
    }
    if (score === 0) break;
  }
  // last resort: keep it on the canvas
  best.x = Math.min(Math.max(best.x, bounds.x), bounds.x + bounds.w - best.w);
  best.y = Math.min(Math.max(best.y, bounds.y), bounds.y + bounds.h - best.h);
  return best;
}

/**
 * Boxes of size w×h in the four quadrants around (x, y), the quadrant (sx, sy)
 * first, each also a little farther away vertically (to clear tick labels).
 */
function quadrants(x, y, w, h, gap, sx, sy) {
  const order = [
    [sx, sy],
    [sx, -sy],
    [-sx, sy],
    [-sx, -sy],
  ];
  const boxes = [];
  for (const extra of LABEL_STEPS) {
    for (const [qx, qy] of order) {
      boxes.push({
        x: qx >= 0 ? x + gap : x - gap - w,
        y: qy >= 0 ? y + gap + extra : y - gap - h - extra,
        w,
        h,
      });
    }
  }
  return boxes;
}

function drawFrame(ctx, width, height, solution, id) {
  const d = frameData(solution, id);
  const L = frameLayout(d, width, height);
  const { X, Y } = L;
  const x0 = X(0);
  const y0 = Y(0);
  const xW = X(d.columns);
  const yH = Y(d.rows);
  const xc = X(d.c0);
  const yc = Y(d.r0);
  const xp = X(d.c);
  const yp = Y(d.r);
  const obstacles = [];
  const note = (box) => {
    obstacles.push(box);
    return box;
  };

  // the image frame
  ctx.save();
  ctx.fillStyle = COLORS.frameFill;
  ctx.strokeStyle = COLORS.frameStroke;
  ctx.lineWidth = 1.5;
  ctx.fillRect(x0, y0, xW - x0, yH - y0);
  ctx.strokeRect(x0, y0, xW - x0, yH - y0);
  ctx.restore();

  // image system (orange): origin at the centre, x right, y up; half-sizes in mm at the frame edges
  const halfW = (d.columns / 2) * d.p;
  const halfH = (d.rows / 2) * d.p;
  const xEnd = Math.max(xW, X(d.c)) + FRAME.axisOverhang;
  const yEnd = Math.min(y0, Y(d.r)) - FRAME.axisOverhang;
  arrow(ctx, x0, yc, xEnd, yc, { color: COLORS.imageSystem });
  arrow(ctx, xc, yH, xc, yEnd, { color: COLORS.imageSystem });
  const axisName = { weight: "bold", size: AXIS_NAME_SIZE };
  note(text(ctx, "x (mm)", xEnd + FRAME.axisNameGap, yc, { ...axisName, color: COLORS.imageSystem }));
  note(text(ctx, "y (mm)", xc + FRAME.axisNameGap + 2, yEnd, { ...axisName, color: COLORS.imageSystem, baseline: "top" }));
  const small = { color: COLORS.imageSystem, size: FONT_SIZE_SMALL, halo: true };
  // just outside the frame, where the image axes cross its edges
  note(text(ctx, formatNumber(-halfW, MM_TICK_DIGITS), x0 - 3, yc + 3, { ...small, baseline: "top", align: "right" }));
  note(text(ctx, formatNumber(halfW, MM_TICK_DIGITS), xW + 3, yc + 3, { ...small, baseline: "top" }));
  note(text(ctx, formatNumber(halfH, MM_TICK_DIGITS), xc - 4, y0 - 3, { ...small, baseline: "bottom", align: "right" }));
  note(text(ctx, formatNumber(-halfH, MM_TICK_DIGITS), xc - 4, yH + 3, { ...small, baseline: "top", align: "right" }));

  // pixel system (blue): origin at the top-left corner, c right, r down; the frame size as ticks
  const cEnd = Math.max(xW, X(d.c)) + FRAME.axisOverhang;
  const rEnd = Math.max(yH, Y(d.r)) + FRAME.axisOverhang;
  arrow(ctx, x0, y0, cEnd, y0, { color: COLORS.pixelSystem, width: 2 });
  arrow(ctx, x0, y0, x0, rEnd, { color: COLORS.pixelSystem, width: 2 });
  note(text(ctx, "c (px)", cEnd + FRAME.axisNameGap, y0, { ...axisName, color: COLORS.pixelSystem }));
  note(text(ctx, "r (px)", x0 + FRAME.axisNameGap + 2, rEnd, { ...axisName, color: COLORS.pixelSystem, baseline: "bottom" }));
  const tickStyle = { color: COLORS.pixelSystem, size: FONT_SIZE_SMALL };
  line(ctx, xW, y0 - FRAME.tick, xW, y0, { color: COLORS.pixelSystem, width: 1.5 });
  line(ctx, x0 - FRAME.tick, yH, x0, yH, { color: COLORS.pixelSystem, width: 1.5 });
  note(text(ctx, "0", x0 - 4, y0 - 4, { ...tickStyle, align: "right", baseline: "bottom" }));
  note(text(ctx, formatNumber(d.columns, PX_DIGITS), xW, y0 - FRAME.tick - 1, { ...tickStyle, align: "center", baseline: "bottom" }));
  note(text(ctx, formatNumber(d.rows, PX_DIGITS), x0 - FRAME.tick - 2, yH, { ...tickStyle, align: "right" }));

  // p to the pixel axes (blue dashes) and to the image axes (orange dots)
  line(ctx, xp, yp, xp, y0, { color: COLORS.pixelSystem, dash: DASH, width: 1.2 });
  line(ctx, xp, yp, x0, yp, { color: COLORS.pixelSystem, dash: DASH, width: 1.2 });
  line(ctx, xp, yp, xp, yc, { color: COLORS.imageSystem, dash: DOTS, width: 1.8 });
  line(ctx, xp, yp, xc, yp, { color: COLORS.imageSystem, dash: DOTS, width: 1.8 });

  // the centre
  ring(ctx, xc, yc, FRAME.centreRadius, COLORS.imageSystem);
  dot(ctx, xc, yc, 1.8, COLORS.imageSystem);

  dot(ctx, xp, yp, FRAME.pointRadius, COLORS.point);
  const bounds = { x: 2, y: 2, w: width - 4, h: height - 4 };

  // the point's label, on the side away from the centre
  const lines = [
    { text: `p: c = ${formatNumber(d.c, PX_DIGITS)}, r = ${formatNumber(d.r, PX_DIGITS)} px`, color: COLORS.pixelSystem },
    { text: `x = ${formatNumber(d.x, MM_DIGITS)}, y = ${formatNumber(d.y, MM_DIGITS)} mm`, color: COLORS.imageSystem },
  ];
  if (d.outside) lines.push({ text: "(outside the image)", color: COLORS.point, weight: "bold" });
  const size = blockSize(ctx, lines);
  const sx = d.c >= d.c0 ? 1 : -1;
  const sy = d.r >= d.r0 ? 1 : -1;
  const pBox = place(quadrants(xp, yp, size.w, size.h, FRAME.labelGap, sx, sy), bounds, obstacles);
  textBlock(ctx, lines, pBox.x, pBox.y);
  obstacles.push(pBox);

  // the centre's label, on the side away from p
  const centreLines = [{ text: `centre (c₀, r₀) = (${formatNumber(d.c0, PX_DIGITS)}, ${formatNumber(d.r0, PX_DIGITS)})`, color: COLORS.imageSystem }];
  const cSize = blockSize(ctx, centreLines, { size: FONT_SIZE_SMALL, pad: 3 });
  const pointDot = { x: xp - FRAME.pointRadius, y: yp - FRAME.pointRadius, w: 2 * FRAME.pointRadius, h: 2 * FRAME.pointRadius };
  const cBox = place(quadrants(xc, yc, cSize.w, cSize.h, FRAME.labelGap - 2, -sx, -sy), bounds, [...obstacles, pointDot]);
  textBlock(ctx, centreLines, cBox.x, cBox.y, { size: FONT_SIZE_SMALL, pad: 3, border: "transparent" });
}

function describeFrame(solution, id) {
  const d = frameData(solution, id);
  const px = (v) => formatNumber(v, PX_DIGITS);
  const mm = (v) => formatNumber(v, MM_DIGITS);
  return (
    `The image frame of ${px(d.columns)} columns by ${px(d.rows)} rows, drawn to scale. ` +
    `Pixel coordinate system: origin at the top-left corner, c to the right, r downward, in pixels. ` +
    `Image coordinate system: origin at the centre c0 = ${px(d.c0)}, r0 = ${px(d.r0)}, x to the right, y upward, in millimetres; ` +
    `the frame reaches x = ±${mm((d.columns / 2) * d.p)} mm and y = ±${mm((d.rows / 2) * d.p)} mm. ` +
    `Point p at c = ${px(d.c)} px, r = ${px(d.r)} px, that is x = ${mm(d.x)} mm, y = ${mm(d.y)} mm` +
    `${d.outside ? ", outside the image" : ""}, with dashed lines to both pairs of axes.`
  );
}

function frameFigure(id) {
  return {
    caption: "The image to scale. Blue: pixel coordinates (c, r) from the top-left corner, r downward. Orange: image coordinates (x, y) in mm from the centre, y upward.",
    height: (width, solution) => frameLayout(frameData(solution, id), width).height,
    describe: (solution) => describeFrame(solution, id),
    tables(solution) {
      const d = frameData(solution, id);
      const px = (v) => formatNumber(v, PX_DIGITS);
      const mm = (v) => formatNumber(v, MM_DIGITS);
      return {
        summary: describeFrame(solution, id),
        tables: [
          seriesTable(
            "The point p in both coordinate systems",
            ["system", "first coordinate", "second coordinate"],
            [
              ["pixel (c, r), px from the top-left corner", px(d.c), px(d.r)],
              ["image (x, y), mm from the centre", mm(d.x), mm(d.y)],
              ["the centre (c0, r0), px", px(d.c0), px(d.r0)],
            ],
            [[d.outside ? "outside the image" : null, null, null], [null, null, null], [null, null, null]],
          ),
          seriesTable("The frame", ["quantity", "value"], [["columns", px(d.columns)], ["rows", px(d.rows)], ["pixel size (mm)", formatNumber(d.p, MM_DIGITS)]]),
        ],
      };
    },
    draw: (ctx, width, height, solution) => drawFrame(ctx, width, height, solution, id),
  };
}

// ---------------------------------------------------------------------------
// Ground sample distance: side view of the camera

const GSD = Object.freeze({
  margin: { left: 14, right: 14, top: 14, bottom: 14 },
  heightPerWidth: 0.8,
  minHeight: 320,
  maxHeight: 440,
  centreX: 0.56, // lens position, fraction of the width (room for the labels on the left)
  imagePlaneY: 62, // from the top: room for the pixel's label
  groundGap: 58, // from the bottom: room for the footprint's label
  focalShare: 0.24, // f's share of the vertical distance from image plane to ground (not to scale)
  pixelWidth: 16, // the drawn pixel (greatly enlarged)
  planeHalfWidth: 0.3, // half the image plane, fraction of the width
  planeHalfMax: 130,
  lensRx: 26,
  lensRy: 6,
  hatch: 8, // ground hatching length and spacing
  dimensionX: 26, // x of the f and H dimension arrows
});

function gsdData(solution) {
  const inp = solution.inputs ?? {};
  const res = solution.result ?? {};
  const p = finite(res.pixel_size_mm, MM_PER_INCH / finite(inp.dpi, MM_PER_INCH));
  const f = finite(inp.focal_length_mm);
  const H = finite(inp.flying_height_m);
  const den = finite(res.scale_denominator, f > 0 ? (H * 1000) / f : 0);
  const gsdCm = finite(res.gsd_cm, finite(res.gsd_mm, p * den) / 10);
  return { p, f, H, den, gsdCm };
}

function gsdLabels(d) {
  return {
    f: `f = ${formatNumber(d.f, 6)} mm`,
    H: `H = ${formatNumber(d.H, 6)} m`,
    p: `one pixel: p = ${formatNumber(d.p, 3)} mm`,
    gsd: `GSD = ${formatNumber(d.gsdCm, 4)} cm`,
    scale: `scale f : H = 1 : ${Math.round(d.den)}`,
  };
}

function drawGsd(ctx, width, height, solution) {
  const d = gsdData(solution);
  const labels = gsdLabels(d);
  const m = GSD.margin;
  const cx = Math.round(width * GSD.centreX);
  const yImage = GSD.imagePlaneY;
  const yGround = height - GSD.groundGap;
  const yLens = yImage + (yGround - yImage) * GSD.focalShare;
  const halfP = GSD.pixelWidth / 2;
  // similar triangles in the drawing: footprint / pixel = (ground - O) / (O - image plane)
  const halfF = halfP * ((yGround - yLens) / (yLens - yImage));
  const planeHalf = Math.min(width * GSD.planeHalfWidth, GSD.planeHalfMax);
  const dimX = GSD.dimensionX;

  // "not to scale"
  text(ctx, "not to scale", width - m.right, m.top, { color: COLORS.muted, style: "italic", align: "right", baseline: "top" });

  // optical axis
  line(ctx, cx, yImage - 10, cx, yGround, { color: COLORS.grid, dash: [8, 3, 2, 3] });

  // image plane with one pixel
  line(ctx, cx - planeHalf, yImage, cx + planeHalf, yImage, { color: COLORS.ink, width: 2 });
  text(ctx, "image plane", cx + planeHalf, yImage + 6, { color: COLORS.muted, size: FONT_SIZE_SMALL, align: "right", baseline: "top" });
  markedSpan(ctx, cx, yImage, halfP);
  text(ctx, labels.p, cx, yImage - 12, { color: COLORS.ink, align: "center", baseline: "bottom", weight: "bold", halo: true });

  // rays through the pixel's edges, crossing at O
  line(ctx, cx - halfP, yImage, cx + halfF, yGround, { color: COLORS.ray, width: 1.2 });
  line(ctx, cx + halfP, yImage, cx - halfF, yGround, { color: COLORS.ray, width: 1.2 });

  // the lens and the projection centre O
  ctx.save();
  ctx.fillStyle = "rgba(29, 95, 191, 0.15)";
  ctx.strokeStyle = COLORS.pixelSystem;
  ctx.lineWidth = 1.5;
  ctx.beginPath();
  ctx.ellipse(cx, yLens, GSD.lensRx, GSD.lensRy, 0, 0, 2 * Math.PI);
  ctx.fill();
  ctx.stroke();
  ctx.restore();
  dot(ctx, cx, yLens, 3, COLORS.ink);
  const oX = cx + GSD.lensRx + 6;
  text(ctx, "O", oX, yLens - FONT_SIZE_SMALL * 0.6, { color: COLORS.ink, weight: "bold", halo: true });
  text(ctx, "projection centre", oX, yLens + FONT_SIZE_SMALL * 0.7, { color: COLORS.muted, size: FONT_SIZE_SMALL, halo: true });

  // the ground with the pixel's footprint
  line(ctx, m.left, yGround, width - m.right, yGround, { color: COLORS.ground, width: 2 });
  ctx.save();
  ctx.strokeStyle = COLORS.ground;
  ctx.lineWidth = 1;
  for (let x = m.left + GSD.hatch; x <= width - m.right; x += GSD.hatch) {
    ctx.beginPath();
    ctx.moveTo(x, yGround);
    ctx.lineTo(x - GSD.hatch, yGround + GSD.hatch);
    ctx.stroke();
  }
  ctx.restore();
  markedSpan(ctx, cx, yGround, halfF);
  text(ctx, "ground", dimX + 8, yGround - 4, { color: COLORS.ground, size: FONT_SIZE_SMALL, baseline: "bottom", halo: true }); // right of the H dimension arrow
  const gsdY = yGround + GSD.hatch + 6;
  text(ctx, labels.gsd, cx, gsdY, { color: COLORS.ink, weight: "bold", align: "center", baseline: "top", halo: true });
  text(ctx, "the pixel's footprint on the ground", cx, gsdY + FONT_SIZE * LINE_HEIGHT + 1, { color: COLORS.muted, size: FONT_SIZE_SMALL, align: "center", baseline: "top", halo: true });

  // dimensions f and H on the left
  line(ctx, dimX - 6, yImage, cx - planeHalf - 4, yImage, { color: COLORS.muted, dash: DASH, width: 0.8 });
  line(ctx, dimX - 6, yLens, cx - GSD.lensRx - 4, yLens, { color: COLORS.muted, dash: DASH, width: 0.8 });
  arrow(ctx, dimX, yImage, dimX, yLens, { color: COLORS.ink, width: 1.2, both: true, size: 7 });
  arrow(ctx, dimX, yLens, dimX, yGround, { color: COLORS.ink, width: 1.2, both: true, size: 7 });
  const labelX = dimX + 8;
  text(ctx, labels.f, labelX, (yImage + yLens) / 2, { color: COLORS.ink, weight: "bold", halo: true });
  const midH = (yLens + yGround) / 2;
  text(ctx, labels.H, labelX, midH - FONT_SIZE * LINE_HEIGHT * 0.6, { color: COLORS.ink, weight: "bold", halo: true });
  text(ctx, labels.scale, labelX, midH + FONT_SIZE * LINE_HEIGHT * 0.6, { color: COLORS.ink, size: FONT_SIZE_SMALL, halo: true });
}

function describeGsd(solution) {
  const d = gsdData(solution);
  const l = gsdLabels(d);
  return (
    `Side view of the camera geometry, not to scale. The image plane lies at the focal length ${l.f} from the projection centre O; ` +
    `the ground lies at the flying height ${l.H} below O. Two rays through the edges of one pixel (${l.p}) cross at O ` +
    `and meet the ground in the pixel's footprint, ${l.gsd}. ${l.scale}.`
  );
}

const gsdFigure = {
  tables(solution) {
    const l = gsdLabels(gsdData(solution));
    return {
      summary: describeGsd(solution),
      tables: [seriesTable("The labelled lengths of the sketch (a side view, not to scale)", ["quantity", "value"], [l.f, l.H, l.p, l.gsd, l.scale].map((t) => t.split(/ = (?=[^=]*$)/)))],
    };
  },
  caption: "Side view of the camera: the rays through one pixel's edges cross at the projection centre O and mark its footprint on the ground (not to scale).",
  height: (width) => Math.min(GSD.maxHeight, Math.max(GSD.minHeight, width * GSD.heightPerWidth)),
  describe: describeGsd,
  draw: drawGsd,
};

export const figures = {
  "pixel-to-photo": frameFigure("pixel-to-photo"),
  "photo-to-pixel": frameFigure("photo-to-pixel"),
  gsd: gsdFigure,
};
