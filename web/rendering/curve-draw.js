// The drawing's curves on the 2D canvas (render.js calls drawCurves after the segments): each as
// the true arc or cubic, not its chords, in its marker's color like a segment, with its marker
// written at its middle; the selected or hovered one thick; when the page may be edited, the
// handles (an arc's center, with thin lines to its ends; a Bézier's controls, with lines to the
// ends they belong to); and the curve a curve tool is making, dashed up to the pointer.
import { COLORS, markerColor } from './colors.js';
import { curveShape, curvesOf, handlesOf } from '../model/curve-data.js';
import { pointAt, tracePath } from '../model/curve-geometry.js';

const HANDLE_COLOR = '#5f6b7a';

/**
 * @param {CanvasRenderingContext2D} ctx the renderer's 2D context
 * @param {object} s the frame (render.js's draw): drawing, view, selection, hoverItem, and
 *   curveHandles (whether to show handles), curvePreview (CurveTools.preview())
 * @param {() => void} world, screen set the context's transform; `px` one CSS pixel in world units
 */
export function drawCurves(ctx, s, world, screen, px) {
  const d = s.drawing;
  const curves = curvesOf(d);
  const is = (item, kind, k) => item?.kind === kind && item.index === k;
  world();
  ctx.lineCap = 'round';
  curves.forEach((c, k) => {
    const path = new Path2D();
    tracePath(path, curveShape(d, k));
    ctx.strokeStyle = markerColor(c.marker ?? 0);
    ctx.lineWidth = 2.5 * px;
    ctx.stroke(path);
    const chosen = is(s.selection, 'curve', k) || is(s.selection, 'handle', k);
    if (chosen || is(s.hoverItem, 'curve', k)) {
      ctx.strokeStyle = chosen ? COLORS.selected : COLORS.hover;
      ctx.lineWidth = 4 * px;
      ctx.stroke(path);
    }
  });
  screen();
  if (s.curveHandles) curves.forEach((_, k) => drawHandles(ctx, s, k));
  drawCurveMarkers(ctx, d, s.view);
  if (s.curvePreview) drawPreview(ctx, s.curvePreview, s.view, world, screen, px);
}

/** Curve k's handles, and thin lines from them to the ends they shape. */
function drawHandles(ctx, s, k) {
  const d = s.drawing;
  const c = d.curves[k];
  const view = s.view;
  const end = (i) => view.toScreen(d.points[2 * i], d.points[2 * i + 1]);
  ctx.setLineDash([3, 3]);
  ctx.lineWidth = 1;
  ctx.strokeStyle = HANDLE_COLOR;
  for (const h of handlesOf(d, k)) {
    const q = view.toScreen(h.x, h.y);
    ctx.beginPath();
    const ends = h.which === 'center' ? [c.from, c.to] : [h.which === 'c1' ? c.from : c.to];
    for (const i of ends) { const e = end(i); ctx.moveTo(q.x, q.y); ctx.lineTo(e.x, e.y); }
    ctx.stroke();
  }
  ctx.setLineDash([]);
  for (const h of handlesOf(d, k)) {
    const q = view.toScreen(h.x, h.y);
    const item = { kind: 'handle', index: k, which: h.which };
    const same = (x) => x?.kind === item.kind && x.index === k && x.which === h.which;
    ctx.beginPath();
    if (h.which === 'center') ctx.rect(q.x - 4.5, q.y - 4.5, 9, 9);
    else ctx.arc(q.x, q.y, 4.5, 0, 2 * Math.PI);
    ctx.fillStyle = '#fff';
    ctx.fill();
    ctx.strokeStyle = same(s.selection) ? COLORS.selected : same(s.hoverItem) ? COLORS.hover : HANDLE_COLOR;
    ctx.lineWidth = 2;
    ctx.stroke();
  }
}

/** Each marked curve's marker at its middle, as render.js writes segments' markers. */
function drawCurveMarkers(ctx, d, view) {
  ctx.font = 'bold 11px system-ui, sans-serif';
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  ctx.lineJoin = 'round';
  curvesOf(d).forEach((c, k) => {
    if (!c.marker) return;
    const [x, y] = pointAt(curveShape(d, k), 0.5);
    const q = view.toScreen(x, y);
    ctx.strokeStyle = '#fff'; ctx.lineWidth = 3; ctx.strokeText(String(c.marker), q.x, q.y);
    ctx.fillStyle = markerColor(c.marker); ctx.fillText(String(c.marker), q.x, q.y);
  });
  ctx.textBaseline = 'alphabetic';
}

/** The curve being made: its shape so far, dashed; a dashed line for a radius or a first end; its clicks. */
function drawPreview(ctx, preview, view, world, screen, px) {
  ctx.strokeStyle = COLORS.hover;
  if (preview.shape) {
    world();
    ctx.beginPath();
    tracePath(ctx, preview.shape);
    ctx.lineWidth = 2 * px;
    ctx.setLineDash([6 * px, 4 * px]);
    ctx.stroke();
    screen();
  }
  ctx.lineWidth = 1.5;
  ctx.setLineDash([6, 4]);
  if (preview.from && preview.to) {
    const a = view.toScreen(...preview.from);
    const b = view.toScreen(...preview.to);
    ctx.beginPath(); ctx.moveTo(a.x, a.y); ctx.lineTo(b.x, b.y); ctx.stroke();
  }
  ctx.setLineDash([]);
  for (const mark of preview.marks) {
    const q = view.toScreen(...mark);
    ctx.beginPath(); ctx.arc(q.x, q.y, 5, 0, 2 * Math.PI); ctx.stroke();
  }
}
