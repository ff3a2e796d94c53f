// Exact cases: the texts' tests and the canvas helpers on hand-checked inputs (touching counts),
// builders, hulls, wasm-resident arrays, the 2D broadphase against brute force, the scalar build
// against the SIMD build, and the FinalizationRegistry's warning.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync, spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import * as c from 'collide';

before(() => c.init());

test('the texts\' 3D tests: inside, touching and outside', () => {
  const box = { minX: 0, maxX: 1, minY: 0, maxY: 2, minZ: -1, maxZ: 1 };
  assert.equal(c.isPointInsideAABB({ x: 0.5, y: 1, z: 0 }, box), true);
  assert.equal(c.isPointInsideAABB({ x: 1, y: 2, z: 1 }, box), true, 'a corner touches');
  assert.equal(c.isPointInsideAABB({ x: 1.001, y: 1, z: 0 }, box), false);
  assert.equal(c.intersectAABB(box, { minX: 1, maxX: 3, minY: 2, maxY: 3, minZ: 1, maxZ: 2 }), true, 'touching at a corner');
  assert.equal(c.intersectAABB(box, { minX: 1.01, maxX: 3, minY: 0, maxY: 3, minZ: 0, maxZ: 2 }), false);
  const s = { x: 0, y: 0, z: 0, radius: 2 };
  assert.equal(c.isPointInsideSphere({ x: 0, y: 2, z: 0 }, s), true, 'on the surface');
  assert.equal(c.isPointInsideSphere({ x: 1.5, y: 1.5, z: 0 }, s), false);
  assert.equal(c.intersectSphere(s, { x: 3, y: 0, z: 0, radius: 1 }), true, 'tangent spheres');
  assert.equal(c.intersectSphere(s, { x: 3.01, y: 0, z: 0, radius: 1 }), false);
  assert.equal(c.intersectSphereAABB({ x: -1, y: 1, z: 0, radius: 1 }, box), true, 'sphere touching a face');
  assert.equal(c.intersectSphereAABB({ x: 2, y: 3, z: 0, radius: 1.4 }, box), false, 'near a corner but apart (distance sqrt 2)');
  assert.equal(c.intersectSphereAABB({ x: 2, y: 3, z: 0, radius: 1.415 }, box), true);
});

