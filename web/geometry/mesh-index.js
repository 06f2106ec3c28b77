// Finding the triangle under the pointer without scanning the mesh: a short walk from the last
// triangle hovered (the pointer moves a little between events); else a walk from the triangle
// whose centroid lies in the point's cell of a coarse grid (one triangle a cell, built in one
// pass); else, where that walk meets the boundary (a hole or a notch between), a uniform grid of
// buckets over the mesh's box, each listing the triangles whose bounding box meets it. Both grids
// are built when first needed (not on the mesh's arrival, so the first picture does not wait).
import { boundsOf } from './bounds.js';

const WALK_STEPS = 64;
const SEED_WALK_STEPS = 1024;
const seedGrids = new WeakMap();  // mesh -> SeedGrid
const grids = new WeakMap();  // mesh -> TriangleGrid

function inside(p, tri, t, x, y) {
  const i = 2 * tri[3 * t]; const j = 2 * tri[3 * t + 1]; const k = 2 * tri[3 * t + 2];
  const side = (a, b) => (p[b] - p[a]) * (y - p[a + 1]) - (p[b + 1] - p[a + 1]) * (x - p[a]);
  return side(i, j) >= 0 && side(j, k) >= 0 && side(k, i) >= 0;  // counter-clockwise triangles
}

/** Walks from triangle t towards (x, y); the triangle reached, or -1 (a hole, the boundary, too far). */
export function walk(mesh, t, x, y, maxSteps = WALK_STEPS) {
  const p = mesh.points;
  const tri = mesh.triangles;
  for (let steps = 0; steps < maxSteps; steps++) {
    let outside = -1;
    for (let e = 0; e < 3 && outside < 0; e++) {
      const a = 2 * tri[3 * t + (e + 1) % 3];
      const b = 2 * tri[3 * t + (e + 2) % 3];
      if ((p[b] - p[a]) * (y - p[a + 1]) - (p[b + 1] - p[a + 1]) * (x - p[a]) < 0) outside = e;
    }
    if (outside < 0) return t;
    t = mesh.neighbors[3 * t + outside];
    if (t < 0) return -1;
  }
  return -1;
}

/** Box of the mesh's points, as the grids use it: corner and (nonzero) size. */
function boxOf(p) {
  const { minX, minY, maxX, maxY } = boundsOf(p);
  return { minX, minY, w: Math.max(maxX - minX, 1e-300), h: Math.max(maxY - minY, 1e-300) };
}

/** One triangle per cell (the last whose centroid falls in it), about four triangles a cell. */
export class SeedGrid {
  constructor(mesh) {
    const p = mesh.points;
    const tri = mesh.triangles;
    const n = tri.length / 3;
    Object.assign(this, boxOf(p));
    const cells = Math.max(1, Math.ceil(n / 4));
    this.nx = Math.max(1, Math.min(2048, Math.round(Math.sqrt(cells * this.w / this.h))));
    this.ny = Math.max(1, Math.min(2048, Math.round(cells / this.nx)));
    this.seeds = new Int32Array(this.nx * this.ny).fill(-1);
    for (let t = 0; t < n; t++) {
      const i = 2 * tri[3 * t]; const j = 2 * tri[3 * t + 1]; const k = 2 * tri[3 * t + 2];
      this.seeds[this.cell((p[i] + p[j] + p[k]) / 3, (p[i + 1] + p[j + 1] + p[k + 1]) / 3)] = t;
    }
  }

  cell(x, y) {
    const cx = Math.min(this.nx - 1, Math.max(0, Math.floor(((x - this.minX) / this.w) * this.nx)));
    const cy = Math.min(this.ny - 1, Math.max(0, Math.floor(((y - this.minY) / this.h) * this.ny)));
    return cy * this.nx + cx;
  }

