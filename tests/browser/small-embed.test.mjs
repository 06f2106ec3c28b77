// The page in small frames and on a laptop screen: the README's 640 x 480 embed keeps most of its
// height for the canvas, in step mode too, with every control in view and no sideways scrolling;
// the full page at 1024 x 680 has its toolbar in two rows and its status line in view.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { SCREENSHOTS, launch, openPage, settle, startHostPage } from './harness.mjs';

let harness;
let host;

before(async () => {
  harness = await launch();
  host = await startHostPage(harness.baseUrl);
});

after(async () => {
  await harness?.close();
  await host?.close();
});

/** In the frame: the canvas's box, the visible controls' boxes, and the scroll sizes. */
function measure(frame) {
  return frame.evaluate(() => {
    const box = (el) => { const r = el.getBoundingClientRect(); return { id: el.id, top: r.top, bottom: r.bottom, left: r.left, right: r.right, height: r.height }; };
    const visible = (el) => el.getClientRects().length > 0 && getComputedStyle(el).visibility !== 'hidden';
    const controls = ['min-angle', 'step-mode', 'step-scrub', 'step-play', 'step-first', 'step-last', 'step-speed', 'status', 'step-info']
      .map((id) => document.getElementById(id)).filter(visible).map(box);
    return {
      canvas: box(document.getElementById('canvas-wrap')),
      controls,
      width: innerWidth, height: innerHeight,
      scrollWidth: document.documentElement.scrollWidth,
      stepMode: document.getElementById('step-mode').checked,
    };
  });
}

function checkFits(m, share, what) {
  console.log(`${what}: canvas ${Math.round(m.canvas.height)} of ${m.height} px (${Math.round(100 * m.canvas.height / m.height)}%)`);
  assert.ok(m.canvas.height >= share * m.height, `${what}: canvas ${m.canvas.height} px of ${m.height} (wanted ${share * 100}%)`);
  assert.ok(m.canvas.top >= 0 && m.canvas.bottom <= m.height && m.canvas.left >= 0 && m.canvas.right <= m.width,
    `${what}: the canvas is wholly visible: ${JSON.stringify(m.canvas)}`);
  for (const c of m.controls) assert.ok(c.top >= 0 && c.bottom <= m.height + 0.5 && c.right <= m.width + 0.5, `${what}: #${c.id} in view: ${JSON.stringify(c)}`);
  assert.ok(m.scrollWidth <= m.width, `${what}: no sideways scroll (${m.scrollWidth} > ${m.width})`);
}

async function ask(page, message, type) {
  const from = await page.evaluate(() => window.replies.length);
  await page.evaluate((m) => window.send(m), message);
  await page.waitForFunction(([n, t, id]) => window.replies.slice(n).some((r) => r.type === t && r.id === id),
    [from, type, message.id], { timeout: 20_000 });
}

test('the 640 x 480 embed: the canvas keeps >= 55% of the height, >= 45% in step mode, all in view', async () => {
  const { page, errors } = await openPage(harness.context, host.url);
  await page.waitForFunction(() => window.replies.some((r) => r.type === 'ruppert:meshed'), null, { timeout: 20_000 });
  const frame = page.frames().find((f) => f.url().includes('embed=1'));
  assert.ok(frame, 'the embedded frame');
  const plain = await measure(frame);
  assert.equal(plain.width, 640);
  checkFits(plain, 0.55, 'the default drawing');
  await page.screenshot({ path: `${SCREENSHOTS}embed-640x480.png` });

  // figure-6-4 opens in step mode, with its stage buttons and captions.
  await ask(page, { type: 'ruppert:preset', id: 'fig', name: 'figure-6-4' }, 'ruppert:meshed');
  await frame.locator('#step-stages button').first().waitFor();
  const figure = await measure(frame);
  assert.equal(figure.stepMode, true);
  checkFits(figure, 0.45, 'figure-6-4 in step mode');
  await page.screenshot({ path: `${SCREENSHOTS}embed-640x480-figure-6-4.png` });

  // A step of a loaded drawing, with a long event text.
  await ask(page, { type: 'ruppert:preset', id: 'lake', name: 'lake' }, 'ruppert:meshed');
  await ask(page, { type: 'ruppert:step', id: 'st', index: 5 }, 'ruppert:stepped');
  const stepped = await measure(frame);
  assert.equal(stepped.stepMode, true);
  checkFits(stepped, 0.45, 'lake at step 5');
  // The legend is one click away.
  await frame.click('#step-legend-box > summary');
  assert.equal(await frame.locator('#step-legend').isVisible(), true);
  assert.deepEqual(errors, []);
  await page.close();
});

test('the full page at 1024 x 680: the toolbar in two rows, the status line in view', async () => {
  const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/`, { width: 1024, height: 680 });
  assert.equal(await settle(page), 'done');
  const rows = await page.evaluate(() => {
    const tops = [...document.querySelectorAll('#topbar h1, #topbar .tool-group > *')]
      .filter((el) => el.getClientRects().length > 0).map((el) => Math.round(el.getBoundingClientRect().top));
    // Items of one row differ in top by a few pixels (their heights differ): rows are tops > 12 px apart.
    const sorted = [...new Set(tops)].sort((a, b) => a - b);
    return sorted.filter((t, i) => i === 0 || t - sorted[i - 1] > 12).length;
  });
  assert.ok(rows <= 2, `the toolbar takes ${rows} rows`);
  const status = await page.locator('#status').boundingBox();
  assert.ok(status.y >= 0 && status.y + status.height <= 680, `status line at ${JSON.stringify(status)}`);
  const canvas = await page.locator('#canvas-wrap').boundingBox();
  assert.ok(canvas.y + canvas.height <= 680 && canvas.height >= 400, `canvas ${JSON.stringify(canvas)}`);
  assert.ok(await page.evaluate(() => document.documentElement.scrollWidth <= innerWidth), 'no sideways scroll');
  // The exports are one click away, in a menu.
  await page.click('#export-menu > summary');
  assert.equal(await page.locator('#export-png').isVisible(), true);
  await page.keyboard.press('Escape');
  assert.equal(await page.locator('#export-png').isVisible(), false);
  await page.screenshot({ path: `${SCREENSHOTS}layout-1024x680.png` });
  assert.deepEqual(errors, []);
  await page.close();
});
