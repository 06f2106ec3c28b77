// Presets that teach and a replay that explains: Fig. 6.4's six stages as replay steps with the
// figure's captions, one preset per idea, and in step mode the Mesh panel and the status line of the
// step on screen, a legend for every overlay symbol, the encroachment region as the option in force.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { init } from '../../wasm/index.js';
import { DEFAULT_OPTIONS, toMeshOptions, toPlc } from '../../web/model/drawing.js';
import { triangleShape } from '../../web/geometry/mesh-geometry.js';
import { findPreset } from '../../web/panels/presets.js';
import { SCREENSHOTS, canvasFingerprint, launch, openPage, readStats, settle } from './harness.mjs';

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

const stepShown = (k) => page.waitForFunction((s) => document.body.dataset.stepShown === String(s), k, { timeout: 20_000 });
const text = (id) => page.locator(`#${id}`).textContent();

/** The preset's mesh through the package, with its trace. */
async function packageMesh(id) {
  const preset = findPreset(id);
  const drawing = { ...preset.build(), options: { ...DEFAULT_OPTIONS, ...preset.options } };
  return (await init()).triangulate(toPlc(drawing), toMeshOptions(drawing, { trace: true }));
}

const FIGURE_STAGES = [
  ['(a)', /input PLC/], ['(b)', /Delaunay triangulation of the input vertices/], ['(c)', /split at its midpoint/],
  ['(d)', /considers inserting its circumcenter c/], ['(e)', /c encroaches upon the segment ab.*instead ab is split/],
  ['(f)', /final mesh/],
];

test("Fig. 6.4 replays its six stages with the book's settings and captions", async () => {
  await page.selectOption('#preset', 'figure-6-4');
  assert.equal(await settle(page), 'done');
  // The algorithm of §6.2: circumcenters, diametral disks.
  assert.equal(await page.inputValue('#placement'), 'circumcenter');
  assert.equal(await page.inputValue('#encroachment'), 'disk');
  const mesh = await packageMesh('figure-6-4');
  const count = mesh.events.count;
  assert.ok(count >= 6, `${count} steps`);
  assert.match(await text('step-info'), new RegExp(`^Step 0 of ${count}:`));
  const buttons = await page.locator('#step-stages button').allTextContents();
  assert.deepEqual(buttons, FIGURE_STAGES.map(([label]) => label));
  const steps = [];
  const pictures = new Set();
  for (const [label, caption] of FIGURE_STAGES) {
    await page.click(`#step-stages button[data-label="${label}"]`);
    const index = Number(/^Step ([\d,]+)/.exec(await text('step-info'))[1].replace(/,/g, ''));
    await stepShown(index);
    await page.waitForTimeout(50);
    const stage = await text('step-stage');
    assert.match(stage, new RegExp(`^Fig\\. 6\\.4 \\${label.slice(0, 2)}\\)`), stage);
    assert.match(stage, caption, stage);
    steps.push(index);
    pictures.add(await canvasFingerprint(page));
    await page.screenshot({ path: `${SCREENSHOTS}figure-6-4-stage-${label[1]}.png` });
  }
  // (a) and (b) are step 0 (the input alone, then its triangulation); the others follow in order.
  assert.equal(steps[0], 0);
  assert.equal(steps[1], 0);
  for (let i = 2; i < steps.length; i++) assert.ok(steps[i] > steps[i - 1], `stages at steps ${steps}`);
  assert.equal(steps[5], count);
  assert.equal(pictures.size, 6, 'each stage is a picture of its own');
  // (c) a midpoint split of the bottom edge (0, 1); (e) a rejected circumcenter, ab = (9, 10) split.
  const kinds = mesh.events.kind;
  assert.equal(kinds[steps[2] - 1], 0);
  assert.deepEqual([mesh.events.a[steps[2] - 1], mesh.events.b[steps[2] - 1]].sort(), [0, 1]);
  assert.equal(kinds[steps[4] - 1], 3);
  assert.deepEqual([mesh.events.a[steps[4] - 1], mesh.events.b[steps[4] - 1]].sort((x, y) => x - y), [9, 10]);
  // Stepping off a stage drops its caption.
  await page.click(`#step-stages button[data-label="(e)"]`);
  await page.click('#step-forward');
  assert.equal(await page.locator('#step-stage').isHidden(), true);
  assert.deepEqual(errors, []);
});

