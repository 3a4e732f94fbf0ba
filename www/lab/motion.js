// Motion in the lab (issue 34, item 2: "in the lab, the same for a chosen
// small window on the photo"): under the explanation of a clicked pixel, a
// "Watch it move" button opens, in the lab itself, the figure of the example
// that explains it — the example pages' figure kit and motion controller
// (www/figures/index.js, www/motion/motion.js) — solved by the page's core
// with the inputs its link carries (explain.js made them: they are read back
// from the link, not built again), so the window of the photo is what moves.
// The photo view outlines the part of the window the frame shows (the kernel
// over the neighbourhood, Moravec's pixel and its neighbours, the follower's
// pixel on the boundary); Escape or Close closes it; a new click's
// explanation replaces it (and opens moving again if it was open).
//
// lab.js creates one per lab (`watchMotion(lab)`); it watches `lab.explain`
// (every family writes its explanation there: showExplain, or its own table
// with links), so no family knows of it.

import { loadCatalog, loadCore } from "../core.js";
import { loadFigures, mountFigures } from "../figures/index.js";
import { el } from "../dom.js";
import { parseHash } from "../url.js";
import { testData } from "../test-hooks.js";

/** The marker of this module's shapes on the photo view (the families' own shapes stay). */
const OWN = "labMotion";

/** The link's inputs as the example's texts ({ key: text }), and its id, from `index.html#/<id>?…`. */
export function linkTexts(href) {
  const { id, params } = parseHash(href.slice(href.indexOf("#")));
  return { id, texts: Object.fromEntries(params) };
}

/**
 * Where on the photo the example's window lies, and what of it a frame
 * covers: [{ c0, r0, w, h }] (lab pixels, the window first), or [] where the
 * lab does not know the place (the matching examples: their window is the
 * search photo's). `family`: the lab family the example explains (the
 * catalog's `lab`); `pick`: the lab's clicked pixel; `inputs`: the parsed
 * inputs; `solution`; `frame`: the frame shown, or null (the whole window).
 */
export function windowBoxes(family, pick, inputs, solution, frame) {
  if (!pick) return [];
  const rows = inputs?.window;
  if ((family === "filters" || family === "edges" || family === "interest") && Array.isArray(rows) && rows.length && Array.isArray(rows[0])) {
    const [h, w] = [rows.length, rows[0].length];
    // filters and edges read the window round the pixel, the interest windows from their anchor (interest.js: c − ⌊(n−1)/2⌋)
    const o = { c: pick[0] - Math.floor((w - 1) / 2), r: pick[1] - Math.floor((h - 1) / 2) };
    const boxes = [{ c0: o.c, r0: o.r, w, h }];
    if (frame && Number.isInteger(frame.c) && Number.isInteger(frame.r)) {
      // the kernel (filters, edges: valid outputs start at its half + 1) or the pixel's 3 × 3 (Moravec's differences)
      const half = (k) => (Number.isInteger(solution?.result?.[k]) ? solution.result[k] - 1 : 1);
      const [hc, hr] = [half("output_first_c"), half("output_first_r")];
      boxes.push({ c0: o.c + frame.c - 1 - hc, r0: o.r + frame.r - 1 - hr, w: 2 * hc + 1, h: 2 * hr + 1 });
    }
    return boxes;
  }
  if (family === "boundaries" && Array.isArray(frame?.to)) {
    // the boundary's pixels are the photo's: the pixel the follower reached
    return [{ c0: frame.to[0], r0: frame.to[1], w: 1, h: 1 }];
  }
  return [];
}

/** The outline shapes of `boxes` for the view (a dark halo under a bright line, visible on any grey); a single pixel also gets a ring of 9 screen px, seen at any zoom. */
function outline(boxes) {
  return boxes.flatMap((b, i) => [
    { kind: "rect", c0: b.c0, r0: b.r0, w: b.w, h: b.h, colour: "#000", width: i ? 5 : 4, [OWN]: true },
    { kind: "rect", c0: b.c0, r0: b.r0, w: b.w, h: b.h, colour: i ? "#00e5ff" : "#ffe600", width: i ? 2.5 : 2, [OWN]: true },
    ...(b.w === 1 && b.h === 1
      ? [{ kind: "dot", c: b.c0, r: b.r0, size: 9, colour: "#000", width: 4, [OWN]: true }, { kind: "dot", c: b.c0, r: b.r0, size: 9, colour: "#00e5ff", width: 2, [OWN]: true }]
      : []),
  ]);
}

