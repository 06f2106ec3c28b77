// Mouse and keyboard editing of the drawing on the canvas.
//
// Tools: select (pick, drag, delete), point, polyline (click, click, ..., click the first vertex
// to close; Enter, double-click or Esc ends an open one), hole seed, region seed, and the curve
// tools circle, arc and Bézier (editing/curve-tools.js).
// Everywhere: wheel zooms, middle-drag or Space+drag pans.
// Touch: two fingers pinch-zoom and pan; one finger on empty space pans once it moves, and a tap
// (no movement) does what a click does, so a pinch never leaves a stray vertex behind.
// Keyboard: with the canvas focused and nothing selected, the arrow keys move a keyboard cursor
// (a crosshair, one grid step, five with Shift) and Enter does what a click there would do.
//
// The editor mutates app.drawing and then calls app.changed({ commit }): commit = true records
// an undo step (a click, the end of a drag), false only re-meshes (while dragging).
// Read-only (an embed without &edit=1): the drawing cannot change; pointer and arrows pan, the
// wheel and +/- zoom, hovering still reports triangles.
import { Item, addPoint, addSegment, hitTest, itemPosition, removeItem } from '../model/drawing.js';
import { CURVE_TOOL_HINTS, CurveTools, hitWithCurves, isCurveTool, moveWithCurves, snapshot } from './curve-tools.js';
import { snapToGrid } from '../rendering/view.js';

const PICK_RADIUS = 9;  // CSS pixels
const TAP_SLOP = 10;    // CSS pixels a touch may move and still be a tap

export const TOOL_HINTS = {
  select: 'Select: click a vertex, segment, curve, curve handle or seed; drag to move it; Delete removes it. Drag empty space to pan.',
  point: 'Point: click (or arrows, then Enter) to add a vertex (drag an existing one to move it).',
  polyline: 'Polygon: click to add vertices, click the first vertex to close, Enter or double-click ends an open polyline.',
  hole: 'Hole: click inside a closed polygon to make it a hole.',
  region: 'Region: click inside a polygon to give it the attribute and max area set in the panel.',
  ...CURVE_TOOL_HINTS,
};

// Capture can fail (a pointer that is already gone throws NotFoundError): the gesture works without it.
function capture(element, pointerId) {
  try { element.setPointerCapture?.(pointerId); } catch { /* not capturable: fine */ }
}
function release(element, pointerId) {
  try { element.releasePointerCapture?.(pointerId); } catch { /* not captured: fine */ }
}

const isTextField = (el) => el instanceof HTMLElement &&
  (el.isContentEditable || el.tagName === 'TEXTAREA' || el.tagName === 'SELECT' ||
    (el.tagName === 'INPUT' && !['checkbox', 'radio', 'button', 'range'].includes(el.type)));

export class Editor {
  /**
   * @param {object} app { canvas, view, drawing, snap, changed({commit}), redraw(), undo(), redo(),
   *   regionSeed() -> { attribute, maxArea }, hover(world | null), setTool(name), shortcut(name) -> bool }
   */
  constructor(app) {
    this.app = app;
    this.tool = 'polyline';
    this.selection = null;   // { kind, index }
    this.hoverItem = null;
    this.chain = null;       // open polyline: { first, from } point indices
    this.cursor = null;      // world position of the pointer
    this.gesture = null;     // { type: 'pan' | 'drag', ... } while a button is down
    this.spaceDown = false;
    this.touches = new Map(); // pointerId -> { x, y } (client pixels) of fingers on the canvas
    this.keyCursor = null;    // world position of the keyboard cursor, once arrows moved it
    this.readOnly = false;
    this.curveTools = new CurveTools(this);
    this.bind();
  }

  get radius() { return PICK_RADIUS / this.app.view.scale; }

  /** The pointer's world position, snapped to the grid when snapping is on. */
  place(world) {
    if (!this.app.snap) return world;
    const step = this.app.view.gridStep();
    return { x: snapToGrid(world.x, step), y: snapToGrid(world.y, step) };
  }

