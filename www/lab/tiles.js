// Image-wide operators over several workers by bands of rows, on any host
// (no cross-origin isolation, no shared memory): the page keeps the open
// photo's 8-bit bytes (or its grey values, when it is not 8-bit: a colour
// photo's BT.601 greys), cuts them into bands with their halo (rows of real
// neighbours above and below, as many as the operator needs: the wasm's
// op_halo; so the border policy acts only at the image's own edges and a
// window near a band's edge sees what it sees in the whole image),
// transfers each band's bytes to a pool worker (www/lab/worker.js,
// `region`), and puts the rows each band owns together into the single
// worker's layers and points: the same numbers at every pixel
// (tests/e2e/lab_tiles.test.mjs).
//  - Förstner's map (the live threshold): each band keeps its own map in its
//    worker, a new threshold asks every band for the points in its rows,
//    and the photo's own threshold is found once over the whole w layer on
//    the main worker (forstner_auto_threshold).
//  - Resampling: bands of output rows; each pool worker holds the whole
//    photo (sent once per photo).
// More bands than workers: a worker that is done takes the next band
// (progress after each; a cancel drops the bands not yet started and stops
// the running ones at once, without touching the lab's main worker and its
// photo). The pool paints layers too, and previews run on the main worker
// meanwhile. No band takes fresh memory once the first have run: a band's
// input is cut into a buffer a worker gave back, its layers are copied out
// of wasm into spare buffers that fit them, and the whole layers (and the
// boundary's, on the main worker: SPARED) reuse the released ones — a fresh
// buffer costs its pages on first write, ~10 µs a 4 KiB page here.

/** A band has about this many pixels (several bands a worker: progress, balance, a quick cancel). */
const BAND_PIXELS = 1 << 21;
/** Layers with more pixels are painted by bands on every pool worker. */
const PAINT_SPLIT = 1 << 21;
/** Buffers of bands' layers kept for the next bands (2 workers × 4 layers). */
const SPARE = 8;
/** Whole layers the page has released (replaced results), kept to carry the next result's (2 results × 2 layers). */
const FREE = 4;
/** Bands a pool worker has sent to it at once (Tiles.lanes). */
const LANES = 2;
/**
 * Requests of the main worker whose whole-image layers are carried by a
 * released whole layer (sent as its spare buffer: no fresh pages) and are
 * released in turn (Tiles.spareFor, Tiles.adopt).
 */
export const SPARED = new Set(["boundary"]);
/** Images with fewer pixels run on the main worker whole (bands would cost more than they save). */
export const MIN_PIXELS = 1 << 19;

/** Requests the pool runs by bands of input rows (the others are one call on the main worker). */
const BANDED = new Set(["filter", "edges", "forstner", "forstnerMaps", "moravec"]);

/**
 * The bands of `height` rows for `n` workers: [start, end) row ranges,
 * about BAND_PIXELS each (`width` a row), at least `n`, each at least
 * `minRows` rows.
 */
export function bandsOf(width, height, n, minRows = 16) {
  const want = Math.max(n, Math.ceil((width * height) / BAND_PIXELS));
  const k = Math.max(1, Math.min(want, Math.floor(height / minRows)));
  return Array.from({ length: k }, (_, i) => [Math.floor((i * height) / k), Math.floor(((i + 1) * height) / k)]);
}

function cancelled() {
  const err = new Error("Cancelled.");
  err.cancelled = true;
  return err;
}

export class Tiles {
  /**
   * @param {number} n workers (navigator.hardwareConcurrency, at most 8)
   * @param {{ minPixels?: number, minRows?: number }} opts (the tests band small images)
   * @param {(type: string, args: object) => Promise<any>} main a request to the lab's main worker
   */
  constructor(n, { minPixels = MIN_PIXELS, minRows = 16 } = {}, main = null) {
    this.n = Math.max(1, Math.min(8, n));
    this.minPixels = minPixels;
    this.minRows = minRows;
    this.main = main;
    this.workers = [];
    this.nextId = 1;
    this.image = null; // { width, height, bytes: Uint8Array }
    this.spare = []; // ArrayBuffers of bands' layers, to be filled again (recycle)
    this.inputs = []; // ArrayBuffers of bands' inputs the workers gave back, to carry the next bands' rows (rows)
    this.inputSizes = new Set(); // their byte lengths (a band's input of this photo)
    this.inputsReused = 0; // bands' inputs cut into a given-back buffer (the tests count them)
    this.free = []; // ArrayBuffers of whole layers the page released, to carry the next result's (release)
    this.owned = new WeakSet(); // the whole layers' buffers this pool made (only those come back)
    this.reused = 0; // whole layers made in a released buffer (the tests count them)
    this.running = new Set();
    this.halos = new Map();
    this.kept = null; // the bands' Förstner maps: { job, size, holders: Map(band → slot), bands }
    this.jobs = 0;
    this.mapRuns = 0;
    this.workerMs = 0;
  }

