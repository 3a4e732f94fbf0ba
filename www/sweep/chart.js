// The sweep's chart (docs/sweeps.md): uPlot (MIT, about 22 KB gzipped, canvas,
// axes, ticks and hover built in), loaded with this module only when a sweep
// opens. Colours are the figures' palettes (figures/draw.js, contrast-tested in
// both themes); each series also has its own dash, so no colour is needed to
// tell them apart. Marks drawn over uPlot's canvas: the worked example's value
// (dashed line), the point in use (solid line) and each point the solver
// refused (× at the foot, its message in the readout).

import uPlot from "uplot";
import { fmt, PALETTES, pageTheme } from "../figures/draw.js";

/** Heights of the plot area by width (a phone's is lower). */
const HEIGHT_WIDE = 320;
const HEIGHT_NARROW = 240;
const NARROW = 520;
/** Series strokes, in order: palette colour names and dashes. */
const STROKES = Object.freeze([
  { color: "pixelSystem", dash: [] },
  { color: "imageSystem", dash: [7, 4] },
  { color: "point", dash: [2, 3] },
  { color: "green", dash: [10, 3, 2, 3] },
]);
/** The longest y axis label: on a wide chart, and on a phone's (its axis is 240 px tall: about 24 characters). */
const AXIS_LABEL_MAX = 34;
const AXIS_LABEL_NARROW = 24;
const FONT = '12px system-ui, -apple-system, "Segoe UI", Roboto, sans-serif';

/** The stroke of series i: { color (a palette key), dash }. */
export const strokeOf = (i) => STROKES[i % STROKES.length];

/** A palette colour for the page's theme. */
export function colour(name) {
  return PALETTES[pageTheme() === "dark" ? "dark" : "light"][name];
}

/** Axis texts: "Flying height H (m)". */
const withUnit = (label, unit) => (unit ? `${label} (${unit})` : label);

/**
 * The units of the plotted results in order of first use: the first on the
 * left axis, the second on the right; a third is not plotted (the caller
 * says so).
 */
export function axesOf(series) {
  const units = [];
  for (const s of series) if (!units.includes(groupOf(s))) units.push(groupOf(s));
  return units.slice(0, 2);
}

/** The axis group of a series: its unit, or what the caller set (`group`: results of one unit but far apart in size). */
export const groupOf = (s) => s.group ?? s.unit ?? "";

/**
 * Makes the chart in `host`.
 * @param {HTMLElement} host
 * @param {{ x: { label, unit, seed }, series: Array<{ key, label, unit }>, onCursor: (i: number|null) => void, onPick: (i: number) => void }} spec
 * @returns the chart: setData(xs, ys, errors, current), select(i), destroy(), canvas(), theme()
 */
