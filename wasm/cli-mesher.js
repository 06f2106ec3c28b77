// The mesher wasm/cli.js runs on: one instance of dist/ruppert-cli.wasm, which holds the mesher,
// the text formats and the native CLI's argument parser and report printers (core/cli), so that
// both CLIs accept the same options and print the same texts. Node only: no bundle imports it.
import createCliModule from './dist/ruppert-cli.mjs';
import { instanceHost } from './instance-host.js';
import { createMesher } from './mesher.js';
import './node.js';  // registers the Node host (reading the .wasm from a file: URL)

const CLI_MODULE = Object.freeze({
  file: 'ruppert-cli.wasm',
  factory: createCliModule,
  probe: 'parseCliArgs',
  defaultUrl: () => new URL('./dist/ruppert-cli.wasm', import.meta.url),
});

/** A mesher whose readers, writers, triangulate() and CLI texts share one instance. */
export async function initCli() {
  const host = await instanceHost({}, CLI_MODULE);
  return createMesher(host, host, true);
}
