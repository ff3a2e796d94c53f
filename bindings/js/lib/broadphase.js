// The broadphase structures (broad.h): a dynamic AABB tree, sweep-and-prune, a hash grid and a
// quadtree/octree behind one class per dimension. Proxies are small integer ids; pairs, query
// hits and ray hits come back as one typed array per call.
import * as w from './wasm.js';
import { num, nonNeg, int, obj, vec2, vec3, describe, throwResult, track, untrack, destroyedError } from './check.js';
import { place, unwrap } from './memory.js';

const TYPES = ['tree', 'sap', 'grid', 'spatialTree'];

function readBox(aabb, dim, name) {
  if (aabb instanceof Float32Array || aabb instanceof Float64Array || Array.isArray(aabb)) {
    const n = 2 * dim;
    if (aabb.length !== n) throw new RangeError(`${name} must hold ${n} numbers (min then max), got ${aabb.length}`);
    const r = [];
    for (let i = 0; i < n; i++) r.push(num(aabb[i], `${name}[${i}]`));
    checkOrder(r, dim, name);
    return r;
  }
  obj(aabb, name);
  const r = dim === 2 ? [...vec2(aabb.min, `${name}.min`), ...vec2(aabb.max, `${name}.max`)]
    : [...vec3(aabb.min, `${name}.min`), ...vec3(aabb.max, `${name}.max`)];
  checkOrder(r, dim, name);
  return r;
}

function checkOrder(r, dim, name) {
  for (let i = 0; i < dim; i++) {
    if (r[i] > r[i + dim]) throw new RangeError(`${name}: min must not exceed max`);
  }
}

class BroadPhase {
  constructor(dim, def) {
    w.requireInit();
    if (def === undefined) def = {};
    obj(def, 'def');
    const type = def.type === undefined ? 'tree' : def.type;
    const typeIndex = TYPES.indexOf(type);
    if (typeIndex < 0) throw new TypeError(`def.type must be one of ${TYPES.map((t) => `'${t}'`).join(', ')}, got ${describe(type)}`);
    const opt = (k) => (def[k] === undefined ? -1 : nonNeg(def[k], `def.${k}`));
    const margin = opt('margin'), mult = opt('displacementMultiplier'), cell = opt('cellSize');
    const capacity = def.capacity === undefined ? -1 : int(def.capacity, 'def.capacity', 0, 1 << 26);
    let boundsPtr = 0;
    const io = w.S + 128;
    if (def.bounds !== undefined) {
      const b = readBox(def.bounds, dim, 'def.bounds');
      w.views();
      for (let i = 0; i < b.length; i++) w.F32[io + i] = b[i];
      boundsPtr = io * 4;
    }
    const resultPtr = (io + 16) * 4;
    this._h = w.exports.bpCreate(dim, typeIndex, margin, mult, cell, capacity, boundsPtr, resultPtr);
    w.views();
    if (this._h === 0) throwResult(w.I32[io + 16], 'def');
    this.dim = dim;
    this.type = type;
    track(this, `BroadPhase${dim}`);
  }

  _live(name = 'broadPhase') {
    if (this._h === 0) throw destroyedError(`BroadPhase${this.dim}`, name);
    w.views();
    return this._h;
  }

  get destroyed() { return this._h === 0; }

  /** Frees the structure; every later call throws. */
  destroy() {
    if (this._h === 0) return;
    w.exports.bpDestroy(this._h);
    this._h = 0;
    untrack(this);
  }

  _box(aabb, name) {
    const b = readBox(aabb, this.dim, name);
    const io = w.S + 128;
    for (let i = 0; i < b.length; i++) w.F32[io + i] = b[i];
    return io * 4;
  }

  /** Adds a proxy for the box ({min, max} or [minX, minY, (minZ,) maxX, maxY, (maxZ)]); returns its id. */
  createProxy(aabb) {
    const h = this._live();
    const ptr = this._box(aabb, 'aabb');
    const id = w.exports.bpCreateProxy(h, ptr);
    if (id === -2) throw new Error('collide: out of wasm memory');
    if (id < 0) throw new RangeError('aabb is not a valid box');
    return id;
  }

