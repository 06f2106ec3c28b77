// An independent check of a mesh returned by the package, in plain JavaScript doubles.
//
// It re-derives every property from the typed arrays alone (never trusting the core's stats):
//   * layout: array lengths agree with each other, indices are in range;
//   * orientation: every triangle is counter-clockwise with non-zero area;
//   * topology: neighbors are symmetric and share the edge, no edge has three triangles, every
//     boundary edge is a subsegment;
//   * constraints: every subsegment is a triangle edge and lies on its input segment's line; every
//     input segment is a chain of subsegments from end to end except where it runs outside the
//     domain, repaired inputs included (validate-chains.mjs); on inputs the core did not repair,
//     the subsegments carrying a segment's id add up to no more than its length;
//   * orientation and constrained Delaunay with exact signs (exact-predicates.mjs): across every
//     edge that is not a subsegment, the opposite vertex is not strictly inside the circumcircle;
//   * bounds, when asked: minimum angle, maximum area.
// Returns a list of problems (empty when valid) so a failing test shows what broke.

import { incircle, orient } from './exact-predicates.mjs';
import { chainProblems, segmentTolerance } from './validate-chains.mjs';

const repairKinds = new Set(['DUPLICATE_SEGMENT', 'ZERO_LENGTH_SEGMENT', 'VERTEX_ON_SEGMENT', 'SEGMENTS_OVERLAP',
  'SEGMENTS_CROSS', 'DUPLICATE_POINT']);

export function triangleAngles(p, a, b, c) {
  const len2 = (i, j) => (p[2 * i] - p[2 * j]) ** 2 + (p[2 * i + 1] - p[2 * j + 1]) ** 2;
  const ea = len2(b, c), eb = len2(c, a), ec = len2(a, b);
  const angle = (opp, s1, s2) => Math.acos(Math.min(1, Math.max(-1, (s1 + s2 - opp) / (2 * Math.sqrt(s1 * s2))))) * 180 / Math.PI;
  return [angle(ea, eb, ec), angle(eb, ec, ea), angle(ec, ea, eb)];
}

export function triangleArea(p, a, b, c) {
  return 0.5 * ((p[2 * b] - p[2 * a]) * (p[2 * c + 1] - p[2 * a + 1]) - (p[2 * b + 1] - p[2 * a + 1]) * (p[2 * c] - p[2 * a]));
}


/**
 * @param {object} mesh result of triangulate()
 * @param {{ input?: { points, segments }, minAngle?: number, maxArea?: number, maxProblems?: number }} [checks]
 * @returns {string[]} problems
 */
