// The 2D world (collide/world2.h) for JavaScript: World2 with Body2, BodyShape2 and Joint2 handles.
// Export layer: src/world2_exports.c. Ids are (index1, generation) pairs inside one world; a
// handle whose object was destroyed (by destroy(), with its body, or by restoring an older
// snapshot) throws a TypeError naming the call.
import * as w from './wasm.js';
import { num, nonNeg, int, obj, vec2, bool, fn, describe, throwResult, track, untrack } from './check.js';
import { encode2 } from './shapes2.js';
import { stagePoints2, chainError } from './chain2.js';

const BODY_TYPES = ['static', 'kinematic', 'dynamic'];
const SHAPE_TYPES = ['circle', 'capsule', 'polygon', 'segment', 'chainSegment'];
const JOINT_TYPES = ['distance', 'filter', 'motor', 'mouse', 'prismatic', 'revolute', 'weld', 'wheel'];
const NO_VALUE = NaN;

const io = () => w.S + 128;

// The module's exports, each followed by a refresh of the typed views (any call may grow memory).
let wrapped = null;
function E() {
  if (wrapped === null) {
    wrapped = {};
    for (const [k, f] of Object.entries(w.exports)) {
      if (typeof f === 'function') wrapped[k] = (...args) => { const r = f(...args); w.views(); return r; };
    }
  }
  return wrapped;
}
const key = (index1, generation) => index1 * 4294967296 + (generation >>> 0);

function opt(def, k, check = num) {
  return def[k] === undefined ? NO_VALUE : check(def[k], `def.${k}`);
}
function optFlag(def, k) {
  return def[k] === undefined ? NO_VALUE : (bool(def[k], `def.${k}`) ? 1 : 0);
}
function optVec(def, k) {
  return def[k] === undefined ? [NO_VALUE, NO_VALUE] : vec2(def[k], `def.${k}`);
}

/** Splits a 64-bit mask (number up to 2^53 - 1 or bigint) into two uint32 words. */
function bits64(v, name, fallback) {
  if (v === undefined) return fallback;
  if (typeof v === 'bigint') {
    if (v < 0n || v > 0xFFFFFFFFFFFFFFFFn) throw new RangeError(`${name} must fit in 64 bits, got ${v}`);
    return [Number(v & 0xFFFFFFFFn), Number(v >> 32n)];
  }
  if (typeof v !== 'number') throw new TypeError(`${name} must be a number or a bigint, got ${describe(v)}`);
  if (!Number.isSafeInteger(v) || v < 0) throw new RangeError(`${name} must be an integer in [0, 2^53) (or a bigint), got ${v}`);
  return [v % 4294967296, Math.floor(v / 4294967296)];
}
const ALL_BITS = [0xFFFFFFFF, 0xFFFFFFFF];

function writeWords(at, words) {
  w.U32[at] = words[0] >>> 0;
  w.U32[at + 1] = words[1] >>> 0;
}
function readBits(at) {
  return (BigInt(w.U32[at + 1]) << 32n) | BigInt(w.U32[at]);
}

function writeQueryFilter(at, filter, name) {
  if (filter === undefined) filter = {};
  obj(filter, name);
  writeWords(at, bits64(filter.categoryBits, `${name}.categoryBits`, [1, 0]));
  writeWords(at + 2, bits64(filter.maskBits, `${name}.maskBits`, ALL_BITS));
}

function staleError(what, call) {
  return new TypeError(`${call}: this ${what} was destroyed (or belongs to a destroyed world or body, or to a state restored from before it existed)`);
}

let worldsById = new Map();

w.callbacks.preSolve = (world0, ia, ga, ib, gb, ptr) => {
  const world = worldsById.get(world0);
  if (world === undefined || world._preSolve === null) return 1;
  w.views();
  const f = w.F32, p = ptr >> 2, n = w.I32[p + 2];
  const manifold = {
    normal: { x: f[p], y: f[p + 1] },
    points: [],
  };
  for (let k = 0; k < n; k++) manifold.points.push({ x: f[p + 3 + 2 * k], y: f[p + 4 + 2 * k] });
  manifold.separation = f[p + 7];
  return world._preSolve(world._shape(ia, ga), world._shape(ib, gb), manifold) === false ? 0 : 1;
};
w.callbacks.customFilter = (world0, ia, ga, ib, gb) => {
  const world = worldsById.get(world0);
  if (world === undefined || world._customFilter === null) return 1;
  return world._customFilter(world._shape(ia, ga), world._shape(ib, gb)) === false ? 0 : 1;
};

export class World2 {
  /**
   * @param {object} [def] gravity {x, y} (default (0, -10)), enableSleep, enableContinuous,
   *   contactHertz, contactDampingRatio, jointHertz, jointDampingRatio, restitutionThreshold,
   *   hitEventThreshold, maximumLinearSpeed, contactPushMaxVelocity, contactRecycleDistance
   *   (metres, default 0.02; 0 runs the narrowphase for every contact every step).
   */
  constructor(def = {}) {
    w.requireInit();
    obj(def, 'def');
    const g = optVec(def, 'gravity');
    const values = [g[0], g[1], optFlag(def, 'enableSleep'), optFlag(def, 'enableContinuous'),
      opt(def, 'contactHertz', nonNeg), opt(def, 'contactDampingRatio', nonNeg), opt(def, 'jointHertz', nonNeg),
      opt(def, 'jointDampingRatio', nonNeg), opt(def, 'restitutionThreshold', nonNeg), opt(def, 'hitEventThreshold', nonNeg),
      opt(def, 'maximumLinearSpeed', nonNeg), opt(def, 'contactPushMaxVelocity', nonNeg),
      opt(def, 'contactRecycleDistance', nonNeg)];
    w.F32.set(values, io());
    const index1 = E().world2Create();
    if (index1 === 0) throw new RangeError('def is not valid, or too many worlds exist (at most 128)');
    this._w = index1 - 1;
    /** @type {Body2[]} the bodies in the order of getTransforms() */
    this.bodies = [];
    this._bodies = new Map();
    this._shapes = new Map();
    this._joints = new Map();
    this._preSolve = null;
    this._customFilter = null;
    this._transforms = null;
    this._transformsBuffer = null;
    this._transformsPtr = 0;
    this._transformsCount = -1;
    worldsById.set(this._w, this);
    track(this, 'World2');
  }

  get destroyed() { return this._w < 0; }

  _check(call) {
    if (this._w < 0) throw new TypeError(`${call}: this World2 was destroyed`);
  }

  _shape(index1, generation) {
    return this._shapes.get(key(index1, generation)) ?? null;
  }

