// 3D shapes: plain objects with a `type` field, factories for them, convex hulls (the Hull class,
// which owns wasm memory) and their encoding into the wasm scratch slots.
import * as w from './wasm.js';
import { num, nonNeg, int, obj, vec3, quat, describe, throwResult, track, untrack, destroyedError } from './check.js';

export const SHAPE3_TYPES = ['sphere', 'capsule', 'aabb', 'box', 'triangle', 'plane', 'segment', 'hull'];

function put3(f, at, a) { f[at] = a[0]; f[at + 1] = a[1]; f[at + 2] = a[2]; }

export function encode3(shape, at, name) {
  obj(shape, name);
  const f = w.F32;
  switch (shape.type) {
    case 'sphere': {
      const c = vec3(shape.center, `${name}.center`);
      const r = nonNeg(shape.radius, `${name}.radius`);
      f[at] = 0; put3(f, at + 1, c); f[at + 4] = r;
      return;
    }
    case 'capsule': {
      const p1 = vec3(shape.p1, `${name}.p1`), p2 = vec3(shape.p2, `${name}.p2`);
      const r = nonNeg(shape.radius, `${name}.radius`);
      f[at] = 1; put3(f, at + 1, p1); put3(f, at + 4, p2); f[at + 7] = r;
      return;
    }
    case 'aabb': {
      const lo = vec3(shape.min, `${name}.min`), hi = vec3(shape.max, `${name}.max`);
      if (lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2]) throw new RangeError(`${name}.min must not exceed ${name}.max`);
      f[at] = 2; put3(f, at + 1, lo); put3(f, at + 4, hi);
      return;
    }
    case 'box': {
      const c = vec3(shape.center, `${name}.center`), h = vec3(shape.halfExtents, `${name}.halfExtents`);
      if (h[0] < 0 || h[1] < 0 || h[2] < 0) throw new RangeError(`${name}.halfExtents must be >= 0`);
      const q = quat(shape.rotation, `${name}.rotation`);
      f[at] = 3; put3(f, at + 1, c); put3(f, at + 4, h);
      f[at + 7] = q[0]; f[at + 8] = q[1]; f[at + 9] = q[2]; f[at + 10] = q[3];
      return;
    }
    case 'triangle': {
      const a = vec3(shape.a, `${name}.a`), b = vec3(shape.b, `${name}.b`), c = vec3(shape.c, `${name}.c`);
      f[at] = 4; put3(f, at + 1, a); put3(f, at + 4, b); put3(f, at + 7, c);
      return;
    }
    case 'plane': {
      const n = vec3(shape.normal, `${name}.normal`);
      const len = Math.hypot(n[0], n[1], n[2]);
      if (Math.abs(len - 1) > 1e-3) throw new RangeError(`${name}.normal must be a unit vector, its length is ${len}`);
      f[at] = 5; put3(f, at + 1, n); f[at + 4] = num(shape.offset, `${name}.offset`);
      return;
    }
    case 'segment': {
      const p1 = vec3(shape.p1, `${name}.p1`), p2 = vec3(shape.p2, `${name}.p2`);
      f[at] = 6; put3(f, at + 1, p1); put3(f, at + 4, p2);
      return;
    }
    case 'hull': {
      const hull = shape.hull;
      if (!(hull instanceof Hull)) throw new TypeError(`${name}.hull must be a Hull, got ${describe(hull)}`);
      if (hull.destroyed) throw destroyedError('Hull', `${name}.hull`);
      const p = shape.position === undefined ? [0, 0, 0] : vec3(shape.position, `${name}.position`);
      const q = quat(shape.rotation, `${name}.rotation`);
      f[at] = 7; put3(f, at + 1, p); f[at + 4] = q[0]; f[at + 5] = q[1]; f[at + 6] = q[2]; f[at + 7] = q[3];
      w.I32[at + 8] = hull._ptr;
      return;
    }
    default:
      throw new TypeError(`${name}.type must be one of ${SHAPE3_TYPES.map((t) => `'${t}'`).join(', ')}, got ${describe(shape.type)}`);
  }
}

const v = (a) => ({ x: a[0], y: a[1], z: a[2] });
const pt = (p, name) => v(vec3(p, name));
const q4 = (q, name) => { const a = quat(q, name); return { x: a[0], y: a[1], z: a[2], w: a[3] }; };

export function sphere(center, radius) {
  return { type: 'sphere', center: pt(center, 'center'), radius: nonNeg(radius, 'radius') };
}

export function capsule3(p1, p2, radius) {
  return { type: 'capsule', p1: pt(p1, 'p1'), p2: pt(p2, 'p2'), radius: nonNeg(radius, 'radius') };
}

export function aabb3(min, max) {
  const s = { type: 'aabb', min: pt(min, 'min'), max: pt(max, 'max') };
  if (s.min.x > s.max.x || s.min.y > s.max.y || s.min.z > s.max.z) throw new RangeError('min must not exceed max');
  return s;
}

export function box3(center, halfExtents, rotation = { x: 0, y: 0, z: 0, w: 1 }) {
  const h = pt(halfExtents, 'halfExtents');
  if (h.x < 0 || h.y < 0 || h.z < 0) throw new RangeError('halfExtents must be >= 0');
  return { type: 'box', center: pt(center, 'center'), halfExtents: h, rotation: q4(rotation, 'rotation') };
}

