// The embed protocol (web/io/embed.js, docs/course-site.md) from a host page of ANOTHER origin: the
// frame comes from the page's server, the host from a second server on another port.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { after, before, test } from 'node:test';
import { init, parsePoly } from '../../wasm/index.js';
import { DEFAULT_OPTIONS, toMeshOptions, toPlc } from '../../web/model/drawing.js';
import { findPreset } from '../../web/panels/presets.js';
import { SCREENSHOTS, launch, openPage, startHostPage } from './harness.mjs';

const VERSION = JSON.parse(readFileSync(new URL('../../package.json', import.meta.url), 'utf8')).version;
const RECTANGLE = '4 2 0 0\n0 0 0\n1 6 0\n2 6 1\n3 0 1\n4 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n0\n';
const RECTANGLE_PLC = { points: [0, 0, 6, 0, 6, 1, 0, 1], segments: [0, 1, 1, 2, 2, 3, 3, 0] };
// Segment markers 1-4 and a region attribute: the mesh message carries both.
const MARKED = '4 2 0 1\n0 0 0 1\n1 4 0 2\n2 4 3 3\n3 0 3 4\n4 1\n0 0 1 1\n1 1 2 2\n2 2 3 3\n3 3 0 4\n0\n1\n0 2 1.5 7 0\n';

let harness;
let host;
let hostUrl;
let mesher;

before(async () => {
  harness = await launch();
  host = await startHostPage(harness.baseUrl);
  hostUrl = host.url;
  assert.notEqual(new URL(hostUrl).origin, host.frameOrigin, 'the host is of another origin');
  mesher = await init();
});

after(async () => {
  await harness?.close();
  await host?.close();
});

/** A fresh host page whose frame has said it is ready and meshed its default drawing. */
async function openHost() {
  const { page, errors } = await openPage(harness.context, hostUrl);
  await page.waitForFunction(() => window.replies.some((r) => r.type === 'ruppert:meshed'), null, { timeout: 20_000 });
  return { page, errors };
}

/** Sends a message; resolves to the first reply of `type` with that id (after any sent before). */
async function ask(page, message, type, timeout = 20_000) {
  const from = await page.evaluate(() => window.replies.length);
  await page.evaluate((m) => window.send(m), message);
  const handle = await page.waitForFunction(([n, t, id]) => window.replies.slice(n).find((r) => r.type === t && r.id === id),
    [from, type, message.id ?? null], { timeout });
  return handle.jsonValue();
}

/** The replies received after index `from`. */
const repliesSince = (page, from) => page.evaluate((n) => window.replies.slice(n), from);

test('the first message is ruppert:ready with the protocol and package versions', async () => {
  const { page, errors } = await openHost();
  const first = await page.evaluate(() => window.replies[0]);
  assert.equal(first.type, 'ruppert:ready');
  assert.equal(first.version, 1);
  assert.equal(first.packageVersion, VERSION);
  assert.ok(first.presets.includes('figure-6-4'));
  assert.deepEqual(first.options, ['minAngle', 'maxAngle', 'smooth', 'maxArea', 'placement', 'variant', 'encroachment', 'maxSteiner']);
  assert.equal((await page.evaluate(() => window.replies.filter((r) => r.type === 'ruppert:ready'))).length, 1);
  // ruppert:hello asks again.
  const again = await ask(page, { type: 'ruppert:hello', id: 'h' }, 'ruppert:ready');
  assert.equal(again.version, 1);
  assert.deepEqual(errors, []);
  await page.close();
});

