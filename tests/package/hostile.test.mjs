// The hostile-input catalog (tests/hostile/, expectations in its expectations.txt) through the
// installed package: each file is read as text by parsePoly / parseNode / parseJson / parseGeoJson
// and meshed as the plain CDT and at 30 and 40 degrees (Steiner budget 20,000, as tests/core/test_hostile.cpp does).
// A "valid" file must give meshes the independent JavaScript validator accepts in every mode; any
// other expectation is the MeshError code the package must throw, with a message that says what.
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import { extname, join } from 'node:path';
import { test } from 'node:test';
import { init, MeshError, parseGeoJson, parseJson, parseNode, parsePoly } from 'ruppert';
import { problemsOf } from './judge-mesh.mjs';
import { validateMesh } from './validate-mesh.mjs';

const dir = process.env.RUPPERT_HOSTILE;
const haveCatalog = dir !== undefined && existsSync(join(dir, 'expectations.txt'));

function readExpectations() {
  const entries = [];
  for (const line of readFileSync(join(dir, 'expectations.txt'), 'utf8').split('\n')) {
    const [file, outcome] = line.replace(/#.*/, '').trim().split(/\s+/);
    if (file) entries.push({ file, outcome });
  }
  return entries;
}

const parsers = { '.poly': parsePoly, '.node': parseNode, '.json': parseJson, '.geojson': parseGeoJson };
const modes = [
  { name: 'plain CDT', options: { minAngle: 0 } },
  { name: 'min angle 30', options: { minAngle: 30, maxSteiner: 20000 } },
  { name: 'min angle 40', options: { minAngle: 40, maxSteiner: 20000 } },
];

test('every file of the hostile catalog has the expected outcome through the package', { skip: !haveCatalog && `catalog not found (${dir})` }, async () => {
  const mesher = await init();
  const entries = readExpectations();
  assert.ok(entries.length >= 70, `only ${entries.length} catalog entries`);
  const failures = [];
  for (const { file, outcome } of entries) {
    const parse = parsers[extname(file)];
    assert.ok(parse, `${file}: no parser for its extension`);
    const text = readFileSync(join(dir, file), 'utf8');
    for (const mode of modes) {
      let got;
      try {
        const plc = parse(text, file);
        const mesh = mesher.triangulate(plc, mode.options);
        const problems = problemsOf(mesh, plc, mode.options);
        got = problems.length === 0 ? 'valid' : `invalid: ${problems.slice(0, 3).join('; ')}`;
      } catch (error) {
        if (!(error instanceof MeshError)) got = `not a MeshError: ${error}`;
        else if (!error.message || error.message.length < 10) got = `${error.code} without a message`;
        else got = error.code;
      }
      if (got !== outcome) failures.push(`${file}, ${mode.name}: expected ${outcome}, got ${got}`);
      // A file that fails to read fails the same way in every mode.
      if (outcome !== 'valid' && got === outcome) break;
    }
  }
  assert.deepEqual(failures, []);
});

test('a 100 MB comment line is read, and the next call works', async () => {
  const mesher = await init();
  const square = '4 2 0 0\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n4 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n0\n';
  const plc = parsePoly(`#${'x'.repeat(100 * 1024 * 1024)}\n${square}`, 'long-comment-line.poly');
  assert.equal(plc.points.length, 8);
  const mesh = mesher.triangulate(plc, { minAngle: 30 });
  assert.deepEqual(validateMesh(mesh, { input: plc, minAngle: 30 }), []);
  assert.deepEqual(validateMesh(mesher.triangulate(parsePoly(square), { minAngle: 30 }), { minAngle: 30 }), []);
});
