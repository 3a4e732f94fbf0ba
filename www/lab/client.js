// The page's side of the lab worker: requests as promises, cancel, and
// recovery. The worker is replaced (a fresh wasm instance) when its wasm
// traps, when it dies, or when a long request is cancelled; `restore()`
// (given by the lab) then puts the student's image back into the new one.
// Cross-origin isolated pages split filters and edges over several workers
// by row tiles (tiles.js); `threads` says how many run (1: single-threaded).

import { Tiles } from "./tiles.js";

export class LabClient {
  /**
   * @param {{ onRestart: (why: string) => Promise<void> }} hooks
   */
  constructor(hooks) {
    this.hooks = hooks;
    this.nextId = 1;
    this.pending = new Map();
    this.tiles = Tiles.available() ? new Tiles(Math.min(4, navigator.hardwareConcurrency)) : null;
    this.threads = this.tiles ? this.tiles.n : 1;
    this.sent = {};
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

  answer({ id, ok, result, error, trapped, progress, rows, of }) {
    const p = this.pending.get(id);
    if (!p) return;
    if (ok === undefined && progress !== undefined) {
      p.onProgress?.({ progress, rows, of });
      return;
    }
    this.pending.delete(id);
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
   * the field. `onProgress({ progress, rows, of })`: the rows done so far,
   * where the worker can say (filters and edges on an 8-bit image).
   */
  call(type, args = {}, transfer = [], onProgress = null) {
    if (this.tiles?.handles(type, args)) {
      this.tiling = (this.tiling || 0) + 1;
      return this.tiles.run(this, type, args).finally(() => this.tiling--);
    }
    const id = this.nextId++;
    // requests sent, by type (the live slider's tests count them)
    this.sent[type] = (this.sent[type] ?? 0) + 1;
    return new Promise((resolve, reject) => {
      this.pending.set(id, { resolve, reject, type, onProgress });
      this.worker.postMessage({ id, type, ...args, ...(onProgress ? { progress: true } : {}) }, transfer);
    });
  }

  /** Whether a request is running. */
  get busy() {
    return this.pending.size > 0 || this.tiling > 0;
  }

  /** Stops whatever runs: the worker is replaced and the image restored. */
  cancel() {
    this.replace("cancelled");
  }

  replace(why) {
    this.tiles?.reset();
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
    this.tiles?.reset();
    this.worker.terminate();
    this.pending.clear();
  }
}
