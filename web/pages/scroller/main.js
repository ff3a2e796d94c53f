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
const [, oneWay] = staticBox(25, 2.4, 2.5, 0.15, '#5fbf6a', { enablePreSolveEvents: true });
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

// The character: a capsule standing upright (the capsule's axis along y), fixed rotation.
const character = world.createBody({ type: 'dynamic', position: { x: 0, y: 1.2 }, fixedRotation: true, enableSleep: false });
const feet = character.createShape(capsule2({ x: 0, y: -0.4 }, { x: 0, y: 0.4 }, 0.35), { density: 1, friction: 0, enablePreSolveEvents: true, enableSensorEvents: true });
character.userData = { draw: [{ capsule: [0.4, 0.35], stroke: '#ffffff' }, { circle: 0.08, at: [0.15, 0.5], color: '#0b0e14' }], color: '#f07040' };

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

// One-way platform: keep the contact only when the character is above the platform's top and
// not moving up through it.
world.setPreSolve((a, b, manifold) => {
  const platformIsA = a === oneWay;
  if (!platformIsA && b !== oneWay) return true;
  const other = platformIsA ? b : a;
  if (other !== feet) return true;
  const ny = platformIsA ? manifold.normal.y : -manifold.normal.y; // from the platform to the character
  return ny > 0.5;
});

// ---- input ------------------------------------------------------------------------------------
const keys = new Set();
const KEYMAP = { ArrowLeft: 'left', KeyA: 'left', ArrowRight: 'right', KeyD: 'right', ArrowUp: 'jump', KeyW: 'jump', Space: 'jump' };
window.addEventListener('keydown', (e) => { const k = KEYMAP[e.code]; if (k) { keys.add(k); e.preventDefault(); } });
window.addEventListener('keyup', (e) => { const k = KEYMAP[e.code]; if (k) keys.delete(k); });

function grounded() {
  const p = character.position;
  for (const dx of [-0.3, 0, 0.3]) {
    const hit = world.castRayClosest({ x: p.x + dx, y: p.y - 0.7 }, { x: 0, y: -0.15 });
    if (hit !== null && hit.shape !== feet && !hit.shape?.isSensor) return true;
  }
  return false;
}

let time = 0, jumpCooldown = 0;
function step() {
  // The moving platform: velocity along a sine, 3 m each side of the pit's middle.
  time += 1 / 60;
  mover.linearVelocity = { x: 3 * Math.cos(time * 0.8) * 0.8, y: 0 };
  // The character: walk by setting the horizontal velocity, jump with an impulse.
  const v = character.linearVelocity;
  const dir = (keys.has('right') ? 1 : 0) - (keys.has('left') ? 1 : 0);
  const onGround = grounded();
  let vx = dir * 6;
  if (onGround && dir === 0) vx = 0;
  else if (!onGround && dir === 0) vx = v.x * 0.98;
  character.linearVelocity = { x: vx, y: v.y };
  jumpCooldown = Math.max(0, jumpCooldown - 1);
  if (keys.has('jump') && onGround && jumpCooldown === 0) {
    character.applyLinearImpulseToCenter({ x: 0, y: character.mass * 10 });
    jumpCooldown = 15;
  }
  world.step(1 / 60, 4);
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
  if (character.position.y < -6) character.setTransform({ x: 0, y: 1.2 }, 0);
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
