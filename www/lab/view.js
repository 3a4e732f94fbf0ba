// The lab's image view: the grey image with a result layer over it (with an
// opacity) or beside it, zoom and pan by mouse wheel / drag, touch (drag,
// pinch) and keyboard (+ − Ctrl+arrows 0), a cell cursor moved by the arrow
// keys (its pixel read out in a polite live region, Enter picks it as a
// click does), a pixel inspector, grey values written
// into the pixels when zoomed in far enough, and shapes drawn on top
// (points with ellipses, boxes, outlines) in image coordinates (shapes.js
// draws them). The photo
// and the layers are painted by the lab's workers (wasm, ImageBitmaps); a
// preview (a part or a reduced image of a result still being computed) is
// drawn over them until the result arrives.

import { drawShapes, drawShapesCached } from "./shapes.js";

/** Pixels of screen per image pixel from which grey values are written in. */
const LABEL_ZOOM = 28;
const MIN_ZOOM = 0.05;
const MAX_ZOOM = 64;
/**
 * A finger covers about 40 CSS pixels: a tap picks a pixel only when one
 * image pixel is at least TAP_PICK CSS pixels wide; a tap on a view zoomed
 * out further zooms in to TAP_ZOOM about the tapped point instead (the next
 * tap picks).
 */
export const TAP_PICK = 12;
export const TAP_ZOOM = 24;

/** A number for people: up to `digits` significant digits, no trailing noise. */
export function fmt(v, digits = 5) {
  if (v === null || v === undefined || !Number.isFinite(v)) return "–";
  if (Number.isInteger(v)) return String(v);
  const s = Number(v.toPrecision(digits));
  return String(s);
}

/**
 * The inspector's words for pixel `p` ({ c, r, grey, layer, layerName }) of
 * `img`: c, r, the grey value, a reduced photo's own pixels, the frame's
 * x, y in mm, the layer's value. `long`: the live region's words ("column
 * 812, row 403, grey 87; Sobel magnitude 143.2"), else the inspector's
 * ("c 812, r 403 · grey 87 · Sobel magnitude 143.2").
 */
export function pixelWords(p, img, long = false) {
  const parts = [long ? `column ${p.c}, row ${p.r}, grey ${fmt(p.grey)}` : `c ${p.c}, r ${p.r}`];
  if (!long) parts.push(`grey ${fmt(p.grey)}`);
  // a reduced photo: the photo's own pixels this lab pixel averages
  const k = img?.photo?.factor ?? 1;
  if (k > 1) parts.push(`photo pixels c ${k * p.c}…${k * p.c + k - 1}, r ${k * p.r}…${k * p.r + k - 1}`);
  const t = img?.truth;
  if (t) {
    // the frame photo has a known pixel size: x, y in mm about the centre
    const m = (img.width - 1) / 2;
    parts.push(`x ${fmt((p.c - m) * t.pixel_mm)} mm, y ${fmt((m - p.r) * t.pixel_mm)} mm (nominal)`);
  }
  if (p.layer !== null) parts.push(`${p.layerName} ${fmt(p.layer)}`);
  else if (long && p.layerName) parts.push(`${p.layerName}: no value here`);
  return parts.join(long ? "; " : " · ");
}

/**
 * Who paints layers and photos to pixels: `(layer) → Promise<{ bitmap,
 * scale }>` (the lab's worker pool: wasm's paint_layer, www/lab/worker.js),
 * set by the lab. `layer`: { data, width, signed }; `scale`: { signed, lo,
 * hi, min, max } (the colours of colour-scales.js: grey dark = low, signed
 * blue − white 0 orange +).
 */
let painter = null;
export function setPainter(p) {
  painter = p;
}

/** Paintings by layer (and photo) object: a layer shown again is drawn at once. */
const painted = new WeakMap();

/**
 * The painting of `layer` when it was asked for already (a promise of {
 * bitmap, scale } or null), without asking for it: its scale has the
 * layer's range (the worker's, so that the page does not loop over a big
 * layer).
 *
 * `layer` painted, once per layer object (null when no painter is set or
 * the painting failed: a cancel, a stopped worker; asked again next time).
 * The lab paints every layer of a result as it arrives (prepaint), so
 * that switching layers draws at once.
 */
export function paintedOf(layer) {
  return painted.get(layer) ?? null;
}