  _body(index1, generation) {
    return this._bodies.get(key(index1, generation)) ?? null;
  }

  destroy() {
    if (this._w < 0) return;
    E().world2Destroy(this._w);
    for (const b of this.bodies) b._dead();
    for (const j of this._joints.values()) j._w = -1;
    worldsById.delete(this._w);
    this.bodies = [];
    this._bodies.clear();
    this._shapes.clear();
    this._joints.clear();
    this._w = -1;
    untrack(this);
  }

  /** Advances the world by timeStep seconds (> 0) in subStepCount sub-steps (default 4). */
  step(timeStep, subStepCount = 4) {
    this._check('step');
    num(timeStep, 'timeStep');
    if (timeStep < 0) throw new RangeError(`timeStep must be >= 0, got ${timeStep}`);
    int(subStepCount, 'subStepCount', 1, 1000);
    E().world2Step(this._w, timeStep, subStepCount);
  }

  get gravity() {
    this._check('gravity');
    E().world2GetGravity(this._w);
    return { x: w.F32[io()], y: w.F32[io() + 1] };
  }

  set gravity(g) {
    this._check('gravity');
    const v = vec2(g, 'gravity');
    E().world2SetGravity(this._w, v[0], v[1]);
  }

  enableSleeping(flag) {
    this._check('enableSleeping');
    E().world2EnableSleeping(this._w, bool(flag, 'flag') ? 1 : 0);
  }

  enableContinuous(flag) {
    this._check('enableContinuous');
    E().world2EnableContinuous(this._w, bool(flag, 'flag') ? 1 : 0);
  }

  /** Counts: bodyCount, shapeCount, contactCount, touchingContactCount, jointCount, awakeBodyCount, islandCount. */
  get counters() {
    this._check('counters');
    E().world2Counters(this._w);
    const i = w.I32, p = io();
    return {
      bodyCount: i[p], shapeCount: i[p + 1], contactCount: i[p + 2], touchingContactCount: i[p + 3],
      jointCount: i[p + 4], awakeBodyCount: i[p + 5], islandCount: i[p + 6],
    };
  }

  /**
   * Creates a body. def: type ('static' (default), 'kinematic', 'dynamic'), position {x, y},
   * angle, linearVelocity {x, y}, angularVelocity, linearDamping, angularDamping, gravityScale,
   * sleepThreshold, enableSleep, isAwake, fixedRotation, isBullet, isEnabled, userData.
   */
  createBody(def = {}) {
    this._check('createBody');
    obj(def, 'def');
    let type = NO_VALUE;
    if (def.type !== undefined) {
      type = BODY_TYPES.indexOf(def.type);
      if (type < 0) throw new TypeError(`def.type must be one of 'static', 'kinematic', 'dynamic', got ${describe(def.type)}`);
    }
    const p = optVec(def, 'position'), v = optVec(def, 'linearVelocity');
    const values = [type, p[0], p[1], opt(def, 'angle'), v[0], v[1], opt(def, 'angularVelocity'),
      opt(def, 'linearDamping', nonNeg), opt(def, 'angularDamping', nonNeg), opt(def, 'gravityScale'),
      opt(def, 'sleepThreshold', nonNeg), optFlag(def, 'enableSleep'), optFlag(def, 'isAwake'),
      optFlag(def, 'fixedRotation'), optFlag(def, 'isBullet'), optFlag(def, 'isEnabled')];
    w.F32.set(values, io());
    const index1 = E().body2Create(this._w);
    if (index1 === 0) throw new RangeError('def is not valid (or wasm memory ran out)');
    const body = new Body2(this, index1, w.I32[io()], this.bodies.length);
    body.userData = def.userData;
    this.bodies.push(body);
    this._bodies.set(key(index1, body._g), body);
    return body;
  }

  _removeBody(body) {
    const slot = body._slot;
    E().body2Destroy(this._w, slot);
    const last = this.bodies.pop();
    if (last !== body) {
      this.bodies[slot] = last;
      last._slot = slot;
    }
    this._bodies.delete(key(body._i, body._g));
    for (const s of body._shapeList) this._shapes.delete(key(s._i, s._g));
    body._dead();
  }

  /**
   * Every body's transform as one Float32Array view of wasm memory: 4 floats per body (x, y,
   * cos, sin of its rotation), in the order of `world.bodies`. The view is refreshed by each call
   * (take it again after each step; it is detached when wasm memory grows).
   */
  getTransforms() {
    this._check('getTransforms');
    const ptr = E().world2Transforms(this._w);
    if (ptr === 0) throw new Error('collide: out of wasm memory');
    const buffer = w.memoryBuffer(), n = this.bodies.length;
    if (this._transformsBuffer !== buffer || this._transformsPtr !== ptr || this._transformsCount !== n) {
      this._transforms = new Float32Array(buffer, ptr, 4 * n);
      this._transformsBuffer = buffer;
      this._transformsPtr = ptr;
      this._transformsCount = n;
    }
    return this._transforms;
  }

  /** Every body's state (x, y, cos, sin, vx, vy, angular velocity: 7 floats per body) as a new Float32Array. */
  getStates() {
    this._check('getStates');
    const ptr = E().world2States(this._w);
    if (ptr === 0 && this.bodies.length > 0) throw new Error('collide: out of wasm memory');
    w.views();
    return new Float32Array(w.memoryBuffer(), ptr, 7 * this.bodies.length).slice();
  }