  /**
   * The open photo: { width, height, bytes } when it is 8-bit, else
   * { width, height, grey, levels?, scale?, bits, maxValue } (its grey values, and their levels over
   * `scale` when they are whole numbers over one: a colour photo's, sent to the bands); null: none
   * (the main worker runs everything).
   */
  setImage(img) {
    this.image = img && (img.bytes || img.grey) ? img : null;
    this.kept = null;
    this.spare = [];
    this.free = [];
    this.inputs = [];
    this.inputSizes = new Set();
  }

  /**
   * The page no longer reads `layers` (a newer result replaced them): the
   * buffers of those this pool put together carry the next result's layers
   * of the same size. A fresh 48 MB layer costs its pages on first write
   * (100–170 ms at 12 MP), a reused one does not. At most FREE are kept.
   */
  release(layers) {
    for (const l of layers ?? []) {
      const b = l?.data?.buffer;
      if (!b || !this.owned.has(b) || this.free.includes(b)) continue;
      this.owned.delete(b);
      this.free.push(b);
      if (this.free.length > FREE) this.free.shift();
    }
  }

  /** A whole layer of `length` values of `Type` (Float32Array …): in a released buffer of that size when there is one. */
  alloc(Type, length) {
    const i = this.free.findIndex((b) => b.byteLength === length * Type.BYTES_PER_ELEMENT);
    const out = i >= 0 ? new Type(this.free.splice(i, 1)[0]) : new Type(length);
    if (i >= 0) this.reused++;
    this.owned.add(out.buffer);
    return out;
  }

  /**
   * Keeps `buffers` (bands' layers already copied into the whole ones, and
   * the bands' inputs the workers gave back) for the next bands: those of a
   * band input's size for the next inputs (at most LANES a worker), the
   * others for the next layers (at most SPARE).
   */
  recycle(buffers) {
    for (const b of buffers) {
      if (!b.byteLength) continue;
      if (this.inputSizes.has(b.byteLength) && this.inputs.length < LANES * this.n) this.inputs.push(b);
      else this.spare.push(b);
    }
    // the largest kept: a band's layers fit in them (bands differ by a row or two)
    this.spare.sort((a, b) => b.byteLength - a.byteLength).splice(SPARE);
  }

  /**
   * Up to `k` kept buffers of at least `bytes` each, for a band's layers (a
   * layer of a band fills a spare buffer only where it fits: spare_buffers;
   * one that does not fit would leave that layer a fresh one).
   */
  spares(bytes, k = 4) {
    const fit = this.spare.filter((b) => b.byteLength >= bytes).slice(-k);
    this.spare = this.spare.filter((b) => !fit.includes(b));
    return fit;
  }

  /**
   * A released whole layer of the open photo's size (4 bytes a pixel) for
   * the main worker's request `type` to write its layer into (SPARED), as
   * the `spare` list of the request; null: none.
   */
  spareFor(type) {
    const img = this.image;
    if (!img || !SPARED.has(type)) return null;
    const i = this.free.findIndex((b) => b.byteLength === img.width * img.height * 4);
    return i >= 0 ? this.free.splice(i, 1) : null;
  }

  /** A SPARED request's answer: its layers' buffers released with the pool's (release), its unused spare buffers kept (FREE). */
  adopt(result) {
    for (const l of result?.layers ?? []) if (l?.data?.buffer?.byteLength) this.owned.add(l.data.buffer);
    for (const b of result?.spare ?? []) if (b.byteLength && this.free.length < FREE) this.free.push(b);
    if (result) delete result.spare;
    return result;
  }

  handles(type, args) {
    const img = this.image;
    if (!img || args.untiled || img.width * img.height < this.minPixels) return false;
    if (type === "forstnerPoints") return this.kept !== null;
    return BANDED.has(type) || type === "resample";
  }

