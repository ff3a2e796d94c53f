// A broadphase frame of n moving boxes in node: collide's broadphase (wasm) against the loop a
// JavaScript reader writes by hand, the texts' intersect(a, b) over all pairs of an array of
// boxes. Both produce the same list: every pair of boxes that overlap this frame.
//   node bench/js/bench_broadphase.mjs [--n 10000] [--frames 30] [--dim 3]
// collide's frame: write the new boxes into a WasmArray, moveProxies (all boxes), findAllPairs on
// the fat boxes, then keep the pairs whose tight boxes overlap (JS). Also timed: the incremental
// form a game uses (updatePairs: only pairs with a box whose fat box changed).
import * as c from '../../bindings/js/index.js';
import { cpuMs, median } from './timing.mjs';

const args = process.argv.slice(2);
const opt = (name, dflt) => { const i = args.indexOf(`--${name}`); return i >= 0 ? Number(args[i + 1]) : dflt; };
const N = opt('n', 10000);
const FRAMES = opt('frames', 30);
const JS_FRAMES = opt('js-frames', 5);

await c.init({ simd: !args.includes('--scalar') && c.simdSupported() });

// The scene: n boxes (sizes 0.5-2) in a cube sized for about 1.5 overlapping pairs per box,
// moving at up to 0.05 per frame and bouncing off the walls.
let seed = 99;
const rnd = (lo, hi) => lo + (hi - lo) * ((seed = (seed * 16807) % 2147483647) / 2147483647);
const side = Math.cbrt(N) * 2.2;
const bodies = [];
for (let i = 0; i < N; i++) {
  bodies.push({
    x: rnd(0, side), y: rnd(0, side), z: rnd(0, side), hx: rnd(0.25, 1), hy: rnd(0.25, 1), hz: rnd(0.25, 1),
    vx: rnd(-0.05, 0.05), vy: rnd(-0.05, 0.05), vz: rnd(-0.05, 0.05),
  });
}
function step() {
  for (const b of bodies) {
    b.x += b.vx; b.y += b.vy; b.z += b.vz;
    if (b.x < 0 || b.x > side) b.vx = -b.vx;
    if (b.y < 0 || b.y > side) b.vy = -b.vy;
    if (b.z < 0 || b.z > side) b.vz = -b.vz;
  }
}

// ---- plain JavaScript: the texts' box objects and intersect() over all pairs ----
const boxes = bodies.map(() => ({ minX: 0, maxX: 0, minY: 0, maxY: 0, minZ: 0, maxZ: 0 }));
function intersect(a, b) {
  return a.minX <= b.maxX && a.maxX >= b.minX && a.minY <= b.maxY && a.maxY >= b.minY && a.minZ <= b.maxZ && a.maxZ >= b.minZ;
}
function jsFrame() {
  for (let i = 0; i < N; i++) {
    const b = bodies[i], o = boxes[i];
    o.minX = Math.fround(b.x - b.hx); o.maxX = Math.fround(b.x + b.hx);
    o.minY = Math.fround(b.y - b.hy); o.maxY = Math.fround(b.y + b.hy);
    o.minZ = Math.fround(b.z - b.hz); o.maxZ = Math.fround(b.z + b.hz);
  }
  const pairs = [];
  for (let i = 0; i < N; i++) {
    const a = boxes[i];
    for (let j = i + 1; j < N; j++) if (intersect(a, boxes[j])) pairs.push(i, j);
  }
  return pairs;
}

// ---- collide ----
const aabbs = new c.WasmArray('f32', 6 * N);
function writeBoxes() {
  const f = aabbs.array;
  for (let i = 0; i < N; i++) {
    const b = bodies[i], k = 6 * i;
    f[k] = b.x - b.hx; f[k + 1] = b.y - b.hy; f[k + 2] = b.z - b.hz;
    f[k + 3] = b.x + b.hx; f[k + 4] = b.y + b.hy; f[k + 5] = b.z + b.hz;
  }
}
writeBoxes();
let bp = null, ids = null;
function useStructure(type) {
  bp?.destroy();
  bp = new c.BroadPhase3({ type });
  writeBoxes();
  ids = bp.createProxies(aabbs);
  bp.updatePairs();
}
useStructure('tree');
function collideFrame() {
  writeBoxes();
  bp.moveProxies(ids, aabbs);
  const fat = bp.findAllPairs();
  const f = aabbs.array;
  const pairs = [];
  for (let k = 0; k < fat.length; k += 2) {
    const i = fat[k], j = fat[k + 1], a = 6 * i, b = 6 * j;
    if (f[a] <= f[b + 3] && f[a + 3] >= f[b] && f[a + 1] <= f[b + 4] && f[a + 4] >= f[b + 1] && f[a + 2] <= f[b + 5] && f[a + 5] >= f[b + 2]) {
      pairs.push(i, j);
    }
  }
  return pairs;
}
function collideIncremental() {
  writeBoxes();
  bp.moveProxies(ids, aabbs);
  return bp.updatePairs();
}

// Same pairs from both on the current frame (ids equal indices: created in order).
{
  const a = jsFrame(), b = collideFrame();
  if (a.length !== b.length || a.some((v, i) => v !== b[i])) throw new Error(`pairs differ: JS ${a.length / 2}, collide ${b.length / 2}`);
  console.log(`scene: ${N} boxes in a cube of side ${side.toFixed(1)}, ${a.length / 2} overlapping pairs; both give the same pairs`);
}

const timeFrames = (fn, frames) => {
  const t = [];
  let pairs = 0;
  for (let f = 0; f < frames; f++) {
    step();
    const t0 = cpuMs();
    pairs = fn().length / 2;
    t.push(cpuMs() - t0);
  }
  return { ms: median(t), pairs };
};
const js = timeFrames(jsFrame, JS_FRAMES);
const rows = [];
for (const type of c.BROADPHASE_TYPES) {
  useStructure(type);
  rows.push([`collide ${type}: moveProxies + findAllPairs + exact filter`, timeFrames(collideFrame, FRAMES)]);
  rows.push([`collide ${type}: moveProxies + updatePairs (new pairs only)`, timeFrames(collideIncremental, FRAMES)]);
}
console.log(`broadphase frame, node ${process.version}, wasm ${c.isSimdBuild() ? 'SIMD' : 'scalar'} build, n = ${N}, median CPU ms per frame (JS ${JS_FRAMES} frames, collide ${FRAMES} frames)`);
console.log('| frame | ms per frame | pairs reported (last frame) | all-pairs JS / this |');
console.log('|---|---|---|---|');
console.log(`| plain JS, intersect() over all pairs | ${js.ms.toFixed(2)} | ${js.pairs} | 1.0x |`);
for (const [name, r] of rows) console.log(`| ${name} | ${r.ms.toFixed(2)} | ${r.pairs} | ${(js.ms / r.ms).toFixed(1)}x |`);
bp.destroy();
aabbs.destroy();
