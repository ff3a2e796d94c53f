// Loads the wasm module (the SIMD build when the engine supports wasm SIMD, else the scalar
// build) and holds the instance every other module uses. Internal: not part of the public API.

// A minimal module that returns a v128 (i32.const 0, i8x16.splat, i8x16.popcnt): valid only
// where wasm SIMD is supported.
const SIMD_PROBE = new Uint8Array([
  0, 97, 115, 109, 1, 0, 0, 0, 1, 5, 1, 96, 0, 1, 123, 3, 2, 1, 0, 10, 10, 1, 8, 0, 65, 0, 253, 15, 253, 98, 11,
]);

/** @type {any} */
export let exports = null;
/** @type {WebAssembly.Memory | null} */
let memory = null;
let cachedBuffer = null;
export let F32 = new Float32Array(0);
export let I32 = new Int32Array(0);
export let U32 = new Uint32Array(0);
export let F64 = new Float64Array(0);
/** Float index of the scratch block: slot A at S, slot B at S + 64, the I/O area at S + 128. */
export let S = 0;
export let simd = false;
let loading = null;

/** Refreshes the typed views after memory growth; cheap when nothing changed. */
export function views() {
  if (memory.buffer !== cachedBuffer) {
    if (cachedBuffer !== null) oldBuffers.add(cachedBuffer);
    cachedBuffer = memory.buffer;
    F32 = new Float32Array(cachedBuffer);
    I32 = new Int32Array(cachedBuffer);
    U32 = new Uint32Array(cachedBuffer);
    F64 = new Float64Array(cachedBuffer);
  }
}

const oldBuffers = new WeakSet();
/** True for a buffer wasm memory had before it grew (views of it are detached). */
export function isOldBuffer(buffer) {
  views();
  return oldBuffers.has(buffer);
}

export function memoryBuffer() {
  views();
  return memory.buffer;
}

export function requireInit() {
  if (exports === null) throw new Error('collide: call `await init()` before using the library');
}

/** True when the module init() loaded is the SIMD build (false: the scalar build). */
export function isSimdBuild() {
  requireInit();
  return simd;
}

export function simdSupported() {
  try {
    return typeof WebAssembly === 'object' && WebAssembly.validate(SIMD_PROBE);
  } catch {
    return false;
  }
}

function isNode() {
  return typeof process === 'object' && process !== null && typeof process.versions === 'object' &&
    typeof process.versions.node === 'string';
}

async function fetchBytes(source) {
  if (source instanceof URL && source.protocol === 'file:') {
    const fsName = 'node:fs/promises';
    const fs = await import(/* @vite-ignore */ fsName);
    return fs.readFile(source);
  }
  const response = await fetch(source);
  if (!response.ok) throw new Error(`collide: cannot load ${source}: HTTP ${response.status}`);
  return response.arrayBuffer();
}

/** Handlers of the functions the module imports from "collide" (set by lib/world2.js). */
export const callbacks = { preSolve: () => 1, customFilter: () => 1 };

function stubImports(module) {
  // The library never does I/O; libc's stdio is linked in (the assert handler) but only
  // reachable after a failed assertion, which release builds compile out. Each WASI import
  // answers ENOSYS (52).
  const imports = {};
  for (const imp of WebAssembly.Module.imports(module)) {
    if (imp.kind !== 'function') continue;
    if (imp.module === 'collide') {
      // The 2D world's callbacks (pre-solve, custom filter): lib/world2.js installs the handlers.
      imports.collide ??= {};
      imports.collide[imp.name] = (...args) => callbacks[imp.name](...args);
      continue;
    }
    imports[imp.module] ??= {};
    imports[imp.module][imp.name] = imp.name === 'proc_exit'
      ? (code) => { throw new Error(`collide: wasm exited with code ${code}`); }
      : () => 52;
  }
  return imports;
}

/**
 * Loads the wasm module. Options: `simd` (force the SIMD or the scalar build), `wasm` (URL, path
 * string, bytes, Response or WebAssembly.Module of the build to use: for bundlers that move the
 * .wasm files). Resolves when every function is ready; calling it again returns the same promise.
 */
export function init(options = {}) {
  if (typeof options !== 'object' || options === null) {
    return Promise.reject(new TypeError(`options must be an object, got ${options === null ? 'null' : typeof options}`));
  }
  if (loading !== null) return loading;
  loading = (async () => {
    const useSimd = options.simd === undefined ? simdSupported() : Boolean(options.simd);
    let source = options.wasm;
    if (source === undefined) {
      source = new URL(useSimd ? '../dist/collide-simd.wasm' : '../dist/collide.wasm', import.meta.url);
    } else if (typeof source === 'string') {
      source = isNode() && !/^[a-z]+:/i.test(source) ? new URL(source, `file://${process.cwd()}/`) : new URL(source, globalThis.location?.href);
    }
    let module;
    if (source instanceof WebAssembly.Module) {
      module = source;
    } else if (source instanceof URL && source.protocol !== 'file:' && typeof WebAssembly.compileStreaming === 'function') {
      try {
        module = await WebAssembly.compileStreaming(fetch(source));
      } catch {
        module = await WebAssembly.compile(await fetchBytes(source));
      }
    } else if (source instanceof URL) {
      module = await WebAssembly.compile(await fetchBytes(source));
    } else if (typeof Response !== 'undefined' && source instanceof Response) {
      module = await WebAssembly.compile(await source.arrayBuffer());
    } else {
      module = await WebAssembly.compile(source);
    }
    const instance = await WebAssembly.instantiate(module, stubImports(module));
    exports = instance.exports;
    memory = exports.memory;
    simd = exports.isSimd() === 1;
    views();
    S = exports.scratch() >> 2;
    if (exports.isDouble() !== 0) throw new Error('collide: the wasm build must use float');
  })();
  loading.catch(() => { loading = null; });
  return loading;
}

// ---- staging memory for variable-size inputs and outputs -----------------------------------

let stagePtr = 0;
let stageBytes = 0;

/** Returns a byte pointer to at least `bytes` bytes of reusable wasm memory (16-byte aligned). */
export function stage(bytes) {
  if (bytes > stageBytes) {
    if (stagePtr !== 0) exports.free(stagePtr);
    let size = Math.max(bytes, 65536);
    size = 2 ** Math.ceil(Math.log2(size));
    stagePtr = exports.malloc(size);
    if (stagePtr === 0) {
      stageBytes = 0;
      throw new RangeError(`collide: out of wasm memory (asked for ${bytes} bytes)`);
    }
    stageBytes = size;
    views();
  }
  return stagePtr;
}

/** A second staging area, for calls with two variable-size inputs. */
let stage2Ptr = 0;
let stage2Bytes = 0;
export function stage2(bytes) {
  if (bytes > stage2Bytes) {
    if (stage2Ptr !== 0) exports.free(stage2Ptr);
    let size = Math.max(bytes, 65536);
    size = 2 ** Math.ceil(Math.log2(size));
    stage2Ptr = exports.malloc(size);
    if (stage2Ptr === 0) {
      stage2Bytes = 0;
      throw new RangeError(`collide: out of wasm memory (asked for ${bytes} bytes)`);
    }
    stage2Bytes = size;
    views();
  }
  return stage2Ptr;
}
