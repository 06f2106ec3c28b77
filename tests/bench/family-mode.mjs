// Family mode of compare-triangle.mjs (--dir DIR): ruppert against Triangle over the generated shape
// families (build-native/tests/write_shape_families DIR writes DIR/<family>-<seed>.poly), per family
// and per placement, with the measures its targets name:
//   * at the compared angles (default 20, 25, 30, 33): ruppert / Triangle triangle counts, geometric
//     means per family and over all PLCs, the worst family;
//   * at the ruppert-only angles (default 35, 38, 40): the share of PLCs where ruppert is complete AND
//     every non-exempt triangle holds the bound (judged from the output arrays: mesh-exemptions.mjs),
//     the wall time per PLC (limit --ruppert-timeout, default 30 s), and for every miss its smallest
//     non-exempt angle and its triangle count over the same PLC's 33-degree mesh (same placement).
// Triangle's results are cached per PLC and angle in DIR/triangle-cache.json (keyed by the file's
// text and the triangle-wasm version), so a re-run meshes with ruppert only; --no-triangle-cache
// ignores and rewrites the cache.
import { readFileSync, readdirSync, writeFileSync, existsSync, mkdirSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { summarisePlacement, familyMarkdown } from './family-report.mjs';

export function parseFamilyArgs(argv) {
  const get = (name, fallback) => {
    const i = argv.indexOf(name);
    return i >= 0 && i + 1 < argv.length ? argv[i + 1] : fallback;
  };
  const numbers = (text) => text.split(',').filter(Boolean).map(Number);
  const names = (text) => text.split(',').filter(Boolean);
  // Placements are written one file each, so choosing some is still a full run of those.
  const partial = ['--families', '--only', '--angles', '--ruppert-only-angles'].some((f) => argv.includes(f));
  return {
    dir: resolve(get('--dir', '')),
    families: names(get('--families', '')),
    only: get('--only', ''),
    placements: names(get('--placements', 'default,offcenter,circumcenter,petal')),
    angles: numbers(get('--angles', '20,25,30,33')),
    highAngles: numbers(get('--ruppert-only-angles', '35,38,40')),
    runs: Number(get('--runs', 0)),
    jobs: Math.max(1, Number(get('--jobs', 2))),  // PLCs meshed side by side, each lane with its own workers  // 0: one timed run, no warm-up (counts are deterministic)
    triangleTimeoutMs: Number(get('--timeout', 10)) * 1000,
    ruppertTimeoutMs: Number(get('--ruppert-timeout', 30)) * 1000,
    triangleCache: !argv.includes('--no-triangle-cache'),
    // A partial run (any filter) prints only, unless --write: the committed results are full runs.
    write: argv.includes('--write') || (!partial && !argv.includes('--no-write')),
  };
}

// FNV-1a over the text: enough to notice that a family file changed since it was cached.
function textHash(text) {
  let h = 0x811c9dc5;
  for (let i = 0; i < text.length; i++) h = Math.imul(h ^ text.charCodeAt(i), 0x01000193) >>> 0;
  return h.toString(16);
}

function loadFamilies(options) {
  const files = readdirSync(options.dir).filter((f) => /^[a-z0-9-]+-\d+\.poly$/.test(f) && f.includes(options.only));
  const plcs = [];
  for (const file of files) {
    const [, family, seed] = /^(.*)-(\d+)\.poly$/.exec(file);
    if (options.families.length && !options.families.includes(family)) continue;
    const text = readFileSync(join(options.dir, file), 'utf8');
    plcs.push({ name: file.replace(/\.poly$/, ''), family, seed: Number(seed), text, hash: textHash(text) });
  }
  return plcs.sort((a, b) => a.family.localeCompare(b.family) || a.seed - b.seed);
}

class TriangleCache {
  constructor(dir, version, enabled) {
    this.file = join(dir, 'triangle-cache.json');
    this.version = version;
    this.entries = {};
    this.dirty = false;
    if (enabled && existsSync(this.file)) {
      const saved = JSON.parse(readFileSync(this.file, 'utf8'));
      if (saved.triangleWasm === version) this.entries = saved.entries;
    }
  }

  get(plc, angle) {
    const e = this.entries[`${plc.name}@${angle}`];
    return e && e.hash === plc.hash ? e.result : null;
  }

  set(plc, angle, result) {
    const { status, error, triangles, minAngle, ms } = result;
    this.entries[`${plc.name}@${angle}`] = { hash: plc.hash, result: { status, error, triangles, minAngle, ms } };
    this.dirty = true;
  }

  save() {
    if (this.dirty) writeFileSync(this.file, `${JSON.stringify({ triangleWasm: this.version, entries: this.entries })}\n`);
  }
}

// The fields of a ruppert result the report needs (the worker's result has more).
function ruppertFields(r) {
  if (r.status !== 'ok') return { status: r.status, error: r.error };
  return {
    status: 'ok', triangles: r.triangles, complete: r.complete, minAngle: r.minAngle,
    nonExemptMin: r.nonExemptMin, exempt: r.exempt, reasons: r.reasons, ms: r.ms, inverted: r.inverted,
  };
}

// One PLC: Triangle at the compared angles (from the cache when it has them), ruppert at every angle
// and placement.
async function meshOne(item, lane, context) {
  const { options, reader, cache, log } = context;
  const { triangle, ruppert } = lane;
  {
    const plc = reader.parsePoly(item.text, `${item.name}.poly`);
    const row = { name: item.name, family: item.family, seed: item.seed, inputPoints: plc.points.length / 2, triangle: {}, ruppert: {} };
    for (const angle of options.angles) {
      let t = cache.get(item, angle);
      if (!t) {
        t = await triangle.run({ plc, switches: `pzQq${angle}`, runs: options.runs }, options.triangleTimeoutMs);
        cache.set(item, angle, t);
      }
      row.triangle[angle] = t;
    }
    for (const placement of options.placements) {
      const byAngle = {};
      for (const angle of [...options.angles, ...options.highAngles]) {
        const meshOptions = placement === 'default' ? { minAngle: angle } : { minAngle: angle, placement };
        const r = await ruppert.run({ plc, options: meshOptions, runs: options.runs, judge: true }, options.ruppertTimeoutMs);
        byAngle[angle] = ruppertFields(r);
      }
      row.ruppert[placement] = byAngle;
    }
    const at = (a) => row.ruppert[options.placements[0]][a];
    log(`${item.name}: ${options.angles.map((a) => `${a}° ${row.triangle[a].triangles ?? row.triangle[a].status}/${at(a).triangles ?? at(a).status}`).join('  ')}`);
    return row;
  }
}

// Every PLC, in options.jobs lanes that take the next PLC when they are free; rows in input order.
async function meshAll(plcs, context) {
  const rows = new Array(plcs.length);
  let next = 0;
  const lanes = Array.from({ length: Math.min(context.options.jobs, plcs.length) }, () => ({
    triangle: new context.Engine('triangle', context.triangleWasmDir), ruppert: new context.Engine('ruppert'),
  }));
  try {
    await Promise.all(lanes.map(async (lane) => {
      while (next < plcs.length) {
        const i = next++;
        rows[i] = await meshOne(plcs[i], lane, context);
      }
    }));
  } finally {
    for (const lane of lanes) {
      await lane.triangle.stop();
      await lane.ruppert.stop();
    }
  }
  return rows;
}

// context: { Engine, triangleWasmDir, triangleWasmVersion, reader, repoRoot, meta, log }
export async function runFamilies(argv, context) {
  const options = parseFamilyArgs(argv);
  if (!existsSync(options.dir)) throw new Error(`--dir ${options.dir} does not exist (write it with build-native/tests/write_shape_families DIR)`);
  const plcs = loadFamilies(options);
  if (plcs.length === 0) throw new Error(`no <family>-<seed>.poly files in ${options.dir} match the filters`);
  const cache = new TriangleCache(options.dir, context.triangleWasmVersion, options.triangleCache);
  const started = performance.now();
  let rows;
  try {
    rows = await meshAll(plcs, { ...context, options, cache });
  } finally {
    cache.save();
  }
  const minutes = (performance.now() - started) / 60000;
  const meta = { ...context.meta, dir: options.dir, plcs: plcs.length, families: [...new Set(plcs.map((p) => p.family))].length, minutes };
  for (const placement of options.placements) {
    const summary = summarisePlacement(rows, placement, options);
    const report = { meta: { ...meta, placement }, options, summary, rows: rows.map((r) => ({ ...r, ruppert: r.ruppert[placement] })) };
    const markdown = familyMarkdown(report);
    console.log(markdown.split('\n## Misses')[0]);
    if (options.write) {
      const dir = join(context.repoRoot, 'tests/bench/results');
      mkdirSync(dir, { recursive: true });
      writeFileSync(join(dir, `families-${placement}.md`), markdown);
      // The per-family miss lists repeat the overall ones (and the rows): left out of the JSON.
      const families = summary.families.map((f) => ({ ...f, high: Object.fromEntries(Object.entries(f.high).map(([a, h]) => [a, { ...h, misses: undefined }])) }));
      writeFileSync(join(dir, `families-${placement}.json`), `${JSON.stringify({ ...report, summary: { ...summary, families } })}\n`);
      context.log(`wrote tests/bench/results/families-${placement}.md and .json`);
    }
  }
}
