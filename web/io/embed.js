// Embedding: `?embed=1` shows the canvas, the step controls, the legend and a link to the full
// page; the drawing is read-only unless `&edit=1`. A host page drives it by postMessage, protocol
// version PROTOCOL_VERSION (docs/course-site.md describes it for hosts):
//
//   page -> host  { type: 'ruppert:ready', version, packageVersion, presets, options }
//                 the first message, once, when the page can take messages (again, with the id,
//                 in answer to 'ruppert:hello')
//                 { type: 'ruppert:meshed', id, stats: { vertices, triangles, minAngle, maxAngle, complete } }
//                 exactly once per 'ruppert:load' and 'ruppert:preset' (id: theirs), and after the
//                 reader's own changes of the drawing (id: null); not when only the trace was added
//                 { type: 'ruppert:stepped', id, index, total, vertices, triangles, minAngle, maxAngle, event }
//                 after every step shown (id: that of the 'ruppert:step' that asked for it, else
//                 null; event: the text of the step's event, or null at index 0)
//                 { type: 'ruppert:mesh', id, points, triangles, segments, ... }   see meshMessage
//                 { type: 'ruppert:error', id, code, message }
//                 a message that is unknown or malformed, an unknown option or preset, a failed load or mesh
//   host -> page  { type: 'ruppert:load', id, poly: '<.poly text>', options }
//                 or { type: 'ruppert:load', id, json: '<.json text>', options }, the package's JSON
//                 input (curves included), e.g. the page's drawing .json
//                 options: the package's names (OPTION_NAMES); those not given take the package's
//                 defaults, whatever the page showed before
//                 { type: 'ruppert:preset', id, name }   a preset of presets.js by its id ('figure-6-4')
//                 { type: 'ruppert:step', id, index }    show the mesh after `index` steps (turns step mode on)
//                 { type: 'ruppert:getMesh', id }        the current mesh (once its meshing is done)
//                 { type: 'ruppert:hello', id }          answered by 'ruppert:ready'
//
// `id` is the host's: a string, a number or null (absent), echoed in the replies. Messages whose
// type does not start with 'ruppert:' belong to other scripts and are left alone; so are the
// page's own kinds of message (ready, meshed, ...), so that two pages never answer each other.
// Replies go to the message's sender, the page's own news to window.parent (the page itself when
// it is not in a frame: it ignores what it sent). They carry a drawing's mesh, nothing private, so
// any origin may receive them ('*'); any origin may also send a drawing to show.
import { DEFAULT_OPTIONS, MIN_ANGLE_RANGE, PACKAGE_OPTION_NAMES, SMOOTH_PASSES_RANGE } from '../model/drawing.js';
import { ENCROACHMENT_LABELS, PLACEMENT_LABELS, VARIANT_LABELS } from '../labels.js';

/** The protocol's version: a host checks `ready.version` against the one it was written for. */
export const PROTOCOL_VERSION = 1;

const params = () => new URLSearchParams(location.search);
export const isEmbedded = () => params().get('embed') === '1';
/** An embed is read-only unless the host asks for editing. */
export const isEditable = () => !isEmbedded() || params().get('edit') === '1';

/** The package's version, from the page's <meta name="ruppert-version"> (build-site.mjs sets it). */
export const packageVersion = () => document.querySelector('meta[name="ruppert-version"]')?.content || null;

function post(message, target = window.parent) {
  if (target === null) return;
  try {
    target.postMessage(message, '*');
  } catch {
    // A host that went away, or a value that cannot be cloned: nothing to tell.
  }
}

export function postReady({ presets, id, target } = {}) {
  post({
    type: 'ruppert:ready', ...(id !== undefined ? { id } : {}),
    version: PROTOCOL_VERSION, packageVersion: packageVersion(), presets, options: OPTION_NAMES,
  }, target);
}

export function postMeshed(mesh, id = null) {
  const s = mesh.stats;
  post({
    type: 'ruppert:meshed',
    id,
    stats: { vertices: s.vertices, triangles: s.triangles, minAngle: s.minAngle, maxAngle: s.maxAngle, complete: mesh.complete },
  });
}

export function postStepped({ id = null, index, total, vertices, triangles, minAngle, maxAngle, event }) {
  post({ type: 'ruppert:stepped', id, index, total, vertices, triangles, minAngle, maxAngle, event });
}

export function postError(error, id = null, target = window.parent) {
  post({ type: 'ruppert:error', id, code: error?.code ?? 'ERROR', message: String(error?.message ?? error) }, target);
}

