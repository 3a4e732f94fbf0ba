// The lab's Web Worker: holds the lab's wasm module and the images in its
// memory, runs one request at a time and answers with plain objects whose
// big arrays are transferred (not copied) to the page.
//   request  { id, type, ...args }
//   answer   { id, ok: true, result } | { id, ok: false, error, trapped }
// The same file runs as the lab's main worker (the photo, every request)
// and as the pool's workers (tiles.js: `region`, one band of an operator;
// `paint`), and the main worker paints the previews (`preview`).
// A wasm trap (WebAssembly.RuntimeError) is reported as `trapped`: the page
// then drops this worker and starts a fresh one.

import { SIGNED_NEGATIVE, SIGNED_POSITIVE } from "../colour-scales.js";

// The SIMD128 build (pkg-simd/, profile `fast`, JPEG its only decoder)
// where the browser validates a tiny SIMD module (every current one does),
// the scalar build (pkg/, every decoder) otherwise or when pkg-simd/ is
// missing; scripts/build.sh writes both. The SIMD build has the scalar
// build decode the other formats (decoders()).
const SIMD_PROBE = new Uint8Array([
  0, 97, 115, 109, 1, 0, 0, 0, 1, 5, 1, 96, 0, 1, 123, 3, 2, 1, 0, 10, 10, 1, 8, 0, 65, 0, 253, 15, 253, 98, 11,
]);
const simd = WebAssembly.validate(SIMD_PROBE);
let lab;
let wasm;
let build = "scalar";
async function init(m) {
  wasm = await m.default();
  return m;
}
// literal import() specifiers: the build (scripts/assets.mjs) rewrites them to hashed names
const ready = (simd ? import("./pkg-simd/photogrammetry_lab.js").then(init).then((m) => ((build = "simd128"), m)) : Promise.reject(new Error("no SIMD")))
  .catch(() => import("./pkg/photogrammetry_lab.js").then(init))
  .then((m) => {
    lab = m;
  });
/**
 * The scalar build as the decoders of the SIMD build, which decodes JPEG
 * only (scripts/build.sh): loaded when a photo of another format is first
 * opened (a lab visit downloads them only then).
 */
let decoderModule = null;
function decoders() {
  decoderModule ??= import("./pkg/photogrammetry_lab.js").then(async (m) => {
    await m.default();
    return m;
  });
  return decoderModule;
}

/** File `bytes` decoded as image "a" or "b" of this build (by the decoders' build when this one has not the format's decoder). */
async function decoded(name, bytes) {
  if (lab.decodes_here(bytes)) return lab.decode_image(name, bytes);
  const d = await decoders();
  const img = d.decode_image(name, bytes);
  try {
    const p = img.photo();
    return lab.image_from_decoded(img.width(), img.height(), img.grey(), img.format(), img.colour(), img.bits(), img.max_value(),
      Float64Array.from([p.orientation, p.photoWidth, p.photoHeight, p.factor]));
  } finally {
    img.free();
  }
}

/** A wasm module whose one export, `trap`, executes `unreachable`. */
const UNREACHABLE = new Uint8Array([
  0, 97, 115, 109, 1, 0, 0, 0, 1, 4, 1, 96, 0, 0, 3, 2, 1, 0, 7, 8, 1, 4, 116, 114, 97, 112, 0, 0, 10, 5, 1, 3, 0, 0, 11,
]);
/** The images by slot: "a" (the open photo), "b" (the second photo of a pair). */
const images = {};

function layersOut(layers, transfer) {
  for (const l of layers) transfer.push(l.data.buffer);
  return layers;
}

/**
 * What the page gets of an opened image: its size and kind, its grey
 * values, its bytes when it is 8-bit (the pool's bands are cut from them:
 * tiles.js), and the image painted (the grey stretch) as an ImageBitmap.
 */
