// A tiny element builder. Strings always become text nodes: nothing here (or
// anywhere in the page) parses data as HTML. (The one HTML the page parses is
// the build's own: the seed solution scripts/prerender.mjs saved from this
// page, which preload-route.js shows until the page's view is in.)

/**
 * el("p", { class: "note", "aria-live": "polite" }, "text", childNode, ...)
 * Attribute values are set with setAttribute (so they are never markup);
 * `class` may be a string; null/false/undefined attributes and children are skipped.
 */
export function el(tag, attrs = {}, ...children) {
  const node = document.createElement(tag);
  for (const [name, value] of Object.entries(attrs || {})) {
    if (value === null || value === undefined || value === false) continue;
    node.setAttribute(name, value === true ? "" : String(value));
  }
  append(node, children);
  return node;
}

/** Appends strings (as text) and nodes, flattening arrays. */
export function append(node, children) {
  for (const child of children.flat(Infinity)) {
    if (child === null || child === undefined || child === false) continue;
    node.append(child instanceof Node ? child : document.createTextNode(String(child)));
  }
  return node;
}

/**
 * Sets the text of an element that holds one text node by changing that node's
 * data (else as textContent). A frame of a motion rewrites its counter and
 * caption 60 times a second: textContent replaces the text node, a change of
 * the element's children, which makes the page's `:has()` rules (style.css
 * `html:has(.update-notice)`, …) recalculate the style of the document (2–7 ms
 * on an example page of 12 000 elements); the node's data is a text change only.
 */
export function setText(node, text) {
  const first = node.firstChild;
  if (first && first === node.lastChild && first.nodeType === Node.TEXT_NODE) {
    if (first.data !== text) first.data = text;
  } else node.textContent = text;
}

/** A string safe to use in an element id. */
/** Adds the stylesheet at `href` to the page once (a module's own rules, loaded with it). */
export function addStylesheet(href) {
  if (typeof document === "undefined" || document.querySelector(`link[rel="stylesheet"][href="${href}"]`)) return;
  document.head.append(el("link", { rel: "stylesheet", href }));
}

export function idPart(text) {
  return String(text).replace(/[^A-Za-z0-9_-]/g, (ch) => `_${ch.charCodeAt(0).toString(16)}`);
}

/**
 * Keeps `node` at the tallest height it has had at its present width: a line
 * whose text gets shorter (the answer line loses "the course notes print …"
 * when an input leaves the seed's value) then keeps its room, and what is
 * below it does not move (a move repaints the whole page: thousands of
 * formula boxes). A new width starts afresh. Returns a stop function.
 */
export function keepTallest(node) {
  let width = null;
  let tallest = 0;
  const observer = new ResizeObserver((entries) => {
    const entry = entries[entries.length - 1];
    const now = entry.contentRect.width;
    const height = entry.borderBoxSize?.[0]?.blockSize ?? node.offsetHeight;
    if (now !== width) {
      // a phone turned, a window resized: the room kept for the old width goes
      // (measured again without it: rare, so one read of the layout is fine)
      width = now;
      tallest = 0;
      if (node.style.minHeight) {
        node.style.minHeight = "";
        tallest = node.offsetHeight;
        if (tallest) node.style.minHeight = `${tallest}px`;
        return;
      }
    }
    if (height > tallest) {
      tallest = height;
      node.style.minHeight = `${height}px`;
    }
  });
  observer.observe(node);
  return () => observer.disconnect();
}
