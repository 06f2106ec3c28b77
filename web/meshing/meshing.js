// Meshing the drawing: the requests to the worker (MeshScheduler, mesh-scheduler.js), and what a
// result or an error changes on the page (the mesh panel, the display panel's legend, step mode,
// the status line, the host). body[data-mesh-state] tells tests and hosts where it stands:
// 'queued', 'meshing', 'done', 'cancelled', 'error', 'empty', or 'loading' while a file is read.
import { isSmoothed, pointCount, toMeshOptions, toPlc } from '../model/drawing.js';
import { MeshScheduler } from './mesh-scheduler.js';
import { UnsmoothedMesher } from './unsmoothed-mesher.js';

const $ = (id) => document.getElementById(id);

/** Marks the page busy while a file or message is read, so that nothing waits on an old mesh. */
export function loading() {
  const previous = document.body.dataset.meshState;
  document.body.dataset.meshState = 'loading';
  return () => { if (document.body.dataset.meshState === 'loading') document.body.dataset.meshState = previous; };
}

/**
 * @param {object} app the page's state (drawing, stepMode; mesh, meshedPlc, notices,
 *   hoverTriangle, stepMesh, exemptions are set here)
 * @param {object} renderer the Renderer
 * @param {object} meshPanel, display, steps, smoothingEffect the panels a mesh changes
 * @param {() => void} scheduleDraw
 * @param {(() => void) | null} onArrival called first when a mesh arrives (`?bench=1`)
 * @param {() => void} onMeshed called after a mesh of a changed drawing or options is shown
 * @param {object} host the embed protocol's news for a host (io/embed.js): postMeshed(mesh, id), postError(error, id)
 * @param {object} status the status line (panels/status-line.js): setStatus, showNotices, startProgress,
 *   showProgress, stopProgress
 */