test('canvas rectangles (y down), circles and polygons', () => {
  const a = { x: 10, y: 20, width: 30, height: 40 };
  assert.deepEqual(c.rectToAabb(a), { type: 'aabb', min: { x: 10, y: 20 }, max: { x: 40, y: 60 } });
  assert.deepEqual(c.aabbToRect(c.rectToAabb(a)), a);
  assert.deepEqual(c.rectToBox(a, 0.5), { type: 'box', center: { x: 25, y: 40 }, halfExtents: { x: 15, y: 20 }, angle: 0.5 });
  assert.equal(c.intersectRect(a, { x: 40, y: 60, width: 5, height: 5 }), true, 'corner to corner');
  assert.equal(c.intersectRect(a, { x: 40.5, y: 20, width: 5, height: 5 }), false);
  assert.equal(c.isPointInsideRect({ x: 10, y: 60 }, a), true);
  assert.equal(c.isPointInsideRect({ x: 9, y: 30 }, a), false);
  assert.equal(c.intersectCircle({ x: 0, y: 0, radius: 5 }, { x: 6, y: 8, radius: 5 }), true, 'tangent (distance 10)');
  assert.equal(c.intersectCircle({ x: 0, y: 0, radius: 5 }, { x: 6, y: 8, radius: 4.9 }), false);
  const tri = [{ x: 0, y: 0 }, { x: 4, y: 0 }, { x: 0, y: 4 }];
  assert.equal(c.intersectPolygon(tri, [{ x: 2, y: 2 }, { x: 5, y: 2 }, { x: 5, y: 5 }, { x: 2, y: 5 }]), true, 'corner on the hypotenuse');
  assert.equal(c.intersectPolygon(tri, [{ x: 2.1, y: 2.1 }, { x: 5, y: 2.1 }, { x: 5, y: 5 }, { x: 2.1, y: 5 }]), false);
  // A rect turned by 45 degrees about its centre reaches sqrt(2) * 5 from it.
  const turned = c.rectToBox({ x: 0, y: 0, width: 10, height: 10 }, Math.PI / 4);
  assert.equal(c.containsPoint2(turned, { x: 5, y: 5 - 5 * Math.SQRT2 + 0.01 }), true);
  assert.equal(c.containsPoint2(turned, { x: 0.2, y: 0.2 }), false);
  // 2D batch forms agree with the single tests.
  const rects = [a, { x: 0, y: 0, width: 5, height: 5 }, { x: 39, y: 59, width: 1, height: 1 }, { x: 100, y: 0, width: 1, height: 1 }];
  const q = { x: 5, y: 20, width: 34, height: 1 };
  assert.deepEqual(Array.from(c.rectsIntersectRect(rects, q)), [0]);
  assert.deepEqual(Array.from(c.rectsIntersectRect(new Float32Array(rects.flatMap((r) => [r.x, r.y, r.x + r.width, r.y + r.height])), a)), [0, 2]);
  assert.deepEqual(Array.from(c.pointsInsideRect([{ x: 10, y: 20 }, { x: 0, y: 0 }, { x: 40, y: 60 }], a)), [0, 2]);
  const circles = [{ x: 0, y: 0, radius: 1 }, { x: 3, y: 4, radius: 4 }, { x: 3, y: 4, radius: 3.9 }];
  assert.deepEqual(Array.from(c.circlesIntersectCircle(circles, { x: 0, y: 0, radius: 1 })), [0, 1]);
  assert.deepEqual(Array.from(c.pointsInsideCircle([{ x: 3, y: 4 }, { x: 3, y: 4.01 }], { x: 0, y: 0, radius: 5 })), [0]);
  assert.deepEqual(Array.from(c.circlesIntersectRect(circles, { x: 1, y: -1, width: 1, height: 1 })), [0], 'the first touches at (1, 0); the others are 4.12 away');
  assert.deepEqual(Array.from(c.rectsIntersectCircle(rects, { x: 5, y: 0, radius: 5 })), [1]);
});

