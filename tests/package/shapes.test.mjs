// Strict input shapes, Triangle's split .poly + .node, load failures that name their URL, the
// package's export conditions and its CommonJS use, against the installed tarball.
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { createMeshWorker, init, MeshError, parsePoly } from 'ruppert';
import { validateMesh } from './validate-mesh.mjs';

const square = { points: [0, 0, 1, 0, 1, 1, 0, 1], segments: [0, 1, 1, 2, 2, 3, 3, 0] };

function expectCode(fn, code, messagePattern) {
  assert.throws(fn, (error) => {
    assert.ok(error instanceof MeshError, `expected a MeshError, got ${error}`);
    assert.equal(error.code, code, error.message);
    assert.match(error.message, messagePattern);
    return true;
  });
}

test('an unknown key of the input, a region or the options is an error naming it, with a did-you-mean', async () => {
  const mesher = await init();
  const cases = [
    [{ points: square.points, Segments: square.segments }, {}, 'MALFORMED_INPUT',
      /the input has an unknown key 'Segments' \(did you mean 'segments'\?\)/],
    [{ ...square, hole: [0.5, 0.5] }, {}, 'MALFORMED_INPUT', /unknown key 'hole' \(did you mean 'holes'\?\)/],
    [{ ...square, point_markers: [1, 1, 1, 1] }, {}, 'MALFORMED_INPUT', /'point_markers' \(did you mean 'pointMarkers'\?\)/],
    // `triangles` is a key (refining a mesh); a near miss still gets its did-you-mean.
    [{ ...square, triangle: [0, 1, 2] }, {}, 'MALFORMED_INPUT', /unknown key 'triangle' \(did you mean 'triangles'\?\); the keys are points, segments/],
    [{ ...square, elements: [0, 1, 2] }, {}, 'MALFORMED_INPUT', /unknown key 'elements'; the keys are points, segments/],
    [{ ...square, regions: [{ x: 0.5, y: 0.5, area: 0.1 }] }, {}, 'MALFORMED_INPUT',
      /regions\[0\] has an unknown key 'area' \(did you mean 'maxArea'\?\)/],
    [square, { min_angle: 30 }, 'INVALID_OPTION', /unknown option 'min_angle' \(did you mean 'minAngle'\?\)/],
    [square, { maxarea: 0.1 }, 'INVALID_OPTION', /unknown option 'maxarea' \(did you mean 'maxArea'\?\)/],
  ];
  for (const [plc, options, code, pattern] of cases) expectCode(() => mesher.triangulate(plc, options), code, pattern);
  // Without the check, { Segments } meshed the convex hull of the points: the same as no segments.
  assert.equal(mesher.triangulate({ points: square.points }, { minAngle: 0 }).triangles.length, 6);
});

test('a value of the wrong type says so before any range', async () => {
  const mesher = await init();
  const cases = [
    [{ minAngle: '30' }, /minAngle = "30" is not a number \(degrees in \[0, 60\]\)/],
    [{ minAngle: NaN }, /minAngle = NaN is not a number/],
    [{ maxArea: '0.1' }, /maxArea = "0.1" is not a number/],
    [{ maxSteiner: '100' }, /maxSteiner = "100" is not a number/],
    [{ minAngle: 61 }, /minAngle = 61 is outside \[0, 60\] degrees/],
    [{ maxArea: -1 }, /maxArea = -1 must be >= 0/],
  ];
  for (const [options, pattern] of cases) expectCode(() => mesher.triangulate(square, options), 'INVALID_OPTION', pattern);
  expectCode(() => mesher.triangulate({ ...square, regions: [{ x: '0.5', y: 0.5 }] }), 'MALFORMED_INPUT',
    /regions\[0\]\.x = "0.5" is not a number/);
});

test('init() and createMeshWorker() reject unknown options', async () => {
  await assert.rejects(init({ wasmURL: 'x.wasm' }), (error) => error instanceof MeshError &&
    error.code === 'INVALID_OPTION' && /init\(options\) has an unknown key 'wasmURL' \(did you mean 'wasmUrl'\?\)/.test(error.message));
  expectCode(() => createMeshWorker({ locateFile: (f) => f }), 'INVALID_OPTION', /unknown key 'locateFile'/);
});

// Triangle's split form: a .poly whose point section is empty ("0 2 0 1") and a .node with the points.
const splitPoly = '# points in the .node\n0 2 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n1\n1 1.5 1.5\n';
const splitNode = '4 2 0 1\n1 0 0 5\n2 3 0 6\n3 3 3 7\n4 0 3 8\n';

