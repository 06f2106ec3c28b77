#!/usr/bin/env node
// Side-by-side measurement of ruppert against Shewchuk's Triangle, both as WebAssembly in Node.
//
//   npm install --no-save triangle-wasm          # the Triangle build this compares against
//   (or install it anywhere and set TRIANGLE_WASM_DIR to its package folder: a later plain
//   `npm install` in the repo prunes a --no-save package, even in the middle of a run)
//   node tests/bench/compare-triangle.mjs [--runs N] [--timeout SECONDS] [--only SUBSTRING]
//        [--angles 20,30,33] [--ruppert-only-angles 35,38,40] [--sizes 1e-4,...] [--no-native] [--no-write]
//        [--placement optimal|offcenter|circumcenter|petal]   (ruppert's Steiner placement; default optimal)
//   node tests/bench/compare-triangle.mjs --dir DIR [--families a,b] [--placements default,petal]
//        [--angles 20,25,30,33] [--ruppert-only-angles 35,38,40] [--ruppert-timeout 30] [--timeout 10]
//        [--only SUBSTRING] [--no-triangle-cache] [--write | --no-write]
//   (family mode, see family-mode.mjs: the shape families written by
//   `build-native/tests/write_shape_families DIR`, per family and placement; placement "default" is
//   the library's own default. Writes tests/bench/results/families-<placement>.{md,json} on a full
//   run, or a partial one (any filter) with --write. A quick re-measure of ruppert only, with
//   Triangle's counts from DIR/triangle-cache.json:
//   node tests/bench/compare-triangle.mjs --dir /tmp/families --placements default --angles 30,33)
//
// For every clean .poly in the shared data folder and every angle it meshes the same PLC with
// Triangle (switches -pzQq<angle>, plus -a when a region carries an area bound) and with ruppert
// (triangulate with minAngle, the default placement), then a unit square with a global area bound for
// the size-driven case. Both meshers run in worker threads of this one Node process, each call
// timed end to end (input copied in, output copied out) as the median of N runs after one warm-up
// (a call over 1 s: its first run alone); a run slower than the time limit stops that case
// ("timeout": Triangle may loop forever above ~34 deg).
// Triangle's own failures (out of its fixed 16 MiB heap, exit() on bad input) end its worker only.
// Quality is judged from the output arrays by one function for both meshers (measureMesh below).
// The native CLI (build-native/core/ruppert, or RUPPERT_CLI) is timed on the same inputs; its time
// is the core time it prints with --stats.
// Writes tests/bench/results/triangle-comparison.{md,json} unless --no-write (with --placement P
// other than offcenter: triangle-comparison-P.{md,json}).
import { execFileSync, spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readFileSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { Worker, isMainThread, parentPort } from 'node:worker_threads';
import { runFamilies } from './family-mode.mjs';
import { nonExemptMinAngle } from './mesh-exemptions.mjs';

const require = createRequire(import.meta.url);
const repoRoot = fileURLToPath(new URL('../../', import.meta.url));

// ---------------------------------------------------------------------------------------------
// Mesh measures shared by both meshers: computed from points + triangle corners only, so neither
// mesher's own statistics are trusted for the comparison.
// ---------------------------------------------------------------------------------------------
function measureMesh(points, triangles) {
  let minAngle = 180;
  let maxAngle = 0;
  let area = 0;
  let inverted = 0;  // triangles that are clockwise or degenerate: a broken mesh
  const used = new Uint8Array(points.length / 2);
  for (let t = 0; t < triangles.length; t += 3) {
    const a = triangles[t];
    const b = triangles[t + 1];
    const c = triangles[t + 2];
    used[a] = used[b] = used[c] = 1;
    const ax = points[2 * a], ay = points[2 * a + 1];
    const bx = points[2 * b], by = points[2 * b + 1];
    const cx = points[2 * c], cy = points[2 * c + 1];
    const cross = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    if (!(cross > 0)) inverted++;
    area += cross / 2;
    // The angle at a corner from atan2(|cross|, dot) is accurate for angles near 0 and 180,
    // where acos of a normalized dot product loses digits.
    const corners = [[ax, ay, bx, by, cx, cy], [bx, by, cx, cy, ax, ay], [cx, cy, ax, ay, bx, by]];
    for (const [px, py, qx, qy, rx, ry] of corners) {
      const ux = qx - px, uy = qy - py, vx = rx - px, vy = ry - py;
      const angle = (Math.atan2(Math.abs(ux * vy - uy * vx), ux * vx + uy * vy) * 180) / Math.PI;
      if (angle < minAngle) minAngle = angle;
      if (angle > maxAngle) maxAngle = angle;
    }
  }
  let vertices = 0;
  for (const u of used) vertices += u;
  return { triangles: triangles.length / 3, vertices, minAngle, maxAngle, area, inverted };
}

const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];

