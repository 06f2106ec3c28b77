// Two builds of the package side by side, per call, in one Node process and one thread: for each
// .poly of --dir, batches of at least --batch-ms alternate between build A and build B for --rounds
// rounds (A first in odd rounds, B first in even ones); a build's time per call is the median over
// rounds of its batch time over its calls. Prints, per input, both times and B's speed relative to
// A (A's time over B's), then the geometric mean of that ratio. For a change to the core that keeps
// the meshes: the triangle counts of both builds are printed and must match.
//   node tests/bench/ab-per-call.mjs --a ROOT_A --b ROOT_B --dir DIR [--placement P] [--angle 30]
//        [--rounds 5] [--batch-ms 20] [--warmup-ms 3000] [--json FILE]
// ROOT_A and ROOT_B each hold wasm/index.js and a built wasm/dist (a repository root, or a copy of
// its wasm/ folder under some directory). Run it in both orders and combine the two means
// (sqrt(AB / BA)): the build loaded second ran about 3% slower when A and B were the same build
// (0.968 over 235 outlines).
import { readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const at = args.indexOf(`--${name}`);
  return at >= 0 ? args[at + 1] : fallback;
};
const rootA = option('a'), rootB = option('b'), dir = option('dir');
if (!rootA || !rootB || !dir) {
  console.error('usage: node tests/bench/ab-per-call.mjs --a ROOT_A --b ROOT_B --dir DIR [--placement P] [--angle 30] [--rounds 5] [--batch-ms 20] [--warmup-ms 3000] [--json FILE]');
  process.exit(2);
}
const angle = Number(option('angle', '30')), rounds = Number(option('rounds', '5'));
const batchMs = Number(option('batch-ms', '20')), warmupMs = Number(option('warmup-ms', '3000'));
const placement = option('placement');
const options = placement ? { minAngle: angle, placement } : { minAngle: angle };

const load = async (root) => (await import(pathToFileURL(join(resolve(root), 'wasm/index.js')).href)).init();
const meshers = [await load(rootA), await load(rootB)];
const inputs = readdirSync(dir).filter((f) => f.endsWith('.poly')).sort()
  .map((f) => ({ name: f.replace(/\.poly$/, ''), plc: meshers[0].parsePoly(readFileSync(join(dir, f), 'utf8'), f) }));

// Calls per batch: enough for batchMs at the build's speed measured once.
function batchOf(mesher, plc) {
  let calls = 0;
  const t0 = performance.now();
  while (performance.now() - t0 < batchMs) mesher.triangulate(plc, options), ++calls;
  return calls;
}
function timeBatch(mesher, plc, calls) {
  const t0 = performance.now();
  for (let k = 0; k < calls; ++k) mesher.triangulate(plc, options);
  return (performance.now() - t0) / calls;
}
const median = (values) => [...values].sort((x, y) => x - y)[Math.floor(values.length / 2)];

// V8 tiers WebAssembly up during the first seconds: run both on small inputs first.
const small = inputs.filter((i) => i.plc.points.length <= 1000).slice(0, 10);
for (const t0 = performance.now(); performance.now() - t0 < warmupMs;)
  for (const { plc } of small) for (const m of meshers) m.triangulate(plc, options);

const rows = [];
console.log(`# A: ${rootA}\n# B: ${rootB}\n# ${JSON.stringify(options)}, ${rounds} rounds of ${batchMs} ms batches\n`);
console.log('| input | triangles A / B | A us | B us | B speed / A |\n|---|---|---|---|---|');
for (const { name, plc } of inputs) {
  let counts;
  try {
    counts = meshers.map((m) => m.triangulate(plc, options).triangles.length / 3);
  } catch (error) {
    console.log(`| ${name} | ${error.message} | | | |`);
    continue;
  }
  const calls = meshers.map((m) => batchOf(m, plc));
  const times = [[], []];
  for (let r = 0; r < rounds; ++r)
    for (const k of r % 2 === 0 ? [0, 1] : [1, 0]) times[k].push(timeBatch(meshers[k], plc, calls[k]));
  const [a, b] = times.map((t) => median(t) * 1000);
  rows.push({ name, counts, a, b, ratio: a / b });
  console.log(`| ${name} | ${counts[0]} / ${counts[1]} | ${a.toPrecision(3)} | ${b.toPrecision(3)} | ${(a / b).toFixed(3)} |`);
}
const geo = Math.exp(rows.reduce((s, r) => s + Math.log(r.ratio), 0) / rows.length);
const differing = rows.filter((r) => r.counts[0] !== r.counts[1]).length;
console.log(`\nB's speed relative to A over ${rows.length} inputs (geometric mean): ${geo.toFixed(3)}; ` +
  `inputs with different triangle counts: ${differing}`);
const json = option('json');
if (json) writeFileSync(json, JSON.stringify({ options, rounds, batchMs, rows, geo }, null, 1));
