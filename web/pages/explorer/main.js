// Collision explorer: two shapes of any kind, 2D (canvas) or 3D (three.js), dragged by the user;
// every answer on screen comes from collide (wasm, through the JavaScript package) and names the
// C function that computed it.
import * as THREE from 'three';
import { ConvexGeometry } from 'three/addons/geometries/ConvexGeometry.js';
import { createHud, runLoop, PAGES } from '../common/hud.js';
import { initCollide } from '../common/collide.js';
import {
  Hull, overlap2, distance2, manifold2, shapeCast2, timeOfImpact2,
  overlap3, distance3, manifold3, shapeCast3, timeOfImpact3,
} from 'collide';

// collide's default tolerances (CD_LINEAR_SLOP, CD_SPECULATIVE_DISTANCE = 4 slops), in metres.
const LINEAR_SLOP = 0.005;
const SPECULATIVE_DISTANCE = 4 * LINEAR_SLOP;

// ---- shapes ----------------------------------------------------------------------------------
const KINDS2 = ['circle', 'capsule', 'box', 'polygon', 'segment'];
const KINDS3 = ['sphere', 'capsule', 'box', 'hull'];

const LOCAL2 = {
  circle: { radius: 1 },
  capsule: { halfLength: 1, radius: 0.5 },
  box: { hx: 1.2, hy: 0.8 },
  // A convex pentagon, counter-clockwise, in its own frame.
  polygon: { points: [[-1, -0.8], [1.1, -0.6], [1.3, 0.5], [0, 1.2], [-1.1, 0.4]], radius: 0 },
  segment: { halfLength: 1.5 },
};
const LOCAL3 = {
  sphere: { radius: 0.8 },
  capsule: { halfLength: 0.6, radius: 0.45 }, // along the local y axis
  box: { hx: 0.7, hy: 0.5, hz: 0.6 },
  // The convex hull of these points (an irregular, gem-like solid).
  hull: {
    points: [[0.8, 0, 0], [-0.7, 0.1, 0], [0, 0.9, 0], [0, -0.6, 0.1], [0.1, 0, 0.8], [0, 0.1, -0.7],
      [0.5, 0.5, 0.4], [-0.4, -0.4, -0.4], [0.45, -0.45, 0.35], [-0.5, 0.4, -0.3]],
  },
};

const rot2 = (angle, [x, y]) => [Math.cos(angle) * x - Math.sin(angle) * y, Math.sin(angle) * x + Math.cos(angle) * y];

/** The shape of a 2D entity at pose (x, y, angle), as the library's plain object. */
function shape2(e, x = e.x, y = e.y, angle = e.angle) {
  const p = (lx, ly) => { const [rx, ry] = rot2(angle, [lx, ly]); return { x: x + rx, y: y + ry }; };
  const l = LOCAL2[e.kind];
  switch (e.kind) {
    case 'circle': return { type: 'circle', center: { x, y }, radius: l.radius };
    case 'capsule': return { type: 'capsule', p1: p(-l.halfLength, 0), p2: p(l.halfLength, 0), radius: l.radius };
    case 'box': return { type: 'box', center: { x, y }, halfExtents: { x: l.hx, y: l.hy }, angle };
    case 'polygon': return { type: 'polygon', vertices: l.points.map(([px, py]) => p(px, py)), radius: l.radius };
    case 'segment': return { type: 'segment', p1: p(-l.halfLength, 0), p2: p(l.halfLength, 0) };
  }
  throw new Error(`unknown 2D kind ${e.kind}`);
}

const hulls = new Map();
function hullOf(kind) {
  if (!hulls.has(kind)) hulls.set(kind, Hull.fromPoints(LOCAL3[kind].points.map(([x, y, z]) => ({ x, y, z }))));
  return hulls.get(kind);
}

/** The shape of a 3D entity at position p (THREE.Vector3) and rotation q (THREE.Quaternion). */
function shape3(e, p = e.pos, q = e.quat) {
  const l = LOCAL3[e.kind];
  const v = (x, y, z) => { const w = new THREE.Vector3(x, y, z).applyQuaternion(q).add(p); return { x: w.x, y: w.y, z: w.z }; };
  const rotation = { x: q.x, y: q.y, z: q.z, w: q.w };
  switch (e.kind) {
    case 'sphere': return { type: 'sphere', center: { x: p.x, y: p.y, z: p.z }, radius: l.radius };
    case 'capsule': return { type: 'capsule', p1: v(0, -l.halfLength, 0), p2: v(0, l.halfLength, 0), radius: l.radius };
    case 'box': return { type: 'box', center: { x: p.x, y: p.y, z: p.z }, halfExtents: { x: l.hx, y: l.hy, z: l.hz }, rotation };
    case 'hull': return { type: 'hull', hull: hullOf('hull'), position: { x: p.x, y: p.y, z: p.z }, rotation };
  }
  throw new Error(`unknown 3D kind ${e.kind}`);
}