// ---------------------------------------------------------------------------------------------
// Worker side: one engine per worker, jobs arrive one at a time. After every run the worker posts
// a tick, so the main thread can hold each single run to the time limit.
// ---------------------------------------------------------------------------------------------
async function runWorker() {
  const { engine, triangleWasmDir } = (await import('node:worker_threads')).workerData;
  let mesh;  // (plc, job) => { points, triangles, extra }
  if (engine === 'triangle') {
    const Triangle = require(triangleWasmDir);
    // Its Emscripten loader predates Node's global fetch: with fetch present it tries to fetch
    // the .wasm by file path and aborts. Without it, it reads the file with fs. This worker needs
    // no fetch, so it is removed here for good.
    delete globalThis.fetch;
    await Triangle.init();
    mesh = (plc, job) => {
      const regionlist = [];
      for (const r of plc.regions) regionlist.push(r.x, r.y, r.attribute, r.maxArea);
      const input = Triangle.makeIO({
        pointlist: plc.points, segmentlist: plc.segments, holelist: plc.holes, regionlist,
      });
      const output = Triangle.makeIO();
      try {
        Triangle.triangulate(job.switches, input, output);
        // The getters are views into Triangle's heap: copy before freeing.
        return { points: Float64Array.from(output.pointlist), triangles: Int32Array.from(output.trianglelist) };
      } finally {
        // Triangle copies the hole and region pointers from input to output: free them once.
        Triangle.freeIO(input, true);
        Triangle.freeIO(output);
      }
    };
  } else {
    const { init } = await import(new URL('../../wasm/index.js', import.meta.url));
    const mesher = await init();
    mesh = (plc, job) => {
      const m = mesher.triangulate(plc, job.options);
      const extra = {
        complete: m.complete, reasons: m.reasons.map((r) => `${r.kind}:${r.count}`),
        notices: m.notices.length, statMinAngle: m.stats.minAngle, coreMs: m.stats.milliseconds,
      };
      // Family mode: the smallest angle over the triangles the chapter does not exempt.
      if (job.judge) ({ minAngle: extra.nonExemptMin, exempt: extra.exempt } = nonExemptMinAngle(m, plc));
      return { points: m.points, triangles: m.triangles, extra };
    };
  }
  parentPort.postMessage({ type: 'ready' });
  parentPort.on('message', (job) => {
    try {
      const times = [];
      const coreTimes = [];
      let out;
      for (let i = 0; i <= job.runs; i++) {  // run 0 is the warm-up
        const t0 = performance.now();
        out = mesh(job.plc, job);
        const ms = performance.now() - t0;
        if (i > 0 || job.runs === 0) {  // runs 0: the single first run is the time
          times.push(ms);
          if (out.extra) coreTimes.push(out.extra.coreMs);
        }
        parentPort.postMessage({ type: 'tick' });
        // A call slower than a second is neither warm-up- nor noise-bound: its first run is the time.
        if (i === 0 && ms > 1000 && job.runs > 0) {
          times.push(ms);
          if (out.extra) coreTimes.push(out.extra.coreMs);
          break;
        }
      }
      const result = { status: 'ok', ms: median(times), runs: times.length, ...measureMesh(out.points, out.triangles) };
      if (out.extra) Object.assign(result, out.extra, { coreMs: median(coreTimes) });
      parentPort.postMessage({ type: 'result', result });
    } catch (error) {
      // Triangle aborts with a RuntimeError ("OOM") when its fixed heap is full; its module is
      // unusable afterwards, so the main thread replaces this worker.
      parentPort.postMessage({ type: 'result', result: { status: 'error', error: String(error?.message ?? error).slice(0, 200) } });
    }
  });
}

