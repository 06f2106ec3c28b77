// The chapter's exemptions from the angle bound (§6.6), judged from a mesh's output arrays and its
// input PLC, as tests/core/validator.cpp judges them for the Catch2 tests:
//   * nestled: the triangle's smallest angle lies between two subsegments meeting at its vertex (an
//     input angle, or a crossing), which no Steiner point can improve;
//   * seditious: its shortest edge joins two vertices inserted on two different input segments that
//     meet (at a shared endpoint or where they cross) at under 45 degrees, at the same distance from
//     where they meet (one concentric shell).
// nonExemptMinAngle() returns the smallest angle over the other triangles: what the bound must hold on
// (and the largest angle over them, for maxAngle, which has the same exemptions).

const SEGMENT_SPLIT = 1;  // VertexKind.SegmentSplit in ruppert.h

// Angle at p of the corner q-p-r, in degrees (atan2 keeps digits near 0 and 180).
export function cornerDegrees(px, py, qx, qy, rx, ry) {
  const ux = qx - px, uy = qy - py, vx = rx - px, vy = ry - py;
  return (Math.atan2(Math.abs(ux * vy - uy * vx), ux * vx + uy * vy) * 180) / Math.PI;
}

const edgeKey = (a, b) => (a < b ? a * 4294967296 + b : b * 4294967296 + a);

// Where input segments s and t meet: a shared endpoint, or their crossing; null if they do not.
function meetingPoint(plc, s, t) {
  const p = plc.points;
  const end = (k, e) => plc.segments[2 * k + e];
  const [a0, a1, b0, b1] = [end(s, 0), end(s, 1), end(t, 0), end(t, 1)];
  const same = (i, j) => p[2 * i] === p[2 * j] && p[2 * i + 1] === p[2 * j + 1];
  if (same(a0, b0) || same(a0, b1)) return [p[2 * a0], p[2 * a0 + 1]];
  if (same(a1, b0) || same(a1, b1)) return [p[2 * a1], p[2 * a1 + 1]];
  const ax = p[2 * a1] - p[2 * a0], ay = p[2 * a1 + 1] - p[2 * a0 + 1];
  const bx = p[2 * b1] - p[2 * b0], by = p[2 * b1 + 1] - p[2 * b0 + 1];
  const den = ax * by - ay * bx;
  if (den === 0) return null;
  const dx = p[2 * b0] - p[2 * a0], dy = p[2 * b0 + 1] - p[2 * a0 + 1];
  const ta = (dx * by - dy * bx) / den, tb = (dx * ay - dy * ax) / den;
  if (!(ta >= 0 && ta <= 1 && tb >= 0 && tb <= 1)) return null;
  return [p[2 * a0] + ta * ax, p[2 * a0 + 1] + ta * ay];
}

class ExemptionJudge {
  constructor(mesh, plc) {
    this.mesh = mesh;
    this.plc = plc;
    this.subsegments = new Set();
    this.segmentOf = new Int32Array(mesh.points.length / 2).fill(-1);  // input segment of each split vertex
    for (let k = 0; k < mesh.segmentIds.length; k++) {
      const a = mesh.segments[2 * k], b = mesh.segments[2 * k + 1];
      this.subsegments.add(edgeKey(a, b));
      for (const v of [a, b]) if (mesh.vertexKinds[v] === SEGMENT_SPLIT) this.segmentOf[v] = mesh.segmentIds[k];
    }
  }

  nestled(corner, v) {
    return this.subsegments.has(edgeKey(v[corner], v[(corner + 1) % 3])) &&
      this.subsegments.has(edgeKey(v[corner], v[(corner + 2) % 3]));
  }

  seditious(v, xy) {
    let shortest = 0;
    let best = Infinity;
    for (let i = 0; i < 3; i++) {
      const a = (i + 1) % 3, b = (i + 2) % 3;
      const l = Math.hypot(xy[2 * a] - xy[2 * b], xy[2 * a + 1] - xy[2 * b + 1]);
      if (l < best) { best = l; shortest = i; }
    }
    const u = v[(shortest + 1) % 3], w = v[(shortest + 2) % 3];
    const su = this.segmentOf[u], sw = this.segmentOf[w];
    if (su < 0 || sw < 0 || su === sw || su >= this.plc.segments.length / 2 || sw >= this.plc.segments.length / 2) return false;
    const z = meetingPoint(this.plc, su, sw);
    if (z === null) return false;
    const p = this.mesh.points;
    const [ux, uy, wx, wy] = [p[2 * u], p[2 * u + 1], p[2 * w], p[2 * w + 1]];
    if (cornerDegrees(z[0], z[1], ux, uy, wx, wy) >= 45) return false;
    const du = Math.hypot(ux - z[0], uy - z[1]), dw = Math.hypot(wx - z[0], wy - z[1]);
    return Math.abs(du - dw) <= 1e-5 * Math.max(du, dw);
  }
}

// mesh: { points, triangles, segments, segmentIds, vertexKinds }; plc: { points, segments } (the
// input, unrepaired: the families need no repair). Returns { minAngle, maxAngle, exempt } where
// minAngle and maxAngle are the smallest and largest angles of non-exempt triangles (180 and 0 when
// there is none) and exempt counts the others.
export function nonExemptMinAngle(mesh, plc) {
  const judge = new ExemptionJudge(mesh, plc);
  const t = mesh.triangles;
  const p = mesh.points;
  const v = [0, 0, 0];
  const xy = new Float64Array(6);
  let minAngle = 180;
  let maxAngle = 0;
  let exempt = 0;
  for (let k = 0; k < t.length; k += 3) {
    for (let i = 0; i < 3; i++) {
      v[i] = t[k + i];
      xy[2 * i] = p[2 * v[i]];
      xy[2 * i + 1] = p[2 * v[i] + 1];
    }
    let corner = 0;
    let smallest = 180;
    let largest = 0;
    for (let i = 0; i < 3; i++) {
      const a = (i + 1) % 3, b = (i + 2) % 3;
      const angle = cornerDegrees(xy[2 * i], xy[2 * i + 1], xy[2 * a], xy[2 * a + 1], xy[2 * b], xy[2 * b + 1]);
      if (angle < smallest) { smallest = angle; corner = i; }
      largest = Math.max(largest, angle);
    }
    if (judge.nestled(corner, v) || judge.seditious(v, xy)) exempt++;
    else minAngle = Math.min(minAngle, smallest), maxAngle = Math.max(maxAngle, largest);
  }
  return { minAngle, maxAngle, exempt };
}
