// Typed usage of the whole API, checked by `tsc --noEmit` (test/types.test.mjs): a call with a
// wrong type anywhere here fails the test suite.
import {
  init, simdSupported, isSimdBuild, circle, capsule2, aabb2, box2, polygon, segment2, sphere, capsule3, aabb3, box3, triangle,
  plane, segment3, hullShape, Hull, overlap2, containsPoint2, closestPoint2, raycast2, distance2, manifold2,
  shapeCast2, timeOfImpact2, computeAabb2, computeMass2, overlap3, containsPoint3, closestPoint3, raycast3,
  distance3, manifold3, shapeCast3, timeOfImpact3, computeAabb3, computeMass3, isPointInsideAABB, intersectAABB,
  isPointInsideSphere, intersectSphere, intersectSphereAABB, pointsInsideAABB, pointsInsideSphere,
  aabbsIntersectAABB, aabbsIntersectSphere, spheresIntersectSphere, spheresIntersectAABB, rectToAabb, aabbToRect,
  rectToBox, isPointInsideRect, intersectRect, intersectCircle, intersectPolygon, pointsInsideRect,
  rectsIntersectRect, pointsInsideCircle, circlesIntersectCircle, circlesIntersectRect, rectsIntersectCircle,
  WasmArray, BroadPhase2, BroadPhase3, BROADPHASE_TYPES, SHAPE2_TYPES, SHAPE3_TYPES, MAX_POLYGON_VERTICES,
} from 'collide';
import type { Shape2, Shape3, Manifold2, ToiOutput, Rect } from 'collide';