test('polygon builder, shape factories and hulls', () => {
  const p = c.polygon([{ x: 0, y: 0 }, { x: 2, y: 0 }, { x: 2, y: 2 }, { x: 0, y: 2 }, { x: 1, y: 1 }]);
  assert.equal(p.vertices.length, 4, 'the interior point is not a vertex');
  assert.deepEqual(p.centroid, { x: 1, y: 1 });
  assert.equal(c.computeMass2(p, 3).mass, 12);
  const rounded = c.polygon([{ x: 0, y: 0 }, { x: 2, y: 0 }, { x: 0, y: 2 }], 0.5);
  assert.equal(rounded.radius, 0.5);
  assert.equal(c.containsPoint2(rounded, { x: -0.49, y: 0 }), true);
  assert.equal(c.overlap2(p, c.circle({ x: 3, y: 1 }, 1)), true);
  assert.deepEqual(c.computeAabb2(c.capsule2({ x: 0, y: 0 }, { x: 2, y: 0 }, 1)), { min: { x: -1, y: -1 }, max: { x: 3, y: 1 } });
  assert.deepEqual(c.closestPoint2(c.segment2({ x: 0, y: 0 }, { x: 4, y: 0 }), { x: 1, y: 3 }), { x: 1, y: 0 });
  assert.deepEqual(c.computeAabb2(c.aabb2({ x: -1, y: -2 }, { x: 3, y: 4 })), { min: { x: -1, y: -2 }, max: { x: 3, y: 4 } });

  const cube = c.Hull.box({ x: 1, y: 1, z: 1 });
  assert.equal(cube.vertexCount, 8);
  assert.equal(cube.faceCount, 6);
  assert.equal(cube.volume, 8);
  assert.deepEqual(cube.bounds, { min: { x: -1, y: -1, z: -1 }, max: { x: 1, y: 1, z: 1 } });
  assert.equal(cube.vertices.length, 24);
  assert.ok(cube.vertices.every((x) => Math.abs(x) === 1));
  const placed = c.hullShape(cube, { x: 5, y: 0, z: 0 }, { x: 0, y: 0, z: Math.SQRT1_2, w: Math.SQRT1_2 });
  assert.equal(c.containsPoint3(placed, { x: 6, y: 1, z: 1 }), true);
  assert.equal(c.containsPoint3(placed, { x: 6.01, y: 0, z: 0 }), false);
  const hit = c.raycast3(placed, { origin: { x: 0, y: 0, z: 0 }, translation: { x: 10, y: 0, z: 0 } });
  assert.ok(Math.abs(hit.fraction - 0.4) < 1e-6 && hit.normal.x < -0.999999);
  const cyl = c.Hull.cylinder(1, 1, 32);
  assert.ok(Math.abs(cyl.volume - 2 * 32 / 2 * Math.sin(2 * Math.PI / 32)) < 1e-4, `cylinder volume ${cyl.volume}`);
  const cone = c.Hull.cone(1, 1, 8);
  assert.equal(cone.vertexCount, 9);
  const m = c.computeMass3(c.hullShape(cube), 1);
  assert.equal(m.mass, 8);
  assert.ok(Math.abs(m.inertia[0] - 8 * 2 / 3 * 2 / 2) < 1e-5, `inertia ${m.inertia[0]}`);
  for (const h of [cube, cyl, cone]) h.destroy();
  // Plane: solid below.
  const ground = c.plane({ x: 0, y: 1, z: 0 }, 0);
  assert.equal(c.overlap3(ground, c.sphere({ x: 0, y: 1, z: 0 }, 1)), true);
  assert.equal(c.overlap3(ground, c.sphere({ x: 0, y: 1.01, z: 0 }, 1)), false);
  const d = c.distance3(ground, c.sphere({ x: 0, y: 1.5, z: 0 }, 1));
  assert.ok(Math.abs(d.distance - 0.5) < 1e-6);
  // cd3Collide has no plane or segment pairs: the JS API says so instead of returning nothing.
  assert.throws(() => c.manifold3(c.sphere({ x: 0, y: 0.9, z: 0 }, 1), ground), /^RangeError: manifold3 has no contact manifold for planes and segments/);
});

test('manifolds, casts and time of impact on hand-checked poses', () => {
  const m = c.manifold2(c.box2({ x: 0, y: 0 }, { x: 1, y: 1 }), c.box2({ x: 0, y: 1.9 }, { x: 1, y: 1 }));
  assert.equal(m.points.length, 2);
  assert.ok(m.normal.x === 0 && m.normal.y === 1, JSON.stringify(m.normal));
  for (const p of m.points) assert.ok(Math.abs(p.separation + 0.1) < 1e-6);
  const cast = c.shapeCast3(c.sphere({ x: -5, y: 0, z: 0 }, 1), c.aabb3({ x: -1, y: -1, z: -1 }, { x: 1, y: 1, z: 1 }), { x: 10, y: 0, z: 0 });
  assert.equal(cast.hit, true);
  assert.ok(Math.abs(cast.fraction - 0.3) < 1e-3);
  const toi = c.timeOfImpact3(c.sphere({ x: 0, y: 0, z: 0 }, 0.5), { center0: { x: -5, y: 0, z: 0 }, center1: { x: 5, y: 0, z: 0 } },
    c.sphere({ x: 0, y: 0, z: 0 }, 0.5), { center0: { x: 0, y: 0, z: 0 } }, { targetSeparation: 0, tolerance: 1e-4 });
  assert.equal(toi.state, 'hit');
  assert.ok(Math.abs(toi.t - 0.4) < 1e-3, `t ${toi.t}`);
  const miss = c.timeOfImpact2(c.circle({ x: 0, y: 0 }, 0.5), { center0: { x: -5, y: 3 }, center1: { x: 5, y: 3 } },
    c.circle({ x: 0, y: 0 }, 0.5), { center0: { x: 0, y: 0 } });
  assert.equal(miss.state, 'separated');
  assert.equal(miss.t, 1);
  assert.equal(c.raycast2(c.circle({ x: 0, y: 0 }, 1), { origin: { x: -5, y: 2 }, translation: { x: 10, y: 0 } }), null);
  const d = c.distance2(c.circle({ x: 0, y: 0 }, 1), c.aabb2({ x: 3, y: -1 }, { x: 4, y: 1 }));
  assert.equal(d.distance, 2);
  assert.ok(d.pointA.x === 1 && d.pointA.y === 0 && d.pointB.x === 3 && d.pointB.y === 0, JSON.stringify(d));
});

