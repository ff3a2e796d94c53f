// Side-scroller on collide's 2D world: a capsule character moved by velocity, a one-way platform
// (pre-solve callback), a moving kinematic platform over a pit, crates, and pick-ups counted from
// sensor events. The page publishes its state on window.__demo for the browser tests.
import { World2, box2, circle, capsule2 } from 'collide';
import { createHud, runLoop } from '../common/hud.js';
import { initCollide } from '../common/collide.js';
import { navigation, createCamera, drawWorld } from '../common/world2d.js';

navigation('scroller');
const canvas = document.getElementById('stage');
const ctx = canvas.getContext('2d');
const hud = createHud(document.getElementById('hud'));
const scoreEl = document.getElementById('score');
const demo = (window.__demo = { page: 'scroller', ready: false, pending: null, bodies: 0, hud: hud.state, score: 0, picked: 0, pickups: 0, character: null, error: null });

try {
  await initCollide();
} catch (err) {
  demo.error = String(err);
  document.getElementById('hud').textContent = `collide failed to load: ${err.message}`;
  throw err;
}

const world = new World2({ gravity: { x: 0, y: -20 } });
const camera = createCamera(canvas, 40, 30);

function staticBox(x, y, hx, hy, color, def = {}) {
  const b = world.createBody({ position: { x, y } });
  const s = b.createShape(box2({ x: 0, y: 0 }, { x: hx, y: hy }), { friction: 0.8, ...def });
  b.userData = { draw: [{ box: [hx, hy] }], color };
  return [b, s];
}

// Ground with a pit from x = 14 to x = 20.
staticBox(4, -0.5, 10, 0.5, '#4a5266');
staticBox(34, -0.5, 14, 0.5, '#4a5266');
staticBox(-6.5, 3, 0.5, 3.5, '#4a5266');
staticBox(48.5, 3, 0.5, 3.5, '#4a5266');
// A solid platform and a one-way platform above the ground.
staticBox(9, 2.2, 1.5, 0.25, '#4a5266');
const [, oneWay] = staticBox(25, 2.4, 2.5, 0.15, '#5fbf6a', { enablePreSolveEvents: true, filter: { categoryBits: 1 | 2 } });
// The moving platform: kinematic, back and forth over the pit.
const mover = world.createBody({ type: 'kinematic', position: { x: 17, y: -0.25 } });
mover.createShape(box2({ x: 0, y: 0 }, { x: 1.5, y: 0.25 }), { friction: 0.8 });
mover.userData = { draw: [{ box: [1.5, 0.25] }], color: '#4a8ae0' };
// Crates to push.
for (let i = 0; i < 3; i++) {
  const crate = world.createBody({ type: 'dynamic', position: { x: 30 + 1.1 * i, y: 0.4 + (i === 2 ? 0.8 : 0) } });
  crate.createShape(box2({ x: 0, y: 0 }, { x: 0.4, y: 0.4 }), { density: 0.5, friction: 0.6 });
  crate.userData = { draw: [{ box: [0.4, 0.4], stroke: '#2a1a08' }], color: '#b07a3c', dynamic: true };
}

// The character: a kinematic capsule moved by collide's character mover (world.moveCharacter:
// cast, collect the planes it touches, slide along them). Its position is the bottom of its feet.
const CAPSULE = { p1: { x: 0, y: 0.35 }, p2: { x: 0, y: 1.15 }, radius: 0.35 };
const CHARACTER_BIT = 4, ONE_WAY_BIT = 2;
const MOVER_FILTER = { categoryBits: 1, maskBits: 0xFFFFFFFFFFFFFFFFn & ~BigInt(CHARACTER_BIT) };
const character = world.createBody({ type: 'kinematic', position: { x: 0, y: 0.5 } });
const feet = character.createShape(capsule2(CAPSULE.p1, CAPSULE.p2, CAPSULE.radius), { enableSensorEvents: true, filter: { categoryBits: CHARACTER_BIT } });
character.userData = { draw: [{ capsule: [0.4, 0.35], at: [0, 0.75], stroke: '#ffffff' }, { circle: 0.08, at: [0.15, 1.25], color: '#0b0e14' }], color: '#f07040' };
let velocity = { x: 0, y: 0 }, planes = [];

