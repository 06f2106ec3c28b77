#!/usr/bin/env node
// Real outlines for the speed benchmarks: the land polygons of every country from the npm package
// @geo-maps/countries-land-10km (MIT; Natural Earth data simplified to 10 km), installed into a
// temporary folder and written out as one Triangle .poly per polygon (outer ring and inner rings as
// segments, one hole point inside each inner ring), in longitude/latitude degrees as given.
// Nothing of it is committed: the benchmarks read the folder this prints.
//
//   node tests/bench/real-outlines.mjs [--out DIR] [--min-vertices 20]
//   node tests/bench/speed-per-call.mjs --no-corpus --no-families --dir DIR [--placement offcenter]
//
// Polygons with fewer than --min-vertices vertices (islands of 4-6 points, most of the 1,405) are
// left out. Each file is named <country>-<k>.poly (ISO A3 code, the polygon's index in its feature).
// The hole point of an inner ring comes from the package's own GeoJSON reader (parseGeoJson), which
// places one inside every ring it reads as a hole.
import { execFileSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const PACKAGE = '@geo-maps/countries-land-10km@0.6.0';

function argument(name, fallback) {
  const i = process.argv.indexOf(name);
  return i > 0 ? process.argv[i + 1] : fallback;
}

const out = argument('--out', mkdtempSync(join(tmpdir(), 'ruppert-outlines-')));
const minVertices = Number(argument('--min-vertices', '20'));
const install = mkdtempSync(join(tmpdir(), 'ruppert-geo-maps-'));
execFileSync('npm', ['install', '--no-save', '--no-audit', '--no-fund', '--prefix', install, PACKAGE], { stdio: 'inherit' });
const map = JSON.parse(readFileSync(join(install, 'node_modules/@geo-maps/countries-land-10km/map.geo.json'), 'utf8'));

const { init } = await import(new URL('../../wasm/index.js', import.meta.url));
const ruppert = await init();

function polyText(plc, source) {
  const n = plc.points.length / 2, m = plc.segments.length / 2, h = plc.holes.length / 2;
  const lines = [`# ${source}`, `${n} 2 0 0`];
  for (let i = 0; i < n; i++) lines.push(`${i} ${plc.points[2 * i]} ${plc.points[2 * i + 1]}`);
  lines.push(`${m} 0`);
  for (let i = 0; i < m; i++) lines.push(`${i} ${plc.segments[2 * i]} ${plc.segments[2 * i + 1]}`);
  lines.push(`${h}`);
  for (let i = 0; i < h; i++) lines.push(`${i} ${plc.holes[2 * i]} ${plc.holes[2 * i + 1]}`);
  return lines.join('\n') + '\n';
}

mkdirSync(out, { recursive: true });
let written = 0, skipped = 0;
for (const feature of map.features) {
  const { type, coordinates } = feature.geometry;
  const polygons = type === 'Polygon' ? [coordinates] : coordinates;
  polygons.forEach((rings, k) => {
    const vertices = rings.reduce((sum, ring) => sum + ring.length - 1, 0);
    if (vertices < minVertices) { skipped++; return; }
    const name = `${feature.properties.A3}-${k}`;
    const plc = ruppert.parseGeoJson(JSON.stringify({ type: 'Polygon', coordinates: rings }), name);
    writeFileSync(join(out, `${name}.poly`), polyText(plc, `${PACKAGE}: ${name}`));
    written++;
  });
}
console.log(`real-outlines: ${written} outlines with at least ${minVertices} vertices in ${out} (${skipped} smaller left out)`);
