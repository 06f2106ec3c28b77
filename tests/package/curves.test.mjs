// Curved boundaries through the installed package: plc.curves and options.curveTolerance.
// Each mesh is judged by the package's validator (Delaunay, the angle and area bounds) and by the
// checks below, computed from the input's curves alone: every vertex of a curve's pieces on the
// curve (within 1e-12 of its size), every piece within the tolerance of its stretch of curve, and the
// mesh's area within the chords' error of the curved domain's.
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { after, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { init, parseJson } from 'ruppert';
import { triangleArea, validateMesh } from './validate-mesh.mjs';
import { bezierAt, nearestT } from './bezier-math.mjs';

const mesher = await init();

// The unit square with a hole of radius 0.25 at its center: two arcs.
const roundHole = {
  points: [0, 0, 1, 0, 1, 1, 0, 1, 0.75, 0.5, 0.25, 0.5],
  segments: [0, 1, 1, 2, 2, 3, 3, 0],
  curves: [{ type: 'arc', from: 4, to: 5, center: [0.5, 0.5] }, { type: 'arc', from: 5, to: 4, center: [0.5, 0.5] }],
  holes: [0.5, 0.5],
};
const quarterDisk = { points: [0, 0, 1, 0, 0, 1], segments: [0, 1, 2, 0], curves: [{ type: 'arc', from: 1, to: 2, center: [0, 0] }] };
// Under the cubic from (1, 0) to (0, 0) with controls (1, 1) and (0, 1): y = 3 t (1 - t), area 0.6.
const underBezier = { points: [0, 0, 1, 0], segments: [0, 1], curves: [{ type: 'bezier', from: 1, to: 0, controls: [1, 1, 0, 1] }] };



// Per curve piece: its ends' distance from the curve and its chord error; the pieces per curve.
function curveChecks(plc, mesh, tolerance) {
  const p = mesh.points, nSeg = plc.segments.length / 2;
  const pieces = plc.curves.map(() => 0);
  let worstOff = 0, worstChord = 0, areaBound = 0;
  for (let k = 0; k < mesh.segmentIds.length; k++) {
    const c = mesh.segmentIds[k] - nSeg;
    if (c < 0) continue;
    const curve = plc.curves[c];
    const a = [p[2 * mesh.segments[2 * k]], p[2 * mesh.segments[2 * k] + 1]];
    const b = [p[2 * mesh.segments[2 * k + 1]], p[2 * mesh.segments[2 * k + 1] + 1]];
    const chord = Math.hypot(b[0] - a[0], b[1] - a[1]);
    const from = [plc.points[2 * curve.from], plc.points[2 * curve.from + 1]];
    let off, error, size;
    if (curve.type === 'arc') {
      const r = Math.hypot(from[0] - curve.center[0], from[1] - curve.center[1]);
      off = Math.max(...[a, b].map((q) => Math.abs(Math.hypot(q[0] - curve.center[0], q[1] - curve.center[1]) - r)));
      error = r - Math.sqrt(r * r - chord * chord / 4), size = r;
    } else {
      const cp = [...from, ...curve.controls, plc.points[2 * curve.to], plc.points[2 * curve.to + 1]];
      size = Math.max(...[2, 4, 6].map((i) => Math.hypot(cp[i] - cp[0], cp[i + 1] - cp[1])));
      const ta = nearestT(cp, a), tb = nearestT(cp, b);
      off = Math.max(...[[a, ta], [b, tb]].map(([q, t]) => { const [x, y] = bezierAt(cp, t); return Math.hypot(x - q[0], y - q[1]); }));
      error = 0;
      for (let i = 1; i < 256; i++) {
        const [x, y] = bezierAt(cp, ta + (tb - ta) * i / 256);
        error = Math.max(error, Math.abs((b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])) / chord);
      }
    }
    pieces[c]++;
    worstOff = Math.max(worstOff, off / size), worstChord = Math.max(worstChord, error);
    areaBound += error * chord;
  }
  assert.ok(worstOff <= 1e-12, `a vertex lies ${worstOff} of its curve's size off it`);
  assert.ok(worstChord <= tolerance * (1 + 1e-9), `a piece lies ${worstChord} from its curve (tolerance ${tolerance})`);
  return { pieces, areaBound, worstOff };
}

