// Browser tests of the demo pages: playwright-core drives Debian's chromium (headless; nothing
// downloads a browser) against the built pages (web/dist) served by serve.mjs. Every run writes
// a screenshot of each page it visits to the output folder.
//
//   node tests/run.mjs [--reference PATH] [--out DIR] [--list] [TEST ...]
//
// TEST is a test name or a prefix (explorer, bounds3d, ...); none runs all. --reference is the
// native C program (tests/reference.c, built by CMake as web_reference) whose answers the pages'
// answers must match. Exit status: 0 all passed, 1 a test failed, 77 every selected test is
// pending (CTest reports it as skipped).
import { chromium } from 'playwright-core';
import { spawn } from 'node:child_process';
import { existsSync, mkdirSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { startServer } from '../serve.mjs';
import { TESTS, Pending } from './cases.mjs';

const here = dirname(fileURLToPath(import.meta.url));
const args = process.argv.slice(2);
const take = (name) => {
  const i = args.indexOf(name);
  if (i < 0) return null;
  const v = args[i + 1];
  args.splice(i, 2);
  return v;
};
const referencePath = take('--reference') ?? process.env.COLLIDE_WEB_REFERENCE ?? null;
const outDir = resolve(take('--out') ?? join(here, '..', '..', 'out'));
const dist = resolve(take('--dist') ?? join(here, '..', 'dist'));
if (args.includes('--list')) {
  for (const t of TESTS) console.log(t.name);
  process.exit(0);
}
const selected = args.length ? TESTS.filter((t) => args.some((a) => t.name === a || t.name.startsWith(`${a}_`))) : TESTS;
if (selected.length === 0) {
  console.error(`no test matches ${args.join(' ')}; tests: ${TESTS.map((t) => t.name).join(', ')}`);
  process.exit(1);
}
if (!existsSync(join(dist, 'index.html'))) {
  console.error(`web tests: ${dist} holds no built pages; run \`npm run build\` in web/ first`);
  process.exit(1);
}
const chromiumPath = process.env.CHROMIUM_PATH ?? '/usr/bin/chromium';
if (!existsSync(chromiumPath)) {
  console.error(`web tests: no chromium at ${chromiumPath}; install Debian's (apt-get install chromium) or set CHROMIUM_PATH`);
  process.exit(1);
}
mkdirSync(outDir, { recursive: true });

// ---- the native reference: one long-running process, one JSON line per query line ----------
let reference = null;
function startReference() {
  if (!referencePath) return null;
  const child = spawn(referencePath, [], { stdio: ['pipe', 'pipe', 'inherit'] });
  let buffer = '';
  const waiting = [];
  child.stdout.setEncoding('utf8');
  child.stdin.on('error', () => {}); // a dead reference is reported by 'exit' below
  child.stdout.on('data', (chunk) => {
    buffer += chunk;
    let nl;
    while ((nl = buffer.indexOf('\n')) >= 0) {
      const line = buffer.slice(0, nl);
      buffer = buffer.slice(nl + 1);
      waiting.shift()?.resolve(JSON.parse(line));
    }
  });
  let exited = null;
  child.on('exit', (code, signal) => {
    exited = new Error(`the reference program ${referencePath} exited (${signal ?? code})`);
    for (const w of waiting.splice(0)) w.reject(exited);
  });
  child.on('error', (err) => {
    exited = err;
    for (const w of waiting.splice(0)) w.reject(err);
  });
  return {
    query(line) {
      return new Promise((resolve, reject) => {
        if (exited) {
          reject(exited);
          return;
        }
        waiting.push({ resolve, reject });
        child.stdin.write(`${line}\n`);
      });
    },
    close() { child.stdin.end(); },
  };
}
reference = startReference();

const { server, url } = await startServer({ port: 0, root: dist });
const browser = await chromium.launch({
  executablePath: chromiumPath,
  headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage'],
});

let failed = 0;
let passed = 0;
let pending = 0;
for (const test of selected) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 760 }, deviceScaleFactor: 1 });
  const page = await context.newPage();
  const errors = [];
  page.on('console', (msg) => { if (msg.type() === 'error') errors.push(`console: ${msg.text()}`); });
  page.on('pageerror', (err) => errors.push(`page error: ${err.message}`));
  const started = performance.now();
  try {
    await test.run({
      page,
      url,
      errors,
      reference,
      screenshot: async (name) => {
        await page.screenshot({ path: join(outDir, name) });
      },
    });
    if (errors.length) throw new Error(`console errors:\n  ${errors.join('\n  ')}`);
    passed++;
    console.log(`PASS ${test.name} (${Math.round(performance.now() - started)} ms)`);
  } catch (err) {
    if (err instanceof Pending) {
      pending++;
      console.log(`PENDING ${test.name}: ${err.message}`);
    } else {
      failed++;
      console.log(`FAIL ${test.name}: ${err.stack ?? err}`);
    }
  }
  await context.close();
}
await browser.close();
server.close();
reference?.close();
console.log(`web tests: ${passed} passed, ${failed} failed, ${pending} pending (screenshots in ${outDir})`);
process.exit(failed ? 1 : passed === 0 && pending > 0 ? 77 : 0);
