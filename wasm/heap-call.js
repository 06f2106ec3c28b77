// triangulate() through the wasm heap (see wasm/binding/heap_triangulate.cpp): the checked input
// and the options are written straight into the staged vectors and table, the mesh (reasons and
// notices included) is read back from a table of (address, length) pairs and numbers. Without callbacks no
// embind call is made: the plain exports Module._rp_* cost no more than any wasm call. Only
// failures, traces and the CLI's texts go through embind objects. Every array handed out is a copy:
// a view into the heap would go stale when it grows.
//
// The tables' layouts are the binding's (wasm/binding/heap_layout.h, read through readDescription()):
// a list of fields per table, "name:type" for an array and "name" for a number, in the table's order.
//
// Imports nothing, so that wasm/build-wasm.mjs can use readDescription() before wasm/dist/names.js,
// which it writes from that description, exists.

const descriptions = new WeakMap();  // per instance: parsed once

/**
 * What the binding exports instead of JavaScript keeping copies (wasm/binding/describe.cpp): the
 * names of the core's enums, the options (ruppert-cli.wasm only) and the layout of the heap tables,
 * as one JSON text in the heap.
 * @param {object} m an instantiated Emscripten module of ruppert.wasm
 * @returns {{ names: Record<string, string[]>, options?: object[], layout: Record<string, string[]> }}
 */
export function readDescription(m) {
  let description = descriptions.get(m);
  if (description === undefined) {
    const start = m._rp_describe(), bytes = m.HEAPU8;
    const end = bytes.indexOf(0, start);
    description = JSON.parse(new TextDecoder().decode(bytes.subarray(start, end)));
    descriptions.set(m, description);
  }
  return description;
}

const TYPES = { f64: Float64Array, u32: Uint32Array, i32: Int32Array, u8: Uint8Array };

// Per table, parsed once per instance: its fields in order ({ name, group, key, Type?, view, slot,
// onlyWith }), the names of its arrays (an input table's lengths go to the binding in this order),
// each field's position by name (`at`) and its first double in the table (`slot`: an input table
// gives every field one, an output table an array two, its address and length).
const layouts = new WeakMap();
function layoutOf(m) {
  let layout = layouts.get(m);
  if (layout === undefined) {
    const { names, layout: tables } = readDescription(m);
    layout = { names };
    for (const [table, list] of Object.entries(tables)) layout[table] = parseTable(list, table === 'input' || table === 'derivedInput');
    layout.output.statsLiteral = sameKeys(layout.output.groups.stats, STATS_KEYS);
    layouts.set(m, layout);
  }
  return layout;
}

// Output arrays that a mesh has only with an option (readMesh leaves them out otherwise): no view is
// made for them.
const ONLY_WITH = { edges: 'edges', edgeMarkers: 'edges', inputToOutput: 'jettison', triangleExemptions: 'exemptions' };

function parseTable(list, isInput) {
  let slot = 0;
  const fields = list.map((field) => {
    // "name:type:heap": reasons' and notices' numbers and texts, read in place at once, before
    // anything can grow the heap (views, not copies).
    const [name, type, where] = field.split(':');
    const [group, key] = name.includes('.') ? name.split('.') : [null, name];
    const Type = type === undefined ? undefined : TYPES[type];
    const parsed = { name, group, key, Type, view: where === 'heap', slot, onlyWith: ONLY_WITH[name] ?? null };
    slot += isInput || Type === undefined ? 1 : 2;
    return parsed;
  });
  const at = {}, slots = {};
  fields.forEach((f, i) => { at[f.name] = i, slots[f.name] = f.slot; });
  // Per group ("stats", "voronoi"): its fields' positions and keys, for groupOf.
  const groups = {};
  fields.forEach((f, i) => { if (f.group !== null) (groups[f.group] ??= []).push([i, f.key]); });
  const arrays = fields.filter((f) => f.Type).map((f) => f.name);
  const indicesWhere = (keep) => fields.flatMap((f, i) => (keep(f) ? [i] : []));
  // An output table's last field, packedBytes.
  return { fields, at, slots, groups, arrays, packedSlot: slot - 1, arrayFields: indicesWhere((f) => f.Type !== undefined),
    numberFields: indicesWhere((f) => f.Type === undefined), stagingArgs: new Array(arrays.length + 2).fill(0) };
}

