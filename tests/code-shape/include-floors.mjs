// The core's floors, drawn from its #include lines: a file may include files on its own floor or
// below, never above, and no files may include each other in a circle. The floors are the
// pipeline's order (docs/architecture.md): what everything uses at the ground, then the
// triangulation, the data a run holds, the shared state, the stages in triangulate()'s order, the
// readers and writers, and triangulate.cpp, which composes them, on top.
// Usage: node tests/code-shape/include-floors.mjs   (exits 1 naming each finding)
import { readFileSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { dirname, join, normalize } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const src = 'core/src/';

// Lowest first. A path belongs to the first floor one of whose prefixes it starts with.
const FLOORS = [
  ['core/include/', 'core/src/cold_code.h', 'core/src/message.', 'core/src/decimal_text.', 'core/src/errors.cpp'],
  ['core/src/mesh/'],
  ['core/src/prepared_input.h', 'core/src/curve_pieces.'],
  ['core/src/mesh_state.h', 'core/src/point_attributes.'],
  ['core/src/cdt/'],
  ['core/src/refine/'],
  ['core/src/smooth/'],
  ['core/src/output/'],
  ['core/src/io/'],
  ['core/src/triangulate.cpp'],
];

const floorOf = (path) => FLOORS.findIndex((prefixes) => prefixes.some((p) => path.startsWith(p)));

const files = execFileSync('git', ['ls-files', 'core/src', 'core/include'], { cwd: root, encoding: 'utf8' })
  .split('\n')
  .filter((f) => /\.(h|cpp)$/.test(f));
const known = new Set(files);

// Includes are written from core/src/ or core/include/, or relative to the including file.
function resolve(from, name) {
  for (const base of [src, 'core/include/', dirname(from) + '/']) {
    const path = normalize(base + name);
    if (known.has(path)) return path;
  }
  return null;
}

const findings = [];
const edges = new Map();
for (const file of files) {
  const floor = floorOf(file);
  if (floor < 0) findings.push(`${file}: on no floor (add it to FLOORS in tests/code-shape/include-floors.mjs)`);
  const targets = [];
  for (const [, name] of readFileSync(join(root, file), 'utf8').matchAll(/^#include "([^"]+)"/gm)) {
    const target = resolve(file, name);
    if (!target) continue;  // a generated or outside header
    targets.push(target);
    const up = floorOf(target);
    if (floor >= 0 && up > floor) findings.push(`${file} (floor ${floor}) includes ${target} (floor ${up}), a floor above it`);
  }
  edges.set(file, targets);
}

// Circles: a depth-first search that finds a file already on the current path.
const state = new Map();  // 1 on the path, 2 done
function visit(file, path) {
  state.set(file, 1);
  for (const next of edges.get(file) ?? []) {
    if (state.get(next) === 1) findings.push(`a circle of includes: ${[...path.slice(path.indexOf(next)), next].join(' -> ')}`);
    else if (!state.has(next)) visit(next, [...path, next]);
  }
  state.set(file, 2);
}
for (const file of files) if (!state.has(file)) visit(file, [file]);

for (const f of findings) console.log(`include-floors: ${f}`);
console.log(`include-floors: ${files.length} files on ${FLOORS.length} floors, ${findings.length} findings`);
process.exit(findings.length ? 1 : 0);
