// TypeScript declarations of the package `collide` (the whole public API of index.js).

// ---- loading -----------------------------------------------------------------------------------

export interface InitOptions {
  /** Force the SIMD build (true) or the scalar build (false); default: feature detection. */
  simd?: boolean;
  /** Where the .wasm file is (URL, path, bytes, Response or compiled module), for bundlers that move it. */
  wasm?: URL | string | ArrayBuffer | ArrayBufferView | Response | WebAssembly.Module;
}
/** Loads the wasm module; afterwards every function is synchronous. Repeated calls share one promise. */
export function init(options?: InitOptions): Promise<void>;
/** True when this engine runs wasm SIMD (the build init() then picks). */
export function simdSupported(): boolean;
/** True when the loaded module is the SIMD build, false for the scalar build (after init()). */
export function isSimdBuild(): boolean;

// ---- values --------------------------------------------------------------------------------------

export interface Vec2 { x: number; y: number }
export interface Vec3 { x: number; y: number; z: number }
/** Unit quaternion (x, y, z, w); identity {x: 0, y: 0, z: 0, w: 1}. */
export interface Quat { x: number; y: number; z: number; w: number }
export interface Aabb2 { min: Vec2; max: Vec2 }
export interface Aabb3 { min: Vec3; max: Vec3 }
/** A ray: the points origin + t * translation for t in [0, 1]. */
export interface Ray2 { origin: Vec2; translation: Vec2 }
export interface Ray3 { origin: Vec3; translation: Vec3 }

// ---- 2D shapes -----------------------------------------------------------------------------------

export interface Circle { type: 'circle'; center: Vec2; radius: number }
export interface Capsule2 { type: 'capsule'; p1: Vec2; p2: Vec2; radius: number }
export interface AabbShape2 { type: 'aabb'; min: Vec2; max: Vec2 }
/** Oriented rectangle; angle in radians, counter-clockwise in y-up axes (clockwise on a y-down canvas). */
export interface Box2 { type: 'box'; center: Vec2; halfExtents: Vec2; angle?: number }
/** Convex polygon: the convex hull of 3 to 8 vertices, optionally rounded by radius. */
export interface Polygon { type: 'polygon'; vertices: Vec2[]; radius?: number; centroid?: Vec2; normals?: Vec2[] }
export interface Segment2 { type: 'segment'; p1: Vec2; p2: Vec2 }
export type Shape2 = Circle | Capsule2 | AabbShape2 | Box2 | Polygon | Segment2;
export const SHAPE2_TYPES: readonly Shape2['type'][];
export const MAX_POLYGON_VERTICES: 8;

export function circle(center: Vec2, radius: number): Circle;
export function capsule2(p1: Vec2, p2: Vec2, radius: number): Capsule2;
export function aabb2(min: Vec2, max: Vec2): AabbShape2;
export function box2(center: Vec2, halfExtents: Vec2, angle?: number): Box2;
/** Builds the convex hull of the points (cd2MakePolygon); RangeError for a degenerate set. */
export function polygon(points: Vec2[], radius?: number): Polygon & { centroid: Vec2; normals: Vec2[]; radius: number };
export function segment2(p1: Vec2, p2: Vec2): Segment2;

// ---- 3D shapes -----------------------------------------------------------------------------------

export interface Sphere { type: 'sphere'; center: Vec3; radius: number }
export interface Capsule3 { type: 'capsule'; p1: Vec3; p2: Vec3; radius: number }
export interface AabbShape3 { type: 'aabb'; min: Vec3; max: Vec3 }
export interface Box3 { type: 'box'; center: Vec3; halfExtents: Vec3; rotation?: Quat }
/** Two-sided flat triangle a-b-c (not solid). */
export interface Triangle { type: 'triangle'; a: Vec3; b: Vec3; c: Vec3 }
/** Solid half-space: the points x with dot(normal, x) <= offset; normal of unit length. */
export interface Plane { type: 'plane'; normal: Vec3; offset: number }
export interface Segment3 { type: 'segment'; p1: Vec3; p2: Vec3 }
/** A Hull placed in the world: position + rotation * (hull point). */
export interface HullShape { type: 'hull'; hull: Hull; position?: Vec3; rotation?: Quat }
export type Shape3 = Sphere | Capsule3 | AabbShape3 | Box3 | Triangle | Plane | Segment3 | HullShape;
export const SHAPE3_TYPES: readonly Shape3['type'][];

