// One set of names per enum: the core declares them (core/include/ruppert/ruppert.h's
// k...Names), the binding exports them (wasm/binding/describe.cpp), and the package's JavaScript and
// its index.d.ts must use exactly those. The .d.ts has to spell them out (TypeScript needs literal
// unions), so this test reads its text and fails on any name that differs, is missing or is extra.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';
import { init, ERROR_CODES, EventKind, VertexKind } from 'ruppert';

const installed = new URL('./node_modules/ruppert/', import.meta.url);

// The binding's own description, from an instance made here (not through the package's names.js).
async function bindingNames() {
  const { compileWasm, instantiate } = await import(new URL('wasm/loader.js', installed));
  const { readDescription } = await import(new URL('wasm/heap-call.js', installed));
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

// ruppert-cli.wasm, the module wasm/cli.js runs on, as a MODULES-like entry of wasm/loader.js.
async function cliModule() {
  const { default: factory } = await import(new URL('wasm/dist/ruppert-cli.mjs', installed));
  const kind = { file: 'ruppert-cli.wasm', factory, probe: 'parseCliArgs' };
  return { kind, wasmBinary: readFileSync(new URL('wasm/dist/ruppert-cli.wasm', installed)) };
}

// A mesher on ruppert-cli.wasm with what wasm/cli.js uses (_parseCliArgs), made as cli.js makes
// its own (cli.js runs its command line when imported, so it exports nothing).
async function cliMesher() {
  const { instanceHost } = await import(new URL('wasm/loader.js', installed));
  const { createMesher } = await import(new URL('wasm/mesher.js', installed));
  const { kind, wasmBinary } = await cliModule();
  const host = await instanceHost({ wasmBinary }, kind);
  return createMesher(host, host, true);
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
  const cli = await cliMesher();
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
  assert.deepEqual(sorted(keys(labels.NOTICE_LABELS)), sorted(names.notices));
  // The page draws only the exemptions among the reasons: those must be reasons.
  for (const reason of keys(labels.EXEMPTION_LABELS)) assert.ok(names.reasons.includes(reason), reason);
});

// Options: every option's name, type, default and range is written once, in
// core/include/ruppert/option_table.h; the binding describes them, triangulate() and the CLI take
// them from there, and index.d.ts, which spells them out, must agree.
// Only the CLI's module (ruppert-cli.wasm) describes them, which keeps the mesher small.
async function bindingOptions() {
  const { compileWasm, instantiate } = await import(new URL('wasm/loader.js', installed));
  const { readDescription } = await import(new URL('wasm/heap-call.js', installed));
  const { kind, wasmBinary } = await cliModule();
  return readDescription(await instantiate(await compileWasm({ wasmBinary }, kind), kind)).options;
}

// TriangulateOptions' members: { name: { type, doc } }, doc the /** */ comment just before it.
function declaredOptions() {
  const text = readFileSync(new URL('wasm/index.d.ts', installed), 'utf8');
  const start = text.indexOf('export interface TriangulateOptions {');
  assert.ok(start >= 0, 'index.d.ts has no TriangulateOptions');
  const body = text.slice(start, text.indexOf('\n}', start));
  const members = {};
  for (const m of body.matchAll(/(\/\*\*(?:[^*]|\*(?!\/))*\*\/)?\s*(\w+)\?:\s*([^;]+);/g)) {
    members[m[2]] = { type: m[3].trim(), doc: (m[1] ?? '').replace(/\s*\n\s*\*\s*/g, ' ') };
  }
  return members;
}

// The TypeScript type an option of each type must have.
function typeScriptOf(option) {
  switch (option.type) {
    case 'number': case 'count': return 'number';
    case 'boolean': return 'boolean';
    case 'choice': return option.values.map((v) => `'${v}'`).sort().join(' | ');
    case 'integer': if (option.whenTrue !== undefined) return 'boolean | number';
      return Array.from({ length: option.max - option.min + 1 }, (_, i) => option.min + i).join(' | ');
    default: return 'function';
  }
}

test("the package's names.js has the binding's options", async () => {
  const { OPTIONS } = await import(new URL('wasm/dist/names.js', installed));
  const options = await bindingOptions();
  assert.deepEqual(JSON.parse(JSON.stringify(OPTIONS)), options);
  assert.ok(options.length > 0 && new Set(options.map((o) => o.name)).size === options.length);
});

test("index.d.ts's TriangulateOptions has exactly the table's options, each of its type", async () => {
  const options = await bindingOptions();
  const declared = declaredOptions();
  assert.deepEqual(Object.keys(declared).sort(), options.map((o) => o.name).sort());
  for (const option of options) {
    const { type } = declared[option.name];
    const written = type.includes('=>') ? 'function' : type.split('|').map((t) => t.trim()).sort().join(' | ');
    assert.equal(written, typeScriptOf(option), `TriangulateOptions.${option.name}`);
  }
});

test("index.d.ts's comments give the table's defaults and ranges", async () => {
  const declared = declaredOptions();
  for (const option of await bindingOptions()) {
    const { doc } = declared[option.name];
    // A number with both ends states its range; every default a comment names is the table's.
    if (option.type === 'number' && option.max !== null) {
      assert.ok(doc.includes(`[${option.min}, ${option.max}]`), `${option.name}'s comment: ${doc}`);
    }
    for (const m of doc.matchAll(/Default (-?[\d.]+)\b/g)) assert.equal(Number(m[1]), option.default, option.name);
    for (const m of doc.matchAll(/'(\w+)' \(default\)/g)) assert.equal(m[1], option.default, option.name);
  }
  assert.match(declared.minAngle.doc, /Default \d/, "minAngle's comment names its default");
});

test("triangulate() and the CLI's parser default every option as the table says", async () => {
  const options = await bindingOptions();
  const mesher = await init();
  const parsed = (await cliMesher())._parseCliArgs(['in.poly']).options;
  const square = { points: [0, 0, 1, 0, 1, 1, 0, 1], segments: [0, 1, 1, 2, 2, 3, 3, 0] };
  const explicit = {};
  for (const option of options) {
    if (option.type === 'function' || option.default === null) {
      assert.equal(parsed[option.name], undefined, `the CLI's ${option.name}`);
      continue;
    }
    assert.equal(parsed[option.name], option.default, `the CLI's ${option.name}`);
    explicit[option.name] = option.default;
  }
  const byDefault = mesher.triangulate(square), given = mesher.triangulate(square, explicit);
  assert.deepEqual([...given.triangles], [...byDefault.triangles]);
  assert.equal(given.stats.minAngle, byDefault.stats.minAngle);
});

test('a number option outside its range names the range', async () => {
  const mesher = await init();
  const square = { points: [0, 0, 1, 0, 1, 1, 0, 1], segments: [0, 1, 1, 2, 2, 3, 3, 0] };
  for (const option of await bindingOptions()) {
    if (option.type !== 'number' || option.max === null) continue;
    assert.throws(() => mesher.triangulate(square, { [option.name]: option.max + 1 }),
      (e) => e.code === 'INVALID_OPTION' &&
        e.message === `${option.name} = ${option.max + 1} is outside [${option.min}, ${option.max}] ${option.unit}`);
  }
});
