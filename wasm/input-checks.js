// Checks what users pass to triangulate() and the writers, and converts it into what the binding
// takes (typed arrays of the exact element type, enums as the core's numbers), before anything
// crosses into wasm; and rejects unknown keys in every object the API takes.
//
// Why here and not only in C++: embind would silently coerce a string or a sparse array into
// numbers (NaN, 0), and a fractional index would be truncated into a different, valid-looking
// vertex. Every message names the item and its value, e.g. "segments[3] = (1, 2.5): 2.5 is not an
// integer" (items, not flat positions, as the core's messages).
// Value checks that need geometry (non-finite coordinates, duplicate points, hole placement) stay
// in the core, which reports them with the same codes.
import { NAMES, OPTIONS } from './dist/names.js';
import { MeshError } from './errors.js';

// Unknown keys are mistakes (`{ Segments: [...] }` would otherwise mesh the convex hull without a
// word): every object the API takes is checked against its known keys, with a did-you-mean.

// Levenshtein distance, for short keys only.
function editDistance(a, b) {
  let previous = Array.from({ length: b.length + 1 }, (_, j) => j);
  for (let i = 1; i <= a.length; i++) {
    const current = [i];
    for (let j = 1; j <= b.length; j++) {
      current[j] = Math.min(previous[j] + 1, current[j - 1] + 1, previous[j - 1] + (a[i - 1] === b[j - 1] ? 0 : 1));
    }
    previous = current;
  }
  return previous[b.length];
}

/** The known key `key` was probably meant as, or undefined. */
function nearestKey(key, known) {
  const plain = (s) => s.toLowerCase().replace(/[-_\s]/g, '');
  const k = plain(key);
  return known.find((name) => plain(name) === k) ??
    known.find((name) => editDistance(plain(name), k) <= 2) ??
    (k.length >= 3 ? known.find((name) => plain(name).includes(k)) : undefined);
}

/**
 * Throws makeError(message) for the first own key of `object` not in `known`.
 * @param {string} what how the message names the object, e.g. "the input" or "regions[2]"
 */
export function rejectUnknownKeys(object, known, what, makeError, knownSet = null) {
  for (const key of Object.keys(object)) {
    if (knownSet !== null ? knownSet.has(key) : known.includes(key)) continue;
    const near = nearestKey(key, known);
    throw makeError(`${what} has an unknown key '${key}'${near ? ` (did you mean '${near}'?)` : ''}; ` +
      `the keys are ${known.join(', ')}`);
  }
}

const MAX_UINT32 = 0xffffffff;
const PLC_KEYS = ['points', 'segments', 'holes', 'regions', 'pointMarkers', 'segmentMarkers', 'indexBase',
  'triangles', 'triangleMaxArea', 'pointAttributes', 'attributesPerPoint', 'curves'];
const PLC_KEY_SET = new Set(PLC_KEYS);
const REGION_KEYS = ['x', 'y', 'attribute', 'maxArea'];
const CURVE_KEYS = ['type', 'from', 'to', 'center', 'controls', 'marker'];

function describe(value) {
  if (value === undefined) return 'undefined';
  if (value === null) return 'null';
  if (typeof value === 'string') return JSON.stringify(value.length > 40 ? value.slice(0, 40) + '...' : value);
  if (typeof value === 'bigint') return `${value}n`;
  if (Array.isArray(value)) return 'an array';
  if (typeof value === 'function') return 'a function';
  if (typeof value === 'object') return 'an object';
  return String(value);
}

// The absent optional arrays of a checked PLC: one frozen empty array of each type, shared, since
// even an empty typed array costs an allocation (a PLC of points alone had eight per call).
const NO_INDICES = Object.freeze(new Uint32Array(0));
const NO_NUMBERS = Object.freeze(new Float64Array(0));
const NO_MARKERS = Object.freeze(new Int32Array(0));

function invalid(message) {
  return new MeshError('MALFORMED_INPUT', message);
}

function isNumericTypedArray(value) {
  return ArrayBuffer.isView(value) && !(value instanceof DataView) &&
    !(value instanceof BigInt64Array) && !(value instanceof BigUint64Array);
}

