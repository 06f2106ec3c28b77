// Curves on the page: the circle, arc and Bézier tools driven by the mouse, meshing on
// the curves (every boundary vertex of a curve on it), the exports (.msh, .vtu, the mesh's .json and
// the drawing's .json with its curves, read back by the file panel), dragging a handle, undo,
// Delete, and a replay step that splits a curve's piece. And the
// whole round trip: a plate with a round hole drawn with the circle tool, meshed and exported.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { after, before, test } from 'node:test';
import { SCREENSHOTS, clickCanvas, launch, moveOnCanvas, openPage, readStats, settle, openExportMenu } from './harness.mjs';
import { bezierAt, distanceToBezier } from '../package/bezier-math.mjs';

let harness;
let page;
let errors;

before(async () => {
  harness = await launch();
  // ?bench=1 gives the test the page's view (window.ruppertBench) to find handles on screen.
  ({ page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/?bench=1`));
  await settle(page);
});

after(async () => {
  await harness?.close();
});

const linked = () => page.evaluate(async () => (await import('./io/url-state.js')).decodeDrawing(location.hash));
const toScreen = (x, y) => page.evaluate(([wx, wy]) => window.ruppertBench.view.toScreen(wx, wy), [x, y]);

async function exportFile(button) {
  if (button.startsWith('#export-')) await openExportMenu(page);
  const [download] = await Promise.all([page.waitForEvent('download'), page.click(button)]);
  return readFileSync(await download.path(), 'utf8');
}

/** Presses at canvas pixel `from`, moves to `to` in steps, releases: a drag. */
async function dragOnCanvas(from, to) {
  const box = await page.locator('#canvas').boundingBox();
  await page.mouse.move(box.x + from[0], box.y + from[1]);
  await page.mouse.down();
  await page.mouse.move(box.x + to[0], box.y + to[1], { steps: 8 });
  await page.mouse.up();
}



/** The vertices of the exported mesh's subsegments that follow curve k (segmentIds = segments + k). */
function curveVertices(mesh, segmentCount, k) {
  const out = new Set();
  mesh.segmentIds.forEach((id, s) => { if (id === segmentCount + k) out.add(mesh.segments[2 * s]).add(mesh.segments[2 * s + 1]); });
  return [...out].map((v) => [mesh.points[2 * v], mesh.points[2 * v + 1]]);
}

test('a plate with a round hole made with the circle tool is meshed on the circle and exported', async () => {
  await page.click('#clear');
  assert.equal(await settle(page), 'empty');
  await page.click('[data-tool="polyline"]');
  for (const [x, y] of [[200, 100], [560, 100], [560, 460], [200, 460], [200, 100]]) await clickCanvas(page, x, y);
  // The circle tool: press at the center, drag to the radius.
  await page.keyboard.press('c');
  assert.equal(await page.getAttribute('[data-tool="circle"]', 'aria-pressed'), 'true');
  await dragOnCanvas([380, 280], [470, 280]);
  await page.click('[data-tool="hole"]');
  await clickCanvas(page, 380, 300);
  assert.equal(await settle(page), 'done');

  const drawing = await linked();
  assert.equal(drawing.curves.length, 2, 'two arcs');
  const [first, second] = drawing.curves;
  assert.deepEqual([first.type, second.type], ['arc', 'arc']);
  assert.deepEqual(first.center, second.center);
  assert.deepEqual([first.from, first.to], [second.to, second.from], 'a closed curve');
  const center = first.center;
  const r = Math.hypot(drawing.points[2 * first.from] - center[0], drawing.points[2 * first.from + 1] - center[1]);
  const stats = await readStats(page);
  assert.equal(stats.complete, 'yes');
  assert.ok(stats.minAngle >= 30 - 1e-9, `min angle ${stats.minAngle}`);

  // The mesh's .json: every vertex of the hole's boundary lies on the circle.
  const mesh = JSON.parse(await exportFile('#export-json'));
  const segmentCount = drawing.segments.length / 2;
  const onHole = [...curveVertices(mesh, segmentCount, 0), ...curveVertices(mesh, segmentCount, 1)];
  assert.ok(onHole.length >= 16, `${onHole.length} vertices on the hole`);
  const worst = Math.max(...onHole.map(([x, y]) => Math.abs(Math.hypot(x - center[0], y - center[1]) - r)));
  assert.ok(worst <= 1e-9, `a hole vertex lies ${worst} off the circle`);
  // No triangle inside the hole: the hole seed took it out.
  assert.equal(mesh.triangles.length / 3, stats.triangles);
  const inside = [];
  for (let t = 0; t < mesh.triangles.length; t += 3) {
    const cx = [0, 1, 2].reduce((sum, i) => sum + mesh.points[2 * mesh.triangles[t + i]], 0) / 3;
    const cy = [0, 1, 2].reduce((sum, i) => sum + mesh.points[2 * mesh.triangles[t + i] + 1], 0) / 3;
    if (Math.hypot(cx - center[0], cy - center[1]) < 0.9 * r) inside.push(t / 3);
  }
  assert.deepEqual(inside, [], 'no triangle in the hole');

  // Solver formats: the .msh and the .vtu hold the same mesh.
  const msh = await exportFile('#export-msh');
  assert.match(msh, /^\$MeshFormat\n4\.1 /);
  assert.equal(Number(/\$Nodes\n\d+ (\d+) /.exec(msh)?.[1]), mesh.points.length / 2, 'every node in the .msh');
  const vtu = await exportFile('#export-vtu');
  assert.ok(vtu.includes(`NumberOfPoints="${mesh.points.length / 2}"`), 'every point in the .vtu');

  // The drawing's .json keeps the curves, and the file panel reads it back to the same mesh.
  const text = await exportFile('#export-drawing-json');
  const saved = JSON.parse(text);
  assert.equal(saved.curves.length, 2);
  assert.deepEqual(saved.curves[0].center, center);
  await page.click('#clear');
  assert.equal(await settle(page), 'empty');
  await page.setInputFiles('#file-input', { name: 'plate.json', mimeType: 'application/json', buffer: Buffer.from(text) });
  assert.equal(await settle(page), 'done');
  assert.equal((await linked()).curves.length, 2, 'the curves came back from the file');
  assert.equal((await readStats(page)).triangles, stats.triangles, 'the same mesh');
  await page.screenshot({ path: `${SCREENSHOTS}curves-plate-circle-tool.png` });
  assert.deepEqual(errors, []);
});

test('the Bézier and arc tools make curved boundaries; the preview shows the curve being made', async () => {
  await page.click('#clear');
  await settle(page);
  // Bézier: start, end, then two control points (the preview follows the pointer before the last).
  await page.keyboard.press('b');
  for (const [x, y] of [[220, 420], [540, 420], [260, 160]]) await clickCanvas(page, x, y);
  await moveOnCanvas(page, 500, 170);
  await page.screenshot({ path: `${SCREENSHOTS}curves-bezier-tool-preview.png` });
  await clickCanvas(page, 500, 170);
  // The chord back from the end to the start closes the region under the cubic.
  await page.keyboard.press('l');
  await clickCanvas(page, 540, 420);
  await clickCanvas(page, 220, 420);
  await page.keyboard.press('Escape');
  assert.equal(await settle(page), 'done');
  const drawing = await linked();
  assert.equal(drawing.curves.length, 1);
  const bezier = drawing.curves[0];
  assert.equal(bezier.type, 'bezier');
  assert.equal(drawing.points.length / 2, 2, 'the chord reuses the Bézier\'s ends');
  const stats = await readStats(page);
  assert.equal(stats.complete, 'yes');
  assert.ok(stats.minAngle >= 30 - 1e-9, `min angle ${stats.minAngle}`);
  const mesh = JSON.parse(await exportFile('#export-json'));
  const c = [drawing.points[2 * bezier.from], drawing.points[2 * bezier.from + 1], ...bezier.controls,
    drawing.points[2 * bezier.to], drawing.points[2 * bezier.to + 1]];
  const size = Math.hypot(c[6] - c[0], c[7] - c[1]);
  const on = curveVertices(mesh, 1, 0);
  assert.ok(on.length >= 8, `${on.length} vertices on the cubic`);
  const worst = Math.max(...on.map((q) => distanceToBezier(c, q)));
  assert.ok(worst <= 1e-9 * size, `a vertex lies ${worst} off the cubic`);
  // Select shows the handles: the picture of the tools in use.
  await page.keyboard.press('v');
  const q = await toScreen(...bezierAt(c, 0.5));
  await clickCanvas(page, q.x, q.y);
  await page.screenshot({ path: `${SCREENSHOTS}curves-bezier-selected.png` });
  // Delete removes the selected curve (the chord stays).
  await page.keyboard.press('Delete');
  assert.equal((await linked()).curves.length, 0, 'Delete removed the curve');
  assert.equal((await linked()).segments.length, 2);

  // Arc: start, end, then the center (put on the ends' bisector): a circular segment with the chord.
  await page.click('#clear');
  await settle(page);
  await page.keyboard.press('a');
  for (const [px, py] of [[500, 400], [260, 400], [390, 330]]) await clickCanvas(page, px, py);
  await page.keyboard.press('l');
  await clickCanvas(page, 260, 400);
  await clickCanvas(page, 500, 400);
  await page.keyboard.press('Escape');
  assert.equal(await settle(page), 'done');
  const arcDrawing = await linked();
  const arc = arcDrawing.curves[0];
  assert.equal(arc.type, 'arc');
  const radius = (i) => Math.hypot(arcDrawing.points[2 * i] - arc.center[0], arcDrawing.points[2 * i + 1] - arc.center[1]);
  assert.ok(Math.abs(radius(arc.from) - radius(arc.to)) <= 1e-12 * radius(arc.from), 'the center is on the bisector');
  assert.equal((await readStats(page)).complete, 'yes');
  assert.deepEqual(errors, []);
});

test('dragging a circle\'s center handle or an end re-meshes with valid arcs; undo restores it', async () => {
  await page.selectOption('#preset', 'plate-round-hole');
  assert.equal(await settle(page), 'done');
  const before = await readStats(page);
  await page.keyboard.press('v');
  const center = await toScreen(0.5, 0.5);
  // Down 30 pixels: the center moves along the vertical bisector of the ends, and the circle grows.
  await dragOnCanvas([center.x, center.y], [center.x + 12, center.y + 30]);
  assert.equal(await settle(page), 'done');
  const dragged = await linked();
  const [a, b] = dragged.curves;
  assert.equal(a.center[0], 0.5, 'the center stays on the bisector x = 0.5');
  assert.ok(a.center[1] < 0.49, `the center moved down to ${a.center[1]}`);
  assert.deepEqual(b.center, a.center, 'both halves of the circle follow');
  const after = await readStats(page);
  assert.notEqual(after.triangles, before.triangles, 'a different mesh');
  assert.equal(after.complete, 'yes');

  await page.keyboard.press('Control+z');
  assert.equal(await settle(page), 'done');
  assert.deepEqual((await linked()).curves[0].center, [0.5, 0.5], 'undo put the center back');
  assert.equal((await readStats(page)).triangles, before.triangles);

  // An end dragged: the arcs' center goes to the new bisector, so both ends stay equidistant.
  const end = await toScreen(0.75, 0.5);
  await dragOnCanvas([end.x, end.y], [end.x + 15, end.y - 10]);
  assert.equal(await settle(page), 'done');
  const moved = await linked();
  const c = moved.curves[0].center;
  const r = (i) => Math.hypot(moved.points[2 * i] - c[0], moved.points[2 * i + 1] - c[1]);
  assert.ok(Math.abs(r(4) - r(5)) <= 1e-12 * r(4), `ends at ${r(4)} and ${r(5)} from the center`);
  assert.deepEqual(moved.curves[1].center, c);
  assert.equal((await readStats(page)).complete, 'yes');
  await page.keyboard.press('Control+z');
  assert.equal(await settle(page), 'done');
  assert.deepEqual(errors, []);
});

test('a selected curve takes a marker: drawn, in the legend, the link and the .msh', async () => {
  await page.selectOption('#preset', 'plate-round-hole');
  assert.equal(await settle(page), 'done');
  await page.keyboard.press('v');
  // The top of the circle: a point of the first arc (counter-clockwise from (0.75, 0.5) to (0.25, 0.5)).
  const top = await toScreen(0.5, 0.75);
  await clickCanvas(page, top.x, top.y);
  assert.equal(await page.isDisabled('#segment-marker'), false, 'the marker field serves the selected curve');
  await page.fill('#segment-marker', '7');
  await page.locator('#segment-marker').dispatchEvent('change');
  assert.equal(await settle(page), 'done');
  assert.deepEqual((await linked()).curves.map((c) => c.marker ?? 0), [7, 0]);
  assert.match(await page.locator('#legend').textContent(), /segment marker 7/);
  const msh = await exportFile('#export-msh');
  assert.ok(msh.includes('"marker 7"'), 'a physical group for the curve\'s marker');
  await page.screenshot({ path: `${SCREENSHOTS}curves-marker.png` });
  assert.deepEqual(errors, []);
});

test('a replay step that splits a curve\'s piece says so and draws it', async () => {
  await page.selectOption('#preset', 'plate-round-hole');
  assert.equal(await settle(page), 'done');
  // A coarse tolerance and an area bound: refinement splits pieces of the circle (at step 54).
  await page.fill('#curve-tolerance', '0.05');
  await page.locator('#curve-tolerance').dispatchEvent('change');
  await page.fill('#max-area', '0.01');
  await page.locator('#max-area').dispatchEvent('change');
  await settle(page);
  await page.check('#step-mode');
  assert.equal(await settle(page), 'done');
  const count = Number(await page.getAttribute('#step-scrub', 'max'));
  let found = -1;
  let text = '';
  for (let k = 1; k <= count && found < 0; k++) {
    await page.evaluate((step) => {
      const scrub = document.getElementById('step-scrub');
      scrub.value = String(step);
      scrub.dispatchEvent(new Event('input'));
    }, k);
    text = await page.locator('#step-info').textContent();
    if (/curve \d+ split at \(/i.test(text)) found = k;
  }
  assert.ok(found > 0, 'a step splits a piece of the circle');
  assert.match(text, /curve [01] split at \([\d.]+, [\d.]+\)( instead)? \(on the curve, not on the chord/i);
  await page.waitForFunction((k) => document.body.dataset.stepShown === String(k), found);
  assert.match(await page.locator('#step-legend').textContent(), /a curve's piece split on the curve/);
  assert.match(await page.locator('#stat-events').textContent(), /rejected circumcenter/);
  await page.screenshot({ path: `${SCREENSHOTS}curves-replay-split.png` });
  await page.uncheck('#step-mode');
  await settle(page);
  assert.deepEqual(errors, []);
});