test('a load with the package\'s option names is meshed once, with its id, as the package meshes it', async () => {
  const { page, errors } = await openHost();
  const options = { minAngle: 25, maxArea: 0.3, placement: 'circumcenter', variant: 'box', encroachment: 'disk', maxSteiner: null };
  const from = await page.evaluate(() => window.replies.length);
  const meshed = await ask(page, { type: 'ruppert:load', id: 'lesson-1', poly: RECTANGLE, options }, 'ruppert:meshed');
  const { maxSteiner, ...given } = options;
  const expected = mesher.triangulate(RECTANGLE_PLC, given);
  assert.equal(meshed.stats.triangles, expected.stats.triangles);
  assert.equal(meshed.stats.vertices, expected.stats.vertices);
  assert.equal(meshed.stats.complete, true);
  // Step mode turned on by a step (the trace is meshed) brings no second ruppert:meshed.
  const stepped = await ask(page, { type: 'ruppert:step', id: 'st', index: 2 }, 'ruppert:stepped');
  assert.equal(stepped.index, 2);
  await page.waitForTimeout(1000);
  const all = (await repliesSince(page, from)).filter((r) => r.type === 'ruppert:meshed');
  assert.deepEqual(all.map((r) => r.id), ['lesson-1'], 'exactly one ruppert:meshed, with the load\'s id');
  // The frame's fields show the load's options.
  const frame = page.frameLocator('#f');
  assert.equal(await frame.locator('#variant').inputValue(), 'box');
  assert.equal(await frame.locator('#encroachment').inputValue(), 'disk');
  // The options not given are the package's defaults, whatever the frame had before.
  const plain = await ask(page, { type: 'ruppert:load', id: 'lesson-2', poly: RECTANGLE }, 'ruppert:meshed');
  assert.equal(plain.stats.triangles, mesher.triangulate(RECTANGLE_PLC, { minAngle: DEFAULT_OPTIONS.minAngle }).stats.triangles);
  assert.equal(await frame.locator('#variant').inputValue(), DEFAULT_OPTIONS.variant);
  // 'algorithm', the old name of 'variant', is still taken.
  const { variant, ...rest } = given;
  const old = await ask(page, { type: 'ruppert:load', id: 3, poly: RECTANGLE, options: { ...rest, algorithm: variant } }, 'ruppert:meshed');
  assert.equal(old.stats.triangles, expected.stats.triangles);
  assert.deepEqual(errors, []);
  await page.close();
});

test('ruppert:getMesh answers with the mesh the stats describe, markers and attributes included', async () => {
  const { page, errors } = await openHost();
  const from = await page.evaluate(() => window.replies.length);
  // Asked right after the load: the answer waits for the load's mesh.
  await page.evaluate((poly) => {
    window.send({ type: 'ruppert:load', id: 'marked', poly, options: { minAngle: 30, maxArea: 0.5 } });
    window.send({ type: 'ruppert:getMesh', id: 'give' });
  }, MARKED);
  await page.waitForFunction((n) => window.replies.slice(n).some((r) => r.type === 'ruppert:mesh'), from, { timeout: 20_000 });
  const replies = await repliesSince(page, from);
  const meshed = replies.find((r) => r.type === 'ruppert:meshed');
  const mesh = replies.find((r) => r.type === 'ruppert:mesh');
  assert.equal(meshed.id, 'marked');
  assert.equal(mesh.id, 'give');
  assert.equal(mesh.points.length / 2, meshed.stats.vertices);
  assert.equal(mesh.triangles.length / 3, meshed.stats.triangles);
  for (const key of ['vertices', 'triangles', 'minAngle', 'maxAngle']) assert.equal(mesh.stats[key], meshed.stats[key], key);
  assert.equal(mesh.complete, meshed.stats.complete);
  assert.equal(mesh.pointMarkers.length, meshed.stats.vertices);
  assert.equal(mesh.triangleAttributes.length, meshed.stats.triangles);
  assert.equal(mesh.segmentMarkers.length, mesh.segments.length / 2);
  assert.ok(mesh.triangleAttributes.every((a) => a === 7), 'the region attribute of the .poly');
  // Every index is a point.
  assert.ok(mesh.triangles.every((v) => v >= 0 && v < meshed.stats.vertices));
  // The same mesh as the package makes of that input.
  const expected = mesher.triangulate(parsePoly(MARKED), { minAngle: 30, maxArea: 0.5 });
  assert.equal(mesh.triangles.length, expected.triangles.length);
  assert.deepEqual(Array.from(mesh.points), Array.from(expected.points));
  assert.deepEqual(errors, []);
  await page.close();
});

