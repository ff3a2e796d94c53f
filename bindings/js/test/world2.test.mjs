// World2 (the 2D world) from JavaScript: each check against an exact physical criterion (free
// fall of the sub-stepped integrator, masses, resting heights, impact speed, joint constraints,
// ray geometry), bit-identical snapshots, and bad input throwing TypeError/RangeError naming the
// argument. The bit-for-bit comparison with the native C library is test/lockstep.test.mjs.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import * as c from 'collide';

before(async () => { await c.init(); });

const DT = 1 / 60;
const unitBox = () => c.box2({ x: 0, y: 0 }, { x: 0.5, y: 0.5 });

function groundWorld(def = {}) {
  const world = new c.World2(def);
  const ground = world.createBody({ position: { x: 0, y: -1 } });
  const groundShape = ground.createShape(c.box2({ x: 0, y: 0 }, { x: 50, y: 1 }));
  return { world, ground, groundShape };
}

test('free fall follows the sub-stepped semi-implicit Euler integrator exactly', () => {
  const world = new c.World2({ gravity: { x: 0, y: -10 } });
  const b = world.createBody({ type: 'dynamic', position: { x: 1, y: 100 } });
  b.createShape(c.circle({ x: 0, y: 0 }, 0.5));
  const steps = 30, sub = 4, h = DT / sub;
  for (let i = 0; i < steps; i++) world.step(DT, sub);
  const n = steps * sub;
  // v_n = -g n h, y_n = y0 - g h^2 n (n + 1) / 2 (float rounding: a few ulps of 100 m).
  assert.ok(Math.abs(b.linearVelocity.y + 10 * n * h) < 1e-4, `vy ${b.linearVelocity.y}`);
  assert.ok(Math.abs(b.position.y - (100 - 10 * h * h * n * (n + 1) / 2)) < 2e-4, `y ${b.position.y}`);
  assert.equal(b.position.x, 1);
  world.destroy();
});

test('contactRecycleDistance: a resting stack settles with and without recycling; a negative one throws', () => {
  const tops = [];
  for (const contactRecycleDistance of [0, 0.02]) {
    const { world } = groundWorld({ enableSleep: false, contactRecycleDistance });
    let top;
    for (let i = 0; i < 5; i++) {
      top = world.createBody({ type: 'dynamic', position: { x: 0, y: 0.5 + i } });
      top.createShape(unitBox());
    }
    for (let i = 0; i < 180; i++) world.step(DT, 4);
    tops.push(top.position.y);
    assert.ok(Math.abs(top.position.y - 4.5) < 0.05, `top at ${top.position.y} with recycling ${contactRecycleDistance}`);
    world.destroy();
  }
  assert.ok(Math.abs(tops[0] - tops[1]) < 0.01, `tops ${tops}`);
  assert.throws(() => new c.World2({ contactRecycleDistance: -1 }), { name: 'RangeError', message: /contactRecycleDistance/ });
});

test('mass and inertia from the shapes', () => {
  const world = new c.World2();
  const disc = world.createBody({ type: 'dynamic' });
  disc.createShape(c.circle({ x: 0, y: 0 }, 0.5), { density: 2 });
  assert.ok(Math.abs(disc.mass - 2 * Math.PI * 0.25) < 1e-5);
  assert.ok(Math.abs(disc.inertia - 0.5 * disc.mass * 0.25) < 1e-5);
  const box = world.createBody({ type: 'dynamic' });
  box.createShape(c.box2({ x: 0, y: 0 }, { x: 1, y: 0.5 }), { density: 3 });
  assert.ok(Math.abs(box.mass - 6) < 1e-5);
  assert.ok(Math.abs(box.inertia - 6 * (4 + 1) / 12) < 1e-4);
  assert.equal(world.createBody().mass, 0);
  world.destroy();
});

