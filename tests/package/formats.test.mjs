// toMsh, toVtu, toGeoJson and parseGeoJson through the installed tarball,
// and the package CLI's --format msh|vtu|geojson, - and -o -. When Debian's python3-meshio is
// installed, meshio reads the package's .msh and .vtu back too.
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { after, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { init, MeshError, parseGeoJson, toGeoJson, toMsh, toVtu } from 'ruppert';
import { triangleArea } from './validate-mesh.mjs';

const dir = mkdtempSync(join(tmpdir(), 'ruppert-formats-'));
after(() => rmSync(dir, { recursive: true, force: true }));
const ring = (x, y, s, reverse = false) => {
  const r = [[x, y], [x + s, y], [x + s, y + s], [x, y + s]];
  if (reverse) r.reverse();
  return [...r, r[0]];
};
const annulus = { type: 'Polygon', coordinates: [ring(0, 0, 4), ring(1, 1, 2, true)] };

function area(mesh) {
  let sum = 0;
  for (let t = 0; t < mesh.triangles.length; t += 3) {
    sum += triangleArea(mesh.points, mesh.triangles[t], mesh.triangles[t + 1], mesh.triangles[t + 2]);
  }
  return sum;
}

function centroidsIn(mesh, x0, y0, x1, y1) {
  let count = 0;
  for (let t = 0; t < mesh.triangles.length; t += 3) {
    let cx = 0;
    let cy = 0;
    for (let k = 0; k < 3; k++) {
      cx += mesh.points[2 * mesh.triangles[t + k]] / 3;
      cy += mesh.points[2 * mesh.triangles[t + k] + 1] / 3;
    }
    if (cx > x0 && cx < x1 && cy > y0 && cy < y1) count++;
  }
  return count;
}

function expectError(fn, code, pattern) {
  assert.throws(fn, (error) => {
    assert.ok(error instanceof MeshError, `expected a MeshError, got ${error}`);
    assert.equal(error.code, code, error.message);
    assert.match(error.message, pattern);
    return true;
  });
}

test('parseGeoJson: a polygon with a hole meshes without hole seeds from the caller; the hole stays empty', async () => {
  const mesher = await init();
  for (const wrap of [(g) => g, (g) => ({ type: 'Feature', properties: { name: 'a' }, geometry: g }),
    (g) => ({ type: 'FeatureCollection', features: [{ type: 'Feature', properties: null, geometry: g }] }),
    (g) => ({ type: 'MultiPolygon', coordinates: [g.coordinates] })]) {
    const text = JSON.stringify(wrap(annulus));
    const plc = parseGeoJson(text, 'annulus.geojson');
    assert.equal(plc.points.length, 16, text);
    assert.equal(plc.segments.length, 16);
    assert.equal(plc.holes.length, 2, 'one hole seed, computed');
    const mesh = mesher.triangulate(plc, { minAngle: 30, maxArea: 0.1 });
    assert.ok(Math.abs(area(mesh) - 12) < 1e-9, `area ${area(mesh)}`);
    assert.equal(centroidsIn(mesh, 1, 1, 3, 3), 0, 'no triangle in the hole');
  }
});

test('parseGeoJson: errors name the feature and what is wrong', async () => {
  await init();
  const good = { type: 'Feature', geometry: annulus };
  expectError(() => parseGeoJson(JSON.stringify({ type: 'FeatureCollection',
    features: [good, { type: 'Feature', geometry: { type: 'Point', coordinates: [0, 0] } }] })),
  'MALFORMED_INPUT', /features\[1\]\.geometry.*Point/);
  expectError(() => parseGeoJson('{"type": "Polygon", "coordinates": [[[0,0],[1,0],[0,0]]]}', 'x.geojson'),
    'MALFORMED_INPUT', /^x\.geojson:1:\d+: coordinates\[0\] has 2 distinct positions/);
  expectError(() => parseGeoJson('{"type": "Polygon",'), 'PARSE_ERROR', /<geojson>:1:/);
  expectError(() => parseGeoJson(42), 'MALFORMED_INPUT', /parseGeoJson/);
});

test('toMsh: Gmsh 4.1 with physical groups from segment markers and region attributes', async () => {
  const mesher = await init();
  const plc = {
    points: [0, 0, 4, 0, 4, 4, 0, 4], segments: [0, 1, 1, 2, 2, 3, 3, 0],
    segmentMarkers: [5, 5, 0, 12], regions: [{ x: 1, y: 1, attribute: 2, maxArea: 0.5 }],
  };
  const mesh = mesher.triangulate(plc, { minAngle: 30 });
  const msh = toMsh(mesh, plc);
  assert.match(msh, /^\$MeshFormat\n4\.1 0 8\n\$EndMeshFormat\n\$PhysicalNames\n4\n/);
  assert.match(msh, /\n1 5 "marker 5"\n/);
  assert.match(msh, /\n1 12 "marker 12"\n/);
  // Segment 2 has marker 0 and lies on the boundary: Triangle's rule gives its subsegments 1.
  assert.match(msh, /\n1 1 "marker 1"\n/, 'an unmarked boundary segment carries marker 1');
  assert.doesNotMatch(msh, /"marker 0"/);
  assert.match(msh, /\n2 2 "attribute 2"\n/);
  const n = mesh.points.length / 2;
  const elements = mesh.triangles.length / 3 + mesh.segments.length / 2;
  assert.ok(msh.includes(`$Nodes\n1 ${n} 1 ${n}\n2 2 0 ${n}\n`));
  assert.ok(msh.includes(`$Elements\n4 ${elements} 1 ${elements}\n`));
  assert.equal(mesher.toMsh(mesh, plc), msh);
  assert.equal(mesher.toMsh(mesh), msh, 'the mesh carries its markers (mesh.segmentMarkers)');
});

test('toVtu and toGeoJson carry the triangles as they are', async () => {
  const mesher = await init();
  const plc = parseGeoJson(JSON.stringify(annulus));
  const mesh = mesher.triangulate(plc, { minAngle: 30, maxArea: 0.2 });
  const vtu = toVtu(mesh);
  const t = mesh.triangles.length / 3;
  assert.ok(vtu.includes(`<Piece NumberOfPoints="${mesh.points.length / 2}" NumberOfCells="${t}">`));
  const connectivity = vtu.match(/Name="connectivity" format="ascii">([^<]*)</)[1].trim().split(/\s+/).map(Number);
  assert.deepEqual(connectivity, Array.from(mesh.triangles));
  const angles = vtu.match(/Name="minAngle" format="ascii">([^<]*)</)[1].trim().split(/\s+/).map(Number);
  assert.equal(angles.length, t);
  assert.ok(angles.every((a) => a >= 30 - 1e-9), 'every smallest angle meets the bound');

  const geo = JSON.parse(toGeoJson(mesh));
  assert.equal(geo.type, 'FeatureCollection');
  assert.equal(geo.features.length, t);
  for (const [i, f] of geo.features.entries()) {
    const ringOut = f.geometry.coordinates[0];
    assert.equal(ringOut.length, 4);
    assert.deepEqual(ringOut[0], ringOut[3]);
    for (let k = 0; k < 3; k++) {
      const v = mesh.triangles[3 * i + k];
      assert.deepEqual(ringOut[k], [mesh.points[2 * v], mesh.points[2 * v + 1]]);
    }
  }
  // The triangles read back as polygons are the same domain: the hole is enclosed but not covered.
  const again = mesher.triangulate(parseGeoJson(toGeoJson(mesh)), { minAngle: 0 });
  assert.ok(Math.abs(area(again) - 12) < 1e-9);
  assert.equal(centroidsIn(again, 1, 1, 3, 3), 0);
});

test('meshio reads the package\'s .msh and .vtu (when python3-meshio is installed)', async (t) => {
  const probe = spawnSync('/usr/bin/python3', ['-c', 'import meshio'], { encoding: 'utf8' });
  if (probe.status !== 0) {
    t.skip('python3-meshio is not installed (.ci/setup.sh installs it)');
    return;
  }
  const mesher = await init();
  const plc = { points: [0, 0, 3, 0, 3, 2, 0, 2], segments: [0, 1, 1, 2, 2, 3, 3, 0], segmentMarkers: [1, 2, 3, 4] };
  const mesh = mesher.triangulate(plc, { minAngle: 30, maxArea: 0.1 });
  writeFileSync(join(dir, 'm.msh'), toMsh(mesh, plc));
  writeFileSync(join(dir, 'm.vtu'), toVtu(mesh));
  const script = 'import meshio, json, sys\n' +
    'out = {}\n' +
    'for f in sys.argv[1:]:\n' +
    '    m = meshio.read(f)\n' +
    '    out[f[-3:]] = {"points": m.points[:, :2].ravel().tolist(),\n' +
    '                   "triangles": [c.data.ravel().tolist() for c in m.cells if c.type == "triangle"],\n' +
    '                   "lines": sum(len(c.data) for c in m.cells if c.type == "line")}\n' +
    'print(json.dumps(out))\n';
  const run = spawnSync('/usr/bin/python3', ['-c', script, join(dir, 'm.msh'), join(dir, 'm.vtu')], { encoding: 'utf8' });
  assert.equal(run.status, 0, run.stderr);
  const read = JSON.parse(run.stdout);
  for (const ext of ['msh', 'vtu']) {
    assert.deepEqual(read[ext].points, Array.from(mesh.points), ext);
    assert.deepEqual(read[ext].triangles.flat().length, mesh.triangles.length, ext);
  }
  assert.deepEqual(read.vtu.triangles[0], Array.from(mesh.triangles));
  assert.equal(read.msh.lines, mesh.segments.length / 2);
});

const bin = fileURLToPath(new URL('./node_modules/.bin/ruppert', import.meta.url));
const cli = (args, input) => spawnSync(bin, args, { cwd: dir, encoding: 'utf8', input });

test('package CLI: --format msh|vtu|geojson, - as INPUT and -o -', () => {
  writeFileSync(join(dir, 'annulus.geojson'), JSON.stringify(annulus));
  for (const [format, head] of [['msh', '$MeshFormat\n4.1 0 8\n'], ['vtu', '<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid"'],
    ['geojson', '{"type": "FeatureCollection"']]) {
    const file = cli(['--format', format, '-o', 'a', 'annulus.geojson']);
    assert.equal(file.status, 0, file.stderr);
    const text = readFileSync(join(dir, `a.${format}`), 'utf8');
    assert.ok(text.startsWith(head), `${format}: ${text.slice(0, 60)}`);
    const piped = cli(['--format', format, '-o', '-', '-'], JSON.stringify(annulus));
    assert.equal(piped.status, 0, piped.stderr);
    assert.equal(piped.stdout, text, `${format} through standard input and output`);
    assert.match(piped.stderr, /^ruppert: /, 'the summary goes to standard error');
  }
  const told = cli(['--input-format', 'poly', '--format', 'msh', '-o', '-', '-'],
    '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n');
  assert.equal(told.status, 0, told.stderr);
  assert.match(told.stdout, /^\$MeshFormat/);
  const triangle = cli(['-o', '-', 'annulus.geojson']);
  assert.equal(triangle.status, 2);
  assert.match(triangle.stderr, /three/);
  const junk = cli(['-'], 'not a mesh');
  assert.equal(junk.status, 1);
  assert.match(junk.stderr, /<stdin>/);
});
