// Figures of the "Map projection" topic (seed 004, UTM):
//   utm, utm-inverse: the zone's graticule on the map (central meridian,
//     zone edges, equator, the point), the scale factor k across the zone;
//   utm: also how far the classical (Snyder) series strays from the exact
//     (Krüger) one, on a log scale in metres;
//   utm-facts: k across the zone with the lines of true scale and the seed's
//     "90 km".
// Every number drawn comes from the solution's step values (the core
// computes the graticule, the k profile and the differences).

import { formatNumber } from "../format.js";
import { seriesTable } from "./data-view.js";
import { COLORS, DASH, DOTS, FONT_SIZE_SMALL, dot, line, text, textWidth } from "./draw.js";

const PAD = Object.freeze({ left: 58, right: 16, top: 30, bottom: 44 });
const TICK = 4;
// colours of the palette in use (read when drawn: the dark theme has its own)
const CM_COLOR = () => COLORS.pixelSystem; // central meridian: blue
const EDGE_COLOR = () => COLORS.imageSystem; // zone edges: orange-brown
const EQUATOR_COLOR = () => COLORS.green; // equator: green
const CURVE = () => COLORS.ink;
const CLASSIC = () => COLORS.imageSystem;
const POINT_R = 5;
const MAP_ASPECT_MAX = 1.25; // the map is at most this tall per unit width
const PLOT_HEIGHT = Object.freeze({ min: 230, perWidth: 0.55, max: 340 });

/** The values of the solution's step that has `key`. */
function stepWith(solution, key) {
  for (const step of solution.steps ?? []) {
    if (step.values && Object.hasOwn(step.values, key)) return step.values;
  }
  return null;
}

/** "Nice" tick values covering [lo, hi], about `n` of them. */
function ticks(lo, hi, n) {
  const span = hi - lo;
  if (!(span > 0)) return [lo];
  const raw = span / Math.max(1, n);
  const mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 2.5, 5, 10].map((m) => m * mag).find((s) => s >= raw) ?? 10 * mag;
  const out = [];
  for (let v = Math.ceil(lo / step) * step; v <= hi + step * 1e-9; v += step) out.push(Math.abs(v) < step * 1e-9 ? 0 : v);
  return out;
}

/** Axes in box {x, y, w, h} for data ranges; returns the mapping functions. */
function axes(ctx, box, [x0, x1], [y0, y1], { xLabel, yLabel, title, log = false, xTicks, yTicks, yFormat }) {
  const sx = (v) => box.x + ((v - x0) / (x1 - x0)) * box.w;
  const ty = (v) => (log ? Math.log10(v) : v);
  const [ly0, ly1] = [ty(y0), ty(y1)];
  const sy = (v) => box.y + box.h - ((ty(v) - ly0) / (ly1 - ly0)) * box.h;
  ctx.save();
  ctx.strokeStyle = COLORS.grid;
  ctx.lineWidth = 1;
  ctx.strokeRect(box.x + 0.5, box.y + 0.5, box.w, box.h);
  ctx.restore();
  for (const v of xTicks ?? ticks(x0, x1, Math.max(2, Math.floor(box.w / 70)))) {
    const X = sx(v);
    line(ctx, X, box.y + box.h, X, box.y + box.h + TICK, { color: COLORS.muted });
    text(ctx, formatNumber(v, 4), X, box.y + box.h + TICK + 8, { size: FONT_SIZE_SMALL, align: "center", color: COLORS.muted });
  }
  for (const v of yTicks ?? ticks(y0, y1, Math.max(2, Math.floor(box.h / 45)))) {
    const Y = sy(v);
    if (Y < box.y - 1 || Y > box.y + box.h + 1) continue;
    line(ctx, box.x - TICK, Y, box.x, Y, { color: COLORS.muted });
    line(ctx, box.x, Y, box.x + box.w, Y, { color: COLORS.grid, dash: DOTS });
    text(ctx, yFormat ? yFormat(v) : formatNumber(v, 6), box.x - TICK - 3, Y, { size: FONT_SIZE_SMALL, align: "right", color: COLORS.muted });
  }
  text(ctx, xLabel, box.x + box.w / 2, box.y + box.h + 32, { size: FONT_SIZE_SMALL, align: "center" });
  const t = title ? text(ctx, title, box.x, box.y - 14, { weight: "bold", size: 12.5 }) : { x: box.x, w: 0 };
  // the y axis's name on the right of the title, when there is room for both
  if (yLabel && t.x + t.w + 12 + textWidth(yLabel, FONT_SIZE_SMALL) <= box.x + box.w) {
    text(ctx, yLabel, box.x + box.w, box.y - 14, { size: FONT_SIZE_SMALL, align: "right", color: COLORS.muted });
  }
  return { sx, sy };
}

