// Bounding volumes in 3D: the texts' point / AABB / sphere tests on objects the user drags
// (with an oriented box, a capsule and a hull beside them), overlaps and contact points live,
// and a broadphase of thousands of moving boxes drawn with its pairs. Every answer comes from
// collide (wasm, through the JavaScript package).
import * as THREE from 'three';
import { ConvexGeometry } from 'three/addons/geometries/ConvexGeometry.js';
import { createHud, runLoop, PAGES } from '../common/hud.js';
import { initCollide } from '../common/collide.js';
import {
  Hull, BroadPhase3, isPointInsideAABB, isPointInsideSphere, intersectAABB, intersectSphere,
  intersectSphereAABB, containsPoint3, overlap3, manifold3,
} from 'collide';

const W = 760;
const H = 540;
const hud = createHud(document.getElementById('hud'));
const panel = document.getElementById('panel');
const demo = (window.__demo = { page: 'bounds3d', ready: false, hud: hud.state, mode: 'tests' });

const nav = document.querySelector('header nav');
for (const [id, title] of PAGES) {
  const a = document.createElement('a');
  a.href = `../${id}/`;
  a.textContent = title;
  if (id === 'bounds3d') a.setAttribute('aria-current', 'page');
  nav.append(a);
}

// ---- renderer and the two scenes ---------------------------------------------------------------
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setSize(W, H);
renderer.setPixelRatio(1);
document.getElementById('view').append(renderer.domElement);
const el = renderer.domElement;

function makeScene(gridSize) {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x0b0e14);
  scene.add(new THREE.HemisphereLight(0xdde8ff, 0x202430, 1.2));
  const sun = new THREE.DirectionalLight(0xffffff, 1.5);
  sun.position.set(5, 10, 6);
  scene.add(sun);
  scene.add(new THREE.GridHelper(gridSize, gridSize, 0x2a3245, 0x1a2030));
  return scene;
}

// ==== mode 1: the texts' tests on objects the user drags ==========================================
const testScene = makeScene(12);
const testCamera = new THREE.PerspectiveCamera(45, W / H, 0.1, 200);
testCamera.position.set(0, 8.5, 10.5);
testCamera.lookAt(0, 0.3, 0);

const GEM = [[0.8, 0, 0], [-0.7, 0.1, 0], [0, 0.9, 0], [0, -0.6, 0.1], [0.1, 0, 0.8], [0, 0.1, -0.7],
  [0.5, 0.5, 0.4], [-0.4, -0.4, -0.4], [0.45, -0.45, 0.35], [-0.5, 0.4, -0.3]];

const euler = (x, y, z) => new THREE.Quaternion().setFromEuler(new THREE.Euler(x, y, z));
// Each object: a kind, a pose (position; rotation for the oriented ones) and its size.
const objects = [
  { name: 'point', kind: 'point', pos: new THREE.Vector3(0.3, 0.6, 0.4) },
  { name: 'aabb1', kind: 'aabb', pos: new THREE.Vector3(-2.4, 0.6, -0.3), half: new THREE.Vector3(0.7, 0.6, 0.8) },
  { name: 'aabb2', kind: 'aabb', pos: new THREE.Vector3(2.6, 0.5, 1.4), half: new THREE.Vector3(0.6, 0.5, 0.6) },
  { name: 'sphere1', kind: 'sphere', pos: new THREE.Vector3(-0.9, 0.7, 2.4), radius: 0.7 },
  { name: 'sphere2', kind: 'sphere', pos: new THREE.Vector3(1.3, 0.8, -1.6), radius: 0.8 },
  { name: 'box', kind: 'box', pos: new THREE.Vector3(-0.6, 0.6, -3.2), half: new THREE.Vector3(0.9, 0.4, 0.5), quat: euler(0, 0.6, 0.3) },
  { name: 'capsule', kind: 'capsule', pos: new THREE.Vector3(3.8, 0.8, -1.4), halfLength: 0.6, radius: 0.35, quat: euler(0, 0, 1.0) },
  { name: 'hull', kind: 'hull', pos: new THREE.Vector3(-3.6, 0.8, 2.6), quat: euler(0.3, 0.2, 0) },
];
const byName = Object.fromEntries(objects.map((o) => [o.name, o]));
let gemHull = null;