// ---- the C functions behind each answer ------------------------------------------------------
const cap = (s) => s[0].toUpperCase() + s.slice(1);
function pairName(prefix, order, ka, kb) {
  const [a, b] = order.indexOf(ka) <= order.indexOf(kb) ? [ka, kb] : [kb, ka];
  return `${prefix}${cap(a)}${cap(b)}`;
}
const functions2 = (ka, kb) => ({
  overlap: `cd2Overlap → ${pairName('cd2Overlap', ['circle', 'capsule', 'aabb', 'box', 'polygon', 'segment'], ka, kb)}`,
  distance: 'cd2Distance (GJK)',
  manifold: `cd2Collide → ${pairName('cd2Collide', ['circle', 'capsule', 'polygon', 'segment'],
    ka === 'box' ? 'polygon' : ka, kb === 'box' ? 'polygon' : kb)}`,
  cast: 'cd2ShapeCast (GJK ray cast)',
  toi: 'cd2TimeOfImpact (conservative advancement)',
});
const functions3 = (ka, kb) => ({
  overlap: ka === 'hull' || kb === 'hull' ? 'cd3Overlap → boolean GJK (hull pair)'
    : `cd3Overlap → ${pairName('cd3Overlap', ['sphere', 'capsule', 'aabb', 'box'], ka, kb)}`,
  distance: 'cd3Distance (GJK)',
  manifold: `cd3Collide → ${pairName('cd3Collide', ['sphere', 'capsule', 'box', 'hull'], ka, kb)}`,
  cast: 'cd3ShapeCast (GJK ray cast)',
  toi: 'cd3TimeOfImpact (conservative advancement)',
});

// ---- page state ------------------------------------------------------------------------------
const SCALE = 40; // pixels per unit in the 2D view
const canvas = document.getElementById('view2d');
const ctx = canvas.getContext('2d');
const origin = { x: canvas.width / 2, y: canvas.height / 2 };
const toScreen = (p) => ({ x: origin.x + p.x * SCALE, y: origin.y - p.y * SCALE });
const toWorld = (sx, sy) => ({ x: (sx - origin.x) / SCALE, y: (origin.y - sy) / SCALE });

const state = {
  mode: '2d',
  a2: { kind: 'box', x: -4, y: 1.5, angle: 0.3 },
  b2: { kind: 'polygon', x: 3, y: -0.5, angle: 0 },
  sweep2: { x: 6, y: -1 }, // A's translation over the sweep
  spin: 0, // A's rotation over the sweep (2D)
  a3: { kind: 'box', pos: new THREE.Vector3(-2.2, 0.8, 0), quat: new THREE.Quaternion().setFromEuler(new THREE.Euler(0.2, 0.4, 0.1)) },
  b3: { kind: 'hull', pos: new THREE.Vector3(1.6, 0.8, 0), quat: new THREE.Quaternion().setFromEuler(new THREE.Euler(0, -0.3, 0.25)) },
  sweep3: new THREE.Vector3(4.5, 0, 0.3),
  results: null,
  dirty: true,
};

const hud = createHud(document.getElementById('hud'));
const demo = (window.__demo = {
  page: 'explorer',
  ready: false,
  hud: hud.state,
  view2d: { scale: SCALE, originX: origin.x, originY: origin.y },
  local2: LOCAL2,
  local3: LOCAL3,
  get mode() { return state.mode; },
  entities() {
    const e2 = (e) => ({ kind: e.kind, x: e.x, y: e.y, angle: e.angle });
    const e3 = (e) => ({ kind: e.kind, pos: e.pos.toArray(), quat: e.quat.toArray() });
    return state.mode === '2d'
      ? { a: e2(state.a2), b: e2(state.b2), sweep: { ...state.sweep2 }, spin: state.spin }
      : { a: e3(state.a3), b: e3(state.b3), sweep: state.sweep3.toArray() };
  },
  results: null,
  screenOf: null, // 3D: (name) -> canvas pixel of an entity's centre (set below)
});

