// Argument checks shared by every module: each throws a TypeError (wrong type, missing field)
// or a RangeError (NaN, infinity, negative size, out of range) naming the argument.

export function describe(v) {
  if (v === null) return 'null';
  if (v === undefined) return 'undefined (missing)';
  if (Array.isArray(v)) return 'an array';
  if (typeof v === 'number' && Number.isNaN(v)) return 'NaN';
  if (typeof v === 'object') return 'an object';
  if (typeof v === 'string') return `the string ${JSON.stringify(v.length > 20 ? v.slice(0, 20) + '...' : v)}`;
  return typeof v === 'number' ? String(v) : `a ${typeof v}`;
}

export function num(v, name) {
  if (typeof v !== 'number') throw new TypeError(`${name} must be a number, got ${describe(v)}`);
  if (!Number.isFinite(v)) throw new RangeError(`${name} must be finite, got ${v}`);
  return v;
}

export function nonNeg(v, name) {
  num(v, name);
  if (v < 0) throw new RangeError(`${name} must be >= 0, got ${v}`);
  return v;
}

export function int(v, name, min = -2147483648, max = 2147483647) {
  if (typeof v !== 'number') throw new TypeError(`${name} must be an integer, got ${describe(v)}`);
  if (!Number.isInteger(v) || v < min || v > max) throw new RangeError(`${name} must be an integer in [${min}, ${max}], got ${v}`);
  return v;
}

export function obj(v, name) {
  if (typeof v !== 'object' || v === null) throw new TypeError(`${name} must be an object, got ${describe(v)}`);
  return v;
}

export function vec2(v, name) {
  obj(v, name);
  return [num(v.x, `${name}.x`), num(v.y, `${name}.y`)];
}

export function vec3(v, name) {
  obj(v, name);
  return [num(v.x, `${name}.x`), num(v.y, `${name}.y`), num(v.z, `${name}.z`)];
}

export function quat(v, name) {
  if (v === undefined) return [0, 0, 0, 1];
  obj(v, name);
  const q = [num(v.x, `${name}.x`), num(v.y, `${name}.y`), num(v.z, `${name}.z`), num(v.w, `${name}.w`)];
  const len = Math.hypot(q[0], q[1], q[2], q[3]);
  if (Math.abs(len - 1) > 1e-3) throw new RangeError(`${name} must be a unit quaternion, its length is ${len}`);
  return q;
}

export function bool(v, name) {
  if (typeof v !== 'boolean') throw new TypeError(`${name} must be a boolean, got ${describe(v)}`);
  return v;
}

export function fn(v, name) {
  if (typeof v !== 'function') throw new TypeError(`${name} must be a function, got ${describe(v)}`);
  return v;
}

const RESULT_TEXT = [
  'ok', 'invalid argument', 'NaN or infinite value', 'negative size', 'degenerate (too few distinct points, collinear or zero area)',
  'too many points', 'rotation or normal not of unit length', 'out of memory', 'parse error', 'coordinate out of range',
];

/** Throws for a cdResult code; `name` names the argument it belongs to. */
export function throwResult(code, name) {
  const text = RESULT_TEXT[code] ?? `error ${code}`;
  if (code === 7) throw new Error(`collide: ${name}: ${text}`);
  throw new RangeError(`${name} is not valid: ${text}`);
}

/** Decodes the shim's negative return codes for calls on shapes A and B. */
export function checkCode(code, nameA, nameB, nameOther = 'options') {
  if (code >= 0) return code;
  const c = -code;
  if (c >= 64) throw new RangeError(`${nameOther} is not valid (NaN, infinity, a negative distance or tolerance, or a non-unit rotation)`);
  if (c >= 32) throwResult(c - 32, nameB);
  throwResult(c, nameA);
}

// ---- destroy() and the safety net ------------------------------------------------------------

const registry = typeof FinalizationRegistry === 'function'
  ? new FinalizationRegistry((what) => {
    console.warn(`collide: a ${what} was garbage-collected without destroy(); its wasm memory is leaked. Call destroy() when done.`);
  })
  : null;

export function track(object, what) {
  registry?.register(object, what, object);
}

export function untrack(object) {
  registry?.unregister(object);
}

export function destroyedError(what, name) {
  return new TypeError(`${name}: this ${what} was destroyed`);
}
