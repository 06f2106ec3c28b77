// Step mode's overlay: the event that made the step on screen, drawn over that step's mesh on the
// renderer's 2D canvas (render.js calls it after the drawing, in both the WebGL and the 2D paths).
import { EventKind } from '../../wasm/index.js';
import { circumcircle, insertionsBefore, pointsAtStep, splitShell } from '../geometry/event-geometry.js';
import { drawCurveSplit } from './curve-events.js';

// Pink for what the event did, blue for what it answered to; neither is among the angle colors
// (render.js), and the new triangles are hatched, not filled, so their angle colors show through.
export const STEP_COLORS = {
  step: '#d6336c',
  stepSecondary: '#1d4ed8',
  newVertex: '#d6336c',
};

/** The angle at which a vertex encroaches a subsegment (degrees): 90 for the disk, the lens's above. */
export function encroachmentAngle(context) {
  if ((context?.encroachment ?? 'lens') === 'disk') return 90;
  return Math.max(90, 180 - 2 * (context?.minAngle ?? 30));
}

const svg = (body) => `<svg width="22" height="16" viewBox="0 0 22 16" aria-hidden="true">${body}</svg>`;
const P = STEP_COLORS.step;
const B = STEP_COLORS.stepSecondary;

/**
 * The legend of the overlay (every symbol drawStep draws), the encroachment region named as the
 * option in force: [{ svg, label }].
 */