  worldOf(event) {
    const rect = this.app.canvas.getBoundingClientRect();
    return this.app.view.toWorld(event.clientX - rect.left, event.clientY - rect.top);
  }

  setTool(tool) {
    if (this.chain && tool !== 'polyline') this.chain = null;
    this.curveTools?.cancel();
    this.tool = tool;
    this.app.redraw();
  }

  select(item) {
    this.selection = item;
    this.app.redraw();
  }

  /** Ends the open polyline, if any. */
  endChain() {
    if (this.chain === null) return false;
    this.chain = null;
    this.app.redraw();
    return true;
  }

  deleteSelection() {
    if (this.selection === null) return false;
    removeItem(this.app.drawing, this.selection);
    this.selection = null;
    this.hoverItem = null;
    this.chain = null;  // indices may have shifted
    this.app.changed({ commit: true });
    return true;
  }

  /** Forgets selections and the open polyline (after undo, loading, ...). */
  reset() {
    this.selection = null;
    this.hoverItem = null;
    this.chain = null;
    this.gesture = null;
    this.keyCursor = null;
    this.curveTools.cancel();
  }

  bind() {
    const canvas = this.app.canvas;
    canvas.addEventListener('pointerdown', (e) => this.pointerDown(e));
    canvas.addEventListener('pointermove', (e) => this.pointerMove(e));
    canvas.addEventListener('pointerup', (e) => this.pointerUp(e));
    canvas.addEventListener('pointercancel', (e) => this.pointerUp(e));
    canvas.addEventListener('pointerleave', () => {
      if (this.gesture) return;
      this.cursor = null;
      this.hoverItem = null;
      this.app.hover(null);
    });
    canvas.addEventListener('dblclick', (e) => { if (this.tool === 'polyline') { e.preventDefault(); this.endChain(); } });
    canvas.addEventListener('wheel', (e) => {
      e.preventDefault();
      const rect = canvas.getBoundingClientRect();
      const delta = e.deltaMode === 1 ? e.deltaY * 16 : e.deltaY;
      this.app.view.zoomAt(e.clientX - rect.left, e.clientY - rect.top, Math.exp(-delta * 0.0015));
      this.app.viewMoved = true;
      this.app.redraw();
    }, { passive: false });
    canvas.addEventListener('contextmenu', (e) => e.preventDefault());
    window.addEventListener('keydown', (e) => this.keyDown(e));
    window.addEventListener('keyup', (e) => { if (e.code === 'Space') this.spaceDown = false; });
    window.addEventListener('blur', () => { this.spaceDown = false; });
  }

  pointerDown(e) {
    const canvas = this.app.canvas;
    canvas.focus({ preventScroll: true });
    this.app.viewMoved = true;  // from now on the view stays where the user works
    const world = this.worldOf(e);
    this.cursor = world;
    this.keyCursor = null;
    const touch = e.pointerType === 'touch';
    if (touch) {
      this.touches.set(e.pointerId, { x: e.clientX, y: e.clientY });
      if (this.touches.size >= 2) {
        this.startPinch();
        return;
      }
    }
    if (e.button === 1 || (e.button === 0 && this.spaceDown)) {
      e.preventDefault();
      this.startGesture(e, { type: 'pan', x: e.clientX, y: e.clientY });
      return;
    }
    if (e.button !== 0) return;
    if (this.readOnly) {
      this.startGesture(e, { type: 'pan', x: e.clientX, y: e.clientY });
      return;
    }
    const d = this.app.drawing;
    const r = this.radius;

    if (this.tool === 'polyline') {
      if (touch) this.startGesture(e, { type: 'tap', x: e.clientX, y: e.clientY, world });
      else this.polylineClick(world);
      return;
    }
    if (isCurveTool(this.tool)) {
      if (touch) this.startGesture(e, { type: 'tap', x: e.clientX, y: e.clientY, world });
      else { this.startGesture(e, { type: 'curve' }); this.curveTools.press(this.tool, world); }
      return;
    }
    // Every other tool drags an existing vertex or seed it is pressed on.
    const kinds = this.tool === 'select' ? undefined : [Item.HOLE, Item.REGION, Item.POINT];
    const hit = hitWithCurves(d, world.x, world.y, r, kinds);
    if (hit !== null) {
      this.select(hit);
      if (hit.kind !== Item.SEGMENT) {
        const start = itemPosition(d, hit);
        // `before`: the curves' centers and controls follow their ends from where the drag began.
        this.startGesture(e, { type: 'drag', item: hit, start, grab: { x: world.x - start.x, y: world.y - start.y }, moved: false, before: snapshot(d) });
      }
      return;
    }
    if (this.tool === 'select') {
      this.select(null);
      this.startGesture(e, { type: 'pan', x: e.clientX, y: e.clientY });
    } else if (touch) {
      this.startGesture(e, { type: 'tap', x: e.clientX, y: e.clientY, world });
    } else {
      this.placeAt(world);
    }
  }

