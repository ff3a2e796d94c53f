// Batch collision queries in node: collide's wasm batch calls against the plain JavaScript a
// reader of the texts (MDN, "3D collision detection") writes by hand: the text's point/AABB/
// sphere functions in a loop over an array of objects, collecting the indices that hit.
//   node bench/js/bench_queries.mjs [--n 10000] [--samples 9]
// Prints one table: per query kind, the median time of one pass over all n objects.
import * as c from '../../bindings/js/index.js';
import { timeAll } from './timing.mjs';

const args = process.argv.slice(2);
const opt = (name, dflt) => { const i = args.indexOf(`--${name}`); return i >= 0 ? Number(args[i + 1]) : dflt; };
const N = opt('n', 10000);
const SAMPLES = opt('samples', 15);

await c.init();

// ---- the texts' functions, as written there (touching made inclusive to match collide) ----
function isPointInsideAABB(point, box) {
  return point.x >= box.minX && point.x <= box.maxX && point.y >= box.minY && point.y <= box.maxY &&
    point.z >= box.minZ && point.z <= box.maxZ;
}
function intersectAABB(a, b) {
  return a.minX <= b.maxX && a.maxX >= b.minX && a.minY <= b.maxY && a.maxY >= b.minY && a.minZ <= b.maxZ && a.maxZ >= b.minZ;
}
function isPointInsideSphere(point, sphere) {
  const distance = Math.sqrt((point.x - sphere.x) * (point.x - sphere.x) + (point.y - sphere.y) * (point.y - sphere.y) +
    (point.z - sphere.z) * (point.z - sphere.z));
  return distance <= sphere.radius;
}
function intersectSphere(sphere, other) {
  const distance = Math.sqrt((sphere.x - other.x) * (sphere.x - other.x) + (sphere.y - other.y) * (sphere.y - other.y) +
    (sphere.z - other.z) * (sphere.z - other.z));
  return distance <= sphere.radius + other.radius;
}
function intersectSphereAABB(sphere, box) {
  const x = Math.max(box.minX, Math.min(sphere.x, box.maxX));
  const y = Math.max(box.minY, Math.min(sphere.y, box.maxY));
  const z = Math.max(box.minZ, Math.min(sphere.z, box.maxZ));
  const distance = Math.sqrt((x - sphere.x) * (x - sphere.x) + (y - sphere.y) * (y - sphere.y) + (z - sphere.z) * (z - sphere.z));
  return distance <= sphere.radius;
}

// ---- the scene: n objects in a 100-unit cube, the query volume hits about 5% of them ----
let seed = 12345;
const rnd = (lo, hi) => Math.fround(lo + (hi - lo) * ((seed = (seed * 16807) % 2147483647) / 2147483647));
const points = [], boxes = [], spheres = [];
const wPoints = new c.WasmArray('f32', 3 * N), wBoxes = new c.WasmArray('f32', 6 * N), wSpheres = new c.WasmArray('f32', 4 * N);
const fp = wPoints.array, fb = wBoxes.array, fs = wSpheres.array;
for (let i = 0; i < N; i++) {
  const p = { x: rnd(0, 100), y: rnd(0, 100), z: rnd(0, 100) };
  points.push(p);
  fp.set([p.x, p.y, p.z], 3 * i);
  const x = rnd(0, 100), y = rnd(0, 100), z = rnd(0, 100);
  const b = { minX: x, minY: y, minZ: z, maxX: Math.fround(x + rnd(0.5, 3)), maxY: Math.fround(y + rnd(0.5, 3)), maxZ: Math.fround(z + rnd(0.5, 3)) };
  boxes.push(b);
  fb.set([b.minX, b.minY, b.minZ, b.maxX, b.maxY, b.maxZ], 6 * i);
  const s = { x: rnd(0, 100), y: rnd(0, 100), z: rnd(0, 100), radius: rnd(0.5, 2) };
  spheres.push(s);
  fs.set([s.x, s.y, s.z, s.radius], 4 * i);
}
const copies = { points: new Float32Array(fp), boxes: new Float32Array(fb), spheres: new Float32Array(fs) };
const qBox = { minX: 30, maxX: 66, minY: 30, maxY: 66, minZ: 40, maxZ: 50 };
const qSphere = { x: 50, y: 50, z: 50, radius: 23 };

function jsLoop(items, q, test) {
  const hits = [];
  for (let i = 0; i < items.length; i++) if (test(items[i], q)) hits.push(i);
  return hits;
}

const kinds = [
  ['points in AABB', points, 'points', qBox, isPointInsideAABB, c.pointsInsideAABB],
  ['points in sphere', points, 'points', qSphere, isPointInsideSphere, c.pointsInsideSphere],
  ['AABBs vs AABB', boxes, 'boxes', qBox, intersectAABB, c.aabbsIntersectAABB],
  ['spheres vs sphere', spheres, 'spheres', qSphere, intersectSphere, c.spheresIntersectSphere],
  ['spheres vs AABB', spheres, 'spheres', qBox, intersectSphereAABB, c.spheresIntersectAABB],
];
const packed = { points: wPoints, boxes: wBoxes, spheres: wSpheres };

console.log(`collide batch queries, node ${process.version}, wasm ${c.simdSupported() ? 'SIMD' : 'scalar'}, n = ${N}, median of ${SAMPLES} samples of CPU time (microseconds per pass over all n)`);
console.log('| query | hits | plain JS (objects) | collide, WasmArray | collide, Float32Array (copied in) | collide, array of objects | JS / collide WasmArray |');
console.log('|---|---|---|---|---|---|---|');
for (const [name, objs, key, q, jsTest, batch] of kinds) {
  const expected = jsLoop(objs, q, jsTest);
  const got = Array.from(batch(packed[key], q));
  if (got.length !== expected.length || got.some((v, i) => v !== expected[i])) throw new Error(`${name}: collide and JS disagree`);
  const view = packed[key];
  const [tJs, tWasm, tCopy, tObj] = timeAll([() => jsLoop(objs, q, jsTest), () => batch(view, q),
    () => batch(copies[key], q), () => batch(objs, q)], SAMPLES);
  const us = (t) => (t * 1000).toFixed(1);
  console.log(`| ${name} | ${expected.length} | ${us(tJs)} | ${us(tWasm)} | ${us(tCopy)} | ${us(tObj)} | ${(tJs / tWasm).toFixed(2)}x |`);
}
wPoints.destroy(); wBoxes.destroy(); wSpheres.destroy();
