// Step-by-step mode: the trace (options.trace) played, stepped and scrubbed; step k shows the mesh
// after k events (insertions, and moves of free vertices), the one `maxSteiner: k` gives through the
// package.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { EventKind, init } from '../../wasm/index.js';
import { DEFAULT_OPTIONS, toMeshOptions, toPlc } from '../../web/model/drawing.js';
import { presetDrawing } from '../../web/panels/presets.js';
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
  const match = /^Step ([\d,]+) of ([\d,]+): (.*)$/.exec(text);
  assert.ok(match, `step text: ${text}`);
  const number = (digits) => Number(digits.replace(/,/g, ''));
  return { index: number(match[1]), count: number(match[2]), what: match[3] };
}

test('step mode records the events and steps through them', async () => {
  await page.selectOption('#preset', 'comb');
  assert.equal(await settle(page), 'done');
  assert.equal(await page.locator('#stepper').isHidden(), true);
  // The page's mesh without step mode (in step mode the panel speaks of the step on screen).
  const vertices = Number((await page.locator('#stat-vertices').textContent()).replace(/\D/g, ''));
  await page.check('#step-mode');
  assert.equal(await settle(page), 'done');
  assert.equal(await page.locator('#stepper').isVisible(), true);

  const first = parseStep(await stepInfo());
  assert.equal(first.index, 0);
  assert.match(first.what, /before refinement/);
  assert.ok(first.count > 5, `${first.count} events`);
  // Step mode meshes what the page meshes without it (a trace changes nothing), and every event but
  // a RELOCATED move inserts one vertex.
  const drawing = { ...presetDrawing('comb'), options: { ...DEFAULT_OPTIONS } };
  const traced = (await init()).triangulate(toPlc(drawing), toMeshOptions(drawing, { trace: true }));
  const plain = (await init()).triangulate(toPlc(drawing), toMeshOptions(drawing));
  assert.equal(traced.events.count, first.count);
  assert.equal(vertices, plain.stats.vertices);
  assert.equal(vertices, presetDrawing('comb').points.length / 2 + insertions(traced.events, first.count));

  const picture = await canvasFingerprint(page);
  await page.click('#step-forward');
  await page.click('#step-forward');
  assert.equal(parseStep(await stepInfo()).index, 2);
  await page.waitForFunction(() => document.body.dataset.stepShown === '2');
  await page.waitForTimeout(50);
  assert.notEqual(await canvasFingerprint(page), picture, 'the canvas shows the new step');
  await page.click('#step-back');
  assert.equal(parseStep(await stepInfo()).index, 1);

  await page.locator('#canvas').focus();
  await page.keyboard.press('End');
  assert.equal(parseStep(await stepInfo()).index, first.count);
  await page.keyboard.press('Home');
  assert.equal(parseStep(await stepInfo()).index, 0);
  await page.keyboard.press('.');
  assert.equal(parseStep(await stepInfo()).index, 1);

  await page.fill('#step-scrub', String(Math.floor(first.count / 2)));
  assert.equal(parseStep(await stepInfo()).index, Math.floor(first.count / 2));
});

/** How many of the first k events insert a vertex (all but RELOCATED moves). */
function insertions(events, k) {
  let n = 0;
  for (let e = 0; e < k; e++) n += events.kind[e] !== EventKind.RELOCATED;
  return n;
}

/** Waits until the page shows step k's mesh; returns its counts as the page states them. */
async function shownStep(k) {
  await page.waitForFunction((want) => document.body.dataset.stepShown === String(want), k, { timeout: 20_000 });
  const text = await page.locator('#step-mesh').textContent();
  const match = /^Mesh at step (\d+): ([\d,]+) vertices, ([\d,]+) triangles/.exec(text);
  assert.ok(match, text);
  return { k: Number(match[1]), vertices: Number(match[2].replace(/,/g, '')), triangles: Number(match[3].replace(/,/g, '')) };
}