  /**
   * The events of the last step: contactBegin [{shapeA, shapeB, normal, points: [{x, y,
   * separation}]}], contactEnd [{shapeA, shapeB}], hits [{shapeA, shapeB, point, normal,
   * approachSpeed}], sensorBegin and sensorEnd [{sensor, visitor}], moves [{body, x, y, cos, sin,
   * fellAsleep}], joints [{joint, force, torque}] (over their thresholds). Shapes, bodies and joints
   * destroyed since the step come back as null.
   */
  getEvents() {
    this._check('getEvents');
    const ptr = E().world2Events(this._w);
    if (ptr === 0) throw new Error('collide: out of wasm memory');
    w.views();
    const f = w.F32, i = w.I32;
    let p = ptr >> 2;
    const [nb, ne, nh, nsb, nse, nm, nj] = [i[p], i[p + 1], i[p + 2], i[p + 3], i[p + 4], i[p + 5], i[p + 6]];
    p += 7;
    const ev = { contactBegin: [], contactEnd: [], hits: [], sensorBegin: [], sensorEnd: [], moves: [], joints: [] };
    for (let k = 0; k < nb; k++, p += 13) {
      const n = i[p + 6];
      const points = [];
      for (let m = 0; m < n; m++) points.push({ x: f[p + 7 + 3 * m], y: f[p + 8 + 3 * m], separation: f[p + 9 + 3 * m] });
      ev.contactBegin.push({ shapeA: this._shape(i[p], i[p + 1]), shapeB: this._shape(i[p + 2], i[p + 3]), normal: { x: f[p + 4], y: f[p + 5] }, points });
    }
    for (let k = 0; k < ne; k++, p += 4) ev.contactEnd.push({ shapeA: this._shape(i[p], i[p + 1]), shapeB: this._shape(i[p + 2], i[p + 3]) });
    for (let k = 0; k < nh; k++, p += 9) {
      ev.hits.push({ shapeA: this._shape(i[p], i[p + 1]), shapeB: this._shape(i[p + 2], i[p + 3]), point: { x: f[p + 4], y: f[p + 5] }, normal: { x: f[p + 6], y: f[p + 7] }, approachSpeed: f[p + 8] });
    }
    for (let k = 0; k < nsb; k++, p += 4) ev.sensorBegin.push({ sensor: this._shape(i[p], i[p + 1]), visitor: this._shape(i[p + 2], i[p + 3]) });
    for (let k = 0; k < nse; k++, p += 4) ev.sensorEnd.push({ sensor: this._shape(i[p], i[p + 1]), visitor: this._shape(i[p + 2], i[p + 3]) });
    for (let k = 0; k < nm; k++, p += 7) {
      ev.moves.push({ body: this._body(i[p], i[p + 1]), x: f[p + 2], y: f[p + 3], cos: f[p + 4], sin: f[p + 5], fellAsleep: f[p + 6] !== 0 });
    }
    for (let k = 0; k < nj; k++, p += 5) {
      ev.joints.push({ joint: this._joints.get(key(i[p], i[p + 1])) ?? null, force: { x: f[p + 2], y: f[p + 3] }, torque: f[p + 4] });
    }
    return ev;
  }

  /**
   * fcn(shapeA, shapeB, manifold) is called during the step for touching contacts of shapes
   * created with enablePreSolveEvents; return false to disable the contact for this step (one-way
   * platforms). manifold: {normal (from A to B), points [{x, y}], separation}. null removes it.
   * The callback must not change the world.
   */
  setPreSolve(fcn) {
    this._check('setPreSolve');
    if (fcn !== null) fn(fcn, 'fcn');
    this._preSolve = fcn;
    E().world2SetPreSolve(this._w, fcn === null ? 0 : 1);
  }

  /** fcn(shapeA, shapeB) decides whether a new pair may collide (false: never). null removes it. */
  setCustomFilter(fcn) {
    this._check('setCustomFilter');
    if (fcn !== null) fn(fcn, 'fcn');
    this._customFilter = fcn;
    E().world2SetCustomFilter(this._w, fcn === null ? 0 : 1);
  }

  _readShapes(ptr, name) {
    w.views();
    const n = w.I32[io()];
    if (n < 0) throw new RangeError(`${name} is not a valid shape`);
    const out = [], p = ptr >> 2, i = w.I32;
    for (let k = 0; k < n; k++) out.push(this._shape(i[p + 2 * k], i[p + 2 * k + 1]));
    return out;
  }

  _readHits(ptr, name) {
    w.views();
    const n = w.I32[io()];
    if (n < 0) throw new RangeError(`${name} is not a valid shape`);
    const out = [], p = ptr >> 2, i = w.I32, f = w.F32;
    for (let k = 0; k < n; k++) {
      const q = p + 7 * k;
      out.push({ shape: this._shape(i[q], i[q + 1]), point: { x: f[q + 2], y: f[q + 3] }, normal: { x: f[q + 4], y: f[q + 5] }, fraction: f[q + 6] });
    }
    return out;
  }

  /** Shapes whose bounding box overlaps aabb {min, max} (sensors included). filter: {categoryBits, maskBits}. */
  overlapAabb(aabb, filter) {
    this._check('overlapAabb');
    obj(aabb, 'aabb');
    const lo = vec2(aabb.min, 'aabb.min'), hi = vec2(aabb.max, 'aabb.max');
    if (lo[0] > hi[0] || lo[1] > hi[1]) throw new RangeError('aabb.min must not exceed aabb.max');
    const p = io();
    w.F32.set([lo[0], lo[1], hi[0], hi[1]], p);
    writeQueryFilter(p + 4, filter, 'filter');
    return this._readShapes(E().world2OverlapAabb(this._w), 'aabb');
  }

  /** Shapes that overlap a world-space shape (circle, capsule, aabb, box, polygon, segment objects). */
  overlapShape(shape, filter) {
    this._check('overlapShape');
    encode2(shape, w.S, 'shape');
    writeQueryFilter(io(), filter, 'filter');
    return this._readShapes(E().world2OverlapShape(this._w), 'shape');
  }

  /** The closest hit of the ray origin + t * translation (t in [0, 1]), or null. */
  raycastClosest(origin, translation, filter) {
    this._check('raycastClosest');
    const o = vec2(origin, 'origin'), t = vec2(translation, 'translation');
    const p = io();
    w.F32.set([o[0], o[1], t[0], t[1]], p);
    writeQueryFilter(p + 4, filter, 'filter');
    if (E().world2RaycastClosest(this._w) === 0) return null;
    const f = w.F32, i = w.I32;
    return { shape: this._shape(i[p + 1], i[p + 2]), point: { x: f[p + 3], y: f[p + 4] }, normal: { x: f[p + 5], y: f[p + 6] }, fraction: f[p + 7] };
  }

  /** Every hit of the ray (unordered): [{shape, point, normal, fraction}]. */
  raycast(origin, translation, filter) {
    this._check('raycast');
    const o = vec2(origin, 'origin'), t = vec2(translation, 'translation');
    const p = io();
    w.F32.set([o[0], o[1], t[0], t[1]], p);
    writeQueryFilter(p + 4, filter, 'filter');
    return this._readHits(E().world2Raycast(this._w), 'ray');
  }

  /** Every hit of a world-space shape moved by translation: [{shape, point, normal, fraction}]. */
  shapeCast(shape, translation, filter) {
    this._check('shapeCast');
    encode2(shape, w.S, 'shape');
    const t = vec2(translation, 'translation');
    const p = io();
    w.F32[p] = t[0]; w.F32[p + 1] = t[1];
    writeQueryFilter(p + 2, filter, 'filter');
    return this._readHits(E().world2ShapeCast(this._w), 'shape');
  }

