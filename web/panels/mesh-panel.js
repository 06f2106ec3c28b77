// The Mesh panel: counts, angle range, completeness with reasons, the angle histogram, the event
// counts and the triangles left skinny on purpose.
import { EventKind } from '../../wasm/index.js';
import { rejectedIsCircumcenter, splitShell, splitsCurve, undoMove } from '../geometry/event-geometry.js';
import { exemptTriangles } from '../geometry/mesh-geometry.js';
import { clearedCanvas } from '../rendering/canvas-2d.js';
import { EVENT_KIND_LABELS, EXEMPTION_LABELS } from '../labels.js';

/**
 * Angles worth seeing against the histogram: Ruppert's guaranteed 20.7°, the 26.45° and 28.6°
 * bounds of later analyses, and the ~34° that off-centers reach in practice (chapter 6.8).
 */
export const REFERENCE_ANGLES = [20.7, 26.45, 28.6, 34];

const format = (value, digits = 2) => (Number.isFinite(value) ? value.toFixed(digits) : '–');

/**
 * The rows of a mesh. `step` ({ k, count }) marks an intermediate step of a replay: refinement
 * stopped there on purpose, so its completeness is the step itself, neutral, with no reasons (the
 * budget that stopped it is the replay's, not the reader's).
 */
export function showStats(elements, mesh, bound = null, step = null) {
  const { vertices, triangles, minAngle, maxAngle, complete, time, reasons, lfsIntegral } = elements;
  if (!mesh) {
    for (const el of [vertices, triangles, minAngle, maxAngle, complete, time, lfsIntegral]) el.textContent = '–';
    reasons.replaceChildren();
    drawHistogram(elements.histogram, null, bound);
    return;
  }
  const s = mesh.stats;
  vertices.textContent = s.vertices.toLocaleString('en-US');
  triangles.textContent = s.triangles.toLocaleString('en-US');
  minAngle.textContent = `${format(s.minAngle)}°`;
  maxAngle.textContent = `${format(s.maxAngle)}°`;
  complete.textContent = step ? `step ${step.k.toLocaleString('en-US')} of ${step.count.toLocaleString('en-US')}: refinement goes on`
    : mesh.complete ? 'yes' : 'no';
  complete.className = step ? 'step' : mesh.complete ? 'good' : 'bad';
  time.textContent = `${format(s.milliseconds, 1)} ms`;
  lfsIntegral.textContent = lfsIntegralText(s);
  reasons.replaceChildren(...(step ? [] : mesh.reasons).map((r) => {
    const li = document.createElement('li');
    li.textContent = `${r.kind} ×${r.count}: ${r.message}`;
    return li;
  }));
  drawHistogram(elements.histogram, s.angleHistogram, bound);
}

/**
 * The size measure row: the integral of 1/lfs² (stats.lfsIntegral, present when the mesh was made
 * with the Size measure flag) and the triangles per unit of it, the ratio a size-optimal mesh keeps
 * bounded.
 */
export function lfsIntegralText(stats) {
  const integral = stats.lfsIntegral;
  if (!(integral > 0)) return 'off (Parameters: Size measure)';
  return `∫1/lfs² = ${integral.toPrecision(4)}; ${(stats.triangles / integral).toPrecision(3)} triangles per unit`;
}

/** A round number at or above `value` (1, 2 or 5 times a power of ten), for the count axis. */
export function niceCeiling(value) {
  if (!(value > 0)) return 1;
  const power = 10 ** Math.floor(Math.log10(value));
  for (const m of [1, 2, 5, 10]) if (m * power >= value) return m * power;
  return 10 * power;
}

// The histogram's colors: bars, the reference angles (dashed), the bound in force (solid, the
// teal no bar has), the axes and their labels.
const HISTOGRAM_COLORS = { bar: '#3b5bdb', reference: '#c92a2a', bound: '#0b7285', axis: '#343a40' };

/**
 * Bars of the 180 one-degree bins over a count axis (0 to a round number at or above the fullest
 * bin), the reference angles as dashed lines and the min-angle bound in force as a solid one, so
 * that the bars left of it are the angles below the bound. canvas.dataset keeps what was drawn
 * (countMax, bound, boundX in CSS pixels) for tests and readers of the page.
 */