test('the Mesh panel and the status line show the step on screen, not the final mesh', async () => {
  await page.selectOption('#preset', 'figure-6-4');
  assert.equal(await settle(page), 'done');
  const mesh = await packageMesh('figure-6-4');
  for (const k of [0, 3, 7]) {
    await page.fill('#step-scrub', String(k));
    await stepShown(k);
    const step = (await init()).triangulate(toPlc({ ...findPreset('figure-6-4').build(), options: {} }),
      { ...toMeshOptions({ ...findPreset('figure-6-4').build(), options: { ...DEFAULT_OPTIONS, ...findPreset('figure-6-4').options } }), maxSteiner: k });
    const stats = await readStats(page);
    assert.equal(stats.triangles, step.stats.triangles, `step ${k}`);
    assert.equal(stats.minAngle.toFixed(2), step.stats.minAngle.toFixed(2), `step ${k}`);
    assert.match(await text('stats-title'), new RegExp(`^Mesh at step ${k} of ${mesh.events.count}`));
    assert.match(await text('status'), new RegExp(`^Step ${k} of ${mesh.events.count}: .*${step.stats.triangles} triangles, smallest angle ${step.stats.minAngle.toFixed(2)}°`));
    await page.screenshot({ path: `${SCREENSHOTS}replay-figure-6-4-step-${k}.png` });
  }
  assert.notEqual((await readStats(page)).triangles, mesh.stats.triangles);
  await page.click('#step-last');
  await stepShown(mesh.events.count);
  assert.equal((await readStats(page)).triangles, mesh.stats.triangles);
  // Leaving step mode: the final mesh and its title again.
  await page.uncheck('#step-mode');
  assert.equal(await settle(page), 'done');
  assert.equal(await text('stats-title'), 'Mesh');
  await page.check('#step-mode');
  assert.equal(await settle(page), 'done');
});

test('the overlay has a legend, its encroachment region as in force, and precise event texts', async () => {
  await page.selectOption('#preset', 'figure-6-4');
  assert.equal(await settle(page), 'done');
  const legend = await text('step-legend');
  for (const symbol of ['the new vertex', 'cavity', 'the triangle split', 'circumcircle', 'considered', 'the encroaching vertex',
    'rejected point', 'concentric shell', 'petal or optimal point', 'relocated vertex']) {
    assert.ok(legend.includes(symbol), `legend: ${symbol} in ${legend}`);
  }
  assert.match(legend, /diametral disk \(encroachment: disk\)/);
  // (e): the rejected circumcenter of a skinny triangle, with the values that decided it.
  await page.click('#step-stages button[data-label="(e)"]');
  assert.match(await text('step-info'), /of skinny triangle \(\d+, \d+, \d+\) \(smallest angle [\d.]+° < bound 30°\) encroached subsegment/);
  const { index } = { index: Number(/^Step ([\d,]+)/.exec(await text('step-info'))[1].replace(/,/g, '')) };
  await stepShown(index);
  await page.waitForTimeout(50);
  const disk = await canvasFingerprint(page);
  // The lens at 30°: angle 120°; the legend and the picture change with the option.
  await page.selectOption('#encroachment', 'lens');
  assert.equal(await settle(page), 'done');
  assert.match(await text('step-legend'), /diametral lens \(encroachment: lens, angle ≥ 120°\)/);
  const lensStep = Number(/^Step ([\d,]+)/.exec(await text('step-info'))[1].replace(/,/g, ''));
  await stepShown(lensStep);
  await page.waitForTimeout(50);
  assert.notEqual(await canvasFingerprint(page), disk, 'the lens is drawn, not the disk');
  await page.screenshot({ path: `${SCREENSHOTS}replay-lens.png` });
  await page.selectOption('#encroachment', 'disk');
  assert.equal(await settle(page), 'done');
  // A triangle split only for its area says so.
  await page.fill('#max-area', '2');
  await page.locator('#max-area').dispatchEvent('change');
  assert.equal(await settle(page), 'done');
  const count = Number(/^Step [\d,]+ of ([\d,]+)/.exec(await text('step-info'))[1].replace(/,/g, ''));
  let large = null;
  for (let k = 1; k <= count && large === null; k++) {
    await page.fill('#step-scrub', String(k));
    const info = await text('step-info');
    if (/too large triangle/.test(info)) large = info;
  }
  assert.ok(large, 'a step splits a triangle that is only too large');
  assert.match(large, /too large triangle \(\d+, \d+, \d+\) \(area [\d.]+ > max 2\)/);
  assert.doesNotMatch(large, /skinny or large/);
  await page.fill('#max-area', '');
  await page.locator('#max-area').dispatchEvent('change');
  assert.equal(await settle(page), 'done');
  assert.deepEqual(errors, []);
});

