#!/usr/bin/env node
// Per-call speed of ruppert against Triangle (npm triangle-wasm), both WebAssembly, in ONE thread
// of one Node process, on the same inputs with the same quality bound.
//
//   npm install --no-save triangle-wasm     (or set TRIANGLE_WASM_DIR to an installed copy's folder,
//                                            safer: a later plain `npm install` prunes --no-save)
//   node tests/bench/speed-per-call.mjs [--dir DIR]... [--no-corpus] [--no-families] [--angle 30]
//        [--batch-ms 40] [--rounds 5] [--only SUBSTRING] [--json FILE] [--placement P] [--warmup-ms 3000]
//        [--cpu-time]
//
// Inputs: every .poly of the shared corpus (RUPPERT_SHARED_DATA or ../shared/data; family "corpus"),
// every .poly of each --dir (family = the file name without a trailing -<seed>), and shape families
// generated here (combs, stars, perforated squares, random points in a square) at a few sizes.
// Triangle runs with -pzQq<angle> (plus -a when a region has an area bound), ruppert with
// { minAngle: angle } (and { placement } with --placement, else the default). A call is timed end
// to end through each package's public API (input copied in, output copied out). Per input: one warm-up call each, then calls in batches of at least
// --batch-ms, the two meshers alternating batch by batch for --rounds rounds; per-call time = the
// median over rounds of batch time / calls. speedup = Triangle's time / ruppert's (> 1: ruppert
// faster). Before the first input (and after any restart of the worker) both meshers run for
// --warmup-ms, alternating, on up to ten of the inputs with at most 500 points: V8 first runs
// WebAssembly from a baseline compiler and optimizes each function only once it is hot, which for
// a module the size of ruppert's takes one to three seconds of calls. Without the warm-up the first
// inputs measured that, not the steady state (A.poly, the first: 232 us without, 83 us with it). Printed: a row per input, then the geometric mean of the speedups per family and overall.
// Inputs that Triangle cannot mesh (its fixed 16 MiB heap, a hang) are listed and left out.
import { readFileSync, readdirSync, existsSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join, basename } from 'node:path';
import { fileURLToPath } from 'node:url';
import { Worker, isMainThread, parentPort, workerData } from 'node:worker_threads';
import { generatedFamilies } from './shape-families.mjs';

const require = createRequire(import.meta.url);
const repoRoot = fileURLToPath(new URL('../../', import.meta.url));

// ---------------------------------------------------------------------------------------------
// Worker: both meshers, one thread. A job is { plc, angle, batchMs, rounds }.
// ---------------------------------------------------------------------------------------------
function loadTriangle(dir) {
  for (const key of Object.keys(require.cache)) if (key.startsWith(dir)) delete require.cache[key];
  return require(dir);
}

