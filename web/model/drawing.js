// The drawing: a planar straight-line graph the user edits, plus the meshing options.
//
// Plain data (flat number arrays, like the package's Plc) so that it copies cheaply for undo,
// serialises into the URL and converts to the mesher's input without translation.
//
//   points   x0, y0, x1, y1, ...        world coordinates, y up
//   segments a0, b0, a1, b1, ...        point indices
//   holes    hx0, hy0, ...              hole seeds
//   regions  [{ x, y, attribute, maxArea }]
//   segmentMarkers m0, m1, ...  a boundary marker per segment (0: none), kept from files, written by
//                                every export; absent from older drawings (all 0)
//   curves   [{ type: 'arc' | 'bezier', from, to, center | controls, marker? }]  (editing/curve-data.js;
//            absent from older drawings: none)
//   options  { minAngle, maxAngle, maxArea, placement, maxSteiner, variant, encroachment }
//            maxAngle/maxArea/maxSteiner: null = none/automatic; variant 'cdt' | 'box'; encroachment 'lens' | 'disk'
import { OPTIONS } from '../../wasm/dist/names.js';
import { boundsOf, hasBounds, includePoint } from '../geometry/bounds.js';
import {
  CurveItem, cloneCurves, curveItemPosition, curvesForPlc, curvesFromPlc, dropPointFromCurves, includeCurves,
  moveCurveItem, removeCurve,
} from './curve-data.js';

// The package's options as the binding describes them (core/include/ruppert/option_table.h): the
// page takes its defaults and the angle's range from there rather than writing them again.
const PACKAGE_OPTIONS = Object.fromEntries(OPTIONS.map((option) => [option.name, option]));

/** The min angle's range in degrees: { min, max }. */
export const MIN_ANGLE_RANGE = Object.freeze({ min: PACKAGE_OPTIONS.minAngle.min, max: PACKAGE_OPTIONS.minAngle.max });

/** The whole number range of smoothing's passes: { min, max } (true stands for the usual passes). */
export const SMOOTH_PASSES_RANGE = Object.freeze({ min: PACKAGE_OPTIONS.smooth.min, max: PACKAGE_OPTIONS.smooth.max });

/** The package's option names, for hosts that pass options the page does not offer. */
export const PACKAGE_OPTION_NAMES = Object.freeze(OPTIONS.map((option) => option.name));

/** A page flag's option: its id in camel case ('size-measure' -> the package's option of that name). */
export const flagOption = (id) => id.replace(/-([a-z])/g, (_, letter) => letter.toUpperCase());

// The package's on/off options that the page offers, as the ids of their checkboxes in index.html
// (the option's name in kebab case): the panel, links and the mesher's options handle them alike,
// so that offering one more is one checkbox and one id here. In this order in links (one bit each).
// The chapter's size measure (stats.lfsIntegral, §6.5) costs a pass over the mesh: on demand.
// Smoothing takes true for its usual passes (the table's whenTrue), so it is a flag here too.
export const PAGE_FLAGS = Object.freeze(['size-measure', 'smooth']);
for (const id of PAGE_FLAGS) {
  const option = PACKAGE_OPTIONS[flagOption(id)];
  if (option?.type !== 'boolean' && option?.whenTrue === undefined) throw new Error(`page flag ${id}: no such on/off option`);
}

/** Options that turn the page flags of those ids on, for presets. */
export const flagOptions = (...ids) => Object.fromEntries(ids.map((id) => [flagOption(id), true]));

// maxAngle, maxArea and maxSteiner: null (none, automatic) where the package's default means the same.
export const DEFAULT_OPTIONS = Object.freeze({
  minAngle: PACKAGE_OPTIONS.minAngle.default, maxAngle: null, maxArea: null, placement: PACKAGE_OPTIONS.placement.default,
  maxSteiner: null, variant: PACKAGE_OPTIONS.variant.default, encroachment: PACKAGE_OPTIONS.encroachment.default,
  ...Object.fromEntries(PAGE_FLAGS.map((id) => [flagOption(id), Boolean(PACKAGE_OPTIONS[flagOption(id)].default)])),
  // Curves' largest distance from their boundary edges; 0: the core's automatic 1e-3 of the diagonal.
  curveTolerance: PACKAGE_OPTIONS.curveTolerance.default,
});

export function emptyDrawing(options = DEFAULT_OPTIONS) {
  return { points: [], segments: [], segmentMarkers: [], curves: [], holes: [], regions: [], options: { ...options } };
}

