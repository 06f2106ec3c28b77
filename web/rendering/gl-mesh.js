// WebGL2 drawing of the mesh: the white background, the grid, the triangles filled with their
// color class and their edges, on a canvas of its own under the 2D canvas (which keeps the
// overlays: the drawing, hover, step events, notices).
//
// Speed. The mesh goes to the GPU once (a coloring change re-sends only the colors); panning
// and zooming change two uniforms. Edges are drawn by the fill shader from each corner's
// barycentric coordinate (no line primitives: in software GL a line costs more than a triangle).
// What a frame costs is its number of triangles (SwiftShader, the GL of headless Chromium,
// takes about 0.4 us each), so:
// - triangles are sorted into chunks (a grid over the mesh's box); a frame draws only the chunks
//   in view, as contiguous ranges;
// - a chunk whose triangles are below a few pixels on screen is not drawn as triangles but
//   shown from an overview picture: the whole mesh rasterized once on the CPU (one sample per
//   texel, the edges as the gray their density gives: mesh-overview.js) into a texture, drawn as
//   one quad.
// Positions are sent relative to the mesh's center so float32 keeps the precision of a zoom.

import { boundsOf, emptyBounds, includePoint } from '../geometry/bounds.js';
import { parseColor, rasterizeOverview, walkOverview } from './mesh-overview.js';

const MESH_VERTEX = `#version 300 es
in vec2 position;
in vec4 color;
in vec3 corner;       // (1,0,0), (0,1,0), (0,0,1): barycentric coordinate of the corner
uniform vec2 scale;   // world units (relative to the origin) -> clip space
uniform vec2 offset;
out vec4 fill;
out vec3 bary;
void main() {
  gl_Position = vec4(position * scale + offset, 0.0, 1.0);
  fill = color;
  bary = corner;
}`;

const MESH_FRAGMENT = `#version 300 es
precision highp float;
in vec4 fill;
in vec3 bary;
uniform vec4 edge;    // edge color, its alpha the line's opacity
uniform float alpha;  // dims everything (a step still on its way)
uniform bool lines;   // grid lines: the color alone
out vec4 outColor;
void main() {
  if (lines) { outColor = vec4(edge.rgb, edge.a * alpha); return; }
  // Distance to the nearest edge in pixels: half a pixel from each side, one pixel per edge.
  vec3 d = bary / max(fwidth(bary), vec3(1e-6));
  float near = min(min(d.x, d.y), d.z);
  float on = (1.0 - smoothstep(0.0, 0.75, near)) * edge.a;
  outColor = vec4(mix(fill.rgb, edge.rgb, on), alpha);
}`;

const QUAD_VERTEX = `#version 300 es
in vec2 position;     // the corners of the overview's box, relative to the origin
in vec2 texel;
uniform vec2 scale;
uniform vec2 offset;
out vec2 uv;
void main() { gl_Position = vec4(position * scale + offset, 0.0, 1.0); uv = texel; }`;

const QUAD_FRAGMENT = `#version 300 es
precision highp float;
in vec2 uv;
uniform sampler2D picture;
uniform float alpha;
out vec4 outColor;
void main() { vec4 c = texture(picture, uv); outColor = vec4(c.rgb, c.a * alpha); }`;

/** Chunks whose triangles' mean edge is below this many device pixels come from the overview. */
export const OVERVIEW_BELOW_PX = 6;
/** Meshes above this many triangles are sent to the GPU after their first picture. */
const DEFER_ABOVE = 200_000;
const MAX_TEXTURE = 4096;

function compile(gl, type, source) {
  const shader = gl.createShader(type);
  gl.shaderSource(shader, source);
  gl.compileShader(shader);
  if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(`shader: ${gl.getShaderInfoLog(shader)}`);
  return shader;
}

function link(gl, vertex, fragment, attributes, uniforms) {
  const program = gl.createProgram();
  gl.attachShader(program, compile(gl, gl.VERTEX_SHADER, vertex));
  gl.attachShader(program, compile(gl, gl.FRAGMENT_SHADER, fragment));
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(`program: ${gl.getProgramInfoLog(program)}`);
  const at = { program };
  for (const a of attributes) at[a] = gl.getAttribLocation(program, a);
  for (const u of uniforms) at[u] = gl.getUniformLocation(program, u);
  return at;
}