// ---------------------------------------------------------------------------------------------
// Main side
// ---------------------------------------------------------------------------------------------
class Engine {
  constructor(name, triangleWasmDir) { this.name = name; this.triangleWasmDir = triangleWasmDir; this.worker = null; }

  async start() {
    const worker = new Worker(new URL(import.meta.url), { workerData: { engine: this.name, triangleWasmDir: this.triangleWasmDir } });
    await new Promise((resolve, reject) => {
      worker.once('message', resolve);
      worker.once('error', reject);
      worker.once('exit', (code) => reject(new Error(`worker exited with code ${code} while loading`)));
    });
    // Only these events: the Worker keeps its own listeners (newListener etc.) for delivery.
    for (const event of ['message', 'error', 'exit']) worker.removeAllListeners(event);
    this.worker = worker;
  }

  // Resolves with the worker's result, or { status: 'timeout' | 'exit' } after killing it.
  async run(job, timeLimitMs) {
    if (this.worker === null) {
      try {
        await this.start();
      } catch (error) {
        return { status: 'error', error: `could not start: ${String(error?.message ?? error).slice(0, 160)}` };
      }
    }
    const worker = this.worker;
    return new Promise((resolve) => {
      let timer;
      const finish = (result, broken) => {
        clearTimeout(timer);
        worker.removeAllListeners('message');
        worker.removeAllListeners('exit');
        worker.removeAllListeners('error');
        if (broken) {
          worker.terminate();
          this.worker = null;
        }
        resolve(result);
      };
      const arm = () => {
        clearTimeout(timer);
        timer = setTimeout(() => finish({ status: 'timeout', error: `a run exceeded ${timeLimitMs / 1000} s` }, true), timeLimitMs);
      };
      worker.on('message', (message) => {
        if (message.type === 'tick') arm();
        else if (message.type === 'result') finish(message.result, message.result.status !== 'ok');
      });
      // Triangle calls exit() on input it rejects; in a worker that ends the thread only.
      worker.on('exit', (code) => finish({ status: 'error', error: `worker exited with code ${code}` }, true));
      worker.on('error', (error) => finish({ status: 'error', error: String(error?.message ?? error).slice(0, 200) }, true));
      arm();
      worker.postMessage(job);
    });
  }

  async stop() { if (this.worker) await this.worker.terminate(); this.worker = null; }
}

function parseArgs(argv) {
  const get = (name, fallback) => {
    const i = argv.indexOf(name);
    return i >= 0 && i + 1 < argv.length ? argv[i + 1] : fallback;
  };
  const list = (text) => text.split(',').filter(Boolean).map(Number);
  return {
    runs: Number(get('--runs', 5)),
    timeoutMs: Number(get('--timeout', 10)) * 1000,
    only: get('--only', ''),
    angles: list(get('--angles', '20,30,33')),
    ruppertOnlyAngles: list(get('--ruppert-only-angles', '35,38,40')),
    // Global area bounds on the unit square: Triangle and ruppert near 1e4, 1e5, 1e6 triangles.
    sizes: list(get('--sizes', '1.5e-4,1.5e-5,1.5e-6,5e-7')),
    sizeAngle: Number(get('--size-angle', 30)),
    placement: get('--placement', 'optimal'),
    native: !argv.includes('--no-native'),
    write: !argv.includes('--no-write'),
  };
}

function nativeCli() {
  const candidates = [process.env.RUPPERT_CLI, join(repoRoot, 'build-native/core/ruppert')].filter(Boolean);
  return candidates.find((path) => existsSync(path)) ?? null;
}

// The native CLI on a file: median of the core times it prints (after one warm-up call).
function runNative(cli, file, args, runs, timeoutMs) {
  const times = [];
  let triangles = null;
  for (let i = 0; i <= runs; i++) {
    const r = spawnSync(cli, [...args, '--quiet', '--stats', file], { encoding: 'utf8', timeout: timeoutMs });
    if (r.error?.code === 'ETIMEDOUT' || r.signal) return { status: 'timeout' };
    if (r.status !== 0) return { status: 'error', error: (r.stderr || r.stdout).trim().slice(0, 200) };
    const count = /^triangles: (\d+)/m.exec(r.stdout);
    const time = /^time: ([\d.]+) ms/m.exec(r.stdout);
    if (!count || !time) return { status: 'error', error: 'unexpected --stats output' };
    triangles = Number(count[1]);
    // As in the worker: a call slower than a second is timed once, without a warm-up.
    if (i > 0 || Number(time[1]) > 1000) times.push(Number(time[1]));
    if (i === 0 && Number(time[1]) > 1000) break;
  }
  return { status: 'ok', triangles, ms: median(times) };
}