  /**
   * Rows [r0, r1) of the photo as a band request's fields, a copy whose
   * buffer is transferred: `bytes`, or `values` with the sample depth. The
   * copy is made in a buffer of its size that a worker gave back (recycle)
   * when there is one: a fresh one costs its pages first, more than the copy
   * (2 MB of bytes, 8 MB of a colour photo's levels a band at 12 MP).
   */
  rows(r0, r1) {
    const { width, bytes, grey, levels, scale, bits, maxValue } = this.image;
    const src = bytes ?? levels ?? grey;
    const [from, to] = [r0 * width, r1 * width];
    const size = (to - from) * src.BYTES_PER_ELEMENT;
    // (the whole photo, sent once to a worker for resampling, does not come back)
    if (r1 - r0 < this.image.height) this.inputSizes.add(size);
    const i = this.inputSizes.has(size) ? this.inputs.findIndex((b) => b.byteLength === size) : -1;
    let a;
    if (i >= 0) {
      a = new src.constructor(this.inputs.splice(i, 1)[0]);
      a.set(src.subarray(from, to));
      this.inputsReused++;
    } else a = src.slice(from, to);
    if (bytes) return [{ bytes: a.buffer }, [a.buffer]];
    if (levels) return [{ levels: a.buffer, scale, bits, maxValue }, [a.buffer]];
    return [{ values: a.buffer, bits, maxValue }, [a.buffer]];
  }

  /** Pool worker `i`, started when first needed. */
  worker(i) {
    if (!this.workers[i]) {
      const w = new Worker(new URL("./worker.js", import.meta.url), { type: "module" });
      const pending = new Map();
      const slot = {
        busy: 0,
        image: null,
        ask: (type, args, transfer = []) => new Promise((resolve, reject) => {
          const id = this.nextId++;
          pending.set(id, { resolve, reject });
          slot.busy++;
          w.postMessage({ id, type, ...args }, transfer);
        }),
        terminate: (why = "Cancelled.") => {
          w.terminate();
          const err = new Error(why);
          err.cancelled = why === "Cancelled.";
          err.trapped = !err.cancelled;
          for (const p of pending.values()) p.reject(err);
          pending.clear();
        },
      };
      w.onmessage = ({ data }) => {
        const p = pending.get(data.id);
        if (!p || data.ok === undefined) return;
        pending.delete(data.id);
        slot.busy--;
        // ms inside the pool's workers (npm run bench -- --lab)
        this.workerMs += data.ms ?? 0;
        if (data.ok) p.resolve(data.result);
        else {
          const err = new Error(data.error);
          err.trapped = Boolean(data.trapped);
          p.reject(err);
          // a trapped instance is not used again
          if (data.trapped) this.drop(slot);
        }
      };
      w.onerror = (ev) => {
        ev.preventDefault?.();
        this.drop(slot, `the lab's engine stopped (${ev.message || "worker error"})`);
      };
      this.workers[i] = slot;
    }
    return this.workers[i];
  }

  drop(slot, why) {
    const i = this.workers.indexOf(slot);
    if (i >= 0) this.workers[i] = undefined;
    // its bands of a kept Förstner map are gone with it
    if (this.kept && [...this.kept.holders.values()].includes(slot)) this.kept = null;
    slot.terminate(why);
  }

  /** An idle pool worker (the least busy). */
  idle() {
    let best = 0;
    for (let i = 0; i < this.n; i++) if ((this.workers[i]?.busy ?? 0) < (this.workers[best]?.busy ?? 0)) best = i;
    return this.worker(best);
  }

  /** Stops every running band (cancel): no band starts after it, and the workers running one are stopped (started again when needed). */
  cancel() {
    for (const job of this.running) job.cancelled = true;
    this.running.clear();
    for (const w of this.workers) if (w?.band?.cancelled) this.drop(w);
  }

  /** Stops every pool worker (the lab closes). */
  reset() {
    this.cancel();
    for (const w of this.workers) w?.terminate();
    this.workers = [];
    this.kept = null;
  }

  /** Rows of real neighbours `type` with `args` needs (wasm op_halo, asked once per parameters). */
  async halo(type, args) {
    const key = `${type} ${JSON.stringify(args)}`;
    if (!this.halos.has(key)) this.halos.set(key, await this.idle().ask("halo", { op: type, args }));
    return this.halos.get(key);
  }

