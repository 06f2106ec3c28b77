// Canvas 2D rendering of the drawing and its mesh.
//
// Speed: the mesh's paths are built once per mesh in world coordinates (one Path2D per color
// class, one for all edges) and drawn under the view's transform, so panning and zooming only
// replay them. Beyond LARGE_MESH triangles, per-triangle fills cost more than they show: only
// the edges are drawn, as one path.
import { minAngleOf, minAngles } from '../geometry/mesh-geometry.js';
import { GlMesh } from './gl-mesh.js';
import { EXEMPTION_LABELS } from '../labels.js';
import { curveMarkers } from '../model/curve-data.js';
import { drawCurves } from './curve-draw.js';
import { ANGLE_CLASSES, COLORS, REGION_COLORS, markerColor } from './colors.js';

const MARKER_LABELS_UP_TO = 300;  // segment markers are written beside their segments up to this many segments

export const LARGE_MESH = 200_000;
/** Vertex numbers are drawn for meshes of up to this many vertices (more would not be legible). */
export const VERTEX_NUMBERS_UP_TO = 1000;

/** Legend rows of the segment markers of a drawing: [{ color, label }]. */
export function markerLegend(drawing) {
  const values = [...new Set([...(drawing.segmentMarkers ?? []), ...curveMarkers(drawing)])].filter((m) => m !== 0).sort((a, b) => a - b);
  return values.map((m) => ({ color: markerColor(m), label: `segment marker ${m}` }));
}

function angleClass(angle) {
  for (let c = 0; c < ANGLE_CLASSES.length; c++) if (angle < ANGLE_CLASSES[c][0]) return c;
  return ANGLE_CLASSES.length - 1;
}

/** Legend rows of the exemptions marked on the canvas (the core's mesh.triangleExemptions). */
export function exemptionLegend(exemptions) {
  const rows = [];
  if (exemptions?.nestled.length) rows.push({ color: COLORS.exempt, label: EXEMPTION_LABELS.SMALL_INPUT_ANGLE.legend, hatched: true });
  if (exemptions?.seditious.length) rows.push({ color: COLORS.seditious, label: EXEMPTION_LABELS.SEDITIOUS_EDGE.legend });
  return rows;
}

/** Legend rows for a color mode: [{ color, label }]. */
export function legendEntries(mode, mesh) {
  if (mode === 'angle') {
    let lower = 0;
    return ANGLE_CLASSES.map(([upper, color]) => {
      const label = `${lower}°–${Math.round(upper)}°`;
      lower = Math.round(upper);
      return { color, label };
    });
  }
  if (mode === 'region' && mesh) {
    return regionValues(mesh).map((value, i) => ({ color: REGION_COLORS[i % REGION_COLORS.length], label: `attribute ${value}` }));
  }
  return [];
}

function regionValues(mesh) {
  return [...new Set(mesh.triangleAttributes)].sort((a, b) => a - b);
}

let ANGLE_TABLE = null;

/**
 * The fill of every triangle for a color mode, as the legend states it: a palette of CSS colors
 * and the palette index of triangle t.
 */
export function triangleColoring(mode, mesh, minAngle) {
  if (mode === 'angle') {
    // A table by hundredths of a degree (every class bound is a multiple of 0.01°): no search.
    const table = ANGLE_TABLE ?? (ANGLE_TABLE = Uint8Array.from({ length: 6001 }, (_, k) => angleClass(k / 100)));
    // Without the per-triangle array (WebGL: a large mesh's first picture needs only some), each on demand.
    const angle = minAngle ? (t) => minAngle[t] : (t) => minAngleOf(mesh, t);
    return { palette: ANGLE_CLASSES.map(([, c]) => c), classOf: (t) => table[Math.min(6000, Math.floor(angle(t) * 100))] };
  }
  if (mode === 'region') {
    const values = regionValues(mesh);
    const index = new Map(values.map((v, i) => [v, i]));
    const attributes = mesh.triangleAttributes;
    return { palette: values.map((v, i) => REGION_COLORS[i % REGION_COLORS.length]), classOf: (t) => index.get(attributes[t]) };
  }
  return { palette: ['#eef2f8'], classOf: () => 0 };
}

