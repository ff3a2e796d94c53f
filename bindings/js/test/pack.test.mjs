// `npm pack` makes an installable package: install the tarball into an empty folder and import
// it from node, as the C package test does for CMake and pkg-config.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, writeFileSync, existsSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

const pkg = fileURLToPath(new URL('..', import.meta.url));
const npm = process.platform === 'win32' ? 'npm.cmd' : 'npm';

test('npm pack, install the tarball into an empty folder, import it from node', () => {
  const dir = mkdtempSync(join(tmpdir(), 'collide-pack-'));
  try {
    const info = JSON.parse(execFileSync(npm, ['pack', '--json', '--pack-destination', dir], { cwd: pkg }).toString());
    const files = info[0].files.map((f) => f.path).sort();
    for (const f of ['index.js', 'index.d.ts', 'dist/collide-simd.wasm', 'dist/collide.wasm', 'lib/wasm.js', 'package.json']) {
      assert.ok(files.includes(f), `${f} is in the package (files: ${files.join(', ')})`);
    }
    assert.ok(!files.some((f) => f.startsWith('test/') || f.startsWith('src/') || f.startsWith('node_modules/')), 'no tests, C sources or node_modules');
    const app = join(dir, 'app');
    execFileSync('mkdir', ['-p', app]);
    writeFileSync(join(app, 'package.json'), JSON.stringify({ name: 'app', version: '1.0.0', type: 'module', private: true }));
    execFileSync(npm, ['install', '--no-audit', '--no-fund', '--offline', join(dir, info[0].filename)], { cwd: app, stdio: 'pipe' });
    assert.ok(existsSync(join(app, 'node_modules', 'collide', 'index.d.ts')));
    writeFileSync(join(app, 'main.mjs'), `
      import { init, overlap2, circle, intersectAABB, BroadPhase3, simdSupported } from 'collide';
      await init();
      const bp = new BroadPhase3();
      bp.createProxy([0, 0, 0, 1, 1, 1]); bp.createProxy([0.5, 0.5, 0.5, 2, 2, 2]);
      console.log(JSON.stringify({
        overlap: overlap2(circle({ x: 0, y: 0 }, 1), circle({ x: 1.5, y: 0 }, 1)),
        texts: intersectAABB({ minX: 0, maxX: 1, minY: 0, maxY: 1, minZ: 0, maxZ: 1 }, { minX: 2, maxX: 3, minY: 0, maxY: 1, minZ: 0, maxZ: 1 }),
        pairs: Array.from(bp.updatePairs()), simd: simdSupported(),
      }));
      bp.destroy();
    `);
    const out = JSON.parse(execFileSync(process.execPath, ['main.mjs'], { cwd: app }).toString());
    assert.deepEqual(out, { overlap: true, texts: false, pairs: [0, 1], simd: true });
    // The scalar build is in the package too.
    const scalar = execFileSync(process.execPath, ['--input-type=module', '-e',
      "import { init, overlap2, circle } from 'collide'; await init({ simd: false }); console.log(overlap2(circle({x:0,y:0},1), circle({x:2,y:0},1)))"], { cwd: app }).toString().trim();
    assert.equal(scalar, 'true');
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