const fmt = (x, digits = 2) => (x === null || x === undefined || Number.isNaN(x) ? '–' : x.toFixed(digits));
const fmtMs = (x) => (x === null || x === undefined ? '–' : x < 10 ? x.toFixed(2) : x < 100 ? x.toFixed(1) : x.toFixed(0));
const geoMean = (values) => (values.length ? Math.exp(values.reduce((s, v) => s + Math.log(v), 0) / values.length) : null);
const triangleCell = (t) => (t.status === 'ok' ? String(t.triangles) : t.status);

function gitDescription() {
  try {
    const head = execFileSync('git', ['rev-parse', '--short', 'HEAD'], { cwd: repoRoot, encoding: 'utf8' }).trim();
    const dirty = execFileSync('git', ['status', '--porcelain', '--', 'core', 'wasm'], { cwd: repoRoot, encoding: 'utf8' }).trim();
    return dirty ? `${head} + uncommitted changes in core/ or wasm/` : head;
  } catch {
    return 'unknown';
  }
}

// What deserves a look by the core developer; each entry names the input and the numbers.
function leadsFor(row) {
  const leads = [];
  const { name, angle, triangle: t, ruppert: r } = row;
  const tag = `${name} @ ${angle}°`;
  if (r.status !== 'ok') {
    leads.push(`${tag}: ruppert ${r.status} (${r.error})`);
    return leads;
  }
  if (r.inverted > 0) leads.push(`${tag}: ruppert output has ${r.inverted} clockwise or degenerate triangles`);
  if (Math.abs(r.statMinAngle - r.minAngle) > 1e-6) {
    leads.push(`${tag}: ruppert stats.minAngle ${r.statMinAngle} differs from the measured ${r.minAngle.toFixed(6)}`);
  }
  if (r.complete && r.minAngle < angle - 1e-9 && !r.reasons.some((x) => /SMALL_INPUT_ANGLE|SEDITIOUS_EDGE/.test(x))) {
    leads.push(`${tag}: ruppert complete but min angle ${r.minAngle.toFixed(3)} < ${angle} with no exemption`);
  }
  // Triangle returns no triangles when a hole seed eats an unenclosed domain (box.poly); ruppert
  // meshes the convex hull and says so. Different rules, not a count to compare.
  if (t?.status === 'ok' && t.triangles === 0) {
    leads.push(`${tag}: Triangle returns no triangles (its hole eats the unclosed domain); ruppert ${r.triangles}, not compared`);
  } else if (t?.status === 'ok') {
    const scale = Math.max(Math.abs(t.area), 1e-300);
    if (Math.abs(r.area - t.area) / scale > 1e-9) {
      leads.push(`${tag}: meshed area differs: ruppert ${r.area.toPrecision(12)} vs Triangle ${t.area.toPrecision(12)}`);
    }
    const ratio = r.triangles / t.triangles;
    if (ratio > 1.5) leads.push(`${tag}: ruppert makes ${ratio.toFixed(2)}x Triangle's triangles (${r.triangles} vs ${t.triangles})`);
    if (!r.complete) leads.push(`${tag}: ruppert incomplete (${r.reasons.join(', ')}) where Triangle finished (min ∠ ${t.minAngle.toFixed(2)})`);
    if (r.minAngle < angle - 1e-6 && r.minAngle + 1 < t.minAngle) {
      leads.push(`${tag}: ruppert min angle ${r.minAngle.toFixed(2)} well below Triangle's ${t.minAngle.toFixed(2)}`);
    }
    if (r.ms > 3 * t.ms && t.ms > 1) leads.push(`${tag}: ruppert ${(r.ms / t.ms).toFixed(1)}x slower (${fmtMs(r.ms)} vs ${fmtMs(t.ms)} ms)`);
  }
  return leads;
}