export class Renderer {
  /**
   * @param {HTMLCanvasElement} canvas the 2D canvas (the overlays; everything when there is no WebGL)
   * @param {HTMLCanvasElement} [glCanvas] a canvas under it for the mesh in WebGL, if the browser has it
   */
  /**
   * @param {HTMLCanvasElement} canvas the 2D canvas (the overlays, and the mesh without WebGL)
   * @param {HTMLCanvasElement|null} glCanvas the canvas under it for the mesh in WebGL, or null
   * @param {{ draw: Function, shows: Function }|null} stepOverlay step mode's overlay (steps/
   *   step-overlay.js's drawStep and showsStep), handed in by the composition root
   */
  constructor(canvas, glCanvas = null, stepOverlay = null) {
    this.canvas = canvas;
    this.stepOverlay = stepOverlay;
    this.ctx = canvas.getContext('2d');
    this.dpr = 1;
    this.mesh = null;
    this.cache = null;  // paths of the current mesh for the current color mode
    this.minAngle = null;  // per-triangle smallest angle
    this.gl = glCanvas ? GlMesh.create(glCanvas) : null;  // null: the mesh is drawn in 2D
    this.onReady = null;  // called when a large mesh's triangles reached the GPU (draw again)
    this.onFallback = null;  // called when a lost WebGL context sends the page back to 2D
    // A lost context (the GPU process gone, too many contexts) takes the buffers with it: the page
    // goes on in 2D rather than showing an empty canvas.
    glCanvas?.addEventListener('webglcontextlost', () => {
      if (!this.gl) return;
      this.gl = null;
      glCanvas.hidden = true;
      this.setMesh(this.mesh);
      this.onFallback?.();
    });
  }

  /** Matches the backing store to the element's CSS size and the device pixel ratio. */
  resize(width, height, dpr) {
    this.dpr = dpr;
    const w = Math.max(1, Math.round(width * dpr));
    const h = Math.max(1, Math.round(height * dpr));
    if (this.canvas.width !== w || this.canvas.height !== h) {
      this.canvas.width = w;
      this.canvas.height = h;
    }
    this.gl?.resize(w, h);
  }

  /** Whether the mesh on screen is already that of the step wanted (else it is dimmed). */
  showsStep(step) {
    return this.stepOverlay === null || this.stepOverlay.shows(step, this.mesh);
  }

  setMesh(mesh) {
    this.mesh = mesh;
    this.cache = null;
    // The 2D path colors from the array; WebGL asks triangle by triangle (triangleColoring).
    this.minAngle = mesh && !this.gl ? minAngles(mesh) : null;
    this.gl?.setMesh(mesh, () => this.onReady?.());
  }

  /** Waits until the frame is drawn (benchmarks). */
  finish() {
    if (this.gl) this.gl.finish();
    else this.ctx.getImageData(0, 0, 1, 1);
  }

  /** The picture as one canvas (the WebGL mesh under the 2D overlays), for PNG export. */
  snapshot() {
    if (!this.gl) return this.canvas;
    const out = document.createElement('canvas');
    out.width = this.canvas.width;
    out.height = this.canvas.height;
    const ctx = out.getContext('2d');
    ctx.drawImage(this.gl.canvas, 0, 0);
    ctx.drawImage(this.canvas, 0, 0);
    return out;
  }

  /** WebGL: background, grid and mesh under the (transparent) 2D canvas. */
  drawGl(s) {
    const { view } = s;
    if (this.mesh) {
      const { palette, classOf } = triangleColoring(s.colorMode, this.mesh, this.minAngle);
      this.gl.setColors(`${s.colorMode}:${palette.join()}`, palette, classOf, COLORS.edge);
    }
    const grid = [];
    const b = view.visibleBounds();
    const step = view.gridStep();
    const lines = (every, color) => {
      const xy = [];
      for (let x = Math.ceil(b.minX / every) * every; x <= b.maxX; x += every) xy.push(x, b.minY, x, b.maxY);
      for (let y = Math.ceil(b.minY / every) * every; y <= b.maxY; y += every) xy.push(b.minX, y, b.maxX, y);
      grid.push({ lines: new Float32Array(xy), color });
    };
    if (s.grid !== false) {
      if (s.snap) lines(step, COLORS.grid);
      lines(step * 5, COLORS.gridStrong);
    }
    const alpha = this.mesh && s.step && !this.showsStep(s.step) ? 0.35 : 1;
    this.gl.draw(view, this.dpr, { background: COLORS.background, grid, edgeColor: COLORS.edge, alpha });
  }

