// The drawing's curves: plain data beside its points and segments, as the package's Plc
// has them, so that they copy for undo, go into the link and reach the mesher untranslated.
//
//   curves [{ type: 'arc', from, to, center: [x, y], marker? }
//           | { type: 'bezier', from, to, controls: [x1, y1, x2, y2], marker? }]
//
// `from` and `to` are point indices. An item of the editor is a whole curve { kind: 'curve', index }
// or one of its handles { kind: 'handle', index, which: 'center' | 'c1' | 'c2' }.
//
// Keeping arcs valid (their ends equidistant from the center, which the core checks to 1e-9): a
// center handle moves only along the perpendicular bisector of its arc's ends (the pointer
// projected onto it), and when an arc's end point moves, its center goes to the point of the new
// bisector nearest to where it was when the move began (followPoints). A Bézier's control moves
// with the end it belongs to (c1 with `from`, c2 with `to`), keeping the curve's tangents there.
// A curve whose two ends move by the same offset (a dragged curve, a circle's other half) moves
// whole, its center or controls with it.
import { includeShape, onBisector, pointAt, shapeOf } from './curve-geometry.js';

export const CurveItem = Object.freeze({ CURVE: 'curve', HANDLE: 'handle' });

const point = (d, i) => [d.points[2 * i], d.points[2 * i + 1]];

/** The drawing's curves (older drawings have none). */
export const curvesOf = (d) => d.curves ?? [];

/** A copy of one curve, its arrays copied too. */
export function copyCurve(c) {
  const out = { type: c.type, from: c.from, to: c.to };
  if (c.type === 'arc') out.center = [c.center[0], c.center[1]];
  else out.controls = Array.from(c.controls);
  if (c.marker) out.marker = c.marker;
  return out;
}

export const cloneCurves = (d) => curvesOf(d).map(copyCurve);

/** The curves as the mesher takes them (plc.curves); none: no key (the Plc of a drawing without curves is unchanged). */
export function curvesForPlc(d) {
  const curves = curvesOf(d);
  return curves.length ? { curves: curves.map(copyCurve) } : {};
}

/** The curves of a parsed file (typed arrays in centers and controls), as the drawing keeps them. */
export const curvesFromPlc = (plc) => (plc.curves ?? []).map(copyCurve);

/** The shape (curve-geometry.js) of curve k of the drawing. */
export function curveShape(d, k) {
  const c = d.curves[k];
  return shapeOf(c, point(d, c.from), point(d, c.to));
}

/** Removes the curves that end at point i and renumbers the points after it (the point itself goes). */
export function dropPointFromCurves(d, i) {
  if (!d.curves?.length) return;
  d.curves = d.curves.filter((c) => c.from !== i && c.to !== i).map((c) => ({
    ...copyCurve(c), from: c.from > i ? c.from - 1 : c.from, to: c.to > i ? c.to - 1 : c.to,
  }));
}

/** The handles of curve k: [{ which, x, y }] (an arc's center, a Bézier's two controls). */
export function handlesOf(d, k) {
  const c = d.curves[k];
  if (c.type === 'arc') return [{ which: 'center', x: c.center[0], y: c.center[1] }];
  return [{ which: 'c1', x: c.controls[0], y: c.controls[1] }, { which: 'c2', x: c.controls[2], y: c.controls[3] }];
}

/** Where a curve item is: a handle's place, a curve's middle (the point a drag grabs it by). */
export function curveItemPosition(d, item) {
  if (item.kind === CurveItem.HANDLE) {
    const h = handlesOf(d, item.index).find((x) => x.which === item.which);
    return h ? { x: h.x, y: h.y } : null;
  }
  if (item.kind === CurveItem.CURVE) {
    const [x, y] = pointAt(curveShape(d, item.index), 0.5);
    return { x, y };
  }
  return null;
}

/**
 * Moves a curve item to (x, y): a center handle to the point of its arc's bisector nearest to
 * (x, y), a control to (x, y), a curve by the offset of its middle (its end points move; its center
 * or controls follow in followPoints).
 */
export function moveCurveItem(d, item, x, y) {
  const c = d.curves[item.index];
  if (!c) return;
  if (item.kind === CurveItem.HANDLE && item.which === 'center') {
    c.center = onBisector(point(d, c.from), point(d, c.to), [x, y]);
  } else if (item.kind === CurveItem.HANDLE) {
    const at = item.which === 'c1' ? 0 : 2;
    c.controls[at] = x;
    c.controls[at + 1] = y;
  } else if (item.kind === CurveItem.CURVE) {
    const from = curveItemPosition(d, item);
    const dx = x - from.x, dy = y - from.y;
    for (const i of new Set([c.from, c.to])) {
      d.points[2 * i] += dx;
      d.points[2 * i + 1] += dy;
    }
  }
}