// Messages name items, as the core does (docs/usage.md, "Indices in messages"): point i's
// coordinates are points[i].x and points[i].y, segment k is segments[k] = (a, b), triangle t is
// triangles[t] = (a, b, c); arrays of one value per item are indexed as they are.
const coordinateName = (name, i) => `${name}[${i >> 1}].${i & 1 ? 'y' : 'x'}`;

/** Item i / stride of a flat index array with its values: "segments[4] = (1, 2.5)". */
function tupleName(name, value, i, stride) {
  const first = i - (i % stride);
  const parts = [];
  for (let j = first; j < first + stride; j++) {
    parts.push(j >= value.length ? '…' : typeof value[j] === 'number' ? String(value[j]) : describe(value[j]));
  }
  return stride === 1 ? `${name}[${i}] = ${parts[0]}` : `${name}[${first / stride}] = (${parts.join(', ')})`;
}

// Any array-like of numbers -> Float64Array (a copy only when the input is not one already).
// `pairs`: x, y coordinates. Messages are built only on failure (here and in toIndices), so that a
// call's checks allocate nothing they do not return.
function toFloat64(value, name, pairs) {
  let out;
  if (value instanceof Float64Array) {
    out = value;
  } else if (isNumericTypedArray(value)) {
    out = Float64Array.from(value);
  } else if (Array.isArray(value)) {
    out = new Float64Array(value.length);
    for (let i = 0; i < value.length; i++) {
      const v = value[i];
      if (typeof v !== 'number') throw notANumber(value, name, pairs, i);
      out[i] = v;
    }
  } else {
    throw invalid(`${name} must be an array or a typed array of numbers, got ${describe(value)}`);
  }
  if (pairs && out.length % 2 !== 0) {
    throw invalid(`${name} has odd length ${out.length}: coordinates come in x, y pairs`);
  }
  return out;
}

function notANumber(value, name, pairs, i) {
  const v = value[i], at = pairs ? coordinateName(name, i) : `${name}[${i}]`;
  if (v === undefined && !(i in value)) return invalid(`${at} is missing (sparse array)`);
  if (Array.isArray(v) && pairs) return invalid(`${at} is an array: ${name} must be flat [x0, y0, x1, y1, ...]`);
  return invalid(`${at} = ${describe(v)} is not a number`);
}

// Array-like of indices -> Uint32Array, each an integer in [0, limit); `stride` indices an item.
function toIndices(value, name, limit, what, stride) {
  if (value instanceof Uint32Array) {
    for (let i = 0; i < value.length; i++) if (value[i] >= limit) throw badIndex(value, name, limit, what, stride, i);
    return value;
  }
  const isTyped = isNumericTypedArray(value);
  if (!isTyped && !Array.isArray(value)) {
    throw invalid(`${name} must be an array or a typed array of integer indices, got ${describe(value)}`);
  }
  const out = new Uint32Array(value.length);
  for (let i = 0; i < value.length; i++) {
    const v = value[i];
    if (typeof v !== 'number' || !Number.isInteger(v) || v < 0 || v >= limit || v > MAX_UINT32) {
      throw badIndex(value, name, limit, what, stride, i);
    }
    out[i] = v;
  }
  return out;
}

// Why value[i] is not an index below `limit`, naming its item ("segments[4] = (1, 2.5)").
function badIndex(value, name, limit, what, stride, i) {
  const v = value[i], item = tupleName(name, value, i, stride);
  if (typeof v !== 'number') {
    if (v === undefined && !(i in value)) return invalid(`${item}: an index is missing (sparse array)`);
    return invalid(`${item}: ${describe(v)} is not a number`);
  }
  if (!Number.isInteger(v)) return invalid(`${item}: ${v} is not an integer`);
  return new MeshError('INDEX_OUT_OF_RANGE',
    v < 0 ? `${item}: ${v} is negative` : `${item}: ${v} refers to ${what} ${v}, but there are only ${limit}`);
}

function toMarkers(value, name) {
  if (value === undefined || value === null) return NO_MARKERS;
  if (value instanceof Int32Array) return value;
  if (!isNumericTypedArray(value) && !Array.isArray(value)) {
    throw invalid(`${name} must be an array or a typed array of integers, got ${describe(value)}`);
  }
  const out = new Int32Array(value.length);
  for (let i = 0; i < value.length; i++) {
    const v = value[i];
    if (!Number.isInteger(v) || v < -0x80000000 || v > 0x7fffffff) {
      throw invalid(`${name}[${i}] = ${describe(v)} is not a 32-bit integer`);
    }
    out[i] = v;
  }
  return out;
}

