// The page: wires the drawing, the editor, the worker mesher, the renderer and the panels.
//
// Data flow: an edit changes `drawing` -> history + URL hash -> MeshScheduler (debounced, in a
// worker) -> onMeshed: renderer, stats, stepper, notices, postMessage to a host.
import { DEFAULT_OPTIONS, cloneDrawing, drawingBounds, emptyDrawing, fromPlc, pointCount, toMeshOptions, toPlc, Item } from './drawing.js';
import { Editor, TOOL_HINTS } from './editor.js';
import { isEditable, isEmbedded, listenToHost, postError, postMeshed, postStepped } from './embed.js';
import { canvasBlob, download, drawingPolyText, exportText, parseInput, parsePolyText } from './files.js';
import { History } from './history.js';
import { MeshScheduler } from './mesh-scheduler.js';
import { triangleShape } from './mesh-geometry.js';
import { locateTriangle } from './mesh-index.js';
import { DEFAULT_PRESET, PRESETS, findPreset } from './presets.js';
import { Renderer, VERTEX_NUMBERS_UP_TO, exemptionLegend, legendEntries } from './render.js';
import { findExemptions } from './exemptions.js';
import { showEventCounts, showExemptions, showStats } from './stats-panel.js';
import { StepReplay } from './step-replay.js';
import { Stepper, describeEvent } from './stepper.js';
import { MAX_HASH_LENGTH, decodeDrawing, decodePageState, encodeDrawing, encodePageState } from './url-state.js';
import { View } from './view.js';

const $ = (id) => document.getElementById(id);
const VERTEX_KINDS = ['input', 'segment split', 'interior (circumcenter)', 'off-center', 'intersection', 'unused'];
const PROGRESS_DELAY_MS = 200;

const canvas = $('canvas');
const view = new View();
// The mesh is drawn in WebGL when the browser has it (`?renderer=2d` asks for the 2D canvas).
const wantGl = new URLSearchParams(location.search).get('renderer') !== '2d';
const renderer = new Renderer(canvas, wantGl ? $('gl-canvas') : null);
$('gl-canvas').hidden = renderer.gl === null;
document.body.dataset.renderer = renderer.gl ? 'webgl' : '2d';
$('renderer-note').hidden = renderer.gl !== null || !wantGl;
// `?bench=1` (tests/bench/render-bench.mjs, tests/browser): the page's view, renderer and drawing, and the
// time from a mesh's arrival to its first finished picture in body[data-first-picture-ms].
renderer.onReady = () => scheduleDraw();
renderer.onFallback = () => {
  document.body.dataset.renderer = '2d';
  $('renderer-note').textContent = 'The WebGL context was lost: the mesh is drawn with the 2D canvas now, slower, and above 200,000 triangles without its colours.';
  $('renderer-note').hidden = false;
  scheduleDraw();
};
const bench = new URLSearchParams(location.search).has('bench');
let meshArrivedAt = null;
if (bench) window.ruppertBench = { view, renderer, draw: () => draw(), exemptions: () => app.exemptions };
const embedded = isEmbedded();
if (embedded) document.body.classList.add('embed');
const readOnly = !isEditable();

const app = {
  canvas,
  view,
  drawing: emptyDrawing(),
  snap: false,
  mesh: null,           // the latest mesh, or null
  meshedPlc: null,      // the input it was made from (for exports)
  notices: [],
  colorMode: 'angle',
  stepMode: false,
  stepMesh: null,       // step mode: the mesh of the step on screen (StepReplay), else null
  pendingStep: null,    // a step to show once the mesh with its trace arrives (link, host)
  hoverTriangle: -1,
  exemptions: null,     // triangles left skinny on purpose (§6.6) in app.mesh, or null
  writtenHash: '',
  viewMoved: false,     // set by the editor on pan and zoom
  changed: ({ commit }) => {
    if (commit) notPreset();  // an edit on the canvas: no longer the preset
    changed(commit);
  },
  redraw: () => scheduleDraw(),
  undo: () => restore(history.undo()),
  redo: () => restore(history.redo()),
  regionSeed: () => regionSeedFields(),
  hover: (world) => hover(world),
  setTool: (tool) => setTool(tool),
  shortcut: (key) => shortcut(key),
};
const history = new History(app.drawing);
const editor = new Editor(app);
editor.readOnly = readOnly;

