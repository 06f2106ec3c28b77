#!/usr/bin/env node
// `npm run build:wasm`: configure and build the WebAssembly targets with Emscripten into
// build-wasm/, then copy each module's .mjs + .wasm into wasm/dist/ (what the package ships: the
// mesher ruppert, the text formats ruppert-formats and, for wasm/cli.js, ruppert-cli) and
// write wasm/dist/names.js: the core's enum names and options as the binding exports them
// (binding/describe.cpp), for the package's constants and option checks, which need them before any
// module is instantiated.
// Debian's emcc needs NODE_PATH=/usr/share/nodejs to find its JS optimizer's `acorn`.
import { spawnSync } from 'node:child_process';
import { copyFileSync, mkdirSync, readFileSync, statSync, writeFileSync } from 'node:fs';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { gzipSync } from 'node:zlib';

const root = fileURLToPath(new URL('..', import.meta.url));
const buildDir = process.env.RUPPERT_WASM_BUILD_DIR ?? `${root}build-wasm`;
const distDir = fileURLToPath(new URL('./dist/', import.meta.url));
const env = { ...process.env, NODE_PATH: [process.env.NODE_PATH, '/usr/share/nodejs'].filter(Boolean).join(':') };

function run(command, args) {
  console.log(`$ ${command} ${args.join(' ')}`);
  const result = spawnSync(command, args, { stdio: 'inherit', env });
  if (result.error) throw result.error;
  if (result.status !== 0) process.exit(result.status ?? 1);
}

run('emcmake', ['cmake', '-S', root, '-B', buildDir, '-DCMAKE_BUILD_TYPE=Release']);
run('cmake', ['--build', buildDir, '--target', 'ruppert_wasm', 'ruppert_wasm_formats', 'ruppert_wasm_cli', '-j2']);

mkdirSync(distDir, { recursive: true });
for (const name of ['ruppert', 'ruppert-formats', 'ruppert-cli']) {
  for (const file of [`${name}.mjs`, `${name}.wasm`]) copyFileSync(`${buildDir}/wasm/dist/${file}`, `${distDir}${file}`);
  const wasm = `${distDir}${name}.wasm`;
  const gzipped = gzipSync(readFileSync(wasm), { level: 9 }).length;
  console.log(`wasm/dist/${name}.wasm: ${statSync(wasm).size} bytes, ${gzipped} bytes gzipped`);
}

// Instantiated here without wasm/loader.js, which imports what this writes.
const { readDescription } = await import('./heap-call.js');
async function describeModule(name) {
  const { default: createModule } = await import(pathToFileURL(`${distDir}${name}.mjs`).href);
  const instance = {
    wasmBinary: readFileSync(`${distDir}${name}.wasm`),
    instantiateWasm(imports, receive) {
      WebAssembly.instantiate(this.wasmBinary, imports).then((r) => receive(r.instance, r.module));
      return {};
    },
    locateFile: (file) => file,
  };
  await createModule(instance);
  return readDescription(instance);
}
// The names from the mesher; the options only the CLI's module describes (binding/describe.cpp).
const { names } = await describeModule('ruppert');
const { options } = await describeModule('ruppert-cli');
writeFileSync(`${distDir}names.js`, `// Written by wasm/build-wasm.mjs from the binding (wasm/binding/describe.cpp): the names of
// the core's enums (core/include/ruppert/ruppert.h), each list in its enum's order, and the options
// (core/include/ruppert/option_table.h): name, type, default and range or values. Do not edit.
export const NAMES = Object.freeze({
${Object.entries(names).map(([key, list]) => `  ${key}: Object.freeze(${JSON.stringify(list)}),`).join('\n')}
});
export const OPTIONS = Object.freeze([
${options.map((option) => `  Object.freeze(${JSON.stringify(option)}),`).join('\n')}
]);
`);
console.log(`wasm/dist/names.js: ${Object.keys(names).join(', ')}; ${options.length} options`);
