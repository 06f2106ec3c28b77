// The page's floors: each file of web/ imports only from floors below its own, or from its own
// folder on its own floor, and no chain of imports comes back to where it started. Services a part
// needs from its side (the status line, the host's messages, file reading) are handed in by
// main.js, the composition root, rather than imported. No browser: the imports are read from the
// files. The floors are declared here, once; web/README.md describes them.
import assert from 'node:assert/strict';
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { dirname, join, normalize, relative } from 'node:path';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('../../', import.meta.url));
const web = join(root, 'web');

/**
 * Floors, lowest first: [name, the paths under web/ on it (a folder ends in '/')]. At the ground
 * the page's words for the core's names, then the measures of meshes, then the drawing model (points, segments, curves,
 * regions) that uses them, pictures above those, the parts of the page (editing, panels, steps,
 * meshing, files and links) above those, the composition root and the Node tools that serve the
 * page on top. The package (wasm/) is below them all.
 */
export const FLOORS = [
  ['words', ['labels.js']],
  ['geometry', ['geometry/']],
  ['model', ['model/']],
  ['rendering', ['rendering/']],
  ['parts', ['editing/', 'panels/', 'steps/', 'meshing/', 'io/']],
  ['root', ['main.js', 'served-check.js', 'serve.mjs', 'start.mjs', 'build-site.mjs', 'wasm-freshness.mjs']],
];
const BELOW_EVERY_FLOOR = ['../wasm/'];  // paths relative to web/ that any floor may import

/** The floor (index into floors) of a path relative to web/, or -1 when none declares it. */
export function floorOf(path, floors = FLOORS) {
  return floors.findIndex(([, paths]) => paths.some((p) => (p.endsWith('/') ? path.startsWith(p) : path === p)));
}

const IMPORT = /(?:^|[\s;])(?:import|export)\s*(?:[\w*{}\s,]*?\s*from\s*)?\(?\s*['"](\.{1,2}\/[^'"]+)['"]/g;

/** Every relative import of the JavaScript files under web/: { from, to } paths relative to web/. */
export function webImports() {
  const edges = [];
  const walk = (dir) => {
    for (const name of readdirSync(dir)) {
      const path = join(dir, name);
      if (statSync(path).isDirectory()) walk(path);
      else if (/\.m?js$/.test(name)) {
        const text = readFileSync(path, 'utf8').replace(/^\s*\/\/.*$/gm, '').replace(/\/\*[\s\S]*?\*\//g, '');
        for (const match of text.matchAll(IMPORT)) {
          edges.push({ from: relative(web, path), to: relative(web, normalize(join(dirname(path), match[1]))) });
        }
      }
    }
  };
  walk(web);
  return edges;
}

/** The imports that break the floors: up a floor, sideways into another folder, or from an undeclared file. */
export function floorViolations(edges, floors = FLOORS, below = BELOW_EVERY_FLOOR) {
  const problems = [];
  for (const { from, to } of edges) {
    if (below.some((p) => to.startsWith(p))) continue;
    const [a, b] = [floorOf(from, floors), floorOf(to, floors)];
    if (a < 0 || b < 0) problems.push(`${from} -> ${to}: ${a < 0 ? from : to} is on no floor`);
    else if (b > a) problems.push(`${from} (${floors[a][0]}) -> ${to} (${floors[b][0]}): up a floor`);
    else if (b === a && dirname(from) !== dirname(to)) problems.push(`${from} -> ${to}: sideways on the ${floors[a][0]} floor`);
  }
  return problems;
}

/** Every circle of imports, as the files on it (one per circle found by a depth-first search). */
export function importCycles(edges) {
  const next = new Map();
  for (const { from, to } of edges) next.set(from, [...(next.get(from) ?? []), to]);
  const state = new Map();  // file -> 'open' while on the search's path, 'done' after
  const path = [];
  const cycles = [];
  const visit = (file) => {
    state.set(file, 'open');
    path.push(file);
    for (const to of next.get(file) ?? []) {
      if (state.get(to) === 'open') cycles.push([...path.slice(path.indexOf(to)), to]);
      else if (!state.has(to)) visit(to);
    }
    path.pop();
    state.set(file, 'done');
  };
  for (const file of next.keys()) if (!state.has(file)) visit(file);
  return cycles;
}

test('the check finds an import up a floor, one sideways, and a circle', () => {
  const edges = [
    { from: 'rendering/a.js', to: 'steps/b.js' },
    { from: 'panels/c.js', to: 'io/d.js' },
    { from: 'model/e.js', to: 'model/f.js' },
    { from: 'model/f.js', to: 'model/e.js' },
    { from: 'panels/c.js', to: 'model/e.js' },
    { from: 'geometry/g.js', to: 'labels.js' },
    { from: 'geometry/g.js', to: 'model/e.js' },
    { from: 'io/d.js', to: '../wasm/index.js' },
  ];
  assert.deepEqual(floorViolations(edges), [
    'rendering/a.js (rendering) -> steps/b.js (parts): up a floor',
    'panels/c.js -> io/d.js: sideways on the parts floor',
    'geometry/g.js (geometry) -> model/e.js (model): up a floor',
  ]);
  assert.deepEqual(importCycles(edges), [['model/e.js', 'model/f.js', 'model/e.js']]);
});

test('the page\'s imports only go down a floor, or within a folder', () => {
  const edges = webImports();
  assert.ok(edges.length > 100, `${edges.length} imports read`);
  assert.ok(edges.some((e) => e.from === 'main.js' && e.to === 'model/drawing.js'), 'main.js\'s imports are read');
  assert.deepEqual(floorViolations(edges), []);
});

test('no circle of imports in the page', () => {
  assert.deepEqual(importCycles(webImports()), []);
});