/** `layer` painted (see paintedOf: the painting asked for already, or null), asked for now when not yet. */
export function paintOf(layer) {
  if (!painter) return Promise.resolve(null);
  let p = painted.get(layer);
  if (!p) {
    p = painter(layer).catch(() => {
      painted.delete(layer);
      return null;
    });
    painted.set(layer, p);
  }
  return p;
}

export class Viewer {
  /**
   * @param {HTMLElement} host
   * @param {{ label: string, onPick?: (c: number, r: number, ev: Event) => void, onHover?: (p: object|null) => void }} opts
   */
  constructor(host, opts) {
    this.opts = opts;
    this.canvas = document.createElement("canvas");
    this.canvas.className = "lab-canvas";
    this.canvas.tabIndex = 0;
    // operated by keys (the cell cursor): a screen reader passes them on
    this.canvas.setAttribute("role", "application");
    this.canvas.setAttribute("aria-label", `${opts.label}. Arrow keys move a cursor by one pixel (Shift: 10), Home and End to the row's ends, Enter picks the pixel; + and − zoom, Ctrl+arrows pan, 0 fits`);
    if (opts.describedBy) this.canvas.setAttribute("aria-describedby", opts.describedBy);
    // the view behind a canvas (the tests read its geometry)
    this.canvas.labViewer = this;
    // the cursor's pixel, read out (polite: the newest position wins)
    this.live = document.createElement("p");
    this.live.className = "visually-hidden lab-cursor-live";
    this.live.setAttribute("aria-live", "polite");
    if (opts.liveId) this.live.id = opts.liveId;
    host.append(this.canvas, this.live);
    /** The keyboard's cell cursor [c, r], or null (drawn while the view has focus). */
    this.cursor = null;
    this.image = null;
    this.base = null;
    this.layer = null;
    this.layerCanvas = null;
    this.opacity = 0.7;
    this.mode = "over";
    this.shapes = [];
    this.shapeCount = 0;
    this.mark = null;
    this.zoom = 1;
    this.ox = 0;
    this.oy = 0;
    this.bind();
    this.resizer = new ResizeObserver(() => this.resize());
    this.resizer.observe(host);
  }

  destroy() {
    clearTimeout(this.viewTimer);
    this.resizer.disconnect();
    this.canvas.remove();
    this.live.remove();
  }

  /**
   * Puts the cell cursor on pixel (c, r) (clamped to the image), pans the
   * view when the pixel is out of it, and reads the pixel out.
   */
  setCursor(c, r) {
    const img = this.image;
    if (!img) return;
    c = Math.min(Math.max(0, Math.round(c)), img.width - 1);
    r = Math.min(Math.max(0, Math.round(r)), img.height - 1);
    this.cursor = [c, r];
    this.keepInView(c, r);
    this.draw();
    this.hover(c, r);
    const p = this.pixelAt(c, r);
    this.live.textContent = pixelWords(p, img, true);
    this.opts.onCursor?.(c, r);
  }

  /** Pans (whole screen steps of the view, no zoom change) so that pixel (c, r) is inside the first panel with a margin. */
  keepInView(c, r) {
    const panels = this.mode === "beside" && this.layer ? 2 : 1;
    const w = this.canvas.width / panels;
    const h = this.canvas.height;
    const margin = Math.min(24 * (this.dpr || 1), w / 4, h / 4);
    const [x0, y0] = [c * this.zoom + this.ox, r * this.zoom + this.oy];
    const [x1, y1] = [x0 + this.zoom, y0 + this.zoom];
    let dx = 0;
    let dy = 0;
    if (x0 < margin) dx = margin - x0;
    else if (x1 > w - margin) dx = w - margin - x1;
    if (y0 < margin) dy = margin - y0;
    else if (y1 > h - margin) dy = h - margin - y1;
    // a jump far out of view: the pixel goes to the middle
    if (Math.abs(dx) > w / 2) dx = w / 2 - (x0 + x1) / 2;
    if (Math.abs(dy) > h / 2) dy = h / 2 - (y0 + y1) / 2;
    if (dx || dy) this.pan(Math.round(dx), Math.round(dy));
  }