// The staging call's arguments: the lengths of the table's arrays in its order, then `first` and
// `second`, in an array kept per table (the call is synchronous; nothing else uses it meanwhile).
function stagingArguments(table, input, first, second) {
  const { arrays, stagingArgs: args } = table;
  let k = 0;
  // for-in visits the keys of checkPlc's object in its order, of which the table's arrays are a
  // subsequence; a property read by for-in's key is a fast load, one by a name from a list is not.
  for (const key in input) if (k < arrays.length && key === arrays[k]) args[k++] = input[key].length;
  for (; k < arrays.length; k++) args[k] = input[arrays[k]].length;
  args[k] = first, args[k + 1] = second;
  return args;
}

// Fills an input table: arrays[name]'s values where the table holds an array's address (only when
// there are values), numbers[name] into a number's slot. The objects' keys are visited in their own
// order (for-in, as stagingArguments), a field's value read by name only where that order differs
// from the table's.
function writeTable(m, address, table, arrays, numbers) {
  const heap = m.HEAPF64, t = address >>> 3, { fields, arrayFields, numberFields } = table;
  let a = 0, n = 0;
  for (const key in arrays) {
    if (a < arrayFields.length && key === fields[arrayFields[a]].name) writeArray(m, heap, t, fields, arrayFields[a++], arrays[key]);
  }
  for (; a < arrayFields.length; a++) writeArray(m, heap, t, fields, arrayFields[a], arrays[fields[arrayFields[a]].name]);
  for (const key in numbers) {
    if (n < numberFields.length && key === fields[numberFields[n]].name) heap[t + numberFields[n++]] = Number(numbers[key]);
  }
  for (; n < numberFields.length; n++) heap[t + numberFields[n]] = Number(numbers[fields[numberFields[n]].name]);
}

function writeArray(m, heap, t, fields, i, values) {
  if (values.length === 0) return;
  const Type = fields[i].Type;
  heapView(m, Type).set(values, heap[t + i] / Type.BYTES_PER_ELEMENT);
}

// An output table's arrays by position (layout's `at` names them), except those read in place and
// those `options` leave out of the mesh (ONLY_WITH); its numbers are read from the heap by slot.
//
// Every array of one table is a view into ONE new ArrayBuffer, each at an offset aligned to 8 bytes.
// Why: V8 gives each typed array over 64 bytes a backing store of its own, 1-5 us apiece in Node 20
// whatever its length, which was most of a small mesh's call; one buffer is one such allocation. A
// worker's transfer list then holds one buffer (mesh-worker.js collects buffers in a Set). The binding
// has packed the arrays into one block laid out as that buffer (packedBytes, heap_layout.h), so the
// buffer is one slice of the heap; a table too large to pack is copied array by array.
function readArrays(m, address, { fields, packedSlot }, options) {
  const heap = m.HEAPF64, table = address >>> 3;
  const arrays = new Array(fields.length);
  const packedBytes = heap[table + packedSlot];
  if (packedBytes > 0) {
    let buffer = null, start = 0;
    for (let i = 0; i < fields.length; i++) {
      const { Type, view, slot, onlyWith } = fields[i];
      if (Type === undefined || view) continue;
      const address = heap[table + slot];
      // The block starts with the first packed array, empty or not.
      if (buffer === null) start = address, buffer = m.HEAPU8.slice(start, start + packedBytes).buffer;
      if (onlyWith === null || options[onlyWith]) arrays[i] = viewOn(Type, buffer, address - start, heap[table + slot + 1]);
    }
    return arrays;
  }
  let bytes = 0;
  for (const { Type, view, slot } of fields) {
    if (Type !== undefined && !view) bytes += (heap[table + slot + 1] * Type.BYTES_PER_ELEMENT + 7) & ~7;
  }
  const buffer = new ArrayBuffer(bytes);
  for (let i = 0, offset = 0; i < fields.length; i++) {
    const { Type, view, slot } = fields[i];
    if (Type === undefined || view) continue;
    const address = heap[table + slot], length = heap[table + slot + 1];
    const copy = new Type(buffer, offset, length);
    if (length > 0) copy.set(heapView(m, Type).subarray(address / Type.BYTES_PER_ELEMENT, address / Type.BYTES_PER_ELEMENT + length));
    offset += (length * Type.BYTES_PER_ELEMENT + 7) & ~7;
    arrays[i] = copy;
  }
  return arrays;
}