  buildPaths(mode) {
    const mesh = this.mesh;
    const tri = mesh.triangles;
    const p = mesh.points;
    const n = tri.length / 3;
    const fills = [];  // [{ color, path }]
    const large = n > LARGE_MESH;
    // No closePath(): fill() closes every subpath anyway, and Chromium's Path2D.closePath()
    // takes time proportional to the path's length (quadratic over a mesh: 20 s for 80k).
    const addTriangle = (path, t) => {
      const i = 2 * tri[3 * t]; const j = 2 * tri[3 * t + 1]; const k = 2 * tri[3 * t + 2];
      path.moveTo(p[i], p[i + 1]);
      path.lineTo(p[j], p[j + 1]);
      path.lineTo(p[k], p[k + 1]);
    };
    if (!large && mode === 'angle') {
      const paths = ANGLE_CLASSES.map(() => new Path2D());
      for (let t = 0; t < n; t++) addTriangle(paths[angleClass(this.minAngle[t])], t);
      ANGLE_CLASSES.forEach(([, color], c) => fills.push({ color, path: paths[c] }));
    } else if (!large && mode === 'region') {
      const values = regionValues(mesh);
      const index = new Map(values.map((v, i) => [v, i]));
      const paths = values.map(() => new Path2D());
      for (let t = 0; t < n; t++) addTriangle(paths[index.get(mesh.triangleAttributes[t])], t);
      values.forEach((v, i) => fills.push({ color: REGION_COLORS[i % REGION_COLORS.length], path: paths[i] }));
    } else if (!large) {
      const path = new Path2D();
      for (let t = 0; t < n; t++) addTriangle(path, t);
      fills.push({ color: '#eef2f8', path });
    }
    // Every interior edge is shared by two triangles: draw it once (from the triangle with the
    // smaller index, or when there is no neighbor).
    const edges = new Path2D();
    for (let t = 0; t < n; t++) {
      for (let e = 0; e < 3; e++) {
        const other = mesh.neighbors[3 * t + e];
        if (other >= 0 && other < t) continue;
        const a = 2 * tri[3 * t + (e + 1) % 3];
        const b = 2 * tri[3 * t + (e + 2) % 3];
        edges.moveTo(p[a], p[a + 1]);
        edges.lineTo(p[b], p[b + 1]);
      }
    }
    this.cache = { mode, fills, edges, large };
  }

