// The 2D world's scenes in node: collide (wasm, through World2) against planck, matter-js,
// @dimforge/rapier2d-compat, box2d-wasm (Box2D 2.4) and box2d3-wasm (Box2D v3). Each scene is
// built as in scenes/world2_scenes.c (pyramid_20 and pyramid_40: Box2D's large_pyramid with bases
// 20 and 40; many_pyramids: 20 x 20 pyramids of base 10 on 20 ground segments): unit boxes,
// density 1, friction 0.6, gravity -10, 60 Hz, sleeping off, each engine's default solver
// (collide and box2d3: 4 sub-steps; box2d-wasm and planck: 8 velocity / 3 position iterations;
// rapier: its defaults; matter-js: its defaults at 40 px per metre).
//
// Every (engine, scene, run) is a separate node process; runs are interleaved across engines.
// Time: CPU time of the process (process.cpuUsage) around the steps only, ms per step. Each
// process runs the scene twice, each time in a new world from its first step: the first run
// ("cold") includes the one-time compilation of the engine's code by V8, the second ("warm") is
// the engine's steady speed and the row's figure; each row is the median of the runs. State: the top box of the pyramid (or of every pyramid) after the
// last step, "standing" when it is within 0.5 m of where it started. --budget caps a run's CPU
// seconds (the slow engines on the big scenes then report over fewer steps, marked in the table);
// rain's cost grows with its population (50 columns of ragdolls by step 400, recycled from step
// 320), so a rain run cut by the budget covers the cheaper early steps only: read such rows as
// lower bounds of that engine's cost.
//
//   bench/js/run.sh world2 [--runs 3] [--scene NAME[,NAME...]] [--engine NAME[,NAME...]] [--budget SECONDS]
// (run.sh installs the engines from npm and builds the wasm module when they are missing)
import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { cpuMs, median } from './timing.mjs';

const ENGINES = ['collide', 'box2d3-wasm', 'rapier', 'box2d-wasm', 'planck', 'matter-js'];
const SCENES = {
  pyramid_20: { steps: 600, kind: 'pyramid', base: 20 },
  pyramid_40: { steps: 600, kind: 'pyramid', base: 40 },
  many_pyramids: { steps: 200, kind: 'many' },
  rain: { steps: 400, kind: 'rain' },
};

// ---- scene layouts (engine-neutral: boxes and ground pieces) ----------------------------------
function layout(scene) {
  const boxes = [], grounds = [], tops = [];
  const a = 0.5;
  if (scene.kind === 'pyramid') {
    grounds.push({ box: [0, -1, 100, 1] });
    const n = scene.base;
    for (let i = 0; i < n; i++) {
      const y = (2 * i + 1) * a;
      for (let j = i; j < n; j++) boxes.push([(i + 1) * a + 2 * (j - i) * a - a * n, y]);
    }
    tops.push(boxes.length - 1);
  } else {
    const base = 10, rows = 20, cols = 20;
    const dy = 2 * a * (base + 1), width = 2 * a * cols * (base + 1);
    for (let i = 0; i < rows; i++) grounds.push({ segment: [-0.5 * width, i * dy, 0.5 * width, i * dy] });
    const baseWidth = 2 * a * base;
    for (let row = 0; row < rows; row++) {
      for (let col = 0; col < cols; col++) {
        const cx = -0.5 * width + col * (baseWidth + 2 * a) + 2 * a;
        for (let i = 0; i < base; i++) {
          const y = (2 * i + 1) * a + row * dy;
          for (let j = i; j < base; j++) boxes.push([(i + 1) * a + 2 * (j - i) * a + cx - 0.5, y]);
        }
        tops.push(boxes.length - 1);
      }
    }
  }
  return { boxes, grounds, tops };
}

// ---- engines: build(layout) -> { step(), position(k) } ----------------------------------------
const DT = 1 / 60;

async function collide(L) {
  const c = await import('collide');
  await c.init();
  const world = new c.World2({ gravity: { x: 0, y: -10 }, enableSleep: false });
  const ground = world.createBody();
  for (const g of L.grounds) {
    if (g.box) ground.createShape(c.box2({ x: g.box[0], y: g.box[1] }, { x: g.box[2], y: g.box[3] }), { friction: 0.6 });
    else ground.createShape(c.segment2({ x: g.segment[0], y: g.segment[1] }, { x: g.segment[2], y: g.segment[3] }), { friction: 0.6 });
  }
  const shape = c.box2({ x: 0, y: 0 }, { x: 0.5, y: 0.5 });
  const bodies = L.boxes.map(([x, y]) => {
    const b = world.createBody({ type: 'dynamic', position: { x, y } });
    b.createShape(shape, { density: 1, friction: 0.6 });
    return b;
  });
  return { step: () => world.step(DT, 4), position: (k) => bodies[k].position };
}