// ---------------------------------------------------------------- status
function setStatus(text, kind = 'info') {
  const status = $('status');
  status.textContent = text;
  status.dataset.kind = kind;
}

function showNotices(notices, error = null) {
  const list = $('notices');
  const items = notices.map((n) => {
    const li = document.createElement('li');
    li.className = 'notice';
    li.textContent = `${n.kind}: ${n.message}`;
    return li;
  });
  if (error) {
    const li = document.createElement('li');
    li.className = 'error';
    li.textContent = `${error.code ?? error.name}: ${error.message}`;
    items.unshift(li);
  }
  list.replaceChildren(...items);
}

// ---------------------------------------------------------------- drawing
let drawQueued = false;
function scheduleDraw() {
  if (drawQueued) return;
  drawQueued = true;
  requestAnimationFrame(() => {
    drawQueued = false;
    draw();
  });
}

function draw() {
  if (app.viewMoved) writeHashSoon();
  const step = app.stepMode && app.mesh?.events
    ? { final: app.mesh, events: app.mesh.events, index: stepper.index, shown: app.stepMesh } : null;
  renderer.draw({
    view,
    drawing: app.drawing,
    colorMode: app.colorMode,
    snap: app.snap,
    selection: editor.selection,
    hoverItem: editor.hoverItem,
    hoverTriangle: app.hoverTriangle,
    pendingChain: editor.pendingChain(),
    keyCursor: editor.keyCursor,
    notices: app.notices,
    step,
    exemptions: app.exemptions,
    vertexNumbers: $('vertex-numbers').checked,
  });
  if (meshArrivedAt !== null) {
    renderer.finish();
    document.body.dataset.firstPictureMs = (performance.now() - meshArrivedAt).toFixed(1);
    meshArrivedAt = null;
  }
}

function resize() {
  const wrap = $('canvas-wrap');
  const rect = wrap.getBoundingClientRect();
  view.resize(rect.width, rect.height);
  renderer.resize(rect.width, rect.height, window.devicePixelRatio || 1);
  // Until the user pans or zooms, keep the whole drawing in view as the layout settles.
  if (!app.viewMoved) view.fit(drawingBounds(app.drawing));
  draw();
}
new ResizeObserver(resize).observe($('canvas-wrap'));

function fitView() {
  app.viewMoved = false;
  view.fit(drawingBounds(app.drawing));
  scheduleDraw();
}

// ---------------------------------------------------------------- edits, history, URL
function changed(commit) {
  if (commit) {
    history.commit(app.drawing);
    writeHash();
  }
  updateButtons();
  remesh();
  scheduleDraw();
}

/** Replaces the drawing (preset, file, link, message); `fit` re-centres the view. */
function setDrawing(drawing, { commit = true, fit = true } = {}) {
  app.drawing = cloneDrawing(drawing);
  editor.reset();
  syncOptionFields();
  if (commit) history.commit(app.drawing);
  else history.reset(app.drawing);
  writeHash();
  if (fit) fitView();
  updateButtons();
  remesh(0);
  scheduleDraw();
}

function restore(drawing) {
  if (drawing === null) return;
  app.drawing = drawing;
  notPreset();
  editor.reset();
  syncOptionFields();
  writeHash();
  updateButtons();
  remesh(0);
  scheduleDraw();
}

function updateButtons() {
  $('undo').disabled = !history.canUndo;
  $('redo').disabled = !history.canRedo;
  $('delete-selected').disabled = editor.selection === null;
}

function writeHash() {
  const state = encodePageState({
    step: app.stepMode ? stepper.index : null,
    color: app.colorMode,
    view: app.viewMoved ? { x: view.centerX, y: view.centerY, scale: view.scale } : null,
  });
  const hash = `${encodeDrawing(app.drawing)}${state}`;
  const base = `${location.pathname}${location.search}`;
  // The embed's link to the full page carries the same state.
  $('open-full').href = `${location.pathname}#${hash}`;
  if (hash.length > MAX_HASH_LENGTH) {
    app.writtenHash = '';
    window.history.replaceState(null, '', base);
    return;
  }
  app.writtenHash = `#${hash}`;
  if (location.hash !== app.writtenHash) window.history.replaceState(null, '', `${base}#${hash}`);
}

