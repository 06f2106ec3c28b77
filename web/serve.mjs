#!/usr/bin/env node
// A tiny static file server for the web page. It serves only what the page needs: the web/ folder
// and the files the npm package publishes (package.json's "files": /wasm/index.js,
// /wasm/dist/ruppert.wasm, ...), so the page imports the very module users install. Nothing else of
// the repository (no .git, no node_modules, no package.json, no dotfiles anywhere) is served.
//
//   node web/serve.mjs            # PORT from the environment, else 8080, else any free port
//
// Listens on 127.0.0.1 only. No dependencies: node:http + node:fs.
//
// When the corpus of real PLCs sits beside the repository (../shared/data, or RUPPERT_SHARED_DATA),
// its .poly files are served read-only under /shared-data/, listed by /shared-data/index.json
// ({ available, files }), so the page can offer them as presets. Without the folder the list is
// empty (a 200 answer, so the page logs no failed request).
import { createServer } from 'node:http';
import { createReadStream, existsSync, readFileSync } from 'node:fs';
import { readdir, stat } from 'node:fs/promises';
import { basename, extname, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = resolve(fileURLToPath(new URL('..', import.meta.url)));
const sharedData = resolve(process.env.RUPPERT_SHARED_DATA || resolve(root, '..', 'shared', 'data'));
const SHARED_PREFIX = '/shared-data/';

// The served part of the repository, as root-relative paths: folders end in '/'. package.json's
// "files" is the one list of what the package publishes, so the page can load nothing a user of the
// package would not have.
const PUBLISHED = JSON.parse(readFileSync(resolve(root, 'package.json'), 'utf8')).files ?? [];
const SERVED_PREFIXES = ['web/', ...PUBLISHED.filter((entry) => !entry.includes('*'))];

/** Whether a root-relative path (no leading '/') is one the page may load. */
function isServed(relative) {
  if (relative.split('/').some((part) => part.startsWith('.'))) return false;  // dotfiles, '..'
  return SERVED_PREFIXES.some((entry) =>
    entry.endsWith('/') ? relative.startsWith(entry) : relative === entry || relative.startsWith(`${entry}/`));
}

/** The corpus's top-level .poly files, sorted; [] when the folder is absent. */
async function sharedDataFiles() {
  if (!existsSync(sharedData)) return [];
  const entries = await readdir(sharedData, { withFileTypes: true });
  return entries.filter((e) => e.isFile() && e.name.endsWith('.poly')).map((e) => e.name).sort();
}

async function handleSharedData(pathname, request, response) {
  let name;
  try {
    name = decodeURIComponent(pathname.slice(SHARED_PREFIX.length));
  } catch {
    send(response, 404, 'not found\n');
    return;
  }
  const files = await sharedDataFiles();
  if (name === 'index.json') {
    const body = JSON.stringify({ available: files.length > 0, files });
    response.writeHead(200, { 'content-type': MIME_TYPES['.json'], 'cache-control': 'no-cache' });
    response.end(request.method === 'HEAD' ? undefined : body);
    return;
  }
  // Only a listed file name (no folders, no '..'): the list is the whitelist.
  if (basename(name) !== name || !files.includes(name)) {
    send(response, 404, 'not found\n');
    return;
  }
  const file = resolve(sharedData, name);
  const info = await stat(file);
  response.writeHead(200, { 'content-type': MIME_TYPES['.poly'], 'content-length': info.size, 'cache-control': 'no-cache' });
  if (request.method === 'HEAD') response.end();
  else createReadStream(file).on('error', () => response.destroy()).pipe(response);
}

const MIME_TYPES = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.wasm': 'application/wasm',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
  '.ico': 'image/x-icon',
  '.txt': 'text/plain; charset=utf-8',
  '.md': 'text/plain; charset=utf-8',
  '.ts': 'text/plain; charset=utf-8',
  '.poly': 'text/plain; charset=utf-8',
  '.node': 'text/plain; charset=utf-8',
  '.ele': 'text/plain; charset=utf-8',
};

