// triangulate() through the wasm heap (see "triangulate() through the heap" in wasm/bindings.cpp):
// the normalised input is written straight into the staged vectors, the mesh is read back from a
// table of (address, length) pairs and scalars, and only reasons, notices, events and CLI texts go
// through embind objects (and only when there are any). Every array handed out is a copy: a view
// into the heap would go stale when it grows.

// In the order of the table written by triangulateStaged().
const ARRAYS = [
  ['points', Float64Array], ['triangles', Uint32Array], ['neighbors', Int32Array], ['segments', Uint32Array],
  ['segmentIds', Int32Array], ['vertexKinds', Uint8Array], ['triangleAttributes', Float64Array],
  ['pointMarkers', Int32Array], ['angleHistogram', Float64Array],
];
const STATS_BEFORE_HISTOGRAM = ['vertices', 'triangles', 'minAngle', 'maxAngle'];
const STATS_AFTER_HISTOGRAM = ['inputVertices', 'segmentVertices', 'interiorVertices', 'offCenterVertices',
  'intersectionVertices', 'rejectedCircumcenters', 'lfsIntegral', 'trianglesPerLfsIntegral', 'milliseconds', 'reachedAngle'];
const TABLE_SIZE = 2 * ARRAYS.length + 5 + STATS_BEFORE_HISTOGRAM.length + STATS_AFTER_HISTOGRAM.length;

const INPUTS = [
  ['points', Float64Array], ['segments', Uint32Array], ['holes', Float64Array], ['regions', Float64Array],
  ['pointMarkers', Int32Array], ['segmentMarkers', Int32Array],
];

/**
 * @param {object} m the Emscripten module
 * @param {object} input normalizePlc()'s result
 * @param {object} options normalizeOptions()'s result with the callbacks wrapped
 * @param {object|null} report for wasm/cli.js: { summary, stats, trace } booleans
 * @returns the mesh object, or a failure { errorCode, errorMessage, reset? }
 */
export function triangulateInHeap(m, input, options, report) {
  const lengths = INPUTS.map(([name]) => input[name].length);
  const inputTable = m.stageInput(...lengths, input.indexBase);
  if (inputTable === 0) {
    return { errorCode: 'TOO_LARGE', errorMessage: 'out of memory: the input does not fit in 4 GB of WebAssembly memory', reset: true };
  }
  // Views made after stageInput(): it may have grown the heap (a new buffer).
  const addresses = new Uint32Array(m.HEAPU8.buffer, inputTable, INPUTS.length);
  INPUTS.forEach(([name, Type], i) => {
    if (lengths[i] > 0) new Type(m.HEAPU8.buffer, addresses[i], lengths[i]).set(input[name]);
  });
  const failure = m.triangulateStaged(options);
  if (failure !== null) return failure;

  const table = new Float64Array(m.HEAPU8.buffer, m.outputTable(), TABLE_SIZE);
  const arrays = {};
  let k = 0;
  for (const [name, Type] of ARRAYS) {
    const address = table[k++], length = table[k++];
    arrays[name] = length > 0 ? new Type(m.HEAPU8.buffer, address, length).slice() : new Type(0);
  }
  const indexBase = table[k++], complete = table[k++] === 1;
  const reasonCount = table[k++], noticeCount = table[k++];
  k++;  // the event count: events come with the extras when traced
  const stats = {};
  for (const name of STATS_BEFORE_HISTOGRAM) stats[name] = table[k++];
  stats.angleHistogram = arrays.angleHistogram;
  for (const name of STATS_AFTER_HISTOGRAM) stats[name] = table[k++];

  const mesh = {
    points: arrays.points, triangles: arrays.triangles, neighbors: arrays.neighbors, segments: arrays.segments,
    segmentIds: arrays.segmentIds, vertexKinds: arrays.vertexKinds, triangleAttributes: arrays.triangleAttributes,
    pointMarkers: arrays.pointMarkers, indexBase, complete, reasons: [], notices: [], stats,
  };
  if (reasonCount > 0 || noticeCount > 0 || options.trace || report != null) {
    const extras = m.stagedExtras(report ?? null, options.trace);
    if (extras.errorCode) {
      m.releaseStaged();
      return extras;
    }
    mesh.reasons = extras.reasons;
    mesh.notices = extras.notices;
    if (options.trace) mesh.events = extras.events;
    if (report != null) mesh.report = extras.report;
  }
  m.releaseStaged();
  return mesh;
}