/** The library's shape (world space) of an object; AABBs also in the texts' form. */
function shapeOf(o) {
  const p = { x: o.pos.x, y: o.pos.y, z: o.pos.z };
  const q = o.quat ? { x: o.quat.x, y: o.quat.y, z: o.quat.z, w: o.quat.w } : null;
  switch (o.kind) {
    case 'aabb': return { type: 'aabb', min: { x: p.x - o.half.x, y: p.y - o.half.y, z: p.z - o.half.z }, max: { x: p.x + o.half.x, y: p.y + o.half.y, z: p.z + o.half.z } };
    case 'sphere': return { type: 'sphere', center: p, radius: o.radius };
    case 'box': return { type: 'box', center: p, halfExtents: { x: o.half.x, y: o.half.y, z: o.half.z }, rotation: q };
    case 'capsule': {
      const axis = new THREE.Vector3(0, o.halfLength, 0).applyQuaternion(o.quat);
      return { type: 'capsule', p1: { x: p.x - axis.x, y: p.y - axis.y, z: p.z - axis.z }, p2: { x: p.x + axis.x, y: p.y + axis.y, z: p.z + axis.z }, radius: o.radius };
    }
    case 'hull': return { type: 'hull', hull: gemHull, position: p, rotation: q };
  }
  return null;
}
const textAabb = (s) => ({ minX: s.min.x, maxX: s.max.x, minY: s.min.y, maxY: s.max.y, minZ: s.min.z, maxZ: s.max.z });
const textSphere = (s) => ({ x: s.center.x, y: s.center.y, z: s.center.z, radius: s.radius });

/** Tests one pair with the function a web developer would call, and names it and its C function. */
function testPair(a, b) {
  const sa = shapeOf(a);
  const sb = shapeOf(b);
  if (a.kind === 'point' || b.kind === 'point') {
    const [pt, o, so] = a.kind === 'point' ? [a, b, sb] : [b, a, sa];
    const point = { x: pt.pos.x, y: pt.pos.y, z: pt.pos.z };
    if (o.kind === 'aabb') return { hit: isPointInsideAABB(point, textAabb(so)), fn: 'isPointInsideAABB', c: 'cd3PointInAabb' };
    if (o.kind === 'sphere') return { hit: isPointInsideSphere(point, textSphere(so)), fn: 'isPointInsideSphere', c: 'cd3PointInSphere' };
    return { hit: containsPoint3(so, point), fn: 'containsPoint3', c: `cd3PointInShape → cd3PointIn${o.kind[0].toUpperCase()}${o.kind.slice(1)}` };
  }
  if (a.kind === 'aabb' && b.kind === 'aabb') return { hit: intersectAABB(textAabb(sa), textAabb(sb)), fn: 'intersectAABB', c: 'cd3OverlapAabbAabb' };
  if (a.kind === 'sphere' && b.kind === 'sphere') return { hit: intersectSphere(textSphere(sa), textSphere(sb)), fn: 'intersectSphere', c: 'cd3OverlapSphereSphere' };
  if (a.kind === 'sphere' && b.kind === 'aabb') return { hit: intersectSphereAABB(textSphere(sa), textAabb(sb)), fn: 'intersectSphereAABB', c: 'cd3OverlapSphereAabb' };
  if (a.kind === 'aabb' && b.kind === 'sphere') return { hit: intersectSphereAABB(textSphere(sb), textAabb(sa)), fn: 'intersectSphereAABB', c: 'cd3OverlapSphereAabb' };
  const order = ['sphere', 'capsule', 'aabb', 'box'];
  const cap = (s) => s[0].toUpperCase() + s.slice(1);
  const [x, y] = order.indexOf(a.kind) <= order.indexOf(b.kind) ? [a.kind, b.kind] : [b.kind, a.kind];
  const c = a.kind === 'hull' || b.kind === 'hull' ? 'cd3Overlap → boolean GJK' : `cd3Overlap → cd3Overlap${cap(x)}${cap(y)}`;
  return { hit: overlap3(sa, sb), fn: 'overlap3', c };
}