  /** The whole simulation state as bytes (same build only: see world2.h's snapshots). */
  saveState() {
    this._check('saveState');
    const size = E().world2StateSize(this._w);
    const ptr = w.stage(size + 16);
    const r = E().world2SaveState(this._w, ptr, size);
    if (r !== 0) throwResult(r, 'saveState');
    return new Uint8Array(w.memoryBuffer(), ptr, size).slice();
  }

  /**
   * Restores a state from saveState() (Uint8Array, ArrayBuffer or DataView). Bodies, shapes and
   * joints created after that save become destroyed handles.
   */
  restoreState(state) {
    this._check('restoreState');
    let bytes;
    if (state instanceof Uint8Array) bytes = state;
    else if (state instanceof ArrayBuffer) bytes = new Uint8Array(state);
    else if (ArrayBuffer.isView(state)) bytes = new Uint8Array(state.buffer, state.byteOffset, state.byteLength);
    else throw new TypeError(`state must be a Uint8Array or an ArrayBuffer, got ${describe(state)}`);
    const ptr = w.stage(bytes.length + 16);
    new Uint8Array(w.memoryBuffer(), ptr, bytes.length).set(bytes);
    const r = E().world2RestoreState(this._w, ptr, bytes.length);
    if (r !== 0) {
      if (r === 8) throw new RangeError('state is not a saved state of this world\'s build (parse error)');
      throwResult(r, 'state');
    }
    // Drop the handles of bodies that the restored state does not have.
    for (let k = this.bodies.length - 1; k >= 0; k--) {
      const b = this.bodies[k];
      if (E().body2Valid(this._w, b._i, b._g) === 0) this._removeBody(b);
    }
  }
}

export class Body2 {
  constructor(world, index1, generation, slot) {
    this.world = world;
    this._i = index1;
    this._g = generation;
    this._slot = slot;
    this._shapeList = [];
    this.userData = undefined;
  }

  _dead() {
    this._i = 0;
    for (const s of this._shapeList) s._i = 0;
    this._shapeList = [];
  }

  get destroyed() {
    return this._i === 0 || this.world._w < 0 || E().body2Valid(this.world._w, this._i, this._g) === 0;
  }

  _call(name, exportName, ...args) {
    if (this._i === 0 || this.world._w < 0) throw staleError('Body2', name);
    const r = E()[exportName](this.world._w, this._i, this._g, ...args);
    if (r === 0) throw staleError('Body2', name);
    return r;
  }

  _get(name) {
    this._call(name, 'body2Get');
    return w.F32.subarray(io(), io() + 19);
  }

  _set(name, what, values) {
    w.F32.set(values, io());
    this._call(name, 'body2Set', what);
  }

  destroy() {
    if (this._i === 0 || this.world._w < 0) return;
    this.world._removeBody(this);
  }

  get type() { return BODY_TYPES[this._get('type')[9]]; }
  set type(t) {
    const k = BODY_TYPES.indexOf(t);
    if (k < 0) throw new TypeError(`type must be one of 'static', 'kinematic', 'dynamic', got ${describe(t)}`);
    this._set('type', 9, [k]);
  }

  /** Position of the body origin {x, y}; setting it teleports the body (keeps the angle). */
  get position() {
    this._call('position', 'body2Transform');
    return { x: w.F32[io()], y: w.F32[io() + 1] };
  }
  set position(p) {
    const v = vec2(p, 'position');
    this._set('position', 0, [v[0], v[1], this.angle]);
  }

  /** Rotation angle in radians (-pi, pi]. */
  get angle() {
    this._call('angle', 'body2Transform');
    return Math.atan2(w.F32[io() + 3], w.F32[io() + 2]);
  }
  set angle(a) {
    num(a, 'angle');
    const p = this.position;
    this._set('angle', 0, [p.x, p.y, a]);
  }

  /** {x, y, cos, sin}. */
  get transform() {
    this._call('transform', 'body2Transform');
    const f = w.F32, p = io();
    return { x: f[p], y: f[p + 1], cos: f[p + 2], sin: f[p + 3] };
  }

  setTransform(position, angle) {
    const v = vec2(position, 'position');
    this._set('setTransform', 0, [v[0], v[1], num(angle, 'angle')]);
  }

  get linearVelocity() {
    this._call('linearVelocity', 'body2Velocity');
    return { x: w.F32[io()], y: w.F32[io() + 1] };
  }
  set linearVelocity(v) { this._set('linearVelocity', 1, vec2(v, 'linearVelocity')); }

  get angularVelocity() {
    this._call('angularVelocity', 'body2Velocity');
    return w.F32[io() + 2];
  }
  set angularVelocity(a) { this._set('angularVelocity', 2, [num(a, 'angularVelocity')]); }

  get mass() { return this._get('mass')[7]; }
  /** Rotational inertia about the centre of mass. */
  get inertia() { return this._get('inertia')[8]; }
  get worldCenterOfMass() { const g = this._get('worldCenterOfMass'); return { x: g[17], y: g[18] }; }

  get awake() { return this._get('awake')[10] !== 0; }
  set awake(f) { this._set('awake', 10, [bool(f, 'awake') ? 1 : 0]); }
  get enabled() { return this._get('enabled')[11] !== 0; }
  set enabled(f) { this._set('enabled', 11, [bool(f, 'enabled') ? 1 : 0]); }
  get fixedRotation() { return this._get('fixedRotation')[12] !== 0; }
  set fixedRotation(f) { this._set('fixedRotation', 12, [bool(f, 'fixedRotation') ? 1 : 0]); }
  get bullet() { return this._get('bullet')[13] !== 0; }
  set bullet(f) { this._set('bullet', 13, [bool(f, 'bullet') ? 1 : 0]); }
  get gravityScale() { return this._get('gravityScale')[14]; }
  set gravityScale(s) { this._set('gravityScale', 14, [num(s, 'gravityScale')]); }
  get linearDamping() { return this._get('linearDamping')[15]; }
  set linearDamping(d) { this._set('linearDamping', 15, [nonNeg(d, 'linearDamping')]); }
  get angularDamping() { return this._get('angularDamping')[16]; }
  set angularDamping(d) { this._set('angularDamping', 16, [nonNeg(d, 'angularDamping')]); }
  enableSleep(flag) { this._set('enableSleep', 17, [bool(flag, 'flag') ? 1 : 0]); }

