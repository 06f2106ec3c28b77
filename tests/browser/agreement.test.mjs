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
    assert.equal(await settle(page), 'done');
    const before = await readStats(page);
    // Set and read back in one task: no mesh can arrive in between and rewrite the status line.
    const shown = await page.evaluate(([selector, value]) => {
      const input = document.querySelector(selector);
      input.value = value;
      input.dispatchEvent(new Event('change'));
      const status = document.getElementById('status');
      return { text: status.textContent, kind: status.dataset.kind, invalid: input.getAttribute('aria-invalid') };
    }, [field, text]);
    const said = packageSays(name, Number(text));
    if (said === null) {
      assert.equal(shown.invalid, null, `${name} = ${text} is taken`);
      assert.equal(await settle(page), 'done');
    } else {
      assert.equal(shown.invalid, 'true', `${name} = ${text} is refused`);
      assert.ok(shown.text.includes(said), `the page says "${shown.text}", the package "${said}"`);
      assert.equal(shown.kind, 'error');
      assert.deepEqual(await readStats(page), before, 'the mesh is kept');
    }
    await page.fill(field, '');
    await page.locator(field).dispatchEvent('change');
    assert.equal(await settle(page), 'done');
  }
  assert.deepEqual(errors, []);
  await page.close();
});

test('points alone: the page says it meshed their convex hull, as the package does', async () => {
  const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/`);
  assert.equal(await settle(page), 'done');
  const node = '5 2 0 0\n0 0 0\n1 4 0\n2 4 3\n3 0 3\n4 1 1\n';
  await page.setInputFiles('#file-input', { name: 'points.node', mimeType: 'text/plain', buffer: Buffer.from(node) });
  assert.equal(await settle(page), 'done');
  assert.match(await page.locator('#status').textContent(), /^Meshed the convex hull of the 5 points \(the drawing has no segments/);
  // The package meshes the same hull (4 x 3) without segments.
  const mesh = mesher.triangulate({ points: [0, 0, 4, 0, 4, 3, 0, 3, 1, 1] });
  let area = 0;
  for (let t = 0; t < mesh.triangles.length; t += 3) {
    const [a, b, c] = [2 * mesh.triangles[t], 2 * mesh.triangles[t + 1], 2 * mesh.triangles[t + 2]];
    const p = mesh.points;
    area += ((p[b] - p[a]) * (p[c + 1] - p[a + 1]) - (p[c] - p[a]) * (p[b + 1] - p[a + 1])) / 2;
  }
  assert.ok(Math.abs(area - 12) < 1e-9, `the package meshes the hull: area ${area}`);
  assert.deepEqual(errors, []);
  await page.close();
});
