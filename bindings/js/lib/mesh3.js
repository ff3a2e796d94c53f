// 3D triangle meshes (mesh3.h): an indexed triangle mesh with a static bounding volume hierarchy,
// built once from typed arrays and immutable afterwards, with ray casts, bounds queries, overlap,
// closest point and contact manifolds of convex shapes against it. A mesh is not a shape type:
// its methods take the mesh's placement ({position, rotation}, identity when omitted); shapes,
// rays and points are in world space, bounds queries in mesh space, as in the C API.
import * as w from './wasm.js';
import { nonNeg, int, obj, vec3, quat, describe, throwResult, checkCode, track, untrack, destroyedError } from './check.js';
import { encode3 } from './shapes3.js';

const IO = () => w.S + 128;
const v = (f, at) => ({ x: f[at], y: f[at + 1], z: f[at + 2] });
const MANIFOLD_FLOATS = 25;
const MAX_COUNT = 1 << 24;

/** Writes the mesh transform into IO[0..6]. */
function writeTransform(transform, name) {
  const f = w.F32, io = IO();
  if (transform === undefined) {
    f.fill(0, io, io + 6);
    f[io + 6] = 1;
    return;
  }
  obj(transform, name);
  const p = transform.position === undefined ? [0, 0, 0] : vec3(transform.position, `${name}.position`);
  const q = quat(transform.rotation, `${name}.rotation`);
  f[io] = p[0]; f[io + 1] = p[1]; f[io + 2] = p[2];
  f[io + 3] = q[0]; f[io + 4] = q[1]; f[io + 5] = q[2]; f[io + 6] = q[3];
}

function typedName(a) {
  return a === null ? 'null' : typeof a === 'object' ? (a.constructor?.name ?? 'an object') : describe(a);
}

/** Copies vertices (x, y, z triples) into staging memory; returns the vertex count. */
function stageVertices(vertices) {
  let n;
  if (vertices instanceof Float32Array || vertices instanceof Float64Array || Array.isArray(vertices)) {
    if (vertices.length % 3 !== 0) throw new RangeError(`vertices must hold x, y, z triples (a length divisible by 3), got length ${vertices.length}`);
    n = vertices.length / 3;
  } else {
    throw new TypeError(`vertices must be a Float32Array, Float64Array or array of numbers (x, y, z per vertex), got ${typedName(vertices)}`);
  }
  if (n < 1) throw new RangeError('vertices must hold at least one vertex');
  if (n > MAX_COUNT) throw new RangeError(`vertices: at most ${MAX_COUNT} vertices, got ${n}`);
  const ptr = w.stage(vertices.length * 4 + 16);
  const f = w.F32, base = ptr >> 2;
  for (let i = 0; i < vertices.length; i++) {
    const x = vertices[i];
    if (typeof x !== 'number') throw new TypeError(`vertices[${i}] must be a number, got ${describe(x)}`);
    if (!Number.isFinite(x)) throw new RangeError(`vertices[${i}] must be finite, got ${x}`);
    f[base + i] = x;
  }
  return [ptr, n];
}

/** Copies indices (three per triangle) into the second staging area; returns the triangle count. */
function stageIndices(indices, vertexCount) {
  const ok = indices instanceof Uint32Array || indices instanceof Int32Array || indices instanceof Uint16Array ||
    indices instanceof Uint8Array || Array.isArray(indices);
  if (!ok) throw new TypeError(`indices must be a Uint32Array, Int32Array, Uint16Array or array of integers (three per triangle), got ${typedName(indices)}`);
  if (indices.length % 3 !== 0) throw new RangeError(`indices must hold three per triangle (a length divisible by 3), got length ${indices.length}`);
  const n = indices.length / 3;
  if (n < 1) throw new RangeError('indices must hold at least one triangle');
  if (n > MAX_COUNT) throw new RangeError(`indices: at most ${MAX_COUNT} triangles, got ${n}`);
  const ptr = w.stage2(indices.length * 4 + 16);
  const I = w.I32, base = ptr >> 2;
  for (let i = 0; i < indices.length; i++) {
    const k = indices[i];
    if (!Number.isInteger(k) || k < 0 || k >= vertexCount) {
      if (typeof k !== 'number') throw new TypeError(`indices[${i}] must be an integer, got ${describe(k)}`);
      throw new RangeError(`indices[${i}] must be an integer in [0, ${vertexCount - 1}] (a vertex), got ${k}`);
    }
    I[base + i] = k;
  }
  return [ptr, n];
}

