// A drawing's curves as plain segments, for formats that hold no curves (Triangle's .poly): each
// curve is cut into pieces whose chords lie within the curve tolerance of it (the tolerance the
// mesher follows curves to), so that the .poly bounds the same domain to that tolerance. A hole or
// region seed that sat between a curve and its chords (inside the curved boundary, outside the
// polygon of chords) is moved across the chord, so that it still marks the area it marked.
// Pure numbers, no DOM: the tests import it in Node too.
import { pointAt, segmentDistance2, shapeOf, subCubic } from '../model/curve-geometry.js';

// The core's automatic tolerance: this fraction of the diagonal of the input points' bounding box.
const AUTO_TOLERANCE_FRACTION = 1e-3;
// A Bézier is cut in halves at most this deep (2^12 pieces): past it the curve is a line to the
// precision of doubles anyway.
const MAX_DEPTH = 12;

/** The tolerance in force: options.curveTolerance when > 0, else the core's automatic one. */
export function curveToleranceOf(plc, curveTolerance) {
  if (curveTolerance > 0) return curveTolerance;
  let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
  for (let i = 0; i < plc.points.length; i += 2) {
    minX = Math.min(minX, plc.points[i]); maxX = Math.max(maxX, plc.points[i]);
    minY = Math.min(minY, plc.points[i + 1]); maxY = Math.max(maxY, plc.points[i + 1]);
  }
  const diagonal = Math.hypot(maxX - minX, maxY - minY);
  return diagonal > 0 ? AUTO_TOLERANCE_FRACTION * diagonal : 1;
}

/** The parameters t in (0, 1) where an arc is cut: equal angles, each piece's sagitta <= tolerance. */
function arcCuts(shape, tolerance) {
  // A piece of angle θ has sagitta r (1 - cos(θ / 2)).
  const ratio = Math.min(1, tolerance / shape.r);
  const step = ratio >= 1 ? Math.PI : 2 * Math.acos(1 - ratio);
  const pieces = Math.max(2, Math.ceil(shape.sweep / Math.min(step, Math.PI / 2)));
  return Array.from({ length: pieces - 1 }, (_, i) => (i + 1) / pieces);
}

/** The largest distance of the cubic c's control points from its chord: the curve lies within it. */
function flatness(c) {
  const d1 = segmentDistance2(c[2], c[3], c[0], c[1], c[6], c[7]);
  const d2 = segmentDistance2(c[4], c[5], c[0], c[1], c[6], c[7]);
  return Math.sqrt(Math.max(d1, d2));
}

/** The parameters t in (0, 1) where a Bézier is cut: halves until each piece is within tolerance. */
function bezierCuts(shape, tolerance) {
  const cuts = [];
  const cut = (t0, t1, depth) => {
    if (depth >= MAX_DEPTH || flatness(subCubic(shape.c, t0, t1)) <= tolerance) return;
    const mid = (t0 + t1) / 2;
    cut(t0, mid, depth + 1);
    cuts.push(mid);
    cut(mid, t1, depth + 1);
  };
  cut(0, 1, 0);
  return cuts;
}

/**
 * If (x, y) lies between a piece's chord and the curve (the side the curve bulges to, within the
 * piece's span), the point mirrored across the chord; else null.
 */
function acrossChord(x, y, a, b, middle) {
  const dx = b[0] - a[0], dy = b[1] - a[1];
  const length2 = dx * dx + dy * dy;
  if (length2 === 0) return null;
  const t = ((x - a[0]) * dx + (y - a[1]) * dy) / length2;
  if (t <= 0 || t >= 1) return null;
  const side = (px, py) => (dx * (py - a[1]) - dy * (px - a[0])) / Math.sqrt(length2);
  const bulge = side(middle[0], middle[1]);
  const s = side(x, y);
  // On the bulge's side and no farther from the chord than the curve is: in the sliver.
  if (bulge === 0 || Math.sign(s) !== Math.sign(bulge) || Math.abs(s) > Math.abs(bulge)) return null;
  const nx = -dy / Math.sqrt(length2), ny = dx / Math.sqrt(length2);
  // Mirrored, and at least the curve's own distance from the chord, so it is clear of the chord.
  const across = -Math.sign(s) * Math.max(Math.abs(s), Math.abs(bulge) / 2);
  return [x - s * nx + across * nx, y - s * ny + across * ny];
}

/**
 * The Plc without curves: every curve replaced by segments along it (new points after the given
 * ones, each piece keeping the curve's marker), seeds in a sliver moved across its chord. A Plc
 * without curves is returned as it is. `curveTolerance`: the drawing's option (<= 0: automatic).
 */
export function flattenCurves(plc, curveTolerance = 0) {
  const curves = plc.curves ?? [];
  if (curves.length === 0) return plc;
  const tolerance = curveToleranceOf(plc, curveTolerance);
  const points = Array.from(plc.points);
  const segments = Array.from(plc.segments);
  const hadMarkers = Boolean(plc.segmentMarkers) || curves.some((c) => c.marker);
  const markers = hadMarkers ? Array.from(plc.segmentMarkers ?? new Array(segments.length / 2).fill(0)) : null;
  const pieces = [];  // [a, b, middle] of every piece, for the seeds
  for (const curve of curves) {
    const a = [plc.points[2 * curve.from], plc.points[2 * curve.from + 1]];
    const b = [plc.points[2 * curve.to], plc.points[2 * curve.to + 1]];
    const shape = shapeOf(curve, a, b);
    const cuts = shape.type === 'arc' ? arcCuts(shape, tolerance) : bezierCuts(shape, tolerance);
    const ts = [0, ...cuts, 1];
    let previous = curve.from;
    for (let i = 1; i < ts.length; i++) {
      let next = curve.to;
      if (i < ts.length - 1) {
        next = points.length / 2;
        points.push(...pointAt(shape, ts[i]));
      }
      segments.push(previous, next);
      markers?.push(curve.marker ?? 0);
      pieces.push([[points[2 * previous], points[2 * previous + 1]], [points[2 * next], points[2 * next + 1]],
        pointAt(shape, (ts[i - 1] + ts[i]) / 2)]);
      previous = next;
    }
  }
  const moveSeed = (x, y) => {
    for (const [a, b, middle] of pieces) {
      const moved = acrossChord(x, y, a, b, middle);
      if (moved) return moved;
    }
    return [x, y];
  };
  const holes = [];
  for (let i = 0; i < plc.holes.length; i += 2) holes.push(...moveSeed(plc.holes[i], plc.holes[i + 1]));
  const regions = plc.regions.map((r) => {
    const [x, y] = moveSeed(r.x, r.y);
    return { ...r, x, y };
  });
  const { curves: _dropped, ...rest } = plc;
  return {
    ...rest,
    points: Float64Array.from(points),
    segments: Uint32Array.from(segments),
    ...(markers ? { segmentMarkers: Int32Array.from(markers) } : {}),
    holes: Float64Array.from(holes),
    regions,
  };
}