// ---- queries -----------------------------------------------------------------------------------
function compute2() {
  const { a2: a, b2: b } = state;
  const sa = shape2(a);
  const sb = shape2(b);
  const manifold = manifold2(sa, sb, SPECULATIVE_DISTANCE);
  const cast = shapeCast2(sa, sb, state.sweep2);
  const toi = timeOfImpact2(
    shape2(a, 0, 0, 0), { localCenter: { x: 0, y: 0 }, center0: { x: a.x, y: a.y },
      center1: { x: a.x + state.sweep2.x, y: a.y + state.sweep2.y }, angle0: a.angle, angle1: a.angle + state.spin },
    shape2(b, 0, 0, 0), { localCenter: { x: 0, y: 0 }, center0: { x: b.x, y: b.y }, center1: { x: b.x, y: b.y },
      angle0: b.angle, angle1: b.angle },
    { targetSeparation: LINEAR_SLOP, tolerance: LINEAR_SLOP / 4 });
  return {
    dim: 2,
    overlap: overlap2(sa, sb),
    distance: distance2(sa, sb),
    manifold,
    cast,
    toi,
    speculativeDistance: SPECULATIVE_DISTANCE,
    functions: functions2(a.kind, b.kind),
  };
}

function compute3() {
  const { a3: a, b3: b } = state;
  const sa = shape3(a);
  const sb = shape3(b);
  const zero = new THREE.Vector3();
  const ident = new THREE.Quaternion();
  const q = (x) => ({ x: x.x, y: x.y, z: x.z, w: x.w });
  const v = (x) => ({ x: x.x, y: x.y, z: x.z });
  return {
    dim: 3,
    overlap: overlap3(sa, sb),
    distance: distance3(sa, sb),
    manifold: manifold3(sa, sb, SPECULATIVE_DISTANCE),
    cast: shapeCast3(sa, sb, v(state.sweep3)),
    toi: timeOfImpact3(
      shape3(a, zero, ident), { localCenter: v(zero), center0: v(a.pos), center1: v(a.pos.clone().add(state.sweep3)), rotation0: q(a.quat), rotation1: q(a.quat) },
      shape3(b, zero, ident), { localCenter: v(zero), center0: v(b.pos), center1: v(b.pos), rotation0: q(b.quat), rotation1: q(b.quat) },
      { targetSeparation: LINEAR_SLOP, tolerance: LINEAR_SLOP / 4 }),
    speculativeDistance: SPECULATIVE_DISTANCE,
    functions: functions3(a.kind, b.kind),
  };
}

// ---- the panel ---------------------------------------------------------------------------------
const panel = document.getElementById('panel');
const f = (x) => (Math.abs(x) < 5e-5 ? 0 : x).toFixed(4);
const vec = (p) => `(${f(p.x)}, ${f(p.y)}${p.z !== undefined ? `, ${f(p.z)}` : ''})`;
const TOI_STATES = ['hit', 'separated', 'overlapped', 'failed'];
function showPanel(r) {
  const fn = (s) => `<div class="fn">${s}</div>`;
  const m = r.manifold;
  const rows = m.points.map((p, i) =>
    `<tr data-point="${i}"><td>point ${i + 1}</td><td>${vec(p.point)}<br>separation <b>${f(p.separation)}</b>` +
    ` (depth ${f(Math.max(0, -p.separation))}) id ${p.id}</td></tr>`).join('');
  const toiState = typeof r.toi.state === 'number' ? TOI_STATES[r.toi.state] : r.toi.state;
  panel.innerHTML =
    `<h2>Overlap</h2>${fn(r.functions.overlap)}<table><tr><td>overlap</td><td data-overlap class="${r.overlap ? 'yes' : 'no'}">${r.overlap ? 'yes' : 'no'}</td></tr></table>` +
    `<h2>Closest points and distance</h2>${fn(r.functions.distance)}<table>` +
    `<tr><td>distance</td><td data-distance>${f(r.distance.distance)}</td></tr>` +
    `<tr><td>on A</td><td>${vec(r.distance.pointA)}</td></tr><tr><td>on B</td><td>${vec(r.distance.pointB)}</td></tr></table>` +
    `<h2>Contact manifold</h2>${fn(r.functions.manifold)}<table>` +
    `<tr><td>points</td><td data-point-count>${m.points.length}</td></tr>` +
    `<tr><td>normal (A→B)</td><td data-normal>${m.points.length ? vec(m.normal) : '—'}</td></tr>${rows}` +
    `<tr><td>speculative</td><td>${f(r.speculativeDistance)}</td></tr></table>` +
    `<h2>Sweep of A (yellow arrow)</h2>${fn(r.functions.cast)}<table>` +
    `<tr><td>shape cast</td><td data-cast>${r.cast.hit ? `hit at fraction <b>${f(r.cast.fraction)}</b>` : 'no hit'}</td></tr>` +
    (r.cast.hit ? `<tr><td>contact</td><td>${vec(r.cast.point)} n ${vec(r.cast.normal)}</td></tr>` : '') +
    `</table>${fn(r.functions.toi)}<table>` +
    `<tr><td>time of impact</td><td data-toi>${toiState}, t = <b>${f(r.toi.t)}</b></td></tr></table>`;
}