  /** What a click on empty space does with the point, hole and region tools. */
  placeAt(world) {
    const d = this.app.drawing;
    const at = this.place(world);
    if (this.tool === 'point') {
      const index = addPoint(d, at.x, at.y);
      this.selection = { kind: Item.POINT, index };
      this.app.changed({ commit: true });
    } else if (this.tool === 'hole') {
      d.holes.push(at.x, at.y);
      this.selection = { kind: Item.HOLE, index: d.holes.length / 2 - 1 };
      this.app.changed({ commit: true });
    } else if (this.tool === 'region') {
      const { attribute, maxArea } = this.app.regionSeed();
      d.regions.push({ x: at.x, y: at.y, attribute, maxArea });
      this.selection = { kind: Item.REGION, index: d.regions.length - 1 };
      this.app.changed({ commit: true });
    }
  }

  polylineClick(world) {
    const d = this.app.drawing;
    const hit = hitTest(d, world.x, world.y, this.radius, [Item.POINT]);
    let index = hit?.index;
    if (this.chain !== null && index === this.chain.from) {
      this.endChain();  // clicking the last vertex again (or a double-click) ends the polyline
      return;
    }
    if (index === undefined) {
      const at = this.place(world);
      index = addPoint(d, at.x, at.y);
    }
    if (this.chain === null) {
      this.chain = { first: index, from: index, length: 0 };
    } else {
      addSegment(d, this.chain.from, index);
      const closed = index === this.chain.first;
      this.chain = closed ? null : { first: this.chain.first, from: index, length: this.chain.length + 1 };
    }
    this.selection = null;
    this.app.changed({ commit: true });
  }

  startGesture(e, gesture) {
    this.gesture = { ...gesture, pointerId: e.pointerId };
    capture(this.app.canvas, e.pointerId);
  }

  /** Two fingers down: whatever the first one started ends (a drag keeps what it moved). */
  startPinch() {
    const g = this.gesture;
    if (g?.type === 'drag' && g.moved) this.app.changed({ commit: true });
    const [a, b] = [...this.touches.values()];
    this.gesture = { type: 'pinch', distance: Math.hypot(a.x - b.x, a.y - b.y), mid: { x: (a.x + b.x) / 2, y: (a.y + b.y) / 2 } };
    for (const id of this.touches.keys()) capture(this.app.canvas, id);
  }

  pinchMove() {
    const g = this.gesture;
    const [a, b] = [...this.touches.values()];
    const distance = Math.hypot(a.x - b.x, a.y - b.y);
    const mid = { x: (a.x + b.x) / 2, y: (a.y + b.y) / 2 };
    const rect = this.app.canvas.getBoundingClientRect();
    this.app.view.panBy(mid.x - g.mid.x, mid.y - g.mid.y);
    if (g.distance > 0 && distance > 0) this.app.view.zoomAt(mid.x - rect.left, mid.y - rect.top, distance / g.distance);
    g.distance = distance;
    g.mid = mid;
    this.app.viewMoved = true;
    this.app.redraw();
  }

