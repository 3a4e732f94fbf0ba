// The page's side of the lab's workers: requests as promises, cancel, and
// recovery. The main worker holds the photo and answers every request; the
// image-wide operators run by bands of rows on a pool of workers instead
// (tiles.js: up to navigator.hardwareConcurrency, at most 8, on any host),
// which also paints the layers (`paint`). `threads` says how many the pool
// has. The main worker is replaced (a fresh wasm instance) when its wasm
// traps, when it dies, or when a long request of its own is cancelled;
// `restore()` (given by the lab) then puts the student's image back into
// the new one. A cancel of banded work stops only the pool's bands.

import { SPARED, Tiles } from "./tiles.js";

/** Requests that open the photo (slot "a"): the pool's bands are cut from its bytes. */
const OPENS = new Set(["load", "frame", "raw"]);
/** Requests a cancel lets finish on the main worker (short, and not the computation being cancelled). */
const QUICK = new Set(["preview", "size", "engine", "memory"]);

export class LabClient {
  /**
   * @param {{ onRestart: (why: string) => Promise<void> }} hooks
   * @param {{ workers?: number, minPixels?: number, minRows?: number }} pool
   *   the pool's size (default: the cores, at most 8) and when bands apply (tiles.js)
   */
  constructor(hooks, pool = {}) {
    this.hooks = hooks;
    this.nextId = 1;
    this.pending = new Map();
    this.tiles = new Tiles(pool.workers ?? (navigator.hardwareConcurrency || 1), pool, (type, args) => this.call(type, args));
    this.threads = this.tiles.n;
    this.sent = {};
    this.tiling = 0;
    this.cancels = 0;
    this.workerMs = 0;
    this.start();
  }

  start() {
    this.worker = new Worker(new URL("./worker.js", import.meta.url), { type: "module" });
    this.worker.onmessage = (ev) => this.answer(ev.data);
    this.worker.onerror = (ev) => {
      ev.preventDefault?.();
      this.replace(`the lab's engine stopped (${ev.message || "worker error"})`);
    };
  }

  answer({ id, ok, result, error, trapped, ms }) {
    const p = this.pending.get(id);
    if (!p || ok === undefined) return;
    this.pending.delete(id);
    // ms inside the main worker (npm run bench -- --lab)
    this.workerMs += ms ?? 0;
    if (ok) {
      p.resolve(result);
      return;
    }
    const err = new Error(error);
    err.trapped = Boolean(trapped);
    p.reject(err);
    if (trapped) this.replace(`the lab's engine crashed (${error})`);
  }

  /**
   * Sends a request; resolves with its result, rejects with an Error naming
   * the field. `onProgress({ progress, rows, of })`: the bands done so far,
   * where the request runs by bands (tiles.js).
   */
  call(type, args = {}, transfer = [], onProgress = null) {
    // requests asked for, by type (the live slider's tests count them)
    this.sent[type] = (this.sent[type] ?? 0) + 1;
    if (this.tiles.handles(type, args)) {
      this.tiling++;
      // a preview asked for first has the cores first (the whole result's bands start when it is painted)
      const previews = [...this.pending.values()].filter((p) => p.type === "preview").map((p) => p.done);
      const cancels = this.cancels;
      return Promise.allSettled(previews)
        .then(() => {
          if (this.cancels !== cancels) throw Object.assign(new Error("Cancelled."), { cancelled: true });
          return this.tiles.run(type, args, onProgress);
        })
        .finally(() => this.tiling--);
    }
    const opens = OPENS.has(type) && (args.slot ?? "a") === "a";
    if (opens) this.tiles.setImage(null);
    // a map the main worker keeps: its points are the main worker's too
    if (type === "forstnerMaps") this.tiles.kept = null;
    const id = this.nextId++;
    // a released whole layer to carry this request's layer (tiles.js SPARED: no fresh pages), its answer's released in turn
    const spare = this.tiles.spareFor(type);
    let entry;
    const p = new Promise((resolve, reject) => {
      entry = { resolve, reject, type };
      this.pending.set(id, entry);
      this.worker.postMessage(spare ? { id, type, ...args, spare } : { id, type, ...args }, spare ? [...transfer, ...spare] : transfer);
    });
    entry.done = p;
    if (SPARED.has(type)) return p.then((r) => this.tiles.adopt(r));
    if (!opens) return p;
    return p.then((r) => {
      this.tiles.setImage({ width: r.width, height: r.height, bytes: r.bytes, grey: r.grey, levels: r.levels, scale: r.scale, bits: r.bits ?? 8, maxValue: r.maxValue ?? 255 });
      return r;
    });
  }

  /** The page no longer reads these result layers (a newer result replaced them): their buffers carry the next result's (tiles.js `release`). */
  release(layers) {
    this.tiles.release(layers);
  }

  /** `layer` painted in a pool worker: { bitmap: ImageBitmap, scale }. */
  paint(layer) {
    return this.tiles.paint(layer);
  }

  /** Whether a request is running. */
  get busy() {
    return this.pending.size > 0 || this.tiling > 0;
  }

  /** Stops whatever runs: the pool's bands; the main worker (replaced, the image restored) when it runs a long request. */
  cancel() {
    this.cancels++;
    this.tiles.cancel();
    if ([...this.pending.values()].some((p) => !QUICK.has(p.type))) this.replace("cancelled");
  }

  replace(why) {
    this.worker.terminate();
    const err = new Error(why === "cancelled" ? "Cancelled." : why);
    err.cancelled = why === "cancelled";
    err.trapped = !err.cancelled;
    for (const p of this.pending.values()) p.reject(err);
    this.pending.clear();
    this.start();
    const t0 = performance.now();
    this.restarting = this.hooks.onRestart(why).finally(() => {
      this.restarting = null;
      // ms from the old worker's end to the photo back in the new one (reported by the live sliders)
      this.lastRestartMs = performance.now() - t0;
    });
  }

  close() {
    this.tiles.reset();
    this.worker.terminate();
    this.pending.clear();
  }
}