test('a box comes to rest on the ground at its half height and falls asleep', () => {
  const { world } = groundWorld();
  const b = world.createBody({ type: 'dynamic', position: { x: 0, y: 2 } });
  b.createShape(unitBox());
  let asleepAt = -1;
  for (let i = 0; i < 300 && asleepAt < 0; i++) {
    world.step(DT, 4);
    if (!b.awake) asleepAt = i;
  }
  assert.ok(asleepAt > 0, 'fell asleep');
  // Resting: the box penetrates at most the linear slop (0.005 m).
  assert.ok(Math.abs(b.position.y - 0.5) < 0.006, `y ${b.position.y}`);
  assert.ok(Math.abs(b.angle) < 1e-3);
  assert.equal(world.counters.awakeBodyCount, 0);
  world.destroy();
});

test('contact begin, hit and end events name the shapes; the hit speed is sqrt(2 g h)', () => {
  const { world, groundShape } = groundWorld({ gravity: { x: 0, y: -10 } });
  const ball = world.createBody({ type: 'dynamic', position: { x: 0, y: 5.5 } });
  const s = ball.createShape(c.circle({ x: 0, y: 0 }, 0.5), { enableHitEvents: true, restitution: 0 });
  let begin = null, hit = null;
  for (let i = 0; i < 120 && (begin === null || hit === null); i++) {
    world.step(DT, 4);
    const ev = world.getEvents();
    begin ??= ev.contactBegin.find((e) => (e.shapeA === s || e.shapeB === s)) ?? null;
    hit ??= ev.hits.find((e) => (e.shapeA === s || e.shapeB === s)) ?? null;
  }
  assert.ok(begin !== null && hit !== null);
  assert.ok(begin.shapeA === groundShape || begin.shapeB === groundShape);
  // Normal from A to B, vertical; the point on the ground's surface (y = 0).
  const up = begin.shapeA === groundShape ? 1 : -1;
  assert.ok(Math.abs(begin.normal.y - up) < 1e-5 && Math.abs(begin.normal.x) < 1e-5);
  assert.equal(begin.points.length, 1);
  assert.ok(Math.abs(begin.points[0].x) < 1e-3);
  // Fall of 5 m: sqrt(2 * 10 * 5) = 10 m/s (the speculative contact begins a step early).
  assert.ok(Math.abs(hit.approachSpeed - 10) < 0.3, `speed ${hit.approachSpeed}`);
  // Lift the ball away: the contact ends.
  ball.setTransform({ x: 0, y: 10 }, 0);
  world.step(DT, 4);
  const ev = world.getEvents();
  assert.ok(ev.contactEnd.some((e) => e.shapeA === s || e.shapeB === s));
  world.destroy();
});

test('sensor events: a falling ball enters and leaves a sensor box', () => {
  const { world } = groundWorld();
  const zone = world.createBody({ position: { x: 0, y: 5 } });
  const sensor = zone.createShape(c.box2({ x: 0, y: 0 }, { x: 1, y: 0.5 }), { isSensor: true });
  const ball = world.createBody({ type: 'dynamic', position: { x: 0, y: 8 } });
  const s = ball.createShape(c.circle({ x: 0, y: 0 }, 0.25), { enableSensorEvents: true });
  let entered = -1, left = -1;
  for (let i = 0; i < 120 && left < 0; i++) {
    world.step(DT, 4);
    const ev = world.getEvents();
    if (ev.sensorBegin.some((e) => e.sensor === sensor && e.visitor === s)) entered = i;
    if (ev.sensorEnd.some((e) => e.sensor === sensor && e.visitor === s)) left = i;
  }
  assert.ok(entered > 0 && left > entered, `entered ${entered} left ${left}`);
  assert.ok(sensor.isSensor && !s.isSensor);
  world.destroy();
});