export async function main(): Promise<number> {
  await init({ simd: simdSupported() });
  const build: boolean = isSimdBuild();
  const shapes2: Shape2[] = [
    circle({ x: 0, y: 0 }, 1), capsule2({ x: 0, y: 0 }, { x: 1, y: 0 }, 0.5), aabb2({ x: 0, y: 0 }, { x: 1, y: 1 }),
    box2({ x: 0, y: 0 }, { x: 1, y: 1 }, 0.5), polygon([{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 0, y: 1 }], 0.1),
    segment2({ x: 0, y: 0 }, { x: 1, y: 1 }),
    { type: 'box', center: { x: 1, y: 1 }, halfExtents: { x: 1, y: 2 } },
  ];
  const a = shapes2[0], b = shapes2[1];
  const hit: boolean = overlap2(a, b) && containsPoint2(a, { x: 0, y: 0 });
  const cp = closestPoint2(a, { x: 3, y: 0 });
  const rh = raycast2(a, { origin: { x: -3, y: 0 }, translation: { x: 6, y: 0 } });
  const frac: number = rh === null ? 1 : rh.fraction;
  const d: number = distance2(a, b).distance;
  const m: Manifold2 = manifold2(a, b, 0.02);
  const sep: number | undefined = m.points[0]?.separation;
  const cast = shapeCast2(a, b, { x: 1, y: 0 });
  const toi: ToiOutput = timeOfImpact2(a, { center0: { x: 0, y: 0 }, center1: { x: 5, y: 0 } }, b, { center0: { x: 3, y: 0 } }, { tolerance: 1e-3 });
  const state: 'hit' | 'separated' | 'overlapped' | 'failed' = toi.state;
  const bounds = computeAabb2(b);
  const mass: number = computeMass2(a, 2).mass;

  const hull = Hull.fromPoints([{ x: 0, y: 0, z: 0 }, { x: 1, y: 0, z: 0 }, { x: 0, y: 1, z: 0 }, { x: 0, y: 0, z: 1 }]);
  const hull2 = Hull.box({ x: 1, y: 1, z: 1 });
  const hull3 = Hull.cylinder(1, 0.5, 12), hull4 = Hull.cone(1, 0.5), hull5 = Hull.fromPoints(new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]));
  const verts: Float32Array = hull.vertices;
  const shapes3: Shape3[] = [
    sphere({ x: 0, y: 0, z: 0 }, 1), capsule3({ x: 0, y: 0, z: 0 }, { x: 1, y: 0, z: 0 }, 0.2),
    aabb3({ x: 0, y: 0, z: 0 }, { x: 1, y: 1, z: 1 }), box3({ x: 0, y: 0, z: 0 }, { x: 1, y: 1, z: 1 }, { x: 0, y: 0, z: 0, w: 1 }),
    triangle({ x: 0, y: 0, z: 0 }, { x: 1, y: 0, z: 0 }, { x: 0, y: 1, z: 0 }), plane({ x: 0, y: 1, z: 0 }, 0),
    segment3({ x: 0, y: 0, z: 0 }, { x: 1, y: 1, z: 1 }), hullShape(hull, { x: 0, y: 1, z: 0 }),
  ];
  const s = shapes3[0], t = shapes3[7];
  const all3: unknown[] = [overlap3(s, t), containsPoint3(s, { x: 0, y: 0, z: 0 }), closestPoint3(s, { x: 2, y: 0, z: 0 }),
    raycast3(s, { origin: { x: -2, y: 0, z: 0 }, translation: { x: 4, y: 0, z: 0 } }), distance3(s, t).pointB.z,
    manifold3(s, t).normal.y, shapeCast3(s, t, { x: 0, y: 1, z: 0 }).hit,
    timeOfImpact3(s, { center0: { x: 0, y: 0, z: 0 }, rotation1: { x: 0, y: 0, z: 0, w: 1 } }, t, { center0: { x: 0, y: 0, z: 0 } }).t,
    computeAabb3(t).max.x, computeMass3(s).inertia[0], verts.length];

  const box = { minX: 0, maxX: 1, minY: 0, maxY: 1, minZ: 0, maxZ: 1 };
  const ball = { x: 0, y: 0, z: 0, radius: 1 };
  const texts: boolean[] = [isPointInsideAABB({ x: 0, y: 0, z: 0 }, box), intersectAABB(box, box),
    isPointInsideSphere({ x: 0, y: 0, z: 0 }, ball), intersectSphere(ball, ball), intersectSphereAABB(ball, box)];
  const idx: Int32Array[] = [pointsInsideAABB([{ x: 0, y: 0, z: 0 }], box), pointsInsideSphere(new Float32Array(3), ball),
    aabbsIntersectAABB([box], box), aabbsIntersectSphere(new Float32Array(6), ball), spheresIntersectSphere([ball], ball),
    spheresIntersectAABB(new Float32Array(4), box)];
  const r: Rect = { x: 0, y: 0, width: 10, height: 5 };
  const c = { x: 1, y: 1, radius: 2 };
  const canvas: unknown[] = [rectToAabb(r), aabbToRect({ min: { x: 0, y: 0 }, max: { x: 1, y: 1 } }), rectToBox(r, 0.3),
    isPointInsideRect({ x: 1, y: 1 }, r), intersectRect(r, r), intersectCircle(c, c),
    intersectPolygon([{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 0, y: 1 }], [{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 0, y: 1 }]),
    pointsInsideRect([{ x: 1, y: 1 }], r), rectsIntersectRect([r], r), pointsInsideCircle(new Float32Array(2), c),
    circlesIntersectCircle([c], c), circlesIntersectRect([c], r), rectsIntersectCircle(new Float32Array(4), c)];

  const boxes = new WasmArray('f32', 6);
  const view: Float32Array = boxes.array;
  view.set([0, 0, 0, 1, 1, 1]);
  const bp = new BroadPhase3({ type: 'tree', margin: 0.05 });
  const ids: Int32Array = bp.createProxies(boxes.array);
  const id: number = bp.createProxy({ min: { x: 0, y: 0, z: 0 }, max: { x: 1, y: 1, z: 1 } });
  const moved: boolean = bp.moveProxy(id, [0, 0, 0, 2, 2, 2], { x: 0.1, y: 0, z: 0 });
  const changed: number = bp.moveProxies(ids, boxes.array);
  const pairs: Int32Array = bp.updatePairs();
  const rc = bp.rayCast({ origin: { x: -1, y: 0.5, z: 0.5 }, translation: { x: 3, y: 0, z: 0 } });
  const fat = bp.getFatAabb(id);
  const bp2 = new BroadPhase2({ type: 'grid', cellSize: 2, bounds: { min: { x: -10, y: -10 }, max: { x: 10, y: 10 } } });
  bp2.createProxy([0, 0, 1, 1]);
  const q2: Int32Array = bp2.query({ min: { x: 0, y: 0 }, max: { x: 1, y: 1 } });
  const st = bp.stats.memoryBytes + bp.proxyCount + (bp.validate() ? 1 : 0) + rc.fractions.length + fat.min.z;
  bp.rebuild(); bp.findAllPairs(); bp.destroyProxy(id); bp.hasProxy(id);
  bp.destroy(); bp2.destroy(); boxes.destroy();
  for (const h of [hull, hull2, hull3, hull4, hull5]) h.destroy();
  const names: readonly string[] = [...BROADPHASE_TYPES, ...SHAPE2_TYPES, ...SHAPE3_TYPES];
  return Number(hit) + cp.x + frac + d + (sep ?? 0) + Number(cast.hit) + state.length + bounds.max.x + mass + all3.length +
    texts.length + idx.length + canvas.length + view.length + Number(moved) + changed + pairs.length + q2.length + st +
    names.length + MAX_POLYGON_VERTICES + Number(build) + world2Usage() + meshChainUsage();
}

