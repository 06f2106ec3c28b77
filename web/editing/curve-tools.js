// The editor's curve tools and what the Select tool does with curves.
//
//   circle  press at the center, drag to a point of the circle, release (or click the center, then
//           click the point): that point and the one opposite it, and two arcs between them, a
//           closed curve (an outer boundary, or a hole with a hole seed inside).
//   arc     click its start (an existing vertex or a new one), its end, then its center: the click
//           goes to the nearest point of the ends' perpendicular bisector, so both ends lie on the
//           circle; the arc runs counter-clockwise from start to end (the preview shows which way).
//   bezier  click its start, its end, then its two control points.
// Nothing is added until the curve is complete (one undo step); Esc or another tool drops it.
// With Select, a curve is picked by its stroke and dragged whole; its handles (an arc's center, a
// Bézier's controls) are dragged as curve-data.js's rules say, which keep every arc valid.
import { Item, addPoint, hitTest, moveItem } from '../model/drawing.js';
import { CurveItem, cloneCurves, curveShape, curvesOf, followPoints, handlesOf, twinArcs } from '../model/curve-data.js';
import { distanceTo, onBisector, segmentDistance2, shapeOf } from '../model/curve-geometry.js';

export const CURVE_TOOLS = Object.freeze(['circle', 'arc', 'bezier']);
export const isCurveTool = (tool) => CURVE_TOOLS.includes(tool);

export const CURVE_TOOL_HINTS = {
  circle: 'Circle: press at the center and drag to the radius (or click the center, then a point on the circle). A hole seed inside makes it a hole.',
  arc: 'Arc: click its start (a vertex or a new point), its end, then its center; it runs counter-clockwise from start to end. Esc drops it.',
  bezier: 'Bézier: click its start (a vertex or a new point), its end, then its two control points. Esc drops it.',
};

const MIN_RADIUS_PIXELS = 4;

/**
 * The item under (x, y) within `radius`: hitTest's (seeds, points, segments) or, when `kinds` is
 * undefined (the Select tool), a curve's handle or stroke too. A handle wins over a point or seed
 * only when it is nearer (a hole seed at a circle's center stays pickable beside the handle), and a
 * curve's stroke counts only where nothing else is.
 */
export function hitWithCurves(d, x, y, radius, kinds) {
  const hit = hitTest(d, x, y, radius, kinds);
  if (kinds !== undefined) return hit;
  const curves = curvesOf(d);
  let best = null;
  let bestDistance = radius;
  curves.forEach((_, k) => {
    for (const h of handlesOf(d, k)) {
      const distance = Math.hypot(h.x - x, h.y - y);
      if (distance <= bestDistance) { best = { kind: CurveItem.HANDLE, index: k, which: h.which }; bestDistance = distance; }
    }
  });
  if (best !== null && hit !== null && hit.kind !== Item.SEGMENT) {
    const position = hit.kind === Item.POINT ? [d.points[2 * hit.index], d.points[2 * hit.index + 1]]
      : hit.kind === Item.HOLE ? [d.holes[2 * hit.index], d.holes[2 * hit.index + 1]] : [d.regions[hit.index].x, d.regions[hit.index].y];
    return Math.hypot(position[0] - x, position[1] - y) < bestDistance ? hit : best;
  }
  if (best !== null || (hit !== null && hit.kind !== Item.SEGMENT)) return best ?? hit;
  // Strokes: a curve nearer than the nearest segment (or than nothing).
  if (hit !== null) {
    const [a, b] = [d.segments[2 * hit.index], d.segments[2 * hit.index + 1]];
    bestDistance = Math.sqrt(segmentDistance2(x, y, d.points[2 * a], d.points[2 * a + 1], d.points[2 * b], d.points[2 * b + 1]));
  }
  curves.forEach((_, k) => {
    const distance = distanceTo(curveShape(d, k), x, y);
    if (distance < bestDistance) { best = { kind: CurveItem.CURVE, index: k }; bestDistance = distance; }
  });
  return best ?? hit;
}

/**
 * Moves an item to (x, y) and keeps the curves valid: `before` is the drawing (points and curves)
 * when the move began (a drag's start; an arrow key's moment), from which followPoints places the
 * centers and controls of the curves whose ends moved. A circle's center drags both its halves.
 */
export function moveWithCurves(d, item, x, y, before = snapshot(d)) {
  moveItem(d, item, x, y);
  if (item.kind === CurveItem.HANDLE && item.which === 'center') {
    const moved = d.curves[item.index];
    const probe = { points: before.points, curves: before.curves };
    for (const k of twinArcs(probe, item.index)) d.curves[k].center = [...moved.center];
  }
  followPoints(d, before);
}

/** What followPoints and twinArcs need of the drawing at the start of a move. */
export const snapshot = (d) => ({ points: d.points.slice(), curves: cloneCurves(d) });

/** The pending curve of a curve tool: its clicks so far, previewed up to the pointer. */
export class CurveTools {
  /** @param {object} editor the Editor: its app (drawing, view, changed, redraw), place(), radius */
  constructor(editor) {
    this.editor = editor;
    this.pending = null;  // { tool, ends: [{ index } | { x, y }], controls: [[x, y]], center, dragging }
    this.pointer = null;  // the (snapped) pointer, for the preview
  }

  get drawing() { return this.editor.app.drawing; }

  cancel() {
    const had = this.pending !== null;
    this.pending = null;
    if (had) this.editor.app.redraw();
    return had;
  }