function regionNumber(region, i, key, fallback) {
  const v = region[key];
  if (v === undefined && fallback !== undefined) return fallback;
  if (typeof v !== 'number') throw invalid(`regions[${i}].${key} = ${describe(v)} is not a number`);
  return v;
}

// Refining a mesh: triangles (3 point indices each) and triangleMaxArea (one per triangle,
// <= 0: none); the core checks the geometry (zero-area triangles) and NaN bounds.
function oldMesh(plc, pointCount) {
  const triangles = plc.triangles == null ? NO_INDICES : toIndices(plc.triangles, 'triangles', pointCount, 'point', 3);
  if (triangles.length % 3 !== 0) {
    throw invalid(`triangles has length ${triangles.length}: a triangle is three point indices`);
  }
  const triangleMaxArea = plc.triangleMaxArea == null ? NO_NUMBERS
    : toFloat64(plc.triangleMaxArea, 'triangleMaxArea', false);
  if (triangleMaxArea.length !== 0 && triangleMaxArea.length !== triangles.length / 3) {
    throw invalid(`triangleMaxArea has ${triangleMaxArea.length} entries for ${triangles.length / 3} triangles`);
  }
  return { triangles, triangleMaxArea };
}

// Curves: each { type: 'arc', from, to, center: [x, y] } or { type: 'bezier', from, to,
// controls: [x1, y1, x2, y2] }, with an optional marker, flattened to 8 numbers (the binding's
// heap_layout.h: type, from, to, 4 coordinates, marker). The core checks the geometry and the
// indices' range, naming the curve.
function checkCurves(plc) {
  if (plc.curves == null) return NO_NUMBERS;
  if (!Array.isArray(plc.curves)) throw invalid(`curves must be an array of { type, from, to, center | controls }, got ${describe(plc.curves)}`);
  const out = new Float64Array(8 * plc.curves.length);
  plc.curves.forEach((c, i) => {
    const at = `curves[${i}]`;
    if (c === null || typeof c !== 'object') throw invalid(`${at} = ${describe(c)} is not an object { type, from, to, ... }`);
    rejectUnknownKeys(c, CURVE_KEYS, at, invalid);
    const type = NAMES.curveTypes.indexOf(c.type);
    if (type < 0) throw invalid(`${at}.type = ${describe(c.type)} must be one of ${NAMES.curveTypes.map((n) => `'${n}'`).join(', ')}`);
    const key = type === 0 ? 'center' : 'controls', count = type === 0 ? 2 : 4;
    const values = c[key] == null ? [] : toFloat64(c[key], `${at}.${key}`, false);
    if (values.length !== count) throw invalid(`${at} needs ${key}: ${count} numbers, got ${describe(c[key])}`);
    const ends = [c.from, c.to];
    ['from', 'to'].forEach((name, k) => {
      if (!Number.isInteger(ends[k]) || ends[k] < 0 || ends[k] > MAX_UINT32) throw invalid(`${at}.${name} = ${describe(ends[k])} is not a point index`);
    });
    const marker = c.marker ?? 0;
    if (!Number.isInteger(marker) || marker < -0x80000000 || marker > 0x7fffffff) throw invalid(`${at}.marker = ${describe(marker)} is not a 32-bit integer`);
    out.set([type, c.from, c.to], 8 * i), out.set(values, 8 * i + 3), out[8 * i + 7] = marker;
  });
  return out;
}

/**
 * @param {unknown} plc { points, segments?, holes?, regions?, pointMarkers?, segmentMarkers?, indexBase? }
 * @returns the same data as exact typed arrays; regions flattened to x, y, attribute, maxArea.
 */
