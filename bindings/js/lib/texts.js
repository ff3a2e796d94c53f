// The primitive tests by the names web developers know from the texts (MDN's "3D collision
// detection" and "2D collision detection"), on the texts' own plain objects, plus batch forms
// over arrays of them (or over packed typed arrays) that answer with the indices that hit in one
// call. Touching counts everywhere, as in the rest of collide. Canvas helpers work in canvas
// coordinates as they are (y down): an axis-aligned test does not care which way y points, so
// nothing is converted; only angles turn the other way on screen (clockwise for positive angles).
import * as w from './wasm.js';
import { num, nonNeg, obj, vec2, describe, checkCode } from './check.js';
import { place, unwrap } from './memory.js';
import { encode2 } from './shapes2.js';

function box3(b, name) {
  obj(b, name);
  const r = [num(b.minX, `${name}.minX`), num(b.minY, `${name}.minY`), num(b.minZ, `${name}.minZ`),
    num(b.maxX, `${name}.maxX`), num(b.maxY, `${name}.maxY`), num(b.maxZ, `${name}.maxZ`)];
  if (r[0] > r[3] || r[1] > r[4] || r[2] > r[5]) throw new RangeError(`${name}: min must not exceed max`);
  return r;
}

function pt3(p, name) {
  obj(p, name);
  return [num(p.x, `${name}.x`), num(p.y, `${name}.y`), num(p.z, `${name}.z`)];
}

function sph(s, name) {
  obj(s, name);
  return [num(s.x, `${name}.x`), num(s.y, `${name}.y`), num(s.z, `${name}.z`), nonNeg(s.radius, `${name}.radius`)];
}

function rect(r, name) {
  obj(r, name);
  const x = num(r.x, `${name}.x`), y = num(r.y, `${name}.y`);
  const wd = nonNeg(r.width, `${name}.width`), ht = nonNeg(r.height, `${name}.height`);
  return [x, y, x + wd, y + ht];
}

function circ(c, name) {
  obj(c, name);
  return [num(c.x, `${name}.x`), num(c.y, `${name}.y`), nonNeg(c.radius, `${name}.radius`)];
}

function ready() {
  w.requireInit();
}

// ---- 3D, single tests (cd3PointInAabb, cd3OverlapAabbAabb, cd3PointInSphere, ...) --------------

/** point {x, y, z} inside box {minX, maxX, minY, maxY, minZ, maxZ} (boundary included). */
export function isPointInsideAABB(point, box) {
  ready();
  const p = pt3(point, 'point'), b = box3(box, 'box');
  return w.exports.pointInAabb3(p[0], p[1], p[2], b[0], b[1], b[2], b[3], b[4], b[5]) === 1;
}

export function intersectAABB(a, b) {
  ready();
  const x = box3(a, 'a'), y = box3(b, 'b');
  return w.exports.overlapAabbAabb3(x[0], x[1], x[2], x[3], x[4], x[5], y[0], y[1], y[2], y[3], y[4], y[5]) === 1;
}

/** point {x, y, z} inside sphere {x, y, z, radius}. */
export function isPointInsideSphere(point, sphere) {
  ready();
  const p = pt3(point, 'point'), s = sph(sphere, 'sphere');
  return w.exports.pointInSphere3(p[0], p[1], p[2], s[0], s[1], s[2], s[3]) === 1;
}

export function intersectSphere(a, b) {
  ready();
  const x = sph(a, 'a'), y = sph(b, 'b');
  return w.exports.overlapSphereSphere3(x[0], x[1], x[2], x[3], y[0], y[1], y[2], y[3]) === 1;
}

export function intersectSphereAABB(sphere, box) {
  ready();
  const s = sph(sphere, 'sphere'), b = box3(box, 'box');
  return w.exports.overlapSphereAabb3(s[0], s[1], s[2], s[3], b[0], b[1], b[2], b[3], b[4], b[5]) === 1;
}

// ---- batch forms -------------------------------------------------------------------------------
// Each takes either an array of the texts' objects or a packed Float32Array (layouts below; a
// Float32Array that is a WasmArray's view is read in place) and returns an Int32Array of the
// indices that pass, in increasing order.
//   points 3D: x y z        AABBs 3D: minX minY minZ maxX maxY maxZ      spheres: x y z radius
//   points 2D: x y          rects/AABBs 2D: minX minY maxX maxY          circles: x y radius

const KIND = {
  pointsInAabb3: 0, pointsInSphere3: 1, aabbsAabb3: 2, aabbsSphere3: 3, spheresSphere3: 4, spheresAabb3: 5,
  pointsInAabb2: 6, pointsInCircle2: 7, aabbsAabb2: 8, aabbsCircle2: 9, circlesCircle2: 10, circlesAabb2: 11,
};
const STRIDE = [3, 3, 6, 6, 4, 4, 2, 2, 4, 4, 3, 3];