function send(response, status, text) {
  response.writeHead(status, { 'content-type': 'text/plain; charset=utf-8', 'cache-control': 'no-store' });
  response.end(text);
}

/** Maps a URL path to a served file under root, or null when it would leave root or is not served. */
function resolvePath(urlPath) {
  let decoded;
  try {
    decoded = decodeURIComponent(urlPath);
  } catch {
    return null;
  }
  if (decoded.includes('\0')) return null;
  // resolve() collapses '..'; the prefix check then rejects anything that climbed out of root.
  const file = resolve(root, `.${decoded.startsWith('/') ? '' : '/'}${decoded}`);
  if (!file.startsWith(root + sep)) return null;
  // A folder asked without its index.html (/web/) is checked as the folder itself.
  const relative = file.slice(root.length + 1).split(sep).join('/');
  return isServed(relative) || isServed(`${relative}/`) ? file : null;
}

async function handle(request, response) {
  if (request.method !== 'GET' && request.method !== 'HEAD') {
    send(response, 405, 'method not allowed\n');
    return;
  }
  const url = new URL(request.url ?? '/', 'http://localhost');
  if (url.pathname === '/') {
    response.writeHead(302, { location: '/web/' });
    response.end();
    return;
  }
  if (url.pathname.startsWith(SHARED_PREFIX)) {
    await handleSharedData(url.pathname, request, response);
    return;
  }
  let file = resolvePath(url.pathname);
  if (file === null) {
    send(response, 404, 'not found\n');
    return;
  }
  let info;
  try {
    info = await stat(file);
    if (info.isDirectory()) {
      if (!url.pathname.endsWith('/')) {
        response.writeHead(301, { location: `${url.pathname}/${url.search}` });
        response.end();
        return;
      }
      file = resolve(file, 'index.html');
      info = await stat(file);
    }
  } catch {
    send(response, 404, 'not found\n');
    return;
  }
  if (!info.isFile()) {
    send(response, 404, 'not found\n');
    return;
  }
  response.writeHead(200, {
    'content-type': MIME_TYPES[extname(file).toLowerCase()] ?? 'application/octet-stream',
    'content-length': info.size,
    // A development server: always serve the file as it is on disk now.
    'cache-control': 'no-cache',
    'x-content-type-options': 'nosniff',
  });
  if (request.method === 'HEAD') {
    response.end();
    return;
  }
  createReadStream(file).on('error', () => response.destroy()).pipe(response);
}

/**
 * Starts the server. Resolves to { server, url } once it listens.
 * @param {{ port?: number, quiet?: boolean }} [options] port 0 picks a free port
 */
export function startServer({ port = 8080, quiet = false } = {}) {
  return new Promise((resolvePromise, reject) => {
    const server = createServer((request, response) => {
      handle(request, response).catch(() => {
        if (!response.headersSent) send(response, 500, 'internal error\n');
        else response.destroy();
      });
    });
    const listen = (wanted) => {
      server.once('error', (error) => {
        // The wanted port is taken: any free port will do for a development server.
        if (error.code === 'EADDRINUSE' && wanted !== 0) {
          if (!quiet) console.error(`port ${wanted} is busy; using a free port instead`);
          listen(0);
        } else {
          reject(error);
        }
      });
      server.listen(wanted, '127.0.0.1', () => {
        const url = `http://127.0.0.1:${server.address().port}/web/`;
        resolvePromise({ server, url });
      });
    };
    listen(port);
  });
}

/** Serves on $PORT (default 8080) and prints the address: `npm run serve`, and `npm start` after its build. */
export async function serveOnEnvironmentPort() {
  const port = process.env.PORT !== undefined && process.env.PORT !== '' ? Number(process.env.PORT) : 8080;
  if (!Number.isInteger(port) || port < 0 || port > 65535) {
    console.error(`PORT=${process.env.PORT} is not a port number`);
    process.exit(2);
  }
  const { url } = await startServer({ port });
  console.log(`ruppert web page: ${url}`);
}

const isMain = process.argv[1] !== undefined && resolve(process.argv[1]) === fileURLToPath(import.meta.url);
if (isMain) await serveOnEnvironmentPort();
