// triangulate() through the wasm heap (see wasm/heap_triangulate.cpp): the checked input and the
// options are written straight into the staged vectors and table, the mesh (reasons and notices
// included) is read back from a table of (address, length) pairs and numbers. Without callbacks no
// embind call is made: the plain exports Module._rp_* cost no more than any wasm call. Only
// failures, traces and the CLI's texts go through embind objects. Every array handed out is a copy:
// a view into the heap would go stale when it grows.
//
// The tables' layouts are the binding's (wasm/heap_layout.h, read through readDescription()): a list
// of fields per table, "name:type" for an array and "name" for a number, in the table's order.
import { readDescription } from './describe.js';

const TYPES = { f64: Float64Array, u32: Uint32Array, i32: Int32Array, u8: Uint8Array };
// Reasons' and notices' numbers and texts are read at once, before anything can grow the heap: views,
// not copies.
const READ_AS_VIEWS = new Set(['reasonNumbers', 'reasonText', 'noticeNumbers', 'noticeText']);

// { name, Type? } per field of each table, parsed once per instance.
const layouts = new WeakMap();
function layoutOf(m) {
  let layout = layouts.get(m);
  if (layout === undefined) {
    const parse = (fields) => fields.map((field) => {
      const [name, type] = field.split(':');
      const [group, key] = name.includes('.') ? name.split('.') : [null, name];
      return { name, group, key, Type: type === undefined ? undefined : TYPES[type], view: READ_AS_VIEWS.has(name) };
    });
    const { names, layout: tables } = readDescription(m);
    layout = { names };
    for (const [table, fields] of Object.entries(tables)) layout[table] = parse(fields);
    layouts.set(m, layout);
  }
  return layout;
}

// Fills an input table: arrays[name]'s values where the table holds an array's address (only when
// there are values), numbers[name] into a number's slot.
function writeTable(m, address, fields, arrays, numbers) {
  const table = address >>> 3;
  fields.forEach(({ name, Type }, i) => {
    if (Type === undefined) m.HEAPF64[table + i] = Number(numbers[name]);
    else if (arrays[name].length > 0) heapView(m, Type).set(arrays[name], m.HEAPF64[table + i] / Type.BYTES_PER_ELEMENT);
  });
}

// An output table's fields by name: arrays copied out (or, for READ_AS_VIEWS, a function that makes
// the view), numbers as they are. "stats.x" goes to fields.stats.x.
function readTable(m, address, fields) {
  const table = m.HEAPF64.subarray(address >>> 3);
  const out = {};
  let k = 0;
  for (const { group, key, Type, view } of fields) {
    let value;
    if (Type === undefined) {
      value = table[k++];
    } else {
      const start = table[k++] / Type.BYTES_PER_ELEMENT, length = table[k++];
      // A view is made only when there is something to read (most calls have no reasons or notices).
      if (view) value = () => heapView(m, Type).subarray(start, start + length);
      else value = length > 0 ? heapView(m, Type).slice(start, start + length) : new Type(0);
    }
    if (group === null) out[key] = value;
    else (out[group] ??= {})[key] = value;
  }
  return out;
}

// Issue 16, derived: the old mesh to refine, order and voronoi go in a table of their own
// (rp_stage_derived); what they give comes back in another (rp_derived_table).
function stageDerived(m, layout, input, options) {
  const lengths = layout.derivedInput.filter((f) => f.Type).map(({ name }) => input[name].length);
  const table = m._rp_stage_derived(...lengths, options.order, options.voronoi ? 1 : 0);
  if (table === 0) return false;
  writeTable(m, table, layout.derivedInput, input, options);
  return true;
}

// mesh.triangles6 (order 2; mesh.points already holds the midpoint nodes) and mesh.voronoi.
function readDerived(m, layout, mesh, options) {
  const { triangles6, voronoi } = readTable(m, m._rp_derived_table(), layout.derivedOutput);
  if (options.order === 2) mesh.triangles6 = triangles6;
  if (options.voronoi) mesh.voronoi = voronoi;
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

// The messages of `count` items, when there are any.
const textsFromHeap = (count, bytes) => (count > 0 ? utf8.decode(bytes()).split('\0') : []);

// One object literal per item (its shape fixed, so building 10^5 of them stays cheap; a kind number
// is made a small integer before it indexes an array, which a double key would make a slow lookup).
// `kinds` are the core's names of the kinds, in enum order.
function reasonsFromHeap(count, numberView, bytes, kinds) {
  const numbers = count > 0 ? numberView() : null;
  const messages = textsFromHeap(count, bytes);
  const reasons = [];
  for (let i = 0; i < count; i++) reasons.push({ kind: kinds[numbers[2 * i] | 0], count: numbers[2 * i + 1], message: messages[i] });
  return reasons;
}

function noticesFromHeap(count, numberView, bytes, kinds) {
  const numbers = count > 0 ? numberView() : null;
  const messages = textsFromHeap(count, bytes);
  const notices = [];
  for (let i = 0, k = 0; i < count; i++, k += 5) {
    notices.push({
      kind: kinds[numbers[k] | 0], a: numbers[k + 1], b: numbers[k + 2], x: numbers[k + 3], y: numbers[k + 4],
      message: messages[i],
    });
  }
  return notices;
}

function readMesh(m, layout, options) {
  const f = readTable(m, m._rp_output_table(), layout.output);
  const { names } = layout;
  const mesh = {
    points: f.points, triangles: f.triangles, neighbors: f.neighbors, segments: f.segments,
    segmentIds: f.segmentIds, vertexKinds: f.vertexKinds, triangleAttributes: f.triangleAttributes,
    pointMarkers: f.pointMarkers, segmentMarkers: f.segmentMarkers,
    pointAttributes: f.pointAttributes, attributesPerPoint: f.attributesPerPoint, indexBase: f.indexBase,
    complete: f.complete === 1,
    reasons: reasonsFromHeap(f.reasonCount, f.reasonNumbers, f.reasonText, names.reasons),
    notices: noticesFromHeap(f.noticeCount, f.noticeNumbers, f.noticeText, names.notices),
    stats: f.stats,
  };
  // (f.eventCount: events come with the extras when traced.)
  if (options.edges) mesh.edges = f.edges, mesh.edgeMarkers = f.edgeMarkers;
  if (options.jettison) mesh.inputToOutput = f.inputToOutput;
  return mesh;
}

/**
 * @param {object} m the Emscripten module
 * @param {object} input checkPlc()'s result (wasm/input-checks.js)
 * @param {object} options checkOptions()'s result with the callbacks wrapped
 * @param {object|null} report for wasm/cli.js: { summary, stats, trace } booleans
 * @returns the mesh object, or a failure { errorCode, errorMessage, reset? }
 */
export function triangulateInHeap(m, input, options, report) {
  const layout = layoutOf(m);
  const lengths = layout.input.filter((f) => f.Type).map(({ name }) => input[name].length);
  const inputTable = m._rp_stage_input(...lengths, input.indexBase, input.attributesPerPoint);
  if (inputTable === 0) {
    return { errorCode: 'TOO_LARGE', errorMessage: 'out of memory: the input does not fit in 4 GB of WebAssembly memory', reset: true };
  }
  writeTable(m, inputTable, layout.input, input, options);
  if (!stageDerived(m, layout, input, options)) {
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
  const mesh = readMesh(m, layout, options);
  readDerived(m, layout, mesh, options);
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
