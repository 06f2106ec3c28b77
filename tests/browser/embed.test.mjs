// Embedding: ?embed=1 and the postMessage protocol, through web/embed-example.html.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { init } from '../../wasm/index.js';
import { DEFAULT_OPTIONS, toMeshOptions, toPlc } from '../../web/model/drawing.js';
import { presetDrawing } from '../../web/panels/presets.js';
import { encodeDrawing } from '../../web/io/url-state.js';
import { SCREENSHOTS, launch, openPage, settle, startHostPage } from './harness.mjs';

let harness;
let page;
let errors;

before(async () => {
  harness = await launch();
  ({ page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/embed-example.html`));
});

after(async () => {
  await harness?.close();
});

const replies = () => page.locator('#log li').evaluateAll((items) => items.map((li) => ({
  kind: li.className, text: li.textContent, triangles: Number(li.dataset.triangles), id: li.dataset.id,
})));

async function waitForReplies(count) {
  await page.waitForFunction((n) => document.querySelectorAll('#log li').length >= n, count, { timeout: 20_000 });
  return replies();
}

test('the host page loads a .poly into the frame and prints the meshed reply', async () => {
  // On ruppert:ready the host sends the 8 x 5 rectangle, max area 1, with id 1: one reply.
  await page.waitForFunction(() => document.querySelector('#log li[data-id="1"]'), null, { timeout: 20_000 });
  assert.match(await page.locator('#ready').textContent(), /^Ready: protocol 1, package \d+\.\d+\.\d+\.$/);
  const second = (await replies()).find((r) => r.id === '1');
  assert.equal(second.kind, 'meshed');
  assert.equal((await replies()).filter((r) => r.id === '1').length, 1);
  assert.ok(second.triangles >= 40, `an 8 x 5 rectangle with max area 1 has at least 40 triangles: ${second.text}`);
  assert.match(second.text, /complete: true/);
  // The frame shows the same numbers as its own (hidden) stats panel.
  const frame = page.frameLocator('#mesher');
  assert.equal(Number((await frame.locator('#stat-triangles').textContent()).replace(/\D/g, '')), second.triangles);
});

test('?embed=1 shows only the canvas and minimal controls', async () => {
  const frame = page.frameLocator('#mesher');
  assert.equal(await frame.locator('body').getAttribute('class'), 'embed');
  assert.equal(await frame.locator('#topbar').isHidden(), true);
  assert.equal(await frame.locator('#stats').isHidden(), true);
  assert.equal(await frame.locator('#help').isHidden(), true);
  assert.equal(await frame.locator('#canvas').isVisible(), true);
  assert.equal(await frame.locator('#min-angle').isVisible(), true);
  assert.equal(await frame.locator('#max-area').isHidden(), true);
  await page.screenshot({ path: `${SCREENSHOTS}embed-example.png` });
});

test('options of later messages apply: a smaller max area gives more triangles', async () => {
  const before = (await replies()).length;
  const previous = (await replies()).at(-1);
  await page.fill('#max-area', '0.2');
  await page.click('#send');
  const all = await waitForReplies(before + 1);
  const reply = all.at(-1);
  assert.equal(reply.kind, 'meshed');
  assert.ok(reply.triangles > previous.triangles, `${reply.triangles} > ${previous.triangles}`);
  // The frame's min angle control follows the message's options.
  assert.equal(await page.frameLocator('#mesher').locator('#min-angle').inputValue(), '30');
});

test('a malformed .poly gets a ruppert:error reply', async () => {
  const before = (await replies()).length;
  await page.fill('#poly', '4 2 0 0\n1 0 0\n');
  await page.click('#send');
  const reply = (await waitForReplies(before + 1)).at(-1);
  assert.equal(reply.kind, 'error');
  assert.match(reply.text, /PARSE_ERROR/);
});

test('the example host opens a preset by name and gets its mesh', async () => {
  const before = (await replies()).length;
  await page.selectOption('#preset', 'figure-6-4');
  await page.click('#send-preset');
  const meshed = (await waitForReplies(before + 1))[before];
  assert.equal(meshed.kind, 'meshed');
  // The preset opens in step mode: its step 0 is announced too ('stepped', unasked, id null),
  // whenever that step's mesh arrives; the reply to getMesh is the 'mesh' among what follows.
  await page.click('#get-mesh');
  await page.waitForFunction((n) => [...document.querySelectorAll('#log li')].slice(n).some((li) => li.className === 'mesh'),
    before + 1, { timeout: 20_000 });
  const mesh = (await replies()).slice(before + 1).find((r) => r.kind === 'mesh');
  assert.equal(mesh.triangles, meshed.triangles);
  assert.match(await page.frameLocator('#mesher').locator('#preset-caption').textContent(), /^Figure 6\.4/);
});

test('the embed is read-only unless &edit=1', async () => {
  for (const [query, editable] of [['embed=1', false], ['embed=1&edit=1', true]]) {
    const { page: framed, errors: own } = await openPage(harness.context, `${harness.baseUrl}/web/index.html?${query}`);
    assert.equal(await settle(framed), 'done');
    const hash = await framed.evaluate(() => location.hash.replace(/&view=[^&]*/, ''));
    const box = await framed.locator('#canvas').boundingBox();
    await framed.mouse.click(box.x + box.width * 0.37, box.y + box.height * 0.41);
    await framed.keyboard.press('Delete');
    await framed.waitForTimeout(200);
    const after = await framed.evaluate(() => location.hash.replace(/&view=[^&]*/, ''));
    if (editable) assert.notEqual(after, hash, `${query}: a click adds a vertex`);
    else assert.equal(after, hash, `${query}: a click leaves the drawing alone`);
    assert.deepEqual(own, []);
    await framed.close();
  }
});

test('the embed shows the step controls, the legend and a link to the full page with the same state', async () => {
  const { page: framed, errors: own } = await openPage(harness.context, `${harness.baseUrl}/web/index.html?embed=1`);
  assert.equal(await settle(framed), 'done');
  assert.equal(await framed.locator('#legend').isVisible(), true);
  assert.equal(await framed.locator('#step-mode').isVisible(), true);
  await framed.check('#step-mode');
  assert.equal(await settle(framed), 'done');
  assert.equal(await framed.locator('#step-forward').isVisible(), true);
  await framed.click('#step-forward');
  await framed.click('#step-forward');
  await framed.waitForFunction(() => document.body.dataset.stepShown === '2');
  await framed.waitForFunction(() => /&step=2/.test(document.getElementById('open-full').href));
  const link = await framed.getAttribute('#open-full', 'href');
  assert.doesNotMatch(link, /embed=1/);
  // The link opens the full page at the same step.
  const { page: full, errors: fullErrors } = await openPage(harness.context, new URL(link, framed.url()).href);
  assert.equal(await settle(full), 'done');
  await full.waitForFunction(() => document.body.dataset.stepShown === '2');
  assert.match(await full.locator('#step-info').textContent(), /^Step 2 of [\d,]+/);
  assert.equal(await full.locator('#topbar').isVisible(), true);
  await framed.screenshot({ path: `${SCREENSHOTS}embed-stepping.png` });
  assert.deepEqual([...own, ...fullErrors], []);
  await full.close();
  await framed.close();
});

test('the link keeps the step, the coloring and the view', async () => {
  const drawing = { ...presetDrawing('comb'), options: { ...DEFAULT_OPTIONS } };
  const url = `${harness.baseUrl}/web/#${encodeDrawing(drawing)}&step=7&color=region&view=1.5,0.5,80`;
  const { page: opened, errors: own } = await openPage(harness.context, url);
  assert.equal(await settle(opened), 'done');
  await opened.waitForFunction(() => document.body.dataset.stepShown === '7');
  assert.match(await opened.locator('#step-info').textContent(), /^Step 7 of [\d,]+/);
  assert.equal(await opened.locator('#color-mode').inputValue(), 'region');
  await opened.waitForTimeout(400);
  const hash = await opened.evaluate(() => location.hash);
  assert.match(hash, /&step=7/);
  assert.match(hash, /&color=region/);
  assert.match(hash, /&view=1\.5,0\.5,80/);
  assert.deepEqual(own, []);
  await opened.close();
});

test('a host page on another origin loads a drawing with an id and steps through it', async () => {
  // The host is served by a second server (another port: another origin); the frame by the page's.
  const host = await startHostPage(harness.baseUrl);
  const hostUrl = host.url;
  assert.notEqual(new URL(hostUrl).origin, host.frameOrigin);
  const { page: hostPage, errors: own } = await openPage(harness.context, hostUrl);
  try {
    await hostPage.waitForFunction(() => window.replies.some((r) => r.type === 'ruppert:meshed'), null, { timeout: 20_000 });
    const poly = '4 2 0 0\n0 0 0\n1 6 0\n2 6 1\n3 0 1\n4 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n0\n';
    await hostPage.evaluate((p) => window.send({ type: 'ruppert:load', id: 'lesson-1', poly: p, options: { minAngle: 30, placement: 'offcenter' } }), poly);
    const meshed = await hostPage.waitForFunction(
      () => window.replies.find((r) => r.type === 'ruppert:meshed' && r.id === 'lesson-1'), null, { timeout: 20_000 });
    const stats = (await meshed.jsonValue()).stats;
    const plc = { points: [0, 0, 6, 0, 6, 1, 0, 1], segments: [0, 1, 1, 2, 2, 3, 3, 0] };
    const mesher = await init();
    assert.equal(stats.triangles, mesher.triangulate(plc, { minAngle: 30 }).stats.triangles);
    for (const index of [3, 0, 1]) {
      await hostPage.evaluate((i) => window.send({ type: 'ruppert:step', index: i }), index);
      const stepped = await (await hostPage.waitForFunction(
        (i) => window.replies.find((r) => r.type === 'ruppert:stepped' && r.index === i), index, { timeout: 20_000 })).jsonValue();
      const expected = mesher.triangulate(plc, { minAngle: 30, maxSteiner: index }).stats;
      assert.equal(stepped.vertices, expected.vertices, `step ${index}`);
      assert.equal(stepped.triangles, expected.triangles, `step ${index}`);
      assert.equal(stepped.vertices, 4 + index);
      assert.ok(stepped.total >= 3);
      if (index > 0) assert.match(stepped.event, /vertex \d+/);
      else assert.equal(stepped.event, null);
    }
    // A bad option is answered with an error carrying the id.
    await hostPage.evaluate((p) => window.send({ type: 'ruppert:load', id: 9, poly: p, options: { minAngel: 30 } }), poly);
    const error = await (await hostPage.waitForFunction(
      () => window.replies.find((r) => r.type === 'ruppert:error' && r.id === 9), null, { timeout: 20_000 })).jsonValue();
    assert.equal(error.code, 'INVALID_OPTION');
    assert.match(error.message, /minAngel/);
    assert.deepEqual(own, []);
  } finally {
    await hostPage.close();
    await host.close();
  }
});

test('no console errors', () => {
  assert.deepEqual(errors, []);
});
