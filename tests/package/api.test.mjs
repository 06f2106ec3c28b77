// The package's main-thread API, run against the installed tarball (see run-installed.mjs).
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { test } from 'node:test';
import { gzipSync } from 'node:zlib';
import { init, MeshError, ERROR_CODES, EventKind, VertexKind, parsePoly, toPoly, toSvg } from 'ruppert';
import { validateMesh, triangleArea } from './validate-mesh.mjs';

const dataDir = process.env.RUPPERT_SHARED_DATA;
const haveData = dataDir !== undefined && existsSync(dataDir);
if (!haveData) console.log(`# shared data folder not found (${dataDir}): fixture tests are skipped`);

const square = { points: [0, 0, 1, 0, 1, 1, 0, 1], segments: [0, 1, 1, 2, 2, 3, 3, 0] };

function expectCode(fn, code, messagePattern) {
  assert.throws(fn, (error) => {
    assert.ok(error instanceof MeshError, `expected a MeshError, got ${error}`);
    assert.equal(error.code, code, error.message);
    if (messagePattern) assert.match(error.message, messagePattern);
    return true;
  });
}

test('the two-line example from the README meshes a square to the requested quality', async () => {
  const mesher = await init();
  const mesh = mesher.triangulate(square, { minAngle: 30, maxArea: 0.01 });
  assert.equal(mesh.complete, true, JSON.stringify(mesh.reasons));
  assert.ok(mesh.triangles.length / 3 >= 100, 'area bound 0.01 on a unit square needs >= 100 triangles');
  assert.deepEqual(validateMesh(mesh, { input: square, minAngle: 30, maxArea: 0.01 }), []);
});

// The mesher module is what every page and worker downloads before its first mesh: its size is held
// to a limit, raised only openly, with what each part costs in docs/measurements.md ("wasm size
// history").
const gzippedSize = (file) => gzipSync(readFileSync(new URL(`./node_modules/ruppert/wasm/dist/${file}`, import.meta.url)), { level: 9 }).length;
test('the mesher .wasm is at most 150 KB gzipped, the text formats at most 60 KB', () => {
  const mesher = gzippedSize('ruppert.wasm'), formats = gzippedSize('ruppert-formats.wasm');
  assert.ok(mesher <= 153600, `ruppert.wasm: ${mesher} bytes gzipped`);
  assert.ok(formats <= 60000, `ruppert-formats.wasm: ${formats} bytes gzipped`);
});

test('init({ formats: false }) meshes without the text formats and says what is missing', async () => {
  const mesher = await init({ formats: false });
  assert.equal(mesher.hasFormats, false);
  const mesh = mesher.triangulate(square, { minAngle: 30, maxArea: 0.01 });
  assert.deepEqual(validateMesh(mesh, { input: square, minAngle: 30, maxArea: 0.01 }), []);
  // GeoJSON is read by the mesher module (its hole seeds need a triangulation).
  const ring = { type: 'Polygon', coordinates: [[[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]]] };
  assert.equal(mesher.parseGeoJson(JSON.stringify(ring)).points.length, 8);
  assert.throws(() => mesher.toVtu(mesh), (e) => e.code === 'INVALID_OPTION' && /formats: false.*to\*\(\) writers/.test(e.message));
  assert.throws(() => mesher.parsePoly('4 2 0 0\n'), (e) => e.code === 'INVALID_OPTION' && /parsePoly/.test(e.message));
  assert.equal((await init()).hasFormats, true);
});

