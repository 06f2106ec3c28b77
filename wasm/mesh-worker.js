// createMeshWorker(): triangulate off the main thread. Both sides are here: the client the page
// holds, and the request loop that the worker scripts run (worker.js in a browser, worker-node.js
// in Node), so that the messages between them are written in one place. The worker meshes one
// request at a time (triangulate is synchronous) and answers
//   { type: 'progress', id, progress }                       while refining
//   { type: 'result', id, mesh }    (buffers transferred)    on success
//   { type: 'error', id, error }    (serialised MeshError)   on failure
// Requests: { type: 'init', options } once, then { type: 'triangulate', id, plc, options, progress }.
//
// Cancellation is by termination: refinement is one synchronous wasm call, so the only prompt way
// to stop it is to end the worker. The cancelled request rejects with MeshError 'CANCELLED', and
// requests queued behind it are re-sent to a fresh worker.
import { MeshError } from './errors.js';
import { checkOptions, checkPlc, rejectUnknownKeys } from './input-checks.js';
import { absoluteUrl, classicScriptUrl, getNodeHost } from './loader.js';

// Workers post errors as plain objects (structured clone drops the class): the worker serialises
// them, the client rebuilds them.
function serializeError(error) {
  if (error instanceof MeshError) return { name: 'MeshError', code: error.code, message: error.message };
  const message = error instanceof Error ? error.message : String(error);
  return { name: error?.name ?? 'Error', code: undefined, message };
}

function deserializeError(data) {
  if (data.name === 'MeshError') return new MeshError(data.code, data.message);
  const error = new Error(data.message);
  error.name = data.name;
  return error;
}

// ---- the client's side ----

// The bundled default: the literal pattern that vite and webpack turn into a worker entry. Both
// rewrite only this exact form (`new Worker(new URL('...', import.meta.url), { type: 'module' })`).
function defaultBrowserWorker() {
  if (import.meta.url === undefined) return new Worker(new URL('worker.js', classicScriptUrl), { type: 'module' });
  return new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
}

// Where the default worker script is expected when no bundler rewrote the line above (unbundled, or
// esbuild): named in the error when it fails to load. Not written as new URL('...', import.meta.url)
// so that bundlers do not copy the unbundled file as an asset.
function expectedWorkerUrl() {
  return import.meta.url === undefined ? new URL('worker.js', classicScriptUrl)
    : new URL(import.meta.url.replace(/[^/?#]*([?#].*)?$/, 'worker.js'));
}

// A worker script that fails to load fires a bare 'error' event: ask the server why.
async function describeLoadFailure(url) {
  try {
    const response = await fetch(url, { credentials: 'same-origin' });
    const type = response.headers.get('content-type') ?? 'no content type';
    return response.ok ? `it loads (HTTP ${response.status}, ${type}) but did not start as a module worker`
      : `HTTP ${response.status}`;
  } catch (cause) {
    return `the request failed (${cause.message})`;
  }
}

function workerFailure(event, url) {
  const hint = ' (pass createMeshWorker({ workerUrl }) to say where ruppert\'s worker.js is served)';
  if (event.message) {
    const where = event.filename ? ` at ${event.filename}:${event.lineno}` : '';
    return Promise.resolve(new MeshError('INTERNAL', `mesh worker failed: ${event.message}${where}`));
  }
  return describeLoadFailure(url).then((reason) =>
    new MeshError('IO_ERROR', `could not load the mesh worker script ${url}: ${reason}${hint}`));
}

function spawnBrowserWorker(workerUrl) {
  if (typeof Worker !== 'function') {
    throw new MeshError('INTERNAL', 'createMeshWorker: this platform has no Worker (in Node, import the package \'ruppert\')');
  }
  const worker = workerUrl === undefined ? defaultBrowserWorker() : new Worker(workerUrl, { type: 'module' });
  const url = absoluteUrl(workerUrl ?? expectedWorkerUrl());
  return {
    post: (data) => worker.postMessage(data),
    onMessage: (fn) => worker.addEventListener('message', (event) => fn(event.data)),
    onFailure: (fn) => worker.addEventListener('error', (event) => {
      event.preventDefault();
      workerFailure(event, url).then(fn);
    }),
    terminate: () => worker.terminate(),
    hold: () => {},
    release: () => {},
  };
}

function spawn(workerUrl) {
  const nodeHost = getNodeHost();
  return nodeHost ? nodeHost.spawnWorker(workerUrl) : spawnBrowserWorker(workerUrl);
}

/**
 * @param {{ workerUrl?: string | URL, wasmUrl?: string | URL, wasmBinary?: ArrayBuffer }} [options]
 *   workerUrl: where ruppert's worker.js is served (default: beside this module, or where the bundler
 *   put it); the others are passed to init() in the worker
 */
export function createMeshWorker(options = {}) {
  if (options === null || typeof options !== 'object') {
    throw new MeshError('MALFORMED_INPUT', 'createMeshWorker(options): options must be an object');
  }
  // No locateFile: a function cannot be sent to the worker.
  rejectUnknownKeys(options, ['workerUrl', 'wasmUrl', 'wasmBinary', 'wasmModule'], 'createMeshWorker(options)',
    (message) => new MeshError('INVALID_OPTION', message));
  const { workerUrl, ...loadOptions } = options;
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
    const handlePromise = new Promise((resolve) => resolve(spawn(workerUrl))).then((handle) => {
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
        checkPlc(plc);
        const opts = checkOptions(options);
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

// ---- the worker's side ----

// The ArrayBuffers inside a mesh result, for postMessage's transfer list: a worker hands them
// over instead of copying (a 2-million-triangle mesh is ~70 MB of typed arrays).
function meshBuffers(mesh) {
  const buffers = new Set();
  const visit = (value) => {
    if (ArrayBuffer.isView(value)) buffers.add(value.buffer);
    else if (value !== null && typeof value === 'object' && !Array.isArray(value)) Object.values(value).forEach(visit);
  };
  visit(mesh);
  return [...buffers];
}

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