  /** A vertex under the pointer (kept by index), else the snapped place (a point added at the end). */
  endAt(world) {
    const hit = hitTest(this.drawing, world.x, world.y, this.editor.radius, [Item.POINT]);
    if (hit !== null) return { index: hit.index };
    const at = this.editor.place(world);
    return { x: at.x, y: at.y };
  }

  endPosition(end) {
    const d = this.drawing;
    return end.index === undefined ? [end.x, end.y] : [d.points[2 * end.index], d.points[2 * end.index + 1]];
  }

  /** A button pressed (or a tap, or Enter at the keyboard cursor) at `world`, with a curve tool. */
  press(tool, world) {
    const at = this.editor.place(world);
    this.pointer = [at.x, at.y];
    const p = this.pending?.tool === tool ? this.pending : (this.pending = { tool, ends: [], controls: [], center: null, dragging: false });
    if (tool === 'circle') {
      if (p.center === null) {
        p.center = [at.x, at.y];
        p.dragging = true;
      } else {
        this.finishCircle([at.x, at.y]);
      }
    } else if (p.ends.length < 2) {
      const end = this.endAt(world);
      // The same vertex twice is no curve: ignore the second click.
      const same = p.ends.length === 1 && end.index !== undefined && end.index === p.ends[0].index;
      if (!same) p.ends.push(end);
    } else if (tool === 'arc') {
      this.finishArc([at.x, at.y]);
    } else {
      p.controls.push([at.x, at.y]);
      if (p.controls.length === 2) this.finishBezier();
    }
    this.editor.app.redraw();
  }

  move(world) {
    const at = this.editor.place(world);
    this.pointer = [at.x, at.y];
    if (this.pending) this.editor.app.redraw();
  }

  /** The button released: a circle dragged far enough is made; else it waits for a second click. */
  release(world) {
    const p = this.pending;
    if (p?.tool !== 'circle' || !p.dragging) return;
    p.dragging = false;
    const at = this.editor.place(world);
    const pixels = Math.hypot(at.x - p.center[0], at.y - p.center[1]) * this.editor.app.view.scale;
    if (pixels >= MIN_RADIUS_PIXELS) this.finishCircle([at.x, at.y]);
  }

  /** The point `through` and its opposite, and the two arcs between them around the center. */
  finishCircle(through) {
    const [cx, cy] = this.pending.center;
    if (through[0] === cx && through[1] === cy) return;
    const d = this.drawing;
    const a = addPoint(d, through[0], through[1]);
    // The opposite point: its distance from the center equals the first's to rounding (1e-16 of
    // the radius; the core allows 1e-9).
    const b = addPoint(d, 2 * cx - through[0], 2 * cy - through[1]);
    d.curves = [...cloneCurves(d), { type: 'arc', from: a, to: b, center: [cx, cy] }, { type: 'arc', from: b, to: a, center: [cx, cy] }];
    this.commit({ kind: CurveItem.CURVE, index: d.curves.length - 2 });
  }

  /** The ends' point indices, adding the new ones. */
  addEnds() {
    const d = this.drawing;
    return this.pending.ends.map((end) => (end.index !== undefined ? end.index : addPoint(d, end.x, end.y)));
  }

  finishArc(click) {
    const [a, b] = this.pending.ends.map((end) => this.endPosition(end));
    const center = onBisector(a, b, click);
    const [from, to] = this.addEnds();
    const d = this.drawing;
    d.curves = [...cloneCurves(d), { type: 'arc', from, to, center }];
    this.commit({ kind: CurveItem.CURVE, index: d.curves.length - 1 });
  }

  finishBezier() {
    const [from, to] = this.addEnds();
    const d = this.drawing;
    d.curves = [...cloneCurves(d), { type: 'bezier', from, to, controls: this.pending.controls.flat() }];
    this.commit({ kind: CurveItem.CURVE, index: d.curves.length - 1 });
  }

  commit(selection) {
    this.pending = null;
    this.editor.selection = selection;
    this.editor.app.changed({ commit: true });
  }

  /**
   * What the renderer previews (rendering/curve-draw.js): { shape } (curve-geometry.js) once the
   * curve is determined up to the pointer, { from, to } (a dashed line) before, with the clicked
   * places as `marks`; null when no curve is pending.
   */
  preview() {
    const p = this.pending;
    const pointer = this.pointer;
    if (p === null || pointer === null) return null;
    if (p.tool === 'circle') {
      const r = Math.hypot(pointer[0] - p.center[0], pointer[1] - p.center[1]);
      const shape = r > 0 ? { type: 'arc', cx: p.center[0], cy: p.center[1], r, start: 0, sweep: 2 * Math.PI } : null;
      return { shape, from: p.center, to: pointer, marks: [p.center] };
    }
    const ends = p.ends.map((end) => this.endPosition(end));
    if (ends.length < 2) return { shape: null, from: ends[0] ?? null, to: pointer, marks: ends };
    if (p.tool === 'arc') {
      const center = onBisector(ends[0], ends[1], pointer);
      return { shape: shapeOf({ type: 'arc', center }, ends[0], ends[1]), from: center, to: null, marks: [...ends, center] };
    }
    const controls = [...p.controls, pointer, pointer].slice(0, 2);
    return { shape: shapeOf({ type: 'bezier', controls: controls.flat() }, ends[0], ends[1]), from: null, to: null, marks: [...ends, ...controls] };
  }
}
