#!/usr/bin/env node
// `npm run test:package`: test the package exactly as users get it.
//   1. `npm pack` (its prepack script builds wasm/dist) into a temporary folder;
//   2. install the tarball into an empty project there;
//   3. type-check tests/package/types-usage.ts against the installed index.d.ts (tsc --strict);
//   4. run tests/package/*.test.mjs, copied next to that project, with `node --test`, so that
//      `import 'ruppert'` resolves to the installed tarball and never to this checkout.
// Set RUPPERT_KEEP_TMP=1 to keep the folder for inspection.
import { spawnSync } from 'node:child_process';
import { copyFileSync, mkdtempSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = fileURLToPath(new URL('.', import.meta.url));
const root = resolve(here, '../..');
const work = mkdtempSync(join(tmpdir(), 'ruppert-package-'));
const app = join(work, 'app');

function run(command, args, options = {}) {
  console.log(`$ ${command} ${args.join(' ')}`);
  const result = spawnSync(command, args, { stdio: 'inherit', ...options });
  if (result.error) throw result.error;
  return result.status ?? 1;
}

function must(status, what) {
  if (status !== 0) {
    console.error(`test:package: ${what} failed (exit ${status}); files kept in ${work}`);
    process.exit(status || 1);
  }
}

must(run('npm', ['pack', '--pack-destination', work], { cwd: root }), 'npm pack');
const tarball = readdirSync(work).find((f) => f.endsWith('.tgz'));
if (!tarball) must(1, 'finding the packed tarball');

run('mkdir', ['-p', app]);
writeFileSync(join(app, 'package.json'), JSON.stringify({ name: 'ruppert-package-test', private: true, type: 'module' }));
must(run('npm', ['install', '--no-audit', '--no-fund', '--no-package-lock', join(work, tarball)], { cwd: app }),
  'installing the tarball');

const files = readdirSync(here).filter((f) => f.endsWith('.mjs') && f !== 'run-installed.mjs' || f.endsWith('.ts') || f === 'tsconfig.json');
for (const file of files) copyFileSync(join(here, file), join(app, file));

// The installed package must type-check from a strict TypeScript project.
must(run(process.execPath, [join(root, 'node_modules/typescript/bin/tsc'), '-p', join(app, 'tsconfig.json')]),
  'tsc --noEmit --strict on types-usage.ts');

const tests = readdirSync(app).filter((f) => f.endsWith('.test.mjs')).sort().map((f) => join(app, f));
const status = run(process.execPath, ['--test', '--test-concurrency=1', ...tests], {
  cwd: app,
  env: {
    ...process.env,
    RUPPERT_SHARED_DATA: process.env.RUPPERT_SHARED_DATA ?? resolve(root, '../shared/data'),
    RUPPERT_HOSTILE: resolve(root, 'tests/hostile'),
    // The page's words for the core's names (web/labels.js), checked by names.test.mjs.
    RUPPERT_WEB: resolve(root, 'web'),
    // The README whose examples readme.test.mjs runs, and the tarball its install line must name.
    RUPPERT_README: resolve(root, 'README.md'),
    RUPPERT_TARBALL: tarball,
  },
});
if (process.env.RUPPERT_KEEP_TMP) console.log(`kept ${work}`);
else rmSync(work, { recursive: true, force: true });
process.exit(status);