async function box2d3(L) {
  const { default: Box2DFactory } = await import('box2d3-wasm');
  const B = await Box2DFactory();
  const wd = B.b2DefaultWorldDef();
  wd.gravity = new B.b2Vec2(0, -10);
  wd.enableSleep = false;
  const world = B.b2CreateWorld(wd);
  const gd = B.b2DefaultBodyDef();
  const ground = B.b2CreateBody(world, gd);
  const sd = B.b2DefaultShapeDef();
  const m = sd.material; m.friction = 0.6; sd.material = m;
  sd.density = 1;
  for (const g of L.grounds) {
    if (g.box) {
      B.b2CreatePolygonShape(ground, sd, B.b2MakeOffsetBox(g.box[2], g.box[3], new B.b2Vec2(g.box[0], g.box[1]), B.b2MakeRot(0)));
    } else {
      const s = new B.b2Segment();
      s.point1 = new B.b2Vec2(g.segment[0], g.segment[1]);
      s.point2 = new B.b2Vec2(g.segment[2], g.segment[3]);
      B.b2CreateSegmentShape(ground, sd, s);
    }
  }
  const box = B.b2MakeBox(0.5, 0.5);
  const bd = B.b2DefaultBodyDef();
  bd.type = B.b2BodyType.b2_dynamicBody;
  const bodies = L.boxes.map(([x, y]) => {
    bd.position = new B.b2Vec2(x, y);
    const b = B.b2CreateBody(world, bd);
    B.b2CreatePolygonShape(b, sd, box);
    return b;
  });
  return { step: () => B.b2World_Step(world, DT, 4), position: (k) => { const p = B.b2Body_GetPosition(bodies[k]); return { x: p.x, y: p.y }; } };
}

async function rapier(L) {
  const { default: R } = await import('@dimforge/rapier2d-compat');
  await R.init();
  const world = new R.World({ x: 0, y: -10 });
  world.timestep = DT;
  for (const g of L.grounds) {
    if (g.box) world.createCollider(R.ColliderDesc.cuboid(g.box[2], g.box[3]).setTranslation(g.box[0], g.box[1]).setFriction(0.6));
    else world.createCollider(R.ColliderDesc.segment({ x: g.segment[0], y: g.segment[1] }, { x: g.segment[2], y: g.segment[3] }).setFriction(0.6));
  }
  const bodies = L.boxes.map(([x, y]) => {
    const b = world.createRigidBody(R.RigidBodyDesc.dynamic().setTranslation(x, y).setCanSleep(false));
    world.createCollider(R.ColliderDesc.cuboid(0.5, 0.5).setDensity(1).setFriction(0.6), b);
    return b;
  });
  return { step: () => world.step(), position: (k) => { const p = bodies[k].translation(); return { x: p.x, y: p.y }; } };
}

async function box2dv2(L) {
  // box2d-wasm's emscripten loader fetches its .wasm by path, which node's fetch refuses: hand
  // it the bytes of the build its entry picks (the SIMD one where wasm SIMD is supported).
  const { default: Box2DFactory } = await import('box2d-wasm');
  const { readFileSync } = await import('node:fs');
  const { createRequire } = await import('node:module');
  const dir = createRequire(import.meta.url).resolve('box2d-wasm').replace(/entry\.js$/, '');
  const simd = WebAssembly.validate(new Uint8Array([0, 97, 115, 109, 1, 0, 0, 0, 1, 5, 1, 96, 0, 1, 123, 3, 2, 1, 0, 10, 10, 1, 8, 0, 65, 0, 253, 15, 253, 98, 11]));
  const B = await Box2DFactory({ wasmBinary: readFileSync(dir + (simd ? 'Box2D.simd.wasm' : 'Box2D.wasm')) });
  const world = new B.b2World(new B.b2Vec2(0, -10));
  world.SetAllowSleeping(false);
  const ground = world.CreateBody(new B.b2BodyDef());
  for (const g of L.grounds) {
    let shape;
    if (g.box) {
      shape = new B.b2PolygonShape();
      shape.SetAsBox(g.box[2], g.box[3], new B.b2Vec2(g.box[0], g.box[1]), 0);
    } else {
      shape = new B.b2EdgeShape();
      shape.SetTwoSided(new B.b2Vec2(g.segment[0], g.segment[1]), new B.b2Vec2(g.segment[2], g.segment[3]));
    }
    const fd = new B.b2FixtureDef();
    fd.set_shape(shape); fd.set_friction(0.6);
    ground.CreateFixture(fd);
  }
  const box = new B.b2PolygonShape();
  box.SetAsBox(0.5, 0.5);
  const fd = new B.b2FixtureDef();
  fd.set_shape(box); fd.set_density(1); fd.set_friction(0.6);
  const bd = new B.b2BodyDef();
  bd.set_type(B.b2_dynamicBody);
  const bodies = L.boxes.map(([x, y]) => {
    bd.set_position(new B.b2Vec2(x, y));
    const b = world.CreateBody(bd);
    b.CreateFixture(fd);
    return b;
  });
  return { step: () => world.Step(DT, 8, 3), position: (k) => { const p = bodies[k].GetPosition(); return { x: p.get_x(), y: p.get_y() }; } };
}