test('parsePoly(text, { node }) reads a .poly declaring 0 points with its .node text', async () => {
  const mesher = await init();
  const plc = parsePoly(splitPoly, { name: 'split.poly', node: splitNode, nodeName: 'split.node' });
  assert.deepEqual([...plc.points], [0, 0, 3, 0, 3, 3, 0, 3]);
  assert.deepEqual([...plc.pointMarkers], [5, 6, 7, 8]);
  assert.deepEqual([...plc.segments], [0, 1, 1, 2, 2, 3, 3, 0]);
  assert.deepEqual([...plc.holes], [1.5, 1.5]);
  assert.equal(plc.indexBase, 1);
  const mesh = mesher.triangulate({ ...plc, holes: [] }, { minAngle: 30, maxArea: 0.5 });
  assert.deepEqual(validateMesh(mesh, { input: { ...plc, holes: [] }, minAngle: 30, maxArea: 0.5 }), []);
  // Without the .node text, the message says what to pass in JavaScript.
  expectCode(() => parsePoly(splitPoly, 'split.poly'), 'PARSE_ERROR',
    /split\.poly:1: the \.poly declares 0 points.*parsePoly\(polyText, \{ node: nodeText \}\)/);
  // The .node's own errors name the .node.
  expectCode(() => mesher.parsePoly(splitPoly, { node: '4 2 0 1\n1 0 0 5\n', nodeName: 'short.node' }), 'PARSE_ERROR',
    /short\.node/);
  expectCode(() => parsePoly(splitPoly, { nodes: splitNode }), 'INVALID_OPTION', /unknown key 'nodes' \(did you mean 'node'\?\)/);
  expectCode(() => parsePoly(splitPoly, { node: 42 }), 'MALFORMED_INPUT', /options\.node expects the file's text/);
});

test('a .wasm that cannot be loaded is named with the reason', async () => {
  const missing = new URL('file:///nonexistent-ruppert-folder/ruppert.wasm');
  await assert.rejects(init({ wasmUrl: missing }), (error) => {
    assert.equal(error.code, 'IO_ERROR');
    assert.match(error.message, /could not load the WebAssembly module file:\/\/\/nonexistent-ruppert-folder\/ruppert\.wasm: .*ENOENT/);
    return true;
  });
  const notWasm = new URL('./package.json', import.meta.url);
  await assert.rejects(init({ wasmUrl: notWasm }), /package\.json: not a WebAssembly module/);
});

test('the export conditions: Node gets node.js and worker-node.js, browsers index.js and worker.js', () => {
  const manifest = JSON.parse(readFileSync(new URL('./node_modules/ruppert/package.json', import.meta.url), 'utf8'));
  assert.match(import.meta.resolve('ruppert'), /\/node_modules\/ruppert\/wasm\/node\.js$/);
  assert.match(import.meta.resolve('ruppert/worker.js'), /\/node_modules\/ruppert\/wasm\/worker-node\.js$/);
  assert.equal(manifest.exports['.'].browser, './wasm/index.js');
  assert.equal(manifest.exports['./worker.js'].browser, './wasm/worker.js');
  // What browsers load has no Node module in it (the bundler tests build it; this is the source).
  for (const file of ['index.js', 'errors.js', 'input-checks.js', 'loader.js', 'mesher.js', 'heap-call.js', 'mesh-worker.js', 'worker.js']) {
    const text = readFileSync(new URL(`./node_modules/ruppert/wasm/${file}`, import.meta.url), 'utf8');
    assert.doesNotMatch(text, /(from|import\()\s*['"]node:/, file);
  }
});

test('require("ruppert") works from CommonJS on this Node, which engines covers', () => {
  const manifest = JSON.parse(readFileSync(new URL('./node_modules/ruppert/package.json', import.meta.url), 'utf8'));
  assert.equal(manifest.engines.node, '>=20.19');
  const [major, minor] = process.versions.node.split('.').map(Number);
  assert.ok(major > 20 || (major === 20 && minor >= 19), `this Node (${process.version}) is older than engines says`);
  const script = `const { init } = require('ruppert');
init().then((m) => { const mesh = m.triangulate({ points: [0, 0, 1, 0, 0, 1] }, { minAngle: 20 });
  console.log(JSON.stringify({ triangles: mesh.triangles.length / 3, complete: mesh.complete })); });`;
  const cwd = fileURLToPath(new URL('.', import.meta.url));
  const result = spawnSync(process.execPath, ['--input-type=commonjs', '-e', script], { cwd, encoding: 'utf8' });
  assert.equal(result.status, 0, result.stderr);
  const out = JSON.parse(result.stdout.trim());
  assert.ok(out.triangles >= 1 && out.complete, result.stdout);
});

test('createMeshWorker({ workerUrl }): a given worker script is used, a missing one is named', async () => {
  const given = createMeshWorker({ workerUrl: import.meta.resolve('ruppert/worker.js') });
  try {
    const mesh = await given.triangulate(square, { minAngle: 30, maxArea: 0.05 });
    assert.ok(mesh.complete && mesh.triangles.length >= 60);
  } finally {
    await given.terminate();
  }
  const missing = createMeshWorker({ workerUrl: new URL('file:///nonexistent-ruppert-folder/worker.js') });
  try {
    await assert.rejects(missing.triangulate(square), /mesh worker failed: .*nonexistent-ruppert-folder\/worker\.js/);
  } finally {
    await missing.terminate();
  }
  // The worker checks shapes in the caller's thread too.
  const worker = createMeshWorker();
  try {
    await assert.rejects(worker.triangulate({ points: square.points, Segments: [] }), /unknown key 'Segments'/);
  } finally {
    await worker.terminate();
  }
});
