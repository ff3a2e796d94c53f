// Bad input from JavaScript: each throws a TypeError or RangeError naming the argument, and the
// module keeps working (and answering correctly) afterwards. Destroyed objects and stale ids.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import * as c from 'collide';

before(() => c.init());

const unit = () => c.circle({ x: 0, y: 0 }, 1);
const ball = () => c.sphere({ x: 0, y: 0, z: 0 }, 1);

function throwsNamed(fn, Type, pattern) {
  assert.throws(fn, (e) => {
    assert.ok(e instanceof Type, `expected ${Type.name}, got ${e?.constructor?.name}: ${e?.message}`);
    assert.match(e.message, pattern);
    return true;
  });
}

test('calling before init() is an Error that says to await init()', async () => {
  const fresh = await import(`../lib/wasm.js?fresh=${Date.now()}`);
  assert.throws(() => fresh.requireInit(), /await init\(\)/);
});

test('wrong types are TypeErrors naming the argument and field', async () => {
  await assert.rejects(c.init('fast'), /^TypeError: options must be an object, got string/);
  throwsNamed(() => c.overlap2(null, unit()), TypeError, /^a must be an object/);
  throwsNamed(() => c.overlap2(unit(), { type: 'circle', center: { x: 0, y: '1' }, radius: 1 }), TypeError, /^b\.center\.y must be a number, got the string "1"/);
  throwsNamed(() => c.overlap2(unit(), { type: 'circle', radius: 1 }), TypeError, /^b\.center must be an object, got undefined \(missing\)/);
  throwsNamed(() => c.overlap2({ type: 'sphere', center: { x: 0, y: 0, z: 0 }, radius: 1 }, unit()), TypeError, /^a\.type must be one of 'circle'/);
  throwsNamed(() => c.overlap3(ball(), { type: 'hull', hull: {} }), TypeError, /^b\.hull must be a Hull/);
  throwsNamed(() => c.raycast2(unit(), { origin: { x: 0, y: 0 } }), TypeError, /^ray\.translation must be an object/);
  throwsNamed(() => c.containsPoint3(ball(), [1, 2, 3]), TypeError, /^point\.x must be a number/);
  throwsNamed(() => c.isPointInsideAABB({ x: 0, y: 0, z: 0 }, { minX: 0, maxX: 1, minY: 0, maxY: 1, minZ: 0 }), TypeError, /^box\.maxZ must be a number/);
  throwsNamed(() => c.pointsInsideAABB('points', { minX: 0, maxX: 1, minY: 0, maxY: 1, minZ: 0, maxZ: 1 }), TypeError, /^points must be an array or a Float32Array/);
  throwsNamed(() => c.aabbsIntersectAABB([{ minX: 0 }], { minX: 0, maxX: 1, minY: 0, maxY: 1, minZ: 0, maxZ: 1 }), TypeError, /^boxes\[0\]\.minY must be a number, got undefined \(missing\)/);
  throwsNamed(() => c.intersectRect({ x: 0, y: 0, width: 1 }, { x: 0, y: 0, width: 1, height: 1 }), TypeError, /^a\.height must be a number/);
  throwsNamed(() => c.polygon('square'), TypeError, /^points\.vertices must be an array/);
  throwsNamed(() => new c.BroadPhase3({ type: 'bvh' }), TypeError, /^def\.type must be one of 'tree'/);
  const bp = new c.BroadPhase2();
  throwsNamed(() => bp.moveProxies([0], new Float32Array(4)), TypeError, /^ids must be an Int32Array/);
  throwsNamed(() => bp.createProxies([0, 0, 1, 1]), TypeError, /^aabbs must be a Float32Array/);
  throwsNamed(() => bp.destroyProxy('0'), TypeError, /^id must be an integer/);
  bp.destroy();
});