  /** The pixel at the view's centre (clamped to the image): where a cursor starts. */
  centrePixel() {
    const { c, r } = this.centre();
    return [Math.min(Math.max(0, Math.round(c)), this.image.width - 1), Math.min(Math.max(0, Math.round(r)), this.image.height - 1)];
  }

  /** @param {{ width, height, grey: Float64Array, maxValue, bitmap?: ImageBitmap }} img (painted when it has no bitmap) */
  setImage(img) {
    this.image = img;
    const gen = (this.imageGen = (this.imageGen ?? 0) + 1);
    this.base = img.bitmap ?? null;
    this.layer = null;
    this.layerCanvas = null;
    this.preview = null;
    this.shapes = [];
    this.shapeCount = 0;
    this.fitted = false;
    this.resize();
    if (this.base) return Promise.resolve();
    // the full range of the values, stretched (the grey scale: dark = low)
    return paintOf({ data: img.grey, width: img.width, signed: false }).then((p) => {
      if (!p || gen !== this.imageGen) return;
      this.base = p.bitmap;
      this.draw();
    });
  }

  /** Shows `layer` (or none) over or beside the image; resolves with its colour scale once it is painted. */
  setLayer(layer) {
    const gen = (this.layerGen = (this.layerGen ?? 0) + 1);
    this.layer = layer;
    if (!layer) {
      this.layerCanvas = null;
      this.draw();
      return Promise.resolve(null);
    }
    return paintOf(layer).then((p) => {
      if (gen !== this.layerGen) return null;
      this.preview = null;
      this.scale = p?.scale ?? null;
      this.layerCanvas = p?.bitmap ?? null;
      this.draw();
      return this.scale;
    });
  }

  /**
   * A preview of the result being computed ({ bitmap, rect: [c, r, w, h]
   * image pixels it covers }), drawn over the photo and the layer until the
   * next layer is shown; null: none.
   */
  setPreview(p) {
    this.preview = p;
    this.draw();
  }

  /** The image pixels in view (the first panel): [c, r, w, h], clipped to the image. */
  visible() {
    if (!this.image) return null;
    const panels = this.mode === "beside" && this.layer ? 2 : 1;
    const w = this.canvas.width / panels;
    const c0 = Math.max(0, Math.floor(-this.ox / this.zoom));
    const r0 = Math.max(0, Math.floor(-this.oy / this.zoom));
    const c1 = Math.min(this.image.width, Math.ceil((w - this.ox) / this.zoom));
    const r1 = Math.min(this.image.height, Math.ceil((this.canvas.height - this.oy) / this.zoom));
    return c1 > c0 && r1 > r0 ? [c0, r0, c1 - c0, r1 - r0] : null;
  }

  setOpacity(o) {
    this.opacity = o;
    this.draw();
  }

  setMode(mode) {
    this.mode = mode;
    this.fit();
  }

  /** `shapes`: single shapes, or batches of points (`{ kind: "points", p, ellipse, magnify, colour }`: `pointShape`). */
  setShapes(shapes) {
    this.shapes = shapes;
    this.shapeCount = shapes.reduce((n, s) => n + (s.kind === "points" ? s.p.length / 6 : 1), 0);
    this.draw();
  }

  /** Marks pixel `[c, r]` (the clicked one: an outlined square, visible at any zoom), or none. */
  setMark(p) {
    this.mark = p;
    this.draw();
  }

  /** The image position (pixel centres at integers) at the view's centre. */
  centre() {
    const panels = this.mode === "beside" && this.layer ? 2 : 1;
    return { c: (this.canvas.width / panels / 2 - this.ox) / this.zoom - 0.5, r: (this.canvas.height / 2 - this.oy) / this.zoom - 0.5 };
  }

  /** Tells the owner the view moved (zoom, pan, fit), at most every 250 ms. */
  viewChanged() {
    if (!this.opts.onView) return;
    clearTimeout(this.viewTimer);
    this.viewTimer = setTimeout(() => this.opts.onView(), 250);
  }