/** The manifold of two overlapping solids (AABBs as boxes without rotation). */
function contactPoints(a, b) {
  const asBox = (o) => {
    const s = shapeOf(o);
    if (o.kind !== 'aabb') return s;
    return { type: 'box', center: { x: o.pos.x, y: o.pos.y, z: o.pos.z }, halfExtents: { x: o.half.x, y: o.half.y, z: o.half.z }, rotation: { x: 0, y: 0, z: 0, w: 1 } };
  };
  return manifold3(asBox(a), asBox(b), 0).points;
}

// Meshes.
const baseColor = { point: 0xffffff, aabb: 0x5096ff, sphere: 0x50c8a0, box: 0xc080ff, capsule: 0xf0a040, hull: 0xe8d44d };
for (const o of objects) {
  let geometry;
  switch (o.kind) {
    case 'point': geometry = new THREE.SphereGeometry(0.09, 16, 8); break;
    case 'aabb': geometry = new THREE.BoxGeometry(2 * o.half.x, 2 * o.half.y, 2 * o.half.z); break;
    case 'sphere': geometry = new THREE.SphereGeometry(o.radius, 32, 16); break;
    case 'box': geometry = new THREE.BoxGeometry(2 * o.half.x, 2 * o.half.y, 2 * o.half.z); break;
    case 'capsule': geometry = new THREE.CapsuleGeometry(o.radius, 2 * o.halfLength, 8, 24); break;
    case 'hull': geometry = new ConvexGeometry(GEM.map(([x, y, z]) => new THREE.Vector3(x, y, z))); break;
  }
  const material = o.kind === 'point'
    ? new THREE.MeshBasicMaterial({ color: baseColor.point, depthTest: false, transparent: true })
    : new THREE.MeshStandardMaterial({ color: baseColor[o.kind], transparent: true, opacity: 0.55, roughness: 0.6, flatShading: o.kind === 'hull' });
  o.mesh = new THREE.Mesh(geometry, material);
  o.mesh.userData.name = o.name;
  if (o.kind === 'point') o.mesh.renderOrder = 3;
  if (o.kind === 'aabb') {
    o.edges = new THREE.LineSegments(new THREE.EdgesGeometry(geometry), new THREE.LineBasicMaterial({ color: 0x9cc4ff }));
    o.mesh.add(o.edges);
  }
  testScene.add(o.mesh);
}
const contactPool = Array.from({ length: 96 }, () => {
  const m = new THREE.Mesh(new THREE.SphereGeometry(0.06, 10, 6), new THREE.MeshBasicMaterial({ color: 0xff3b3b, depthTest: false, transparent: true }));
  m.renderOrder = 4;
  m.visible = false;
  testScene.add(m);
  return m;
});

