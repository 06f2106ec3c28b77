// Reads what the binding exports instead of JavaScript keeping copies (wasm/describe.cpp): the
// names of the core's enums, the options (ruppert-cli.wasm only) and the layout of the heap tables,
// as one JSON text in the heap.
// Imports nothing, so that wasm/build-wasm.mjs can use it before wasm/dist/names.js exists.

const descriptions = new WeakMap();  // per instance: parsed once

/**
 * @param {object} m an instantiated Emscripten module of ruppert.wasm
 * @returns {{ names: Record<string, string[]>, options?: object[], layout: Record<string, string[]> }}
 */
export function readDescription(m) {
  let description = descriptions.get(m);
  if (description === undefined) {
    const start = m._rp_describe(), bytes = m.HEAPU8;
    const end = bytes.indexOf(0, start);
    description = JSON.parse(new TextDecoder().decode(bytes.subarray(start, end)));
    descriptions.set(m, description);
  }
  return description;
}
