// Slingshot on collide's 2D world: drag and release to launch a projectile into two towers of
// blocks and a jointed rope bridge carrying targets; a score from what moved. The page publishes
// its state on window.__demo for the browser tests (launch(), the anchor in canvas pixels,
// the number of blocks moved, awake bodies, stepsPerFrame to fast-forward).
import { World2, box2, circle } from 'collide';
import { createHud, runLoop } from '../common/hud.js';
import { initCollide } from '../common/collide.js';
import { navigation, createCamera, drawWorld } from '../common/world2d.js';

navigation('slingshot');
const canvas = document.getElementById('stage');
const ctx = canvas.getContext('2d');
const hud = createHud(document.getElementById('hud'));
const scoreEl = document.getElementById('score');
const shotsEl = document.getElementById('shots');
const demo = (window.__demo = {
  page: 'slingshot', ready: false, pending: null, bodies: 0, hud: hud.state, score: 0, shots: 0, moved: 0,
  targetsDown: 0, awake: 0, asleep: false, anchor: null, stepsPerFrame: 1, error: null,
});

try {
  await initCollide();
} catch (err) {
  demo.error = String(err);
  document.getElementById('hud').textContent = `collide failed to load: ${err.message}`;
  throw err;
}

const camera = createCamera(canvas, 24, 20);
camera.cx = 4;
camera.cy = 0;
const ANCHOR = { x: -9, y: 3 };
const MAX_PULL = 3;
let world, projectile, blocks, targets;
// Joint friction for the bridge: a motor at zero speed with a small torque (the bridge settles
// instead of ringing like a taut string).
const JOINT_FRICTION = { enableMotor: true, motorSpeed: 0, maxMotorTorque: 5 };

function buildLevel() {
  world?.destroy();
  world = new World2({ gravity: { x: 0, y: -10 } });
  blocks = [];
  targets = [];
  const ground = world.createBody({ position: { x: 0, y: -0.5 } });
  ground.createShape(box2({ x: 0, y: 0 }, { x: 40, y: 0.5 }), { friction: 0.7 });
  ground.userData = { draw: [{ box: [40, 0.5] }], color: '#4a5266' };
  // The slingshot's post (drawing only, no shape).
  const post = world.createBody({ position: { x: ANCHOR.x, y: 1.2 } });
  post.userData = { draw: [{ box: [0.12, 1.4] }], color: '#7a5230' };

  const block = (x, y, hx, hy, color = '#b07a3c') => {
    const b = world.createBody({ type: 'dynamic', position: { x, y } });
    b.createShape(box2({ x: 0, y: 0 }, { x: hx, y: hy }), { density: 1, friction: 0.6 });
    b.userData = { draw: [{ box: [hx, hy], stroke: '#2a1a08' }], color, dynamic: true, start: { x, y } };
    blocks.push(b);
    return b;
  };
  // Two towers: pillars and lintels.
  for (const cx of [4, 8]) {
    let y = 0;
    for (let level = 0; level < 3; level++) {
      block(cx - 0.8, y + 0.9, 0.2, 0.9);
      block(cx + 0.8, y + 0.9, 0.2, 0.9);
      block(cx, y + 1.95, 1.2, 0.15, '#9a6a34');
      y += 2.1;
    }
  }
  // The rope bridge: 8 planks linked by revolute joints between two pillars, targets on top.
  const pillar = (x) => {
    const p = world.createBody({ position: { x, y: 2 } });
    p.createShape(box2({ x: 0, y: 0 }, { x: 0.3, y: 2 }));
    p.userData = { draw: [{ box: [0.3, 2] }], color: '#5a6276' };
    return p;
  };
  const left = pillar(12), right = pillar(19.6);
  const n = 8, span = 19.3 - 12.3, plank = span / n;
  let prev = left, prevAnchor = { x: 0.3, y: 2 };
  for (let i = 0; i < n; i++) {
    const x = 12.3 + plank * (i + 0.5);
    const b = world.createBody({ type: 'dynamic', position: { x, y: 3.9 }, linearDamping: 0.2, angularDamping: 0.5 });
    b.createShape(box2({ x: 0, y: 0 }, { x: plank / 2, y: 0.1 }), { density: 2, friction: 0.8 });
    b.userData = { draw: [{ box: [plank / 2, 0.1], stroke: '#1a1a1a' }], color: '#8a7a5a', dynamic: true };
    world.createJoint({ type: 'revolute', bodyA: prev, bodyB: b, localAnchorA: prevAnchor, localAnchorB: { x: -plank / 2, y: 0 }, ...JOINT_FRICTION });
    prev = b;
    prevAnchor = { x: plank / 2, y: 0 };
  }
  world.createJoint({ type: 'revolute', bodyA: prev, bodyB: right, localAnchorA: prevAnchor, localAnchorB: { x: -0.3, y: 2 }, ...JOINT_FRICTION });
  for (const x of [14.5, 17]) {
    const t = world.createBody({ type: 'dynamic', position: { x, y: 4.5 } });
    t.createShape(circle({ x: 0, y: 0 }, 0.45), { density: 0.5, friction: 0.8 });
    t.userData = { draw: [{ circle: 0.45, stroke: '#1d4a22' }], color: '#6fdc7a', dynamic: true, start: { x, y: 4.5 } };
    targets.push(t);
  }
  projectile = null;
  demo.score = 0; demo.moved = 0; demo.targetsDown = 0; demo.shots = 0;
  for (const b of [...blocks, ...targets]) b.userData.counted = false;
}

