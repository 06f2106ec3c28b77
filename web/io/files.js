// Reading input files and writing exports, with the package's own readers and writers.
//
// These run on the main thread, so the WebAssembly module is loaded here too, but only when a
// file is first read or written.
import { init } from '../../wasm/index.js';

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
    case 'svg': return m.toSvg(mesh);
    case 'node': return m.toNode(mesh);
    case 'ele': return m.toEle(mesh);
    case 'msh': return m.toMsh(mesh, plc);
    // The boundary as line cells with their markers, as the CLI's --format vtu writes it.
    case 'vtu': return m.toVtu(mesh, { segmentCells: true });
    case 'geojson': return withBoundary(m.toGeoJson(mesh), mesh);
    default: throw new Error(`unknown export format ${format}`);
  }
}

/**
 * The package's GeoJSON (one Polygon feature per triangle) with each triangle's boundary markers:
 * properties.edgeMarkers, per edge opposite vertices[0], [1], [2] (the order of mesh.neighbors), the
 * marker of the subsegment on it (mesh.segmentMarkers, the input's where it had them), 0 for an edge
 * on no segment; a solver reading the .geojson tells its boundaries apart as with .poly, .msh and
 * .vtu, and the file still reads back as the triangles it holds.
 */
export function withBoundary(text, mesh) {
  const collection = JSON.parse(text);
  const key = (a, b) => (a < b ? `${a},${b}` : `${b},${a}`);
  const markers = new Map();
  for (let s = 0; s < mesh.segments.length / 2; s++) {
    markers.set(key(mesh.segments[2 * s], mesh.segments[2 * s + 1]), mesh.segmentMarkers[s]);
  }
  const tri = mesh.triangles;
  for (const feature of collection.features) {
    const t = feature.properties?.triangle;
    if (!Number.isInteger(t)) continue;
    const [i, j, k] = [tri[3 * t], tri[3 * t + 1], tri[3 * t + 2]];
    feature.properties.edgeMarkers = [key(j, k), key(k, i), key(i, j)].map((e) => markers.get(e) ?? 0);
  }
  return JSON.stringify(collection);
}

// Numbers in the shortest text that reads back to the same double.
const num = (v) => String(v);

/**
 * The drawing itself (points, segments, holes, regions), not its mesh, as Triangle's .poly: what the
 * page was given, so that another program (or Triangle) can mesh the same PLC.
 */
export function drawingPolyText(plc) {
  const n = plc.points.length / 2, m = plc.segments.length / 2, h = plc.holes.length / 2;
  const lines = ['# A drawing from the ruppert page: the PLC as drawn (points, segments, holes, regions)',
    `${n} 2 0 0`];
  for (let i = 0; i < n; i++) lines.push(`${i} ${num(plc.points[2 * i])} ${num(plc.points[2 * i + 1])}`);
  // With markers (a column of boundary markers) when the drawing has any.
  const markers = plc.segmentMarkers;
  lines.push(`${m} ${markers ? 1 : 0}`);
  for (let i = 0; i < m; i++) lines.push(`${i} ${plc.segments[2 * i]} ${plc.segments[2 * i + 1]}${markers ? ` ${markers[i]}` : ''}`);
  lines.push(`${h}`);
  for (let i = 0; i < h; i++) lines.push(`${i} ${num(plc.holes[2 * i])} ${num(plc.holes[2 * i + 1])}`);
  lines.push(`${plc.regions.length}`);
  plc.regions.forEach((r, i) => lines.push(`${i} ${num(r.x)} ${num(r.y)} ${num(r.attribute ?? 0)} ${num(r.maxArea > 0 ? r.maxArea : -1)}`));
  return `${lines.join('\n')}\n`;
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