  /**
   * @param {object} s what to draw:
   *   view, drawing, colorMode, snap (the fine grid too), grid (false: none), selection, hoverItem, hoverTriangle,
   *   pendingChain: { from: pointIndex, to: {x,y}, first } | null, keyCursor: {x,y} | null (keyboard cursor),
   *   notices, step: { final, events, index, shown } | null: `final` the full mesh (its points
   *   number every vertex of every step), `index` the step wanted, `shown` the mesh on screen;
   *   exemptions (mesh-geometry.js's exemptTriangles, of `exemptions.mesh`) | null, vertexNumbers: whether to number the vertices
   */
  draw(s) {
    const { ctx, dpr } = this;
    const view = s.view;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    if (this.gl) {
      ctx.clearRect(0, 0, this.canvas.width, this.canvas.height);
      this.drawGl(s);
    } else {
      ctx.fillStyle = COLORS.background;
      ctx.fillRect(0, 0, this.canvas.width, this.canvas.height);
    }
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    if (!this.gl && s.grid !== false) this.drawGrid(view, s.snap);

    const px = 1 / view.scale;  // one CSS pixel in world units
    const world = () => ctx.setTransform(...view.matrix(dpr));
    const screen = () => ctx.setTransform(dpr, 0, 0, dpr, 0, 0);

    if (this.mesh && this.gl) {
      if (s.hoverTriangle >= 0 && s.hoverTriangle < this.mesh.triangles.length / 3) {
        world();
        ctx.strokeStyle = COLORS.hover;
        ctx.lineWidth = 2.5 * px;
        ctx.stroke(this.trianglePath(s.hoverTriangle));
        screen();
      }
    } else if (this.mesh) {
      if (this.cache === null || this.cache.mode !== s.colorMode) this.buildPaths(s.colorMode);
      world();
      // Step mode: the mesh is that of the step (StepReplay); dimmed only while it is still on
      // its way, when the picture under the event is the previous step's.
      ctx.globalAlpha = s.step && !this.showsStep(s.step) ? 0.35 : 1;
      for (const { color, path } of this.cache.fills) {
        ctx.fillStyle = color;
        ctx.fill(path);
      }
      ctx.strokeStyle = COLORS.edge;
      ctx.lineWidth = (this.cache.large ? 0.5 : 0.8) * px;
      ctx.stroke(this.cache.edges);
      ctx.globalAlpha = 1;
      if (s.hoverTriangle >= 0 && s.hoverTriangle < this.mesh.triangles.length / 3) {
        ctx.strokeStyle = COLORS.hover;
        ctx.lineWidth = 2.5 * px;
        ctx.stroke(this.trianglePath(s.hoverTriangle));
      }
      screen();
    }

    if (s.exemptions && this.mesh === s.exemptions.mesh) this.drawExemptions(s.exemptions, view, world, screen, px);
    this.drawDrawing(s, world, screen, px);
    if (s.step && this.stepOverlay) this.stepOverlay.draw(ctx, this.mesh, s.step, view, world, screen, px);
    if (s.vertexNumbers) this.drawVertexNumbers(view);
    this.drawNotices(s.notices ?? [], view);
  }

  trianglePath(t) {
    const p = this.mesh.points;
    const tri = this.mesh.triangles;
    const path = new Path2D();
    const i = 2 * tri[3 * t]; const j = 2 * tri[3 * t + 1]; const k = 2 * tri[3 * t + 2];
    path.moveTo(p[i], p[i + 1]);
    path.lineTo(p[j], p[j + 1]);
    path.lineTo(p[k], p[k + 1]);
    path.closePath();
    return path;
  }

  /**
   * The triangles left skinny on purpose (§6.6, as the core marks them): those nestled in a small input
   * angle hatched, those on a seditious edge outlined, the seditious edge itself thick, in teal.
   */
  drawExemptions(x, view, world, screen, px) {
    const { ctx } = this;
    const p = this.mesh.points;
    const tri = this.mesh.triangles;
    const path = (list, at) => {
      const out = new Path2D();
      for (const t of list) {
        for (let c = 0; c < 3; c++) {
          const q = at(tri[3 * t + c]);
          if (c === 0) out.moveTo(q.x, q.y); else out.lineTo(q.x, q.y);
        }
        out.closePath();
      }
      return out;
    };
    if (x.nestled.length) {
      // In screen coordinates, so the hatching keeps its pixel spacing at any zoom.
      const nestled = path(x.nestled, (v) => view.toScreen(p[2 * v], p[2 * v + 1]));
      ctx.fillStyle = this.hatch();
      ctx.fill(nestled);
      ctx.strokeStyle = COLORS.exempt;
      ctx.lineWidth = 1.2;
      ctx.stroke(nestled);
    }
    world();
    if (x.seditious.length) {
      ctx.strokeStyle = COLORS.seditious;
      ctx.lineWidth = 1.2 * px;
      ctx.setLineDash([4 * px, 3 * px]);
      ctx.stroke(path(x.seditious, (v) => ({ x: p[2 * v], y: p[2 * v + 1] })));
      ctx.setLineDash([]);
      const edges = new Path2D();
      for (let i = 0; i < x.seditiousEdges.length; i += 2) {
        const a = x.seditiousEdges[i]; const b = x.seditiousEdges[i + 1];
        edges.moveTo(p[2 * a], p[2 * a + 1]);
        edges.lineTo(p[2 * b], p[2 * b + 1]);
      }
      ctx.lineWidth = 3.5 * px;
      ctx.stroke(edges);
    }
    screen();
  }

