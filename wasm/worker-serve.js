// The request loop of createMeshWorker()'s worker, shared by the browser worker (worker.js) and the
// Node one (worker-node.js). It meshes one request at a time (triangulate is synchronous) and answers
//   { type: 'progress', id, progress }                       while refining
//   { type: 'result', id, mesh }    (buffers transferred)    on success
//   { type: 'error', id, error }    (serialised MeshError)   on failure
// Requests: { type: 'init', options } once, then { type: 'triangulate', id, plc, options, progress }.
import { serializeError } from './errors.js';
import { meshBuffers } from './mesh-transfer.js';

/**
 * @param {(options?: object) => Promise<object>} init the package's init()
 * @param {(data: object, transfer?: ArrayBuffer[]) => void} post sends a message to the client
 * @returns {(message: object) => Promise<void>} handles one message from the client
 */
export function meshRequestHandler(init, post) {
  let mesherPromise = null;
  // A worker only meshes: the text formats module stays unloaded.
  const initMesher = (options = {}) => init({ formats: false, ...options });
  return async function handle(message) {
    if (message.type === 'init') {
      mesherPromise = initMesher(message.options);
      mesherPromise.catch(() => {});  // reported with the first request
      return;
    }
    if (message.type !== 'triangulate') return;
    const { id } = message;
    try {
      const mesher = await (mesherPromise ??= initMesher());
      const options = { ...message.options };
      if (message.progress) {
        options.onProgress = (progress) => { post({ type: 'progress', id, progress }); };
      }
      const mesh = mesher.triangulate(message.plc, options);
      post({ type: 'result', id, mesh }, meshBuffers(mesh));
    } catch (error) {
      post({ type: 'error', id, error: serializeError(error) });
    }
  };
}