  /** A triangle near (x, y): its cell's seed, or the first seed of the cells around it. */
  near(x, y) {
    const c = this.cell(x, y);
    if (this.seeds[c] >= 0) return this.seeds[c];
    const cx = c % this.nx; const cy = (c - cx) / this.nx;
    for (let r = 1; r < 4; r++) {
      for (let dy = -r; dy <= r; dy++) {
        for (let dx = -r; dx <= r; dx++) {
          const x2 = cx + dx; const y2 = cy + dy;
          if (x2 < 0 || y2 < 0 || x2 >= this.nx || y2 >= this.ny) continue;
          const s = this.seeds[y2 * this.nx + x2];
          if (s >= 0) return s;
        }
      }
    }
    return 0;
  }
}

export class TriangleGrid {
  constructor(mesh) {
    const p = mesh.points;
    const tri = mesh.triangles;
    const n = tri.length / 3;
    const { minX, minY, w, h } = boxOf(p);
    // About one triangle per cell, the cells square-ish.
    const cells = Math.max(1, n);
    this.nx = Math.max(1, Math.min(4096, Math.round(Math.sqrt(cells * w / h))));
    this.ny = Math.max(1, Math.min(4096, Math.round(cells / this.nx)));
    this.minX = minX; this.minY = minY;
    this.cx = this.nx / w; this.cy = this.ny / h;
    // Two passes over the triangles' cell ranges: count, then fill (compressed rows).
    const start = new Uint32Array(this.nx * this.ny + 1);
    this.forCells(p, tri, n, (cell) => { start[cell + 1]++; });
    for (let c = 0; c < this.nx * this.ny; c++) start[c + 1] += start[c];
    const fill = start.slice(0, this.nx * this.ny);
    const items = new Uint32Array(start[this.nx * this.ny]);
    this.forCells(p, tri, n, (cell, t) => { items[fill[cell]++] = t; });
    this.start = start;
    this.items = items;
  }

  cellX(x) { return Math.min(this.nx - 1, Math.max(0, Math.floor((x - this.minX) * this.cx))); }
  cellY(y) { return Math.min(this.ny - 1, Math.max(0, Math.floor((y - this.minY) * this.cy))); }

  forCells(p, tri, n, visit) {
    for (let t = 0; t < n; t++) {
      const i = 2 * tri[3 * t]; const j = 2 * tri[3 * t + 1]; const k = 2 * tri[3 * t + 2];
      const x0 = this.cellX(Math.min(p[i], p[j], p[k])); const x1 = this.cellX(Math.max(p[i], p[j], p[k]));
      const y0 = this.cellY(Math.min(p[i + 1], p[j + 1], p[k + 1])); const y1 = this.cellY(Math.max(p[i + 1], p[j + 1], p[k + 1]));
      for (let cy = y0; cy <= y1; cy++) for (let cx = x0; cx <= x1; cx++) visit(cy * this.nx + cx, t);
    }
  }

  /** The triangle containing (x, y) among those listed in its cell, or -1. */
  find(mesh, x, y) {
    if (x < this.minX || y < this.minY || (x - this.minX) * this.cx > this.nx || (y - this.minY) * this.cy > this.ny) return -1;
    const cell = this.cellY(y) * this.nx + this.cellX(x);
    for (let s = this.start[cell]; s < this.start[cell + 1]; s++) {
      if (inside(mesh.points, mesh.triangles, this.items[s], x, y)) return this.items[s];
    }
    return -1;
  }
}

/** The triangle of `mesh` containing (x, y), or -1; `hint` is the last one found. */
export function locateTriangle(mesh, x, y, hint = -1) {
  const n = mesh.triangles.length / 3;
  if (n === 0) return -1;
  if (hint >= 0 && hint < n) {
    const t = walk(mesh, hint, x, y);
    if (t >= 0) return t;
  }
  let seeds = seedGrids.get(mesh);
  if (!seeds) {
    seeds = new SeedGrid(mesh);
    seedGrids.set(mesh, seeds);
  }
  const t = walk(mesh, seeds.near(x, y), x, y, SEED_WALK_STEPS);
  if (t >= 0) return t;
  let grid = grids.get(mesh);
  if (!grid) {
    grid = new TriangleGrid(mesh);
    grids.set(mesh, grid);
  }
  return grid.find(mesh, x, y);
}