  applyForce(force, point, wake = true) {
    const f = vec2(force, 'force'), p = vec2(point, 'point');
    this._set('applyForce', 3, [f[0], f[1], p[0], p[1], bool(wake, 'wake') ? 1 : 0]);
  }
  applyForceToCenter(force, wake = true) {
    const f = vec2(force, 'force');
    this._set('applyForceToCenter', 4, [f[0], f[1], bool(wake, 'wake') ? 1 : 0]);
  }
  applyTorque(torque, wake = true) {
    this._set('applyTorque', 5, [num(torque, 'torque'), bool(wake, 'wake') ? 1 : 0]);
  }
  applyLinearImpulse(impulse, point, wake = true) {
    const f = vec2(impulse, 'impulse'), p = vec2(point, 'point');
    this._set('applyLinearImpulse', 6, [f[0], f[1], p[0], p[1], bool(wake, 'wake') ? 1 : 0]);
  }
  applyLinearImpulseToCenter(impulse, wake = true) {
    const f = vec2(impulse, 'impulse');
    this._set('applyLinearImpulseToCenter', 7, [f[0], f[1], bool(wake, 'wake') ? 1 : 0]);
  }
  applyAngularImpulse(impulse, wake = true) {
    this._set('applyAngularImpulse', 8, [num(impulse, 'impulse'), bool(wake, 'wake') ? 1 : 0]);
  }

  /** The shapes created on this body (chain segments included), oldest first. */
  get shapes() {
    if (this._i === 0) throw staleError('Body2', 'shapes');
    return this._shapeList.filter((s) => s._i !== 0);
  }

  /**
   * Attaches a shape in the body frame: geometry is a circle, capsule, aabb, box, polygon or
   * segment object (the factories circle(), capsule2(), box2(), polygon(), segment2(), or plain
   * objects of that form). def: density, friction, restitution, rollingResistance, tangentSpeed,
   * filter {categoryBits, maskBits, groupIndex}, isSensor, enableSensorEvents,
   * enableContactEvents, enableHitEvents, enablePreSolveEvents, userData.
   */
  createShape(geometry, def = {}) {
    if (this._i === 0 || this.world._w < 0) throw staleError('Body2', 'createShape');
    obj(def, 'def');
    w.F32.fill(0, w.S, w.S + 24);
    encode2(geometry, w.S, 'geometry');
    const p = io();
    const f = w.F32;
    f[p] = opt(def, 'density', nonNeg); f[p + 1] = opt(def, 'friction', nonNeg); f[p + 2] = opt(def, 'restitution', nonNeg);
    f[p + 3] = opt(def, 'rollingResistance', nonNeg); f[p + 4] = opt(def, 'tangentSpeed');
    const filter = def.filter === undefined ? {} : obj(def.filter, 'def.filter');
    writeWords(p + 5, bits64(filter.categoryBits, 'def.filter.categoryBits', [1, 0]));
    writeWords(p + 7, bits64(filter.maskBits, 'def.filter.maskBits', ALL_BITS));
    w.I32[p + 9] = filter.groupIndex === undefined ? 0 : int(filter.groupIndex, 'def.filter.groupIndex');
    const flag = (k, dflt) => (def[k] === undefined ? dflt : bool(def[k], `def.${k}`));
    const sensor = flag('isSensor', false);
    w.I32[p + 10] = 32 | (sensor ? 1 : 0) | (flag('enableSensorEvents', sensor) ? 2 : 0) |
      (flag('enableContactEvents', true) ? 4 : 0) | (flag('enableHitEvents', false) ? 8 : 0) |
      (flag('enablePreSolveEvents', false) ? 16 : 0);
    const r = E().shape2Create(this.world._w, this._i, this._g);
    if (r === 0) throw staleError('Body2', 'createShape');
    if (r < 0) throw new RangeError('geometry is not valid for a shape (degenerate, negative radius, ...) or def is not valid');
    return this._addShape(r, w.I32[p], def.userData);
  }

  _addShape(index1, generation, userData) {
    const s = new BodyShape2(this, index1, generation);
    s.userData = userData;
    this._shapeList.push(s);
    this.world._shapes.set(key(index1, generation), s);
    return s;
  }

  /**
   * One-sided terrain (cd2CreateChainShape; see chain2.h for the winding: a floor runs from right
   * to left, a loop around a solid counter-clockwise) through points in the body frame: an array
   * of {x, y} or a Float32Array/Float64Array of x, y pairs. options: loop, friction, restitution,
   * filter {categoryBits, maskBits, groupIndex}, enableSensorEvents. Returns a ChainShape2 whose
   * `segments` are the chain's segment shapes (type 'chainSegment').
   */
  createChain(points, options = {}) {
    if (this._i === 0 || this.world._w < 0) throw staleError('Body2', 'createChain');
    obj(options, 'options');
    const [ptr, count] = stagePoints2(points, 'points');
    const p = io();
    const f = w.F32;
    f[p] = options.loop === undefined ? 0 : (bool(options.loop, 'options.loop') ? 1 : 0);
    f[p + 1] = options.friction === undefined ? NO_VALUE : nonNeg(options.friction, 'options.friction');
    f[p + 2] = options.restitution === undefined ? NO_VALUE : nonNeg(options.restitution, 'options.restitution');
    const filter = options.filter === undefined ? {} : obj(options.filter, 'options.filter');
    writeWords(p + 3, bits64(filter.categoryBits, 'options.filter.categoryBits', [1, 0]));
    writeWords(p + 5, bits64(filter.maskBits, 'options.filter.maskBits', ALL_BITS));
    w.I32[p + 7] = filter.groupIndex === undefined ? 0 : int(filter.groupIndex, 'options.filter.groupIndex');
    f[p + 8] = options.enableSensorEvents === undefined ? 0 : (bool(options.enableSensorEvents, 'options.enableSensorEvents') ? 1 : 0);
    const r = E().chain2Create(this.world._w, this._i, this._g, ptr, count);
    if (r === 0) throw staleError('Body2', 'createChain');
    if (r < 0) chainError(-r, 'points');
    const generation = w.I32[p];
    // The chain's segment shapes are the new shapes the world reports on the body.
    return new ChainShape2(this, r, generation, this._collectNewShapes());
  }

  _collectNewShapes() {
    const ptr = E().body2Shapes(this.world._w, this._i, this._g);
    w.views();
    const n = w.I32[io()], q = ptr >> 2, made = [];
    for (let k = 0; k < n; k++) {
      const i1 = w.I32[q + 2 * k], g = w.I32[q + 2 * k + 1];
      if (this.world._shape(i1, g) === null) made.push(this._addShape(i1, g, undefined));
    }
    return made;
  }
}

export class BodyShape2 {
  constructor(body, index1, generation) {
    this.body = body;
    this._i = index1;
    this._g = generation;
    this.userData = undefined;
  }