async function worker() {
  // Triangle's Emscripten loader predates Node's global fetch: with fetch present it tries to fetch
  // its .wasm by file path. ruppert reads its own .wasm with fs under Node, so fetch can go.
  delete globalThis.fetch;
  const Triangle = loadTriangle(workerData.triangleWasmDir);
  await Triangle.init();
  const { init } = await import(new URL('../../wasm/index.js', import.meta.url));
  const ruppert = await init();
  const meshTriangle = (plc, switches) => {
    const regionlist = [];
    for (const r of plc.regions) regionlist.push(r.x, r.y, r.attribute, r.maxArea);
    const input = Triangle.makeIO({ pointlist: plc.points, segmentlist: plc.segments, holelist: plc.holes, regionlist });
    const output = Triangle.makeIO();
    try {
      Triangle.triangulate(switches, input, output);
      // Views into Triangle's heap: copied, as ruppert's results are.
      return { points: Float64Array.from(output.pointlist), triangles: Int32Array.from(output.trianglelist) };
    } finally {
      Triangle.freeIO(input, true);  // Triangle shares the hole and region lists between input and output
      Triangle.freeIO(output);
    }
  };
  const optionsOf = ({ angle, placement }) => (placement ? { minAngle: angle, placement } : { minAngle: angle });
  const switchesOf = (plc, angle) => `pzQq${angle}${plc.regions.some((r) => r.maxArea > 0) ? 'a' : ''}`;
  parentPort.on('message', (job) => {
    try {
      if (job.warmup) {
        const t0 = performance.now();
        while (performance.now() - t0 < job.ms) {
          for (const plc of job.warmup) meshTriangle(plc, switchesOf(plc, job.angle)), ruppert.triangulate(plc, optionsOf(job));
        }
        parentPort.postMessage({ status: 'ok' });
        return;
      }
      const { plc, angle } = job;
      const options = optionsOf(job);
      const switches = switchesOf(plc, angle);
      const result = timePair(() => meshTriangle(plc, switches), () => ruppert.triangulate(plc, options), job);
      parentPort.postMessage({ status: 'ok', ...result });
    } catch (error) {
      // An abort (Triangle out of its heap) leaves that module unusable: the main thread restarts us.
      parentPort.postMessage({ status: 'error', error: String(error?.message ?? error).slice(0, 160) });
    }
  });
  parentPort.postMessage({ status: 'ready' });
}

const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];

// Per-call times of two meshers, alternating batches so that both see the same machine state.
// --cpu-time: a batch is timed by the process's CPU time (user + system) instead of the wall clock,
// so that time the machine gives other processes (a shared, loaded machine) is not counted; the
// worker is the only busy thread, besides V8's own helpers, whose work counts either way.
const cpuClock = () => {
  const { user, system } = process.cpuUsage();
  return (user + system) / 1000;
};

function timePair(triangle, ruppert, { batchMs, rounds, cpuTime }) {
  const now = cpuTime ? cpuClock : () => performance.now();
  const warm = (mesh) => {
    const t0 = performance.now();
    const out = mesh();
    return { ms: performance.now() - t0, triangles: out.triangles.length / 3 };
  };
  const t = warm(triangle);
  const r = warm(ruppert);
  const callsFor = (ms) => Math.max(1, Math.min(100000, Math.ceil(batchMs / Math.max(ms, 1e-3))));
  const batch = (mesh, calls) => {
    const t0 = now();
    for (let i = 0; i < calls; i++) mesh();
    return (now() - t0) / calls;
  };
  // The warm-up's time overstates small calls; a first short batch sizes them better.
  const tCalls = callsFor(batch(triangle, callsFor(t.ms) > 10 ? 10 : 1));
  const rCalls = callsFor(batch(ruppert, callsFor(r.ms) > 10 ? 10 : 1));
  const tTimes = [], rTimes = [];
  for (let k = 0; k < rounds; k++) {
    if (k % 2 === 0) tTimes.push(batch(triangle, tCalls)), rTimes.push(batch(ruppert, rCalls));
    else rTimes.push(batch(ruppert, rCalls)), tTimes.push(batch(triangle, tCalls));
  }
  return { triangleMs: median(tTimes), ruppertMs: median(rTimes), triangleTris: t.triangles, ruppertTris: r.triangles,
    triangleCalls: tCalls, ruppertCalls: rCalls };
}

// ---------------------------------------------------------------------------------------------
// Main thread: inputs, the worker's lifecycle, the report.
// ---------------------------------------------------------------------------------------------
function parseArgs(argv) {
  const values = (name) => argv.flatMap((a, i) => (a === name && i + 1 < argv.length ? [argv[i + 1]] : []));
  const one = (name, fallback) => values(name).at(-1) ?? fallback;
  return {
    dirs: values('--dir'), corpus: !argv.includes('--no-corpus'), families: !argv.includes('--no-families'),
    angle: Number(one('--angle', 30)), batchMs: Number(one('--batch-ms', 40)), rounds: Number(one('--rounds', 5)),
    only: one('--only', ''), json: one('--json', null), placement: one('--placement', null), timeoutMs: Number(one('--timeout', 60)) * 1000,
    warmupMs: Number(one('--warmup-ms', 3000)), cpuTime: argv.includes('--cpu-time'),
  };
}