  /** Adds one proxy per box of a packed Float32Array (2·dim numbers per box); returns their ids (-1 for an invalid box). */
  createProxies(aabbs) {
    const h = this._live();
    aabbs = unwrap(aabbs);
    const stride = 2 * this.dim;
    if (!(aabbs instanceof Float32Array)) throw new TypeError(`aabbs must be a Float32Array, got ${describe(aabbs)}`);
    if (aabbs.length % stride !== 0) throw new RangeError(`aabbs must hold ${stride} numbers per box, its length ${aabbs.length} is not a multiple`);
    const count = aabbs.length / stride;
    const boxPtr = place(aabbs, Float32Array, 'aabbs');
    const outPtr = w.stage2(count * 4 + 16);
    w.exports.bpCreateProxies(h, boxPtr, count, outPtr);
    w.views();
    return w.I32.slice(outPtr >> 2, (outPtr >> 2) + count);
  }

  /** Removes a proxy; its id may be given to a later proxy. Throws a RangeError for an id that is not live. */
  destroyProxy(id) {
    const h = this._live();
    int(id, 'id');
    if (w.exports.bpDestroyProxy(h, id) === 0) throw new RangeError(`id ${id} is not a live proxy`);
  }

  /** True when id names a live proxy. */
  hasProxy(id) {
    const h = this._live();
    return Number.isInteger(id) && id >= -2147483648 && id <= 2147483647 && w.exports.bpIsLive(h, id) === 1;
  }

  /** New tight box and optional predicted displacement; true when the fat box changed. */
  moveProxy(id, aabb, displacement) {
    const h = this._live();
    int(id, 'id');
    const ptr = this._box(aabb, 'aabb');
    let dPtr = 0;
    if (displacement !== undefined) {
      const d = this.dim === 2 ? vec2(displacement, 'displacement') : vec3(displacement, 'displacement');
      const at = w.S + 140;
      for (let i = 0; i < d.length; i++) w.F32[at + i] = d[i];
      dPtr = at * 4;
    }
    const r = w.exports.bpMoveProxy(h, id, ptr, dPtr);
    if (r < 0) throw new RangeError(`id ${id} is not a live proxy`);
    return r === 1;
  }

  /**
   * Moves many proxies in one call: ids (Int32Array), their new boxes (Float32Array, 2·dim per
   * id) and optional displacements (Float32Array, dim per id). Returns how many fat boxes changed.
   * Views of WasmArrays are read in place.
   */
  moveProxies(ids, aabbs, displacements) {
    const h = this._live();
    ids = unwrap(ids);
    aabbs = unwrap(aabbs);
    displacements = unwrap(displacements);
    if (!(ids instanceof Int32Array)) throw new TypeError(`ids must be an Int32Array, got ${describe(ids)}`);
    if (!(aabbs instanceof Float32Array)) throw new TypeError(`aabbs must be a Float32Array, got ${describe(aabbs)}`);
    const count = ids.length, stride = 2 * this.dim;
    if (aabbs.length !== count * stride) throw new RangeError(`aabbs must hold ${stride} numbers per id (${count * stride}), got ${aabbs.length}`);
    if (displacements !== undefined) {
      if (!(displacements instanceof Float32Array)) throw new TypeError(`displacements must be a Float32Array, got ${describe(displacements)}`);
      if (displacements.length !== count * this.dim) throw new RangeError(`displacements must hold ${this.dim} numbers per id (${count * this.dim}), got ${displacements.length}`);
    }
    // Boxes must be valid (finite, min <= max): the library ignores invalid ones, so say so.
    const idPtr = place(ids, Int32Array, 'ids', true);
    const boxPtr = place(aabbs, Float32Array, 'aabbs');
    let dPtr = 0;
    let ownD = false;
    if (displacements !== undefined) {
      if (displacements.buffer === w.memoryBuffer()) {
        dPtr = displacements.byteOffset;
      } else {
        if (w.isOldBuffer(displacements.buffer)) {
          throw new TypeError('displacements is a view of wasm memory that was detached when the memory grew; pass the WasmArray itself');
        }
        // A third array: copied into a block of its own for this call.
        dPtr = w.exports.malloc(displacements.byteLength + 16);
        if (dPtr === 0) throw new Error('collide: out of wasm memory');
        ownD = true;
        new Float32Array(w.memoryBuffer(), dPtr, displacements.length).set(displacements);
      }
    }
    const r = w.exports.bpMoveProxies(h, count, idPtr, boxPtr, dPtr);
    if (ownD) w.exports.free(dPtr);
    w.views();
    if (r < 0) throw new RangeError(`ids[${-r - 1}] = ${ids[-r - 1]} is not a live proxy (nothing was moved)`);
    return r;
  }