async function imageInfo(img, transfer) {
  const grey = img.grey();
  const bytes = eightBit(img, grey);
  // not 8-bit: its levels (a colour photo's n = 299R+587G+114B over 1000), found once here, cut into the pool's bands (tiles.js)
  const lv = bytes ? undefined : lab.image_levels(img);
  const base = await painted(grey, img.width(), false);
  transfer.push(grey.buffer, base.bitmap);
  if (lv) transfer.push(lv.levels.buffer);
  return {
    width: img.width(),
    height: img.height(),
    format: img.format(),
    colour: img.colour(),
    bits: img.bits(),
    maxValue: img.max_value(),
    grey,
    bytes: bytes && bytes.slice(),
    levels: lv?.levels,
    scale: lv?.scale,
    bitmap: base.bitmap,
  };
}

/** A band of a photo that is not 8-bit: its levels over `scale` (tiles.js cuts them from the photo's, found once), else its grey values. */
function band(width, height, { values, levels, scale, bits, maxValue }) {
  if (levels) return lab.image_from_levels(width, height, new Float32Array(levels), scale, bits, maxValue);
  return lab.image_from_grey(width, height, new Float64Array(values), bits, maxValue);
}

/** Keeps the image's values as bytes with it when they are 8-bit (`grey`: its values); returns them or null. */
function eightBit(img, grey) {
  if (img.u8 === undefined) img.u8 = grey.every((v) => Number.isInteger(v) && v >= 0 && v <= 255) ? Uint8Array.from(grey) : null;
  return img.u8;
}

function need(slot) {
  const img = images[slot];
  if (!img) throw new Error(`image: no image is open${slot === "b" ? " as the second photo" : ""}`);
  return img;
}

function put(slot, img) {
  images[slot]?.free();
  images[slot] = img;
  if (slot === "a") dropForstner();
}

/** The operators that run by bands and previews, by request type: (image, args) → { layers, points? }. */
const OPS = {
  filter: (img, a) => ({ layers: lab.run_filter(img, a.kernel, a.border, a.custom, a.divisor) }),
  edges: (img, a) => ({ layers: lab.run_edges(img, a.operator, a.border) }),
  forstner: (img, a) => lab.run_forstner(img, a.size, a.sigmaN, a.thresholdPx, a.qMin),
  moravec: (img, a) => lab.run_moravec(img, a.size, a.threshold),
  // (the map's layers only: previews; the kept map of the live threshold is the main worker's)
  forstnerMaps: (img, a) => {
    const kept = lab.forstner_maps(img, a.size);
    try {
      return { layers: kept.layers() };
    } finally {
      kept.free();
    }
  },
};

/** A result whose layers' buffers are transferred. */
function out(r, transfer) {
  layersOut(r.layers, transfer);
  return r;
}

/**
 * A result of an image part cut to `own` [c, r, w, h] (the part's
 * coordinates) and placed at `at` [c, r] in the image: each layer's pixels
 * inside `own`, the points inside `own` (6 numbers each: c, r, …).
 */
function cut(r, own, at) {
  const [oc, or, ow, oh] = own;
  const layers = r.layers.map((l) => {
    const [c0, r0] = [Math.max(l.c0, oc), Math.max(l.r0, or)];
    const [c1, r1] = [Math.min(l.c0 + l.width, oc + ow), Math.min(l.r0 + l.height, or + oh)];
    const [w, h] = [Math.max(0, c1 - c0), Math.max(0, r1 - r0)];
    let data;
    if (w === l.width) {
      // whole rows (a band): a view of them, no copy (its buffer is transferred)
      data = l.data.subarray((r0 - l.r0) * l.width, (r0 - l.r0 + h) * l.width);
    } else {
      data = new l.data.constructor(w * h);
      for (let j = 0; j < h; j++) {
        const from = (r0 + j - l.r0) * l.width + (c0 - l.c0);
        data.set(l.data.subarray(from, from + w), j * w);
      }
    }
    return { ...l, c0: c0 + at[0], r0: r0 + at[1], width: w, height: h, data };
  });
  if (!r.points) return { ...r, layers };
  const p = r.points;
  const points = new Float64Array(p.length);
  let n = 0;
  for (let i = 0; i < p.length; i += 6) {
    const [c, rr] = [p[i], p[i + 1]];
    if (c < oc || c >= oc + ow || rr < or || rr >= or + oh) continue;
    points.set(p.subarray(i, i + 6), n);
    points[n] += at[0];
    points[n + 1] += at[1];
    n += 6;
  }
  return { ...r, layers, points: points.slice(0, n) };
}