test('a load passes maxAngle and smooth on as the package takes them', async () => {
  const { page, errors } = await openHost();
  const frame = page.frameLocator('#f');
  const cases = [
    { minAngle: 30, maxArea: 0.05, maxAngle: 100, smooth: true },
    { minAngle: 30, maxArea: 0.05, smooth: 2 },
  ];
  for (const [k, options] of cases.entries()) {
    const from = await page.evaluate(() => window.replies.length);
    await page.evaluate(([poly, o, id]) => {
      window.send({ type: 'ruppert:load', id, poly, options: o });
      window.send({ type: 'ruppert:getMesh', id: `${id}-mesh` });
    }, [RECTANGLE, options, `smooth-${k}`]);
    await page.waitForFunction((n) => window.replies.slice(n).some((r) => r.type === 'ruppert:mesh'), from, { timeout: 20_000 });
    const mesh = (await repliesSince(page, from)).find((r) => r.type === 'ruppert:mesh');
    const expected = mesher.triangulate(RECTANGLE_PLC, options);
    const unsmoothed = mesher.triangulate(RECTANGLE_PLC, { ...options, smooth: 0 });
    assert.deepEqual(Array.from(mesh.points), Array.from(expected.points), `case ${k}: the package's mesh`);
    assert.notDeepEqual(Array.from(mesh.points), Array.from(unsmoothed.points), `case ${k}: smoothing moved vertices`);
    assert.equal(await frame.locator('#smooth').isChecked(), true);
    assert.equal(await frame.locator('#max-angle').inputValue(), options.maxAngle ? String(options.maxAngle) : '');
  }
  const badAngle = await ask(page, { type: 'ruppert:load', id: 'a', poly: RECTANGLE, options: { maxAngle: 50 } }, 'ruppert:error');
  assert.equal(badAngle.code, 'INVALID_OPTION');
  assert.match(badAngle.message, /maxAngle must be a number above 60 and below 180/);
  const badSmooth = await ask(page, { type: 'ruppert:load', id: 's', poly: RECTANGLE, options: { smooth: 'yes' } }, 'ruppert:error');
  assert.equal(badSmooth.code, 'INVALID_OPTION');
  assert.match(badSmooth.message, /smooth must be true, false or a whole number of passes in \[0, 100\]/);
  assert.deepEqual(errors, []);
  await page.close();
});

test('a load of JSON text with curves meshes them on the curve', async () => {
  const { page, errors } = await openHost();
  const from = await page.evaluate(() => window.replies.length);
  // The unit square with a round hole of radius 0.25: two arcs and a hole seed.
  const json = JSON.stringify({
    points: [0, 0, 1, 0, 1, 1, 0, 1, 0.75, 0.5, 0.25, 0.5],
    segments: [0, 1, 1, 2, 2, 3, 3, 0],
    curves: [{ type: 'arc', from: 4, to: 5, center: [0.5, 0.5] }, { type: 'arc', from: 5, to: 4, center: [0.5, 0.5] }],
    holes: [0.5, 0.5],
  });
  await page.evaluate((text) => {
    window.send({ type: 'ruppert:load', id: 'plate', json: text, options: { minAngle: 30 } });
    window.send({ type: 'ruppert:getMesh', id: 'plate-mesh' });
  }, json);
  await page.waitForFunction((n) => window.replies.slice(n).some((r) => r.type === 'ruppert:mesh'), from, { timeout: 20_000 });
  const replies = await repliesSince(page, from);
  const meshed = replies.find((r) => r.type === 'ruppert:meshed');
  const mesh = replies.find((r) => r.type === 'ruppert:mesh');
  assert.equal(meshed.id, 'plate');
  assert.ok(meshed.stats.complete && meshed.stats.minAngle >= 30, JSON.stringify(meshed.stats));
  // Vertices of the hole's boundary (the curves' pieces, segment ids 4 and 5) lie on the circle.
  let onHole = 0;
  for (let k = 0; k < mesh.segments.length / 2; ++k) {
    for (const v of [mesh.segments[2 * k], mesh.segments[2 * k + 1]]) {
      const r = Math.hypot(mesh.points[2 * v] - 0.5, mesh.points[2 * v + 1] - 0.5);
      if (r < 0.4) {
        onHole += 1;
        assert.ok(Math.abs(r - 0.25) < 1e-12, `vertex ${v} at radius ${r}`);
      }
    }
  }
  assert.ok(onHole >= 24, `${onHole} hole vertex ends`);
  // One of poly and json, not both.
  const both = await ask(page, { type: 'ruppert:load', id: 'both', poly: RECTANGLE, json }, 'ruppert:error');
  assert.equal(both.code, 'MALFORMED_MESSAGE');
  assert.deepEqual(errors, []);
  await page.close();
});