let testDirty = true;
let testResult = { pairs: [], overlaps: [], contacts: 0 };
function updateTests() {
  const pairs = [];
  const touched = new Set();
  let nContacts = 0;
  for (let i = 0; i < objects.length; i++) {
    for (let j = i + 1; j < objects.length; j++) {
      const a = objects[i];
      const b = objects[j];
      const r = testPair(a, b);
      pairs.push({ a: a.name, b: b.name, ...r });
      if (!r.hit) continue;
      touched.add(a.name);
      touched.add(b.name);
      if (a.kind !== 'point' && b.kind !== 'point') {
        for (const p of contactPoints(a, b)) {
          if (nContacts < contactPool.length) contactPool[nContacts].position.set(p.point.x, p.point.y, p.point.z);
          nContacts++;
        }
      }
    }
  }
  contactPool.forEach((m, i) => { m.visible = i < nContacts; });
  for (const o of objects) {
    const hit = touched.has(o.name);
    if (o.kind === 'point') o.mesh.material.color.setHex(hit ? 0xff3b3b : baseColor.point);
    else {
      o.mesh.material.color.setHex(hit ? 0xff5c5c : baseColor[o.kind]);
      o.mesh.material.emissive.setHex(hit ? 0x401010 : 0x000000);
    }
  }
  const overlaps = pairs.filter((p) => p.hit).map((p) => `${p.a}|${p.b}`);
  testResult = { pairs, overlaps, contacts: nContacts };
  const rows = pairs.filter((p) => p.hit).map((p) =>
    `<tr data-overlap="${p.a}|${p.b}"><td>${p.a} × ${p.b}</td><td><span class="fn">${p.fn}</span><br><span class="fn" style="color:var(--dim)">${p.c}</span></td></tr>`).join('');
  panel.innerHTML =
    `<h2>Overlapping now (${overlaps.length} of ${pairs.length} pairs)</h2>` +
    `<table>${rows || '<tr><td>none</td><td>drag an object onto another</td></tr>'}</table>` +
    `<h2>Contact points</h2><table><tr><td>points</td><td data-contacts>${nContacts}</td></tr>` +
    `<tr><td>from</td><td><span class="fn">manifold3</span><br><span class="fn" style="color:var(--dim)">cd3Collide (AABBs as boxes)</span></td></tr></table>` +
    `<h2>The texts' functions</h2><p style="margin:0;color:var(--dim)">isPointInsideAABB(point, box), intersectAABB(a, b), ` +
    `isPointInsideSphere(point, sphere), intersectSphere(a, b), intersectSphereAABB(sphere, box) take the texts' plain objects ` +
    `({x, y, z}, {minX, maxX, ...}, {x, y, z, radius}); touching counts.</p>`;
  demo.tests = testResult;
}

// Dragging in the test scene.
const raycaster = new THREE.Raycaster();
const ndc = new THREE.Vector2();
let drag = null;
function rayAt(ev) {
  const r = el.getBoundingClientRect();
  const x = (ev.clientX - r.left - el.clientLeft) / el.clientWidth;
  const y = (ev.clientY - r.top - el.clientTop) / el.clientHeight;
  ndc.set(x * 2 - 1, -y * 2 + 1);
  raycaster.setFromCamera(ndc, testCamera);
  return raycaster.ray.clone();
}
function pick(ray) {
  raycaster.ray.copy(ray);
  // The point first (it is small and often inside another object).
  const point = byName.point;
  if (ray.distanceToPoint(point.pos) < 0.25) return point;
  const hits = raycaster.intersectObjects(objects.map((o) => o.mesh), false);
  return hits.length ? byName[hits[0].object.userData.name] : null;
}
el.addEventListener('pointerdown', (ev) => {
  if (demo.mode !== 'tests') return;
  const ray = rayAt(ev);
  const o = pick(ray);
  if (!o) return;
  el.setPointerCapture(ev.pointerId);
  const normal = ev.shiftKey ? new THREE.Vector3().subVectors(testCamera.position, o.pos).setY(0).normalize() : new THREE.Vector3(0, 1, 0);
  const plane = new THREE.Plane().setFromNormalAndCoplanarPoint(normal, o.pos);
  const hit = ray.intersectPlane(plane, new THREE.Vector3());
  if (!hit) return;
  drag = { o, plane, offset: o.pos.clone().sub(hit) };
});
el.addEventListener('pointermove', (ev) => {
  if (!drag) return;
  const hit = rayAt(ev).intersectPlane(drag.plane, new THREE.Vector3());
  if (!hit) return;
  drag.o.pos.copy(hit.add(drag.offset));
  testDirty = true;
});
const endDrag = () => { drag = null; };
el.addEventListener('pointerup', endDrag);
el.addEventListener('pointercancel', endDrag);
el.addEventListener('wheel', (ev) => {
  if (demo.mode !== 'tests') return;
  const o = pick(rayAt(ev));
  if (!o || !o.quat) return;
  ev.preventDefault();
  o.quat.premultiply(new THREE.Quaternion().setFromAxisAngle(new THREE.Vector3(0, 1, 0), ev.deltaY > 0 ? -0.08 : 0.08));
  testDirty = true;
}, { passive: false });

