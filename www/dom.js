// A tiny element builder. Strings always become text nodes: nothing here (or
// anywhere in the page) parses data as HTML.

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

/** A string safe to use in an element id. */
export function idPart(text) {
  return String(text).replace(/[^A-Za-z0-9_-]/g, (ch) => `_${ch.charCodeAt(0).toString(16)}`);
}