export function createMeshing({
  app, renderer, meshPanel, display, steps, smoothingEffect, scheduleDraw, host, status, onArrival = null, onMeshed = () => {},
}) {
  const { postError, postMeshed } = host;
  const { setStatus, showNotices, showProgress, startProgress, stopProgress } = status;
  // A smoothed mesh is compared with the same mesh unsmoothed, meshed after it.
  const unsmoothed = new UnsmoothedMesher((refined, smoothed) => {
    if (smoothed !== app.mesh) return;
    app.refinedMesh = refined;
    const moved = smoothingEffect.show(refined, smoothed, app.meshedOptions.minAngle);
    steps.refined(refined, moved);
    document.body.dataset.smoothingState = 'shown';
    scheduleDraw();
  });
  const scheduler = new MeshScheduler({
    onStart() {
      document.body.dataset.meshState = 'meshing';
      startProgress();
    },
    onProgress: showProgress,
    onResult(mesh, request) {
      onArrival?.();
      stopProgress();
      app.mesh = mesh;
      app.meshedPlc = request.plc;
      app.meshedOptions = request.options;
      app.refinedMesh = null;
      app.notices = mesh.notices;
      app.hoverTriangle = -1;
      app.stepMesh = null;
      renderer.setMesh(mesh);
      app.exemptions = meshPanel.show(mesh, request);
      display.vertexNumbersNote();
      showNotices(mesh.notices);
      display.updateLegend();
      steps.meshed(mesh, request);
      compareUnsmoothed(mesh, request);
      const s = mesh.stats;
      const summary = `${s.triangles.toLocaleString('en-US')} triangles, ${s.vertices.toLocaleString('en-US')} vertices, ` +
        `min angle ${s.minAngle.toFixed(2)}° in ${s.milliseconds.toFixed(1)} ms`;
      if (mesh.notices.length) setStatus(`Meshed with ${mesh.notices.length} repair(s) of the input: ${summary}.`, 'warn');
      else if (!mesh.complete) setStatus(`Meshed, not complete (see Mesh panel): ${summary}.`, 'warn');
      // Points alone: the package meshes their convex hull (an open polyline gets NOTHING_ENCLOSED
      // instead); say so rather than leave a hull no one drew unexplained.
      else if (request.plc.segments.length === 0) {
        setStatus(`Meshed the convex hull of the ${(request.plc.points.length / 2).toLocaleString('en-US')} points ` +
          `(the drawing has no segments; add some to bound the domain): ${summary}.`, 'info');
      }
      else setStatus(`Meshed: ${summary}.`, 'ok');
      // A result that a newer, still debounced request will replace is shown, but not 'done'.
      document.body.dataset.meshState = scheduler.queued ? 'queued' : 'done';
      document.body.dataset.meshCount = String(Number(document.body.dataset.meshCount ?? 0) + 1);
      // The host hears of a new mesh: one per load or preset it sent (with its id), and one per
      // change of the reader's; a mesh that only adds or drops the trace (step mode) is the same.
      if (request.id !== null || !request.quiet) postMeshed(mesh, request.id);
      if (!request.quiet) onMeshed();
      steps.showPending();
      scheduleDraw();
    },
    onError(error, request) {
      stopProgress();
      if (error?.code === 'CANCELLED') {
        setStatus('Meshing cancelled. Change the drawing or a parameter to mesh again.', 'warn');
        if (app.mesh) meshPanel.cancelled();
        document.body.dataset.meshState = scheduler.queued ? 'queued' : 'cancelled';
        if (request?.id != null) postError(error, request.id);
        return;
      }
      clear();
      setStatus(`Cannot mesh this drawing: ${error?.message ?? error}`, 'error');
      showNotices([], error);
      document.body.dataset.meshState = scheduler.queued ? 'queued' : 'error';
      postError(error, request?.id ?? null);
      scheduleDraw();
    },
    onSuperseded(request) {
      postError({ code: 'CANCELLED', message: 'a newer request from the host replaced this one before it was meshed' }, request.id);
    },
  });
  $('cancel').addEventListener('click', () => scheduler.cancel());

  /** A smoothed mesh: its smoothing rows wait for the unsmoothed mesh (body[data-smoothing-state]). */
  function compareUnsmoothed(mesh, request) {
    const smoothed = isSmoothed(request.options);
    unsmoothed.request(request, mesh);
    if (smoothed) smoothingEffect.waiting();
    else smoothingEffect.hide();
    document.body.dataset.smoothingState = smoothed ? 'waiting' : 'none';
  }

  /** No mesh on the page (an error, or too few points). */
  function clear() {
    app.mesh = null;
    app.meshedPlc = null;
    app.meshedOptions = null;
    app.refinedMesh = null;
    unsmoothed.clear();
    smoothingEffect.hide();
    document.body.dataset.smoothingState = 'none';
    app.notices = [];
    app.hoverTriangle = -1;
    $('hover-info').hidden = true;
    app.stepMesh = null;
    renderer.setMesh(null);
    app.exemptions = null;
    meshPanel.clear();
    steps.clear();
    display.updateLegend();
  }

  // The id of a host's 'ruppert:load', given to the mesh request it causes (and echoed in the reply).
  let hostId = null;

  /**
   * Meshes the drawing after `delay` ms (the scheduler's own throttle when undefined). `quiet`:
   * the drawing and its options did not change (step mode asks for the trace, or drops it).
   */
  function remesh(delay, { quiet = false } = {}) {
    // A circle alone (two points, two arcs) is a domain too.
    if (pointCount(app.drawing) < 3 && !app.drawing.curves?.length) {
      if (hostId !== null) postError({ code: 'EMPTY_INPUT', message: 'the drawing has fewer than three points: nothing to mesh' }, hostId);
      hostId = null;
      scheduler.clear();
      stopProgress();
      clear();
      showNotices([]);
      setStatus(pointCount(app.drawing) === 0
        ? 'Empty drawing: pick a tool and click on the canvas, or choose a preset.'
        : 'Add at least three points (not all on one line) to mesh.', 'info');
      document.body.dataset.meshState = 'empty';
      return;
    }
    // 'queued' until the result of this very request arrives (tests and hosts can wait for 'done').
    document.body.dataset.meshState = 'queued';
    scheduler.request(toPlc(app.drawing), toMeshOptions(app.drawing, { trace: app.stepMode }), delay, hostId, quiet);
    hostId = null;
  }

  return {
    remesh,
    /** The next request answers a host's load with this id. */
    forHost(id) { hostId = id; },
  };
}