test('NaN, infinities, negative sizes and out-of-range values are RangeErrors naming the argument', () => {
  throwsNamed(() => c.overlap2(unit(), { type: 'circle', center: { x: NaN, y: 0 }, radius: 1 }), RangeError, /^b\.center\.x must be finite, got NaN/);
  throwsNamed(() => c.circle({ x: 0, y: 0 }, -1), RangeError, /^radius must be >= 0/);
  throwsNamed(() => c.distance3(ball(), { type: 'sphere', center: { x: 0, y: 0, z: Infinity }, radius: 1 }), RangeError, /^b\.center\.z must be finite/);
  // Finite in double, infinite in float: the library's validator catches it.
  throwsNamed(() => c.overlap3({ type: 'sphere', center: { x: 1e39, y: 0, z: 0 }, radius: 1 }, ball()), RangeError, /^a is not valid: NaN or infinite/);
  throwsNamed(() => c.box3({ x: 0, y: 0, z: 0 }, { x: 1, y: 1, z: 1 }, { x: 0, y: 0, z: 0, w: 2 }), RangeError, /^rotation must be a unit quaternion/);
  throwsNamed(() => c.plane({ x: 0, y: 2, z: 0 }, 0), RangeError, /^normal must be a unit vector/);
  throwsNamed(() => c.aabb3({ x: 1, y: 0, z: 0 }, { x: 0, y: 1, z: 1 }), RangeError, /min must not exceed max/);
  throwsNamed(() => c.polygon([{ x: 0, y: 0 }, { x: 1, y: 1 }, { x: 2, y: 2 }]), RangeError, /^points is not valid: degenerate/);
  throwsNamed(() => c.polygon([{ x: 0, y: 0 }, { x: 1, y: 0 }]), RangeError, /3 to 8 points/);
  throwsNamed(() => c.overlap2({ type: 'polygon', vertices: new Array(9).fill({ x: 0, y: 0 }) }, unit()), RangeError, /^a\.vertices must hold 3 to 8 points, got 9/);
  throwsNamed(() => c.Hull.fromPoints([{ x: 0, y: 0, z: 0 }, { x: 1, y: 0, z: 0 }, { x: 0, y: 1, z: 0 }]), RangeError, /^points is not valid: degenerate/);
  throwsNamed(() => c.Hull.fromPoints(new Float32Array(7)), RangeError, /divisible by 3/);
  throwsNamed(() => c.Hull.fromPoints(new Float64Array([0, 0, NaN])), RangeError, /^points\[2\] must be finite/);
  throwsNamed(() => c.manifold2(unit(), unit(), -1), RangeError, /^speculativeDistance must be >= 0/);
  throwsNamed(() => c.timeOfImpact2(unit(), { center0: { x: 0, y: 0 } }, unit(), { center0: { x: 3, y: 0 } }, { tolerance: 0 }), RangeError, /^options\.tolerance must be > 0/);
  throwsNamed(() => c.timeOfImpact3(ball(), { center0: { x: 0, y: 0, z: 0 }, rotation1: { x: 0, y: 0, z: 0, w: 0.5 } }, ball(), { center0: { x: 3, y: 0, z: 0 } }), RangeError, /^sweepA\.rotation1 must be a unit quaternion/);
  throwsNamed(() => c.pointsInsideSphere(new Float32Array([0, 0, 0, 1, NaN, 1]), { x: 0, y: 0, z: 0, radius: 1 }), RangeError, /^points\[1\] holds NaN/);
  throwsNamed(() => c.pointsInsideSphere(new Float32Array(4), { x: 0, y: 0, z: 0, radius: 1 }), RangeError, /multiple of 3/);
  throwsNamed(() => c.intersectRect({ x: 0, y: 0, width: -1, height: 1 }, { x: 0, y: 0, width: 1, height: 1 }), RangeError, /^a\.width must be >= 0/);
  throwsNamed(() => c.computeMass3(c.triangle({ x: 0, y: 0, z: 0 }, { x: 1, y: 0, z: 0 }, { x: 0, y: 1, z: 0 })), RangeError, /^shape is not valid/);
  throwsNamed(() => new c.BroadPhase3({ margin: -1 }), RangeError, /^def\.margin must be >= 0/);
  throwsNamed(() => new c.WasmArray('f32', -1), RangeError, /^length must be an integer/);
  const bp = new c.BroadPhase3();
  throwsNamed(() => bp.createProxy({ min: { x: 0, y: 0, z: 0 }, max: { x: NaN, y: 1, z: 1 } }), RangeError, /^aabb\.max\.x must be finite/);
  throwsNamed(() => bp.createProxy([0, 0, 0, 1, 1]), RangeError, /^aabb must hold 6 numbers/);
  throwsNamed(() => bp.moveProxies(new Int32Array(2), new Float32Array(6)), RangeError, /^aabbs must hold 6 numbers per id \(12\), got 6/);
  bp.destroy();
  // After all of that the module still answers correctly.
  assert.equal(c.overlap2(unit(), c.circle({ x: 2, y: 0 }, 1)), true);
  assert.equal(c.overlap2(unit(), c.circle({ x: 2.01, y: 0 }, 1)), false);
});