// Steps, pans and zooms change the link too, but at most a few times a second (browsers throttle
// history.replaceState calls).
let hashTimer = null;
function writeHashSoon() {
  if (hashTimer !== null) return;
  hashTimer = setTimeout(() => { hashTimer = null; writeHash(); }, 300);
}

function readHash() {
  try {
    return decodeDrawing(location.hash);
  } catch (error) {
    setStatus(`The link's drawing could not be read (${error.message}); showing the default drawing.`, 'error');
    return null;
  }
}

window.addEventListener('hashchange', () => {
  if (location.hash === app.writtenHash) return;
  const drawing = readHash();
  if (drawing) setDrawing(drawing);
});

// ---------------------------------------------------------------- meshing
let progressTimer = null;

const scheduler = new MeshScheduler({
  onStart() {
    document.body.dataset.meshState = 'meshing';
    clearTimeout(progressTimer);
    // Show the progress indicator only for work that takes a noticeable time.
    progressTimer = setTimeout(() => {
      $('progress').hidden = false;
      $('cancel').hidden = false;
      $('progress-text').textContent = 'Meshing…';
    }, PROGRESS_DELAY_MS);
  },
  onProgress(p) {
    $('progress-text').textContent =
      `Meshing… ${p.insertedVertices.toLocaleString('en-US')} vertices inserted, ${p.triangles.toLocaleString('en-US')} triangles, worst angle ${p.worstAngle.toFixed(1)}°`;
  },
  onResult(mesh, request) {
    if (bench) {
      meshArrivedAt = performance.now();
      document.body.dataset.meshArrivedAt = String(meshArrivedAt);
    }
    stopProgress();
    app.mesh = mesh;
    app.meshedPlc = request.plc;
    app.notices = mesh.notices;
    app.hoverTriangle = -1;
    app.stepMesh = null;
    renderer.setMesh(mesh);
    showStats(statElements, mesh);
    markExemptions(mesh, request);
    vertexNumbersNote();
    showEventCounts($('stat-events'), mesh);
    showNotices(mesh.notices);
    updateLegend();
    replay.reset(request.plc, request.options, app.stepMode ? mesh : null);
    stepper.setEvents(app.stepMode ? mesh.events : null,
      { points: mesh.points, minAngle: request.options.minAngle, placement: request.options.placement });
    const s = mesh.stats;
    const summary = `${s.triangles.toLocaleString('en-US')} triangles, ${s.vertices.toLocaleString('en-US')} vertices, ` +
      `min angle ${s.minAngle.toFixed(2)}° in ${s.milliseconds.toFixed(1)} ms`;
    if (mesh.notices.length) setStatus(`Meshed with ${mesh.notices.length} repair(s) of the input: ${summary}.`, 'warn');
    else if (!mesh.complete) setStatus(`Meshed, not complete (see Mesh panel): ${summary}.`, 'warn');
    else setStatus(`Meshed: ${summary}.`, 'ok');
    // A result that a newer, still debounced request will replace is shown, but not 'done'.
    document.body.dataset.meshState = scheduler.queued ? 'queued' : 'done';
    document.body.dataset.meshCount = String(Number(document.body.dataset.meshCount ?? 0) + 1);
    postMeshed(mesh, request.id);
    showPendingStep();
    scheduleDraw();
  },
  onError(error, request) {
    stopProgress();
    if (error?.code === 'CANCELLED') {
      setStatus('Meshing cancelled. Change the drawing or a parameter to mesh again.', 'warn');
      // The mesh on screen is an older one: its panel must not claim it answers the new request.
      if (app.mesh) {
        $('stat-complete').textContent = 'cancelled: the mesh shown is of the previous drawing or parameters';
        $('stat-complete').className = 'bad';
      }
      document.body.dataset.meshState = scheduler.queued ? 'queued' : 'cancelled';
      return;
    }
    clearMesh();
    setStatus(`Cannot mesh this drawing: ${error?.message ?? error}`, 'error');
    showNotices([], error);
    document.body.dataset.meshState = scheduler.queued ? 'queued' : 'error';
    postError(error, request?.id ?? null);
    scheduleDraw();
  },
});

