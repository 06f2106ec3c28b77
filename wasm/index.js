// ruppert: 2D quality triangle meshing (Ruppert's Delaunay refinement) compiled to WebAssembly.
//
//   import { init } from 'ruppert';
//   const mesher = await init();
//   const mesh = mesher.triangulate({ points, segments }, { minAngle: 30, maxArea: 0.01 });
//
// Results are plain objects of typed arrays owned by JavaScript: nothing to free, nothing that
// goes stale when the wasm heap grows. See index.d.ts for every field.
import { NAMES } from './dist/names.js';
import { MeshError, ERROR_CODES } from './errors.js';
import { rejectUnknownKeys } from './input-checks.js';
import { MODULES, instanceHost } from './loader.js';
import { createMesher } from './mesher.js';

export { MeshError, ERROR_CODES };
export { createMeshWorker } from './mesh-worker.js';

// { NAME: value } of one of the core's enums, from its names in enum order.
const enumObject = (names) => Object.freeze(Object.fromEntries(names.map((name, value) => [name, value])));

/**
 * VertexKind values in mesh.vertexKinds (ruppert::VertexKind): INPUT 0, SEGMENT_SPLIT 1, INTERIOR 2,
 * OFF_CENTER 3, INTERSECTION 4, UNUSED 5.
 */
export const VertexKind = enumObject(NAMES.vertexKinds);
/**
 * EventKind values in mesh.events.kind (ruppert::EventKind): SEGMENT_SPLIT 0, CIRCUMCENTER 1,
 * OFF_CENTER 2, REJECTED 3, and the point placement 'petal' or 'optimal' chose instead of the
 * off-center (never rejected): PETAL_POINT 4, OPTIMAL_POINT 5; and RELOCATED 6, a free vertex the
 * 'optimal' placement moved (no vertex added; it uses one unit of maxSteiner, as an insertion does).
 */
export const EventKind = enumObject(NAMES.events);
/** mesh.neighbors entry for an edge on the domain boundary. */
export const NO_NEIGHBOR = -1;
/** mesh.segmentIds entry for a convex-hull edge that no input segment covers. */
export const NO_INPUT_SEGMENT = -1;

const INIT_KEYS = ['wasmUrl', 'locateFile', 'wasmBinary', 'wasmModule', 'formats'];
const SOURCE_KEYS = ['wasmUrl', 'wasmBinary', 'wasmModule'];
const invalidOption = (message) => new MeshError('INVALID_OPTION', message);

let defaultMesher = null;  // Promise of the mesher for init() without options: loaded once
let lastMesher = null;     // the most recent mesher, used by the top-level helpers below

// `file` in the folder of `url` (resolved against the page), or undefined where `url` does not resolve
// (a relative path under Node, which has no page): then the package's own copy is used.
function besideUrl(url, file) {
  try {
    return new URL(file, new URL(url, globalThis.location?.href));
  } catch {
    return undefined;
  }
}

// Where the text formats module comes from: options.formats' own source if it names one, else
// locateFile's answer, else beside the mesher's wasmUrl, else where the package keeps it. null: none.
function formatsSource(options) {
  const { formats = true } = options;
  if (formats === false) return null;
  if (formats === true) {
    const source = { locateFile: options.locateFile };
    if (options.wasmUrl !== undefined && typeof options.locateFile !== 'function') {
      source.fallbackUrl = besideUrl(options.wasmUrl, MODULES.formats.file);
    }
    return source;
  }
  if (formats === null || typeof formats !== 'object') {
    throw invalidOption(`init(options): formats must be true, false or { ${SOURCE_KEYS.join(', ')} }, got ${typeof formats === 'string' ? JSON.stringify(formats) : String(formats)}`);
  }
  rejectUnknownKeys(formats, SOURCE_KEYS, 'init(options).formats', invalidOption);
  return { locateFile: options.locateFile, ...formats };
}

async function build(options) {
  const formats = formatsSource(options);
  const { fallbackUrl, ...formatsOptions } = formats ?? {};
  // Both modules load at once; the mesher's failure is the one reported when both fail.
  const mesherHost = instanceHost(options, MODULES.mesher);
  const formatsHost = formats === null ? Promise.resolve(null) : instanceHost(formatsOptions, MODULES.formats, fallbackUrl);
  formatsHost.catch(() => {});
  const mesher = createMesher(await mesherHost, await formatsHost);
  lastMesher = mesher;
  return mesher;
}

