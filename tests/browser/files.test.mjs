// Presets, importing files (picker and drag-and-drop), exports, and links that reproduce a drawing.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { after, before, test } from 'node:test';
import { PRESETS } from '../../web/panels/presets.js';
import { SCREENSHOTS, launch, openPage, readStats, settle, openExportMenu } from './harness.mjs';

let harness;
let page;
let errors;
const wasmFetched = [];  // the .wasm files requested by the page and its worker, in order

before(async () => {
  harness = await launch();
  harness.context.on('request', (request) => {
    if (request.url().endsWith('.wasm')) wasmFetched.push(request.url().slice(harness.baseUrl.length));
  });
  ({ page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/`));
  assert.equal(await settle(page), 'done');
});

after(async () => {
  await harness?.close();
});

// A pentagon with a triangular hole, 1-based, with comments: Triangle's .poly format.
const PENTAGON = `# pentagon with a hole
8 2 0 0
1 0 0
2 10 0
3 13 8
4 5 13
5 -3 8
6 4 4
7 6 4
8 5 6
8 0
1 1 2
2 2 3
3 3 4
4 4 5
5 5 1
6 6 7
7 7 8
8 8 6
1
1 5 4.6
`;

// The page meshes in a worker on the mesher module alone (the smaller download); the text
// formats module comes with the first file read or written.
test('the page fetches only the mesher to mesh, and the text formats with the first file', async () => {
  assert.deepEqual(wasmFetched, ['/wasm/dist/ruppert.wasm']);
  await page.setInputFiles('#file-input', { name: 'pentagon-with-hole.poly', mimeType: 'text/plain', buffer: Buffer.from(PENTAGON) });
  assert.equal(await settle(page), 'done');
  assert.deepEqual(wasmFetched.filter((path) => path.includes('formats')), ['/wasm/dist/ruppert-formats.wasm']);
});

test('every preset loads and meshes', async () => {
  const counts = new Map();
  for (const preset of PRESETS) {
    await page.selectOption('#preset', preset.id);
    assert.equal(await settle(page), 'done', preset.id);
    const stats = await readStats(page);
    assert.ok(stats.triangles > 0, `${preset.id}: ${stats.triangles} triangles`);
    assert.ok(stats.vertices >= preset.build().points.length / 2, preset.id);
    counts.set(preset.id, stats.triangles);
  }
  // Distinct meshes, but for the side-by-side comparison, whose own mesh is by design that of the
  // off-centers' preset (compare-view.js draws the other one beside it).
  const own = PRESETS.filter((p) => !p.compare);
  assert.equal(new Set(own.map((p) => counts.get(p.id))).size, own.length, `distinct meshes: ${[...counts]}`);
  // Presets that teach turn step mode on, where the Mesh panel shows the step on screen: the tests
  // below read the final mesh's statistics.
  if (await page.isChecked('#step-mode')) {
    await page.uncheck('#step-mode');
    assert.equal(await settle(page), 'done');
  }
  await page.selectOption('#preset', 'two-sizes');
  await settle(page);
  await page.selectOption('#color-mode', 'region');
  assert.match(await page.locator('#legend').textContent(), /attribute 1.*attribute 2/);
  await page.screenshot({ path: `${SCREENSHOTS}preset-two-sizes-regions.png` });
  await page.selectOption('#color-mode', 'angle');
});

test('a .poly file chosen in the file picker is read by the package and meshed', async () => {
  await page.setInputFiles('#file-input', { name: 'pentagon-with-hole.poly', mimeType: 'text/plain', buffer: Buffer.from(PENTAGON) });
  assert.equal(await settle(page), 'done');
  assert.match(await page.locator('#status').textContent(), /Meshed/);
  const stats = await readStats(page);
  assert.ok(stats.vertices >= 8 && stats.triangles > 0);
  assert.equal(stats.complete, 'yes');
  // The hole survived the import: the URL holds one hole seed at (5, 4.6).
  const drawing = await page.evaluate(async () => (await import('./io/url-state.js')).decodeDrawing(location.hash));
  assert.deepEqual(drawing.holes, [5, 4.6]);
  assert.equal(drawing.points.length, 16);
  assert.equal(drawing.segments.length, 16);
});

test('a broken file is reported, and the drawing kept', async () => {
  const before = await page.evaluate(() => location.hash);
  await page.setInputFiles('#file-input', { name: 'broken.poly', mimeType: 'text/plain', buffer: Buffer.from('3 2 0 0\n1 0 0\n2 1\n') });
  await page.waitForFunction(() => document.getElementById('status').dataset.kind === 'error');
  assert.match(await page.locator('#status').textContent(), /Could not load broken\.poly/);
  assert.match(await page.locator('#notices .error').textContent(), /PARSE_ERROR/);
  assert.equal(await page.evaluate(() => location.hash), before);
});

test('a .json file dropped on the canvas is loaded', async () => {
  const json = JSON.stringify({ points: [0, 0, 4, 0, 4, 3, 0, 3], segments: [0, 1, 1, 2, 2, 3, 3, 0] });
  const dataTransfer = await page.evaluateHandle((text) => {
    const transfer = new DataTransfer();
    transfer.items.add(new File([text], 'rectangle.json', { type: 'application/json' }));
    return transfer;
  }, json);
  await page.dispatchEvent('#canvas-wrap', 'dragover', { dataTransfer });
  assert.equal(await page.locator('#drop-hint').isVisible(), true);
  await page.dispatchEvent('#canvas-wrap', 'drop', { dataTransfer });
  assert.equal(await settle(page), 'done');
  const drawing = await page.evaluate(async () => (await import('./io/url-state.js')).decodeDrawing(location.hash));
  assert.deepEqual(drawing.points, [0, 0, 4, 0, 4, 3, 0, 3]);
  assert.equal(await page.locator('#drop-hint').isHidden(), true);
});

async function exportFile(button) {
  if (button.startsWith('#export-')) await openExportMenu(page);
  const [download] = await Promise.all([page.waitForEvent('download'), page.click(button)]);
  return { name: download.suggestedFilename(), bytes: readFileSync(await download.path()) };
}

test('exports .poly, .json, .svg and .png downloads of the mesh', async () => {
  await page.setInputFiles('#file-input', { name: 'pentagon-with-hole.poly', mimeType: 'text/plain', buffer: Buffer.from(PENTAGON) });
  assert.equal(await settle(page), 'done');
  const stats = await readStats(page);

  const poly = await exportFile('#export-poly');
  assert.equal(poly.name, 'ruppert-mesh.poly');
  const lines = poly.bytes.toString('utf8').split('\n').map((l) => l.replace(/#.*/, '').trim()).filter(Boolean);
  assert.equal(Number(lines[0].split(/\s+/)[0]), stats.vertices, `.poly header: ${lines[0]}`);

  const json = JSON.parse((await exportFile('#export-json')).bytes.toString('utf8'));
  assert.equal(json.triangles.length, 3 * stats.triangles, 'three vertex indices per triangle');

  const svg = (await exportFile('#export-svg')).bytes.toString('utf8');
  assert.match(svg, /<svg[\s>]/);

  const png = await exportFile('#export-png');
  assert.deepEqual([...png.bytes.subarray(0, 8)], [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);

  // The exported .poly reads back in (through the same file picker).
  await page.setInputFiles('#file-input', { name: 'again.poly', mimeType: 'text/plain', buffer: poly.bytes });
  assert.equal(await settle(page), 'done');
  assert.ok((await readStats(page)).vertices >= stats.vertices);
});

test('exports the drawing itself as a .poly that reads back to the same drawing', async () => {
  await page.setInputFiles('#file-input', { name: 'pentagon-with-hole.poly', mimeType: 'text/plain', buffer: Buffer.from(PENTAGON) });
  assert.equal(await settle(page), 'done');
  const before = await page.evaluate(async () => (await import('./io/url-state.js')).decodeDrawing(location.hash));
  const exported = await exportFile('#export-drawing');
  assert.equal(exported.name, 'ruppert-drawing.poly');
  const lines = exported.bytes.toString('utf8').split('\n').map((l) => l.replace(/#.*/, '').trim()).filter(Boolean);
  // The input's points and segments, not the mesh's vertices and subsegments.
  assert.equal(Number(lines[0].split(/\s+/)[0]), before.points.length / 2, `.poly header: ${lines[0]}`);
  await page.setInputFiles('#file-input', { name: 'again.poly', mimeType: 'text/plain', buffer: exported.bytes });
  assert.equal(await settle(page), 'done');
  const after = await page.evaluate(async () => (await import('./io/url-state.js')).decodeDrawing(location.hash));
  assert.deepEqual(after.points, before.points);
  assert.deepEqual(after.segments, before.segments);
  assert.deepEqual(after.holes, before.holes);
});

/** The area of a mesh's triangles, and whether any triangle's centroid lies within r of (cx, cy). */
function meshArea(mesh, cx, cy, r) {
  let area = 0;
  let inside = false;
  const p = mesh.points;
  for (let t = 0; t < mesh.triangles.length; t += 3) {
    const [a, b, c] = [2 * mesh.triangles[t], 2 * mesh.triangles[t + 1], 2 * mesh.triangles[t + 2]];
    area += ((p[b] - p[a]) * (p[c + 1] - p[a + 1]) - (p[c] - p[a]) * (p[b + 1] - p[a + 1])) / 2;
    const gx = (p[a] + p[b] + p[c]) / 3, gy = (p[a + 1] + p[b + 1] + p[c + 1]) / 3;
    if (Math.hypot(gx - cx, gy - cy) < r) inside = true;
  }
  return { area, inside };
}

test('a curved drawing\'s "drawing .poly" opens again as the same domain: its area and its hole', async () => {
  await page.selectOption('#preset', 'plate-round-hole');
  assert.equal(await settle(page), 'done');
  const curved = meshArea(JSON.parse((await exportFile('#export-json')).bytes.toString('utf8')), 0.5, 0.5, 0.24);
  const exported = await exportFile('#export-drawing');
  assert.match(await page.locator('#status').textContent(), /holds no curves.*2 curves are \d+ segments within/);
  const text = exported.bytes.toString('utf8');
  await page.setInputFiles('#file-input', { name: 'plate.poly', mimeType: 'text/plain', buffer: exported.bytes });
  assert.equal(await settle(page), 'done', text);
  const again = meshArea(JSON.parse((await exportFile('#export-json')).bytes.toString('utf8')), 0.5, 0.5, 0.24);
  // The unit square less a disk of radius 0.25, both meshes to the curve tolerance (1e-3 of the
  // diagonal: the chords cut at most perimeter x tolerance off the hole).
  const exact = 1 - Math.PI * 0.25 ** 2;
  const slack = 2 * Math.PI * 0.25 * Math.SQRT2 * 1e-3;
  assert.equal(again.inside, false, 'the hole is still a hole');
  assert.ok(Math.abs(again.area - exact) <= slack, `area ${again.area}, exact ${exact}`);
  assert.ok(Math.abs(again.area - curved.area) <= slack, `area ${again.area}, curved drawing's ${curved.area}`);
});

test('the .png export has the mesh without the grid, the seeds or the handles', async () => {
  await page.selectOption('#preset', 'plate-round-hole');
  assert.equal(await settle(page), 'done');
  await page.check('#snap');
  const png = await exportFile('#export-png');
  await page.uncheck('#snap');
  // Pixels of the hole seed's red and of the grid's lines, counted in the page from the PNG.
  const counts = await page.evaluate(async (base64) => {
    const image = new Image();
    image.src = `data:image/png;base64,${base64}`;
    await image.decode();
    const canvas = document.createElement('canvas');
    canvas.width = image.width; canvas.height = image.height;
    const ctx = canvas.getContext('2d');
    ctx.drawImage(image, 0, 0);
    const data = ctx.getImageData(0, 0, image.width, image.height).data;
    const near = (i, [r, g, b]) => Math.abs(data[i] - r) + Math.abs(data[i + 1] - g) + Math.abs(data[i + 2] - b) < 12;
    let seed = 0, grid = 0;
    for (let i = 0; i < data.length; i += 4) {
      if (near(i, [0xc9, 0x2a, 0x2a])) seed++;
      if (near(i, [0xd9, 0xdd, 0xe6]) || near(i, [0xee, 0xf0, 0xf4])) grid++;
    }
    return { seed, grid, pixels: data.length / 4 };
  }, png.bytes.toString('base64'));
  assert.equal(counts.seed, 0, 'no hole seed drawn');
  assert.ok(counts.grid < counts.pixels * 0.002, `${counts.grid} grid pixels of ${counts.pixels}`);
});

test('.poly, .json and .geojson open again to the same mesh; .node and .ele say what they cannot hold', async () => {
  for (const format of ['poly', 'json', 'geojson']) {
    await page.setInputFiles('#file-input', { name: 'pentagon-with-hole.poly', mimeType: 'text/plain', buffer: Buffer.from(PENTAGON) });
    assert.equal(await settle(page), 'done');
    const before = await readStats(page);
    const exported = await exportFile(`#export-${format}`);
    assert.match(await page.locator('#status').textContent(), /Open file reads it back to the same mesh/, format);
    await page.setInputFiles('#file-input', { name: `again.${format}`, mimeType: 'text/plain', buffer: exported.bytes });
    assert.equal(await settle(page), 'done', format);
    assert.deepEqual(await readStats(page), before, `${format} opens again to the same mesh`);
  }
  await exportFile('#export-node');
  assert.match(await page.locator('#status').textContent(), /vertices only: a \.node holds no segments, holes or triangles/);
  assert.equal(await page.getAttribute('#status', 'data-kind'), 'warn');
  await exportFile('#export-ele');
  assert.match(await page.locator('#status').textContent(), /triangles only.*an \.ele holds no coordinates/);
});

test('exports .node, .ele, .msh, .vtu and .geojson downloads whose headers match the mesh', async () => {
  await page.setInputFiles('#file-input', { name: 'pentagon-with-hole.poly', mimeType: 'text/plain', buffer: Buffer.from(PENTAGON) });
  assert.equal(await settle(page), 'done');
  const { vertices, triangles } = await readStats(page);
  const firstLine = (file) => file.bytes.toString('utf8').split('\n')[0].trim().split(/\s+/).map(Number);

  const node = await exportFile('#export-node');
  assert.equal(node.name, 'ruppert-mesh.node');
  const [n, dimension] = firstLine(node);
  assert.ok(n >= vertices && dimension === 2, `.node header ${firstLine(node)} for ${vertices} vertices`);
  const ele = await exportFile('#export-ele');
  assert.equal(ele.name, 'ruppert-mesh.ele');
  assert.deepEqual(firstLine(ele).slice(0, 2), [triangles, 3]);

  const msh = await exportFile('#export-msh');
  assert.equal(msh.name, 'ruppert-mesh.msh');
  const mshText = msh.bytes.toString('utf8');
  assert.ok(mshText.startsWith('$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n'), mshText.slice(0, 80));
  const elements = Number(mshText.split('$Elements\n')[1].split(/\s+/)[1]);
  assert.ok(elements > triangles, `${elements} elements: ${triangles} triangles and the boundary lines`);

  const vtu = (await exportFile('#export-vtu')).bytes.toString('utf8');
  assert.ok(vtu.startsWith('<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid"'), vtu.slice(0, 80));
  // The triangles, then the boundary's subsegments as lines (as the .msh has them).
  const types = /Name="types"[^>]*>([^<]*)</.exec(vtu)[1].trim().split(/\s+/).map(Number);
  assert.equal(types.filter((t) => t === 5).length, triangles);
  assert.ok(types.filter((t) => t === 3).length >= 8, 'the pentagon\'s and the hole\'s segments as lines');
  assert.match(vtu, new RegExp(`NumberOfCells="${types.length}"`));

  const geojson = await exportFile('#export-geojson');
  assert.equal(geojson.name, 'ruppert-mesh.geojson');
  const collection = JSON.parse(geojson.bytes.toString('utf8'));
  assert.equal(collection.type, 'FeatureCollection');
  assert.equal(collection.features.length, triangles);

  // The exported GeoJSON opens again: the triangles as polygons, the pentagon's hole left empty.
  await page.setInputFiles('#file-input', { name: 'again.geojson', mimeType: 'application/geo+json', buffer: geojson.bytes });
  assert.equal(await settle(page), 'done');
  const drawing = await page.evaluate(async () => (await import('./io/url-state.js')).decodeDrawing(location.hash));
  assert.equal(drawing.holes.length, 2, 'one hole seed, computed by parseGeoJson');
  assert.deepEqual(errors, []);
});

test('the URL reproduces the drawing and its parameters', async () => {
  await page.selectOption('#preset', 'skyline');
  await page.fill('#min-angle', '25');
  await page.press('#min-angle', 'Tab');
  await page.selectOption('#placement', 'circumcenter');
  assert.equal(await settle(page), 'done');
  const stats = await readStats(page);
  const other = await harness.context.newPage();
  await other.goto(page.url());
  assert.equal(await settle(other), 'done');
  assert.deepEqual(await readStats(other), stats);
  assert.equal(await other.inputValue('#min-angle'), '25');
  assert.equal(await other.inputValue('#placement'), 'circumcenter');
  await other.close();
});

test('no console errors', () => {
  assert.deepEqual(errors, []);
});