  resize() {
    const w = Math.max(200, this.canvas.parentElement?.clientWidth || 600);
    const img = this.image;
    const aspect = img ? (img.height / (img.width * (this.mode === "beside" && this.layer ? 2 : 1))) : 0.75;
    const h = Math.round(Math.min(Math.max(220, w * aspect), window.innerHeight * 0.7));
    const dpr = window.devicePixelRatio || 1;
    const [oldW, oldH] = [this.canvas.width, this.canvas.height];
    this.canvas.style.height = `${h}px`;
    this.canvas.width = Math.round(w * dpr);
    this.canvas.height = Math.round(h * dpr);
    this.dpr = dpr;
    // the whole image stays fitted until the student zooms or pans; after
    // that (or a zoomTo) the image point at the view's centre stays there
    if (!this.fitted || this.atFit) this.fit();
    else {
      const panels = this.mode === "beside" && this.layer ? 2 : 1;
      this.ox += (this.canvas.width - oldW) / panels / 2;
      this.oy += (this.canvas.height - oldH) / 2;
      this.draw();
    }
  }

  /** The whole image in view. */
  fit() {
    if (!this.image || !this.canvas.width) {
      this.draw();
      return;
    }
    const panels = this.mode === "beside" && this.layer ? 2 : 1;
    const w = this.canvas.width / panels;
    this.zoom = Math.min(w / this.image.width, this.canvas.height / this.image.height);
    this.ox = (w - this.image.width * this.zoom) / 2;
    this.oy = (this.canvas.height - this.image.height * this.zoom) / 2;
    this.fitted = true;
    this.atFit = true;
    this.draw();
    this.viewChanged();
  }

  /** Image position (continuous, pixel centres at integers) under canvas point (px, py). */
  toImage(px, py) {
    const panels = this.mode === "beside" && this.layer ? 2 : 1;
    const w = this.canvas.width / panels;
    const x = ((px % w) - this.ox) / this.zoom - 0.5;
    const y = (py - this.oy) / this.zoom - 0.5;
    return [x, y];
  }

  zoomAt(f, px, py) {
    const z = Math.max(MIN_ZOOM, Math.min(MAX_ZOOM, this.zoom * f));
    const k = z / this.zoom;
    this.ox = px - (px - this.ox) * k;
    this.oy = py - (py - this.oy) * k;
    this.zoom = z;
    this.atFit = false;
    this.draw();
    this.viewChanged();
  }

  /** Moves the image by (dx, dy) canvas pixels. */
  pan(dx, dy) {
    this.ox += dx;
    this.oy += dy;
    this.atFit = false;
    this.draw();
    this.viewChanged();
  }

  /** Zooms so that one image pixel is `z` screen pixels, centred on (c, r). */
  zoomTo(z, c, r) {
    z = Math.max(MIN_ZOOM, Math.min(MAX_ZOOM, z)); // (a link's zoom is any number)
    this.zoom = z;
    this.ox = this.canvas.width / 2 - (c + 0.5) * z;
    this.oy = this.canvas.height / 2 - (r + 0.5) * z;
    this.atFit = false;
    this.draw();
    this.viewChanged();
  }

