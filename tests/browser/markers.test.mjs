// Boundary markers on the page: segment markers kept from a loaded .poly, shown (a color and a
// label per marker, in the legend too), set per segment in the editor, kept in the link, and
// written by every export (.poly, .msh physical groups, .vtu point markers, .geojson edge markers,
// the drawing's .poly).
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { after, before, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { decodeDrawing } from '../../web/io/url-state.js';
import { toMeshOptions } from '../../web/model/drawing.js';
import { SCREENSHOTS, launch, openPage, settle, openExportMenu } from './harness.mjs';

let harness;
let page;
let errors;

before(async () => {
  harness = await launch();
  ({ page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/`));
  await settle(page);
});

after(async () => {
  await harness?.close();
});

// A square (markers 1, 2, 3 on its sides, 3 on the left too) with a square hole (marker 4).
const MARKED = `8 2 0 0
0 0 0
1 10 0
2 10 10
3 0 10
4 4 4
5 6 4
6 6 6
7 4 6
8 1
0 0 1 1
1 1 2 2
2 2 3 3
3 3 0 3
4 4 5 4
5 5 6 4
6 6 7 4
7 7 4 4
1
0 5 5
`;

// The CLI's flags for the mesher's options the page sets.
const CLI_FLAGS = {
  minAngle: '--min-angle', maxAngle: '--max-angle', maxArea: '--max-area', maxSteiner: '--max-steiner',
  placement: '--placement', encroachment: '--encroachment', variant: '--variant',
};

async function exportFile(button) {
  if (button.startsWith('#export-')) await openExportMenu(page);
  const [download] = await Promise.all([page.waitForEvent('download'), page.click(button)]);
  return readFileSync(await download.path(), 'utf8');
}

test('markers 1-4 of a loaded .poly are shown and written by every export', async () => {
  await page.setInputFiles('#file-input', { name: 'marked.poly', mimeType: 'text/plain', buffer: Buffer.from(MARKED) });
  assert.equal(await settle(page), 'done');
  const legend = await page.locator('#legend').textContent();
  for (const m of [1, 2, 3, 4]) assert.ok(legend.includes(`segment marker ${m}`), legend);
  await page.screenshot({ path: `${SCREENSHOTS}markers-loaded.png` });

  // .msh: a physical group per marker.
  const msh = await exportFile('#export-msh');
  for (const m of [1, 2, 3, 4]) assert.ok(msh.includes(`1 ${m} "marker ${m}"`), `marker ${m} in the .msh`);
  // .poly: the subsegments with their markers.
  const poly = await exportFile('#export-poly');
  const [header] = poly.split('\n').filter((l) => !l.startsWith('#')).filter((l, i, all) => i > 0 && /^\d+ 1$/.test(l));
  assert.ok(header, 'a segment header with a marker column');
  const polyMarkers = new Set(poly.split('\n').filter((l) => /^\d+ \d+ \d+ \d+$/.test(l)).map((l) => Number(l.split(' ')[3])));
  for (const m of [1, 2, 3, 4]) assert.ok(polyMarkers.has(m), `marker ${m} in the .poly`);
  // .vtu: the point markers carry them, and the boundary's line cells their segment markers.
  const vtu = await exportFile('#export-vtu');
  const array = (name) => new RegExp(`Name="${name}"[^>]*>([^<]*)<`).exec(vtu)?.[1].trim().split(/\s+/).map(Number) ?? [];
  const pointMarkers = array('pointMarker');
  for (const m of [1, 2, 3, 4]) assert.ok(pointMarkers.includes(m), `marker ${m} in the .vtu's points`);
  const types = array('types');
  const cellMarkers = array('segmentMarker');
  assert.equal(cellMarkers.length, types.length, 'one segment marker a cell');
  assert.equal(Number(/NumberOfCells="(\d+)"/.exec(vtu)[1]), types.length);
  const lineMarkers = new Set(cellMarkers.filter((_, c) => types[c] === 3));
  assert.deepEqual([...lineMarkers].sort(), [1, 2, 3, 4], 'the lines carry markers 1-4');
  assert.ok(cellMarkers.every((m, c) => types[c] === 3 || m === 0), 'the triangles have none');
  for (const name of ['regionAttribute', 'minAngle']) assert.equal(array(name).length, types.length, `${name}: one value a cell`);
  // The core's writer made it: the CLI's --format vtu of the same input, with the page's options
  // (the package's defaults), is the same text. The native CLI's too, when it is built, but for the
  // last digits of the smallest angles, which come from the C library's atan2 (glibc's there,
  // Emscripten's here): those are compared to 12 significant digits.
  const roundAngles = (text) => text.replace(/(Name="minAngle" format="ascii">)([^<]*)</,
    (all, open, values) => `${open}${values.trim().split(/\s+/).map((v) => Number(v).toPrecision(12)).join(' ')}<`);
  const options = toMeshOptions(decodeDrawing(await page.evaluate(() => location.hash)));
  const flags = Object.entries(CLI_FLAGS).flatMap(([key, flag]) => (options[key] === undefined ? [] : [flag, String(options[key])]));
  assert.ok(flags.includes('--max-area'), `the page's options, the lake's max area among them: ${flags.join(' ')}`);
  const dir = mkdtempSync(join(tmpdir(), 'ruppert-vtu-'));
  try {
    writeFileSync(join(dir, 'marked.poly'), MARKED);
    const cliVtu = (command, args) => {
      const run = spawnSync(command, [...args, ...flags, '--format', 'vtu', '-o', join(dir, 'cli'), join(dir, 'marked.poly')], { encoding: 'utf8' });
      assert.equal(run.status, 0, run.stderr);
      return readFileSync(join(dir, 'cli.vtu'), 'utf8');
    };
    assert.equal(vtu, cliVtu(process.execPath, [fileURLToPath(new URL('../../wasm/cli.js', import.meta.url))]), 'the package CLI\'s .vtu');
    const native = fileURLToPath(new URL('../../build-native/core/ruppert', import.meta.url));
    if (existsSync(native)) assert.equal(roundAngles(vtu), roundAngles(cliVtu(native, [])), 'the native CLI\'s .vtu');
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
  // .geojson: each triangle's edge markers.
  const geojson = JSON.parse(await exportFile('#export-geojson'));
  const edgeMarkers = new Set(geojson.features.flatMap((f) => f.properties.edgeMarkers));
  for (const m of [0, 1, 2, 3, 4]) assert.ok(edgeMarkers.has(m), `marker ${m} in the .geojson`);
  // The drawing's .poly keeps them too.
  const drawing = await exportFile('#export-drawing');
  assert.match(drawing, /\n8 1\n0 0 1 1\n1 1 2 2\n2 2 3 3\n3 3 0 3\n4 4 5 4\n/);
  // And the link.
  const linked = await page.evaluate(async () => (await import('./io/url-state.js')).decodeDrawing(location.hash));
  assert.deepEqual(linked.segmentMarkers, [1, 2, 3, 3, 4, 4, 4, 4]);
  assert.deepEqual(errors, []);
});

test('a segment selected in the editor gets a marker', async () => {
  await page.selectOption('#preset', 'square-hole');
  assert.equal(await settle(page), 'done');
  assert.equal(await page.isDisabled('#segment-marker'), true);
  // Select the bottom side (segment 0, from (0, 0) to (10, 0)) at its middle.
  await page.click('[data-tool="select"]');
  const box = await page.locator('#canvas').boundingBox();
  const point = await page.evaluate(async () => {
    const { decodeDrawing } = await import('./io/url-state.js');
    return decodeDrawing(location.hash).points.slice(0, 4);
  });
  assert.deepEqual(point, [0, 0, 10, 0]);
  // The view fits the 10 x 10 square: find the bottom side's middle by scanning for the enabled field.
  let selected = false;
  for (let y = box.height - 5; y > box.height / 2 && !selected; y -= 3) {
    await page.mouse.click(box.x + box.width / 2, box.y + y);
    selected = !(await page.isDisabled('#segment-marker'));
  }
  assert.ok(selected, 'a segment was selected');
  await page.fill('#segment-marker', '7');
  await page.locator('#segment-marker').dispatchEvent('change');
  assert.equal(await settle(page), 'done');
  const linked = await page.evaluate(async () => (await import('./io/url-state.js')).decodeDrawing(location.hash));
  assert.equal(linked.segmentMarkers.filter((m) => m === 7).length, 1);
  assert.match(await page.locator('#legend').textContent(), /segment marker 7/);
  const msh = await exportFile('#export-msh');
  assert.ok(msh.includes('"marker 7"'), 'the new marker is a physical group');
  await page.screenshot({ path: `${SCREENSHOTS}markers-edited.png` });
  assert.deepEqual(errors, []);
});
