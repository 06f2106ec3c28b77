// Derived outputs through the installed package: refining a mesh (triangles,
// triangleMaxArea, parseEle, the CLI's BASE.ele), quadratic elements (order: 2) and the Voronoi dual
// (voronoi: true), with the bounds and geometry re-checked here in plain JavaScript.
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { createMeshWorker, init, MeshError } from 'ruppert';
import { orient } from './exact-predicates.mjs';
import { triangleArea, validateMesh } from './validate-mesh.mjs';

const mesher = await init();
const shared = process.env.RUPPERT_SHARED_DATA;

// A polygon with a hole: 12 points on a circle and a square hole in its middle.
function ringPlc() {
  const points = [], segments = [];
  for (let i = 0; i < 12; i++) {
    points.push(Math.cos(i * Math.PI / 6), Math.sin(i * Math.PI / 6));
    segments.push(i, (i + 1) % 12);
  }
  points.push(-0.25, -0.25, 0.25, -0.25, 0.25, 0.25, -0.25, 0.25);
  for (let i = 0; i < 4; i++) segments.push(12 + i, 12 + (i + 1) % 4);
  return { points, segments, holes: [0, 0] };
}

// Deterministic bounds: a fraction of each triangle's area, or -1 one time in four.
function boundsFor(mesh, seed) {
  let s = seed >>> 0;
  const next = () => ((s = (Math.imul(s, 1664525) + 1013904223) >>> 0) / 2 ** 32);
  const bounds = [];
  for (let t = 0; t < mesh.triangles.length / 3; t++) {
    const area = triangleArea(mesh.points, mesh.triangles[3 * t], mesh.triangles[3 * t + 1], mesh.triangles[3 * t + 2]);
    bounds.push(next() < 0.25 ? -1 : area * (0.05 + 0.95 * next()));
  }
  return bounds;
}

const insideOrOn = (p, a, b, c, q) => orient(p[2 * a], p[2 * a + 1], p[2 * b], p[2 * b + 1], q[0], q[1]) >= 0 &&
  orient(p[2 * b], p[2 * b + 1], p[2 * c], p[2 * c + 1], q[0], q[1]) >= 0 &&
  orient(p[2 * c], p[2 * c + 1], p[2 * a], p[2 * a + 1], q[0], q[1]) >= 0;

// Every new triangle lying within an old one (all three corners inside or on it, exact signs) has
// at most its bound; returns how many such containments there were.
function boundsKept(old, bounds, mesh) {
  let covered = 0;
  const p = mesh.points, t = mesh.triangles, op = old.points, ot = old.triangles;
  for (let k = 0; k < t.length / 3; k++) {
    const corners = [0, 1, 2].map((i) => [p[2 * t[3 * k + i]], p[2 * t[3 * k + i] + 1]]);
    const area = triangleArea(p, t[3 * k], t[3 * k + 1], t[3 * k + 2]);
    for (let o = 0; o < ot.length / 3; o++) {
      if (!(bounds[o] > 0)) continue;
      if (!corners.every((q) => insideOrOn(op, ot[3 * o], ot[3 * o + 1], ot[3 * o + 2], q))) continue;
      covered++;
      assert.ok(area <= bounds[o], `new triangle ${k} (area ${area}) within old triangle ${o} (bound ${bounds[o]})`);
    }
  }
  return covered;
}

const totalArea = (m) => {
  let sum = 0;
  for (let k = 0; k < m.triangles.length / 3; k++) sum += triangleArea(m.points, m.triangles[3 * k], m.triangles[3 * k + 1], m.triangles[3 * k + 2]);
  return sum;
};