test('pre-solve callback makes a one-way platform; a custom filter lets everything through', () => {
  const { world } = groundWorld();
  const platform = world.createBody({ position: { x: 0, y: 3 } });
  const top = platform.createShape(c.box2({ x: 0, y: 0 }, { x: 2, y: 0.1 }), { enablePreSolveEvents: true });
  let calls = 0;
  world.setPreSolve((a, b, m) => {
    calls++;
    assert.ok(a === top || b === top);
    // Keep the contact only when the normal points up out of the platform towards the other shape.
    const ny = a === top ? m.normal.y : -m.normal.y;
    return ny > 0.5;
  });
  // A ball thrown up from below passes through; then it lands on top and stays there.
  const ball = world.createBody({ type: 'dynamic', position: { x: 0, y: 1 }, linearVelocity: { x: 0, y: 12 } });
  ball.createShape(c.circle({ x: 0, y: 0 }, 0.25), { enablePreSolveEvents: true });
  for (let i = 0; i < 240; i++) world.step(DT, 4);
  assert.ok(calls > 0);
  assert.ok(Math.abs(ball.position.y - 3.35) < 0.01, `ball rests on the platform at ${ball.position.y}`);
  world.setPreSolve(null);
  world.destroy();

  const g = groundWorld();
  g.world.setCustomFilter(() => false);
  const b = g.world.createBody({ type: 'dynamic', position: { x: 0, y: 2 } });
  b.createShape(unitBox());
  for (let i = 0; i < 60; i++) g.world.step(DT, 4);
  assert.ok(b.position.y < -2, 'falls through the ground');
  g.world.destroy();
});

test('joints hold: a revolute pendulum keeps its anchor, a distance joint its length', () => {
  const world = new c.World2({ gravity: { x: 0, y: -10 } });
  const pivot = world.createBody({ position: { x: 0, y: 10 } });
  const bob = world.createBody({ type: 'dynamic', position: { x: 2, y: 10 } });
  bob.createShape(c.circle({ x: 0, y: 0 }, 0.2));
  const rev = world.createJoint({ type: 'revolute', bodyA: pivot, bodyB: bob, localAnchorA: { x: 0, y: 0 }, localAnchorB: { x: -2, y: 0 } });
  const other = world.createBody({ type: 'dynamic', position: { x: 5, y: 10 } });
  other.createShape(c.circle({ x: 0, y: 0 }, 0.2));
  const anchor2 = world.createBody({ position: { x: 5, y: 13 } });
  const dist = world.createJoint({ type: 'distance', bodyA: anchor2, bodyB: other, length: 3 });
  let maxErr = 0, maxLen = 0;
  for (let i = 0; i < 120; i++) {
    world.step(DT, 4);
    const p = bob.position;
    maxErr = Math.max(maxErr, Math.abs(Math.hypot(p.x, p.y - 10) - 2));
    maxLen = Math.max(maxLen, Math.abs(dist.currentLength - 3));
  }
  assert.ok(maxErr < 0.01, `pendulum radius error ${maxErr}`);
  assert.ok(maxLen < 0.01, `distance error ${maxLen}`);
  assert.ok(bob.position.y < 10, 'the bob swung down');
  assert.equal(rev.type, 'revolute');
  assert.ok(Math.abs(rev.angle - Math.atan2(bob.transform.sin, bob.transform.cos)) < 1e-4);
  assert.ok(rev.constraintForce.y > 0, 'the pivot holds the bob up');
  assert.throws(() => dist.angle, TypeError);
  world.destroy();
});

test('joint events: a breakable joint reports a pull over its threshold and breaks when destroyed', () => {
  const world = new c.World2({ gravity: { x: 0, y: -10 }, enableSleep: false });
  const pivot = world.createBody({ position: { x: 0, y: 10 } });
  const bob = world.createBody({ type: 'dynamic', position: { x: 0, y: 9 } });
  bob.createShape(c.circle({ x: 0, y: 0 }, 0.25));
  const weight = bob.mass * 10;
  const rope = world.createJoint({ type: 'revolute', bodyA: pivot, bodyB: bob, localAnchorB: { x: 0, y: 1 }, forceThreshold: 2 * weight, userData: 'rope' });
  assert.ok(Math.abs(rope.forceThreshold - 2 * weight) < 1e-6 * weight);
  assert.equal(rope.torqueThreshold, 0);
  let quiet = 0;
  for (let i = 0; i < 60; i++) { world.step(DT, 4); quiet += world.getEvents().joints.length; }
  assert.equal(quiet, 0, 'no event while the ball hangs at rest');
  bob.applyForceToCenter({ x: 0, y: -5 * weight });
  world.step(DT, 4);
  const { joints } = world.getEvents();
  assert.equal(joints.length, 1);
  assert.equal(joints[0].joint, rope);
  assert.ok(Math.hypot(joints[0].force.x, joints[0].force.y) > 2 * weight, `force ${joints[0].force.y}`);
  joints[0].joint.destroy();
  const y0 = bob.position.y;
  for (let i = 0; i < 30; i++) world.step(DT, 4);
  assert.ok(bob.position.y < y0 - 1, 'the ball falls once the joint broke');
  const other = world.createBody({ type: 'dynamic', position: { x: 3, y: 9 } });
  other.createShape(c.circle({ x: 0, y: 0 }, 0.25));
  const j2 = world.createJoint({ type: 'weld', bodyA: pivot, bodyB: other, localAnchorA: { x: 3, y: -1 } });
  j2.torqueThreshold = 5;
  assert.equal(j2.torqueThreshold, 5);
  assert.throws(() => { j2.forceThreshold = -1; }, { name: 'RangeError', message: /forceThreshold must be >= 0/ });
  assert.throws(() => world.createJoint({ type: 'filter', bodyA: pivot, bodyB: other, forceThreshold: 1 }), TypeError);
  const filter = world.createJoint({ type: 'filter', bodyA: pivot, bodyB: other });
  assert.throws(() => { filter.torqueThreshold = 1; }, { name: 'TypeError', message: /torqueThreshold does not apply to a filter joint/ });
  world.destroy();
});

