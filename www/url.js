// The example's address: "#/<id>?key=text&key=text".
// Pure functions, no DOM: what is read here only ever becomes strings that the
// core parses; nothing from the URL is written into the page as HTML.

/** The longest text taken from one URL value (a matrix of a few hundred numbers fits). */
export const MAX_URL_VALUE_LENGTH = 20000;

/**
 * Reads a location hash.
 * @param {string} hash  e.g. "#/gsd?dpi=900"
 * @returns {{ id: string, params: Array<[string, string]> }}  id "" for the home view
 */
export function parseHash(hash) {
  let h = hash || "";
  if (h.startsWith("#")) h = h.slice(1);
  if (h.startsWith("/")) h = h.slice(1);
  const q = h.indexOf("?");
  const path = q >= 0 ? h.slice(0, q) : h;
  const query = q >= 0 ? h.slice(q + 1) : "";
  let id;
  try {
    id = decodeURIComponent(path);
  } catch {
    id = path;
  }
  // URLSearchParams never throws: a malformed %-escape is kept as written.
  const params = [];
  for (const [key, value] of new URLSearchParams(query)) {
    params.push([key, value.slice(0, MAX_URL_VALUE_LENGTH)]);
  }
  return { id: id.replace(/\/+$/, ""), params };
}

/** Escapes a key or a value for the hash, keeping "," and ";" readable and spaces as "+". */
export function encodePart(text) {
  return encodeURIComponent(text)
    .replace(/%2C/gi, ",")
    .replace(/%3B/gi, ";")
    .replace(/%3A/gi, ":")
    .replace(/%20/g, "+");
}

/**
 * Builds the hash of an example with its input texts, in the given order.
 * @param {string} id
 * @param {Array<[string, string]>} entries
 */
export function buildHash(id, entries = []) {
  const query = entries.map(([k, v]) => `${encodePart(k)}=${encodePart(v)}`).join("&");
  return `#/${encodePart(id)}${query ? `?${query}` : ""}`;
}
