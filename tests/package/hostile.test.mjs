// The hostile-input catalogue (tests/hostile/, expectations in its expectations.txt) through the
// installed package: each file is read as text by parsePoly / parseNode / parseJson and meshed as the
// plain CDT and at 30 and 40 degrees (Steiner budget 20,000, as tests/core/test_hostile.cpp does).
// A "valid" file must give meshes the independent JavaScript validator accepts in every mode; any
// other expectation is the MeshError code the package must throw, with a message that says what.
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import { extname, join } from 'node:path';
import { test } from 'node:test';
import { init, MeshError, parseJson, parseNode, parsePoly } from 'ruppert';
import { validateMesh, triangleAngles } from './validate-mesh.mjs';

const dir = process.env.RUPPERT_HOSTILE;
const haveCatalogue = dir !== undefined && existsSync(join(dir, 'expectations.txt'));

function readExpectations() {
  const entries = [];
  for (const line of readFileSync(join(dir, 'expectations.txt'), 'utf8').split('\n')) {
    const [file, outcome] = line.replace(/#.*/, '').trim().split(/\s+/);
    if (file) entries.push({ file, outcome });
  }
  return entries;
}

const parsers = { '.poly': parsePoly, '.node': parseNode, '.json': parseJson };
const modes = [
  { name: 'plain CDT', options: { minAngle: 0 } },
  { name: 'min angle 30', options: { minAngle: 30, maxSteiner: 20000 } },
  { name: 'min angle 40', options: { minAngle: 40, maxSteiner: 20000 } },
];

// The same mesh scaled by a power of two (exact) so that its largest coordinate is near 1: the
// validator's plain-double predicates would overflow on 1e300 or underflow on 1e-300 coordinates.
function scaled(mesh, plc) {
  let largest = 0;
  for (const v of mesh.points) largest = Math.max(largest, Math.abs(v));
  const exponent = largest > 0 ? -Math.ceil(Math.log2(largest)) : 0;
  // In two steps: for subnormal extents 2^exponent itself overflows.
  const half = 2 ** Math.trunc(exponent / 2), rest = 2 ** (exponent - Math.trunc(exponent / 2));
  const scale = (array) => Float64Array.from(array, (v) => v * half * rest);
  return { mesh: { ...mesh, points: scale(mesh.points) }, input: { ...plc, points: scale(plc.points) } };
}

// Inputs the core repaired (duplicates, overlaps, crossings) have segments that no chain of
// subsegments with that id covers one to one, so the per-segment cover check applies only to
// inputs the core took as they were.
const repairKinds = new Set(['DUPLICATE_SEGMENT', 'ZERO_LENGTH_SEGMENT', 'VERTEX_ON_SEGMENT', 'SEGMENTS_OVERLAP', 'SEGMENTS_CROSS']);

function problemsOf(mesh, plc, options) {
  const { mesh: m, input } = scaled(mesh, plc);
  const repaired = mesh.notices.some((n) => repairKinds.has(n.kind));
  const problems = validateMesh(m, repaired ? {} : { input });
  // Angles: a complete mesh meets the bound unless the core names triangles it exempts (small input
  // angles, seditious edges: section 6.6), which this validator does not re-derive.
  const exempting = mesh.reasons.some((r) => r.kind === 'SMALL_INPUT_ANGLE' || r.kind === 'SEDITIOUS_EDGE');
  if (mesh.complete && options.minAngle > 0 && !exempting) {
    const t = m.triangles;
    for (let k = 0; k < t.length / 3; k++) {
      const smallest = Math.min(...triangleAngles(m.points, t[3 * k], t[3 * k + 1], t[3 * k + 2]));
      if (smallest < options.minAngle - 1e-6) problems.push(`complete, but triangle ${k} has angle ${smallest}`);
    }
  }
  if (!mesh.complete && mesh.reasons.length === 0) problems.push('incomplete without a reason');
  return problems;
}

test('every file of the hostile catalogue has the expected outcome through the package', { skip: !haveCatalogue && `catalogue not found (${dir})` }, async () => {
  const mesher = await init();
  const entries = readExpectations();
  assert.ok(entries.length >= 70, `only ${entries.length} catalogue entries`);
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