function polyline(ctx, pts, map, { color, width = 1, dash = null }) {
  if (pts.length < 2) return;
  ctx.save();
  ctx.strokeStyle = color;
  ctx.lineWidth = width;
  ctx.setLineDash(dash ? [...dash] : []);
  ctx.beginPath();
  pts.forEach(([a, b], i) => {
    const X = map.sx(a);
    const Y = map.sy(b);
    if (i === 0) ctx.moveTo(X, Y);
    else ctx.lineTo(X, Y);
  });
  ctx.stroke();
  ctx.restore();
}

function plotBox(width, height) {
  return { x: PAD.left, y: PAD.top, w: Math.max(40, width - PAD.left - PAD.right), h: Math.max(40, height - PAD.top - PAD.bottom) };
}

function plotHeight(width) {
  return Math.min(PLOT_HEIGHT.max, Math.max(PLOT_HEIGHT.min, width * PLOT_HEIGHT.perWidth));
}

function lonName(lon) {
  const l = ((((lon + 180) % 360) + 360) % 360) - 180;
  return `${formatNumber(Math.abs(l), 4)}°${l < 0 ? "W" : l > 0 ? "E" : ""}`;
}

function latName(lat) {
  return `${formatNumber(Math.abs(lat), 4)}°${lat < 0 ? "S" : lat > 0 ? "N" : ""}`;
}

// ---------------------------------------------------------------------------
// The zone on the map

function mapData(solution) {
  const v = stepWith(solution, "meridians");
  if (!v) return null;
  const all = [...v.meridians, ...v.parallels].flat();
  const es = all.map((p) => p[0]);
  const ns = all.map((p) => p[1]);
  return { v, e: [Math.min(...es), Math.max(...es)], n: [Math.min(...ns), Math.max(...ns)] };
}

/** Every `step`-th row of a plotted profile, and its last (the Data views' tables: the samples as the core gave them). */
const thinned = (rows, step) => rows.filter((_, i) => i % step === 0 || i === rows.length - 1);

