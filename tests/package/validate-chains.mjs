// Every input segment must be a chain of mesh subsegments from one end to the other, except where it
// runs outside the meshed domain (through a hole, or beyond the segments that enclose the domain).
// Judged from the package's output and the input alone, with exact orientation signs, and valid
// for repaired inputs too: the mesh's notices say which points were merged, which segments were
// dropped as duplicates or zero-length, and which share collinear pieces (either may carry them).
//
// Along a segment, the stretches its candidate subsegments cover are merged (a subsegment passing
// beside a vertex of the segment's own chain, or one exactly on it, covers nothing); what is left
// is a stretch that no chain covers. Such a stretch is a problem when it
// runs into a triangle: its midpoint is inside one (or on an edge between two), or it leaves one of
// its ends into a triangle's corner. A stretch no longer than the tolerance (rounding of crossings,
// see `tolerance`) is forgiven, as is one leaving the domain within the tolerance of a vertex.
import { orient, orientToMidpoint } from './exact-predicates.mjs';

// How far a vertex of a segment's chain may lie from its line: rounded crossings lie off their
// segments by a few ulps of the coordinates and of the length (as tests/core/validator.h allows).
export const segmentTolerance = (length, magnitude) => 1e-9 * length + 2 ** -46 * magnitude;

function repairsOf(mesh, nPoints) {
  const mergedInto = new Int32Array(nPoints).fill(-1);
  const dropped = new Set();
  const partners = new Map();
  const link = (a, b) => {
    if (!partners.has(a)) partners.set(a, new Set());
    partners.get(a).add(b);
  };
  for (const n of mesh.notices ?? []) {
    if (n.kind === 'DUPLICATE_POINT' && n.a >= 0 && n.a < nPoints) mergedInto[n.a] = n.b;
    if (n.kind === 'ZERO_LENGTH_SEGMENT') dropped.add(n.a);
    if (n.kind === 'DUPLICATE_SEGMENT') dropped.add(n.a), link(n.b, n.a), link(n.a, n.b);
    if (n.kind === 'SEGMENTS_OVERLAP') link(n.a, n.b), link(n.b, n.a);
  }
  const resolve = (p) => {
    for (let guard = 0; guard < 64 && mergedInto[p] >= 0; guard++) p = mergedInto[p];
    return p;
  };
  return { resolve, dropped, partners };
}

// Triangles around each vertex, and point location by a scan with bounding boxes (only stretches
// without a chain are located, and they are few).
function meshIndex(mesh) {
  const { points: p, triangles: t } = mesh;
  const around = new Map();
  for (let k = 0; k < t.length / 3; k++) {
    for (let i = 0; i < 3; i++) {
      const v = t[3 * k + i];
      if (!around.has(v)) around.set(v, []);
      around.get(v).push(k);
    }
  }
  const corner = (k, i) => [p[2 * t[3 * k + i]], p[2 * t[3 * k + i] + 1]];
  // Triangles whose closed region holds the exact midpoint of vertices u and w, and how many hold
  // it in their interior. The bounding boxes are widened by an ulp: the rounded midpoint only
  // filters, the exact signs decide.
  const containingMidpoint = (u, w) => {
    const [ux, uy, wx, wy] = [p[2 * u], p[2 * u + 1], p[2 * w], p[2 * w + 1]];
    const x = (ux + wx) / 2, y = (uy + wy) / 2;
    const slack = 2 ** -51 * Math.max(Math.abs(x), Math.abs(y), Number.MIN_VALUE);
    const hits = [];
    let strict = 0;
    for (let k = 0; k < t.length / 3; k++) {
      const [a, b, c] = [corner(k, 0), corner(k, 1), corner(k, 2)];
      if (x < Math.min(a[0], b[0], c[0]) - slack || x > Math.max(a[0], b[0], c[0]) + slack ||
          y < Math.min(a[1], b[1], c[1]) - slack || y > Math.max(a[1], b[1], c[1]) + slack) continue;
      const o = [[a, b], [b, c], [c, a]].map(([f, g]) => orientToMidpoint(...f, ...g, ux, uy, wx, wy));
      if (o.some((s) => s < 0)) continue;
      hits.push(k);
      if (o.every((s) => s > 0)) strict++;
    }
    return { hits, strict };
  };
  return { around, corner, containingMidpoint };
}

