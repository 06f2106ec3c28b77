// Mouse and keyboard editing of the drawing on the canvas.
//
// Tools: select (pick, drag, delete), point, polyline (click, click, ..., click the first vertex
// to close; Enter, double-click or Esc ends an open one), hole seed, region seed.
// Everywhere: wheel zooms, middle-drag or Space+drag pans.
//
// The editor mutates app.drawing and then calls app.changed({ commit }): commit = true records
// an undo step (a click, the end of a drag), false only re-meshes (while dragging).
import { Item, addPoint, addSegment, hitTest, itemPosition, moveItem, removeItem } from './drawing.js';
import { snapToGrid } from './view.js';

const PICK_RADIUS = 9;  // CSS pixels

export const TOOL_HINTS = {
  select: 'Select: click a vertex, segment or seed; drag to move it; Delete removes it. Drag empty space to pan.',
  point: 'Point: click to add a vertex (drag an existing one to move it).',
  polyline: 'Polygon: click to add vertices, click the first vertex to close, Enter or double-click ends an open polyline.',
  hole: 'Hole: click inside a closed polygon to make it a hole.',
  region: 'Region: click inside a polygon to give it the attribute and max area set in the panel.',
};

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
    if (e.button === 1 || (e.button === 0 && this.spaceDown)) {
      e.preventDefault();
      this.startGesture(e, { type: 'pan', x: e.clientX, y: e.clientY });
      return;
    }
    if (e.button !== 0) return;
    const d = this.app.drawing;
    const r = this.radius;

    if (this.tool === 'polyline') {
      this.polylineClick(world);
      return;
    }
    // Every other tool drags an existing vertex or seed it is pressed on.
    const kinds = this.tool === 'select' ? undefined : [Item.HOLE, Item.REGION, Item.POINT];
    const hit = hitTest(d, world.x, world.y, r, kinds);
    if (hit !== null) {
      this.select(hit);
      if (hit.kind !== Item.SEGMENT) {
        const start = itemPosition(d, hit);
        this.startGesture(e, { type: 'drag', item: hit, start, grab: { x: world.x - start.x, y: world.y - start.y }, moved: false });
      }
      return;
    }
    const at = this.place(world);
    if (this.tool === 'select') {
      this.select(null);
      this.startGesture(e, { type: 'pan', x: e.clientX, y: e.clientY });
    } else if (this.tool === 'point') {
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
    this.app.canvas.setPointerCapture?.(e.pointerId);
  }

  pointerMove(e) {
    const world = this.worldOf(e);
    this.cursor = world;
    const g = this.gesture;
    if (g?.type === 'pan') {
      this.app.view.panBy(e.clientX - g.x, e.clientY - g.y);
      this.app.viewMoved = true;
      g.x = e.clientX;
      g.y = e.clientY;
      this.app.redraw();
      return;
    }
    if (g?.type === 'drag') {
      const at = this.place({ x: world.x - g.grab.x, y: world.y - g.grab.y });
      moveItem(this.app.drawing, g.item, at.x, at.y);
      g.moved = true;
      this.app.changed({ commit: false });
      return;
    }
    const hit = this.tool === 'polyline'
      ? hitTest(this.app.drawing, world.x, world.y, this.radius, [Item.POINT])
      : hitTest(this.app.drawing, world.x, world.y, this.radius, this.tool === 'select' ? undefined : [Item.HOLE, Item.REGION, Item.POINT]);
    this.hoverItem = hit;
    this.app.canvas.style.cursor = hit ? (this.tool === 'polyline' ? 'crosshair' : 'move') : (this.tool === 'select' ? 'grab' : 'crosshair');
    this.app.hover(world);
  }

  pointerUp(e) {
    const g = this.gesture;
    if (!g || (e.pointerId !== undefined && g.pointerId !== e.pointerId)) return;
    this.gesture = null;
    this.app.canvas.releasePointerCapture?.(e.pointerId);
    if (g.type === 'drag' && g.moved) this.app.changed({ commit: true });
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
    if (ctrl && (key === 'z' || key === 'Z')) {
      if (e.shiftKey) this.app.redo(); else this.app.undo();
    } else if (ctrl && (key === 'y' || key === 'Y')) {
      this.app.redo();
    } else if (ctrl || e.altKey) {
      handled = false;
    } else if (key === 'Delete' || key === 'Backspace') {
      handled = this.deleteSelection();
    } else if (key === 'Escape') {
      if (!this.endChain()) this.select(null);
    } else if (key === 'Enter' && this.chain !== null && e.target === this.app.canvas) {
      this.endChain();
    } else if (key.startsWith('Arrow') && (e.target === this.app.canvas || e.target === document.body)) {
      this.arrow(key, e.shiftKey);
    } else if (key === '+' || key === '=') {
      this.app.view.zoomAt(this.app.view.width / 2, this.app.view.height / 2, 1.25);
      this.app.viewMoved = true;
      this.app.redraw();
    } else if (key === '-' || key === '_') {
      this.app.view.zoomAt(this.app.view.width / 2, this.app.view.height / 2, 0.8);
      this.app.viewMoved = true;
      this.app.redraw();
    } else {
      const tools = { v: 'select', p: 'point', l: 'polyline', h: 'hole', r: 'region' };
      const lower = key.toLowerCase();
      if (tools[lower] && !e.shiftKey) this.app.setTool(tools[lower]);
      else handled = this.app.shortcut(lower);
    }
    if (handled) e.preventDefault();
  }

  /** Arrow keys move the selected vertex or seed by one grid step, else pan the view. */
  arrow(key, large) {
    const dx = key === 'ArrowLeft' ? -1 : key === 'ArrowRight' ? 1 : 0;
    const dy = key === 'ArrowUp' ? 1 : key === 'ArrowDown' ? -1 : 0;
    const item = this.selection;
    if (item && item.kind !== Item.SEGMENT) {
      const step = this.app.view.gridStep() * (large ? 5 : 1) / (this.app.snap ? 1 : 4);
      const at = itemPosition(this.app.drawing, item);
      const round = (v) => (this.app.snap ? snapToGrid(v, step) : Number(v.toPrecision(12)));
      moveItem(this.app.drawing, item, round(at.x + dx * step), round(at.y + dy * step));
      this.app.changed({ commit: true });
    } else {
      const pixels = large ? 200 : 40;
      this.app.view.panBy(-dx * pixels, dy * pixels);
      this.app.viewMoved = true;
      this.app.redraw();
    }
  }
}
