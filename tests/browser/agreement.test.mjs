// The page and the package agree: a value of an option the package refuses is refused by the page
// with the package's own words (never quietly read as "none"), and what it accepts the page takes.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { init } from '../../wasm/index.js';
import { launch, openPage, readStats, settle } from './harness.mjs';

let harness;
let mesher;

before(async () => {
  harness = await launch();
  mesher = await init();
});

after(async () => {
  await harness?.close();
});

const SQUARE = { points: [0, 0, 1, 0, 1, 1, 0, 1], segments: [0, 1, 1, 2, 2, 3, 3, 0] };

/** The package's message for that option value, or null when it takes it. */
function packageSays(name, value) {
  try {
    mesher.triangulate(SQUARE, { [name]: value });
    return null;
  } catch (error) {
    return error.message;
  }
}

test('the option fields refuse what the package refuses, in its words, and keep the mesh', async () => {
  const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/`);
  assert.equal(await settle(page), 'done');
  const cases = [
    ['#max-area', 'maxArea', '-1'], ['#max-area', 'maxArea', '0.5'], ['#max-area', 'maxArea', '0'],
    ['#max-steiner', 'maxSteiner', '-1'], ['#max-steiner', 'maxSteiner', '2.5'], ['#max-steiner', 'maxSteiner', '40'],
    ['#curve-tolerance', 'curveTolerance', '-0.1'], ['#curve-tolerance', 'curveTolerance', '0.01'],
  ];
  for (const [field, name, text] of cases) {
    const before = await readStats(page);
    await page.fill(field, text);
    await page.locator(field).dispatchEvent('change');
    const said = packageSays(name, Number(text));
    if (said === null) {
      assert.equal(await page.getAttribute(field, 'aria-invalid'), null, `${name} = ${text} is taken`);
      assert.equal(await settle(page), 'done');
    } else {
      assert.equal(await page.getAttribute(field, 'aria-invalid'), 'true', `${name} = ${text} is refused`);
      const status = await page.locator('#status').textContent();
      assert.ok(status.includes(said), `the page says "${status}", the package "${said}"`);
      assert.equal(await page.getAttribute('#status', 'data-kind'), 'error');
      assert.deepEqual(await readStats(page), before, 'the mesh is kept');
    }
    await page.fill(field, '');
    await page.locator(field).dispatchEvent('change');
    assert.equal(await settle(page), 'done');
  }
  assert.deepEqual(errors, []);
  await page.close();
});