test('unknown options, unknown message types and malformed messages get ruppert:error', async () => {
  const { page, errors } = await openHost();
  const from = await page.evaluate(() => window.replies.length);
  const unknownOption = await ask(page, { type: 'ruppert:load', id: 'o', poly: RECTANGLE, options: { minAngel: 30 } }, 'ruppert:error');
  assert.equal(unknownOption.code, 'INVALID_OPTION');
  assert.match(unknownOption.message, /minAngel/);
  const packageOnly = await ask(page, { type: 'ruppert:load', id: 'q', poly: RECTANGLE, options: { convexHull: true } }, 'ruppert:error');
  assert.equal(packageOnly.code, 'INVALID_OPTION');
  assert.match(packageOnly.message, /does not offer/);
  const badValue = await ask(page, { type: 'ruppert:load', id: 'v', poly: RECTANGLE, options: { variant: 'quadtree' } }, 'ruppert:error');
  assert.equal(badValue.code, 'INVALID_OPTION');
  assert.match(badValue.message, /'cdt', 'box'/);
  const unknownType = await ask(page, { type: 'ruppert:frobnicate', id: 't' }, 'ruppert:error');
  assert.equal(unknownType.code, 'UNKNOWN_MESSAGE');
  assert.match(unknownType.message, /ruppert:frobnicate/);
  const noPoly = await ask(page, { type: 'ruppert:load', id: 'p' }, 'ruppert:error');
  assert.equal(noPoly.code, 'MALFORMED_MESSAGE');
  const unknownField = await ask(page, { type: 'ruppert:getMesh', id: 'f', format: 'obj' }, 'ruppert:error');
  assert.equal(unknownField.code, 'MALFORMED_MESSAGE');
  assert.match(unknownField.message, /format/);
  const badStep = await ask(page, { type: 'ruppert:step', id: 's', index: -1 }, 'ruppert:error');
  assert.equal(badStep.code, 'INVALID_OPTION');
  const unknownPreset = await ask(page, { type: 'ruppert:preset', id: 'n', name: 'figure-9-9' }, 'ruppert:error');
  assert.equal(unknownPreset.code, 'UNKNOWN_PRESET');
  assert.match(unknownPreset.message, /figure-6-4/);
  const badPoly = await ask(page, { type: 'ruppert:load', id: 'b', poly: '4 2 0 0\n1 0 0\n' }, 'ruppert:error');
  assert.equal(badPoly.code, 'PARSE_ERROR');
  // A string and a bad id are malformed too; other scripts' messages are left alone.
  await page.evaluate(() => window.send('ruppert:load'));
  await page.waitForFunction((n) => window.replies.slice(n).some((r) => r.type === 'ruppert:error' && r.id === null), from);
  await page.evaluate(() => window.send({ type: 'webpackOk' }));
  await page.evaluate(() => window.send({ type: 'ruppert:meshed', id: 'echo' }));
  await page.waitForTimeout(500);
  const replies = await repliesSince(page, from);
  assert.equal(replies.filter((r) => r.type === 'ruppert:error').length, 10);
  assert.equal(replies.filter((r) => r.type === 'ruppert:meshed').length, 0, 'no bad message was meshed');
  assert.deepEqual(errors, []);
  await page.close();
});