// A field read in place (at double `slot` of the table at double `table`): its view, made only when
// there is something to read (most calls have no reasons or notices), before anything can grow the heap.
function viewOf(m, Type, table, slot) {
  const heap = m.HEAPF64, start = heap[table + slot] / Type.BYTES_PER_ELEMENT;
  return heapView(m, Type).subarray(start, start + heap[table + slot + 1]);
}

// Fields "group.key" of a table as one object (mesh.voronoi), numbers from the heap.
function groupOf(m, { groups, fields }, address, arrays, group) {
  const out = {}, heap = m.HEAPF64, table = address >>> 3;
  for (const [i, key] of groups[group] ?? []) out[key] = fields[i].Type === undefined ? heap[table + fields[i].slot] : arrays[i];
  return out;
}

// mesh.stats' keys in the binding's order. Built as one object literal when the binding's "stats."
// fields are exactly these (checked once per instance), since setting 15 keys by name one by one
// took eight times as long; any other list of fields goes through groupOf.
const STATS_KEYS = ['vertices', 'triangles', 'minAngle', 'maxAngle', 'angleHistogram', 'inputVertices',
  'segmentVertices', 'interiorVertices', 'offCenterVertices', 'intersectionVertices', 'rejectedCircumcenters',
  'lfsIntegral', 'trianglesPerLfsIntegral', 'milliseconds', 'reachedAngle'];

const sameKeys = (group, keys) => group !== undefined && group.length === keys.length && group.every(([, key], i) => key === keys[i]);

function statsOf(m, table, address, arrays) {
  if (!table.statsLiteral) return groupOf(m, table, address, arrays, 'stats');
  const heap = m.HEAPF64, t = address >>> 3, { slots } = table;
  return {
    vertices: heap[t + slots['stats.vertices']], triangles: heap[t + slots['stats.triangles']],
    minAngle: heap[t + slots['stats.minAngle']], maxAngle: heap[t + slots['stats.maxAngle']],
    angleHistogram: arrays[table.at['stats.angleHistogram']],
    inputVertices: heap[t + slots['stats.inputVertices']], segmentVertices: heap[t + slots['stats.segmentVertices']],
    interiorVertices: heap[t + slots['stats.interiorVertices']], offCenterVertices: heap[t + slots['stats.offCenterVertices']],
    intersectionVertices: heap[t + slots['stats.intersectionVertices']],
    rejectedCircumcenters: heap[t + slots['stats.rejectedCircumcenters']], lfsIntegral: heap[t + slots['stats.lfsIntegral']],
    trianglesPerLfsIntegral: heap[t + slots['stats.trianglesPerLfsIntegral']],
    milliseconds: heap[t + slots['stats.milliseconds']], reachedAngle: heap[t + slots['stats.reachedAngle']],
  };
}

// Derived outputs: the old mesh to refine, order and voronoi go in a table of their own
// (rp_stage_derived); what they give comes back in another (rp_derived_table).
// A call that uses none of them skips the staging: the binding's release left the derived table
// empty and at order 1 without voronoi.
function stageDerived(m, layout, input, options) {
  if (input.triangles.length === 0 && input.triangleMaxArea.length === 0 && options.order !== 2 && !options.voronoi) {
    return true;
  }
  const table = m._rp_stage_derived(...stagingArguments(layout.derivedInput, input, options.order, options.voronoi ? 1 : 0));
  if (table === 0) return false;
  writeTable(m, table, layout.derivedInput, input, options);
  return true;
}

