// The shapes a lab view draws over its image, in image coordinates: points
// with their error ellipses (one batch per operator run: pointShape), dots,
// boxes, outlines, lines, arrows, crosses and labels. Many of them (Förstner's
// points on a 12 MP photo) are drawn once into a canvas of the panel's size
// (drawShapesCached), the small round ones stamped instead of stroked
// (stamps); the rest stroked a path per style (drawShapes). `view` is the
// Viewer (view.js): its zoom, offset (ox, oy), device pixel ratio (dpr),
// canvas and shapes.

/** Views with at least this many shapes keep them drawn in a canvas of their own (drawShapesCached). */
const SHAPES_CACHED = 200;
/** Stroked shapes of one style drawn as one path, at most this many a path (drawShapes). */
const PATH_SHAPES = 64;

/**
 * Shapes' sizes, shared by their strokes (drawShapes) and their stamps
 * (stamps), so that the two draw the same: a line's width and a dot's radius
 * in screen pixels (times the device pixel ratio), an ellipse's least
 * semi-axis in canvas pixels.
 */
const LINE_WIDTH = 2;
const DOT_SIZE = 3;
const LEAST_AXIS = 2;

/** Point `i` (its first number's index) of batch `s` ({ p: [c, r, score, σmax, σmin, angle]…, ellipse, magnify, colour }) as a shape. */
export function pointShape(s, i) {
  const p = s.p;
  return s.ellipse
    ? { kind: "ellipse", c: p[i], r: p[i + 1], a: p[i + 3] * s.magnify, b: p[i + 4] * s.magnify, angle: p[i + 5] + Math.PI / 2, colour: s.colour }
    : { kind: "dot", c: p[i], r: p[i + 1], size: DOT_SIZE, colour: s.colour };
}

/** Stamps by radius, stroke width and colour (stampOf). */
const STAMPS = new Map();

/**
 * The shapes of panel `x0` (`w` wide): when there are many (Förstner's
 * points on a 12 MP photo: 100 000 ellipses), drawn once into a canvas of
 * the panel's size and that canvas drawn while neither the shapes nor the
 * view change, so that a preview, the cursor or the opacity redraw the
 * view at once; else drawn directly. Into that canvas, the shapes outside
 * the panel are left out and the ones a few pixels across (a point's
 * ellipse smaller than its least size, a dot) are stamped (`stamps`):
 * stroking 100 000 ellipses took Chromium a second, stamping them about 40 ms.
 */
export function drawShapesCached(ctx, x0, w, view) {
  if (view.shapeCount < SHAPES_CACHED || typeof OffscreenCanvas === "undefined") {
    drawShapes(ctx, view.shapes, view);
    return;
  }
  const [cw, ch] = [Math.ceil(w), view.canvas.height];
  const key = [view.zoom, view.ox, view.oy, cw, ch, view.dpr].join(" ");
  view.shapeCache ??= new Map();
  let cache = view.shapeCache.get(x0);
  if (!cache || cache.shapes !== view.shapes || cache.key !== key) {
    const canvas = cache && cache.canvas.width === cw && cache.canvas.height === ch ? cache.canvas : new OffscreenCanvas(cw, ch);
    const c = canvas.getContext("2d");
    c.setTransform(1, 0, 0, 1, 0, 0);
    c.clearRect(0, 0, cw, ch);
    const rest = stamps(c, cw, ch, view);
    c.setTransform(view.zoom, 0, 0, view.zoom, view.ox, view.oy);
    drawShapes(c, rest, view);
    cache = { shapes: view.shapes, key, canvas };
    view.shapeCache.set(x0, cache);
  }
  ctx.save();
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.drawImage(cache.canvas, x0, 0);
  ctx.restore();
}

/**
 * Into the panel canvas `ctx` (`cw` × `ch` canvas pixels, identity
 * transform): the small round shapes of one colour stamped — one stroked
 * circle of their size drawn once (`stampOf`), its alpha laid over the
 * panel's at each shape's pixel (source over, the centre within half a
 * pixel), coloured and put in one `putImageData`. Returns the shapes left
 * to stroke, without those wholly outside the panel.
 */
