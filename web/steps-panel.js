// Step-by-step mode: the checkbox, the step controls (Stepper, stepper.js), the mesh of each step
// (StepReplay, step-replay.js, meshed on demand), and the step a link or a host asked for, shown
// once the mesh with its trace arrives.
import { postStepped } from './embed.js';
import { StepReplay } from './step-replay.js';
import { Stepper, describeEvent } from './stepper.js';

const $ = (id) => document.getElementById(id);

/**
 * @param {object} app the page's state (mesh, stepMode, stepMesh, pendingStep, hoverTriangle)
 * @param {object} renderer the Renderer (it shows the step's mesh)
 * @param {() => void} scheduleDraw
 * @param {() => void} writeLinkSoon the step is in the link
 * @param {() => void} remeshNow mesh again (the trace is recorded only in step mode)
 */
export function createStepsPanel({ app, renderer, scheduleDraw, writeLinkSoon, remeshNow }) {
  // A host's 'ruppert:step' waiting for its reply: { index, id }.
  let hostRequest = null;
  // The mesh of each step, meshed on demand; shown when it is still the step wanted.
  const replay = new StepReplay((k, mesh) => {
    if (!app.stepMode || k !== stepper.index) return;
    app.stepMesh = mesh;
    app.hoverTriangle = -1;
    renderer.setMesh(mesh);
    const { vertices, triangles, minAngle, maxAngle } = mesh.stats;
    $('step-mesh').textContent = `Mesh at step ${k}: ${vertices.toLocaleString('en-US')} vertices, ` +
      `${triangles.toLocaleString('en-US')} triangles, smallest angle ${minAngle.toFixed(2)}°`;
    document.body.dataset.stepShown = String(k);
    const events = app.mesh.events;
    let id = null;
    if (hostRequest !== null && Math.min(hostRequest.index, stepper.count) === k) {
      id = hostRequest.id;
      hostRequest = null;
    }
    postStepped({
      id, index: k, total: stepper.count, vertices, triangles, minAngle, maxAngle,
      event: k > 0 ? describeEvent(events, k - 1, stepper.context) : null,
    });
    scheduleDraw();
  });

  const stepper = new Stepper({
    first: $('step-first'), back: $('step-back'), play: $('step-play'), forward: $('step-forward'),
    last: $('step-last'), scrub: $('step-scrub'), speed: $('step-speed'), info: $('step-info'),
  }, (k) => {
    delete document.body.dataset.stepShown;
    writeLinkSoon();
    $('step-mesh').textContent = `Mesh at step ${k}: meshing…`;
    replay.show(k);
    scheduleDraw();
  });

  /** Step mode on or off, without meshing again (the caller does). */
  function setMode(on) {
    $('step-mode').checked = on;
    app.stepMode = on;
    $('stepper').hidden = !on;
    if (!on) {
      stepper.pause();
      replay.clear();
      app.stepMesh = null;
      if (app.mesh) renderer.setMesh(app.mesh);
    }
  }

  /** Follows the checkbox. */
  function setStepMode() {
    setMode($('step-mode').checked);
    // Events are recorded only on request (options.trace): mesh again.
    remeshNow();
    scheduleDraw();
  }
  $('step-mode').addEventListener('change', setStepMode);

  /** Step mode on before a mesh is asked for (a link): no remesh here. */
  function turnOn() {
    setMode(true);
  }

  /**
   * A drawing opened afresh (a preset), nothing pending; meshing again is the caller's. One that
   * asks for steps turns step mode on at step 0; another leaves step mode as the reader set it, at
   * the final mesh when it is on (at step 0 when it is turned on later, as on a fresh page).
   */
  function restart(asksSteps) {
    if (asksSteps) setMode(true);
    stepper.pause();
    stepper.index = app.stepMode && !asksSteps ? Number.MAX_SAFE_INTEGER : 0;  // clamped by the new events
    app.pendingStep = null;
    hostRequest = null;
  }

  /** A new mesh (with its trace in step mode) of the request's input and options. */
  function meshed(mesh, request) {
    replay.reset(request.plc, request.options, app.stepMode ? mesh : null);
    stepper.setEvents(app.stepMode ? mesh.events : null,
      { points: mesh.points, minAngle: request.options.minAngle, placement: request.options.placement });
  }

  function clear() {
    replay.clear();
    stepper.setEvents(null);
  }

  /** Shows the step a link or a host asked for, once the mesh with the trace is there. */
  function showPending() {
    if (app.pendingStep === null || !app.stepMode || !app.mesh?.events) return;
    const k = app.pendingStep;
    app.pendingStep = null;
    stepper.pause();
    stepper.go(k);
  }

  /** A host's 'ruppert:step': step mode on if it is not, the step once its mesh is there. */
  function hostStep(index, id = null) {
    hostRequest = { index, id };
    if (!app.stepMode) {
      app.pendingStep = index;
      $('step-mode').checked = true;
      setStepMode();
    } else if (app.mesh?.events) {
      stepper.pause();
      stepper.go(index);
    } else {
      app.pendingStep = index;  // the mesh with the trace is still on its way
    }
  }

  /** The step mode keys (editor.js passes them on); true when the key was used. */
  function shortcut(key) {
    switch (key) {
      case 's': $('step-mode').checked = !$('step-mode').checked; setStepMode(); return true;
      case 'k': if (app.stepMode) stepper.toggle(); return app.stepMode;
      case ',': if (app.stepMode) stepper.step(-1); return app.stepMode;
      case '.': if (app.stepMode) stepper.step(1); return app.stepMode;
      case 'home': if (app.stepMode) stepper.go(0); return app.stepMode;
      case 'end': if (app.stepMode) stepper.go(stepper.count); return app.stepMode;
      default: return false;
    }
  }

  return {
    get index() { return stepper.index; },
    turnOn, restart, meshed, clear, showPending, hostStep, shortcut,
  };
}
