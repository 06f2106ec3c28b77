// Shared setup of the browser tests: the page's own static server on a free port, and Debian's
// Chromium driven by playwright-core (which never downloads a browser) with a fresh profile.
import { mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import { createServer } from 'node:http';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { startServer } from '../../web/serve.mjs';

export const CHROMIUM = process.env.CHROMIUM_PATH ?? '/usr/bin/chromium';
// Where the tests save their screenshots (each figure preset's among them): RUPPERT_SCREENSHOTS, else
// tests/browser/screenshots/.
export const SCREENSHOTS = process.env.RUPPERT_SCREENSHOTS
  ? `${process.env.RUPPERT_SCREENSHOTS.replace(/\/+$/, '')}/`
  : fileURLToPath(new URL('./screenshots/', import.meta.url));

const ARGS = [
  '--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
  '--disable-component-update', '--disable-quic', '--no-first-run', '--disable-sync',
  // WebGL in software (SwiftShader through ANGLE): Debian's Chromium 156 gives it without a GPU
  // already; these keep it when a later Chromium stops falling back to it on its own.
  '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
];

/**
 * A course page of another origin (a second server, on another port) embedding the page served at
 * baseUrl: a frame of it in embed mode, every message from the frame kept in window.replies, and
 * window.send(message) posting to the frame. Returns { url, frameOrigin, close() }.
 */
export async function startHostPage(baseUrl) {
  const frameUrl = `${baseUrl}/web/index.html?embed=1`;
  const frameOrigin = new URL(frameUrl).origin;
  const html = `<!doctype html><meta charset="utf-8"><title>course page</title>
    <iframe id="f" src="${frameUrl}" width="640" height="480"></iframe>
    <script>
      window.replies = [];
      const f = document.getElementById('f');
      window.send = (message) => f.contentWindow.postMessage(message, ${JSON.stringify(frameOrigin)});
      addEventListener('message', (e) => { if (e.source === f.contentWindow) window.replies.push(e.data); });
    </script>`;
  const server = createServer((request, response) => {
    response.writeHead(200, { 'content-type': 'text/html; charset=utf-8' });
    response.end(html);
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  return {
    url: `http://127.0.0.1:${server.address().port}/`,
    frameOrigin,
    async close() {
      server.closeAllConnections?.();
      await new Promise((resolve) => server.close(resolve));
    },
  };
}

/** Starts the server and the browser. Returns { baseUrl, context, close() }. */
export async function launch() {
  const { server, url } = await startServer({ port: 0, quiet: true });
  const baseUrl = url.replace(/\/web\/$/, '');
  const profile = mkdtempSync(join(tmpdir(), 'ruppert-chromium-'));
  // launchPersistentContext is how a fresh --user-data-dir is given to Chromium.
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM,
    headless: true,
    args: ARGS,
    viewport: { width: 1280, height: 800 },
    acceptDownloads: true,
  });
  mkdirSync(SCREENSHOTS, { recursive: true });
  return {
    baseUrl,
    context,
    async close() {
      await context.close();
      server.closeAllConnections?.();
      await new Promise((resolve) => server.close(resolve));
      rmSync(profile, { recursive: true, force: true });
    },
  };
}

/**
 * Opens a page and collects console errors and uncaught exceptions in `errors`. The "Start here"
 * panel (web/panels/start-here.js) is dismissed beforehand, as a returning reader has it, so that it
 * covers no part of the canvas a test clicks; `startHere: true` leaves the page's storage alone.
 */
export async function openPage(context, url, { width = 1280, height = 800, startHere = false } = {}) {
  const page = await context.newPage();
  await page.setViewportSize({ width, height });
  if (!startHere) {
    await page.addInitScript(() => {
      try { localStorage.setItem('ruppert:start-here-dismissed', '1'); } catch { /* a sandboxed frame */ }
    });
  }
  const errors = [];
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(`console: ${message.text()}`);
  });
  page.on('pageerror', (error) => errors.push(`pageerror: ${error.message}`));
  await page.goto(url);
  return { page, errors };
}

/** Opens the toolbar's Export menu (its buttons are visible, and clickable, only when it is open). */
export async function openExportMenu(page) {
  if (!(await page.evaluate(() => document.getElementById('export-menu').open))) await page.click('#export-menu > summary');
}

const SETTLED = ['done', 'error', 'cancelled', 'empty'];

/**
 * Waits until the page has no meshing queued or running, and returns the final state
 * ('done', 'error', 'cancelled' or 'empty'). The page sets body[data-mesh-state] to 'queued'
 * synchronously on every change, so this cannot return a result older than the last action.
 */
export async function settle(page, timeout = 20_000) {
  await page.waitForFunction((states) => states.includes(document.body.dataset.meshState), SETTLED, { timeout });
  return page.evaluate(() => document.body.dataset.meshState);
}

/** The statistics panel as numbers. */
export async function readStats(page) {
  return page.evaluate(() => {
    const text = (id) => document.getElementById(id).textContent;
    const number = (id) => Number(text(id).replace(/[^0-9.\-e]/g, ''));
    return {
      vertices: number('stat-vertices'),
      triangles: number('stat-triangles'),
      minAngle: number('stat-min-angle'),
      maxAngle: number('stat-max-angle'),
      complete: text('stat-complete'),
    };
  });
}

/** Clicks at canvas pixel (x, y), relative to the canvas's top-left corner. */
export async function clickCanvas(page, x, y, options = {}) {
  const box = await page.locator('#canvas').boundingBox();
  await page.mouse.click(box.x + x, box.y + y, options);
}

export async function moveOnCanvas(page, x, y) {
  const box = await page.locator('#canvas').boundingBox();
  await page.mouse.move(box.x + x, box.y + y);
}

/** A cheap fingerprint of the canvas pixels, to see that the picture changed. */
export function canvasFingerprint(page) {
  return page.evaluate(() => {
    // The picture as seen: the WebGL mesh (when the page draws with it) under the 2D overlays.
    const top = document.getElementById('canvas');
    const gl = document.getElementById('gl-canvas');
    const both = document.createElement('canvas');
    both.width = top.width;
    both.height = top.height;
    const ctx = both.getContext('2d');
    if (gl && !gl.hidden) ctx.drawImage(gl, 0, 0);
    ctx.drawImage(top, 0, 0);
    const url = both.toDataURL('image/png');
    let hash = 0;
    for (let i = 0; i < url.length; i++) hash = (hash * 31 + url.charCodeAt(i)) | 0;
    return `${url.length}:${hash}`;
  });
}