export function stepLegend(context) {
  const angle = encroachmentAngle(context);
  const region = angle === 90
    ? { svg: svg(`<line x1="3" y1="8" x2="19" y2="8" stroke="${P}" stroke-width="3"/><circle cx="11" cy="8" r="7.5" fill="none" stroke="${P}" stroke-dasharray="3 2"/>`),
      label: 'split subsegment and its diametral disk (encroachment: disk)' }
    : { svg: svg(`<line x1="3" y1="8" x2="19" y2="8" stroke="${P}" stroke-width="3"/><path d="M3 8 Q11 1 19 8 Q11 15 3 8" fill="none" stroke="${P}" stroke-dasharray="3 2"/>`),
      label: `split subsegment and its diametral lens (encroachment: lens, angle ≥ ${Number(angle.toFixed(2))}°)` };
  return [
    { svg: svg(`<circle cx="11" cy="8" r="5" fill="${P}" stroke="#fff" stroke-width="1.5"/>`), label: 'the new vertex' },
    { svg: svg(`<rect x="2" y="2" width="18" height="12" fill="url(#h)" stroke="${P}"/><defs><pattern id="h" width="4" height="4" patternUnits="userSpaceOnUse" patternTransform="rotate(45)"><line x1="0" y1="0" x2="0" y2="4" stroke="${P}" stroke-width="1.5"/></pattern></defs>`),
      label: 'its triangles (the cavity it retriangulated)' },
    { svg: svg(`<path d="M2 14 L20 14 L8 3 Z" fill="none" stroke="${P}" stroke-width="2" stroke-dasharray="4 2"/>`), label: 'the triangle split, where it was' },
    { svg: svg(`<circle cx="11" cy="8" r="6.5" fill="none" stroke="${P}" stroke-width="1.5" stroke-dasharray="3 2"/>`), label: 'its circumcircle' },
    { svg: svg(`<circle cx="11" cy="8" r="5" fill="#fff" stroke="${P}" stroke-width="2.5"/>`), label: 'a circumcenter considered (Fig. 6.4 (d))' },
    region,
    ...(context?.curves?.length ? [{ svg: svg(`<path d="M3 12 Q11 0 19 12" fill="none" stroke="${P}" stroke-width="3"/><line x1="3" y1="12" x2="19" y2="12" stroke="${P}" stroke-dasharray="3 2"/>`),
      label: 'a curve\'s piece split on the curve (its chord dashed, with the chord\'s diametral disk)' }] : []),
    { svg: svg(`<circle cx="11" cy="8" r="4.5" fill="${B}" stroke="#fff" stroke-width="1.5"/>`), label: 'the encroaching vertex' },
    { svg: svg(`<path d="M5 2 L17 14 M17 2 L5 14" stroke="${B}" stroke-width="3"/>`), label: 'a rejected point (its triangle dashed blue)' },
    { svg: svg(`<circle cx="11" cy="8" r="6.5" fill="none" stroke="${B}" stroke-width="1.5" stroke-dasharray="3 2"/>`), label: 'a concentric shell (§6.6)' },
    { svg: svg(`<path d="M11 1 L18 8 L11 15 L4 8 Z" fill="none" stroke="${B}" stroke-width="2"/>`), label: 'a petal or optimal point' },
    { svg: svg(`<path d="M3 12 L18 4 M18 4 L12 4 M18 4 L15 9" fill="none" stroke="${B}" stroke-width="2"/>`), label: 'a relocated vertex' },
  ];
}

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
  if (!events || events.count === 0) return;
  // Fig. 6.4 (d): the next event's triangle and its circumcenter, considered before anything happens.
  // Alone: the step's own event is the stage before (c), not what (d) shows.
  if (step.stage?.preview && index < events.count) {
    drawConsidered(ctx, step, view, world, screen, px);
    return;
  }
  if (index === 0) return;
  // The step after the last event: the smoothing of a smoothed mesh.
  if (index > events.count) {
    if (step.smoothed) drawSmoothingMoves(ctx, final.points, step.smoothed.points, view);
    return;
  }
  const e = index - 1;
  const p = pointsAtStep(events, e, final.points);
  const at = (v) => view.toScreen(p[2 * v], p[2 * v + 1]);
  if (showsStep(step, mesh)) drawNewTriangles(ctx, step.shown, events.vertex[e], world, screen, px);

  const circle = (cx, cy, r, color) => {
    world();
    ctx.beginPath(); ctx.arc(cx, cy, r, 0, 2 * Math.PI);
    ctx.strokeStyle = color; ctx.lineWidth = 1.5 * px; ctx.setLineDash([6 * px, 4 * px]); ctx.stroke();
    ctx.setLineDash([]);
    screen();
  };
  const line = (a, b, color, width) => {
    const qa = at(a); const qb = at(b);
    ctx.beginPath(); ctx.moveTo(qa.x, qa.y); ctx.lineTo(qb.x, qb.y);
    ctx.strokeStyle = color; ctx.lineWidth = width; ctx.stroke();
  };
  // The triangle split is gone from this step's mesh: drawn as an outline where it was.
  const triangle = (color) => {
    const [i, j, k] = [events.triangle[3 * e], events.triangle[3 * e + 1], events.triangle[3 * e + 2]];
    const qi = at(i); const qj = at(j); const qk = at(k);
    ctx.beginPath(); ctx.moveTo(qi.x, qi.y); ctx.lineTo(qj.x, qj.y); ctx.lineTo(qk.x, qk.y); ctx.closePath();
    ctx.strokeStyle = color; ctx.lineWidth = 2.5; ctx.setLineDash([5, 3]); ctx.stroke(); ctx.setLineDash([]);
    const c = circumcircle(p, i, j, k);
    if (c) circle(c.x, c.y, c.r, color);
  };
  const subsegment = (color) => {
    const a = events.a[e]; const b = events.b[e];
    line(a, b, color, 4);
    encroachmentRegion(ctx, p, a, b, encroachmentAngle(step.context), color, world, screen, px);
  };
  const marker = (x, y, color, r = 6) => {
    const q = view.toScreen(x, y);
    ctx.beginPath(); ctx.arc(q.x, q.y, r, 0, 2 * Math.PI);
    ctx.fillStyle = color; ctx.fill();
    ctx.strokeStyle = '#fff'; ctx.lineWidth = 2; ctx.stroke();
  };

  const kind = events.kind[e];
  // A curve's piece split: the stretch of curve, its chord and the chord's disk, instead of the subsegment's.
  const curve = drawCurveSplit(ctx, p, events, e, step.context, STEP_COLORS.step, world, screen, px);
  if (kind === EventKind.SEGMENT_SPLIT) {
    if (!curve) subsegment(STEP_COLORS.step);
    // A concentric-shell split (§6.6): the shell around the corner vertex, through the new vertex.
    const shell = curve ? null : splitShell(events, e, p);
    if (shell !== null) circle(p[2 * shell.center], p[2 * shell.center + 1], shell.radius, STEP_COLORS.stepSecondary);
    const by = events.by[e];
    if (by >= 0) marker(p[2 * by], p[2 * by + 1], STEP_COLORS.stepSecondary, 5);  // the encroaching vertex
  } else if (kind === EventKind.CIRCUMCENTER || kind === EventKind.OFF_CENTER) {
    triangle(STEP_COLORS.step);
  } else if (kind === EventKind.PETAL_POINT || kind === EventKind.OPTIMAL_POINT) {  // a diamond round the point chosen
    triangle(STEP_COLORS.step);
    const q = view.toScreen(events.xy[2 * e], events.xy[2 * e + 1]);
    ctx.beginPath();
    ctx.moveTo(q.x, q.y - 12); ctx.lineTo(q.x + 12, q.y); ctx.lineTo(q.x, q.y + 12); ctx.lineTo(q.x - 12, q.y); ctx.closePath();
    ctx.strokeStyle = STEP_COLORS.stepSecondary; ctx.lineWidth = 2.5; ctx.stroke();
  } else if (kind === EventKind.RELOCATED) {  // the skinny triangle as it was, and the move
    triangle(STEP_COLORS.stepSecondary);
    const from = view.toScreen(events.circumcenter[2 * e], events.circumcenter[2 * e + 1]);
    const to = view.toScreen(events.xy[2 * e], events.xy[2 * e + 1]);
    const angle = Math.atan2(to.y - from.y, to.x - from.x);
    ctx.beginPath();
    ctx.moveTo(from.x, from.y); ctx.lineTo(to.x, to.y);
    for (const side of [-1, 1]) {
      ctx.moveTo(to.x, to.y);
      ctx.lineTo(to.x - 10 * Math.cos(angle + side * 0.45), to.y - 10 * Math.sin(angle + side * 0.45));
    }
    ctx.strokeStyle = STEP_COLORS.stepSecondary; ctx.lineWidth = 2.5; ctx.stroke();
    ctx.beginPath(); ctx.arc(from.x, from.y, 4, 0, 2 * Math.PI);
    ctx.strokeStyle = STEP_COLORS.stepSecondary; ctx.lineWidth = 2; ctx.stroke();
  } else if (kind === EventKind.REJECTED) {
    triangle(STEP_COLORS.stepSecondary);
    if (!curve) subsegment(STEP_COLORS.step);
    const q = view.toScreen(events.circumcenter[2 * e], events.circumcenter[2 * e + 1]);
    ctx.beginPath();
    ctx.moveTo(q.x - 6, q.y - 6); ctx.lineTo(q.x + 6, q.y + 6);
    ctx.moveTo(q.x + 6, q.y - 6); ctx.lineTo(q.x - 6, q.y + 6);
    ctx.strokeStyle = STEP_COLORS.stepSecondary; ctx.lineWidth = 3; ctx.stroke();
  }
  marker(events.xy[2 * e], events.xy[2 * e + 1], STEP_COLORS.newVertex, 6);
  // The numbers the event's text names, whether or not every vertex is numbered.
  const named = kind === EventKind.SEGMENT_SPLIT ? [events.a[e], events.b[e], events.by[e]]
    : [events.triangle[3 * e], events.triangle[3 * e + 1], events.triangle[3 * e + 2],
      ...(kind === EventKind.REJECTED ? [events.a[e], events.b[e]] : [])];
  // The new vertex first: where labels crowd, its number is the one kept.
  labelVertices(ctx, [events.vertex[e], ...named].filter((v) => v >= 0), p, view);
}

