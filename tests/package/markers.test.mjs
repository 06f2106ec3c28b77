// Boundary markers and edges from the installed package: box.poly keeps
// Triangle's markers 5, 10 and 33; random markers on random PLCs land on exactly the subsegments and
// vertices of their segments; `edges: true` lists every edge once with its marker; the CLI's -e.
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { init } from 'ruppert';

const dataDir = process.env.RUPPERT_SHARED_DATA;
const boxPath = dataDir === undefined ? '' : join(dataDir, 'box.poly');
const haveBox = boxPath !== '' && existsSync(boxPath);
if (!haveBox) console.log(`# box.poly not found in ${dataDir}: its tests are skipped`);

// Deterministic random numbers (xorshift), so a failure can be replayed.
function rng(seed) {
  let s = BigInt(seed) | 1n;
  return () => {
    s ^= s << 13n; s &= (1n << 64n) - 1n; s ^= s >> 7n; s ^= s << 17n; s &= (1n << 64n) - 1n;
    return Number(s >> 11n) / 2 ** 53;
  };
}

// Input segments through point (x, y), in index order.
function segmentsThrough(plc, x, y) {
  const out = [];
  for (let j = 0; j < plc.segments.length / 2; j++) {
    const a = plc.segments[2 * j], b = plc.segments[2 * j + 1];
    const ax = plc.points[2 * a], ay = plc.points[2 * a + 1], bx = plc.points[2 * b], by = plc.points[2 * b + 1];
    const dx = bx - ax, dy = by - ay, len = Math.hypot(dx, dy);
    const off = Math.abs((x - ax) * dy - (y - ay) * dx) / len, along = ((x - ax) * dx + (y - ay) * dy) / (len * len);
    if (off <= 1e-9 * len && along >= -1e-9 && along <= 1 + 1e-9) out.push(j);
  }
  return out;
}

function boundaryEdges(mesh) {
  const uses = new Map();
  const t = mesh.triangles;
  for (let k = 0; k < t.length; k += 3) {
    for (let i = 0; i < 3; i++) {
      const a = t[k + i], b = t[k + (i + 1) % 3], key = `${Math.min(a, b)},${Math.max(a, b)}`;
      uses.set(key, (uses.get(key) ?? 0) + 1);
    }
  }
  return new Set([...uses].filter(([, n]) => n === 1).map(([key]) => key));
}

const key = (a, b) => `${Math.min(a, b)},${Math.max(a, b)}`;

// Triangle's rules, checked from the geometry (see Mesh.pointMarkers in index.d.ts).
function markerProblems(mesh, plc) {
  const problems = [];
  const boundary = boundaryEdges(mesh);
  const onBoundary = new Set([...boundary].flatMap((k) => k.split(',').map(Number)));
  const segMarker = (j) => plc.segmentMarkers?.[j] ?? 0;
  for (let s = 0; s < mesh.segments.length / 2; s++) {
    const a = mesh.segments[2 * s], b = mesh.segments[2 * s + 1], p = mesh.points;
    const through = segmentsThrough(plc, p[2 * a], p[2 * a + 1]).filter((j) => segmentsThrough(plc, p[2 * b], p[2 * b + 1]).includes(j));
    const marked = through.find((j) => segMarker(j) !== 0);
    const expected = marked !== undefined ? segMarker(marked) : boundary.has(key(a, b)) ? 1 : 0;
    if (mesh.segmentMarkers[s] !== expected) problems.push(`subsegment ${s}: marker ${mesh.segmentMarkers[s]}, expected ${expected}`);
  }
  const inputCount = plc.points.length / 2;
  for (let v = 0; v < mesh.points.length / 2; v++) {
    if (mesh.vertexKinds[v] === 5) continue;  // unused
    let expected = v < inputCount ? (plc.pointMarkers?.[v] ?? 0) : 0;
    if (expected === 0) {
      const marked = segmentsThrough(plc, mesh.points[2 * v], mesh.points[2 * v + 1]).find((j) => segMarker(j) !== 0);
      expected = marked !== undefined ? segMarker(marked) : onBoundary.has(v) ? 1 : 0;
    }
    if (mesh.pointMarkers[v] !== expected) problems.push(`vertex ${v}: marker ${mesh.pointMarkers[v]}, expected ${expected}`);
  }
  return problems.slice(0, 10);
}

function edgeProblems(mesh) {
  const problems = [];
  const boundary = boundaryEdges(mesh);
  const sub = new Map();
  for (let s = 0; s < mesh.segments.length / 2; s++) sub.set(key(mesh.segments[2 * s], mesh.segments[2 * s + 1]), mesh.segmentMarkers[s]);
  const all = new Set();
  for (let k = 0; k < mesh.triangles.length; k += 3) for (let i = 0; i < 3; i++) all.add(key(mesh.triangles[k + i], mesh.triangles[k + (i + 1) % 3]));
  const seen = new Set();
  for (let e = 0; e < mesh.edgeMarkers.length; e++) {
    const k = key(mesh.edges[2 * e], mesh.edges[2 * e + 1]);
    if (seen.has(k)) problems.push(`edge ${e} listed twice`);
    if (!all.has(k)) problems.push(`edge ${e} is no triangle's edge`);
    seen.add(k);
    const expected = sub.get(k) ?? (boundary.has(k) ? 1 : 0);
    if (mesh.edgeMarkers[e] !== expected) problems.push(`edge ${e}: marker ${mesh.edgeMarkers[e]}, expected ${expected}`);
  }
  if (seen.size !== all.size) problems.push(`${all.size - seen.size} edges missing`);
  if (2 * mesh.edgeMarkers.length !== mesh.triangles.length + boundary.size) problems.push('not (3T + B) / 2 edges');
  return problems.slice(0, 10);
}