export function sphere(center: Vec3, radius: number): Sphere;
export function capsule3(p1: Vec3, p2: Vec3, radius: number): Capsule3;
export function aabb3(min: Vec3, max: Vec3): AabbShape3;
export function box3(center: Vec3, halfExtents: Vec3, rotation?: Quat): Box3;
export function triangle(a: Vec3, b: Vec3, c: Vec3): Triangle;
export function plane(normal: Vec3, offset: number): Plane;
export function segment3(p1: Vec3, p2: Vec3): Segment3;
export function hullShape(hull: Hull, position?: Vec3, rotation?: Quat): HullShape;

/** A convex hull in wasm memory (quickhull). Immutable and shareable; call destroy() when done. */
export class Hull {
  private constructor();
  /** Hull of an array of points or of a packed array of x, y, z triples (up to 16384 points). */
  static fromPoints(points: Vec3[] | Float32Array | Float64Array): Hull;
  static box(halfExtents: Vec3): Hull;
  static cylinder(halfHeight: number, radius: number, segments?: number): Hull;
  static cone(halfHeight: number, radius: number, segments?: number): Hull;
  readonly vertexCount: number;
  readonly faceCount: number;
  readonly edgeCount: number;
  readonly volume: number;
  readonly centroid: Vec3;
  readonly bounds: Aabb3;
  /** x, y, z per vertex (a copy). */
  readonly vertices: Float32Array;
  readonly destroyed: boolean;
  destroy(): void;
}

// ---- meshes and chains ---------------------------------------------------------------------------

/** A mesh's placement in the world (identity when omitted). */
export interface MeshTransform3 { position?: Vec3; rotation?: Quat }
export interface MeshRayHit3 extends RayHit3 { triangleIndex: number }
export interface MeshClosestPoint3 { point: Vec3; distance: number; triangleIndex: number }
export interface MeshManifold3 extends Manifold3 { triangleIndex: number }
export interface ManifoldOptions { speculativeDistance?: number; capacity?: number }

/**
 * A triangle mesh in wasm memory (cd3CreateMesh) with a static BVH. Vertices x, y, z per vertex,
 * indices three per triangle (counter-clockwise from the front). Zero-area triangles are dropped;
 * the others keep their input index. Call destroy() when done.
 */
export class Mesh3 {
  constructor(vertices: Float32Array | Float64Array | number[], indices: Uint32Array | Int32Array | Uint16Array | Uint8Array | number[]);
  readonly triangleCount: number;
  readonly droppedTriangleCount: number;
  readonly vertexCount: number;
  readonly nodeCount: number;
  readonly leafCount: number;
  readonly depth: number;
  readonly activeEdgeCount: number;
  /** Of the kept triangles, mesh space. */
  readonly bounds: Aabb3;
  readonly bytes: number;
  readonly destroyed: boolean;
  /** Triangle by input index (mesh space); null for a dropped one. */
  triangle(index: number): Triangle | null;
  validate(): boolean;
  raycast(ray: Ray3, transform?: MeshTransform3): MeshRayHit3 | null;
  raycastAny(ray: Ray3, transform?: MeshTransform3): boolean;
  /** Input indices of the triangles whose bounds overlap `bounds` (mesh space). */
  queryAabb(bounds: Aabb3): Int32Array;
  overlap(shape: Shape3, transform?: MeshTransform3): boolean;
  closestPoint(point: Vec3, transform?: MeshTransform3, maxDistance?: number): MeshClosestPoint3 | null;
  /** Sphere, capsule, aabb, box or hull against the mesh: one manifold per triangle in contact. */
  manifolds(shape: Sphere | Capsule3 | AabbShape3 | Box3 | HullShape, transform?: MeshTransform3, options?: ManifoldOptions): MeshManifold3[];
  destroy(): void;
}