test('one preset per idea, each with a caption, screenshot and its options', async () => {
  for (const [id, options] of [
    ['encroachment', { placement: 'circumcenter', encroachment: 'disk' }],
    ['shells', { placement: 'circumcenter' }],
    ['placement-circumcenter', { placement: 'circumcenter' }],
    ['placement-offcenter', { placement: 'offcenter' }],
  ]) {
    await page.selectOption('#preset', id);
    assert.equal(await settle(page), 'done', id);
    assert.ok((await text('preset-caption')).length > 20, id);
    for (const [name, value] of Object.entries(options)) assert.equal(await page.inputValue(`#${name}`), value, `${id} ${name}`);
    await page.screenshot({ path: `${SCREENSHOTS}preset-${id}.png` });
  }
  // The two placements on the same input: off-centers make several times fewer triangles.
  const circum = await packageMesh('placement-circumcenter');
  const off = await packageMesh('placement-offcenter');
  assert.ok(circum.stats.triangles > 3 * off.stats.triangles, `${circum.stats.triangles} vs ${off.stats.triangles}`);
  // The shells preset splits on a concentric shell somewhere in its replay.
  await page.selectOption('#preset', 'shells');
  assert.equal(await settle(page), 'done');
  const count = Number(/^Step [\d,]+ of ([\d,]+)/.exec(await text('step-info'))[1].replace(/,/g, ''));
  let shell = false;
  for (let k = 1; k <= count && !shell; k++) {
    await page.fill('#step-scrub', String(k));
    shell = /on the concentric shell/.test(await text('step-info'));
    if (shell) {
      await stepShown(k);
      await page.screenshot({ path: `${SCREENSHOTS}preset-shells-shell-split.png` });
    }
  }
  assert.ok(shell, 'a shell split in the shells preset');
  assert.deepEqual(errors, []);
});

test('the presets of one idea each exist: encroachment, shells, small input angles, placements, size measure', async () => {
  for (const id of ['encroachment', 'shells', 'fan', 'placement-compare', 'size-measure']) assert.ok(findPreset(id), id);
});