/**
 * Where labels of the given size go beside their points: for each { x, y, width, height }, the
 * first of four corners (above right, above left, below right, below left) whose box overlaps no
 * label already placed, or null when all four do (a crowded label is left out rather than drawn
 * over another). Returns [{ x, y } (the box's left and bottom) | null], in the given order.
 */
export function placeLabels(labels, gap = 4) {
  const placed = [];
  const overlaps = (a, b) => a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
  return labels.map(({ x, y, width, height }) => {
    for (const [dx, dy] of [[gap + 1, -gap], [-gap - width, -gap], [gap + 1, gap + height], [-gap - width, gap + height]]) {
      const box = { left: x + dx, right: x + dx + width, bottom: y + dy, top: y + dy - height };
      if (placed.some((other) => overlaps(box, other))) continue;
      placed.push(box);
      return { x: box.left, y: box.bottom };
    }
    return null;
  });
}

/**
 * Vertex numbers beside the given vertices (a white halo keeps them legible over any color), the
 * first given first; where they crowd, a later one moves to another corner or is left out.
 */
function labelVertices(ctx, ids, p, view) {
  ctx.font = 'bold 12px system-ui, sans-serif';
  ctx.textAlign = 'left';
  ctx.textBaseline = 'bottom';
  ctx.lineJoin = 'round';
  const unique = [...new Set(ids)];
  const labels = unique.map((v) => {
    const q = view.toScreen(p[2 * v], p[2 * v + 1]);
    return { x: q.x, y: q.y, width: ctx.measureText(String(v)).width, height: 12 };
  });
  placeLabels(labels).forEach((at, i) => {
    if (at === null) return;
    const text = String(unique[i]);
    ctx.strokeStyle = '#fff'; ctx.lineWidth = 3; ctx.strokeText(text, at.x, at.y);
    ctx.fillStyle = '#111827'; ctx.fillText(text, at.x, at.y);
  });
}

