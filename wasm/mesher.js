// The object init() resolves to: triangulate(), the readers and writers, over the mesher's and the
// text formats' wasm instances (loader.js's instance hosts replace an instance after an abort).
//
// Every binding returns a plain object; a failure is { errorCode, errorMessage, reset? } and
// becomes a MeshError here.
import { MeshError } from './errors.js';
import { triangulateInHeap } from './heap-call.js';
import { checkMesh, checkOptions, checkPlc, rejectUnknownKeys } from './input-checks.js';

// The binding's name -> what the user called, for the message of a mesher without formats.
const PUBLIC_NAMES = { readPlc: 'parsePoly, parseNode and parseJson', readPolyWithNode: 'parsePoly',
  writeMesh: 'the to*() writers', readMeshFiles: 'parseEle', writeVoronoi: 'toVoronoiNode and toVoronoiEdge',
  parseCliArgs: 'the CLI' };

function describeReturn(value) {
  if (typeof value === 'string') return JSON.stringify(value);
  if (value === null || typeof value !== 'object') return String(value);
  return Array.isArray(value) ? 'an array' : 'an object';
}

function requireText(text, what) {
  if (typeof text !== 'string') {
    throw new MeshError('MALFORMED_INPUT', `${what} expects the file's text as a string, got ${describeReturn(text)}`);
  }
}

/**
 * @param {object} mesher the mesher module's instance host (loader.js): triangulate(), GeoJSON
 * @param {object | null} formats the text formats module's host, or null (init({ formats: false }));
 *   the same host as `mesher` for wasm/cli.js's module, which holds both
 * @param {boolean} [cli] add what wasm/cli.js uses (its module holds the CLI's parser and texts)
 */