/** The least size (CSS px) the window has on the photo view while it moves: a smaller one is zoomed in to. */
const MIN_WINDOW_PX = 72;

/** The lab's motion: watches `lab.explain`; returns { close(), destroy() }. */
export function watchMotion(lab) {
  const button = el("button", { type: "button", id: "lab-motion-open", "aria-expanded": "false", "aria-controls": "lab-motion" }, "▶ Watch it move");
  const playing = el("a", { id: "lab-motion-link" }, "open it playing");
  const offer = el("p", { class: "lab-motion-offer", id: "lab-motion-offer", hidden: true }, button, " ", el("span", { class: "muted" }, "(here, on this window of the photo; or ", playing, ")"));
  const close = el("button", { type: "button", id: "lab-motion-close" }, "Close");
  const title = el("h3", { id: "lab-motion-title", tabindex: "-1" }, "The window in motion");
  const where = el("p", { class: "muted lab-motion-where", id: "lab-motion-where" });
  const figures = el("div", { class: "lab-motion-figure" });
  const panel = el("section", { class: "lab-motion", id: "lab-motion", "aria-labelledby": "lab-motion-title", hidden: true },
    el("div", { class: "lab-motion-head" }, title, close), where, figures);
  const host = el("div", { class: "lab-motion-host", id: "lab-motion-host" }, offer, panel);
  lab.explain.after(host);

  /** The offered motion: { href, id, inputs, solution, mounted } or null; `open` while its panel shows. */
  let current = null;
  let open = false;
  let serial = 0;

  const ownShapes = (viewer) => (viewer?.shapes ?? []).filter((s) => !s[OWN]);
  function outlineNow() {
    const viewer = lab.viewer;
    if (!viewer) return;
    const boxes = open && current ? windowBoxes(current.family, current.pick, current.inputs, current.solution, current.mounted.frame?.() ?? null) : [];
    testData(host, "window", boxes.map((b) => [b.c0, b.r0, b.w, b.h].join(",")).join(" "));
    const base = ownShapes(viewer);
    if (!boxes.length && base.length === viewer.shapes.length) return;
    viewer.setShapes([...base, ...outline(boxes)]);
  }

  function hide({ focus = false } = {}) {
    if (!open) return;
    open = false;
    panel.hidden = true;
    button.setAttribute("aria-expanded", "false");
    current?.mounted.motions().forEach((m) => m.playing && m.pause({ speak: false }));
    outlineNow();
    if (focus && !offer.hidden) button.focus();
  }

  function drop() {
    hide();
    current?.mounted.destroy();
    current = null;
    figures.replaceChildren();
    offer.hidden = true;
    testData(host, "window", "");
  }

  async function show() {
    if (!current) return;
    open = true;
    panel.hidden = false;
    button.setAttribute("aria-expanded", "true");
    const shown = current;
    if (!shown.solution) {
      // the topic's wasm is fetched when a student first asks for a motion, not with every explanation
      where.textContent = `${shown.title}: loading…`;
      const message = await solve(shown).catch((e) => e?.message ?? String(e));
      if (current !== shown || !open) return;
      if (message) {
        where.textContent = `${shown.title}: ${message}`;
        return;
      }
      where.textContent = windowWords(shown);
    }
    if (!figures.firstChild) {
      figures.append(current.host);
      current.mounted.update(current.solution);
    }
    current.mounted.play({ auto: true });
    // a window of a few pixels is a speck on a fitted photo: the view zooms in about it (the student zooms out as ever)
    const box = windowBoxes(current.family, current.pick, current.inputs, current.solution, null)[0];
    const viewer = lab.viewer;
    const dpr = viewer?.dpr || 1;
    if (box && box.w > 1 && viewer && (Math.max(box.w, box.h) * viewer.zoom) / dpr < MIN_WINDOW_PX) {
      viewer.zoomTo((MIN_WINDOW_PX * dpr) / Math.max(box.w, box.h), box.c0 + (box.w - 1) / 2, box.r0 + (box.h - 1) / 2);
    }
    outlineNow();
    // the keyboard lands on the motion's first control (Play, or Step forward with reduced motion)
    requestAnimationFrame(() => {
      const first = [...panel.querySelectorAll(".motion-bar button")].find((b) => !b.hidden && !b.disabled);
      (first ?? title).focus();
    });
  }

  /** The explanation changed: the first of its links whose example moves is offered (the same link: nothing changes). */
  async function follow() {
    const links = lab.explain.hidden ? [] : [...lab.explain.querySelectorAll('a[href^="index.html#/"]')];
    if (current && links.some((a) => a.getAttribute("href") === current.href)) return;
    const reopen = open;
    drop();
    const mine = ++serial;
    const pick = lab.picked ? [...lab.picked] : null;
    for (const a of links) {
      const href = a.getAttribute("href");
      const next = await prepare(href, pick, outlineNow).catch((e) => {
        console.warn("lab motion:", e);
        return null;
      });
      if (mine !== serial) {
        next?.mounted.destroy();
        return;
      }
      if (!next) continue;
      current = next;
      playing.href = `${href}&play=auto`;
      playing.setAttribute("aria-label", `${next.id}, open it playing`);
      where.textContent = next.title;
      offer.hidden = false;
      if (reopen) show();
      return;
    }
  }

  button.addEventListener("click", () => (open ? hide({ focus: true }) : show()));
  close.addEventListener("click", () => hide({ focus: true }));
  panel.addEventListener("keydown", (e) => {
    if (e.key !== "Escape" || e.defaultPrevented) return;
    e.preventDefault();
    hide({ focus: true });
  });
  const observer = new MutationObserver(() => follow());
  observer.observe(lab.explain, { childList: true, subtree: true, attributes: true, attributeFilter: ["hidden", "href"] });
  follow(); // the explanation that loaded this module (lab.js lazyMotion)

  return {
    close: () => hide(),
    destroy() {
      serial++;
      observer.disconnect();
      drop();
      host.remove();
    },
  };
}

