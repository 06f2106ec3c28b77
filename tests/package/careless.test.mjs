// The careless-PLC sweep through the installed package (careless-plc.mjs says what the inputs are):
// every input must give a mesh the independent validator accepts (judge-mesh.mjs: segments as
// chains even where the input was repaired, exact Delaunay and orientation, holes, the angle bound
// when complete) or a MeshError that names a problem of the input, never INTERNAL.
// CI runs 300 seeded inputs; RUPPERT_CARELESS_COUNT=10000 (and RUPPERT_CARELESS_SEED, the first
// seed) make a longer run, and RUPPERT_CARELESS_DUMP=folder writes each failing input there as a
// .poly file whose first line holds its options.
import assert from 'node:assert/strict';
import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { test } from 'node:test';
import { init, MeshError } from 'ruppert';
import { carelessPlc, toPolyText } from './careless-plc.mjs';
import { problemsOf } from './judge-mesh.mjs';

const count = Number(process.env.RUPPERT_CARELESS_COUNT ?? 300);
const first = Number(process.env.RUPPERT_CARELESS_SEED ?? 1);
const dump = process.env.RUPPERT_CARELESS_DUMP;
// Errors a careless input may earn: a hole seed on a segment, nothing left to mesh, all points
// collinear or coincident.
const inputErrors = new Set(['HOLE_ON_SEGMENT', 'EMPTY_DOMAIN', 'DEGENERATE_INPUT']);

test(`${count} careless PLCs from seed ${first} give valid meshes or input errors`, async (t) => {
  const mesher = await init();
  const failures = [];
  const outcomes = {};
  for (let seed = first; seed < first + count; seed++) {
    const input = carelessPlc(seed);
    let got;
    try {
      const mesh = mesher.triangulate(input.plc, input.options);
      const problems = problemsOf(mesh, input.plc, input.options);
      got = problems.length === 0 ? 'valid' : `invalid: ${problems.slice(0, 3).join('; ')}`;
    } catch (error) {
      if (!(error instanceof MeshError)) got = `not a MeshError: ${error}`;
      else if (!inputErrors.has(error.code)) got = `${error.code}: ${error.message}`;
      else got = error.code;
    }
    const kind = got.startsWith('invalid') ? 'invalid' : got.split(':')[0];
    outcomes[kind] = (outcomes[kind] ?? 0) + 1;
    if (got === 'valid' || inputErrors.has(got)) continue;
    failures.push(`seed ${seed} (${JSON.stringify(input.options)}): ${got}`);
    if (dump) {
      mkdirSync(dump, { recursive: true });
      writeFileSync(join(dump, `careless-seed-${seed}.poly`), toPolyText(input));
    }
  }
  t.diagnostic(`outcomes of ${count} careless PLCs: ${JSON.stringify(outcomes)}`);
  assert.deepEqual(failures, []);
});