function stopProgress() {
  clearTimeout(progressTimer);
  $('progress').hidden = true;
  $('cancel').hidden = true;
  $('progress-text').textContent = '';
}

function clearMesh() {
  app.mesh = null;
  app.meshedPlc = null;
  app.notices = [];
  app.hoverTriangle = -1;
  $('hover-info').hidden = true;
  app.stepMesh = null;
  renderer.setMesh(null);
  showStats(statElements, null);
  app.exemptions = null;
  showExemptions($('stat-exempt'), null);
  showEventCounts($('stat-events'), null);
  replay.clear();
  stepper.setEvents(null);
  updateLegend();
}

function remesh(delay) {
  if (pointCount(app.drawing) < 3) {
    scheduler.clear();
    stopProgress();
    clearMesh();
    showNotices([]);
    setStatus(pointCount(app.drawing) === 0
      ? 'Empty drawing: pick a tool and click on the canvas, or choose a preset.'
      : 'Add at least three points (not all on one line) to mesh.', 'info');
    document.body.dataset.meshState = 'empty';
    return;
  }
  // 'queued' until the result of this very request arrives (tests and hosts can wait for 'done').
  document.body.dataset.meshState = 'queued';
  scheduler.request(toPlc(app.drawing), toMeshOptions(app.drawing, { trace: app.stepMode }), delay, hostId);
  hostId = null;
}

// The id of a host's 'ruppert:load', given to the mesh request it causes (and echoed in the reply).
let hostId = null;

/** Shows the step a link or a host asked for, once the mesh with the trace is there. */
function showPendingStep() {
  if (app.pendingStep === null || !app.stepMode || !app.mesh?.events) return;
  const k = app.pendingStep;
  app.pendingStep = null;
  stepper.pause();
  stepper.go(k);
}

$('cancel').addEventListener('click', () => scheduler.cancel());

// Triangles left skinny on purpose (§6.6), found from the mesh and marked; not looked for in
// meshes above EXEMPTIONS_UP_TO triangles (the search would hold up their first picture).
const EXEMPTIONS_UP_TO = 200_000;
function markExemptions(mesh, request) {
  if (mesh.triangles.length / 3 > EXEMPTIONS_UP_TO) {
    app.exemptions = null;
    $('stat-exempt').textContent = `not looked for above ${EXEMPTIONS_UP_TO.toLocaleString('en-US')} triangles`;
    return;
  }
  app.exemptions = { mesh, ...findExemptions(mesh, request.plc, request.options.minAngle) };
  showExemptions($('stat-exempt'), app.exemptions);
}

// ---------------------------------------------------------------- hover
function hover(world) {
  const info = $('hover-info');
  if (world === null || app.mesh === null) {
    info.hidden = true;
    if (app.hoverTriangle !== -1) { app.hoverTriangle = -1; }
    scheduleDraw();
    return;
  }
  // In step mode the mesh on screen is that of the step shown.
  const mesh = app.stepMesh ?? app.mesh;
  const t = locateTriangle(mesh, world.x, world.y, app.hoverTriangle);
  app.hoverTriangle = t;
  if (t < 0) {
    info.hidden = true;
  } else {
    const shape = triangleShape(mesh, t);
    const kinds = shape.vertices.map((v) => `${v} ${VERTEX_KINDS[mesh.vertexKinds[v]] ?? '?'}`);
    const attribute = mesh.triangleAttributes[t];
    info.textContent = `Triangle ${t}: angles ${shape.angles.map((a) => `${a.toFixed(2)}°`).join(', ')}; ` +
      `radius-edge ratio ${shape.radiusEdge.toFixed(3)}; area ${shape.area.toPrecision(4)}; ` +
      `vertices ${kinds.join(', ')}${attribute ? `; attribute ${attribute}` : ''}`;
    info.hidden = false;
  }
  scheduleDraw();
}

// ---------------------------------------------------------------- tools and shortcuts
function setTool(tool) {
  editor.setTool(tool);
  for (const button of document.querySelectorAll('[data-tool]')) {
    button.setAttribute('aria-pressed', String(button.dataset.tool === tool));
  }
  $('tool-hint').textContent = TOOL_HINTS[tool];
  canvas.style.cursor = tool === 'select' ? 'grab' : 'crosshair';
}
for (const button of document.querySelectorAll('[data-tool]')) {
  button.addEventListener('click', () => setTool(button.dataset.tool));
}

