// Re-meshing on every change, off the main thread.
//
// Requests are debounced (a drag produces dozens of changes a second) and only the newest one
// matters: starting a request aborts the one still running, which createMeshWorker implements by
// terminating that worker. Results of superseded requests are dropped.
import { MeshError, createMeshWorker } from '../wasm/index.js';

export const DEBOUNCE_MS = 150;

export class MeshScheduler {
  /**
   * @param {{ onStart?: () => void, onResult: (mesh, request) => void, onError: (error, request) => void,
   *           onProgress?: (progress) => void, onIdle?: () => void }} handlers
   */
  constructor(handlers) {
    this.handlers = handlers;
    this.worker = createMeshWorker();
    this.timer = null;
    this.running = null;  // { controller, request }
    this.generation = 0;
  }

  /** Meshes `plc` with `options` after the debounce delay (0: now). */
  request(plc, options, delay = DEBOUNCE_MS) {
    clearTimeout(this.timer);
    this.timer = setTimeout(() => this.run({ plc, options }), delay);
  }

  run(request) {
    this.timer = null;
    this.running?.controller.abort();
    const generation = ++this.generation;
    const controller = new AbortController();
    this.running = { controller, request };
    this.handlers.onStart?.();
    this.worker.triangulate(request.plc, request.options, {
      signal: controller.signal,
      onProgress: (progress) => { if (generation === this.generation) this.handlers.onProgress?.(progress); },
    }).then(
      (mesh) => {
        if (generation !== this.generation) return;
        this.running = null;
        this.handlers.onResult(mesh, request);
      },
      (error) => {
        // A superseded request was aborted on purpose: nothing to report.
        if (generation !== this.generation) return;
        this.running = null;
        this.handlers.onError(error, request);
      },
    );
  }

  /** A newer request waits for its debounce delay. */
  get queued() { return this.timer !== null; }

  /** Stops the running request (and a pending one); onError receives MeshError 'CANCELLED'. */
  cancel() {
    const waiting = this.timer !== null;
    clearTimeout(this.timer);
    this.timer = null;
    if (this.running !== null) this.running.controller.abort();
    else if (waiting) this.handlers.onError(new MeshError('CANCELLED', 'triangulation cancelled'), null);
  }

  /** Forgets pending work without reporting (the drawing became empty). */
  clear() {
    clearTimeout(this.timer);
    this.timer = null;
    this.generation++;
    this.running?.controller.abort();
    this.running = null;
  }
}