/** The preview of output rows of request `op` (worker `preview` with `rows`): output box `rect`, each layer painted. */
async function rowsPreview(op, args, rect, ranges, transfer) {
  const [c, r, w, h] = rect;
  const handler = handlers[op];
  if (!handler) throw new Error(`op: "${String(op).slice(0, 40)}" has no preview`);
  const whole = handler({ ...args, row0: r, row1: r + h }, []);
  const layers = [];
  for (const l of cut(whole, [c, r, w, h], [0, 0]).layers) {
    const range = ranges?.[l.name];
    const p = await painted(l.data, l.width, false, range ? Float64Array.from(range) : null);
    transfer.push(p.bitmap, l.data.buffer);
    layers.push({ ...p, name: l.name, rect: [l.c0, l.r0, l.width, l.height], values: l.data });
  }
  return { layers, rect };
}

/** The signed scale's end colours as paint_layer takes them (colour-scales.js). */
const ENDS = Uint8Array.from([...SIGNED_NEGATIVE, ...SIGNED_POSITIVE]);
/** Rows a painting puts into its canvas at a time (the RGBA of one part in wasm memory). */
const PAINT_PIXELS = 1 << 20;

/**
 * Values painted by the wasm (paint_layer): an ImageBitmap and the scale
 * (`whole`: [min, max] of the whole layer `data` is a part of, else
 * `data`'s own). Large layers part by part (on the whole layer's scale)
 * into an OffscreenCanvas, so that their RGBA is never whole in wasm memory.
 */
async function painted(data, width, signed, whole = null) {
  const height = data.length / width;
  if (typeof OffscreenCanvas === "undefined" || data.length <= PAINT_PIXELS) {
    const { image, scale } = lab.paint_layer(data, width, Boolean(signed), ENDS, whole ?? undefined);
    return { bitmap: await createImageBitmap(image), scale };
  }
  const range = whole ?? lab.layer_range(data);
  const canvas = new OffscreenCanvas(width, height);
  const ctx = canvas.getContext("2d");
  const rows = Math.max(1, Math.floor(PAINT_PIXELS / width));
  let scale = null;
  for (let r = 0; r < height; r += rows) {
    const part = data.subarray(r * width, Math.min(height, r + rows) * width);
    const p = lab.paint_layer(part, width, Boolean(signed), ENDS, range);
    ctx.putImageData(p.image, 0, r);
    scale = p.scale;
  }
  return { bitmap: canvas.transferToImageBitmap(), scale };
}

/** Parts of layers being painted on several workers (paintPart), by "job part": { job, data, width }. */
const paintParts = new Map();

/** The pool's bands of Förstner maps kept for the live threshold, by band: { job, kept, own, at }. */
const keptBands = new Map();

/** Förstner's map of image "a", kept so that a new threshold re-uses it. */
let forstnerKept = null;
/** How many Förstner maps this worker has computed (the page's tests read it). */
let forstnerMapRuns = 0;
function dropForstner() {
  forstnerKept?.free();
  forstnerKept = null;
}

