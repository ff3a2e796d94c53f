// Builds and runs test/oracle.c natively against the C library (float build) and returns its
// JSON. With COLLIDE_NATIVE_LIB (a libcollide.a of the float build) and COLLIDE_NATIVE_INCLUDE
// (that build's generated include directory) it links that library, as CTest does; otherwise it
// compiles the library's sources itself.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readdirSync, existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const root = join(here, '..', '..', '..');

function configHeader(dir) {
  const cmake = readFileSync(join(root, 'CMakeLists.txt'), 'utf8');
  const [major, minor, patch] = /project\(collide VERSION (\d+)\.(\d+)\.(\d+)/.exec(cmake).slice(1);
  const text = readFileSync(join(root, 'include', 'collide', 'config.h.in'), 'utf8')
    .replace('@CD_DOUBLE_VALUE@', '0').replace('@PROJECT_VERSION_MAJOR@', major)
    .replace('@PROJECT_VERSION_MINOR@', minor).replace('@PROJECT_VERSION_PATCH@', patch);
  mkdirSync(join(dir, 'collide'), { recursive: true });
  writeFileSync(join(dir, 'collide', 'config.h'), text);
}

export function runOracle() {
  const dir = mkdtempSync(join(tmpdir(), 'collide-oracle-'));
  const exe = join(dir, 'oracle');
  const cc = process.env.CC || 'cc';
  const common = ['-std=c11', '-O2', '-ffp-contract=off', '-I', join(root, 'include')];
  const lib = process.env.COLLIDE_NATIVE_LIB;
  if (lib && existsSync(lib)) {
    const inc = process.env.COLLIDE_NATIVE_INCLUDE;
    execFileSync(cc, [...common, '-I', inc, join(here, 'oracle.c'), lib, '-lm', '-o', exe], { stdio: 'inherit' });
  } else {
    const gen = join(dir, 'include');
    configHeader(gen);
    const sources = [];
    for (const sub of readdirSync(join(root, 'src'))) {
      for (const f of readdirSync(join(root, 'src', sub))) if (f.endsWith('.c')) sources.push(join(root, 'src', sub, f));
    }
    execFileSync(cc, [...common, '-I', gen, '-I', join(root, 'src'), '-DNDEBUG', ...sources, join(here, 'oracle.c'), '-lm', '-o', exe],
      { stdio: 'inherit' });
  }
  return JSON.parse(execFileSync(exe, { maxBuffer: 1 << 28 }).toString());
}