function shortcut(key) {
  switch (key) {
    case 'f': fitView(); return true;
    case 'g': $('snap').checked = !$('snap').checked; setSnap(); return true;
    case 's': $('step-mode').checked = !$('step-mode').checked; setStepMode(); return true;
    case 'k': if (app.stepMode) stepper.toggle(); return app.stepMode;
    case ',': if (app.stepMode) stepper.step(-1); return app.stepMode;
    case '.': if (app.stepMode) stepper.step(1); return app.stepMode;
    case 'home': if (app.stepMode) stepper.go(0); return app.stepMode;
    case 'end': if (app.stepMode) stepper.go(stepper.count); return app.stepMode;
    default: return false;
  }
}

$('undo').addEventListener('click', () => app.undo());
$('redo').addEventListener('click', () => app.redo());
$('delete-selected').addEventListener('click', () => editor.deleteSelection());
$('clear').addEventListener('click', () => setDrawing(emptyDrawing(app.drawing.options), { fit: false }));
$('fit').addEventListener('click', fitView);
function setSnap() {
  app.snap = $('snap').checked;
  scheduleDraw();
}
$('snap').addEventListener('change', setSnap);
// The editor changes the selection on clicks; keep the Delete button's state in step.
canvas.addEventListener('pointerup', () => { updateButtons(); syncRegionFields(); });
canvas.addEventListener('pointerdown', () => queueMicrotask(() => { updateButtons(); syncRegionFields(); }));

// ---------------------------------------------------------------- parameters
const minAngleRange = $('min-angle-range');
const minAngleNumber = $('min-angle');

function readNumber(input) {
  if (input.value.trim() === '') return null;
  const value = Number(input.value);
  return Number.isFinite(value) ? value : null;
}

function syncOptionFields() {
  const o = app.drawing.options;
  minAngleRange.value = String(o.minAngle);
  minAngleNumber.value = String(o.minAngle);
  $('min-angle-warning').hidden = !(o.minAngle > 34);
  $('max-area').value = o.maxArea > 0 ? String(o.maxArea) : '';
  $('placement').value = o.placement;
  $('max-steiner').value = Number.isInteger(o.maxSteiner) ? String(o.maxSteiner) : '';
  $('variant').value = o.variant ?? DEFAULT_OPTIONS.variant;
  $('encroachment').value = o.encroachment ?? DEFAULT_OPTIONS.encroachment;
}

function setMinAngle(value, commit) {
  if (value === null || value < 0 || value > 60) {
    minAngleNumber.setAttribute('aria-invalid', 'true');
    setStatus('Min angle must be a number from 0 to 60 degrees.', 'error');
    return;
  }
  minAngleNumber.removeAttribute('aria-invalid');
  app.drawing.options.minAngle = value;
  $('min-angle-warning').hidden = !(value > 34);
  changed(commit);
}
// The slider re-meshes while it moves and records an undo step once it rests (browsers differ in
// when they fire 'change' for keyboard input, so a short quiet period also commits).
let sliderCommit = null;
minAngleRange.addEventListener('input', () => {
  minAngleNumber.value = minAngleRange.value;
  setMinAngle(Number(minAngleRange.value), false);
  clearTimeout(sliderCommit);
  sliderCommit = setTimeout(() => changed(true), 600);
});
minAngleRange.addEventListener('change', () => {
  clearTimeout(sliderCommit);
  setMinAngle(Number(minAngleRange.value), true);
});
minAngleNumber.addEventListener('input', () => {
  const value = readNumber(minAngleNumber);
  if (value !== null && value >= 0 && value <= 60) minAngleRange.value = String(value);
  setMinAngle(value, false);
});
minAngleNumber.addEventListener('change', () => setMinAngle(readNumber(minAngleNumber), true));

