// Live parameters (a slider being dragged): the newest value wins, and a
// preview comes first.
//
// A new value first paints a preview (worker.js `preview`, on the main
// worker while the pool computes the whole image): the operator at full
// resolution on the part of the photo in view (its middle, when the view
// shows more than PREVIEW_PIXELS), with its halo, so that its pixels are
// already the result's; drawn over the photo until the whole result
// arrives. (A reduced photo was tried: window sizes then cover k times more
// of the photo, and Förstner's 15 × 15 windows showed blobs the result has
// not.) Only on photos big enough for the whole result to take longer than
// a frame or so (PREVIEW_FROM).
//
// Resampling's output is another image (views of their own, `target`): its
// preview is the part of the OUTPUT in those views (their union), each of
// its pixels computed from the whole photo the main worker holds, exactly
// as the pool's bands compute it (run_resample over output rows): whole
// output rows are what the wasm resamples, so the box keeps at most
// PREVIEW_PIXELS / (output width) rows (the middle ones of those in view)
// and is then cut to the columns in view. Its greys are painted on the
// grey stretch of the result shown in each view (`target.ranges()`: the
// new one's is nearly the same, the photo's range with the rotation's
// empty corners). Before the first result there are no views: no preview.
//
// A running computation that is no longer wanted is stopped: by bands on
// the pool (tiles.js), no band starts after the cancel and the running ones
// are stopped, and the photo stays in the main worker; a request of the main
// worker itself cannot be interrupted from inside, so the worker is
// terminated (LabClient.cancel): a fresh one starts at once and gets the
// photo back (the lab keeps its bytes), and the new request goes right
// behind that. Cheap requests (a new threshold on a kept Förstner map) are
// not cancelled but coalesced: while one runs, only the newest waiting one
// is kept. A result older than the one on screen is never drawn.
//
//   live.request({ type, args, label, cancel, apply })

import { testHook } from "../test-hooks.js";

/** Photos with fewer pixels get no preview (their whole result comes about as soon). */
export const PREVIEW_FROM = 1 << 20;
/** A preview has at most this many pixels (the part in view, or its middle). */
const PREVIEW_PIXELS = 1 << 18;
/** The requests that have a preview (worker.js OPS). */
const PREVIEWS = new Set(["filter", "edges", "forstner", "forstnerMaps", "moravec"]);

export class Live {
  constructor(lab, name) {
    this.lab = lab;
    this.name = name;
    this.gen = 0;
    this.shown = 0;
    this.running = null;
    this.queued = null;
    this.cancels = 0;
  }

  /** Whether a request of this controller is running. */
  get busy() {
    return this.running !== null;
  }

  /**
   * Runs `type` with `args`; `apply(result)` draws it if no newer result is
   * on screen. `cancel`: a running request is stopped (else the new one
   * waits for it, replacing any older waiting one). `target`: where the
   * preview is drawn ({ visible(), setPreview(p), ranges()? }: the photo's
   * viewer when not given; ranges: the layers' grey stretch by name); `layer`: the layer to preview when the one shown is not
   * one of the result's; `rowWidth`: the request computes whole output
   * rows this wide (resampling): its preview is of output rows (worker.js
   * `preview` with `rows`).
   */
  request({ type, args, label, cancel = false, apply, target = null, layer = null, rowWidth = 0 }) {
    const req = { type, args, label, apply, target: target ?? this.lab.viewer, layer, rowWidth, gen: ++this.gen, t0: performance.now() };
    if (this.running) {
      if (!cancel) {
        this.queued = req;
        return Promise.resolve();
      }
      this.cancels++;
      testHook(`${this.name}Cancels`, String(this.cancels));
      this.lab.say(`${this.running.label}: stopped for the newer setting (the last result stays on screen until the new one is ready).`);
      this.running = null;
      this.lab.client.cancel();
    }
    this.queued = null;
    return this.start(req);
  }

  async start(req) {
    this.running = req;
    testHook(`${this.name}Live`, "busy");
    this.preview(req);
    const r = await this.lab.run(req.type, req.args, req.label, [], { quietCancel: true });
    if (this.running === req) this.running = null;
    // a failed run leaves no preview behind (a newer one draws its own)
    if (!r && !this.running && !this.queued) req.target.setPreview(null);
    if (this.lab.client.lastRestartMs !== undefined) testHook("restartMs", this.lab.client.lastRestartMs.toFixed(0));
    if (r && req.gen > this.shown) {
      this.shown = req.gen;
      req.apply(r);
    }
    if (!this.running && this.queued) {
      const q = this.queued;
      this.queued = null;
      if (q.gen > this.shown) return this.start(q);
    }
    if (!this.running) testHook(`${this.name}Live`, "idle");
    return undefined;
  }

  /**
   * Paints the preview of `req` while it runs: the part of the photo in
   * view, or its middle when that has more than PREVIEW_PIXELS, at full
   * resolution (with the operator's halo: the worker asks op_halo, so its
   * pixels are the whole result's); the layer shown now (by name), else
   * the result's first.
   */
  preview(req) {
    const lab = this.lab;
    const img = lab.image;
    const view = req.target.visible();
    const from = lab.previewFrom ?? PREVIEW_FROM;
    if (!(PREVIEWS.has(req.type) || req.rowWidth) || !img || !view || img.width * img.height < from) return;
    let rect = previewRect(view, PREVIEW_PIXELS);
    const rows = req.rowWidth > 0;
    if (rows) rect = rowsRect(rect, Math.floor(PREVIEW_PIXELS / req.rowWidth));
    const name = lab.layers[Number(lab.layerSelect.value)]?.name ?? null;
    const ranges = req.target.ranges?.() ?? null;
    lab.busyWhile(lab.client.call("preview", { op: req.type, args: req.args, name, fallback: req.layer, rect, rows, ranges }))
      .then((p) => {
        if (!p || this.running !== req || req.gen <= this.shown) return;
        req.target.setPreview(p);
        // ms from the new value to its preview on screen (npm run bench -- --lab)
        testHook("previewMs", (performance.now() - req.t0).toFixed(1));
        testHook(`${this.name}Preview`, rect.join(","));
      })
      .catch(() => {});
  }
}

/**
 * The box of a preview: `view` [c, r, w, h] when it has at most `most`
 * pixels, else its middle, of the same shape, with about `most`.
 */
export function previewRect(view, most) {
  const [c, r, w, h] = view;
  if (w * h <= most) return view;
  const pw = Math.max(1, Math.min(w, Math.round(Math.sqrt((most * w) / h))));
  const ph = Math.max(1, Math.min(h, Math.floor(most / pw)));
  return [c + ((w - pw) >> 1), r + ((h - ph) >> 1), pw, ph];
}

/** `rect` [c, r, w, h] with at most `rows` rows (its middle ones; at least one). */
export function rowsRect(rect, rows) {
  const [c, r, w, h] = rect;
  const n = Math.max(1, Math.min(h, rows));
  return [c, r + ((h - n) >> 1), w, n];
}
