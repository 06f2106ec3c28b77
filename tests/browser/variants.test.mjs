// The Algorithm (options.variant) and Encroachment (options.encroachment) controls: the comb of
// Figure 6.16 meshed by constrained Delaunay refinement and by Ruppert's original bounding-box
// algorithm, closed diametral disks, and links that carry (or predate) the two options.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { presetDrawing } from '../../web/panels/presets.js';
import { SCREENSHOTS, launch, openPage, readStats, settle } from './harness.mjs';

let harness;
let page;
let errors;
let cdtTriangles;

before(async () => {
  harness = await launch();
  ({ page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/`));
  assert.equal(await settle(page), 'done');
});

after(async () => {
  await harness?.close();
});

const decodeHash = (p) => p.evaluate(async () => (await import('./io/url-state.js')).decodeDrawing(location.hash));

/** A link in the compact format of url-state.js, built here by hand so the decoder is really tested. */
function link(drawing, o) {
  const compact = { v: 1, p: drawing.points, s: drawing.segments, h: drawing.holes, r: [], o };
  return `${harness.baseUrl}/web/#d=${Buffer.from(JSON.stringify(compact)).toString('base64url')}`;
}

async function assertValidMesh(p, what) {
  assert.equal(await settle(p), 'done', what);
  const stats = await readStats(p);
  assert.equal(stats.complete, 'yes', `${what}: complete`);
  assert.ok(stats.triangles > 0, `${what}: ${stats.triangles} triangles`);
  assert.ok(stats.minAngle >= 30 - 1e-9, `${what}: min angle ${stats.minAngle}`);
  assert.equal(await p.locator('#notices li').count(), 0, `${what}: no notices or errors`);
  assert.doesNotMatch(await p.locator('#status').textContent(), /error|failed/i, what);
  return stats;
}

test('the two controls are labeled selects with the defaults', async () => {
  assert.equal(await page.getByLabel('Algorithm', { exact: true }).inputValue(), 'cdt');
  assert.equal(await page.getByLabel('Encroachment', { exact: true }).inputValue(), 'lens');
  const options = await page.locator('#variant option').allTextContents();
  assert.deepEqual(options, ['Constrained Delaunay (CDT)', "Delaunay in a bounding box (Ruppert's original)"]);
  assert.deepEqual(await page.locator('#encroachment option').allTextContents(), ['Diametral lens', 'Diametral disk']);
  // The long option text must not push the select out of the panel.
  const panel = await page.locator('#panel').boundingBox();
  for (const id of ['#variant', '#encroachment']) {
    const box = await page.locator(id).boundingBox();
    assert.ok(box.x + box.width <= panel.x + panel.width, `${id} ends at ${box.x + box.width}, panel at ${panel.x + panel.width}`);
  }
});

test('the comb preset tells how to compare the algorithms, and loads with CDT', async () => {
  const option = page.locator('#preset option[value="comb"]');
  assert.match(await option.textContent(), /Fig\. 6\.16/);
  assert.match(await option.getAttribute('title'), /bounding box/);
  await page.selectOption('#preset', 'comb');
  const stats = await assertValidMesh(page, 'comb, CDT');
  cdtTriangles = stats.triangles;
  assert.equal(await page.locator('#variant').inputValue(), 'cdt', 'loading the preset changes no option');
  // The geometry really has narrow exterior gaps: gaps much narrower than the teeth.
  const xs = presetDrawing('comb').points.filter((_, i) => i % 2 === 0);
  const distinct = [...new Set(xs)].sort((a, b) => a - b);
  const steps = distinct.slice(1).map((x, i) => x - distinct[i]);
  assert.ok(Math.min(...steps) <= 0.05 + 1e-12 && Math.max(...steps) >= 1 - 1e-12, `x steps ${steps}`);
});

test('the bounding-box variant, chosen with the keyboard, over-refines the comb', async () => {
  await page.locator('#variant').focus();
  await page.keyboard.press('ArrowDown');
  assert.equal(await page.locator('#variant').inputValue(), 'box');
  const stats = await assertValidMesh(page, 'comb, box');
  assert.ok(stats.triangles >= 2 * cdtTriangles, `box ${stats.triangles} triangles vs CDT ${cdtTriangles}`);
  assert.equal((await decodeHash(page)).options.variant, 'box', 'the link records the variant');
  await page.screenshot({ path: `${SCREENSHOTS}comb-box-variant.png` });

  // Undo brings CDT (and its mesh) back: the option is part of the undo history.
  await page.locator('#canvas').focus();
  await page.keyboard.press('Control+z');
  assert.equal(await page.locator('#variant').inputValue(), 'cdt');
  assert.equal((await assertValidMesh(page, 'comb, undone')).triangles, cdtTriangles);
  await page.keyboard.press('Control+y');
  assert.equal(await page.locator('#variant').inputValue(), 'box');
  assert.equal((await assertValidMesh(page, 'comb, redone')).triangles, stats.triangles);
});

test('diametral disks give a valid, complete mesh', async () => {
  await page.locator('#encroachment').focus();
  await page.keyboard.press('ArrowDown');
  assert.equal(await page.locator('#encroachment').inputValue(), 'disk');
  await assertValidMesh(page, 'comb, box, disk');
  await page.selectOption('#variant', 'cdt');
  const cdtDisk = await assertValidMesh(page, 'comb, CDT, disk');
  // Disks are larger than lenses: they can only ask for as many splits or more.
  assert.ok(cdtDisk.triangles >= cdtTriangles, `disk ${cdtDisk.triangles} vs lens ${cdtTriangles}`);
  await page.selectOption('#variant', 'box');
  await assertValidMesh(page, 'comb, box, disk again');
  assert.deepEqual((await decodeHash(page)).options, {
    minAngle: 30, maxArea: null, placement: 'optimal', maxSteiner: null, variant: 'box', encroachment: 'disk',
    sizeMeasure: false, smooth: false, maxAngle: null,
  });
});

test('a link with the new fields round-trips', async () => {
  const url = page.url();
  const before = await readStats(page);
  const other = await harness.context.newPage();
  await other.goto(url);
  assert.equal(await other.locator('#variant').inputValue(), 'box');
  assert.equal(await other.locator('#encroachment').inputValue(), 'disk');
  assert.equal((await assertValidMesh(other, 'reopened link')).triangles, before.triangles);
  assert.equal(await other.evaluate(() => location.hash), new URL(url).hash, 'the link is written back unchanged');

  // A hand-made link with the new fields reads the same way.
  await other.goto(link(presetDrawing('comb'), [30, 0, 'o', -1, 'b', 'l']));
  await other.reload();  // a hash-only navigation does not reload the page
  assert.equal(await other.locator('#variant').inputValue(), 'box');
  assert.equal(await other.locator('#encroachment').inputValue(), 'lens');
  assert.ok((await assertValidMesh(other, 'hand-made link')).triangles >= 2 * cdtTriangles);
  await other.close();
});

test('an old link without the new fields loads with the defaults', async () => {
  const other = await harness.context.newPage();
  // (Links of the time named the placement: 't', optimal points, the default now.)
  await other.goto(link(presetDrawing('comb'), [30, 0, 't', -1]));
  assert.equal(await other.locator('#placement').inputValue(), 'optimal');
  assert.equal(await other.locator('#variant').inputValue(), 'cdt');
  assert.equal(await other.locator('#encroachment').inputValue(), 'lens');
  assert.equal((await assertValidMesh(other, 'old link')).triangles, cdtTriangles);
  const drawing = await decodeHash(other);
  assert.equal(drawing.options.variant, 'cdt');
  assert.equal(drawing.options.encroachment, 'lens');
  await other.close();
});

test('no console errors', () => {
  assert.deepEqual(errors, []);
});