/**
 * Loads the WebAssembly modules: the mesher (ruppert.wasm) and, unless `formats: false`, the text
 * formats (ruppert-formats.wasm: parsePoly, toVtu and the other readers and writers). Without
 * options they are loaded once and every call resolves to the same mesher.
 * @param {{ wasmUrl?: string | URL, locateFile?: (file: string) => string,
 *           wasmBinary?: ArrayBuffer | ArrayBufferView, wasmModule?: WebAssembly.Module,
 *           formats?: boolean | { wasmUrl?: string | URL, wasmBinary?: ArrayBuffer | ArrayBufferView,
 *                                 wasmModule?: WebAssembly.Module } }} [options]
 */
export function init(options) {
  if (options !== undefined && (options === null || typeof options !== 'object')) {
    return Promise.reject(new MeshError('MALFORMED_INPUT', 'init(options): options must be an object'));
  }
  try {
    if (options !== undefined) rejectUnknownKeys(options, INIT_KEYS, 'init(options)', invalidOption);
  } catch (error) {
    return Promise.reject(error);
  }
  if (options === undefined || Object.keys(options).length === 0) {
    if (defaultMesher === null) {
      defaultMesher = build({});
      defaultMesher.catch(() => { defaultMesher = null; });  // a failed load may be retried
    }
    return defaultMesher;
  }
  return build(options);
}

function loaded(name) {
  if (lastMesher === null) throw new Error(`ruppert: call \`await init()\` before ${name}()`);
  return lastMesher;
}

/**
 * Reads Triangle's .poly text into a PLC (needs a prior `await init()`). The second argument is a
 * name for messages, or { name, node, nodeName } with `node` the text of the .node file that holds
 * the points of a .poly declaring 0 points.
 */
export const parsePoly = (text, options) => loaded('parsePoly').parsePoly(text, options);
/** Reads Triangle's .node text into a PLC without segments. */
export const parseNode = (text, name) => loaded('parseNode').parseNode(text, name);
/** Reads the JSON input format into a PLC. */
export const parseJson = (text, name) => loaded('parseJson').parseJson(text, name);
/** Triangle's .poly text of a mesh's subsegments, with the input's holes and regions. */
export const toPoly = (mesh, input) => loaded('toPoly').toPoly(mesh, input);
/** Triangle's .node text of a mesh's vertices. */
export const toNode = (mesh) => loaded('toNode').toNode(mesh);
/** Triangle's .ele text of a mesh's triangles. */
export const toEle = (mesh) => loaded('toEle').toEle(mesh);
/** Triangle's .edge text: every edge of a mesh once, with its boundary marker. */
export const toEdge = (mesh) => loaded('toEdge').toEdge(mesh);
/** JSON text of a mesh (the input format plus triangles etc.). */
export const toJson = (mesh, input) => loaded('toJson').toJson(mesh, input);
/** SVG text drawing a mesh. */
export const toSvg = (mesh) => loaded('toSvg').toSvg(mesh);
/** Reads GeoJSON polygons (Polygon, MultiPolygon, Feature, FeatureCollection) into a PLC with hole seeds. */
export const parseGeoJson = (text, name) => loaded('parseGeoJson').parseGeoJson(text, name);
/** Gmsh MSH 4.1 text: triangles, subsegment lines, physical groups from markers and region attributes. */
export const toMsh = (mesh, input) => loaded('toMsh').toMsh(mesh, input);
/**
 * VTK XML UnstructuredGrid (.vtu) text with vertex kinds, markers, region attributes and smallest
 * angles; { segmentCells: true } adds the subsegments as line cells with their markers.
 */
export const toVtu = (mesh, options) => loaded('toVtu').toVtu(mesh, options);
/** GeoJSON FeatureCollection text: one Polygon feature per triangle. */
export const toGeoJson = (mesh) => loaded('toGeoJson').toGeoJson(mesh);
/** Triangle's .ele text with { node, poly?, area? } texts: a PLC with triangles to refine. */
export const parseEle = (text, options) => loaded('parseEle').parseEle(text, options);
/** Triangle's .v.node text of mesh.voronoi. */
export const toVoronoiNode = (mesh) => loaded('toVoronoiNode').toVoronoiNode(mesh);
/** Triangle's .v.edge text of mesh.voronoi. */
export const toVoronoiEdge = (mesh) => loaded('toVoronoiEdge').toVoronoiEdge(mesh);