/** A chain's placement in the world (identity when omitted). */
export interface ChainTransform2 { position?: Vec2; angle?: number }
export interface ChainRayHit2 extends RayHit2 { segmentIndex: number }
export interface ChainManifold2 extends Manifold2 { segmentIndex: number }
export interface ChainSegment2 { ghost1: Vec2; p1: Vec2; p2: Vec2; ghost2: Vec2 }

/**
 * A chain in wasm memory (cd2CreateChain): a polyline (or loop) of one-sided segments, free side to
 * the right of each segment's direction. Call destroy() when done.
 */
export class Chain2 {
  constructor(points: Vec2[] | Float32Array | Float64Array, options?: { loop?: boolean });
  readonly segmentCount: number;
  readonly pointCount: number;
  readonly loop: boolean;
  /** In the chain's frame. */
  readonly bounds: Aabb2;
  /** x, y pairs after welding (a copy). */
  readonly points: Float32Array;
  readonly destroyed: boolean;
  segment(index: number): ChainSegment2;
  raycast(ray: Ray2, transform?: ChainTransform2): ChainRayHit2 | null;
  /** Segments whose bounds overlap `bounds` (world space), increasing. */
  queryAabb(bounds: Aabb2, transform?: ChainTransform2): Int32Array;
  /** The chain (A) against a shape (B, world space): one manifold per segment in contact. */
  manifolds(shape: Shape2, transform?: ChainTransform2, options?: ManifoldOptions): ChainManifold2[];
  destroy(): void;
}

// ---- queries -------------------------------------------------------------------------------------

export interface RayHit2 { fraction: number; point: Vec2; normal: Vec2 }
export interface RayHit3 { fraction: number; point: Vec3; normal: Vec3 }
export interface ClosestPoints2 { pointA: Vec2; pointB: Vec2; distance: number; iterations: number; hitIterationCap: boolean }
export interface ClosestPoints3 { pointA: Vec3; pointB: Vec3; distance: number; iterations: number; hitIterationCap: boolean }
export interface ManifoldPoint2 { point: Vec2; separation: number; id: number }
export interface ManifoldPoint3 { point: Vec3; separation: number; id: number }
/** normal points from a to b; no points when the shapes are apart by more than the speculative distance. */
export interface Manifold2 { normal: Vec2; points: ManifoldPoint2[] }
export interface Manifold3 { normal: Vec3; points: ManifoldPoint3[] }
export interface CastOutput2 { hit: boolean; hitIterationCap: boolean; fraction: number; point: Vec2; normal: Vec2; iterations: number }
export interface CastOutput3 { hit: boolean; hitIterationCap: boolean; fraction: number; point: Vec3; normal: Vec3; iterations: number }
export interface Sweep2 { localCenter?: Vec2; center0: Vec2; center1?: Vec2; angle0?: number; angle1?: number }
export interface Sweep3 { localCenter?: Vec3; center0: Vec3; center1?: Vec3; rotation0?: Quat; rotation1?: Quat }
export interface ToiOptions { targetSeparation?: number; tolerance?: number }
export interface ToiOutput { state: 'hit' | 'separated' | 'overlapped' | 'failed'; t: number; iterations: number }
export interface MassData2 { mass: number; center: Vec2; rotationalInertia: number }
export interface MassData3 { mass: number; center: Vec3; inertia: number[] }

