// collide for JavaScript: the package's main module. `await init()` once; everything else is
// synchronous. Modules per area live in lib/; the 2D world is lib/world2.js.
export { init, simdSupported, isSimdBuild } from './lib/wasm.js';
export { WasmArray } from './lib/memory.js';
export {
  circle, capsule2, aabb2, box2, polygon, segment2, MAX_POLYGON_VERTICES, SHAPE2_TYPES,
} from './lib/shapes2.js';
export {
  sphere, capsule3, aabb3, box3, triangle, plane, segment3, hullShape, Hull, SHAPE3_TYPES,
} from './lib/shapes3.js';
export {
  overlap2, containsPoint2, closestPoint2, raycast2, distance2, manifold2, shapeCast2, timeOfImpact2,
  computeAabb2, computeMass2,
} from './lib/query2.js';
export {
  overlap3, containsPoint3, closestPoint3, raycast3, distance3, manifold3, shapeCast3, timeOfImpact3,
  computeAabb3, computeMass3,
} from './lib/query3.js';
export {
  isPointInsideAABB, intersectAABB, isPointInsideSphere, intersectSphere, intersectSphereAABB,
  pointsInsideAABB, pointsInsideSphere, aabbsIntersectAABB, aabbsIntersectSphere, spheresIntersectSphere,
  spheresIntersectAABB,
  rectToAabb, aabbToRect, rectToBox, isPointInsideRect, intersectRect, intersectCircle, intersectPolygon,
  pointsInsideRect, rectsIntersectRect, pointsInsideCircle, circlesIntersectCircle, circlesIntersectRect,
  rectsIntersectCircle,
} from './lib/texts.js';
export { BroadPhase2, BroadPhase3, BROADPHASE_TYPES } from './lib/broadphase.js';
export { Mesh3 } from './lib/mesh3.js';
export { Chain2 } from './lib/chain2.js';
export { World2, Body2, BodyShape2, ChainShape2, Joint2, BODY2_TYPES, JOINT2_TYPES, solvePlanes2, clipVector2 } from './lib/world2.js';
