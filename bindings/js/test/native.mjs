// Compiles one C program of test/ natively against the C library (float build), for the tests
// that compare the wasm build with the native one. With an executable given in `envName` (CTest
// builds it with the project's flags) that one is used; otherwise the program is compiled here
// with the library's sources (-O2 -ffp-contract=off, as the project builds them).
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readdirSync, existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const root = join(here, '..', '..', '..');

export function nativeProgram(source, envName) {
  const given = process.env[envName];
  if (given && existsSync(given)) return given;
  const dir = mkdtempSync(join(tmpdir(), 'collide-native-'));
  const gen = join(dir, 'include');
  const cmake = readFileSync(join(root, 'CMakeLists.txt'), 'utf8');
  const [major, minor, patch] = /project\(collide VERSION (\d+)\.(\d+)\.(\d+)/.exec(cmake).slice(1);
  const text = readFileSync(join(root, 'include', 'collide', 'config.h.in'), 'utf8')
    .replace('@CD_DOUBLE_VALUE@', '0').replace('@PROJECT_VERSION_MAJOR@', major)
    .replace('@PROJECT_VERSION_MINOR@', minor).replace('@PROJECT_VERSION_PATCH@', patch);
  mkdirSync(join(gen, 'collide'), { recursive: true });
  writeFileSync(join(gen, 'collide', 'config.h'), text);
  const sources = [];
  for (const sub of readdirSync(join(root, 'src'))) {
    for (const f of readdirSync(join(root, 'src', sub))) if (f.endsWith('.c')) sources.push(join(root, 'src', sub, f));
  }
  const exe = join(dir, 'program');
  execFileSync(process.env.CC || 'cc', ['-std=c11', '-O2', '-ffp-contract=off', '-DNDEBUG', '-I', join(root, 'include'), '-I', gen,
    '-I', join(root, 'src'), ...sources, join(here, source), '-lm', '-o', exe], { stdio: 'inherit' });
  return exe;
}