export function drawHistogram(canvas, histogram, bound = null) {
  const { ctx, width: cssWidth, height: cssHeight } = clearedCanvas(canvas, 320, 140);
  ctx.font = '10px system-ui, sans-serif';
  let countMax = 0;
  if (histogram && histogram.length) {
    for (const count of histogram) countMax = Math.max(countMax, count);
    countMax = niceCeiling(countMax);
  }
  // Room for the widest count label ("100,000" on a big mesh) and its tick.
  const left = Math.max(34, Math.ceil(ctx.measureText(countMax.toLocaleString('en-US')).width) + 8);
  canvas.dataset.axisLeft = String(left);
  const top = 12;       // room for the bound's label
  const bottom = cssHeight - 16;
  const width = cssWidth - left - 6;
  const x = (angle) => left + (angle / 180) * width;

  ctx.fillStyle = '#f7f8fa';
  ctx.fillRect(left, top, width, bottom - top);
  if (histogram && histogram.length) {
    ctx.fillStyle = HISTOGRAM_COLORS.bar;
    for (let bin = 0; bin < histogram.length; bin++) {
      if (!histogram[bin]) continue;
      const h = Math.max(1, (histogram[bin] / countMax) * (bottom - top));
      ctx.fillRect(x(bin), bottom - h, Math.max(1, width / 180), h);
    }
  }
  ctx.strokeStyle = HISTOGRAM_COLORS.reference;
  ctx.lineWidth = 1;
  ctx.setLineDash([3, 2]);
  for (const angle of REFERENCE_ANGLES) {
    ctx.beginPath();
    ctx.moveTo(Math.round(x(angle)) + 0.5, top);
    ctx.lineTo(Math.round(x(angle)) + 0.5, bottom);
    ctx.stroke();
  }
  ctx.setLineDash([]);
  ctx.font = '10px system-ui, sans-serif';
  ctx.textBaseline = 'alphabetic';
  if (bound > 0) {
    const bx = Math.round(x(bound));  // 2 pixels wide: the pixels either side of bx, both solid
    ctx.strokeStyle = HISTOGRAM_COLORS.bound;
    ctx.lineWidth = 2;
    ctx.beginPath();
    ctx.moveTo(bx, top - 2);
    ctx.lineTo(bx, bottom);
    ctx.stroke();
    ctx.fillStyle = HISTOGRAM_COLORS.bound;
    ctx.textAlign = 'left';
    ctx.fillText(`bound ${Number(bound.toFixed(2))}°`, bx + 3, top - 2);
    canvas.dataset.bound = String(bound);
    canvas.dataset.boundX = String(bx);
  } else {
    delete canvas.dataset.bound;
    delete canvas.dataset.boundX;
  }
  // The axes: counts up the left, angles along the bottom.
  ctx.strokeStyle = HISTOGRAM_COLORS.axis;
  ctx.lineWidth = 1;
  ctx.beginPath();
  ctx.moveTo(left - 0.5, top);
  ctx.lineTo(left - 0.5, bottom + 0.5);
  ctx.lineTo(left + width, bottom + 0.5);
  ctx.stroke();
  ctx.fillStyle = HISTOGRAM_COLORS.axis;
  ctx.textAlign = 'right';
  if (countMax > 0) {
    for (const count of [0, countMax / 2, countMax]) {
      const y = bottom - (count / countMax) * (bottom - top);
      ctx.fillText(count.toLocaleString('en-US'), left - 4, Math.max(y + 3, top + 6));
      ctx.beginPath();
      ctx.moveTo(left - 3, Math.round(y) + 0.5);
      ctx.lineTo(left, Math.round(y) + 0.5);
      ctx.stroke();
    }
  }
  canvas.dataset.countMax = String(countMax);
  ctx.textAlign = 'center';
  for (const angle of [0, 30, 60, 90, 120, 150, 180]) {
    ctx.fillText(`${angle}°`, Math.min(Math.max(x(angle), left + 8), cssWidth - 12), cssHeight - 4);
  }
}

const { SEGMENT_SPLIT, CIRCUMCENTER, OFF_CENTER, REJECTED, PETAL_POINT, OPTIMAL_POINT, RELOCATED } = EventKind;
const L = EVENT_KIND_LABELS;

/** Event names, in the panel's order, and how to tell each from the trace (p: the points before event e). */
const EVENT_NAMES = [
  [L.SEGMENT_SPLIT.midpoint, (ev, e, p) => ev.kind[e] === SEGMENT_SPLIT && splitShell(ev, e, p) === null],
  [L.SEGMENT_SPLIT.curve, splitsCurve],  // off the chord: on a curve (before shells, which stay on it)
  [L.SEGMENT_SPLIT.shell, (ev, e, p) => ev.kind[e] === SEGMENT_SPLIT && splitShell(ev, e, p) !== null],
  [L.CIRCUMCENTER, (ev, e) => ev.kind[e] === CIRCUMCENTER],
  [L.OFF_CENTER, (ev, e) => ev.kind[e] === OFF_CENTER],
  [L.PETAL_POINT, (ev, e) => ev.kind[e] === PETAL_POINT],
  [L.OPTIMAL_POINT, (ev, e) => ev.kind[e] === OPTIMAL_POINT],
  [L.RELOCATED, (ev, e) => ev.kind[e] === RELOCATED],
  [L.REJECTED.circumcenter, (ev, e, p) => ev.kind[e] === REJECTED && rejectedIsCircumcenter(ev, e, p)],
  [L.REJECTED.offCenter, (ev, e, p) => ev.kind[e] === REJECTED && !rejectedIsCircumcenter(ev, e, p)],
];

