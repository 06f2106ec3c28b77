// maxAngle from the installed package and its CLI: the largest angle bounded together with the
// smallest, and values outside (60, 180) refused with the value named.
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { init, MeshError } from 'ruppert';
import { triangleAngles, validateMesh } from './validate-mesh.mjs';

const bin = fileURLToPath(new URL('./node_modules/.bin/ruppert', import.meta.url));

// An L with a slanted notch: no input angle below 30 degrees, so no triangle is exempt.
const plc = {
  points: [0, 0, 3, 0, 3, 1, 1.6, 1.3, 1, 2.5, 0, 2],
  segments: [0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 0],
};

const largestAngle = (mesh) => {
  let largest = 0;
  const t = mesh.triangles;
  for (let k = 0; k < t.length; k += 3) largest = Math.max(largest, ...triangleAngles(mesh.points, t[k], t[k + 1], t[k + 2]));
  return largest;
};

test('maxAngle bounds every largest angle and keeps minAngle', async () => {
  const mesher = await init();
  const plain = mesher.triangulate(plc, { minAngle: 30 });
  assert.ok(largestAngle(plain) > 100, 'the bound has something to do');
  for (const maxAngle of [90, 100, 110]) {
    const mesh = mesher.triangulate(plc, { minAngle: 30, maxAngle });
    assert.equal(mesh.complete, true, `maxAngle ${maxAngle}: ${JSON.stringify(mesh.reasons)}`);
    assert.deepEqual(validateMesh(mesh, { input: plc, minAngle: 30 }), []);
    assert.ok(largestAngle(mesh) <= maxAngle + 1e-6, `maxAngle ${maxAngle}: ${largestAngle(mesh)}`);
  }
});

test('maxAngle outside (60, 180), other than 0, is an INVALID_OPTION naming the value', async () => {
  const mesher = await init();
  for (const bad of [60, 30, 180, 181, -1, Number.NaN, '100']) {
    assert.throws(() => mesher.triangulate(plc, { maxAngle: bad }),
      (e) => e instanceof MeshError && e.code === 'INVALID_OPTION' && e.message.includes('maxAngle'), `maxAngle ${String(bad)}`);
  }
  assert.equal(mesher.triangulate(plc, { maxAngle: 0 }).complete, true, '0: no bound');
});

test('the CLI takes --max-angle and refuses 50 naming it', () => {
  const dir = mkdtempSync(join(tmpdir(), 'ruppert-max-angle-'));
  try {
    const poly = [`${plc.points.length / 2} 2 0 0`, ...Array.from({ length: plc.points.length / 2 },
      (_, i) => `${i} ${plc.points[2 * i]} ${plc.points[2 * i + 1]}`),
    `${plc.segments.length / 2} 0`, ...Array.from({ length: plc.segments.length / 2 },
      (_, i) => `${i} ${plc.segments[2 * i]} ${plc.segments[2 * i + 1]}`), '0'].join('\n');
    writeFileSync(join(dir, 'in.poly'), `${poly}\n`);
    const ok = spawnSync(bin, ['--quiet', '--max-angle', '100', '--format', 'json', '-o', '-', join(dir, 'in.poly')], { encoding: 'utf8' });
    assert.equal(ok.status, 0, ok.stderr);
    const mesh = JSON.parse(ok.stdout);
    assert.equal(mesh.complete, true);
    assert.ok(largestAngle(mesh) <= 100 + 1e-6);
    const bad = spawnSync(bin, ['--quiet', '--max-angle', '50', join(dir, 'in.poly')], { encoding: 'utf8' });
    assert.notEqual(bad.status, 0);
    assert.match(bad.stderr, /maxAngle = 50/);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
