#!/usr/bin/env node
// Triangle counts under an area bound, ruppert's native CLI against Triangle's, on the generated
// shape families: max area = bounding box / 3000 (so the bound decides most of the mesh).
//
//   build-native/tests/write_shape_families /tmp/families
//   TRIANGLE_BIN=/path/to/triangle node tests/bench/area-bound.mjs --dir /tmp/families [--angles 30,33]
//        [--divisor 3000] [--cli build-native/core/ruppert]
//
// Triangle runs as `triangle -pzQq<angle>a<area> in.poly` (the area in fixed notation: Triangle's
// switch parser reads no exponent), ruppert as `ruppert in.poly --min-angle A --max-area area`.
// Printed per angle: the geometric mean of ruppert / Triangle triangles per family and over all,
// and how many ruppert runs did not complete.
import { execFileSync, spawnSync } from 'node:child_process';
import { copyFileSync, mkdtempSync, readFileSync, readdirSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const args = process.argv.slice(2);
const option = (name, fallback) => (args.includes(name) ? args[args.indexOf(name) + 1] : fallback);
const dir = option('--dir');
const triangle = process.env.TRIANGLE_BIN;
if (!dir || !triangle) {
  console.error('usage: TRIANGLE_BIN=... node tests/bench/area-bound.mjs --dir DIR [--angles 30,33] [--divisor 3000]');
  process.exit(2);
}
const angles = option('--angles', '30,33').split(',');
const divisor = Number(option('--divisor', '3000'));
const cli = option('--cli', new URL('../../build-native/core/ruppert', import.meta.url).pathname);
const work = mkdtempSync(join(tmpdir(), 'area-bound-'));

function boundingBoxArea(text) {
  const rows = text.split('\n').map((l) => l.split('#')[0].trim()).filter(Boolean).map((l) => l.split(/\s+/));
  const n = Number(rows[0][0]);
  const xs = rows.slice(1, 1 + n).map((r) => Number(r[1])), ys = rows.slice(1, 1 + n).map((r) => Number(r[2]));
  return (Math.max(...xs) - Math.min(...xs)) * (Math.max(...ys) - Math.min(...ys));
}

function triangleCount(file, angle, area) {
  copyFileSync(file, join(work, 'in.poly'));
  const run = spawnSync(triangle, [`-pzQq${angle}a${area.toFixed(20)}`, join(work, 'in.poly')], { timeout: 60000 });
  if (run.status !== 0) return null;
  return Number(readFileSync(join(work, 'in.1.ele'), 'utf8').trim().split(/\s+/)[0]);
}

function ruppertCount(file, angle, area) {
  const out = execFileSync(cli, [file, '--min-angle', angle, '--max-area', String(area), '-o', join(work, 'r')], {
    encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'],
  });
  const m = /(\d+) triangles.*\b(complete|incomplete)\b/.exec(out);
  return m ? { triangles: Number(m[1]), complete: m[2] === 'complete' } : null;
}

const files = readdirSync(dir).filter((f) => f.endsWith('.poly')).sort();
const geo = (xs) => Math.exp(xs.reduce((s, x) => s + Math.log(x), 0) / xs.length);
for (const angle of angles) {
  const byFamily = new Map();
  let incomplete = 0;
  for (const f of files) {
    const path = join(dir, f);
    const area = boundingBoxArea(readFileSync(path, 'utf8')) / divisor;
    const t = triangleCount(path, angle, area);
    const r = ruppertCount(path, angle, area);
    if (!r || !r.complete) ++incomplete;
    if (!t || !r) continue;
    const family = f.replace(/-\d+\.poly$/, '');
    if (!byFamily.has(family)) byFamily.set(family, []);
    byFamily.get(family).push(r.triangles / t);
  }
  const all = [...byFamily.values()].flat();
  console.log(`${angle} degrees: ${all.length} PLCs, ruppert / Triangle triangles ${geo(all).toFixed(3)} (geometric mean), ${incomplete} incomplete`);
  console.log('  ' + [...byFamily].map(([k, v]) => `${k} ${geo(v).toFixed(3)}`).join(', '));
}
rmSync(work, { recursive: true, force: true });