function stamps(ctx, cw, ch, view) {
  const [z, dpr] = [view.zoom, view.dpr || 1];
  const rest = [];
  // the stamped shapes: their pixels (x, y pairs) and stamps
  const [at, used] = [[], []];
  let st = null;
  // a shape at image (c, r), `radius` canvas pixels from its centre to its stroke (null: not round), stamped
  // when it can be (of the first stamp's colour), else stroked (`s`, or point `i` of batch `s`); none out of view
  const take = (c, r, radius, stroke, colour, stamp, s, i) => {
    const [x, y] = [(c + 0.5) * z + view.ox, (r + 0.5) * z + view.oy];
    const reach = radius + stroke;
    if (radius !== null && (x < -reach || y < -reach || x > cw + reach || y > ch + reach)) return;
    if (!stamp || (st && st.colour !== colour)) {
      rest.push(i < 0 ? s : pointShape(s, i));
      return;
    }
    if (!st || st.radius !== radius || st.width !== stroke) st = stampOf(radius, stroke, colour);
    at.push(Math.floor(x), Math.floor(y));
    used.push(st);
  };
  for (const s of view.shapes) {
    if (s.kind === "points") {
      // an ellipse at its least size (a circle of 2 canvas pixels) or a dot: stamped
      const [p, m] = [s.p, s.magnify * z];
      for (let i = 0; i < p.length; i += 6) {
        const radius = s.ellipse ? Math.max(p[i + 3] * m, p[i + 4] * m, LEAST_AXIS) : DOT_SIZE * dpr;
        take(p[i], p[i + 1], radius, LINE_WIDTH * dpr, s.colour, radius <= LEAST_AXIS || !s.ellipse, s, i);
      }
      continue;
    }
    const radius = s.kind === "dot" ? (s.size || DOT_SIZE) * dpr : s.kind === "ellipse" ? Math.max(s.a * z, s.b * z, LEAST_AXIS) : null;
    const stamp = radius !== null && !s.fill && !(radius > LEAST_AXIS && s.kind === "ellipse");
    take(s.c, s.r, radius, (s.width || LINE_WIDTH) * dpr, s.colour || "#ff8c00", stamp, s, -1);
  }
  if (!used.length) return rest;
  const alpha = new Uint8ClampedArray(cw * ch);
  used.forEach((t, m) => {
    for (let n = 0; n < t.alpha.length; n++) {
      const i = at[2 * m] + t.dx[n];
      const j = at[2 * m + 1] + t.dy[n];
      if (i < 0 || j < 0 || i >= cw || j >= ch) continue;
      const k = j * cw + i;
      // source over: sa + da (1 − sa)
      alpha[k] = t.alpha[n] + (alpha[k] * (255 - t.alpha[n])) / 255;
    }
  });
  // (the panel canvas was just cleared: its pixels are transparent; one colour, so the alphas alone combine)
  const px = new ImageData(cw, ch);
  const [d, [r, g, b]] = [px.data, used[0].rgb];
  for (let k = 0; k < alpha.length; k++) {
    if (!alpha[k]) continue;
    [d[4 * k], d[4 * k + 1], d[4 * k + 2], d[4 * k + 3]] = [r, g, b, alpha[k]];
  }
  ctx.putImageData(px, 0, 0);
  return rest;
}

/** A circle of `radius` canvas pixels stroked `width` wide in `colour`, drawn as drawShapes draws it: its pixels' alpha and its colour. */
function stampOf(radius, width, colour) {
  const key = `${radius} ${width} ${colour}`;
    let st = STAMPS.get(key);
  if (!st) {
    const half = Math.ceil(radius + width / 2) + 1;
    const size = 2 * half + 1;
    const ctx = new OffscreenCanvas(size, size).getContext("2d", { willReadFrequently: true });
    ctx.strokeStyle = colour;
    ctx.lineWidth = width;
    ctx.beginPath();
    ctx.arc(half + 0.5, half + 0.5, radius, 0, 2 * Math.PI);
    ctx.stroke();
    const d = ctx.getImageData(0, 0, size, size).data;
    // its pixels with some colour: where (from the centre's pixel), and their alpha
    const [dx, dy, alpha] = [[], [], []];
    let best = 0;
    for (let i = 0; i < size * size; i++) {
      if (d[4 * i + 3] === 0) continue;
      dx.push((i % size) - half);
      dy.push(Math.floor(i / size) - half);
      alpha.push(d[4 * i + 3]);
      if (d[4 * i + 3] > d[4 * best + 3]) best = i;
    }
    st = { radius, width, colour, dx: Int16Array.from(dx), dy: Int16Array.from(dy), alpha: Uint8Array.from(alpha), rgb: [d[4 * best], d[4 * best + 1], d[4 * best + 2]] };
    STAMPS.set(key, st);
  }
  return st;
}