test('refining a mesh: triangles and triangleMaxArea; every triangle within an old one meets its bound', () => {
  const old = mesher.triangulate(ringPlc(), { minAngle: 25 });
  const bounds = boundsFor(old, 3);
  const mesh = mesher.triangulate({ points: old.points, triangles: old.triangles, triangleMaxArea: bounds }, { minAngle: 25 });
  assert.ok(mesh.complete);
  assert.deepEqual(validateMesh(mesh, { minAngle: 25 }), []);
  assert.ok(mesh.triangles.length > 2 * old.triangles.length);
  assert.ok(boundsKept(old, bounds, mesh) > old.triangles.length / 6);
  // The hole stays a hole without a seed: the area is the old mesh's.
  assert.ok(Math.abs(totalArea(mesh) - totalArea(old)) < 1e-12 * totalArea(old));
});

test('refining shared .poly meshes with random per-triangle areas', { skip: !shared || !existsSync(`${shared}/A.poly`) }, () => {
  for (const name of ['A.poly', 'box.poly', 'cdt_guitar.poly', 'earcut_hilbert.poly']) {
    if (!existsSync(`${shared}/${name}`)) continue;
    const old = mesher.triangulate(mesher.parsePoly(readFileSync(`${shared}/${name}`, 'utf8'), name), { minAngle: 20 });
    if (old.triangles.length / 3 > 1500) continue;
    const bounds = boundsFor(old, name.length);
    const mesh = mesher.triangulate({ points: old.points, triangles: old.triangles, triangleMaxArea: bounds }, { minAngle: 20 });
    assert.ok(mesh.complete, name);
    assert.deepEqual(validateMesh(mesh), [], name);
    assert.ok(boundsKept(old, bounds, mesh) > 0, name);
  }
});

test('refining a mesh: malformed triangles are named; a misspelt key gets a did-you-mean', () => {
  const points = [0, 0, 1, 0, 0, 1, 1, 1];
  const fails = (plc, options, code, pattern) => assert.throws(() => mesher.triangulate(plc, options),
    (e) => e instanceof MeshError && e.code === code && pattern.test(e.message));
  fails({ points, triangles: [0, 1, 2, 1, 3, 9] }, {}, 'INDEX_OUT_OF_RANGE', /triangles\[1\] = \(1, 3, 9\): 9 refers/);
  fails({ points, triangles: [0, 1, 2, 1] }, {}, 'MALFORMED_INPUT', /triangles has length 4/);
  fails({ points, triangles: [0, 1, 2], triangleMaxArea: [1, 2] }, {}, 'MALFORMED_INPUT', /triangleMaxArea has 2 entries for 1 triangles/);
  fails({ points, triangles: [0, 1, 2, 1, 1, 3] }, {}, 'DEGENERATE_INPUT', /triangles\[1\] = \(1, 1, 3\) has zero area/);
  fails({ points, triangle: [0, 1, 2] }, {}, 'MALFORMED_INPUT', /did you mean 'triangles'/);
  fails({ points }, { order: 3 }, 'INVALID_OPTION', /order = 3 must be 1 or 2/);
  fails({ points }, { voronoi: 1 }, 'INVALID_OPTION', /voronoi = 1 must be true or false/);
});

test('parseEle reads .ele with .node and .area; errors name the file and line', () => {
  const old = mesher.triangulate(ringPlc(), { minAngle: 20 });
  const bounds = boundsFor(old, 7);
  const area = `${bounds.length}\n${bounds.map((b, i) => `${i} ${b}`).join('\n')}\n`;
  const plc = mesher.parseEle(mesher.toEle(old), { node: mesher.toNode(old), area, name: 'old.ele' });
  assert.deepEqual([...plc.triangles], [...old.triangles]);
  assert.deepEqual([...plc.triangleMaxArea], bounds);
  const mesh = mesher.triangulate(plc, { minAngle: 20 });
  assert.ok(boundsKept(old, bounds, mesh) > 0);
  assert.throws(() => mesher.parseEle('1 3 0\n0 0 1 99\n', { node: mesher.toNode(old), name: 'bad.ele' }),
    (e) => e.code === 'INDEX_OUT_OF_RANGE' && /^bad\.ele:2: triangle 0: node 99 is not a point/.test(e.message));
  assert.throws(() => mesher.parseEle(mesher.toEle(old), { node: mesher.toNode(old), area: '1\n0 x\n', areaName: 'a.area' }),
    (e) => e.code === 'PARSE_ERROR' && /^a\.area:1: declares 1 triangles/.test(e.message));
  assert.throws(() => mesher.parseEle('1 3 0\n0 0 1 2\n', {}), (e) => e.code === 'MALFORMED_INPUT');
});