function buffer(gl, program, name, data, size, type = gl.FLOAT, normalized = false) {
  const b = gl.createBuffer();
  gl.bindBuffer(gl.ARRAY_BUFFER, b);
  if (data) gl.bufferData(gl.ARRAY_BUFFER, data, gl.STATIC_DRAW);
  gl.enableVertexAttribArray(program[name]);
  gl.vertexAttribPointer(program[name], size, type, normalized, 0, 0);
  return b;
}

export class GlMesh {
  /** Returns null when the browser gives no WebGL2 context (the page then draws in 2D). */
  static create(canvas) {
    let gl = null;
    try {
      // preserveDrawingBuffer: the picture stays readable after the frame (PNG export, tests).
      gl = canvas.getContext('webgl2', { antialias: false, preserveDrawingBuffer: true });
    } catch { gl = null; }
    if (!gl) return null;
    try { return new GlMesh(canvas, gl); } catch { return null; }
  }

  constructor(canvas, gl) {
    this.canvas = canvas;
    this.gl = gl;
    this.mesh = link(gl, MESH_VERTEX, MESH_FRAGMENT, ['position', 'color', 'corner'], ['scale', 'offset', 'edge', 'alpha', 'lines']);
    this.quad = link(gl, QUAD_VERTEX, QUAD_FRAGMENT, ['position', 'texel'], ['scale', 'offset', 'picture', 'alpha']);
    this.fills = gl.createVertexArray();
    gl.bindVertexArray(this.fills);
    this.positions = buffer(gl, this.mesh, 'position', null, 2);
    this.colors = buffer(gl, this.mesh, 'color', null, 4, gl.UNSIGNED_BYTE, true);
    this.corners = buffer(gl, this.mesh, 'corner', null, 3, gl.UNSIGNED_BYTE, false);
    this.gridArray = gl.createVertexArray();
    gl.bindVertexArray(this.gridArray);
    this.gridPositions = buffer(gl, this.mesh, 'position', null, 2);
    this.quadArray = gl.createVertexArray();
    gl.bindVertexArray(this.quadArray);
    this.quadPositions = buffer(gl, this.quad, 'position', null, 2);
    buffer(gl, this.quad, 'texel', new Float32Array([0, 0, 1, 0, 0, 1, 1, 1]), 2);
    gl.bindVertexArray(null);
    this.texture = gl.createTexture();
    this.triangleCount = 0;
    this.chunks = [];
    this.origin = [0, 0];
    this.colorKey = null;
    this.overview = null;  // { width, height } of the overview texture, or null
    this.cornerCapacity = 0;
  }

  /**
   * Takes a mesh (null: no mesh); its colors follow with setColors. A large mesh's triangles
   * go to the GPU after its first picture (from the overview), in a task of their own; `onReady`
   * is called then, to draw again.
   */
  setMesh(mesh, onReady = () => {}) {
    this.colorKey = null;
    this.overview = null;
    this.source = mesh && mesh.triangles.length > 0 ? mesh : null;
    this.triangleCount = this.source ? mesh.triangles.length / 3 : 0;
    this.chunks = [];
    this.geometryReady = false;
    this.readyAt = null;
    this.generation = (this.generation ?? 0) + 1;
    clearTimeout(this.deferred);
    if (!this.source) return;
    const p = mesh.points;
    const box = boundsOf(p);
    this.box = box;
    this.origin = [(box.minX + box.maxX) / 2, (box.minY + box.maxY) / 2];
    if (this.triangleCount <= DEFER_ABOVE) {
      this.buildGeometry();
      this.geometryReady = true;
      return;
    }
    const generation = this.generation;
    const later = (step) => {
      this.deferred = setTimeout(() => { if (generation === this.generation) step(); }, 0);
    };
    // After the first picture (drawn in the next animation frame), in two tasks so neither holds
    // the page long: the triangles, then their colors and the sharp overview. Frames in between
    // still come from the quick overview (geometryReady is set with the colors).
    later(() => later(() => {
      this.buildGeometry();
      later(() => {
        this.geometryReady = true;
        if (this.coloring) {
          this.coloring.classes ??= this.classesOf(this.coloring.classOf);
          this.applyColors();
        }
        this.warmUp();
        this.readyAt = performance.now();  // benchmarks: when the triangles were on the GPU
        onReady();
      });
    }));
  }