export function overlap2(a: Shape2, b: Shape2): boolean;
export function containsPoint2(shape: Shape2, point: Vec2): boolean;
export function closestPoint2(shape: Shape2, point: Vec2): Vec2;
export function raycast2(shape: Shape2, ray: Ray2): RayHit2 | null;
export function distance2(a: Shape2, b: Shape2): ClosestPoints2;
export function manifold2(a: Shape2, b: Shape2, speculativeDistance?: number): Manifold2;
export function shapeCast2(a: Shape2, b: Shape2, translation: Vec2): CastOutput2;
export function timeOfImpact2(a: Shape2, sweepA: Sweep2, b: Shape2, sweepB: Sweep2, options?: ToiOptions): ToiOutput;
export function computeAabb2(shape: Shape2): Aabb2;
export function computeMass2(shape: Shape2, density?: number): MassData2;

export function overlap3(a: Shape3, b: Shape3): boolean;
export function containsPoint3(shape: Shape3, point: Vec3): boolean;
export function closestPoint3(shape: Shape3, point: Vec3): Vec3;
export function raycast3(shape: Shape3, ray: Ray3): RayHit3 | null;
export function distance3(a: Shape3, b: Shape3): ClosestPoints3;
export function manifold3(a: Shape3, b: Shape3, speculativeDistance?: number): Manifold3;
export function shapeCast3(a: Shape3, b: Shape3, translation: Vec3): CastOutput3;
export function timeOfImpact3(a: Shape3, sweepA: Sweep3, b: Shape3, sweepB: Sweep3, options?: ToiOptions): ToiOutput;
export function computeAabb3(shape: Shape3): Aabb3;
/** Solid shapes only (not triangle, plane, segment). inertia: 9 numbers, row by row. */
export function computeMass3(shape: Shape3, density?: number): MassData3;

// ---- the texts' tests, batch forms and canvas helpers ------------------------------------------------

export interface TextPoint { x: number; y: number; z: number }
export interface TextAABB { minX: number; maxX: number; minY: number; maxY: number; minZ: number; maxZ: number }
export interface TextSphere { x: number; y: number; z: number; radius: number }
/** Canvas rectangle (y down): top-left corner and size. */
export interface Rect { x: number; y: number; width: number; height: number }
export interface TextCircle { x: number; y: number; radius: number }

export function isPointInsideAABB(point: TextPoint, box: TextAABB): boolean;
export function intersectAABB(a: TextAABB, b: TextAABB): boolean;
export function isPointInsideSphere(point: TextPoint, sphere: TextSphere): boolean;
export function intersectSphere(a: TextSphere, b: TextSphere): boolean;
export function intersectSphereAABB(sphere: TextSphere, box: TextAABB): boolean;

/** Batch forms: an array of objects or a packed Float32Array (points x y z; AABBs minX minY minZ maxX maxY maxZ; spheres x y z radius); returns the indices that pass. */
export function pointsInsideAABB(points: TextPoint[] | Float32Array | WasmArray<'f32'>, box: TextAABB): Int32Array;
export function pointsInsideSphere(points: TextPoint[] | Float32Array | WasmArray<'f32'>, sphere: TextSphere): Int32Array;
export function aabbsIntersectAABB(boxes: TextAABB[] | Float32Array | WasmArray<'f32'>, box: TextAABB): Int32Array;
export function aabbsIntersectSphere(boxes: TextAABB[] | Float32Array | WasmArray<'f32'>, sphere: TextSphere): Int32Array;
export function spheresIntersectSphere(spheres: TextSphere[] | Float32Array | WasmArray<'f32'>, sphere: TextSphere): Int32Array;
export function spheresIntersectAABB(spheres: TextSphere[] | Float32Array | WasmArray<'f32'>, box: TextAABB): Int32Array;