function triangleWasmDir() {
  try {
    const manifest = process.env.TRIANGLE_WASM_DIR
      ? join(process.env.TRIANGLE_WASM_DIR, 'package.json') : require.resolve('triangle-wasm/package.json');
    return { dir: join(manifest, '..'), version: JSON.parse(readFileSync(manifest, 'utf8')).version };
  } catch {
    return null;
  }
}

// [{ name, family, plc }] from the corpus, the --dir folders and the generated families.
async function collectInputs(options) {
  const { init } = await import(new URL('../../wasm/index.js', import.meta.url));
  const reader = await init();
  const inputs = [];
  const fromDir = (dir, familyOf) => {
    for (const file of readdirSync(dir).filter((f) => f.endsWith('.poly')).sort()) {
      const plc = reader.parsePoly(readFileSync(join(dir, file), 'utf8'), file);
      inputs.push({ name: file.replace(/\.poly$/, ''), family: familyOf(file), plc });
    }
  };
  const corpus = process.env.RUPPERT_SHARED_DATA ?? join(repoRoot, '../shared/data');
  if (options.corpus && existsSync(corpus)) fromDir(corpus, () => 'corpus');
  else if (options.corpus) console.error(`speed-per-call: no corpus at ${corpus} (set RUPPERT_SHARED_DATA)`);
  for (const dir of options.dirs) fromDir(dir, (file) => basename(file, '.poly').replace(/-\d+$/, ''));
  if (options.families) inputs.push(...generatedFamilies());
  return inputs.filter((input) => input.name.includes(options.only));
}

class MeshWorker {
  // warmup: { warmup: [plc...], ms, angle, placement }, run after every start (null: none).
  constructor(triangleDir, warmup) { this.triangleDir = triangleDir; this.warmup = warmup; this.worker = null; }

  async start() {
    this.worker = new Worker(fileURLToPath(import.meta.url), { workerData: { triangleWasmDir: this.triangleDir } });
    await new Promise((resolve, reject) => {
      this.worker.once('message', resolve);
      this.worker.once('error', reject);
    });
    if (this.warmup) {
      const worker = this.worker;
      const reply = await new Promise((resolve) => {
        worker.once('message', resolve);
        worker.postMessage(this.warmup);
      });
      if (reply.status !== 'ok') throw new Error(`speed-per-call: the warm-up failed: ${reply.error}`);
    }
  }

  // The worker's reply, or { status: 'timeout' | 'error' } after which it is replaced.
  async run(job, timeoutMs) {
    if (this.worker === null) await this.start();
    const worker = this.worker;
    const reply = await new Promise((resolve) => {
      const timer = setTimeout(() => resolve({ status: 'timeout' }), timeoutMs);
      const done = (message) => { clearTimeout(timer); resolve(message); };
      worker.once('message', done);
      worker.once('error', (error) => done({ status: 'error', error: String(error?.message ?? error) }));
      worker.once('exit', (code) => done({ status: 'error', error: `worker exited with code ${code}` }));
      worker.postMessage(job);
    });
    worker.removeAllListeners('message'), worker.removeAllListeners('error'), worker.removeAllListeners('exit');
    if (reply.status !== 'ok') await this.stop();
    return reply;
  }

  async stop() { if (this.worker) await this.worker.terminate(); this.worker = null; }
}

const geoMean = (values) => Math.exp(values.reduce((s, v) => s + Math.log(v), 0) / values.length);
const us = (ms) => (ms * 1000).toFixed(ms < 0.1 ? 1 : 0);

