// Embedding: ?embed=1 and the postMessage protocol, through web/embed-example.html.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { SCREENSHOTS, launch, openPage } from './harness.mjs';

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
  kind: li.className, text: li.textContent, triangles: Number(li.dataset.triangles),
})));

async function waitForReplies(count) {
  await page.waitForFunction((n) => document.querySelectorAll('#log li').length >= n, count, { timeout: 20_000 });
  return replies();
}

test('the host page loads a .poly into the frame and prints the meshed reply', async () => {
  // Reply 1: the frame's default drawing. Reply 2: the 8 x 5 rectangle the host sent, max area 1.
  const [first, second] = await waitForReplies(2);
  assert.equal(first.kind, 'meshed');
  assert.equal(second.kind, 'meshed');
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

test('no console errors', () => {
  assert.deepEqual(errors, []);
});