export function rectToAabb(rect: Rect): AabbShape2;
export function aabbToRect(aabb: Aabb2): Rect;
export function rectToBox(rect: Rect, angle?: number): Box2;
export function isPointInsideRect(point: Vec2, rect: Rect): boolean;
export function intersectRect(a: Rect, b: Rect): boolean;
export function intersectCircle(a: TextCircle, b: TextCircle): boolean;
export function intersectPolygon(a: Vec2[], b: Vec2[]): boolean;
/** 2D batch forms (packed: points x y; rects minX minY maxX maxY; circles x y radius). */
export function pointsInsideRect(points: Vec2[] | Float32Array | WasmArray<'f32'>, rect: Rect): Int32Array;
export function rectsIntersectRect(rects: Rect[] | Float32Array | WasmArray<'f32'>, rect: Rect): Int32Array;
export function pointsInsideCircle(points: Vec2[] | Float32Array | WasmArray<'f32'>, circle: TextCircle): Int32Array;
export function circlesIntersectCircle(circles: TextCircle[] | Float32Array | WasmArray<'f32'>, circle: TextCircle): Int32Array;
export function circlesIntersectRect(circles: TextCircle[] | Float32Array | WasmArray<'f32'>, rect: Rect): Int32Array;
export function rectsIntersectCircle(rects: Rect[] | Float32Array | WasmArray<'f32'>, circle: TextCircle): Int32Array;

// ---- wasm-resident arrays ----------------------------------------------------------------------

/** A typed array in wasm memory, read in place by batch queries and moveProxies. Pass the WasmArray itself to those calls (not a view kept from earlier: growing wasm memory detaches old views). */
export class WasmArray<K extends 'f32' | 'i32' = 'f32' | 'i32'> {
  constructor(kind: K, length: number);
  readonly kind: K;
  readonly length: number;
  /** A view of the elements; take it again after calls that may grow wasm memory. */
  readonly array: K extends 'f32' ? Float32Array : Int32Array;
  readonly destroyed: boolean;
  destroy(): void;
}

// ---- broadphase --------------------------------------------------------------------------------

export type BroadPhaseType = 'tree' | 'sap' | 'grid' | 'spatialTree';
export const BROADPHASE_TYPES: readonly BroadPhaseType[];
export interface BroadPhaseDef<A> {
  type?: BroadPhaseType;
  /** Fat-box margin on every side (default 0.1). */
  margin?: number;
  /** Predicted displacement multiplier (default 4). */
  displacementMultiplier?: number;
  /** Grid cell size; 0 picks one from the first proxies. */
  cellSize?: number;
  /** Quadtree/octree root region. */
  bounds?: A | number[] | Float32Array;
  capacity?: number;
}
export interface BroadPhaseStats { proxyCount: number; nodeCount: number; height: number; memoryBytes: number; sahCost: number }

declare class BroadPhaseBase<V, A, R> {
  readonly dim: number;
  readonly type: BroadPhaseType;
  readonly destroyed: boolean;
  readonly proxyCount: number;
  readonly stats: BroadPhaseStats;
  createProxy(aabb: A | number[] | Float32Array): number;
  createProxies(aabbs: Float32Array | WasmArray<'f32'>): Int32Array;
  destroyProxy(id: number): void;
  hasProxy(id: number): boolean;
  moveProxy(id: number, aabb: A | number[] | Float32Array, displacement?: V): boolean;
  moveProxies(ids: Int32Array | WasmArray<'i32'>, aabbs: Float32Array | WasmArray<'f32'>, displacements?: Float32Array | WasmArray<'f32'>): number;
  /** Pairs [a0, b0, a1, b1, ...] (a < b, sorted) with at least one moved proxy since the last call. */
  updatePairs(): Int32Array;
  findAllPairs(): Int32Array;
  query(aabb: A | number[] | Float32Array): Int32Array;
  rayCast(ray: R): { ids: Int32Array; fractions: Float32Array };
  getFatAabb(id: number): A;
  rebuild(): void;
  validate(): boolean;
  destroy(): void;
}
export class BroadPhase2 extends BroadPhaseBase<Vec2, Aabb2, Ray2> {
  constructor(def?: BroadPhaseDef<Aabb2>);
}
export class BroadPhase3 extends BroadPhaseBase<Vec3, Aabb3, Ray3> {
  constructor(def?: BroadPhaseDef<Aabb3>);
}

