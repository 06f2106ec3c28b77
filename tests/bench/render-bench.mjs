#!/usr/bin/env node
// Rendering benchmark of the web page (run by hand, not in CI): a square meshed to about
// 1.5 M triangles in the page's worker, drawn by the WebGL renderer and by the 2D canvas
// (`?renderer=2d`, the page before WebGL) in the same headless Chromium, in alternating (paired)
// rounds because the machine is shared. Measured per round:
//   first picture: from the mesh's arrival in the page (onResult) to its first finished frame
//   triangles on the GPU (WebGL, meshes above 200k triangles): from the arrival until the task
//     after the first picture has sent them (until then the view comes from the quick overview)
//   frame: one pan or zoom step redrawn and finished (GPU readback / 2D pixel read), median of N
//   hover (WebGL rounds): the triangle under 200 random points of the mesh's box, found from the
//     spatial index (mesh-index.js; its first call builds its seed grid, timed apart) and by the
//     page's former lookup (mesh-geometry.js findTriangle: a walk of up to 4096 steps from
//     triangle 0, then a scan), both without a hint (a jump of the pointer)
//
//   node tests/bench/render-bench.mjs [--rounds 3] [--frames 20] [--max-area 6.5e-7] [--out FILE]
import { writeFileSync } from 'node:fs';
import { launch, openPage, settle } from '../browser/harness.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(`--${name}`);
  return i >= 0 ? args[i + 1] : fallback;
};
const ROUNDS = Number(option('rounds', 3));
const FRAMES = Number(option('frames', 20));
const MAX_AREA = Number(option('max-area', 6.5e-7));
const OUT = option('out', null);

const SQUARE = '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n';
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

