// One set of names per enum (issue 18): the core declares them (core/include/ruppert/ruppert.h's
// k...Names), the binding exports them (wasm/describe.cpp), and the package's JavaScript and its
// index.d.ts must use exactly those. The .d.ts has to spell them out (TypeScript needs literal
// unions), so this test reads its text and fails on any name that differs, is missing or is extra.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';
import { init, ERROR_CODES, EventKind, VertexKind } from 'ruppert';

const installed = new URL('./node_modules/ruppert/', import.meta.url);

// The binding's own description, from an instance made here (not through the package's names.js).
async function bindingNames() {
  const { compileWasm, instantiate } = await import(new URL('wasm/loader.js', installed));
  const { readDescription } = await import(new URL('wasm/describe.js', installed));
  const wasmBinary = readFileSync(new URL('wasm/dist/ruppert.wasm', installed));
  return readDescription(await instantiate(await compileWasm({ wasmBinary }))).names;
}

// index.d.ts without comments, so that a name mentioned in prose is not taken for a member.
const declarations = readFileSync(new URL('wasm/index.d.ts', installed), 'utf8')
  .replace(/\/\*[\s\S]*?\*\//g, '').replace(/\/\/.*$/gm, '');

// The string literals of the union that follows `start` up to the next ';'.
function union(start) {
  const at = declarations.indexOf(start);
  assert.ok(at >= 0, `index.d.ts has no ${start}`);
  const text = declarations.slice(at + start.length, declarations.indexOf(';', at));
  return [...text.matchAll(/'([^']*)'/g)].map((m) => m[1]);
}

// { NAME: value } of `export declare const <name>: Readonly<{ NAME: 0; ... }>`.
function declaredEnum(name) {
  const start = `export declare const ${name}: Readonly<{`;
  const at = declarations.indexOf(start);
  assert.ok(at >= 0, `index.d.ts has no ${start}`);
  const text = declarations.slice(at + start.length, declarations.indexOf('}>', at));
  return Object.fromEntries([...text.matchAll(/(\w+):\s*(\d+)/g)].map((m) => [m[1], Number(m[2])]));
}

const asEnum = (names) => Object.fromEntries(names.map((name, value) => [name, value]));
const sorted = (names) => [...names].sort();

test('the binding exports every enum the package names, none empty', async () => {
  const names = await bindingNames();
  assert.deepEqual(Object.keys(names).sort(),
    ['curveTypes', 'encroachments', 'errorCodes', 'events', 'notices', 'placements', 'reasons', 'variants', 'vertexKinds']);
  for (const [key, list] of Object.entries(names)) {
    assert.ok(list.length > 0 && new Set(list).size === list.length, `${key}: ${list}`);
  }
});

test("the package's names.js is the binding's", async () => {
  const { NAMES } = await import(new URL('wasm/dist/names.js', installed));
  assert.deepEqual(JSON.parse(JSON.stringify(NAMES)), await bindingNames());
});

test("ERROR_CODES and index.d.ts's ErrorCode are the core's error codes", async () => {
  const { errorCodes } = await bindingNames();
  assert.deepEqual([...ERROR_CODES], errorCodes);
  assert.deepEqual(union('export type ErrorCode ='), errorCodes);
});

test("VertexKind and EventKind, in JavaScript and in index.d.ts, are the core's", async () => {
  const { vertexKinds, events } = await bindingNames();
  assert.deepEqual({ ...VertexKind }, asEnum(vertexKinds));
  assert.deepEqual(declaredEnum('VertexKind'), asEnum(vertexKinds));
  assert.deepEqual({ ...EventKind }, asEnum(events));
  assert.deepEqual(declaredEnum('EventKind'), asEnum(events));
});

test("index.d.ts's ReasonKind and NoticeKind are the core's", async () => {
  const { reasons, notices } = await bindingNames();
  assert.deepEqual(union('export type ReasonKind ='), reasons);
  assert.deepEqual(union('export type NoticeKind ='), notices);
});

test('placement, encroachment and variant: the core\'s names, accepted by triangulate(), the CLI and index.d.ts', async () => {
  const names = await bindingNames();
  const mesher = await init();
  // The native CLI's parser is in the module wasm/cli.js runs on (ruppert-cli.wasm).
  const { initCli } = await import(new URL('wasm/cli-mesher.js', installed));
  const cli = await initCli();
  const square = { points: [0, 0, 1, 0, 1, 1, 0, 1], segments: [0, 1, 1, 2, 2, 3, 3, 0] };
  for (const [option, key] of [['placement', 'placements'], ['encroachment', 'encroachments'], ['variant', 'variants']]) {
    const core = names[key];
    assert.deepEqual(sorted(union(`${option}?:`)), sorted(core), `index.d.ts's Options.${option}`);
    // The rejection lists what triangulate() accepts, in the enum's order; each of them meshes.
    assert.throws(() => mesher.triangulate(square, { [option]: 'no-such-name' }),
      (e) => e.code === 'INVALID_OPTION' && e.message.endsWith(`must be one of ${core.map((n) => `'${n}'`).join(', ')}`),
      option);
    for (const name of core) {
      assert.equal(mesher.triangulate(square, { [option]: name }).complete, true, `${option} '${name}'`);
      // The native CLI's parser (compiled into the package for wasm/cli.js) reads and returns it.
      const parsed = cli._parseCliArgs([`--${option}`, name, 'in.poly']);
      assert.equal(parsed.usageError, undefined, `--${option} ${name}`);
      assert.equal(parsed.options[option], name);
    }
  }
});

test("index.d.ts's CurveType is the core's curve types", async () => {
  const { curveTypes } = await bindingNames();
  assert.deepEqual(union('export type CurveType ='), curveTypes);
});

test("the page's words (web/labels.js) are keyed by the core's names", async () => {
  const web = process.env.RUPPERT_WEB;
  assert.ok(web, 'RUPPERT_WEB (the repository\'s web/ folder) is set by tests/package/run-installed.mjs');
  const labels = await import(new URL('labels.js', `file://${web}/`));
  const names = await bindingNames();
  const keys = (table) => Object.keys(table);
  // Every kind of vertex and event is shown, so each needs words, and no others.
  assert.deepEqual(keys(labels.VERTEX_KIND_LABELS), names.vertexKinds);
  assert.deepEqual(sorted(keys(labels.EVENT_KIND_LABELS)), sorted(names.events));
  assert.deepEqual(sorted(keys(labels.PLACEMENT_LABELS)), sorted(names.placements));
  assert.deepEqual(sorted(keys(labels.VARIANT_LABELS)), sorted(names.variants));
  assert.deepEqual(sorted(keys(labels.ENCROACHMENT_LABELS)), sorted(names.encroachments));
  // The page draws only the exemptions among the reasons: those must be reasons.
  for (const reason of keys(labels.EXEMPTION_LABELS)) assert.ok(names.reasons.includes(reason), reason);
});