test('order: 2 gives triangles6 and one shared midpoint node per edge appended to points', () => {
  const plain = mesher.triangulate(ringPlc(), { minAngle: 25 });
  const mesh = mesher.triangulate(ringPlc(), { minAngle: 25, order: 2 });
  const v = plain.points.length / 2;
  assert.deepEqual([...mesh.triangles], [...plain.triangles]);
  assert.deepEqual([...mesh.points.subarray(0, 2 * v)], [...plain.points]);
  const edges = new Map();
  const t = mesh.triangles, t6 = mesh.triangles6, p = mesh.points;
  assert.equal(t6.length, 2 * t.length);
  for (let k = 0; k < t.length / 3; k++) {
    for (let i = 0; i < 3; i++) {
      assert.equal(t6[6 * k + i], t[3 * k + i]);
      const a = t[3 * k + (i + 1) % 3], b = t[3 * k + (i + 2) % 3], m = t6[6 * k + 3 + i];
      const key = Math.min(a, b) * 1e6 + Math.max(a, b);
      if (edges.has(key)) assert.equal(edges.get(key), m, 'an interior edge shares its midpoint node');
      edges.set(key, m);
      assert.ok(m >= v);
      assert.equal(p[2 * m], 0.5 * p[2 * a] + 0.5 * p[2 * b]);
      assert.equal(p[2 * m + 1], 0.5 * p[2 * a + 1] + 0.5 * p[2 * b + 1]);
    }
  }
  assert.equal(p.length / 2, v + edges.size);
  assert.equal(new Set(edges.values()).size, edges.size);
  assert.equal(mesh.pointMarkers.length, p.length / 2);
  const ele = mesher.toEle(mesh);
  assert.match(ele, new RegExp(`^${t.length / 3} 6 0\\n`));
  assert.equal(Number(mesher.toNode(mesh).split(/\s/)[0]), v + edges.size);
});

test('voronoi: true gives one equidistant circumcenter per triangle and an outward ray per boundary edge', () => {
  const mesh = mesher.triangulate(ringPlc(), { minAngle: 25, voronoi: true });
  const { points: c, edges, rayDirections: ray, meshEdges } = mesh.voronoi;
  const p = mesh.points, t = mesh.triangles, nt = t.length / 3;
  assert.equal(c.length, 2 * nt);
  for (let k = 0; k < nt; k++) {
    const r = [0, 1, 2].map((i) => Math.hypot(p[2 * t[3 * k + i]] - c[2 * k], p[2 * t[3 * k + i] + 1] - c[2 * k + 1]));
    assert.ok(Math.abs(r[1] - r[0]) <= 1e-9 * r[0] && Math.abs(r[2] - r[0]) <= 1e-9 * r[0], `triangle ${k}`);
  }
  const boundary = new Set();
  for (let s = 0; s < mesh.segments.length / 2; s++) boundary.add(`${Math.min(mesh.segments[2 * s], mesh.segments[2 * s + 1])} ${Math.max(mesh.segments[2 * s], mesh.segments[2 * s + 1])}`);
  let rays = 0, finite = 0;
  for (let e = 0; e < edges.length / 2; e++) {
    const a = meshEdges[2 * e], b = meshEdges[2 * e + 1];
    if (edges[2 * e + 1] === -1) {
      rays++;
      assert.ok(boundary.has(`${Math.min(a, b)} ${Math.max(a, b)}`), 'a ray crosses a boundary edge');
      const k = edges[2 * e];
      const apex = [0, 1, 2].map((i) => t[3 * k + i]).find((w) => w !== a && w !== b);
      const dx = ray[2 * e], dy = ray[2 * e + 1];
      assert.ok(dx * (p[2 * apex] - p[2 * a]) + dy * (p[2 * apex + 1] - p[2 * a + 1]) < 0, 'the ray points outward');
      assert.ok(Math.abs(dx * (p[2 * b] - p[2 * a]) + dy * (p[2 * b + 1] - p[2 * a + 1])) < 1e-12);
    } else {
      finite++;
      assert.equal(ray[2 * e], 0);
    }
  }
  assert.equal(rays, boundary.size);
  assert.equal(rays + finite, (3 * nt + rays) / 2, 'every mesh edge has its dual');
  const vedge = mesher.toVoronoiEdge(mesh);
  assert.match(vedge, new RegExp(`^${edges.length / 2} 0\\n`));
  assert.equal((vedge.match(/ -1 /g) ?? []).length, rays);
  assert.match(mesher.toVoronoiNode(mesh), new RegExp(`^${nt} 2 0 0\\n`));
  assert.throws(() => mesher.toVoronoiNode(mesher.triangulate(ringPlc())), (e) => e.code === 'MALFORMED_INPUT');
});

