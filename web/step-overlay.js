// Step mode's overlay: the event that made the step on screen, drawn over that step's mesh on the
// renderer's 2D canvas (render.js calls it after the drawing, in both the WebGL and the 2D paths).
import { EventKind } from '../wasm/index.js';
import { circumcircle, insertionsBefore, pointsAtStep, splitShell } from './event-geometry.js';

const STEP_COLOURS = {
  step: '#d6336c',
  stepSecondary: '#1d4ed8',
  newVertex: '#d6336c',
};

/**
 * Whether `mesh`, the mesh on screen, is that of step s.index (it arrives from a worker): it has the
 * input's points plus one per insertion among the first s.index events (a RELOCATED event moves a
 * vertex and adds none).
 */
export function showsStep(step, mesh) {
  if (step.shown === null || step.shown !== mesh) return false;
  const { events } = step;
  const added = (k) => insertionsBefore(events, k);
  return step.shown.points.length === step.final.points.length - 2 * (added(events.count) - added(step.index));
}

/**
 * Step mode: the event that made step `index` (the index-th event) drawn over that step's
 * mesh: its new triangles (the star of the new vertex: the cavity it retriangulated), the
 * skinny triangle and its circumcircle, the encroached subsegment and its diametral circle, the
 * rejected point; for a RELOCATED event, the move, as an arrow from where the vertex was. Vertex
 * numbers are those of the final mesh, the same in every step; their places are those before the
 * event (pointsAtStep: later moves undone). `mesh`:
 * the renderer's mesh on screen; `world`/`screen` set the context's transform, `px` one CSS pixel.
 */