  get destroyed() {
    return this._i === 0 || this.body.world._w < 0 || E().shape2Get(this.body.world._w, this._i, this._g) === 0;
  }

  _call(name, exportName, ...args) {
    const world = this.body.world;
    if (this._i === 0 || world._w < 0) throw staleError('BodyShape2', name);
    const r = E()[exportName](world._w, this._i, this._g, ...args);
    if (r === 0) throw staleError('BodyShape2', name);
    return r;
  }

  _get(name) {
    this._call(name, 'shape2Get');
    return io();
  }

  _set(name, what, values) {
    w.F32.set(values, io());
    this._call(name, 'shape2Set', what);
  }

  destroy() {
    const world = this.body.world;
    if (this._i === 0 || world._w < 0) return;
    E().shape2Destroy(world._w, this._i, this._g);
    world._shapes.delete(key(this._i, this._g));
    this._i = 0;
  }

  /** 'circle', 'capsule', 'polygon', 'segment' or 'chainSegment'. */
  get type() { return SHAPE_TYPES[w.I32[this._get('type')]]; }
  get isSensor() { return w.F32[this._get('isSensor') + 6] !== 0; }
  get density() { return w.F32[this._get('density') + 3]; }
  /** Sets the density and recomputes the body's mass. */
  set density(d) { this._set('density', 0, [nonNeg(d, 'density'), 1]); }
  get friction() { return w.F32[this._get('friction') + 4]; }
  set friction(v) { this._set('friction', 1, [nonNeg(v, 'friction')]); }
  get restitution() { return w.F32[this._get('restitution') + 5]; }
  set restitution(v) { this._set('restitution', 2, [nonNeg(v, 'restitution')]); }
  /** World-space bounds {min, max} (the broadphase's fat box is larger). */
  get aabb() {
    const p = this._get('aabb'), f = w.F32;
    return { min: { x: f[p + 7], y: f[p + 8] }, max: { x: f[p + 9], y: f[p + 10] } };
  }
  /** {categoryBits, maskBits (bigints), groupIndex}. */
  get filter() {
    const p = this._get('filter');
    return { categoryBits: readBits(p + 11), maskBits: readBits(p + 13), groupIndex: w.I32[p + 15] };
  }
  set filter(filter) {
    obj(filter, 'filter');
    const c = bits64(filter.categoryBits, 'filter.categoryBits', [1, 0]);
    const m = bits64(filter.maskBits, 'filter.maskBits', ALL_BITS);
    const g = filter.groupIndex === undefined ? 0 : int(filter.groupIndex, 'filter.groupIndex');
    const p = io();
    writeWords(p, c); writeWords(p + 2, m); w.I32[p + 4] = g;
    this._call('filter', 'shape2Set', 3);
  }
  enableSensorEvents(flag) { this._set('enableSensorEvents', 4, [bool(flag, 'flag') ? 1 : 0]); }
  enableContactEvents(flag) { this._set('enableContactEvents', 5, [bool(flag, 'flag') ? 1 : 0]); }
  enableHitEvents(flag) { this._set('enableHitEvents', 6, [bool(flag, 'flag') ? 1 : 0]); }
  enablePreSolveEvents(flag) { this._set('enablePreSolveEvents', 7, [bool(flag, 'flag') ? 1 : 0]); }
}

const J = {
  type: 0, bodyA: 1, bodyB: 3, anchorA: 5, anchorB: 7, axis: 9, referenceAngle: 11, enableSpring: 12,
  hertz: 13, dampingRatio: 14, enableLimit: 15, lower: 16, upper: 17, enableMotor: 18, maxMotor: 19,
  motorSpeed: 20, collideConnected: 21, length: 22, target: 23, maxForce: 25, maxTorque: 26,
  linearOffset: 27, angularOffset: 29, correctionFactor: 30, angularHertz: 31, angularDampingRatio: 32,
  forceThreshold: 33, torqueThreshold: 34, constraintHertz: 35, constraintDampingRatio: 36,
};
const TUNED_JOINTS = ['distance', 'prismatic', 'revolute', 'weld', 'wheel'];

World2.prototype.createJoint = function createJoint(def) {
  this._check('createJoint');
  obj(def, 'def');
  const type = JOINT_TYPES.indexOf(def.type);
  if (type < 0) throw new TypeError(`def.type must be one of ${JOINT_TYPES.map((t) => `'${t}'`).join(', ')}, got ${describe(def.type)}`);
  for (const k of ['bodyA', 'bodyB']) {
    if (!(def[k] instanceof Body2)) throw new TypeError(`def.${k} must be a Body2, got ${describe(def[k])}`);
    if (def[k].world !== this) throw new TypeError(`def.${k} belongs to another world`);
    if (def[k]._i === 0) throw staleError('Body2', `def.${k}`);
  }
  if (def.bodyA === def.bodyB) throw new RangeError('def.bodyA and def.bodyB must be different bodies');
  const p = io(), f = w.F32;
  f.fill(NaN, p, p + 40);
  w.I32[p] = type;
  w.I32[p + 1] = def.bodyA._i; w.I32[p + 2] = def.bodyA._g;
  w.I32[p + 3] = def.bodyB._i; w.I32[p + 4] = def.bodyB._g;
  const put = (k, at, check = num) => { if (def[k] !== undefined) f[p + at] = check(def[k], `def.${k}`); };
  const putVec = (k, at) => { if (def[k] !== undefined) f.set(vec2(def[k], `def.${k}`), p + at); };
  const putFlag = (k, at) => { if (def[k] !== undefined) f[p + at] = bool(def[k], `def.${k}`) ? 1 : 0; };
  putVec('localAnchorA', J.anchorA); putVec('localAnchorB', J.anchorB);
  if (def.localAxisA !== undefined) {
    const a = vec2(def.localAxisA, 'def.localAxisA');
    const len = Math.hypot(a[0], a[1]);
    if (Math.abs(len - 1) > 1e-3) throw new RangeError(`def.localAxisA must be a unit vector, its length is ${len}`);
    f.set(a, p + J.axis);
  }
  put('referenceAngle', J.referenceAngle); putFlag('enableSpring', J.enableSpring);
  put('hertz', J.hertz, nonNeg); put('dampingRatio', J.dampingRatio, nonNeg);
  put('linearHertz', J.hertz, nonNeg); put('linearDampingRatio', J.dampingRatio, nonNeg);
  putFlag('enableLimit', J.enableLimit);
  put('lowerAngle', J.lower); put('upperAngle', J.upper);
  put('lowerTranslation', J.lower); put('upperTranslation', J.upper);
  put('minLength', J.lower, nonNeg); put('maxLength', J.upper, nonNeg);
  putFlag('enableMotor', J.enableMotor);
  put('maxMotorTorque', J.maxMotor, nonNeg); put('maxMotorForce', J.maxMotor, nonNeg); put('motorSpeed', J.motorSpeed);
  putFlag('collideConnected', J.collideConnected);
  put('length', J.length, nonNeg);
  putVec('target', J.target);
  put('maxForce', J.maxForce, nonNeg); put('maxTorque', J.maxTorque, nonNeg);
  putVec('linearOffset', J.linearOffset); put('angularOffset', J.angularOffset);
  put('correctionFactor', J.correctionFactor, nonNeg);
  put('angularHertz', J.angularHertz, nonNeg); put('angularDampingRatio', J.angularDampingRatio, nonNeg);
  if (def.type === 'filter' && (def.forceThreshold !== undefined || def.torqueThreshold !== undefined)) {
    throw new TypeError('def: a filter joint has no force, so no forceThreshold or torqueThreshold');
  }
  put('forceThreshold', J.forceThreshold, nonNeg); put('torqueThreshold', J.torqueThreshold, nonNeg);
  if (!TUNED_JOINTS.includes(def.type) && (def.constraintHertz !== undefined || def.constraintDampingRatio !== undefined)) {
    throw new TypeError(`def: a ${def.type} joint has no constraintHertz or constraintDampingRatio`);
  }
  put('constraintHertz', J.constraintHertz, nonNeg); put('constraintDampingRatio', J.constraintDampingRatio, nonNeg);
  if (f[p + J.lower] > f[p + J.upper]) throw new RangeError('def: the lower limit must not exceed the upper limit');
  const r = E().joint2Create(this._w);
  if (r === 0) throw staleError('Body2', 'createJoint');
  if (r < 0) throw new RangeError(`def is not a valid ${def.type} joint`);
  const joint = new Joint2(this, r, w.I32[p], def.type, def.bodyA, def.bodyB);
  joint.userData = def.userData;
  this._joints.set(key(r, joint._g), joint);
  return joint;
};

