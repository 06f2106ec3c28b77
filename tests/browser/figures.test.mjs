// The chapter's figures as presets (each names its figure in a caption), and the page's small
// promises: the slider's warning past 34 degrees, the preset box after a file is opened.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { init } from '../../wasm/index.js';
import { DEFAULT_OPTIONS, toMeshOptions, toPlc } from '../../web/model/drawing.js';
import { triangleShape } from '../../web/geometry/mesh-geometry.js';
import { DEFAULT_PRESET, PRESETS, findPreset } from '../../web/panels/presets.js';
import { SCREENSHOTS, launch, openPage, readStats, settle } from './harness.mjs';

let harness;
let page;
let errors;

before(async () => {
  harness = await launch();
  ({ page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/`));
  assert.equal(await settle(page), 'done');
});

after(async () => {
  await harness?.close();
});

test('the first sight is a drawing whose mesh shows refinement: many triangles, graded', async () => {
  const stats = await readStats(page);
  assert.ok(stats.triangles >= 150, `${stats.triangles} triangles`);
  assert.equal(await page.inputValue('#preset'), DEFAULT_PRESET);
  assert.ok((await page.locator('#preset-caption').textContent()).length > 40, 'a caption says what it shows');
  // Graded: the largest triangle is many times the smallest (Fig. 6.9 at 30 degrees with the
  // default placement, the old first sight, is ten large triangles and a sliver).
  const preset = findPreset(DEFAULT_PRESET);
  const drawing = { ...preset.build(), options: { ...DEFAULT_OPTIONS, ...preset.options } };
  const mesh = (await init()).triangulate(toPlc(drawing), toMeshOptions(drawing));
  assert.equal(mesh.stats.triangles, stats.triangles, 'the page shows the package\'s mesh');
  const areas = Array.from({ length: mesh.triangles.length / 3 }, (_, t) => triangleShape(mesh, t).area);
  assert.ok(Math.max(...areas) > 10 * Math.min(...areas), `areas ${Math.min(...areas)} to ${Math.max(...areas)}`);
  await page.screenshot({ path: `${SCREENSHOTS}first-sight.png` });
});

test('each figure preset names its figure, applies its options and meshes completely', async () => {
  // The chapter's figures (the presets of one idea each are tested by teach.test.mjs).
  const figures = PRESETS.filter((p) => /^Figures? 6\./.test(p.caption ?? ''));
  assert.ok(figures.length >= 9, `${figures.length} figure presets`);
  for (const preset of figures) {
    await page.selectOption('#preset', preset.id);
    assert.equal(await settle(page), 'done', preset.id);
    assert.match(preset.name, /^Figs?\. 6\.\d+/, preset.id);
    const caption = await page.locator('#preset-caption').textContent();
    assert.match(caption, /^Figures? 6\.\d+/, `${preset.id}: ${caption}`);
    assert.equal(await page.locator('#preset-caption').isVisible(), true);
    if (preset.options?.minAngle !== undefined) {
      assert.equal(Number(await page.inputValue('#min-angle')), preset.options.minAngle, preset.id);
    }
    if (preset.options?.variant) assert.equal(await page.inputValue('#variant'), preset.options.variant, preset.id);
    if (preset.steps) {
      assert.equal(await page.isChecked('#step-mode'), true, `${preset.id} opens in step mode`);
      // The panel describes the step on screen: the final mesh is the last step.
      await page.click('#step-last');
      const last = Number(/ of ([\d,]+)/.exec(await page.locator('#step-info').textContent())[1].replace(/,/g, ''));
      await page.waitForFunction((k) => document.body.dataset.stepShown === String(k), last);
    }
    const stats = await readStats(page);
    assert.equal(stats.complete, 'yes', preset.id);
    await page.screenshot({ path: `${SCREENSHOTS}figure-${preset.id}.png` });
  }
  await page.uncheck('#step-mode');
  await settle(page);
});

test('the slider warns past what the placement reaches: 40 degrees with optimal points, 34 with off-centers', async () => {
  const angle = async (value) => {
    await page.fill('#min-angle', String(value));
    await page.press('#min-angle', 'Enter');
    await settle(page);
  };
  assert.equal(await page.inputValue('#placement'), 'optimal');
  await angle(36);
  assert.equal(await page.locator('#min-angle-warning').isHidden(), true, 'optimal points at 36°');
  await angle(41);
  assert.equal(await page.locator('#min-angle-warning').isVisible(), true, 'optimal points at 41°');
  await page.selectOption('#placement', 'offcenter');
  await angle(33);
  assert.equal(await page.locator('#min-angle-warning').isHidden(), true, 'off-centers at 33°');
  await angle(36);
  assert.equal(await page.locator('#min-angle-warning').isVisible(), true, 'off-centers at 36°');
  // The note and the placement box say the same of the default placement: 35-40 degrees.
  assert.match(await page.locator('#min-angle-note').textContent(), /optimal points\) bounds of 35-40°/);
  assert.match(await page.locator('#placement option[value="optimal"]').textContent(), /35-40°/);
  await page.selectOption('#placement', 'optimal');
  assert.equal(await page.getAttribute('#min-angle-range', 'list'), 'angle-marks');
  const marks = await page.locator('#angle-marks option').evaluateAll((o) => o.map((x) => Number(x.value)));
  assert.ok(marks.includes(20.7) && marks.includes(34) && marks.includes(40), marks.join(', '));
  await page.fill('#min-angle', '30');
  await page.press('#min-angle', 'Enter');
  await settle(page);
});

test('optimal points are offered, mesh past 34 degrees and survive the link', async () => {
  await page.selectOption('#preset', 'figure-6-9-30');
  await settle(page);
  await page.selectOption('#placement', 'optimal');
  await page.fill('#min-angle', '36');
  await page.press('#min-angle', 'Enter');
  assert.equal(await settle(page), 'done');
  const stats = await readStats(page);
  assert.ok(stats.triangles > 0);
  const { decodeDrawing } = await import('../../web/io/url-state.js');
  const drawing = decodeDrawing(await page.evaluate(() => location.hash));
  assert.equal(drawing.options.placement, 'optimal');
  assert.equal(drawing.options.minAngle, 36);
  await page.selectOption('#placement', 'offcenter');
  await page.fill('#min-angle', '30');
  await page.press('#min-angle', 'Enter');
  await settle(page);
});

test('opening a file clears the preset box and its caption', async () => {
  await page.selectOption('#preset', 'comb');
  await settle(page);
  const poly = '4 2 0 0\n0 0 0\n1 3 0\n2 3 2\n3 0 2\n4 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n0\n';
  await page.setInputFiles('#file-input', { name: 'rectangle.poly', mimeType: 'text/plain', buffer: Buffer.from(poly) });
  assert.equal(await settle(page), 'done');
  assert.equal(await page.inputValue('#preset'), '');
  assert.equal(await page.locator('#preset-caption').isHidden(), true);
});

test('no console errors', () => {
  assert.deepEqual(errors, []);
});
