// The geometry of the drawing's curves, as the core reads them (core/src/cdt/curves.h):
// an arc runs counter-clockwise from its `from` point to its `to` point around `center`, its radius
// the `from` point's distance; a Bézier is the cubic from `from` through controls [x1, y1, x2, y2]
// to `to`. Both are functions of a parameter t in [0, 1]. Pure numbers, no DOM: the page's tests
// import it in Node too.

const TWO_PI = 2 * Math.PI;

/**
 * A curve's shape from its end points: { type: 'arc', cx, cy, r, start, sweep } (radians, sweep in
 * (0, 2π]) or { type: 'bezier', c: [x0, y0, x1, y1, x2, y2, x3, y3] }.
 */
export function shapeOf(curve, a, b) {
  if (curve.type === 'bezier') return { type: 'bezier', c: [a[0], a[1], ...curve.controls, b[0], b[1]] };
  const [cx, cy] = curve.center;
  const start = Math.atan2(a[1] - cy, a[0] - cx);
  let sweep = Math.atan2(b[1] - cy, b[0] - cx) - start;
  // As the core: equal angles are a whole turn, never an empty arc.
  if (sweep <= 0) sweep += TWO_PI;
  return { type: 'arc', cx, cy, r: Math.hypot(a[0] - cx, a[1] - cy), start, sweep };
}

/** The point [x, y] of the shape at parameter t. */
export function pointAt(shape, t) {
  if (shape.type === 'arc') {
    const angle = shape.start + t * shape.sweep;
    return [shape.cx + shape.r * Math.cos(angle), shape.cy + shape.r * Math.sin(angle)];
  }
  const c = shape.c, s = 1 - t;
  const w0 = s * s * s, w1 = 3 * s * s * t, w2 = 3 * s * t * t, w3 = t * t * t;
  return [w0 * c[0] + w1 * c[2] + w2 * c[4] + w3 * c[6], w0 * c[1] + w1 * c[3] + w2 * c[5] + w3 * c[7]];
}

/** `n` + 1 points along the shape between parameters t0 and t1, flat [x0, y0, ...]. */
export function samples(shape, n = 64, t0 = 0, t1 = 1) {
  const out = [];
  for (let i = 0; i <= n; i++) out.push(...pointAt(shape, t0 + (t1 - t0) * (i / n)));
  return out;
}

/** Squared distance from (px, py) to the segment (ax, ay)-(bx, by). */
export function segmentDistance2(px, py, ax, ay, bx, by) {
  const dx = bx - ax, dy = by - ay;
  const length2 = dx * dx + dy * dy;
  const t = length2 > 0 ? Math.max(0, Math.min(1, ((px - ax) * dx + (py - ay) * dy) / length2)) : 0;
  return (ax + t * dx - px) ** 2 + (ay + t * dy - py) ** 2;
}

/**
 * The distance from (x, y) to the shape, measured to a polyline of 96 pieces: close enough for
 * picking a curve with the pointer (a piece's sagitta is far under a pixel at any usual zoom).
 */
export function distanceTo(shape, x, y) {
  const xy = samples(shape, 96);
  let best = Infinity;
  for (let i = 0; i + 3 < xy.length; i += 2) best = Math.min(best, segmentDistance2(x, y, xy[i], xy[i + 1], xy[i + 2], xy[i + 3]));
  return Math.sqrt(best);
}

/** Grows `box` ({ minX, minY, maxX, maxY }) to hold the shape (by samples: the fit needs no more). */
export function includeShape(box, shape) {
  const xy = samples(shape, 64);
  for (let i = 0; i < xy.length; i += 2) {
    box.minX = Math.min(box.minX, xy[i]); box.maxX = Math.max(box.maxX, xy[i]);
    box.minY = Math.min(box.minY, xy[i + 1]); box.maxY = Math.max(box.maxY, xy[i + 1]);
  }
}

/**
 * The point of the perpendicular bisector of a-b nearest to q: where an arc's center may go so
 * that both its ends lie at one distance from it (the core refuses an arc whose ends differ beyond
 * 1e-9 of the radius). When a and b coincide there is no bisector: q itself.
 */
export function onBisector(a, b, q) {
  const dx = b[0] - a[0], dy = b[1] - a[1];
  const length = Math.hypot(dx, dy);
  if (length === 0) return [q[0], q[1]];
  const nx = -dy / length, ny = dx / length;
  const mx = (a[0] + b[0]) / 2, my = (a[1] + b[1]) / 2;
  const s = (q[0] - mx) * nx + (q[1] - my) * ny;
  return [mx + s * nx, my + s * ny];
}

/**
 * The parameter of the shape nearest to (x, y): an arc's by its angle; a Bézier's by 256 samples,
 * then a ternary search around the best (the cubic is smooth, and a split point lies on it).
 */
export function parameterOf(shape, x, y) {
  if (shape.type === 'arc') {
    let turn = Math.atan2(y - shape.cy, x - shape.cx) - shape.start;
    while (turn < 0) turn += TWO_PI;
    while (turn >= TWO_PI) turn -= TWO_PI;
    // Past the arc's end: the nearer end (the angle just before 0 means the start).
    if (turn > shape.sweep) return turn - shape.sweep < TWO_PI - turn ? 1 : 0;
    return turn / shape.sweep;
  }
  const d2 = (t) => { const [px, py] = pointAt(shape, t); return (px - x) ** 2 + (py - y) ** 2; };
  const n = 256;
  let best = 0;
  for (let i = 1; i <= n; i++) if (d2(i / n) < d2(best / n)) best = i;
  let lo = Math.max(0, (best - 1) / n), hi = Math.min(1, (best + 1) / n);
  for (let k = 0; k < 60; k++) {
    const m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (d2(m1) < d2(m2)) hi = m2; else lo = m1;
  }
  return (lo + hi) / 2;
}

/**
 * Adds the shape between parameters t0 and t1 to a path (Path2D or a 2D context) in world
 * coordinates: an arc as an arc, a whole Bézier as a cubic, a stretch of one as its sub-cubic.
 */
export function tracePath(path, shape, t0 = 0, t1 = 1) {
  const [x0, y0] = pointAt(shape, t0);
  path.moveTo(x0, y0);
  if (shape.type === 'arc') {
    const a0 = shape.start + t0 * shape.sweep, a1 = shape.start + t1 * shape.sweep;
    path.arc(shape.cx, shape.cy, shape.r, a0, a1, a1 < a0);
    return;
  }
  const q = subCubic(shape.c, t0, t1);
  path.bezierCurveTo(q[2], q[3], q[4], q[5], q[6], q[7]);
}

/** The control points of the cubic c restricted to [t0, t1] (by its derivative at the ends). */
export function subCubic(c, t0, t1) {
  const shape = { type: 'bezier', c };
  const derivative = (t) => {
    const s = 1 - t;
    const k = [3 * s * s, 6 * s * t, 3 * t * t];
    return [0, 1].map((j) => k[0] * (c[2 + j] - c[j]) + k[1] * (c[4 + j] - c[2 + j]) + k[2] * (c[6 + j] - c[4 + j]));
  };
  const p0 = pointAt(shape, t0), p3 = pointAt(shape, t1);
  const d0 = derivative(t0), d1 = derivative(t1), h = (t1 - t0) / 3;
  return [p0[0], p0[1], p0[0] + h * d0[0], p0[1] + h * d0[1], p3[0] - h * d1[0], p3[1] - h * d1[1], p3[0], p3[1]];
}