  /**
   * Runs `type` by bands: resolves with what the main worker answers for
   * the whole image (layers; points for the interest operators; the
   * threshold's fields for Förstner's kept map). `onProgress({ progress,
   * rows, of })` after each band.
   */
  async run(type, args, onProgress = null) {
    if (type === "forstnerPoints") return this.points(args);
    if (type === "resample") return this.resample(args, onProgress);
    const { width, height } = this.image;
    const halo = await this.halo(type, args);
    const bands = bandsOf(width, height, this.n, Math.max(this.minRows, 2 * halo));
    const job = ++this.jobs;
    const keep = type === "forstnerMaps";
    const holders = new Map();
    const whole = new Whole(height, (T, n) => this.alloc(T, n));
    const parts = await this.lanes(bands, height, onProgress, async (w, k, [start, end]) => {
      const [r0, r1] = [Math.max(0, start - halo), Math.min(height, end + halo)];
      const [data, transfer] = this.rows(r0, r1);
      const own = [0, start - r0, width, end - start];
      // buffers of earlier bands' layers to copy this band's into (no fresh pages: spare_buffers), and
      // its input's own buffer: the worker gives back the spare buffers it did not fill, so the input's comes back
      const spare = [...this.spares((r1 - r0) * width * 4), ...transfer];
      const part = await w.ask("region", { op: type, args, width, height: r1 - r0, ...data, own, at: [0, r0], keep: keep ? { job, band: k } : null, spare }, spare);
      holders.set(k, w);
      // its rows into the whole layers at once; its buffers are then the next bands'
      this.recycle([...part.spare, ...whole.add(part)]);
      return part;
    });
    const out = whole.result(parts, { bands: bands.length, workers: Math.min(this.n, bands.length) });
    if (!keep) return out;
    this.kept = { job, size: args.size, holders, bands: bands.length };
    const auto = await this.main("forstnerAuto", { size: args.size, sigmaN: args.sigmaN, w: out.layers[0].data });
    return { ...out, size: args.size, mapRuns: ++this.mapRuns, auto };
  }

  /**
   * `bands` run on the pool, a worker taking the next band when it is done:
   * `one(worker, k, band)` → the band's answer; the answers in band order.
   * Progress counts the rows of `of` done.
   */
  async lanes(bands, of, onProgress, one) {
    const job = { cancelled: false };
    this.running.add(job);
    const parts = new Array(bands.length);
    let next = 0;
    let rowsDone = 0;
    const lane = async (w) => {
      while (next < bands.length && !job.cancelled) {
        const k = next++;
        w.band = job;
        parts[k] = await one(w, k, bands[k]);
        // (the worker's other lane may still run a band of the job: a cancel stops it then)
        if (!w.busy) w.band = null;
        rowsDone += bands[k][1] - bands[k][0];
        if (!job.cancelled) onProgress?.({ progress: rowsDone / of, rows: rowsDone, of });
      }
    };
    try {
      // two lanes a worker: its next band is sent before the page has put the last one's rows
      // together (Whole.add), so that the worker computes while the page copies
      await Promise.all(Array.from({ length: Math.min(LANES * this.n, bands.length) }, (_, i) => lane(this.worker(i % this.n))));
    } catch (e) {
      throw job.cancelled ? cancelled() : e;
    } finally {
      this.running.delete(job);
    }
    if (job.cancelled) throw cancelled();
    return parts;
  }

  /** Förstner's points for a threshold from the bands' kept maps, in band order (row-major, as one map gives them). */
  async points(args) {
    const kept = this.kept;
    const t0 = performance.now();
    const slots = [...new Set(kept.holders.values())];
    const answers = (await Promise.all(slots.map((w) => w.ask("keptPoints", { job: kept.job, ...args })))).flat();
    if (answers.length !== kept.bands) throw new Error("threshold_px: the kept Förstner map is incomplete (press Run again)");
    answers.sort((a, b) => a.band - b.band);
    const points = new Float64Array(answers.reduce((s, a) => s + a.points.length, 0));
    let at = 0;
    for (const a of answers) {
      points.set(a.points, at);
      at += a.points.length;
    }
    return { points, thresholdPx: args.thresholdPx, size: kept.size, mapRuns: this.mapRuns, pointsMs: performance.now() - t0 };
  }

  /** Resampling by bands of output rows; each worker gets the whole photo once. */
  async resample(args, onProgress) {
    const img = this.image;
    const bands = bandsOf(args.width, args.height, this.n, this.minRows);
    const whole = new Whole(args.height, (T, n) => this.alloc(T, n));
    const parts = await this.lanes(bands, args.height, onProgress, async (w, k, [row0, row1]) => {
      if (w.image !== img) {
        // (once a worker: its two lanes wait for the same photo)
        const [data, transfer] = this.rows(0, img.height);
        w.image = img;
        w.imageSent = w.ask(img.bytes ? "raw" : "grey", { width: img.width, height: img.height, ...data }, transfer);
      }
      await w.imageSent;
      const spare = this.spares((row1 - row0) * args.width * 4);
      const part = await w.ask("resample", { ...args, row0, row1, spare }, spare);
      this.recycle([...part.spare, ...whole.add(part)]);
      return part;
    });
    return whole.result(parts, { bands: bands.length, workers: Math.min(this.n, bands.length) });
  }