/**
 * The region of points that encroach subsegment ab: those that see it at `angle` degrees or more.
 * 90: the diametral disk; above: the lens, two arcs of circles of radius |ab| / (2 sin angle)
 * through a and b, their centers |cos angle| times that radius from the midpoint on either side.
 */
export function encroachmentRegion(ctx, p, a, b, angle, color, world, screen, px) {
  const ax = p[2 * a]; const ay = p[2 * a + 1];
  const dx = p[2 * b] - ax; const dy = p[2 * b + 1] - ay;
  const length = Math.hypot(dx, dy);
  if (length === 0) return;
  const mx = ax + dx / 2; const my = ay + dy / 2;
  const phi = (angle * Math.PI) / 180;
  const r = length / (2 * Math.sin(phi));
  const h = r * Math.abs(Math.cos(phi));
  const half = Math.PI - phi;  // half the angle the arc spans at its center
  const normal = Math.atan2(dx, -dy);  // (−dy, dx) / length: the normal's direction
  world();
  ctx.strokeStyle = color; ctx.lineWidth = 1.5 * px; ctx.setLineDash([6 * px, 4 * px]);
  for (const side of [1, -1]) {
    // The arc on this side of ab belongs to the circle centered on the other side.
    const cx = mx - side * h * Math.cos(normal); const cy = my - side * h * Math.sin(normal);
    const towards = side === 1 ? normal : normal + Math.PI;
    ctx.beginPath(); ctx.arc(cx, cy, r, towards - half, towards + half); ctx.stroke();
  }
  ctx.setLineDash([]);
  screen();
}

