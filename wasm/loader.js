// Finds, compiles and instantiates the package's WebAssembly modules: dist/ruppert.wasm (the
// mesher) and dist/ruppert-formats.wasm (the readers and writers of text formats). Each is a
// MODULES entry: its Emscripten factory, its file name and where the package keeps it. An
// instance host (instanceHost() below) holds one compiled module and its current instance.
//
// The compiled WebAssembly.Module is kept so that a fresh instance can be made after an abort
// (out of memory, a trap): instantiating an already compiled module is cheap and can be done
// synchronously where the platform allows it (Node, workers).
import createRuppertModule from './dist/ruppert.mjs';
import createFormatsModule from './dist/ruppert-formats.mjs';
import { MeshError } from './errors.js';

// What only Node can do: read a file: URL, start a worker_threads worker. The package's "node"
// export (node.js) registers it; browser bundles never import node.js, so they hold no Node code.
let nodeHost = null;

/** @param {{ readFile(url: URL): Promise<Uint8Array>, spawnWorker(url?: string | URL): object }} host */
export function registerNodeHost(host) {
  nodeHost = host;
}

/** The registered Node host, or null in browsers (and in Node before node.js is loaded). */
export function getNodeHost() {
  return nodeHost;
}

// Where a classic-script bundle (esbuild's default iife format, which has no import.meta.url) was
// loaded from; document.currentScript is only set while that script first runs, so read it now.
export const classicScriptUrl = globalThis.document?.currentScript?.src || globalThis.location?.href;

/** A URL as the platform resolves it (relative to the page or worker), for error messages. */
export function absoluteUrl(url) {
  try {
    return new URL(url, globalThis.location?.href).href;
  } catch {
    return String(url);
  }
}

// Where the package keeps `file`. `packaged` returns the literal new URL('./dist/<file>',
// import.meta.url), written out per file so that bundlers that copy assets (vite, webpack) see it and
// copy the file; it is only called where there is an import.meta.url: a classic-script bundle
// (esbuild's default iife format) has none, and the file is expected beside the bundle. A bundler
// that copies no assets (esbuild) leaves that URL as it is, relative to the bundle: then, as
// docs/usage.md says, the file is expected beside the bundle rather than in a dist/ below it.
function packagedOrBeside(file, packaged) {
  if (import.meta.url === undefined) return new URL(file, classicScriptUrl);
  const url = packaged();
  const inPackage = new URL(import.meta.url).pathname.endsWith('/loader.js');
  const rewritten = url.href !== besideThisModule(`./dist/${file}`).href;
  return inPackage || rewritten ? url : besideThisModule(`./${file}`);
}

export const MODULES = Object.freeze({
  mesher: Object.freeze({
    file: 'ruppert.wasm',
    factory: createRuppertModule,
    probe: 'triangulateStaged',  // a binding that is there once the instance is ready
    defaultUrl: () => packagedOrBeside('ruppert.wasm', () => new URL('./dist/ruppert.wasm', import.meta.url)),
  }),
  formats: Object.freeze({
    file: 'ruppert-formats.wasm',
    factory: createFormatsModule,
    probe: 'readPlc',
    defaultUrl: () => packagedOrBeside('ruppert-formats.wasm', () => new URL('./dist/ruppert-formats.wasm', import.meta.url)),
  }),
});

// new URL(file, import.meta.url) as the platform resolves it, out of bundlers' sight: webpack
// rewrites that form even with a variable first argument, so the base goes through a variable too.
function besideThisModule(file) {
  const here = import.meta.url;
  return new URL(file, here);
}

function loadFailure(url, reason, cause, kind) {
  const hint = kind === MODULES.formats
    ? ' (pass init({ formats: { wasmUrl } }) to say where ruppert-formats.wasm is served, or init({ formats: false }) to mesh without the text formats)'
    : kind === MODULES.mesher ? ' (pass init({ wasmUrl }) to say where ruppert.wasm is served)' : '';
  return new MeshError('IO_ERROR', `could not load the WebAssembly module ${absoluteUrl(url)}: ${reason}${hint}`, { cause });
}

