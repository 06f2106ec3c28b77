// The page's composition root: it creates every part (the editor, the history, the renderer, the
// panels, the meshing, step mode, the link, the embed protocol) and wires them together: each part
// is handed here the values, callbacks and other parts it uses, rather than importing them.
//
// Data flow: an edit changes `app.drawing` -> history + URL hash (io/page-link.js) ->
// meshing/meshing.js (MeshScheduler: throttled, in a worker) -> the renderer, the mesh panel, the
// display panel, step mode, the status line, and a postMessage to a host.
//
// Floors, each importing only from those below it (tests/browser/layers.test.mjs): labels.js (the
// page's words), geometry/ (measures of a mesh, no DOM), model/ (the drawing), rendering/, then the
// parts: editing/ (editor, toolbar, history), panels/, steps/ (step mode), meshing/, io/ (files, the
// URL hash, the embed protocol); this file on top hands each part the services beside it.
import { cloneDrawing, drawingBounds, emptyDrawing, fromPlc } from './model/drawing.js';
import { createCompareView } from './rendering/compare-view.js';
import { createDisplayPanel } from './panels/display-panel.js';
import { Editor } from './editing/editor.js';
import { isEditable, isEmbedded, listenToHost, postError, postMesh, postMeshed, postReady, postStepped } from './io/embed.js';
import { createExportMenu } from './io/export-menu.js';
import { createFilePanel } from './io/file-panel.js';
import { parseInput, parsePolyText } from './io/files.js';
import { History } from './editing/history.js';
import { createHoverInfo } from './panels/hover-info.js';
import { createMeshPanel } from './panels/mesh-panel.js';
import { createMeshing, loading } from './meshing/meshing.js';
import { createPageLink } from './io/page-link.js';
import { createParametersPanel } from './panels/parameters-panel.js';
import { createPresetBox } from './panels/preset-box.js';
import { PRESETS, findPreset } from './panels/presets.js';
import { Renderer } from './rendering/render.js';
import { createSmoothingEffect } from './panels/smoothing-effect.js';
import { createStartHere } from './panels/start-here.js';
import { setStatus, showNotices, showProgress, startProgress, stopProgress } from './panels/status-line.js';
import { createStepsPanel } from './steps/steps-panel.js';
import { drawStep, showsStep } from './steps/step-overlay.js';
import { createToolbar } from './editing/toolbar.js';
import { decodePageState } from './io/url-state.js';
import { View } from './rendering/view.js';

const $ = (id) => document.getElementById(id);
// The status line, a service every part that reports to the reader is handed.
const status = { setStatus, showNotices, showProgress, startProgress, stopProgress };

const canvas = $('canvas');
const view = new View();
// The mesh is drawn in WebGL when the browser has it (`?renderer=2d` asks for the 2D canvas).
const wantGl = new URLSearchParams(location.search).get('renderer') !== '2d';
const renderer = new Renderer(canvas, wantGl ? $('gl-canvas') : null, { draw: drawStep, shows: showsStep });
$('gl-canvas').hidden = renderer.gl === null;
document.body.dataset.renderer = renderer.gl ? 'webgl' : '2d';
$('renderer-note').hidden = renderer.gl !== null || !wantGl;
renderer.onReady = () => scheduleDraw();
renderer.onFallback = () => {
  document.body.dataset.renderer = '2d';
  $('renderer-note').textContent = 'The WebGL context was lost: the mesh is drawn with the 2D canvas now, slower, and above 200,000 triangles without its colors.';
  $('renderer-note').hidden = false;
  scheduleDraw();
};
// `?bench=1` (tests/bench/render-bench.mjs, tests/browser): the page's view, renderer and drawing, and the
// time from a mesh's arrival to its first finished picture in body[data-first-picture-ms].
const bench = new URLSearchParams(location.search).has('bench');
let meshArrivedAt = null;
if (bench) window.ruppertBench = { view, renderer, draw: () => draw(), exemptions: () => app.exemptions };
const embedded = isEmbedded();
if (embedded) document.body.classList.add('embed');
// A small frame needs its height for the canvas: the step legend starts closed there.
if (embedded) $('step-legend-box').open = false;
const readOnly = !isEditable();
// `&edit=1`: the reader draws, so the embed shows the drawing tools and the edit buttons too.
if (embedded && !readOnly) document.body.classList.add('editable');