test('ruppert:preset opens a preset the same way after another drawing as on a fresh page', async () => {
  const fresh = await openHost();
  const first = await ask(fresh.page, { type: 'ruppert:preset', id: 'p1', name: 'figure-6-4' }, 'ruppert:meshed');
  const freshInfo = await fresh.page.frameLocator('#f').locator('#step-info').textContent();
  assert.match(freshInfo, /^Step 0 of \d+/);
  // What the page's own preset gives, meshed by the package.
  const preset = findPreset('figure-6-4');
  const drawing = { ...preset.build(), options: { ...DEFAULT_OPTIONS, ...(preset.options ?? {}) } };
  assert.equal(first.stats.triangles, mesher.triangulate(toPlc(drawing), toMeshOptions(drawing)).stats.triangles);

  const { page, errors } = await openHost();
  await ask(page, { type: 'ruppert:load', id: 'other', poly: RECTANGLE, options: { maxArea: 0.05, minAngle: 20 } }, 'ruppert:meshed');
  const stepped = await ask(page, { type: 'ruppert:step', id: 'st', index: 12 }, 'ruppert:stepped');
  assert.equal(stepped.index, 12);
  assert.ok(stepped.triangles > 0 && stepped.minAngle > 0, 'the step reply carries its mesh statistics');
  const second = await ask(page, { type: 'ruppert:preset', id: 'p2', name: 'figure-6-4' }, 'ruppert:meshed');
  assert.deepEqual(second.stats, first.stats);
  const frame = page.frameLocator('#f');
  assert.equal(await frame.locator('#step-info').textContent(), freshInfo);
  assert.equal(await frame.locator('#max-area').inputValue(), '');
  assert.equal(await frame.locator('#min-angle').inputValue(), String(DEFAULT_OPTIONS.minAngle));
  await page.screenshot({ path: `${SCREENSHOTS}embed-protocol-preset.png` });
  assert.deepEqual([...fresh.errors, ...errors], []);
  await fresh.page.close();
  await page.close();
});

test('a load after a stepping preset shows its final mesh, out of step mode', async () => {
  const { page, errors } = await openHost();
  await ask(page, { type: 'ruppert:preset', id: 'fig', name: 'figure-6-4' }, 'ruppert:meshed');
  const frame = page.frameLocator('#f');
  assert.match(await frame.locator('#step-info').textContent(), /^Step 0 of/);
  const meshed = await ask(page, { type: 'ruppert:load', id: 'after', poly: RECTANGLE, options: { maxArea: 0.05, minAngle: 20 } }, 'ruppert:meshed');
  const expected = mesher.triangulate(RECTANGLE_PLC, { maxArea: 0.05, minAngle: 20 });
  assert.equal(meshed.stats.triangles, expected.stats.triangles);
  // The frame shows what a fresh frame shows for that load: the final mesh, no stepper, no caption.
  await frame.locator('body[data-mesh-state="done"]').waitFor({ state: 'attached' });
  assert.equal(await frame.locator('#step-mode').isChecked(), false);
  assert.equal(await frame.locator('#stepper').isHidden(), true);
  assert.equal(await frame.locator('#preset-caption').isHidden(), true);
  assert.equal(await frame.locator('#stats-title').textContent(), 'Mesh');
  assert.equal(Number((await frame.locator('#stat-triangles').textContent()).replace(/,/g, '')), expected.stats.triangles);
  assert.equal(await frame.locator('#stat-complete').textContent(), 'yes');
  // A step asked for afterwards turns step mode on again.
  const stepped = await ask(page, { type: 'ruppert:step', id: 's', index: 3 }, 'ruppert:stepped');
  assert.equal(stepped.index, 3);
  assert.equal(await frame.locator('#step-mode').isChecked(), true);
  assert.deepEqual(errors, []);
  await page.close();
});