test('step k shows the mesh that maxSteiner: k gives through the package', async () => {
  const mesher = await init();
  // two-sizes: its trace has RELOCATED moves, each a step that adds no vertex.
  for (const preset of ['comb', 'fan', 'two-sizes']) {
    await page.selectOption('#preset', preset);
    assert.equal(await settle(page), 'done');
    const drawing = { ...presetDrawing(preset), options: { ...DEFAULT_OPTIONS } };  // the page's defaults
    const plc = toPlc(drawing);
    const options = toMeshOptions(drawing, { trace: true });
    const { events } = mesher.triangulate(plc, options);
    const { count } = parseStep(await stepInfo());
    assert.equal(count, events.count);
    const moves = [];
    for (let e = 0; e < count; e++) if (events.kind[e] === EventKind.RELOCATED) moves.push(e + 1);
    if (preset === 'two-sizes') assert.ok(moves.length > 0, 'two-sizes no longer relocates: pick another preset');
    for (const k of [0, 1, 2, Math.floor(count / 3), ...moves.slice(0, 2), count - 1, count]) {
      await page.fill('#step-scrub', String(k));
      const shown = await shownStep(k);
      const expected = mesher.triangulate(plc, { ...options, trace: false, maxSteiner: k });
      assert.equal(shown.k, k);
      assert.equal(shown.vertices, expected.stats.vertices, `${preset} step ${k}: vertices`);
      assert.equal(shown.triangles, expected.stats.triangles, `${preset} step ${k}: triangles`);
      // Each insertion adds one vertex (a move none): step k has the input's points plus its insertions.
      assert.equal(expected.stats.vertices, plc.points.length / 2 + insertions(events, k), `${preset} step ${k}`);
    }
    await page.screenshot({ path: `${SCREENSHOTS}step-${preset}-middle.png` });
  }
});

test('a step is shown within a frame or two, and a revisited one at once', async () => {
  await page.selectOption('#preset', 'comb');
  assert.equal(await settle(page), 'done');
  const { count } = parseStep(await stepInfo());
  // Timed in the page: from the scrub's input event to the step's mesh being handed to the renderer.
  const times = await page.evaluate(async (n) => {
    const scrub = document.getElementById('step-scrub');
    const showOne = async (k) => {
      const started = performance.now();
      scrub.value = String(k);
      scrub.dispatchEvent(new Event('input'));
      while (document.body.dataset.stepShown !== String(k)) await new Promise((r) => setTimeout(r, 0));
      return performance.now() - started;
    };
    const fresh = [];
    const cached = [];
    for (let k = 1; k <= n; k++) fresh.push(await showOne(k));
    for (let k = n; k >= 1; k--) cached.push(await showOne(k));
    const median = (a) => [...a].sort((x, y) => x - y)[a.length >> 1];
    return { fresh: median(fresh), cached: median(cached), worst: Math.max(...fresh) };
  }, Math.min(40, count));
  console.log(`comb, ${count} steps: a new step in ${times.fresh.toFixed(1)} ms (median; worst ` +
    `${times.worst.toFixed(1)}), a cached one in ${times.cached.toFixed(2)} ms`);
  assert.ok(times.cached < times.fresh, 'cached steps come faster than new ones');
});