const map = {
  tables(solution) {
    const r = solution.result ?? {};
    const point = stepWith(solution, "point")?.point ?? [];
    const lon0 = stepWith(solution, "central_meridian")?.central_meridian ?? r.central_meridian;
    const rows = [
      ["zone", String(r.zone ?? solution.inputs?.zone ?? "")],
      ["central meridian", lonName(lon0)],
      ["point: easting (km)", formatNumber(point[0], 9)],
      ["point: northing (km)", formatNumber(point[1], 10)],
    ];
    return { summary: map.describe(solution), tables: [seriesTable("The zone and the point (the curves are the zone's meridians and parallels)", ["what", "value"], rows)] };
  },
  caption: "The zone on the map: meridians and parallels as the transverse Mercator draws them (every 1° or 5°), the central meridian (blue), the zone's edges 3° either side (orange, dashed), the equator (green) when near, and the point.",
  height(width, solution) {
    const d = mapData(solution);
    if (!d) return 200;
    const w = width - PAD.left - PAD.right;
    const aspect = (d.n[1] - d.n[0]) / Math.max(1e-9, d.e[1] - d.e[0]);
    return Math.round(Math.min(w * MAP_ASPECT_MAX, Math.max(200, w * aspect)) + PAD.top + PAD.bottom);
  },
  describe(solution) {
    const r = solution.result ?? {};
    const inp = solution.inputs ?? {};
    const zone = r.zone ?? inp.zone;
    const lon0 = stepWith(solution, "central_meridian")?.central_meridian ?? r.central_meridian;
    return `Map of UTM zone ${zone}: the central meridian ${lonName(lon0)} runs straight up the middle at easting 500 km; the other meridians curve toward it near the pole; the point lies at easting ${formatNumber((stepWith(solution, "point")?.point ?? [0])[0], 9)} km, northing ${formatNumber((stepWith(solution, "point")?.point ?? [0, 0])[1], 10)} km.`;
  },
  draw(ctx, width, height, solution) {
    const d = mapData(solution);
    if (!d) return;
    const { v } = d;
    const box = plotBox(width, height);
    // equal scale in E and N: widen the smaller range
    const cx = (d.e[0] + d.e[1]) / 2;
    const cy = (d.n[0] + d.n[1]) / 2;
    const kmPerPx = Math.max((d.e[1] - d.e[0]) / box.w, (d.n[1] - d.n[0]) / box.h) * 1.04;
    const er = [cx - (kmPerPx * box.w) / 2, cx + (kmPerPx * box.w) / 2];
    const nr = [cy - (kmPerPx * box.h) / 2, cy + (kmPerPx * box.h) / 2];
    const m = axes(ctx, box, er, nr, { xLabel: "Easting E (km)", yLabel: "Northing N (km)", title: "The zone on the map" });
    ctx.save();
    ctx.beginPath();
    ctx.rect(box.x, box.y, box.w, box.h);
    ctx.clip();
    const lon0 = v.map_central_meridian;
    v.parallels.forEach((p, i) => {
      const lat = v.parallel_latitudes[i];
      polyline(ctx, p, m, lat === 0 ? { color: EQUATOR_COLOR(), width: 2.5 } : { color: COLORS.muted, width: 0.8 });
    });
    v.meridians.forEach((p, i) => {
      const d0 = v.meridian_longitudes[i] - lon0;
      const centre = Math.abs(d0) < 1e-9;
      polyline(ctx, p, m, centre ? { color: CM_COLOR(), width: 2.5 } : { color: COLORS.muted, width: 0.8 });
    });
    // the zone's edges, ±3°, from the meridians at those offsets
    v.meridians.forEach((p, i) => {
      const d0 = v.meridian_longitudes[i] - lon0;
      if (Math.abs(Math.abs(d0) - 3) < 1e-9) polyline(ctx, p, m, { color: EDGE_COLOR(), width: 2, dash: DASH });
    });
    ctx.restore();
    // labels along the top edge: the central meridian first, then the zone's
    // edges, then the others where they do not cover one already written
    const placed = [];
    const order = v.meridians.map((p, i) => {
      const d0 = v.meridian_longitudes[i] - lon0;
      return { p, i, rank: Math.abs(d0) < 1e-9 ? 0 : Math.abs(Math.abs(d0) - 3) < 1e-9 ? 1 : 2 };
    });
    order.sort((a, b) => a.rank - b.rank);
    for (const { p, i, rank } of order) {
      const X = m.sx(p[p.length - 1][0]);
      const label = lonName(v.meridian_longitudes[i]);
      const w = textWidth(label, FONT_SIZE_SMALL) + 6;
      const boxL = { x: X - w / 2, w };
      if (boxL.x < box.x || boxL.x + w > box.x + box.w) continue;
      if (placed.some((q) => boxL.x < q.x + q.w && q.x < boxL.x + w)) continue;
      placed.push(boxL);
      const color = rank === 0 ? CM_COLOR() : rank === 1 ? EDGE_COLOR() : COLORS.muted;
      text(ctx, label, X, box.y + 9, { size: FONT_SIZE_SMALL, align: "center", color, halo: true, weight: rank === 0 ? "bold" : "normal" });
    }
    let lastTop = Infinity;
    v.parallels.forEach((p, i) => {
      const left = p[0];
      const Y = m.sy(left[1]);
      if (Y < box.y + 18 || Y > box.y + box.h - 8 || Y + 14 > lastTop) return;
      const lat = v.parallel_latitudes[i];
      const b = text(ctx, latName(lat), box.x + 4, Y, { size: FONT_SIZE_SMALL, color: lat === 0 ? EQUATOR_COLOR() : COLORS.muted, halo: true });
      lastTop = b.y;
    });
    const [pe, pn] = v.point;
    const X = m.sx(pe);
    const Y = m.sy(pn);
    dot(ctx, X, Y, POINT_R, COLORS.point);
    const label = `E ${formatNumber(pe, 7)} km, N ${formatNumber(pn, 7)} km`;
    // beside the point where it fits, else centred above it, kept inside the plot
    const w = textWidth(label, FONT_SIZE_SMALL);
    let lx = X + 8;
    if (lx + w > box.x + box.w - 2) lx = X - 8 - w;
    if (lx < box.x + 2) lx = Math.min(Math.max(box.x + 2, X - w / 2), box.x + box.w - 2 - w);
    text(ctx, label, lx, Y - 14, { size: FONT_SIZE_SMALL, color: COLORS.point, halo: true });
  },
};

