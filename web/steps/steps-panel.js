// Step-by-step mode: the checkbox, the step controls (Stepper, stepper.js), the mesh of each step
// (StepReplay, step-replay.js, meshed on demand), and the step a link or a host asked for, shown
// once the mesh with its trace arrives.
import { isSmoothed } from '../model/drawing.js';
import { stepLegend } from './step-overlay.js';
import { StepReplay } from './step-replay.js';
import { Stepper } from './stepper.js';

const $ = (id) => document.getElementById(id);

/**
 * @param {object} app the page's state (mesh, stepMode, stepMesh, pendingStep, hoverTriangle)
 * @param {object} renderer the Renderer (it shows the step's mesh)
 * @param {object} meshPanel the Mesh panel (it shows the step's mesh too)
 * @param {() => void} scheduleDraw
 * @param {() => void} writeLinkSoon the step is in the link
 * @param {() => void} remeshNow mesh again (the trace is recorded only in step mode)
 * @param {(message: object) => void} postStepped tells a host of the step shown (io/embed.js)
 * @param {object} status the status line (panels/status-line.js): setStatus(text, kind), showNotices(notices, error)
 */
export function createStepsPanel({ app, renderer, meshPanel, scheduleDraw, writeLinkSoon, remeshNow, postStepped, status }) {
  const { setStatus } = status;
  // A host's 'ruppert:step' waiting for its reply: { index, id }.
  let hostRequest = null;
  // A figure's stages (presets.js): the function that finds them in a trace, those of the trace
  // in hand, the stage on screen (null: the step is none), and the one a stage button asked for.
  let stagesOf = null;
  let stages = [];
  let stage = null;
  let stageWanted = null;
  // The mesh of each step, meshed on demand; shown when it is still the step wanted.
  const replay = new StepReplay((k, mesh) => {
    if (!app.stepMode || k !== stepper.index) return;
    app.stepMesh = mesh;
    app.hoverTriangle = -1;
    // Stage (a) of a figure: the input alone, no triangulation yet.
    renderer.setMesh(stage?.inputOnly ? null : mesh);
    const { vertices, triangles, minAngle, maxAngle } = mesh.stats;
    const summary = `${vertices.toLocaleString('en-US')} vertices, ` +
      `${triangles.toLocaleString('en-US')} triangles, smallest angle ${minAngle.toFixed(2)}°`;
    const at = k.toLocaleString('en-US');
    $('step-mesh').textContent = `Mesh at step ${at}: ${summary}`;
    // The panel and the status line speak of the mesh on screen: this step's.
    meshPanel.showStep(mesh, k, stepper.count);
    setStatus(`Step ${at} of ${stepper.count.toLocaleString('en-US')}: ${summary}${k === stepper.count ? ' (the final mesh)' : ''}.`, 'info');
    document.body.dataset.stepShown = String(k);
    let id = null;
    if (hostRequest !== null && Math.min(hostRequest.index, stepper.count) === k) {
      id = hostRequest.id;
      hostRequest = null;
    }
    postStepped({
      id, index: k, total: stepper.count, vertices, triangles, minAngle, maxAngle,
      event: k > 0 ? stepper.describe(k) : null,
    });
    scheduleDraw();
  });

  const stepper = new Stepper({
    first: $('step-first'), back: $('step-back'), play: $('step-play'), forward: $('step-forward'),
    last: $('step-last'), scrub: $('step-scrub'), speed: $('step-speed'), info: $('step-info'),
  }, (k) => {
    showStage(stageWanted?.step === k ? stageWanted : stages.find((s) => s.step === k && !s.inputOnly) ?? null);
    stageWanted = null;
    delete document.body.dataset.stepShown;
    writeLinkSoon();
    $('step-mesh').textContent = `Mesh at step ${k.toLocaleString('en-US')}: meshing…`;
    replay.show(k);
    scheduleDraw();
  });

  /** The stage on screen (or none): its caption and its button pressed. */
  function showStage(s) {
    stage = s;
    $('step-stage').textContent = s ? `${s.figure} ${s.label}: ${s.caption}` : '';
    $('step-stage').hidden = s === null;
    for (const button of $('step-stages').querySelectorAll('button')) {
      button.setAttribute('aria-pressed', String(s !== null && button.dataset.label === s.label));
    }
  }

  /** The stage buttons of the trace in hand (none without stages). */
  function showStages(events) {
    stages = stagesOf && events ? stagesOf(events) : [];
    $('step-stages').hidden = stages.length === 0;
    $('step-stages').replaceChildren(...stages.map((s) => {
      const button = document.createElement('button');
      button.type = 'button';
      button.textContent = s.label;
      button.dataset.label = s.label;
      button.title = `Step ${s.step}: ${s.caption}`;
      button.addEventListener('click', () => {
        stepper.pause();
        stageWanted = s;
        stepper.go(s.step);
      });
      return button;
    }));
    if (stages.length === 0) showStage(null);
  }

  /** The overlay's legend: every symbol step mode draws, the encroachment region as in force. */
  function showLegend(options) {
    $('step-legend').replaceChildren(...stepLegend(options).map(({ svg, label }) => {
      const item = document.createElement('span');
      item.className = 'legend-item';
      const symbol = document.createElement('span');
      symbol.className = 'step-symbol';
      symbol.innerHTML = svg;  // the page's own markup (step-overlay.js), no input in it
      item.append(symbol, label);
      return item;
    }));
  }

  /** Step mode on or off, without meshing again (the caller does). */
  function setMode(on) {
    $('step-mode').checked = on;
    app.stepMode = on;
    $('stepper').hidden = !on;
    if (!on) {
      stepper.pause();
      replay.clear();
      app.stepMesh = null;
      showStage(null);
      if (app.mesh) {
        renderer.setMesh(app.mesh);
        meshPanel.showStep(null);
      }
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

  /**
   * A drawing the host sent (ruppert:load): step mode off, whatever an earlier preset or step
   * left, so that a load gives the same page on every frame; a later ruppert:step turns it on.
   * Meshing again is the caller's.
   */
  function leave() {
    setMode(false);
    restart(false);
  }

  /** A new mesh (with its trace in step mode) of the request's input and options. */
  function meshed(mesh, request) {
    replay.reset(request.plc, request.options, app.stepMode ? mesh : null);
    const { minAngle, placement, maxArea, encroachment } = request.options;
    showStages(app.stepMode ? mesh.events : null);
    showLegend({ ...request.options, curves: request.plc.curves });
    // The curves and the final mesh's subsegments tell which splits were a curve's (steps/curve-events.js).
    const curves = { curves: request.plc.curves ?? [], segmentCount: request.plc.segments.length / 2, segments: mesh.segments, segmentIds: mesh.segmentIds };
    const smoothed = isSmoothed(request.options);
    stepper.setEvents(app.stepMode ? mesh.events : null,
      { points: mesh.points, minAngle, placement, maxArea: maxArea ?? null, encroachment, regions: request.plc.regions, ...curves },
      smoothed);
  }

  /**
   * A smoothed mesh's mesh before smoothing: the events' texts measure its places, and the last
   * step says how many vertices smoothing moved.
   */
  function refined(mesh, moved) {
    if (stepper.context) stepper.context = { ...stepper.context, points: mesh.points };
    stepper.setSmoothingMoved(moved);
  }

  function clear() {
    replay.clear();
    showStages(null);
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
    /** The figure stage on screen, or null. */
    get stage() { return stage; },
    /** What the event texts and the overlay know of the options: { minAngle, encroachment, ... }. */
    get context() { return stepper.context; },
    /** The preset's stages (a function of the trace, presets.js), or null. */
    setStages(fn) { stagesOf = fn; },
    turnOn, restart, leave, meshed, refined, clear, showPending, hostStep, shortcut,
  };
}
