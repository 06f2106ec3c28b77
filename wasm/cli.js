#!/usr/bin/env node
// `npx ruppert [options] INPUT`: the native `ruppert` executable (core/cli) on the WebAssembly
// build. Its argument parser, --help text, summary, --stats and --trace printers are the native
// C++ code compiled into the wasm, so both CLIs accept and print the same things; only the file
// input/output is done here, with node:fs.
//   ruppert --min-angle 30 -o out in.poly   writes out.node, out.ele, out.poly
//   cat in.geojson | ruppert --format msh -o - -   reads standard input, writes the .msh to standard output
// (The native CLI's progress line on a terminal is not drawn here: the mesher runs in one call.)
// Exit status: 0 success, 1 invalid input, 2 usage error, 3 an output file could not be written.
import { readFile, writeFile } from 'node:fs/promises';
import { extname } from 'node:path';
import createCliModule from './dist/ruppert-cli.mjs';
import { MeshError } from './errors.js';
import { instanceHost } from './loader.js';
import { createMesher } from './mesher.js';
import './node.js';  // registers the Node host (reading the .wasm from a file: URL)

const EXIT_OK = 0;
const EXIT_INVALID_INPUT = 1;
const EXIT_USAGE = 2;
const EXIT_WRITE_FAILED = 3;

class WriteFailure extends Error {}

// The mesher this CLI runs on: one instance of dist/ruppert-cli.wasm, which holds the mesher, the
// text formats and the native CLI's argument parser and report printers (core/cli), so that both
// CLIs accept the same options and print the same texts. Only this file loads it: no bundle does.
const CLI_MODULE = Object.freeze({
  file: 'ruppert-cli.wasm',
  factory: createCliModule,
  probe: 'parseCliArgs',
  defaultUrl: () => new URL('./dist/ruppert-cli.wasm', import.meta.url),
});

/** A mesher whose readers, writers, triangulate() and CLI texts share one instance. */
async function initCli() {
  const host = await instanceHost({}, CLI_MODULE);
  return createMesher(host, host, true);
}

const READERS = { poly: 'parsePoly', node: 'parseNode', json: 'parseJson', geojson: 'parseGeoJson' };

