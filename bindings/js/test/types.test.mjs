// The TypeScript declarations: test/usage.ts (every export, typed) must pass `tsc --noEmit`
// (including its @ts-expect-error lines, which must be errors), and, compiled, must run.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync, rmSync } from 'node:fs';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { join } from 'node:path';

const pkg = fileURLToPath(new URL('..', import.meta.url));
const tsc = join(pkg, 'node_modules', 'typescript', 'bin', 'tsc');

test('tsc --noEmit accepts the typed usage file against index.d.ts', () => {
  assert.ok(existsSync(tsc), 'typescript is not installed: run npm install in bindings/js');
  execFileSync(process.execPath, [tsc, '-p', 'test/tsconfig.json'], { cwd: pkg, stdio: 'inherit' });
});

test('the usage file, compiled, runs against the module', async () => {
  const out = join(pkg, 'build', 'usage');
  rmSync(out, { recursive: true, force: true });
  execFileSync(process.execPath, [tsc, '-p', 'test/tsconfig.json', '--noEmit', 'false', '--rootDir', 'test', '--outDir', out], { cwd: pkg, stdio: 'inherit' });
  const { main } = await import(pathToFileURL(join(out, 'usage.js')).href);
  const value = await main();
  assert.equal(typeof value, 'number');
  assert.ok(Number.isFinite(value));
});