// Node without the package's node entry (a direct import of wasm/index.js, as the benchmarks do).
function builtinReadFile() {
  const fs = globalThis.process?.getBuiltinModule?.('fs');
  return fs ? (url) => fs.promises.readFile(url) : null;
}

async function compileBytes(bytes, url, contentType, kind) {
  try {
    return await WebAssembly.compile(bytes);
  } catch (cause) {
    const served = contentType ? `, served as ${contentType}` : '';
    throw loadFailure(url, `not a WebAssembly module (${cause.message}${served})`, cause, kind);
  }
}

async function readLocal(url, kind) {
  const readFile = getNodeHost()?.readFile ?? builtinReadFile();
  if (readFile === null) throw loadFailure(url, 'file: URLs can only be read in Node', undefined, kind);
  let bytes;
  try {
    bytes = await readFile(new URL(url));
  } catch (cause) {
    throw loadFailure(url, cause.message, cause, kind);
  }
  return compileBytes(bytes, url, undefined, kind);
}

async function fetchAndCompile(url, kind) {
  if (String(url).startsWith('file:')) return readLocal(url, kind);
  let response;
  try {
    response = await fetch(url, { credentials: 'same-origin' });
  } catch (cause) {
    throw loadFailure(url, `the request failed (${cause.message})`, cause, kind);
  }
  if (!response.ok) throw loadFailure(url, `HTTP ${response.status}${response.statusText ? ` ${response.statusText}` : ''}`, undefined, kind);
  const contentType = response.headers.get('content-type') ?? '';
  // Streaming compilation needs the application/wasm MIME type; fall back when a server lacks it.
  if (typeof WebAssembly.compileStreaming === 'function' && contentType.startsWith('application/wasm')) {
    try {
      return await WebAssembly.compileStreaming(response);
    } catch (cause) {
      throw loadFailure(url, `not a WebAssembly module (${cause.message})`, cause, kind);
    }
  }
  return compileBytes(await response.arrayBuffer(), url, contentType, kind);
}

/**
 * @param {{ wasmUrl?: string | URL, locateFile?: (file: string) => string,
 *           wasmBinary?: ArrayBuffer | ArrayBufferView, wasmModule?: WebAssembly.Module }} options
 * @param {object} kind a MODULES entry (default: the mesher)
 * @param {string | URL} [fallbackUrl] where to look when the options name no source
 * @returns {Promise<WebAssembly.Module>}
 */
export async function compileWasm(options = {}, kind = MODULES.mesher, fallbackUrl = undefined) {
  if (options.wasmModule instanceof WebAssembly.Module) return options.wasmModule;
  if (options.wasmBinary) return WebAssembly.compile(options.wasmBinary);
  let url = options.wasmUrl;
  if (url === undefined && typeof options.locateFile === 'function') url = options.locateFile(kind.file);
  if (url === undefined) url = fallbackUrl ?? kind.defaultUrl();
  return fetchAndCompile(url, kind);
}

function moduleArgument(instantiate) {
  return {
    instantiateWasm: instantiate,
    // Never used for loading (instantiateWasm does that), but without it Emscripten's glue evaluates
    // new URL('ruppert.wasm', import.meta.url), which throws where a bundle has no import.meta.url.
    locateFile: (file) => file,
    // The binding reports every error itself; keep Emscripten from printing to the console.
    print: () => {},
    printErr: () => {},
  };
}

/** Asynchronous instantiation: always allowed, also on a browser's main thread. */
export async function instantiate(compiled, kind = MODULES.mesher) {
  let fail;
  const failed = new Promise((resolve, reject) => { fail = reject; });
  const module = moduleArgument((imports, receive) => {
    WebAssembly.instantiate(compiled, imports).then((instance) => {
      // The glue's start-up runs inside receive(): on another module's instance it throws.
      try {
        receive(instance, compiled);
      } catch (error) {
        fail(error);
      }
    }, fail);
    return {};
  });
  await Promise.race([kind.factory(module), failed]);
  if (typeof module[kind.probe] !== 'function') throw new Error(`it has no ${kind.probe} binding`);
  return module;
}