// Name labels over the objects (the names the panel uses).
const view = document.getElementById('view');
view.style.position = 'relative';
const labels = Object.fromEntries(objects.map((o) => {
  const span = document.createElement('span');
  span.textContent = o.name;
  span.style.cssText = 'position:absolute;pointer-events:none;font:11px ui-monospace,monospace;color:#c8d0e0;' +
    'transform:translate(-50%,-100%);text-shadow:0 0 3px #000;white-space:nowrap';
  view.append(span);
  return [o.name, span];
}));
const labelPos = new THREE.Vector3();

function frameTests() {
  if (testDirty) {
    updateTests();
    testDirty = false;
  }
  for (const o of objects) {
    o.mesh.position.copy(o.pos);
    if (o.quat) o.mesh.quaternion.copy(o.quat);
    labelPos.copy(o.pos).setY(o.pos.y + (o.kind === 'point' ? 0.25 : 1.0)).project(testCamera);
    const label = labels[o.name];
    label.style.display = '';
    label.style.left = `${el.clientLeft + ((labelPos.x + 1) / 2) * el.clientWidth}px`;
    label.style.top = `${el.clientTop + ((1 - labelPos.y) / 2) * el.clientHeight}px`;
  }
  renderer.render(testScene, testCamera);
  return [objects.length, 'objects'];
}

demo.objects = () => objects.map((o) => {
  const s = shapeOf(o);
  if (o.kind === 'point') return { name: o.name, kind: o.kind, point: { x: o.pos.x, y: o.pos.y, z: o.pos.z } };
  if (o.kind === 'hull') return { name: o.name, kind: o.kind, points: GEM, position: s.position, rotation: s.rotation };
  return { name: o.name, kind: o.kind, shape: s };
});
demo.screenOf = (name) => {
  const p = byName[name].pos.clone().project(testCamera);
  const r = el.getBoundingClientRect();
  return { x: r.left + el.clientLeft + ((p.x + 1) / 2) * el.clientWidth, y: r.top + el.clientTop + ((1 - p.y) / 2) * el.clientHeight };
};

// ==== mode 2: a broadphase of thousands of moving boxes ==========================================
const broadScene = makeScene(40);
const broadCamera = new THREE.PerspectiveCamera(50, W / H, 0.5, 400);
broadCamera.position.set(0, 30, 42);
broadCamera.lookAt(0, 4, 0);
const REGION = { min: [-20, 0, -20], max: [20, 14, 20] };
const MAX_BOXES = 5000;
const MAX_LINES = 20000;