/** Removes curve k (a handle's item removes its curve). */
export function removeCurve(d, k) {
  d.curves = cloneCurves(d);
  d.curves.splice(k, 1);
}

/**
 * After points moved (a drag from `before`, a copy of the drawing when it began): every curve
 * whose ends moved gets its center or controls from `before` as the rules at the top say, so the
 * result depends only on where the points are, not on the path the pointer took.
 */
export function followPoints(d, before) {
  curvesOf(d).forEach((c, k) => {
    const old = before.curves?.[k];
    if (!old || old.from !== c.from || old.to !== c.to || old.type !== c.type) return;
    const delta = (i) => [d.points[2 * i] - before.points[2 * i], d.points[2 * i + 1] - before.points[2 * i + 1]];
    const df = delta(c.from), dt = delta(c.to);
    const moved = (v) => v[0] !== 0 || v[1] !== 0;
    if (!moved(df) && !moved(dt)) return;
    const whole = df[0] === dt[0] && df[1] === dt[1];
    if (c.type === 'arc') {
      c.center = whole ? [old.center[0] + df[0], old.center[1] + df[1]] : onBisector(point(d, c.from), point(d, c.to), old.center);
    } else {
      c.controls = [old.controls[0] + df[0], old.controls[1] + df[1], old.controls[2] + dt[0], old.controls[3] + dt[1]];
    }
  });
}

/**
 * Arcs that share arc k's center and ends (either way round: a circle's two halves): a drag of
 * k's center moves theirs too, so the circle stays one circle.
 */
export function twinArcs(d, k) {
  const c = d.curves[k];
  if (c?.type !== 'arc') return [];
  const ends = (x) => [x.from, x.to].sort((p, q) => p - q).join();
  return d.curves.flatMap((x, j) => (j !== k && x.type === 'arc' && ends(x) === ends(c) &&
    x.center[0] === c.center[0] && x.center[1] === c.center[1] ? [j] : []));
}

/** Grows a bounding box to hold every curve (a circle's two points alone would cut it off). */
export function includeCurves(box, d) {
  curvesOf(d).forEach((_, k) => includeShape(box, curveShape(d, k)));
}

/** The curves' markers (0: none), one per curve. */
export const curveMarkers = (d) => curvesOf(d).map((c) => c.marker ?? 0);

// ---------------------------------------------------------------- the link (url-state.js)
// In the link's JSON, "c": one array per curve: ["a", from, to, cx, cy, marker] or
// ["b", from, to, x1, y1, x2, y2, marker] (the marker only when there is one).

export function encodeCurves(d) {
  const curves = curvesOf(d);
  if (!curves.length) return {};
  return {
    c: curves.map((c) => [c.type === 'arc' ? 'a' : 'b', c.from, c.to,
      ...(c.type === 'arc' ? c.center : c.controls), ...(c.marker ? [c.marker] : [])]),
  };
}

/** The curves of a link's "c" (absent: none); throws on a damaged one, naming the curve. */
export function decodeCurves(list, pointCount) {
  if (list === undefined) return [];
  if (!Array.isArray(list)) throw new Error('link: curves must be an array');
  return list.map((entry, k) => {
    const [code, from, to, ...rest] = Array.isArray(entry) ? entry : [];
    const numbers = rest.length > 0 && rest.every((v) => typeof v === 'number' && Number.isFinite(v));
    const size = code === 'a' ? 2 : code === 'b' ? 4 : -1;
    const index = (i) => Number.isInteger(i) && i >= 0 && i < pointCount;
    if (size < 0 || !numbers || !index(from) || !index(to) || (rest.length !== size && rest.length !== size + 1)) {
      throw new Error(`link: curve ${k} is damaged`);
    }
    const c = code === 'a' ? { type: 'arc', from, to, center: rest.slice(0, 2) } : { type: 'bezier', from, to, controls: rest.slice(0, 4) };
    if (rest.length > size && Number.isInteger(rest[size]) && rest[size] !== 0) c.marker = rest[size];
    return c;
  });
}

// ---------------------------------------------------------------- the drawing's .json

/**
 * The drawing (points, segments with their markers, curves, holes, regions) in the package's JSON
 * input format, which parseJson and the file panel read back: unlike .poly it keeps the curves.
 */
export function drawingJsonText(plc) {
  const out = {
    points: Array.from(plc.points),
    segments: Array.from(plc.segments),
    ...(plc.segmentMarkers ? { segmentMarkers: Array.from(plc.segmentMarkers) } : {}),
    ...(plc.curves?.length ? { curves: plc.curves.map(copyCurve) } : {}),
    holes: Array.from(plc.holes),
    regions: plc.regions.map((r) => ({ ...r })),
  };
  return `${JSON.stringify(out, null, 1)}\n`;
}
