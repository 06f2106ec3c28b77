// Whether wasm/dist is older than the sources it is built from, so that `npm start` (web/start.mjs)
// and web/build-site.mjs never serve a page whose mesher predates the C++ beside it.
import { existsSync, readdirSync, statSync } from 'node:fs';
import { join } from 'node:path';

// What wasm/build-wasm.mjs builds from (folders are walked) and what it writes.
export const WASM_SOURCES = ['core', 'wasm/binding', 'wasm/CMakeLists.txt', 'CMakeLists.txt', 'wasm/build-wasm.mjs'];
export const WASM_OUTPUTS = ['ruppert.wasm', 'ruppert-formats.wasm', 'ruppert-cli.wasm', 'names.js'].map((f) => `wasm/dist/${f}`);

/** The newest file under `path` (a file or a folder): { file, mtimeMs }, or null when there is none. */
function newestUnder(path) {
  if (!existsSync(path)) return null;
  const stats = statSync(path);
  if (!stats.isDirectory()) return { file: path, mtimeMs: stats.mtimeMs };
  let newest = null;
  for (const entry of readdirSync(path)) {
    const found = newestUnder(join(path, entry));
    if (found && (newest === null || found.mtimeMs > newest.mtimeMs)) newest = found;
  }
  return newest;
}

/**
 * Why wasm/dist must be built again under `root`, or null when it is up to date: an output is
 * missing, or a source file was changed after the oldest output was written.
 */
export function wasmStaleReason(root) {
  let oldest = null;
  for (const output of WASM_OUTPUTS) {
    const path = join(root, output);
    if (!existsSync(path)) return `${output} is missing`;
    const mtimeMs = statSync(path).mtimeMs;
    if (oldest === null || mtimeMs < oldest.mtimeMs) oldest = { file: output, mtimeMs };
  }
  for (const source of WASM_SOURCES) {
    const newest = newestUnder(join(root, source));
    if (newest && newest.mtimeMs > oldest.mtimeMs) {
      return `${newest.file.slice(root.length + 1)} is newer than ${oldest.file}`;
    }
  }
  return null;
}
