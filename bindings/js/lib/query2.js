// 2D queries on shapes: overlap, containment, closest point, ray cast, distance, contact
// manifold, shape cast, time of impact, bounds and mass. Each calls the library's generic
// dispatcher (cd2Overlap, cd2Raycast, cd2Distance, cd2Collide, cd2ShapeCast, cd2TimeOfImpact).
import * as w from './wasm.js';
import { num, nonNeg, obj, vec2, checkCode } from './check.js';
import { encode2 } from './shapes2.js';

const A = () => w.S;
const B = () => w.S + 64;
const IO = () => w.S + 128;
const v = (x, y) => ({ x, y });

function prepA(a, nameA = 'shape') {
  w.requireInit();
  w.views();
  encode2(a, A(), nameA);
}

function prepAB(a, b) {
  w.requireInit();
  w.views();
  encode2(a, A(), 'a');
  encode2(b, B(), 'b');
}

/** True when the shapes touch or overlap (touching counts). */
export function overlap2(a, b) {
  prepAB(a, b);
  return checkCode(w.exports.overlap2(), 'a', 'b') === 1;
}

/** True when the point lies in the shape (on the boundary counts). */
export function containsPoint2(shape, point) {
  prepA(shape);
  const p = vec2(point, 'point');
  return checkCode(w.exports.pointIn2(p[0], p[1]), 'shape', '') === 1;
}

/** The point of the shape closest to `point` (the point itself when inside a solid shape). */
export function closestPoint2(shape, point) {
  prepA(shape);
  const p = vec2(point, 'point');
  checkCode(w.exports.closestPoint2(p[0], p[1]), 'shape', '');
  const f = w.F32, io = IO();
  return v(f[io], f[io + 1]);
}

function ray2(ray) {
  obj(ray, 'ray');
  return [...vec2(ray.origin, 'ray.origin'), ...vec2(ray.translation, 'ray.translation')];
}

/** Ray {origin, translation} (points origin + t translation, t in [0, 1]); null on a miss. */
export function raycast2(shape, ray) {
  prepA(shape);
  const r = ray2(ray);
  const hit = checkCode(w.exports.raycast2(r[0], r[1], r[2], r[3]), 'shape', '');
  if (hit === 0) return null;
  const f = w.F32, io = IO();
  return { fraction: f[io], point: v(f[io + 1], f[io + 2]), normal: v(f[io + 3], f[io + 4]) };
}

/** GJK distance: closest points (pointA on a, pointB on b) and their distance; 0 when overlapping. */
export function distance2(a, b) {
  prepAB(a, b);
  checkCode(w.exports.distance2(), 'a', 'b');
  const f = w.F32, io = IO();
  return {
    pointA: v(f[io], f[io + 1]), pointB: v(f[io + 2], f[io + 3]), distance: f[io + 4],
    iterations: f[io + 5], hitIterationCap: f[io + 6] !== 0,
  };
}

/**
 * Contact manifold (cd2Collide): normal from a to b and up to 2 points, each midway between the
 * surfaces with its separation (negative when penetrating) and a feature id.
 */
export function manifold2(a, b, speculativeDistance = 0) {
  prepAB(a, b);
  const n = checkCode(w.exports.collide2(nonNeg(speculativeDistance, 'speculativeDistance')), 'a', 'b', 'speculativeDistance');
  const f = w.F32, u = w.U32, io = IO();
  const points = [];
  for (let i = 0; i < n; i++) {
    const o = io + 2 + 4 * i;
    points.push({ point: v(f[o], f[o + 1]), separation: f[o + 2], id: u[o + 3] });
  }
  return { normal: v(f[io], f[io + 1]), points };
}

/** Shape a moves by `translation` against the static shape b: the first contact. */
export function shapeCast2(a, b, translation) {
  prepAB(a, b);
  const t = vec2(translation, 'translation');
  checkCode(w.exports.shapeCast2(t[0], t[1]), 'a', 'b');
  const f = w.F32, io = IO();
  return {
    hit: f[io] !== 0, hitIterationCap: f[io + 1] !== 0, fraction: f[io + 2],
    point: v(f[io + 3], f[io + 4]), normal: v(f[io + 5], f[io + 6]), iterations: f[io + 7],
  };
}

const TOI_STATES = ['hit', 'separated', 'overlapped', 'failed'];
export { TOI_STATES };

/** [targetSeparation, tolerance] of the time-of-impact options (shared with query3.js). */
export function toiOptions(options) {
  obj(options, 'options');
  const target = options.targetSeparation === undefined ? 0.005 : nonNeg(options.targetSeparation, 'options.targetSeparation');
  const tol = options.tolerance === undefined ? 0.00125 : num(options.tolerance, 'options.tolerance');
  if (tol <= 0) throw new RangeError(`options.tolerance must be > 0, got ${tol}`);
  return [target, tol];
}

function sweep2(s, name, f, at) {
  obj(s, name);
  const lc = s.localCenter === undefined ? [0, 0] : vec2(s.localCenter, `${name}.localCenter`);
  const c0 = vec2(s.center0, `${name}.center0`);
  const c1 = s.center1 === undefined ? c0 : vec2(s.center1, `${name}.center1`);
  const a0 = s.angle0 === undefined ? 0 : num(s.angle0, `${name}.angle0`);
  const a1 = s.angle1 === undefined ? a0 : num(s.angle1, `${name}.angle1`);
  f[at] = lc[0]; f[at + 1] = lc[1]; f[at + 2] = c0[0]; f[at + 3] = c0[1];
  f[at + 4] = c1[0]; f[at + 5] = c1[1]; f[at + 6] = a0; f[at + 7] = a1;
}

/**
 * Time of impact of two moving shapes (shapes in their bodies' frames; sweeps
 * {localCenter?, center0, center1, angle0?, angle1?}). Options: targetSeparation (default
 * 0.005, the linear slop), tolerance (default a quarter of it).
 */
export function timeOfImpact2(a, sweepA, b, sweepB, options = {}) {
  prepAB(a, b);
  const [target, tol] = toiOptions(options);
  const f = w.F32, io = IO();
  sweep2(sweepA, 'sweepA', f, io);
  sweep2(sweepB, 'sweepB', f, io + 8);
  checkCode(w.exports.timeOfImpact2(target, tol), 'a', 'b', 'sweeps and options');
  return { state: TOI_STATES[f[io]], t: f[io + 1], iterations: f[io + 2] };
}

/** Tight bounding box {min, max}. */
export function computeAabb2(shape) {
  prepA(shape);
  checkCode(w.exports.shape2Aabb(), 'shape', '');
  const f = w.F32, io = IO();
  return { min: v(f[io], f[io + 1]), max: v(f[io + 2], f[io + 3]) };
}

/** Mass, centre of mass and rotational inertia (about the centre) at `density`. */
export function computeMass2(shape, density = 1) {
  prepA(shape);
  checkCode(w.exports.mass2(nonNeg(density, 'density')), 'shape', '');
  const f = w.F32, io = IO();
  return { mass: f[io], center: v(f[io + 1], f[io + 2]), rotationalInertia: f[io + 3] };
}