/**
 * The shapes in image coordinates; stroked shapes of one colour and
 * width one after another go into one path, stroked once.
 */
export function drawShapes(ctx, shapes, view) {
  shapes = shapes.flatMap((s) => (s.kind === "points" ? Array.from({ length: s.p.length / 6 }, (_, k) => pointShape(s, 6 * k)) : [s]));
  const px = 1 / view.zoom;
  // the style of the path being built (stroked when the style changes)
  let open = null;
  // shapes in it (a path grows slower with each shape added: Chromium's path of 50 000 ellipses took seconds)
  let count = 0;
  const flush = () => {
    if (open !== null) ctx.stroke();
    open = null;
    count = 0;
  };
  for (const s of shapes) {
    const lineWidth = (s.width || LINE_WIDTH) * px * (view.dpr || 1);
    const style = s.fill || s.kind === "text" ? null : `${s.colour || "#ff8c00"} ${lineWidth}`;
    if (style === null || style !== open || count >= PATH_SHAPES) {
      flush();
      ctx.strokeStyle = s.colour || "#ff8c00";
      ctx.fillStyle = s.colour || "#ff8c00";
      ctx.lineWidth = lineWidth;
      ctx.beginPath();
    }
    if (s.kind === "rect") {
      ctx.rect(s.c0, s.r0, s.w, s.h);
    } else if (s.kind === "ellipse") {
      // centre at pixel centre (c + 0.5); semi-axes scaled to be visible
      const [a, b, t] = [Math.max(s.a, LEAST_AXIS * px), Math.max(s.b, LEAST_AXIS * px), s.angle || 0];
      // (a path of its own within the shared one: from the point the ellipse starts at)
      ctx.moveTo(s.c + 0.5 + a * Math.cos(t), s.r + 0.5 + a * Math.sin(t));
      ctx.ellipse(s.c + 0.5, s.r + 0.5, a, b, t, 0, 2 * Math.PI);
    } else if (s.kind === "dot") {
      const radius = (s.size || DOT_SIZE) * px * (view.dpr || 1);
      ctx.moveTo(s.c + 0.5 + radius, s.r + 0.5);
      ctx.arc(s.c + 0.5, s.r + 0.5, radius, 0, 2 * Math.PI);
    } else if (s.kind === "poly") {
      s.points.forEach(([c, r], i) => (i ? ctx.lineTo(c + 0.5, r + 0.5) : ctx.moveTo(c + 0.5, r + 0.5)));
      if (s.closed) ctx.closePath();
    } else if (s.kind === "line" || s.kind === "arrow") {
      const [x0, y0, x1, y1] = [s.from[0] + 0.5, s.from[1] + 0.5, s.to[0] + 0.5, s.to[1] + 0.5];
      ctx.moveTo(x0, y0);
      ctx.lineTo(x1, y1);
      const len = Math.hypot(x1 - x0, y1 - y0);
      if (s.kind === "arrow" && len > 0) {
        // a head of 8 screen pixels (at most a third of the arrow)
        const head = Math.min(8 * px * (view.dpr || 1), len / 3);
        const a = Math.atan2(y1 - y0, x1 - x0);
        for (const t of [a + 2.7, a - 2.7]) {
          ctx.moveTo(x1, y1);
          ctx.lineTo(x1 + head * Math.cos(t), y1 + head * Math.sin(t));
        }
      }
    } else if (s.kind === "cross") {
      const h = (s.size || 6) * px * (view.dpr || 1);
      ctx.moveTo(s.c + 0.5 - h, s.r + 0.5);
      ctx.lineTo(s.c + 0.5 + h, s.r + 0.5);
      ctx.moveTo(s.c + 0.5, s.r + 0.5 - h);
      ctx.lineTo(s.c + 0.5, s.r + 0.5 + h);
    } else if (s.kind === "text") {
      // a label of ~13 screen pixels at image position (c, r)
      ctx.font = `${13 * px * (view.dpr || 1)}px sans-serif`;
      ctx.textAlign = s.align || "left";
      ctx.textBaseline = "middle";
      ctx.lineWidth = 3 * px * (view.dpr || 1);
      ctx.strokeStyle = s.halo || "#fff";
      ctx.strokeText(s.text, s.c, s.r);
      ctx.fillText(s.text, s.c, s.r);
      continue;
    }
    if (s.fill) ctx.fill();
    else {
      open = style;
      count++;
    }
  }
  flush();
}
