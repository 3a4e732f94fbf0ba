// The lab's Web Worker: holds the lab's wasm module and the images in its
// memory, runs one request at a time and answers with plain objects whose
// big arrays are transferred (not copied) to the page.
//   request  { id, type, ...args }
//   answer   { id, ok: true, result } | { id, ok: false, error, trapped }
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
    return imageInfo(img, transfer);
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
  filter({ kernel, border, custom, divisor }, transfer) {
    return { layers: layersOut(lab.run_filter(need("a"), kernel, border, custom, divisor), transfer) };
  },
  checkKernel({ custom, divisor }) {
    return lab.check_custom_kernel(custom, divisor);
  },
  // the live threshold: the map once (forstnerMaps), then points for any
  // threshold from the kept map (forstnerPoints), without recomputing it
  forstnerMaps({ size }, transfer) {
    dropForstner();
    forstnerKept = lab.forstner_maps(need("a"), size);
    forstnerMapRuns++;
    return { layers: layersOut(forstnerKept.layers(), transfer), size, mapRuns: forstnerMapRuns };
  },
  forstnerPoints({ sigmaN, thresholdPx, qMin }) {
    if (!forstnerKept) throw new Error("threshold_px: no Förstner map is kept (press Run first)");
    const t0 = performance.now();
    const points = forstnerKept.points(sigmaN, thresholdPx, qMin);
    return { points, thresholdPx, size: forstnerKept.size(), mapRuns: forstnerMapRuns, pointsMs: performance.now() - t0 };
  },
  edges({ operator, border }, transfer) {
    return { layers: layersOut(lab.run_edges(need("a"), operator, border), transfer) };
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
  trap() {
    lab.trap_for_tests();
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
    const result = handler(args, transfer);
    // ms: the time inside the worker (for npm run bench -- --lab)
    self.postMessage({ id, ok: true, result, ms: performance.now() - t0 }, transfer);
  } catch (e) {
    const trapped = e instanceof WebAssembly.RuntimeError;
    self.postMessage({ id, ok: false, trapped, error: String(e?.message ?? e) });
  }
};
