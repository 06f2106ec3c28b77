// Reading input files and writing exports, with the package's own readers and writers.
//
// These run on the main thread, so the WebAssembly module is loaded here too, but only when a
// file is first read or written.
import { init } from '../wasm/index.js';

let mesherPromise = null;
const mesher = () => (mesherPromise ??= init());

const READERS = { poly: 'parsePoly', node: 'parseNode', json: 'parseJson', geojson: 'parseGeoJson' };

export function fileFormat(name) {
  const match = /\.([a-z]+)$/i.exec(name);
  const ext = match ? match[1].toLowerCase() : '';
  return READERS[ext] ? ext : null;
}

/** Parses file text by its extension into a ParsedPlc; throws MeshError on bad input. */
export async function parseInput(text, name) {
  const format = fileFormat(name);
  if (format === null) throw new Error(`${name}: unknown file type (expected .poly, .node, .json or .geojson)`);
  return (await mesher())[READERS[format]](text, name);
}

export async function parsePolyText(text, name = '<message>') {
  return (await mesher()).parsePoly(text, name);
}

export async function exportText(format, mesh, plc) {
  const m = await mesher();
  switch (format) {
    case 'poly': return m.toPoly(mesh, plc);
    case 'json': return m.toJson(mesh, plc);
    case 'svg': return m.toSVG(mesh);
    case 'node': return m.toNode(mesh);
    case 'ele': return m.toEle(mesh);
    case 'msh': return m.toMsh(mesh, plc);
    case 'vtu': return m.toVtu(mesh);
    case 'geojson': return m.toGeoJson(mesh);
    default: throw new Error(`unknown export format ${format}`);
  }
}

const MIME = { poly: 'text/plain', json: 'application/json', svg: 'image/svg+xml', png: 'image/png',
  vtu: 'application/xml', geojson: 'application/geo+json' };

/** Offers `blobOrText` as a download named `name`. */
export function download(blobOrText, name, format) {
  const blob = blobOrText instanceof Blob ? blobOrText : new Blob([blobOrText], { type: MIME[format] ?? 'text/plain' });
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  a.style.display = 'none';
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

export function canvasBlob(canvas) {
  return new Promise((resolve, reject) => {
    canvas.toBlob((blob) => (blob ? resolve(blob) : reject(new Error('the canvas could not be encoded as PNG'))), 'image/png');
  });
}
