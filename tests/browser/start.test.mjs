// `npm start` builds wasm/dist again when a C++ source is newer than it (web/wasm-freshness.mjs):
// checked on a scratch tree whose files' times are set by hand, no build run.
import assert from 'node:assert/strict';
import { mkdirSync, mkdtempSync, readFileSync, rmSync, utimesSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { test } from 'node:test';
import { WASM_OUTPUTS, wasmStaleReason } from '../../web/wasm-freshness.mjs';

function touch(root, file, seconds) {
  const path = join(root, file);
  mkdirSync(dirname(path), { recursive: true });
  writeFileSync(path, '');
  utimesSync(path, seconds, seconds);
}

test('wasm/dist is stale when missing or older than a source, fresh otherwise', () => {
  const root = mkdtempSync(join(tmpdir(), 'ruppert-fresh-'));
  try {
    touch(root, 'core/src/refine/refine.cpp', 1000);
    touch(root, 'wasm/binding/bindings.cpp', 1000);
    assert.match(wasmStaleReason(root), /wasm\/dist\/ruppert\.wasm is missing/);
    for (const output of WASM_OUTPUTS) touch(root, output, 2000);
    assert.equal(wasmStaleReason(root), null);
    touch(root, 'core/src/refine/refine.cpp', 3000);  // the C++ changed after the build
    assert.equal(wasmStaleReason(root), 'core/src/refine/refine.cpp is newer than wasm/dist/ruppert.wasm');
    for (const output of WASM_OUTPUTS) touch(root, output, 4000);
    touch(root, 'wasm/binding/bindings.cpp', 5000);
    assert.match(wasmStaleReason(root), /^wasm\/binding\/bindings\.cpp is newer/);
  } finally {
    rmSync(root, { recursive: true, force: true });
  }
});

test('npm start goes through the freshness check', () => {
  const scripts = JSON.parse(readFileSync(new URL('../../package.json', import.meta.url), 'utf8')).scripts;
  assert.equal(scripts.start, 'node web/start.mjs');
  assert.match(readFileSync(new URL('../../web/start.mjs', import.meta.url), 'utf8'), /wasmStaleReason\(root\)/);
});