  _ints(count, name) {
    if (count < 0) throw new Error(`collide: out of wasm memory in ${name}`);
    w.views();
    const p = w.exports.bpInts(this._h) >> 2;
    return w.I32.slice(p, p + count);
  }

  /**
   * The pairs of proxies whose fat boxes overlap and at least one of which moved since the last
   * call, as one Int32Array [a0, b0, a1, b1, ...] with a < b, sorted; then forgets the moves.
   */
  updatePairs() {
    const h = this._live();
    const n = w.exports.bpUpdatePairs(h, 0);
    return this._ints(n < 0 ? n : 2 * n, 'updatePairs');
  }

  /** Every overlapping pair, moved or not, in the same form; leaves the moves alone. */
  findAllPairs() {
    const h = this._live();
    const n = w.exports.bpUpdatePairs(h, 1);
    return this._ints(n < 0 ? n : 2 * n, 'findAllPairs');
  }

  /** Ids of the proxies whose fat box overlaps the box. */
  query(aabb) {
    const h = this._live();
    const ptr = this._box(aabb, 'aabb');
    return this._ints(w.exports.bpQuery(h, ptr), 'query');
  }

  /** Proxies whose fat box the ray {origin, translation} meets, nearest entry first: {ids, fractions}. */
  rayCast(ray) {
    const h = this._live();
    obj(ray, 'ray');
    const r = this.dim === 2 ? [...vec2(ray.origin, 'ray.origin'), ...vec2(ray.translation, 'ray.translation')]
      : [...vec3(ray.origin, 'ray.origin'), ...vec3(ray.translation, 'ray.translation')];
    const io = w.S + 128;
    for (let i = 0; i < r.length; i++) w.F32[io + i] = r[i];
    const n = w.exports.bpRayCast(h, io * 4);
    const ids = this._ints(n, 'rayCast');
    const fp = w.exports.bpFractions(h) >> 2;
    return { ids, fractions: w.F32.slice(fp, fp + n) };
  }

  /** The fat box the structure keeps for a proxy. */
  getFatAabb(id) {
    const h = this._live();
    int(id, 'id');
    const io = w.S + 128;
    if (w.exports.bpFatAabb(h, id, io * 4) === 0) throw new RangeError(`id ${id} is not a live proxy`);
    const f = w.F32;
    return this.dim === 2
      ? { min: { x: f[io], y: f[io + 1] }, max: { x: f[io + 2], y: f[io + 3] } }
      : { min: { x: f[io], y: f[io + 1], z: f[io + 2] }, max: { x: f[io + 3], y: f[io + 4], z: f[io + 5] } };
  }

  get proxyCount() {
    return w.exports.bpProxyCount(this._live());
  }

  /** Rebuilds the structure for the current boxes (same answers, often faster queries). */
  rebuild() {
    w.exports.bpRebuild(this._live());
  }

  /** Checks every invariant of the structure. */
  validate() {
    return w.exports.bpValidate(this._live()) === 1;
  }

  /** {proxyCount, nodeCount, height, memoryBytes, sahCost}. */
  get stats() {
    const h = this._live();
    const io = w.S + 128;
    w.exports.bpStats(h, io * 4);
    const d = new Float64Array(w.memoryBuffer(), io * 4, 5);
    return { proxyCount: d[0], nodeCount: d[1], height: d[2], memoryBytes: d[3], sahCost: d[4] };
  }
}

/** A 2D broadphase: new BroadPhase2({type: 'tree' | 'sap' | 'grid' | 'spatialTree', margin, ...}). */
export class BroadPhase2 extends BroadPhase {
  constructor(def) { super(2, def); }
}

/** A 3D broadphase: new BroadPhase3({type, margin, displacementMultiplier, cellSize, bounds, capacity}). */
export class BroadPhase3 extends BroadPhase {
  constructor(def) { super(3, def); }
}

export const BROADPHASE_TYPES = TYPES;
