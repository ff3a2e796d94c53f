// 2D chains (chain2.h): polylines of one-sided segments for terrain and level geometry, with a
// static bounding hierarchy. Built once, read-only afterwards. The chain lives in its own frame;
// its methods take the chain's placement ({position, angle}, identity when omitted) and shapes,
// rays and boxes in world space. Winding: the free side of a segment is to the right of its
// direction, so a floor runs from right to left and a loop around a solid island runs
// counter-clockwise.
import * as w from './wasm.js';
import { num, nonNeg, int, obj, vec2, describe, throwResult, checkCode, track, untrack, destroyedError } from './check.js';
import { encode2 } from './shapes2.js';

const IO = () => w.S + 128;
const v = (f, at) => ({ x: f[at], y: f[at + 1] });
const MANIFOLD_FLOATS = 12;
const MAX_POINTS = 1 << 24;

/**
 * Copies 2D points (an array of {x, y}, or a Float32Array/Float64Array of x, y pairs) into staging
 * memory; returns [pointer, count]. Shared with World2's chain shapes.
 */
export function stagePoints2(points, name) {
  let n;
  if (Array.isArray(points)) {
    n = points.length;
    if (n > MAX_POINTS) throw new RangeError(`${name}: at most ${MAX_POINTS} points, got ${n}`);
    const ptr = w.stage(n * 8 + 16);
    const f = w.F32, base = ptr >> 2;
    for (let i = 0; i < n; i++) {
      const p = vec2(points[i], `${name}[${i}]`);
      f[base + 2 * i] = p[0];
      f[base + 2 * i + 1] = p[1];
    }
    return [ptr, n];
  }
  if (points instanceof Float32Array || points instanceof Float64Array) {
    if (points.length % 2 !== 0) throw new RangeError(`${name}: a typed array of x, y pairs must have an even length, got ${points.length}`);
    n = points.length / 2;
    if (n > MAX_POINTS) throw new RangeError(`${name}: at most ${MAX_POINTS} points, got ${n}`);
    const ptr = w.stage(points.length * 4 + 16);
    const f = w.F32, base = ptr >> 2;
    for (let i = 0; i < points.length; i++) {
      const x = points[i];
      if (!Number.isFinite(x)) throw new RangeError(`${name}[${i}] must be finite, got ${x}`);
      f[base + i] = x;
    }
    return [ptr, n];
  }
  const got = points === null ? 'null' : typeof points === 'object' ? (points.constructor?.name ?? 'an object') : describe(points);
  throw new TypeError(`${name} must be an array of {x, y} or a Float32Array/Float64Array of x, y pairs, got ${got}`);
}

/** The error of cd2CreateChain's result `code` for the points argument `name`. */
export function chainError(code, name) {
  if (code === 4) throw new RangeError(`${name} is not a valid chain: fewer than 2 distinct points (3 for a loop) after welding`);
  throwResult(code, name);
}

function writeTransform(transform, name) {
  const f = w.F32, io = IO();
  if (transform === undefined) {
    f[io] = 0; f[io + 1] = 0; f[io + 2] = 0;
    return;
  }
  obj(transform, name);
  const p = transform.position === undefined ? [0, 0] : vec2(transform.position, `${name}.position`);
  f[io] = p[0]; f[io + 1] = p[1];
  f[io + 2] = transform.angle === undefined ? 0 : num(transform.angle, `${name}.angle`);
}

/**
 * A chain in wasm memory (cd2CreateChain): `new Chain2(points, {loop})`. points: an array of
 * {x, y} or a Float32Array/Float64Array of x, y pairs (copied; consecutive points closer than the
 * weld tolerance are welded). Call destroy() when done.
 */
export class Chain2 {
  constructor(points, options = {}) {
    w.requireInit();
    obj(options, 'options');
    const loop = options.loop === undefined ? false : options.loop;
    if (typeof loop !== 'boolean') throw new TypeError(`options.loop must be a boolean, got ${describe(loop)}`);
    const [ptr, n] = stagePoints2(points, 'points');
    const code = w.exports.chain2Build(ptr, n, loop ? 1 : 0);
    w.views();
    if (code !== 0) chainError(code, 'points');
    this._ptr = w.I32[IO()];
    this._pointsPtr = w.exports.chain2Info(this._ptr);
    w.views();
    const f = w.F32, io = IO();
    this.segmentCount = f[io];
    this.pointCount = f[io + 1];
    this.loop = f[io + 2] !== 0;
    /** Bounds in the chain's frame. */
    this.bounds = { min: v(f, io + 3), max: v(f, io + 5) };
    track(this, 'Chain2');
  }

