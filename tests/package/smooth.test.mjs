// Smoothing (options.smooth) from the installed package: true or a number of passes, the mesh
// valid, constrained Delaunay, at the bound and the area bound, with the same triangle count and
// rounder triangles; bad values refused with the option named; the CLI's --smooth.
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { init } from 'ruppert';
import { validateMesh } from './validate-mesh.mjs';

const bin = fileURLToPath(new URL('./node_modules/.bin/ruppert', import.meta.url));

// A square with a ring of holes: refinement leaves many free vertices and segment vertices.
function perforated() {
  const points = [0, 0, 4, 0, 4, 4, 0, 4];
  const segments = [0, 1, 1, 2, 2, 3, 3, 0];
  const holes = [];
  for (let k = 0; k < 5; k++) {
    const cx = 0.8 + 0.6 * k, cy = 1.2 + 0.35 * k, r = 0.22, first = points.length / 2;
    for (let i = 0; i < 9; i++) points.push(cx + r * Math.cos((2 * Math.PI * i) / 9), cy + r * Math.sin((2 * Math.PI * i) / 9));
    for (let i = 0; i < 9; i++) segments.push(first + i, first + ((i + 1) % 9));
    holes.push(cx, cy);
  }
  return { points, segments, holes };
}

function shapes(mesh) {
  const p = mesh.points, t = mesh.triangles;
  const corner = (a, b, c) => {
    const ux = p[2 * b] - p[2 * a], uy = p[2 * b + 1] - p[2 * a + 1], vx = p[2 * c] - p[2 * a], vy = p[2 * c + 1] - p[2 * a + 1];
    return (Math.atan2(Math.abs(ux * vy - uy * vx), ux * vx + uy * vy) * 180) / Math.PI;
  };
  let sum = 0, obtuse = 0;
  for (let k = 0; k < t.length; k += 3) {
    const angles = [corner(t[k], t[k + 1], t[k + 2]), corner(t[k + 1], t[k + 2], t[k]), corner(t[k + 2], t[k], t[k + 1])];
    sum += Math.min(...angles);
    if (Math.max(...angles) > 90) obtuse++;
  }
  return { meanSmallest: sum / (t.length / 3), obtuse };
}

test('smooth: true keeps the mesh valid, constrained Delaunay, at the bounds, with the same count', async () => {
  const mesher = await init();
  const plc = perforated();
  const plain = mesher.triangulate(plc, { minAngle: 30, maxArea: 0.05 });
  const smooth = mesher.triangulate(plc, { minAngle: 30, maxArea: 0.05, smooth: true });
  assert.deepEqual(validateMesh(smooth, { input: plc, minAngle: 30, maxArea: 0.05 }), []);
  assert.equal(smooth.complete, true);
  assert.equal(smooth.triangles.length, plain.triangles.length);
  assert.equal(smooth.points.length, plain.points.length);
  const before = shapes(plain), after = shapes(smooth);
  assert.ok(after.meanSmallest > before.meanSmallest + 1, `mean smallest angle ${before.meanSmallest} -> ${after.meanSmallest}`);
  assert.ok(after.obtuse < before.obtuse, `obtuse ${before.obtuse} -> ${after.obtuse}`);
});

test('smooth takes a number of passes: 4 is true, 0 and false are none', async () => {
  const mesher = await init();
  const plc = perforated();
  const points = (options) => [...mesher.triangulate(plc, { minAngle: 30, ...options }).points];
  const none = points({});
  assert.deepEqual(points({ smooth: 0 }), none);
  assert.deepEqual(points({ smooth: false }), none);
  assert.deepEqual(points({ smooth: 4 }), points({ smooth: true }));
  assert.notDeepEqual(points({ smooth: 1 }), none);
});

test('a bad smooth is refused with its name and range', async () => {
  const mesher = await init();
  for (const bad of [-1, 101, 2.5, 'yes', NaN]) {
    assert.throws(() => mesher.triangulate(perforated(), { smooth: bad }),
      (e) => e.code === 'INVALID_OPTION' && e.message.includes('smooth') && e.message.includes('0 to 100'), String(bad));
  }
});

test('the CLI takes --smooth alone or with passes', () => {
  const dir = mkdtempSync(join(tmpdir(), 'ruppert-smooth-'));
  try {
    writeFileSync(join(dir, 'in.json'), JSON.stringify(perforated()));
    const run = (...args) => spawnSync(bin, ['--min-angle', '30', '--format', 'json', ...args], { cwd: dir, encoding: 'utf8' });
    // -o BASE: the JSON goes to BASE.json.
    const plain = run('-o', 'plain', 'in.json');
    const alone = run('--smooth', '-o', 'alone', 'in.json');
    const four = run('--smooth', '4', '-o', 'four', 'in.json');
    for (const r of [plain, alone, four]) assert.equal(r.status, 0, r.stderr);
    const read = (name) => JSON.parse(readFileSync(join(dir, name), 'utf8'));
    assert.deepEqual(read('alone.json').points, read('four.json').points);
    assert.notDeepEqual(read('alone.json').points, read('plain.json').points);
    assert.equal(read('alone.json').triangles.length, read('plain.json').triangles.length);
    const bad = run('--smooth=101', 'in.json');
    assert.equal(bad.status, 2);
    assert.match(bad.stderr, /--smooth/);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