  /** Diagonal violet lines for the triangles nestled in small input angles (screen-aligned). */
  hatch() {
    if (!this.hatchPattern) {
      const tile = document.createElement('canvas');
      tile.width = 8; tile.height = 8;
      const t = tile.getContext('2d');
      t.strokeStyle = COLORS.exempt;
      t.lineWidth = 1.5;
      t.beginPath(); t.moveTo(0, 8); t.lineTo(8, 0); t.moveTo(-2, 2); t.lineTo(2, -2); t.moveTo(6, 10); t.lineTo(10, 6); t.stroke();
      this.hatchPattern = this.ctx.createPattern(tile, 'repeat');
    }
    return this.hatchPattern;
  }

  drawGrid(view, snap) {
    const { ctx } = this;
    const step = view.gridStep();
    const b = view.visibleBounds();
    const lines = (strong) => {
      ctx.beginPath();
      const every = strong ? step * 5 : step;
      for (let x = Math.ceil(b.minX / every) * every; x <= b.maxX; x += every) {
        const sx = Math.round(view.toScreen(x, 0).x) + 0.5;
        ctx.moveTo(sx, 0); ctx.lineTo(sx, view.height);
      }
      for (let y = Math.ceil(b.minY / every) * every; y <= b.maxY; y += every) {
        const sy = Math.round(view.toScreen(0, y).y) + 0.5;
        ctx.moveTo(0, sy); ctx.lineTo(view.width, sy);
      }
      ctx.strokeStyle = strong ? COLORS.gridStrong : COLORS.grid;
      ctx.lineWidth = 1;
      ctx.stroke();
    };
    if (snap) lines(false);
    lines(true);
  }

  /** Each marked segment's marker at its midpoint (up to MARKER_LABELS_UP_TO segments). */
  drawMarkerLabels(d, view) {
    const { ctx } = this;
    if (d.segments.length / 2 > MARKER_LABELS_UP_TO) return;
    ctx.font = 'bold 11px system-ui, sans-serif';
    ctx.textAlign = 'center';
    ctx.textBaseline = 'middle';
    ctx.lineJoin = 'round';
    for (let k = 0; k < d.segments.length / 2; k++) {
      const marker = d.segmentMarkers[k] ?? 0;
      if (marker === 0) continue;
      const a = d.segments[2 * k]; const b = d.segments[2 * k + 1];
      const q = view.toScreen((d.points[2 * a] + d.points[2 * b]) / 2, (d.points[2 * a + 1] + d.points[2 * b + 1]) / 2);
      ctx.strokeStyle = '#fff'; ctx.lineWidth = 3; ctx.strokeText(String(marker), q.x, q.y);
      ctx.fillStyle = markerColor(marker); ctx.fillText(String(marker), q.x, q.y);
    }
  }

