// The falling pyramid of test/world2_lockstep.c built through World2: per-step 32-bit FNV-1a hashes of
// every body's state (x, y, cos, sin, vx, vy, angular velocity as float bits, creation order).
export const STEPS = 300, BASE = 20, DROP = 1;

function fnv(h, bytes) {
  for (let i = 0; i < bytes.length; i++) h = Math.imul(h ^ bytes[i], 16777619) >>> 0;
  return h;
}

export function runWasm(c) {
  const world = new c.World2({ enableSleep: false });
  const ground = world.createBody({ position: { x: 0, y: -1 } });
  ground.createShape(c.box2({ x: 0, y: 0 }, { x: 100, y: 1 }));
  const a = 0.5;
  for (let i = 0; i < BASE; i++) {
    const y = (2 * i + 1) * a + DROP;
    for (let j = i; j < BASE; j++) {
      const x = (i + 1) * a + 2 * (j - i) * a - a * BASE;
      world.createBody({ type: 'dynamic', position: { x, y } }).createShape(c.box2({ x: 0, y: 0 }, { x: a, y: a }), { density: 1 });
    }
  }
  const hashes = [];
  for (let s = 0; s < STEPS; s++) {
    world.step(1 / 60, 4);
    const states = world.getStates();
    hashes.push(fnv(2166136261, new Uint8Array(states.buffer)).toString(16).padStart(8, '0'));
  }
  const top = world.bodies.at(-1).position;
  world.destroy();
  return { hashes, top };
}

