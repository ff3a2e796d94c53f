// Every query of the API against the native C library's answer on the same inputs
// (test/oracle.c, compiled natively in this test): 400 random 2D pairs, 300 random 3D pairs
// (every shape kind, hulls included), the batch queries and the broadphase structures.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import * as c from 'collide';
import { runOracle } from './oracle.mjs';

let oracle;
before(async () => {
  await c.init();
  oracle = runOracle();
});

// Same float math on both sides; the only differences come from libm (cosf/sinf of box angles,
// musl in wasm against glibc natively), so numbers agree to a few float ulps of the scene size.
const TOL = 2e-4;
function near(actual, expected, what, tol = TOL) {
  if (typeof expected === 'number') {
    assert.ok(Math.abs(actual - expected) <= tol * Math.max(1, Math.abs(expected)),
      `${what}: ${actual} vs C ${expected}`);
  } else if (expected && typeof expected === 'object') {
    for (const k of Object.keys(expected)) near(actual[k], expected[k], `${what}.${k}`, tol);
  } else {
    assert.equal(actual, expected, what);
  }
}

const hulls = new Map();
function shape3(s) {
  if (s.type !== 'hull') return s;
  const key = s.hullPoints.join(',');
  if (!hulls.has(key)) hulls.set(key, c.Hull.fromPoints(new Float32Array(s.hullPoints)));
  return { type: 'hull', hull: hulls.get(key), position: s.position, rotation: s.rotation };
}

test('2D queries agree with the C library (400 random pairs of every shape kind)', () => {
  let hits = 0, manifoldPoints = 0;
  for (const [i, k] of oracle.cases2.entries()) {
    const w = `case2 ${i} (${k.a.type}/${k.b.type})`;
    assert.equal(c.overlap2(k.a, k.b), k.overlap, `${w} overlap`);
    assert.equal(c.containsPoint2(k.a, k.p), k.contains, `${w} contains`);
    near(c.closestPoint2(k.a, k.p), k.closest, `${w} closest`);
    const hit = c.raycast2(k.a, k.ray);
    if (k.ray_hit === null) assert.equal(hit, null, `${w} ray`);
    else { near(hit, k.ray_hit, `${w} ray`); hits++; }
    near(c.distance2(k.a, k.b), k.distance, `${w} distance`);
    const m = c.manifold2(k.a, k.b, 0.05);
    assert.equal(m.points.length, k.manifold.points.length, `${w} manifold point count`);
    near(m, k.manifold, `${w} manifold`);
    manifoldPoints += m.points.length;
    near(c.shapeCast2(k.a, k.b, k.translation), k.cast, `${w} shape cast`, 1e-3);
    const toi = c.timeOfImpact2(k.a, { center0: { x: -4, y: 0 }, center1: { x: 4, y: 0.5 }, angle0: 0, angle1: k.toi.angle1 },
      k.b, { center0: { x: 0, y: 0 } }, { targetSeparation: 0.005, tolerance: 0.00125 });
    assert.equal(toi.state, ['hit', 'separated', 'overlapped', 'failed'][k.toi.state], `${w} toi state`);
    near(toi.t, k.toi.t, `${w} toi t`, 1e-3);
    near(c.computeAabb2(k.a), k.aabb, `${w} aabb`);
    near(c.computeMass2(k.a, 2), k.mass, `${w} mass`, 1e-3);
  }
  // The sample must exercise both answers of each query.
  assert.ok(oracle.cases2.some((k) => k.overlap) && oracle.cases2.some((k) => !k.overlap));
  assert.ok(hits > 20 && manifoldPoints > 50, `ray hits ${hits}, manifold points ${manifoldPoints}`);
});

test('3D queries agree with the C library (300 random pairs, hulls included)', () => {
  let hullCases = 0, manifoldPoints = 0;
  for (const [i, k] of oracle.cases3.entries()) {
    const a = shape3(k.a), b = shape3(k.b);
    const w = `case3 ${i} (${k.a.type}/${k.b.type})`;
    if (a.type === 'hull' || b.type === 'hull') hullCases++;
    assert.equal(c.overlap3(a, b), k.overlap, `${w} overlap`);
    assert.equal(c.containsPoint3(a, k.p), k.contains, `${w} contains`);
    near(c.closestPoint3(a, k.p), k.closest, `${w} closest`);
    const hit = c.raycast3(a, k.ray);
    if (k.ray_hit === null) assert.equal(hit, null, `${w} ray`);
    else near(hit, k.ray_hit, `${w} ray`);
    near(c.distance3(a, b), k.distance, `${w} distance`);
    if (a.type === 'segment' || b.type === 'segment') {
      assert.equal(k.manifold.points.length, 0, 'cd3Collide has no segment pairs');
      assert.throws(() => c.manifold3(a, b, 0.05), RangeError);
    } else {
      const m = c.manifold3(a, b, 0.05);
      assert.equal(m.points.length, k.manifold.points.length, `${w} manifold point count`);
      near(m, k.manifold, `${w} manifold`, 1e-3);
      manifoldPoints += m.points.length;
    }
    near(c.shapeCast3(a, b, k.translation), k.cast, `${w} shape cast`, 1e-3);
    const toi = c.timeOfImpact3(a, { center0: { x: -4, y: 0, z: 0 }, center1: { x: 4, y: 0.5, z: 0 }, rotation1: k.toi.rotation1 },
      b, { center0: { x: 0, y: 0, z: 0 } });
    assert.equal(toi.state, ['hit', 'separated', 'overlapped', 'failed'][k.toi.state], `${w} toi state`);
    near(toi.t, k.toi.t, `${w} toi t`, 1e-3);
    near(c.computeAabb3(a), k.aabb, `${w} aabb`);
    if (k.mass) near(c.computeMass3(a, 2), k.mass, `${w} mass`, 1e-3);
    else assert.throws(() => c.computeMass3(a, 2), RangeError);
  }
  assert.ok(hullCases > 50 && manifoldPoints > 30, `hull cases ${hullCases}, manifold points ${manifoldPoints}`);
  for (const h of hulls.values()) h.destroy();
});