function newProjectile() {
  const b = world.createBody({ type: 'kinematic', position: { ...ANCHOR } });
  b.createShape(circle({ x: 0, y: 0 }, 0.35), { density: 4, friction: 0.5 });
  b.userData = { draw: [{ circle: 0.35, stroke: '#ffd0d0' }], color: '#e04040', dynamic: true };
  return b;
}

/** Launches the projectile from `pull` (world offset from the anchor, clamped to MAX_PULL m). */
function launch(pull) {
  const len = Math.hypot(pull.x, pull.y);
  const k = len > MAX_PULL ? MAX_PULL / len : 1;
  const p = { x: pull.x * k, y: pull.y * k };
  if (projectile === null || projectile.type !== 'kinematic') projectile = newProjectile();
  projectile.setTransform({ x: ANCHOR.x + p.x, y: ANCHOR.y + p.y }, 0);
  projectile.type = 'dynamic';
  projectile.bullet = true;
  projectile.linearVelocity = { x: -p.x * 9, y: -p.y * 9 };
  demo.shots += 1;
  shotsEl.textContent = String(demo.shots);
}
demo.launch = launch;

// ---- dragging -----------------------------------------------------------------------------------
let dragging = null;
const eventToWorld = (e) => {
  const r = canvas.getBoundingClientRect();
  return camera.toWorld((e.clientX - r.left) * (canvas.width / r.width), (e.clientY - r.top) * (canvas.height / r.height));
};
canvas.addEventListener('pointerdown', (e) => {
  const [x, y] = eventToWorld(e);
  if (Math.hypot(x - ANCHOR.x, y - ANCHOR.y) < 1.5) {
    if (projectile === null || projectile.type !== 'kinematic') projectile = newProjectile();
    dragging = { x: 0, y: 0 };
    canvas.setPointerCapture(e.pointerId);
  }
});
canvas.addEventListener('pointermove', (e) => {
  if (dragging === null) return;
  const [x, y] = eventToWorld(e);
  dragging = { x: x - ANCHOR.x, y: y - ANCHOR.y };
  const len = Math.hypot(dragging.x, dragging.y), k = len > MAX_PULL ? MAX_PULL / len : 1;
  projectile.setTransform({ x: ANCHOR.x + dragging.x * k, y: ANCHOR.y + dragging.y * k }, 0);
});
canvas.addEventListener('pointerup', () => {
  if (dragging === null) return;
  const pull = dragging;
  dragging = null;
  if (Math.hypot(pull.x, pull.y) > 0.3) launch(pull);
});
document.getElementById('reset').addEventListener('click', buildLevel);

function score() {
  for (const b of blocks) {
    const d = b.userData;
    if (d.counted) continue;
    const p = b.position;
    if (Math.hypot(p.x - d.start.x, p.y - d.start.y) > 0.5 || Math.abs(b.angle) > 0.35) {
      d.counted = true;
      demo.moved += 1;
      demo.score += 100;
    }
  }
  for (const t of targets) {
    const d = t.userData;
    if (!d.counted && t.position.y < 3) {
      d.counted = true;
      demo.targetsDown += 1;
      demo.score += 500;
    }
  }
  scoreEl.textContent = String(demo.score);
}

function draw() {
  ctx.fillStyle = '#0b0e14';
  ctx.fillRect(0, 0, canvas.width, canvas.height);
  // The band, from the slingshot's fork to the projectile while dragging.
  drawWorld(ctx, camera, world);
  if (dragging !== null && projectile !== null) {
    const [ax, ay] = camera.toCanvas(ANCHOR.x, ANCHOR.y);
    const p = projectile.position;
    const [px, py] = camera.toCanvas(p.x, p.y);
    ctx.strokeStyle = '#d0a070';
    ctx.lineWidth = 3;
    ctx.beginPath(); ctx.moveTo(ax, ay); ctx.lineTo(px, py); ctx.stroke();
  }
  ctx.fillStyle = '#dde3ee';
  ctx.font = '16px system-ui, sans-serif';
  ctx.fillText(`score ${demo.score}   blocks moved ${demo.moved}/${blocks.length}   targets ${demo.targetsDown}/${targets.length}`, 12, 22);
}

buildLevel();
demo.anchor = camera.toCanvas(ANCHOR.x, ANCHOR.y);
runLoop(hud, () => {
  for (let i = 0; i < demo.stepsPerFrame; i++) world.step(1 / 60, 4);
  score();
  draw();
  const counters = world.counters;
  demo.awake = counters.awakeBodyCount;
  demo.bodies = counters.bodyCount;
  return [demo.bodies, 'bodies'];
});
demo.ready = true;