// ---------------------------------------------------------------------------
// k across the zone

function kProfile(solution) {
  const v = stepWith(solution, "k_profile");
  return v ? { v, rows: v.k_profile } : null;
}

/** The x (km) at longitude difference `dl`, by interpolation in the profile. */
function xAt(rows, dl) {
  for (let i = 1; i < rows.length; i++) {
    const [d0, x0] = rows[i - 1];
    const [d1, x1] = rows[i];
    if ((dl - d0) * (dl - d1) <= 0 && d1 !== d0) return x0 + ((dl - d0) / (d1 - d0)) * (x1 - x0);
  }
  return null;
}

function kAt(rows, dl) {
  for (let i = 1; i < rows.length; i++) {
    const [d0, , k0] = rows[i - 1];
    const [d1, , k1] = rows[i];
    if ((dl - d0) * (dl - d1) <= 0 && d1 !== d0) return k0 + ((dl - d0) / (d1 - d0)) * (k1 - k0);
  }
  return null;
}

function kSpec(seedLine) {
  return {
    caption: seedLine
      ? "The scale factor k along the parallel, against the distance x from the central meridian: 0.9996 in the middle, 1 on the two lines of true scale (dashed), largest at the zone's edges (orange). Dotted: the seed's “1.0000 at 90 km”."
      : "The scale factor k along the point's parallel, against the distance x from the central meridian: 0.9996 in the middle, 1 where the dashed line crosses, largest at the zone's edges (orange); the dot is the point.",
    height: (width) => plotHeight(width),
    tables(solution) {
      const p = kProfile(solution);
      if (!p) return { summary: "Scale factor plot (no data).", tables: [] };
      return {
        summary: this.describe(solution),
        tables: [seriesTable("The plotted scale factor k (every fifth sample of the curve)", ["longitude from the central meridian (°)", "x (km)", "k"], thinned(p.rows, 5).map(([dl, x, k]) => [formatNumber(dl, 4), formatNumber(x, 6), formatNumber(k, 8)]))],
      };
    },
    describe(solution) {
      const p = kProfile(solution);
      if (!p) return "Scale factor plot (no data).";
      const kEdge = kAt(p.rows, 3);
      return `Plot of the scale factor k across the zone: ${formatNumber(p.rows[Math.floor(p.rows.length / 2)][2], 6)} on the central meridian, 1 about ${formatNumber(Math.abs(xAt(p.rows, solution.result?.k1_longitude_offset ?? 1.6) ?? 180), 4)} km either side, ${kEdge == null ? "" : `${formatNumber(kEdge, 7)} at the zone's edges`}.`;
    },
    draw(ctx, width, height, solution) {
      const p = kProfile(solution);
      if (!p) return;
      const rows = p.rows;
      const xs = rows.map((r) => r[1]);
      const ks = rows.map((r) => r[2]);
      const kLo = Math.min(...ks, 0.9996) - (Math.max(...ks) - Math.min(...ks)) * 0.12;
      const kHi = Math.max(...ks, 1.0002);
      const padK = (kHi - kLo) * 0.08;
      const box = plotBox(width, height);
      const m = axes(ctx, box, [Math.min(...xs), Math.max(...xs)], [kLo - padK, kHi + padK], {
        xLabel: "Distance x from the central meridian (km, east +)",
        yLabel: "k",
        title: "Scale factor k across the zone",
        yFormat: (v) => formatNumber(v, 6),
      });
      ctx.save();
      ctx.beginPath();
      ctx.rect(box.x, box.y, box.w, box.h);
      ctx.clip();
      line(ctx, box.x, m.sy(1), box.x + box.w, m.sy(1), { color: CM_COLOR(), dash: DASH });
      for (const e of [-3, 3]) {
        const x = xAt(rows, e);
        if (x != null) line(ctx, m.sx(x), box.y, m.sx(x), box.y + box.h, { color: EDGE_COLOR(), width: 1.5, dash: DASH });
      }
      if (seedLine) for (const s of [-90, 90]) line(ctx, m.sx(s), box.y, m.sx(s), box.y + box.h, { color: COLORS.point, dash: DOTS, width: 1.5 });
      polyline(ctx, rows.map((r) => [r[1], r[2]]), m, { color: CURVE(), width: 2 });
      ctx.restore();
      text(ctx, "k = 1", box.x + 4, m.sy(1) - 9, { size: FONT_SIZE_SMALL, color: CM_COLOR(), halo: true });
      const kc = ks[Math.floor(ks.length / 2)];
      text(ctx, `${formatNumber(kc, 6)} on the central meridian`, m.sx(0), m.sy(kc) - 12, { size: FONT_SIZE_SMALL, align: "center", halo: true });
      const kEdge = kAt(rows, 3);
      const xEdge = xAt(rows, 3);
      if (kEdge != null && xEdge != null) {
        text(ctx, `edge: ${formatNumber(kEdge, 7)}`, m.sx(xEdge) - 4, box.y + 12, { size: FONT_SIZE_SMALL, color: EDGE_COLOR(), align: "right", halo: true });
      }
      if (seedLine) text(ctx, "seed: 90 km", m.sx(90) + 4, box.y + box.h - 12, { size: FONT_SIZE_SMALL, color: COLORS.point, halo: true });
      const pd = p.v.point_dlon;
      if (!seedLine && typeof pd === "number") {
        const x = xAt(rows, pd);
        const k = kAt(rows, pd);
        if (x != null && k != null) dot(ctx, m.sx(x), m.sy(k), POINT_R, COLORS.point);
      }
    },
  };
}

