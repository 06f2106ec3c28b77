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

// Per table, parsed once per instance: its fields in order ({ name, group, key, Type?, view }),
// the names of its arrays (an input table's lengths go to the binding in this order) and, for
// reading, each field's position by name.
const layouts = new WeakMap();
function layoutOf(m) {
  let layout = layouts.get(m);
  if (layout === undefined) {
    const parse = (list) => {
      const fields = list.map((field) => {
        // "name:type:heap": reasons' and notices' numbers and texts, read in place at once, before
        // anything can grow the heap (views, not copies).
        const [name, type, where] = field.split(':');
        const [group, key] = name.includes('.') ? name.split('.') : [null, name];
        return { name, group, key, Type: type === undefined ? undefined : TYPES[type], view: where === 'heap' };
      });
      const at = Object.fromEntries(fields.map((f, i) => [f.name, i]));
      // Per group ("stats", "voronoi"): its fields' positions and keys, for groupOf.
      const groups = {};
      fields.forEach((f, i) => { if (f.group !== null) (groups[f.group] ??= []).push([i, f.key]); });
      const arrays = fields.filter((f) => f.Type).map((f) => f.name);
      // An output table's last field, packedBytes (an array takes two slots there).
      return { fields, at, groups, arrays, packedSlot: fields.length + arrays.length - 1 };
    };
    const { names, layout: tables } = readDescription(m);
    layout = { names };
    for (const [table, list] of Object.entries(tables)) layout[table] = parse(list);
    layouts.set(m, layout);
  }
  return layout;
}

// The lengths of `arrays` in the input's order (the staging call's first arguments).
function lengthsOf(table, input) {
  const lengths = new Array(table.arrays.length);
  for (let i = 0; i < lengths.length; i++) lengths[i] = input[table.arrays[i]].length;
  return lengths;
}

// Fills an input table: arrays[name]'s values where the table holds an array's address (only when
// there are values), numbers[name] into a number's slot.
function writeTable(m, address, { fields }, arrays, numbers) {
  const heap = m.HEAPF64, table = address >>> 3;
  for (let i = 0; i < fields.length; i++) {
    const { name, Type } = fields[i];
    if (Type === undefined) heap[table + i] = Number(numbers[name]);
    else if (arrays[name].length > 0) heapView(m, Type).set(arrays[name], heap[table + i] / Type.BYTES_PER_ELEMENT);
  }
}

// An output table's values by position (layout's `at` names them): arrays copied out (or, for
// fields read in place, [start, length] in elements, for viewOf), numbers as they are. No object keyed
// by name: a call's fixed cost is most of a small mesh's.
//
// Every array of one table is a view into ONE new ArrayBuffer, each at an offset aligned to 8 bytes.
// Why: V8 gives each typed array over 64 bytes a backing store of its own, 1-5 us apiece in Node 20
// whatever its length, which was most of a small mesh's call; one buffer is one such allocation. A
// worker's transfer list then holds one buffer (mesh-worker.js collects buffers in a Set). The binding
// has packed the arrays into one block laid out as that buffer (packedBytes, heap_layout.h), so the
// buffer is one slice of the heap; a table too large to pack is copied array by array.
function readTable(m, address, { fields, packedSlot }) {
  const heap = m.HEAPF64, table = address >>> 3;
  const values = new Array(fields.length);
  const packedBytes = heap[table + packedSlot];
  let buffer, start = -1, bytes = packedBytes;
  if (packedBytes === 0) {
    for (let i = 0, k = table; i < fields.length; i++) {
      const { Type, view } = fields[i];
      if (Type === undefined) { k++; continue; }
      if (!view) bytes += (heap[k + 1] * Type.BYTES_PER_ELEMENT + 7) & ~7;
      k += 2;
    }
    buffer = new ArrayBuffer(bytes);
  }
  for (let i = 0, k = table, offset = 0; i < fields.length; i++) {
    const { Type, view } = fields[i];
    if (Type === undefined) {
      values[i] = heap[k++];
      continue;
    }
    const address = heap[k], length = heap[k + 1];
    k += 2;
    if (view) {
      values[i] = [address / Type.BYTES_PER_ELEMENT, length];
    } else if (packedBytes > 0) {
      if (start < 0) start = address, buffer = m.HEAPU8.slice(start, start + packedBytes).buffer;
      values[i] = new Type(buffer, address - start, length);
    } else {
      const copy = new Type(buffer, offset, length);
      if (length > 0) copy.set(heapView(m, Type).subarray(address / Type.BYTES_PER_ELEMENT, address / Type.BYTES_PER_ELEMENT + length));
      offset += (length * Type.BYTES_PER_ELEMENT + 7) & ~7;
      values[i] = copy;
    }
  }
  return values;
}