export function makeChart(host, spec) {
  const units = axesOf(spec.series);
  const scaleOf = (s) => (units.indexOf(groupOf(s)) === 1 ? "y2" : "y");
  let xs = [];
  let errors = [];
  let current = null;
  const width = () => Math.max(260, Math.floor(host.clientWidth));
  const height = () => (width() < NARROW ? HEIGHT_NARROW : HEIGHT_WIDE);
  /** One result's name and unit; several (the legend names them): the unit, else "value". */
  const axisLabel = (group) => {
    const members = spec.series.filter((s) => groupOf(s) === group);
    const names = members.map((s) => s.label);
    const unit = members[0]?.unit ?? "";
    const one = withUnit(names[0], unit);
    const max = width() < NARROW ? AXIS_LABEL_NARROW : AXIS_LABEL_MAX;
    if (names.length === 1 && one.length <= max) return one;
    return unit || (names.length === 1 ? `${names[0].slice(0, max - 1)}…` : "value");
  };

  function options() {
    const c = (name) => colour(name);
    const axis = {
      stroke: c("ink"),
      font: FONT,
      labelFont: `600 ${FONT}`,
      grid: { stroke: c("grid"), width: 1 },
      ticks: { stroke: c("muted"), width: 1, size: 5 },
      values: (u, splits) => splits.map((v) => fmt(v, 6, "")),
    };
    const axes = [
      { ...axis, label: withUnit(spec.x.label, spec.x.unit), labelSize: 22 },
      { ...axis, scale: "y", label: axisLabel(units[0]), labelSize: 22, size: 62 },
    ];
    if (units.length > 1) axes.push({ ...axis, scale: "y2", side: 1, label: axisLabel(units[1]), labelSize: 22, size: 62, grid: { show: false } });
    return {
      width: width(),
      height: height(),
      legend: { show: false },
      scales: { x: { time: false }, y: { auto: true }, y2: { auto: true } },
      cursor: {
        drag: { x: false, y: false },
        points: { size: 9, width: 2 },
        focus: { prox: -1 },
      },
      axes,
      series: [
        { label: spec.x.label },
        ...spec.series.map((s, i) => ({
          label: withUnit(s.label, s.unit),
          scale: scaleOf(s),
          stroke: c(strokeOf(i).color),
          dash: strokeOf(i).dash,
          width: 2,
          spanGaps: false,
          points: { show: (u) => xs.length <= 60, size: 5, fill: c("background") },
        })),
      ],
      hooks: {
        setCursor: [(u) => spec.onCursor(u.cursor.idx ?? null)],
        draw: [(u) => drawMarks(u)],
      },
    };
  }

  /** The worked example's value, the point in use and the refused points, over the plot. */
  function drawMarks(u) {
    const { ctx } = u;
    const { left, top, width: w, height: h } = u.bbox;
    const dpr = uPlot.pxRatio;
    const xAt = (v) => u.valToPos(v, "x", true);
    const inside = (px) => px >= left - 0.5 && px <= left + w + 0.5;
    ctx.save();
    ctx.font = `${Math.round(11 * dpr)}px system-ui, sans-serif`;
    ctx.textBaseline = "top";
    const vline = (v, color, dash, text, align) => {
      const px = xAt(v);
      if (!Number.isFinite(v) || !inside(px)) return;
      ctx.strokeStyle = color;
      ctx.lineWidth = 1.5 * dpr;
      ctx.setLineDash(dash.map((d) => d * dpr));
      ctx.beginPath();
      ctx.moveTo(px, top);
      ctx.lineTo(px, top + h);
      ctx.stroke();
      ctx.setLineDash([]);
      ctx.fillStyle = color;
      ctx.textAlign = px > left + w * 0.75 ? "right" : "left";
      ctx.fillText(text, px + (ctx.textAlign === "right" ? -4 : 4) * dpr, top + (align === "low" ? 16 : 3) * dpr);
    };
    vline(spec.x.seed, colour("highlight"), [5, 4], "worked example", "high");
    if (current !== null && current !== spec.x.seed) vline(current, colour("muted"), [], "shown", "low");
    // × at the foot of each refused point
    ctx.strokeStyle = colour("red");
    ctx.lineWidth = 2 * dpr;
    const s = 4 * dpr;
    const y = top + h - 8 * dpr;
    xs.forEach((x, i) => {
      if (!errors[i]) return;
      const px = xAt(x);
      if (!inside(px)) return;
      ctx.beginPath();
      ctx.moveTo(px - s, y - s);
      ctx.lineTo(px + s, y + s);
      ctx.moveTo(px + s, y - s);
      ctx.lineTo(px - s, y + s);
      ctx.stroke();
    });
    ctx.restore();
  }

  let data = [[], ...spec.series.map(() => [])];
  let u = null;
  /** (Re)makes the uPlot: its options (colours, the axis labels' length) are read when it is made. */
  const build = () => {
    u?.destroy();
    u = new uPlot(options(), data, host);
    u.over.addEventListener("click", () => {
      if (u.cursor.idx != null) spec.onPick(u.cursor.idx);
    });
  };
  build();
  const resize = new ResizeObserver(() => {
    // across the phone width the axis labels change length: made again; otherwise resized
    if (u.height !== height()) build();
    else if (u.width !== width()) u.setSize({ width: width(), height: height() });
  });
  resize.observe(host);

  return {
    /** New numbers: xs, ys per series (null = a gap), errors per point (a message or null), the value in use. */
    setData(nextXs, ys, nextErrors, value) {
      xs = nextXs;
      errors = nextErrors;
      current = value;
      data = [xs, ...spec.series.map((s) => ys[s.key])];
      u.setData(data);
    },
    /** The value in use changed (the slider): marks redrawn. */
    setCurrent(value) {
      current = value;
      u.redraw(false, false);
    },
    /** Puts the hover cursor on point i (the keyboard's and the slider's point). */
    select(i) {
      if (i === null || !xs.length) {
        u.setCursor({ left: -10, top: -10 });
        return;
      }
      const k = spec.series.findIndex((s) => data[spec.series.indexOf(s) + 1][i] != null);
      const sc = k >= 0 ? scaleOf(spec.series[k]) : "y";
      const yv = k >= 0 ? data[k + 1][i] : null;
      const top = yv == null ? u.bbox.height / uPlot.pxRatio / 2 : u.valToPos(yv, sc);
      u.setCursor({ left: u.valToPos(xs[i], "x"), top });
    },
    /** Rebuilt in the page's theme (colours are read when uPlot draws). */
    theme() {
      build();
    },
    /** The chart's canvas (axes, ticks, lines and marks: what the PNG holds). */
    canvas: () => u.ctx.canvas,
    destroy() {
      resize.disconnect();
      u.destroy();
    },
  };
}
