// Per-triangle measures for coloring and hovering, and finding the triangle under the pointer.

const DEG = 180 / Math.PI;

/** The three angles (degrees) of triangle t, at its vertices 0, 1, 2, and its edge lengths. */
export function triangleShape(mesh, t) {
  const p = mesh.points;
  const i = mesh.triangles[3 * t];
  const j = mesh.triangles[3 * t + 1];
  const k = mesh.triangles[3 * t + 2];
  const ax = p[2 * i]; const ay = p[2 * i + 1];
  const bx = p[2 * j]; const by = p[2 * j + 1];
  const cx = p[2 * k]; const cy = p[2 * k + 1];
  // Edge lengths opposite each vertex.
  const a = Math.hypot(cx - bx, cy - by);
  const b = Math.hypot(ax - cx, ay - cy);
  const c = Math.hypot(bx - ax, by - ay);
  // Angles from the law of cosines via atan2 of (|cross|, dot): accurate also for tiny angles.
  const angleAt = (ox, oy, ux, uy, vx, vy) => {
    const x1 = ux - ox; const y1 = uy - oy; const x2 = vx - ox; const y2 = vy - oy;
    return Math.atan2(Math.abs(x1 * y2 - y1 * x2), x1 * x2 + y1 * y2) * DEG;
  };
  const angles = [angleAt(ax, ay, bx, by, cx, cy), angleAt(bx, by, cx, cy, ax, ay), angleAt(cx, cy, ax, ay, bx, by)];
  const doubleArea = Math.abs((bx - ax) * (cy - ay) - (by - ay) * (cx - ax));
  // Circumradius R = abc / (4 * area); radius-edge ratio = R / shortest edge.
  const circumradius = doubleArea > 0 ? (a * b * c) / (2 * doubleArea) : Infinity;
  const radiusEdge = circumradius / Math.min(a, b, c);
  return { vertices: [i, j, k], angles, area: doubleArea / 2, radiusEdge };
}

/** Smallest angle (degrees) of triangle t of the points p and corners tri. */
function smallestAngle(p, tri, t) {
  const i = 2 * tri[3 * t]; const j = 2 * tri[3 * t + 1]; const k = 2 * tri[3 * t + 2];
  const ux = p[j] - p[i]; const uy = p[j + 1] - p[i + 1];
  const vx = p[k] - p[j]; const vy = p[k + 1] - p[j + 1];
  const wx = p[i] - p[k]; const wy = p[i + 1] - p[k + 1];
  // The smallest angle is opposite the shortest edge: sin(angle) = 2*area / (product of the two others).
  const a2 = ux * ux + uy * uy; const b2 = vx * vx + vy * vy; const c2 = wx * wx + wy * wy;
  const cross = Math.abs(ux * vy - uy * vx);
  const s = a2 <= b2 && a2 <= c2 ? cross / Math.sqrt(b2 * c2) : b2 <= c2 ? cross / Math.sqrt(a2 * c2) : cross / Math.sqrt(a2 * b2);
  return Math.asin(Math.min(1, s)) * DEG;
}

/** Smallest angle (degrees) of every triangle, for coloring. */
export function minAngles(mesh) {
  const n = mesh.triangles.length / 3;
  const result = new Float32Array(n);
  for (let t = 0; t < n; t++) result[t] = smallestAngle(mesh.points, mesh.triangles, t);
  return result;
}

/** Smallest angle (degrees) of triangle t alone (coloring a few triangles before all). */
export function minAngleOf(mesh, t) {
  return smallestAngle(mesh.points, mesh.triangles, t);
}

function contains(mesh, t, x, y) {
  const p = mesh.points;
  const tri = mesh.triangles;
  const i = 2 * tri[3 * t]; const j = 2 * tri[3 * t + 1]; const k = 2 * tri[3 * t + 2];
  // Counter-clockwise triangles: inside when left of (or on) all three edges.
  const side = (ax, ay, bx, by) => (bx - ax) * (y - ay) - (by - ay) * (x - ax);
  return side(p[i], p[i + 1], p[j], p[j + 1]) >= 0 &&
    side(p[j], p[j + 1], p[k], p[k + 1]) >= 0 &&
    side(p[k], p[k + 1], p[i], p[i + 1]) >= 0;
}

/**
 * The triangle containing (x, y), or -1. Walks from `hint` through neighbors (fast while the
 * pointer moves a little); a walk can stop at a hole or the boundary, then every triangle is tried.
 */