  pointerMove(e) {
    if (this.touches.has(e.pointerId)) this.touches.set(e.pointerId, { x: e.clientX, y: e.clientY });
    this.keyCursor = null;  // the pointer is back in charge
    const world = this.worldOf(e);
    this.cursor = world;
    const g = this.gesture;
    if (g?.type === 'pinch') {
      if (this.touches.size >= 2) this.pinchMove();
      return;
    }
    if (g?.type === 'tap') {
      // A finger that moves is panning, not tapping.
      if (Math.hypot(e.clientX - g.x, e.clientY - g.y) > TAP_SLOP) this.gesture = { type: 'pan', x: g.x, y: g.y, pointerId: g.pointerId };
      else return;
    }
    if (this.gesture?.type === 'pan') {
      const p = this.gesture;
      this.app.view.panBy(e.clientX - p.x, e.clientY - p.y);
      this.app.viewMoved = true;
      p.x = e.clientX;
      p.y = e.clientY;
      this.app.redraw();
      return;
    }
    if (g?.type === 'drag') {
      const at = this.place({ x: world.x - g.grab.x, y: world.y - g.grab.y });
      moveWithCurves(this.app.drawing, g.item, at.x, at.y, g.before);
      g.moved = true;
      this.app.changed({ commit: false });
      return;
    }
    if (isCurveTool(this.tool)) this.curveTools.move(world);
    const hit = this.tool === 'polyline' || isCurveTool(this.tool)
      ? hitTest(this.app.drawing, world.x, world.y, this.radius, [Item.POINT])
      : hitWithCurves(this.app.drawing, world.x, world.y, this.radius, this.tool === 'select' ? undefined : [Item.HOLE, Item.REGION, Item.POINT]);
    this.hoverItem = hit;
    this.app.canvas.style.cursor = hit ? (this.tool === 'polyline' ? 'crosshair' : 'move') : (this.tool === 'select' ? 'grab' : 'crosshair');
    this.app.hover(world);
  }

  pointerUp(e) {
    this.touches.delete(e.pointerId);
    const g = this.gesture;
    if (g?.type === 'pinch') {
      release(this.app.canvas, e.pointerId);
      if (this.touches.size < 2) this.gesture = null;  // the finger left behind does nothing
      return;
    }
    if (!g || (e.pointerId !== undefined && g.pointerId !== e.pointerId)) return;
    this.gesture = null;
    release(this.app.canvas, e.pointerId);
    if (g.type === 'drag' && g.moved) this.app.changed({ commit: true });
    if (g.type === 'curve') this.curveTools.release(this.worldOf(e));
    if (g.type === 'tap' && e.type === 'pointerup') this.clickAt(g.world);
  }

  /** A click (or tap, or Enter at the keyboard cursor) on empty space or a vertex, by tool. */
  clickAt(world) {
    if (this.tool === 'polyline') {
      this.polylineClick(world);
      return;
    }
    if (isCurveTool(this.tool)) {
      this.curveTools.press(this.tool, world);
      this.curveTools.release(world);
      return;
    }
    const hit = hitWithCurves(this.app.drawing, world.x, world.y, this.radius, this.tool === 'select' ? undefined : [Item.HOLE, Item.REGION, Item.POINT]);
    if (hit !== null || this.tool === 'select') this.select(hit);
    else this.placeAt(world);
  }

  /** The pending polyline for the renderer. */
  pendingChain() {
    if (this.chain === null || this.cursor === null || this.chain.from >= this.app.drawing.points.length / 2) return null;
    return { from: this.chain.from, first: this.chain.length >= 1 ? this.chain.first : undefined, to: this.place(this.cursor) };
  }

