#!/usr/bin/env node
// `npm run test:browser`: the web page's tests in Debian's Chromium (see harness.mjs).
// Builds wasm/dist first when it is missing (the page imports the package's module), then runs
// every tests/browser/*.test.mjs with node:test, one file at a time (each starts a browser).
import { spawnSync } from 'node:child_process';
import { existsSync, readdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { CHROMIUM } from './harness.mjs';

const here = fileURLToPath(new URL('.', import.meta.url));
const root = fileURLToPath(new URL('../../', import.meta.url));

function run(command, args, env = process.env) {
  console.log(`$ ${command} ${args.join(' ')}`);
  const result = spawnSync(command, args, { stdio: 'inherit', cwd: root, env });
  if (result.error) throw result.error;
  return result.status ?? 1;
}

if (!existsSync(CHROMIUM)) {
  console.error(`test:browser: no Chromium at ${CHROMIUM}; install Debian's chromium (apt-get install -y chromium) ` +
    'or set CHROMIUM_PATH');
  process.exit(1);
}
if (!['ruppert', 'ruppert-formats', 'ruppert-cli'].every((name) => existsSync(`${root}wasm/dist/${name}.wasm`))) {
  const env = { ...process.env, NODE_PATH: [process.env.NODE_PATH, '/usr/share/nodejs'].filter(Boolean).join(':') };
  const status = run('node', ['wasm/build-wasm.mjs'], env);
  if (status !== 0) process.exit(status);
}
// `node tests/browser/run.mjs render steps`: only the files whose names contain one of the words.
const only = process.argv.slice(2);
const files = readdirSync(here).filter((f) => f.endsWith('.test.mjs'))
  .filter((f) => only.length === 0 || only.some((word) => f.includes(word))).sort().map((f) => `tests/browser/${f}`);
process.exit(run('node', ['--test', ...files]));
