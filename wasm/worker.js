// Browser side of createMeshWorker(): a module Web Worker (see mesh-worker.js for the messages).
// No top-level await and no Node code, so that bundlers can build it in any worker format;
// Node uses worker-node.js.
import { init } from './index.js';
import { meshRequestHandler } from './mesh-worker.js';

const handle = meshRequestHandler(init, (data, transfer = []) => self.postMessage(data, transfer));
// Listen synchronously, so no message can arrive before the listener exists.
self.addEventListener('message', (event) => { handle(event.data); });