// ---- 2D view -----------------------------------------------------------------------------------
function pathShape2(s) {
  ctx.beginPath();
  if (s.type === 'circle') {
    const c = toScreen(s.center);
    ctx.arc(c.x, c.y, s.radius * SCALE, 0, 2 * Math.PI);
  } else if (s.type === 'capsule' || s.type === 'segment') {
    const p1 = toScreen(s.p1);
    const p2 = toScreen(s.p2);
    if (s.type === 'segment') {
      ctx.moveTo(p1.x, p1.y);
      ctx.lineTo(p2.x, p2.y);
      return;
    }
    const ang = Math.atan2(p2.y - p1.y, p2.x - p1.x);
    ctx.arc(p2.x, p2.y, s.radius * SCALE, ang - Math.PI / 2, ang + Math.PI / 2);
    ctx.arc(p1.x, p1.y, s.radius * SCALE, ang + Math.PI / 2, ang + 1.5 * Math.PI);
    ctx.closePath();
  } else {
    let pts = s.vertices;
    if (s.type === 'box') {
      const { x: hx, y: hy } = s.halfExtents;
      pts = [[-hx, -hy], [hx, -hy], [hx, hy], [-hx, hy]].map((p) => {
        const [rx, ry] = rot2(s.angle, p);
        return { x: s.center.x + rx, y: s.center.y + ry };
      });
    }
    pts.forEach((p, i) => { const q = toScreen(p); if (i) ctx.lineTo(q.x, q.y); else ctx.moveTo(q.x, q.y); });
    ctx.closePath();
  }
}

function drawShape2(s, fill, stroke, width = 2, dash = []) {
  pathShape2(s);
  ctx.setLineDash(dash);
  if (fill && s.type !== 'segment') { ctx.fillStyle = fill; ctx.fill(); }
  ctx.strokeStyle = stroke;
  ctx.lineWidth = s.type === 'segment' ? width + 2 : width;
  ctx.stroke();
  ctx.setLineDash([]);
}

function arrow(from, to, color, width = 2) {
  const a = toScreen(from);
  const b = toScreen(to);
  const ang = Math.atan2(b.y - a.y, b.x - a.x);
  ctx.strokeStyle = color;
  ctx.fillStyle = color;
  ctx.lineWidth = width;
  ctx.beginPath();
  ctx.moveTo(a.x, a.y);
  ctx.lineTo(b.x, b.y);
  ctx.stroke();
  ctx.beginPath();
  ctx.moveTo(b.x, b.y);
  ctx.lineTo(b.x - 10 * Math.cos(ang - 0.4), b.y - 10 * Math.sin(ang - 0.4));
  ctx.lineTo(b.x - 10 * Math.cos(ang + 0.4), b.y - 10 * Math.sin(ang + 0.4));
  ctx.closePath();
  ctx.fill();
}

function dot(p, color, r = 4) {
  const q = toScreen(p);
  ctx.fillStyle = color;
  ctx.beginPath();
  ctx.arc(q.x, q.y, r, 0, 2 * Math.PI);
  ctx.fill();
}

