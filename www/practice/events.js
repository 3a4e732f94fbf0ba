// Answer events for a host page embedding a practice question in an iframe.
// (The embedding protocol lives in embed.js; this is the one place practice
// sends from, to be unified with it.)

/** The embed's options, from the hash query or the page's search string. */
function embedOption(name) {
  const hash = location.hash;
  const q = hash.indexOf("?");
  const fromHash = new URLSearchParams(q >= 0 ? hash.slice(q + 1) : "").get(name);
  return fromHash ?? new URLSearchParams(location.search).get(name);
}

/** The host's origin from the `host` option, or "*" when there is none (or it is not a URL). */
export function targetOrigin() {
  const host = embedOption("host");
  if (!host) return "*";
  try {
    return new URL(host).origin;
  } catch {
    return "*";
  }
}

/**
 * Posts one graded answer to the host page:
 * { type: "photogrammetry-playground:answer", version: 1, id, example, code, box, verdict, score, out_of }
 * (score: the points of the whole variant so far, out of out_of boxes).
 */
export function postAnswer({ example, code, box, verdict, score, outOf }) {
  if (window.parent === window) return false;
  const message = {
    type: "photogrammetry-playground:answer",
    version: 1,
    id: embedOption("id") ?? null,
    example,
    code,
    box,
    verdict,
    score,
    out_of: outOf,
  };
  window.parent.postMessage(message, targetOrigin());
  return true;
}
