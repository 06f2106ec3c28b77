// The WebGL renderer: it draws (the canvas is not blank), each triangle is filled with the color
// the legend gives its smallest angle (on a small mesh, and zoomed into a mesh above 200 000
// triangles, where the 2D path drops the colors), hover names the triangle under the pointer
// (found from the spatial index), and the page falls back to the 2D canvas, saying so, without
// WebGL2. `?bench=1` exposes the page's view and renderer (web/main.js).
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { SCREENSHOTS, launch, moveOnCanvas, openPage, settle } from './harness.mjs';

let harness;

before(async () => {
  harness = await launch();
});

after(async () => {
  await harness?.close();
});

const SQUARE = '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n';
// An irregular pentagon: under an area bound alone the square is split into a grid of congruent
// right triangles (the largest first), all of one color; this one's triangles span several classes.
const PENTAGON = '5 2 0 0\n1 0 0\n2 1 0.1\n3 0.9 0.9\n4 0.3 1\n5 -0.1 0.5\n5 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 1\n0\n';

/** Loads a .poly (the square unless given) with the options through the host protocol; waits for its picture. */
async function loadSquare(page, options, poly = SQUARE) {
  const before = await page.evaluate(() => Number(document.body.dataset.meshCount ?? 0));
  await page.evaluate(([text, o]) => window.postMessage({ type: 'ruppert:load', id: 'render-test', poly: text, options: o }, '*'), [poly, options]);
  await page.waitForFunction((n) => Number(document.body.dataset.meshCount) > n, before, { timeout: 60_000 });
  assert.equal(await settle(page, 60_000), 'done');
}

/**
 * Triangles whose incircle is at least `minRadius` CSS pixels, with the screen point of their
 * incenter, their smallest angle, and the color of the WebGL canvas there (after the frame the
 * page draws next: a large mesh's triangles reach the GPU a little after its first picture).
 */
function sampleTriangles(page, { minRadius = 5, limit = 40 } = {}) {
  return page.evaluate(async ({ minRadius, limit }) => {
    const { view, renderer, draw } = window.ruppertBench;
    for (let i = 0; i < 3; i++) await new Promise((resolve) => setTimeout(resolve, 50));
    draw();
    const mesh = renderer.mesh;
    const gl = document.getElementById('gl-canvas');
    const copy = document.createElement('canvas');
    copy.width = gl.width; copy.height = gl.height;
    const ctx = copy.getContext('2d');
    ctx.drawImage(gl, 0, 0);
    const pixels = ctx.getImageData(0, 0, copy.width, copy.height).data;
    const dpr = copy.width / view.width;
    const out = [];
    const p = mesh.points; const tri = mesh.triangles;
    const order = [...Array(tri.length / 3).keys()].sort((a, b) => ((a * 2654435761) % 1000) - ((b * 2654435761) % 1000));
    for (const t of order) {
      const q = [0, 1, 2].map((c) => view.toScreen(p[2 * tri[3 * t + c]], p[2 * tri[3 * t + c] + 1]));
      const len = (a, b) => Math.hypot(a.x - b.x, a.y - b.y);
      const a = len(q[1], q[2]); const b = len(q[2], q[0]); const c = len(q[0], q[1]);
      const area = Math.abs((q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[1].y - q[0].y) * (q[2].x - q[0].x)) / 2;
      const r = (2 * area) / (a + b + c);
      const x = (a * q[0].x + b * q[1].x + c * q[2].x) / (a + b + c);
      const y = (a * q[0].y + b * q[1].y + c * q[2].y) / (a + b + c);
      if (r < minRadius || x < 2 || y < 2 || x > view.width - 2 || y > view.height - 2) continue;
      const angles = [[a, b, c], [b, c, a], [c, a, b]].map(([o, u, v]) => Math.acos((u * u + v * v - o * o) / (2 * u * v)) * 180 / Math.PI);
      const i = 4 * (Math.floor(y * dpr) * copy.width + Math.floor(x * dpr));
      out.push({ t, x, y, minAngle: Math.min(...angles), rgb: [pixels[i], pixels[i + 1], pixels[i + 2]] });
      if (out.length >= limit) break;
    }
    return out;
  }, { minRadius, limit });
}