function draw2(r) {
  ctx.fillStyle = '#0b0e14';
  ctx.fillRect(0, 0, canvas.width, canvas.height);
  ctx.strokeStyle = '#161c28';
  ctx.lineWidth = 1;
  ctx.beginPath();
  for (let x = origin.x % SCALE; x < canvas.width; x += SCALE) { ctx.moveTo(x + 0.5, 0); ctx.lineTo(x + 0.5, canvas.height); }
  for (let y = origin.y % SCALE; y < canvas.height; y += SCALE) { ctx.moveTo(0, y + 0.5); ctx.lineTo(canvas.width, y + 0.5); }
  ctx.stroke();
  const { a2: a, b2: b } = state;
  const hitColor = r.overlap ? '#ff5c5c' : null;
  // Where A ends its sweep, and where the time of impact stops it.
  drawShape2(shape2(a, a.x + state.sweep2.x, a.y + state.sweep2.y, a.angle + state.spin), null, '#4a5570', 1, [4, 4]);
  if (r.toi.t < 1) {
    const t = r.toi.t;
    drawShape2(shape2(a, a.x + t * state.sweep2.x, a.y + t * state.sweep2.y, a.angle + t * state.spin), null, '#e8d44d', 1.5, [6, 3]);
  }
  drawShape2(shape2(b), 'rgba(240,160,64,0.25)', hitColor ?? '#f0a040');
  drawShape2(shape2(a), 'rgba(80,150,255,0.25)', hitColor ?? '#5096ff');
  arrow({ x: a.x, y: a.y }, { x: a.x + state.sweep2.x, y: a.y + state.sweep2.y }, '#e8d44d', 1.5);
  dot({ x: a.x + state.sweep2.x, y: a.y + state.sweep2.y }, '#e8d44d', 7);
  if (r.cast.hit) dot(r.cast.point, '#e8d44d', 4);
  // Closest points (green) when apart, the manifold (red points, white normal) when close.
  if (r.distance.distance > 0) {
    const pa = toScreen(r.distance.pointA);
    const pb = toScreen(r.distance.pointB);
    ctx.strokeStyle = '#5ce07a';
    ctx.lineWidth = 1.5;
    ctx.setLineDash([5, 4]);
    ctx.beginPath(); ctx.moveTo(pa.x, pa.y); ctx.lineTo(pb.x, pb.y); ctx.stroke();
    ctx.setLineDash([]);
    dot(r.distance.pointA, '#5ce07a');
    dot(r.distance.pointB, '#5ce07a');
  }
  for (const p of r.manifold.points) {
    dot(p.point, '#ff3b3b', 5);
    arrow(p.point, { x: p.point.x + r.manifold.normal.x, y: p.point.y + r.manifold.normal.y }, '#ffffff', 1.5);
  }
  ctx.fillStyle = '#8a94a8';
  ctx.font = '12px ui-monospace, monospace';
  ctx.fillText(`A: ${a.kind} (blue)   B: ${b.kind} (orange)`, 10, 18);
}

// 2D input: drag shapes or the sweep handle; wheel or Q/E turns the shape last touched.
let drag2 = null;
let last2 = 'b2';
function pick2(w) {
  const tip = { x: state.a2.x + state.sweep2.x, y: state.a2.y + state.sweep2.y };
  if (Math.hypot(w.x - tip.x, w.y - tip.y) < 0.3) return 'sweep';
  const probe = { type: 'circle', center: w, radius: 0.1 };
  for (const name of ['a2', 'b2']) if (overlap2(probe, shape2(state[name]))) return name;
  return null;
}
/** The canvas pixel under a pointer event (inside the border, in the canvas's own pixels). */
function canvasPoint(ev, el) {
  const r = el.getBoundingClientRect();
  const x = ev.clientX - r.left - el.clientLeft;
  const y = ev.clientY - r.top - el.clientTop;
  return { x: x * (el.width / el.clientWidth), y: y * (el.height / el.clientHeight) };
}
canvas.addEventListener('pointerdown', (ev) => {
  const c = canvasPoint(ev, canvas);
  const w = toWorld(c.x, c.y);
  const what = pick2(w);
  if (!what) return;
  canvas.setPointerCapture(ev.pointerId);
  const e = what === 'sweep' ? { x: state.a2.x + state.sweep2.x, y: state.a2.y + state.sweep2.y } : state[what];
  drag2 = { what, dx: e.x - w.x, dy: e.y - w.y };
  if (what !== 'sweep') last2 = what;
});
canvas.addEventListener('pointermove', (ev) => {
  if (!drag2) return;
  const c = canvasPoint(ev, canvas);
  const w = toWorld(c.x, c.y);
  if (drag2.what === 'sweep') {
    state.sweep2 = { x: w.x + drag2.dx - state.a2.x, y: w.y + drag2.dy - state.a2.y };
  } else {
    state[drag2.what].x = w.x + drag2.dx;
    state[drag2.what].y = w.y + drag2.dy;
  }
  state.dirty = true;
});
const endDrag2 = () => { drag2 = null; };
canvas.addEventListener('pointerup', endDrag2);
canvas.addEventListener('pointercancel', endDrag2);
canvas.addEventListener('wheel', (ev) => {
  const c = canvasPoint(ev, canvas);
  const what = pick2(toWorld(c.x, c.y));
  if (!what || what === 'sweep') return;
  ev.preventDefault();
  state[what].angle += ev.deltaY > 0 ? -0.05 : 0.05;
  last2 = what;
  state.dirty = true;
}, { passive: false });