$('max-area').addEventListener('change', () => {
  const value = readNumber($('max-area'));
  app.drawing.options.maxArea = value !== null && value > 0 ? value : null;
  changed(true);
});
$('placement').addEventListener('change', () => {
  app.drawing.options.placement = $('placement').value;
  changed(true);
});
$('variant').addEventListener('change', () => {
  app.drawing.options.variant = $('variant').value;
  changed(true);
});
$('encroachment').addEventListener('change', () => {
  app.drawing.options.encroachment = $('encroachment').value;
  changed(true);
});
$('max-steiner').addEventListener('change', () => {
  const value = readNumber($('max-steiner'));
  app.drawing.options.maxSteiner = value !== null && value >= 0 ? Math.floor(value) : null;
  changed(true);
});

// Region seed fields: values for new seeds, and the selected seed's values.
function regionSeedFields() {
  const attribute = readNumber($('region-attribute')) ?? 0;
  const maxArea = readNumber($('region-max-area'));
  return { attribute, maxArea: maxArea !== null && maxArea > 0 ? maxArea : null };
}
function syncRegionFields() {
  const item = editor.selection;
  if (item?.kind !== Item.REGION) return;
  const region = app.drawing.regions[item.index];
  if (!region) return;
  $('region-attribute').value = String(region.attribute ?? 0);
  $('region-max-area').value = region.maxArea > 0 ? String(region.maxArea) : '';
}
for (const id of ['region-attribute', 'region-max-area']) {
  $(id).addEventListener('change', () => {
    const item = editor.selection;
    if (item?.kind !== Item.REGION || !app.drawing.regions[item.index]) return;
    Object.assign(app.drawing.regions[item.index], regionSeedFields());
    changed(true);
  });
}

// ---------------------------------------------------------------- display and step mode
function updateLegend() {
  const entries = [...legendEntries(app.colorMode, app.mesh), ...exemptionLegend(app.exemptions)];
  $('legend').replaceChildren(...entries.map(({ colour, label, hatched }) => {
    const item = document.createElement('span');
    item.className = 'legend-item';
    const swatch = document.createElement('span');
    swatch.className = 'swatch';
    swatch.style.background = hatched ? `repeating-linear-gradient(135deg, ${colour} 0 2px, #fff 2px 5px)` : colour;
    item.append(swatch, label);
    return item;
  }));
}
// Vertex numbers on demand, for meshes small enough to read them.
function vertexNumbersNote() {
  const note = $('vertex-numbers-note');
  const many = app.mesh && app.mesh.points.length / 2 > VERTEX_NUMBERS_UP_TO;
  note.hidden = !($('vertex-numbers').checked && many);
  note.textContent = `shown for meshes of up to ${VERTEX_NUMBERS_UP_TO.toLocaleString('en-US')} vertices`;
}
$('vertex-numbers').addEventListener('change', () => {
  vertexNumbersNote();
  scheduleDraw();
});

$('color-mode').addEventListener('change', () => {
  app.colorMode = $('color-mode').value;
  updateLegend();
  writeHash();
  scheduleDraw();
});

// The mesh of each step, meshed on demand; shown when it is still the step wanted.
const replay = new StepReplay((k, mesh) => {
  if (!app.stepMode || k !== stepper.index) return;
  app.stepMesh = mesh;
  app.hoverTriangle = -1;
  renderer.setMesh(mesh);
  const { vertices, triangles, minAngle } = mesh.stats;
  $('step-mesh').textContent = `Mesh at step ${k}: ${vertices.toLocaleString('en-US')} vertices, ` +
    `${triangles.toLocaleString('en-US')} triangles, smallest angle ${minAngle.toFixed(2)}°`;
  document.body.dataset.stepShown = String(k);
  const events = app.mesh.events;
  postStepped({
    index: k, total: stepper.count, vertices, triangles,
    event: k > 0 ? describeEvent(events, k - 1, stepper.context) : null,
  });
  scheduleDraw();
});

const stepper = new Stepper({
  first: $('step-first'), back: $('step-back'), play: $('step-play'), forward: $('step-forward'),
  last: $('step-last'), scrub: $('step-scrub'), speed: $('step-speed'), info: $('step-info'),
}, (k) => {
  delete document.body.dataset.stepShown;
  writeHashSoon();
  $('step-mesh').textContent = `Mesh at step ${k}: meshing…`;
  replay.show(k);
  scheduleDraw();
});