async function planck(L) {
  const pl = await import('planck');
  const P = pl.default ?? pl;
  const world = new P.World({ gravity: { x: 0, y: -10 }, allowSleep: false });
  const ground = world.createBody();
  for (const g of L.grounds) {
    if (g.box) ground.createFixture(new P.Box(g.box[2], g.box[3], { x: g.box[0], y: g.box[1] }, 0), { friction: 0.6 });
    else ground.createFixture(new P.Edge({ x: g.segment[0], y: g.segment[1] }, { x: g.segment[2], y: g.segment[3] }), { friction: 0.6 });
  }
  const bodies = L.boxes.map(([x, y]) => {
    const b = world.createDynamicBody({ position: { x, y } });
    b.createFixture(new P.Box(0.5, 0.5), { density: 1, friction: 0.6 });
    return b;
  });
  return { step: () => world.step(DT, 8, 3), position: (k) => { const p = bodies[k].getPosition(); return { x: p.x, y: p.y }; } };
}

async function matter(L) {
  const M = (await import('matter-js')).default;
  const PX = 40;
  const engine = M.Engine.create({ enableSleeping: false });
  engine.gravity.y = 1;
  engine.gravity.scale = 10 * PX / 1e6; // px/ms^2 (y down)
  const statics = L.grounds.map((g) => (g.box
    ? M.Bodies.rectangle(g.box[0] * PX, -g.box[1] * PX, 2 * g.box[2] * PX, 2 * g.box[3] * PX, { isStatic: true, friction: 0.6 })
    : M.Bodies.rectangle(0.5 * (g.segment[0] + g.segment[2]) * PX, -(g.segment[1] - 0.05) * PX, (g.segment[2] - g.segment[0]) * PX, 0.1 * PX, { isStatic: true, friction: 0.6 })));
  const bodies = L.boxes.map(([x, y]) => M.Bodies.rectangle(x * PX, -y * PX, PX, PX, { friction: 0.6, density: 0.001 }));
  M.Composite.add(engine.world, [...statics, ...bodies]);
  return { step: () => M.Engine.update(engine, 1000 / 60), position: (k) => ({ x: bodies[k].position.x / PX, y: -bodies[k].position.y / PX }) };
}