function meshAndCheck(plc, options, exactArea) {
  const mesh = mesher.triangulate(plc, options);
  assert.equal(mesh.complete, true, JSON.stringify(mesh.reasons));
  assert.deepEqual(validateMesh(mesh, { input: plc, minAngle: options.minAngle, maxArea: options.maxArea }), []);
  const checked = curveChecks(plc, mesh, options.curveTolerance);
  let area = 0;
  for (let k = 0; k < mesh.triangles.length / 3; k++) area += triangleArea(mesh.points, ...mesh.triangles.subarray(3 * k, 3 * k + 3));
  assert.ok(Math.abs(area - exactArea) <= checked.areaBound + 1e-12, `area ${area}, exact ${exactArea}, bound ${checked.areaBound}`);
  return { mesh, ...checked };
}

test('a unit square with a round hole at 30 degrees: hole vertices on the circle, edges within the tolerance', () => {
  const coarse = meshAndCheck(roundHole, { minAngle: 30, curveTolerance: 1e-3 }, 1 - Math.PI / 16);
  const fine = meshAndCheck(roundHole, { minAngle: 30, curveTolerance: 1e-5 }, 1 - Math.PI / 16);
  assert.ok(coarse.mesh.stats.minAngle >= 30);
  const edges = (m) => m.pieces[0] + m.pieces[1];
  // The sagitta shrinks as 1 / n^2: a hundredth of the tolerance takes ten times the edges.
  assert.ok(edges(fine) >= 8 * edges(coarse), `${edges(coarse)} hole edges at 1e-3, ${edges(fine)} at 1e-5`);
  // Pieces carry segmentIds after the segments': 4 + the curve's index.
  assert.ok([...coarse.mesh.segmentIds].every((id) => id >= 0 && id <= 5));
});

test('a quarter disk under an area bound and a region under a cubic Bezier mesh on their curves', () => {
  meshAndCheck(quarterDisk, { minAngle: 30, curveTolerance: 1e-3, maxArea: 1e-3 }, Math.PI / 4);
  meshAndCheck(underBezier, { minAngle: 30, curveTolerance: 1e-3 }, 0.6);
  meshAndCheck(underBezier, { minAngle: 25, curveTolerance: 1e-4, maxArea: 1e-3 }, 0.6);
});

test('bad curves and curve options are refused, naming the curve', () => {
  const refused = (plc, options, code, words) => assert.throws(() => mesher.triangulate(plc, options),
    (e) => e.code === code && e.message.includes(words), `${code}: ${words}`);
  refused({ ...quarterDisk, curves: [{ type: 'spline', from: 1, to: 2 }] }, {}, 'MALFORMED_INPUT', "curves[0].type");
  refused({ ...quarterDisk, curves: [{ type: 'arc', from: 1, to: 2 }] }, {}, 'MALFORMED_INPUT', 'curves[0] needs center');
  refused({ ...quarterDisk, curves: [{ type: 'arc', from: 1, to: 7, center: [0, 0] }] }, {}, 'INDEX_OUT_OF_RANGE', 'curve 0');
  refused({ ...quarterDisk, curves: [{ type: 'arc', from: 1, to: 2, center: [0.1, 0] }] }, {}, 'MALFORMED_INPUT', 'curve 0: from and to lie at distances');
  refused({ ...quarterDisk, curves: [{ type: 'arc', from: 1, to: 2, centre: [0, 0] }] }, {}, 'MALFORMED_INPUT', "did you mean 'center'");
  refused(quarterDisk, { curveTolerance: -1 }, 'INVALID_OPTION', 'curveTolerance');
});

test('parseJson reads curves, and the CLI meshes them with --curve-tolerance', () => {
  const text = JSON.stringify(roundHole);
  const parsed = parseJson(text);
  assert.equal(parsed.curves.length, 2);
  assert.equal(parsed.curves[1].type, 'arc');
  assert.deepEqual([...parsed.curves[1].center], [0.5, 0.5]);
  meshAndCheck(parsed, { minAngle: 30, curveTolerance: 1e-3 }, 1 - Math.PI / 16);
  const dir = mkdtempSync(join(tmpdir(), 'ruppert-curves-'));
  after(() => rmSync(dir, { recursive: true, force: true }));
  writeFileSync(join(dir, 'hole.json'), text);
  const bin = fileURLToPath(new URL('./node_modules/.bin/ruppert', import.meta.url));
  const run = spawnSync(bin, ['--min-angle', '30', '--curve-tolerance', '1e-3', 'hole.json'], { cwd: dir, encoding: 'utf8' });
  assert.equal(run.status, 0, run.stderr);
  assert.match(run.stdout, /min angle 30\.\d\d, .*complete/);
});
