#!/usr/bin/env node
// `npm run test:bundlers`: the package as users bundle it. `npm pack`, install the tarball and
// vite, webpack 5 and esbuild into one temporary app, build app/src/main.js with each (no bundler
// configuration beyond the entry; esbuild gets the .wasm copied beside the bundle, as docs/usage.md
// says), serve each output on 127.0.0.1 (and the sources through vite's development server) and
// run it in Debian's Chromium: a mesh on the main
// thread, the text formats module read and write there, a worker mesh with progress, a cancel and a
// request after it, and the three load failures (a missing mesher or formats .wasm, a missing worker
// script) named with their URL and HTTP status.
// Set RUPPERT_KEEP_TMP=1 to keep the folder for inspection.
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { cpSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { CHROMIUM } from '../browser/harness.mjs';
import { serveFolder, startViteDev } from './serve-folder.mjs';

// The versions measured in /work/shared/GUIDE.md; pinned so that CI does not change under us.
const BUNDLERS = ['vite@8.4.0', 'webpack@5.113.0', 'webpack-cli@7.3.1', 'esbuild@0.28.2'];

const here = fileURLToPath(new URL('.', import.meta.url));
const root = resolve(here, '../..');
const work = mkdtempSync(join(tmpdir(), 'ruppert-bundlers-'));
const app = join(work, 'app');

function run(command, args, cwd = app) {
  console.log(`$ ${command} ${args.join(' ')}`);
  const result = spawnSync(command, args, { stdio: 'inherit', cwd });
  if (result.error) throw result.error;
  if (result.status !== 0) {
    console.error(`test:bundlers: '${command} ${args.join(' ')}' failed (exit ${result.status}); files kept in ${work}`);
    process.exit(result.status || 1);
  }
}

const page = (script) => `<!doctype html>\n<meta charset="utf-8">\n<title>ruppert bundler check</title>\n${script}\n`;
const bin = (name) => join(app, 'node_modules/.bin', name);
const esbuildEntries = ['src/main.js', 'node_modules/ruppert/wasm/worker.js', '--bundle', '--platform=browser',
  '--entry-names=[name]'];

function copyWasmBeside(out) {
  for (const file of ['ruppert.wasm', 'ruppert-formats.wasm']) {
    cpSync(join(app, `node_modules/ruppert/wasm/dist/${file}`), join(app, out, file));
  }
}

// Each build: its command and the page that loads its output (vite writes its own from index.html).
const BUILDS = {
  vite: () => run(bin('vite'), ['build', '--outDir', 'out/vite', '--logLevel', 'warn']),
  webpack: () => {
    run(bin('webpack'), ['--mode', 'production', '--entry', './src/main.js', '--output-path', 'out/webpack']);
    writeFileSync(join(app, 'out/webpack/index.html'), page('<script src="main.js"></script>'));
  },
  'esbuild (esm)': () => {
    run(bin('esbuild'), [...esbuildEntries, '--format=esm', '--outdir=out/esbuild-esm', '--log-level=warning']);
    copyWasmBeside('out/esbuild-esm');
    writeFileSync(join(app, 'out/esbuild-esm/index.html'), page('<script type="module" src="main.js"></script>'));
  },
  'esbuild (iife, its default format)': () => {
    run(bin('esbuild'), [...esbuildEntries, '--outdir=out/esbuild-iife', '--log-level=error']);
    copyWasmBeside('out/esbuild-iife');
    writeFileSync(join(app, 'out/esbuild-iife/index.html'), page('<script src="main.js"></script>'));
  },
};
// vite's development server (`vite`), which serves the package through its dependency optimizer.
const VITE_DEV = 'vite (development server)';
const OUT = { vite: 'out/vite', webpack: 'out/webpack', 'esbuild (esm)': 'out/esbuild-esm',
  'esbuild (iife, its default format)': 'out/esbuild-iife' };

function setUpApp() {
  run('npm', ['pack', '--pack-destination', work], root);
  const tarball = readdirSync(work).find((f) => f.endsWith('.tgz'));
  cpSync(join(here, 'app'), app, { recursive: true });
  writeFileSync(join(app, 'package.json'), JSON.stringify({ name: 'ruppert-bundler-test', private: true, type: 'module' }));
  run('npm', ['install', '--no-audit', '--no-fund', '--no-package-lock', join(work, tarball), ...BUNDLERS]);
}

/** What a browser bundle must not contain: Node's modules (esbuild's check) in any import form. */
function assertNoNodeImports(out) {
  const files = readdirSync(join(app, out), { recursive: true }).filter((f) => /\.m?js$/.test(f));
  assert.ok(files.length > 0, `${out} holds no script`);
  for (const file of files) {
    const text = readFileSync(join(app, out, file), 'utf8');
    const found = text.match(/(?:from\s*|import\s*\(\s*|require\s*\(\s*)["'`]node:[\w/]+/);
    assert.equal(found, null, `${out}/${file} imports a Node module: ${found?.[0]}`);
  }
}

function checkResults(results, url, devServer) {
  assert.deepEqual(Object.keys(results.mainThread).sort(), ['complete', 'minAngle', 'triangles'],
    `main thread: ${JSON.stringify(results.mainThread)}`);
  assert.ok(results.mainThread.triangles > 100 && results.mainThread.complete && results.mainThread.minAngle >= 30);
  assert.deepEqual(results.formats, { nodeHeader: results.formats.nodeHeader, vtu: true, points: 8 }, `formats: ${JSON.stringify(results.formats)}`);
  assert.match(results.formats.nodeHeader ?? '', /^\d+ 2 0 1$/, `formats: ${JSON.stringify(results.formats)}`);
  const { worker } = results;
  assert.ok(worker.mesh?.triangles > 10000 && worker.mesh.complete, `worker mesh: ${JSON.stringify(worker)}`);
  assert.ok(worker.progressCalls >= 1, `worker progress calls: ${worker.progressCalls}`);
  assert.equal(worker.cancelled?.code, 'CANCELLED', `cancel: ${JSON.stringify(worker.cancelled)}`);
  assert.ok(worker.afterCancel.complete && worker.afterCancel.triangles > 10, 'a request after the cancel');
  const { wasm, formatsWasm, workerScript } = results.loadFailures;
  assert.equal(wasm.code, 'IO_ERROR', JSON.stringify(wasm));
  assert.equal(formatsWasm.code, 'IO_ERROR', JSON.stringify(formatsWasm));
  assert.equal(workerScript.code, 'IO_ERROR', JSON.stringify(workerScript));
  if (devServer) {
    // vite's development server answers an unknown path with its index.html (HTTP 200).
    assert.match(wasm.message, new RegExp(`${url}no-such-file\\.wasm: not a WebAssembly module .*served as text/html`));
    assert.match(formatsWasm.message, new RegExp(`${url}no-such-formats\\.wasm: not a WebAssembly module .*formats: false`));
    assert.match(workerScript.message, new RegExp(`${url}no-such-worker\\.js: it loads \\(HTTP 200, text/html\\)`));
  } else {
    assert.match(wasm.message, new RegExp(`${url}no-such-file\\.wasm: HTTP 404`));
    assert.match(formatsWasm.message, new RegExp(`${url}no-such-formats\\.wasm: HTTP 404.*formats: false`));
    assert.match(workerScript.message, new RegExp(`${url}no-such-worker\\.js: HTTP 404`));
  }
}

async function runInBrowser(browser, name) {
  const devServer = name === VITE_DEV;
  const server = devServer ? await startViteDev(bin('vite'), app) : await serveFolder(join(app, OUT[name]));
  const tab = await browser.newPage();
  const problems = [];
  tab.on('pageerror', (error) => problems.push(`pageerror: ${error.message}`));
  tab.on('response', (response) => {
    const deliberate = /no-such-(file\.wasm|formats\.wasm|worker\.js)$/.test(response.url());
    if (response.status() >= 400 && !deliberate) problems.push(`HTTP ${response.status()} for ${response.url()}`);
  });
  try {
    await tab.goto(server.url);
    await tab.waitForFunction(() => window.ruppertResults !== undefined, null, { timeout: 120_000 });
    const results = await tab.evaluate(() => window.ruppertResults);
    assert.deepEqual(problems, []);
    checkResults(results, server.url, devServer);
    console.log(`${name}: ok ${JSON.stringify(results.mainThread)}, worker ${results.worker.mesh.triangles} triangles, ` +
      `${results.worker.progressCalls} progress calls, cancel ${results.worker.cancelled.code}`);
    console.log(`  ${results.loadFailures.wasm.message}\n  ${results.loadFailures.workerScript.message}`);
  } finally {
    await tab.close();
    await server.close();
  }
}

setUpApp();
for (const [name, build] of Object.entries(BUILDS)) {
  build();
  assertNoNodeImports(OUT[name]);
}
const browser = await chromium.launch({ executablePath: CHROMIUM, args: ['--no-sandbox', '--disable-gpu'] });
let failed = false;
for (const name of [...Object.keys(BUILDS), VITE_DEV]) {
  try {
    await runInBrowser(browser, name);
  } catch (error) {
    failed = true;
    console.error(`${name}: FAILED\n${error.stack}`);
  }
}
await browser.close();
if (process.env.RUPPERT_KEEP_TMP || failed) console.log(`files in ${work}`);
else rmSync(work, { recursive: true, force: true });
process.exit(failed ? 1 : 0);
