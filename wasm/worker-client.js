// createMeshWorker(): triangulate off the main thread.
//
// Cancellation is by termination: refinement is one synchronous wasm call, so the only prompt way
// to stop it is to end the worker. The cancelled request rejects with MeshError 'CANCELLED', and
// requests queued behind it are re-sent to a fresh worker.
import { MeshError, deserializeError } from './errors.js';
import { normalizeOptions, normalizePlc } from './validate.js';

const isNode = typeof process === 'object' && typeof process.versions === 'object' &&
  typeof process.versions.node === 'string' && typeof window === 'undefined';

// Browsers and bundlers: the literal `new Worker(new URL(...), { type: 'module' })` pattern.
function spawnBrowserWorker() {
  const worker = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
  return {
    post: (data) => worker.postMessage(data),
    onMessage: (fn) => worker.addEventListener('message', (event) => fn(event.data)),
    onFailure: (fn) => worker.addEventListener('error', (event) => {
      event.preventDefault();
      fn(new MeshError('INTERNAL', `mesh worker failed: ${event.message ?? 'error'}`));
    }),
    terminate: () => worker.terminate(),
    hold: () => {},
    release: () => {},
  };
}

async function spawnNodeWorker() {
  const { Worker } = await import(/* webpackIgnore: true */ /* @vite-ignore */ 'node:worker_threads');
  const worker = new Worker(new URL('./worker.js', import.meta.url));
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

/**
 * @param {{ wasmUrl?: string | URL, wasmBinary?: ArrayBuffer }} [loadOptions] passed to init() in the worker
 */
export function createMeshWorker(loadOptions = {}) {
  let worker = null;       // Promise of the current worker handle
  let nextId = 1;
  const jobs = new Map();  // id -> { request, resolve, reject, onProgress, cleanup }

  function settle(id) {
    const job = jobs.get(id);
    jobs.delete(id);
    job?.cleanup();
    return job;
  }

  function start() {
    const handlePromise = (isNode ? spawnNodeWorker() : Promise.resolve(spawnBrowserWorker())).then((handle) => {
      handle.onMessage((message) => {
        const job = jobs.get(message.id);
        if (job === undefined) return;
        if (message.type === 'progress') {
          job.onProgress?.(message.progress);
        } else if (message.type === 'result') {
          settle(message.id).resolve(message.mesh);
        } else if (message.type === 'error') {
          settle(message.id).reject(deserializeError(message.error));
        }
        if (jobs.size === 0) handle.release();
      });
      handle.onFailure((error) => {
        // A crashed worker takes its queue with it; the next request starts a new one.
        if (worker === handlePromise) worker = null;
        handle.terminate();
        for (const id of [...jobs.keys()]) settle(id).reject(error);
      });
      handle.post({ type: 'init', options: loadOptions });
      return handle;
    });
    return handlePromise;
  }

  async function send(id) {
    worker ??= start();
    const handle = await worker;
    const job = jobs.get(id);
    if (job === undefined) return;  // cancelled while the worker was starting
    handle.hold();
    handle.post(job.request);
  }

  function restartWith(cancelledId) {
    const old = worker;
    worker = null;
    old?.then((handle) => handle.terminate());
    settle(cancelledId);
    for (const id of jobs.keys()) send(id);
  }

  return {
    /**
     * @param {object} plc as for mesher.triangulate (no functions: they cannot cross to a worker)
     * @param {object} [options] as for mesher.triangulate, without sizeFunction/onProgress
     * @param {{ signal?: AbortSignal, onProgress?: (p: object) => void }} [control]
     */
    triangulate(plc, options = {}, control = {}) {
      try {
        // Check here so that mistakes surface with a stack trace in the caller's code.
        normalizePlc(plc);
        const opts = normalizeOptions(options);
        if (opts.sizeFunction || opts.onProgress) {
          throw new MeshError('INVALID_OPTION',
            'sizeFunction and onProgress cannot be sent to a worker: use maxArea/regions, and control.onProgress');
        }
      } catch (error) {
        return Promise.reject(error);
      }
      const { signal, onProgress } = control ?? {};
      const cancelled = () => new MeshError('CANCELLED', 'triangulation cancelled', { cause: signal?.reason });
      if (signal?.aborted) return Promise.reject(cancelled());

      const id = nextId++;
      return new Promise((resolve, reject) => {
        const onAbort = () => {
          if (!jobs.has(id)) return;
          jobs.get(id).reject(cancelled());
          restartWith(id);
        };
        signal?.addEventListener('abort', onAbort, { once: true });
        jobs.set(id, {
          request: { type: 'triangulate', id, plc, options, progress: typeof onProgress === 'function' },
          resolve,
          reject,
          onProgress,
          cleanup: () => signal?.removeEventListener('abort', onAbort),
        });
        send(id).catch((error) => {
          if (jobs.has(id)) settle(id).reject(error);
        });
      });
    },

    /** Ends the worker; pending requests reject with 'CANCELLED'. A later request starts a new one. */
    terminate() {
      const old = worker;
      worker = null;
      for (const id of [...jobs.keys()]) settle(id).reject(new MeshError('CANCELLED', 'mesh worker terminated'));
      return old ? old.then((handle) => handle.terminate()).then(() => {}) : Promise.resolve();
    },
  };
}
