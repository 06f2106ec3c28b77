// The app every bundler builds (tests/bundlers/run.mjs): what a user writes, importing 'ruppert'
// with no bundler configuration. It meshes on the main thread and in a worker (progress, a
// cancel, a request after the cancel), provokes the two load failures, and publishes what it saw
// in window.ruppertResults for the test to check.
import { init, createMeshWorker } from 'ruppert';

const square = { points: [0, 0, 1, 0, 1, 1, 0, 1], segments: [0, 1, 1, 2, 2, 3, 3, 0] };

const summary = (mesh) => ({
  triangles: mesh.triangles.length / 3, minAngle: mesh.stats.minAngle, complete: mesh.complete,
});
const outcome = (promise) => promise.then(() => 'succeeded', (error) => ({ code: error.code, message: error.message }));

async function mainThread() {
  const mesher = await init();
  return summary(mesher.triangulate(square, { minAngle: 30, maxArea: 0.001 }));
}

// The text formats module (ruppert-formats.wasm), which init() loads beside the mesher.
async function formats() {
  const mesher = await init();
  const plc = mesher.parsePoly('4 2 0 0\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n4 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n0\n');
  const mesh = mesher.triangulate(plc, { minAngle: 30, maxArea: 0.01 });
  return { nodeHeader: mesher.toNode(mesh).split('\n')[0], vtu: mesher.toVtu(mesh).startsWith('<?xml'), points: plc.points.length };
}

async function inWorker() {
  const worker = createMeshWorker();
  let progressCalls = 0;
  const mesh = await worker.triangulate(square, { minAngle: 30, maxArea: 1e-5 },
    { onProgress: () => { progressCalls++; } });
  // About a million triangles: cancelled at its first progress report, long before it would end.
  const controller = new AbortController();
  const cancelled = outcome(worker.triangulate(square, { minAngle: 30, maxArea: 1e-6 },
    { signal: controller.signal, onProgress: () => controller.abort() }));
  const after = worker.triangulate(square, { minAngle: 30, maxArea: 0.01 });
  const result = { mesh: summary(mesh), progressCalls, cancelled: await cancelled, afterCancel: summary(await after) };
  await worker.terminate();
  return result;
}

async function loadFailures() {
  const wasm = await outcome(init({ wasmUrl: 'no-such-file.wasm', formats: false }));
  const formatsWasm = await outcome(init({ formats: { wasmUrl: 'no-such-formats.wasm' } }));
  const worker = createMeshWorker({ workerUrl: 'no-such-worker.js' });
  const workerScript = await outcome(worker.triangulate(square));
  await worker.terminate();
  return { wasm, formatsWasm, workerScript };
}

async function main() {
  const results = {};
  for (const [name, check] of [['mainThread', mainThread], ['formats', formats], ['worker', inWorker], ['loadFailures', loadFailures]]) {
    try {
      results[name] = await check();
    } catch (error) {
      results[name] = { thrown: `${error?.name}: ${error?.message}` };
    }
  }
  window.ruppertResults = results;
}

main();