test('batch queries agree with the C library, from typed arrays and from arrays of objects', () => {
  const B = oracle.batch;
  const boxes = new Float32Array(B.boxes), spheres = new Float32Array(B.spheres), points = new Float32Array(B.points);
  const boxObjs = [], sphereObjs = [], pointObjs = [];
  for (let i = 0; i < boxes.length / 6; i++) {
    const [minX, minY, minZ, maxX, maxY, maxZ] = boxes.subarray(6 * i, 6 * i + 6);
    boxObjs.push({ minX, maxX, minY, maxY, minZ, maxZ });
    const [x, y, z, radius] = spheres.subarray(4 * i, 4 * i + 4);
    sphereObjs.push({ x, y, z, radius });
    pointObjs.push({ x: points[3 * i], y: points[3 * i + 1], z: points[3 * i + 2] });
  }
  const qb = B.queryBox, qs = B.querySphere;
  const cases = [
    ['pointsInsideAABB', points, pointObjs, qb], ['pointsInsideSphere', points, pointObjs, qs],
    ['aabbsIntersectAABB', boxes, boxObjs, qb], ['aabbsIntersectSphere', boxes, boxObjs, qs],
    ['spheresIntersectSphere', spheres, sphereObjs, qs], ['spheresIntersectAABB', spheres, sphereObjs, qb],
  ];
  for (const [name, packed, objs, q] of cases) {
    assert.ok(B[name].length > 5 && B[name].length < 495, `${name}: a sample with hits and misses`);
    assert.deepEqual(Array.from(c[name](packed, q)), B[name], `${name} (packed)`);
    assert.deepEqual(Array.from(c[name](objs, q)), B[name], `${name} (objects)`);
  }
  // The single tests give the same answers as the batch.
  const single = pointObjs.flatMap((p, i) => (c.isPointInsideAABB(p, qb) ? [i] : []));
  assert.deepEqual(single, B.pointsInsideAABB);
  assert.deepEqual(sphereObjs.flatMap((s, i) => (c.intersectSphere(s, qs) ? [i] : [])), B.spheresIntersectSphere);
  assert.deepEqual(sphereObjs.flatMap((s, i) => (c.intersectSphereAABB(s, qb) ? [i] : [])), B.spheresIntersectAABB);
  assert.deepEqual(boxObjs.flatMap((b, i) => (c.intersectAABB(b, qb) ? [i] : [])), B.aabbsIntersectAABB);
  assert.deepEqual(pointObjs.flatMap((p, i) => (c.isPointInsideSphere(p, qs) ? [i] : [])), B.pointsInsideSphere);
});

test('every broadphase structure reports the C library\'s pairs and query hits, frame after frame', () => {
  const { boxes, n, frames, runs } = oracle.broad;
  const all = new Float32Array(boxes);
  for (const run of runs) {
    const bp = new c.BroadPhase3({ type: c.BROADPHASE_TYPES[run.type] });
    const ids = new Int32Array(n);
    for (let i = 0; i < n; i++) ids[i] = bp.createProxy(all.subarray(6 * i, 6 * i + 6));
    for (let f = 0; f < frames; f++) {
      if (f > 0) bp.moveProxies(ids, all.subarray(6 * n * f, 6 * n * (f + 1)));
      const expected = run.frames[f];
      assert.deepEqual(Array.from(bp.updatePairs()), expected.pairs, `${bp.type} frame ${f} updatePairs`);
      assert.deepEqual(Array.from(bp.findAllPairs()), expected.all, `${bp.type} frame ${f} findAllPairs`);
      const q = Array.from(bp.query({ min: { x: -5, y: -5, z: -5 }, max: { x: 5, y: 5, z: 5 } })).sort((a, b) => a - b);
      assert.deepEqual(q, [...expected.query].sort((a, b) => a - b), `${bp.type} frame ${f} query`);
      assert.ok(expected.pairs.length > 0, 'the scene has pairs');
    }
    assert.equal(bp.validate(), true);
    bp.destroy();
  }
});