test('a joint tuned to 4 Hz sags g / (2 pi f)^2 under its load; tuning is refused where it does not apply', () => {
  const world = new c.World2({ gravity: { x: 0, y: -10 }, enableSleep: false });
  const pivot = world.createBody({ position: { x: 0, y: 0 } });
  const bob = world.createBody({ type: 'dynamic', position: { x: 0, y: -1 } });
  bob.createShape(c.circle({ x: 0, y: 0 }, 0.25));
  const j = world.createJoint({ type: 'revolute', bodyA: pivot, bodyB: bob, localAnchorB: { x: 0, y: 1 }, constraintHertz: 4, constraintDampingRatio: 1 });
  assert.equal(j.constraintHertz, 4);
  assert.equal(j.constraintDampingRatio, 1);
  for (let i = 0; i < 240; i++) world.step(DT, 4);
  const expected = 10 / (2 * Math.PI * 4) ** 2;
  const sag = -1 - bob.position.y;
  assert.ok(Math.abs(sag - expected) < 0.01 * expected, `sag ${sag}, expected ${expected}`);
  j.setConstraintTuning(0, 0);
  for (let i = 0; i < 60; i++) world.step(DT, 4);
  assert.ok(Math.abs(-1 - bob.position.y) < 1e-3, 'back to the world softness');
  assert.throws(() => j.setConstraintTuning(-1, 1), RangeError);
  assert.throws(() => world.createJoint({ type: 'motor', bodyA: pivot, bodyB: bob, constraintHertz: 5 }), TypeError);
  const motor = world.createJoint({ type: 'motor', bodyA: pivot, bodyB: bob });
  assert.throws(() => motor.setConstraintTuning(5, 1), { name: 'TypeError', message: /does not apply to a motor joint/ });
  world.destroy();
});

test('ray casts and overlap queries hit the right shapes at the right places', () => {
  const { world, groundShape } = groundWorld();
  const b = world.createBody({ position: { x: 3, y: 2 } });
  const s = b.createShape(unitBox());
  const hit = world.raycastClosest({ x: 3.2, y: 10 }, { x: 0, y: -20 });
  assert.equal(hit.shape, s);
  assert.ok(Math.abs(hit.point.y - 2.5) < 1e-5 && Math.abs(hit.point.x - 3.2) < 1e-6);
  assert.ok(Math.abs(hit.normal.y - 1) < 1e-6);
  assert.ok(Math.abs(hit.fraction - 7.5 / 20) < 1e-6);
  const all = world.raycast({ x: 3.2, y: 10 }, { x: 0, y: -20 });
  assert.deepEqual(new Set(all.map((h) => h.shape)), new Set([s, groundShape]));
  assert.equal(world.raycastClosest({ x: 3.2, y: 10 }, { x: 0, y: 1 }), null);
  assert.deepEqual(world.overlapAabb({ min: { x: 2.9, y: 1.9 }, max: { x: 3.1, y: 2.1 } }), [s]);
  assert.deepEqual(world.overlapShape(c.circle({ x: 3, y: 2.9 }, 0.5)), [s]);
  assert.deepEqual(world.overlapShape(c.circle({ x: 3, y: 3.1 }, 0.5)), []);
  // Filters: a query whose mask misses the shapes' category finds nothing.
  assert.deepEqual(world.overlapAabb({ min: { x: 2.9, y: 1.9 }, max: { x: 3.1, y: 2.1 } }, { maskBits: 2 }), []);
  const cast = world.shapeCast(c.circle({ x: 3, y: 6 }, 0.5), { x: 0, y: -6 });
  const first = cast.find((h) => h.shape === s);
  assert.ok(first && Math.abs(first.fraction - 3 / 6) < 0.01, `cast fraction ${first?.fraction}`);
  world.destroy();
});