  drawDrawing(s, world, screen, px) {
    const { ctx } = this;
    const d = s.drawing;
    const view = s.view;
    const selected = (kind, index) => s.selection?.kind === kind && s.selection.index === index;
    const hovered = (kind, index) => s.hoverItem?.kind === kind && s.hoverItem.index === index;

    // Input segments, bold, in their marker's color (black: no marker).
    world();
    const markers = d.segmentMarkers ?? [];
    const byColor = new Map();
    for (let k = 0; k < d.segments.length; k += 2) {
      const a = d.segments[k]; const b = d.segments[k + 1];
      const color = markerColor(markers[k / 2] ?? 0);
      if (!byColor.has(color)) byColor.set(color, new Path2D());
      byColor.get(color).moveTo(d.points[2 * a], d.points[2 * a + 1]);
      byColor.get(color).lineTo(d.points[2 * b], d.points[2 * b + 1]);
    }
    ctx.lineWidth = 2.5 * px;
    ctx.lineCap = 'round';
    for (const [color, path] of byColor) {
      ctx.strokeStyle = color;
      ctx.stroke(path);
    }
    for (const [kind, color] of [['segment', COLORS.selected], ['segment-hover', COLORS.hover]]) {
      const item = kind === 'segment' ? s.selection : s.hoverItem;
      if (item?.kind !== 'segment') continue;
      const a = d.segments[2 * item.index]; const b = d.segments[2 * item.index + 1];
      ctx.beginPath();
      ctx.moveTo(d.points[2 * a], d.points[2 * a + 1]);
      ctx.lineTo(d.points[2 * b], d.points[2 * b + 1]);
      ctx.strokeStyle = color;
      ctx.lineWidth = 4 * px;
      ctx.stroke();
    }
    screen();
    drawCurves(ctx, s, world, screen, px);  // curves, their handles and the one being made (curveHandles, curvePreview)
    if (markers.some((m) => m !== 0)) this.drawMarkerLabels(d, view);

    // The polyline being drawn: a dashed segment from its last vertex to the pointer.
    if (s.pendingChain) {
      const from = view.toScreen(d.points[2 * s.pendingChain.from], d.points[2 * s.pendingChain.from + 1]);
      const to = view.toScreen(s.pendingChain.to.x, s.pendingChain.to.y);
      ctx.setLineDash([6, 4]);
      ctx.beginPath(); ctx.moveTo(from.x, from.y); ctx.lineTo(to.x, to.y);
      ctx.strokeStyle = COLORS.hover; ctx.lineWidth = 1.5; ctx.stroke();
      ctx.setLineDash([]);
      if (s.pendingChain.first !== undefined && s.pendingChain.first !== s.pendingChain.from) {
        const first = view.toScreen(d.points[2 * s.pendingChain.first], d.points[2 * s.pendingChain.first + 1]);
        ctx.beginPath(); ctx.arc(first.x, first.y, 9, 0, 2 * Math.PI);
        ctx.strokeStyle = COLORS.hover; ctx.lineWidth = 1.5; ctx.stroke();
      }
    }

    // The keyboard cursor: a crosshair where Enter places the next vertex or seed.
    if (s.keyCursor) {
      const c = view.toScreen(s.keyCursor.x, s.keyCursor.y);
      ctx.beginPath();
      ctx.moveTo(c.x - 10, c.y); ctx.lineTo(c.x + 10, c.y);
      ctx.moveTo(c.x, c.y - 10); ctx.lineTo(c.x, c.y + 10);
      ctx.strokeStyle = COLORS.hover; ctx.lineWidth = 2; ctx.stroke();
    }

    // Points.
    const many = d.points.length / 2 > 5000;
    ctx.fillStyle = COLORS.point;
    ctx.beginPath();
    for (let i = 0; i < d.points.length / 2; i++) {
      const q = view.toScreen(d.points[2 * i], d.points[2 * i + 1]);
      if (many) ctx.rect(q.x - 1, q.y - 1, 2, 2);
      else { ctx.moveTo(q.x + 3.5, q.y); ctx.arc(q.x, q.y, 3.5, 0, 2 * Math.PI); }
    }
    ctx.fill();
    const ring = (x, y, color, r = 7) => {
      const q = view.toScreen(x, y);
      ctx.beginPath(); ctx.arc(q.x, q.y, r, 0, 2 * Math.PI);
      ctx.strokeStyle = color; ctx.lineWidth = 2; ctx.stroke();
    };
    for (const item of [s.hoverItem, s.selection]) {
      if (item?.kind !== 'point' || item.index >= d.points.length / 2) continue;
      ring(d.points[2 * item.index], d.points[2 * item.index + 1], item === s.selection ? COLORS.selected : COLORS.hover);
    }

    // Hole seeds: a red cross in a circle.
    for (let i = 0; i < d.holes.length / 2; i++) {
      const q = view.toScreen(d.holes[2 * i], d.holes[2 * i + 1]);
      ctx.beginPath();
      ctx.arc(q.x, q.y, 7, 0, 2 * Math.PI);
      ctx.fillStyle = '#fff'; ctx.fill();
      ctx.moveTo(q.x - 4, q.y - 4); ctx.lineTo(q.x + 4, q.y + 4);
      ctx.moveTo(q.x + 4, q.y - 4); ctx.lineTo(q.x - 4, q.y + 4);
      ctx.strokeStyle = COLORS.hole; ctx.lineWidth = 2; ctx.stroke();
      if (selected('hole', i) || hovered('hole', i)) ring(d.holes[2 * i], d.holes[2 * i + 1], selected('hole', i) ? COLORS.selected : COLORS.hover, 11);
    }

    // Region seeds: a violet diamond with the attribute (and max area) beside it.
    ctx.font = '12px system-ui, sans-serif';
    d.regions.forEach((r, i) => {
      const q = view.toScreen(r.x, r.y);
      ctx.beginPath();
      ctx.moveTo(q.x, q.y - 7); ctx.lineTo(q.x + 7, q.y); ctx.lineTo(q.x, q.y + 7); ctx.lineTo(q.x - 7, q.y); ctx.closePath();
      ctx.fillStyle = '#fff'; ctx.fill();
      ctx.strokeStyle = COLORS.region; ctx.lineWidth = 2; ctx.stroke();
      const label = `${r.attribute ?? 0}${r.maxArea > 0 ? ` ≤${r.maxArea}` : ''}`;
      ctx.lineWidth = 3; ctx.strokeStyle = '#fff'; ctx.strokeText(label, q.x + 10, q.y + 4);
      ctx.fillStyle = COLORS.region; ctx.fillText(label, q.x + 10, q.y + 4);
      if (selected('region', i) || hovered('region', i)) ring(r.x, r.y, selected('region', i) ? COLORS.selected : COLORS.hover, 11);
    });
  }