export function checkPlc(plc) {
  if (plc === null || typeof plc !== 'object' || Array.isArray(plc) || ArrayBuffer.isView(plc)) {
    throw invalid(`the input must be an object { points, segments, holes, regions }, got ${describe(plc)}`);
  }
  rejectUnknownKeys(plc, PLC_KEYS, 'the input', invalid, PLC_KEY_SET);
  if (plc.points === undefined) throw invalid('the input has no "points" array');
  const points = toFloat64(plc.points, 'points', true);
  const pointCount = points.length / 2;
  const segments = plc.segments == null ? NO_INDICES
    : toIndices(plc.segments, 'segments', pointCount, 'point', 2);
  if (segments.length % 2 !== 0) {
    throw invalid(`segments has odd length ${segments.length}: a segment is a pair of point indices`);
  }
  const holes = plc.holes == null ? NO_NUMBERS : toFloat64(plc.holes, 'holes', true);

  let regions = NO_NUMBERS;
  if (plc.regions != null) {
    if (!Array.isArray(plc.regions)) {
      throw invalid(`regions must be an array of { x, y, attribute, maxArea }, got ${describe(plc.regions)}`);
    }
    if (plc.regions.length > 0) regions = new Float64Array(4 * plc.regions.length);
    for (let i = 0; i < plc.regions.length; i++) {
      const r = plc.regions[i];
      if (r === null || typeof r !== 'object') {
        if (r === undefined && !(i in plc.regions)) throw invalid(`regions[${i}] is missing (sparse array)`);
        throw invalid(`regions[${i}] = ${describe(r)} is not an object { x, y, attribute, maxArea }`);
      }
      rejectUnknownKeys(r, REGION_KEYS, `regions[${i}]`, invalid);
      regions[4 * i] = regionNumber(r, i, 'x');
      regions[4 * i + 1] = regionNumber(r, i, 'y');
      regions[4 * i + 2] = regionNumber(r, i, 'attribute', 0);
      regions[4 * i + 3] = regionNumber(r, i, 'maxArea', 0);
    }
  }

  const pointMarkers = toMarkers(plc.pointMarkers, 'pointMarkers');
  if (pointMarkers.length !== 0 && pointMarkers.length !== pointCount) {
    throw invalid(`pointMarkers has ${pointMarkers.length} entries for ${pointCount} points`);
  }
  const segmentMarkers = toMarkers(plc.segmentMarkers, 'segmentMarkers');
  if (segmentMarkers.length !== 0 && segmentMarkers.length !== segments.length / 2) {
    throw invalid(`segmentMarkers has ${segmentMarkers.length} entries for ${segments.length / 2} segments`);
  }
  const indexBase = plc.indexBase ?? 0;
  if (indexBase !== 0 && indexBase !== 1) throw invalid(`indexBase = ${describe(indexBase)} must be 0 or 1`);
  const { triangles, triangleMaxArea } = oldMesh(plc, pointCount);
  const { pointAttributes, attributesPerPoint } = checkAttributes(plc, pointCount);
  return { points, segments, holes, regions, pointMarkers, segmentMarkers, indexBase, triangles, triangleMaxArea,
    pointAttributes, attributesPerPoint, curves: checkCurves(plc) };
}

// pointAttributes: flat, attributesPerPoint values per point; without attributesPerPoint the count is
// the length divided by the number of points (which must divide it).
function checkAttributes(plc, pointCount) {
  const pointAttributes = plc.pointAttributes == null ? NO_NUMBERS
    : toFloat64(plc.pointAttributes, 'pointAttributes', false);
  let attributesPerPoint = plc.attributesPerPoint;
  if (attributesPerPoint !== undefined &&
      (!Number.isInteger(attributesPerPoint) || attributesPerPoint < 0 || attributesPerPoint > 0xffff)) {
    throw invalid(`attributesPerPoint = ${describe(attributesPerPoint)} must be an integer in [0, 65535]`);
  }
  if (attributesPerPoint === undefined) {
    if (pointAttributes.length % Math.max(pointCount, 1) !== 0) {
      throw invalid(`pointAttributes has ${pointAttributes.length} entries, not a multiple of the ${pointCount} points`);
    }
    attributesPerPoint = pointCount > 0 ? pointAttributes.length / pointCount : 0;
  }
  if (pointAttributes.length !== attributesPerPoint * pointCount) {
    throw invalid(`pointAttributes has ${pointAttributes.length} entries for ${pointCount} points with ` +
      `${attributesPerPoint} attribute(s) each`);
  }
  return { pointAttributes, attributesPerPoint: pointAttributes.length === 0 ? 0 : attributesPerPoint };
}

