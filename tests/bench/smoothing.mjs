#!/usr/bin/env node
// Smoothing (Options::smooth) against the same meshes unsmoothed, through the native CLI, over the
// generated shape families, with the measures of the smoothing item's "Done when":
//   * mean smallest angle: per PLC the mean over triangles of each one's smallest angle; the table
//     gives the mean over PLCs, unsmoothed and smoothed, and its gain (done: >= 3 degrees);
//   * obtuse triangles (largest angle over 90), all PLCs of the family together, and how many fewer
//     (done: >= 30% fewer);
//   * grading: the share of PLCs whose 5th, 50th and 95th percentiles of triangle areas are each
//     within 25% of the unsmoothed mesh's (done: >= 90%);
//   * triangle count: the largest relative change (done: within 1%);
//   * the bound: PLCs where a smoothed mesh is incomplete or has a non-exempt triangle under the
//     angle (mesh-exemptions.mjs), which must be none; and the median time per PLC of both runs.
//
//   build-native/tests/write_shape_families /tmp/families
//   node tests/bench/smoothing.mjs --dir /tmp/families [--angle 30] [--smooth N] [--families a,b]
//        [--cli build-native/core/ruppert] [--out tests/bench/results/smoothing.md]
import { execFileSync } from 'node:child_process';
import { readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { cornerDegrees, nonExemptMinAngle } from './mesh-exemptions.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => (args.includes(name) ? args[args.indexOf(name) + 1] : fallback);
const dir = option('--dir');
if (!dir) {
  console.error('usage: node tests/bench/smoothing.mjs --dir DIR [--angle 30] [--smooth N] [--families a,b] [--out FILE]');
  process.exit(2);
}
const cli = option('--cli', 'build-native/core/ruppert');
const angle = option('--angle', '30');
const passes = option('--smooth');
const families = option('--families')?.split(',');
const out = option('--out');

// Points and segments of a .poly file (the families write 0-based indices, no attributes).
function readPoly(file) {
  const lines = readFileSync(file, 'utf8').split('\n').map((l) => l.replace(/#.*/, '').trim()).filter(Boolean);
  let at = 0;
  const [n] = lines[at++].split(/\s+/).map(Number);
  const points = [];
  for (let i = 0; i < n; i++) {
    const f = lines[at++].split(/\s+/).map(Number);
    points.push(f[1], f[2]);
  }
  const [m] = lines[at++].split(/\s+/).map(Number);
  const segments = [];
  for (let i = 0; i < m; i++) {
    const f = lines[at++].split(/\s+/).map(Number);
    segments.push(f[1], f[2]);
  }
  return { points, segments };
}

function mesh(file, smooth) {
  const flags = ['--quiet', '--min-angle', angle, '--format', 'json', '-o', '-', file];
  if (smooth) flags.push(...(passes === undefined ? ['--smooth'] : ['--smooth', passes]));
  const start = process.hrtime.bigint();
  const text = execFileSync(cli, flags, { maxBuffer: 1 << 30, timeout: 300000 });
  const ms = Number(process.hrtime.bigint() - start) / 1e6;
  return { ...JSON.parse(text), ms };
}

const percentile = (sorted, q) => sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))];

// Per mesh: triangle count, mean smallest angle, obtuse count, area percentiles.
function measures(m) {
  const { points: p, triangles: t } = m;
  let sumMin = 0;
  let obtuse = 0;
  const areas = [];
  for (let k = 0; k < t.length; k += 3) {
    const [a, b, c] = [t[k], t[k + 1], t[k + 2]];
    const corners = [[a, b, c], [b, c, a], [c, a, b]].map(([u, v, w]) =>
      cornerDegrees(p[2 * u], p[2 * u + 1], p[2 * v], p[2 * v + 1], p[2 * w], p[2 * w + 1]));
    sumMin += Math.min(...corners);
    if (Math.max(...corners) > 90) obtuse++;
    areas.push(Math.abs((p[2 * b] - p[2 * a]) * (p[2 * c + 1] - p[2 * a + 1]) - (p[2 * b + 1] - p[2 * a + 1]) * (p[2 * c] - p[2 * a])) / 2);
  }
  areas.sort((x, y) => x - y);
  return { triangles: t.length / 3, meanMin: sumMin / (t.length / 3), obtuse,
    areaPercentiles: [0.05, 0.5, 0.95].map((q) => percentile(areas, q)) };
}

