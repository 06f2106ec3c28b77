#!/usr/bin/env node
// `npx ruppert [options] INPUT`: the native `ruppert` executable (core/cli) on the WebAssembly
// build. Its argument parser, --help text, summary, --stats and --trace printers are the native
// C++ code compiled into the wasm, so both CLIs accept and print the same things; only the file
// input/output is done here, with node:fs.
//   ruppert --min-angle 30 -o out in.poly   writes out.node, out.ele, out.poly
// Exit status: 0 success, 1 invalid input, 2 usage error, 3 an output file could not be written.
import { readFile, writeFile } from 'node:fs/promises';
import { extname } from 'node:path';
import { init, MeshError } from './node.js';

const EXIT_OK = 0;
const EXIT_INVALID_INPUT = 1;
const EXIT_USAGE = 2;
const EXIT_WRITE_FAILED = 3;

class WriteFailure extends Error {}

async function readPlc(mesher, path) {
  let text;
  try {
    text = await readFile(path, 'utf8');
  } catch (cause) {
    throw new MeshError('IO_ERROR', `cannot read '${path}': ${cause.message}`, { cause });
  }
  const ext = extname(path).toLowerCase();
  if (ext === '.poly') return mesher.parsePoly(text, path);
  if (ext === '.node') return mesher.parseNode(text, path);
  if (ext === '.json') return mesher.parseJson(text, path);
  throw new MeshError('IO_ERROR', `'${path}': unknown extension '${ext}' (expected .poly, .node or .json)`);
}

async function write(path, text) {
  try {
    await writeFile(path, text);
  } catch (cause) {
    throw new WriteFailure(`cannot write '${path}': ${cause.message}`);
  }
}

async function main(argv) {
  const mesher = await init();
  const args = mesher._parseCliArgs(argv);
  if (args.usageError !== undefined) {
    process.stderr.write(`error: ${args.usageError}\n${args.usageLine}\n`);
    return EXIT_USAGE;
  }
  if (args.help) {
    process.stdout.write(args.helpText);
    return EXIT_OK;
  }
  if (args.version) {
    const pkg = JSON.parse(await readFile(new URL('../package.json', import.meta.url), 'utf8'));
    process.stdout.write(`ruppert ${pkg.version}\n`);
    return EXIT_OK;
  }

  let plc;
  let mesh;
  try {
    plc = await readPlc(mesher, args.input);
    mesh = mesher._triangulateWithReport(plc, args.options,
      { summary: !args.quiet, stats: args.stats, trace: args.tracePath !== '' });
  } catch (error) {
    if (!(error instanceof MeshError)) throw error;
    process.stderr.write(`error: ${error.message}\n`);
    if (error.code === 'INVALID_OPTION') {
      process.stderr.write(`${args.usageLine}\n`);
      return EXIT_USAGE;
    }
    return EXIT_INVALID_INPUT;
  }

  if (!args.quiet) {
    for (const notice of mesh.notices) process.stderr.write(`warning: ${notice.message}\n`);
  }
  try {
    const base = args.outputBase;
    if (base !== '') {
      if (args.format === 'triangle') {
        await write(`${base}.node`, mesher.toNode(mesh));
        await write(`${base}.ele`, mesher.toEle(mesh));
        await write(`${base}.poly`, mesher.toPoly(mesh, plc));
        if (args.options.edges) await write(`${base}.edge`, mesher.toEdge(mesh));
      } else if (args.format === 'json') {
        await write(`${base}.json`, mesher.toJson(mesh, plc));
      } else {
        await write(`${base}.svg`, mesher.toSVG(mesh));
      }
    }
    if (args.tracePath !== '') await write(args.tracePath, mesh.report.trace);
  } catch (error) {
    if (!(error instanceof WriteFailure)) throw error;
    process.stderr.write(`error: ${error.message}\n`);
    return EXIT_WRITE_FAILED;
  }
  if (!args.quiet) process.stdout.write(mesh.report.summary);
  if (args.stats) process.stdout.write(mesh.report.stats);
  return EXIT_OK;
}

main(process.argv.slice(2)).then(
  (status) => { process.exitCode = status; },
  (error) => {
    process.stderr.write(`error: internal: ${error instanceof Error ? error.message : String(error)}\n`);
    process.exitCode = EXIT_INVALID_INPUT;
  });