// Every option, as the binding describes it (core/include/ruppert/option_table.h, through
// wasm/binding/describe.cpp): { name, type, default, and min, max, unit or values }. The checks
// below go by type, so that no option's name, default or range is written here.
const OPTION_KEYS = OPTIONS.map((option) => option.name);

function badOption(message) {
  return new MeshError('INVALID_OPTION', message);
}

// A number-valued option: the wrong type (or NaN) is named as such before any range check;
// meaning(option) says what is expected (called only for the message).
function numberOf(options, option, fallback, meaning) {
  const v = options[option.name] ?? fallback;
  if (typeof v !== 'number' || Number.isNaN(v)) {
    throw badOption(`${option.name} = ${describe(v)} is not a number (${meaning(option)})`);
  }
  return v;
}

const boundedMeaning = ({ min, max, unit }) => `${unit} in [${min}, ${max}]`;
const openMeaning = ({ default: fallback, min, unit }) => `an ${unit} >= ${min}; ${fallback}: no bound`;
const countMeaning = ({ unit }) => `a count of ${unit}, or Infinity`;

// A number in [min, max]; with no upper end (max null), Infinity is the default, "no bound".
function numberOption(options, option) {
  const { name, default: fallback, min, max, unit } = option;
  if (max !== null) {
    const v = numberOf(options, option, fallback, boundedMeaning);
    if (!(v >= min && v <= max)) throw badOption(`${name} = ${describe(v)} is outside [${min}, ${max}] ${unit}`);
    return v;
  }
  const v = numberOf(options, option, fallback, openMeaning);
  if (!(v >= min)) throw badOption(`${name} = ${describe(v)} must be >= ${min} (${fallback}: no bound)`);
  return v === Infinity ? fallback : v;
}

// A count, or Infinity (the default, null in the table) for automatic: -1 for the binding.
function countOption(options, option) {
  const v = numberOf(options, option, Infinity, countMeaning);
  if (!(v >= 0) || (v !== Infinity && (!Number.isInteger(v) || v > Number.MAX_SAFE_INTEGER))) {
    throw badOption(`${option.name} = ${describe(v)} must be a non-negative integer or Infinity`);
  }
  return v === Infinity ? -1 : v;
}

// One of the integers min..max ("1 or 2"); where the table gives whenTrue, also true (that many)
// or false (min).
function integerOption(options, { name, default: fallback, min, max, whenTrue }) {
  let v = options[name] ?? fallback;
  if (whenTrue !== undefined && typeof v === 'boolean') v = v ? whenTrue : min;
  if (!Number.isInteger(v) || v < min || v > max) {
    const values = Array.from({ length: max - min + 1 }, (_, i) => min + i);
    const allowed = values.length > 4 ? `an integer from ${min} to ${max}` : `${values.slice(0, -1).join(', ')} or ${values.at(-1)}`;
    throw badOption(`${name} = ${describe(v)} must be ${allowed}${whenTrue !== undefined ? ', true or false' : ''}`);
  }
  return v;
}

function booleanOption(options, { name, default: fallback }) {
  const v = options[name];
  if (v === undefined) return fallback;
  if (typeof v !== 'boolean') throw badOption(`${name} = ${describe(v)} must be true or false`);
  return v;
}

// One of the enum's names (in enum order: a name's index is its value), as the core's number.
function choiceOption(options, { name, default: fallback, values }) {
  const v = options[name];
  if (v === undefined) return values.indexOf(fallback);
  const value = typeof v === 'string' ? values.indexOf(v) : -1;
  if (value < 0) throw badOption(`${name} = ${describe(v)} must be one of ${values.map((k) => `'${k}'`).join(', ')}`);
  return value;
}

function functionOption(options, { name }) {
  const v = options[name];
  if (v === undefined || v === null) return undefined;
  if (typeof v !== 'function') throw badOption(`${name} = ${describe(v)} must be a function`);
  return v;
}

const CHECK_BY_TYPE = {
  number: numberOption, count: countOption, integer: integerOption, boolean: booleanOption,
  choice: choiceOption, function: functionOption,
};

