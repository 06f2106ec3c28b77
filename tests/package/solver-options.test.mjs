// The solver-facing options from the installed package: pointAttributes interpolated
// onto new vertices, noBoundarySteiner / noSegmentSteiner, jettison; and their CLI switches.
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { init, MeshError } from 'ruppert';
import { validateMesh } from './validate-mesh.mjs';

const dataDir = process.env.RUPPERT_SHARED_DATA;
const haveData = dataDir !== undefined && existsSync(dataDir);
const bin = fileURLToPath(new URL('./node_modules/.bin/ruppert', import.meta.url));

const field = (x, y) => 3 * x - 2 * y + 1;

function boundaryVertices(mesh) {
  const uses = new Map();
  const t = mesh.triangles;
  for (let k = 0; k < t.length; k += 3) {
    for (let i = 0; i < 3; i++) {
      const a = t[k + i], b = t[k + (i + 1) % 3], key = `${Math.min(a, b)},${Math.max(a, b)}`;
      uses.set(key, (uses.get(key) ?? 0) + 1);
    }
  }
  return new Set([...uses].filter(([, n]) => n === 1).flatMap(([key]) => key.split(',').map(Number)));
}

test('pointAttributes: a linear field at the input points comes back at every vertex', async () => {
  const mesher = await init();
  const points = [0, 0, 2, 0, 2, 1, 0, 1, 0.7, 0.3, 1.4, 0.8];
  const plc = {
    points, segments: [0, 1, 1, 2, 2, 3, 3, 0, 4, 5],
    pointAttributes: points.flatMap((v, i) => (i % 2 === 0 ? [field(v, points[i + 1]), 7] : [])),
  };
  const mesh = mesher.triangulate(plc, { minAngle: 30, maxArea: 0.01 });
  assert.equal(mesh.attributesPerPoint, 2, 'two per point, from the length');
  assert.equal(mesh.pointAttributes.length, mesh.points.length);
  assert.ok(mesh.points.length / 2 > 100);
  for (let v = 0; v < mesh.points.length / 2; v++) {
    const [x, y] = [mesh.points[2 * v], mesh.points[2 * v + 1]];
    assert.ok(Math.abs(mesh.pointAttributes[2 * v] - field(x, y)) < 1e-12, `vertex ${v}`);
    assert.ok(Math.abs(mesh.pointAttributes[2 * v + 1] - 7) < 1e-12, `vertex ${v}`);
  }
  const node = mesher.parseNode(mesher.toNode(mesh));
  assert.deepEqual(node.pointAttributes, mesh.pointAttributes, 'written in the .node columns');
  assert.throws(() => mesher.triangulate({ ...plc, attributesPerPoint: 3 }),
    (e) => e instanceof MeshError && e.code === 'MALFORMED_INPUT' && /12 entries for 6 points with 3/.test(e.message));
  assert.throws(() => mesher.triangulate({ ...plc, pointAttributes: [1, 2, 3] }),
    (e) => e instanceof MeshError && /not a multiple of the 6 points/.test(e.message));
});

test('noBoundarySteiner / noSegmentSteiner: nothing new on the boundary or segments, a valid CDT, a reason', { skip: !haveData && 'shared data absent' }, async () => {
  const mesher = await init();
  let forbidden = 0;
  for (const name of ['A.poly', 'face.poly', 'box.poly', 'cdt_guitar.poly']) {
    const plc = mesher.parsePoly(readFileSync(join(dataDir, name), 'utf8'), name);
    for (const minAngle of [20, 30]) {
      for (const option of ['noBoundarySteiner', 'noSegmentSteiner']) {
        const mesh = mesher.triangulate(plc, { minAngle, [option]: true });
        const what = `${name} at ${minAngle} degrees with ${option}`;
        assert.deepEqual(validateMesh(mesh, { input: plc }), [], what);
        for (const v of boundaryVertices(mesh)) assert.ok(mesh.vertexKinds[v] === 0 || mesh.vertexKinds[v] === 4, `${what}: new vertex ${v} on the boundary`);
        if (option === 'noSegmentSteiner') assert.equal(mesh.stats.segmentVertices, 0, what);
        const reason = mesh.reasons.find((r) => r.kind === 'SEGMENT_SPLIT_FORBIDDEN');
        if (reason) {
          forbidden++;
          assert.equal(mesh.complete, false);
          assert.match(reason.message, /refused/);
        }
      }
    }
  }
  assert.ok(forbidden > 0, 'some of these cannot reach the bound without splitting');
});

test('jettison: unused points left out, inputToOutput maps them', async () => {
  const mesher = await init();
  const plc = { points: [0, 0, 4, 0, 4, 4, 0, 4, 4, 4, 9, 9, 2, 2], segments: [0, 1, 1, 2, 2, 3, 3, 0] };
  const kept = mesher.triangulate(plc, { minAngle: 25 });
  assert.equal(kept.vertexKinds[4], 5, 'the duplicate is unused');
  assert.equal(kept.inputToOutput, undefined);
  const mesh = mesher.triangulate(plc, { minAngle: 25, jettison: true });
  assert.deepEqual([...mesh.inputToOutput], [0, 1, 2, 3, 2, -1, 4]);
  assert.equal(mesh.points.length, kept.points.length - 4);
  assert.ok(!mesh.vertexKinds.includes(5));
  assert.deepEqual(validateMesh(mesh), []);
  assert.deepEqual([mesh.points[8], mesh.points[9]], [2, 2]);
});

test('cli: --no-segment-steiner, --jettison and attribute columns', (t) => {
  const dir = mkdtempSync(join(tmpdir(), 'ruppert-solver-'));
  t.after(() => rmSync(dir, { recursive: true, force: true }));
  // 10 + x + y as the attribute; a duplicate of point 1 (numbered 4).
  writeFileSync(join(dir, 'in.poly'), '5 2 1 0\n1 0 0 10\n2 4 0 14\n3 4 4 18\n4 0 4 14\n5 4 0 14\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n');
  const run = spawnSync(bin, ['--quiet', '--min-angle', '30', '--max-area', '0.5', '--no-segment-steiner', '--jettison', '-o', join(dir, 'out'), join(dir, 'in.poly')], { encoding: 'utf8' });
  assert.equal(run.status, 0, run.stderr);
  const rows = readFileSync(join(dir, 'out.node'), 'utf8').trim().split('\n').map((l) => l.trim().split(/\s+/).map(Number));
  const [count, , attributes] = rows[0];
  assert.equal(attributes, 1);
  assert.equal(count, rows.length - 1);
  for (const [, x, y, a] of rows.slice(1)) assert.ok(Math.abs(a - (10 + x + y)) < 1e-12, `(${x}, ${y}): ${a}`);
  // Jettisoned: the duplicate is gone; no vertex on the sides but the corners.
  const sides = rows.slice(1).filter(([, x, y]) => x === 0 || y === 0 || x === 4 || y === 4);
  assert.equal(sides.length, 4);
  assert.ok(count > 20, `${count} vertices: the area bound 0.5 on 16 needs more than 20`);
  assert.ok(spawnSync(bin, ['--help'], { encoding: 'utf8' }).stdout.includes('--no-boundary-steiner'));
});