async function round(harness, renderer) {
  const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/?bench=1&renderer=${renderer}`);
  await settle(page);
  const shown = await page.evaluate(() => document.body.dataset.renderer);
  if (shown !== renderer) throw new Error(`asked for ${renderer}, the page draws with ${shown}`);
  const before = await page.evaluate(() => Number(document.body.dataset.meshCount));
  await page.evaluate(({ poly, maxArea }) => window.postMessage({ type: 'ruppert:load', id: 'bench', poly, options: { minAngle: 30, maxArea } }, '*'),
    { poly: SQUARE, maxArea: MAX_AREA });
  await page.waitForFunction((n) => Number(document.body.dataset.meshCount) > n && document.body.dataset.meshState === 'done', before, { timeout: 120_000 });
  await page.waitForFunction(() => document.body.dataset.firstPictureMs !== undefined, null, { timeout: 60_000 });
  // Frames around the whole mesh in view, then zoomed in 16x (where WebGL draws the triangles
  // themselves, not the overview); a second's pause first lets the page finish its work on the mesh.
  const result = await page.evaluate(async (frames) => {
    await new Promise((resolve) => setTimeout(resolve, 1000));
    const { view, renderer, draw } = window.ruppertBench;
    const triangles = renderer.mesh.triangles.length / 3;
    const run = async () => {
      const times = [];
      for (let f = 0; f < frames; f++) {
        if (f % 2 === 0) view.panBy(7, -5); else view.zoomAt(view.width / 2, view.height / 2, f % 4 === 1 ? 1.15 : 1 / 1.15);
        const t0 = performance.now();
        draw();
        renderer.finish();
        times.push(performance.now() - t0);
        await new Promise(requestAnimationFrame);
      }
      return times;
    };
    const times = await run();
    view.zoomAt(view.width / 2, view.height / 2, 16);
    const zoomed = await run();
    let hover = null;
    if (renderer.gl) {
      const { locateTriangle } = await import('./geometry/mesh-index.js');
      const { findTriangle } = await import('./geometry/mesh-geometry.js');
      const p = renderer.mesh.points;
      let seed = 1;
      const random = () => { seed = (seed * 16807) % 2147483647; return seed / 2147483647; };
      const points = Array.from({ length: 200 }, () => [random(), random()]);
      const timed = (find) => points.map(([x, y]) => { const t0 = performance.now(); find(x, y); return performance.now() - t0; });
      const t0 = performance.now();
      locateTriangle(renderer.mesh, 0.5, 0.5, -1);
      const gridBuild = performance.now() - t0;  // the first lookup builds the seed grid
      const grid = timed((x, y) => locateTriangle(renderer.mesh, x, y, -1));
      const scan = timed((x, y) => findTriangle(renderer.mesh, x, y, -1)).slice(0, 40);
      const mid = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
      hover = { gridBuild, grid: mid(grid), scan: mid(scan), points: p.length / 2 };
    }
    const ready = renderer.gl?.readyAt ? renderer.gl.readyAt - Number(document.body.dataset.meshArrivedAt) : null;
    return { triangles, times, zoomed, ready, hover, firstPicture: Number(document.body.dataset.firstPictureMs) };
  }, FRAMES);
  await page.close();
  if (errors.length) throw new Error(`console errors: ${errors.join('; ')}`);
  return {
    renderer, triangles: result.triangles, firstPictureMs: result.firstPicture, onGpuMs: result.ready, hover: result.hover,
    frameMs: median(result.times), zoomedFrameMs: median(result.zoomed),
  };
}

const harness = await launch();
const rows = [];
try {
  for (let r = 0; r < ROUNDS; r++) {
    for (const renderer of r % 2 === 0 ? ['webgl', '2d'] : ['2d', 'webgl']) {
      const row = await round(harness, renderer);
      rows.push({ round: r, ...row });
      const gpu = row.onGpuMs === null ? '' : ` (triangles on the GPU after ${row.onGpuMs.toFixed(0)} ms)`;
      if (row.hover) {
        console.log(`round ${r} hover: ${row.hover.grid.toFixed(3)} ms from the index (its grid built in ${row.hover.gridBuild.toFixed(0)} ms on the first hover), ` +
          `${row.hover.scan.toFixed(1)} ms by the former walk-then-scan (medians)`);
      }
      console.log(`round ${r} ${renderer.padEnd(5)} ${row.triangles} triangles: first picture ${row.firstPictureMs.toFixed(0)} ms${gpu}, ` +
        `median frame ${row.frameMs.toFixed(1)} ms (whole mesh in view), ${row.zoomedFrameMs.toFixed(1)} ms (zoomed in 16x)`);
    }
  }
} finally {
  await harness.close();
}
const summary = {};
for (const renderer of ['webgl', '2d']) {
  const mine = rows.filter((r) => r.renderer === renderer);
  summary[renderer] = {
    firstPictureMs: median(mine.map((r) => r.firstPictureMs)),
    frameMs: median(mine.map((r) => r.frameMs)),
    zoomedFrameMs: median(mine.map((r) => r.zoomedFrameMs)),
    onGpuMs: renderer === 'webgl' ? median(mine.map((r) => r.onGpuMs)) : null,
    hoverMs: renderer === 'webgl' ? median(mine.map((r) => r.hover.grid)) : null,
    hoverScanMs: renderer === 'webgl' ? median(mine.map((r) => r.hover.scan)) : null,
    gridBuildMs: renderer === 'webgl' ? median(mine.map((r) => r.hover.gridBuild)) : null,
  };
}
const speedup = summary['2d'].frameMs / summary.webgl.frameMs;
const zoomedSpeedup = summary['2d'].zoomedFrameMs / summary.webgl.zoomedFrameMs;
const line = (r) => `first picture ${summary[r].firstPictureMs.toFixed(0)} ms, frame ${summary[r].frameMs.toFixed(1)} ms, zoomed ${summary[r].zoomedFrameMs.toFixed(1)} ms`;
console.log(`median of ${ROUNDS} rounds: webgl ${line('webgl')}, triangles on the GPU after ${summary.webgl.onGpuMs?.toFixed(0)} ms; 2d ${line('2d')}; frames ${speedup.toFixed(1)}x faster, zoomed ${zoomedSpeedup.toFixed(1)}x`);
if (OUT) {
  const command = `node tests/bench/render-bench.mjs ${args.join(' ')}`.trim();
  writeFileSync(OUT, `${JSON.stringify({ command, date: new Date().toISOString(), rows, summary, speedup, zoomedSpeedup }, null, 2)}\n`);
}
