// Step mode and curves: which refinement events split a piece of a curve, their text
// and their overlay. The trace records a split as any subsegment split (SEGMENT_SPLIT, or REJECTED
// with the subsegment split instead), so the page reads the curve from the final mesh: the new
// vertex stays on its piece's subsegments to the end, and their segmentIds entry is the number of
// input segments plus the curve's index (README's output table). No change to the core's trace.
import { EventKind } from '../../wasm/index.js';
import { parameterOf, shapeOf, tracePath } from '../model/curve-geometry.js';
import { pointsAtStep, rejectedIsCircumcenter } from '../geometry/event-geometry.js';
import { EVENT_KIND_LABELS as L } from '../labels.js';

const fmt = (v) => (Math.abs(v) >= 1e4 || (Math.abs(v) < 1e-3 && v !== 0) ? v.toExponential(3) : Number(v.toFixed(4)).toString());

const idsOfVertices = new WeakMap();  // mesh.segmentIds -> Int32Array: per vertex, a subsegment's id there (-2: none)

/** Per vertex of the final mesh, the segmentIds entry of a subsegment ending at it (-2: none). */
function vertexSegmentIds(context) {
  let ids = idsOfVertices.get(context.segmentIds);
  if (ids === undefined) {
    ids = new Int32Array(context.points.length / 2).fill(-2);
    for (let s = 0; s < context.segmentIds.length; s++) {
      ids[context.segments[2 * s]] = context.segmentIds[s];
      ids[context.segments[2 * s + 1]] = context.segmentIds[s];
    }
    idsOfVertices.set(context.segmentIds, ids);
  }
  return ids;
}

/**
 * The index of the curve whose piece event e split (a SEGMENT_SPLIT, or a REJECTED point's split
 * instead), or null. `context`: the steps panel's (curves, segmentCount, and the final mesh's
 * points, segments and segmentIds).
 */
export function curveOfEvent(events, e, context) {
  if (!context?.curves?.length || !context.segmentIds) return null;
  const kind = events.kind[e];
  if (kind !== EventKind.SEGMENT_SPLIT && kind !== EventKind.REJECTED) return null;
  const k = vertexSegmentIds(context)[events.vertex[e]] - context.segmentCount;
  return k >= 0 && k < context.curves.length ? k : null;
}

/**
 * The event's line when it split a curve's piece ("Curve k split at (x, y) ..."), else null.
 * `where` is the new vertex's place as stepper.js writes it, `triangle` its words for the triangle.
 */
export function describeCurveSplit(events, e, context, where, triangle) {
  const k = curveOfEvent(events, e, context);
  if (k === null) return null;
  const piece = `its piece (${events.a[e]}, ${events.b[e]})`;
  const vertex = events.vertex[e];
  const on = 'on the curve, not on the chord, so every vertex of the boundary lies on the curve';
  if (events.kind[e] === EventKind.SEGMENT_SPLIT) {
    const by = events.by[e];
    return `Curve ${k} split at ${where} (${on}): ${piece}${by >= 0 ? `, encroached by vertex ${by}` : ''}; vertex ${vertex}.`;
  }
  const points = pointsAtStep(events, e, context.points);
  const what = rejectedIsCircumcenter(events, e, points) ? L.CIRCUMCENTER : L.OFF_CENTER;
  return `The ${what} (${fmt(events.circumcenter[2 * e])}, ${fmt(events.circumcenter[2 * e + 1])}) of ${triangle} ` +
    `encroached ${piece.slice(4)} of curve ${k}: rejected; curve ${k} split at ${where} instead (${on}): vertex ${vertex}.`;
}

/**
 * The overlay of a curve split: the stretch of curve the piece followed (thick), its chord
 * (dashed) and the chord's diametral disk (the core tests curve pieces against the disk whatever
 * the encroachment option). `p`: the points before the event. Returns false when e split no curve.
 */
export function drawCurveSplit(ctx, p, events, e, context, color, world, screen, px) {
  const k = curveOfEvent(events, e, context);
  if (k === null) return false;
  const c = context.curves[k];
  const shape = shapeOf(c, [p[2 * c.from], p[2 * c.from + 1]], [p[2 * c.to], p[2 * c.to + 1]]);
  const a = [p[2 * events.a[e]], p[2 * events.a[e] + 1]];
  const b = [p[2 * events.b[e]], p[2 * events.b[e] + 1]];
  const ta = parameterOf(shape, ...a), tb = parameterOf(shape, ...b);
  world();
  ctx.strokeStyle = color;
  ctx.beginPath();
  tracePath(ctx, shape, Math.min(ta, tb), Math.max(ta, tb));
  ctx.lineWidth = 5 * px;
  ctx.stroke();
  ctx.lineWidth = 1.5 * px;
  ctx.setLineDash([6 * px, 4 * px]);
  ctx.beginPath();
  ctx.moveTo(...a);
  ctx.lineTo(...b);
  const r = Math.hypot(b[0] - a[0], b[1] - a[1]) / 2;
  ctx.moveTo((a[0] + b[0]) / 2 + r, (a[1] + b[1]) / 2);
  ctx.arc((a[0] + b[0]) / 2, (a[1] + b[1]) / 2, r, 0, 2 * Math.PI);
  ctx.stroke();
  ctx.setLineDash([]);
  screen();
  return true;
}
