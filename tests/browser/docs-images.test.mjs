// The README's pictures cannot drift from the build: the figures `npm run docs:images`
// (docs/make-images.mjs) recorded in docs/images/figures.json, and those the README's captions
// state, are measured again here from the current CLI and page (counts, not pixels).
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { createServer } from 'node:http';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { after, before, test } from 'node:test';
import { LAKE_ARGS, LAKE_INPUT, readmeHostPage, runCli } from '../../docs/make-images.mjs';
import { findPreset } from '../../web/panels/presets.js';
import { launch, openPage, settle } from './harness.mjs';

const root = new URL('../../', import.meta.url);
const readme = readFileSync(new URL('README.md', root), 'utf8');
const figures = JSON.parse(readFileSync(new URL('docs/images/figures.json', root), 'utf8'));

/** The alt text of the README's <img> of that file. */
function altOf(file) {
  const match = new RegExp(`<img src="docs/images/${file.replace('.', '\\.')}"[^>]*alt="([^"]*)"`).exec(readme);
  assert.ok(match, `README.md shows docs/images/${file}`);
  return match[1].replace(/\s+/g, ' ');
}

let harness;
before(async () => {
  harness = await launch();
});
after(async () => {
  await harness?.close();
});

test('lake.svg: the CLI makes today what the picture and its caption say', () => {
  const scratch = mkdtempSync(join(tmpdir(), 'ruppert-docs-'));
  try {
    const now = runCli([...LAKE_ARGS, '-o', join(scratch, 'lake'), LAKE_INPUT]);
    assert.deepEqual({ vertices: figures.lake.vertices, triangles: figures.lake.triangles }, now,
      'docs/images/figures.json is stale: run npm run docs:images');
    const title = /<title>(\d+) vertices, (\d+) triangles<\/title>/.exec(readFileSync(new URL('docs/images/lake.svg', root), 'utf8'));
    assert.deepEqual([Number(title[1]), Number(title[2])], [now.vertices, now.triangles], 'lake.svg is stale');
    const alt = altOf('lake.svg');
    assert.match(alt, new RegExp(`\\b${now.triangles} triangles`), alt);
    assert.ok(alt.includes(`ruppert ${LAKE_ARGS.join(' ')}`), `the caption names the command: ${alt}`);
  } finally {
    rmSync(scratch, { recursive: true, force: true });
  }
});

test('page.png: the page opens today on the drawing and counts its caption states', async () => {
  const { page, errors } = await openPage(harness.context, `${harness.baseUrl}/web/`, { width: 1280, height: 800 });
  assert.equal(await settle(page), 'done');
  const preset = await page.inputValue('#preset');
  const triangles = Number((await page.locator('#stat-triangles').textContent()).replace(/,/g, ''));
  assert.equal(preset, figures.page.preset, 'docs/images/figures.json is stale: run npm run docs:images');
  assert.equal(triangles, figures.page.triangles, 'docs/images/figures.json is stale: run npm run docs:images');
  const alt = altOf('page.png');
  assert.ok(alt.includes(`the ${preset} preset`), alt);
  assert.ok(findPreset(preset), preset);
  assert.match(alt, new RegExp(`\\b${triangles} triangles`), alt);
  assert.deepEqual(errors, []);
  await page.close();
});

test('embed.png: the README\'s host snippet, as written, still reaches its step', async () => {
  const host = createServer((request, response) => {
    response.writeHead(200, { 'content-type': 'text/html; charset=utf-8' });
    response.end(readmeHostPage(`${harness.baseUrl}/web/`));
  });
  await new Promise((resolve) => host.listen(0, '127.0.0.1', resolve));
  try {
    const { page, errors } = await openPage(harness.context, `http://127.0.0.1:${host.address().port}/`);
    const frame = await (await page.waitForSelector('#mesher')).contentFrame();
    await frame.waitForFunction(() => document.body.dataset.stepShown === '5', null, { timeout: 30_000 });
    assert.equal(await frame.locator('#step-info').textContent(), figures.embed.stepInfo,
      'docs/images/figures.json is stale: run npm run docs:images');
    assert.deepEqual(errors, []);
    await page.close();
  } finally {
    host.closeAllConnections?.();
    await new Promise((resolve) => host.close(resolve));
  }
});
