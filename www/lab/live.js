// Live parameters (a slider being dragged): the newest value wins.
//
// The worker runs one wasm call at a time and cannot be interrupted from
// inside, so a computation that is no longer wanted is stopped by
// terminating the worker (LabClient.cancel): a fresh one starts at once and
// gets the photo back (the lab keeps its bytes), and the new request goes
// right behind that. This was chosen over cutting the work into row bands
// with a cancel check between them: it needs no change in any operator,
// stops a run at once instead of at the end of a band. Its price is the
// restart: a new wasm instance and the photo copied back before the new run
// starts (2 s for a 2048² photo measured on the shared 2-core machine at a
// load of 30, where the runs it cancels took 10–60 s; the e2e test prints
// it). Cheap requests (a new threshold on a kept Förstner map) are
// not cancelled but coalesced: while one runs, only the newest waiting one
// is kept. A result older than the one on screen is never drawn.
//
//   live.request({ type, args, label, cancel, apply })

import { testHook } from "../test-hooks.js";

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
   * waits for it, replacing any older waiting one).
   */
  request({ type, args, label, cancel = false, apply }) {
    const req = { type, args, label, apply, gen: ++this.gen };
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
    const r = await this.lab.run(req.type, req.args, req.label, [], { quietCancel: true });
    if (this.running === req) this.running = null;
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
}