// Calls that must not type-check (never run).
export function typeErrors(): void {
  // @ts-expect-error a 3D shape is not a 2D shape
  overlap2(sphere({ x: 0, y: 0, z: 0 }, 1), circle({ x: 0, y: 0 }, 1));
  // @ts-expect-error the radius is a number
  circle({ x: 0, y: 0 }, '1');
  // @ts-expect-error ids must be an Int32Array
  new BroadPhase2().moveProxies([1, 2], new Float32Array(8));
  // @ts-expect-error mesh indices are integers in a typed array or number[], not points
  new c.Mesh3(new Float32Array(9), [{ x: 0, y: 0, z: 0 }]);
  // @ts-expect-error a mesh has no manifold for a plane
  new c.Mesh3(new Float32Array(9), [0, 1, 2]).manifolds(plane({ x: 0, y: 1, z: 0 }, 0));
}

// The 2D world (called by main() once the module is loaded).
import * as c from 'collide';
export function world2Usage(): number {
  const world = new c.World2({ gravity: { x: 0, y: -10 } });
  const ground = world.createBody();
  ground.createShape(c.box2({ x: 0, y: -1 }, { x: 50, y: 1 }));
  const body: c.Body2 = world.createBody({ type: 'dynamic', position: { x: 0, y: 4 } });
  const shape: c.BodyShape2 = body.createShape(c.circle({ x: 0, y: 0 }, 0.5), { density: 1, enableHitEvents: true });
  const joint: c.Joint2 = world.createJoint({ type: 'revolute', bodyA: ground, bodyB: body, localAnchorB: { x: 0, y: 1 } });
  world.setPreSolve((a, b, m) => m.normal.y > 0 && a !== b);
  world.step(1 / 60, 4);
  const t: Float32Array = world.getTransforms();
  const ev: c.WorldEvents2 = world.getEvents();
  const hit = world.raycastClosest({ x: 0, y: 10 }, { x: 0, y: -20 });
  const state: Uint8Array = world.saveState();
  world.restoreState(state);
  const p: c.Vec2 = body.position;
  joint.motorSpeed = 1;
  void [t, ev, hit, p, shape.friction];
  world.destroy();
  return world.destroyed ? 1 : 0;
}

// Meshes and chains (called by main()).
export function meshChainUsage(): number {
  const mesh = new c.Mesh3(new Float32Array([0, 0, 0, 1, 0, 0, 0, 0, 1, 1, 0, 1]), new Uint32Array([0, 2, 1, 1, 2, 3]));
  const tf: c.MeshTransform3 = { position: { x: 0, y: 1, z: 0 } };
  const hit: c.MeshRayHit3 | null = mesh.raycast({ origin: { x: 0.3, y: 3, z: 0.3 }, translation: { x: 0, y: -4, z: 0 } }, tf);
  const any: boolean = mesh.raycastAny({ origin: { x: 0.3, y: 3, z: 0.3 }, translation: { x: 0, y: -4, z: 0 } });
  const tris: Int32Array = mesh.queryAabb({ min: { x: 0, y: -1, z: 0 }, max: { x: 1, y: 1, z: 1 } });
  const ms: c.MeshManifold3[] = mesh.manifolds(sphere({ x: 0.5, y: 0.2, z: 0.5 }, 0.3), undefined, { speculativeDistance: 0.1 });
  const cp: c.MeshClosestPoint3 | null = mesh.closestPoint({ x: 2, y: 0, z: 0 });
  const tri: c.Triangle | null = mesh.triangle(0);
  const over: boolean = mesh.overlap(sphere({ x: 0, y: 0, z: 0 }, 0.1));
  mesh.destroy();
  const chain = new c.Chain2([{ x: 4, y: 0 }, { x: 0, y: 0 }, { x: -4, y: 0 }], { loop: false });
  const chit: c.ChainRayHit2 | null = chain.raycast({ origin: { x: 1, y: 2 }, translation: { x: 0, y: -4 } }, { angle: 0 });
  const seg: c.ChainSegment2 = chain.segment(0);
  const cm: c.ChainManifold2[] = chain.manifolds(circle({ x: 1, y: 0.4 }, 0.5));
  const segs: Int32Array = chain.queryAabb({ min: { x: -1, y: -1 }, max: { x: 1, y: 1 } });
  const pts: Float32Array = chain.points;
  chain.destroy();
  const world = new c.World2();
  const terrain: c.ChainShape2 = world.createBody().createChain(new Float32Array([2, 0, 0, 0, -2, 0]), { friction: 0.4, filter: { groupIndex: 1 } });
  const n = terrain.segmentCount + terrain.segments.length;
  terrain.destroy();
  world.destroy();
  return (hit?.triangleIndex ?? 0) + Number(any) + tris.length + ms.length + (cp?.distance ?? 0) + (tri ? 1 : 0) +
    Number(over) + (chit?.segmentIndex ?? 0) + seg.p1.x + cm.length + segs.length + pts.length + n;
}
