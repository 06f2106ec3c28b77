// The `ruppert` bin of the installed package (node_modules/.bin/ruppert -> wasm/cli.js): the native
// CLI's options, outputs and exit statuses (0 ok, 1 invalid input, 2 usage, 3 write failure).
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { after, test } from 'node:test';
import { fileURLToPath } from 'node:url';

const bin = fileURLToPath(new URL('./node_modules/.bin/ruppert', import.meta.url));
const dir = mkdtempSync(join(tmpdir(), 'ruppert-cli-'));
after(() => rmSync(dir, { recursive: true, force: true }));
const squarePoly = '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n';
writeFileSync(join(dir, 'in.poly'), squarePoly);

function cli(...args) {
  return spawnSync(bin, args, { cwd: dir, encoding: 'utf8' });
}

test('`ruppert --min-angle 30 -o out in.poly` writes out.node, out.ele and out.poly', () => {
  const run = cli('--min-angle', '30', '--max-area', '0.05', '-o', 'out', 'in.poly');
  assert.equal(run.status, 0, run.stderr);
  for (const ext of ['node', 'ele', 'poly']) assert.ok(existsSync(join(dir, `out.${ext}`)), `out.${ext}`);
  const [vertices] = readFileSync(join(dir, 'out.node'), 'utf8').trim().split(/\s+/).map(Number);
  const [triangles, corners] = readFileSync(join(dir, 'out.ele'), 'utf8').trim().split(/\s+/).map(Number);
  assert.equal(corners, 3);
  assert.ok(triangles >= 20, `${triangles} triangles for max area 0.05 on a unit square`);
  assert.match(run.stdout, new RegExp(`^ruppert: ${vertices} vertices, ${triangles} triangles, min angle \\d+\\.\\d\\d, .*complete`));
});

test('--format json / svg, --stats, --trace, --quiet; without -o only the summary', () => {
  const json = cli('--format', 'json', '-o', 'j', '--quiet', 'in.poly');
  assert.equal(json.status, 0, json.stderr);
  assert.equal(json.stdout, '');
  assert.ok(Array.isArray(JSON.parse(readFileSync(join(dir, 'j.json'), 'utf8')).points));
  assert.equal(cli('--format=svg', '-o', 's', 'in.poly').status, 0);
  assert.match(readFileSync(join(dir, 's.svg'), 'utf8'), /<svg/);

  const traced = cli('--max-area', '0.01', '--stats', '--trace', 't.jsonl', 'in.poly');
  assert.equal(traced.status, 0, traced.stderr);
  assert.match(traced.stdout, /angle histogram/);
  assert.ok(!existsSync(join(dir, 'in.1.node')), 'files written without -o');
  const lines = readFileSync(join(dir, 't.jsonl'), 'utf8').trim().split('\n').map((l) => JSON.parse(l));
  const [, vertices] = traced.stdout.match(/^ruppert: (\d+) vertices/);
  assert.ok(lines.length >= Number(vertices) - 4, 'a trace line per inserted vertex');
  assert.ok(lines.every((e) => typeof e.kind === 'string' && Number.isFinite(e.x)));
});

test('exit statuses: 1 invalid input, 2 usage, 3 unwritable output', () => {
  const missing = cli('missing.poly');
  assert.equal(missing.status, 1);
  assert.match(missing.stderr, /^error: cannot read 'missing\.poly'/);
  writeFileSync(join(dir, 'bad.poly'), '4 2 0 0\n1 0 0\n');
  const bad = cli('bad.poly');
  assert.equal(bad.status, 1);
  assert.match(bad.stderr, /^error: .*bad\.poly/);
  const angle = cli('--min-angle', '75', 'in.poly');
  assert.equal(angle.status, 2);
  assert.match(angle.stderr, /--min-angle/);
  assert.match(angle.stderr, /^usage: ruppert/m);
  assert.equal(cli('--no-such-flag', 'in.poly').status, 2);
  assert.equal(cli().status, 2);
  assert.equal(cli('--min-angle', 'abc', 'in.poly').status, 2);
  assert.equal(cli('-o', join(dir, 'no-such-dir', 'x'), 'in.poly').status, 3);
  const help = cli('--help');
  assert.equal(help.status, 0);
  assert.match(help.stdout, /--min-angle DEG/);
  assert.match(cli('--version').stdout, /^ruppert \d+\.\d+\.\d+\n$/);
});

// The progress line needs a terminal: script(1) gives the CLI one (and the test says so when it is
// missing). A run of several seconds (about 5 million triangles) draws it; with standard error a
// pipe, the same run draws nothing.
const haveScript = spawnSync('script', ['--version'], { encoding: 'utf8' }).status === 0;
test('a progress line on a terminal for runs over a second, none otherwise', { skip: !haveScript && 'script(1) not found' }, () => {
  const typescript = join(dir, 'typescript');
  const command = `'${bin}' --max-area 3e-7 in.poly`;
  const run = spawnSync('script', ['-qec', command, typescript], { cwd: dir, encoding: 'utf8' });
  assert.equal(run.status, 0, run.stderr);
  const seen = readFileSync(typescript, 'utf8');
  assert.match(seen, /\rruppert: \d+ vertices inserted, \d+ triangles, worst angle [\d.]+ deg, [\d.]+ s\x1b\[K/);
  assert.match(seen, /\r\x1b\[K/, 'cleared at the end');
  const plain = cli('--max-area', '3e-7', 'in.poly');
  assert.equal(plain.status, 0, plain.stderr);
  assert.doesNotMatch(plain.stderr, /vertices inserted/);
});