/**
 * A triangle mesh in wasm memory (cd3CreateMesh). `new Mesh3(vertices, indices)`: vertices x, y, z
 * per vertex (Float32Array, Float64Array or numbers), indices three per triangle, counter-clockwise
 * seen from the front (Uint32Array, Int32Array, Uint16Array or integers). Zero-area triangles are
 * dropped (droppedTriangleCount); the others keep their input index, which every query reports.
 * Call destroy() when done.
 */
export class Mesh3 {
  constructor(vertices, indices) {
    w.requireInit();
    const [vp, vertexCount] = stageVertices(vertices);
    const [ip, triangleCount] = stageIndices(indices, vertexCount);
    const code = w.exports.mesh3Create(vp, vertexCount, ip, triangleCount);
    w.views();
    if (code !== 0) throwResult(code, code === 4 ? 'indices (every triangle has zero area)' : code === 9 ? 'vertices' : 'mesh');
    this._ptr = w.I32[IO()];
    w.exports.mesh3Info(this._ptr);
    w.views();
    const f = w.F32, io = IO();
    /** Triangles kept. */ this.triangleCount = f[io];
    /** Zero-area input triangles the builder dropped. */ this.droppedTriangleCount = f[io + 1];
    this.vertexCount = f[io + 2];
    this.nodeCount = f[io + 3];
    this.leafCount = f[io + 4];
    this.depth = f[io + 5];
    this.activeEdgeCount = f[io + 6];
    /** Bounds of the kept triangles, mesh space. */
    this.bounds = { min: v(f, io + 7), max: v(f, io + 10) };
    this.bytes = f[io + 13];
    track(this, 'Mesh3');
  }

  get destroyed() { return this._ptr === 0; }

  _check(name) {
    if (this._ptr === 0) throw destroyedError('Mesh3', name);
    w.views();
  }

  /** The triangle of input index `index` in mesh space ({a, b, c}), null for a dropped one. */
  triangle(index) {
    this._check('triangle');
    int(index, 'index', 0, 2147483647);
    if (w.exports.mesh3Triangle(this._ptr, index) === 0) return null;
    const f = w.F32, io = IO();
    return { type: 'triangle', a: v(f, io), b: v(f, io + 3), c: v(f, io + 6) };
  }

  /** true when the mesh's hierarchy and data pass cd3ValidateMesh (always, for a mesh built here). */
  validate() {
    this._check('validate');
    return w.exports.mesh3Info(this._ptr) === 0;
  }

  _ray(ray, transform, any, name) {
    this._check(name);
    obj(ray, 'ray');
    const o = vec3(ray.origin, 'ray.origin'), t = vec3(ray.translation, 'ray.translation');
    writeTransform(transform, 'transform');
    return w.exports.mesh3Raycast(this._ptr, o[0], o[1], o[2], t[0], t[1], t[2], any ? 1 : 0);
  }

  /**
   * The first hit of a ray {origin, translation} (world space): {fraction, point, normal,
   * triangleIndex}, or null (cd3RaycastMesh; triangles are two-sided).
   */
  raycast(ray, transform) {
    if (this._ray(ray, transform, false, 'raycast') === 0) return null;
    const f = w.F32, io = IO();
    return { fraction: f[io], point: v(f, io + 1), normal: v(f, io + 4), triangleIndex: w.I32[io + 7] };
  }

  /** Whether the ray hits any triangle (cd3RaycastMeshAny: stops at the first found). */
  raycastAny(ray, transform) {
    return this._ray(ray, transform, true, 'raycastAny') === 1;
  }

