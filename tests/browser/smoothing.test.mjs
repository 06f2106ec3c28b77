// What smoothing and the max angle do, as the page shows them: the Parameters panel's fields reach
// the mesher, the Mesh panel's Smoothing block compares the mesh with the same mesh unsmoothed,
// and step mode ends on one step, the smoothing.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { init } from '../../wasm/index.js';
import { toMeshOptions, toPlc } from '../../web/model/drawing.js';
import { movedVertices, smallestAngleSummary } from '../../web/geometry/mesh-geometry.js';
import { decodeDrawing } from '../../web/io/url-state.js';
import { launch, openPage, readStats, settle } from './harness.mjs';

let harness;
let page;
let errors;
let mesher;

before(async () => {
  harness = await launch();
  ({ page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/`));
  await settle(page);
  mesher = await init();
});

after(async () => {
  await harness?.close();
});

/** The page's drawing and options, as its link has them (the panel's fields included). */
async function pageMeshes() {
  await page.waitForTimeout(300);  // the link is written a moment after a change
  const drawing = decodeDrawing(await page.evaluate(() => location.hash));
  return { plc: toPlc(drawing), options: toMeshOptions(drawing) };
}

const smoothingShown = () => page.waitForFunction(() => document.body.dataset.smoothingState === 'shown', null, { timeout: 20_000 });

/** Pixels of the smoothing histogram near an RGB color. */
const pixelsOf = (rgb) => page.evaluate((c) => {
  const canvas = document.getElementById('smoothing-histogram');
  const data = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
  let n = 0;
  for (let i = 0; i < data.length; i += 4) {
    if (Math.abs(data[i] - c[0]) + Math.abs(data[i + 1] - c[1]) + Math.abs(data[i + 2] - c[2]) < 30 && data[i + 3] > 200) n++;
  }
  return n;
}, rgb);

test('the max angle field bounds the mesh as the package does', async () => {
  await page.selectOption('#preset', 'lake');
  await settle(page);
  await page.fill('#max-angle', '100');
  await page.locator('#max-angle').dispatchEvent('change');
  assert.equal(await settle(page), 'done');
  const stats = await readStats(page);
  const { plc, options } = await pageMeshes();
  assert.equal(options.maxAngle, 100);
  const expected = mesher.triangulate(plc, options);
  assert.equal(stats.triangles, expected.stats.triangles);
  assert.ok(stats.maxAngle <= 100, `largest angle ${stats.maxAngle}`);
  const unbounded = mesher.triangulate(plc, { ...options, maxAngle: 0 });
  assert.ok(unbounded.stats.maxAngle > 100, 'the bound changes this mesh');
  await page.fill('#max-angle', '');
  await page.locator('#max-angle').dispatchEvent('change');
  await settle(page);
});

test('a smoothed mesh shows its smallest angles before and after smoothing', async () => {
  assert.equal(await page.locator('#smoothing-effect').isHidden(), true, 'no block without smoothing');
  await page.check('#smooth');
  assert.equal(await settle(page), 'done');
  await smoothingShown();
  const { plc, options } = await pageMeshes();
  assert.equal(options.smooth, true);
  const smoothed = mesher.triangulate(plc, options);
  const unsmoothed = mesher.triangulate(plc, { ...options, smooth: 0 });
  const before = smallestAngleSummary(unsmoothed);
  const after = smallestAngleSummary(smoothed);
  const moved = movedVertices(unsmoothed, smoothed);
  assert.ok(after.mean > before.mean, `smoothing raised the mean smallest angle: ${before.mean} -> ${after.mean}`);
  assert.ok(moved > 0);
  const shown = await page.locator('#smoothing-effect').evaluate((box) => ({ ...box.dataset }));
  assert.equal(Number(shown.beforeMean), before.mean);
  assert.equal(Number(shown.afterMean), after.mean);
  assert.equal(Number(shown.beforeObtuse), before.obtuse);
  assert.equal(Number(shown.afterObtuse), after.obtuse);
  assert.equal(Number(shown.moved), moved);
  assert.equal(await page.locator('#smoothing-mean').textContent(), `${before.mean.toFixed(2)}° before, ${after.mean.toFixed(2)}° after`);
  assert.equal(await page.locator('#smoothing-obtuse').textContent(),
    `${before.obtuse} before, ${after.obtuse} after, of ${after.triangles.toLocaleString('en-US')}`);
  assert.equal(await page.locator('#smoothing-moved').textContent(), `${moved} of ${smoothed.points.length / 2}`);
  // The bars (after) and the outline (before) are both drawn.
  assert.ok(await pixelsOf([0x3b, 0x5b, 0xdb]) > 50, 'bars of the smoothed mesh');
  assert.ok(await pixelsOf([0xe8, 0x59, 0x0c]) > 50, 'outline of the unsmoothed mesh');
  // The panel's own counts are the smoothed mesh's.
  assert.equal((await readStats(page)).minAngle, Number(smoothed.stats.minAngle.toFixed(2)));
});

test('step mode ends on one step, the smoothing, from the refined mesh to the smoothed one', async () => {
  await page.check('#step-mode');
  assert.equal(await settle(page), 'done');
  await smoothingShown();
  const { plc, options } = await pageMeshes();
  const traced = mesher.triangulate(plc, { ...options, trace: true });
  const events = traced.events.count;
  const unsmoothed = mesher.triangulate(plc, { ...options, smooth: 0 });
  const moved = movedVertices(unsmoothed, traced);
  await page.click('#step-last');
  await page.waitForFunction((k) => document.body.dataset.stepShown === String(k), events + 1);
  const last = await page.locator('#step-info').textContent();
  assert.equal(last, `Step ${(events + 1).toLocaleString('en-US')} of ${(events + 1).toLocaleString('en-US')}: ` +
    `Smoothing: ${moved.toLocaleString('en-US')} vertices moved; the refined mesh of the step before, smoothed into the final mesh.`);
  assert.equal((await readStats(page)).maxAngle, Number(traced.stats.maxAngle.toFixed(2)), 'the last step is the smoothed mesh');
  // The step before: the refined mesh, not smoothed.
  await page.click('#step-back');
  await page.waitForFunction((k) => document.body.dataset.stepShown === String(k), events);
  assert.match(await page.locator('#step-info').textContent(), new RegExp(`^Step ${events.toLocaleString('en-US')} of `));
  const refined = mesher.triangulate(plc, { ...options, smooth: 0, maxSteiner: events });
  const stats = await readStats(page);
  assert.equal(stats.triangles, refined.stats.triangles);
  assert.equal(stats.minAngle, Number(refined.stats.minAngle.toFixed(2)));
  // Smoothing changed the largest angle: the panel shows the refined mesh's here, the smoothed one's last.
  assert.notEqual(refined.stats.maxAngle.toFixed(2), traced.stats.maxAngle.toFixed(2));
  assert.equal(stats.maxAngle, Number(refined.stats.maxAngle.toFixed(2)));
  await page.uncheck('#step-mode');
  await settle(page);
});

test('turning smoothing off hides the block', async () => {
  await page.uncheck('#smooth');
  assert.equal(await settle(page), 'done');
  assert.equal(await page.locator('#smoothing-effect').isHidden(), true);
  assert.equal(await page.evaluate(() => document.body.dataset.smoothingState), 'none');
});

test('no console errors', () => {
  assert.deepEqual(errors, []);
});
