// Presets open in the same state whatever came before: their own options over the defaults, the
// replay at step 0 when they ask for steps, else (in step mode) at the final mesh.
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

// A figure that steps, one that does not, one with another algorithm, and the two ideas whose
// presets carry their own views (the side-by-side comparison, the size measure).
const IDS = ['figure-6-4', 'skyline', 'comb-box', 'placement-compare', 'size-measure'];

/** What the page shows of a preset once it is meshed. */
async function presetState(page, id) {
  await page.selectOption('#preset', id);
  assert.equal(await settle(page), 'done', id);
  // In step mode the Mesh panel shows the step's mesh, which arrives after the final one.
  if (await page.locator('#stepper').isVisible()) {
    const index = Number(/^Step ([\d,]+)/.exec(await page.locator('#step-info').textContent())?.[1].replace(/,/g, ''));
    await page.waitForFunction((k) => document.body.dataset.stepShown === String(k), index);
  }
  return {
    stats: await readStats(page),
    stepMode: await page.isChecked('#step-mode'),
    stepInfo: await page.locator('#stepper').isVisible() ? await page.locator('#step-info').textContent() : null,
    options: await page.evaluate(() => ['min-angle', 'max-area', 'placement', 'variant', 'encroachment', 'max-steiner']
      .map((id) => document.getElementById(id).value).concat(document.getElementById('size-measure').checked)),
    comparing: await page.locator('#compare').isVisible(),
    sizeMeasure: await page.locator('#stat-size-measure').textContent(),
    caption: await page.locator('#preset-caption').textContent(),
  };
}

test('a preset opens the same after other options and a replay step as on a fresh page', async () => {
  const { page: fresh, errors: freshErrors } = await openPage(harness.context, `${harness.baseUrl}/web/`);
  assert.equal(await settle(fresh), 'done');
  const expected = {};
  for (const id of IDS) expected[id] = await presetState(await reopen(fresh), id);
  assert.match(expected['figure-6-4'].stepInfo, /^Step 0 of \d+/);
  assert.equal(expected.skyline.stepMode, false);
  assert.equal(expected['figure-6-4'].stepMode, true);

  const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/`);
  assert.equal(await settle(page), 'done');
  for (const id of IDS) {
    // Another state first: max area 0.5, another placement, step mode at some step.
    await page.fill('#max-area', '0.5');
    await page.locator('#max-area').dispatchEvent('change');
    await page.selectOption('#placement', 'circumcenter');
    if (!(await page.isChecked('#step-mode'))) await page.check('#step-mode');
    assert.equal(await settle(page), 'done');
    await page.click('#step-first');
    for (let i = 0; i < 5; i++) await page.click('#step-forward');
    await page.waitForFunction(() => document.body.dataset.stepShown === '5');
    const state = await presetState(page, id);
    if (expected[id].stepMode) {
      assert.deepEqual(state, expected[id], id);
    } else {
      // Step mode is the reader's to turn off: the preset shows its final mesh in it.
      const { stepMode, stepInfo, ...rest } = state;
      const { stepMode: freshMode, stepInfo: freshInfo, ...freshRest } = expected[id];
      assert.deepEqual(rest, freshRest, id);
      assert.equal(stepMode, true, id);
      assert.match(stepInfo, /^Step ([\d,]+) of \1: /, `${id} opens at the final mesh`);
    }
  }
  await page.screenshot({ path: `${SCREENSHOTS}preset-after-other-state.png` });
  assert.deepEqual([...freshErrors, ...errors], []);
  await fresh.close();
  await page.close();
});

/** A fresh page each time: the presets must not depend on one another either. */
async function reopen(page) {
  await page.goto(`${harness.baseUrl}/web/`);
  assert.equal(await settle(page), 'done');
  return page;
}