// A triangle the stretch u-w runs into, or -1 (see the file's comment). Mesh vertices exactly on
// the stretch cut it into pieces judged one by one: a stretch that only touches the domain at a
// vertex (its midpoint may be that very vertex) does not run into the triangles around it.
function stretchInDomain(mesh, index, u, w, tol) {
  const p = mesh.points;
  const [ux, uy, wx, wy] = [p[2 * u], p[2 * u + 1], p[2 * w], p[2 * w + 1]];
  const along = (v) => (p[2 * v] - ux) * (wx - ux) + (p[2 * v + 1] - uy) * (wy - uy);
  const end = along(w);
  const cuts = [...index.around.keys()].filter((v) => v !== u && v !== w && along(v) > 0 && along(v) < end &&
    orient(ux, uy, wx, wy, p[2 * v], p[2 * v + 1]) === 0).sort((x, y) => along(x) - along(y));
  if (cuts.length > 0) {
    const ends = [u, ...cuts, w];
    for (let i = 0; i + 1 < ends.length; i++) {
      const hit = stretchInDomain(mesh, index, ends[i], ends[i + 1], tol);
      if (hit >= 0) return hit;
    }
    return -1;
  }
  const { hits, strict } = index.containingMidpoint(u, w);
  if (hits.length > 1 || strict > 0) return hits[0];
  for (const [from, to] of [[u, w], [w, u]]) {
    const f = [p[2 * from], p[2 * from + 1]], g = [p[2 * to], p[2 * to + 1]];
    for (const k of index.around.get(from) ?? []) {
      const i = [0, 1, 2].find((j) => mesh.triangles[3 * k + j] === from);
      const x = index.corner(k, (i + 1) % 3), y = index.corner(k, (i + 2) % 3);
      if (!(orient(...f, ...x, ...g) >= 0 && orient(...f, ...y, ...g) <= 0)) continue;
      if (mesh.neighbors[3 * k + i] === -1 && orient(...x, ...y, ...g) < 0) {
        // It leaves through the boundary edge x-y: forgiven if it does so within the tolerance.
        const inside = (y[0] - x[0]) * (f[1] - x[1]) - (y[1] - x[1]) * (f[0] - x[0]);
        const beyond = (y[0] - x[0]) * (g[1] - x[1]) - (y[1] - x[1]) * (g[0] - x[0]);
        if ((inside / (inside - beyond)) * Math.hypot(g[0] - f[0], g[1] - f[1]) <= tol) continue;
      }
      return k;
    }
  }
  return -1;
}

const usedVertices = (mesh) => new Set(mesh.triangles);

// The smallest value in the sorted `list` above x (Infinity if none).
function firstAbove(list, x) {
  let lo = 0, hi = list.length;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (list[mid] > x) hi = mid;
    else lo = mid + 1;
  }
  return lo < list.length ? list[lo] : Infinity;
}

