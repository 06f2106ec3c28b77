// The package tests' chain check (validate-chains.mjs) must still find real gaps after the
// relaxations the careless-PLC sweep called for: an uncovered stretch is cut at the mesh
// vertices exactly on it and judged piece by piece, midpoints are located exactly, and only mesh
// vertices are stations. Half of an interior segment through a vertex, taken out of a true mesh,
// must be reported; the true mesh must not.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { init } from 'ruppert';
import { problemsOf } from './judge-mesh.mjs';

const plc = {
  points: [0, 0, 4, 0, 4, 4, 0, 4, 1, 2, 2, 2, 3, 2],
  segments: [0, 1, 1, 2, 2, 3, 3, 0, 4, 6], // segment 4 runs through point 5, (2, 2)
};
const options = { minAngle: 0 };

function without(mesh, drop) {
  const segments = [], segmentIds = [];
  for (let k = 0; k < mesh.segmentIds.length; k++) {
    const [u, w, id] = [mesh.segments[2 * k], mesh.segments[2 * k + 1], mesh.segmentIds[k]];
    if (drop(u, w, id)) continue;
    segments.push(u, w), segmentIds.push(id);
  }
  assert.equal(segmentIds.length + 1, mesh.segmentIds.length);
  return { ...mesh, segments: Uint32Array.from(segments), segmentIds: Int32Array.from(segmentIds) };
}

test('the chain check finds either half of a segment through a vertex missing', async () => {
  const mesher = await init();
  const mesh = mesher.triangulate(plc, options);
  assert.deepEqual(problemsOf(mesh, plc, options), []);
  const second = problemsOf(without(mesh, (u, w, id) => id === 4 && (u === 6 || w === 6)), plc, options);
  assert.ok(second.some((p) => p.includes('input segment 4 (4, 6) is not a chain of subsegments between vertices 5 and 6')),
    second.join('\n'));
  const first = problemsOf(without(mesh, (u, w, id) => id === 4 && (u === 4 || w === 4)), plc, options);
  assert.ok(first.some((p) => p.includes('input segment 4 (4, 6) is not a chain of subsegments between vertices 4 and 5')),
    first.join('\n'));
});
