#!/usr/bin/env node
// Benchmark of the WebAssembly build: input families x sizes, one warm-up, median of several runs.
//   node tests/bench/bench-wasm.mjs [--runs N] [--json]
// Last, 10^5 random points given once and each given twice (copies after the originals), at 0 and
// 30 degrees, the two alternating: median times, the ratio twice / once, and whether the meshes
// have the same triangles (compared by corner coordinates).
// Needs wasm/dist (npm run build:wasm). Uses ../shared/data fixtures when present (says so if not).
import { existsSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { init } from '../../wasm/index.js';

const args = process.argv.slice(2);
const runs = Number(args[args.indexOf('--runs') + 1]) || 5;
const asJson = args.includes('--json');
const dataDir = process.env.RUPPERT_SHARED_DATA ?? fileURLToPath(new URL('../../../shared/data', import.meta.url));

const square = { points: [0, 0, 1, 0, 1, 1, 0, 1], segments: [0, 1, 1, 2, 2, 3, 3, 0] };

// Deterministic pseudo-random points (Marsaglia's xorshift32 in 32-bit integer arithmetic):
// the same distinct points every run.
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

const cases = [];
for (const maxArea of [1e-3, 1e-4, 1e-5]) {
  cases.push({ family: 'square, quality 30', size: `maxArea ${maxArea}`, plc: square, options: { minAngle: 30, maxArea } });
}
for (const n of [10000, 100000, 1000000]) {
  cases.push({ family: 'random points, CDT', size: `${n} points`, plc: scattered(n), options: { minAngle: 0 } });
}
const fixtures = ['cdt_guitar.poly', 'earcut_water_huge.poly', 'greenland_boundary.poly'];
const haveData = existsSync(dataDir);
if (!haveData) console.error(`# ${dataDir} not found: fixture cases skipped`);

const mesher = await init();
if (haveData) {
  for (const name of fixtures) {
    const path = `${dataDir}/${name}`;
    if (!existsSync(path)) continue;
    const plc = mesher.parsePoly(readFileSync(path, 'utf8'), name);
    cases.push({ family: name, size: 'quality 30', plc, options: { minAngle: 30 } });
    cases.push({ family: name, size: 'quality 30, placement circumcenter', plc, options: { minAngle: 30, placement: 'circumcenter' } });
  }
}

const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];
const rows = [];
for (const c of cases) {
  mesher.triangulate(c.plc, c.options);  // warm-up: compilation tiers, heap growth
  const wall = [];
  const core = [];
  let mesh;
  for (let i = 0; i < runs; i++) {
    const t0 = performance.now();
    mesh = mesher.triangulate(c.plc, c.options);
    wall.push(performance.now() - t0);
    core.push(mesh.stats.milliseconds);
  }
  const triangles = mesh.triangles.length / 3;
  const ms = median(wall);
  rows.push({
    family: c.family, size: c.size, triangles, complete: mesh.complete, minAngle: +mesh.stats.minAngle.toFixed(2),
    wallMs: +ms.toFixed(1), coreMs: +median(core).toFixed(1), trianglesPerSecond: Math.round(triangles / (ms / 1000)),
  });
}

// Steiner vertices are numbered after the input points: triangles are compared by their corners.
function sameTriangles(a, b) {
  if (a.triangles.length !== b.triangles.length) return false;
  for (let i = 0; i < a.triangles.length; i++) {
    const u = a.triangles[i], v = b.triangles[i];
    if (a.points[2 * u] !== b.points[2 * v] || a.points[2 * u + 1] !== b.points[2 * v + 1]) return false;
  }
  return true;
}

const duplicates = [];
{
  const once = scattered(100000);
  const twice = { points: new Float64Array(2 * once.points.length) };
  twice.points.set(once.points);
  twice.points.set(once.points, once.points.length);
  for (const minAngle of [0, 30]) {
    const time = (plc) => {
      const t0 = performance.now();
      const mesh = mesher.triangulate(plc, { minAngle });
      return { ms: performance.now() - t0, mesh };
    };
    time(once), time(twice);  // warm-up
    const onceMs = [], twiceMs = [];
    let a, b;
    for (let i = 0; i < runs; i++) {
      ({ ms: onceMs[i], mesh: a } = time(once));
      ({ ms: twiceMs[i], mesh: b } = time(twice));
    }
    duplicates.push({
      minAngle, triangles: a.triangles.length / 3, onceMs: +median(onceMs).toFixed(1), twiceMs: +median(twiceMs).toFixed(1),
      ratio: +(median(twiceMs) / median(onceMs)).toFixed(2), notices: b.notices.length, sameTriangles: sameTriangles(a, b),
    });
  }
}

if (asJson) {
  console.log(JSON.stringify({ node: process.version, runs, rows, duplicates }, null, 2));
} else {
  console.log(`node ${process.version}, median of ${runs} runs after one warm-up`);
  console.table(rows);
  console.log('10^5 random points given once and each given twice (alternating runs):');
  console.table(duplicates);
}