// ---------------------------------------------------------------------------
// Classical against exact

const LOG_LABELS = [
  [1e-10, "0.1 nm"],
  [1e-9, "1 nm"],
  [1e-8, "10 nm"],
  [1e-7, "0.1 µm"],
  [1e-6, "1 µm"],
  [1e-5, "10 µm"],
  [1e-4, "0.1 mm"],
  [1e-3, "1 mm"],
  [1e-2, "1 cm"],
  [1e-1, "10 cm"],
  [1, "1 m"],
  [10, "10 m"],
  [100, "100 m"],
  [1e3, "1 km"],
];

const difference = {
  tables(solution) {
    const v = stepWith(solution, "difference_profile");
    if (!v) return { summary: "Difference plot (no data).", tables: [] };
    return {
      summary: difference.describe(solution),
      tables: [seriesTable("The plotted difference, classical minus exact series", ["longitude from the central meridian (°)", "x (km)", "difference (m)"], v.difference_profile.map(([dl, x, dm]) => [formatNumber(dl, 4), formatNumber(x, 6), formatNumber(dm, 3)]))],
    };
  },
  caption: "How far the classical series (Snyder) puts the point from the exact Krüger series, along the point's parallel, against the distance from the central meridian; log scale in metres. The dot is the point; the dashed line is 1 mm.",
  height: (width) => plotHeight(width),
  describe(solution) {
    const v = stepWith(solution, "difference_profile");
    if (!v) return "Difference plot (no data).";
    const rows = v.difference_profile;
    const last = rows[rows.length - 1];
    const mm = rows.find((r) => r[2] >= 1e-3);
    return `Log plot of the classical series' error: ${formatNumber(rows[0][2], 3)} m at ${formatNumber(rows[0][1], 4)} km from the central meridian, ${mm ? `1 mm reached at ${formatNumber(mm[1], 4)} km, ` : ""}${formatNumber(last[2], 3)} m at ${formatNumber(last[1], 4)} km.`;
  },
  draw(ctx, width, height, solution) {
    const v = stepWith(solution, "difference_profile");
    if (!v) return;
    const rows = v.difference_profile.filter((r) => r[2] > 0);
    if (!rows.length) return;
    const ds = rows.map((r) => r[2]);
    const lo = 10 ** Math.floor(Math.log10(Math.min(...ds)));
    const hi = 10 ** Math.ceil(Math.log10(Math.max(...ds, 2e-3)));
    const box = plotBox(width, height);
    const yTicks = [];
    for (let e = Math.log10(lo); e <= Math.log10(hi) + 1e-9; e++) yTicks.push(10 ** e);
    const m = axes(ctx, box, [0, Math.max(...rows.map((r) => r[1]))], [lo, hi], {
      xLabel: "Distance x from the central meridian (km)",
      title: "Classical − exact (m, log scale)",
      log: true,
      yTicks,
      yFormat: (t) => LOG_LABELS.find(([x]) => Math.abs(Math.log10(t / x)) < 1e-9)?.[1] ?? `1e${Math.round(Math.log10(t))} m`,
    });
    ctx.save();
    ctx.beginPath();
    ctx.rect(box.x, box.y, box.w, box.h);
    ctx.clip();
    line(ctx, box.x, m.sy(1e-3), box.x + box.w, m.sy(1e-3), { color: CM_COLOR(), dash: DASH });
    polyline(ctx, rows.map((r) => [r[1], r[2]]), m, { color: CLASSIC(), width: 2 });
    ctx.restore();
    const pd = Math.abs(stepWith(solution, "point_dlon")?.point_dlon ?? NaN);
    const res = solution.result ?? {};
    if (Number.isFinite(pd) && typeof res.classical_difference_m === "number" && res.classical_difference_m > 0) {
      const r0 = v.difference_profile;
      let x = null;
      for (let i = 1; i < r0.length; i++) {
        if ((pd - r0[i - 1][0]) * (pd - r0[i][0]) <= 0) x = r0[i - 1][1] + ((pd - r0[i - 1][0]) / (r0[i][0] - r0[i - 1][0])) * (r0[i][1] - r0[i - 1][1]);
      }
      const y = Math.min(hi, Math.max(lo, res.classical_difference_m));
      if (x != null) dot(ctx, m.sx(x), m.sy(y), POINT_R, COLORS.point);
    }
  },
};

export const figures = {
  utm: [map, kSpec(false), difference],
  "utm-inverse": [map, kSpec(false)],
  "utm-facts": kSpec(true),
};
