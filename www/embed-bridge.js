// The one place where the page posts to the page that embeds it (docs: README,
// "Embedding"). Every message has the same shape:
//   { type: "photogrammetry-playground:<event>", version: 1, id, ...payload }
// events: resize, ready, change, error (and practice mode's answer).
// targetOrigin is the `host` option when the link gives one, "*" otherwise
// (the messages carry only the example's own inputs and results).

export const NAMESPACE = "photogrammetry-playground";
export const VERSION = 1;

const framed = window.parent !== window;
let embedId = null;
let targetOrigin = "*";

/** Sets the embed's id (echoed in every message) and the host's origin (or null for "*"). */
export function configure({ id = null, host = null } = {}) {
  embedId = id;
  targetOrigin = host ?? "*";
}

/** Whether the page runs inside a frame (only then is anything posted). */
export function isFramed() {
  return framed;
}

/** Posts `{ type: "photogrammetry-playground:<event>", version: 1, id, ...payload }` to the host. */
export function post(event, payload = {}) {
  if (!framed) return false;
  try {
    window.parent.postMessage({ ...payload, type: `${NAMESPACE}:${event}`, version: VERSION, id: embedId }, targetOrigin);
    return true;
  } catch {
    return false; // a payload that cannot be cloned, or a closed parent
  }
}

/** Canvas LMS resizes the iframe of a frame that posts this (its own, un-namespaced message). */
export function postCanvasResize(height) {
  if (!framed) return;
  try {
    window.parent.postMessage(JSON.stringify({ subject: "lti.frameResize", height }), "*");
  } catch {
    // nothing to do: the host keeps its size
  }
}

/**
 * Calls `handler(event, data)` for a namespaced message from the host page
 * (the parent window; from `host` only when it is set).
 */
export function listen(handler) {
  window.addEventListener("message", (e) => {
    if (!framed || e.source !== window.parent) return;
    if (targetOrigin !== "*" && e.origin !== targetOrigin) return;
    const d = e.data;
    if (!d || typeof d !== "object" || typeof d.type !== "string" || d.version !== VERSION) return;
    if (!d.type.startsWith(`${NAMESPACE}:`)) return;
    if (embedId !== null && d.id !== embedId) return;
    handler(d.type.slice(NAMESPACE.length + 1), d);
  });
}
