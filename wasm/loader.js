// Finds, compiles and instantiates dist/ruppert.wasm.
//
// The compiled WebAssembly.Module is kept so that a fresh instance can be made after an abort
// (out of memory, a trap): instantiating an already compiled module is cheap and can be done
// synchronously where the platform allows it (Node, workers).
import createRuppertModule from './dist/ruppert.mjs';

const isNode = typeof process === 'object' && typeof process.versions === 'object' &&
  typeof process.versions.node === 'string';

function defaultWasmUrl() {
  // Written literally so that bundlers see the asset and copy it.
  return new URL('./dist/ruppert.wasm', import.meta.url);
}

async function fetchAndCompile(url) {
  if (isNode && String(url).startsWith('file:')) {
    const { readFile } = await import(/* webpackIgnore: true */ /* @vite-ignore */ 'node:fs/promises');
    return WebAssembly.compile(await readFile(new URL(url)));
  }
  const response = await fetch(url, { credentials: 'same-origin' });
  if (!response.ok) throw new Error(`could not load ${url}: HTTP ${response.status}`);
  // Streaming compilation needs the application/wasm MIME type; fall back when a server lacks it.
  if (typeof WebAssembly.compileStreaming === 'function' &&
      (response.headers.get('content-type') ?? '').startsWith('application/wasm')) {
    return WebAssembly.compileStreaming(response);
  }
  return WebAssembly.compile(await response.arrayBuffer());
}

/**
 * @param {{ wasmUrl?: string | URL, locateFile?: (file: string) => string,
 *           wasmBinary?: ArrayBuffer | ArrayBufferView, wasmModule?: WebAssembly.Module }} options
 * @returns {Promise<WebAssembly.Module>}
 */
export async function compileWasm(options = {}) {
  if (options.wasmModule instanceof WebAssembly.Module) return options.wasmModule;
  if (options.wasmBinary) return WebAssembly.compile(options.wasmBinary);
  let url = options.wasmUrl;
  if (url === undefined && typeof options.locateFile === 'function') url = options.locateFile('ruppert.wasm');
  if (url === undefined) url = defaultWasmUrl();
  return fetchAndCompile(url);
}

function moduleArgument(instantiate) {
  return {
    instantiateWasm: instantiate,
    // The binding reports every error itself; keep Emscripten from printing to the console.
    print: () => {},
    printErr: () => {},
  };
}

/** Asynchronous instantiation: always allowed, also on a browser's main thread. */
export async function instantiate(compiled) {
  let fail;
  const failed = new Promise((resolve, reject) => { fail = reject; });
  const module = moduleArgument((imports, receive) => {
    WebAssembly.instantiate(compiled, imports).then((instance) => receive(instance, compiled), fail);
    return {};
  });
  await Promise.race([createRuppertModule(module), failed]);
  return module;
}

/**
 * Synchronous instantiation. Emscripten's factory fills in the object it is given before it
 * returns, so the bindings are usable at once. Browsers may refuse this on their main thread for
 * large modules; then it throws and the caller falls back to the asynchronous path.
 */
export function instantiateSync(compiled) {
  const module = moduleArgument((imports, receive) => {
    const instance = new WebAssembly.Instance(compiled, imports);
    receive(instance, compiled);
    return instance.exports;
  });
  // The factory's promise only matters for the asynchronous path; silence a later rejection
  // (an abort rejects it again).
  createRuppertModule(module).catch(() => {});
  if (typeof module.triangulateStaged !== 'function') throw new Error('synchronous instantiation failed');
  return module;
}
