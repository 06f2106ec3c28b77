// triangulate() through the wasm heap (see "triangulate() through the heap" in wasm/bindings.cpp):
// the normalised input and the options are written straight into the staged vectors and table, the
// mesh (reasons and notices included) is read back from a table of (address, length) pairs and
// scalars. Without callbacks no embind call is made: the plain exports Module._rp_* cost no more
// than any wasm call. Only failures, traces and the CLI's texts go through embind objects. Every
// array handed out is a copy: a view into the heap would go stale when it grows.

// In the order of the table written by writeOutputTable() (bindings.cpp). Reasons and notices come
// as numbers per item (the kind's number first), a UTF-8 text of "message\0" per item, and the
// kinds' names ("NAME\0" per kind number).
const ARRAYS = [
  ['points', Float64Array], ['triangles', Uint32Array], ['neighbors', Int32Array], ['segments', Uint32Array],
  ['segmentIds', Int32Array], ['vertexKinds', Uint8Array], ['triangleAttributes', Float64Array],
  ['pointMarkers', Int32Array], ['angleHistogram', Float64Array],
  // Read here at once, before anything can grow the heap: views, not copies.
  ['reasonNumbers', Float64Array, 'view'], ['reasonText', Uint8Array, 'view'], ['reasonKinds', Uint8Array, 'view'],
  ['noticeNumbers', Float64Array, 'view'], ['noticeText', Uint8Array, 'view'], ['noticeKinds', Uint8Array, 'view'],
  // Issue 16: boundary markers, edges, attributes, jettison's numbering.
  ['segmentMarkers', Int32Array], ['edges', Uint32Array], ['edgeMarkers', Int32Array],
  ['pointAttributes', Float64Array], ['inputToOutput', Int32Array],
];
const STATS_BEFORE_HISTOGRAM = ['vertices', 'triangles', 'minAngle', 'maxAngle'];
const STATS_AFTER_HISTOGRAM = ['inputVertices', 'segmentVertices', 'interiorVertices', 'offCenterVertices',
  'intersectionVertices', 'rejectedCircumcenters', 'lfsIntegral', 'trianglesPerLfsIntegral', 'milliseconds', 'reachedAngle'];
// The scalars after the stats (the attribute count), in the table's order.
const SCALARS_AFTER_STATS = ['attributesPerPoint'];

const INPUTS = [
  ['points', Float64Array], ['segments', Uint32Array], ['holes', Float64Array], ['regions', Float64Array],
  ['pointMarkers', Int32Array], ['segmentMarkers', Int32Array], ['pointAttributes', Float64Array],
];
// After the input arrays' addresses in the input table, one double each (optionsFromTable in bindings.cpp).
const OPTION_FIELDS = ['minAngle', 'maxArea', 'maxSteiner', 'placement', 'encroachment', 'variant', 'convexHull',
  'autoHoles', 'trace', 'sizeMeasure', 'edges', 'noBoundarySteiner', 'noSegmentSteiner', 'jettison'];

// Issue 16, derived: the old mesh to refine, order and voronoi go in a table of their own
// (rp_stage_derived, DerivedStaged in bindings.cpp); what they give comes back in another
// (rp_derived_table): (address, length) pairs in this order.
const DERIVED_INPUTS = [['triangles', Uint32Array], ['triangleMaxArea', Float64Array]];
const DERIVED_OUTPUTS = [['triangles6', Uint32Array], ['points', Float64Array], ['edges', Int32Array],
  ['rayDirections', Float64Array], ['meshEdges', Uint32Array]];

function stageDerived(m, input, options) {
  const table = m._rp_stage_derived(input.triangles.length, input.triangleMaxArea.length, options.order,
    options.voronoi ? 1 : 0);
  if (table === 0) return false;
  DERIVED_INPUTS.forEach(([name, Type], i) => {
    const values = input[name];
    if (values.length > 0) heapView(m, Type).set(values, m.HEAPF64[(table >>> 3) + i] / Type.BYTES_PER_ELEMENT);
  });
  return true;
}

// mesh.triangles6 (order 2; mesh.points already holds the midpoint nodes) and mesh.voronoi.
function readDerived(m, mesh, options) {
  const table = m.HEAPF64.subarray(m._rp_derived_table() >>> 3);
  const arrays = {};
  DERIVED_OUTPUTS.forEach(([name, Type], i) => {
    const start = table[2 * i] / Type.BYTES_PER_ELEMENT, length = table[2 * i + 1];
    arrays[name] = length > 0 ? heapView(m, Type).slice(start, start + length) : new Type(0);
  });
  if (options.order === 2) mesh.triangles6 = arrays.triangles6;
  if (options.voronoi) {
    const { points, edges, rayDirections, meshEdges } = arrays;
    mesh.voronoi = { points, edges, rayDirections, meshEdges };
  }
}

// The module's view of the heap for an element type (fetched after every call that may grow it).
function heapView(m, Type) {
  switch (Type) {
    case Float64Array: return m.HEAPF64;
    case Uint32Array: return m.HEAPU32;
    case Int32Array: return m.HEAP32;
    default: return m.HEAPU8;
  }
}

const utf8 = new TextDecoder();

// The messages of `count` items (and the kinds' names), when there are any.
const textsFromHeap = (count, bytes) => (count > 0 ? utf8.decode(bytes()).split('\0') : []);

