// Worker side of createMeshWorker(): a module Web Worker in browsers, a worker_threads worker in
// Node. It meshes one request at a time (triangulate is synchronous) and answers with
//   { type: 'progress', id, progress }                       while refining
//   { type: 'result', id, mesh }    (buffers transferred)    on success
//   { type: 'error', id, error }    (serialised MeshError)   on failure
// Requests: { type: 'init', options } once, then { type: 'triangulate', id, plc, options, progress }.
import { init } from './index.js';
import { serializeError } from './errors.js';
import { meshBuffers } from './mesh-transfer.js';

let mesherPromise = null;
let post;

async function handle(message) {
  if (message.type === 'init') {
    mesherPromise = init(message.options ?? {});
    mesherPromise.catch(() => {});  // reported with the first request
    return;
  }
  if (message.type !== 'triangulate') return;
  const { id } = message;
  try {
    const mesher = await (mesherPromise ??= init());
    const options = { ...message.options };
    if (message.progress) {
      options.onProgress = (progress) => { post({ type: 'progress', id, progress }); };
    }
    const mesh = mesher.triangulate(message.plc, options);
    post({ type: 'result', id, mesh }, meshBuffers(mesh));
  } catch (error) {
    post({ type: 'error', id, error: serializeError(error) });
  }
}

// Browsers: listen synchronously, so no message can arrive before the listener exists.
if (typeof WorkerGlobalScope !== 'undefined' && typeof self !== 'undefined' && self instanceof WorkerGlobalScope) {
  post = (data, transfer = []) => self.postMessage(data, transfer);
  self.addEventListener('message', (event) => { handle(event.data); });
} else {
  // Node: a MessagePort queues messages until a listener is attached, so awaiting is safe here.
  const { parentPort } = await import(/* webpackIgnore: true */ /* @vite-ignore */ 'node:worker_threads');
  post = (data, transfer = []) => parentPort.postMessage(data, transfer);
  parentPort.on('message', (data) => { handle(data); });
}
