#!/usr/bin/env node
// `npm start`: builds wasm/dist when it is missing or older than its C++ sources
// (wasm-freshness.mjs), then serves the page (serve.mjs).
import { spawnSync } from 'node:child_process';
import { resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { wasmStaleReason } from './wasm-freshness.mjs';

const root = resolve(fileURLToPath(new URL('..', import.meta.url)));
const stale = wasmStaleReason(root);
if (stale !== null) {
  console.log(`npm start: building wasm/dist (${stale})`);
  // Emscripten needs Debian's JavaScript modules (CONTRIBUTING.md).
  const env = { ...process.env, NODE_PATH: [process.env.NODE_PATH, '/usr/share/nodejs'].filter(Boolean).join(':') };
  const build = spawnSync(process.execPath, ['wasm/build-wasm.mjs'], { cwd: root, stdio: 'inherit', env });
  if (build.status !== 0) process.exit(build.status ?? 1);
}
const { serveOnEnvironmentPort } = await import('./serve.mjs');
await serveOnEnvironmentPort();