function setStepMode() {
  app.stepMode = $('step-mode').checked;
  $('stepper').hidden = !app.stepMode;
  if (!app.stepMode) {
    stepper.pause();
    replay.clear();
    app.stepMesh = null;
    if (app.mesh) renderer.setMesh(app.mesh);
  }
  // Events are recorded only on request (options.trace): mesh again.
  remesh(0);
  scheduleDraw();
}
$('step-mode').addEventListener('change', setStepMode);

const statElements = {
  vertices: $('stat-vertices'), triangles: $('stat-triangles'), minAngle: $('stat-min-angle'),
  maxAngle: $('stat-max-angle'), complete: $('stat-complete'), time: $('stat-time'),
  reasons: $('reasons'), histogram: $('histogram'),
};

// ---------------------------------------------------------------- presets, files, exports
for (const preset of PRESETS) {
  const option = document.createElement('option');
  option.value = preset.id;
  option.textContent = preset.name;
  if (preset.title) option.title = preset.title;
  $('preset').append(option);
}
$('preset').addEventListener('change', () => {
  const value = $('preset').value;
  if (value.startsWith(SHARED_PRESET)) {
    loadSharedPreset(value.slice(SHARED_PRESET.length));
    return;
  }
  applyPreset(findPreset(value), app.drawing.options);
});

/** Loads a preset: its drawing, its options over `base`, its caption, and step mode if it asks. */
function applyPreset(preset, base) {
  showCaption(preset?.caption ?? '');
  if (!preset) return;
  if (preset.steps && !app.stepMode) {
    $('step-mode').checked = true;
    app.stepMode = true;
    $('stepper').hidden = false;
  }
  setDrawing({ ...preset.build(), options: { ...base, ...(preset.options ?? {}) } });
}

/** The drawing is no longer a preset (edited, a file, a message): the box and caption say so. */
function notPreset() {
  $('preset').value = '';
  showCaption('');
}

function showCaption(text) {
  $('preset-caption').textContent = text;
  $('preset-caption').hidden = text === '';
}

// The corpus of real PLCs beside the repository (../shared/data), when the server offers it
// (web/serve.mjs does; a plain static host does not, and the group is simply absent).
const SHARED_PRESET = 'shared:';
async function addSharedPresets() {
  let list;
  try {
    const response = await fetch('../shared-data/index.json', { cache: 'no-cache' });
    if (!response.ok) return;
    list = await response.json();
  } catch {
    return;
  }
  if (!list?.available || !Array.isArray(list.files) || list.files.length === 0) return;
  const group = document.createElement('optgroup');
  group.label = 'Real inputs (../shared/data)';
  group.id = 'shared-presets';
  for (const name of list.files) {
    const option = document.createElement('option');
    option.value = SHARED_PRESET + name;
    option.textContent = name;
    group.append(option);
  }
  $('preset').append(group);
}

async function loadSharedPreset(name) {
  const failed = loading();
  try {
    const response = await fetch(`../shared-data/${encodeURIComponent(name)}`, { cache: 'no-cache' });
    if (!response.ok) throw new Error(`the server answered ${response.status}`);
    const plc = await parseInput(await response.text(), name);
    showCaption('');
    setDrawing(fromPlc(plc, app.drawing.options));
    $('preset').value = SHARED_PRESET + name;
    setStatus(`Loaded ${name}: ${plc.points.length / 2} points, ${plc.segments.length / 2} segments.`, 'ok');
  } catch (error) {
    failed();
    setStatus(`Could not load ${name}: ${error.message}`, 'error');
  }
}
if (!embedded) addSharedPresets();

/** Marks the page busy while a file or message is read, so that nothing waits on an old mesh. */
function loading() {
  const previous = document.body.dataset.meshState;
  document.body.dataset.meshState = 'loading';
  return () => { if (document.body.dataset.meshState === 'loading') document.body.dataset.meshState = previous; };
}

async function loadFile(file) {
  const failed = loading();
  try {
    const text = await file.text();
    const plc = await parseInput(text, file.name);
    notPreset();
    setDrawing(fromPlc(plc, app.drawing.options));
    setStatus(`Loaded ${file.name}: ${plc.points.length / 2} points, ${plc.segments.length / 2} segments.`, 'ok');
  } catch (error) {
    failed();
    setStatus(`Could not load ${file.name}: ${error.message}`, 'error');
    showNotices([], error);
  }
}
$('file-input').addEventListener('change', () => {
  const file = $('file-input').files[0];
  if (file) loadFile(file);
  $('file-input').value = '';
});

