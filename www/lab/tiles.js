// Image-wide operators over several workers, by row tiles with halos, when
// the page is cross-origin isolated (npm start -- --isolate); otherwise the
// lab stays on its one worker. Each tile worker gets its rows plus HALO rows
// above and below (real neighbours, so the border policy acts only at the
// image's own edges), runs the same request as the single worker, and the
// rows each tile owns are put together into the single worker's layers:
// the same numbers at every pixel (tests/e2e/lab_tiles.test.mjs).

/** Rows of real neighbours above and below a tile: enough for every 5×5 kernel. */
const HALO = 2;
/** Tiles thinner than this are not worth a message. */
const MIN_ROWS = 64;

/** Requests that can be tiled (filters of a named kernel, edges). */
function tileable(type, args) {
  if (type === "edges") return true;
  return type === "filter" && args.kernel !== "custom";
}

export class Tiles {
  /** Whether this page may use several workers (cross-origin isolated, more than one core). */
  static available() {
    return globalThis.crossOriginIsolated === true && (navigator.hardwareConcurrency || 1) > 1;
  }

  constructor(n) {
    this.n = n;
    this.workers = [];
    this.nextId = 1;
  }

  handles(type, args) {
    return this.n > 1 && tileable(type, args) && !args.untiled;
  }

  worker(i) {
    if (!this.workers[i]) {
      const w = new Worker(new URL("./worker.js", import.meta.url), { type: "module" });
      const pending = new Map();
      w.onmessage = ({ data }) => {
        const p = pending.get(data.id);
        if (!p) return;
        pending.delete(data.id);
        if (data.ok) p.resolve(data.result);
        else p.reject(new Error(data.error));
      };
      this.workers[i] = {
        ask: (type, args, transfer = []) => new Promise((resolve, reject) => {
          const id = this.nextId++;
          pending.set(id, { resolve, reject });
          w.postMessage({ id, type, ...args }, transfer);
        }),
        terminate: () => {
          w.terminate();
          const err = new Error("Cancelled.");
          err.cancelled = true;
          for (const p of pending.values()) p.reject(err);
          pending.clear();
        },
      };
    }
    return this.workers[i];
  }

  /** Stops every tile worker (cancel, restart); they are started again when needed. */
  reset() {
    for (const w of this.workers) w?.terminate();
    this.workers = [];
  }

  /**
   * Runs `type` over row tiles; `client.call` serves the open image's size
   * and rows, and the single-worker request when tiling does not apply (not
   * an 8-bit image, too few rows).
   */
  async run(client, type, args) {
    const single = () => client.call(type, { ...args, untiled: true });
    const { width, height } = await client.call("size", {});
    const n = Math.min(this.n, Math.floor(height / MIN_ROWS));
    if (n < 2) return single();
    const bounds = Array.from({ length: n }, (_, k) => [Math.floor((k * height) / n), Math.floor(((k + 1) * height) / n)]);
    const windows = [];
    for (const [start, end] of bounds) {
      const r0 = Math.max(0, start - HALO);
      const r1 = Math.min(height, end + HALO);
      const values = await client.call("window", { c: 0, r: r0, w: width, h: r1 - r0 });
      // the fast paths (and image_from_u8) take 8-bit images: anything else runs on one worker
      if (!values.every((v) => Number.isInteger(v) && v >= 0 && v <= 255)) return single();
      windows.push({ r0, rows: r1 - r0, bytes: Uint8Array.from(values) });
    }
    let results;
    try {
      results = await Promise.all(windows.map(async (t, k) => {
        const w = this.worker(k);
        await w.ask("raw", { width, height: t.rows, bytes: t.bytes.buffer }, [t.bytes.buffer]);
        return w.ask(type, args);
      }));
    } catch (e) {
      if (e.cancelled) throw e;
      // a refused request or a trapped tile worker: fresh workers next time, the answer from one worker now
      this.reset();
      return single();
    }
    return { layers: stitch(results.map((r) => r.layers), windows, bounds) };
  }
}

/** The rows each tile owns, from its layers, as the whole image's layers. */
function stitch(tileLayers, windows, bounds) {
  return tileLayers[0].map((first, li) => {
    const rows = [];
    let r0 = null;
    tileLayers.forEach((layers, k) => {
      const l = layers[li];
      const [start, end] = bounds[k];
      for (let j = 0; j < l.height; j++) {
        const row = windows[k].r0 + l.r0 + j;
        if (row < start || row >= end) continue;
        if (r0 === null) r0 = row;
        rows.push(l.data.subarray(j * l.width, (j + 1) * l.width));
      }
    });
    const data = new Float64Array(rows.length * first.width);
    rows.forEach((r, j) => data.set(r, j * first.width));
    // a reference-path layer is signed when any of its values is negative: in any tile
    const signed = tileLayers.some((layers) => layers[li].signed);
    return { ...first, r0: r0 ?? 0, height: rows.length, signed, data };
  });
}