test('off-centers against circumcenters: both meshes side by side, each with its count and smallest angle', async () => {
  const done = () => page.waitForFunction(() => document.getElementById('compare').dataset.state === 'done', null, { timeout: 20_000 });
  await page.selectOption('#preset', 'placement-compare');
  assert.equal(await settle(page), 'done');
  await done();
  assert.equal(await page.locator('#canvas-wrap').isHidden(), true, 'the comparison takes the canvas\'s place');
  const sides = page.locator('#compare .compare-side');
  assert.equal(await sides.count(), 2);
  const [left, right] = [await sides.nth(0).locator('canvas').boundingBox(), await sides.nth(1).locator('canvas').boundingBox()];
  assert.ok(Math.abs(left.y - right.y) < 1 && right.x >= left.x + left.width, 'side by side');
  assert.ok(left.width > 200 && left.height > 150, `each picture ${left.width} x ${left.height}`);
  const read = async () => (await sides.locator('figcaption').allTextContents()).map((caption) => {
    const match = /^(.+): ([\d,]+) triangles, smallest angle ([\d.]+)°$/.exec(caption);
    assert.ok(match, caption);
    return { name: match[1], triangles: Number(match[2].replace(/,/g, '')), minAngle: Number(match[3]) };
  });
  const [circum, off] = await read();
  assert.match(circum.name, /circumcenter/);
  assert.match(off.name, /off-center/);
  // The package's meshes of the same input and angle, one per placement.
  const preset = findPreset('placement-compare');
  const drawing = { ...preset.build(), options: { ...DEFAULT_OPTIONS, ...preset.options } };
  const mesher = await init();
  const mesh = (placement) => mesher.triangulate(toPlc(drawing), { ...toMeshOptions(drawing), placement });
  assert.equal(circum.triangles, mesh('circumcenter').stats.triangles);
  assert.equal(off.triangles, mesh('offcenter').stats.triangles);
  assert.ok(circum.triangles > 3 * off.triangles, `${circum.triangles} vs ${off.triangles}`);
  for (const side of [circum, off]) assert.ok(side.minAngle >= 33 - 0.005, `${side.name} ${side.minAngle}`);
  assert.match(await text('preset-caption'), /compare the triangle counts/);
  await page.screenshot({ path: `${SCREENSHOTS}preset-placement-compare.png` });
  // Another angle: both sides are meshed again at it.
  await page.fill('#min-angle', '25');
  await page.press('#min-angle', 'Enter');
  assert.equal(await settle(page), 'done');
  await page.waitForFunction(() => document.getElementById('compare').dataset.state === 'done' &&
    / 2\d\.\d\d°/.test(document.querySelector('#compare figcaption').textContent), null, { timeout: 20_000 });
  const [circum25, off25] = await read();
  assert.ok(circum25.triangles < circum.triangles && off25.triangles <= off.triangles, 'fewer triangles at 25°');
  // Closing brings the canvas back; another preset too.
  await page.click('#compare-close');
  assert.equal(await page.locator('#canvas-wrap').isVisible(), true);
  assert.equal(await page.locator('#compare').isHidden(), true);
  await page.selectOption('#preset', 'placement-compare');
  await settle(page);
  await done();
  await page.selectOption('#preset', 'skyline');
  await settle(page);
  assert.equal(await page.locator('#compare').isHidden(), true);
  assert.equal(await page.locator('#canvas-wrap').isVisible(), true);
  assert.deepEqual(errors, []);
});

test('the size measure: a small feature far from a large one, graded, with the integral in the Mesh panel', async () => {
  await page.selectOption('#preset', 'size-measure');
  assert.equal(await settle(page), 'done');
  assert.equal(await page.isChecked('#size-measure'), true);
  assert.match(await text('preset-caption'), /size measure.*Look at/i);
  const row = await text('stat-size-measure');
  const match = /^∫1\/lfs² = ([\d.]+); ([\d.]+) triangles per unit$/.exec(row);
  assert.ok(match, row);
  const preset = findPreset('size-measure');
  const drawing = { ...preset.build(), options: { ...DEFAULT_OPTIONS, ...preset.options } };
  const mesh = (await init()).triangulate(toPlc(drawing), toMeshOptions(drawing));
  assert.ok(Math.abs(Number(match[1]) - mesh.stats.lfsIntegral) <= 0.001 * mesh.stats.lfsIntegral, `${match[1]} vs ${mesh.stats.lfsIntegral}`);
  // Graded: the triangles near the small feature are far smaller than those far from it.
  const areas = Array.from({ length: mesh.triangles.length / 3 }, (_, t) => triangleShape(mesh, t).area);
  assert.ok(Math.max(...areas) > 100 * Math.min(...areas), `areas ${Math.min(...areas)} to ${Math.max(...areas)}`);
  await page.screenshot({ path: `${SCREENSHOTS}preset-size-measure.png` });
  // The link keeps the option; without it the row says how to turn it on.
  const { decodeDrawing } = await import('../../web/io/url-state.js');
  assert.equal(decodeDrawing(await page.evaluate(() => location.hash)).options.sizeMeasure, true);
  await page.uncheck('#size-measure');
  assert.equal(await settle(page), 'done');
  assert.match(await text('stat-size-measure'), /^off/);
  assert.deepEqual(errors, []);
});