  bind() {
    const cv = this.canvas;
    const pos = (ev) => {
      const b = cv.getBoundingClientRect();
      return [((ev.clientX - b.left) / b.width) * cv.width, ((ev.clientY - b.top) / b.height) * cv.height];
    };
    cv.addEventListener("wheel", (ev) => {
      ev.preventDefault();
      const [px, py] = pos(ev);
      this.zoomAt(ev.deltaY < 0 ? 1.25 : 0.8, px, py);
    }, { passive: false });
    const pointers = new Map();
    let moved = 0;
    let pinch = null;
    // a shape being dragged (dragHandler: { start(pos) → grabbed?, move(pos), end(pos) }, image positions)
    let dragging = null;
    cv.addEventListener("pointerdown", (ev) => {
      cv.setPointerCapture(ev.pointerId);
      pointers.set(ev.pointerId, pos(ev));
      moved = 0;
      if (pointers.size === 1 && this.image && this.dragHandler?.start?.(this.toImage(...pos(ev)))) dragging = ev.pointerId;
      if (pointers.size === 2) {
        const [a, b] = [...pointers.values()];
        pinch = Math.hypot(a[0] - b[0], a[1] - b[1]);
      }
    });
    cv.addEventListener("pointermove", (ev) => {
      const p = pos(ev);
      if (this.image) {
        const [x, y] = this.toImage(p[0], p[1]);
        this.hover(Math.round(x), Math.round(y));
      }
      const last = pointers.get(ev.pointerId);
      if (!last) return;
      pointers.set(ev.pointerId, p);
      if (pointers.size === 2 && pinch) {
        const [a, b] = [...pointers.values()];
        const d = Math.hypot(a[0] - b[0], a[1] - b[1]);
        this.zoomAt(d / pinch, (a[0] + b[0]) / 2, (a[1] + b[1]) / 2);
        pinch = d;
        moved += 10;
        return;
      }
      if (dragging === ev.pointerId) {
        moved += Math.abs(p[0] - last[0]) + Math.abs(p[1] - last[1]);
        this.dragHandler?.move?.(this.toImage(...p));
        return;
      }
      moved += Math.abs(p[0] - last[0]) + Math.abs(p[1] - last[1]);
      this.pan(p[0] - last[0], p[1] - last[1]);
    });
    const up = (ev) => {
      const p = pointers.get(ev.pointerId);
      pointers.delete(ev.pointerId);
      if (pointers.size < 2) pinch = null;
      if (dragging === ev.pointerId) {
        dragging = null;
        if (this.image) this.dragHandler?.end?.(this.toImage(...p), moved);
        return;
      }
      if (!p || !this.image) return;
      if (moved < 6) {
        if (ev.pointerType === "touch" && this.opts.tapZoom !== false && this.zoom / (this.dpr || 1) < TAP_PICK) {
          this.zoomAt(TAP_ZOOM * (this.dpr || 1) / this.zoom, p[0], p[1]);
          this.opts.onTapZoom?.();
          return;
        }
        const [x, y] = this.toImage(p[0], p[1]);
        const c = Math.round(x);
        const r = Math.round(y);
        if (c >= 0 && r >= 0 && c < this.image.width && r < this.image.height) {
          // the keyboard's cursor goes on from the clicked pixel
          this.cursor = [c, r];
          this.opts.onPick?.(c, r, ev, [x, y]);
        }
      }
    };
    cv.addEventListener("pointerup", up);
    cv.addEventListener("pointercancel", (ev) => {
      pointers.delete(ev.pointerId);
      if (dragging === ev.pointerId) {
        dragging = null;
        this.dragHandler?.end?.(null, 0);
      }
    });
    cv.addEventListener("pointerleave", () => this.opts.onHover?.(null));
    cv.addEventListener("keydown", (ev) => this.key(ev));
    // the cursor shows while the view has the focus
    cv.addEventListener("focus", () => {
      if (this.image && !this.cursor) this.setCursor(...this.centrePixel());
      else this.draw();
    });
    cv.addEventListener("blur", () => this.draw());
  }