function report(rows, failed, options, meta) {
  console.log(`\n# ruppert vs triangle-wasm ${meta.triangleWasm}, per call, one thread (${meta.node}); min angle ${options.angle}; placement ${options.placement ?? 'default'}; warm-up ${options.warmupMs} ms`);
  console.log(`command: node tests/bench/speed-per-call.mjs ${process.argv.slice(2).join(' ')}`.trim(), '\n');
  console.log('| family | input | in pts | Triangle tris | ruppert tris | Triangle us | ruppert us | speedup |');
  console.log('|---|---|---|---|---|---|---|---|');
  for (const r of rows) {
    console.log(`| ${r.family} | ${r.name} | ${r.inputPoints} | ${r.triangleTris} | ${r.ruppertTris} | ${us(r.triangleMs)} | ${us(r.ruppertMs)} | ${r.speedup.toFixed(2)} |`);
  }
  const families = [...new Set(rows.map((r) => r.family))];
  console.log('\n| family | inputs | geo-mean speedup | worst | worst input |\n|---|---|---|---|---|');
  const summary = families.map((family) => {
    const mine = rows.filter((r) => r.family === family);
    const worst = mine.reduce((a, b) => (b.speedup < a.speedup ? b : a));
    return { family, inputs: mine.length, geoMean: geoMean(mine.map((r) => r.speedup)), worst: worst.speedup, worstInput: worst.name };
  });
  for (const s of summary) console.log(`| ${s.family} | ${s.inputs} | ${s.geoMean.toFixed(2)} | ${s.worst.toFixed(2)} | ${s.worstInput} |`);
  const overall = geoMean(rows.map((r) => r.speedup));
  console.log(`\ngeometric mean of the speedups over ${rows.length} inputs: ${overall.toFixed(2)}x` +
    `; lowest family: ${summary.reduce((a, b) => (b.geoMean < a.geoMean ? b : a)).family}`);
  if (failed.length) console.log(`left out (Triangle or ruppert failed):\n  ${failed.map((f) => `${f.name}: ${f.status} ${f.error ?? ''}`).join('\n  ')}`);
  return { meta, options, rows, failed, summary, geoMean: overall };
}

async function main() {
  const options = parseArgs(process.argv.slice(2));
  const triangle = triangleWasmDir();
  if (!triangle) {
    console.log('speed-per-call: triangle-wasm is not installed (npm install --no-save triangle-wasm, or set TRIANGLE_WASM_DIR). Skipped.');
    return;
  }
  const inputs = await collectInputs(options);
  const warmInputs = inputs.filter(({ plc }) => plc.points.length / 2 <= 500).slice(0, 10).map(({ plc }) => plc);
  const warmup = options.warmupMs > 0 && warmInputs.length > 0
    ? { warmup: warmInputs, ms: options.warmupMs, angle: options.angle, placement: options.placement } : null;
  const worker = new MeshWorker(triangle.dir, warmup);
  const rows = [], failed = [];
  for (const { name, family, plc } of inputs) {
    const job = { plc, angle: options.angle, placement: options.placement, batchMs: options.batchMs, rounds: options.rounds,
      cpuTime: options.cpuTime };
    const r = await worker.run(job, options.timeoutMs);
    if (r.status !== 'ok' || r.triangleTris === 0) {
      failed.push({ name, status: r.status, error: r.error ?? (r.triangleTris === 0 ? 'Triangle returned no triangles' : '') });
      continue;
    }
    rows.push({ name, family, inputPoints: plc.points.length / 2, ...r, speedup: r.triangleMs / r.ruppertMs });
    process.stderr.write(`${name}: Triangle ${us(r.triangleMs)} us, ruppert ${us(r.ruppertMs)} us\n`);
  }
  await worker.stop();
  const meta = { node: `Node ${process.version}`, triangleWasm: triangle.version, date: new Date().toISOString() };
  const result = report(rows, failed, options, meta);
  if (options.json) writeFileSync(options.json, `${JSON.stringify(result, null, 1)}\n`);
}

if (isMainThread) await main();
else await worker();
