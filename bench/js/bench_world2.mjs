// The 2D world's scenes in node: collide (wasm, through World2) against planck, matter-js,
// @dimforge/rapier2d-compat, box2d-wasm (Box2D 2.4) and box2d3-wasm (Box2D v3). Each scene is
// built as in scenes/world2_scenes.c (pyramid_20 and pyramid_40: Box2D's large_pyramid with bases
// 20 and 40; many_pyramids: 20 x 20 pyramids of base 10 on 20 ground segments): unit boxes,
// density 1, friction 0.6, gravity -10, 60 Hz, sleeping off, each engine's default solver
// (collide and box2d3: 4 sub-steps; box2d-wasm and planck: 8 velocity / 3 position iterations;
// rapier: its defaults; matter-js: its defaults at 40 px per metre).
//
// Every (engine, scene, run) is a separate node process; runs are interleaved across engines.
// Time: CPU time of the process (process.cpuUsage) around the steps only, ms per step; each row
// is the median of the runs. State: the top box of the pyramid (or of every pyramid) after the
// last step, "standing" when it is within 0.5 m of where it started.
//
//   cd bench/js && npm install && node bench_world2.mjs [--runs 3] [--scene NAME] [--engine NAME] [--budget SECONDS]
import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { cpuMs, median } from './timing.mjs';

const ENGINES = ['collide', 'box2d3-wasm', 'rapier', 'box2d-wasm', 'planck', 'matter-js'];
const SCENES = {
  pyramid_20: { steps: 600, kind: 'pyramid', base: 20 },
  pyramid_40: { steps: 600, kind: 'pyramid', base: 40 },
  many_pyramids: { steps: 200, kind: 'many' },
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

const BUILD = { collide, 'box2d3-wasm': box2d3, rapier, 'box2d-wasm': box2dv2, planck, 'matter-js': matter };

async function child(engine, sceneName, budgetMs) {
  const scene = SCENES[sceneName];
  const L = layout(scene);
  const sim = await BUILD[engine](L);
  const start = L.tops.map((k) => sim.position(k));
  let steps = 0;
  const t0 = cpuMs();
  while (steps < scene.steps) {
    sim.step();
    steps++;
    if ((steps & 15) === 0 && cpuMs() - t0 > budgetMs) break;
  }
  const ms = (cpuMs() - t0) / steps;
  const end = L.tops.map((k) => sim.position(k));
  const standing = end.filter((p, i) => Math.hypot(p.x - start[i].x, p.y - start[i].y) < 0.5).length;
  const top = end[0];
  console.log(JSON.stringify({ engine, scene: sceneName, bodies: L.boxes.length, steps, ms, standing, pyramids: L.tops.length, top, topStart: start[0] }));
}

// ---- driver -------------------------------------------------------------------------------------
const args = process.argv.slice(2);
const opt = (name, dflt) => { const i = args.indexOf(name); return i < 0 ? dflt : args[i + 1]; };
if (args[0] === '--child') {
  await child(args[1], args[2], Number(args[3]));
} else {
  const runs = Number(opt('--runs', 3));
  const budget = Number(opt('--budget', 20)) * 1000;
  const scenes = opt('--scene', null) ? [opt('--scene')] : Object.keys(SCENES);
  const engines = opt('--engine', null) ? opt('--engine').split(',') : ENGINES;
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
        process.stderr.write(`${scene} ${engine} run ${r + 1}: ${res.error ?? `${res.ms.toFixed(3)} ms/step over ${res.steps} steps, standing ${res.standing}/${res.pyramids}`}\n`);
      }
    }
  }
  // Markdown table: ms/step (median), ratio collide / engine, final state.
  const lines = ['| scene | engine | bodies | ms/step (median) | runs | collide / engine | final state |', '|---|---|---:|---:|---|---:|---|'];
  for (const scene of scenes) {
    const ours = results[`${scene} collide`]?.filter((r) => !r.error);
    const oursMs = ours?.length ? median(ours.map((r) => r.ms)) : NaN;
    for (const engine of engines) {
      const rs = results[`${scene} ${engine}`] ?? [];
      const ok = rs.filter((r) => !r.error);
      if (!ok.length) { lines.push(`| ${scene} | ${engine} | | failed | | | ${rs[0]?.error ?? ''} |`); continue; }
      const ms = median(ok.map((r) => r.ms));
      const last = ok[ok.length - 1];
      const state = last.pyramids === 1
        ? `${last.standing ? 'standing' : 'fallen'}: top (${last.top.x.toFixed(3)}, ${last.top.y.toFixed(3)}) from (${last.topStart.x.toFixed(1)}, ${last.topStart.y.toFixed(1)})`
        : `${last.standing}/${last.pyramids} pyramids standing`;
      const partial = last.steps < SCENES[scene].steps ? ` (${last.steps} of ${SCENES[scene].steps} steps: time budget)` : '';
      lines.push(`| ${scene} | ${engine} | ${last.bodies} | ${ms.toFixed(3)} | ${ok.map((r) => r.ms.toFixed(2)).join(' / ')} | ${engine === 'collide' ? '1' : (oursMs / ms).toFixed(2) + 'x'} | ${state}${partial} |`);
    }
  }
  console.log(lines.join('\n'));
}
