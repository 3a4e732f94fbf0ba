// Answer events for a host page embedding a practice question in an iframe,
// sent through the one module that talks to the host (embed-bridge.js): the
// same namespaced, versioned message as ready/change/error, to the origin of
// the link's `host` option.

import { post } from "../embed-bridge.js";

/**
 * Posts one graded answer to the host page:
 * { type: "photogrammetry-playground:answer", version: 1, id, example, code, box, verdict, score, out_of }
 * (score: the points of the whole variant so far, out of out_of boxes).
 * Returns whether it was posted (only inside a frame).
 */
export function postAnswer({ example, code, box, verdict, score, outOf }) {
  return post("answer", { example, code, box, verdict, score, out_of: outOf });
}