test('getTransforms is one Float32Array view of every body, in world.bodies order', () => {
  const { world } = groundWorld();
  for (let i = 0; i < 5; i++) world.createBody({ type: 'dynamic', position: { x: i * 2, y: 3 + i }, angle: 0.1 * i }).createShape(unitBox());
  for (let i = 0; i < 10; i++) world.step(DT, 4);
  world.bodies[2].destroy();
  const t = world.getTransforms();
  assert.equal(t.length, 4 * world.bodies.length);
  assert.equal(world.bodies.length, 5);
  world.bodies.forEach((b, k) => {
    const x = b.transform;
    assert.deepEqual([t[4 * k], t[4 * k + 1], t[4 * k + 2], t[4 * k + 3]], [x.x, x.y, x.cos, x.sin]);
  });
  world.step(DT, 4);
  const t2 = world.getTransforms();
  assert.equal(t2[4 * 1 + 1], world.bodies[1].position.y);
  world.destroy();
});

test('snapshots: restoring and stepping gives the same bits; later bodies become destroyed handles', () => {
  const { world } = groundWorld();
  for (let i = 0; i < 6; i++) world.createBody({ type: 'dynamic', position: { x: 0.1 * i, y: 1 + 1.1 * i }, angle: 0.2 }).createShape(unitBox());
  for (let i = 0; i < 20; i++) world.step(DT, 4);
  const state = world.saveState();
  assert.ok(state instanceof Uint8Array && state.length > 0);
  for (let i = 0; i < 60; i++) world.step(DT, 4);
  const after = world.getStates();
  const late = world.createBody({ type: 'dynamic', position: { x: 10, y: 5 } });
  world.restoreState(state.buffer);
  assert.ok(late.destroyed);
  assert.throws(() => late.position, { name: 'TypeError', message: /position: this Body2 was destroyed/ });
  assert.equal(world.bodies.length, 7);
  for (let i = 0; i < 60; i++) world.step(DT, 4);
  assert.deepEqual(world.getStates(), after);
  assert.throws(() => world.restoreState(new Uint8Array([1, 2, 3])), RangeError);
  assert.throws(() => world.restoreState('state'), { name: 'TypeError', message: /state/ });
  world.destroy();
});

test('body controls: velocity, impulses, type, teleport', () => {
  const world = new c.World2({ gravity: { x: 0, y: 0 } });
  const b = world.createBody({ type: 'dynamic' });
  b.createShape(c.circle({ x: 0, y: 0 }, 0.5), { density: 1 });
  const m = b.mass;
  b.applyLinearImpulseToCenter({ x: m * 2, y: 0 });
  assert.ok(Math.abs(b.linearVelocity.x - 2) < 1e-5);
  world.step(0.5, 4);
  assert.ok(Math.abs(b.position.x - 1) < 1e-4);
  b.linearVelocity = { x: 0, y: 0 };
  b.angularVelocity = 1;
  world.step(0.5, 4);
  // Each sub-step turns the rotation by atan(w h) (the integrator normalizes q + h w q_perp).
  assert.ok(Math.abs(b.angle - 4 * Math.atan(0.125)) < 1e-5, `angle ${b.angle}`);
  b.type = 'kinematic';
  assert.equal(b.type, 'kinematic');
  assert.equal(b.mass, 0);
  b.position = { x: 7, y: 8 };
  assert.deepEqual(b.position, { x: 7, y: 8 });
  world.destroy();
});