/**
 * The count of each event kind: [[name, count], ...] (every kind, zeros included). `points`: the
 * final mesh's; each event is measured with the points as they were before it (undoing, from the
 * last event back, the moves of RELOCATED events).
 */
export function countEvents(events, points) {
  const counts = EVENT_NAMES.map(([name]) => [name, 0]);
  let p = points;
  for (let e = events.count - 1; e >= 0; e--) {
    if (events.kind[e] === RELOCATED && p === points) p = Float64Array.from(points);
    undoMove(events, e, p);
    const i = EVENT_NAMES.findIndex(([, is]) => is(events, e, p));
    if (i >= 0) counts[i][1]++;
  }
  return counts;
}

/** The Events row: the nonzero counts, or why there are none. */
export function showEventCounts(element, mesh) {
  if (!mesh) { element.textContent = '–'; return; }
  if (!mesh.events) { element.textContent = 'recorded in step mode'; return; }
  const counts = countEvents(mesh.events, mesh.points).filter(([, n]) => n > 0);
  element.textContent = counts.length === 0 ? 'none'
    : counts.map(([name, n]) => `${n.toLocaleString('en-US')} ${name}${n === 1 ? '' : 's'}`).join(', ');
}

/** The Exempt row: triangles left skinny on purpose (the core's mesh.triangleExemptions), marked on the canvas. */
export function showExemptions(element, exemptions) {
  if (!exemptions) { element.textContent = '–'; return; }
  const { nestled, seditious } = exemptions;
  element.textContent = nestled.length + seditious.length === 0 ? 'none'
    : `${nestled.length} ${EXEMPTION_LABELS.SMALL_INPUT_ANGLE.row}, ${seditious.length} ${EXEMPTION_LABELS.SEDITIOUS_EDGE.row}`;
}

/** The panel's rows in the page (index.html). */
export function createMeshPanel() {
  const $ = (id) => document.getElementById(id);
  const elements = {
    vertices: $('stat-vertices'), triangles: $('stat-triangles'), minAngle: $('stat-min-angle'),
    maxAngle: $('stat-max-angle'), complete: $('stat-complete'), time: $('stat-time'),
    reasons: $('reasons'), histogram: $('histogram'), lfsIntegral: $('stat-size-measure'),
  };

  /** The triangles left skinny on purpose in the mesh (as the core marks them), in the panel: the exemptions or null. */
  function markExemptions(mesh) {
    const found = exemptTriangles(mesh);
    const exemptions = found && { mesh, ...found };
    showExemptions($('stat-exempt'), exemptions);
    return exemptions;
  }

  let final = null;  // the mesh of the drawing (step mode: its last step)
  let bound = null;  // the min angle it was made for: the histogram's solid line
  /** The title says which mesh the rows describe. */
  const title = (text) => { $('stats-title').textContent = text; };

  return {
    /** A new mesh of request.plc: every row; returns its exemptions (or null) for the canvas. */
    show(mesh, request) {
      final = mesh;
      bound = request.options.minAngle;
      title('Mesh');
      showStats(elements, mesh, bound);
      showEventCounts($('stat-events'), mesh);
      return markExemptions(mesh);
    },
    /**
     * Step mode: the counts, angles, completeness and histogram of step k's mesh (of count); the
     * Events and Exempt rows stay those of the whole refinement. Null: the final mesh again.
     */
    showStep(mesh, k = 0, count = 0) {
      if (mesh === null || mesh === final) {
        title(mesh === null ? 'Mesh' : `Mesh at step ${k.toLocaleString('en-US')} of ${count.toLocaleString('en-US')} (the final mesh)`);
        showStats(elements, final, bound);
        return;
      }
      title(`Mesh at step ${k.toLocaleString('en-US')} of ${count.toLocaleString('en-US')}`);
      showStats(elements, mesh, bound, { k, count });
    },
    clear() {
      final = null;
      bound = null;
      title('Mesh');
      showStats(elements, null);
      showExemptions($('stat-exempt'), null);
      showEventCounts($('stat-events'), null);
    },
    /** A cancel: the mesh on screen is an older one, and the panel must not claim it answers. */
    cancelled() {
      $('stat-complete').textContent = 'cancelled: the mesh shown is of the previous drawing or parameters';
      $('stat-complete').className = 'bad';
    },
  };
}