  /**
   * One triangle drawn with color writes off: the GL takes in the new buffers now rather than
   * in the first frame that needs them (0.6 s for 1.5 M triangles in SwiftShader).
   */
  warmUp() {
    const gl = this.gl;
    gl.colorMask(false, false, false, false);
    gl.useProgram(this.mesh.program);
    gl.bindVertexArray(this.fills);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.bindVertexArray(null);
    gl.colorMask(true, true, true, true);
  }

  /** The triangles, chunk by chunk, to the GPU. */
  buildGeometry() {
    const gl = this.gl;
    const mesh = this.source;
    const p = mesh.points;
    const tri = mesh.triangles;
    const n = this.triangleCount;
    const [ox, oy] = this.origin;
    this.order = this.sortIntoChunks(mesh);
    const corners = new Float32Array(6 * n);
    for (let s = 0; s < n; s++) {
      const t = this.order[s];
      for (let c = 0; c < 3; c++) {
        const v = 2 * tri[3 * t + c];
        corners[6 * s + 2 * c] = p[v] - ox;
        corners[6 * s + 2 * c + 1] = p[v + 1] - oy;
      }
    }
    gl.bindBuffer(gl.ARRAY_BUFFER, this.positions);
    gl.bufferData(gl.ARRAY_BUFFER, corners, gl.STATIC_DRAW);
    if (this.cornerCapacity < n) {
      // The same (1,0,0) (0,1,0) (0,0,1) for every triangle: sent again only when the mesh grows.
      this.cornerCapacity = Math.max(n, 2 * this.cornerCapacity);
      const bary = new Uint8Array(9 * this.cornerCapacity);
      for (let s = 0; s < this.cornerCapacity; s++) { bary[9 * s] = 1; bary[9 * s + 4] = 1; bary[9 * s + 8] = 1; }
      gl.bindBuffer(gl.ARRAY_BUFFER, this.corners);
      gl.bufferData(gl.ARRAY_BUFFER, bary, gl.STATIC_DRAW);
    }
  }

  /**
   * Triangles ordered chunk by chunk (a grid of about 2000 triangles a cell over the box, by
   * centroid); each chunk's range, box and mean edge length kept for culling and level of detail.
   */
  sortIntoChunks(mesh) {
    const p = mesh.points;
    const tri = mesh.triangles;
    const n = this.triangleCount;
    const { minX, minY, maxX, maxY } = this.box;
    const side = Math.max(1, Math.min(128, Math.round(Math.sqrt(n / 2000))));
    const w = Math.max(maxX - minX, 1e-300); const h = Math.max(maxY - minY, 1e-300);
    const cellOf = new Uint32Array(n);
    const count = new Uint32Array(side * side + 1);
    for (let t = 0; t < n; t++) {
      const i = 2 * tri[3 * t]; const j = 2 * tri[3 * t + 1]; const k = 2 * tri[3 * t + 2];
      const cx = Math.min(side - 1, Math.floor(((p[i] + p[j] + p[k]) / 3 - minX) / w * side));
      const cy = Math.min(side - 1, Math.floor(((p[i + 1] + p[j + 1] + p[k + 1]) / 3 - minY) / h * side));
      cellOf[t] = cy * side + cx;
      count[cellOf[t] + 1]++;
    }
    for (let c = 0; c < side * side; c++) count[c + 1] += count[c];
    const next = count.slice(0, side * side);
    const order = new Uint32Array(n);
    for (let t = 0; t < n; t++) order[next[cellOf[t]]++] = t;
    for (let c = 0; c < side * side; c++) {
      const start = count[c]; const end = count[c + 1];
      if (start === end) continue;
      const chunk = { start, count: end - start, ...emptyBounds(), meanEdge: 0 };
      let area = 0;
      for (let s = start; s < end; s++) {
        const t = order[s];
        const i = 2 * tri[3 * t]; const j = 2 * tri[3 * t + 1]; const k = 2 * tri[3 * t + 2];
        for (const v of [i, j, k]) includePoint(chunk, p[v], p[v + 1]);
        area += Math.abs((p[j] - p[i]) * (p[k + 1] - p[i + 1]) - (p[j + 1] - p[i + 1]) * (p[k] - p[i])) / 2;
      }
      // The edge of an equilateral triangle of the chunk's mean area.
      chunk.meanEdge = Math.sqrt((4 / Math.sqrt(3)) * area / chunk.count);
      this.chunks.push(chunk);
    }
    return order;
  }