test('bad input throws TypeError or RangeError naming the argument', () => {
  const { world, ground } = groundWorld();
  assert.throws(() => world.step(NaN), { name: 'RangeError', message: /timeStep/ });
  assert.throws(() => world.step('1/60'), { name: 'TypeError', message: /timeStep/ });
  assert.throws(() => world.step(DT, 0), { name: 'RangeError', message: /subStepCount/ });
  assert.throws(() => world.createBody({ position: { x: NaN, y: 0 } }), { name: 'RangeError', message: /def\.position\.x/ });
  assert.throws(() => world.createBody({ type: 'rigid' }), { name: 'TypeError', message: /def\.type/ });
  assert.throws(() => world.createBody({ linearDamping: -1 }), { name: 'RangeError', message: /def\.linearDamping/ });
  assert.throws(() => world.createBody('dynamic'), { name: 'TypeError', message: /def/ });
  assert.throws(() => new c.World2({ gravity: { x: 0, y: Infinity } }), { name: 'RangeError', message: /def\.gravity\.y/ });
  const b = world.createBody({ type: 'dynamic' });
  assert.throws(() => b.createShape({ type: 'star' }), { name: 'TypeError', message: /geometry\.type/ });
  assert.throws(() => b.createShape(c.circle({ x: 0, y: 0 }, 1), { density: -1 }), { name: 'RangeError', message: /def\.density/ });
  assert.throws(() => b.createShape({ type: 'circle', center: { x: 0, y: 0 }, radius: NaN }), { name: 'RangeError', message: /geometry\.radius/ });
  assert.throws(() => b.applyForceToCenter({ x: 1 }), { name: 'TypeError', message: /force\.y/ });
  assert.throws(() => { b.linearVelocity = { x: NaN, y: 0 }; }, { name: 'RangeError', message: /linearVelocity\.x/ });
  assert.throws(() => world.createJoint({ type: 'revolute', bodyA: b, bodyB: b }), { name: 'RangeError', message: /bodyA and def\.bodyB/ });
  assert.throws(() => world.createJoint({ type: 'rope', bodyA: ground, bodyB: b }), { name: 'TypeError', message: /def\.type/ });
  assert.throws(() => world.createJoint({ type: 'revolute', bodyA: ground, bodyB: {} }), { name: 'TypeError', message: /def\.bodyB/ });
  assert.throws(() => world.setPreSolve(42), { name: 'TypeError', message: /fcn/ });
  assert.throws(() => world.overlapAabb({ min: { x: 1, y: 1 }, max: { x: 0, y: 0 } }), { name: 'RangeError', message: /aabb/ });
  assert.throws(() => world.raycastClosest({ x: 0, y: 0 }, { x: NaN, y: 1 }), { name: 'RangeError', message: /translation\.x/ });
  assert.throws(() => world.overlapAabb({ min: { x: 0, y: 0 }, max: { x: 1, y: 1 } }, { maskBits: -1 }), { name: 'RangeError', message: /filter\.maskBits/ });

  // Destroyed objects and stale ids.
  const j = world.createJoint({ type: 'revolute', bodyA: ground, bodyB: b });
  const s = b.createShape(c.circle({ x: 0, y: 0 }, 0.5));
  b.destroy();
  assert.ok(b.destroyed && s.destroyed && j.destroyed);
  assert.throws(() => b.position, { name: 'TypeError', message: /position: this Body2 was destroyed/ });
  assert.throws(() => b.applyForceToCenter({ x: 1, y: 0 }), { name: 'TypeError', message: /applyForceToCenter/ });
  assert.throws(() => s.friction, { name: 'TypeError', message: /friction: this BodyShape2 was destroyed/ });
  assert.throws(() => j.constraintForce, { name: 'TypeError', message: /constraintForce: this Joint2 was destroyed/ });
  assert.throws(() => world.createJoint({ type: 'revolute', bodyA: ground, bodyB: b }), { name: 'TypeError', message: /def\.bodyB/ });
  b.destroy(); // twice is harmless
  world.destroy();
  assert.throws(() => world.step(DT), { name: 'TypeError', message: /step: this World2 was destroyed/ });
  assert.throws(() => ground.position, { name: 'TypeError', message: /Body2 was destroyed/ });
});

