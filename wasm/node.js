// The package's "node" export: the same API as index.js, plus what only Node can do (read the
// .wasm from a file: URL, run createMeshWorker() on worker_threads). Browser bundles resolve
// 'ruppert' to index.js and never see this file.
import { readFile } from 'node:fs/promises';
import { Worker } from 'node:worker_threads';
import { MeshError } from './errors.js';
import { registerNodeHost } from './loader.js';

function spawnWorker(workerUrl) {
  // worker_threads reads a string as a path: a 'file:' string is meant as a URL.
  const url = typeof workerUrl === 'string' && workerUrl.startsWith('file:') ? new URL(workerUrl) : workerUrl;
  const worker = new Worker(url ?? new URL('./worker-node.js', import.meta.url));
  let ended = false;
  return {
    post: (data) => worker.postMessage(data),
    onMessage: (fn) => worker.on('message', fn),
    onFailure: (fn) => {
      worker.on('error', (error) => fn(new MeshError('INTERNAL', `mesh worker failed: ${error.message}`, { cause: error })));
      worker.on('exit', (code) => { if (!ended) fn(new MeshError('INTERNAL', `mesh worker exited with code ${code}`)); });
    },
    terminate: () => { ended = true; return worker.terminate(); },
    // An idle worker must not keep a Node process alive.
    hold: () => worker.ref(),
    release: () => worker.unref(),
  };
}

registerNodeHost({ readFile, spawnWorker });

export * from './index.js';
