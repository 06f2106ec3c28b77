// What an event's numbers say about the chapter's geometry, read back from the mesh's points: the
// trace records where a vertex went, not which rule put it there, so the page tells a
// concentric-shell split from a midpoint split, and a rejected circumcenter from a rejected
// off-center, by measuring.

import { EventKind } from '../../wasm/index.js';

const RELATIVE = 1e-9;

/** The circumcircle { x, y, r } of the triangle of vertices i, j, k of points, or null if flat. */
export function circumcircle(p, i, j, k) {
  const ax = p[2 * i]; const ay = p[2 * i + 1];
  const bx = p[2 * j] - ax; const by = p[2 * j + 1] - ay;
  const cx = p[2 * k] - ax; const cy = p[2 * k + 1] - ay;
  const d = 2 * (bx * cy - by * cx);
  if (d === 0) return null;
  const b2 = bx * bx + by * by;
  const c2 = cx * cx + cy * cy;
  const ux = (cy * b2 - by * c2) / d;
  const uy = (bx * c2 - cx * b2) / d;
  return { x: ax + ux, y: ay + uy, r: Math.hypot(ux, uy) };
}

/**
 * A subsegment split (event kind 0) off its midpoint: the concentric shell it lies on (§6.6), as
 * { center: vertex id, radius }, the shell around the end whose distance to the split is a power
 * of two. Null for a midpoint split.
 */
export function splitShell(events, e, points) {
  const a = events.a[e];
  const b = events.b[e];
  const x = events.xy[2 * e];
  const y = events.xy[2 * e + 1];
  const length = Math.hypot(points[2 * b] - points[2 * a], points[2 * b + 1] - points[2 * a + 1]);
  const mx = (points[2 * a] + points[2 * b]) / 2;
  const my = (points[2 * a + 1] + points[2 * b + 1]) / 2;
  if (Math.hypot(x - mx, y - my) <= RELATIVE * length) return null;
  let best = null;
  for (const v of [a, b]) {
    const radius = Math.hypot(x - points[2 * v], y - points[2 * v + 1]);
    const exponent = Math.log2(radius);
    const off = Math.abs(exponent - Math.round(exponent));
    if (best === null || off < best.off) best = { center: v, radius, off };
  }
  return { center: best.center, radius: best.radius };
}

/** Whether the point a triangle event rejected (kind 3) is that triangle's circumcenter. */
export function rejectedIsCircumcenter(events, e, points) {
  const c = circumcircle(points, events.triangle[3 * e], events.triangle[3 * e + 1], events.triangle[3 * e + 2]);
  if (c === null) return true;
  const px = events.circumcenter[2 * e];
  const py = events.circumcenter[2 * e + 1];
  return Math.hypot(px - c.x, py - c.y) <= RELATIVE * Math.max(c.r, 1e-300) + 1e-12 * Math.hypot(c.x, c.y);
}

// A RELOCATED event moves a vertex (from `circumcenter` to `xy`) and adds none.
const { RELOCATED } = EventKind;
const lastMove = new WeakMap();  // events -> index of the last RELOCATED event (-1: none)
let rewound = { events: null, k: -1, final: null, points: null };

/**
 * The points as they were after the first k events: the final mesh's points with every later move
 * (RELOCATED, from `circumcenter` to `xy`) undone. Vertex numbers are the final mesh's; a vertex
 * inserted later keeps its final place (nothing refers to it before its insertion). Without moves
 * after step k, `final` itself.
 */
export function pointsAtStep(events, k, final) {
  let last = lastMove.get(events);
  if (last === undefined) {
    last = -1;
    for (let e = events.count - 1; e >= 0 && last < 0; e--) if (events.kind[e] === RELOCATED) last = e;
    lastMove.set(events, last);
  }
  if (last < k) return final;
  if (rewound.events === events && rewound.k === k && rewound.final === final) return rewound.points;
  const points = Float64Array.from(final);
  for (let e = last; e >= k; e--) undoMove(events, e, points);
  rewound = { events, k, final, points };
  return points;
}

/** Puts event e's vertex back where it was before e, if e is a move (RELOCATED); points is changed. */
export function undoMove(events, e, points) {
  if (events.kind[e] !== RELOCATED) return;
  const v = events.vertex[e];
  points[2 * v] = events.circumcenter[2 * e];
  points[2 * v + 1] = events.circumcenter[2 * e + 1];
}

const insertionCounts = new WeakMap();  // events -> Uint32Array: insertions among the first k, per k

/** How many of the first k events inserted a vertex (all but RELOCATED); counted once per trace. */
export function insertionsBefore(events, k) {
  let counts = insertionCounts.get(events);
  if (counts === undefined) {
    counts = new Uint32Array(events.count + 1);
    for (let e = 0; e < events.count; e++) counts[e + 1] = counts[e] + (events.kind[e] !== RELOCATED);
    insertionCounts.set(events, counts);
  }
  return counts[Math.max(0, Math.min(k, events.count))];
}

/**
 * Whether a SEGMENT_SPLIT put its vertex off the chord of the subsegment it split: a curve's
 * piece, split on its curve (a midpoint or shell split stays on the chord, to rounding). For the
 * Mesh panel's event counts, which have the trace and the points alone.
 */
export function splitsCurve(events, e, points) {
  if (events.kind[e] !== EventKind.SEGMENT_SPLIT) return false;
  const a = events.a[e], b = events.b[e];
  const ax = points[2 * a], ay = points[2 * a + 1];
  const dx = points[2 * b] - ax, dy = points[2 * b + 1] - ay;
  const length = Math.hypot(dx, dy);
  const off = Math.abs(dx * (events.xy[2 * e + 1] - ay) - dy * (events.xy[2 * e] - ax)) / (length || 1);
  return off > 1e-9 * length;
}
