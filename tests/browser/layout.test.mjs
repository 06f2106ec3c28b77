// Layout at desktop and phone widths, labeled controls, keyboard operation, the static server.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { SCREENSHOTS, launch, openPage, readStats, settle } from './harness.mjs';

let harness;

before(async () => {
  harness = await launch();
});

after(async () => {
  await harness?.close();
});

const box = (page, selector) => page.locator(selector).boundingBox();

test('at 1280 x 800 the panel is beside the canvas and nothing overflows sideways', async () => {
  const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/`, { width: 1280, height: 800 });
  assert.equal(await settle(page), 'done');
  const canvas = await box(page, '#canvas-wrap');
  const panel = await box(page, '#panel');
  assert.ok(panel.x >= canvas.x + canvas.width - 1, 'panel right of the canvas');
  assert.ok(canvas.width >= 700 && canvas.height >= 400, `canvas ${canvas.width} x ${canvas.height}`);
  assert.ok(canvas.y + canvas.height <= 800, 'the canvas fits in the window');
  assert.equal(await page.evaluate(() => document.documentElement.scrollWidth), 1280);
  await page.screenshot({ path: `${SCREENSHOTS}layout-1280.png` });
  assert.deepEqual(errors, []);
  await page.close();
});

test('at 390 x 800 the panels stack under the canvas', async () => {
  const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/`, { width: 390, height: 800 });
  assert.equal(await settle(page), 'done');
  const canvas = await box(page, '#canvas-wrap');
  const panel = await box(page, '#panel');
  assert.ok(panel.y >= canvas.y + canvas.height, 'panel under the canvas');
  assert.ok(canvas.width >= 350, `canvas ${canvas.width} wide`);
  assert.ok(await page.evaluate(() => document.documentElement.scrollWidth) <= 390, 'no sideways scrolling');
  await page.screenshot({ path: `${SCREENSHOTS}layout-390.png`, fullPage: true });
  assert.deepEqual(errors, []);
  await page.close();
});

test('at 390 x 844 the canvas comes right after the tools, before the toolbar\'s other rows', async () => {
  const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/`, { width: 390, height: 844 });
  assert.equal(await settle(page), 'done');
  const canvas = await box(page, '#canvas-wrap');
  const tools = await box(page, '[data-tool="select"]');
  assert.ok(tools.y + tools.height <= canvas.y, 'the tool buttons above the canvas');
  for (const id of ['#undo', '#fit', '#preset', '#export-menu', '#copy-link']) {
    const control = await box(page, id);
    assert.ok(control.y >= canvas.y + canvas.height, `${id} under the canvas (y ${control.y}, canvas ends at ${canvas.y + canvas.height})`);
  }
  const panel = await box(page, '#panel');
  const preset = await box(page, '#preset');
  assert.ok(panel.y >= preset.y + preset.height, 'the panels after the toolbar\'s rows');
  assert.ok(canvas.y < 844 / 3, `the canvas starts at ${canvas.y}, in the first third of the screen`);
  assert.ok(await page.evaluate(() => document.documentElement.scrollWidth) <= 390, 'no sideways scrolling');
  await page.screenshot({ path: `${SCREENSHOTS}layout-390x844.png` });
  assert.deepEqual(errors, []);
  await page.close();
});

test('every control has an accessible name', async () => {
  const { page } = await openPage(harness.context, `${harness.baseUrl}/web/`);
  const unnamed = await page.evaluate(() => [...document.querySelectorAll('button, input, select, canvas#canvas')]
    .filter((el) => {
      const labeled = (el.labels && [...el.labels].some((l) => l.textContent.trim())) ||
        el.getAttribute('aria-label') || el.getAttribute('aria-labelledby') ||
        (el.tagName === 'BUTTON' && el.textContent.trim());
      return !labeled;
    })
    .map((el) => el.outerHTML.slice(0, 80)));
  assert.deepEqual(unnamed, []);
  await page.close();
});

test('keyboard only: tools, zoom, step mode, and a visible focus ring', async () => {
  const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/`);
  assert.equal(await settle(page), 'done');
  // Tab from the start reaches the first tool button, which shows a focus outline.
  await page.keyboard.press('Tab');
  const focused = await page.evaluate(() => {
    const el = document.activeElement;
    return { tool: el.dataset.tool, outline: getComputedStyle(el).outlineStyle };
  });
  assert.equal(focused.tool, 'select');
  assert.notEqual(focused.outline, 'none');
  await page.keyboard.press('Enter');
  assert.equal(await page.getAttribute('[data-tool="select"]', 'aria-pressed'), 'true');

  await page.locator('#canvas').focus();
  await page.keyboard.press('r');
  assert.equal(await page.getAttribute('[data-tool="region"]', 'aria-pressed'), 'true');
  await page.keyboard.press('s');
  assert.equal(await page.isChecked('#step-mode'), true);
  assert.equal(await settle(page), 'done');
  assert.match(await page.locator('#step-info').textContent(), /^Step 0 of [\d,]+: .*before refinement|No refinement events/);
  await page.keyboard.press('s');
  assert.equal(await page.isChecked('#step-mode'), false);
  await page.keyboard.press('g');
  assert.equal(await page.isChecked('#snap'), true);
  assert.equal(await settle(page), 'done');
  assert.ok((await readStats(page)).triangles > 0);
  assert.deepEqual(errors, []);
  await page.close();
});

test('the server sends the right types and refuses paths outside the repository', async () => {
  const get = (path) => fetch(`${harness.baseUrl}${path}`);
  assert.equal((await get('/wasm/dist/ruppert.wasm')).headers.get('content-type'), 'application/wasm');
  assert.equal((await get('/wasm/dist/ruppert-formats.wasm')).headers.get('content-type'), 'application/wasm');
  assert.match((await get('/wasm/index.js')).headers.get('content-type'), /^text\/javascript/);
  assert.match((await get('/web/')).headers.get('content-type'), /^text\/html/);
  for (const path of ['/../../etc/passwd', '/web/..%2f..%2f..%2fetc%2fpasswd', '/%2e%2e/%2e%2e/etc/passwd']) {
    const response = await get(path);
    assert.ok(response.status === 403 || response.status === 404, `${path}: ${response.status}`);
    assert.doesNotMatch(await response.text(), /root:/);
  }
  assert.equal((await get('/no-such-file.js')).status, 404);
});

test('the server serves only the page and the published package files', async () => {
  const get = (path) => fetch(`${harness.baseUrl}${path}`);
  for (const path of ['/.git/config', '/.git/HEAD', '/.gitignore', '/.ci/run', '/package.json', '/package-lock.json',
    '/node_modules/playwright-core/package.json', '/README.md', '/core/src/refine/refine.cpp', '/wasm/binding/bindings.cpp',
    '/tests/browser/harness.mjs', '/web/.hidden', '/wasm/']) {
    const response = await get(path);
    assert.equal(response.status, 404, `${path} answered ${response.status}`);
    await response.arrayBuffer();
  }
  for (const path of ['/web/', '/web/index.html', '/web/main.js', '/wasm/index.js', '/wasm/dist/ruppert.mjs']) {
    const response = await get(path);
    assert.equal(response.status, 200, `${path} answered ${response.status}`);
    await response.arrayBuffer();
  }
});
