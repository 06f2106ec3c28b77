// The page for courses, its smaller promises: an editable embed shows its tools, the
// canvas fills a small window, the histogram has a count axis and the bound and is in view, Clear
// takes the caption away, the hover box hides off the mesh, a resize keeps the drawing in view,
// notices read as words and short numbers, and a first visit gets a dismissible "Start here".
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { SCREENSHOTS, launch, openPage, settle } from './harness.mjs';

let harness;

before(async () => {
  harness = await launch();
});

after(async () => {
  await harness?.close();
});

const box = (page, selector) => page.locator(selector).boundingBox();

test('an embed with &edit=1 opens with the drawing tools, a read-only one without', async () => {
  for (const [query, editable] of [['embed=1&edit=1', true], ['embed=1', false]]) {
    const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/index.html?${query}`, { width: 640, height: 480 });
    assert.equal(await settle(page), 'done');
    for (const selector of ['[data-tool="polyline"]', '[data-tool="select"]', '#undo', '#clear']) {
      assert.equal(await page.locator(selector).isVisible(), editable, `${query}: ${selector}`);
    }
    assert.equal(await page.locator('#preset').isVisible(), false, `${query}: no preset box in an embed`);
    if (editable) {
      assert.equal(await page.getAttribute('[data-tool="polyline"]', 'aria-pressed'), 'true', 'the polygon tool is on');
      await page.screenshot({ path: `${SCREENSHOTS}embed-edit.png` });
    }
    assert.deepEqual(errors, []);
    await page.close();
  }
});

test('at 640 x 480 the canvas takes most of the window\'s height', async () => {
  const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/`, { width: 640, height: 480 });
  assert.equal(await settle(page), 'done');
  const canvas = await box(page, '#canvas-wrap');
  assert.ok(canvas.height >= 0.6 * 480, `canvas ${canvas.height} px tall`);
  assert.ok(canvas.y + canvas.height <= 480, `the canvas ends at ${canvas.y + canvas.height}, in the window`);
  await page.screenshot({ path: `${SCREENSHOTS}layout-640x480.png` });
  assert.deepEqual(errors, []);
  await page.close();
});

test('the histogram has a count axis and a line at the bound, in view at 1440 x 900', async () => {
  const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/`, { width: 1440, height: 900 });
  assert.equal(await settle(page), 'done');
  const histogram = await box(page, '#histogram');
  assert.ok(histogram.y >= 0 && histogram.y + histogram.height <= 900, `histogram from ${histogram.y} to ${histogram.y + histogram.height}`);
  const drawn = await page.evaluate(() => {
    const canvas = document.getElementById('histogram');
    const dpr = window.devicePixelRatio || 1;
    const ctx = canvas.getContext('2d');
    const pixel = (x, y) => Array.from(ctx.getImageData(Math.round(x * dpr), Math.round(y * dpr), 1, 1).data);
    const middle = canvas.clientHeight / 2;
    return { ...canvas.dataset, boundPixel: pixel(Number(canvas.dataset.boundX), middle), axisPixel: pixel(33, middle) };
  });
  assert.equal(Number(drawn.bound), Number(await page.inputValue('#min-angle')), 'the line is at the min angle in force');
  // The bound's line is teal (#0b7285), the axis dark gray (#343a40).
  const [r, g, b] = drawn.boundPixel;
  assert.ok(r < 60 && g > 80 && b > 100, `bound line pixel ${drawn.boundPixel}`);
  assert.ok(drawn.axisPixel[3] > 200 && drawn.axisPixel.slice(0, 3).every((c) => c < 110), `axis pixel ${drawn.axisPixel}`);
  // The axis goes to a round number at or above the fullest bin.
  const fullest = await page.evaluate(async () => {
    const { decodeDrawing } = await import('./io/url-state.js');
    const { toMeshOptions, toPlc } = await import('./model/drawing.js');
    const { init } = await import('../wasm/index.js');
    const drawing = decodeDrawing(location.hash);
    return Math.max(...(await init()).triangulate(toPlc(drawing), toMeshOptions(drawing)).stats.angleHistogram);
  });
  const countMax = Number(drawn.countMax);
  assert.ok(countMax >= fullest && countMax <= 2.5 * fullest, `axis to ${countMax}, fullest bin ${fullest}`);
  assert.match(String(countMax), /^[125]0*$/);
  await page.screenshot({ path: `${SCREENSHOTS}layout-1440x900.png` });
  assert.deepEqual(errors, []);
  await page.close();
});

test('Clear takes the preset\'s caption away', async () => {
  const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/`);
  assert.equal(await settle(page), 'done');
  await page.selectOption('#preset', 'skyline');
  assert.equal(await settle(page), 'done');
  assert.equal(await page.locator('#preset-caption').isVisible(), true);
  await page.click('#clear');
  assert.equal(await settle(page), 'empty');
  assert.equal(await page.locator('#preset-caption').isHidden(), true);
  assert.equal(await page.inputValue('#preset'), '');
  assert.deepEqual(errors, []);
  await page.close();
});

/** The screen point (relative to the canvas) of a world point, from the page's view (`?bench=1`). */
const toScreen = (page, x, y) => page.evaluate(([wx, wy]) => window.ruppertBench.view.toScreen(wx, wy), [x, y]);