export function drawStep(ctx, mesh, step, view, world, screen, px) {
  const { final, events, index } = step;
  if (!events || events.count === 0 || index === 0) return;
  const e = index - 1;
  const p = pointsAtStep(events, e, final.points);
  const at = (v) => view.toScreen(p[2 * v], p[2 * v + 1]);
  if (showsStep(step, mesh)) drawNewTriangles(ctx, step.shown, events.vertex[e], world, screen, px);

  const circle = (cx, cy, r, colour) => {
    world();
    ctx.beginPath(); ctx.arc(cx, cy, r, 0, 2 * Math.PI);
    ctx.strokeStyle = colour; ctx.lineWidth = 1.5 * px; ctx.setLineDash([6 * px, 4 * px]); ctx.stroke();
    ctx.setLineDash([]);
    screen();
  };
  const line = (a, b, colour, width) => {
    const qa = at(a); const qb = at(b);
    ctx.beginPath(); ctx.moveTo(qa.x, qa.y); ctx.lineTo(qb.x, qb.y);
    ctx.strokeStyle = colour; ctx.lineWidth = width; ctx.stroke();
  };
  // The triangle split is gone from this step's mesh: drawn as an outline where it was.
  const triangle = (colour) => {
    const [i, j, k] = [events.triangle[3 * e], events.triangle[3 * e + 1], events.triangle[3 * e + 2]];
    const qi = at(i); const qj = at(j); const qk = at(k);
    ctx.beginPath(); ctx.moveTo(qi.x, qi.y); ctx.lineTo(qj.x, qj.y); ctx.lineTo(qk.x, qk.y); ctx.closePath();
    ctx.strokeStyle = colour; ctx.lineWidth = 2.5; ctx.setLineDash([5, 3]); ctx.stroke(); ctx.setLineDash([]);
    const c = circumcircle(p, i, j, k);
    if (c) circle(c.x, c.y, c.r, colour);
  };
  const subsegment = (colour) => {
    const a = events.a[e]; const b = events.b[e];
    line(a, b, colour, 4);
    // The diametral circle: centred at the midpoint, through both endpoints.
    const mx = (p[2 * a] + p[2 * b]) / 2; const my = (p[2 * a + 1] + p[2 * b + 1]) / 2;
    circle(mx, my, Math.hypot(p[2 * b] - p[2 * a], p[2 * b + 1] - p[2 * a + 1]) / 2, colour);
  };
  const marker = (x, y, colour, r = 6) => {
    const q = view.toScreen(x, y);
    ctx.beginPath(); ctx.arc(q.x, q.y, r, 0, 2 * Math.PI);
    ctx.fillStyle = colour; ctx.fill();
    ctx.strokeStyle = '#fff'; ctx.lineWidth = 2; ctx.stroke();
  };

  const kind = events.kind[e];
  if (kind === EventKind.SEGMENT_SPLIT) {
    subsegment(STEP_COLOURS.step);
    // A concentric-shell split (§6.6): the shell around the corner vertex, through the new vertex.
    const shell = splitShell(events, e, p);
    if (shell !== null) circle(p[2 * shell.center], p[2 * shell.center + 1], shell.radius, STEP_COLOURS.stepSecondary);
    const by = events.by[e];
    if (by >= 0) marker(p[2 * by], p[2 * by + 1], STEP_COLOURS.stepSecondary, 5);  // the encroaching vertex
  } else if (kind === EventKind.CIRCUMCENTER || kind === EventKind.OFF_CENTER) {
    triangle(STEP_COLOURS.step);
  } else if (kind === EventKind.PETAL_POINT || kind === EventKind.OPTIMAL_POINT) {  // a diamond round the point chosen
    triangle(STEP_COLOURS.step);
    const q = view.toScreen(events.xy[2 * e], events.xy[2 * e + 1]);
    ctx.beginPath();
    ctx.moveTo(q.x, q.y - 12); ctx.lineTo(q.x + 12, q.y); ctx.lineTo(q.x, q.y + 12); ctx.lineTo(q.x - 12, q.y); ctx.closePath();
    ctx.strokeStyle = STEP_COLOURS.stepSecondary; ctx.lineWidth = 2.5; ctx.stroke();
  } else if (kind === EventKind.RELOCATED) {  // the skinny triangle as it was, and the move
    triangle(STEP_COLOURS.stepSecondary);
    const from = view.toScreen(events.circumcenter[2 * e], events.circumcenter[2 * e + 1]);
    const to = view.toScreen(events.xy[2 * e], events.xy[2 * e + 1]);
    const angle = Math.atan2(to.y - from.y, to.x - from.x);
    ctx.beginPath();
    ctx.moveTo(from.x, from.y); ctx.lineTo(to.x, to.y);
    for (const side of [-1, 1]) {
      ctx.moveTo(to.x, to.y);
      ctx.lineTo(to.x - 10 * Math.cos(angle + side * 0.45), to.y - 10 * Math.sin(angle + side * 0.45));
    }
    ctx.strokeStyle = STEP_COLOURS.stepSecondary; ctx.lineWidth = 2.5; ctx.stroke();
    ctx.beginPath(); ctx.arc(from.x, from.y, 4, 0, 2 * Math.PI);
    ctx.strokeStyle = STEP_COLOURS.stepSecondary; ctx.lineWidth = 2; ctx.stroke();
  } else if (kind === EventKind.REJECTED) {
    triangle(STEP_COLOURS.stepSecondary);
    subsegment(STEP_COLOURS.step);
    const q = view.toScreen(events.circumcenter[2 * e], events.circumcenter[2 * e + 1]);
    ctx.beginPath();
    ctx.moveTo(q.x - 6, q.y - 6); ctx.lineTo(q.x + 6, q.y + 6);
    ctx.moveTo(q.x + 6, q.y - 6); ctx.lineTo(q.x - 6, q.y + 6);
    ctx.strokeStyle = STEP_COLOURS.stepSecondary; ctx.lineWidth = 3; ctx.stroke();
  }
  marker(events.xy[2 * e], events.xy[2 * e + 1], STEP_COLOURS.newVertex, 6);
}

/** The triangles of `mesh` around vertex v, filled: what the insertion of v created. */
function drawNewTriangles(ctx, mesh, v, world, screen, px) {
  const tri = mesh.triangles;
  const p = mesh.points;
  const path = new Path2D();
  for (let t = 0; t < tri.length; t += 3) {
    if (tri[t] !== v && tri[t + 1] !== v && tri[t + 2] !== v) continue;
    path.moveTo(p[2 * tri[t]], p[2 * tri[t] + 1]);
    path.lineTo(p[2 * tri[t + 1]], p[2 * tri[t + 1] + 1]);
    path.lineTo(p[2 * tri[t + 2]], p[2 * tri[t + 2] + 1]);
    path.closePath();
  }
  world();
  ctx.fillStyle = 'rgba(250, 204, 21, 0.45)';
  ctx.fill(path);
  ctx.strokeStyle = STEP_COLOURS.newVertex;
  ctx.lineWidth = 1.5 * px;
  ctx.stroke(path);
  screen();
}
