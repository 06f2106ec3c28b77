// Events named as such and counted, and the section 6.6 exemptions marked: the stats panel's
// Events row gives the count of each kind the package's trace has; petal and optimal points are
// their own events with their own text; the fan's triangles in small input angles and on
// seditious edges are counted as the core counts them (mesh.reasons) and drawn in their colors.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { EventKind, init } from '../../wasm/index.js';
import { DEFAULT_OPTIONS, toMeshOptions, toPlc } from '../../web/model/drawing.js';
import { findPreset } from '../../web/panels/presets.js';
import { SCREENSHOTS, launch, openPage, settle } from './harness.mjs';

let harness;
let page;
let errors;
let mesher;

before(async () => {
  mesher = await init();
  harness = await launch();
  ({ page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/?bench=1`));
  await settle(page);
});

after(async () => {
  await harness?.close();
});

/** The package's trace for a preset with the page's options plus `extra`. */
function packageMesh(id, extra = {}) {
  const preset = findPreset(id);
  const drawing = { ...preset.build(), options: { ...DEFAULT_OPTIONS, ...(preset.options ?? {}), ...extra } };
  return mesher.triangulate(toPlc(drawing), toMeshOptions(drawing, { trace: true }));
}

/** The Events row as { name: count }. */
async function eventCounts() {
  const text = await page.locator('#stat-events').textContent();
  const counts = {};
  for (const part of text.split(', ')) {
    const match = /^([\d,]+) (.+?)s?$/.exec(part);
    assert.ok(match, `events row: ${text}`);
    counts[match[2]] = Number(match[1].replace(/,/g, ''));
  }
  return counts;
}

const kindCount = (mesh, kind) => mesh.events.kind.filter((k) => k === kind).length;

async function stepModeOn() {
  if (!(await page.isChecked('#step-mode'))) await page.check('#step-mode');
  assert.equal(await settle(page), 'done');
}

test('the Events row counts each kind of the trace, splits and rejections told apart', async () => {
  await page.selectOption('#preset', 'fan');
  assert.equal(await settle(page), 'done');
  assert.equal(await page.locator('#stat-events').textContent(), 'recorded in step mode');
  await stepModeOn();
  const counts = await eventCounts();
  const mesh = packageMesh('fan');
  const total = Object.values(counts).reduce((a, b) => a + b, 0);
  assert.equal(total, mesh.events.count);
  assert.equal((counts['midpoint split'] ?? 0) + (counts['shell split'] ?? 0), kindCount(mesh, EventKind.SEGMENT_SPLIT));
  assert.ok(counts['midpoint split'] > 0 && counts['shell split'] > 0, JSON.stringify(counts));
  assert.equal((counts['rejected circumcenter'] ?? 0) + (counts['rejected off-center'] ?? 0), kindCount(mesh, EventKind.REJECTED));
  assert.equal(counts['off-center'] ?? 0, kindCount(mesh, EventKind.OFF_CENTER));
  assert.equal(counts['circumcenter'] ?? 0, kindCount(mesh, EventKind.CIRCUMCENTER));
});

for (const [placement, kind, name] of [['petal', EventKind.PETAL_POINT, 'petal point'], ['optimal', EventKind.OPTIMAL_POINT, 'optimal point']]) {
  test(`${placement} placement: its points are events of their own, named and drawn`, async () => {
    await page.selectOption('#preset', 'skyline');
    assert.equal(await settle(page), 'done');
    await page.selectOption('#placement', placement);
    assert.equal(await settle(page), 'done');
    await stepModeOn();
    const mesh = packageMesh('skyline', { placement });
    const expected = kindCount(mesh, kind);
    assert.ok(expected > 0, `the package's trace has ${expected} ${name}s`);
    assert.equal((await eventCounts())[name], expected);
    const e = mesh.events.kind.indexOf(kind);
    await page.fill('#step-scrub', String(e + 1));
    await page.waitForFunction((k) => document.body.dataset.stepShown === String(k), e + 1, { timeout: 20_000 });
    const info = await page.locator('#step-info').textContent();
    assert.match(info, new RegExp(`Inserted the ${name} of skinny triangle`), info);
    assert.match(info, new RegExp(`vertex ${mesh.events.vertex[e]}\\.$`), info);
    await page.screenshot({ path: `${SCREENSHOTS}event-${placement}-point.png` });
    await page.uncheck('#step-mode');
    assert.equal(await settle(page), 'done');
    await page.selectOption('#placement', 'offcenter');
    assert.equal(await settle(page), 'done');
  });
}

/** Pixels of the 2D canvas (the overlays) drawn in about rgb (un-premultiplied, half opaque or more). */
function countColor(rgb) {
  return page.evaluate((want) => {
    const c = document.getElementById('canvas');
    const data = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < data.length; i += 4) {
      if (data[i + 3] > 128 && Math.abs(data[i] - want[0]) <= 24 && Math.abs(data[i + 1] - want[1]) <= 24 && Math.abs(data[i + 2] - want[2]) <= 24) n++;
    }
    return n;
  }, rgb);
}