// The state the parts share, each field with the part that writes it; the parts that only read a
// field or two are handed getters instead. The functions after the state are the editor's way out
// (editing/editor.js takes this object as its host).
const app = {
  canvas,
  view,
  drawing: emptyDrawing(),  // main.js (setDrawing, restore), edited in place by the editor
  snap: false,              // toolbar
  mesh: null,               // meshing: the latest mesh, or null
  meshedPlc: null,          // meshing: the input it was made from (for exports)
  meshedOptions: null,      // meshing: the options it was made with
  refinedMesh: null,        // meshing: a smoothed mesh's mesh before smoothing, once meshed, else null
  notices: [],              // meshing
  colorMode: 'angle',       // display panel
  stepMode: false,          // steps panel
  stepMesh: null,           // steps panel (meshing clears it): the mesh of the step on screen, else null
  pendingStep: null,        // steps panel and main.js: a step to show once the mesh with its trace arrives (link, host)
  hoverTriangle: -1,        // hover line (a new mesh or step resets it)
  exemptions: null,         // meshing: triangles left skinny on purpose (§6.6) in app.mesh, or null
  viewMoved: false,         // the editor on pan and zoom, main.js on fit
  changed: ({ commit }) => {
    if (commit) presets.notPreset();  // an edit on the canvas: no longer the preset
    changed(commit);
  },
  redraw: () => scheduleDraw(),
  undo: () => restore(history.undo()),
  redo: () => restore(history.redo()),
  regionSeed: () => parameters.regionSeed(),
  hover: (world) => hover(world),
  setTool: (tool) => toolbar.setTool(tool),
  shortcut: (key) => toolbar.shortcut(key),
};
const history = new History(app.drawing);
const editor = new Editor(app);
editor.readOnly = readOnly;

// ---------------------------------------------------------------- drawing the frame
let drawQueued = false;
function scheduleDraw() {
  if (drawQueued) return;
  drawQueued = true;
  requestAnimationFrame(() => {
    drawQueued = false;
    draw();
  });
}

/**
 * Draws the frame. `print`: the picture a reader would print (the .png export): the mesh, the
 * drawing's lines and points and the step overlay, without the editing aids (grid, seeds,
 * handles, selection, hover, the polyline being drawn, the keyboard cursor).
 */
function draw({ print = false } = {}) {
  if (app.viewMoved) link.writeSoon();
  const step = app.stepMode && app.mesh?.events
    ? {
      // A smoothed mesh's events happened in the mesh before smoothing: their places are its.
      final: app.refinedMesh ?? app.mesh, smoothed: app.refinedMesh ? app.mesh : null,
      events: app.mesh.events, index: steps.index, shown: app.stepMesh, stage: steps.stage, context: steps.context,
    }
    : null;
  const aid = (value, none) => (print ? none : value);
  renderer.draw({
    view,
    drawing: aid(app.drawing, { ...app.drawing, holes: [], regions: [] }),
    colorMode: app.colorMode,
    snap: app.snap,
    grid: !print,
    selection: aid(editor.selection, null),
    hoverItem: aid(editor.hoverItem, null),
    hoverTriangle: aid(app.hoverTriangle, -1),
    pendingChain: aid(editor.pendingChain(), null),
    curvePreview: aid(editor.curveTools.preview(), null),
    curveHandles: !readOnly && !print,
    keyCursor: aid(editor.keyCursor, null),
    notices: app.notices,
    step,
    exemptions: app.exemptions,
    vertexNumbers: display.vertexNumbers,
  });
  if (meshArrivedAt !== null) {
    renderer.finish();
    document.body.dataset.firstPictureMs = (performance.now() - meshArrivedAt).toFixed(1);
    meshArrivedAt = null;
  }
}

function resize() {
  const rect = $('canvas-wrap').getBoundingClientRect();
  // Hidden (the side-by-side comparison shows instead): nothing to fit until it is back.
  if (rect.width === 0 || rect.height === 0) return;
  const before = { width: view.width };
  view.resize(rect.width, rect.height);
  renderer.resize(rect.width, rect.height, window.devicePixelRatio || 1);
  // Until the user pans or zooms, keep the whole drawing in view as the layout settles; after, keep
  // the width of the world that was in view (a phone turned, a window made narrow: the canvas's
  // width changes). A change of height alone (the stepper shown, a status line) zooms nothing.
  if (!app.viewMoved) view.fit(drawingBounds(app.drawing));
  else if (before.width > 1 && rect.width !== before.width) view.scale *= rect.width / before.width;
  draw();
}
new ResizeObserver(resize).observe($('canvas-wrap'));

function fitView() {
  app.viewMoved = false;
  view.fit(drawingBounds(app.drawing));
  scheduleDraw();
}

// ---------------------------------------------------------------- edits and history
function changed(commit) {
  if (commit) {
    history.commit(app.drawing);
    link.write();
  }
  toolbar.updateButtons();
  meshing.remesh();
  scheduleDraw();
}

/** Replaces the drawing (preset, file, link, message); `fit` re-centers the view. */
function setDrawing(drawing, { commit = true, fit = true } = {}) {
  app.drawing = cloneDrawing(drawing);
  editor.reset();
  parameters.sync();
  if (commit) history.commit(app.drawing);
  else history.reset(app.drawing);
  link.write();
  if (fit) fitView();
  toolbar.updateButtons();
  meshing.remesh(0);
  scheduleDraw();
}

function restore(drawing) {
  if (drawing === null) return;
  app.drawing = drawing;
  presets.notPreset();
  editor.reset();
  parameters.sync();
  link.write();
  toolbar.updateButtons();
  meshing.remesh(0);
  scheduleDraw();
}