export function cloneDrawing(d) {
  return {
    points: d.points.slice(),
    segments: d.segments.slice(),
    segmentMarkers: segmentMarkers(d),
    curves: cloneCurves(d),
    holes: d.holes.slice(),
    regions: d.regions.map((r) => ({ ...r })),
    options: { ...d.options },
  };
}

export const pointCount = (d) => d.points.length / 2;

/** The drawing's segment markers, one per segment (0 where none was given). */
export function segmentMarkers(d) {
  const m = d.segments.length / 2;
  return Array.from({ length: m }, (_, k) => d.segmentMarkers?.[k] ?? 0);
}

/** The mesher's input (Plc of index.d.ts). */
export function toPlc(d) {
  return {
    points: Float64Array.from(d.points),
    segments: Uint32Array.from(d.segments),
    // Markers only when some segment has one: the mesh's own rules apply otherwise.
    ...(segmentMarkers(d).some((m) => m !== 0) ? { segmentMarkers: Int32Array.from(segmentMarkers(d)) } : {}),
    ...curvesForPlc(d),
    holes: Float64Array.from(d.holes),
    regions: d.regions.map((r) => ({
      x: r.x, y: r.y, attribute: r.attribute ?? 0, ...(r.maxArea > 0 ? { maxArea: r.maxArea } : {}),
    })),
  };
}

/** The mesher's options (TriangulateOptions of index.d.ts) for the worker. */
export function toMeshOptions(d, { trace = false } = {}) {
  const o = d.options;
  const options = {
    minAngle: o.minAngle,
    placement: o.placement,
    // Drawings from before these options existed (undo snapshots, old links) mean the defaults.
    variant: o.variant ?? DEFAULT_OPTIONS.variant,
    encroachment: o.encroachment ?? DEFAULT_OPTIONS.encroachment,
    trace,
    // The triangles the chapter exempts (§6.6), as the core decides, for the canvas and the Mesh panel.
    exemptions: true,
  };
  if (o.maxArea > 0) options.maxArea = o.maxArea;
  if (o.maxAngle > 0) options.maxAngle = o.maxAngle;
  if (Number.isInteger(o.maxSteiner) && o.maxSteiner >= 0) options.maxSteiner = o.maxSteiner;
  // A flag is on or off; smoothing may also be a number of passes (a host's load).
  for (const id of PAGE_FLAGS) {
    const value = o[flagOption(id)];
    if (value === true || (Number.isInteger(value) && value > 0)) options[flagOption(id)] = value;
  }
  if (o.curveTolerance > 0) options.curveTolerance = o.curveTolerance;
  return options;
}

/** Whether mesher options ask for smoothing (true, or a number of passes). */
export const isSmoothed = (options) => options?.smooth === true || options?.smooth > 0;

/** A drawing from a parsed file (ParsedPlc), keeping the given options. */
export function fromPlc(plc, options = DEFAULT_OPTIONS) {
  return {
    points: Array.from(plc.points ?? []),
    segments: Array.from(plc.segments ?? []),
    segmentMarkers: Array.from(plc.segmentMarkers ?? []),
    curves: curvesFromPlc(plc),
    holes: Array.from(plc.holes ?? []),
    regions: (plc.regions ?? []).map((r) => ({
      x: r.x, y: r.y, attribute: r.attribute ?? 0, maxArea: r.maxArea > 0 ? r.maxArea : null,
    })),
    options: { ...options },
  };
}

export function addPoint(d, x, y) {
  d.points.push(x, y);
  return d.points.length / 2 - 1;
}

/** Adds segment (a, b) unless it is degenerate or already present. Returns whether it was added. */
export function addSegment(d, a, b) {
  if (a === b) return false;
  for (let i = 0; i < d.segments.length; i += 2) {
    const s = d.segments[i];
    const t = d.segments[i + 1];
    if ((s === a && t === b) || (s === b && t === a)) return false;
  }
  d.segments.push(a, b);
  d.segmentMarkers = [...segmentMarkers(d).slice(0, -1), 0];
  return true;
}

