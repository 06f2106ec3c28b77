// Touch (tap, one-finger pan, two-finger pinch), the keyboard cursor, and presets from the corpus
// of real PLCs beside the repository (../shared/data, served by web/serve.mjs when present).
import assert from 'node:assert/strict';
import { existsSync } from 'node:fs';
import { after, before, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { SCREENSHOTS, launch, openPage, readStats, settle } from './harness.mjs';

let harness;
let page;
let errors;
let touch;  // a CDP session: Chromium turns its touch events into pointer events of type 'touch'

const decodeHash = () => page.evaluate(async () => (await import('./io/url-state.js')).decodeDrawing(location.hash));
const points = async () => (await decodeHash()).points;

before(async () => {
  harness = await launch();
  ({ page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/`));
  assert.equal(await settle(page), 'done', 'the default drawing is meshed on load');
  touch = await page.context().newCDPSession(page);
});

after(async () => {
  assert.deepEqual(errors, [], 'no console errors');
  await harness?.close();
});

/** Canvas pixel -> page pixel. */
async function at(x, y) {
  const box = await page.locator('#canvas').boundingBox();
  return { x: box.x + x, y: box.y + y };
}

async function touches(type, fingers) {
  const touchPoints = [];
  for (const [id, x, y] of fingers) touchPoints.push({ ...(await at(x, y)), id });
  await touch.send('Input.dispatchTouchEvent', { type, touchPoints });
}

async function tap(x, y) {
  await touches('touchStart', [[1, x, y]]);
  await touches('touchEnd', []);
}

async function emptyWithTool(key) {
  await page.click('#clear');
  assert.equal(await settle(page), 'empty');
  await page.locator('#canvas').focus();
  await page.keyboard.press(key);
}

test('touch: taps add vertices, a two-finger pinch zooms about its center and adds none', async () => {
  await emptyWithTool('p');
  await tap(200, 200);
  await tap(300, 200);
  let p = await points();
  assert.equal(p.length, 4, `two taps, two points: ${p}`);
  const before = Math.hypot(p[2] - p[0], p[3] - p[1]);

  // Fingers 100 px apart move to 200 px apart: a zoom of 2 (and the center moves 50 px: a pan).
  await touches('touchStart', [[2, 300, 300]]);
  await touches('touchStart', [[2, 300, 300], [3, 400, 300]]);
  for (let x = 420; x <= 500; x += 20) await touches('touchMove', [[2, 300, 300], [3, x, 300]]);
  await touches('touchEnd', [[2, 300, 300]]);
  await touches('touchEnd', []);
  assert.equal((await points()).length, 4, 'the pinch added no vertex');

  await tap(200, 200);
  await tap(300, 200);
  p = await points();
  assert.equal(p.length, 8);
  const after = Math.hypot(p[6] - p[4], p[7] - p[5]);
  assert.ok(Math.abs(after / before - 0.5) < 1e-6, `100 px spanned ${before} before the pinch and ${after} after`);

  // One finger that moves pans (and adds no vertex).
  await touches('touchStart', [[4, 250, 400]]);
  for (let y = 380; y >= 300; y -= 20) await touches('touchMove', [[4, 250, y]]);
  await touches('touchEnd', []);
  assert.equal((await points()).length, 8, 'a one-finger drag pans');
  await tap(200, 200);
  p = await points();
  assert.equal(p.length, 10);
  // The content followed the finger 100 px up: the world point now under (200, 200) was 100 px
  // lower, i.e. `after` world units lower (100 px span `after` units at this zoom).
  assert.ok(Math.abs(p[9] - (p[5] - after)) < 1e-6 * after, `pan: y ${p[9]} vs ${p[5]} - ${after}`);
  assert.equal(p[8], p[4], 'the pan was vertical');
});

test('keyboard: arrows move a cursor on the focused canvas, Enter draws there', async () => {
  await emptyWithTool('p');
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('Enter');
  await page.keyboard.press('ArrowUp');
  await page.keyboard.press('ArrowUp');
  await page.keyboard.press('Enter');
  let p = await points();
  assert.equal(p.length, 4, `two points: ${p}`);
  assert.equal(p[2], p[0], 'Up moved the cursor vertically only');
  assert.ok(p[3] > p[1], 'Up is up (world y grows)');

  // A polygon by keyboard alone: three corners, then Enter on the first one again closes it.
  await emptyWithTool('l');
  const path = ['ArrowRight', 'ArrowUp', 'ArrowLeft'];
  await page.keyboard.press('Enter');  // no cursor yet (clearing hides it): nothing happens
  assert.equal((await points()).length, 0);
  await page.keyboard.press('ArrowDown');  // the cursor appears near the center
  await page.keyboard.press('Enter');
  for (const key of path) {
    for (let i = 0; i < 3; i++) await page.keyboard.press(`Shift+${key}`);
    await page.keyboard.press('Enter');
  }
  for (let i = 0; i < 3; i++) await page.keyboard.press('Shift+ArrowDown');
  await page.keyboard.press('Enter');  // back on the first vertex: closes the ring
  const d = await decodeHash();
  assert.equal(d.points.length, 8, `four corners: ${d.points}`);
  assert.equal(d.segments.length, 8, `a closed ring of four segments: ${d.segments}`);
  assert.equal(await settle(page), 'done');
  const stats = await readStats(page);
  assert.ok(stats.triangles >= 2 && stats.minAngle >= 30 - 1e-9, JSON.stringify(stats));
  await page.screenshot({ path: `${SCREENSHOTS}keyboard-square.png` });
});

const sharedData = fileURLToPath(new URL('../../../shared/data/', import.meta.url));

test('presets from the corpus of real PLCs, when it sits beside the repository', async () => {
  const index = await page.evaluate(async () => (await fetch('../shared-data/index.json')).json());
  const group = page.locator('#shared-presets');
  if (!existsSync(sharedData)) {
    assert.equal(index.available, false);
    assert.equal(await group.count(), 0, 'no corpus, no corpus presets');
    console.log(`# ${sharedData} is absent: the corpus presets are checked to be absent only`);
    return;
  }
  assert.equal(index.available, true);
  assert.ok(index.files.includes('cdt_guitar.poly'), `listed: ${index.files.length} files`);
  assert.equal(await group.locator('option').count(), index.files.length);
  await page.selectOption('#preset', 'shared:cdt_guitar.poly');
  assert.equal(await settle(page), 'done');
  const d = await decodeHash();
  assert.ok(d.points.length / 2 >= 100, `cdt_guitar.poly has ${d.points.length / 2} points`);
  const stats = await readStats(page);
  assert.equal(stats.complete, 'yes');
  assert.ok(stats.minAngle >= 30 - 1e-9 && stats.triangles > d.points.length / 2, JSON.stringify(stats));
  assert.equal(await page.inputValue('#preset'), 'shared:cdt_guitar.poly');
  await page.screenshot({ path: `${SCREENSHOTS}corpus-preset-guitar.png` });
  // Names outside the list are refused by the server (asked from here: the page would log the 404).
  const response = await fetch(`${harness.baseUrl}/shared-data/..%2F..%2Fmain%2Fpackage.json`);
  assert.equal(response.status, 404);
});