// One object literal per item (its shape fixed, so building 10^5 of them stays cheap; a kind number
// is made a small integer before it indexes an array, which a double key would make a slow lookup).
function reasonsFromHeap(count, numberView, bytes, kindBytes) {
  const numbers = count > 0 ? numberView() : null;
  const messages = textsFromHeap(count, bytes), kinds = textsFromHeap(count, kindBytes);
  const reasons = [];
  for (let i = 0; i < count; i++) reasons.push({ kind: kinds[numbers[2 * i] | 0], count: numbers[2 * i + 1], message: messages[i] });
  return reasons;
}

function noticesFromHeap(count, numberView, bytes, kindBytes) {
  const numbers = count > 0 ? numberView() : null;
  const messages = textsFromHeap(count, bytes), kinds = textsFromHeap(count, kindBytes);
  const notices = [];
  for (let i = 0, k = 0; i < count; i++, k += 5) {
    notices.push({
      kind: kinds[numbers[k] | 0], a: numbers[k + 1], b: numbers[k + 2], x: numbers[k + 3], y: numbers[k + 4],
      message: messages[i],
    });
  }
  return notices;
}

function writeInput(m, inputTable, input, options) {
  const table = inputTable >>> 3;
  INPUTS.forEach(([name, Type], i) => {
    const values = input[name];
    if (values.length > 0) heapView(m, Type).set(values, m.HEAPF64[table + i] / Type.BYTES_PER_ELEMENT);
  });
  const f64 = m.HEAPF64;
  for (let i = 0; i < OPTION_FIELDS.length; i++) f64[table + INPUTS.length + i] = Number(options[OPTION_FIELDS[i]]);
}

function readMesh(m, options) {
  const table = m.HEAPF64.subarray(m._rp_output_table() >>> 3);
  const arrays = {};
  let k = 0;
  for (const [name, Type, view] of ARRAYS) {
    const address = table[k++], length = table[k++];
    const start = address / Type.BYTES_PER_ELEMENT;
    // A view is made only when there is something to read (most calls have no reasons or notices).
    if (view) arrays[name] = () => heapView(m, Type).subarray(start, start + length);
    else arrays[name] = length > 0 ? heapView(m, Type).slice(start, start + length) : new Type(0);
  }
  const indexBase = table[k++], complete = table[k++] === 1;
  const reasonCount = table[k++], noticeCount = table[k++];
  k++;  // the event count: events come with the extras when traced
  const stats = {};
  for (const name of STATS_BEFORE_HISTOGRAM) stats[name] = table[k++];
  stats.angleHistogram = arrays.angleHistogram;
  for (const name of STATS_AFTER_HISTOGRAM) stats[name] = table[k++];
  const scalars = {};
  for (const name of SCALARS_AFTER_STATS) scalars[name] = table[k++];
  const mesh = {
    points: arrays.points, triangles: arrays.triangles, neighbors: arrays.neighbors, segments: arrays.segments,
    segmentIds: arrays.segmentIds, vertexKinds: arrays.vertexKinds, triangleAttributes: arrays.triangleAttributes,
    pointMarkers: arrays.pointMarkers, segmentMarkers: arrays.segmentMarkers,
    pointAttributes: arrays.pointAttributes, attributesPerPoint: scalars.attributesPerPoint, indexBase, complete,
    reasons: reasonsFromHeap(reasonCount, arrays.reasonNumbers, arrays.reasonText, arrays.reasonKinds),
    notices: noticesFromHeap(noticeCount, arrays.noticeNumbers, arrays.noticeText, arrays.noticeKinds),
    stats,
  };
  if (options.edges) mesh.edges = arrays.edges, mesh.edgeMarkers = arrays.edgeMarkers;
  if (options.jettison) mesh.inputToOutput = arrays.inputToOutput;
  return mesh;
}

/**
 * @param {object} m the Emscripten module
 * @param {object} input normalizePlc()'s result
 * @param {object} options normalizeOptions()'s result with the callbacks wrapped
 * @param {object|null} report for wasm/cli.js: { summary, stats, trace } booleans
 * @returns the mesh object, or a failure { errorCode, errorMessage, reset? }
 */
export function triangulateInHeap(m, input, options, report) {
  const lengths = INPUTS.map(([name]) => input[name].length);
  const inputTable = m._rp_stage_input(...lengths, input.indexBase, input.attributesPerPoint);
  if (inputTable === 0) {
    return { errorCode: 'TOO_LARGE', errorMessage: 'out of memory: the input does not fit in 4 GB of WebAssembly memory', reset: true };
  }
  writeInput(m, inputTable, input, options);
  if (!stageDerived(m, input, options)) {
    m._rp_release_staged();
    return { errorCode: 'TOO_LARGE', errorMessage: 'out of memory: the input does not fit in 4 GB of WebAssembly memory', reset: true };
  }
  let failure = null;
  if (options.sizeFunction || options.onProgress) {
    failure = m.triangulateStaged(options.sizeFunction ?? null, options.onProgress ?? null);
  } else if (m._rp_triangulate() !== 0) {
    failure = m.stagedFailure();
  }
  if (failure !== null) {
    m._rp_release_staged();
    return failure;
  }
  const mesh = readMesh(m, options);
  readDerived(m, mesh, options);
  if (options.trace || report != null) {
    const extras = m.stagedExtras(report ?? null, options.trace);
    if (extras.errorCode) {
      m._rp_release_staged();
      return extras;
    }
    if (options.trace) mesh.events = extras.events;
    if (report != null) mesh.report = extras.report;
  }
  m._rp_release_staged();
  return mesh;
}