  keyDown(e) {
    if (e.code === 'Space' && !isTextField(e.target) && !(e.target instanceof HTMLButtonElement)) {
      this.spaceDown = true;
      if (e.target === this.app.canvas || e.target === document.body) e.preventDefault();
      return;
    }
    if (isTextField(e.target)) return;
    const ctrl = e.ctrlKey || e.metaKey;
    const key = e.key;
    let handled = true;
    if (this.readOnly && !ctrl && key.startsWith('Arrow')) {
      this.arrow(key, e.shiftKey, false);  // pans
    } else if (this.readOnly && !ctrl && !['+', '=', '-', '_'].includes(key)) {
      handled = this.app.shortcut(key.toLowerCase());  // fit, step mode and stepping only
    } else if (this.readOnly && ctrl) {
      handled = false;
    } else if (ctrl && (key === 'z' || key === 'Z')) {
      if (e.shiftKey) this.app.redo(); else this.app.undo();
    } else if (ctrl && (key === 'y' || key === 'Y')) {
      this.app.redo();
    } else if (ctrl || e.altKey) {
      handled = false;
    } else if (key === 'Delete' || key === 'Backspace') {
      handled = this.deleteSelection();
    } else if (key === 'Escape') {
      if (!this.curveTools.cancel() && !this.endChain()) this.select(null);
    } else if (key === 'Enter' && this.keyCursor !== null && e.target === this.app.canvas) {
      this.clickAt(this.keyCursor);
      this.select(null);  // the arrows keep moving the cursor, not what was just placed
    } else if (key === 'Enter' && this.chain !== null && e.target === this.app.canvas) {
      this.endChain();
    } else if (key.startsWith('Arrow') && (e.target === this.app.canvas || e.target === document.body)) {
      this.arrow(key, e.shiftKey, e.target === this.app.canvas);
    } else if (key === '+' || key === '=') {
      this.app.view.zoomAt(this.app.view.width / 2, this.app.view.height / 2, 1.25);
      this.app.viewMoved = true;
      this.app.redraw();
    } else if (key === '-' || key === '_') {
      this.app.view.zoomAt(this.app.view.width / 2, this.app.view.height / 2, 0.8);
      this.app.viewMoved = true;
      this.app.redraw();
    } else {
      const tools = { v: 'select', p: 'point', l: 'polyline', h: 'hole', r: 'region', c: 'circle', a: 'arc', b: 'bezier' };
      const lower = key.toLowerCase();
      if (tools[lower] && !e.shiftKey) this.app.setTool(tools[lower]);
      else handled = this.app.shortcut(lower);
    }
    if (handled) e.preventDefault();
  }

  /**
   * Arrow keys move the selected vertex or seed by one grid step; with nothing selected they move
   * the keyboard cursor on the focused canvas (the view follows it), else pan the view.
   */
  arrow(key, large, onCanvas) {
    const dx = key === 'ArrowLeft' ? -1 : key === 'ArrowRight' ? 1 : 0;
    const dy = key === 'ArrowUp' ? 1 : key === 'ArrowDown' ? -1 : 0;
    const item = this.selection;
    if (item && item.kind !== Item.SEGMENT) {
      const step = this.app.view.gridStep() * (large ? 5 : 1) / (this.app.snap ? 1 : 4);
      const at = itemPosition(this.app.drawing, item);
      const round = (v) => (this.app.snap ? snapToGrid(v, step) : Number(v.toPrecision(12)));
      moveWithCurves(this.app.drawing, item, round(at.x + dx * step), round(at.y + dy * step));
      this.app.changed({ commit: true });
    } else if (onCanvas && this.tool !== 'select') {
      const view = this.app.view;
      const step = view.gridStep() * (large ? 5 : 1);
      const start = this.keyCursor ?? this.place(view.toWorld(view.width / 2, view.height / 2));
      const round = (v) => snapToGrid(v, step / (large ? 5 : 1));
      this.keyCursor = { x: round(start.x + dx * step), y: round(start.y + dy * step) };
      this.cursor = this.keyCursor;
      // Keep the cursor in view: pan by the part that left it (plus a margin).
      const s = view.toScreen(this.keyCursor.x, this.keyCursor.y);
      const margin = 40;
      const px = s.x < margin ? margin - s.x : s.x > view.width - margin ? view.width - margin - s.x : 0;
      const py = s.y < margin ? margin - s.y : s.y > view.height - margin ? view.height - margin - s.y : 0;
      if (px || py) view.panBy(px, py);
      this.app.viewMoved = true;
      this.app.hover(this.keyCursor);
      this.app.redraw();
    } else {
      const pixels = large ? 200 : 40;
      this.app.view.panBy(-dx * pixels, dy * pixels);
      this.app.viewMoved = true;
      this.app.redraw();
    }
  }
}