/** The example of `href` with its link's texts and its figure mounted (not yet solved nor shown; `onFrame` after each frame drawn); null when it does not move. */
async function prepare(href, pick, onFrame) {
  const { id, texts } = linkTexts(href);
  const entry = (await loadCatalog()).find((e) => e.id === id);
  if (!entry) return null;
  await loadFigures(entry.module);
  const host = el("div", { class: "lab-motion-figures", "data-id": id });
  // every frame drawn (the controller's onStep) moves the outline on the photo
  const mounted = mountFigures(host, id, { onStep: () => onFrame() });
  if (!mounted?.hasMotion) {
    mounted?.destroy();
    return null;
  }
  return { href, id, texts, family: entry.lab, title: entry.title, inputs: null, solution: null, mounted, host, pick };
}

/** Solves the prepared example with its link's inputs (the page's core, `solve(id, inputs)`): null, or what went wrong in words. */
async function solve(p) {
  const core = await loadCore();
  await core.load(p.id);
  const parsed = core.parseInputs(p.id, p.texts);
  const errors = Object.entries(parsed?.errors ?? {});
  if (errors.length) return `the link's inputs are not valid (${errors.map(([k, m]) => `${k}: ${m}`).join("; ")})`;
  p.inputs = parsed.inputs;
  p.solution = core.solve(p.id, parsed.inputs ?? {});
  return null;
}

/** What the panel shows, in words: the example and where its window is on the photo. */
function windowWords(p) {
  const box = windowBoxes(p.family, p.pick, p.inputs, p.solution, null)[0];
  const at = box
    ? ` on the photo's ${box.w} × ${box.h} pixels from column ${box.c0}, row ${box.r0} (outlined on the photo in yellow, the frame's part in cyan)`
    : p.family === "boundaries"
      ? " along the traced boundary (the pixel reached is outlined on the photo)"
      : " with the windows of the photo the lab used";
  return `${p.title}${at}.`;
}