export function findTriangle(mesh, x, y, hint = -1) {
  const n = mesh.triangles.length / 3;
  if (n === 0) return -1;
  const p = mesh.points;
  const tri = mesh.triangles;
  let t = hint >= 0 && hint < n ? hint : 0;
  for (let steps = 0; steps < 4096; steps++) {
    let outside = -1;  // an edge the point lies strictly beyond
    for (let e = 0; e < 3 && outside < 0; e++) {
      const a = 2 * tri[3 * t + (e + 1) % 3];
      const b = 2 * tri[3 * t + (e + 2) % 3];
      // Edge e is opposite vertex e; counter-clockwise order puts the inside on its left.
      if ((p[b] - p[a]) * (y - p[a + 1]) - (p[b + 1] - p[a + 1]) * (x - p[a]) < 0) outside = e;
    }
    if (outside < 0) return t;
    const next = mesh.neighbors[3 * t + outside];
    if (next < 0) break;  // the walk reached the boundary or a hole
    t = next;
  }
  for (let s = 0; s < n; s++) if (contains(mesh, s, x, y)) return s;
  return -1;
}

/** Bins of smallestAngleSummary's histogram: one degree each over [0, 60], the smallest angle's range. */
export const SMALLEST_ANGLE_BINS = 60;

/**
 * What smoothing is meant to change, measured on one mesh: a histogram of the triangles' smallest
 * angles (one-degree bins over [0, 60]; 60 itself in the last), their mean in degrees, and how
 * many triangles are obtuse (largest angle over 90 degrees: the longest edge's square exceeds
 * the sum of the other two's).
 */
export function smallestAngleSummary(mesh) {
  const smallest = minAngles(mesh);
  const histogram = new Uint32Array(SMALLEST_ANGLE_BINS);
  let sum = 0;
  for (const angle of smallest) {
    histogram[Math.min(SMALLEST_ANGLE_BINS - 1, Math.floor(angle))]++;
    sum += angle;
  }
  const p = mesh.points;
  const tri = mesh.triangles;
  let obtuse = 0;
  for (let t = 0; t < smallest.length; t++) {
    const i = 2 * tri[3 * t]; const j = 2 * tri[3 * t + 1]; const k = 2 * tri[3 * t + 2];
    const a2 = (p[j] - p[i]) ** 2 + (p[j + 1] - p[i + 1]) ** 2;
    const b2 = (p[k] - p[j]) ** 2 + (p[k + 1] - p[j + 1]) ** 2;
    const c2 = (p[i] - p[k]) ** 2 + (p[i + 1] - p[k + 1]) ** 2;
    const longest = Math.max(a2, b2, c2);
    if (longest > a2 + b2 + c2 - longest) obtuse++;
  }
  return { histogram, mean: smallest.length ? sum / smallest.length : NaN, obtuse, triangles: smallest.length };
}

/** How many vertices sit elsewhere in `after` than in `before` (two meshes numbering the same vertices). */
export function movedVertices(before, after) {
  const n = Math.min(before.points.length, after.points.length) / 2;
  let moved = 0;
  for (let v = 0; v < n; v++) {
    if (before.points[2 * v] !== after.points[2 * v] || before.points[2 * v + 1] !== after.points[2 * v + 1]) moved++;
  }
  return moved;
}

// mesh.triangleExemptions' values (the core's kExemptSmallInputAngle, kExemptSeditiousEdge).
const SMALL_INPUT_ANGLE = 1;
const SEDITIOUS_EDGE = 2;

/**
 * The triangles the core left below the bounds on purpose (§6.6), read from its per-triangle
 * mesh.triangleExemptions (options.exemptions): { nestled, seditious: triangle indices,
 * seditiousEdges: [u, w, ...] each seditious triangle's shortest edge, the one the rule is about },
 * or null when the mesh has none recorded.
 */
export function exemptTriangles(mesh) {
  const flags = mesh?.triangleExemptions;
  if (!flags) return null;
  const result = { nestled: [], seditious: [], seditiousEdges: [] };
  const p = mesh.points;
  const tri = mesh.triangles;
  const length2 = (a, b) => (p[2 * b] - p[2 * a]) ** 2 + (p[2 * b + 1] - p[2 * a + 1]) ** 2;
  for (let t = 0; t < flags.length; t++) {
    if (flags[t] === SMALL_INPUT_ANGLE) result.nestled.push(t);
    else if (flags[t] === SEDITIOUS_EDGE) {
      result.seditious.push(t);
      const v = [tri[3 * t], tri[3 * t + 1], tri[3 * t + 2]];
      const l2 = [length2(v[1], v[2]), length2(v[2], v[0]), length2(v[0], v[1])];
      const e = l2[0] <= l2[1] && l2[0] <= l2[2] ? 0 : l2[1] <= l2[2] ? 1 : 2;
      result.seditiousEdges.push(v[(e + 1) % 3], v[(e + 2) % 3]);
    }
  }
  return result;
}