  /**
   * The keys: arrows move the cell cursor (Shift: 10 pixels), Home / End to
   * the row's first / last pixel (Ctrl: the image's first / last), Enter or
   * Space picks the cursor's pixel as a click does; + − zoom about the
   * view's middle, Ctrl+arrows pan, 0 fits.
   */
  key(ev) {
    const cv = this.canvas;
    const step = 40 * (this.dpr || 1);
    const mid = [cv.width / 2, cv.height / 2];
    const dir = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] }[ev.key];
    const img = this.image;
    let k = null;
    if (dir && (ev.ctrlKey || ev.metaKey)) k = () => this.pan(-dir[0] * step, -dir[1] * step);
    else if (dir && img) {
      k = () => {
        const [c, r] = this.cursor ?? this.centrePixel();
        const n = ev.shiftKey ? 10 : 1;
        this.setCursor(c + dir[0] * n, r + dir[1] * n);
      };
    } else if ((ev.key === "Home" || ev.key === "End") && img) {
      k = () => {
        const [, r] = this.cursor ?? this.centrePixel();
        const end = ev.key === "End";
        const row = ev.ctrlKey || ev.metaKey ? (end ? img.height - 1 : 0) : r;
        this.setCursor(end ? img.width - 1 : 0, row);
      };
    } else if ((ev.key === "Enter" || ev.key === " ") && img && !ev.repeat) {
      k = () => {
        const [c, r] = this.cursor ?? this.centrePixel();
        this.opts.onPick?.(c, r, ev, [c, r]);
      };
    } else {
      k = {
        "+": () => this.zoomAt(1.25, ...mid),
        "=": () => this.zoomAt(1.25, ...mid),
        "-": () => this.zoomAt(0.8, ...mid),
        0: () => this.fit(),
      }[ev.key];
    }
    if (k) {
      ev.preventDefault();
      k();
    }
  }

  hover(c, r) {
    const img = this.image;
    if (!img || c < 0 || r < 0 || c >= img.width || r >= img.height) {
      this.opts.onHover?.(null);
      return;
    }
    this.opts.onHover?.(this.pixelAt(c, r));
  }

  /** Pixel (c, r) inside the image: { c, r, grey, layer (null: none or not finite), layerName }. */
  pixelAt(c, r) {
    const img = this.image;
    let layerValue = null;
    const l = this.layer;
    if (l && c >= l.c0 && r >= l.r0 && c < l.c0 + l.width && r < l.r0 + l.height) {
      const v = l.data[(r - l.r0) * l.width + (c - l.c0)];
      if (Number.isFinite(v)) layerValue = v;
    }
    return { c, r, grey: img.grey[r * img.width + c], layer: layerValue, layerName: l?.name ?? null };
  }

  draw() {
    const cv = this.canvas;
    const ctx = cv.getContext("2d");
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.fillStyle = getComputedStyle(cv).getPropertyValue("--bg-soft") || "#f6f8fa";
    ctx.fillRect(0, 0, cv.width, cv.height);
    if (!this.base) return;
    const panels = this.mode === "beside" && this.layerCanvas ? 2 : 1;
    const w = cv.width / panels;
    for (let p = 0; p < panels; p++) {
      ctx.save();
      ctx.beginPath();
      ctx.rect(p * w, 0, w, cv.height);
      ctx.clip();
      ctx.setTransform(this.zoom, 0, 0, this.zoom, p * w + this.ox, this.oy);
      ctx.imageSmoothingEnabled = false;
      const onlyLayer = panels === 2 && p === 1;
      if (!onlyLayer) ctx.drawImage(this.base, 0, 0);
      if (this.layerCanvas && (onlyLayer || panels === 1)) {
        ctx.globalAlpha = onlyLayer ? 1 : this.opacity;
        ctx.drawImage(this.layerCanvas, this.layer.c0, this.layer.r0);
        ctx.globalAlpha = 1;
      }
      if (this.preview && (onlyLayer || panels === 1)) {
        const [c, r, pw, ph] = this.preview.rect;
        // over the photo, as the result will be (not over the old layer: that drew it darker)
        if (!onlyLayer) ctx.drawImage(this.base, c, r, pw, ph, c, r, pw, ph);
        ctx.globalAlpha = onlyLayer ? 1 : this.opacity;
        ctx.drawImage(this.preview.bitmap, c, r, pw, ph);
        ctx.globalAlpha = 1;
        // its outline, dashed (the part already computed; the rest follows)
        const px = (this.dpr || 1) / this.zoom;
        ctx.lineWidth = 2 * px;
        for (const [colour, offset] of [["#fff", 0], ["#d6336c", 6 * px]]) {
          ctx.strokeStyle = colour;
          ctx.setLineDash([6 * px, 6 * px]);
          ctx.lineDashOffset = offset;
          ctx.strokeRect(c, r, pw, ph);
        }
        ctx.setLineDash([]);
      }
      if (this.zoom >= LABEL_ZOOM) this.labels(ctx, p * w, w, onlyLayer);
      drawShapesCached(ctx, p * w, w, this);
      this.drawMark(ctx);
      this.drawCursor(ctx);
      ctx.restore();
    }
  }

  /** Grey values (or layer values) written into the visible pixels. */
  labels(ctx, x0, w, layerOnly) {
    const img = this.image;
    const c0 = Math.max(0, Math.floor(-this.ox / this.zoom));
    const r0 = Math.max(0, Math.floor(-this.oy / this.zoom));
    const c1 = Math.min(img.width - 1, Math.ceil((w - this.ox) / this.zoom));
    const r1 = Math.min(img.height - 1, Math.ceil((this.canvas.height - this.oy) / this.zoom));
    if (c1 < c0 || r1 < r0) return;
    ctx.font = `${0.3}px sans-serif`;
    ctx.textAlign = "center";
    ctx.textBaseline = "middle";
    const l = this.layer;
    const drawn = this.drawnPixels(c0, r0, c1 - c0 + 1, r1 - r0 + 1, layerOnly);
    for (let r = r0; r <= r1; r++) {
      for (let c = c0; c <= c1; c++) {
        const grey = img.grey[r * img.width + c];
        const inside = l && c >= l.c0 && r >= l.r0 && c < l.c0 + l.width && r < l.r0 + l.height;
        const lv = inside ? l.data[(r - l.r0) * l.width + (c - l.c0)] : NaN;
        const v = layerOnly ? lv : grey;
        if (!Number.isFinite(v)) continue;
        // dark text on light pixels, light on dark ones (the colour the pixel is drawn in)
        const i = 4 * ((r - r0) * (c1 - c0 + 1) + (c - c0));
        ctx.fillStyle = 0.299 * drawn[i] + 0.587 * drawn[i + 1] + 0.114 * drawn[i + 2] > 140 ? "#000" : "#fff";
        const text = Number.isInteger(v) ? String(v) : v.toFixed(Math.abs(v) < 10 ? 2 : 1);
        ctx.fillText(text, c + 0.5, r + 0.5, 0.95);
      }
    }
  }

  /**
   * The RGBA the view draws at image pixels [c0, c0 + w) × [r0, r0 + h):
   * the painted photo with the layer over it at the view's opacity (or the
   * layer alone on black), read back from a canvas of that size.
   */
  drawnPixels(c0, r0, w, h, layerOnly) {
    const cv = typeof OffscreenCanvas === "undefined" ? Object.assign(document.createElement("canvas"), { width: w, height: h }) : new OffscreenCanvas(w, h);
    const ctx = cv.getContext("2d", { willReadFrequently: true });
    ctx.fillStyle = "#000";
    ctx.fillRect(0, 0, w, h);
    if (!layerOnly && this.base) ctx.drawImage(this.base, -c0, -r0);
    if (this.layerCanvas) {
      ctx.globalAlpha = layerOnly ? 1 : this.opacity;
      ctx.drawImage(this.layerCanvas, this.layer.c0 - c0, this.layer.r0 - r0);
    }
    return ctx.getImageData(0, 0, w, h).data;
  }

  /**
   * The clicked pixel: its square outlined (dark inside, light outside, so
   * that it shows on any grey), with four ticks pointing at it from 6 to 16
   * screen pixels away, so that it is found when the pixel is smaller than a
   * screen pixel.
   */
  drawMark(ctx) {
    if (!this.mark) return;
    const [c, r] = this.mark;
    const px = (1 / this.zoom) * (this.dpr || 1);
    const [x, y] = [c + 0.5, r + 0.5];
    const half = Math.max(0.5, 3 * px);
    for (const [colour, width] of [["#fff", 4], ["#d6336c", 2]]) {
      ctx.strokeStyle = colour;
      ctx.lineWidth = width * px;
      ctx.beginPath();
      ctx.rect(x - half, y - half, 2 * half, 2 * half);
      for (const [dx, dy] of [[1, 0], [-1, 0], [0, 1], [0, -1]]) {
        ctx.moveTo(x + dx * (half + 6 * px), y + dy * (half + 6 * px));
        ctx.lineTo(x + dx * (half + 16 * px), y + dy * (half + 16 * px));
      }
      ctx.stroke();
    }
  }

  /**
   * The keyboard's cursor while the view has the focus: the pixel's square
   * (at least 10 screen pixels) in the focus colour, a white and a dark
   * line, so that it shows on any grey and any layer colour.
   */
  drawCursor(ctx) {
    if (!this.cursor || document.activeElement !== this.canvas) return;
    const [c, r] = this.cursor;
    const px = (1 / this.zoom) * (this.dpr || 1);
    const half = Math.max(0.5, 5 * px);
    const [x, y] = [c + 0.5, r + 0.5];
    const focus = getComputedStyle(this.canvas).getPropertyValue("--focus").trim() || "#c2410c";
    for (const [colour, width, grow] of [["#000", 5, 2], ["#fff", 3, 1], [focus, 2, 0]]) {
      ctx.strokeStyle = colour;
      ctx.lineWidth = width * px;
      ctx.strokeRect(x - half - grow * px, y - half - grow * px, 2 * (half + grow * px), 2 * (half + grow * px));
    }
  }

  /** The shapes (default: the view's) stroked into `ctx` (shapes.js drawShapes). */
  drawShapes(ctx, shapes = this.shapes) {
    drawShapes(ctx, shapes, this);
  }
}