/**
 * A chain on a body (World2): one-sided terrain made of segment shapes. `segments` are its
 * BodyShape2 handles; destroy() removes the chain and its segments.
 */
export class ChainShape2 {
  constructor(body, index1, generation, segments) {
    this.body = body;
    this._i = index1;
    this._g = generation;
    /** The segment shapes, in chain order. */
    this.segments = segments;
  }

  get destroyed() {
    const world = this.body.world;
    return this._i === 0 || world._w < 0 || E().chain2SegmentCount(world._w, this._i, this._g) === 0;
  }

  get segmentCount() {
    const world = this.body.world;
    const n = this._i === 0 || world._w < 0 ? 0 : E().chain2SegmentCount(world._w, this._i, this._g);
    if (n === 0) throw staleError('ChainShape2', 'segmentCount');
    return n;
  }

  destroy() {
    const world = this.body.world;
    if (this._i === 0 || world._w < 0) return;
    if (E().chain2Destroy(world._w, this._i, this._g) !== 0) {
      for (const s of this.segments) {
        world._shapes.delete(key(s._i, s._g));
        s._i = 0;
      }
    }
    this._i = 0;
  }
}

export class Joint2 {
  constructor(world, index1, generation, type, bodyA, bodyB) {
    this.world = world;
    this._i = index1;
    this._g = generation;
    /** 'distance', 'filter', 'motor', 'mouse', 'prismatic', 'revolute', 'weld' or 'wheel' */
    this.type = type;
    this.bodyA = bodyA;
    this.bodyB = bodyB;
    this.userData = undefined;
  }

  get destroyed() {
    return this._i === 0 || this.world._w < 0 || E().joint2Get(this.world._w, this._i, this._g) === 0;
  }

  _call(name, exportName, ...args) {
    if (this._i === 0 || this.world._w < 0) throw staleError('Joint2', name);
    const r = E()[exportName](this.world._w, this._i, this._g, ...args);
    if (r === 0) throw staleError('Joint2', name);
    if (r < 0) throw new TypeError(`${name} does not apply to a ${this.type} joint`);
    return r;
  }

  _get(name) { this._call(name, 'joint2Get'); return io(); }
  _set(name, what, values) { w.F32.set(values, io()); this._call(name, 'joint2Set', what); }

  destroy() {
    if (this._i === 0 || this.world._w < 0) return;
    E().joint2Destroy(this.world._w, this._i, this._g);
    this.world._joints.delete(key(this._i, this._g));
    this._i = 0;
  }

  /** Reaction force on body B over the last step (N). */
  get constraintForce() { const p = this._get('constraintForce'); return { x: w.F32[p + 5], y: w.F32[p + 6] }; }
  get constraintTorque() { return w.F32[this._get('constraintTorque') + 7]; }
  /** Joint events (World2.getEvents().joints) when the reaction force exceeds it (N); 0: none. */
  get forceThreshold() { return w.F32[this._get('forceThreshold') + 11]; }
  set forceThreshold(v) { this._set('forceThreshold', 13, [nonNeg(v, 'forceThreshold')]); }
  /** Joint events when the reaction torque exceeds it (N m); 0: none. */
  get torqueThreshold() { return w.F32[this._get('torqueThreshold') + 12]; }
  set torqueThreshold(v) { this._set('torqueThreshold', 14, [nonNeg(v, 'torqueThreshold')]); }
  /** The softness of the point, angle and length constraints (0: the world's jointHertz / jointDampingRatio). */
  get constraintHertz() { return w.F32[this._get('constraintHertz') + 13]; }
  get constraintDampingRatio() { return w.F32[this._get('constraintDampingRatio') + 14]; }
  setConstraintTuning(hertz, dampingRatio) {
    this._set('setConstraintTuning', 15, [nonNeg(hertz, 'hertz'), nonNeg(dampingRatio, 'dampingRatio')]);
  }
  /** Revolute joints: angle of B relative to A minus the reference angle. */
  get angle() { if (this.type !== 'revolute') throw new TypeError(`angle does not apply to a ${this.type} joint`); return w.F32[this._get('angle') + 8]; }
  /** Prismatic and wheel joints: translation along the axis. */
  get translation() {
    if (this.type !== 'prismatic' && this.type !== 'wheel') throw new TypeError(`translation does not apply to a ${this.type} joint`);
    return w.F32[this._get('translation') + 9];
  }
  /** Distance joints: current distance between the anchors. */
  get currentLength() { if (this.type !== 'distance') throw new TypeError(`currentLength does not apply to a ${this.type} joint`); return w.F32[this._get('currentLength') + 10]; }