test('the hover box shows over a triangle and hides over a hole and outside the mesh', async () => {
  const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/?bench=1`);
  assert.equal(await settle(page), 'done');
  await page.selectOption('#preset', 'square-hole');
  assert.equal(await settle(page), 'done');
  const canvas = await box(page, '#canvas');
  const move = async ([x, y]) => {
    const p = await toScreen(page, x, y);
    await page.mouse.move(canvas.x + p.x, canvas.y + p.y);
    await page.waitForTimeout(50);
  };
  for (const [where, point, shown] of [
    ['a triangle', [2, 2], true], ['the hole', [5, 5], false], ['a triangle again', [8, 2], true],
    ['outside the square', [-1, 5], false], ['a triangle, then', [2, 8], true], ['the hole again', [4.5, 5.5], false],
  ]) {
    await move(point);
    assert.equal(await page.locator('#hover-info').isVisible(), shown, `over ${where}`);
  }
  assert.deepEqual(errors, []);
  await page.close();
});

test('a resize to phone width keeps the drawing in view, also after a zoom', async () => {
  for (const zoomed of [false, true]) {
    const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/?bench=1`, { width: 1280, height: 800 });
    assert.equal(await settle(page), 'done');
    if (zoomed) {
      const canvas = await box(page, '#canvas');
      await page.mouse.move(canvas.x + canvas.width / 2, canvas.y + canvas.height / 2);
      await page.mouse.wheel(0, 200);  // out a little: the whole drawing still in view
      await page.waitForTimeout(100);
    }
    const inView = () => page.evaluate(async () => {
      const { drawingBounds } = await import('./model/drawing.js');
      const b = drawingBounds((await import('./io/url-state.js')).decodeDrawing(location.hash));
      const { view } = window.ruppertBench;
      const a = view.toScreen(b.minX, b.minY);
      const c = view.toScreen(b.maxX, b.maxY);
      return a.x >= 0 && c.x <= view.width && c.y >= 0 && a.y <= view.height;
    });
    assert.equal(await inView(), true, `zoomed ${zoomed}: in view at 1280`);
    await page.setViewportSize({ width: 390, height: 800 });
    await page.waitForFunction(() => window.ruppertBench.view.width < 400);
    await page.waitForTimeout(100);
    assert.equal(await inView(), true, `zoomed ${zoomed}: in view at 390`);
    await page.screenshot({ path: `${SCREENSHOTS}resized-390${zoomed ? '-zoomed' : ''}.png` });
    assert.deepEqual(errors, []);
    await page.close();
  }
});

test('notices give coordinates to six digits and their codes in words', async () => {
  const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/`);
  assert.equal(await settle(page), 'done');
  // A square with two segments inside crossing at (1, 4/3): the core prints 1.3333333333333333.
  const crossing = '8 2 0 0\n0 0 0\n1 3 0\n2 3 3\n3 0 3\n4 0.5 1\n5 2 2\n6 1 0.5\n7 1 2.5\n6 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n4 4 5\n5 6 7\n0\n';
  await page.setInputFiles('#file-input', { name: 'crossing.poly', mimeType: 'text/plain', buffer: Buffer.from(crossing) });
  assert.equal(await settle(page), 'done');
  const notice = await page.locator('#notices .notice').first().textContent();
  assert.match(notice, /^Segments cross: .*\(1, 1\.33333\).*\(SEGMENTS_CROSS\)$/);
  assert.doesNotMatch(notice, /\d\.\d{7,}/, 'no coordinate past six digits');
  assert.deepEqual(errors, []);
  await page.close();
});

test('"Start here" shows on a first visit, stays away once dismissed, and shows in an embed only when asked', async () => {
  const open = (query = '') => openPage(harness.context, `${harness.baseUrl}/web/${query}`, { startHere: true });
  let { page, errors } = await open();
  await page.evaluate(() => localStorage.clear());
  await page.reload();
  assert.equal(await settle(page), 'done');
  const panel = page.locator('#start-here');
  assert.equal(await panel.isVisible(), true, 'a first visit');
  const steps = await panel.locator('li').allTextContents();
  assert.ok(steps.length >= 4 && steps.length <= 6, `${steps.length} steps`);
  for (const word of [/preset/i, /angle/i, /mesh/i, /step/i, /export/i]) assert.ok(steps.some((s) => word.test(s)), `${word} in the steps`);
  await page.screenshot({ path: `${SCREENSHOTS}start-here.png` });
  await page.click('#start-here-dismiss');
  assert.equal(await panel.isHidden(), true, 'dismissed');
  await page.reload();
  assert.equal(await settle(page), 'done');
  assert.equal(await panel.isHidden(), true, 'still dismissed after a reload');
  await page.click('#start-here-show');
  assert.equal(await panel.isVisible(), true, 'the toolbar button shows it again');
  await page.close();
  for (const [query, shown] of [['index.html?embed=1', false], ['index.html?embed=1&help=1', true]]) {
    const framed = await open(query);
    assert.equal(await settle(framed.page), 'done');
    assert.equal(await framed.page.locator('#start-here').isVisible(), shown, query);
    errors = errors.concat(framed.errors);
    await framed.page.close();
  }
  assert.deepEqual(errors, []);
});

test('a preset\'s caption goes when its options are changed', async () => {
  const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/`);
  assert.equal(await settle(page), 'done');
  await page.selectOption('#preset', 'lake');
  assert.equal(await settle(page), 'done');
  assert.match(await page.locator('#preset-caption').textContent(), /no angle under 30°/);
  await page.fill('#min-angle', '25');
  await page.locator('#min-angle').dispatchEvent('change');
  assert.equal(await settle(page), 'done');
  assert.equal(await page.locator('#preset-caption').isHidden(), true, 'the caption of 30° is gone at 25°');
  assert.equal(await page.inputValue('#preset'), '');
  assert.deepEqual(errors, []);
  await page.close();
});