// Pick-ups: sensor circles (yellow) along the way, one above the one-way platform, one across the pit.
const pickupSpots = [[4, 0.8], [9, 3.2], [17, 2.0], [25, 3.3], [36, 0.8]];
const pickups = new Set();
for (const [x, y] of pickupSpots) {
  const b = world.createBody({ position: { x, y } });
  const s = b.createShape(circle({ x: 0, y: 0 }, 0.3), { isSensor: true });
  b.userData = { draw: [{ circle: 0.3, stroke: '#fff6c0' }], color: '#ffd23c' };
  pickups.add(s);
}
demo.pickups = pickups.size;

// One-way platform: the character mover holds the character on it only from above (its
// oneWayBits); for the dynamic crates a pre-solve callback keeps the contact only when the normal
// points up out of the platform.
world.setPreSolve((a, b, manifold) => {
  if (a !== oneWay && b !== oneWay) return true;
  const ny = a === oneWay ? manifold.normal.y : -manifold.normal.y; // from the platform to the crate
  return ny > 0.5;
});

// ---- input ------------------------------------------------------------------------------------
const keys = new Set();
const KEYMAP = { ArrowLeft: 'left', KeyA: 'left', ArrowRight: 'right', KeyD: 'right', ArrowUp: 'jump', KeyW: 'jump', Space: 'jump' };
window.addEventListener('keydown', (e) => { const k = KEYMAP[e.code]; if (k) { keys.add(k); e.preventDefault(); } });
window.addEventListener('keyup', (e) => { const k = KEYMAP[e.code]; if (k) keys.delete(k); });

const onGround = () => planes.some((p) => p.normal.y > 0.7);

let time = 0;
const GRAVITY = 20, DT = 1 / 60;
function step() {
  // The moving platform: velocity along a sine, 3 m each side of the pit's middle.
  time += DT;
  const platformVx = 3 * Math.cos(time * 0.8) * 0.8;
  mover.linearVelocity = { x: platformVx, y: 0 };
  // The character: walking speed from the keys, gravity, a jump from the ground; standing on the
  // moving platform carries it along.
  const grounded = onGround();
  const dir = (keys.has('right') ? 1 : 0) - (keys.has('left') ? 1 : 0);
  const carry = planes.some((p) => p.normal.y > 0.7 && p.shape?.body === mover) ? platformVx : 0;
  velocity = { x: 6 * dir, y: velocity.y - GRAVITY * DT };
  if (keys.has('jump') && grounded) velocity.y = 10;
  const from = character.position;
  const r = world.moveCharacter({ capsule: CAPSULE, position: from, velocity: { x: velocity.x + carry, y: velocity.y }, dt: DT, filter: MOVER_FILTER, oneWayBits: ONE_WAY_BIT });
  velocity = { x: velocity.x, y: r.velocity.y };
  planes = r.planes;
  // The kinematic body reaches the mover's answer during the step (and pushes crates on the way).
  character.linearVelocity = { x: (r.position.x - from.x) / DT, y: (r.position.y - from.y) / DT };
  world.step(DT, 4);
  for (const e of world.getEvents().sensorBegin) {
    if (e.visitor === feet && pickups.has(e.sensor)) {
      pickups.delete(e.sensor);
      e.sensor.body.destroy();
      demo.score += 10;
      demo.picked += 1;
      scoreEl.textContent = String(demo.score);
    }
  }
  // Fell into the pit: back to the start.
  if (character.position.y < -6) { character.setTransform({ x: 0, y: 0.5 }, 0); velocity = { x: 0, y: 0 }; }
}

function draw() {
  const p = character.position;
  camera.cx += (Math.max(4, Math.min(38, p.x)) - camera.cx) * 0.15;
  camera.cy = 0;
  ctx.fillStyle = '#0b0e14';
  ctx.fillRect(0, 0, canvas.width, canvas.height);
  drawWorld(ctx, camera, world);
  ctx.fillStyle = '#dde3ee';
  ctx.font = '16px system-ui, sans-serif';
  ctx.fillText(`score ${demo.score}   pick-ups ${demo.picked}/${demo.pickups}`, 12, 22);
  demo.character = p;
}

runLoop(hud, () => {
  step();
  draw();
  demo.bodies = world.bodies.length;
  return [demo.bodies, 'bodies'];
});
demo.ready = true;
canvas.focus();