// ---------------------------------------------------------------- the panels
const link = createPageLink({ app, view, stepIndex: () => steps.index, onLinkChanged: (drawing) => setDrawing(drawing), status });
const hover = createHoverInfo({ app, scheduleDraw });
// A changed option makes the drawing no longer the preset: its caption and stages speak of the
// preset's options (the side-by-side comparison stays, meshed with the new ones).
const parameters = createParametersPanel({
  app, editor, changed: (commit) => { presets.notPreset({ keepCompare: true }); changed(commit); }, status,
});
const display = createDisplayPanel({ app, scheduleDraw, writeLink: link.write });
const meshPanel = createMeshPanel();
const smoothingEffect = createSmoothingEffect();
const steps = createStepsPanel({
  app, renderer, meshPanel, scheduleDraw, writeLinkSoon: link.writeSoon, remeshNow: () => meshing.remesh(0, { quiet: true }),
  postStepped, status,
});
const compare = createCompareView({ drawing: () => app.drawing });
const meshing = createMeshing({
  app, renderer, meshPanel, display, steps, smoothingEffect, scheduleDraw, host: { postMeshed, postError }, status, onMeshed: () => compare.update(),
  onArrival: bench ? () => {
    meshArrivedAt = performance.now();
    document.body.dataset.meshArrivedAt = String(meshArrivedAt);
  } : null,
});
const toolbar = createToolbar({
  app, editor, history, canvas, fitView, scheduleDraw, setDrawing,
  syncRegion: parameters.syncRegion, stepShortcut: steps.shortcut, notPreset: () => presets.notPreset(),
});
const presets = createPresetBox({
  drawingOptions: () => app.drawing.options, setDrawing, restartSteps: steps.restart, setStages: steps.setStages, compare, shared: !embedded,
  parseInput, loading, status,
});
createFilePanel({ drawingOptions: () => app.drawing.options, setDrawing, notPreset: presets.notPreset, loading, status });
createExportMenu({
  meshed: () => ({ mesh: app.mesh, plc: app.meshedPlc }), drawing: () => app.drawing, renderer,
  drawForPrint: () => draw({ print: true }), redraw: () => draw(), writeLink: link.write, status,
});
createStartHere({ embedded });

// ---------------------------------------------------------------- embedding (embed.js)
const SETTLED = ['done', 'error', 'cancelled', 'empty'];
/** Resolves once no meshing is queued, running or being read (body[data-mesh-state]). */
function meshSettled() {
  return new Promise((resolve) => {
    if (SETTLED.includes(document.body.dataset.meshState)) {
      resolve();
      return;
    }
    const observer = new MutationObserver(() => {
      if (!SETTLED.includes(document.body.dataset.meshState)) return;
      observer.disconnect();
      resolve();
    });
    observer.observe(document.body, { attributes: true, attributeFilter: ['data-mesh-state'] });
  });
}

listenToHost({
  async onLoad({ poly, json, options, id }) {
    const failed = loading();
    try {
      const plc = json !== undefined
        ? await parseInput(json, '<ruppert:load>.json')
        : await parsePolyText(poly, '<ruppert:load>');
      presets.notPreset();
      steps.leave();
      meshing.forHost(id);
      setDrawing(fromPlc(plc, options));
    } catch (error) {
      failed();
      setStatus(`Could not load the posted drawing: ${error.message}`, 'error');
      postError(error, id);
    }
  },
  onPreset({ name, id, source }) {
    if (!findPreset(name)) {
      postError({ code: 'UNKNOWN_PRESET', message: `no preset named '${name}' (the presets are ${PRESETS.map((p) => p.id).join(', ')})` }, id, source);
      return;
    }
    meshing.forHost(id);
    presets.open(name);
  },
  onStep: ({ index, id }) => steps.hostStep(index, id),
  async onGetMesh({ id, source }) {
    await meshSettled();
    if (app.mesh) postMesh(app.mesh, id, source);
    else postError({ code: 'NO_MESH', message: `no mesh to send (${document.body.dataset.meshState})` }, id, source);
  },
  onHello: ({ id, source }) => postReady({ presets: PRESETS.map((p) => p.id), id, target: source }),
});
// The first message to the host: the protocol's version and what the page offers.
postReady({ presets: PRESETS.map((p) => p.id) });

// ---------------------------------------------------------------- start
const linked = link.read();
const pageState = decodePageState(location.hash);
if (pageState.color) display.setColorMode(pageState.color);
if (pageState.step !== null) {  // step mode from the link: one mesh, with its trace
  steps.turnOn();
  app.pendingStep = pageState.step;
}
toolbar.setTool(readOnly ? 'select' : 'polyline');
if (readOnly) $('tool-hint').textContent = 'View only: drag to pan, wheel or +/- to zoom, hover a triangle for its angles.';
if (linked) setDrawing(linked, { commit: false });
else presets.openDefault();
if (pageState.view) {
  view.centerX = pageState.view.x;
  view.centerY = pageState.view.y;
  view.scale = pageState.view.scale;
  app.viewMoved = true;
  scheduleDraw();
}
display.updateLegend();