  /**
   * Sends the fill color of every triangle: `classOf(t)` gives its index into `palette`
   * (CSS colors); and rasterizes the overview picture with them. `key` names the coloring, so
   * an unchanged one is not sent again. `edgeColor`: the color of the edges in the overview.
   */
  setColors(key, palette, classOf, edgeColor) {
    if (this.colorKey === key || this.triangleCount === 0) return;
    this.colorKey = key;
    if (!this.geometryReady) {
      // A large mesh's first picture: only the triangles under the overview's texels are colored.
      this.coloring = { palette, classOf, edgeColor, classes: null };
      this.uploadOverview(walkOverview(this.source, this.overviewBox(), palette, classOf, edgeColor), false);
      return;
    }
    this.coloring = { palette, classOf, edgeColor, classes: this.classesOf(classOf) };
    this.applyColors();
  }

  classesOf(classOf) {
    const classes = new Uint16Array(this.triangleCount);
    for (let t = 0; t < this.triangleCount; t++) classes[t] = classOf(t);
    return classes;
  }

  /** The colors to the triangles (on the GPU by now) and the sharp overview. */
  applyColors() {
    const { palette, classes, edgeColor } = this.coloring;
    if (this.geometryReady) {
      const words = palette.map((css) => {
        const [r, g, b, a] = parseColor(css).map((x) => Math.round(x * 255));
        return ((a << 24) | (b << 16) | (g << 8) | r) >>> 0;  // little-endian RGBA bytes
      });
      const packed = new Uint32Array(3 * this.triangleCount);
      for (let s = 0; s < this.triangleCount; s++) {
        const w = words[classes[this.order[s]]];
        packed[3 * s] = w; packed[3 * s + 1] = w; packed[3 * s + 2] = w;
      }
      const gl = this.gl;
      gl.bindBuffer(gl.ARRAY_BUFFER, this.colors);
      gl.bufferData(gl.ARRAY_BUFFER, packed, gl.STATIC_DRAW);
    }
    this.uploadOverview(rasterizeOverview(this.source, this.overviewBox(), palette, classes, edgeColor), true);
  }

  /** Device pixels per world unit when the mesh's box fills the canvas. */
  fitScale() {
    const { minX, minY, maxX, maxY } = this.box;
    return Math.min(this.canvas.width / Math.max(maxX - minX, 1e-300), this.canvas.height / Math.max(maxY - minY, 1e-300));
  }

  /** What the overview rasterizers need: the mesh's box, the fit scale and the texture limit. */
  overviewBox() {
    return {
      ...this.box,
      fit: this.fitScale(),
      limit: Math.min(MAX_TEXTURE, this.gl.getParameter(this.gl.MAX_TEXTURE_SIZE)),
    };
  }