// Every option at its default, as the checks give it: a call checks only the options it names and
// copies the rest from here. Reading all of them from the caller's object, each by a name unknown
// until run time, was most of the cost of this check, itself a tenth of a small mesh's call.
// Not frozen: spreading a frozen object takes V8's slow path, about nine times the cost of the
// fast one for these 22 keys; nothing outside this module sees DEFAULTS.
const DEFAULTS = Object.fromEntries(OPTIONS.map((option) => [option.name, CHECK_BY_TYPE[option.type]({}, option)]));
const OPTION_BY_NAME = new Map(OPTIONS.map((option) => [option.name, option]));

/**
 * @returns every option by name, checked and defaulted: enums as the core's integers, maxSteiner -1
 *          for automatic, sizeFunction and onProgress undefined when absent.
 */
export function checkOptions(options) {
  if (options === undefined || options === null) options = {};
  if (typeof options !== 'object' || Array.isArray(options)) {
    throw invalid(`options must be an object, got ${describe(options)}`);
  }
  const keys = Object.keys(options);
  for (const key of keys) {
    if (!OPTION_BY_NAME.has(key)) {
      const near = nearestKey(key, OPTION_KEYS);
      throw badOption(`unknown option '${key}'${near ? ` (did you mean '${near}'?)` : ''}`);
    }
  }
  const checked = { ...DEFAULTS };
  for (const key of keys) {
    const option = OPTION_BY_NAME.get(key);
    checked[key] = CHECK_BY_TYPE[option.type](options, option);
  }
  return checked;
}

export function checkMesh(mesh) {
  if (mesh === null || typeof mesh !== 'object') {
    throw invalid(`expected a mesh returned by triangulate(), got ${describe(mesh)}`);
  }
  const points = toFloat64(mesh.points ?? [], 'mesh.points', true);
  const n = points.length / 2;
  const triangles = toIndices(mesh.triangles ?? [], 'mesh.triangles', n, 'point', 3);
  if (triangles.length % 3 !== 0) throw invalid(`mesh.triangles has length ${triangles.length}, not a multiple of 3`);
  const segments = toIndices(mesh.segments ?? [], 'mesh.segments', n, 'point', 2);
  if (segments.length % 2 !== 0) throw invalid(`mesh.segments has odd length ${segments.length}`);
  const neighbors = toMarkers(mesh.neighbors, 'mesh.neighbors');
  const segmentIds = toMarkers(mesh.segmentIds, 'mesh.segmentIds');
  const pointMarkers = toMarkers(mesh.pointMarkers, 'mesh.pointMarkers');
  const vertexKinds = mesh.vertexKinds == null ? new Uint8Array(0) : Uint8Array.from(mesh.vertexKinds);
  const triangleAttributes = mesh.triangleAttributes == null ? new Float64Array(0)
    : toFloat64(mesh.triangleAttributes, 'mesh.triangleAttributes', false);
  const indexBase = mesh.indexBase ?? 0;
  if (indexBase !== 0 && indexBase !== 1) throw invalid(`mesh.indexBase = ${describe(indexBase)} must be 0 or 1`);
  const triangles6 = mesh.triangles6 == null ? new Uint32Array(0) : toIndices(mesh.triangles6, 'mesh.triangles6', n, 'point', 6);
  if (triangles6.length !== 0 && triangles6.length !== 2 * triangles.length) {
    throw invalid(`mesh.triangles6 has length ${triangles6.length}, not 6 per triangle`);
  }
  const segmentMarkers = toMarkers(mesh.segmentMarkers, 'mesh.segmentMarkers');
  const edges = toIndices(mesh.edges ?? [], 'mesh.edges', n, 'point', 2);
  if (edges.length % 2 !== 0) throw invalid(`mesh.edges has odd length ${edges.length}`);
  const edgeMarkers = toMarkers(mesh.edgeMarkers, 'mesh.edgeMarkers');
  const { pointAttributes, attributesPerPoint } = checkAttributes(
    { pointAttributes: mesh.pointAttributes, attributesPerPoint: mesh.attributesPerPoint || undefined }, n);
  return { points, triangles, neighbors, segments, segmentIds, vertexKinds, triangleAttributes,
    pointMarkers, indexBase, triangles6, segmentMarkers, edges, edgeMarkers, pointAttributes, attributesPerPoint };
}