export function createMesher(mesher, formats, cli = false) {
  // The readers and writers other than GeoJSON's (wasm/binding/geojson_reader.cpp) are in `formats`.
  function call(name, ...args) {
    if (formats === null) {
      throw new MeshError('INVALID_OPTION', `this mesher was made with init({ formats: false }), which loads no text formats: ` +
        `call init() (or init({ formats: { wasmUrl } })) for ${PUBLIC_NAMES[name] ?? name}`);
    }
    return formats.call(name, ...args);
  }

  function check(result) {
    if (result.errorCode) throw new MeshError(result.errorCode, result.errorMessage);
    return result;
  }

  function triangulate(plc, options, report = null) {
    const input = checkPlc(plc);
    const opts = checkOptions(options);
    // The wrappers never throw into wasm (that would skip the core's destructors): they keep the
    // first error and tell the binding to unwind (NaN / -1), and we rethrow it below.
    let callbackError = null;
    // checkOptions' result is this call's own object: the callbacks' wrappers replace the user's in it.
    const native = opts;
    if (opts.sizeFunction) {
      const user = opts.sizeFunction;
      native.sizeFunction = (x, y) => {
        try {
          const area = user(x, y);
          if (typeof area === 'number' && !Number.isNaN(area)) return area;
          callbackError = new MeshError('INVALID_OPTION',
            `sizeFunction(${x}, ${y}) returned ${describeReturn(area)}: return a number (<= 0 or Infinity: no bound)`);
        } catch (error) {
          callbackError = error;
        }
        return NaN;
      };
    }
    if (opts.onProgress) {
      const user = opts.onProgress;
      native.onProgress = (insertedVertices, triangles, worstAngle) => {
        try {
          return user({ insertedVertices, triangles, worstAngle }) === false ? 0 : 1;
        } catch (error) {
          callbackError = error;
          return -1;
        }
      };
    }
    const result = mesher.run('triangulate', (m) => triangulateInHeap(m, input, native, report));
    if (result.errorCode === 'CALLBACK_FAILED') {
      throw callbackError ?? new MeshError('INTERNAL', 'a callback failed without an error');
    }
    return check(result);
  }

  function read(text, format, name, what) {
    requireText(text, what);
    if (typeof name !== 'string') throw new MeshError('MALFORMED_INPUT', `${what}: name must be a string`);
    if (format === 'geojson') return check(mesher.call('readGeoJson', text, name)).plc;
    return check(call('readPlc', text, format, name)).plc;
  }

  // parsePoly(text, name) or parsePoly(text, { name, node, nodeName }): `node` is the text of the
  // .node file that holds the points of a .poly declaring 0 points (Triangle's split form).
  function readPoly(text, options = '<poly>') {
    if (typeof options === 'string') return read(text, 'poly', options, 'parsePoly');
    if (options === null || typeof options !== 'object') {
      throw new MeshError('MALFORMED_INPUT', 'parsePoly(text, options): options must be a name or { name, node, nodeName }');
    }
    rejectUnknownKeys(options, ['name', 'node', 'nodeName'], 'parsePoly\'s options',
      (message) => new MeshError('INVALID_OPTION', message));
    const { name = '<poly>', node, nodeName = '<node>' } = options;
    if (node === undefined) return read(text, 'poly', name, 'parsePoly');
    requireText(text, 'parsePoly');
    requireText(node, 'parsePoly\'s options.node');
    if (typeof name !== 'string' || typeof nodeName !== 'string') {
      throw new MeshError('MALFORMED_INPUT', 'parsePoly: name and nodeName must be strings');
    }
    return check(call('readPolyWithNode', text, name, node, nodeName)).plc;
  }

  function write(mesh, input, format, segmentCells = false) {
    const checked = checkMesh(mesh);
    const plc = input == null ? null : checkPlc(input);
    return check(call('writeMesh', checked, plc, format, segmentCells)).text;
  }

  // toVtu's options: { segmentCells } (core's VtuOptions), each checked.
  function vtuSegmentCells(options) {
    if (options === undefined || options === null) return false;
    const fail = (message) => new MeshError('INVALID_OPTION', message);
    if (typeof options !== 'object') throw fail(`toVtu(mesh, options): options must be an object, got ${typeof options}`);
    rejectUnknownKeys(options, ['segmentCells'], 'toVtu\'s options', fail);
    const { segmentCells = false } = options;
    if (typeof segmentCells !== 'boolean') throw fail(`toVtu's options.segmentCells must be true or false, got ${JSON.stringify(segmentCells)}`);
    return segmentCells;
  }

  // Refining a mesh: Triangle's .ele text with { node, poly?, area?, names } texts.
  function readEle(text, options) {
    requireText(text, 'parseEle');
    if (options === null || typeof options !== 'object') {
      throw new MeshError('MALFORMED_INPUT', 'parseEle(eleText, { node, poly?, area? }): the .node text is needed');
    }
    rejectUnknownKeys(options, ['name', 'node', 'nodeName', 'poly', 'polyName', 'area', 'areaName'],
      'parseEle\'s options', (message) => new MeshError('INVALID_OPTION', message));
    const { name = '<ele>', node, nodeName = '<node>', poly, polyName = '<poly>', area, areaName = '<area>' } = options;
    requireText(node, 'parseEle\'s options.node');
    if (poly !== undefined) requireText(poly, 'parseEle\'s options.poly');
    if (area !== undefined) requireText(area, 'parseEle\'s options.area');
    for (const n of [name, nodeName, polyName, areaName]) {
      if (typeof n !== 'string') throw new MeshError('MALFORMED_INPUT', 'parseEle: file names must be strings');
    }
    return check(call('readMeshFiles', { ele: text, eleName: name, node, nodeName, poly, polyName, area, areaName })).plc;
  }

  // Voronoi: Triangle's .v.node / .v.edge texts of mesh.voronoi (triangulate with voronoi: true).
  function writeVoronoi(mesh, which) {
    if (mesh === null || typeof mesh !== 'object' || mesh.voronoi == null || typeof mesh.voronoi !== 'object') {
      throw new MeshError('MALFORMED_INPUT', 'expected a mesh with mesh.voronoi (triangulate with { voronoi: true })');
    }
    const indexBase = mesh.indexBase === 1 ? 1 : 0;
    return check(call('writeVoronoi', mesh.voronoi, indexBase, which)).text;
  }

  const forCli = cli ? {
    /** For wasm/cli.js: also returns mesh.report = { summary?, stats?, trace? } (the native CLI's texts). */
    _triangulateWithReport: (plc, options, report) => triangulate(plc, options, report),
    /** For wasm/cli.js: the native CLI's argument parser. */
    _parseCliArgs: (args) => check(call('parseCliArgs', args)),
  } : {};
  return {
    ...forCli,
    parseEle: (text, options) => readEle(text, options),
    toVoronoiNode: (mesh) => writeVoronoi(mesh, 'node'),
    toVoronoiEdge: (mesh) => writeVoronoi(mesh, 'edge'),
    triangulate: (plc, options) => triangulate(plc, options),
    parsePoly: (text, options) => readPoly(text, options),
    parseNode: (text, name = '<node>') => read(text, 'node', name, 'parseNode'),
    parseJson: (text, name = '<json>') => read(text, 'json', name, 'parseJson'),
    toNode: (mesh) => write(mesh, null, 'node'),
    toEle: (mesh) => write(mesh, null, 'ele'),
    toEdge: (mesh) => write(mesh, null, 'edge'),
    toPoly: (mesh, input) => write(mesh, input, 'poly'),
    toJson: (mesh, input) => write(mesh, input, 'json'),
    toSvg: (mesh) => write(mesh, null, 'svg'),
    parseGeoJson: (text, name = '<geojson>') => read(text, 'geojson', name, 'parseGeoJson'),
    toMsh: (mesh, input) => write(mesh, input, 'msh'),
    toVtu: (mesh, options) => write(mesh, null, 'vtu', vtuSegmentCells(options)),
    toGeoJson: (mesh) => write(mesh, null, 'geojson'),
    /** Whether the text formats are loaded (init() without formats: false). */
    hasFormats: formats !== null,
    /** Resolves once an instance is available (only ever pending right after an abort). */
    get ready() {
      return Promise.all([mesher.ready, formats?.ready]).then(() => {});
    },
    /** Size of the mesher's wasm heap and bytes currently allocated in it. */
    memoryUsage() {
      const m = mesher.current();
      return { heapBytes: m.HEAPU8.length, allocatedBytes: m.allocatedBytes() };
    },
    /** Test hook: aborts the current instance (as an out-of-memory abort would). */
    _abortForTesting() {
      return mesher.call('abortForTesting');
    },
  };
}