/** Removes point i, the segments that use it, and renumbers the later points. */
export function removePoint(d, i) {
  d.points.splice(2 * i, 2);
  const kept = [];
  const markers = [];
  const old = segmentMarkers(d);
  for (let k = 0; k < d.segments.length; k += 2) {
    const a = d.segments[k];
    const b = d.segments[k + 1];
    if (a === i || b === i) continue;
    kept.push(a > i ? a - 1 : a, b > i ? b - 1 : b);
    markers.push(old[k / 2]);
  }
  d.segments = kept;
  d.segmentMarkers = markers;
  dropPointFromCurves(d, i);
}

export function removeSegment(d, k) {
  d.segmentMarkers = segmentMarkers(d);
  d.segments.splice(2 * k, 2);
  d.segmentMarkers.splice(k, 1);
}

/** Item addresses used by selection and hit testing. */
export const Item = Object.freeze({ POINT: 'point', SEGMENT: 'segment', HOLE: 'hole', REGION: 'region' });

export function itemPosition(d, item) {
  switch (item.kind) {
    case Item.POINT: return { x: d.points[2 * item.index], y: d.points[2 * item.index + 1] };
    case Item.HOLE: return { x: d.holes[2 * item.index], y: d.holes[2 * item.index + 1] };
    case Item.REGION: return { x: d.regions[item.index].x, y: d.regions[item.index].y };
    default: return curveItemPosition(d, item);
  }
}

export function moveItem(d, item, x, y) {
  switch (item.kind) {
    case Item.POINT: d.points[2 * item.index] = x; d.points[2 * item.index + 1] = y; break;
    case Item.HOLE: d.holes[2 * item.index] = x; d.holes[2 * item.index + 1] = y; break;
    case Item.REGION: d.regions[item.index].x = x; d.regions[item.index].y = y; break;
    default: moveCurveItem(d, item, x, y); break;
  }
}

export function removeItem(d, item) {
  switch (item.kind) {
    case Item.POINT: removePoint(d, item.index); break;
    case Item.SEGMENT: removeSegment(d, item.index); break;
    case Item.HOLE: d.holes.splice(2 * item.index, 2); break;
    case Item.REGION: d.regions.splice(item.index, 1); break;
    case CurveItem.CURVE: case CurveItem.HANDLE: removeCurve(d, item.index); break;
    default: break;
  }
}

function distanceToSegmentSquared(px, py, ax, ay, bx, by) {
  const dx = bx - ax;
  const dy = by - ay;
  const length2 = dx * dx + dy * dy;
  let t = length2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / length2 : 0;
  t = Math.max(0, Math.min(1, t));
  const ex = ax + t * dx - px;
  const ey = ay + t * dy - py;
  return ex * ex + ey * ey;
}

/**
 * The item nearest to (x, y) within `radius` world units: seeds and points first (they sit on
 * top), then segments. `kinds` restricts the search.
 */
export function hitTest(d, x, y, radius, kinds = [Item.HOLE, Item.REGION, Item.POINT, Item.SEGMENT]) {
  const r2 = radius * radius;
  let best = null;
  let bestDistance = r2;
  const consider = (kind, index, distance2) => {
    if (distance2 <= bestDistance) {
      best = { kind, index };
      bestDistance = distance2;
    }
  };
  const near = (px, py) => (px - x) ** 2 + (py - y) ** 2;
  if (kinds.includes(Item.HOLE)) {
    for (let i = 0; i < d.holes.length / 2; i++) consider(Item.HOLE, i, near(d.holes[2 * i], d.holes[2 * i + 1]));
  }
  if (kinds.includes(Item.REGION)) {
    d.regions.forEach((r, i) => consider(Item.REGION, i, near(r.x, r.y)));
  }
  if (kinds.includes(Item.POINT)) {
    for (let i = 0; i < d.points.length / 2; i++) consider(Item.POINT, i, near(d.points[2 * i], d.points[2 * i + 1]));
  }
  if (best === null && kinds.includes(Item.SEGMENT)) {
    for (let k = 0; k < d.segments.length / 2; k++) {
      const a = d.segments[2 * k];
      const b = d.segments[2 * k + 1];
      consider(Item.SEGMENT, k, distanceToSegmentSquared(x, y, d.points[2 * a], d.points[2 * a + 1],
        d.points[2 * b], d.points[2 * b + 1]));
    }
  }
  return best;
}

/** Axis-aligned bounds of everything drawn, or null when empty. */
export function drawingBounds(d) {
  const box = boundsOf(d.holes, boundsOf(d.points));
  for (const r of d.regions) includePoint(box, r.x, r.y);
  includeCurves(box, d);
  return hasBounds(box) ? box : null;
}