function markdownReport(report) {
  const lines = [];
  const { meta, fixtureRows, sizeRows, summary, leads } = report;
  lines.push('# ruppert vs Triangle (triangle-wasm), side by side', '');
  lines.push(`Written by \`tests/bench/compare-triangle.mjs\` on ${meta.date}. ${meta.node}, ${meta.cpu}.`);
  lines.push(`ruppert ${meta.ruppert} (wasm/dist + native CLI \`${meta.nativeCli ?? 'absent'}\`); Triangle: npm triangle-wasm ${meta.triangleWasm} (Triangle 1.6 compiled by Emscripten, fixed 16 MiB heap).`);
  lines.push(`Command: \`${meta.command}\``, '');
  lines.push('How: the same PLC (read by ruppert\'s .poly reader) goes to both meshers in worker threads of one Node process.',
    `Triangle runs with \`-pzQq<angle>\` (plus \`-a\` when a region has an area bound); ruppert with \`{ minAngle, placement: '${meta.placement ?? 'optimal'}' }\` (constrained variant).`,
    `Times are per call, end to end (copy in, mesh, copy out), median of ${meta.runs} after one warm-up (a call over 1 s: its single first run); a single run longer than ${meta.timeoutMs / 1000} s is "timeout".`,
    'Min angles and triangle counts are measured from the output arrays by the same code for both. "native" is the core time printed by the ruppert CLI (`--stats`), measured at the angles compared with Triangle only.',
    'Ratios: tri ratio = ruppert triangles / Triangle triangles (< 1: ruppert smaller); speed = Triangle ms / ruppert wasm ms (> 1: ruppert faster).', '');

  lines.push('## Summary', '');
  lines.push('| min angle | inputs | Triangle finished | ruppert complete | geo-mean tri ratio | geo-mean speed (all) | geo-mean speed (Triangle ≥ 1 ms) | total ms Triangle / ruppert wasm / native |');
  lines.push('|---|---|---|---|---|---|---|---|');
  for (const s of summary) {
    lines.push(`| ${s.angle} | ${s.inputs} | ${s.triangleFinished ?? '–'} | ${s.ruppertComplete} | ${fmt(s.geoMeanTriRatio, 3)} | ${fmt(s.geoMeanSpeed, 2)} | ${fmt(s.geoMeanSpeedSlow, 2)} | ${fmtMs(s.totalTriangleMs)} / ${fmtMs(s.totalRuppertMs)} / ${fmtMs(s.totalNativeMs)} |`);
  }
  lines.push('', 'Tri ratio and speed are over the inputs where both meshers returned a non-empty mesh. "Triangle finished" means it returned within the time limit; it has no notion of completeness.', '');

  lines.push(`## Size-driven: unit square, min angle ${meta.sizeAngle}, global max area`, '');
  lines.push('| max area | Triangle tris | ruppert tris | tri ratio | Triangle ms | ruppert wasm ms | native ms | speed | Triangle min ∠ | ruppert min ∠ | ruppert complete |');
  lines.push('|---|---|---|---|---|---|---|---|---|---|---|');
  for (const row of sizeRows) {
    const t = row.triangle;
    const r = row.ruppert;
    const both = t.status === 'ok' && r.status === 'ok';
    lines.push(`| ${row.maxArea} | ${t.status === 'ok' ? t.triangles : `${t.status}${t.error ? ` (${t.error})` : ''}`} | ${triangleCell(r)} | ${both ? fmt(r.triangles / t.triangles, 3) : '–'} | ${t.status === 'ok' ? fmtMs(t.ms) : '–'} | ${r.status === 'ok' ? fmtMs(r.ms) : '–'} | ${row.native?.status === 'ok' ? fmtMs(row.native.ms) : row.native?.status ?? '–'} | ${both ? fmt(t.ms / r.ms) : '–'} | ${t.status === 'ok' ? fmt(t.minAngle) : '–'} | ${r.status === 'ok' ? fmt(r.minAngle) : '–'} | ${r.status === 'ok' ? r.complete : '–'} |`);
  }
  lines.push('');

  const angles = [...new Set(fixtureRows.map((row) => row.angle))];
  for (const angle of angles) {
    const rows = fixtureRows.filter((row) => row.angle === angle);
    const withTriangle = rows.some((row) => row.triangle);
    lines.push(`## Min angle ${angle}°${withTriangle ? '' : ' (ruppert only)'}`, '');
    if (withTriangle) {
      lines.push('| input | in pts | Triangle tris | ruppert tris | tri ratio | Triangle min ∠ | ruppert min ∠ | ruppert complete | Triangle ms | ruppert ms | native ms | speed |');
      lines.push('|---|---|---|---|---|---|---|---|---|---|---|---|');
    } else {
      lines.push('| input | in pts | ruppert tris | ruppert min ∠ | complete | reasons | ruppert ms | native ms |');
      lines.push('|---|---|---|---|---|---|---|---|');
    }
    for (const row of rows) {
      const t = row.triangle;
      const r = row.ruppert;
      const rOk = r.status === 'ok';
      const nat = row.native?.status === 'ok' ? fmtMs(row.native.ms) : row.native?.status ?? '–';
      if (withTriangle) {
        const both = t.status === 'ok' && t.triangles > 0 && rOk;
        lines.push(`| ${row.name} | ${row.inputPoints} | ${triangleCell(t)} | ${triangleCell(r)} | ${both ? fmt(r.triangles / t.triangles, 3) : '–'} | ${t.status === 'ok' ? fmt(t.minAngle) : '–'} | ${rOk ? fmt(r.minAngle) : '–'} | ${rOk ? (r.complete ? 'yes' : `**no** (${r.reasons.join(', ')})`) : '–'} | ${t.status === 'ok' ? fmtMs(t.ms) : '–'} | ${rOk ? fmtMs(r.ms) : '–'} | ${nat} | ${both ? fmt(t.ms / r.ms) : '–'} |`);
      } else {
        lines.push(`| ${row.name} | ${row.inputPoints} | ${triangleCell(r)} | ${rOk ? fmt(r.minAngle) : '–'} | ${rOk ? (r.complete ? 'yes' : '**no**') : '–'} | ${rOk ? r.reasons.join(', ') : r.error} | ${rOk ? fmtMs(r.ms) : '–'} | ${nat} |`);
      }
    }
    lines.push('');
  }

  lines.push('## Leads for the core developer', '');
  lines.push('Automatic flags: ruppert failing, inverted triangles, stats.minAngle disagreeing with the measured one, a meshed area',
    'different from Triangle\'s, > 1.5x Triangle\'s triangle count, incomplete where Triangle finished, a min angle under the',
    'bound and > 1° below Triangle\'s, or > 3x slower on a case where Triangle needs > 1 ms.', '');
  if (leads.length === 0) lines.push('None.');
  for (const lead of leads) lines.push(`- ${lead}`);
  lines.push('');
  return lines.join('\n');
}