/** The legend as [{ lower, upper, rgb }] from the page's swatches and labels ('20°–25°'). */
function readLegend(page) {
  return page.evaluate(() => [...document.querySelectorAll('#legend .legend-item')].map((item) => {
    const [lower, upper] = item.textContent.split('–').map((s) => Number.parseFloat(s));
    const rgb = getComputedStyle(item.querySelector('.swatch')).backgroundColor.match(/\d+/g).slice(0, 3).map(Number);
    return { lower, upper, rgb };
  }));
}

function checkColors(samples, legend, what) {
  assert.ok(samples.length >= 5, `${what}: only ${samples.length} triangles large enough to sample`);
  const classes = new Set();
  for (const s of samples) {
    // The legend's last class ends at 60° (rounded); a triangle's smallest angle is at most 60°.
    const row = legend.find((l, i) => s.minAngle >= l.lower && (s.minAngle < l.upper || i === legend.length - 1));
    assert.ok(row, `${what}: no legend row for ${s.minAngle.toFixed(2)}°`);
    const near = Math.abs(s.minAngle - row.lower) < 0.01 || Math.abs(s.minAngle - row.upper) < 0.01;
    if (near) continue;  // on a class bound: the page's rounding may take either side
    const off = Math.max(...s.rgb.map((v, k) => Math.abs(v - row.rgb[k])));
    assert.ok(off <= 3, `${what}: triangle ${s.t} (smallest angle ${s.minAngle.toFixed(2)}°) is rgb(${s.rgb}) on the canvas, ` +
      `the legend says rgb(${row.rgb}) for ${row.lower}°–${row.upper}°`);
    classes.add(row.lower);
  }
  return classes;
}

test('the WebGL renderer draws the triangles in the colors of the legend', async () => {
  const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/?bench=1`);
  assert.equal(await settle(page), 'done');
  assert.equal(await page.evaluate(() => document.body.dataset.renderer), 'webgl', 'headless Chromium gives WebGL2 (SwiftShader)');
  assert.equal(await page.locator('#renderer-note').isHidden(), true);
  await loadSquare(page, { minAngle: 30, maxArea: 0.004 }, PENTAGON);

  const blank = await page.evaluate(() => {
    const gl = document.getElementById('gl-canvas');
    const copy = document.createElement('canvas');
    copy.width = gl.width; copy.height = gl.height;
    const ctx = copy.getContext('2d');
    ctx.drawImage(gl, 0, 0);
    const data = ctx.getImageData(0, 0, copy.width, copy.height).data;
    let colored = 0;
    for (let i = 0; i < data.length; i += 4) if (data[i] < 240 || data[i + 1] < 240 || data[i + 2] < 240) colored++;
    return colored / (data.length / 4);
  });
  assert.ok(blank > 0.2, `only ${(100 * blank).toFixed(1)}% of the WebGL canvas is not white`);

  const legend = await readLegend(page);
  assert.equal(legend.length, 8);
  const classes = checkColors(await sampleTriangles(page), legend, 'small mesh');
  assert.ok(classes.size >= 2, `the samples show ${classes.size} color classes`);

  // Region coloring: one attribute, one swatch, every triangle in it.
  await page.selectOption('#color-mode', 'region');
  const regions = await readLegend(page);
  assert.equal(regions.length, 1);
  for (const s of await sampleTriangles(page)) {
    const off = Math.max(...s.rgb.map((v, k) => Math.abs(v - regions[0].rgb[k])));
    assert.ok(off <= 3, `region coloring: triangle ${s.t} is rgb(${s.rgb}), the legend says rgb(${regions[0].rgb})`);
  }
  await page.selectOption('#color-mode', 'angle');
  assert.deepEqual(errors, []);
  await page.close();
});

test('hover names the triangle under the pointer', async () => {
  const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/?bench=1`);
  assert.equal(await settle(page), 'done');
  await loadSquare(page, { minAngle: 30, maxArea: 0.002 });
  await page.click('[data-tool=select]');
  const samples = await sampleTriangles(page, { minRadius: 4, limit: 12 });
  assert.ok(samples.length >= 8, `${samples.length} triangles to hover`);
  for (const s of samples) {
    await moveOnCanvas(page, s.x, s.y);
    await page.waitForFunction((t) => document.getElementById('hover-info').textContent.startsWith(`Triangle ${t}:`), s.t, { timeout: 5000 })
      .catch(async () => assert.fail(`hover at triangle ${s.t}'s incenter says: ${await page.locator('#hover-info').textContent()}`));
  }
  assert.deepEqual(errors, []);
  await page.close();
});