function compare(file) {
  const plc = readPoly(file);
  const plain = mesh(file, false);
  const smooth = mesh(file, true);
  const a = measures(plain), b = measures(smooth);
  const within = a.areaPercentiles.every((x, i) => Math.abs(b.areaPercentiles[i] - x) <= 0.25 * x);
  const holds = smooth.complete && nonExemptMinAngle(smooth, plc).minAngle >= Number(angle) - 1e-7;
  return { plain: a, smooth: b, within, holds, plainMs: plain.ms, smoothMs: smooth.ms };
}

const median = (v) => [...v].sort((x, y) => x - y)[Math.floor(v.length / 2)];
const mean = (v) => v.reduce((s, x) => s + x, 0) / v.length;

function summary(name, rows) {
  const plainObtuse = rows.reduce((s, r) => s + r.plain.obtuse, 0);
  const smoothObtuse = rows.reduce((s, r) => s + r.smooth.obtuse, 0);
  const countChange = Math.max(...rows.map((r) => Math.abs(r.smooth.triangles / r.plain.triangles - 1)));
  return {
    name, plcs: rows.length,
    meanMinPlain: mean(rows.map((r) => r.plain.meanMin)), meanMinSmooth: mean(rows.map((r) => r.smooth.meanMin)),
    obtusePlain: plainObtuse, obtuseSmooth: smoothObtuse, obtuseFewer: 1 - smoothObtuse / plainObtuse,
    gradingKept: rows.filter((r) => r.within).length / rows.length, countChange,
    boundMisses: rows.filter((r) => !r.holds).length,
    msPlain: median(rows.map((r) => r.plainMs)), msSmooth: median(rows.map((r) => r.smoothMs)),
  };
}

const files = readdirSync(dir).filter((f) => f.endsWith('.poly')).sort();
const byFamily = new Map();
for (const f of files) {
  const family = f.replace(/-\d+\.poly$/, '');
  if (families && !families.includes(family)) continue;
  if (!byFamily.has(family)) byFamily.set(family, []);
  byFamily.get(family).push(compare(join(dir, f)));
}
const lines = [
  `Smoothing at --min-angle ${angle}, \`--smooth${passes === undefined ? '' : ` ${passes}`}\` against none (${cli})`,
  '',
  '| family | PLCs | mean min angle | smoothed | gain | obtuse | smoothed | fewer | areas kept | count change | bound misses | ms | ms smoothed |',
  '|---|---|---|---|---|---|---|---|---|---|---|---|---|',
];
const all = [];
const row = (s) => `| ${s.name} | ${s.plcs} | ${s.meanMinPlain.toFixed(2)} | ${s.meanMinSmooth.toFixed(2)} | ` +
  `${(s.meanMinSmooth - s.meanMinPlain).toFixed(2)} | ${s.obtusePlain} | ${s.obtuseSmooth} | ` +
  `${(100 * s.obtuseFewer).toFixed(1)}% | ${(100 * s.gradingKept).toFixed(0)}% | ${(100 * s.countChange).toFixed(2)}% | ` +
  `${s.boundMisses} | ${s.msPlain.toFixed(1)} | ${s.msSmooth.toFixed(1)} |`;
for (const [family, rows] of byFamily) {
  all.push(...rows);
  lines.push(row(summary(family, rows)));
}
lines.push(row(summary('all', all)));
const text = lines.join('\n') + '\n';
process.stdout.write(text);
if (out) writeFileSync(out, text);
