#!/usr/bin/env node
// `npm run docs:images`: the README's pictures, made from the real CLI and the real page, and the
// figures their captions state, in docs/images/figures.json (tests/browser/docs-images.test.mjs
// measures them again from the current build and compares: a caption cannot drift from what the
// build makes).
//
//   docs/images/lake.svg           the CLI (the package's, wasm/cli.js) on docs/examples/lake.poly
//   docs/images/page.png           the page as `npm start` opens it, 1280 x 800
//   docs/images/embed.png          the README's host snippet, as written, its frame 640 x 480
//   docs/images/embed-example.png  web/embed-example.html (site/embed-example.html)
//
// Needs wasm/dist (npm run build:wasm) and Debian's chromium (tests/browser/harness.mjs).
import { spawnSync } from 'node:child_process';
import { readFileSync, writeFileSync } from 'node:fs';
import { createServer } from 'node:http';
import { fileURLToPath } from 'node:url';
import { launch, openPage, settle } from '../tests/browser/harness.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));
const images = `${root}docs/images/`;

// The README's lake picture: these flags on this input (its caption names both).
export const LAKE_ARGS = ['--min-angle', '30', '--max-area', '0.5', '--format', 'svg'];
export const LAKE_INPUT = 'docs/examples/lake.poly';

/** Runs the package's CLI; returns { vertices, triangles } from its summary line. */
export function runCli(args) {
  const run = spawnSync(process.execPath, [`${root}wasm/cli.js`, ...args], { cwd: root, encoding: 'utf8' });
  if (run.status !== 0) throw new Error(`ruppert ${args.join(' ')}: ${run.stderr}`);
  const match = /^ruppert: (\d+) vertices, (\d+) triangles/m.exec(run.stdout);
  if (!match) throw new Error(`ruppert ${args.join(' ')} printed: ${run.stdout}`);
  return { vertices: Number(match[1]), triangles: Number(match[2]) };
}

/** The README's ```html block, with its host and folder pointed at `pageUrl` (ending in '/'). */
export function readmeHostPage(pageUrl) {
  const readme = readFileSync(`${root}README.md`, 'utf8');
  const block = /^```html\n([\s\S]*?)^```$/m.exec(readme);
  if (!block) throw new Error('README.md has no ```html block');
  const origin = new URL(pageUrl).origin;
  return `<!doctype html><meta charset="utf-8"><title>the README's host snippet</title>\n${block[1]
    .replaceAll('https://YOUR-HOST/site/', pageUrl).replaceAll('https://YOUR-HOST', origin)}`;
}

/** The page's counts as its Mesh panel states them. */
const panelCounts = (page) => page.evaluate(() => ({
  vertices: Number(document.getElementById('stat-vertices').textContent.replace(/,/g, '')),
  triangles: Number(document.getElementById('stat-triangles').textContent.replace(/,/g, '')),
}));

async function pageImages(figures) {
  const harness = await launch();
  const host = createServer((request, response) => {
    response.writeHead(200, { 'content-type': 'text/html; charset=utf-8' });
    response.end(readmeHostPage(`${harness.baseUrl}/web/`));
  });
  await new Promise((resolve) => host.listen(0, '127.0.0.1', resolve));
  try {
    const { page } = await openPage(harness.context, `${harness.baseUrl}/web/`, { width: 1280, height: 800 });
    if (await settle(page) !== 'done') throw new Error('the page did not mesh its default drawing');
    await page.screenshot({ path: `${images}page.png` });
    figures.page = { viewport: '1280x800', preset: await page.inputValue('#preset'), ...(await panelCounts(page)) };
    await page.close();

    // The README's snippet loads a square and asks for step 5.
    const { page: hostPage } = await openPage(harness.context, `http://127.0.0.1:${host.address().port}/`, { width: 700, height: 540 });
    const frame = await (await hostPage.waitForSelector('#mesher')).contentFrame();
    await frame.waitForFunction(() => document.body.dataset.stepShown === '5', null, { timeout: 30_000 });
    await hostPage.locator('#mesher').screenshot({ path: `${images}embed.png` });
    figures.embed = { frame: '640x480', step: 5, stepInfo: await frame.locator('#step-info').textContent() };
    await hostPage.close();

    const { page: example } = await openPage(harness.context, `${harness.baseUrl}/web/embed-example.html`, { width: 900, height: 900 });
    const exampleFrame = await (await example.waitForSelector('#mesher')).contentFrame();
    await exampleFrame.waitForFunction(() => document.body.dataset.meshState === 'done', null, { timeout: 30_000 });
    await example.screenshot({ path: `${images}embed-example.png`, fullPage: true });
    await example.close();
  } finally {
    host.closeAllConnections?.();
    await new Promise((resolve) => host.close(resolve));
    await harness.close();
  }
}

const isMain = process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1];
if (isMain) {
  const figures = { lake: { command: `ruppert ${LAKE_ARGS.join(' ')} ${LAKE_INPUT}`, ...runCli([...LAKE_ARGS, '-o', 'docs/images/lake', LAKE_INPUT]) } };
  await pageImages(figures);
  writeFileSync(`${images}figures.json`, `${JSON.stringify(figures, null, 2)}\n`);
  console.log(`docs:images: lake.svg (${figures.lake.triangles} triangles), page.png (${figures.page.preset}, ` +
    `${figures.page.triangles} triangles), embed.png, embed-example.png; figures in docs/images/figures.json`);
}