/**
 * The 'ruppert:mesh' reply: the mesh's arrays as the package returns them (typed arrays; 0-based
 * indices), those a host may want to draw or to compute on, and its statistics.
 */
export function meshMessage(mesh, id) {
  const s = mesh.stats;
  const message = {
    type: 'ruppert:mesh',
    id,
    points: mesh.points,                          // x0, y0, x1, y1, ...
    triangles: mesh.triangles,                    // a0, b0, c0, ... counterclockwise
    segments: mesh.segments,                      // the subsegments: a0, b0, ...
    segmentMarkers: mesh.segmentMarkers,          // one per subsegment
    pointMarkers: mesh.pointMarkers,              // one per point
    triangleAttributes: mesh.triangleAttributes,  // one per triangle (its region's attribute)
    complete: mesh.complete,
    stats: { vertices: s.vertices, triangles: s.triangles, minAngle: s.minAngle, maxAngle: s.maxAngle },
  };
  if (mesh.attributesPerPoint > 0) {
    message.pointAttributes = mesh.pointAttributes;
    message.attributesPerPoint = mesh.attributesPerPoint;
  }
  return message;
}

export function postMesh(mesh, id, target) {
  post(meshMessage(mesh, id), target);
}

// The option names a load takes: the package's (TriangulateOptions of wasm/index.d.ts) that the
// page offers. `algorithm` is the name of protocol version 0 for `variant`, still accepted.
const { min, max } = MIN_ANGLE_RANGE;
const OPTION_CHECKS = {
  minAngle: (v) => (typeof v === 'number' && v >= min && v <= max ? null : `must be a number in [${min}, ${max}]`),
  // The package's own test (triangulate()'s): above 60 and below 180 degrees; 0 or null: none.
  maxAngle: (v) => (v === null || v === 0 || (typeof v === 'number' && v > 60 && v < 180) ? null
    : 'must be a number above 60 and below 180, or 0 or null for none'),
  smooth: (v) => (typeof v === 'boolean' || (Number.isInteger(v) && v >= SMOOTH_PASSES_RANGE.min && v <= SMOOTH_PASSES_RANGE.max) ? null
    : `must be true, false or a whole number of passes in [${SMOOTH_PASSES_RANGE.min}, ${SMOOTH_PASSES_RANGE.max}]`),
  maxArea: (v) => (v === null || (typeof v === 'number' && v >= 0 && v < Infinity) ? null : 'must be a number > 0, or 0 or null for none'),
  placement: (v) => oneOf(v, PLACEMENT_LABELS),
  variant: (v) => oneOf(v, VARIANT_LABELS),
  encroachment: (v) => oneOf(v, ENCROACHMENT_LABELS),
  maxSteiner: (v) => (v === null || (Number.isInteger(v) && v >= 0) ? null : 'must be a whole number >= 0, or null for automatic'),
};
export const OPTION_NAMES = Object.keys(OPTION_CHECKS);
const OLD_NAMES = { algorithm: 'variant' };
// The package's other options (and the worker's `signal`): a host may mean them, but the page does
// not offer them.
const PACKAGE_ONLY = [...PACKAGE_OPTION_NAMES.filter((name) => !(name in OPTION_CHECKS)), 'signal'];

function oneOf(value, labels) {
  const values = Object.keys(labels);
  return values.includes(value) ? null : `must be one of ${values.map((v) => `'${v}'`).join(', ')}`;
}

/**
 * The options of a load, checked: { options } (the package's defaults, with the given ones over
 * them, as the page's drawing options), or { error } naming the first unknown or bad one.
 */
export function loadOptions(given) {
  if (given === undefined || given === null) return { options: { ...DEFAULT_OPTIONS } };
  if (typeof given !== 'object' || Array.isArray(given)) return { error: "'options' must be an object" };
  const options = { ...DEFAULT_OPTIONS };
  for (const [key, value] of Object.entries(given)) {
    if (value === undefined) continue;  // as if not given
    const name = OLD_NAMES[key] ?? key;
    const check = OPTION_CHECKS[name];
    if (!check) {
      const why = PACKAGE_ONLY.includes(key) ? 'is an option of the package that the page does not offer'
        : 'is not an option';
      return { error: `unknown option '${key}': '${key}' ${why} (the options are ${OPTION_NAMES.join(', ')})` };
    }
    const bad = check(value);
    if (bad) return { error: `options.${key} ${bad}, got ${JSON.stringify(value)}` };
    options[name] = (name === 'maxArea' || name === 'maxAngle') && !(value > 0) ? null : value;
  }
  return { options };
}