// ---- rain (Box2D's benchmark, as scenes/world2_scenes.c): ragdolls of 11 capsule bones with
// revolute joints (limits, a friction motor, a spring) raining onto 5 floors of 501 boxes; a new
// column of 5 groups of 5 ragdolls per floor every 8 steps, the oldest recycled after 40 columns.
// Each engine gives primitives; the driver is shared. Where an engine lacks a feature the
// approximation is named in RAIN_NOTES and in the table.
const BONES = [
  [-1, 0.95, -0.02, 0.02, 0.095, 0, 0, 0, 1, 0, 0, false],
  [0, 1.2, -0.135, 0.135, 0.09, 1.0, -0.25, 0, 0.5, 0, 0, false],
  [1, 1.475, -0.038, 0.039, 0.075, 1.4, -0.3, 0.1, 0.25, 0.1, 0, false],
  [0, 0.775, -0.125, 0.125, 0.06, 0.9, -0.05, 0.4, 1.0, 0, 0, false],
  [3, 0.475, -0.155, 0.125, 0.045, 0.625, -0.5, -0.02, 0.5, 0, 0, true],
  [0, 0.775, -0.125, 0.125, 0.06, 0.9, -0.05, 0.4, 1.0, 0, 0, false],
  [5, 0.475, -0.155, 0.125, 0.045, 0.625, -0.5, -0.02, 0.5, 0, 0, true],
  [1, 1.225, -0.125, 0.125, 0.035, 1.35, -0.1, 0.8, 0.5, 0, 0, false],
  [7, 0.975, -0.125, 0.125, 0.03, 1.1, -0.2, 0.3, 0.1, 0.1, 0.25, false],
  [1, 1.225, -0.125, 0.125, 0.035, 1.35, -0.1, 0.8, 0.5, 0, 0, false],
  [9, 0.975, -0.125, 0.125, 0.03, 1.1, -0.2, 0.3, 0.1, 0.1, 0.25, false],
].map(([parent, y, y1, y2, radius, pivot, lower, upper, friction, damping, reference, foot]) => ({ parent, y, y1, y2, radius, pivot, lower, upper, friction, damping, reference, foot }));
const FOOT = [[-0.03, -0.185], [0.11, -0.185], [0.11, -0.16], [-0.03, -0.14]];
export const RAIN_NOTES = {
  collide: 'as in C',
  'box2d3-wasm': 'as in C (Box2D v3 is the scene\'s origin)',
  rapier: 'no joint spring; joint friction as a velocity motor; bones of one ragdoll collide unless jointed (no group index)',
  'box2d-wasm': 'no joint spring; capsules as a box and two circles; sharp foot',
  planck: 'no joint spring; capsules as a box and two circles; sharp foot',
  'matter-js': 'not run: no joint limits or motors',
};

function runRain(E, steps, budgetMs) {
  const ROWS = 5, COLS = 40, GROUP = 5;
  // Ground: 5 floors of 501 boxes (0.25 half size), 45 m apart.
  const ground = E.staticBody();
  for (let i = 0, y = 0; i < ROWS; i++, y += 45) {
    for (let j = 0, x = -125; j <= 500; j++, x += 0.5) E.groundBox(ground, x, y, 0.25);
  }
  const groups = new Array(ROWS * COLS).fill(null);
  const createGroup = (row, col) => {
    const humans = [];
    let px = -125 + 6.25 * (col + 0.5);
    const py = 40 + 45 * row;
    for (let g = 0; g < GROUP; g++, px += 0.5) {
      const bodies = [];
      for (const bone of BONES) {
        const b = E.body(px, py + bone.y, bone.damping);
        E.capsule(b, bone.y1, bone.y2, bone.radius, g + 1);
        if (bone.foot) E.foot(b, g + 1);
        if (bone.parent >= 0) {
          E.revolute(bodies[bone.parent], b, px, py + bone.pivot, BONES[bone.parent].y + py, bone.y + py, px,
            { reference: bone.reference * Math.PI, lower: bone.lower * Math.PI, upper: bone.upper * Math.PI, torque: bone.friction * 0.05, hertz: 5, damping: 0.5 });
        }
        bodies.push(b);
      }
      humans.push(bodies);
    }
    groups[row * COLS + col] = humans;
  };
  let columnCount = 0, columnIndex = 0, n = 0;
  const t0 = cpuMs();
  for (; n < steps; n++) {
    if ((n & 7) === 0) {
      if (columnCount < COLS) {
        for (let row = 0; row < ROWS; row++) createGroup(row, columnCount);
        columnCount++;
      } else {
        for (let row = 0; row < ROWS; row++) {
          for (const human of groups[row * COLS + columnIndex]) for (const b of human) E.destroy(b);
          createGroup(row, columnIndex);
        }
        columnIndex = (columnIndex + 1) % COLS;
      }
    }
    E.step();
    if ((n & 15) === 15 && cpuMs() - t0 > budgetMs) { n++; break; }
  }
  const ms = (cpuMs() - t0) / n;
  return { ms, steps: n, bodies: E.count() };
}

