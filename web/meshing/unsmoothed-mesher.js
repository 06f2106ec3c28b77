// The mesh a smoothed mesh was made from: the same input and options with no smoothing, meshed in a
// worker of its own after the page's mesh arrives, so that the page can show what smoothing changed
// (the smallest-angle histograms, the replay's last step) without holding up the mesh itself.
// Only the newest request counts: one still being meshed when a newer one comes is left to finish
// (terminating a worker costs more than most meshes) and its result dropped.
import { createMeshWorker } from '../../wasm/index.js';
import { isSmoothed } from '../model/drawing.js';

export class UnsmoothedMesher {
  /** @param {(unsmoothed: object, smoothed: object) => void} onMeshed called with both meshes */
  constructor(onMeshed) {
    this.onMeshed = onMeshed;
    this.worker = null;
    this.generation = 0;
  }

  /** Meshes request.plc without smoothing, for `smoothed`, the mesh of request; none when it was not smoothed. */
  request(request, smoothed) {
    const generation = ++this.generation;
    if (!isSmoothed(request.options)) return;
    this.worker ??= createMeshWorker();
    const options = { ...request.options, smooth: 0, trace: false };
    this.worker.triangulate(request.plc, options).then(
      (mesh) => { if (generation === this.generation) this.onMeshed(mesh, smoothed); },
      () => {},  // the smoothed mesh is on the page already; its comparison is only missing
    );
  }

  /** No mesh on the page: a result still on its way is dropped. */
  clear() { this.generation++; }
}