  get destroyed() { return this._ptr === 0; }

  _check(name) {
    if (this._ptr === 0) throw destroyedError('Chain2', name);
    w.views();
  }

  /** The points after welding, x, y pairs in the chain's frame (a copy). */
  get points() {
    this._check('points');
    const base = this._pointsPtr >> 2;
    return w.F32.slice(base, base + 2 * this.pointCount);
  }

  /** Segment `index` in the chain's frame with its ghosts (the neighbours' far vertices): {ghost1, p1, p2, ghost2}. */
  segment(index) {
    this._check('segment');
    int(index, 'index', 0, this.segmentCount - 1);
    w.exports.chain2Segment(this._ptr, index);
    const f = w.F32, io = IO();
    return { ghost1: v(f, io), p1: v(f, io + 2), p2: v(f, io + 4), ghost2: v(f, io + 6) };
  }

  /**
   * One-sided ray cast (cd2RaycastChain): a segment is hit only from its free side. Ray
   * {origin, translation} in world space; {fraction, point, normal, segmentIndex} or null.
   */
  raycast(ray, transform) {
    this._check('raycast');
    obj(ray, 'ray');
    const o = vec2(ray.origin, 'ray.origin'), t = vec2(ray.translation, 'ray.translation');
    writeTransform(transform, 'transform');
    if (w.exports.chain2Raycast(this._ptr, o[0], o[1], t[0], t[1]) !== 1) return null;
    const f = w.F32, io = IO();
    return { fraction: f[io], point: v(f, io + 1), normal: v(f, io + 3), segmentIndex: w.I32[io + 5] };
  }

  /** Indices of the segments whose bounds overlap `bounds` ({min, max}, world space), increasing, as an Int32Array. */
  queryAabb(bounds, transform) {
    this._check('queryAabb');
    obj(bounds, 'bounds');
    const lo = vec2(bounds.min, 'bounds.min'), hi = vec2(bounds.max, 'bounds.max');
    if (lo[0] > hi[0] || lo[1] > hi[1]) throw new RangeError('bounds.min must not exceed bounds.max');
    let capacity = Math.min(256, this.segmentCount);
    for (;;) {
      writeTransform(transform, 'transform');
      const ptr = w.stage(capacity * 4 + 16);
      const n = w.exports.chain2QueryAabb(this._ptr, lo[0], lo[1], hi[0], hi[1], ptr, capacity);
      w.views();
      if (n <= capacity) return w.I32.slice(ptr >> 2, (ptr >> 2) + n);
      capacity = n;
    }
  }

  /**
   * Contact manifolds of the chain (A) against a 2D shape (B, world space) (cd2CollideChain):
   * one per segment in contact, in increasing segment order, [{segmentIndex, normal, points:
   * [{point, separation, id}]}], normal from the terrain to the shape. Options:
   * speculativeDistance (default 0), capacity (most manifolds, default 64).
   */
  manifolds(shape, transform, options = {}) {
    this._check('manifolds');
    obj(options, 'options');
    const spec = options.speculativeDistance === undefined ? 0 : nonNeg(options.speculativeDistance, 'options.speculativeDistance');
    const capacity = options.capacity === undefined ? 64 : int(options.capacity, 'options.capacity', 0, 65536);
    encode2(shape, w.S, 'shape');
    writeTransform(transform, 'transform');
    const ptr = w.stage(Math.max(1, capacity) * MANIFOLD_FLOATS * 4);
    const n = checkCode(w.exports.chain2Collide(this._ptr, spec, ptr, capacity), 'shape', '', 'transform');
    w.views();
    const f = w.F32, u = w.U32, out = [];
    for (let k = 0; k < n; k++) {
      const o = (ptr >> 2) + MANIFOLD_FLOATS * k;
      const points = [];
      for (let i = 0; i < f[o + 3]; i++) {
        const q = o + 4 + 4 * i;
        points.push({ point: v(f, q), separation: f[q + 2], id: u[q + 3] });
      }
      out.push({ segmentIndex: w.I32[o], normal: v(f, o + 1), points });
    }
    return out;
  }

  /** Frees the chain's memory; every method throws from then on. */
  destroy() {
    if (this._ptr === 0) return;
    w.exports.chain2Free(this._ptr);
    this._ptr = 0;
    untrack(this);
  }
}
