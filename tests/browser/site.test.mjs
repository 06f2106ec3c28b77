// `npm run build:site` (web/build-site.mjs): the static site, served by Python's http.server (not
// this repository's server) from a sub-folder, as a course's file area would. The page meshes its
// default drawing and asks for nothing outside that folder.
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, posix } from 'node:path';
import { after, before, test } from 'node:test';
import { buildSite } from '../../web/build-site.mjs';
import { SCREENSHOTS, launch, openPage, readStats, settle } from './harness.mjs';

const FOLDER = '/course/mesher/';
let harness;
let served;      // the temporary folder python serves
let python;      // its process
let siteUrl;     // http://127.0.0.1:<port>/course/mesher/
let written;

/** Starts python3 -m http.server on a free port in `folder`; resolves to its port. */
function startPython(folder) {
  return new Promise((resolve, reject) => {
    python = spawn('python3', ['-u', '-m', 'http.server', '0', '--bind', '127.0.0.1', '--directory', folder],
      { stdio: ['ignore', 'pipe', 'pipe'] });
    let out = '';
    const timer = setTimeout(() => reject(new Error(`python3 -m http.server did not start: ${out}`)), 10_000);
    python.stdout.on('data', (chunk) => {
      out += chunk;
      const port = /port (\d+)/.exec(out);
      if (port) {
        clearTimeout(timer);
        resolve(Number(port[1]));
      }
    });
    python.stderr.on('data', () => {});  // its request log
    python.on('error', reject);
  });
}

before(async () => {
  served = mkdtempSync(join(tmpdir(), 'ruppert-site-'));
  written = buildSite(join(served, FOLDER));
  const port = await startPython(served);
  siteUrl = `http://127.0.0.1:${port}${FOLDER}`;
  harness = await launch();
});

after(async () => {
  await harness?.close();
  python?.kill();
  if (served) rmSync(served, { recursive: true, force: true });
});

test('the site holds the page and the package\'s browser modules, and no Node-only part', () => {
  for (const file of ['index.html', 'main.js', 'style.css', 'embed-example.html', 'wasm/index.js', 'wasm/worker.js',
    'wasm/dist/ruppert.wasm', 'wasm/dist/ruppert-formats.wasm', 'wasm/dist/ruppert.js']) {
    assert.ok(written.includes(file), `${file} is in the site`);
  }
  for (const file of ['serve.mjs', 'build-site.mjs', 'wasm/cli.js', 'wasm/node.js', 'wasm/dist/ruppert-cli.wasm']) {
    assert.ok(!written.includes(file), `${file} is not in the site`);
  }
  const page = readFileSync(join(served, FOLDER, 'index.html'), 'utf8');
  const version = JSON.parse(readFileSync(new URL('../../package.json', import.meta.url), 'utf8')).version;
  assert.match(page, new RegExp(`<meta name="ruppert-version" content="${version.replace(/\./g, '\\.')}">`));
  assert.doesNotMatch(page, /shared-data/);
  // The page's modules sit in folders (web/panels/, web/rendering/, ...), so '../' is fine as long
  // as it stays inside the site.
  for (const file of written.filter((f) => /\.(js|html)$/.test(f))) {
    const text = readFileSync(join(served, FOLDER, file), 'utf8');
    assert.doesNotMatch(text, /(?:src|href)="\//, `${file}: no URL from the server's root`);
    for (const [, spec] of text.matchAll(/\bfrom\s*'(\.{1,2}\/[^']+)'/g)) {
      assert.ok(!posix.normalize(posix.join(posix.dirname(file), spec)).startsWith('..'), `${file}: ${spec} stays inside the site`);
    }
  }
});

test('the dev page\'s version tag is the package\'s version', () => {
  const page = readFileSync(new URL('../../web/index.html', import.meta.url), 'utf8');
  const version = JSON.parse(readFileSync(new URL('../../package.json', import.meta.url), 'utf8')).version;
  assert.ok(page.includes(`<meta name="ruppert-version" content="${version}">`), 'web/index.html names the package version');
});

test('served by python3 -m http.server from a folder, the page meshes and asks for nothing outside it', async () => {
  assert.ok(existsSync(join(served, FOLDER, 'index.html')));
  const requests = [];
  const failed = [];
  const page = await harness.context.newPage();
  page.on('request', (request) => requests.push(request.url()));
  page.on('requestfailed', (request) => failed.push(request.url()));
  page.on('response', (response) => { if (response.status() >= 400) failed.push(`${response.status()} ${response.url()}`); });
  // The worker's own requests (its module and the .wasm it fetches) are the context's, not the page's.
  harness.context.on('request', (request) => requests.push(request.url()));
  const errors = [];
  page.on('console', (message) => { if (message.type() === 'error') errors.push(message.text()); });
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto(siteUrl);
  assert.equal(await settle(page), 'done');
  const stats = await readStats(page);
  assert.ok(stats.triangles > 10, `the default drawing is meshed: ${JSON.stringify(stats)}`);
  assert.match(await page.locator('#status').textContent(), /^Meshed/);
  // A file read uses the formats module: open a .poly through the file input.
  await page.setInputFiles('#file-input', {
    name: 'square.poly', mimeType: 'text/plain',
    buffer: Buffer.from('4 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n'),
  });
  await page.waitForFunction(() => /square\.poly/.test(document.getElementById('status').textContent) ||
    document.body.dataset.meshState === 'done', null, { timeout: 20_000 });
  assert.equal(await settle(page), 'done');
  await page.screenshot({ path: `${SCREENSHOTS}site-python-server.png` });
  const wanted = requests.filter((url) => !url.startsWith('data:'));
  assert.ok(wanted.some((url) => url.endsWith('/wasm/dist/ruppert.wasm')), 'the mesher module came from the site');
  assert.ok(wanted.some((url) => url.endsWith('/wasm/dist/ruppert-formats.wasm')), 'the formats module came from the site');
  const outside = wanted.filter((url) => !url.startsWith(siteUrl));
  assert.deepEqual(outside, [], 'every request stays inside the site\'s folder');
  assert.deepEqual(failed, []);
  assert.deepEqual(errors, []);
  await page.close();
});

test('the embedding example of the site works from the same folder', async () => {
  const { page, errors } = await openPage(harness.context, `${siteUrl}embed-example.html`);
  await page.waitForFunction(() => document.querySelectorAll('#log li.meshed').length >= 1, null, { timeout: 20_000 });
  assert.deepEqual(errors, []);
  await page.close();
});

test('opened from disk (file://), the page says it must be served over http, with the command', async () => {
  const { page } = await openPage(harness.context, `file://${join(served, FOLDER)}index.html`);
  const note = page.locator('#served-note');
  await note.waitFor({ state: 'visible', timeout: 10_000 });
  const text = await note.textContent();
  assert.match(text, /must be served over http/);
  assert.match(text, new RegExp(`python3 -m http\\.server 8000 --directory "${join(served, FOLDER).replace(/[.*+?^${}()|[\]\\]/g, '\\$&')}"`));
  const box = await note.boundingBox();
  assert.ok(box.y < 50 && box.height > 20, `the note is at the top: ${JSON.stringify(box)}`);
  await page.screenshot({ path: `${SCREENSHOTS}site-from-disk.png` });
  await page.close();
  // Served over http, there is no such note.
  const { page: served2 } = await openPage(harness.context, `${siteUrl}index.html`);
  assert.equal(await settle(served2), 'done');
  assert.equal(await served2.locator('#served-note').count(), 0);
  await served2.close();
});