// ---- 3D view -----------------------------------------------------------------------------------
const view3 = document.getElementById('view3d');
let three = null;
function setup3() {
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setSize(720, 520);
  renderer.setPixelRatio(1);
  view3.append(renderer.domElement);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x0b0e14);
  const camera = new THREE.PerspectiveCamera(45, 720 / 520, 0.1, 100);
  camera.position.set(1.5, 6, 9);
  camera.lookAt(0, 0.5, 0);
  scene.add(new THREE.HemisphereLight(0xdde8ff, 0x202430, 1.2));
  const sun = new THREE.DirectionalLight(0xffffff, 1.6);
  sun.position.set(4, 8, 5);
  scene.add(sun);
  const grid = new THREE.GridHelper(14, 14, 0x2a3245, 0x1a2030);
  grid.position.y = -0.5;
  scene.add(grid);

  const makeGeometry = (kind) => {
    const l = LOCAL3[kind];
    switch (kind) {
      case 'sphere': return new THREE.SphereGeometry(l.radius, 32, 16);
      case 'capsule': return new THREE.CapsuleGeometry(l.radius, 2 * l.halfLength, 8, 24);
      case 'box': return new THREE.BoxGeometry(2 * l.hx, 2 * l.hy, 2 * l.hz);
      case 'hull': return new ConvexGeometry(l.points.map(([x, y, z]) => new THREE.Vector3(x, y, z)));
    }
    throw new Error(kind);
  };
  const geometries = Object.fromEntries(KINDS3.map((k) => [k, makeGeometry(k)]));
  const mat = (color) => new THREE.MeshStandardMaterial({ color, transparent: true, opacity: 0.7, roughness: 0.6, flatShading: true });
  const meshes = { a3: new THREE.Mesh(geometries.box, mat(0x5096ff)), b3: new THREE.Mesh(geometries.hull, mat(0xf0a040)) };
  const ghost = new THREE.Mesh(geometries.box, new THREE.MeshBasicMaterial({ color: 0xe8d44d, wireframe: true }));
  scene.add(meshes.a3, meshes.b3, ghost);
  const handle = new THREE.Mesh(new THREE.SphereGeometry(0.15, 16, 8), new THREE.MeshBasicMaterial({ color: 0xe8d44d }));
  scene.add(handle);
  const sweepArrow = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(), 1, 0xe8d44d, 0.3, 0.15);
  scene.add(sweepArrow);
  const contactDots = [0, 1, 2, 3].map(() => new THREE.Mesh(new THREE.SphereGeometry(0.07, 12, 8), new THREE.MeshBasicMaterial({ color: 0xff3b3b, depthTest: false, transparent: true })));
  contactDots.forEach((d) => { d.renderOrder = 2; scene.add(d); });
  const normalArrow = new THREE.ArrowHelper(new THREE.Vector3(0, 1, 0), new THREE.Vector3(), 1, 0xffffff, 0.25, 0.12);
  scene.add(normalArrow);
  const closestGeom = new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(), new THREE.Vector3()]);
  const closestLine = new THREE.Line(closestGeom, new THREE.LineBasicMaterial({ color: 0x5ce07a, depthTest: false, transparent: true }));
  closestLine.renderOrder = 2;
  scene.add(closestLine);
  const closestDots = [0, 1].map(() => new THREE.Mesh(new THREE.SphereGeometry(0.06, 12, 8), new THREE.MeshBasicMaterial({ color: 0x5ce07a, depthTest: false, transparent: true })));
  closestDots.forEach((d) => { d.renderOrder = 2; scene.add(d); });
  three = { renderer, scene, camera, meshes, ghost, handle, sweepArrow, contactDots, normalArrow, closestLine, closestDots, geometries };

  // Input: drag a shape (or the sweep handle) on the horizontal plane through it; shift-drag
  // moves it vertically; the wheel turns it about the vertical axis, Q / E about x.
  const raycaster = new THREE.Raycaster();
  const ndc = new THREE.Vector2();
  let drag = null;
  const el = renderer.domElement;
  const rayAt = (ev) => {
    const c = canvasPoint(ev, el);
    ndc.set((c.x / el.width) * 2 - 1, -(c.y / el.height) * 2 + 1);
    raycaster.setFromCamera(ndc, camera);
    return raycaster.ray;
  };
  const pickAt = (ray) => {
    raycaster.ray.copy(ray);
    const hits = raycaster.intersectObjects([handle, meshes.a3, meshes.b3], false);
    if (!hits.length) return null;
    const o = hits[0].object;
    return o === handle ? 'sweep' : o === meshes.a3 ? 'a3' : 'b3';
  };
  const planeHit = (ray, plane) => ray.intersectPlane(plane, new THREE.Vector3());
  el.addEventListener('pointerdown', (ev) => {
    const ray = rayAt(ev);
    const what = pickAt(ray);
    if (!what) return;
    el.setPointerCapture(ev.pointerId);
    const p0 = what === 'sweep' ? state.a3.pos.clone().add(state.sweep3) : state[what].pos.clone();
    const normal = ev.shiftKey
      ? new THREE.Vector3().subVectors(camera.position, p0).setY(0).normalize()
      : new THREE.Vector3(0, 1, 0);
    const plane = new THREE.Plane().setFromNormalAndCoplanarPoint(normal, p0);
    const hit = planeHit(ray, plane);
    if (!hit) return;
    drag = { what, plane, offset: p0.clone().sub(hit) };
    if (what !== 'sweep') last3 = what;
  });
  el.addEventListener('pointermove', (ev) => {
    if (!drag) return;
    const hit = planeHit(rayAt(ev), drag.plane);
    if (!hit) return;
    const p = hit.add(drag.offset);
    if (drag.what === 'sweep') state.sweep3.copy(p.sub(state.a3.pos));
    else state[drag.what].pos.copy(p);
    state.dirty = true;
  });
  const end = () => { drag = null; };
  el.addEventListener('pointerup', end);
  el.addEventListener('pointercancel', end);
  el.addEventListener('wheel', (ev) => {
    const what = pickAt(rayAt(ev));
    if (!what || what === 'sweep') return;
    ev.preventDefault();
    state[what].quat.premultiply(new THREE.Quaternion().setFromAxisAngle(new THREE.Vector3(0, 1, 0), ev.deltaY > 0 ? -0.05 : 0.05));
    last3 = what;
    state.dirty = true;
  }, { passive: false });

  demo.screenOf = (name) => {
    const p = name === 'sweep' ? state.a3.pos.clone().add(state.sweep3) : state[name === 'a' ? 'a3' : name === 'b' ? 'b3' : name].pos.clone();
    p.project(camera);
    const r = el.getBoundingClientRect();
    return { x: r.left + el.clientLeft + ((p.x + 1) / 2) * el.clientWidth, y: r.top + el.clientTop + ((1 - p.y) / 2) * el.clientHeight };
  };
}
let last3 = 'b3';