// The fields each message may carry (beyond type and id), and whether they are required.
const MESSAGES = {
  'ruppert:load': { poly: false, json: false, options: false },
  'ruppert:preset': { name: true },
  'ruppert:step': { index: true },
  'ruppert:getMesh': {},
  'ruppert:hello': {},
};
// What the page sends: never answered, whoever sends it.
const OWN_MESSAGES = ['ruppert:ready', 'ruppert:meshed', 'ruppert:stepped', 'ruppert:mesh', 'ruppert:error'];

/** Why a message to the page cannot be taken, as { code, message }, or null when it can. */
export function checkMessage(data) {
  const type = data.type;
  const fields = MESSAGES[type];
  if (!fields) {
    return { code: 'UNKNOWN_MESSAGE', message: `unknown message type '${type}' (the page takes ${Object.keys(MESSAGES).join(', ')})` };
  }
  const malformed = (text) => ({ code: 'MALFORMED_MESSAGE', message: `${type}: ${text}` });
  if (data.id !== undefined && data.id !== null && typeof data.id !== 'string' && typeof data.id !== 'number') {
    return malformed(`'id' must be a string, a number or null, got ${typeof data.id}`);
  }
  for (const key of Object.keys(data)) {
    if (key !== 'type' && key !== 'id' && !(key in fields)) {
      const known = Object.keys(fields);
      return malformed(`unknown field '${key}' (the fields are type, id${known.length ? `, ${known.join(', ')}` : ''})`);
    }
  }
  for (const [key, required] of Object.entries(fields)) {
    if (required && data[key] === undefined) return malformed(`'${key}' is missing`);
  }
  if (type === 'ruppert:load') {
    if ((data.poly === undefined) === (data.json === undefined)) return malformed("give one of 'poly' (the text of a .poly file) and 'json' (the text of a .json input)");
    if (data.poly !== undefined && typeof data.poly !== 'string') return malformed("'poly' must be the text of a .poly file");
    if (data.json !== undefined && typeof data.json !== 'string') return malformed("'json' must be the text of a .json input");
  }
  if (type === 'ruppert:preset' && typeof data.name !== 'string') return malformed("'name' must be a preset's name, a string");
  if (type === 'ruppert:step' && !(Number.isInteger(data.index) && data.index >= 0)) {
    return { code: 'INVALID_OPTION', message: `ruppert:step needs 'index', a whole number >= 0, got ${JSON.stringify(data.index)}` };
  }
  return null;
}

/**
 * Listens to a host. Each valid message calls its handler with ({ ...message fields, id, source }):
 * onLoad({ poly, json, options, id }) (one of poly and json) with the options checked, onPreset({ name, id }), onStep({ index, id }),
 * onGetMesh({ id, source }), onHello({ id, source }). Anything else addressed to the page (a type
 * starting with 'ruppert:') gets a 'ruppert:error' reply.
 */
export function listenToHost({ onLoad, onPreset, onStep, onGetMesh, onHello }) {
  window.addEventListener('message', (event) => {
    const data = event.data;
    const source = event.source ?? window.parent;
    if (typeof data === 'string' && data.startsWith('ruppert:')) {
      postError({ code: 'MALFORMED_MESSAGE', message: `a message must be an object { type: '${data}', ... }, not a string` }, null, source);
      return;
    }
    if (data === null || typeof data !== 'object' || typeof data.type !== 'string' || !data.type.startsWith('ruppert:')) return;
    if (OWN_MESSAGES.includes(data.type)) return;
    const id = typeof data.id === 'string' || typeof data.id === 'number' ? data.id : null;
    const problem = checkMessage(data);
    if (problem) {
      postError(problem, id, source);
      return;
    }
    switch (data.type) {
      case 'ruppert:load': {
        const { options, error } = loadOptions(data.options);
        if (error) postError({ code: 'INVALID_OPTION', message: `ruppert:load: ${error}` }, id, source);
        else onLoad({ poly: data.poly, json: data.json, options, id });
        break;
      }
      case 'ruppert:preset': onPreset({ name: data.name, id, source }); break;
      case 'ruppert:step': onStep({ index: data.index, id }); break;
      case 'ruppert:getMesh': onGetMesh({ id, source }); break;
      case 'ruppert:hello': onHello({ id, source }); break;
      default: break;
    }
  });
}
