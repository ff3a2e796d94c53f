// 2D shapes: plain objects with a `type` field, factories for them, and their encoding into the
// wasm scratch slots (layout in src/exports.c).
import * as w from './wasm.js';
import { num, nonNeg, obj, vec2, describe, checkCode } from './check.js';

export const SHAPE2_TYPES = ['circle', 'capsule', 'aabb', 'box', 'polygon', 'segment'];
export const MAX_POLYGON_VERTICES = 8;

/** Writes shape into the scratch slot at float index `at`; `name` names it in errors. */
export function encode2(shape, at, name) {
  obj(shape, name);
  const f = w.F32;
  switch (shape.type) {
    case 'circle': {
      const c = vec2(shape.center, `${name}.center`);
      const r = nonNeg(shape.radius, `${name}.radius`);
      f[at] = 0; f[at + 1] = c[0]; f[at + 2] = c[1]; f[at + 3] = r;
      return;
    }
    case 'capsule': {
      const p1 = vec2(shape.p1, `${name}.p1`), p2 = vec2(shape.p2, `${name}.p2`);
      const r = nonNeg(shape.radius, `${name}.radius`);
      f[at] = 1; f[at + 1] = p1[0]; f[at + 2] = p1[1]; f[at + 3] = p2[0]; f[at + 4] = p2[1]; f[at + 5] = r;
      return;
    }
    case 'aabb': {
      const lo = vec2(shape.min, `${name}.min`), hi = vec2(shape.max, `${name}.max`);
      if (lo[0] > hi[0] || lo[1] > hi[1]) throw new RangeError(`${name}.min must not exceed ${name}.max`);
      f[at] = 2; f[at + 1] = lo[0]; f[at + 2] = lo[1]; f[at + 3] = hi[0]; f[at + 4] = hi[1];
      return;
    }
    case 'box': {
      const c = vec2(shape.center, `${name}.center`), h = vec2(shape.halfExtents, `${name}.halfExtents`);
      if (h[0] < 0 || h[1] < 0) throw new RangeError(`${name}.halfExtents must be >= 0`);
      const angle = shape.angle === undefined ? 0 : num(shape.angle, `${name}.angle`);
      f[at] = 3; f[at + 1] = c[0]; f[at + 2] = c[1]; f[at + 3] = h[0]; f[at + 4] = h[1]; f[at + 5] = angle;
      return;
    }
    case 'polygon': {
      const vs = shape.vertices;
      if (!Array.isArray(vs)) throw new TypeError(`${name}.vertices must be an array of {x, y}, got ${describe(vs)}`);
      if (vs.length < 3 || vs.length > MAX_POLYGON_VERTICES) {
        throw new RangeError(`${name}.vertices must hold 3 to ${MAX_POLYGON_VERTICES} points, got ${vs.length}`);
      }
      const r = shape.radius === undefined ? 0 : nonNeg(shape.radius, `${name}.radius`);
      f[at] = 4; f[at + 1] = vs.length; f[at + 2] = r;
      for (let i = 0; i < vs.length; i++) {
        const p = vec2(vs[i], `${name}.vertices[${i}]`);
        f[at + 3 + 2 * i] = p[0]; f[at + 4 + 2 * i] = p[1];
      }
      return;
    }
    case 'segment': {
      const p1 = vec2(shape.p1, `${name}.p1`), p2 = vec2(shape.p2, `${name}.p2`);
      f[at] = 5; f[at + 1] = p1[0]; f[at + 2] = p1[1]; f[at + 3] = p2[0]; f[at + 4] = p2[1];
      return;
    }
    default:
      throw new TypeError(`${name}.type must be one of ${SHAPE2_TYPES.map((t) => `'${t}'`).join(', ')}, got ${describe(shape.type)}`);
  }
}

const v = (x, y) => ({ x, y });
const pt = (p, name) => { const a = vec2(p, name); return v(a[0], a[1]); };

/** @returns {{type:'circle', center:{x:number,y:number}, radius:number}} */
export function circle(center, radius) {
  return { type: 'circle', center: pt(center, 'center'), radius: nonNeg(radius, 'radius') };
}

export function capsule2(p1, p2, radius) {
  return { type: 'capsule', p1: pt(p1, 'p1'), p2: pt(p2, 'p2'), radius: nonNeg(radius, 'radius') };
}

export function aabb2(min, max) {
  const s = { type: 'aabb', min: pt(min, 'min'), max: pt(max, 'max') };
  if (s.min.x > s.max.x || s.min.y > s.max.y) throw new RangeError('min must not exceed max');
  return s;
}

export function box2(center, halfExtents, angle = 0) {
  const h = pt(halfExtents, 'halfExtents');
  if (h.x < 0 || h.y < 0) throw new RangeError('halfExtents must be >= 0');
  return { type: 'box', center: pt(center, 'center'), halfExtents: h, angle: num(angle, 'angle') };
}

export function segment2(p1, p2) {
  return { type: 'segment', p1: pt(p1, 'p1'), p2: pt(p2, 'p2') };
}

/**
 * A convex polygon: the convex hull of 3 to 8 points (welded, counter-clockwise in y-up axes),
 * optionally rounded by `radius`. Built by cd2MakePolygon; throws a RangeError for a degenerate
 * set (collinear, coincident). The returned object lists the hull's vertices, its centroid and
 * edge normals.
 */
export function polygon(points, radius = 0) {
  w.requireInit();
  encode2({ type: 'polygon', vertices: points, radius }, w.S, 'points');
  checkCode(w.exports.polygon2Make(), 'points', 'points');
  const f = w.F32, io = w.S + 128;
  const n = f[io];
  const vertices = [], normals = [];
  for (let i = 0; i < n; i++) {
    vertices.push(v(f[io + 4 + 2 * i], f[io + 5 + 2 * i]));
    normals.push(v(f[io + 4 + 2 * n + 2 * i], f[io + 5 + 2 * n + 2 * i]));
  }
  return { type: 'polygon', vertices, radius: f[io + 1], centroid: v(f[io + 2], f[io + 3]), normals };
}