test('the 2D broadphase matches brute force on fat boxes; WasmArray views are read in place', () => {
  let seed = 7;
  const rnd = () => ((seed = (seed * 1103515245 + 12345) >>> 0) / 4294967296);
  const n = 400;
  const boxes = new c.WasmArray('f32', 4 * n);
  const fill = () => {
    const b = boxes.array;
    for (let i = 0; i < n; i++) {
      const x = rnd() * 100, y = rnd() * 100;
      b.set([x, y, x + 1 + rnd() * 4, y + 1 + rnd() * 4], 4 * i);
    }
  };
  fill();
  for (const type of c.BROADPHASE_TYPES) {
    const bp = new c.BroadPhase2({ type, margin: 0 });
    const ids = bp.createProxies(boxes.array);
    assert.deepEqual(Array.from(ids), Array.from({ length: n }, (_, i) => i));
    const check = () => {
      const fat = Array.from({ length: n }, (_, i) => bp.getFatAabb(i));
      const expected = [];
      for (let i = 0; i < n; i++) for (let j = i + 1; j < n; j++) {
        const a = fat[i], b = fat[j];
        if (a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y) expected.push(i, j);
      }
      assert.deepEqual(Array.from(bp.findAllPairs()), expected, `${type}: all pairs`);
      const q = { min: { x: 20, y: 30 }, max: { x: 50, y: 45 } };
      const inQ = fat.flatMap((a, i) => (a.min.x <= q.max.x && q.min.x <= a.max.x && a.min.y <= q.max.y && q.min.y <= a.max.y ? [i] : []));
      assert.deepEqual(Array.from(bp.query(q)).sort((x, y) => x - y), inQ, `${type}: query`);
      const ray = bp.rayCast({ origin: { x: -1, y: 50 }, translation: { x: 102, y: 0 } });
      const crossing = fat.flatMap((a, i) => (a.min.y <= 50 && a.max.y >= 50 ? [i] : []));
      assert.deepEqual(Array.from(ray.ids).sort((x, y) => x - y), crossing, `${type}: ray`);
      for (let k = 1; k < ray.fractions.length; k++) assert.ok(ray.fractions[k - 1] <= ray.fractions[k], 'nearest first');
      return expected.length / 2;
    };
    const first = check();
    assert.equal(bp.updatePairs().length, 2 * first, 'a new proxy counts as moved');
    assert.equal(bp.updatePairs().length, 0, 'nothing moved since');
    fill();
    const changed = bp.moveProxies(ids, boxes.array);
    assert.equal(changed, n);
    check();
    assert.ok(bp.updatePairs().length > 0);
    assert.equal(bp.moveProxy(0, bp.getFatAabb(0)), false, 'a box inside its fat box changes nothing');
    // A predicted displacement stretches the fat box along it (by the multiplier, 4 by default).
    const before = bp.getFatAabb(1);
    const moved = new Float32Array([before.min.x + 30, before.min.y, before.max.x + 30, before.max.y]);
    assert.equal(bp.moveProxies(new Int32Array([1]), moved, new Float32Array([1, 0])), 1);
    const stretched = bp.getFatAabb(1);
    assert.ok(stretched.max.x >= moved[2] + 4 - 1e-4 && stretched.min.x <= moved[0] + 1e-4, JSON.stringify(stretched));
    bp.rebuild();
    check();
    assert.equal(bp.validate(), true);
    assert.equal(bp.proxyCount, n);
    assert.equal(bp.stats.proxyCount, n);
    bp.destroy();
  }
  boxes.destroy();
});