test('destroyed objects and stale ids throw; destroy() twice is harmless', () => {
  const hull = c.Hull.box({ x: 1, y: 1, z: 1 });
  const shape = c.hullShape(hull);
  assert.equal(c.overlap3(shape, ball()), true);
  hull.destroy();
  hull.destroy();
  assert.equal(hull.destroyed, true);
  throwsNamed(() => c.overlap3(shape, ball()), TypeError, /^a\.hull: this Hull was destroyed/);
  throwsNamed(() => c.manifold3(ball(), shape), TypeError, /^b\.hull: this Hull was destroyed/);
  throwsNamed(() => hull.vertices, TypeError, /destroyed/);

  const bp = new c.BroadPhase3({ type: 'sap' });
  const a = bp.createProxy([0, 0, 0, 1, 1, 1]);
  const b = bp.createProxy([0.5, 0.5, 0.5, 2, 2, 2]);
  bp.destroyProxy(a);
  assert.equal(bp.hasProxy(a), false);
  assert.equal(bp.hasProxy(b), true);
  throwsNamed(() => bp.destroyProxy(a), RangeError, new RegExp(`^id ${a} is not a live proxy`));
  throwsNamed(() => bp.moveProxy(a, [0, 0, 0, 1, 1, 1]), RangeError, /not a live proxy/);
  throwsNamed(() => bp.getFatAabb(12345), RangeError, /not a live proxy/);
  throwsNamed(() => bp.moveProxies(new Int32Array([b, 99]), new Float32Array(12)), RangeError, /^ids\[1\] = 99 is not a live proxy \(nothing was moved\)/);
  throwsNamed(() => bp.destroyProxy(-1), RangeError, /not a live proxy/);
  assert.equal(bp.validate(), true);
  bp.destroy();
  bp.destroy();
  throwsNamed(() => bp.updatePairs(), TypeError, /^broadPhase: this BroadPhase3 was destroyed/);
  throwsNamed(() => bp.proxyCount, TypeError, /destroyed/);

  const arr = new c.WasmArray('f32', 6);
  arr.destroy();
  throwsNamed(() => arr.array, TypeError, /this WasmArray was destroyed/);
});

test('a view of wasm memory detached by memory growth is refused, not read as empty', () => {
  const arr = new c.WasmArray('f32', 3);
  const view = arr.array;
  view.set([0, 0, 0]);
  // Grow wasm memory by allocating a large array.
  const big = new c.WasmArray('f32', 8 << 20);
  throwsNamed(() => c.pointsInsideSphere(view, { x: 0, y: 0, z: 0, radius: 1 }), TypeError, /detached when the memory grew/);
  assert.deepEqual(Array.from(c.pointsInsideSphere(arr.array, { x: 0, y: 0, z: 0, radius: 1 })), [0]);
  big.destroy();
  arr.destroy();
});