test('the CLI refines BASE.ele with BASE.area and writes --order 2 and --voronoi files', (t) => {
  const bin = fileURLToPath(new URL('./node_modules/.bin/ruppert', import.meta.url));
  const dir = mkdtempSync(join(tmpdir(), 'ruppert-derived-'));
  t.after(() => rmSync(dir, { recursive: true, force: true }));
  const old = mesher.triangulate(ringPlc(), { minAngle: 20 });
  const bounds = boundsFor(old, 11);
  writeFileSync(join(dir, 'old.node'), mesher.toNode(old));
  writeFileSync(join(dir, 'old.ele'), mesher.toEle(old));
  writeFileSync(join(dir, 'old.area'), `${bounds.length}\n${bounds.map((b, i) => `${i} ${b}`).join('\n')}\n`);
  const run = spawnSync(bin, ['--min-angle', '20', '-o', 'new', 'old.ele'], { cwd: dir, encoding: 'utf8' });
  assert.equal(run.status, 0, run.stderr);
  const back = mesher.parseEle(readFileSync(join(dir, 'new.ele'), 'utf8'), { node: readFileSync(join(dir, 'new.node'), 'utf8') });
  assert.ok(boundsKept(old, bounds, { points: back.points, triangles: back.triangles }) > old.triangles.length / 6);
  const derived = spawnSync(bin, ['--order', '2', '--voronoi', '-o', 'q', 'old.ele'], { cwd: dir, encoding: 'utf8' });
  assert.equal(derived.status, 0, derived.stderr);
  assert.match(readFileSync(join(dir, 'q.ele'), 'utf8'), /^\d+ 6 0\n/);
  for (const ext of ['v.node', 'v.edge']) assert.ok(existsSync(join(dir, `q.${ext}`)), ext);
  const missing = spawnSync(bin, ['nothing.ele'], { cwd: dir, encoding: 'utf8' });
  assert.equal(missing.status, 1);
  assert.match(missing.stderr, /cannot read 'nothing.ele'/);
});

test('a worker refines a mesh and hands back triangles6 and the Voronoi dual', async () => {
  const old = mesher.triangulate(ringPlc(), { minAngle: 20 });
  const bounds = boundsFor(old, 5);
  const worker = createMeshWorker();
  try {
    const mesh = await worker.triangulate({ points: old.points, triangles: old.triangles, triangleMaxArea: bounds },
      { minAngle: 20, order: 2, voronoi: true });
    const here = mesher.triangulate({ points: old.points, triangles: old.triangles, triangleMaxArea: bounds },
      { minAngle: 20, order: 2, voronoi: true });
    assert.deepEqual([...mesh.triangles6], [...here.triangles6]);
    assert.deepEqual([...mesh.points], [...here.points]);
    assert.deepEqual([...mesh.voronoi.edges], [...here.voronoi.edges]);
    assert.ok(boundsKept(old, bounds, mesh) > 0);
  } finally {
    await worker.terminate();
  }
});
