// The maxAngle option over the generated shape families, through the native CLI: per family, how
// often `--min-angle A --max-angle B` gives a mesh that is valid, complete and within both bounds
// outside the chapter's exemptions (§6.6, judged from the output by mesh-exemptions.mjs), the worst
// largest angle among those exempt from nothing, and the triangle count over `--min-angle A` alone
// (geometric mean and largest ratio per family, over the PLCs where both runs complete).
//
//   build-native/tests/write_shape_families /tmp/families
//   node tests/bench/max-angle.mjs --dir /tmp/families [--min-angle 30] [--max-angle 100]
//        [--cli build-native/core/ruppert] [--jobs 2] [--timeout 60] [--out FILE.md]
//
// Each run is one CLI process writing JSON to a pipe (no file); the time column is that process's
// wall time, for orientation only (two jobs share the machine).
import { execFile } from 'node:child_process';
import { readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { nonExemptMinAngle } from './mesh-exemptions.mjs';
import { validateMesh } from '../package/validate-mesh.mjs';

const argv = process.argv.slice(2);
const get = (name, fallback) => {
  const i = argv.indexOf(name);
  return i >= 0 && i + 1 < argv.length ? argv[i + 1] : fallback;
};
const options = {
  dir: resolve(get('--dir', '')),
  cli: resolve(get('--cli', 'build-native/core/ruppert')),
  minAngle: Number(get('--min-angle', 30)),
  maxAngle: Number(get('--max-angle', 100)),
  jobs: Math.max(1, Number(get('--jobs', 2))),
  timeoutMs: Number(get('--timeout', 60)) * 1000,
  out: get('--out', ''),
};
const TOLERANCE = 1e-6;  // degrees: the bounds are judged on doubles

// A Triangle .poly (points and segments only: the families have no holes or regions to judge).
function parsePoly(text) {
  const lines = text.split('\n').map((l) => l.replace(/#.*/, '').trim()).filter(Boolean).map((l) => l.split(/\s+/).map(Number));
  let at = 0;
  const [n] = lines[at++];
  const points = [];
  let base = 0;
  for (let i = 0; i < n; i++, at++) {
    if (i === 0) base = lines[at][0];
    points.push(lines[at][1], lines[at][2]);
  }
  const [m] = lines[at++];
  const segments = [];
  for (let i = 0; i < m; i++, at++) segments.push(lines[at][1] - base, lines[at][2] - base);
  return { points: Float64Array.from(points), segments: Uint32Array.from(segments) };
}

const snake = (kind) => kind.replace(/[A-Z]/g, (c) => `_${c}`).toUpperCase();

function meshOf(json) {
  return {
    points: Float64Array.from(json.points), triangles: Uint32Array.from(json.triangles),
    neighbors: Int32Array.from(json.neighbors), segments: Uint32Array.from(json.segments),
    segmentIds: Int32Array.from(json.segmentIds), vertexKinds: Uint8Array.from(json.vertexKinds),
    triangleAttributes: Float64Array.from(json.triangleAttributes),
    notices: json.notices.map((n) => ({ ...n, kind: snake(n.kind) })), complete: json.complete, reasons: json.reasons,
  };
}

function run(file, extra) {
  const args = ['--quiet', '--min-angle', String(options.minAngle), ...extra, '--format', 'json', '-o', '-', file];
  const start = process.hrtime.bigint();
  return new Promise((done) => {
    execFile(options.cli, args, { maxBuffer: 1 << 30, timeout: options.timeoutMs }, (error, stdout) => {
      const seconds = Number(process.hrtime.bigint() - start) / 1e9;
      if (error) return done({ failed: error.killed ? 'timeout' : String(error.message).split('\n')[0], seconds });
      done({ mesh: meshOf(JSON.parse(stdout)), seconds });
    });
  });
}

async function measure(item) {
  const plc = parsePoly(readFileSync(item.path, 'utf8'));
  const [base, bounded] = await Promise.all([run(item.path, []), run(item.path, ['--max-angle', String(options.maxAngle)])]);
  const r = { ...item, seconds: bounded.seconds, failed: bounded.failed ?? base.failed };
  if (r.failed) return r;
  const m = bounded.mesh;
  r.valid = validateMesh(m, { input: plc }).length === 0;
  r.complete = m.complete;
  r.reasons = m.reasons.map((x) => x.kind).join(',');
  const angles = nonExemptMinAngle(m, plc);
  r.worstLargest = angles.maxAngle, r.worstSmallest = angles.minAngle;
  r.held = r.valid && r.complete && angles.maxAngle <= options.maxAngle + TOLERANCE && angles.minAngle >= options.minAngle - TOLERANCE;
  r.baseComplete = base.mesh.complete;
  r.ratio = m.triangles.length / base.mesh.triangles.length;
  return r;
}

async function measureAll(items) {
  const results = new Array(items.length);
  let next = 0;
  const lane = async () => {
    while (next < items.length) {
      const k = next++;
      results[k] = await measure(items[k]);
    }
  };
  await Promise.all(Array.from({ length: options.jobs }, lane));
  return results;
}

const geomean = (xs) => (xs.length ? Math.exp(xs.reduce((s, x) => s + Math.log(x), 0) / xs.length) : NaN);
const fixed = (x, d) => (Number.isFinite(x) ? x.toFixed(d) : '-');

function row(name, rs) {
  const held = rs.filter((r) => r.held).length;
  const judged = rs.filter((r) => !r.failed && r.complete);
  const worst = judged.reduce((w, r) => Math.max(w, r.worstLargest), 0);
  const smallest = judged.reduce((w, r) => Math.min(w, r.worstSmallest), 180);
  const paired = rs.filter((r) => !r.failed && r.complete && r.baseComplete).map((r) => r.ratio);
  const seconds = rs.reduce((s, r) => Math.max(s, r.seconds), 0);
  return `| ${name} | ${rs.length} | ${held} (${fixed((100 * held) / rs.length, 1)}%) | ${fixed(worst, 3)} | ` +
    `${fixed(smallest, 3)} | ${fixed(geomean(paired), 3)} | ${fixed(Math.max(...paired), 3)} | ${fixed(seconds, 2)} |`;
}

const files = readdirSync(options.dir).filter((f) => /^[a-z0-9-]+-\d+\.poly$/.test(f)).sort();
if (files.length === 0) throw new Error(`no <family>-<seed>.poly files in ${options.dir}`);
const items = files.map((f) => ({ name: f.replace(/\.poly$/, ''), family: /^(.*)-\d+\.poly$/.exec(f)[1], path: join(options.dir, f) }));
const results = await measureAll(items);
const families = [...new Set(items.map((i) => i.family))];
const lines = [
  `--min-angle ${options.minAngle} --max-angle ${options.maxAngle} against --min-angle ${options.minAngle} alone, ${items.length} PLCs`,
  '',
  '| family | PLCs | valid, complete, bounds held | worst largest angle (complete, non-exempt) | worst smallest angle (same) | triangles / without maxAngle (geometric mean) | largest ratio | slowest run (s) |',
  '|---|---|---|---|---|---|---|---|',
  ...families.map((f) => row(f, results.filter((r) => r.family === f))),
  row('**all**', results),
];
const misses = results.filter((r) => !r.held);
if (misses.length) {
  lines.push('', 'Misses:', '');
  for (const r of misses) {
    lines.push(`- ${r.name}: ${r.failed ? `failed (${r.failed})` : `valid ${r.valid}, complete ${r.complete}` +
      `${r.reasons ? ` (${r.reasons})` : ''}, largest non-exempt angle ${fixed(r.worstLargest, 3)}, smallest ${fixed(r.worstSmallest, 3)}`}`);
  }
}
console.log(lines.join('\n'));
if (options.out) writeFileSync(options.out, `${lines.join('\n')}\n`);
