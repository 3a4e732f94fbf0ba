// The lab's Web Worker: holds the lab's wasm module and the images in its
// memory, runs one request at a time and answers with plain objects whose
// big arrays are transferred (not copied) to the page.
//   request  { id, type, ...args }
//   answer   { id, ok: true, result } | { id, ok: false, error, trapped }
//   (filters and edges asked with `progress: true` also send
//   { id, progress, rows, of } while they run)
// A wasm trap (WebAssembly.RuntimeError) is reported as `trapped`: the page
// then drops this worker and starts a fresh one.

// The SIMD128 build (pkg-simd/, profile `fast`) where the browser validates
// a tiny SIMD module (every current one does), the scalar build (pkg/)
// otherwise or when pkg-simd/ is missing; scripts/build.sh writes both.
const SIMD_PROBE = new Uint8Array([
  0, 97, 115, 109, 1, 0, 0, 0, 1, 5, 1, 96, 0, 1, 123, 3, 2, 1, 0, 10, 10, 1, 8, 0, 65, 0, 253, 15, 253, 98, 11,
]);
const simd = WebAssembly.validate(SIMD_PROBE);
let lab;
let build = "scalar";
async function init(m) {
  await m.default();
  return m;
}
// literal import() specifiers: the build (scripts/assets.mjs) rewrites them to hashed names
const ready = (simd ? import("./pkg-simd/photogrammetry_lab.js").then(init).then((m) => ((build = "simd128"), m)) : Promise.reject(new Error("no SIMD")))
  .catch(() => import("./pkg/photogrammetry_lab.js").then(init))
  .then((m) => {
    lab = m;
  });
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

function imageInfo(img, transfer) {
  const grey = img.grey();
  transfer.push(grey.buffer);
  return {
    width: img.width(),
    height: img.height(),
    format: img.format(),
    colour: img.colour(),
    bits: img.bits(),
    maxValue: img.max_value(),
    grey,
  };
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

// Progress of the row-wise operators (filters, edges): when the page asks
// for it (`progress: true`), an 8-bit image is run in bands of rows, each
// with HALO rows of real neighbours above and below (the border policy acts
// only at the image's own edges), a { id, progress, rows, of } message after
// each band, and the rows each band owns put together: the numbers of one
// call over the whole image (tests/e2e/lab.test.mjs compares them at every
// pixel). Other images, and small ones, run in one call.

/** Rows of real neighbours above and below a band: enough for the largest kernel (15×15). */
const HALO = 7;
/** Rows a band has at least. */
const BAND_ROWS = 256;

/** The image's values as bytes when it is 8-bit (cached on it), else null. */
function bytesOf(img) {
  if (img.u8 === undefined) {
    const g = img.grey();
    img.u8 = g.every((v) => Number.isInteger(v) && v >= 0 && v <= 255) ? Uint8Array.from(g) : null;
  }
  return img.u8;
}

/** `run(image)` (→ layers) over `img`, by bands with progress messages when asked and possible. */
function banded(id, progress, img, run) {
  const [width, height] = [img.width(), img.height()];
  const n = Math.min(16, Math.floor(height / BAND_ROWS));
  const bytes = progress && n >= 2 ? bytesOf(img) : null;
  if (!bytes) return run(img);
  const parts = [];
  for (let k = 0; k < n; k++) {
    const [start, end] = [Math.floor((k * height) / n), Math.floor(((k + 1) * height) / n)];
    const [r0, r1] = [Math.max(0, start - HALO), Math.min(height, end + HALO)];
    const band = lab.image_from_u8(width, r1 - r0, bytes.subarray(r0 * width, r1 * width));
    try {
      parts.push({ start, end, r0, layers: run(band) });
    } finally {
      band.free();
    }
    self.postMessage({ id, progress: (k + 1) / n, rows: end, of: height });
  }
  // the rows each band owns, as the whole image's layers
  return parts[0].layers.map((first, li) => {
    const rows = [];
    let top = null;
    for (const p of parts) {
      const l = p.layers[li];
      for (let j = 0; j < l.height; j++) {
        const row = p.r0 + l.r0 + j;
        if (row < p.start || row >= p.end) continue;
        top ??= row;
        rows.push(l.data.subarray(j * l.width, (j + 1) * l.width));
      }
    }
    const data = new first.data.constructor(rows.length * first.width);
    rows.forEach((r, j) => data.set(r, j * first.width));
    // a reference-path layer is signed when any of its values is negative: in any band
    return { ...first, r0: top ?? 0, height: rows.length, signed: parts.some((p) => p.layers[li].signed), data };
  });
}

/** Förstner's map of image "a", kept so that a new threshold re-uses it. */
let forstnerKept = null;
/** How many Förstner maps this worker has computed (the page's tests read it). */
let forstnerMapRuns = 0;
function dropForstner() {
  forstnerKept?.free();
  forstnerKept = null;
}

const handlers = {
  load({ slot = "a", name, bytes }, transfer) {
    const img = lab.decode_image(name, new Uint8Array(bytes));
    put(slot, img);
    // what decoding did: the EXIF orientation and the reduction (decode.rs's Photo)
    return { ...imageInfo(img, transfer), photo: img.photo() };
  },
  /** A file's format, orientation and reduction from its header alone (the lab offers a reduction with it). */
  probe({ name, bytes }) {
    return lab.probe_image(name, new Uint8Array(bytes));
  },
  frame({ slot = "a" }, transfer) {
    const img = lab.scanned_frame();
    put(slot, img);
    return { ...imageInfo(img, transfer), truth: lab.scanned_frame_truth() };
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
  filter({ kernel, border, custom, divisor, progress }, transfer, id) {
    const layers = banded(id, progress, need("a"), (img) => lab.run_filter(img, kernel, border, custom, divisor));
    return { layers: layersOut(layers, transfer) };
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
  edges({ operator, border, progress }, transfer, id) {
    return { layers: layersOut(banded(id, progress, need("a"), (img) => lab.run_edges(img, operator, border)), transfer) };
  },
  forstner({ size, sigmaN, thresholdPx, qMin }, transfer) {
    const r = lab.run_forstner(need("a"), size, sigmaN, thresholdPx, qMin);
    layersOut(r.layers, transfer);
    return r;
  },
  moravec({ size, threshold }, transfer) {
    const r = lab.run_moravec(need("a"), size, threshold);
    layersOut(r.layers, transfer);
    return r;
  },
  correlation({ template, search, model, sameImage }, transfer) {
    const b = sameImage || !images.b ? need("a") : images.b;
    const r = lab.run_correlation(need("a"), Float64Array.from(template), b, Float64Array.from(search), model);
    layersOut(r.layers, transfer);
    return r;
  },
  resample({ kind, params, width, height }, transfer) {
    return { layers: layersOut(lab.run_resample(need("a"), kind, Float64Array.from(params), width, height), transfer) };
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
  raw({ slot = "a", width, height, bytes }) {
    put(slot, lab.image_from_u8(width, height, new Uint8Array(bytes)));
    return { width, height };
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
  const { id, type, ...args } = ev.data;
  try {
    await ready;
    const handler = handlers[type];
    if (!handler) throw new Error(`unknown request "${type}"`);
    const transfer = [];
    const t0 = performance.now();
    const result = handler(args, transfer, id);
    // ms: the time inside the worker (for npm run bench -- --lab)
    self.postMessage({ id, ok: true, result, ms: performance.now() - t0 }, transfer);
  } catch (e) {
    const trapped = e instanceof WebAssembly.RuntimeError;
    self.postMessage({ id, ok: false, trapped, error: String(e?.message ?? e) });
  }
};