const handlers = {
  async load({ slot = "a", name, bytes }, transfer) {
    const img = await decoded(name, new Uint8Array(bytes));
    put(slot, img);
    // what decoding did: the EXIF orientation and the reduction (decode.rs's Photo)
    return { ...(await imageInfo(img, transfer)), photo: img.photo() };
  },
  /** A file's format, orientation and reduction from its header alone (the lab offers a reduction with it). */
  async probe({ name, bytes }) {
    const b = new Uint8Array(bytes);
    return (lab.decodes_here(b) ? lab : await decoders()).probe_image(name, b);
  },
  async frame({ slot = "a" }, transfer) {
    const img = lab.scanned_frame();
    put(slot, img);
    return { ...(await imageInfo(img, transfer)), truth: lab.scanned_frame_truth() };
  },
  neighbourhood({ slot = "a", c, r, w, h, border }) {
    return need(slot).neighbourhood(c, r, w, h, border);
  },
  size({ slot = "a" }) {
    const img = need(slot);
    return { width: img.width(), height: img.height() };
  },
  window({ slot = "a", c, r, w, h }) {
    return need(slot).window(c, r, w, h);
  },
  filter(args, transfer) {
    return out(OPS.filter(need("a"), args), transfer);
  },
  checkKernel({ custom, divisor }) {
    return lab.check_custom_kernel(custom, divisor);
  },
  // the live threshold: the map once (forstnerMaps), then points for any
  // threshold from the kept map (forstnerPoints), without recomputing it
  forstnerMaps({ size, sigmaN }, transfer) {
    dropForstner();
    forstnerKept = lab.forstner_maps(need("a"), size);
    forstnerMapRuns++;
    // the threshold chosen for this photo (w among the strongest 0.1 %: ops::auto_threshold)
    const auto = sigmaN > 0 ? forstnerKept.auto_threshold(sigmaN) : null;
    return { layers: layersOut(forstnerKept.layers(), transfer), size, mapRuns: forstnerMapRuns, auto };
  },
  forstnerPoints({ sigmaN, thresholdPx, qMin }) {
    if (!forstnerKept) throw new Error("threshold_px: no Förstner map is kept (press Run first)");
    const t0 = performance.now();
    const points = forstnerKept.points(sigmaN, thresholdPx, qMin);
    return { points, thresholdPx, size: forstnerKept.size(), mapRuns: forstnerMapRuns, pointsMs: performance.now() - t0 };
  },
  edges(args, transfer) {
    return out(OPS.edges(need("a"), args), transfer);
  },
  forstner(args, transfer) {
    return out(OPS.forstner(need("a"), args), transfer);
  },
  moravec(args, transfer) {
    return out(OPS.moravec(need("a"), args), transfer);
  },
  /**
   * One band of an operator (tiles.js): `bytes` (8-bit, `width × height`),
   * or `values` (grey values of a photo with `bits`, `maxValue` that is not
   * 8-bit), are the band with its halo, `own` [c, r, w, h] the part of it whose
   * pixels this band answers for, `at` [c, r] where the band lies in the
   * image. Answers as `type` does for the whole image, cut to `own` and
   * placed in the image.
   */
  region({ op, args, width, height, bytes, values, levels, scale, bits, maxValue, own, at, keep = null }, transfer) {
    const img = bytes ? lab.image_from_u8(width, height, new Uint8Array(bytes)) : band(width, height, { values, levels, scale, bits, maxValue });
    try {
      if (op === "forstnerMaps" && keep) {
        // the band's map kept for the live threshold (keptPoints), the older jobs' dropped
        for (const [k, b] of keptBands) {
          if (b.job !== keep.job) {
            b.kept.free();
            keptBands.delete(k);
          }
        }
        const kept = lab.forstner_maps(img, args.size);
        keptBands.get(keep.band)?.kept.free();
        keptBands.set(keep.band, { job: keep.job, kept, own, at });
        return out(cut({ layers: kept.layers() }, own, at), transfer);
      }
      const run = OPS[op];
      if (!run) throw new Error(`op: "${String(op).slice(0, 40)}" does not run by bands`);
      return out(cut(run(img, args), own, at), transfer);
    } finally {
      img.free();
    }
  },
  /**
   * Points for a threshold from the bands' kept maps of Förstner job `job`
   * (region with `keep`): `[{ band, points }]`, each band's points in its
   * own rows, placed in the image.
   */
  keptPoints({ job, sigmaN, thresholdPx, qMin }) {
    const out = [];
    for (const [band, b] of keptBands) {
      if (b.job !== job) continue;
      out.push({ band, points: cut({ layers: [], points: b.kept.points(sigmaN, thresholdPx, qMin) }, b.own, b.at).points });
    }
    return out;
  },
  /** The photo's own Förstner threshold from its whole `w` layer (bands: forstner_auto_threshold). */
  forstnerAuto({ size, sigmaN, w }) {
    return sigmaN > 0 ? lab.forstner_auto_threshold(need("a"), size, w, sigmaN) : null;
  },
  /**
   * A layer painted (wasm: paint_layer) as an ImageBitmap: `{ bitmap,
   * scale }`; `data` its values (Float32Array or Float64Array), `width`
   * values a row; `signed`: the diverging scale.
   */
  async paint({ data, width, signed }, transfer) {
    const p = await painted(data, width, signed);
    transfer.push(p.bitmap);
    return p;
  },
  /**
   * A part of a large layer painted on several pool workers (tiles.js):
   * first `{ job, part, data, width }` (kept here) → its [min, max], then
   * `{ job, part, signed, range }` (the whole layer's range) → `{ bitmap,
   * scale }`.
   */
  async paintPart({ job, part, data, width, signed, range }, transfer) {
    const key = `${job} ${part}`;
    if (data) {
      // (parts of paintings long gone: a cancelled one never asks for its second step)
      for (const [k, p] of paintParts) if (p.job < job - 8) paintParts.delete(k);
      paintParts.set(key, { job, data, width });
      return Array.from(lab.layer_range(data));
    }
    const p = paintParts.get(key);
    if (!p) throw new Error("part: this part of the layer is not here (paint it again)");
    paintParts.delete(key);
    const out = await painted(p.data, p.width, signed, Float64Array.from(range));
    transfer.push(out.bitmap);
    return out;
  },
  /**
   * A preview of `op` (a band type of OPS) on image "a": the box `rect`
   * [c, r, w, h] at full resolution, read with the operator's halo of real
   * neighbours around it (op_halo), so its pixels are the whole result's
   * (an 8-bit photo's bytes, a colour photo's greys as they are: every
   * operator here has its fast path on both).
   * Answers the layer named `name` (else `fallback`, else the first)
   * painted: `{ bitmap, scale, name, rect, values }`, `rect` the image
   * pixels it covers, `values` its numbers. `rows` (resampling): `op` is
   * a request of output rows (`row0`, `row1`: its handler here, as the
   * pool's bands ask it), `rect` a box of its output, each layer painted on
   * `ranges[its name]` ([lo, hi]: the shown result's, else its own):
   * `{ layers: [{ bitmap, scale, name, rect, values }] }`.
   */
  async preview({ op, args, rect, name = null, fallback = null, rows = false, ranges = null }, transfer) {
    if (rows) return rowsPreview(op, args, rect, ranges, transfer);
    const run = OPS[op];
    if (!run) throw new Error(`op: "${String(op).slice(0, 40)}" has no preview`);
    const a = need("a");
    const [W, H] = [a.width(), a.height()];
    const halo = lab.op_halo(op, args) ?? 0;
    const [c0, r0] = [Math.max(0, rect[0] - halo), Math.max(0, rect[1] - halo)];
    const [c1, r1] = [Math.min(W, rect[0] + rect[2] + halo), Math.min(H, rect[1] + rect[3] + halo)];
    // (a photo that is not 8-bit: its greys as they are — a colour photo's take the fast paths, ops::Levels)
    const img = lab.crop_image(a, c0, r0, c1 - c0, r1 - r0, false);
    try {
      const r = cut(run(img, args), [rect[0] - c0, rect[1] - r0, rect[2], rect[3]], [c0, r0]);
      const layer = r.layers.find((l) => l.name === name) ?? r.layers.find((l) => l.name === fallback) ?? r.layers[0];
      if (!layer || !layer.width || !layer.height) return null;
      const p = await painted(layer.data, layer.width, layer.signed);
      transfer.push(p.bitmap, layer.data.buffer);
      return { ...p, name: layer.name, rect: [layer.c0, layer.r0, layer.width, layer.height], values: layer.data };
    } finally {
      img.free();
    }
  },
  /** Bytes of wasm memory this worker's instance holds now. */
  memory() {
    return { bytes: wasm?.memory?.buffer?.byteLength ?? 0 };
  },
  correlation({ template, search, model, sameImage }, transfer) {
    const b = sameImage || !images.b ? need("a") : images.b;
    const r = lab.run_correlation(need("a"), Float64Array.from(template), b, Float64Array.from(search), model);
    layersOut(r.layers, transfer);
    return r;
  },
  /** `row0`, `row1`: a band of the output's rows (the pool's bands: tiles.js), else all. */
  resample({ kind, params, width, height, row0, row1 }, transfer) {
    return { layers: layersOut(lab.run_resample(need("a"), kind, Float64Array.from(params), width, height, row0, row1), transfer) };
  },
  /** Rows of real neighbours a band of `op` needs (wasm op_halo; null: it does not run by bands of input rows). */
  halo({ op, args }) {
    return lab.op_halo(op, args) ?? null;
  },
  resamplePosition({ kind, params, width, height, c, r }) {
    return lab.resample_position(need("a"), kind, Float64Array.from(params), width, height, c, r);
  },
  /**
   * The exact value of layer `layer` of operator `op` (its request's
   * `args`) at pixel (c, r): the reference function on the pixel's window,
   * the worked example's number (wasm exact_at); null where there is none.
   */
  exact({ op, args, layer, c, r }) {
    const b = args?.sameImage || !images.b ? need("a") : images.b;
    return lab.exact_at(need("a"), b, op, args, layer, c, r) ?? null;
  },
  boundary({ threshold, c, r }, transfer) {
    const out = lab.run_boundary(need("a"), threshold, c, r);
    layersOut(out.layers, transfer);
    return out;
  },
  fiducials({ approx }) {
    return lab.run_fiducials(need("a"), Float64Array.from(approx));
  },
  refineMark({ c, r }) {
    return lab.refine_mark(need("a"), c, r);
  },
  fitMarks({ measured }) {
    return lab.fit_fiducial_marks(Float64Array.from(measured));
  },
  /** A photo that is not 8-bit as image "a" of a pool worker (its resampling bands: tiles.js). */
  grey({ width, height, values, levels, scale, bits, maxValue }) {
    put("a", band(width, height, { values, levels, scale, bits, maxValue }));
    return { width, height };
  },
  raw({ slot = "a", width, height, bytes }) {
    const img = lab.image_from_u8(width, height, new Uint8Array(bytes));
    img.u8 = new Uint8Array(bytes);
    put(slot, img);
    return { width, height, bytes: img.u8.slice() };
  },
  /**
   * The tests' trap (lab.js trapForTests): a wasm `unreachable` executed in
   * this worker, a WebAssembly.RuntimeError as a trap of the lab's module
   * throws, so that the page's recovery (a fresh worker, the photo put back)
   * runs as after a real one. The lab's module has no trapping export (its
   * trap_for_tests is in the tests' builds only: lab/tests/web_lab.rs traps
   * an instance of it and shows a fresh one working).
   */
  trap() {
    new WebAssembly.Instance(new WebAssembly.Module(UNREACHABLE)).exports.trap();
  },
  /** Which build runs: "simd128" or "scalar", and whether the browser has SIMD. */
  engine() {
    return { build, simd };
  },
};

self.onmessage = async (ev) => {
  const { id, type, spare, ...args } = ev.data;
  try {
    await ready;
    const handler = handlers[type];
    if (!handler) throw new Error(`unknown request "${type}"`);
    const transfer = [];
    const t0 = performance.now();
    // the page's spare buffers for this request's layers (tiles.js: bands); those not used go back
    if (spare) lab.spare_buffers(spare);
    const result = await handler(args, transfer, id);
    if (spare) {
      result.spare = Array.from(lab.spare_buffers([]));
      transfer.push(...result.spare);
    }
    // ms: the time inside the worker (for npm run bench -- --lab)
    self.postMessage({ id, ok: true, result, ms: performance.now() - t0 }, transfer);
  } catch (e) {
    const trapped = e instanceof WebAssembly.RuntimeError;
    self.postMessage({ id, ok: false, trapped, error: String(e?.message ?? e) });
  }
};