function summarise(fixtureRows, angles) {
  const summary = [];
  for (const angle of angles) {
    const rows = fixtureRows.filter((row) => row.angle === angle);
    if (rows.length === 0) continue;
    const hasTriangle = rows.some((row) => row.triangle);
    const both = rows.filter((row) => row.triangle?.status === 'ok' && row.triangle.triangles > 0 && row.ruppert.status === 'ok');
    const sum = (values) => values.reduce((s, v) => s + v, 0);
    const native = rows.filter((row) => row.native?.status === 'ok');
    summary.push({
      angle,
      inputs: rows.length,
      triangleFinished: hasTriangle ? `${rows.filter((row) => row.triangle?.status === 'ok').length}/${rows.length}` : null,
      ruppertComplete: `${rows.filter((row) => row.ruppert.status === 'ok' && row.ruppert.complete).length}/${rows.length}`,
      geoMeanTriRatio: geoMean(both.map((row) => row.ruppert.triangles / row.triangle.triangles)),
      geoMeanSpeed: geoMean(both.map((row) => row.triangle.ms / row.ruppert.ms)),
      geoMeanSpeedSlow: geoMean(both.filter((row) => row.triangle.ms >= 1).map((row) => row.triangle.ms / row.ruppert.ms)),
      totalTriangleMs: hasTriangle ? sum(both.map((row) => row.triangle.ms)) : null,
      totalRuppertMs: sum((hasTriangle ? both : rows.filter((row) => row.ruppert.status === 'ok')).map((row) => row.ruppert.ms)),
      totalNativeMs: native.length === rows.length ? sum((hasTriangle ? both : rows).map((row) => row.native.ms)) : null,
    });
  }
  return summary;
}

