// Embedding: `?embed=1` shows the canvas, the step controls, the legend and a link to the full
// page; the drawing is read-only unless `&edit=1`. A host page drives it by postMessage:
//
//   host -> page  { type: 'ruppert:load', poly: '<.poly text>', id,
//                   options: { minAngle, maxArea, placement, algorithm, encroachment, maxSteiner } }
//                 { type: 'ruppert:step', index }     show the mesh after `index` steps (insertions or moves)
//                                                     (turns step mode on when it is off)
//   page -> host  { type: 'ruppert:meshed', id, stats: { vertices, triangles, minAngle, maxAngle, complete } }
//                 after every mesh (id: that of the load it answers, null for the page's own changes)
//                 { type: 'ruppert:stepped', index, total, vertices, triangles, event }
//                 after every step shown (event: the text of the step's event (an insertion or a move), or null
//                 at index 0)
//                 { type: 'ruppert:error', id, code, message }   a load, an option or a mesh failed
//
// Messages go to window.parent, which is the page itself when it is not in a frame (harmless:
// the page ignores its own replies). They carry only mesh statistics, so any origin may receive
// them ('*'); any origin may also send a drawing to show.

const params = () => new URLSearchParams(location.search);
export const isEmbedded = () => params().get('embed') === '1';
/** An embed is read-only unless the host asks for editing. */
export const isEditable = () => !isEmbedded() || params().get('edit') === '1';

function post(message) {
  try {
    window.parent.postMessage(message, '*');
  } catch {
    // A host that went away: nothing to tell.
  }
}

export function postMeshed(mesh, id = null) {
  const s = mesh.stats;
  post({
    type: 'ruppert:meshed',
    id,
    stats: { vertices: s.vertices, triangles: s.triangles, minAngle: s.minAngle, maxAngle: s.maxAngle, complete: mesh.complete },
  });
}

export function postStepped({ index, total, vertices, triangles, event }) {
  post({ type: 'ruppert:stepped', index, total, vertices, triangles, event });
}

export function postError(error, id = null) {
  post({ type: 'ruppert:error', id, code: error?.code ?? null, message: String(error?.message ?? error) });
}

const PLACEMENTS = ['offcenter', 'circumcenter', 'petal', 'optimal'];
const ALGORITHMS = { cdt: 'cdt', box: 'box' };
const ENCROACHMENTS = ['lens', 'disk'];

/**
 * The drawing options a load message asks for, checked: { options } with only the keys given,
 * or { error } naming the first bad one.
 */
export function loadOptions(o) {
  if (o === undefined || o === null) return { options: {} };
  if (typeof o !== 'object') return { error: "'options' must be an object" };
  const options = {};
  const bad = (name, what) => ({ error: `options.${name} ${what}, got ${JSON.stringify(o[name])}` });
  for (const name of Object.keys(o)) {
    const value = o[name];
    switch (name) {
      case 'minAngle':
        if (typeof value !== 'number' || !(value >= 0 && value <= 60)) return bad(name, 'must be a number in [0, 60]');
        options.minAngle = value;
        break;
      case 'maxArea':
        if (value !== null && (typeof value !== 'number' || !(value >= 0) || value === Infinity)) return bad(name, 'must be a positive number or null');
        options.maxArea = value > 0 ? value : null;
        break;
      case 'placement':
        if (!PLACEMENTS.includes(value)) return bad(name, `must be one of ${PLACEMENTS.join(', ')}`);
        options.placement = value;
        break;
      case 'algorithm':
        if (!(value in ALGORITHMS)) return bad(name, "must be 'cdt' or 'box'");
        options.variant = ALGORITHMS[value];
        break;
      case 'encroachment':
        if (!ENCROACHMENTS.includes(value)) return bad(name, "must be 'lens' or 'disk'");
        options.encroachment = value;
        break;
      case 'maxSteiner':
        if (value !== null && !(Number.isInteger(value) && value >= 0)) return bad(name, 'must be a whole number >= 0 or null');
        options.maxSteiner = value;
        break;
      default:
        return { error: `unknown option '${name}' (known: minAngle, maxArea, placement, algorithm, encroachment, maxSteiner)` };
    }
  }
  return { options };
}

/**
 * Listens to a host: onLoad({ poly, options, id }) for each valid 'ruppert:load', onStep(index)
 * for each 'ruppert:step'. Invalid messages get a 'ruppert:error' reply.
 */
export function listenToHost({ onLoad, onStep }) {
  window.addEventListener('message', (event) => {
    const data = event.data;
    if (data === null || typeof data !== 'object') return;
    const id = data.id ?? null;
    if (data.type === 'ruppert:load') {
      if (typeof data.poly !== 'string') {
        postError({ code: 'MALFORMED_INPUT', message: "ruppert:load needs 'poly': the text of a .poly file" }, id);
        return;
      }
      const { options, error } = loadOptions(data.options);
      if (error) {
        postError({ code: 'INVALID_OPTION', message: `ruppert:load: ${error}` }, id);
        return;
      }
      onLoad({ poly: data.poly, options, id });
    } else if (data.type === 'ruppert:step') {
      if (!Number.isInteger(data.index) || data.index < 0) {
        postError({ code: 'INVALID_OPTION', message: `ruppert:step needs 'index', a whole number >= 0, got ${JSON.stringify(data.index)}` }, id);
        return;
      }
      onStep(data.index);
    }
  });
}