test('init({ formats }) takes a source of its own, and a bad one is named', async () => {
  const formatsBinary = readFileSync(new URL('./node_modules/ruppert/wasm/dist/ruppert-formats.wasm', import.meta.url));
  const mesher = await init({ formats: { wasmBinary: formatsBinary } });
  assert.match(mesher.toNode(mesher.triangulate(square)), /^4 2 0 1\n/);
  await assert.rejects(init({ formats: { wasmUrl: 'file:///nonexistent-ruppert-folder/ruppert-formats.wasm' } }),
    (e) => e.code === 'IO_ERROR' && /nonexistent-ruppert-folder\/ruppert-formats\.wasm.*formats: false/.test(e.message));
  // Another module's bytes (a locateFile answering one URL for both files): named, not a crash.
  const mesherBinary = readFileSync(new URL('./node_modules/ruppert/wasm/dist/ruppert.wasm', import.meta.url));
  await assert.rejects(init({ formats: { wasmBinary: mesherBinary } }),
    (e) => e.code === 'IO_ERROR' && /given for ruppert-formats\.wasm is not this package's/.test(e.message));
  await assert.rejects(init({ wasmBinary: formatsBinary, formats: false }),
    (e) => e.code === 'IO_ERROR' && /given for ruppert\.wasm is not this package's/.test(e.message));
  const oneUrl = new URL('./node_modules/ruppert/wasm/dist/ruppert.wasm', import.meta.url);
  await assert.rejects(init({ locateFile: () => oneUrl }), (e) => e.code === 'IO_ERROR' && /ruppert-formats\.wasm is not/.test(e.message));
  await assert.rejects(init({ formats: 'yes' }), (e) => e.code === 'INVALID_OPTION' && /formats must be true, false or/.test(e.message));
  await assert.rejects(init({ formats: { wasmURL: 'x' } }), (e) => e.code === 'INVALID_OPTION' && /wasmURL/.test(e.message));
});

test('init() loads once and returns the same mesher', async () => {
  assert.equal(await init(), await init());
});

test('plain CDT of a square with an interior point: typed arrays owned by JavaScript', async () => {
  const mesher = await init();
  const plc = { points: new Float64Array([0, 0, 1, 0, 1, 1, 0, 1, 0.25, 0.5]), segments: new Uint32Array(square.segments) };
  const mesh = mesher.triangulate(plc, { minAngle: 0 });
  assert.equal(mesh.triangles.length / 3, 4);
  assert.deepEqual([...mesh.vertexKinds], [0, 0, 0, 0, 0].map(() => VertexKind.INPUT));
  assert.deepEqual(validateMesh(mesh, { input: plc }), []);
  // Copies, not views into wasm memory: the result's arrays share one buffer of their own, each at
  // an 8-byte-aligned offset, and that buffer holds nothing else.
  const views = [];
  const collect = (value) => {
    if (ArrayBuffer.isView(value)) views.push(value);
    else if (value !== null && typeof value === 'object' && !Array.isArray(value)) Object.values(value).forEach(collect);
  };
  collect(mesh);
  for (const name of ['points', 'triangles', 'neighbors', 'segments', 'segmentIds', 'vertexKinds', 'triangleAttributes']) {
    assert.ok(views.includes(mesh[name]), name);
  }
  assert.equal(new Set(views.map((v) => v.buffer)).size, 1);
  const aligned = (bytes) => Math.ceil(bytes / 8) * 8;
  assert.equal(views[0].buffer.byteLength, views.reduce((sum, v) => sum + aligned(v.byteLength), 0));
  const spans = views.map((v) => [v.byteOffset, v.byteOffset + v.byteLength]).sort((a, b) => a[0] - b[0]);
  for (let i = 0; i < spans.length; i++) {
    assert.equal(spans[i][0] % 8, 0);
    if (i > 0) assert.ok(spans[i][0] >= spans[i - 1][1], 'views do not overlap');
  }
  // ... so they survive the heap growing under a later, larger call.
  const before = Array.from(mesh.points);
  const many = new Float64Array(200000).map((_, i) => (i % 2 ? Math.sin(i) : Math.cos(i * 1.3)) * 1000);
  mesher.triangulate({ points: many }, { minAngle: 0 });
  assert.deepEqual(Array.from(mesh.points), before);
});

// triangulate() writes the six input arrays straight into the wasm heap (wasm/heap-call.js): each
// must arrive intact, also when staging them grows the heap.
test('every input array reaches the core intact through the heap', async () => {
  const mesher = await init();
  const side = 400, n = side * side;
  const points = new Float64Array(2 * n + 16);
  for (let k = 0; k < n; k++) {
    points[2 * k] = ((k % side) + 0.5 + 0.3 * Math.sin(k)) / side;
    points[2 * k + 1] = (Math.floor(k / side) + 0.5 + 0.3 * Math.cos(k)) / side;
  }
  // An outer square and a square hole around (0.5, 0.5).
  points.set([-0.01, -0.01, 1.01, -0.01, 1.01, 1.01, -0.01, 1.01, 0.4, 0.4, 0.6, 0.4, 0.6, 0.6, 0.4, 0.6], 2 * n);
  const segments = [];
  for (const first of [n, n + 4]) for (let i = 0; i < 4; i++) segments.push(first + i, first + ((i + 1) % 4));
  const pointMarkers = Int32Array.from({ length: n + 8 }, (_, i) => i % 3);
  const plc = {
    points, segments: new Uint32Array(segments), holes: [0.5, 0.5], pointMarkers,
    segmentMarkers: [5, 6, 7, 8, 9, 10, 11, 12], regions: [{ x: 0.1, y: 0.1, attribute: 7 }],
  };
  const heapBefore = mesher.memoryUsage().heapBytes;
  const mesh = mesher.triangulate(plc, { minAngle: 0 });
  assert.deepEqual(mesh.points.subarray(0, points.length), points);
  // Nonzero input markers are kept; a zero one on a marked segment takes the segment's marker (the
  // lowest segment index's: segments 0-3 are the outer square's, 4-7 the hole's, 5..12).
  const expectedMarkers = Int32Array.from(pointMarkers, (m, i) => (m !== 0 || i < n ? m : i < n + 4 ? [5, 5, 6, 7][i - n] : [9, 9, 10, 11][i - n - 4]));
  assert.deepEqual(mesh.pointMarkers.subarray(0, n + 8), expectedMarkers);
  assert.ok(mesh.triangleAttributes.every((a) => a === 7), 'the region attribute reaches every triangle');
  const p = mesh.points, t = mesh.triangles;
  for (let k = 0; k < t.length / 3; k++) {
    const cx = (p[2 * t[3 * k]] + p[2 * t[3 * k + 1]] + p[2 * t[3 * k + 2]]) / 3;
    const cy = (p[2 * t[3 * k] + 1] + p[2 * t[3 * k + 1] + 1] + p[2 * t[3 * k + 2] + 1]) / 3;
    assert.ok(!(cx > 0.4 && cx < 0.6 && cy > 0.4 && cy < 0.6), `triangle ${k} lies in the hole`);
  }
  assert.ok(mesh.segments.length / 2 >= 8, 'the eight segments are in the mesh');
  assert.equal(toPoly(mesh, plc).split('\n').at(-4), '0 0.5 0.5', 'the hole is written back');
  console.log(`# heap ${heapBefore} -> ${mesher.memoryUsage().heapBytes} bytes, ${t.length / 3} triangles`);
});

test('meshes of real PLCs pass the independent validator', { skip: !haveData && 'shared data absent' }, async () => {
  const mesher = await init();
  for (const name of ['A.poly', 'face.poly', 'double_hex.poly', 'cdt_guitar.poly', 'earcut_dude.poly', 'box.poly']) {
    const path = join(dataDir, name);
    if (!existsSync(path)) {
      console.log(`# ${name} not in ${dataDir}: skipped`);
      continue;
    }
    const plc = parsePoly(readFileSync(path, 'utf8'), name);
    const cdt = mesher.triangulate(plc, { minAngle: 0 });
    assert.ok(cdt.triangles.length > 0, `${name}: no triangles`);
    assert.deepEqual(validateMesh(cdt, { input: plc }), [], `${name} (CDT)`);
    const refined = mesher.triangulate(plc, { minAngle: 25 });
    assert.deepEqual(validateMesh(refined, { input: plc }), [], `${name} (refined)`);
    assert.ok(refined.triangles.length >= cdt.triangles.length, `${name}: refinement removed triangles`);
  }
});

// A star-shaped polygon around (0.5, 0.5) with n vertices (a deterministic generator: LCG).
function starPolygon(seed, n) {
  let state = seed >>> 0;
  const random = () => ((state = (Math.imul(state, 1664525) + 1013904223) >>> 0) / 2 ** 32);
  const angles = Array.from({ length: n }, () => random() * 2 * Math.PI).sort((a, b) => a - b);
  const points = [];
  const segments = [];
  angles.forEach((a, i) => {
    const r = 0.2 + 0.3 * random();
    points.push(0.5 + r * Math.cos(a), 0.5 + r * Math.sin(a));
    segments.push(i, (i + 1) % n);
  });
  return { points, segments };
}

test("placement 'petal' gives valid meshes with fewer triangles than off-centers", async () => {
  const mesher = await init();
  let offCenter = 0;
  let petal = 0;
  for (let seed = 1; seed <= 12; seed++) {
    const plc = starPolygon(seed, 30);
    offCenter += mesher.triangulate(plc, { minAngle: 33, placement: 'offcenter' }).triangles.length / 3;
    const mesh = mesher.triangulate(plc, { minAngle: 33, placement: 'petal' });
    assert.deepEqual(validateMesh(mesh, { input: plc }), [], `seed ${seed}`);
    assert.equal(mesh.complete, true, `seed ${seed}: ${JSON.stringify(mesh.reasons)}`);
    petal += mesh.triangles.length / 3;
  }
  assert.ok(petal < offCenter, `petal ${petal} triangles, off-centers ${offCenter}`);
});

test("the default placement is 'optimal', with fewer triangles than off-centers", async () => {
  const mesher = await init();
  let optimal = 0;
  let offCenter = 0;
  for (let seed = 1; seed <= 6; seed++) {
    const plc = starPolygon(seed, 30);
    const byDefault = mesher.triangulate(plc, { minAngle: 33 });
    const named = mesher.triangulate(plc, { minAngle: 33, placement: 'optimal' });
    assert.deepEqual(byDefault.triangles, named.triangles, `seed ${seed}`);
    assert.deepEqual(byDefault.points, named.points, `seed ${seed}`);
    optimal += byDefault.triangles.length / 3;
    offCenter += mesher.triangulate(plc, { minAngle: 33, placement: 'offcenter' }).triangles.length / 3;
  }
  assert.ok(optimal < offCenter, `optimal ${optimal} triangles, off-centers ${offCenter}`);
});

test("placement 'optimal' gives valid meshes that meet 38 degrees where off-centers do not", async () => {
  const mesher = await init();
  let optimal = 0;
  let offCenter = 0;
  for (let seed = 1; seed <= 6; seed++) {
    const plc = starPolygon(seed, 30);
    offCenter += mesher.triangulate(plc, { minAngle: 38, placement: 'offcenter', maxSteiner: 3000 }).complete ? 1 : 0;
    const mesh = mesher.triangulate(plc, { minAngle: 38, placement: 'optimal', maxSteiner: 3000 });
    assert.deepEqual(validateMesh(mesh, { input: plc }), [], `seed ${seed}`);
    optimal += mesh.complete ? 1 : 0;
  }
  assert.ok(optimal > offCenter, `complete at 38 degrees: optimal ${optimal} of 6, off-centers ${offCenter}`);
});

test('parsePoly / toPoly / toSvg round trip through the C++ readers and writers', async () => {
  const mesher = await init();
  const text = '# a square\n4 2 0 1\n1 0 0 1\n2 1 0 1\n3 1 1 1\n4 0 1 1\n4 1\n1 1 2 5\n2 2 3 5\n3 3 4 5\n4 4 1 5\n0\n';
  const plc = parsePoly(text);
  assert.deepEqual(Array.from(plc.points), [0, 0, 1, 0, 1, 1, 0, 1]);
  assert.deepEqual(Array.from(plc.segments), [0, 1, 1, 2, 2, 3, 3, 0]);
  assert.equal(plc.indexBase, 1);
  const mesh = mesher.triangulate(plc, { minAngle: 0 });
  const poly = toPoly(mesh, plc);
  const again = parsePoly(poly);
  assert.equal(again.points.length, mesh.points.length);
  assert.equal(again.segments.length, mesh.segments.length);
  const svg = toSvg(mesh);
  assert.match(svg, /^<\?xml|^<svg/);
  assert.match(svg, /<\/svg>\s*$/);
  const node = mesher.toNode(mesh);
  assert.equal(mesher.parseNode(node).points.length, mesh.points.length);
  assert.equal(Number(mesher.toEle(mesh).trim().split(/\s+/)[0]), mesh.triangles.length / 3);
});

test('JavaScript-side validation names the offending item', async () => {
  const mesher = await init();
  const cases = [
    [() => mesher.triangulate('0 0 1 1'), 'MALFORMED_INPUT', /input must be an object/],
    [() => mesher.triangulate({ points: '0 0 1 0 0 1' }), 'MALFORMED_INPUT', /points must be an array/],
    [() => mesher.triangulate({ points: [0, 0, 1, 0, 0] }), 'MALFORMED_INPUT', /odd length 5/],
    // eslint-disable-next-line no-sparse-arrays
    [() => mesher.triangulate({ points: [0, 0, 1, , 0, 1] }), 'MALFORMED_INPUT', /points\[1\]\.y is missing/],
    [() => mesher.triangulate({ points: [0, 0, 1, '0', 0, 1] }), 'MALFORMED_INPUT', /points\[1\]\.y = "0" is not a number/],
    [() => mesher.triangulate({ points: [[0, 0], [1, 0], [0, 1]] }), 'MALFORMED_INPUT', /points\[0\]\.x is an array/],
    [() => mesher.triangulate({ ...square, segments: [0, 1, 1, 2, 2, 3, 3, 0, 1, 2.5] }), 'MALFORMED_INPUT',
      /segments\[4\] = \(1, 2\.5\): 2\.5 is not an integer/],
    [() => mesher.triangulate({ ...square, segments: [0, 1, 1, 4] }), 'INDEX_OUT_OF_RANGE', /segments\[1\] = \(1, 4\): 4 refers to point 4/],
    [() => mesher.triangulate({ ...square, segments: new Int32Array([0, -1]) }), 'INDEX_OUT_OF_RANGE', /segments\[0\] = \(0, -1\): -1 is negative/],
    [() => mesher.triangulate({ ...square, segments: [0, 1, 2] }), 'MALFORMED_INPUT', /segments has odd length 3/],
    [() => mesher.triangulate({ ...square, holes: [0.5] }), 'MALFORMED_INPUT', /holes has odd length/],
    [() => mesher.triangulate({ ...square, regions: [{ x: 0.5 }] }), 'MALFORMED_INPUT', /regions\[0\]\.y = undefined/],
    [() => mesher.triangulate({ ...square, regions: { x: 0.5, y: 0.5 } }), 'MALFORMED_INPUT', /regions must be an array/],
    [() => mesher.triangulate(square, { minAngle: 61 }), 'INVALID_OPTION', /minAngle = 61/],
    [() => mesher.triangulate(square, { minAngle: -1 }), 'INVALID_OPTION', /minAngle = -1/],
    [() => mesher.triangulate(square, { minAngle: '30' }), 'INVALID_OPTION', /minAngle = "30"/],
    [() => mesher.triangulate(square, { maxArea: -0.5 }), 'INVALID_OPTION', /maxArea = -0.5/],
    [() => mesher.triangulate(square, { maxArea: NaN }), 'INVALID_OPTION', /maxArea = NaN/],
    [() => mesher.triangulate(square, { maxSteiner: 1.5 }), 'INVALID_OPTION', /maxSteiner = 1.5/],
    [() => mesher.triangulate(square, { placement: 'centroid' }), 'INVALID_OPTION', /placement = "centroid"/],
    [() => mesher.triangulate(square, { encroachment: 'circle' }), 'INVALID_OPTION', /encroachment = "circle"/],
    [() => mesher.triangulate(square, { variant: 'conforming' }), 'INVALID_OPTION', /variant/],
    [() => mesher.triangulate(square, { convexHull: 1 }), 'INVALID_OPTION', /convexHull = 1/],
    [() => mesher.triangulate(square, { sizeFunction: 0.1 }), 'INVALID_OPTION', /sizeFunction = 0.1/],
    [() => mesher.triangulate(square, { minangle: 30 }), 'INVALID_OPTION', /unknown option 'minangle' \(did you mean 'minAngle'\?\)/],
    [() => mesher.parsePoly(42), 'MALFORMED_INPUT', /parsePoly expects the file's text/],
  ];
  for (const [fn, code, pattern] of cases) expectCode(fn, code, pattern);
});

test('every error code of the core is reachable from JavaScript', async () => {
  const mesher = await init();
  const q = { minAngle: 0 };
  const seen = new Set();
  const reach = (fn, code, pattern) => { expectCode(fn, code, pattern); seen.add(code); };
  reach(() => mesher.triangulate({ points: [] }, q), 'EMPTY_INPUT');
  reach(() => mesher.triangulate({ points: [0, 0, 1, 0, NaN, 1] }, q), 'NON_FINITE_COORDINATE', /points\[2\]/);
  // The core rescales, so only a range over 2^128 between coordinates is out of reach.
  reach(() => mesher.triangulate({ points: [0, 0, 1, 0, 0, 1, 1e-50, 0.5] }, q), 'COORDINATE_RANGE', /points\[3\]\.x/);
  reach(() => mesher.triangulate({ ...square, segments: [0, 9] }, q), 'INDEX_OUT_OF_RANGE', /segments\[0\] = \(0, 9\): 9 refers/);
  reach(() => mesher.triangulate({ points: [0, 0, 1, 1, 2, 2] }, q), 'DEGENERATE_INPUT');
  reach(() => mesher.triangulate({ ...square, holes: [0.5, 0] }, q), 'HOLE_ON_SEGMENT', /holes\[0\]/);
  reach(() => mesher.triangulate({ ...square, regions: [{ x: 0.5, y: 0.5, maxArea: NaN }] }, q), 'INVALID_REGION', /regions\[0\]/);
  // An open inner polyline: the hole seed reaches the whole square.
  reach(() => mesher.triangulate({ points: [0, 0, 10, 0, 10, 10, 0, 10, 4, 4, 6, 4, 4, 6],
    segments: [0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 6, 4], holes: [5, 5] }, q), 'EMPTY_DOMAIN', /holes\[0\]/);
  reach(() => mesher.triangulate(square, { minAngle: 60.5 }), 'INVALID_OPTION', /minAngle/);
  reach(() => mesher.parsePoly('4 2 0 0\n1 0 0\n'), 'PARSE_ERROR', /<poly>:\d/);
  reach(() => mesher.parsePoly('1000000000000 2 0 0\n'), 'TOO_LARGE');
  reach(() => mesher.parseJson('[1, 2]'), 'MALFORMED_INPUT');
  reach(() => mesher.triangulate({ points: [0, 0, 1, 0, 0] }), 'MALFORMED_INPUT', /odd length/);
  reach(() => mesher._abortForTesting(), 'INTERNAL', /aborted/);
  // CANCELLED is reached in worker.test.mjs (an aborted request). IO_ERROR cannot come from the
  // library: the wasm has no file system, so only the CLI reads files (cli.test.mjs checks it fails).
  for (const code of ['CANCELLED', 'IO_ERROR']) seen.add(code);
  assert.deepEqual([...seen].sort(), [...ERROR_CODES].sort(), 'a new error code needs a test here');
});

test('a wasm abort does not leave the module unusable', async () => {
  const mesher = await init();
  expectCode(() => mesher._abortForTesting(), 'INTERNAL');
  // The very next call runs on a fresh instance (synchronously re-instantiated under Node).
  const mesh = mesher.triangulate(square, { minAngle: 0 });
  assert.equal(mesh.triangles.length / 3, 2);
  await mesher.ready;
  assert.equal(mesher.triangulate(square, { minAngle: 0 }).triangles.length / 3, 2);
});

test('sizeFunction is called from C++ and grades the mesh', async () => {
  const mesher = await init();
  let calls = 0;
  const sizeFunction = (x, y) => { calls++; return x < 0.5 ? 0.0005 : 0.01; };
  const mesh = mesher.triangulate(square, { minAngle: 25, sizeFunction });
  assert.ok(calls > 0, 'sizeFunction was never called');
  assert.deepEqual(validateMesh(mesh, { input: square }), []);
  const p = mesh.points, t = mesh.triangles;
  let left = 0, right = 0;
  for (let k = 0; k < t.length / 3; k++) {
    const xs = [p[2 * t[3 * k]], p[2 * t[3 * k + 1]], p[2 * t[3 * k + 2]]];
    const area = triangleArea(p, t[3 * k], t[3 * k + 1], t[3 * k + 2]);
    // Well inside the fine half, wherever the core samples the field (centroid or circumcenter).
    if (Math.max(...xs) < 0.4) assert.ok(area <= 0.0005 * (1 + 1e-9), `triangle ${k} area ${area} at x < 0.4`);
    if (xs[0] + xs[1] + xs[2] < 1.5) left++; else right++;
  }
  assert.ok(left > 4 * right, `left ${left} vs right ${right}`);
});

test('errors thrown by callbacks propagate unchanged and leave the module usable', async () => {
  const mesher = await init();
  const boom = new Error('boom');
  assert.throws(() => mesher.triangulate(square, { maxArea: 0.001, sizeFunction: () => { throw boom; } }), (e) => e === boom);
  expectCode(() => mesher.triangulate(square, { maxArea: 0.001, sizeFunction: () => 'small' }), 'INVALID_OPTION',
    /sizeFunction\(.*\) returned "small"/);
  assert.throws(() => mesher.triangulate(square, { maxArea: 1e-6, onProgress: () => { throw boom; } }), (e) => e === boom);
  assert.equal(mesher.triangulate(square, { minAngle: 0 }).triangles.length / 3, 2);
});

test('onProgress reports and can stop refinement early', async () => {
  const mesher = await init();
  const seen = [];
  const mesh = mesher.triangulate(square, { maxArea: 1e-6, onProgress: (p) => { seen.push(p); return seen.length < 2; } });
  assert.ok(seen.length >= 1, 'no progress reported');
  assert.equal(typeof seen[0].insertedVertices, 'number');
  assert.equal(mesh.complete, false);
  assert.ok(mesh.reasons.some((r) => r.kind === 'CANCELLED'), JSON.stringify(mesh.reasons));
  assert.deepEqual(validateMesh(mesh, { input: square }), []);
});

test('maxSteiner: 0 inserts nothing, maxSteiner: k exactly k vertices', async () => {
  const mesher = await init();
  for (const k of [0, 1, 5]) {
    const mesh = mesher.triangulate(square, { minAngle: 30, maxArea: 0.001, maxSteiner: k });
    assert.equal(mesh.points.length / 2, 4 + k, `budget ${k}`);
    assert.equal(mesh.complete, false);
    assert.equal(mesh.reasons[0].kind, 'STEINER_BUDGET');
  }
});

test('above 34 degrees an unreachable bound gives the best mesh reached, ANGLE_UNREACHABLE', async () => {
  const mesher = await init();
  const plc = { points: [0, 0, 1, 0, 1, 1, 0, 1, 0.3, 0.31, 0.7, 0.2], segments: [0, 1, 1, 2, 2, 3, 3, 0] };
  const at33 = mesher.triangulate(plc, { minAngle: 33 });
  assert.equal(at33.complete, true);
  const mesh = mesher.triangulate(plc, { minAngle: 45 });
  assert.equal(mesh.complete, false);
  assert.equal(mesh.reasons[0].kind, 'ANGLE_UNREACHABLE', JSON.stringify(mesh.reasons));
  assert.ok(mesh.stats.reachedAngle >= 33 && mesh.stats.reachedAngle < 45, `${mesh.stats.reachedAngle}`);
  assert.ok(mesh.stats.triangles <= 4 * at33.stats.triangles);
  assert.deepEqual(validateMesh(mesh, { input: plc, minAngle: mesh.stats.reachedAngle - 1e-9 }), []);
});

test('trace records every insertion as typed arrays', async () => {
  const mesher = await init();
  const mesh = mesher.triangulate(square, { minAngle: 30, maxArea: 0.01, trace: true });
  assert.ok(mesh.events, 'no events');
  const inserted = mesh.points.length / 2 - square.points.length / 2;
  assert.equal(mesh.events.count, mesh.events.kind.length);
  assert.ok(mesh.events.count >= inserted, `${mesh.events.count} events for ${inserted} new vertices`);
  assert.equal(mesh.events.xy.length, 2 * mesh.events.count);
  assert.equal(mesher.triangulate(square, { minAngle: 30, maxArea: 0.01 }).events, undefined);
});

// The page's replay shows step k as the mesh maxSteiner: k gives, with the trace's event k: a trace
// must change nothing, and the optimal placement's moves of free vertices are events of their own.
test('a trace changes nothing: RELOCATED moves are events, and step k is maxSteiner: k', async () => {
  const mesher = await init();
  let seed = 12345;
  const random = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
  const points = [0, 0, 1, 0, 1, 1, 0, 1];
  for (let i = 0; i < 300; i++) points.push(random(), random());
  const plc = { points, segments: [0, 1, 1, 2, 2, 3, 3, 0] };
  const plain = mesher.triangulate(plc, { minAngle: 30 });
  const traced = mesher.triangulate(plc, { minAngle: 30, trace: true });
  assert.deepEqual(traced.points, plain.points);
  assert.deepEqual(traced.triangles, plain.triangles);
  const { events } = traced;
  const moves = [];
  for (let e = 0; e < events.count; e++) {
    if (events.kind[e] !== EventKind.RELOCATED) continue;
    moves.push(e);
    assert.ok(events.xy[2 * e] !== events.circumcenter[2 * e] || events.xy[2 * e + 1] !== events.circumcenter[2 * e + 1]);
  }
  assert.ok(moves.length > 0, 'no RELOCATED event: this input no longer tests what it is for');
  assert.equal(traced.points.length / 2, points.length / 2 + events.count - moves.length);
  for (const k of [moves[0], moves[0] + 1, events.count - 1]) {
    const step = mesher.triangulate(plc, { minAngle: 30, maxSteiner: k });
    const stepTraced = mesher.triangulate(plc, { minAngle: 30, maxSteiner: k, trace: true });
    assert.deepEqual(step.points, stepTraced.points, `step ${k}`);
    assert.equal(stepTraced.events.count, k);
    assert.deepEqual(stepTraced.events.kind, events.kind.subarray(0, k));
    // The moved vertex is where the move put it, until a later event moves it again.
    const e = moves[0];
    if (k === e + 1) {
      const v = events.vertex[e];
      assert.deepEqual([step.points[2 * v], step.points[2 * v + 1]], [events.xy[2 * e], events.xy[2 * e + 1]]);
    }
  }
});

// Notices and reasons come back through the heap (wasm/heap-call.js), not as embind objects.
test('points given twice: one DUPLICATE_POINT notice per copy, in input order, and the same mesh', async () => {
  const mesher = await init();
  const n = 500;
  const points = new Float64Array(4 * n);
  for (let i = 0; i < 2 * n; i++) points[i] = ((i * 7919) % 1009) / 1009 + i / 1e6;
  points.set(points.subarray(0, 2 * n), 2 * n);
  const once = mesher.triangulate({ points: points.subarray(0, 2 * n) }, { minAngle: 0 });
  const twice = mesher.triangulate({ points }, { minAngle: 0 });
  assert.deepEqual(twice.triangles, once.triangles);
  assert.equal(twice.notices.length, n);
  twice.notices.forEach((notice, k) => {
    assert.deepEqual({ ...notice, message: undefined },
      { kind: 'DUPLICATE_POINT', a: n + k, b: k, x: points[2 * k], y: points[2 * k + 1], message: undefined });
    assert.equal(notice.message, `points[${n + k}] duplicates points[${k}]; merged`);
  });
  const limited = mesher.triangulate({ points }, { minAngle: 30, maxArea: 1e-4, maxSteiner: 5 });
  assert.ok(limited.reasons.some((r) => r.kind === 'STEINER_BUDGET' && r.count > 0 && r.message.length > 0),
    JSON.stringify(limited.reasons));
});

test('the heap does not grow over 10,000 calls (successes and every failure path)', async () => {
  const mesher = await init();
  const tiny = { points: [0, 0, 1, 0, 1, 1, 0, 1, 0.3, 0.6], segments: square.segments, holes: [], regions: [] };
  const round = (i) => {
    switch (i % 6) {
      case 0: return mesher.triangulate(tiny, { minAngle: 0 });
      // Notices (a duplicate, nothing enclosed) and a reason (the Steiner budget), read from the heap.
      case 5: return mesher.triangulate({ points: [...tiny.points, 1, 1] }, { minAngle: 30, maxArea: 0.01, maxSteiner: 3 });
      case 1: try { mesher.triangulate({ points: [0, 0, 1, 1, 2, 2] }, { minAngle: 0 }); } catch { /* C++ throw */ } return null;
      case 2: try { mesher.parsePoly('3 2 0 0\n1 0 0\n'); } catch { /* parse error */ } return null;
      case 3: try { mesher.triangulate(tiny, { minAngle: 0, sizeFunction: () => { throw new Error('x'); } }); } catch { /* callback */ } return null;
      default: return mesher.toSvg(mesher.triangulate(tiny, { minAngle: 20, maxArea: 0.05 }));
    }
  };
  for (let i = 0; i < 200; i++) round(i);
  const before = mesher.memoryUsage();
  for (let i = 0; i < 10000; i++) round(i);
  const after = mesher.memoryUsage();
  assert.equal(after.heapBytes, before.heapBytes, 'the wasm heap grew');
  assert.ok(after.allocatedBytes <= before.allocatedBytes + 4096,
    `allocated bytes went from ${before.allocatedBytes} to ${after.allocatedBytes}`);
});

test('a 2-million-triangle mesh succeeds', { timeout: 600000 }, async () => {
  const mesher = await init();
  const maxArea = 0.5e-6;  // every triangle <= maxArea on a unit square: at least 2,000,000 triangles
  const mesh = mesher.triangulate(square, { minAngle: 30, maxArea });
  const triangles = mesh.triangles.length / 3;
  assert.ok(triangles >= 2000000, `${triangles} triangles`);
  assert.equal(mesh.complete, true, JSON.stringify(mesh.reasons));
  assert.deepEqual(validateMesh(mesh, { input: square, minAngle: 30, maxArea }), []);
});