/** The next event's triangle, its circumcircle and circumcenter c, drawn as considered (Fig. 6.4 (d)). */
function drawConsidered(ctx, step, view, world, screen, px) {
  const { events, index: e, final } = step;
  if (events.kind[e] === EventKind.SEGMENT_SPLIT || events.kind[e] === EventKind.RELOCATED) return;
  const p = pointsAtStep(events, e, final.points);
  const [i, j, k] = [events.triangle[3 * e], events.triangle[3 * e + 1], events.triangle[3 * e + 2]];
  const q = [i, j, k].map((v) => view.toScreen(p[2 * v], p[2 * v + 1]));
  ctx.beginPath(); ctx.moveTo(q[0].x, q[0].y); ctx.lineTo(q[1].x, q[1].y); ctx.lineTo(q[2].x, q[2].y); ctx.closePath();
  ctx.strokeStyle = STEP_COLORS.step; ctx.lineWidth = 2.5; ctx.setLineDash([5, 3]); ctx.stroke(); ctx.setLineDash([]);
  const c = circumcircle(p, i, j, k);
  if (!c) return;
  world();
  ctx.beginPath(); ctx.arc(c.x, c.y, c.r, 0, 2 * Math.PI);
  ctx.strokeStyle = STEP_COLORS.step; ctx.lineWidth = 1.5 * px; ctx.setLineDash([6 * px, 4 * px]); ctx.stroke(); ctx.setLineDash([]);
  screen();
  const at = view.toScreen(c.x, c.y);
  ctx.beginPath(); ctx.arc(at.x, at.y, 6, 0, 2 * Math.PI);
  ctx.fillStyle = '#fff'; ctx.fill(); ctx.strokeStyle = STEP_COLORS.step; ctx.lineWidth = 2.5; ctx.stroke();
  ctx.font = 'bold 14px system-ui, sans-serif'; ctx.textAlign = 'left'; ctx.textBaseline = 'bottom';
  ctx.fillStyle = STEP_COLORS.step; ctx.fillText('c', at.x + 8, at.y - 6);
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
  // The pattern in device pixels, not world units: undo the world transform for it.
  const pattern = hatch(ctx);
  pattern.setTransform(ctx.getTransform().inverse());
  ctx.fillStyle = pattern;
  ctx.fill(path);
  ctx.strokeStyle = STEP_COLORS.newVertex;
  ctx.lineWidth = 1.5 * px;
  ctx.stroke(path);
  screen();
}

let hatchPattern = null;
/** Diagonal pink lines, 6 pixels apart: the new triangles stay readable over their angle colors. */
function hatch(ctx) {
  if (hatchPattern) return hatchPattern.pattern;
  const tile = document.createElement('canvas');
  tile.width = 6; tile.height = 6;
  const t = tile.getContext('2d');
  t.strokeStyle = STEP_COLORS.newVertex; t.lineWidth = 1.5;
  t.beginPath(); t.moveTo(-1, 7); t.lineTo(7, -1); t.moveTo(5, 7); t.lineTo(7, 5); t.moveTo(-1, 1); t.lineTo(1, -1); t.stroke();
  hatchPattern = { pattern: ctx.createPattern(tile, 'repeat') };
  return hatchPattern.pattern;
}

/** The smoothing step: a short line from each vertex's refined place to its smoothed one, ending in a dot. */
function drawSmoothingMoves(ctx, before, after, view) {
  ctx.strokeStyle = STEP_COLORS.step;
  ctx.fillStyle = STEP_COLORS.step;
  ctx.lineWidth = 1.5;
  const n = Math.min(before.length, after.length) / 2;
  for (let v = 0; v < n; v++) {
    if (before[2 * v] === after[2 * v] && before[2 * v + 1] === after[2 * v + 1]) continue;
    const from = view.toScreen(before[2 * v], before[2 * v + 1]);
    const to = view.toScreen(after[2 * v], after[2 * v + 1]);
    ctx.beginPath(); ctx.moveTo(from.x, from.y); ctx.lineTo(to.x, to.y); ctx.stroke();
    ctx.beginPath(); ctx.arc(to.x, to.y, 2, 0, 2 * Math.PI); ctx.fill();
  }
}