test('play advances on its own and pause stops it', async () => {
  // 30 events a second: the comb's events last long enough that playback is still running when the
  // pause is clicked, even on a loaded machine (at 120 it once ended first, and the click restarted it).
  await page.selectOption('#step-speed', '30');
  await page.click('#step-first');
  await page.click('#step-play');
  assert.equal(await page.getAttribute('#step-play', 'aria-label'), 'Pause');
  await page.waitForFunction(() => Number(/^Step ([\d,]+)/.exec(document.getElementById('step-info').textContent)[1].replace(/,/g, '')) > 5);
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
    for (let k = 1; k <= count; k++) {
      await page.fill('#step-scrub', String(k));
      const { what } = parseStep(await stepInfo());
      const kind = /^Split subsegment \(\d+, \d+\).* at its midpoint/.test(what) ? 'split'
        : /^Split subsegment \(\d+, \d+\).* on the concentric shell of radius [\d.e+-]+ around vertex \d+/.test(what) ? 'shell split'
          : /^Inserted the (circumcenter|off-center) of .*triangle \(\d+, \d+, \d+\)/.test(what) ? 'triangle'
          : /^Inserted the optimal point of .*triangle \(\d+, \d+, \d+\) .*its off-center would have made a skinny triangle/.test(what) ? 'optimal point'
          : /^Moved vertex \d+ from \([-\d.e+]+, [-\d.e+]+\) to \([-\d.e+]+, [-\d.e+]+\): no point fixed skinny triangle \(\d+, \d+, \d+\)/.test(what) ? 'relocated vertex'
            : /^The (circumcenter|off-center) \(.*\) of (skinny |too large )?triangle \(\d+, \d+, \d+\) \((smallest angle [\d.]+°( < bound [\d.]+°)?|area [\d.e+-]+ > max [\d.e+-]+)\) encroached subsegment \(\d+, \d+\): rejected/.test(what)
              ? `rejected ${/^The (\S+)/.exec(what)[1]}` : 'unknown';
      assert.notEqual(kind, 'unknown', what);
      if (!seen.has(kind)) {
        seen.add(kind);
        await page.screenshot({ path: `${SCREENSHOTS}step-${kind.replace(/ /g, '-')}.png` });
      }
    }
  }
  // The fan (5 degree input angles) splits on concentric shells, and with off-centers the point it
  // rejects is sometimes the off-center, not the circumcenter: each is named as what it is. The
  // default placement puts an optimal point where an off-center would make a skinny triangle.
  // two-sizes moves free vertices where no point fixes a skinny triangle.
  for (const kind of ['split', 'shell split', 'triangle', 'optimal point', 'relocated vertex', 'rejected off-center', 'rejected circumcenter']) {
    assert.ok(seen.has(kind), `${kind} not seen among ${[...seen].join(', ')}`);
  }
});

test('an intermediate step is a step, not a failed run: no "Complete: no", no budget warning', async () => {
  // lake: step mode turned on by the reader; figure-6-4: a preset that opens at step 0.
  for (const [preset, k] of [['lake', 5], ['figure-6-4', 0]]) {
    await page.selectOption('#preset', preset);
    assert.equal(await settle(page), 'done');
    if (!(await page.isChecked('#step-mode'))) {
      await page.check('#step-mode');
      assert.equal(await settle(page), 'done');
    }
    const { count } = parseStep(await stepInfo());
    assert.ok(count > k, `${preset}: ${count} steps`);
    await page.fill('#step-scrub', String(k));
    await shownStep(k);
    const complete = await page.locator('#stat-complete').textContent();
    assert.match(complete, new RegExp(`^step ${k} of ${count.toLocaleString('en-US')}`), `${preset} step ${k}`);
    assert.notEqual(await page.getAttribute('#stat-complete', 'class'), 'bad');
    assert.equal(await page.locator('#reasons li').count(), 0, `${preset} step ${k}: reasons listed`);
    const text = await page.locator('body').innerText();
    assert.doesNotMatch(text, /STEINER_BUDGET|budget of \d+ vertices was reached/i, `${preset} step ${k}`);
    assert.equal(await page.getAttribute('#status', 'data-kind'), 'info');
    // The final step is the mesh itself, complete as it is.
    await page.fill('#step-scrub', String(count));
    await shownStep(count);
    assert.equal(await page.locator('#stat-complete').textContent(), 'yes');
  }
  await page.uncheck('#step-mode');
  assert.equal(await settle(page), 'done');
});

test('leaving step mode hides the stepper', async () => {
  await page.uncheck('#step-mode');
  assert.equal(await settle(page), 'done');
  assert.equal(await page.locator('#stepper').isHidden(), true);
});

test('no console errors', () => {
  assert.deepEqual(errors, []);
});