const RAIN = {
  async collide() {
    const c = await import('collide');
    await c.init();
    const world = new c.World2({ gravity: { x: 0, y: -10 }, enableSleep: true });
    const foot = c.polygon(FOOT.map(([x, y]) => ({ x, y })), 0.015);
    const ground = { b: world.createBody() };
    return {
      staticBody: () => ground,
      groundBox: (g, x, y, h) => g.b.createShape(c.box2({ x, y }, { x: h, y: h })),
      body: (x, y, d) => ({ b: world.createBody({ type: 'dynamic', position: { x, y }, linearDamping: d, sleepThreshold: 0.1 }), x, y }),
      capsule: (o, y1, y2, r, g) => o.b.createShape(c.capsule2({ x: 0, y: y1 }, { x: 0, y: y2 }, r), { friction: 0.2, filter: { groupIndex: -g, categoryBits: 2, maskBits: 3 } }),
      foot: (o, g) => o.b.createShape(foot, { friction: 0.05, filter: { groupIndex: -g, categoryBits: 2, maskBits: 1 } }),
      revolute: (a, b, px, py, ay, by, ax, j) => world.createJoint({ type: 'revolute', bodyA: a.b, bodyB: b.b,
        localAnchorA: { x: px - a.x, y: py - a.y }, localAnchorB: { x: px - b.x, y: py - b.y }, referenceAngle: j.reference,
        enableLimit: true, lowerAngle: j.lower, upperAngle: j.upper, enableMotor: true, maxMotorTorque: j.torque, motorSpeed: 0,
        enableSpring: true, hertz: j.hertz, dampingRatio: j.damping }),
      destroy: (o) => o.b.destroy(),
      step: () => world.step(DT, 4),
      count: () => world.counters.bodyCount,
    };
  },
  async 'box2d3-wasm'() {
    const { default: F } = await import('box2d3-wasm');
    const B = await F();
    const wd = B.b2DefaultWorldDef();
    wd.gravity = new B.b2Vec2(0, -10);
    const world = B.b2CreateWorld(wd);
    const V = (x, y) => new B.b2Vec2(x, y);
    const footPoly = B.b2MakePolygon(B.b2ComputeHull(FOOT.map(([x, y]) => V(x, y))), 0.015);
    const shapeDef = (friction, g, mask) => {
      const sd = B.b2DefaultShapeDef();
      const m = sd.material; m.friction = friction; sd.material = m;
      if (g) { const f = sd.filter; f.groupIndex = -g; f.categoryBits = 2; f.maskBits = mask; sd.filter = f; }
      return sd;
    };
    const groundDef = shapeDef(0.6, 0, 0);
    let count = 0;
    return {
      staticBody: () => B.b2CreateBody(world, B.b2DefaultBodyDef()),
      groundBox: (g, x, y, h) => B.b2CreatePolygonShape(g, groundDef, B.b2MakeOffsetBox(h, h, V(x, y), B.b2MakeRot(0))),
      body: (x, y, d) => {
        const bd = B.b2DefaultBodyDef();
        bd.type = B.b2BodyType.b2_dynamicBody; bd.position = V(x, y); bd.linearDamping = d; bd.sleepThreshold = 0.1;
        count++;
        return { b: B.b2CreateBody(world, bd), x, y };
      },
      capsule: (o, y1, y2, r, g) => { const cp = new B.b2Capsule(); cp.center1 = V(0, y1); cp.center2 = V(0, y2); cp.radius = r; B.b2CreateCapsuleShape(o.b, shapeDef(0.2, g, 3), cp); },
      foot: (o, g) => B.b2CreatePolygonShape(o.b, shapeDef(0.05, g, 1), footPoly),
      revolute: (a, b, px, py, ay, by, ax, j) => {
        const jd = B.b2DefaultRevoluteJointDef();
        const base = jd.base;
        base.bodyIdA = a.b; base.bodyIdB = b.b;
        const fa = base.localFrameA; fa.p = V(px - a.x, py - a.y); fa.q = B.b2MakeRot(j.reference); base.localFrameA = fa;
        const fb = base.localFrameB; fb.p = V(px - b.x, py - b.y); base.localFrameB = fb;
        jd.base = base;
        jd.enableLimit = true; jd.lowerAngle = j.lower; jd.upperAngle = j.upper;
        jd.enableMotor = true; jd.maxMotorTorque = j.torque; jd.motorSpeed = 0;
        jd.enableSpring = true; jd.hertz = j.hertz; jd.dampingRatio = j.damping;
        B.b2CreateRevoluteJoint(world, jd);
      },
      destroy: (o) => { B.b2DestroyBody(o.b); count--; },
      step: () => B.b2World_Step(world, DT, 4),
      count: () => count,
    };
  },
  async rapier() {
    const { default: R } = await import('@dimforge/rapier2d-compat');
    await R.init();
    const world = new R.World({ x: 0, y: -10 });
    world.timestep = DT;
    const groups = (member, filter) => (member << 16) | filter;
    let count = 0;
    return {
      staticBody: () => world.createRigidBody(R.RigidBodyDesc.fixed()),
      groundBox: (g, x, y, h) => world.createCollider(R.ColliderDesc.cuboid(h, h).setTranslation(x, y).setFriction(0.6).setCollisionGroups(groups(1, 0xffff)), g),
      body: (x, y, d) => { count++; return { b: world.createRigidBody(R.RigidBodyDesc.dynamic().setTranslation(x, y).setLinearDamping(d)), x, y }; },
      capsule: (o, y1, y2, r) => world.createCollider(R.ColliderDesc.capsule((y2 - y1) / 2, r).setTranslation(0, (y1 + y2) / 2).setFriction(0.2).setCollisionGroups(groups(2, 3)), o.b),
      foot: (o) => world.createCollider(R.ColliderDesc.roundConvexHull(new Float32Array(FOOT.flat()), 0.015).setFriction(0.05).setCollisionGroups(groups(2, 1)), o.b),
      revolute: (a, b, px, py, ay, by, ax, j) => {
        const joint = world.createImpulseJoint(R.JointData.revolute({ x: px - a.x, y: py - a.y }, { x: px - b.x, y: py - b.y }), a.b, b.b, true);
        joint.setContactsEnabled(false);
        joint.setLimits(j.lower + j.reference, j.upper + j.reference);
        joint.configureMotorVelocity(0, j.torque * 60);
      },
      destroy: (o) => { world.removeRigidBody(o.b); count--; },
      step: () => world.step(),
      count: () => count,
    };
  },
  async planck() {
    const pl = await import('planck');
    const P = pl.default ?? pl;
    const world = new P.World({ gravity: { x: 0, y: -10 } });
    let count = 0;
    const capsule = (body, y1, y2, r, fd) => {
      body.createFixture(new P.Box(r, (y2 - y1) / 2, { x: 0, y: (y1 + y2) / 2 }, 0), fd);
      body.createFixture(new P.Circle({ x: 0, y: y1 }, r), fd);
      body.createFixture(new P.Circle({ x: 0, y: y2 }, r), fd);
    };
    return {
      staticBody: () => world.createBody(),
      groundBox: (g, x, y, h) => g.createFixture(new P.Box(h, h, { x, y }, 0), { friction: 0.6 }),
      body: (x, y, d) => { count++; return { b: world.createDynamicBody({ position: { x, y }, linearDamping: d }), x, y }; },
      capsule: (o, y1, y2, r, g) => capsule(o.b, y1, y2, r, { density: 1, friction: 0.2, filterGroupIndex: -g, filterCategoryBits: 2, filterMaskBits: 3 }),
      foot: (o, g) => o.b.createFixture(new P.Polygon(FOOT.map(([x, y]) => ({ x, y }))), { density: 1, friction: 0.05, filterGroupIndex: -g, filterCategoryBits: 2, filterMaskBits: 1 }),
      revolute: (a, b, px, py, ay, by, ax, j) => world.createJoint(new P.RevoluteJoint({ enableLimit: true, lowerAngle: j.lower, upperAngle: j.upper,
        enableMotor: true, maxMotorTorque: j.torque, motorSpeed: 0, referenceAngle: j.reference }, a.b, b.b, { x: px, y: py })),
      destroy: (o) => { world.destroyBody(o.b); count--; },
      step: () => world.step(DT, 8, 3),
      count: () => count,
    };
  },
  async 'box2d-wasm'() {
    const { default: Box2DFactory } = await import('box2d-wasm');
    const { readFileSync } = await import('node:fs');
    const { createRequire } = await import('node:module');
    const dir = createRequire(import.meta.url).resolve('box2d-wasm').replace(/entry\.js$/, '');
    const simd = WebAssembly.validate(new Uint8Array([0, 97, 115, 109, 1, 0, 0, 0, 1, 5, 1, 96, 0, 1, 123, 3, 2, 1, 0, 10, 10, 1, 8, 0, 65, 0, 253, 15, 253, 98, 11]));
    const B = await Box2DFactory({ wasmBinary: readFileSync(dir + (simd ? 'Box2D.simd.wasm' : 'Box2D.wasm')) });
    const world = new B.b2World(new B.b2Vec2(0, -10));
    let count = 0;
    const fixture = (body, shape, friction, g, mask) => {
      const fd = new B.b2FixtureDef();
      fd.set_shape(shape); fd.set_density(1); fd.set_friction(friction);
      if (g) { const f = fd.get_filter(); f.set_groupIndex(-g); f.set_categoryBits(2); f.set_maskBits(mask); fd.set_filter(f); }
      body.CreateFixture(fd);
    };
    const circle = (x, y, r) => { const c = new B.b2CircleShape(); c.set_m_radius(r); c.set_m_p(new B.b2Vec2(x, y)); return c; };
    const foot = new B.b2PolygonShape();
    {
      const buf = B._malloc(FOOT.length * 8);
      FOOT.forEach(([x, y], i) => { B.HEAPF32[(buf >> 2) + 2 * i] = x; B.HEAPF32[(buf >> 2) + 2 * i + 1] = y; });
      foot.Set(B.wrapPointer(buf, B.b2Vec2), FOOT.length);
      B._free(buf);
    }
    return {
      staticBody: () => world.CreateBody(new B.b2BodyDef()),
      groundBox: (g, x, y, h) => { const s = new B.b2PolygonShape(); s.SetAsBox(h, h, new B.b2Vec2(x, y), 0); fixture(g, s, 0.6, 0, 0); },
      body: (x, y, d) => {
        const bd = new B.b2BodyDef();
        bd.set_type(B.b2_dynamicBody); bd.set_position(new B.b2Vec2(x, y)); bd.set_linearDamping(d);
        count++;
        return { b: world.CreateBody(bd), x, y };
      },
      capsule: (o, y1, y2, r, g) => {
        const s = new B.b2PolygonShape(); s.SetAsBox(r, (y2 - y1) / 2, new B.b2Vec2(0, (y1 + y2) / 2), 0);
        fixture(o.b, s, 0.2, g, 3); fixture(o.b, circle(0, y1, r), 0.2, g, 3); fixture(o.b, circle(0, y2, r), 0.2, g, 3);
      },
      foot: (o, g) => fixture(o.b, foot, 0.05, g, 1),
      revolute: (a, b, px, py, ay, by, ax, j) => {
        const jd = new B.b2RevoluteJointDef();
        jd.Initialize(a.b, b.b, new B.b2Vec2(px, py));
        jd.set_referenceAngle(j.reference);
        jd.set_enableLimit(true); jd.set_lowerAngle(j.lower); jd.set_upperAngle(j.upper);
        jd.set_enableMotor(true); jd.set_maxMotorTorque(j.torque); jd.set_motorSpeed(0);
        world.CreateJoint(jd);
      },
      destroy: (o) => { world.DestroyBody(o.b); count--; },
      step: () => world.Step(DT, 8, 3),
      count: () => count,
    };
  },
};

