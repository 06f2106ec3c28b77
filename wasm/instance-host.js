// One compiled WebAssembly module and its current instance. Anything that escapes a binding (an
// abort, a trap, a stack overflow) leaves the instance in an unknown state, so it is dropped and
// the next call runs on a fresh instance of the same compiled module.
import { MeshError } from './errors.js';
import { compileWasm, instantiate, instantiateSync } from './loader.js';

/**
 * @param {WebAssembly.Module} compiled
 * @param {object} kind the module's entry in loader.js's MODULES
 * @param {object} firstModule an instantiated Emscripten module of it (see loader.js)
 */
export function createInstanceHost(compiled, kind, firstModule) {
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
 * Compiles and instantiates one of loader.js's MODULES from `options` (wasmUrl, locateFile,
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
