// 3D queries on shapes: overlap, containment, closest point, ray cast, distance, contact
// manifold, shape cast, time of impact, bounds and mass, through the library's generic
// dispatchers (cd3Overlap, cd3Raycast, cd3Distance, cd3Collide, cd3ShapeCast, cd3TimeOfImpact).
import * as w from './wasm.js';
import { nonNeg, num, obj, vec3, quat, checkCode } from './check.js';
import { encode3 } from './shapes3.js';
import { TOI_STATES, toiOptions } from './query2.js';

const IO = () => w.S + 128;
const v = (x, y, z) => ({ x, y, z });

function prepA(a) {
  w.requireInit();
  w.views();
  encode3(a, w.S, 'shape');
}

function prepAB(a, b) {
  w.requireInit();
  w.views();
  encode3(a, w.S, 'a');
  encode3(b, w.S + 64, 'b');
}

export function overlap3(a, b) {
  prepAB(a, b);
  return checkCode(w.exports.overlap3(), 'a', 'b') === 1;
}

export function containsPoint3(shape, point) {
  prepA(shape);
  const p = vec3(point, 'point');
  return checkCode(w.exports.pointIn3(p[0], p[1], p[2]), 'shape', '') === 1;
}

export function closestPoint3(shape, point) {
  prepA(shape);
  const p = vec3(point, 'point');
  checkCode(w.exports.closestPoint3(p[0], p[1], p[2]), 'shape', '');
  const f = w.F32, io = IO();
  return v(f[io], f[io + 1], f[io + 2]);
}

export function raycast3(shape, ray) {
  prepA(shape);
  obj(ray, 'ray');
  const o = vec3(ray.origin, 'ray.origin'), t = vec3(ray.translation, 'ray.translation');
  const hit = checkCode(w.exports.raycast3(o[0], o[1], o[2], t[0], t[1], t[2]), 'shape', '');
  if (hit === 0) return null;
  const f = w.F32, io = IO();
  return { fraction: f[io], point: v(f[io + 1], f[io + 2], f[io + 3]), normal: v(f[io + 4], f[io + 5], f[io + 6]) };
}

export function distance3(a, b) {
  prepAB(a, b);
  checkCode(w.exports.distance3(), 'a', 'b');
  const f = w.F32, io = IO();
  return {
    pointA: v(f[io], f[io + 1], f[io + 2]), pointB: v(f[io + 3], f[io + 4], f[io + 5]), distance: f[io + 6],
    iterations: f[io + 7], hitIterationCap: f[io + 8] !== 0,
  };
}

/** Contact manifold (cd3Collide): normal from a to b and up to 4 points. Spheres, capsules, AABBs, boxes, hulls and triangles; a RangeError for planes and segments (the library has no manifold for them). */
export function manifold3(a, b, speculativeDistance = 0) {
  prepAB(a, b);
  for (const [s, name] of [[a, 'a'], [b, 'b']]) {
    if (s.type === 'plane' || s.type === 'segment') {
      throw new RangeError(`manifold3 has no contact manifold for planes and segments (${name} is a ${s.type}); use distance3 or overlap3`);
    }
  }
  const n = checkCode(w.exports.collide3(nonNeg(speculativeDistance, 'speculativeDistance')), 'a', 'b', 'speculativeDistance');
  const f = w.F32, u = w.U32, io = IO();
  const points = [];
  for (let i = 0; i < n; i++) {
    const o = io + 3 + 5 * i;
    points.push({ point: v(f[o], f[o + 1], f[o + 2]), separation: f[o + 3], id: u[o + 4] });
  }
  return { normal: v(f[io], f[io + 1], f[io + 2]), points };
}

export function shapeCast3(a, b, translation) {
  prepAB(a, b);
  const t = vec3(translation, 'translation');
  checkCode(w.exports.shapeCast3(t[0], t[1], t[2]), 'a', 'b');
  const f = w.F32, io = IO();
  return {
    hit: f[io] !== 0, hitIterationCap: f[io + 1] !== 0, fraction: f[io + 2],
    point: v(f[io + 3], f[io + 4], f[io + 5]), normal: v(f[io + 6], f[io + 7], f[io + 8]), iterations: f[io + 9],
  };
}

function sweep3(s, name, f, at) {
  obj(s, name);
  const lc = s.localCenter === undefined ? [0, 0, 0] : vec3(s.localCenter, `${name}.localCenter`);
  const c0 = vec3(s.center0, `${name}.center0`);
  const c1 = s.center1 === undefined ? c0 : vec3(s.center1, `${name}.center1`);
  const r0 = quat(s.rotation0, `${name}.rotation0`);
  const r1 = s.rotation1 === undefined ? r0 : quat(s.rotation1, `${name}.rotation1`);
  const all = [...lc, ...c0, ...c1, ...r0, ...r1];
  for (let i = 0; i < 17; i++) f[at + i] = all[i];
}

/** Time of impact; sweeps {localCenter?, center0, center1?, rotation0?, rotation1?}. */
export function timeOfImpact3(a, sweepA, b, sweepB, options = {}) {
  prepAB(a, b);
  const [target, tol] = toiOptions(options);
  const f = w.F32, io = IO();
  sweep3(sweepA, 'sweepA', f, io);
  sweep3(sweepB, 'sweepB', f, io + 17);
  checkCode(w.exports.timeOfImpact3(target, tol), 'a', 'b', 'sweeps and options');
  return { state: TOI_STATES[f[io]], t: f[io + 1], iterations: f[io + 2] };
}

export function computeAabb3(shape) {
  prepA(shape);
  checkCode(w.exports.shape3Aabb(), 'shape', '');
  const f = w.F32, io = IO();
  return { min: v(f[io], f[io + 1], f[io + 2]), max: v(f[io + 3], f[io + 4], f[io + 5]) };
}

/** Mass, centre of mass and inertia tensor (about the centre, rows of a symmetric 3x3). */
export function computeMass3(shape, density = 1) {
  prepA(shape);
  checkCode(w.exports.mass3(nonNeg(density, 'density')), 'shape', '');
  const f = w.F32, io = IO();
  return {
    mass: f[io], center: v(f[io + 1], f[io + 2], f[io + 3]),
    inertia: [f[io + 4], f[io + 5], f[io + 6], f[io + 7], f[io + 8], f[io + 9], f[io + 10], f[io + 11], f[io + 12]],
  };
}