const BUILD = { collide, 'box2d3-wasm': box2d3, rapier, 'box2d-wasm': box2dv2, planck, 'matter-js': matter };

// One measured run of a scene in a fresh world of the engine, from its first step.
async function runScene(engine, sceneName, budgetMs) {
  const scene = SCENES[sceneName];
  if (scene.kind === 'rain') {
    const r = runRain(await RAIN[engine](), scene.steps, budgetMs);
    return { ...r, note: RAIN_NOTES[engine], pyramids: 0, standing: 0 };
  }
  const L = layout(scene);
  const sim = await BUILD[engine](L);
  const start = L.tops.map((k) => sim.position(k));
  let steps = 0;
  const t0 = cpuMs();
  while (steps < scene.steps) {
    sim.step();
    steps++;
    if (cpuMs() - t0 > budgetMs) break;
  }
  const ms = (cpuMs() - t0) / steps;
  const end = L.tops.map((k) => sim.position(k));
  const standing = end.filter((p, i) => Math.hypot(p.x - start[i].x, p.y - start[i].y) < 0.5).length;
  return { bodies: L.boxes.length, steps, ms, standing, pyramids: L.tops.length, top: end[0], topStart: start[0] };
}

// The scene twice in one process: the first run ("cold") pays for compiling the engine's code
// (V8 compiles wasm and JavaScript lazily and re-compiles hot functions with its optimising tier
// on background threads, which process CPU time counts); the second run, in a new world of the
// same engine, measures the engine as a game sees it after its first seconds. The row's figure
// is the second run's; the cold figure is reported beside it.
async function child(engine, sceneName, budgetMs) {
  if (SCENES[sceneName].kind === 'rain' && !RAIN[engine]) {
    console.log(JSON.stringify({ engine, scene: sceneName, error: RAIN_NOTES[engine] }));
    return;
  }
  const cold = await runScene(engine, sceneName, budgetMs);
  const warm = await runScene(engine, sceneName, budgetMs);
  console.log(JSON.stringify({ engine, scene: sceneName, ...warm, msCold: cold.ms }));
}