  /** Input indices of the triangles whose bounds overlap `bounds` ({min, max}, mesh space), as an Int32Array. */
  queryAabb(bounds) {
    this._check('queryAabb');
    obj(bounds, 'bounds');
    const lo = vec3(bounds.min, 'bounds.min'), hi = vec3(bounds.max, 'bounds.max');
    if (lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2]) throw new RangeError('bounds.min must not exceed bounds.max');
    let capacity = Math.min(256, this.triangleCount);
    for (;;) {
      const ptr = w.stage(capacity * 4 + 16);
      const n = w.exports.mesh3QueryAabb(this._ptr, lo[0], lo[1], lo[2], hi[0], hi[1], hi[2], ptr, capacity);
      w.views();
      if (n <= capacity) return w.I32.slice(ptr >> 2, (ptr >> 2) + n);
      capacity = n;
    }
  }

  /** true when the shape (world space, any 3D shape) touches a triangle (cd3OverlapMesh). */
  overlap(shape, transform) {
    this._check('overlap');
    encode3(shape, w.S, 'shape');
    writeTransform(transform, 'transform');
    return checkCode(w.exports.mesh3Overlap(this._ptr), 'shape', '', 'transform') === 1;
  }

  /**
   * The closest point of the mesh to `point` (world space): {point, distance, triangleIndex}, or
   * null when nothing lies within maxDistance (cd3ClosestPointOnMesh).
   */
  closestPoint(point, transform, maxDistance = Infinity) {
    this._check('closestPoint');
    const p = vec3(point, 'point');
    if (typeof maxDistance !== 'number' || Number.isNaN(maxDistance)) throw new TypeError(`maxDistance must be a number, got ${describe(maxDistance)}`);
    if (maxDistance < 0) throw new RangeError(`maxDistance must be >= 0, got ${maxDistance}`);
    writeTransform(transform, 'transform');
    const r = checkCode(w.exports.mesh3ClosestPoint(this._ptr, p[0], p[1], p[2], maxDistance), 'point', '', 'transform');
    if (r === 0) return null;
    const f = w.F32, io = IO();
    return { point: v(f, io), distance: f[io + 3], triangleIndex: w.I32[io + 4] };
  }

  /**
   * Contact manifolds of a convex shape (sphere, capsule, aabb, box, hull) against the mesh
   * (cd3CollideMesh): one per triangle in contact, [{triangleIndex, normal, points: [{point,
   * separation, id}]}], normal from the shape to the triangle. Options: speculativeDistance
   * (default 0), capacity (most manifolds, default 64; the first met in the hierarchy are kept).
   */
  manifolds(shape, transform, options = {}) {
    this._check('manifolds');
    obj(options, 'options');
    const spec = options.speculativeDistance === undefined ? 0 : nonNeg(options.speculativeDistance, 'options.speculativeDistance');
    const capacity = options.capacity === undefined ? 64 : int(options.capacity, 'options.capacity', 0, 65536);
    encode3(shape, w.S, 'shape');
    if (shape.type === 'plane' || shape.type === 'segment' || shape.type === 'triangle') {
      throw new RangeError(`manifolds has no contact manifold for a ${shape.type} against a mesh; use overlap or closestPoint`);
    }
    writeTransform(transform, 'transform');
    const ptr = w.stage(Math.max(1, capacity) * MANIFOLD_FLOATS * 4);
    const n = checkCode(w.exports.mesh3Collide(this._ptr, spec, ptr, capacity), 'shape', '', 'transform');
    w.views();
    const f = w.F32, u = w.U32, out = [];
    for (let k = 0; k < n; k++) {
      const o = (ptr >> 2) + MANIFOLD_FLOATS * k;
      const points = [];
      for (let i = 0; i < f[o + 4]; i++) {
        const q = o + 5 + 5 * i;
        points.push({ point: v(f, q), separation: f[q + 3], id: u[q + 4] });
      }
      out.push({ triangleIndex: w.I32[o], normal: v(f, o + 1), points });
    }
    return out;
  }

  /** Frees the mesh's memory; every method throws from then on. */
  destroy() {
    if (this._ptr === 0) return;
    w.exports.mesh3Destroy(this._ptr);
    this._ptr = 0;
    untrack(this);
  }
}