  uploadOverview({ image, size: { width, height, sx } }, sharp) {
    const gl = this.gl;
    gl.bindTexture(gl.TEXTURE_2D, this.texture);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, width, height, 0, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(image.buffer));
    gl.generateMipmap(gl.TEXTURE_2D);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR_MIPMAP_LINEAR);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
    const { minX, minY, maxX, maxY } = this.box;
    const [ox, oy] = this.origin;
    const quad = new Float32Array([minX - ox, minY - oy, maxX - ox, minY - oy, minX - ox, maxY - oy, maxX - ox, maxY - oy]);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.quadPositions);
    gl.bufferData(gl.ARRAY_BUFFER, quad, gl.STATIC_DRAW);
    this.overview = { width, height, texelWorld: 1 / sx, sharp };
  }

  resize(width, height) {
    if (this.canvas.width !== width || this.canvas.height !== height) {
      this.canvas.width = width;
      this.canvas.height = height;
    }
  }

  /**
   * The chunks to draw as triangles in this view: those in view whose triangles are large
   * enough on screen (or when the overview is too coarse for them). Adjacent ranges merged.
   */
  visibleRanges(view, dpr) {
    const b = view.visibleBounds();
    const pxPerUnit = view.scale * dpr;
    const texelPx = this.overview ? this.overview.texelWorld * pxPerUnit : Infinity;
    const ranges = [];
    this.drawnTriangles = 0;
    this.overviewUsed = !this.geometryReady;
    for (const c of this.chunks) {
      if (c.maxX < b.minX || c.minX > b.maxX || c.maxY < b.minY || c.minY > b.maxY) continue;
      if (c.meanEdge * pxPerUnit < OVERVIEW_BELOW_PX && texelPx <= 2) {  // the overview shows it
        this.overviewUsed = true;
        continue;
      }
      const last = ranges[ranges.length - 1];
      if (last && last.start + last.count === c.start) last.count += c.count;
      else ranges.push({ start: c.start, count: c.count });
      this.drawnTriangles += c.count;
    }
    return ranges;
  }

  /**
   * One frame: background, grid lines ([{ lines: Float32Array of world segments, color }]), the
   * overview and the triangles in view. `view` is the page's View; `alpha` dims the mesh.
   */
  draw(view, dpr, { background, grid, edgeColor, alpha = 1 }) {
    const gl = this.gl;
    const [br, bg, bb] = parseColor(background);
    gl.viewport(0, 0, this.canvas.width, this.canvas.height);
    gl.clearColor(br, bg, bb, 1);
    gl.clear(gl.COLOR_BUFFER_BIT);
    gl.enable(gl.BLEND);
    // Colors blend over what is there; the canvas's alpha stays 1 (it is composited as
    // premultiplied: an alpha below 1 would wash a dimmed mesh out towards white).
    gl.blendFuncSeparate(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA, gl.ZERO, gl.ONE);
    const sx = (2 * view.scale) / view.width;
    const sy = (2 * view.scale) / view.height;
    const [ox, oy] = this.origin;
    const offset = [(ox - view.centerX) * sx, (oy - view.centerY) * sy];
    const m = this.mesh;
    gl.useProgram(m.program);
    gl.uniform2f(m.scale, sx, sy);
    gl.uniform2f(m.offset, ...offset);
    gl.uniform1f(m.alpha, 1);
    gl.uniform1i(m.lines, 1);
    for (const { lines, color } of grid) this.drawGrid(lines, color);
    this.drawnTriangles = 0;
    this.overviewUsed = false;
    if (this.triangleCount === 0) return;
    const ranges = this.visibleRanges(view, dpr);
    if (this.overview && this.overviewUsed) {
      const q = this.quad;
      gl.useProgram(q.program);
      gl.uniform2f(q.scale, sx, sy);
      gl.uniform2f(q.offset, ...offset);
      gl.uniform1f(q.alpha, alpha);
      gl.activeTexture(gl.TEXTURE0);
      gl.bindTexture(gl.TEXTURE_2D, this.texture);
      gl.uniform1i(q.picture, 0);
      gl.bindVertexArray(this.quadArray);
      gl.drawArrays(gl.TRIANGLE_STRIP, 0, 4);
    }
    gl.useProgram(m.program);
    gl.uniform1i(m.lines, 0);
    gl.uniform1f(m.alpha, alpha);
    gl.uniform4f(m.edge, ...parseColor(edgeColor));
    gl.bindVertexArray(this.fills);
    for (const { start, count } of ranges) gl.drawArrays(gl.TRIANGLES, 3 * start, 3 * count);
    gl.bindVertexArray(null);
  }

  drawGrid(lines, color) {
    const gl = this.gl;
    if (lines.length === 0) return;
    const [ox, oy] = this.origin;
    const relative = new Float32Array(lines.length);
    for (let i = 0; i < lines.length; i += 2) { relative[i] = lines[i] - ox; relative[i + 1] = lines[i + 1] - oy; }
    gl.bindBuffer(gl.ARRAY_BUFFER, this.gridPositions);
    gl.bufferData(gl.ARRAY_BUFFER, relative, gl.DYNAMIC_DRAW);
    gl.uniform4f(this.mesh.edge, ...parseColor(color));
    gl.bindVertexArray(this.gridArray);
    gl.drawArrays(gl.LINES, 0, relative.length / 2);
  }

  /** Waits for the GPU to finish the frame (benchmarks: a frame's true cost). */
  finish() {
    const pixel = new Uint8Array(4);
    this.gl.readPixels(0, 0, 1, 1, this.gl.RGBA, this.gl.UNSIGNED_BYTE, pixel);
  }
}
