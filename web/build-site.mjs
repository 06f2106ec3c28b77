#!/usr/bin/env node
// `npm run build:site`: writes site/, one folder of static files that any static server (GitHub
// Pages, a course's file area, python3 -m http.server) serves as it is:
//
//   site/index.html            the page (web/index.html)
//   site/embed-example.html    a host page embedding it (web/embed-example.html)
//   site/*.js, site/style.css  the page's modules, as web/ has them
//   site/wasm/...              the package's modules and .wasm files the page loads (wasm/, wasm/dist/;
//                              its .mjs files renamed .js)
//
// What is copied is what the two pages reach: their <script src> and <link href>, then every module
// those import (import ... from, export ... from, import(), new URL('...', import.meta.url)), so
// the Node-only parts of the package (the CLI, node.js) stay out. Every URL is relative, and the
// build checks that none climbs out of site/ ('../') or starts at the server's root ('/').
//
//   node web/build-site.mjs [--out <folder>]     default: site/ at the repository's root
//
// Builds wasm/dist first when it is missing (as `npm start` does).
import { spawnSync } from 'node:child_process';
import { copyFileSync, existsSync, mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { dirname, join, posix, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = resolve(fileURLToPath(new URL('..', import.meta.url)));
const PAGES = ['web/index.html', 'web/embed-example.html'];
const WASM_FILES = ['ruppert.wasm', 'ruppert-formats.wasm', 'ruppert-cli.wasm'];

/**
 * Where a repository file goes in the site: web/x -> x, wasm/x -> wasm/x, except that the
 * package's .mjs modules become .js: a course's file area may not know .mjs, and a module served
 * as application/octet-stream is refused by the browser.
 */
function sitePath(repoPath) {
  if (repoPath.startsWith('web/')) return repoPath.slice('web/'.length);
  if (repoPath.startsWith('wasm/')) return repoPath.replace(/\.mjs$/, '.js');
  throw new Error(`build-site: ${repoPath} is neither in web/ nor in wasm/`);
}

const isRelative = (spec) => spec.startsWith('./') || spec.startsWith('../');

// The references a file makes, as [whole match, specifier] pairs. Comments are skipped: a
// reference is a quoted relative path in code.
const JS_REFERENCES = [
  /\b(?:import|export)\s[^'"`;]*?\bfrom\s*(['"])([^'"]+)\1/g,
  /\bimport\s*(['"])([^'"]+)\1/g,
  /\bimport\(\s*(['"])([^'"]+)\1\s*\)/g,
  /\bnew URL\(\s*(['"])([^'"]+)\1\s*,\s*import\.meta\.url\s*\)/g,
];
const HTML_REFERENCES = [
  /<script\b[^>]*\bsrc=(["'])([^"']+)\1/g,
  /<link\b[^>]*\bhref=(["'])([^"']+)\1/g,
];

function withoutComments(text) {
  // Line comments that start a line (after spaces) and block comments: enough for this repository's
  // style, where a '//' inside a string is never at a line's start.
  return text.replace(/\/\*[\s\S]*?\*\//g, '').replace(/^\s*\/\/.*$/gm, '');
}

function references(repoPath, text) {
  const html = repoPath.endsWith('.html');
  const code = html ? text : withoutComments(text);
  const found = [];
  for (const pattern of html ? HTML_REFERENCES : JS_REFERENCES) {
    for (const match of code.matchAll(pattern)) {
      const spec = match[2];
      if (!isRelative(spec)) continue;  // data:, node:, bare package names (Node-only branches)
      found.push(spec);
    }
  }
  return found;
}

/** Every file the pages reach, as repository paths, and the text files' references. */
function collect() {
  const files = new Map();  // repo path -> [specifier]
  const queue = [...PAGES];
  while (queue.length > 0) {
    const repoPath = queue.shift();
    if (files.has(repoPath)) continue;
    const absolute = join(root, repoPath);
    if (!existsSync(absolute)) throw new Error(`build-site: ${repoPath} is referenced but missing`);
    if (!/\.(html|js|mjs|css)$/.test(repoPath)) {
      files.set(repoPath, []);
      continue;
    }
    const specs = references(repoPath, readFileSync(absolute, 'utf8'));
    files.set(repoPath, specs);
    for (const spec of specs) {
      const target = posix.normalize(posix.join(posix.dirname(repoPath), spec.replace(/[?#].*$/, '')));
      queue.push(target);
    }
  }
  return files;
}

/** The text of a copied file with its relative references rewritten for the site's layout. */
function rewrite(repoPath, text, specs) {
  let out = text;
  for (const spec of new Set(specs)) {
    const [path, suffix = ''] = spec.split(/(?=[?#])/);
    const target = sitePath(posix.normalize(posix.join(posix.dirname(repoPath), path)));
    let moved = posix.relative(posix.dirname(sitePath(repoPath)), target);
    if (!moved.startsWith('.')) moved = `./${moved}`;
    if (moved === path) continue;
    for (const quote of ["'", '"']) out = out.split(`${quote}${spec}${quote}`).join(`${quote}${moved}${suffix}${quote}`);
  }
  return out;
}

/** The page's <head> as a static site has it: the package version, no corpus of the dev server. */
function siteHead(text, version) {
  const withVersion = text.replace(/(<meta name="ruppert-version" content=")[^"]*(")/, `$1${version}$2`);
  return withVersion.replace(/\s*<meta name="ruppert-shared-data"[^>]*>/, '');
}

function ensureWasm() {
  if (WASM_FILES.every((file) => existsSync(join(root, 'wasm/dist', file)))) return;
  console.log('build-site: wasm/dist is missing; building it (node wasm/build-wasm.mjs)');
  const env = { ...process.env, NODE_PATH: [process.env.NODE_PATH, '/usr/share/nodejs'].filter(Boolean).join(':') };
  const result = spawnSync(process.execPath, ['wasm/build-wasm.mjs'], { stdio: 'inherit', cwd: root, env });
  if (result.status !== 0) process.exit(result.status ?? 1);
}

/** Builds the site into `out` (emptied first); returns the list of site paths written. */
export function buildSite(out = join(root, 'site')) {
  const version = JSON.parse(readFileSync(join(root, 'package.json'), 'utf8')).version;
  const files = collect();
  rmSync(out, { recursive: true, force: true });
  const written = [];
  for (const [repoPath, specs] of files) {
    const destination = join(out, sitePath(repoPath));
    mkdirSync(dirname(destination), { recursive: true });
    if (!/\.(html|js|mjs|css)$/.test(repoPath)) {
      copyFileSync(join(root, repoPath), destination);
    } else {
      let text = rewrite(repoPath, readFileSync(join(root, repoPath), 'utf8'), specs);
      if (repoPath === 'web/index.html') text = siteHead(text, version);
      // Every relative reference stays inside the site, and none starts at the server's root.
      for (const spec of references(repoPath, text)) {
        if (posix.normalize(posix.join(posix.dirname(sitePath(repoPath)), spec)).startsWith('..')) {
          throw new Error(`build-site: ${repoPath} refers to ${spec}, outside the site`);
        }
      }
      const rooted = withoutComments(text).match(/(?:src|href)=["']\/[^"']*["']|\bfetch\(\s*['"`]\.\.\//);
      if (rooted) throw new Error(`build-site: ${repoPath} has a URL outside the site: ${rooted[0]}`);
      writeFileSync(destination, text);
    }
    written.push(sitePath(repoPath));
  }
  for (const needed of ['index.html', 'wasm/worker.js', 'wasm/dist/ruppert.wasm', 'wasm/dist/ruppert-formats.wasm']) {
    if (!written.includes(needed)) throw new Error(`build-site: ${needed} was not reached from the pages`);
  }
  return written.sort();
}

const isMain = process.argv[1] !== undefined && resolve(process.argv[1]) === fileURLToPath(import.meta.url);
if (isMain) {
  const at = process.argv.indexOf('--out');
  const out = at >= 0 && process.argv[at + 1] ? resolve(process.argv[at + 1]) : join(root, 'site');
  ensureWasm();
  const written = buildSite(out);
  console.log(`build-site: ${written.length} files in ${relative(process.cwd(), out) || '.'}/ ` +
    `(${written.filter((f) => f.startsWith('wasm/')).length} of the package); serve that folder as it is, ` +
    'e.g. python3 -m http.server -d ' + (relative(process.cwd(), out) || '.'));
}