// ---- driver -------------------------------------------------------------------------------------
const args = process.argv.slice(2);
const opt = (name, dflt) => { const i = args.indexOf(name); return i < 0 ? dflt : args[i + 1]; };
if (args[0] === '--child') {
  await child(args[1], args[2], Number(args[3]));
} else {
  const runs = Number(opt('--runs', 3));
  const budget = Number(opt('--budget', 20)) * 1000;
  const scenes = opt('--scene', null) ? opt('--scene').split(',') : Object.keys(SCENES);
  const engines = opt('--engine', null) ? opt('--engine').split(',') : ENGINES;
  const unknown = [...scenes.filter((s) => !(s in SCENES)), ...engines.filter((e) => !ENGINES.includes(e))];
  if (unknown.length > 0) {
    process.stderr.write(`bench_world2: unknown scene or engine: ${unknown.join(', ')} (scenes: ${Object.keys(SCENES).join(', ')}; engines: ${ENGINES.join(', ')})\n`);
    process.exit(2);
  }
  const self = fileURLToPath(import.meta.url);
  const results = {};
  for (const scene of scenes) {
    for (let r = 0; r < runs; r++) {
      for (const engine of engines) {
        let res;
        try {
          res = JSON.parse(execFileSync(process.execPath, [self, '--child', engine, scene, String(budget)], { maxBuffer: 1 << 24, stdio: ['ignore', 'pipe', 'pipe'] }).toString().trim().split('\n').pop());
        } catch (err) {
          res = { engine, scene, error: String(err.stderr ?? err).split('\n').slice(0, 3).join(' ') };
        }
        (results[`${scene} ${engine}`] ??= []).push(res);
        process.stderr.write(`${scene} ${engine} run ${r + 1}: ${res.error ?? `${res.ms.toFixed(3)} ms/step (cold ${res.msCold.toFixed(3)}) over ${res.steps} steps, standing ${res.standing}/${res.pyramids}, ${res.bodies} bodies`}\n`);
      }
    }
  }
  // Markdown table: ms/step (median, warm and cold), ratios collide / engine, final state.
  const lines = ['| scene | engine | bodies | ms/step (median) | runs | collide / engine | cold ms/step | cold collide / engine | final state |', '|---|---|---:|---:|---|---:|---:|---:|---|'];
  for (const scene of scenes) {
    const ours = results[`${scene} collide`]?.filter((r) => !r.error);
    const oursMs = ours?.length ? median(ours.map((r) => r.ms)) : NaN;
    const oursCold = ours?.length ? median(ours.map((r) => r.msCold)) : NaN;
    for (const engine of engines) {
      const rs = results[`${scene} ${engine}`] ?? [];
      const ok = rs.filter((r) => !r.error);
      if (!ok.length) { lines.push(`| ${scene} | ${engine} | | failed | | | | | ${rs[0]?.error ?? ''} |`); continue; }
      const ms = median(ok.map((r) => r.ms));
      const cold = median(ok.map((r) => r.msCold));
      const last = ok[ok.length - 1];
      const state = scene === 'rain' ? `${last.bodies} bodies at the end; ${last.note}` : last.pyramids === 1
        ? `${last.standing ? 'standing' : 'fallen'}: top (${last.top.x.toFixed(3)}, ${last.top.y.toFixed(3)}) from (${last.topStart.x.toFixed(1)}, ${last.topStart.y.toFixed(1)})`
        : `${last.standing}/${last.pyramids} pyramids standing`;
      const partial = last.steps < SCENES[scene].steps ? ` (${last.steps} of ${SCENES[scene].steps} steps: time budget)` : '';
      lines.push(`| ${scene} | ${engine} | ${last.bodies} | ${ms.toFixed(3)} | ${ok.map((r) => r.ms.toFixed(2)).join(' / ')} | ${engine === 'collide' ? '1' : (oursMs / ms).toFixed(2) + 'x'} | ${cold.toFixed(3)} | ${engine === 'collide' ? '1' : (oursCold / cold).toFixed(2) + 'x'} | ${state}${partial} |`);
    }
  }
  console.log(lines.join('\n'));
}
