// createMeshWorker() under Node (worker_threads), against the installed tarball.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { createMeshWorker, MeshError } from 'ruppert';
import { validateMesh } from './validate-mesh.mjs';

const square = { points: [0, 0, 1, 0, 1, 1, 0, 1], segments: [0, 1, 1, 2, 2, 3, 3, 0] };

// Deterministic pseudo-random points (Marsaglia's xorshift32 in 32-bit integer arithmetic): the
// same distinct points every run. A CDT of a million of them takes seconds: long enough to cancel.
function scattered(n) {
  const points = new Float64Array(2 * n);
  let x = 2463534242;
  for (let i = 0; i < 2 * n; i++) {
    x ^= x << 13;
    x ^= x >>> 17;
    x ^= x << 5;
    points[i] = (x >>> 0) / 4294967296;
  }
  return { points };
}

test('round trip: a worker returns a valid mesh of typed arrays', async () => {
  const worker = createMeshWorker();
  try {
    const plc = { points: [0, 0, 1, 0, 1, 1, 0, 1, 0.4, 0.6], segments: square.segments };
    const mesh = await worker.triangulate(plc, { minAngle: 0 });
    assert.ok(mesh.points instanceof Float64Array && mesh.triangles instanceof Uint32Array);
    assert.equal(mesh.triangles.length / 3, 4);
    assert.deepEqual(validateMesh(mesh, { input: plc }), []);
    // Several requests queue on one worker and come back in order.
    const results = await Promise.all([1, 2, 3].map((k) => worker.triangulate(scattered(100 * k), { minAngle: 0 })));
    assert.deepEqual(results.map((m) => m.points.length / 2), [100, 200, 300]);
  } finally {
    await worker.terminate();
  }
});

test('errors come back as MeshError with their code', async () => {
  const worker = createMeshWorker();
  try {
    await assert.rejects(worker.triangulate({ points: [0, 0, 1, 1, 2, 2] }, { minAngle: 0 }),
      (e) => e instanceof MeshError && e.code === 'DEGENERATE_INPUT');
    await assert.rejects(worker.triangulate(square, { minAngle: 99 }),
      (e) => e instanceof MeshError && e.code === 'INVALID_OPTION');
    await assert.rejects(worker.triangulate(square, { sizeFunction: () => 1 }),
      (e) => e instanceof MeshError && e.code === 'INVALID_OPTION' && /worker/.test(e.message));
  } finally {
    await worker.terminate();
  }
});

test('progress events arrive from Options::onProgress during refinement', { timeout: 120000 }, async () => {
  const worker = createMeshWorker();
  try {
    const seen = [];
    const mesh = await worker.triangulate(square, { minAngle: 30, maxArea: 2e-6 }, { onProgress: (p) => seen.push(p) });
    assert.ok(seen.length >= 1, 'no progress event');
    assert.ok(seen.every((p) => typeof p.triangles === 'number' && typeof p.insertedVertices === 'number'));
    assert.ok(mesh.triangles.length / 3 >= 500000);
  } finally {
    await worker.terminate();
  }
});

test('an AbortSignal cancels promptly; the next request runs on a fresh worker', { timeout: 120000 }, async () => {
  const worker = createMeshWorker();
  try {
    // Warm up so that the cancelled request is busy meshing, not loading wasm.
    await worker.triangulate(square, { minAngle: 0 });
    const controller = new AbortController();
    const big = worker.triangulate(scattered(1000000), { minAngle: 0 }, { signal: controller.signal });
    const queued = worker.triangulate(square, { minAngle: 0 });
    await new Promise((resolve) => setTimeout(resolve, 300));
    const abortedAt = performance.now();
    controller.abort();
    await assert.rejects(big, (e) => e instanceof MeshError && e.code === 'CANCELLED');
    const latency = performance.now() - abortedAt;
    assert.ok(latency < 500, `cancellation took ${latency} ms`);
    // The request queued behind the cancelled one is re-sent to the new worker.
    assert.equal((await queued).triangles.length / 3, 2);
    assert.equal((await worker.triangulate(square, { minAngle: 0 })).triangles.length / 3, 2);
    // An already aborted signal rejects at once.
    await assert.rejects(worker.triangulate(square, {}, { signal: AbortSignal.abort() }),
      (e) => e instanceof MeshError && e.code === 'CANCELLED');
  } finally {
    await worker.terminate();
  }
});

test('terminate() rejects pending requests with CANCELLED', async () => {
  const worker = createMeshWorker();
  const pending = worker.triangulate(scattered(1000), { minAngle: 0 });
  const rejected = assert.rejects(pending, (e) => e instanceof MeshError && e.code === 'CANCELLED');
  await worker.terminate();
  await rejected;
});

test('the worker loads the mesher alone (init with formats: false), keeping the load options it is given', async () => {
  const { meshRequestHandler } = await import(new URL('./node_modules/ruppert/wasm/mesh-worker.js', import.meta.url));
  const { init } = await import('ruppert');
  const seen = [];
  const posted = [];
  const handle = meshRequestHandler((options) => { seen.push(options); return init(options); }, (data) => posted.push(data));
  await handle({ type: 'init', options: { wasmUrl: new URL('./node_modules/ruppert/wasm/dist/ruppert.wasm', import.meta.url).href } });
  await handle({ type: 'triangulate', id: 1, plc: square, options: { minAngle: 30, maxArea: 0.01 } });
  assert.equal(seen.length, 1);
  assert.equal(seen[0].formats, false);
  assert.match(String(seen[0].wasmUrl), /ruppert\.wasm$/);
  assert.equal(posted.length, 1);
  assert.equal(posted[0].type, 'result', JSON.stringify(posted[0]).slice(0, 200));
  assert.deepEqual(validateMesh(posted[0].mesh, { input: square, minAngle: 30, maxArea: 0.01 }), []);
});