// The format of standard input's text, as the native CLI sniffs it (core/cli/cli_input.cpp).
function sniffFormat(text) {
  if (!/^\uFEFF?\s*\{/.test(text)) return 'triangle';
  return text.includes('"type"') && !text.includes('"points"') ? 'geojson' : 'json';
}

// Triangle's text without an extension: .poly, or failing that .node (the .poly error is shown).
function parseTriangleText(mesher, text, name) {
  try {
    return mesher.parsePoly(text, name);
  } catch (polyError) {
    if (!(polyError instanceof MeshError) || polyError.code !== 'PARSE_ERROR') throw polyError;
    try {
      return mesher.parseNode(text, name);
    } catch {
      throw polyError;
    }
  }
}

async function readStdin() {
  const chunks = [];
  for await (const chunk of process.stdin) chunks.push(chunk);
  return Buffer.concat(chunks).toString('utf8');
}

async function readPlc(mesher, path, inputFormat) {
  let text;
  try {
    text = path === '-' ? await readStdin() : await readFile(path, 'utf8');
  } catch (cause) {
    throw new MeshError('IO_ERROR', `cannot read '${path}': ${cause.message}`, { cause });
  }
  const name = path === '-' ? '<stdin>' : path;
  const ext = extname(path).toLowerCase().slice(1);
  const format = inputFormat || (path === '-' ? sniffFormat(text) : ext);
  if (format === 'triangle') return parseTriangleText(mesher, text, name);
  if (format === 'ele' && path !== '-') return readEle(mesher, path, text);
  if (READERS[format] !== undefined) return mesher[READERS[format]](text, name);
  throw new MeshError('IO_ERROR', `'${path}': unknown extension '.${ext}' (expected .poly, .node, .ele, .json or .geojson)`);
}

// Refining a mesh: BASE.ele with BASE.node, and BASE.poly and BASE.area when they exist.
async function readEle(mesher, path, ele) {
  const stem = path.slice(0, -4);
  const sibling = (ext) => stem + (path.endsWith('.ELE') ? ext.toUpperCase() : ext);
  const optional = async (file) => {
    try {
      return await readFile(file, 'utf8');
    } catch (cause) {
      if (cause.code === 'ENOENT') return undefined;
      throw new MeshError('IO_ERROR', `cannot read '${file}': ${cause.message}`, { cause });
    }
  };
  const nodeName = sibling('.node'), polyName = sibling('.poly'), areaName = sibling('.area');
  const node = await optional(nodeName);
  if (node === undefined) {
    throw new MeshError('IO_ERROR', `${nodeName}: cannot open for reading (refining ${path} needs its points)`);
  }
  return mesher.parseEle(ele, {
    name: path, node, nodeName, poly: await optional(polyName), polyName, area: await optional(areaName), areaName,
  });
}

// On a terminal, a run that lasts over a second shows a progress line on standard error, rewritten
// in place at most five times a second and cleared at the end, as the native CLI's (cli_progress.cpp).
function progressLine(quiet) {
  if (quiet || !process.stderr.isTTY) return null;
  const start = performance.now();
  let drawn = false, last = 0;
  return {
    draw(p) {
      const now = performance.now(), seconds = (now - start) / 1000;
      if (seconds < 1 || (drawn && now - last < 200)) return true;
      process.stderr.write(`\rruppert: ${p.insertedVertices} vertices inserted, ${p.triangles} triangles, ` +
        `worst angle ${p.worstAngle.toFixed(1)} deg, ${seconds.toFixed(1)} s\x1b[K`);
      drawn = true, last = now;
      return true;
    },
    clear() {
      if (drawn) process.stderr.write('\r\x1b[K');
      drawn = false;
    },
  };
}

async function write(path, text) {
  if (path.startsWith('-.')) {  // -o -: the one file of the format goes to standard output
    await new Promise((resolve, reject) => process.stdout.write(text, (error) => (error ? reject(error) : resolve())));
    return;
  }
  try {
    await writeFile(path, text);
  } catch (cause) {
    throw new WriteFailure(`cannot write '${path}': ${cause.message}`);
  }
}

async function main(argv) {
  const mesher = await initCli();
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
  const progress = progressLine(args.quiet);
  try {
    plc = await readPlc(mesher, args.input, args.inputFormat);
    const options = progress ? { ...args.options, onProgress: progress.draw } : args.options;
    mesh = mesher._triangulateWithReport(plc, options,
      { summary: !args.quiet, stats: args.stats, trace: args.tracePath !== '' });
  } catch (error) {
    progress?.clear();
    if (!(error instanceof MeshError)) throw error;
    process.stderr.write(`error: ${error.message}\n`);
    if (error.code === 'INVALID_OPTION') {
      process.stderr.write(`${args.usageLine}\n`);
      return EXIT_USAGE;
    }
    return EXIT_INVALID_INPUT;
  }

  progress?.clear();
  if (!args.quiet) {
    for (const notice of mesh.notices) process.stderr.write(`warning: ${notice.message}\n`);
  }
  try {
    const base = args.outputBase;
    if (base !== '' && args.options.voronoi) {
      await write(`${base}.v.node`, mesher.toVoronoiNode(mesh));
      await write(`${base}.v.edge`, mesher.toVoronoiEdge(mesh));
    }
    if (base !== '') {
      if (args.format === 'triangle') {
        await write(`${base}.node`, mesher.toNode(mesh));
        await write(`${base}.ele`, mesher.toEle(mesh));
        await write(`${base}.poly`, mesher.toPoly(mesh, plc));
        if (args.options.edges) await write(`${base}.edge`, mesher.toEdge(mesh));
      } else if (args.format === 'json') {
        await write(`${base}.json`, mesher.toJson(mesh, plc));
      } else if (args.format === 'msh') {
        await write(`${base}.msh`, mesher.toMsh(mesh, plc));
      } else if (args.format === 'vtu') {
        await write(`${base}.vtu`, mesher.toVtu(mesh, { segmentCells: true }));  // as the native CLI
      } else if (args.format === 'geojson') {
        await write(`${base}.geojson`, mesher.toGeoJson(mesh));
      } else {
        await write(`${base}.svg`, mesher.toSvg(mesh));
      }
    }
    if (args.tracePath !== '') await write(args.tracePath, mesh.report.trace);
  } catch (error) {
    if (!(error instanceof WriteFailure)) throw error;
    process.stderr.write(`error: ${error.message}\n`);
    return EXIT_WRITE_FAILED;
  }
  // With -o - standard output holds the mesh, so the reports go to standard error.
  const report = args.outputBase === '-' ? process.stderr : process.stdout;
  if (!args.quiet) report.write(mesh.report.summary);
  if (args.stats) report.write(mesh.report.stats);
  return EXIT_OK;
}

main(process.argv.slice(2)).then(
  (status) => { process.exitCode = status; },
  (error) => {
    process.stderr.write(`error: internal: ${error instanceof Error ? error.message : String(error)}\n`);
    process.exitCode = EXIT_INVALID_INPUT;
  });