export function validateMesh(mesh, checks = {}) {
  const problems = [];
  const maxProblems = checks.maxProblems ?? 20;
  const report = (message) => { if (problems.length < maxProblems) problems.push(message); };

  const { points: p, triangles: t, neighbors: nb, segments: s, segmentIds: ids } = mesh;
  const nv = p.length / 2, nt = t.length / 3, ns = s.length / 2;
  if (!(p instanceof Float64Array) || !(t instanceof Uint32Array) || !(nb instanceof Int32Array) ||
      !(s instanceof Uint32Array) || !(ids instanceof Int32Array)) report('wrong typed array types');
  if (!Number.isInteger(nv)) report(`points has odd length ${p.length}`);
  if (!Number.isInteger(nt)) report(`triangles length ${t.length} is not a multiple of 3`);
  if (nb.length !== t.length) report(`neighbors length ${nb.length} != triangles length ${t.length}`);
  if (!Number.isInteger(ns) || ids.length !== ns) report(`segments/segmentIds lengths ${s.length}/${ids.length}`);
  if (mesh.vertexKinds.length !== nv) report(`vertexKinds length ${mesh.vertexKinds.length} != ${nv} points`);
  if (mesh.triangleAttributes.length !== nt) report(`triangleAttributes length ${mesh.triangleAttributes.length} != ${nt}`);
  if (problems.length) return problems;
  for (let i = 0; i < t.length; i++) if (t[i] >= nv) report(`triangles[${i}] = ${t[i]} out of range`);
  for (let i = 0; i < s.length; i++) if (s[i] >= nv) report(`segments[${i}] = ${s[i]} out of range`);
  for (let i = 0; i < nb.length; i++) if (nb[i] < -1 || nb[i] >= nt) report(`neighbors[${i}] = ${nb[i]} out of range`);
  if (problems.length) return problems;
  // Numeric edge keys: exact below 2^53, far faster than strings on millions of edges.
  const key = (u, v) => (u < v ? u * nv + v : v * nv + u);

  // Orientation.
  for (let k = 0; k < nt; k++) {
    const a = t[3 * k], b = t[3 * k + 1], c = t[3 * k + 2];
    const o = orient(p[2 * a], p[2 * a + 1], p[2 * b], p[2 * b + 1], p[2 * c], p[2 * c + 1]);
    if (!(o > 0)) report(`triangle ${k} (${a}, ${b}, ${c}) is ${o === 0 ? 'degenerate' : 'clockwise'}`);
  }

  // Edges: each at most twice, neighbors symmetric.
  const edgeCount = new Map();
  for (let k = 0; k < nt; k++) {
    for (let i = 0; i < 3; i++) {
      const u = t[3 * k + (i + 1) % 3], v = t[3 * k + (i + 2) % 3];
      const e = key(u, v);
      edgeCount.set(e, (edgeCount.get(e) ?? 0) + 1);
      const n = nb[3 * k + i];
      if (n === -1) continue;
      let j = -1;
      for (let m = 0; m < 3; m++) {
        if (t[3 * n + (m + 1) % 3] === v && t[3 * n + (m + 2) % 3] === u) j = m;
      }
      if (j < 0) report(`triangle ${k} edge ${i} (${u}, ${v}): neighbor ${n} does not have edge (${v}, ${u})`);
      else if (nb[3 * n + j] !== k) report(`triangle ${k} -> ${n} but ${n} edge ${j} -> ${nb[3 * n + j]}`);
    }
  }
  for (const [e, count] of edgeCount) if (count > 2) report(`edge ${Math.floor(e / nv)}-${e % nv} belongs to ${count} triangles`);

  const subsegments = new Set();
  for (let i = 0; i < ns; i++) {
    const e = key(s[2 * i], s[2 * i + 1]);
    subsegments.add(e);
    if (!edgeCount.has(e)) report(`subsegment ${i} (${s[2 * i]}, ${s[2 * i + 1]}) is not a triangle edge`);
  }
  for (let k = 0; k < nt; k++) {
    for (let i = 0; i < 3; i++) {
      if (nb[3 * k + i] !== -1) continue;
      const u = t[3 * k + (i + 1) % 3], v = t[3 * k + (i + 2) % 3];
      if (!subsegments.has(key(u, v))) report(`boundary edge (${u}, ${v}) of triangle ${k} is not a subsegment`);
    }
  }

  // Constrained Delaunay: only edges that are not subsegments must be locally Delaunay.
  for (let k = 0; k < nt; k++) {
    for (let i = 0; i < 3; i++) {
      const n = nb[3 * k + i];
      if (n < k) continue;  // boundary, or checked from the other side
      const u = t[3 * k + (i + 1) % 3], v = t[3 * k + (i + 2) % 3];
      if (subsegments.has(key(u, v))) continue;
      let d = -1;
      for (let m = 0; m < 3; m++) if (t[3 * n + m] !== u && t[3 * n + m] !== v) d = t[3 * n + m];
      const a = t[3 * k], b = t[3 * k + 1], c = t[3 * k + 2];
      if (incircle(p[2 * a], p[2 * a + 1], p[2 * b], p[2 * b + 1], p[2 * c], p[2 * c + 1], p[2 * d], p[2 * d + 1]) > 0) report(`edge (${u}, ${v}) is not locally Delaunay: vertex ${d} inside the circumcircle of triangle ${k}`);
    }
  }

  // Each input segment covered by its chain of subsegments.
  if (checks.input?.segments) {
    const ip = checks.input.points, is = checks.input.segments;
    const covered = new Float64Array(is.length / 2);
    for (let i = 0; i < ns; i++) {
      const id = ids[i];
      if (id === -1) continue;
      // A piece of plc.curves[c] has id segments + c: curves.test.mjs checks those against their curves.
      if (id >= is.length / 2 && id < is.length / 2 + (checks.input.curves?.length ?? 0)) continue;
      if (id < 0 || id >= is.length / 2) { report(`segmentIds[${i}] = ${id} out of range`); continue; }
      const a = s[2 * i], b = s[2 * i + 1];
      covered[id] += Math.hypot(p[2 * b] - p[2 * a], p[2 * b + 1] - p[2 * a + 1]);
      const ia = is[2 * id], ib = is[2 * id + 1];
      const [ax, ay, bx, by] = [ip[2 * ia], ip[2 * ia + 1], ip[2 * ib], ip[2 * ib + 1]];
      const length = Math.hypot(bx - ax, by - ay);
      const tol = segmentTolerance(length, Math.max(Math.abs(ax), Math.abs(ay), Math.abs(bx), Math.abs(by)));
      for (const w of [a, b]) {
        if (Math.abs((p[2 * w] - ax) * (by - ay) - (p[2 * w + 1] - ay) * (bx - ax)) / length > tol) {
          report(`subsegment ${i} vertex ${w} is off input segment ${id}`);
        }
      }
    }
    for (const problem of chainProblems(mesh, checks.input, maxProblems)) report(problem);
    // Where the core repaired nothing, one segment's subsegments cannot add up to more than it.
    const repaired = (mesh.notices ?? []).some((n) => repairKinds.has(n.kind));
    for (let id = 0; id < covered.length && !repaired; id++) {
      const a = is[2 * id], b = is[2 * id + 1];
      const length = Math.hypot(ip[2 * b] - ip[2 * a], ip[2 * b + 1] - ip[2 * a + 1]);
      if (covered[id] - length > 1e-9 * length) {
        report(`input segment ${id}: subsegments add up to ${covered[id]}, more than its length ${length}`);
      }
    }
  }

  if (checks.minAngle !== undefined || checks.maxArea !== undefined) {
    for (let k = 0; k < nt; k++) {
      const a = t[3 * k], b = t[3 * k + 1], c = t[3 * k + 2];
      if (checks.minAngle !== undefined) {
        const smallest = Math.min(...triangleAngles(p, a, b, c));
        if (smallest < checks.minAngle - 1e-6) report(`triangle ${k} has angle ${smallest} < ${checks.minAngle}`);
      }
      if (checks.maxArea !== undefined) {
        const area = triangleArea(p, a, b, c);
        if (area > checks.maxArea * (1 + 1e-9)) report(`triangle ${k} has area ${area} > ${checks.maxArea}`);
      }
    }
  }
  return problems;
}