// Fast packers for arrays of objects: write one record at f[at...] and return true when it is
// valid (numbers, finite, min <= max, radius >= 0); on false the caller re-checks the item with
// the naming validators, which throw the precise error. (x - x === 0 is false for NaN and +-Inf.)
const ok = (v) => typeof v === 'number' && v - v === 0;
const isObj = (o) => typeof o === 'object' && o !== null;
function packPoint3(f, at, p) {
  if (!isObj(p)) return false;
  const x = p.x, y = p.y, z = p.z;
  f[at] = x; f[at + 1] = y; f[at + 2] = z;
  return ok(x) && ok(y) && ok(z);
}
function packBox3(f, at, b) {
  if (!isObj(b)) return false;
  const a = b.minX, c = b.minY, d = b.minZ, e = b.maxX, g = b.maxY, h = b.maxZ;
  f[at] = a; f[at + 1] = c; f[at + 2] = d; f[at + 3] = e; f[at + 4] = g; f[at + 5] = h;
  return ok(a) && ok(c) && ok(d) && ok(e) && ok(g) && ok(h) && a <= e && c <= g && d <= h;
}
function packSphere3(f, at, s) {
  if (!isObj(s)) return false;
  const x = s.x, y = s.y, z = s.z, r = s.radius;
  f[at] = x; f[at + 1] = y; f[at + 2] = z; f[at + 3] = r;
  return ok(x) && ok(y) && ok(z) && ok(r) && r >= 0;
}
function packPoint2(f, at, p) {
  if (!isObj(p)) return false;
  const x = p.x, y = p.y;
  f[at] = x; f[at + 1] = y;
  return ok(x) && ok(y);
}
function packRect(f, at, r) {
  if (!isObj(r)) return false;
  const x = r.x, y = r.y, wd = r.width, ht = r.height;
  f[at] = x; f[at + 1] = y; f[at + 2] = x + wd; f[at + 3] = y + ht;
  return ok(x) && ok(y) && ok(wd) && ok(ht) && wd >= 0 && ht >= 0;
}
function packCircle(f, at, c) {
  if (!isObj(c)) return false;
  const x = c.x, y = c.y, r = c.radius;
  f[at] = x; f[at + 1] = y; f[at + 2] = r;
  return ok(x) && ok(y) && ok(r) && r >= 0;
}

function runBatch(kind, items, itemsName, query, pack, check) {
  ready();
  items = unwrap(items);
  const stride = STRIDE[kind];
  let count, dataPtr;
  if (items instanceof Float32Array) {
    if (items.length % stride !== 0) throw new RangeError(`${itemsName}: a packed Float32Array must hold ${stride} numbers per item, its length ${items.length} is not a multiple of ${stride}`);
    count = items.length / stride;
    dataPtr = place(items, Float32Array, itemsName);
  } else if (Array.isArray(items)) {
    count = items.length;
    dataPtr = w.stage(count * stride * 4 + 16);
    const f = w.F32;
    let at = dataPtr >> 2;
    for (let i = 0; i < count; i++, at += stride) {
      if (!pack(f, at, items[i])) {
        check(items[i], `${itemsName}[${i}]`);
        throw new RangeError(`${itemsName}[${i}] is not valid`);
      }
    }
  } else {
    throw new TypeError(`${itemsName} must be an array or a Float32Array, got ${describe(items)}`);
  }
  const outPtr = w.stage2(count * 4 + 16);
  const f = w.F32, io = w.S + 128;
  for (let k = 0; k < query.length; k++) f[io + k] = query[k];
  const n = w.exports.batch(kind, dataPtr, count, outPtr);
  if (n < 0) throw new RangeError(`${itemsName}[${-n - 1}] holds NaN or an infinite value`);
  w.views();
  return w.I32.slice(outPtr >> 2, (outPtr >> 2) + n);
}

export function pointsInsideAABB(points, box) {
  return runBatch(KIND.pointsInAabb3, points, 'points', box3(box, 'box'), packPoint3, pt3);
}

export function pointsInsideSphere(points, sphere) {
  return runBatch(KIND.pointsInSphere3, points, 'points', sph(sphere, 'sphere'), packPoint3, pt3);
}

export function aabbsIntersectAABB(boxes, box) {
  return runBatch(KIND.aabbsAabb3, boxes, 'boxes', box3(box, 'box'), packBox3, box3);
}

export function aabbsIntersectSphere(boxes, sphere) {
  return runBatch(KIND.aabbsSphere3, boxes, 'boxes', sph(sphere, 'sphere'), packBox3, box3);
}