test('the character mover stops at a wall, stands on the ground and walks up a 20 degree slope', () => {
  const world = new c.World2();
  world.createBody({ position: { x: 0, y: -1 } }).createShape(c.box2({ x: 0, y: 0 }, { x: 50, y: 1 }));
  world.createBody({ position: { x: 5, y: 1.5 } }).createShape(c.box2({ x: 0, y: 0 }, { x: 0.5, y: 1.5 })); // wall face at x = 4.5
  const slope = Math.tan(20 * Math.PI / 180);
  world.createBody().createShape(c.polygon([{ x: -3, y: 0 }, { x: -13, y: 0 }, { x: -13, y: 10 * slope }]));
  // The capsule's feet at the character's position: radius 0.3, from 0.3 to 1.0 above it.
  const capsule = { p1: { x: 0, y: 0.3 }, p2: { x: 0, y: 1 }, radius: 0.3 };
  let position = { x: 0, y: 0.5 }, velocity = { x: 0, y: 0 }, planes = [];
  for (let i = 0; i < 180; i++) {
    velocity = { x: 3, y: velocity.y - 10 / 60 };
    ({ position, velocity, planes } = world.moveCharacter({ capsule, position, velocity, dt: 1 / 60 }));
    assert.ok(position.y > -0.02);
  }
  // Stopped by the wall: its face at 4.5 minus the radius 0.3; standing on the ground.
  assert.ok(Math.abs(position.x - 4.2) < 0.03 && Math.abs(position.y) < 0.03, `at ${position.x}, ${position.y}`);
  assert.ok(Math.abs(velocity.y) < 0.2);
  assert.ok(planes.some((p) => p.normal.y > 0.99) && planes.some((p) => p.normal.x < -0.99), 'ground and wall planes');
  position = { x: -2, y: 0 }; velocity = { x: 0, y: 0 };
  for (let i = 0; i < 120; i++) {
    velocity = { x: -3, y: velocity.y - 10 / 60 };
    ({ position, velocity } = world.moveCharacter({ capsule, position, velocity, dt: 1 / 60 }));
  }
  assert.ok(position.x < -6 && Math.abs(position.y - (-3 - position.x) * slope) < 0.05, `on the slope at ${position.x}, ${position.y}`);
  // The building blocks: planes of a capsule resting on the ground, a cast, solve and clip.
  const resting = world.collideMover({ p1: { x: 0, y: 0.3 }, p2: { x: 0, y: 1 }, radius: 0.3 });
  assert.equal(resting.length, 1);
  assert.ok(Math.abs(resting[0].normal.y - 1) < 1e-5 && Math.abs(resting[0].separation) < 1e-4);
  const t = world.castMover({ p1: { x: 0, y: 1.3 }, p2: { x: 0, y: 2 }, radius: 0.3 }, { x: 0, y: -2 });
  assert.ok(Math.abs(t - 0.5) < 0.01, `cast fraction ${t}`);
  const floor = [{ normal: { x: 0, y: 1 }, separation: -0.1, point: { x: 0, y: 0 } }];
  // Separation -0.1 and a target 1 m into the floor: pushed up to 0.1 m above (float rounding).
  const solved = c.solvePlanes2({ x: 1, y: -1 }, floor);
  assert.ok(solved.x === 1 && Math.abs(solved.y - 0.1) < 1e-6, `solved ${solved.x}, ${solved.y}`);
  const clipped = c.clipVector2({ x: 2, y: -5 }, floor);
  assert.equal(clipped.x, 2);
  assert.ok(Math.abs(clipped.y) < 1e-6);
  assert.throws(() => world.moveCharacter({ capsule: { p1: { x: 0, y: 0 }, p2: { x: 0, y: 1 }, radius: 0 }, position, velocity, dt: 1 / 60 }), { name: 'RangeError', message: /options\.capsule\.radius/ });
  assert.throws(() => world.moveCharacter({ capsule, position: { x: NaN, y: 0 }, velocity, dt: 1 / 60 }), { name: 'RangeError', message: /options\.position\.x/ });
  world.destroy();
});
