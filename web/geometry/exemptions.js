// The triangles the refinement leaves skinny on purpose (§6.6), found again from the mesh the
// page has, by the core's own rules (core/src/refine/refine.cpp: nestledInInputAngle, seditious):
// - nestled in a small input angle: the smallest angle's two edges are both subsegments;
// - on a seditious edge: the shortest edge joins split vertices of two input segments that meet
//   at a vertex z at under 45°, at the same distance from z (the same concentric shell).
// The core counts them in mesh.reasons (SMALL_INPUT_ANGLE, SEDITIOUS_EDGE); the page marks them.

const SEGMENT_SPLIT = 1;  // VertexKind
const SEDITIOUS_BELOW = Math.PI / 4;
const DEG = Math.PI / 180;

/**
 * { nestled: triangle indices, seditious: triangle indices, seditiousEdges: [u, w, ...] } of a mesh
 * refined to `minAngle` degrees from `plc` (its input segments name the segments' corners).
 */
export function findExemptions(mesh, plc, minAngle) {
  const result = { nestled: [], seditious: [], seditiousEdges: [] };
  if (!(minAngle > 0) || !mesh) return result;
  const p = mesh.points;
  const tri = mesh.triangles;
  const sub = new Set();
  const key = (a, b) => (a < b ? a * 4294967296 + b : b * 4294967296 + a);
  const segmentOf = new Map();  // split vertex -> input segment it lies on
  for (let s = 0; s < mesh.segments.length / 2; s++) {
    const a = mesh.segments[2 * s]; const b = mesh.segments[2 * s + 1];
    sub.add(key(a, b));
    const id = mesh.segmentIds[s];
    if (id >= 0) { segmentOf.set(a, id); segmentOf.set(b, id); }
  }
  const sin2Bound = Math.sin(minAngle * DEG) ** 2;
  const length2 = (a, b) => (p[2 * b] - p[2 * a]) ** 2 + (p[2 * b + 1] - p[2 * a + 1]) ** 2;
  for (let t = 0; t < tri.length / 3; t++) {
    const v = [tri[3 * t], tri[3 * t + 1], tri[3 * t + 2]];
    // Edge e is opposite corner e; the shortest edge faces the smallest angle.
    const l2 = [length2(v[1], v[2]), length2(v[2], v[0]), length2(v[0], v[1])];
    const e = l2[0] <= l2[1] && l2[0] <= l2[2] ? 0 : l2[1] <= l2[2] ? 1 : 2;
    const cross = Math.abs((p[2 * v[1]] - p[2 * v[0]]) * (p[2 * v[2] + 1] - p[2 * v[0] + 1]) -
      (p[2 * v[1] + 1] - p[2 * v[0] + 1]) * (p[2 * v[2]] - p[2 * v[0]]));
    // sin^2 of the smallest angle = (2 area)^2 / (product of its two edges' squared lengths).
    const sin2 = (cross * cross) / (l2[(e + 1) % 3] * l2[(e + 2) % 3]);
    if (!(sin2 < sin2Bound)) continue;
    const corner = v[e];
    if (sub.has(key(corner, v[(e + 1) % 3])) && sub.has(key(corner, v[(e + 2) % 3]))) {
      result.nestled.push(t);
    } else if (seditious(v[(e + 1) % 3], v[(e + 2) % 3], mesh, plc, segmentOf)) {
      result.seditious.push(t);
      result.seditiousEdges.push(v[(e + 1) % 3], v[(e + 2) % 3]);
    }
  }
  return result;
}

function seditious(u, w, mesh, plc, segmentOf) {
  if (mesh.vertexKinds[u] !== SEGMENT_SPLIT || mesh.vertexKinds[w] !== SEGMENT_SPLIT) return false;
  const su = segmentOf.get(u); const sw = segmentOf.get(w);
  if (su === undefined || sw === undefined || su === sw) return false;
  const s = plc.segments;
  const a = [s[2 * su], s[2 * su + 1]]; const b = [s[2 * sw], s[2 * sw + 1]];
  const shared = a.find((x) => b.includes(x));
  const p = mesh.points;
  let zx; let zy;
  if (shared !== undefined) {
    zx = plc.points[2 * shared]; zy = plc.points[2 * shared + 1];
  } else {
    const z = crossing(plc.points, a, b);
    if (z === null) return false;
    [zx, zy] = z;
  }
  const ux = p[2 * u] - zx; const uy = p[2 * u + 1] - zy;
  const wx = p[2 * w] - zx; const wy = p[2 * w + 1] - zy;
  if (Math.atan2(Math.abs(ux * wy - uy * wx), ux * wx + uy * wy) >= SEDITIOUS_BELOW) return false;
  const du = Math.hypot(ux, uy); const dw = Math.hypot(wx, wy);
  return Math.abs(du - dw) <= 1e-6 * Math.max(du, dw);
}

/** Where segments a and b of points cross, or null. */
function crossing(q, a, b) {
  const [x1, y1, x2, y2] = [q[2 * a[0]], q[2 * a[0] + 1], q[2 * a[1]], q[2 * a[1] + 1]];
  const [x3, y3, x4, y4] = [q[2 * b[0]], q[2 * b[0] + 1], q[2 * b[1]], q[2 * b[1] + 1]];
  const d = (x2 - x1) * (y4 - y3) - (y2 - y1) * (x4 - x3);
  if (d === 0) return null;
  const s = ((x3 - x1) * (y4 - y3) - (y3 - y1) * (x4 - x3)) / d;
  const t = ((x3 - x1) * (y2 - y1) - (y3 - y1) * (x2 - x1)) / d;
  if (s < 0 || s > 1 || t < 0 || t > 1) return null;
  return [x1 + s * (x2 - x1), y1 + s * (y2 - y1)];
}
