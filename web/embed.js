// Embedding: `?embed=1` hides the chrome, and a host page talks to the page by postMessage.
//
//   host -> page  { type: 'ruppert:load', poly: '<.poly text>', options: { minAngle, maxArea } }
//   page -> host  { type: 'ruppert:meshed', stats: { vertices, triangles, minAngle, maxAngle, complete } }
//                 after every mesh, and { type: 'ruppert:error', code, message } when a load or a
//                 mesh fails.
//
// Messages go to window.parent, which is the page itself when it is not in a frame (harmless:
// the page ignores its own 'ruppert:meshed'). They carry only mesh statistics, so any origin may
// receive them ('*'); any origin may also send a drawing to show.

export const isEmbedded = () => new URLSearchParams(location.search).get('embed') === '1';

function post(message) {
  try {
    window.parent.postMessage(message, '*');
  } catch {
    // A host that went away: nothing to tell.
  }
}

export function postMeshed(mesh) {
  const s = mesh.stats;
  post({
    type: 'ruppert:meshed',
    stats: { vertices: s.vertices, triangles: s.triangles, minAngle: s.minAngle, maxAngle: s.maxAngle, complete: mesh.complete },
  });
}

export function postError(error) {
  post({ type: 'ruppert:error', code: error?.code ?? null, message: String(error?.message ?? error) });
}

/**
 * Calls onLoad({ poly, options }) for each valid 'ruppert:load' message.
 * @param {(request: { poly: string, options: { minAngle?: number, maxArea?: number } }) => void} onLoad
 */
export function listenForLoad(onLoad) {
  window.addEventListener('message', (event) => {
    const data = event.data;
    if (data === null || typeof data !== 'object' || data.type !== 'ruppert:load') return;
    if (typeof data.poly !== 'string') {
      postError({ code: 'MALFORMED_INPUT', message: "ruppert:load needs 'poly': the text of a .poly file" });
      return;
    }
    const options = {};
    const o = data.options ?? {};
    if (typeof o.minAngle === 'number' && Number.isFinite(o.minAngle)) options.minAngle = o.minAngle;
    if (typeof o.maxArea === 'number' && Number.isFinite(o.maxArea)) options.maxArea = o.maxArea;
    onLoad({ poly: data.poly, options });
  });
}
