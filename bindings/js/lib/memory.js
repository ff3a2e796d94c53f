// Typed arrays that live in wasm memory: batch queries and broadphase moves read them in place,
// without a copy. A view is replaced when wasm memory grows, so take `.array` again after any
// call that may allocate (creating hulls, broadphases, proxies) rather than keeping it.
import * as w from './wasm.js';
import { int, track, untrack, destroyedError } from './check.js';

const KINDS = { f32: [Float32Array, 4], i32: [Int32Array, 4] };

export class WasmArray {
  /** @param {'f32'|'i32'} kind @param {number} length */
  constructor(kind, length) {
    w.requireInit();
    if (!(kind in KINDS)) throw new TypeError(`kind must be 'f32' or 'i32', got ${String(kind)}`);
    int(length, 'length', 0, 1 << 28);
    const [Type, size] = KINDS[kind];
    this.kind = kind;
    this.length = length;
    this._Type = Type;
    this._ptr = w.exports.malloc(Math.max(16, length * size));
    if (this._ptr === 0) throw new RangeError(`out of wasm memory for ${length} elements`);
    this._view = null;
    this._buffer = null;
    w.views();
    this.array.fill(0);
    track(this, 'WasmArray');
  }

  get destroyed() { return this._ptr === 0; }

  /** The elements as a typed array over wasm memory (a new view after memory growth). */
  get array() {
    if (this._ptr === 0) throw destroyedError('WasmArray', 'array');
    const buffer = w.memoryBuffer();
    if (this._buffer !== buffer) {
      this._buffer = buffer;
      this._view = new this._Type(buffer, this._ptr, this.length);
    }
    return this._view;
  }

  destroy() {
    if (this._ptr === 0) return;
    w.exports.free(this._ptr);
    this._ptr = 0;
    this._view = null;
    this._buffer = null;
    untrack(this);
  }
}

/** A WasmArray's current view; anything else as it is. */
export function unwrap(x) {
  return x instanceof WasmArray ? x.array : x;
}

/**
 * Makes `arr` (a Float32Array or Int32Array of `count * stride` elements) available in wasm
 * memory and returns its byte pointer: in place when it is a view of wasm memory, else copied
 * into a staging area (`second` picks the second one, for calls with two arrays).
 */
export function place(arr, Type, name, second = false) {
  if (!(arr instanceof Type)) {
    const got = arr === null ? 'null' : typeof arr === 'object' ? (arr.constructor?.name ?? 'an object') : typeof arr;
    throw new TypeError(`${name} must be a ${Type.name}, got ${got}`);
  }
  if (arr.buffer === w.memoryBuffer()) return arr.byteOffset;
  if (w.isOldBuffer(arr.buffer)) {
    throw new TypeError(`${name} is a view of wasm memory that was detached when the memory grew; take WasmArray.array again`);
  }
  const ptr = (second ? w.stage2 : w.stage)(arr.byteLength + 16);
  new Type(w.memoryBuffer(), ptr, arr.length).set(arr);
  return ptr;
}