const queriesScript = `
import * as c from 'collide';
await c.init({ simd: process.argv[2] === 'simd' });
if (c.isSimdBuild() !== (process.argv[2] === 'simd')) throw new Error('wrong build loaded');
const out = [];
let s = 1;
const r = () => ((s = (s * 16807) % 2147483647) / 2147483647) * 4 - 2;
for (let i = 0; i < 200; i++) {
  const a = c.box3({ x: r(), y: r(), z: r() }, { x: 1, y: 0.5, z: 0.7 }, { x: 0, y: Math.sin(i), z: 0, w: Math.cos(i) });
  const b = c.capsule3({ x: r(), y: r(), z: r() }, { x: r(), y: r(), z: r() }, 0.3);
  const p = c.polygon([{ x: r(), y: r() }, { x: r() + 3, y: r() }, { x: r(), y: r() + 3 }]);
  out.push(c.overlap3(a, b), c.distance3(a, b).distance, c.manifold3(a, b, 0.1), c.manifold2(p, c.box2({ x: 0, y: 0 }, { x: 1, y: 1 }, i)));
}
console.log(JSON.stringify(out));
`;

test('the scalar build gives the same answers as the SIMD build', () => {
  const cwd = fileURLToPath(new URL('..', import.meta.url));
  const run = (mode) => execFileSync(process.execPath, ['--input-type=module', '-e', queriesScript, mode], { cwd }).toString();
  const simd = JSON.parse(run('simd')), scalar = JSON.parse(run('scalar'));
  assert.equal(simd.length, 800);
  assert.deepEqual(scalar, simd);
});

test('an object dropped without destroy() gets a warning from the FinalizationRegistry, and destroy() prevents it', () => {
  const cwd = fileURLToPath(new URL('..', import.meta.url));
  const script = (destroy) => `
import * as c from 'collide';
await c.init();
(() => { const h = c.Hull.box({ x: 1, y: 1, z: 1 }); const b = new c.BroadPhase2(); ${destroy ? 'h.destroy(); b.destroy();' : ''} })();
for (let i = 0; i < 5; i++) { globalThis.gc(); await new Promise((r) => setTimeout(r, 20)); }
`;
  const leaked = spawnSync(process.execPath, ['--expose-gc', '--input-type=module', '-e', script(false)], { cwd }).stderr.toString();
  assert.match(leaked, /a Hull was garbage-collected without destroy\(\)/);
  assert.match(leaked, /a BroadPhase2 was garbage-collected without destroy\(\)/);
  const clean = spawnSync(process.execPath, ['--expose-gc', '--input-type=module', '-e', script(true)], { cwd }).stderr.toString();
  assert.equal(clean, '');
});

test('init() takes the wasm as bytes, as a path or as a compiled module', () => {
  const cwd = fileURLToPath(new URL('..', import.meta.url));
  const script = `
import { readFileSync } from 'node:fs';
import * as c from 'collide';
const how = process.argv[1];
const file = how.endsWith('scalar') ? 'dist/collide.wasm' : 'dist/collide-simd.wasm';
const wasm = how.startsWith('bytes') ? readFileSync(file) : how.startsWith('module') ? new WebAssembly.Module(readFileSync(file)) : file;
await c.init({ wasm });
console.log(JSON.stringify([c.isSimdBuild(), c.overlap2(c.circle({ x: 0, y: 0 }, 1), c.circle({ x: 2, y: 0 }, 1))]));
`;
  for (const how of ['bytes-scalar', 'bytes-simd', 'path-scalar', 'module-simd']) {
    const out = execFileSync(process.execPath, ['--input-type=module', '-e', script, how], { cwd }).toString();
    assert.deepEqual(JSON.parse(out), [how.endsWith('simd'), true], how);
  }
});