test('a mesh above 200 000 triangles keeps its colors', async () => {
  const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/?bench=1`);
  assert.equal(await settle(page), 'done');
  await loadSquare(page, { minAngle: 30, maxArea: 6e-6 });
  const triangles = await page.evaluate(() => window.ruppertBench.renderer.mesh.triangles.length / 3);
  assert.ok(triangles > 200_000, `${triangles} triangles`);
  // Zoomed in, the triangles themselves are drawn (the overview picture serves the zoomed-out view).
  await page.evaluate(() => {
    const { view } = window.ruppertBench;
    view.zoomAt(view.width / 2, view.height / 2, 40);
  });
  const legend = await readLegend(page);
  checkColors(await sampleTriangles(page, { minRadius: 6 }), legend, `${triangles} triangles, zoomed in`);
  const drawn = await page.evaluate(() => window.ruppertBench.renderer.gl.drawnTriangles);
  assert.ok(drawn > 0 && drawn < triangles / 4, `${drawn} of ${triangles} triangles drawn for the zoomed-in view`);
  assert.deepEqual(errors, []);
  await page.close();
});

test('without WebGL2 the page draws with the 2D canvas and says so', async () => {
  const page = await harness.context.newPage();
  const errors = [];
  page.on('pageerror', (error) => errors.push(error.message));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  await page.addInitScript(() => {
    const original = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function getContext(kind, ...rest) {
      return kind === 'webgl2' ? null : original.call(this, kind, ...rest);
    };
  });
  await page.goto(`${harness.baseUrl}/web/`);
  assert.equal(await settle(page), 'done');
  assert.equal(await page.evaluate(() => document.body.dataset.renderer), '2d');
  assert.equal(await page.locator('#renderer-note').isVisible(), true);
  assert.equal(await page.locator('#gl-canvas').isHidden(), true);
  const colored = await page.evaluate(() => {
    const c = document.getElementById('canvas');
    const data = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < data.length; i += 4) if (data[i] < 240 || data[i + 1] < 240 || data[i + 2] < 240) n++;
    return n;
  });
  assert.ok(colored > 1000, `${colored} pixels drawn on the 2D canvas`);
  assert.deepEqual(errors, []);
  await page.close();
});

test('vertex numbers are drawn on demand for meshes small enough to read', async () => {
  const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/?bench=1`);
  assert.equal(await settle(page), 'done');
  // Dark text pixels of the 2D canvas (the overlays) near the screen point of vertex v.
  const darkNear = (v) => page.evaluate(async (vertex) => {
    await new Promise(requestAnimationFrame);
    const { view, renderer } = window.ruppertBench;
    const p = renderer.mesh.points;
    const q = view.toScreen(p[2 * vertex], p[2 * vertex + 1]);
    const c = document.getElementById('canvas');
    const dpr = c.width / view.width;
    const data = c.getContext('2d').getImageData(Math.round((q.x + 3) * dpr), Math.round((q.y - 14) * dpr), Math.round(14 * dpr), Math.round(12 * dpr)).data;
    let n = 0;
    for (let i = 0; i < data.length; i += 4) if (data[i + 3] > 200 && data[i] < 60 && data[i + 1] < 60 && data[i + 2] < 80) n++;
    return n;
  }, v);
  const vertices = await page.evaluate(() => window.ruppertBench.renderer.mesh.points.length / 2);
  assert.ok(vertices > 20 && vertices <= 1000, `${vertices} vertices`);
  const v = vertices - 1;  // a vertex refinement inserted: no input point (drawn dark) there
  const before = await darkNear(v);
  await page.check('#vertex-numbers');
  const after = await darkNear(v);
  assert.ok(after > before + 5, `dark pixels beside vertex ${v}: ${before} without numbers, ${after} with`);
  assert.equal(await page.locator('#vertex-numbers-note').isHidden(), true);
  await page.screenshot({ path: `${SCREENSHOTS}vertex-numbers.png` });
  // Too many vertices to read: the page says so and draws none.
  await loadSquare(page, { minAngle: 30, maxArea: 0.0005 });
  assert.equal(await page.locator('#vertex-numbers-note').isVisible(), true);
  assert.match(await page.locator('#vertex-numbers-note').textContent(), /up to 1,000 vertices/);
  assert.deepEqual(errors, []);
  await page.close();
});