// ---- the 2D world (collide/world2.h) --------------------------------------------------------

export type BodyType2 = 'static' | 'kinematic' | 'dynamic';
export type JointType2 = 'distance' | 'filter' | 'motor' | 'mouse' | 'prismatic' | 'revolute' | 'weld' | 'wheel';
export const BODY2_TYPES: readonly BodyType2[];
export const JOINT2_TYPES: readonly JointType2[];

/** 64-bit masks: a number up to 2^53 - 1 or a bigint. */
export type Bits64 = number | bigint;
export interface Filter2 { categoryBits?: Bits64; maskBits?: Bits64; groupIndex?: number }
export interface QueryFilter2 { categoryBits?: Bits64; maskBits?: Bits64 }

export interface WorldDef2 {
  gravity?: Vec2; enableSleep?: boolean; enableContinuous?: boolean;
  contactHertz?: number; contactDampingRatio?: number; jointHertz?: number; jointDampingRatio?: number;
  restitutionThreshold?: number; hitEventThreshold?: number; maximumLinearSpeed?: number; contactPushMaxVelocity?: number;
  /** metres (default 0.02): a contact whose bodies moved less than this relative to each other keeps its manifold; 0 turns it off */
  contactRecycleDistance?: number;
}

export interface BodyDef2 {
  type?: BodyType2; position?: Vec2; angle?: number; linearVelocity?: Vec2; angularVelocity?: number;
  linearDamping?: number; angularDamping?: number; gravityScale?: number; sleepThreshold?: number;
  enableSleep?: boolean; isAwake?: boolean; fixedRotation?: boolean; isBullet?: boolean; isEnabled?: boolean;
  userData?: unknown;
}

export interface ShapeDef2 {
  density?: number; friction?: number; restitution?: number; rollingResistance?: number; tangentSpeed?: number;
  filter?: Filter2; isSensor?: boolean; enableSensorEvents?: boolean; enableContactEvents?: boolean;
  enableHitEvents?: boolean; enablePreSolveEvents?: boolean; userData?: unknown;
}

export interface JointDef2 {
  type: JointType2; bodyA: Body2; bodyB: Body2;
  localAnchorA?: Vec2; localAnchorB?: Vec2; localAxisA?: Vec2; referenceAngle?: number;
  enableSpring?: boolean; hertz?: number; dampingRatio?: number;
  enableLimit?: boolean; lowerAngle?: number; upperAngle?: number; lowerTranslation?: number; upperTranslation?: number;
  minLength?: number; maxLength?: number; length?: number;
  enableMotor?: boolean; maxMotorTorque?: number; maxMotorForce?: number; motorSpeed?: number;
  collideConnected?: boolean; target?: Vec2; maxForce?: number; maxTorque?: number;
  linearOffset?: Vec2; angularOffset?: number; correctionFactor?: number;
  linearHertz?: number; linearDampingRatio?: number; angularHertz?: number; angularDampingRatio?: number;
  /** Joint events (getEvents().joints) when the reaction force (N) or torque (N m) exceeds it; 0 (default): none. Not for filter joints. */
  forceThreshold?: number; torqueThreshold?: number;
  /** Distance, prismatic, revolute, weld and wheel joints: the constraints' own softness; 0 (default): the world's jointHertz / jointDampingRatio. */
  constraintHertz?: number; constraintDampingRatio?: number;
  userData?: unknown;
}