function draw3(r) {
  const t = three;
  for (const name of ['a3', 'b3']) {
    const e = state[name];
    const m = t.meshes[name];
    m.geometry = t.geometries[e.kind];
    m.position.copy(e.pos);
    m.quaternion.copy(e.quat);
    m.material.emissive.setHex(r.overlap ? 0x551010 : 0x000000);
  }
  const a = state.a3;
  t.handle.position.copy(a.pos).add(state.sweep3);
  const len = state.sweep3.length();
  t.sweepArrow.visible = len > 1e-3;
  if (len > 1e-3) {
    t.sweepArrow.position.copy(a.pos);
    t.sweepArrow.setDirection(state.sweep3.clone().normalize());
    t.sweepArrow.setLength(len, Math.min(0.3, len * 0.3), 0.15);
  }
  t.ghost.visible = r.toi.t < 1;
  t.ghost.geometry = t.geometries[a.kind];
  t.ghost.position.copy(a.pos).addScaledVector(state.sweep3, r.toi.t);
  t.ghost.quaternion.copy(a.quat);
  const pts = r.manifold.points;
  t.contactDots.forEach((d, i) => {
    d.visible = i < pts.length;
    if (d.visible) d.position.set(pts[i].point.x, pts[i].point.y, pts[i].point.z);
  });
  t.normalArrow.visible = pts.length > 0;
  if (pts.length) {
    const c = new THREE.Vector3();
    pts.forEach((p) => c.add(new THREE.Vector3(p.point.x, p.point.y, p.point.z)));
    c.multiplyScalar(1 / pts.length);
    t.normalArrow.position.copy(c);
    t.normalArrow.setDirection(new THREE.Vector3(r.manifold.normal.x, r.manifold.normal.y, r.manifold.normal.z));
  }
  const apart = r.distance.distance > 0;
  t.closestLine.visible = apart;
  t.closestDots.forEach((d) => { d.visible = apart; });
  if (apart) {
    const { pointA: pa, pointB: pb } = r.distance;
    t.closestLine.geometry.setFromPoints([new THREE.Vector3(pa.x, pa.y, pa.z), new THREE.Vector3(pb.x, pb.y, pb.z)]);
    t.closestDots[0].position.set(pa.x, pa.y, pa.z);
    t.closestDots[1].position.set(pb.x, pb.y, pb.z);
  }
  t.renderer.render(t.scene, t.camera);
}