export function spheresIntersectSphere(spheres, sphere) {
  return runBatch(KIND.spheresSphere3, spheres, 'spheres', sph(sphere, 'sphere'), packSphere3, sph);
}

export function spheresIntersectAABB(spheres, box) {
  return runBatch(KIND.spheresAabb3, spheres, 'spheres', box3(box, 'box'), packSphere3, sph);
}

// ---- 2D, canvas coordinates ------------------------------------------------------------------

/** {x, y, width, height} (canvas, y down) to collide's 2D AABB shape {type:'aabb', min, max}: min is the top-left corner. */
export function rectToAabb(r) {
  const b = rect(r, 'rect');
  return { type: 'aabb', min: { x: b[0], y: b[1] }, max: { x: b[2], y: b[3] } };
}

/** A 2D AABB {min, max} back to {x, y, width, height}. */
export function aabbToRect(aabb) {
  obj(aabb, 'aabb');
  const lo = vec2(aabb.min, 'aabb.min'), hi = vec2(aabb.max, 'aabb.max');
  return { x: lo[0], y: lo[1], width: hi[0] - lo[0], height: hi[1] - lo[1] };
}

/** A rect {x, y, width, height} turned by `angle` radians about its centre (clockwise on a y-down canvas) as a 2D box shape. */
export function rectToBox(r, angle = 0) {
  const b = rect(r, 'rect');
  return {
    type: 'box', center: { x: (b[0] + b[2]) / 2, y: (b[1] + b[3]) / 2 },
    halfExtents: { x: (b[2] - b[0]) / 2, y: (b[3] - b[1]) / 2 }, angle: num(angle, 'angle'),
  };
}

function overlapSlots(a, b) {
  const code = checkCode(w.exports.overlap2(), a, b);
  return code === 1;
}

export function isPointInsideRect(point, r) {
  ready();
  const p = vec2(point, 'point');
  const b = rect(r, 'rect');
  w.views();
  const f = w.F32, s = w.S;
  f[s] = 2; f[s + 1] = b[0]; f[s + 2] = b[1]; f[s + 3] = b[2]; f[s + 4] = b[3];
  return checkCode(w.exports.pointIn2(p[0], p[1]), 'rect', '') === 1;
}

/** Rectangles {x, y, width, height} overlap (touching edges count). */
export function intersectRect(a, b) {
  ready();
  const x = rect(a, 'a'), y = rect(b, 'b');
  w.views();
  const f = w.F32, s = w.S;
  f[s] = 2; f[s + 1] = x[0]; f[s + 2] = x[1]; f[s + 3] = x[2]; f[s + 4] = x[3];
  f[s + 64] = 2; f[s + 65] = y[0]; f[s + 66] = y[1]; f[s + 67] = y[2]; f[s + 68] = y[3];
  return overlapSlots('a', 'b');
}

/** Circles {x, y, radius} overlap. */
export function intersectCircle(a, b) {
  ready();
  const x = circ(a, 'a'), y = circ(b, 'b');
  w.views();
  const f = w.F32, s = w.S;
  f[s] = 0; f[s + 1] = x[0]; f[s + 2] = x[1]; f[s + 3] = x[2];
  f[s + 64] = 0; f[s + 65] = y[0]; f[s + 66] = y[1]; f[s + 67] = y[2];
  return overlapSlots('a', 'b');
}

/** Convex polygons given as arrays of 3 to 8 points {x, y} (any winding; the convex hull of each is used) overlap, by the separating axis test. */
export function intersectPolygon(a, b) {
  ready();
  w.views();
  encode2({ type: 'polygon', vertices: a }, w.S, 'a');
  encode2({ type: 'polygon', vertices: b }, w.S + 64, 'b');
  return overlapSlots('a', 'b');
}

export function pointsInsideRect(points, r) {
  return runBatch(KIND.pointsInAabb2, points, 'points', rect(r, 'rect'), packPoint2, vec2);
}

export function rectsIntersectRect(rects, r) {
  return runBatch(KIND.aabbsAabb2, rects, 'rects', rect(r, 'rect'), packRect, rect);
}

export function pointsInsideCircle(points, circle) {
  return runBatch(KIND.pointsInCircle2, points, 'points', circ(circle, 'circle'), packPoint2, vec2);
}

export function circlesIntersectCircle(circles, circle) {
  return runBatch(KIND.circlesCircle2, circles, 'circles', circ(circle, 'circle'), packCircle, circ);
}

export function circlesIntersectRect(circles, r) {
  return runBatch(KIND.circlesAabb2, circles, 'circles', rect(r, 'rect'), packCircle, circ);
}

export function rectsIntersectCircle(rects, circle) {
  return runBatch(KIND.aabbsCircle2, rects, 'rects', circ(circle, 'circle'), packRect, rect);
}