test('box.poly at 30 degrees: 5 and 10 on their subsegments and vertices, 33 on vertex 4, in .node/.poly/.edge', { skip: !haveBox && 'box.poly absent' }, async () => {
  const mesher = await init();
  const plc = mesher.parsePoly(readFileSync(boxPath, 'utf8'), boxPath);
  const mesh = mesher.triangulate(plc, { minAngle: 30, edges: true });
  assert.deepEqual(markerProblems(mesh, plc), []);
  assert.deepEqual(edgeProblems(mesh), []);
  const p = mesh.points;
  const onLeft = (v) => p[2 * v] === 0;
  const onTen = (v) => p[2 * v + 1] === 2 && p[2 * v] >= 1 && p[2 * v] <= 2;
  let fives = 0;
  for (let s = 0; s < mesh.segmentMarkers.length; s++) {
    const a = mesh.segments[2 * s], b = mesh.segments[2 * s + 1];
    const expected = onLeft(a) && onLeft(b) ? 5 : onTen(a) && onTen(b) ? 10 : 1;
    assert.equal(mesh.segmentMarkers[s], expected, `subsegment ${s}`);
    fives += expected === 5;
  }
  assert.ok(fives >= 2, 'the left side is split');
  assert.equal(mesh.pointMarkers[3], 33);
  for (let v = 8; v < p.length / 2; v++) if (onLeft(v)) assert.equal(mesh.pointMarkers[v], 5, `inserted vertex ${v}`);
  const back = mesher.parsePoly(mesher.toPoly(mesh, plc));
  assert.deepEqual(back.segmentMarkers, mesh.segmentMarkers);
  assert.deepEqual(back.pointMarkers, mesh.pointMarkers);
  const edgeLines = mesher.toEdge(mesh).trim().split('\n');
  assert.equal(edgeLines[0], `${mesh.edgeMarkers.length} 1`);
  assert.equal(edgeLines[1], `1 ${mesh.edges[0] + 1} ${mesh.edges[1] + 1} ${mesh.edgeMarkers[0]}`);
});

test('random markers on random PLCs: every subsegment and vertex carries its segment\'s marker', async () => {
  const mesher = await init();
  for (let seed = 1; seed <= 8; seed++) {
    const random = rng(seed * 7919);
    const points = [0, 0, 1, 0, 1, 1, 0, 1];
    const segments = [0, 1, 1, 2, 2, 3, 3, 0];
    for (let k = 0; k < 5; k++) {
      const i = points.length / 2;
      points.push(0.05 + 0.9 * random(), 0.05 + 0.9 * random(), 0.05 + 0.9 * random(), 0.05 + 0.9 * random());
      segments.push(i, i + 1);
    }
    const draw = () => Math.floor(random() * 9) - 2;
    const plc = {
      points, segments,
      pointMarkers: points.filter((_, i) => i % 2 === 0).map(() => (random() < 0.3 ? draw() : 0)),
      segmentMarkers: segments.filter((_, i) => i % 2 === 0).map(draw),
    };
    const mesh = mesher.triangulate(plc, { minAngle: 25, edges: true });
    assert.deepEqual(markerProblems(mesh, plc), [], `seed ${seed}`);
    assert.deepEqual(edgeProblems(mesh), [], `seed ${seed}`);
  }
});

test('without markers: 1 on the boundary, 0 inside; edges only when asked for', async () => {
  const mesher = await init();
  const plc = { points: [0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 3, 1, 3, 3, 1, 3], segments: [0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4], holes: [2, 2] };
  const mesh = mesher.triangulate(plc, { minAngle: 30, maxArea: 0.2, edges: true });
  assert.deepEqual(markerProblems(mesh, plc), []);
  assert.ok(mesh.segmentMarkers.every((m) => m === 1), 'every subsegment is on the boundary');
  assert.ok(mesh.pointMarkers.some((m) => m === 0), 'interior vertices get 0');
  assert.deepEqual(edgeProblems(mesh), []);
  assert.equal(mesher.triangulate(plc, { minAngle: 30 }).edges, undefined);
});

const bin = fileURLToPath(new URL('./node_modules/.bin/ruppert', import.meta.url));
test('cli: -e writes BASE.edge with box.poly\'s markers', { skip: !haveBox && 'box.poly absent' }, async (t) => {
  const dir = mkdtempSync(join(tmpdir(), 'ruppert-markers-'));
  t.after(() => rmSync(dir, { recursive: true, force: true }));
  const run = spawnSync(bin, ['--quiet', '--min-angle', '30', '-e', '-o', join(dir, 'box'), boxPath], { encoding: 'utf8' });
  assert.equal(run.status, 0, run.stderr);
  const mesher = await init();
  const mesh = mesher.triangulate(mesher.parsePoly(readFileSync(boxPath, 'utf8')), { minAngle: 30, edges: true });
  assert.equal(readFileSync(join(dir, 'box.edge'), 'utf8'), mesher.toEdge(mesh));
  assert.deepEqual(mesher.parsePoly(readFileSync(join(dir, 'box.poly'), 'utf8')).segmentMarkers, mesh.segmentMarkers);
});
