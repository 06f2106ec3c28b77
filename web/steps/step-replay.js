// The mesh as it was at every step of the refinement.
//
// Step k is the triangulation after k events (Steiner insertions, and the optimal placement's moves
// of free vertices, each of which uses one unit of the budget): exactly the mesh that `maxSteiner: k`
// gives with the same options (refinement is deterministic and a trace changes nothing, so its
// first k events are those of the full run, with the same vertex numbers), and step 0 is the constrained Delaunay
// triangulation before refinement. Each step is meshed on demand in a worker of its own, so the
// page's main mesher is never interrupted. Requests do not abort one another (aborting terminates
// a worker, and a new one costs more than most steps): while one step is being meshed, only the
// newest wanted step is remembered, and it is meshed next. Recent steps are cached, so stepping
// back and forth is instant. A smoothed mesh has one step more than its events: steps up to the
// events' count are meshed without smoothing (smoothing runs after refinement, whatever its
// budget), and the last is the final, smoothed mesh.
import { createMeshWorker } from '../../wasm/index.js';
import { isSmoothed } from '../model/drawing.js';

const CACHE_SIZE = 64;

export class StepReplay {
  /** @param {(k: number, mesh: object) => void} onStep called when step k's mesh is ready */
  constructor(onStep) {
    this.onStep = onStep;
    this.worker = null;
    this.source = null;     // { plc, options, final, count, generation }
    this.generation = 0;
    this.cache = new Map(); // k -> mesh, in use order
    this.busy = false;
    this.wanted = -1;
  }

  /**
   * A new final mesh (with its trace): steps refer to it from now on.
   * @param {object} plc the input it was meshed from
   * @param {object} options its options (trace included)
   * @param {object} final the mesh; its events count the steps (one more when it was smoothed)
   */
  reset(plc, options, final) {
    this.generation++;
    this.cache.clear();
    this.wanted = -1;
    const smoothed = isSmoothed(options);
    const count = (final?.events?.count ?? 0) + (final && smoothed ? 1 : 0);
    this.source = final ? { plc, options, final, count, smoothed, generation: this.generation } : null;
  }

  clear() { this.reset(null, null, null); }

  /** The cached mesh of step k, or null. */
  cached(k) {
    if (this.source !== null && k === this.source.count) return this.source.final;
    const mesh = this.cache.get(k);
    if (mesh === undefined) return null;
    this.cache.delete(k);
    this.cache.set(k, mesh);
    return mesh;
  }

  /** Asks for step k; onStep(k, mesh) follows (at once when cached). */
  show(k) {
    if (this.source === null) return;
    const mesh = this.cached(k);
    if (mesh !== null) {
      this.wanted = -1;
      this.onStep(k, mesh);
      return;
    }
    this.wanted = k;
    if (!this.busy) this.next();
  }

  next() {
    const source = this.source;
    const k = this.wanted;
    if (source === null || k < 0) return;
    this.wanted = -1;
    this.busy = true;
    this.worker ??= createMeshWorker();
    const options = { ...source.options, trace: false, maxSteiner: k, ...(source.smoothed ? { smooth: 0 } : {}) };
    this.worker.triangulate(source.plc, options).then(
      (mesh) => this.arrived(source, k, mesh),
      () => this.arrived(source, k, null),
    );
  }

  arrived(source, k, mesh) {
    this.busy = false;
    if (source.generation === this.generation && mesh !== null) {
      this.remember(k, mesh);
      // A newer wish is meshed first; this one is shown only if nothing newer is wanted.
      if (this.wanted < 0) this.onStep(k, mesh);
    }
    this.next();
  }

  remember(k, mesh) {
    this.cache.set(k, mesh);
    while (this.cache.size > CACHE_SIZE) this.cache.delete(this.cache.keys().next().value);
  }

  terminate() {
    this.worker?.terminate?.();
    this.worker = null;
  }
}