/** Centers the view on triangle t of the mesh on screen, about `size` pixels across. */
function zoomTo(t, size = 150) {
  return page.evaluate(([tri, px]) => {
    const { view, renderer, draw } = window.ruppertBench;
    const p = renderer.mesh.points; const v = renderer.mesh.triangles;
    const xs = [0, 1, 2].map((c) => p[2 * v[3 * tri + c]]); const ys = [0, 1, 2].map((c) => p[2 * v[3 * tri + c] + 1]);
    view.centerX = (xs[0] + xs[1] + xs[2]) / 3;
    view.centerY = (ys[0] + ys[1] + ys[2]) / 3;
    view.scale = px / Math.max(Math.max(...xs) - Math.min(...xs), Math.max(...ys) - Math.min(...ys));
    draw();
  }, [t, size]);
}

test('triangles in small input angles and on seditious edges are counted as the core does and drawn', async () => {
  await page.selectOption('#preset', 'fan');
  assert.equal(await settle(page), 'done');
  const mesh = packageMesh('fan');
  const reason = (kind) => mesh.reasons.find((r) => r.kind === kind)?.count ?? 0;
  const nestled = reason('SMALL_INPUT_ANGLE');
  const seditious = reason('SEDITIOUS_EDGE');
  assert.ok(nestled > 0 && seditious > 0, `the fan has ${nestled} nestled and ${seditious} seditious triangles`);
  const text = await page.locator('#stat-exempt').textContent();
  assert.equal(text, `${nestled} in small input angles (hatched), ${seditious} on seditious edges (edge in teal)`);
  const legend = await page.locator('#legend').textContent();
  assert.match(legend, /in a small input angle \(exempt\)/);
  assert.match(legend, /seditious edge \(exempt\)/);
  // Zoomed to one of each: the violet hatching and the orange edges show there.
  const marked = await page.evaluate(() => window.ruppertBench.exemptions());
  const { nestled: [first], seditious: [other] } = marked;
  // They are the core's: mesh.triangleExemptions, 1 nestled, 2 seditious, as many as reasons count.
  const flags = Array.from(mesh.triangleExemptions);
  assert.equal(flags.length, mesh.triangles.length / 3);
  assert.deepEqual(marked.nestled, flags.flatMap((f, t) => (f === 1 ? [t] : [])));
  assert.deepEqual(marked.seditious, flags.flatMap((f, t) => (f === 2 ? [t] : [])));
  assert.equal(marked.nestled.length, nestled);
  assert.equal(marked.seditious.length, seditious);
  await zoomTo(first);
  const violet = await countColor([0x70, 0x48, 0xe8]);
  await page.screenshot({ path: `${SCREENSHOTS}exemptions-fan-nestled.png` });
  await zoomTo(other);
  const teal = await countColor([0x0b, 0x72, 0x85]);
  await page.screenshot({ path: `${SCREENSHOTS}exemptions-fan-seditious.png` });
  assert.ok(violet > 50, `${violet} violet pixels around nestled triangle ${first}`);
  assert.ok(teal > 50, `${teal} teal pixels around seditious triangle ${other}`);
  assert.deepEqual(errors, []);
});