test('a lost WebGL context sends the page back to the 2D canvas', async () => {
  const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/?bench=1`);
  assert.equal(await settle(page), 'done');
  assert.equal(await page.evaluate(() => document.body.dataset.renderer), 'webgl');
  await page.evaluate(() => window.ruppertBench.renderer.gl.gl.getExtension('WEBGL_lose_context').loseContext());
  await page.waitForFunction(() => document.body.dataset.renderer === '2d');
  assert.equal(await page.locator('#renderer-note').isVisible(), true);
  assert.equal(await page.locator('#gl-canvas').isHidden(), true);
  await page.waitForTimeout(100);
  const colored = await page.evaluate(() => {
    const c = document.getElementById('canvas');
    const data = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < data.length; i += 4) if (data[i + 3] > 200 && (data[i] < 240 || data[i + 1] < 240 || data[i + 2] < 240)) n++;
    return n;
  });
  assert.ok(colored > 10_000, `${colored} pixels of mesh drawn in 2D`);
  assert.deepEqual(errors.filter((e) => !/WebGL/.test(e)), []);
  await page.close();
});

test('a step still on its way dims the mesh as the 2D path does, edges included', async () => {
  // The same frame drawn dimmed by both renderers: the WebGL picture must not be washed out.
  const picture = async (renderer) => {
    const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/?bench=1&renderer=${renderer}`);
    assert.equal(await settle(page), 'done');
    const mean = await page.evaluate(async () => {
      const { renderer: r, view } = window.ruppertBench;
      await new Promise(requestAnimationFrame);
      // A step whose mesh has not arrived: drawn at 0.35 opacity (Renderer.showsStep is false).
      r.draw({
        view, drawing: { points: [], segments: [], holes: [], regions: [] }, colorMode: 'angle', snap: false,
        selection: null, hoverItem: null, hoverTriangle: -1, pendingChain: null, keyCursor: null, notices: [],
        step: { final: r.mesh, events: { count: 1 }, index: 0, shown: null },
      });
      const out = document.createElement('canvas');
      const top = document.getElementById('canvas');
      out.width = top.width; out.height = top.height;
      const ctx = out.getContext('2d');
      ctx.fillStyle = '#fff'; ctx.fillRect(0, 0, out.width, out.height);
      if (r.gl) ctx.drawImage(document.getElementById('gl-canvas'), 0, 0);
      ctx.drawImage(top, 0, 0);
      const data = ctx.getImageData(0, 0, out.width, out.height).data;
      let sum = 0;
      for (let i = 0; i < data.length; i += 4) sum += data[i] + data[i + 1] + data[i + 2];
      return sum / (data.length / 4) / 3;
    });
    assert.deepEqual(errors, []);
    await page.close();
    return mean;
  };
  const gl = await picture('webgl');
  const canvas2d = await picture('2d');
  assert.ok(Math.abs(gl - canvas2d) < 4, `mean brightness of the dimmed picture: WebGL ${gl.toFixed(1)}, 2D ${canvas2d.toFixed(1)}`);
});