const wrap = $('canvas-wrap');
wrap.addEventListener('dragover', (e) => {
  if (![...(e.dataTransfer?.types ?? [])].includes('Files')) return;
  e.preventDefault();
  $('drop-hint').hidden = false;
});
wrap.addEventListener('dragleave', () => { $('drop-hint').hidden = true; });
wrap.addEventListener('drop', (e) => {
  e.preventDefault();
  $('drop-hint').hidden = true;
  const file = e.dataTransfer?.files?.[0];
  if (file) loadFile(file);
});

async function exportAs(format) {
  if (app.mesh === null) {
    setStatus('Nothing to export: the drawing has no mesh yet.', 'error');
    return;
  }
  try {
    if (format === 'png') {
      draw();
      download(await canvasBlob(renderer.snapshot()), 'ruppert-mesh.png', 'png');
    } else {
      download(await exportText(format, app.mesh, app.meshedPlc), `ruppert-mesh.${format}`, format);
    }
    setStatus(`Exported ruppert-mesh.${format}.`, 'ok');
  } catch (error) {
    setStatus(`Export failed: ${error.message}`, 'error');
  }
}
for (const format of ['poly', 'json', 'svg', 'png', 'node', 'ele', 'msh', 'vtu', 'geojson']) $(`export-${format}`).addEventListener('click', () => exportAs(format));
// The drawing needs no mesh: what was drawn, as a .poly another program can mesh.
$('export-drawing').addEventListener('click', () => {
  download(drawingPolyText(toPlc(app.drawing)), 'ruppert-drawing.poly', 'poly');
  setStatus('Exported ruppert-drawing.poly (the drawing, not its mesh).', 'ok');
});

$('copy-link').addEventListener('click', async () => {
  writeHash();
  if (app.writtenHash === '') {
    setStatus('This drawing is too large to fit in a link; export a .poly file instead.', 'warn');
    return;
  }
  try {
    await navigator.clipboard.writeText(location.href);
    setStatus('Link copied: it reproduces this drawing and its parameters.', 'ok');
  } catch {
    setStatus(`Copy this link: ${location.href}`, 'info');
  }
});

// ---------------------------------------------------------------- embedding
listenToHost({
  async onLoad({ poly, options, id }) {
    const failed = loading();
    try {
      const plc = await parsePolyText(poly, '<ruppert:load>');
      hostId = id;
      notPreset();
      setDrawing(fromPlc(plc, { ...DEFAULT_OPTIONS, ...app.drawing.options, ...options }));
    } catch (error) {
      failed();
      setStatus(`Could not load the posted drawing: ${error.message}`, 'error');
      postError(error, id);
    }
  },
  onStep(index) {
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
  },
});

// ---------------------------------------------------------------- start
const linked = readHash();
const pageState = decodePageState(location.hash);
if (!linked) $('preset').value = DEFAULT_PRESET;
if (pageState.color) {
  $('color-mode').value = pageState.color;
  app.colorMode = pageState.color;
}
if (pageState.step !== null) {  // step mode from the link: one mesh, with its trace
  $('step-mode').checked = true;
  app.stepMode = true;
  $('stepper').hidden = false;
  app.pendingStep = pageState.step;
}
setTool(readOnly ? 'select' : 'polyline');
if (readOnly) $('tool-hint').textContent = 'View only: drag to pan, wheel or +/- to zoom, hover a triangle for its angles.';
if (linked) setDrawing(linked, { commit: false });
else {
  const preset = findPreset(DEFAULT_PRESET);
  showCaption(preset.caption ?? '');
  setDrawing({ ...preset.build(), options: { ...DEFAULT_OPTIONS, ...(preset.options ?? {}) } }, { commit: false });
}
if (pageState.view) {
  view.centerX = pageState.view.x;
  view.centerY = pageState.view.y;
  view.scale = pageState.view.scale;
  app.viewMoved = true;
  scheduleDraw();
}
updateLegend();