/**
 * Synchronous instantiation. Emscripten's factory fills in the object it is given before it
 * returns, so the bindings are usable at once. Browsers may refuse this on their main thread for
 * large modules; then it throws and the caller falls back to the asynchronous path.
 */
export function instantiateSync(compiled, kind = MODULES.mesher) {
  const module = moduleArgument((imports, receive) => {
    const instance = new WebAssembly.Instance(compiled, imports);
    receive(instance, compiled);
    return instance.exports;
  });
  // The factory's promise only matters for the asynchronous path; silence a later rejection
  // (an abort rejects it again).
  kind.factory(module).catch(() => {});
  if (typeof module[kind.probe] !== 'function') throw new Error('synchronous instantiation failed');
  return module;
}

/**
 * One compiled WebAssembly module and its current instance. Anything that escapes a binding (an
 * abort, a trap, a stack overflow) leaves the instance in an unknown state, so it is dropped and
 * the next call runs on a fresh instance of the same compiled module.
 * @param {WebAssembly.Module} compiled
 * @param {object} kind the module's entry in MODULES
 * @param {object} firstModule an instantiated Emscripten module of it (instantiate())
 */
function createInstanceHost(compiled, kind, firstModule) {
  let module = firstModule;
  let replacement = null;

  // Forget the current instance and start preparing the next one in the background, so that a
  // browser main thread (where synchronous instantiation may be refused) has it ready in time.
  function discard() {
    module = null;
    const pending = instantiate(compiled, kind).then((fresh) => {
      if (module === null) module = fresh;
      if (replacement === pending) replacement = null;
    });
    pending.catch(() => { if (replacement === pending) replacement = null; });
    replacement = pending;
  }

  function current() {
    if (module !== null) return module;
    try {
      module = instantiateSync(compiled, kind);
      return module;
    } catch (cause) {
      throw new MeshError('INTERNAL',
        'the WebAssembly module is being re-instantiated after an abort; await mesher.ready and retry', { cause });
    }
  }

  // Runs body(module); an exception out of it (an abort, a trap) discards the instance.
  function run(name, body) {
    const m = current();
    let result;
    try {
      result = body(m);
    } catch (cause) {
      discard();
      const detail = cause instanceof Error ? cause.message : String(cause);
      throw new MeshError('INTERNAL',
        `the WebAssembly module aborted in ${name}() (${detail}); the next call runs on a fresh instance`, { cause });
    }
    if (result && result.reset) discard();
    return result;
  }

  return {
    run,
    call: (name, ...args) => run(name, (m) => m[name](...args)),
    current,
    /** Resolves once an instance is available (only ever pending right after an abort). */
    get ready() {
      return module !== null || replacement === null ? Promise.resolve() : replacement;
    },
  };
}

/**
 * Compiles and instantiates one of MODULES from `options` (wasmUrl, locateFile,
 * wasmBinary, wasmModule; fallbackUrl where they name no source) and returns its host.
 */
export async function instanceHost(options, kind, fallbackUrl = undefined) {
  const compiled = await compileWasm(options, kind, fallbackUrl);
  let first;
  try {
    first = await instantiate(compiled, kind);
  } catch (cause) {
    // No memory for the instance (RangeError) is not the module's fault: passed on as it is.
    if (cause instanceof RangeError) throw cause;
    // A WebAssembly module, but not this one (a locateFile that answers one URL for every file,
    // the other module's bytes, another version's): its imports do not match the glue's.
    throw new MeshError('IO_ERROR', `the WebAssembly module given for ${kind.file} is not this package's ${kind.file} ` +
      `(${cause?.message ?? cause}); locateFile is called with each file's name`, { cause });
  }
  return createInstanceHost(compiled, kind, first);
}
