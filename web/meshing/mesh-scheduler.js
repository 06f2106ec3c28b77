// Re-meshing on every change, off the main thread.
//
// Changes are throttled to the mesh time, not debounced: the first change of a burst is meshed
// after a short delay, and while a mesh is being made, only the newest change is kept and meshed
// as soon as that mesh arrives. So a dragged vertex re-meshes while it moves, and the latest
// position is always meshed last. A request that has run longer than ABORT_AFTER_MS is aborted
// in favor of a newer one (createMeshWorker aborts by terminating the worker, which costs a
// restart: worth it only when the mesh in the way is slow). Results of superseded requests are
// dropped.
import { MeshError, createMeshWorker } from '../../wasm/index.js';

/** Delay of the first change of a burst: lets a click's several changes arrive as one. */
export const DEBOUNCE_MS = 30;
/** A running request older than this gives way to a newer one. */
export const ABORT_AFTER_MS = 400;

export class MeshScheduler {
  /**
   * @param {{ onStart?: () => void, onResult: (mesh, request) => void, onError: (error, request) => void,
   *           onProgress?: (progress) => void, onSuperseded?: (request) => void }} handlers
   */
  constructor(handlers) {
    this.handlers = handlers;
    this.worker = createMeshWorker();
    this.timer = null;
    this.waiting = null;  // the newest request not yet started
    this.running = null;  // { controller, request, started }
    this.generation = 0;
  }

  /**
   * Meshes `plc` with `options` after `delay` ms (0: now), or once the running mesh is done.
   * `id` (a host's request id) rides along to onResult/onError; a request that replaces a waiting
   * or a running one keeps its id when it has none. `quiet`: the mesh is the same as the last one
   * (only its trace is asked for or dropped); a request is quiet when all it replaces were.
   */
  request(plc, options, delay = DEBOUNCE_MS, id = null, quiet = false) {
    const replaced = this.waiting;
    if (replaced && replaced.id !== null && id !== null && replaced.id !== id) this.handlers.onSuperseded?.(replaced);
    this.waiting = { plc, options, id: id ?? replaced?.id ?? null, quiet: quiet && (replaced?.quiet ?? true) };
    if (this.running !== null) {
      if (performance.now() - this.running.started > ABORT_AFTER_MS) this.startWaiting();
      return;
    }
    if (delay <= 0) {
      this.startWaiting();
    } else if (this.timer === null) {
      this.timer = setTimeout(() => this.startWaiting(), delay);
    }
  }

  startWaiting() {
    clearTimeout(this.timer);
    this.timer = null;
    const request = this.waiting;
    this.waiting = null;
    if (request !== null) this.run(request);
  }

  run(request) {
    const superseded = this.running?.request;
    this.running?.controller.abort();
    if (superseded) {
      // The aborted request's host (if any) gets this one's reply, or, when this one answers
      // another host request, is told that its request gave way.
      if (request.id === null) request.id = superseded.id;
      else if (superseded.id !== null && superseded.id !== request.id) this.handlers.onSuperseded?.(superseded);
      request.quiet &&= superseded.quiet;
    }
    const generation = ++this.generation;
    const controller = new AbortController();
    this.running = { controller, request, started: performance.now() };
    this.handlers.onStart?.();
    this.worker.triangulate(request.plc, request.options, {
      signal: controller.signal,
      onProgress: (progress) => { if (generation === this.generation) this.handlers.onProgress?.(progress); },
    }).then(
      (mesh) => this.settled(generation, () => this.handlers.onResult(mesh, request)),
      // A superseded request was aborted on purpose: nothing to report.
      (error) => this.settled(generation, () => this.handlers.onError(error, request)),
    );
  }

  /** The running request ended: report it (unless superseded), then start the newest waiting one. */
  settled(generation, report) {
    if (generation !== this.generation) return;
    this.running = null;
    report();
    if (this.waiting !== null && this.timer === null) this.startWaiting();
  }

  /** A newer request waits (for its delay, or for the running mesh). */
  get queued() { return this.waiting !== null; }

  /** Stops the running request (and a waiting one); onError receives MeshError 'CANCELLED'. */
  cancel() {
    const waiting = this.waiting !== null;
    clearTimeout(this.timer);
    this.timer = null;
    this.waiting = null;
    if (this.running !== null) this.running.controller.abort();
    else if (waiting) this.handlers.onError(new MeshError('CANCELLED', 'triangulation cancelled'), null);
  }

  /** Forgets pending work without reporting (the drawing became empty). */
  clear() {
    clearTimeout(this.timer);
    this.timer = null;
    this.waiting = null;
    this.generation++;
    this.running?.controller.abort();
    this.running = null;
  }
}