  /**
   * Each vertex of the mesh on screen with its number (the numbers the event texts use; in step
   * mode those of the final mesh, the same in every step), for meshes of up to
   * VERTEX_NUMBERS_UP_TO vertices and only those in view, one per small cell of the screen.
   */
  drawVertexNumbers(view) {
    const { ctx } = this;
    const p = this.mesh?.points;
    if (!p || p.length / 2 > VERTEX_NUMBERS_UP_TO) return;
    const used = new Uint8Array(p.length / 2);
    for (const v of this.mesh.triangles) used[v] = 1;
    ctx.font = '11px system-ui, sans-serif';
    ctx.textAlign = 'left';
    ctx.textBaseline = 'bottom';
    ctx.lineJoin = 'round';
    // One label per 18 x 12 pixel cell: where vertices crowd, the first takes the place (zoom in for the rest).
    const taken = new Set();
    for (let v = 0; v < p.length / 2; v++) {
      if (!used[v]) continue;
      const q = view.toScreen(p[2 * v], p[2 * v + 1]);
      if (q.x < -20 || q.y < -20 || q.x > view.width + 20 || q.y > view.height + 20) continue;
      const cell = `${Math.floor(q.x / 18)},${Math.floor(q.y / 12)}`;
      if (taken.has(cell)) continue;
      taken.add(cell);
      ctx.lineWidth = 3; ctx.strokeStyle = '#fff'; ctx.strokeText(String(v), q.x + 3, q.y - 2);
      ctx.fillStyle = '#111827'; ctx.fillText(String(v), q.x + 3, q.y - 2);
    }
    ctx.textBaseline = 'alphabetic';
  }

  drawNotices(notices, view) {
    const { ctx } = this;
    for (const notice of notices) {
      // NOTHING_ENCLOSED is about the whole input, not a place.
      if (!Number.isFinite(notice.x) || !Number.isFinite(notice.y) || notice.kind === 'NOTHING_ENCLOSED') continue;
      const q = view.toScreen(notice.x, notice.y);
      ctx.beginPath(); ctx.arc(q.x, q.y, 10, 0, 2 * Math.PI);
      ctx.strokeStyle = COLORS.notice; ctx.lineWidth = 2.5; ctx.stroke();
    }
  }
}
