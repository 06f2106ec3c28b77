// Drawing with the mouse and keyboard, meshing in the worker, parameters, undo, error display.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { init } from '../../wasm/index.js';
import { DEFAULT_OPTIONS, PAGE_FLAGS, emptyDrawing, flagOption, toMeshOptions, toPlc } from '../../web/model/drawing.js';
import { decodeDrawing, encodeDrawing } from '../../web/io/url-state.js';
import {
  SCREENSHOTS, canvasFingerprint, clickCanvas, launch, moveOnCanvas, openPage, readStats, settle,
} from './harness.mjs';

let harness;
let page;
let errors;

before(async () => {
  harness = await launch();
  ({ page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/`));
  assert.equal(await settle(page), 'done', 'the default drawing is meshed on load');
  // Record what the page posts to window.parent (itself, at top level).
  await page.evaluate(() => {
    window.receivedMessages = [];
    window.addEventListener('message', (event) => {
      if (event.data?.type === 'ruppert:meshed') window.receivedMessages.push(event.data);
    });
  });
});

after(async () => {
  await harness?.close();
});

// Irregular quadrilaterals (canvas pixels): unlike squares, their mesh depends on the min angle.
const OUTER = [[120, 90], [600, 130], [520, 520], [160, 460]];
const INNER = [[300, 250], [420, 270], [400, 360], [290, 340]];
const HOLE = [350, 300];

async function drawRing(corners) {
  for (const [x, y] of corners) await clickCanvas(page, x, y);
  await clickCanvas(page, corners[0][0], corners[0][1]);  // the first vertex again: closes it
}

test('a polygon with a hole drawn by mouse is meshed by the worker', async () => {
  const before = await readStats(page);
  await page.click('#clear');
  assert.equal(await settle(page), 'empty');
  assert.equal(await page.locator('#stat-triangles').textContent(), '–');

  await page.click('[data-tool="polyline"]');
  await drawRing(OUTER);
  await drawRing(INNER);
  await page.keyboard.press('h');
  assert.equal(await page.getAttribute('[data-tool="hole"]', 'aria-pressed'), 'true');
  await clickCanvas(page, ...HOLE);
  assert.equal(await settle(page), 'done');

  const stats = await readStats(page);
  assert.ok(stats.triangles > 0, `triangles: ${stats.triangles}`);
  assert.ok(stats.vertices >= 8, `vertices: ${stats.vertices}`);
  assert.equal(stats.complete, 'yes');
  assert.ok(stats.minAngle >= 30 - 1e-9, `min angle ${stats.minAngle}`);
  assert.notDeepEqual(stats, before);

  // Hovering inside the hole finds no triangle; inside the domain it shows one's angles.
  await moveOnCanvas(page, ...HOLE);
  assert.equal(await page.locator('#hover-info').isHidden(), true, 'no triangle in the hole');
  await moveOnCanvas(page, 200, 150);
  const info = await page.locator('#hover-info').textContent();
  assert.match(info, /angles [\d.]+°, [\d.]+°, [\d.]+°; radius-edge ratio [\d.]+/);
  assert.match(info, /input|segment split|off-center|circumcenter/);

  // The page reported the same statistics to its host (itself here).
  const last = await page.evaluate(() => window.receivedMessages.at(-1));
  assert.equal(last.stats.triangles, stats.triangles);
  assert.equal(last.stats.complete, true);

  await page.screenshot({ path: `${SCREENSHOTS}drawn-polygon-with-hole.png` });
});

test('changing the min angle re-meshes with a different mesh', async () => {
  // No max area (Clear kept the first sight's 0.5, which would decide the mesh at either angle).
  await page.fill('#max-area', '');
  await page.locator('#max-area').dispatchEvent('change');
  await page.fill('#min-angle', '5');
  await page.press('#min-angle', 'Tab');
  assert.equal(await settle(page), 'done');
  const low = await readStats(page);
  assert.equal(await page.inputValue('#min-angle-range'), '5', 'the slider follows the number');

  await page.fill('#min-angle', '33');
  await page.press('#min-angle', 'Tab');
  assert.equal(await settle(page), 'done');
  const high = await readStats(page);
  assert.ok(high.triangles > low.triangles, `33°: ${high.triangles} triangles, 5°: ${low.triangles}`);
  assert.ok(high.minAngle >= 33 - 1e-9, `min angle ${high.minAngle}`);
  assert.match(page.url(), /#d=/, 'the drawing is in the URL hash');

  // The slider drives it too (keyboard: arrows on the focused range input).
  await page.focus('#min-angle-range');
  await page.keyboard.press('ArrowLeft');
  assert.equal(await settle(page), 'done');
  assert.equal(await page.inputValue('#min-angle'), '32.5');
});

test('undo and redo with Ctrl+Z / Ctrl+Y', async () => {
  await page.fill('#min-angle', '30');
  await page.press('#min-angle', 'Tab');
  await settle(page);
  await page.locator('#canvas').focus();
  // The min-angle edits since the hole seed are undo steps too: undo until the seed is gone.
  let undos = 0;
  for (; undos < 8; undos++) {
    await moveOnCanvas(page, HOLE[0] + (undos % 2), HOLE[1]);
    if (await page.locator('#hover-info').isVisible()) break;
    await page.keyboard.press('Control+z');
    assert.equal(await settle(page), 'done');
  }
  assert.ok(undos >= 2 && undos < 8, `the hole seed went after ${undos} undo steps`);
  assert.equal(await page.inputValue('#min-angle'), '30', 'undo restored the min angle the seed was placed with');
  await page.keyboard.press('Control+y');
  assert.equal(await settle(page), 'done');
  await moveOnCanvas(page, ...HOLE);
  assert.equal(await page.locator('#hover-info').isHidden(), true, 'after redo the hole is back');
});

test('select, drag and delete a vertex; zoom with the wheel', async () => {
  await page.keyboard.press('v');
  const before = await readStats(page);
  const hashBefore = await page.evaluate(() => /(?:^#|&)(d=[^&]*)/.exec(location.hash)?.[1]);
  const box = await page.locator('#canvas').boundingBox();
  await page.mouse.move(box.x + 520, box.y + 520);
  await page.mouse.down();
  // The mesh follows the vertex while it moves: meshes arrive before the button is released.
  const meshesBefore = await page.evaluate(() => Number(document.body.dataset.meshCount ?? 0));
  for (let i = 1; i <= 12; i++) {
    await page.mouse.move(box.x + 520 + 5 * i, box.y + 520 + 3 * i);
    await page.waitForTimeout(40);
  }
  const meshesDuring = await page.evaluate(() => Number(document.body.dataset.meshCount ?? 0));
  assert.ok(meshesDuring - meshesBefore >= 2, `${meshesDuring - meshesBefore} meshes during the drag`);
  await page.mouse.up();
  assert.equal(await settle(page), 'done');
  assert.notEqual(await page.evaluate(() => /(?:^#|&)(d=[^&]*)/.exec(location.hash)?.[1]), hashBefore, 'the drag moved a vertex');
  assert.notDeepEqual(await readStats(page), before);
  // The last mesh is of the last position: the drawing in the link, meshed by the package here,
  // gives the same counts.
  const dragged = await readStats(page);
  const drawing = decodeDrawing(await page.evaluate(() => location.hash));
  const expected = (await init()).triangulate(toPlc(drawing), toMeshOptions(drawing)).stats;
  assert.equal(dragged.triangles, expected.triangles, 'the last position was meshed last');
  assert.equal(dragged.vertices, expected.vertices, 'the last position was meshed last');

  // Delete the hole seed (the hole fills), then an inner vertex (its two segments go with it).
  await clickCanvas(page, ...HOLE);
  assert.equal(await page.isDisabled('#delete-selected'), false);
  const withHole = await readStats(page);
  await page.keyboard.press('Delete');
  assert.equal(await settle(page), 'done');
  const filled = await readStats(page);
  assert.ok(filled.triangles > withHole.triangles, `${filled.triangles} > ${withHole.triangles}`);
  await clickCanvas(page, 400, 360);
  await page.keyboard.press('Delete');
  assert.equal(await settle(page), 'done');
  const opened = await readStats(page);
  assert.ok(opened.triangles > 0);
  assert.notDeepEqual(opened, filled);
  const hash = await page.evaluate(() => /(?:^#|&)(d=[^&]*)/.exec(location.hash)?.[1]);

  const picture = await canvasFingerprint(page);
  await page.mouse.move(box.x + 300, box.y + 300);
  await page.mouse.wheel(0, -400);
  await page.waitForTimeout(100);
  assert.notEqual(await canvasFingerprint(page), picture, 'the wheel zoomed');
  assert.equal(await page.evaluate(() => /(?:^#|&)(d=[^&]*)/.exec(location.hash)?.[1]), hash, 'zooming does not change the drawing');

  // Pan: middle-button drag, and Space + left drag (over a vertex: it must not move).
  for (const pan of ['middle', 'space']) {
    const before = await canvasFingerprint(page);
    await page.mouse.move(box.x + 120, box.y + 90);
    if (pan === 'space') await page.keyboard.down('Space');
    await page.mouse.down({ button: pan === 'middle' ? 'middle' : 'left' });
    await page.mouse.move(box.x + 200, box.y + 150, { steps: 4 });
    await page.mouse.up({ button: pan === 'middle' ? 'middle' : 'left' });
    if (pan === 'space') await page.keyboard.up('Space');
    await page.waitForTimeout(100);
    assert.notEqual(await canvasFingerprint(page), before, `${pan} drag panned`);
    assert.equal(await page.evaluate(() => /(?:^#|&)(d=[^&]*)/.exec(location.hash)?.[1]), hash, `${pan} drag left the drawing alone`);
  }
  await page.keyboard.press('f');
});

test('crossing segments and degenerate input are reported to the user', async () => {
  await page.click('#clear');
  await settle(page);
  await page.click('[data-tool="polyline"]');
  // A bow tie: its two long edges cross.
  await drawRing([[150, 100], [550, 500], [550, 100], [150, 500]]);
  assert.equal(await settle(page), 'done');
  const notices = await page.locator('#notices').textContent();
  assert.match(notices, /SEGMENTS_CROSS/);
  assert.equal(await page.getAttribute('#status', 'data-kind'), 'warn');

  await page.click('#clear');
  await settle(page);
  await page.keyboard.press('p');
  for (const x of [200, 300, 400]) await clickCanvas(page, x, 300);
  assert.equal(await settle(page), 'error');
  assert.match(await page.locator('#notices .error').textContent(), /DEGENERATE_INPUT/);
  assert.match(await page.locator('#status').textContent(), /Cannot mesh/);
  assert.equal(await page.locator('#stat-triangles').textContent(), '–');
});

test('a long meshing job shows progress and can be cancelled', async () => {
  await page.selectOption('#preset', 'square-hole');
  assert.equal(await settle(page), 'done');
  // About ten million triangles: far longer than the test waits.
  await page.fill('#max-area', '0.00001');
  await page.press('#max-area', 'Tab');
  await page.locator('#cancel').waitFor({ state: 'visible', timeout: 10_000 });
  assert.equal(await page.locator('#progress').isVisible(), true);
  await page.click('#cancel');
  assert.equal(await settle(page), 'cancelled');
  assert.match(await page.locator('#status').textContent(), /cancelled/i);
  assert.equal(await page.locator('#cancel').isHidden(), true);
  // The mesh still on screen is the older one: the panel must not call it complete.
  assert.match(await page.locator('#stat-complete').textContent(), /cancelled/);

  // A fresh worker meshes the next request.
  await page.fill('#max-area', '');
  await page.press('#max-area', 'Tab');
  assert.equal(await settle(page), 'done');
  assert.ok((await readStats(page)).triangles > 0);
});

test('page flags: each a checkbox bound to its package option, in links and in the mesher\'s options', async () => {
  assert.ok(PAGE_FLAGS.length > 0);
  for (const [k, id] of PAGE_FLAGS.entries()) {
    const key = flagOption(id);
    assert.equal(DEFAULT_OPTIONS[key], false, `${id} is off by default`);
    assert.equal(await page.locator(`#${id}[type=checkbox]`).count(), 1, `${id} is a checkbox of the page`);
    const on = emptyDrawing();
    on.options[key] = true;
    assert.equal(toMeshOptions(on)[key], true, `${id} on reaches the mesher as ${key}`);
    assert.equal(key in toMeshOptions(emptyDrawing()), false, `${id} off is left to the package's default`);
    const hash = `#${encodeDrawing(on)}`;
    assert.equal(decodeDrawing(hash).options[key], true, `${id} survives a link`);
    assert.equal(decodeDrawing(`#${encodeDrawing(emptyDrawing())}`).options[key], false);
    // Links from before the flags were general carry the first flag as a 7th entry of 1.
    const old = { v: 1, p: [0, 0, 1, 0, 0, 1], s: [0, 1, 1, 2, 2, 0], h: [], r: [], o: [30, 0, 't', -1, 'c', 'l', 1 << k] };
    const encoded = Buffer.from(JSON.stringify(old)).toString('base64url');
    assert.equal(decodeDrawing(`#d=${encoded}`).options[key], true, `bit ${k} of an older link is ${id}`);
  }
});

test('max angle: a field of the Parameters panel, in links and in the mesher\'s options', async () => {
  assert.equal(DEFAULT_OPTIONS.maxAngle, null, 'none by default');
  assert.equal('maxAngle' in toMeshOptions(emptyDrawing()), false, 'none is left to the package\'s default');
  const bounded = emptyDrawing();
  bounded.options.maxAngle = 100;
  assert.equal(toMeshOptions(bounded).maxAngle, 100);
  assert.equal(decodeDrawing(`#${encodeDrawing(bounded)}`).options.maxAngle, 100, 'it survives a link');
  assert.equal(decodeDrawing(`#${encodeDrawing(emptyDrawing())}`).options.maxAngle, null);
  // A value the mesher refuses is not taken: the field says so and the option stays as it was.
  await page.fill('#max-angle', '50');
  await page.locator('#max-angle').dispatchEvent('change');
  assert.equal(await page.getAttribute('#max-angle', 'aria-invalid'), 'true');
  await page.fill('#max-angle', '100');
  await page.locator('#max-angle').dispatchEvent('change');
  assert.equal(await page.getAttribute('#max-angle', 'aria-invalid'), null);
  assert.equal(await settle(page), 'done');
  await page.fill('#max-angle', '');
  await page.locator('#max-angle').dispatchEvent('change');
  assert.equal(await settle(page), 'done');
});

test('no console errors', () => {
  assert.deepEqual(errors, []);
});