  enableMotor(flag) { this._set('enableMotor', 0, [bool(flag, 'flag') ? 1 : 0]); }
  set motorSpeed(v) { this._set('motorSpeed', 1, [num(v, 'motorSpeed')]); }
  set maxMotor(v) { this._set('maxMotor', 2, [nonNeg(v, 'maxMotor')]); }
  enableLimit(flag) { this._set('enableLimit', 3, [bool(flag, 'flag') ? 1 : 0]); }
  setLimits(lower, upper) {
    num(lower, 'lower'); num(upper, 'upper');
    if (lower > upper) throw new RangeError(`lower must not exceed upper, got ${lower} > ${upper}`);
    this._set('setLimits', 4, [lower, upper]);
  }
  enableSpring(flag) { this._set('enableSpring', 5, [bool(flag, 'flag') ? 1 : 0]); }
  set springHertz(v) { this._set('springHertz', 6, [nonNeg(v, 'springHertz')]); }
  set springDampingRatio(v) { this._set('springDampingRatio', 7, [nonNeg(v, 'springDampingRatio')]); }
  /** Mouse joints: the world target. */
  set target(t) { this._set('target', 8, vec2(t, 'target')); }
  /** Distance joints: the rest length. */
  set length(v) { this._set('length', 9, [nonNeg(v, 'length')]); }
  set linearOffset(v) { this._set('linearOffset', 10, vec2(v, 'linearOffset')); }
  set angularOffset(v) { this._set('angularOffset', 11, [num(v, 'angularOffset')]); }
  wakeBodies() { this._set('wakeBodies', 12, []); }
}

export const BODY2_TYPES = BODY_TYPES;
export const JOINT2_TYPES = JOINT_TYPES;

// ---- kinematic character mover (world2.h) ------------------------------------------------------

function writeCapsule(at, capsule, name) {
  obj(capsule, name);
  const p1 = vec2(capsule.p1, `${name}.p1`), p2 = vec2(capsule.p2, `${name}.p2`);
  const r = num(capsule.radius, `${name}.radius`);
  if (r <= 0) throw new RangeError(`${name}.radius must be > 0, got ${r}`);
  w.F32.set([p1[0], p1[1], p2[0], p2[1], r], at);
}

function readPlanes(world, ptr, count) {
  const out = [], p = ptr >> 2, f = w.F32, i = w.I32;
  for (let k = 0; k < count; k++) {
    const q = p + 7 * k;
    out.push({ shape: world._shape(i[q], i[q + 1]), normal: { x: f[q + 2], y: f[q + 3] }, separation: f[q + 4], point: { x: f[q + 5], y: f[q + 6] } });
  }
  return out;
}

/**
 * The planes of the non-sensor shapes touching (or within the speculative distance of) a capsule
 * {p1, p2, radius} in world space: [{shape, normal (from the shape to the mover), separation, point}].
 */
World2.prototype.collideMover = function collideMover(capsule, filter) {
  this._check('collideMover');
  writeCapsule(io(), capsule, 'capsule');
  writeQueryFilter(io() + 5, filter, 'filter');
  const ptr = E().mover2Collide(this._w);
  return readPlanes(this, ptr, w.I32[io()]);
};

/** The fraction in [0, 1] of translation the capsule can move before it touches a shape it does not already overlap. */
World2.prototype.castMover = function castMover(capsule, translation, filter) {
  this._check('castMover');
  writeCapsule(io(), capsule, 'capsule');
  w.F32.set(vec2(translation, 'translation'), io() + 5);
  writeQueryFilter(io() + 7, filter, 'filter');
  return E().mover2Cast(this._w);
};

/**
 * One frame of the kinematic character mover (the loop of world2.h: collect the planes around the
 * target and solve them four times, cast from the position to the target, clip the velocity).
 * options: capsule {p1, p2, radius} in the character's frame, position, velocity, dt, filter,
 * oneWayBits (shapes whose category has one of these bits hold the character only from above).
 * Returns {position, velocity, planes}; a plane with normal.y > 0.7 is ground under the feet.
 */
World2.prototype.moveCharacter = function moveCharacter(options) {
  this._check('moveCharacter');
  obj(options, 'options');
  const p = io();
  writeCapsule(p, options.capsule, 'options.capsule');
  const pos = vec2(options.position, 'options.position'), vel = vec2(options.velocity, 'options.velocity');
  const dt = num(options.dt, 'options.dt');
  if (dt < 0) throw new RangeError(`options.dt must be >= 0, got ${dt}`);
  w.F32.set([pos[0], pos[1], vel[0], vel[1], dt], p + 5);
  writeQueryFilter(p + 10, options.filter, 'options.filter');
  writeWords(p + 14, bits64(options.oneWayBits, 'options.oneWayBits', [0, 0]));
  const ptr = E().mover2Move(this._w);
  if (ptr === 0) throw new RangeError('options is not valid');
  const f = w.F32;
  const result = { position: { x: f[p], y: f[p + 1] }, velocity: { x: f[p + 2], y: f[p + 3] } };
  result.planes = readPlanes(this, ptr, w.I32[p + 4]);
  return result;
};

function planesCall(what, vector, planes, name) {
  w.requireInit();
  const v = vec2(vector, name);
  if (!Array.isArray(planes)) throw new TypeError(`planes must be an array, got ${describe(planes)}`);
  if (planes.length > 32) throw new RangeError(`planes must hold at most 32 planes, got ${planes.length}`);
  const p = io();
  w.I32[p] = planes.length;
  planes.forEach((pl, k) => {
    obj(pl, `planes[${k}]`);
    const n = vec2(pl.normal, `planes[${k}].normal`);
    const pt = pl.point === undefined ? [0, 0] : vec2(pl.point, `planes[${k}].point`);
    w.F32.set([0, 0, n[0], n[1], num(pl.separation, `planes[${k}].separation`), pt[0], pt[1]], p + 1 + 7 * k);
  });
  w.F32.set(v, p + 1 + 7 * planes.length);
  E().mover2Planes(what);
  return { x: w.F32[p], y: w.F32[p + 1] };
}

/** cd2SolvePlanes: the smallest change of targetDelta after which the mover overlaps no plane. */
export function solvePlanes2(targetDelta, planes) { return planesCall(0, targetDelta, planes, 'targetDelta'); }
/** cd2ClipVector: the vector without its components into the planes the mover touches. */
export function clipVector2(vector, planes) { return planesCall(1, vector, planes, 'vector'); }