export function triangle(a, b, c) {
  return { type: 'triangle', a: pt(a, 'a'), b: pt(b, 'b'), c: pt(c, 'c') };
}

export function plane(normal, offset) {
  const n = pt(normal, 'normal');
  const len = Math.hypot(n.x, n.y, n.z);
  if (Math.abs(len - 1) > 1e-3) throw new RangeError(`normal must be a unit vector, its length is ${len}`);
  return { type: 'plane', normal: n, offset: num(offset, 'offset') };
}

export function segment3(p1, p2) {
  return { type: 'segment', p1: pt(p1, 'p1'), p2: pt(p2, 'p2') };
}

export function hullShape(hull, position = { x: 0, y: 0, z: 0 }, rotation = { x: 0, y: 0, z: 0, w: 1 }) {
  if (!(hull instanceof Hull)) throw new TypeError(`hull must be a Hull, got ${describe(hull)}`);
  return { type: 'hull', hull, position: pt(position, 'position'), rotation: q4(rotation, 'rotation') };
}

/**
 * A convex hull in wasm memory (cd3ComputeHull: quickhull with welding and coplanar merging).
 * Immutable; share one hull between many `hullShape`s. Call destroy() when done.
 */
export class Hull {
  /** @param {number} ptr @param {symbol} key */
  constructor(ptr, key) {
    if (key !== HULL_KEY) throw new TypeError('use Hull.fromPoints, Hull.box, Hull.cylinder or Hull.cone');
    this._ptr = ptr;
    const f = w.F32, io = w.S + 128;
    const vertexPtr = w.exports.hullInfo(ptr);
    w.views();
    this.vertexCount = f[io];
    this.faceCount = f[io + 1];
    this.edgeCount = f[io + 2];
    this.volume = f[io + 3];
    this.centroid = v([f[io + 4], f[io + 5], f[io + 6]]);
    this.bounds = { min: v([f[io + 7], f[io + 8], f[io + 9]]), max: v([f[io + 10], f[io + 11], f[io + 12]]) };
    this._vertexPtr = vertexPtr;
    track(this, 'Hull');
  }

  /** Hull of points: an array of {x, y, z} or a Float32Array/Float64Array of x, y, z triples. */
  static fromPoints(points) {
    w.requireInit();
    let n;
    let ptr;
    if (ArrayBuffer.isView(points) && !(points instanceof DataView)) {
      if (points.length % 3 !== 0) throw new RangeError(`points: a typed array of x, y, z triples must have a length divisible by 3, got ${points.length}`);
      n = points.length / 3;
      ptr = w.stage(Math.max(4, points.length * 4));
      const f = w.F32;
      const base = ptr >> 2;
      for (let i = 0; i < points.length; i++) {
        const x = points[i];
        if (!Number.isFinite(x)) throw new RangeError(`points[${i}] must be finite, got ${x}`);
        f[base + i] = x;
      }
    } else if (Array.isArray(points)) {
      n = points.length;
      ptr = w.stage(Math.max(4, n * 12));
      const f = w.F32;
      const base = ptr >> 2;
      for (let i = 0; i < n; i++) put3(f, base + 3 * i, vec3(points[i], `points[${i}]`));
    } else {
      throw new TypeError(`points must be an array of {x, y, z} or a Float32Array, got ${describe(points)}`);
    }
    return makeHull(0, ptr, n, 'points');
  }

  static box(halfExtents) {
    w.requireInit();
    const h = vec3(halfExtents, 'halfExtents');
    put3(w.F32, w.S + 128, h);
    return makeHull(1, 0, 0, 'halfExtents');
  }

  static cylinder(halfHeight, radius, segments = 16) {
    w.requireInit();
    const f = w.F32, io = w.S + 128;
    f[io] = num(halfHeight, 'halfHeight'); f[io + 1] = num(radius, 'radius');
    return makeHull(2, 0, int(segments, 'segments', 3, 1024), 'cylinder');
  }

  static cone(halfHeight, radius, segments = 16) {
    w.requireInit();
    const f = w.F32, io = w.S + 128;
    f[io] = num(halfHeight, 'halfHeight'); f[io + 1] = num(radius, 'radius');
    return makeHull(3, 0, int(segments, 'segments', 3, 1024), 'cone');
  }

  get destroyed() { return this._ptr === 0; }

  /** The hull's vertices, x, y, z per vertex (a copy). */
  get vertices() {
    if (this._ptr === 0) throw destroyedError('Hull', 'hull');
    w.views();
    const base = this._vertexPtr >> 2;
    return w.F32.slice(base, base + 3 * this.vertexCount);
  }

  /** Frees the hull's memory. Shapes that still refer to it throw from then on. */
  destroy() {
    if (this._ptr === 0) return;
    w.exports.hullDestroy(this._ptr);
    this._ptr = 0;
    untrack(this);
  }
}

const HULL_KEY = Symbol('Hull');

function makeHull(kind, ptr, count, name) {
  const code = w.exports.hullCreate(kind, ptr, count);
  w.views();
  if (code !== 0) throwResult(code, name);
  const hullPtr = w.I32[w.S + 128];
  return new Hull(hullPtr, HULL_KEY);
}
