// The README's JavaScript and npm commands, run as written against the installed tarball (see
// run-installed.mjs, which says where the README is and which tarball it installed). The native
// commands are tests/readme/run-native-blocks.sh's.
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';

const readmePath = process.env.RUPPERT_README;
const skip = readmePath === undefined && 'RUPPERT_README is not set (run through run-installed.mjs)';
const app = dirname(fileURLToPath(import.meta.url));  // the folder the tarball is installed in

// Fenced blocks in order: { lang, code }.
function blocks() {
  const text = readFileSync(readmePath, 'utf8');
  return [...text.matchAll(/^```(\w*)\n([\s\S]*?)^```$/gm)].map(([, lang, code]) => ({ lang, code }));
}

// The command lines of the sh blocks (comments dropped).
function shellLines() {
  return blocks().filter((b) => b.lang === 'sh')
    .flatMap((b) => b.code.split('\n')).map((l) => l.replace(/\s*#.*$/, '')).filter((l) => l.trim() !== '');
}

test('every JavaScript block of the README runs against the installed package', { skip }, () => {
  const js = blocks().filter((b) => b.lang === 'js');
  assert.ok(js.length >= 2, `expected the quick start and the worker example, found ${js.length} blocks`);
  js.forEach(({ code }, i) => {
    const file = join(app, `readme-example-${i + 1}.mjs`);
    writeFileSync(file, code);
    const run = spawnSync(process.execPath, [file], { cwd: app, encoding: 'utf8', timeout: 120000 });
    assert.equal(run.status, 0, `block ${i + 1}:\n${code}\n${run.stderr}`);
    // Each example ends by printing the triangle count and the mesh's `complete`, which must be true.
    const last = run.stdout.trim().split('\n').at(-1);
    assert.match(last, /^\d+ .*\btrue$/, `block ${i + 1} printed:\n${run.stdout}`);
  });
});

test("the README's npm pack and install lines name the tarball run-installed.mjs packed", { skip }, () => {
  const lines = shellLines();
  assert.ok(lines.includes('npm pack'), lines.join('\n'));
  const install = lines.find((l) => /^npm install \S+\.tgz$/.test(l));
  assert.ok(install, `no 'npm install ....tgz' line in:\n${lines.join('\n')}`);
  assert.equal(install.split('/').at(-1), process.env.RUPPERT_TARBALL);
  assert.match(readFileSync(readmePath, 'utf8'), /Once published, `npm install ruppert`/);
});

test("every npx line of the README runs on the shipped examples", { skip }, () => {
  const npx = shellLines().filter((l) => l.startsWith('npx ruppert '));
  assert.ok(npx.length >= 1, 'no npx ruppert line in the README');
  // The examples must come with the package (no link to the clone's docs/): a package user has
  // only node_modules/ruppert.
  assert.ok(existsSync(join(app, 'node_modules/ruppert/docs/examples/lake.poly')), 'docs/examples ships in the tarball');
  for (const line of npx) {
    const run = spawnSync('bash', ['-euo', 'pipefail', '-c', line], { cwd: app, encoding: 'utf8', timeout: 120000 });
    assert.equal(run.status, 0, `${line}\n${run.stderr}`);
    assert.match(run.stdout, /^ruppert: \d+ vertices, \d+ triangles/, `${line} printed:\n${run.stdout}`);
  }
  assert.ok(existsSync(join(app, 'lake.ele')), 'the npx example writes lake.ele');
});