/** Problems with the chains of `input`'s segments in `mesh` (strings; empty when every one is whole). */
export function chainProblems(mesh, input, maxProblems = 20) {
  const problems = [];
  const p = mesh.points, s = mesh.segments, ids = mesh.segmentIds;
  const nPoints = input.points.length / 2, nSegments = input.segments.length / 2;
  const { resolve, dropped, partners } = repairsOf(mesh, nPoints);
  const bySegment = new Map();
  for (let k = 0; k < ids.length; k++) {
    if (!bySegment.has(ids[k])) bySegment.set(ids[k], []);
    bySegment.get(ids[k]).push(k);
  }
  const key = (u, v) => (u < v ? `${u},${v}` : `${v},${u}`);
  let index = null, used = null;
  for (let id = 0; id < nSegments && problems.length < maxProblems; id++) {
    if (dropped.has(id)) continue;
    const a = resolve(input.segments[2 * id]), b = resolve(input.segments[2 * id + 1]);
    if (a === b) {
      problems.push(`input segment ${id} has zero length but no ZERO_LENGTH_SEGMENT notice`);
      continue;
    }
    const ax = p[2 * a], ay = p[2 * a + 1], dx = p[2 * b] - ax, dy = p[2 * b + 1] - ay;
    const len2 = dx * dx + dy * dy, len = Math.sqrt(len2);
    const tol = segmentTolerance(len, Math.max(Math.abs(ax), Math.abs(ay), Math.abs(p[2 * b]), Math.abs(p[2 * b + 1])));
    const param = (v) => ((p[2 * v] - ax) * dx + (p[2 * v + 1] - ay) * dy) / len2;
    const nearLine = (v) => Math.abs((p[2 * v] - ax) * dy - (p[2 * v + 1] - ay) * dx) / len <= tol;
    const onSegment = (v) => nearLine(v) && param(v) * len >= -tol && (param(v) - 1) * len <= tol;
    // Another segment's subsegment carries this one only where the core merged them: within rounding
    // (2^-48 of the coordinates' magnitude or the length, 2^-40 for a snapped crossing), here 2^-38.
    // The looser `tol` let a partner 1e-6 rad away carry this segment 1.5e-10 off its line, across a
    // third segment it had already crossed (careless-sweep seed 39953).
    const mergeTol = 2 ** -38 * Math.max(Math.abs(ax), Math.abs(ay), Math.abs(p[2 * b]), Math.abs(p[2 * b + 1]), len);
    const merged = (v) => Math.abs((p[2 * v] - ax) * dy - (p[2 * v + 1] - ay) * dx) / len <= mergeTol;
    // Candidate carriers: this segment's subsegments and those of segments sharing pieces with it.
    const group = new Set([id]);
    for (const todo = [id]; todo.length;) {
      for (const other of partners.get(todo.pop()) ?? []) if (!group.has(other)) group.add(other), todo.push(other);
    }
    const graph = new Map([[a, []], [b, []]]);
    const carried = new Set();
    for (const g of group) {
      for (const k of bySegment.get(g) ?? []) {
        const u = s[2 * k], w = s[2 * k + 1];
        if (!onSegment(u) || !onSegment(w)) continue;
        if (g !== id && (!merged(u) || !merged(w))) continue;
        if (!graph.has(u)) graph.set(u, []);
        if (!graph.has(w)) graph.set(w, []);
        graph.get(u).push(w), graph.get(w).push(u);
        carried.add(key(u, w));
      }
    }
    const seen = new Set([a]);
    for (const queue = [a]; queue.length && !seen.has(b);) {
      for (const w of graph.get(queue.shift())) if (!seen.has(w)) seen.add(w), queue.push(w);
    }
    if (seen.has(b)) continue;
    // Stations: the vertices of the segment's own subsegments and those exactly on it. A carrier
    // passing beside a station (one strictly between its ends) covers nothing, so a chain stepping
    // back past a vertex of its segment leaves a gap. A segment at a tiny angle to this one has
    // vertices within the tolerance on its own chain, not this one's: they are not stations, and its
    // carriers may pass beside this one's stations, which this one's own chain then covers.
    const own = new Set();
    for (const k of bySegment.get(id) ?? []) own.add(s[2 * k]), own.add(s[2 * k + 1]);
    // The segment's ends are stations only where they are mesh vertices: an end the mesh does not
    // use (outside the domain) a hair before the end of a carrier must not void that carrier.
    used ??= usedVertices(mesh);
    const stations = [a, b].filter((v) => used.has(v)).map(param);
    for (const v of graph.keys()) {
      if (!used.has(v)) continue;
      if (own.has(v) || orient(ax, ay, p[2 * b], p[2 * b + 1], p[2 * v], p[2 * v + 1]) === 0) stations.push(param(v));
    }
    stations.sort((x, y) => x - y);
    const covers = [];
    for (const edge of carried) {
      let [u, w] = edge.split(',').map(Number);
      if (param(w) < param(u)) [u, w] = [w, u];
      if (firstAbove(stations, param(u)) < param(w)) continue;  // passes beside a station
      covers.push({ lo: param(u), hi: param(w), from: u, to: w });
    }
    covers.sort((x, y) => x.lo - y.lo);
    covers.push({ lo: param(b), hi: param(b), from: b, to: b });  // the far end closes the last stretch
    let reached = a, reachedParam = param(a);
    for (const c of covers) {
      if (c.lo <= reachedParam) {
        if (c.hi > reachedParam) reached = c.to, reachedParam = c.hi;
        continue;
      }
      const u = reached, w = c.from;
      reached = c.to, reachedParam = c.hi;
      if (Math.hypot(p[2 * w] - p[2 * u], p[2 * w + 1] - p[2 * u + 1]) <= tol) continue;
      index ??= meshIndex(mesh);
      const hit = stretchInDomain(mesh, index, u, w, tol);
      if (hit < 0) continue;
      // A triangle lying wholly within the tolerance of the line is one the chain may pass beside.
      if ([0, 1, 2].every((i) => nearLine(mesh.triangles[3 * hit + i]))) continue;
      problems.push(`input segment ${id} (${input.segments[2 * id]}, ${input.segments[2 * id + 1]}) is not a chain ` +
        `of subsegments between vertices ${u} and ${w}: the stretch runs into triangle ${hit}`);
      break;
    }
  }
  return problems;
}