let broad = null; // { n, bp, ids, boxes (Float32Array 6n), centers, half, vel, mesh, lines, pairs }
function rng(seed) {
  let s = seed >>> 0;
  return () => {
    s = (s + 0x6d2b79f5) >>> 0;
    let t = s;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

function setupBroad(n) {
  if (broad) {
    broad.bp.destroy();
    broadScene.remove(broad.mesh, broad.lines);
    broad.mesh.geometry.dispose();
    broad.lines.geometry.dispose();
  }
  const rand = rng(12345);
  const centers = new Float32Array(3 * n);
  const half = new Float32Array(3 * n);
  const vel = new Float32Array(3 * n);
  const boxes = new Float32Array(6 * n);
  for (let i = 0; i < n; i++) {
    for (let k = 0; k < 3; k++) {
      half[3 * i + k] = 0.15 + 0.3 * rand();
      centers[3 * i + k] = REGION.min[k] + 1 + (REGION.max[k] - REGION.min[k] - 2) * rand();
      vel[3 * i + k] = (rand() - 0.5) * 6;
    }
  }
  const mesh = new THREE.InstancedMesh(new THREE.BoxGeometry(1, 1, 1), new THREE.MeshLambertMaterial(), n);
  mesh.instanceMatrix.setUsage(THREE.DynamicDrawUsage);
  const color = new THREE.Color(0x4a6fb0);
  for (let i = 0; i < n; i++) mesh.setColorAt(i, color);
  const lineGeom = new THREE.BufferGeometry();
  lineGeom.setAttribute('position', new THREE.BufferAttribute(new Float32Array(MAX_LINES * 6), 3).setUsage(THREE.DynamicDrawUsage));
  lineGeom.setDrawRange(0, 0);
  // Drawn over the boxes (the centres of touching boxes lie inside them).
  const lines = new THREE.LineSegments(lineGeom, new THREE.LineBasicMaterial({ color: 0xffe070, depthTest: false, transparent: true }));
  lines.frustumCulled = false;
  lines.renderOrder = 2;
  broadScene.add(mesh, lines);
  fillBoxes(n, centers, half, boxes);
  // Margin 0: the fat boxes are the tight boxes, so the pairs of a frame are exactly the boxes
  // that overlap now (touching counts).
  const bp = new BroadPhase3({ type: structureSel.value, margin: 0 });
  const ids = bp.createProxies(boxes);
  broad = { n, bp, ids, boxes, centers, half, vel, mesh, lines, pairs: new Int32Array(0), paused: false, inPair: new Uint8Array(n), collideMs: 0, steps: 0 };
  demo.broad.n = n;
}
function fillBoxes(n, c, h, out) {
  for (let i = 0; i < n; i++) {
    for (let k = 0; k < 3; k++) {
      out[6 * i + k] = c[3 * i + k] - h[3 * i + k];
      out[6 * i + 3 + k] = c[3 * i + k] + h[3 * i + k];
    }
  }
}

const tmpMatrix = new THREE.Matrix4();
const tmpPos = new THREE.Vector3();
const tmpScale = new THREE.Vector3();
const noRotation = new THREE.Quaternion();
const pairColor = new THREE.Color(0xff5c5c);
const freeColor = new THREE.Color(0x4a6fb0);
let lastBroadTime = 0;
function frameBroad(now) {
  const b = broad;
  const dt = lastBroadTime ? Math.min((now - lastBroadTime) / 1000, 1 / 30) : 1 / 60;
  lastBroadTime = now;
  if (!b.paused) {
    const { n, centers: c, half: h, vel: v } = b;
    for (let i = 0; i < 3 * n; i++) {
      const k = i % 3;
      c[i] += v[i] * dt;
      if (c[i] - h[i] < REGION.min[k]) { c[i] = REGION.min[k] + h[i]; v[i] = Math.abs(v[i]); }
      if (c[i] + h[i] > REGION.max[k]) { c[i] = REGION.max[k] - h[i]; v[i] = -Math.abs(v[i]); }
    }
    fillBoxes(n, c, h, b.boxes);
    const t0 = performance.now();
    b.bp.moveProxies(b.ids, b.boxes);
    b.pairs = b.bp.findAllPairs();
    // Mean over about a second of frames: what collide itself costs per frame.
    b.collideMs += ((performance.now() - t0) - b.collideMs) / Math.min(++b.steps, 60);
  }
  // Draw: boxes (red when in a pair) and a line between the centres of each pair.
  const { n, centers: c, half: h, pairs, inPair } = b;
  inPair.fill(0);
  const pos = b.lines.geometry.attributes.position.array;
  const nPairs = pairs.length / 2;
  const nLines = Math.min(nPairs, MAX_LINES);
  for (let p = 0; p < nPairs; p++) {
    const i = pairs[2 * p];
    const j = pairs[2 * p + 1];
    inPair[i] = 1;
    inPair[j] = 1;
    if (p < nLines) {
      pos.set([c[3 * i], c[3 * i + 1], c[3 * i + 2], c[3 * j], c[3 * j + 1], c[3 * j + 2]], 6 * p);
    }
  }
  b.lines.geometry.setDrawRange(0, 2 * nLines);
  b.lines.geometry.attributes.position.needsUpdate = true;
  for (let i = 0; i < n; i++) {
    tmpPos.set(c[3 * i], c[3 * i + 1], c[3 * i + 2]);
    tmpScale.set(2 * h[3 * i], 2 * h[3 * i + 1], 2 * h[3 * i + 2]);
    b.mesh.setMatrixAt(i, tmpMatrix.compose(tmpPos, noRotation, tmpScale));
    b.mesh.setColorAt(i, inPair[i] ? pairColor : freeColor);
  }
  b.mesh.instanceMatrix.needsUpdate = true;
  b.mesh.instanceColor.needsUpdate = true;
  renderer.render(broadScene, broadCamera);
  if (performance.now() - (b.shown ?? 0) > 250) {
    b.shown = performance.now();
    panel.innerHTML =
      `<h2>Broadphase</h2><table>` +
      `<tr><td>boxes</td><td data-boxes>${n}</td></tr>` +
      `<tr><td>pairs this frame</td><td data-pairs>${nPairs}</td></tr>` +
      `<tr><td>collide per frame</td><td>${b.collideMs.toFixed(2)} ms (move + pairs)</td></tr>` +
      `<tr><td>structure</td><td><span class="fn">new BroadPhase3({ type: '${structureSel.value}', margin: 0 })</span></td></tr>` +
      `<tr><td>per frame</td><td><span class="fn">bp.moveProxies(ids, boxes)</span> → cd3BroadPhase_MoveProxies<br>` +
      `<span class="fn">bp.findAllPairs()</span> → cd3BroadPhase_FindAllPairs, all pairs as one Int32Array</td></tr></table>` +
      `<p style="color:var(--dim)">Boxes in a pair are red; a yellow line joins the centres of each pair. ` +
      `Margin 0: a pair is two boxes that overlap in this frame.</p>`;
  }
  return [n, 'boxes'];
}
demo.broad = {
  n: 0,
  setPaused(p) { if (broad) broad.paused = p; },
  /** The boxes and pairs of the last frame (for the browser test). */
  snapshot() {
    return broad ? { boxes: Array.from(broad.boxes), pairs: Array.from(broad.pairs), ids: Array.from(broad.ids) } : null;
  },
  setCount(n) { setupBroad(n); },
};

// ---- modes -----------------------------------------------------------------------------------------
const countSel = document.getElementById('count');
const structureSel = document.getElementById('structure');
countSel.addEventListener('change', () => setupBroad(Number(countSel.value)));
structureSel.addEventListener('change', () => setupBroad(Number(countSel.value)));
for (const radio of document.querySelectorAll('input[name=mode]')) {
  radio.addEventListener('change', () => {
    if (!radio.checked) return;
    demo.mode = radio.value;
    document.getElementById('countLabel').style.display = demo.mode === 'broad' ? '' : 'none';
    document.getElementById('structureLabel').style.display = demo.mode === 'broad' ? '' : 'none';
    document.getElementById('physicsPending').style.display = demo.mode === 'physics' ? '' : 'none';
    document.getElementById('help').style.display = demo.mode === 'tests' ? '' : 'none';
    el.style.display = demo.mode === 'physics' ? 'none' : '';
    if (demo.mode !== 'tests') for (const span of Object.values(labels)) span.style.display = 'none';
    if (demo.mode === 'broad' && !broad) setupBroad(Number(countSel.value));
    if (demo.mode === 'tests') testDirty = true;
    if (demo.mode === 'physics') {
      panel.innerHTML = '<h2>Physics</h2><p data-pending>needs the 3D world: collide\'s 3D world is not written yet, ' +
        'so this mode simulates nothing.</p>';
    }
  });
}

try {
  await initCollide();
} catch (err) {
  document.getElementById('hud').textContent = `collide did not load: ${err.message}`;
  throw err;
}
gemHull = Hull.fromPoints(GEM.map(([x, y, z]) => ({ x, y, z })));
runLoop(hud, (now) => {
  if (demo.mode === 'tests') return frameTests();
  if (demo.mode === 'broad') return frameBroad(now);
  return [0, 'bodies'];
});
demo.ready = true;