// ---- controls ----------------------------------------------------------------------------------
const selA = document.getElementById('kindA');
const selB = document.getElementById('kindB');
const spin = document.getElementById('spin');
function fillSelects() {
  const kinds = state.mode === '2d' ? KINDS2 : KINDS3;
  const [ka, kb] = state.mode === '2d' ? [state.a2.kind, state.b2.kind] : [state.a3.kind, state.b3.kind];
  for (const [sel, k] of [[selA, ka], [selB, kb]]) {
    sel.innerHTML = kinds.map((x) => `<option value="${x}"${x === k ? ' selected' : ''}>${x}</option>`).join('');
  }
  spin.disabled = state.mode !== '2d';
}
selA.addEventListener('change', () => { state[state.mode === '2d' ? 'a2' : 'a3'].kind = selA.value; state.dirty = true; });
selB.addEventListener('change', () => { state[state.mode === '2d' ? 'b2' : 'b3'].kind = selB.value; state.dirty = true; });
spin.addEventListener('input', () => { state.spin = Number(spin.value); state.dirty = true; });
for (const radio of document.querySelectorAll('input[name=mode]')) {
  radio.addEventListener('change', () => {
    if (!radio.checked) return;
    state.mode = radio.value;
    canvas.style.display = state.mode === '2d' ? '' : 'none';
    view3.style.display = state.mode === '3d' ? '' : 'none';
    if (state.mode === '3d' && !three) setup3();
    fillSelects();
    state.dirty = true;
  });
}
window.addEventListener('keydown', (ev) => {
  const k = ev.key.toLowerCase();
  if (k !== 'q' && k !== 'e') return;
  const s = k === 'q' ? 1 : -1;
  if (state.mode === '2d') state[last2].angle += 0.1 * s;
  else state[last3].quat.premultiply(new THREE.Quaternion().setFromAxisAngle(new THREE.Vector3(1, 0, 0), 0.1 * s));
  state.dirty = true;
});

const nav = document.querySelector('header nav');
for (const [id, title] of PAGES) {
  const a = document.createElement('a');
  a.href = `../${id}/`;
  a.textContent = title;
  if (id === 'explorer') a.setAttribute('aria-current', 'page');
  nav.append(a);
}

// ---- start -------------------------------------------------------------------------------------
try {
  await initCollide();
} catch (err) {
  document.getElementById('hud').textContent = `collide did not load: ${err.message}`;
  throw err;
}
fillSelects();
runLoop(hud, () => {
  if (state.dirty) {
    state.results = state.mode === '2d' ? compute2() : compute3();
    demo.results = state.results;
    state.dirty = false;
    showPanel(state.results);
  }
  if (state.mode === '2d') draw2(state.results);
  else draw3(state.results);
  return [2, 'shapes'];
});
demo.ready = true;
