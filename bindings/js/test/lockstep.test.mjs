// One simulation, two machines: the falling pyramid (test/world2_lockstep.c) run natively and on
// the wasm build through World2 must give the same bits for every body's state after every step
// (both builds use float, no fused multiply-add, and the same scalar code paths).
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import * as c from 'collide';
import { nativeProgram } from './native.mjs';
import { runWasm, STEPS, BASE, DROP } from './lockstep_scene.mjs';


before(async () => { await c.init(); });

test('the falling pyramid gives the same bits natively and in wasm, step after step', () => {
  const exe = nativeProgram('world2_lockstep.c', 'COLLIDE_WORLD2_LOCKSTEP');
  const native = execFileSync(exe, [String(STEPS), String(BASE), String(DROP)], { maxBuffer: 1 << 24 }).toString().trim().split('\n');
  assert.equal(native.length, STEPS);
  const { hashes, top } = runWasm(c);
  const first = hashes.findIndex((h, k) => h !== native[k]);
  assert.equal(first, -1, `states differ from step ${first + 1} on (wasm ${hashes[first]}, native ${native[first]})`);
  // The scene is not trivial: the pyramid fell 1 m, landed and still stands 20 rows high (the
  // landing shifts the upper rows sideways by most of a box: top x is about 0.8).
  assert.ok(new Set(hashes).size > STEPS / 2, 'the states change from step to step');
  assert.ok(Math.abs(top.x) < 1 && Math.abs(top.y - (BASE - 0.5)) < 0.1, `top box at (${top.x}, ${top.y})`);
});

test('the scalar wasm build (engines without wasm SIMD) gives the same bits as the native build', () => {
  const exe = nativeProgram('world2_lockstep.c', 'COLLIDE_WORLD2_LOCKSTEP');
  const native = execFileSync(exe, [String(STEPS), String(BASE), String(DROP)], { maxBuffer: 1 << 24 }).toString().trim().split('\n');
  const script = `import * as c from 'collide'; import { runWasm } from './test/lockstep_scene.mjs';
await c.init({ simd: false }); const r = runWasm(c); console.log(JSON.stringify({ simd: c.isSimdBuild(), hashes: r.hashes }));`;
  const out = JSON.parse(execFileSync(process.execPath, ['--input-type=module', '-e', script],
    { cwd: new URL('..', import.meta.url).pathname, maxBuffer: 1 << 24 }).toString());
  assert.equal(out.simd, false);
  const first = out.hashes.findIndex((h, k) => h !== native[k]);
  assert.equal(first, -1, `scalar build differs from step ${first + 1} on`);
});