// --from-json FILE: rebuild summary, leads and Markdown from a saved JSON report, without meshing.
function rerender(file) {
  const report = JSON.parse(readFileSync(file, 'utf8'));
  const angles = [...new Set(report.fixtureRows.map((row) => row.angle))];
  report.summary = summarise(report.fixtureRows, angles);
  report.leads = [...report.fixtureRows.flatMap(leadsFor), ...report.leads.filter((lead) => lead.startsWith('square'))];
  writeFileSync(file, `${JSON.stringify(report, null, 1)}\n`);
  writeFileSync(file.replace(/\.json$/, '.md'), markdownReport(report));
  console.log(`rewrote ${file} and its .md`);
}

async function main() {
  const fromJson = process.argv.indexOf('--from-json');
  if (fromJson >= 0) return rerender(process.argv[fromJson + 1]);
  const options = parseArgs(process.argv.slice(2));
  let triangleWasmVersion;
  let triangleWasmDir;
  try {
    const manifest = process.env.TRIANGLE_WASM_DIR
      ? join(process.env.TRIANGLE_WASM_DIR, 'package.json') : require.resolve('triangle-wasm/package.json');
    triangleWasmVersion = JSON.parse(readFileSync(manifest, 'utf8')).version;
    triangleWasmDir = join(manifest, '..');
  } catch {
    console.log('compare-triangle: the npm package triangle-wasm is not installed, so there is nothing to compare against.\n' +
      '  Install it without touching package.json:  npm install --no-save triangle-wasm\n' +
      '  (or install it elsewhere and set TRIANGLE_WASM_DIR=<that>/node_modules/triangle-wasm). Skipped.');
    return;
  }
  if (!existsSync(join(repoRoot, 'wasm/dist/ruppert.wasm'))) {
    console.error('compare-triangle: wasm/dist/ruppert.wasm is missing; build it first: node wasm/build-wasm.mjs');
    process.exitCode = 1;
    return;
  }
  if (process.argv.includes('--dir')) {
    const { init } = await import(new URL('../../wasm/index.js', import.meta.url));
    const cpus = (await import('node:os')).cpus();
    const meta = {
      date: new Date().toISOString().slice(0, 10), node: `Node ${process.version}`,
      cpu: `${cpus.length} x ${cpus[0]?.model ?? 'unknown CPU'}`, ruppert: gitDescription(), triangleWasm: triangleWasmVersion,
      command: `node tests/bench/compare-triangle.mjs ${process.argv.slice(2).join(' ')}`.trim(),
    };
    const log = (text) => process.stderr.write(`${text}\n`);
    await runFamilies(process.argv.slice(2), {
      Engine, triangleWasmDir, triangleWasmVersion, reader: await init(), repoRoot, meta, log,
    });
    return;
  }
  const dataDir = process.env.RUPPERT_SHARED_DATA ?? join(repoRoot, '../shared/data');
  const haveData = existsSync(dataDir);
  if (!haveData) console.log(`compare-triangle: ${dataDir} not found: only the size-driven cases run`);
  const cli = options.native ? nativeCli() : null;
  if (options.native && !cli) console.log('compare-triangle: no native CLI (build-native/core/ruppert or RUPPERT_CLI): native column left empty');

  const { init } = await import(new URL('../../wasm/index.js', import.meta.url));
  const reader = await init();
  const triangle = new Engine('triangle', triangleWasmDir);
  const ruppert = new Engine('ruppert');
  const scratch = mkdtempSync(join(tmpdir(), 'compare-triangle-'));
  const log = (text) => process.stderr.write(`${text}\n`);

  const fixtureRows = [];
  const files = haveData
    ? readdirSync(dataDir).filter((f) => f.endsWith('.poly') && f.includes(options.only)).sort()
    : [];
  for (const name of files) {
    const path = join(dataDir, name);
    const plc = reader.parsePoly(readFileSync(path, 'utf8'), name);
    const areaSwitch = plc.regions.some((r) => r.maxArea > 0) ? 'a' : '';
    for (const angle of [...options.angles, ...options.ruppertOnlyAngles]) {
      const withTriangle = options.angles.includes(angle);
      const row = { name, angle, inputPoints: plc.points.length / 2 };
      if (withTriangle) {
        row.triangle = await triangle.run({ plc, switches: `pzQq${angle}${areaSwitch}`, runs: options.runs }, options.timeoutMs);
      }
      row.ruppert = await ruppert.run({ plc, options: { minAngle: angle, placement: options.placement }, runs: options.runs }, options.timeoutMs);
      if (cli && withTriangle) row.native = runNative(cli, path, ['--min-angle', String(angle), '--placement', options.placement], options.runs, options.timeoutMs);
      fixtureRows.push(row);
      log(`${name} @${angle}: Triangle ${row.triangle ? triangleCell(row.triangle) : '-'}  ruppert ${triangleCell(row.ruppert)}${row.ruppert.complete === false ? ' (incomplete)' : ''}`);
    }
  }

  const square = { points: [0, 0, 1, 0, 1, 1, 0, 1], segments: [0, 1, 1, 2, 2, 3, 3, 0], holes: [], regions: [] };
  const squareFile = join(scratch, 'unit-square.json');
  writeFileSync(squareFile, JSON.stringify({ points: square.points, segments: square.segments }));
  const sizeRows = [];
  let triangleDied = false;  // once Triangle's heap is too small, larger sizes are not attempted
  for (const maxArea of options.sizes) {
    const row = { maxArea };
    row.triangle = triangleDied
      ? { status: 'skipped', error: 'failed at a smaller size' }
      : await triangle.run({ plc: square, switches: `pzQq${options.sizeAngle}a${maxArea}`, runs: options.runs }, 60000);
    if (row.triangle.status === 'error') triangleDied = true;
    row.ruppert = await ruppert.run({ plc: square, options: { minAngle: options.sizeAngle, maxArea, placement: options.placement }, runs: options.runs }, 60000);
    if (cli) row.native = runNative(cli, squareFile, ['--min-angle', String(options.sizeAngle), '--max-area', String(maxArea), '--placement', options.placement], options.runs, 60000);
    sizeRows.push(row);
    log(`square maxArea ${maxArea}: Triangle ${triangleCell(row.triangle)}${row.triangle.error ? ` (${row.triangle.error})` : ''}  ruppert ${triangleCell(row.ruppert)}`);
  }
  await triangle.stop();
  await ruppert.stop();
  rmSync(scratch, { recursive: true, force: true });

  const leads = fixtureRows.flatMap(leadsFor);
  for (const row of sizeRows) {
    if (row.ruppert.status !== 'ok') leads.push(`square maxArea ${row.maxArea}: ruppert ${row.ruppert.status} (${row.ruppert.error})`);
    else if (row.ruppert.inverted > 0) leads.push(`square maxArea ${row.maxArea}: ${row.ruppert.inverted} inverted triangles`);
  }
  const cpus = (await import('node:os')).cpus();
  const report = {
    meta: {
      date: new Date().toISOString().slice(0, 10),
      node: `Node ${process.version}`,
      cpu: `${cpus.length} x ${cpus[0]?.model ?? 'unknown CPU'}`,
      ruppert: gitDescription(),
      triangleWasm: triangleWasmVersion,
      nativeCli: cli ? cli.replace(repoRoot, '') : null,
      command: `node tests/bench/compare-triangle.mjs ${process.argv.slice(2).join(' ')}`.trim(),
      runs: options.runs, timeoutMs: options.timeoutMs, sizeAngle: options.sizeAngle, placement: options.placement,
    },
    summary: summarise(fixtureRows, [...options.angles, ...options.ruppertOnlyAngles]),
    sizeRows, fixtureRows, leads,
  };
  const markdown = markdownReport(report);
  if (options.write) {
    const dir = join(repoRoot, 'tests/bench/results');
    mkdirSync(dir, { recursive: true });
    const base = options.placement === 'optimal' ? 'triangle-comparison' : `triangle-comparison-${options.placement}`;
    writeFileSync(join(dir, `${base}.md`), markdown);
    writeFileSync(join(dir, `${base}.json`), `${JSON.stringify(report, null, 1)}\n`);
    log(`wrote tests/bench/results/${base}.md and .json`);
  }
  console.log(markdown.split('\n## Size-driven')[0]);
  console.table(report.summary);
  if (leads.length) console.log(`leads:\n  ${leads.join('\n  ')}`);
}

if (isMainThread) await main();
else await runWorker();
