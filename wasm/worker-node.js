// Node side of createMeshWorker(): a worker_threads worker (see mesh-worker.js for the messages).
import { parentPort } from 'node:worker_threads';
import { init } from './node.js';
import { meshRequestHandler } from './mesh-worker.js';

const handle = meshRequestHandler(init, (data, transfer = []) => parentPort.postMessage(data, transfer));
parentPort.on('message', (data) => { handle(data); });