// A field read in place: its view, made only when there is something to read (most calls have no
// reasons or notices), before anything can grow the heap.
function viewOf(m, Type, [start, length]) {
  return heapView(m, Type).subarray(start, start + length);
}

// Fields "group.key" of a table as one object (mesh.stats).
function groupOf({ groups }, values, group) {
  const out = {};
  for (const [i, key] of groups[group] ?? []) out[key] = values[i];
  return out;
}

// Derived outputs: the old mesh to refine, order and voronoi go in a table of their own
// (rp_stage_derived); what they give comes back in another (rp_derived_table).
// A call that uses none of them skips the staging: the binding's release left the derived table
// empty and at order 1 without voronoi.
function stageDerived(m, layout, input, options) {
  if (input.triangles.length === 0 && input.triangleMaxArea.length === 0 && options.order !== 2 && !options.voronoi) {
    return true;
  }
  const table = m._rp_stage_derived(...lengthsOf(layout.derivedInput, input), options.order, options.voronoi ? 1 : 0);
  if (table === 0) return false;
  writeTable(m, table, layout.derivedInput, input, options);
  return true;
}

// mesh.triangles6 (order 2; mesh.points already holds the midpoint nodes) and mesh.voronoi.
function readDerived(m, layout, mesh, options) {
  if (options.order !== 2 && !options.voronoi) return;
  const table = layout.derivedOutput;
  const values = readTable(m, m._rp_derived_table(), table);
  if (options.order === 2) mesh.triangles6 = values[table.at.triangles6];
  if (options.voronoi) mesh.voronoi = groupOf(table, values, 'voronoi');
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

// The messages of `count` items, when there are any (`text` is a range read in place of UTF-8).
const textsFromHeap = (m, count, text) => (count > 0 ? utf8.decode(viewOf(m, Uint8Array, text)).split('\0') : []);

// One object literal per item (its shape fixed, so building 10^5 of them stays cheap; a kind number
// is made a small integer before it indexes an array, which a double key would make a slow lookup).
// `kinds` are the core's names of the kinds, in enum order; `numbers` and `text` ranges read in place.
function reasonsFromHeap(m, count, numberRange, text, kinds) {
  if (count === 0) return [];
  const numbers = viewOf(m, Float64Array, numberRange);
  const messages = textsFromHeap(m, count, text);
  const reasons = [];
  for (let i = 0; i < count; i++) reasons.push({ kind: kinds[numbers[2 * i] | 0], count: numbers[2 * i + 1], message: messages[i] });
  return reasons;
}

function noticesFromHeap(m, count, numberRange, text, kinds) {
  if (count === 0) return [];
  const numbers = viewOf(m, Float64Array, numberRange);
  const messages = textsFromHeap(m, count, text);
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
  const table = layout.output, { at } = table;
  const v = readTable(m, m._rp_output_table(), table);
  const { names } = layout;
  const mesh = {
    points: v[at.points], triangles: v[at.triangles], neighbors: v[at.neighbors], segments: v[at.segments],
    segmentIds: v[at.segmentIds], vertexKinds: v[at.vertexKinds], triangleAttributes: v[at.triangleAttributes],
    pointMarkers: v[at.pointMarkers], segmentMarkers: v[at.segmentMarkers],
    pointAttributes: v[at.pointAttributes], attributesPerPoint: v[at.attributesPerPoint], indexBase: v[at.indexBase],
    complete: v[at.complete] === 1,
    reasons: reasonsFromHeap(m, v[at.reasonCount], v[at.reasonNumbers], v[at.reasonText], names.reasons),
    notices: noticesFromHeap(m, v[at.noticeCount], v[at.noticeNumbers], v[at.noticeText], names.notices),
    stats: groupOf(table, v, 'stats'),
  };
  // (eventCount: events come with the extras when traced.)
  if (options.edges) mesh.edges = v[at.edges], mesh.edgeMarkers = v[at.edgeMarkers];
  if (options.jettison) mesh.inputToOutput = v[at.inputToOutput];
  if (options.exemptions) mesh.triangleExemptions = v[at.triangleExemptions];
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
  const inputTable = m._rp_stage_input(...lengthsOf(layout.input, input), input.indexBase, input.attributesPerPoint);
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