export interface Transform2 { x: number; y: number; cos: number; sin: number }
export interface Counters2 {
  bodyCount: number; shapeCount: number; contactCount: number; touchingContactCount: number;
  jointCount: number; awakeBodyCount: number; islandCount: number;
}
export interface ContactManifold2 { normal: Vec2; points: Vec2[]; separation: number }
export interface WorldEvents2 {
  contactBegin: { shapeA: BodyShape2 | null; shapeB: BodyShape2 | null; normal: Vec2; points: { x: number; y: number; separation: number }[] }[];
  contactEnd: { shapeA: BodyShape2 | null; shapeB: BodyShape2 | null }[];
  hits: { shapeA: BodyShape2 | null; shapeB: BodyShape2 | null; point: Vec2; normal: Vec2; approachSpeed: number }[];
  sensorBegin: { sensor: BodyShape2 | null; visitor: BodyShape2 | null }[];
  sensorEnd: { sensor: BodyShape2 | null; visitor: BodyShape2 | null }[];
  moves: { body: Body2 | null; x: number; y: number; cos: number; sin: number; fellAsleep: boolean }[];
  /** Joints whose reaction exceeded their forceThreshold or torqueThreshold in the last step (destroy one to break it). */
  joints: { joint: Joint2 | null; force: Vec2; torque: number }[];
}
export interface WorldHit2 { shape: BodyShape2 | null; point: Vec2; normal: Vec2; fraction: number }

/** A 2D physics world. Call destroy() when done. */
export class World2 {
  constructor(def?: WorldDef2);
  /** The bodies, in the order of getTransforms(). */
  readonly bodies: Body2[];
  readonly destroyed: boolean;
  destroy(): void;
  step(timeStep: number, subStepCount?: number): void;
  gravity: Vec2;
  enableSleeping(flag: boolean): void;
  enableContinuous(flag: boolean): void;
  readonly counters: Counters2;
  createBody(def?: BodyDef2): Body2;
  createJoint(def: JointDef2): Joint2;
  /** 4 floats per body (x, y, cos, sin): a view of wasm memory, refreshed by each call. */
  getTransforms(): Float32Array;
  /** 7 floats per body (x, y, cos, sin, vx, vy, angular velocity), a copy. */
  getStates(): Float32Array;
  getEvents(): WorldEvents2;
  setPreSolve(fcn: ((shapeA: BodyShape2 | null, shapeB: BodyShape2 | null, manifold: ContactManifold2) => boolean) | null): void;
  setCustomFilter(fcn: ((shapeA: BodyShape2 | null, shapeB: BodyShape2 | null) => boolean) | null): void;
  overlapAabb(aabb: Aabb2, filter?: QueryFilter2): (BodyShape2 | null)[];
  overlapShape(shape: Shape2, filter?: QueryFilter2): (BodyShape2 | null)[];
  raycastClosest(origin: Vec2, translation: Vec2, filter?: QueryFilter2): WorldHit2 | null;
  raycast(origin: Vec2, translation: Vec2, filter?: QueryFilter2): WorldHit2[];
  shapeCast(shape: Shape2, translation: Vec2, filter?: QueryFilter2): WorldHit2[];
  saveState(): Uint8Array;
  restoreState(state: Uint8Array | ArrayBuffer | ArrayBufferView): void;
  /** Kinematic character mover: planes of the shapes touching a world-space capsule. */
  collideMover(capsule: MoverCapsule2, filter?: QueryFilter2): MoverPlane2[];
  /** Fraction of translation the capsule can move before it touches a shape it does not overlap. */
  castMover(capsule: MoverCapsule2, translation: Vec2, filter?: QueryFilter2): number;
  /** One frame of the mover loop; capsule in the character's frame. */
  moveCharacter(options: { capsule: MoverCapsule2; position: Vec2; velocity: Vec2; dt: number; filter?: QueryFilter2; oneWayBits?: Bits64 }):
    { position: Vec2; velocity: Vec2; planes: MoverPlane2[] };
}

export interface MoverCapsule2 { p1: Vec2; p2: Vec2; radius: number }
export interface MoverPlane2 { shape: BodyShape2 | null; normal: Vec2; separation: number; point: Vec2 }
export function solvePlanes2(targetDelta: Vec2, planes: { normal: Vec2; separation: number; point?: Vec2 }[]): Vec2;
export function clipVector2(vector: Vec2, planes: { normal: Vec2; separation: number; point?: Vec2 }[]): Vec2;