  /**
   * Paints `layer` on the pool: { bitmap, scale } (worker.js `paint`); a
   * layer of more than PAINT_SPLIT pixels by bands of rows on every worker
   * (each band's range, then each band painted on the whole range, the
   * bitmaps drawn into one).
   */
  async paint(layer) {
    const { width, data } = layer;
    const height = data.length / width;
    const signed = Boolean(layer.signed);
    const k = Math.min(this.n, Math.floor(height / 16));
    if (width * height <= PAINT_SPLIT || k < 2 || typeof OffscreenCanvas === "undefined") {
      // a copy of the values: the page keeps its own (the inspector, the explained pixel read them)
      return this.idle().ask("paint", { data, width, signed });
    }
    const job = (this.paints = (this.paints ?? 0) + 1);
    const bands = Array.from({ length: k }, (_, i) => [Math.floor((i * height) / k), Math.floor(((i + 1) * height) / k)]);
    const ranges = await Promise.all(bands.map(([r0, r1], i) => {
      const part = data.slice(r0 * width, r1 * width);
      return this.worker(i).ask("paintPart", { job, part: i, data: part, width }, [part.buffer]);
    }));
    const range = [Math.min(...ranges.map((r) => r[0])), Math.max(...ranges.map((r) => r[1]))];
    const parts = await Promise.all(bands.map((_, i) => this.worker(i).ask("paintPart", { job, part: i, signed, range })));
    const canvas = new OffscreenCanvas(width, height);
    const ctx = canvas.getContext("2d");
    parts.forEach((p, i) => {
      ctx.drawImage(p.bitmap, 0, bands[i][0]);
      p.bitmap.close();
    });
    return { bitmap: canvas.transferToImageBitmap(), scale: parts[0].scale };
  }
}

/**
 * Layers of the whole image put together as the bands' answers arrive
 * (any order): each layer allocated once for the image's rows, a band's
 * own rows (placed in the image by the worker) copied in, so that the
 * band's buffers can carry the next bands' layers; `result` gives the
 * whole image's answer: its layers made of the rows each band owns (the
 * worker cut them to its own rows and placed them in the image), its points
 * in band order (row-major, as one call finds them).
 */
export class Whole {
  /** `alloc(Type, length)`: a whole layer's array (Tiles.alloc: a released one when it fits). */
  constructor(height, alloc = (Type, length) => new Type(length)) {
    this.height = height;
    this.alloc = alloc;
    this.layers = null;
  }

  /** Copies `part`'s layers in; returns their buffers (free now). */
  add(part) {
    this.layers ??= part.layers.map((l) => ({ data: this.alloc(l.data.constructor, this.height * l.width), top: Infinity, rows: 0, signed: false }));
    return part.layers.map((l, i) => {
      const whole = this.layers[i];
      if (l.height > 0) {
        whole.data.set(l.data, l.r0 * l.width);
        whole.top = Math.min(whole.top, l.r0);
        whole.rows += l.height;
      }
      // a reference-path layer is signed when any of its values is negative: in any band
      whole.signed ||= Boolean(l.signed);
      const b = l.data.buffer;
      l.data = null;
      return b;
    });
  }

  /** The whole image's answer from the bands' `parts` (their layers added), in band order. */
  result(parts, info) {
    const first = parts[0];
    const layers = first.layers.map((l0, i) => {
      const { data, top, rows, signed } = this.layers[i];
      const r0 = rows ? top : l0.r0;
      // (a layer without the image's first or last rows, e.g. border crop: the view of its rows)
      const view = r0 === 0 && rows === this.height ? data : data.subarray(r0 * l0.width, (r0 + rows) * l0.width);
      return { ...l0, r0, height: rows, signed, data: view };
    });
    const out = { ...first, layers, bands: info };
    if (first.points) out.points = concat(parts.map((p) => p.points));
    return out;
  }
}

/** Float64Arrays one after another. */
function concat(arrays) {
  const out = new Float64Array(arrays.reduce((s, a) => s + a.length, 0));
  let at = 0;
  for (const a of arrays) {
    out.set(a, at);
    at += a.length;
  }
  return out;
}