// mesh.triangles6 (order 2; mesh.points already holds the midpoint nodes) and mesh.voronoi.
function readDerived(m, layout, mesh, options) {
  if (options.order !== 2 && !options.voronoi) return;
  const table = layout.derivedOutput, address = m._rp_derived_table();
  const arrays = readArrays(m, address, table, options);
  if (options.order === 2) mesh.triangles6 = arrays[table.at.triangles6];
  if (options.voronoi) mesh.voronoi = groupOf(m, table, address, arrays, 'voronoi');
}

// A typed array of `Type` over `buffer`, made by a constructor named at each site: one `new Type()`
// seeing four constructors took a third longer for a mesh's eleven views.
function viewOn(Type, buffer, offset, length) {
  switch (Type) {
    case Float64Array: return new Float64Array(buffer, offset, length);
    case Uint32Array: return new Uint32Array(buffer, offset, length);
    case Int32Array: return new Int32Array(buffer, offset, length);
    default: return new Uint8Array(buffer, offset, length);
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

// The messages of `count` items, when there are any (the UTF-8 text read in place, at `slot`).
const textsFromHeap = (m, count, table, slot) => (count > 0 ? utf8.decode(viewOf(m, Uint8Array, table, slot)).split('\0') : []);

// One object literal per item (its shape fixed, so building 10^5 of them stays cheap; a kind number
// is made a small integer before it indexes an array, which a double key would make a slow lookup).
// `kinds` are the core's names of the kinds, in enum order; the numbers (at `numberSlot`) and the
// texts (at `textSlot`) are read in place from the table at double `table`.
function reasonsFromHeap(m, count, table, numberSlot, textSlot, kinds) {
  if (count === 0) return [];
  const numbers = viewOf(m, Float64Array, table, numberSlot);
  const messages = textsFromHeap(m, count, table, textSlot);
  const reasons = [];
  for (let i = 0; i < count; i++) reasons.push({ kind: kinds[numbers[2 * i] | 0], count: numbers[2 * i + 1], message: messages[i] });
  return reasons;
}

function noticesFromHeap(m, count, table, numberSlot, textSlot, kinds) {
  if (count === 0) return [];
  const numbers = viewOf(m, Float64Array, table, numberSlot);
  const messages = textsFromHeap(m, count, table, textSlot);
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
  const table = layout.output, { at, slots } = table;
  const address = m._rp_output_table();
  const a = readArrays(m, address, table, options);
  const heap = m.HEAPF64, t = address >>> 3, { names } = layout;
  const mesh = {
    points: a[at.points], triangles: a[at.triangles], neighbors: a[at.neighbors], segments: a[at.segments],
    segmentIds: a[at.segmentIds], vertexKinds: a[at.vertexKinds], triangleAttributes: a[at.triangleAttributes],
    pointMarkers: a[at.pointMarkers], segmentMarkers: a[at.segmentMarkers],
    pointAttributes: a[at.pointAttributes], attributesPerPoint: heap[t + slots.attributesPerPoint],
    indexBase: heap[t + slots.indexBase], complete: heap[t + slots.complete] === 1,
    reasons: reasonsFromHeap(m, heap[t + slots.reasonCount], t, slots.reasonNumbers, slots.reasonText, names.reasons),
    notices: noticesFromHeap(m, heap[t + slots.noticeCount], t, slots.noticeNumbers, slots.noticeText, names.notices),
    stats: statsOf(m, table, address, a),
  };
  // (eventCount: events come with the extras when traced.)
  if (options.edges) mesh.edges = a[at.edges], mesh.edgeMarkers = a[at.edgeMarkers];
  if (options.jettison) mesh.inputToOutput = a[at.inputToOutput];
  if (options.exemptions) mesh.triangleExemptions = a[at.triangleExemptions];
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
  const inputTable = m._rp_stage_input(...stagingArguments(layout.input, input, input.indexBase, input.attributesPerPoint));
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