export class Body2 {
  private constructor();
  readonly world: World2;
  readonly destroyed: boolean;
  userData: unknown;
  destroy(): void;
  type: BodyType2;
  position: Vec2;
  angle: number;
  readonly transform: Transform2;
  setTransform(position: Vec2, angle: number): void;
  linearVelocity: Vec2;
  angularVelocity: number;
  readonly mass: number;
  readonly inertia: number;
  readonly worldCenterOfMass: Vec2;
  awake: boolean;
  enabled: boolean;
  fixedRotation: boolean;
  bullet: boolean;
  gravityScale: number;
  linearDamping: number;
  angularDamping: number;
  enableSleep(flag: boolean): void;
  applyForce(force: Vec2, point: Vec2, wake?: boolean): void;
  applyForceToCenter(force: Vec2, wake?: boolean): void;
  applyTorque(torque: number, wake?: boolean): void;
  applyLinearImpulse(impulse: Vec2, point: Vec2, wake?: boolean): void;
  applyLinearImpulseToCenter(impulse: Vec2, wake?: boolean): void;
  applyAngularImpulse(impulse: number, wake?: boolean): void;
  readonly shapes: BodyShape2[];
  createShape(geometry: Shape2, def?: ShapeDef2): BodyShape2;
  /** One-sided terrain (cd2CreateChainShape): a floor runs from right to left, a loop around a solid counter-clockwise. */
  createChain(points: Vec2[] | Float32Array | Float64Array, options?: ChainShapeOptions2): ChainShape2;
}

export interface ChainShapeOptions2 {
  loop?: boolean;
  friction?: number;
  restitution?: number;
  filter?: Filter2;
  enableSensorEvents?: boolean;
}

/** A chain on a body: its segment shapes; destroy() removes them all. */
export class ChainShape2 {
  private constructor();
  readonly body: Body2;
  /** The segment shapes (type 'chainSegment'), in chain order. */
  readonly segments: BodyShape2[];
  readonly segmentCount: number;
  readonly destroyed: boolean;
  destroy(): void;
}

/** A shape attached to a body (the geometry types are Shape2). */
export class BodyShape2 {
  private constructor();
  readonly body: Body2;
  readonly destroyed: boolean;
  userData: unknown;
  destroy(): void;
  readonly type: 'circle' | 'capsule' | 'polygon' | 'segment' | 'chainSegment';
  readonly isSensor: boolean;
  density: number;
  friction: number;
  restitution: number;
  readonly aabb: Aabb2;
  filter: Filter2 | { categoryBits: bigint; maskBits: bigint; groupIndex: number };
  enableSensorEvents(flag: boolean): void;
  enableContactEvents(flag: boolean): void;
  enableHitEvents(flag: boolean): void;
  enablePreSolveEvents(flag: boolean): void;
}

export class Joint2 {
  private constructor();
  readonly world: World2;
  readonly type: JointType2;
  readonly bodyA: Body2;
  readonly bodyB: Body2;
  readonly destroyed: boolean;
  userData: unknown;
  destroy(): void;
  readonly constraintForce: Vec2;
  readonly constraintTorque: number;
  /** Joint event thresholds (>= 0; 0: none). */
  forceThreshold: number;
  torqueThreshold: number;
  readonly constraintHertz: number;
  readonly constraintDampingRatio: number;
  setConstraintTuning(hertz: number, dampingRatio: number): void;
  readonly angle: number;
  readonly translation: number;
  readonly currentLength: number;
  enableMotor(flag: boolean): void;
  set motorSpeed(v: number);
  set maxMotor(v: number);
  enableLimit(flag: boolean): void;
  setLimits(lower: number, upper: number): void;
  enableSpring(flag: boolean): void;
  set springHertz(v: number);
  set springDampingRatio(v: number);
  set target(t: Vec2);
  set length(v: number);
  set linearOffset(v: Vec2);
  set angularOffset(v: number);
  wakeBodies(): void;
}
