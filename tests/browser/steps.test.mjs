// Step-by-step mode: the trace (options.trace) played, stepped and scrubbed.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { presetDrawing } from '../../web/presets.js';
import { SCREENSHOTS, canvasFingerprint, launch, openPage, settle } from './harness.mjs';

let harness;
let page;
let errors;

before(async () => {
  harness = await launch();
  ({ page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/`));
  await settle(page);
});

after(async () => {
  await harness?.close();
});

const stepInfo = () => page.locator('#step-info').textContent();

function parseStep(text) {
  const match = /^Event (\d+) of (\d+): (.*)$/.exec(text);
  assert.ok(match, `step text: ${text}`);
  return { index: Number(match[1]), count: Number(match[2]), what: match[3] };
}

test('step mode records the events and steps through them', async () => {
  await page.selectOption('#preset', 'comb');
  assert.equal(await settle(page), 'done');
  assert.equal(await page.locator('#stepper').isHidden(), true);
  await page.check('#step-mode');
  assert.equal(await settle(page), 'done');
  assert.equal(await page.locator('#stepper').isVisible(), true);

  const first = parseStep(await stepInfo());
  assert.equal(first.index, 1);
  assert.ok(first.count > 5, `${first.count} events`);
  // Every event inserts one vertex: the mesh has the input's points plus one per event.
  const vertices = Number((await page.locator('#stat-vertices').textContent()).replace(/\D/g, ''));
  assert.equal(vertices, presetDrawing('comb').points.length / 2 + first.count);

  const picture = await canvasFingerprint(page);
  await page.click('#step-forward');
  await page.click('#step-forward');
  assert.equal(parseStep(await stepInfo()).index, 3);
  await page.waitForTimeout(50);
  assert.notEqual(await canvasFingerprint(page), picture, 'the canvas shows the new step');
  await page.click('#step-back');
  assert.equal(parseStep(await stepInfo()).index, 2);

  await page.locator('#canvas').focus();
  await page.keyboard.press('End');
  assert.equal(parseStep(await stepInfo()).index, first.count);
  await page.keyboard.press('Home');
  assert.equal(parseStep(await stepInfo()).index, 1);
  await page.keyboard.press('.');
  assert.equal(parseStep(await stepInfo()).index, 2);

  await page.fill('#step-scrub', String(Math.floor(first.count / 2)));
  assert.equal(parseStep(await stepInfo()).index, Math.floor(first.count / 2) + 1);
});

test('play advances on its own and pause stops it', async () => {
  // 30 events a second: the comb's events last long enough that playback is still running when the
  // pause is clicked, even on a loaded machine (at 120 it once ended first, and the click restarted it).
  await page.selectOption('#step-speed', '30');
  await page.click('#step-first');
  await page.click('#step-play');
  assert.equal(await page.getAttribute('#step-play', 'aria-label'), 'Pause');
  await page.waitForFunction(() => /^Event (\d+)/.exec(document.getElementById('step-info').textContent)[1] > 5);
  await page.click('#step-play');
  assert.equal(await page.getAttribute('#step-play', 'aria-label'), 'Play');
  const paused = parseStep(await stepInfo()).index;
  await page.waitForTimeout(200);
  assert.equal(parseStep(await stepInfo()).index, paused);
});

test('each kind of event is described with its geometry', async () => {
  // The fan has small input angles: segment splits; the skyline has skinny triangles.
  const seen = new Set();
  for (const preset of ['fan', 'skyline', 'two-sizes']) {
    await page.selectOption('#preset', preset);
    assert.equal(await settle(page), 'done');
    const { count } = parseStep(await stepInfo());
    for (let k = 0; k < count; k++) {
      await page.fill('#step-scrub', String(k));
      const { what } = parseStep(await stepInfo());
      const kind = /^Split subsegment \(\d+, \d+\)/.test(what) ? 'split'
        : /^Inserted the (circumcenter|off-center) of .*triangle \(\d+, \d+, \d+\)/.test(what) ? 'triangle'
          : /^The circumcenter \(.*\) of \(\d+, \d+, \d+\) encroached subsegment \(\d+, \d+\): rejected/.test(what) ? 'rejected'
            : 'unknown';
      assert.notEqual(kind, 'unknown', what);
      if (!seen.has(kind)) {
        seen.add(kind);
        await page.screenshot({ path: `${SCREENSHOTS}step-${kind}.png` });
      }
    }
  }
  assert.ok(seen.has('split') && seen.has('triangle'), [...seen].join(', '));
});

test('leaving step mode hides the stepper', async () => {
  await page.uncheck('#step-mode');
  assert.equal(await settle(page), 'done');
  assert.equal(await page.locator('#stepper').isHidden(), true);
});

test('no console errors', () => {
  assert.deepEqual(errors, []);
});
