// Triangle meshes (Mesh3), chains (Chain2) and chain shapes on World2 bodies from JavaScript: each
// query against an exact answer (a tessellated floor and a terrain line whose hits, distances,
// contacts and overlapping elements are known in closed form), against the package's
// single-shape queries on the same triangle or segment (cd3Collide / cd2Collide, whose wasm
// answers js_api compares with the native library), and bad input throwing TypeError/RangeError
// naming the argument.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import * as c from 'collide';

before(async () => { await c.init(); });

const near = (a, b, tol, what) => assert.ok(Math.abs(a - b) <= tol, `${what}: ${a} vs ${b}`);

// An N x N grid of unit cells on y = 0 from (0, 0) to (N, N), two triangles per cell, counter-
// clockwise seen from above (+y): cell (i, j) -> triangles 2 (i N + j) and 2 (i N + j) + 1.
function floorMesh(N) {
  const vertices = new Float32Array(3 * (N + 1) * (N + 1));
  for (let i = 0; i <= N; i++) {
    for (let j = 0; j <= N; j++) vertices.set([j, 0, i], 3 * (i * (N + 1) + j));
  }
  const indices = new Uint32Array(6 * N * N);
  for (let i = 0; i < N; i++) {
    for (let j = 0; j < N; j++) {
      const a = i * (N + 1) + j, b = a + 1, d = a + N + 1, e = d + 1;
      // Seen from +y with x right and z down the page: (a, d, b) and (b, d, e) are counter-clockwise.
      indices.set([a, d, b, b, d, e], 6 * (i * N + j));
    }
  }
  return { vertices, indices };
}

// The triangle of the grid under (x, z): cell (floor(z), floor(x)); the first triangle holds the
// points with (x - j) + (z - i) < 1.
function cellTriangle(N, x, z) {
  const i = Math.floor(z), j = Math.floor(x);
  return 2 * (i * N + j) + ((x - j) + (z - i) < 1 ? 0 : 1);
}

function rng(seed) {
  let s = seed >>> 0;
  return () => { s = (s * 1664525 + 1013904223) >>> 0; return s / 4294967296; };
}

test('Mesh3: building a floor, its stats, its triangles by input index and a dropped degenerate triangle', () => {
  const N = 8;
  const { vertices, indices } = floorMesh(N);
  const mesh = new c.Mesh3(vertices, indices);
  assert.equal(mesh.triangleCount, 2 * N * N);
  assert.equal(mesh.vertexCount, (N + 1) * (N + 1));
  assert.equal(mesh.droppedTriangleCount, 0);
  assert.ok(mesh.validate());
  near(mesh.bounds.min.x, 0, 1e-3, 'min x'); near(mesh.bounds.max.z, N, 1e-3, 'max z');
  // 8-wide nodes, each with 2 to 8 children (nodes and leaves; a root over one leaf has 1).
  assert.ok(mesh.depth >= 2 && mesh.leafCount >= 1 && mesh.nodeCount >= 1 &&
    mesh.nodeCount <= Math.max(1, mesh.leafCount - 1) && 7 * mesh.nodeCount >= mesh.leafCount - 1);
  for (const k of [0, 1, 37, 2 * N * N - 1]) {
    const t = mesh.triangle(k);
    const corner = (m) => ({ x: vertices[3 * indices[3 * k + m]], y: vertices[3 * indices[3 * k + m] + 1], z: vertices[3 * indices[3 * k + m] + 2] });
    assert.deepEqual([t.a, t.b, t.c], [corner(0), corner(1), corner(2)], `triangle ${k}`);
  }
  assert.equal(mesh.triangle(2 * N * N), null);
  mesh.destroy();
  assert.ok(mesh.destroyed);
  mesh.destroy(); // twice is harmless

  // Plain arrays work too; a zero-area triangle (repeated vertex) is dropped but keeps the others' indices.
  const m2 = new c.Mesh3([0, 0, 0, 1, 0, 0, 0, 0, 1, 1, 0, 1], [0, 2, 1, 1, 1, 2, 1, 2, 3]);
  assert.equal(m2.triangleCount, 2);
  assert.equal(m2.droppedTriangleCount, 1);
  assert.equal(m2.triangle(1), null);
  assert.deepEqual(m2.triangle(2).c, { x: 1, y: 0, z: 1 });
  m2.destroy();
});

test('Mesh3: ray casts hit the triangle under the ray at the exact height, from both sides, placed by a transform', () => {
  const N = 8;
  const { vertices, indices } = floorMesh(N);
  const mesh = new c.Mesh3(vertices, indices);
  const r = rng(7);
  for (let k = 0; k < 200; k++) {
    const x = 0.05 + r() * (N - 0.1), z = 0.05 + r() * (N - 0.1);
    const dx = x - Math.floor(x), dz = z - Math.floor(z);
    if (Math.abs(dx + dz - 1) < 1e-3) continue; // on a diagonal: either triangle is right
    const h = 1 + 4 * r();
    const down = mesh.raycast({ origin: { x, y: h, z }, translation: { x: 0, y: -2 * h, z: 0 } });
    assert.ok(down !== null, `ray ${k} misses`);
    near(down.fraction, 0.5, 1e-5, 'fraction');
    near(down.point.x, x, 1e-5, 'x'); near(down.point.y, 0, 1e-5, 'y'); near(down.point.z, z, 1e-5, 'z');
    assert.deepEqual(down.normal, { x: 0, y: 1, z: 0 });
    assert.equal(down.triangleIndex, cellTriangle(N, x, z));
    // The same answer as the single-triangle ray cast on that triangle.
    const one = c.raycast3(mesh.triangle(down.triangleIndex), { origin: { x, y: h, z }, translation: { x: 0, y: -2 * h, z: 0 } });
    assert.equal(one.fraction, down.fraction);
    // Two-sided: from below the normal faces down.
    const up = mesh.raycast({ origin: { x, y: -h, z }, translation: { x: 0, y: 2 * h, z: 0 } });
    assert.ok(up.normal.x === 0 && up.normal.y === -1 && up.normal.z === 0, `normal from below ${JSON.stringify(up.normal)}`);
    assert.ok(mesh.raycastAny({ origin: { x, y: h, z }, translation: { x: 0, y: -2 * h, z: 0 } }));
    // Too short, or beside the floor: no hit.
    assert.equal(mesh.raycast({ origin: { x, y: h, z }, translation: { x: 0, y: -0.5 * h, z: 0 } }), null);
    assert.equal(mesh.raycastAny({ origin: { x: x + N, y: h, z }, translation: { x: 0, y: -2 * h, z: 0 } }), false);
  }
  // Lifted by 3 and turned a quarter about x (+90 degrees maps +y to +z and +z to -y): the floor
  // becomes the plane z = 0, facing +z.
  const s = Math.SQRT1_2;
  const tf = { position: { x: 0, y: 3, z: 0 }, rotation: { x: s, y: 0, z: 0, w: s } };
  const hit = mesh.raycast({ origin: { x: 2.5, y: 1.6, z: 5 }, translation: { x: 0, y: 0, z: -10 } }, tf);
  near(hit.fraction, 0.5, 1e-5, 'placed fraction');
  near(hit.normal.z, 1, 1e-5, 'placed normal');
  // Mesh point (x, 0, z) maps to world (x, 3 - z, 0): the hit is mesh point (2.5, 0, 1.4).
  near(hit.point.y, 1.6, 1e-5, 'placed point');
  assert.equal(hit.triangleIndex, cellTriangle(N, 2.5, 1.4));
  mesh.destroy();
});

test('Mesh3: queryAabb reports exactly the triangles whose bounds meet the box (mesh space)', () => {
  const N = 10;
  const { vertices, indices } = floorMesh(N);
  const mesh = new c.Mesh3(vertices, indices);
  const r = rng(11);
  for (let k = 0; k < 50; k++) {
    // Box edges at x.37 / x.63 offsets: never within the bounds' padding of a grid line.
    const x0 = Math.floor(r() * N) + 0.37, z0 = Math.floor(r() * N) + 0.37;
    const x1 = Math.min(N + 1, x0 + Math.floor(r() * 4) + 0.26), z1 = Math.min(N + 1, z0 + Math.floor(r() * 4) + 0.26);
    const got = [...mesh.queryAabb({ min: { x: x0, y: -1, z: z0 }, max: { x: x1, y: 1, z: z1 } })].sort((a, b) => a - b);
    const want = [];
    for (let t = 0; t < 2 * N * N; t++) {
      const tri = mesh.triangle(t);
      const xs = [tri.a.x, tri.b.x, tri.c.x], zs = [tri.a.z, tri.b.z, tri.c.z];
      if (Math.min(...xs) <= x1 && Math.max(...xs) >= x0 && Math.min(...zs) <= z1 && Math.max(...zs) >= z0) want.push(t);
    }
    assert.deepEqual(got, want, `box ${k}`);
  }
  // More results than the first buffer (256) holds: the whole floor.
  assert.equal(mesh.queryAabb({ min: { x: -1, y: -1, z: -1 }, max: { x: N + 1, y: 1, z: N + 1 } }).length, 2 * N * N);
  assert.equal(mesh.queryAabb({ min: { x: -1, y: 2, z: -1 }, max: { x: N + 1, y: 3, z: N + 1 } }).length, 0);
  mesh.destroy();
});

test('Mesh3: closest point, overlap and contact manifolds against the floor', () => {
  const N = 6;
  const { vertices, indices } = floorMesh(N);
  const mesh = new c.Mesh3(vertices, indices);
  // Above the floor: straight down; beyond the edge x = N: the edge point.
  const above = mesh.closestPoint({ x: 2.3, y: 1.5, z: 4.1 });
  near(above.distance, 1.5, 1e-5, 'distance above');
  near(above.point.x, 2.3, 1e-5, 'x'); near(above.point.y, 0, 1e-6, 'y'); near(above.point.z, 4.1, 1e-5, 'z');
  assert.equal(above.triangleIndex, cellTriangle(N, 2.3, 4.1));
  const beside = mesh.closestPoint({ x: N + 3, y: 4, z: 2.5 });
  near(beside.distance, 5, 1e-5, 'distance beside');
  near(beside.point.x, N, 1e-5, 'edge x');
  assert.equal(mesh.closestPoint({ x: N + 3, y: 4, z: 2.5 }, undefined, 4.9), null);
  // Placed 2 lower: the distance grows by 2.
  near(mesh.closestPoint({ x: 2.3, y: 1.5, z: 4.1 }, { position: { x: 0, y: -2, z: 0 } }).distance, 3.5, 1e-5, 'placed distance');

  assert.equal(mesh.overlap(c.sphere({ x: 3.3, y: 0.4, z: 2.2 }, 0.5)), true);
  assert.equal(mesh.overlap(c.sphere({ x: 3.3, y: 0.6, z: 2.2 }, 0.5)), false);
  assert.equal(mesh.overlap(c.box3({ x: 3, y: 0.49, z: 3 }, { x: 0.5, y: 0.5, z: 0.5 })), true);
  assert.equal(mesh.overlap(c.sphere({ x: 3.3, y: 0.4, z: 2.2 }, 0.5), { position: { x: 0, y: -1, z: 0 } }), false);

  // A sphere sunk 0.1 into the middle of a triangle: one manifold, normal from the sphere to the
  // floor (down), one point at separation -0.1, equal to manifold3 on that triangle.
  const ball = c.sphere({ x: 2.25, y: 0.4, z: 1.25 }, 0.5);
  const ms = mesh.manifolds(ball);
  assert.equal(ms.length, 1);
  assert.equal(ms[0].triangleIndex, cellTriangle(N, 2.25, 1.25));
  near(ms[0].normal.y, -1, 1e-6, 'normal');
  assert.equal(ms[0].points.length, 1);
  near(ms[0].points[0].separation, -0.1, 1e-5, 'separation');
  const single = c.manifold3(ball, mesh.triangle(ms[0].triangleIndex));
  assert.deepEqual(ms[0].normal, single.normal);
  assert.deepEqual(ms[0].points, single.points);
  // A box resting over four cells: every manifold points down; the points cover the box's base,
  // all at separation -0.02.
  const box = c.box3({ x: 3, y: 0.48, z: 3 }, { x: 0.5, y: 0.5, z: 0.5 });
  const bm = mesh.manifolds(box);
  assert.ok(bm.length >= 4, `box manifolds ${bm.length}`);
  for (const m of bm) {
    near(m.normal.y, -1, 1e-5, 'box normal');
    for (const p of m.points) {
      near(p.separation, -0.02, 1e-4, 'box separation');
      assert.ok(Math.abs(p.point.x - 3) <= 0.5 + 1e-4 && Math.abs(p.point.z - 3) <= 0.5 + 1e-4);
    }
  }
  const corners = new Set(bm.flatMap((m) => m.points.map((p) => `${Math.round(p.point.x * 2)},${Math.round(p.point.z * 2)}`)));
  for (const k of ['5,5', '7,5', '5,7', '7,7']) assert.ok(corners.has(k), `box corner ${k} in ${[...corners]}`);
  // capacity caps the count; speculative distance reports a hovering sphere.
  assert.equal(mesh.manifolds(box, undefined, { capacity: 2 }).length, 2);
  assert.equal(mesh.manifolds(c.sphere({ x: 2.25, y: 0.55, z: 1.25 }, 0.5)).length, 0);
  const spec = mesh.manifolds(c.sphere({ x: 2.25, y: 0.55, z: 1.25 }, 0.5), undefined, { speculativeDistance: 0.1 });
  assert.equal(spec.length, 1);
  near(spec[0].points[0].separation, 0.05, 1e-5, 'speculative separation');
  // A hull shape works as well.
  const hull = c.Hull.box({ x: 0.5, y: 0.5, z: 0.5 });
  const hm = mesh.manifolds(c.hullShape(hull, { x: 1.5, y: 0.45, z: 1.5 }));
  assert.ok(hm.length >= 1 && hm.every((m) => m.points.every((p) => Math.abs(p.separation + 0.05) < 1e-4)));
  hull.destroy();
  mesh.destroy();
});

test('Mesh3: bad input throws TypeError/RangeError naming the argument', () => {
  const tri = () => new c.Mesh3(new Float32Array([0, 0, 0, 1, 0, 0, 0, 0, 1]), new Uint32Array([0, 2, 1]));
  assert.throws(() => new c.Mesh3('abc', [0, 1, 2]), (e) => e instanceof TypeError && /vertices/.test(e.message));
  assert.throws(() => new c.Mesh3(new Float32Array(8), [0, 1, 2]), (e) => e instanceof RangeError && /vertices/.test(e.message));
  assert.throws(() => new c.Mesh3(new Float32Array([0, 0, 0, 1, NaN, 0, 0, 0, 1]), [0, 1, 2]), (e) => e instanceof RangeError && /vertices\[4\]/.test(e.message));
  assert.throws(() => new c.Mesh3(new Float32Array(9), new Float32Array(3)), (e) => e instanceof TypeError && /indices/.test(e.message));
  assert.throws(() => new c.Mesh3(new Float32Array(9), [0, 1]), (e) => e instanceof RangeError && /indices/.test(e.message));
  assert.throws(() => new c.Mesh3(new Float32Array(9), [0, 1, 3]), (e) => e instanceof RangeError && /indices\[2\]/.test(e.message));
  assert.throws(() => new c.Mesh3(new Float32Array(9), [0, -1, 2]), (e) => e instanceof RangeError && /indices\[1\]/.test(e.message));
  assert.throws(() => new c.Mesh3(new Float32Array(9), [0, 1, 2]), (e) => e instanceof RangeError && /zero area/.test(e.message));
  assert.throws(() => new c.Mesh3(new Float32Array([0, 0, 0, 1e30, 0, 0, 0, 0, 1]), [0, 1, 2]), (e) => e instanceof RangeError && /vertices/.test(e.message));
  const mesh = tri();
  assert.throws(() => mesh.raycast({ origin: { x: 0, y: 1, z: 0 } }), (e) => e instanceof TypeError && /ray\.translation/.test(e.message));
  assert.throws(() => mesh.raycast({ origin: { x: 0, y: 1, z: 0 }, translation: { x: 0, y: -2, z: 0 } }, { rotation: { x: 1, y: 1, z: 0, w: 0 } }),
    (e) => e instanceof RangeError && /transform\.rotation/.test(e.message));
  assert.throws(() => mesh.queryAabb({ min: { x: 1, y: 0, z: 0 }, max: { x: 0, y: 1, z: 1 } }), RangeError);
  assert.throws(() => mesh.closestPoint({ x: 0, y: 0, z: 0 }, undefined, -1), (e) => e instanceof RangeError && /maxDistance/.test(e.message));
  assert.throws(() => mesh.overlap({ type: 'sphere', center: { x: 0, y: 0, z: 0 }, radius: -1 }), (e) => e instanceof RangeError && /shape\.radius/.test(e.message));
  assert.throws(() => mesh.manifolds(c.plane({ x: 0, y: 1, z: 0 }, 0)), (e) => e instanceof RangeError && /plane/.test(e.message));
  assert.throws(() => mesh.manifolds(c.sphere({ x: 0, y: 0, z: 0 }, 1), undefined, { capacity: 1.5 }), (e) => e instanceof RangeError && /options\.capacity/.test(e.message));
  assert.throws(() => mesh.triangle(-1), (e) => e instanceof RangeError && /index/.test(e.message));
  mesh.destroy();
  assert.throws(() => mesh.raycastAny({ origin: { x: 0, y: 1, z: 0 }, translation: { x: 0, y: -2, z: 0 } }), (e) => e instanceof TypeError && /destroyed/.test(e.message));
  assert.throws(() => mesh.manifolds(c.sphere({ x: 0, y: 0, z: 0 }, 1)), TypeError);
});

// A terrain line from right to left (free side up): (8, 0) -> (4, 0) -> (0, 0) -> (-4, 1).
const TERRAIN = [{ x: 8, y: 0 }, { x: 4, y: 0 }, { x: 0, y: 0 }, { x: -4, y: 1 }];

test('Chain2: points, welding, loops and segments with their ghosts', () => {
  const chain = new c.Chain2(TERRAIN);
  assert.equal(chain.segmentCount, 3);
  assert.equal(chain.pointCount, 4);
  assert.equal(chain.loop, false);
  assert.deepEqual([...chain.points], [8, 0, 4, 0, 0, 0, -4, 1]);
  assert.deepEqual(chain.bounds, { min: { x: -4, y: 0 }, max: { x: 8, y: 1 } });
  // Segment 1 is (4,0) -> (0,0) with the neighbours' far vertices as ghosts; the open ends extend
  // the end segments straight on by their own length.
  assert.deepEqual(chain.segment(1), { ghost1: { x: 8, y: 0 }, p1: { x: 4, y: 0 }, p2: { x: 0, y: 0 }, ghost2: { x: -4, y: 1 } });
  assert.deepEqual(chain.segment(0).ghost1, { x: 12, y: 0 });
  assert.deepEqual(chain.segment(2).ghost2, { x: -8, y: 2 });
  chain.destroy();
  // A repeated point is welded; a loop's repeated first point too.
  const welded = new c.Chain2(new Float32Array([2, 0, 1, 0, 1, 0, 0, 0]));
  assert.equal(welded.pointCount, 3);
  welded.destroy();
  const square = new c.Chain2([{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 1, y: 1 }, { x: 0, y: 1 }, { x: 0, y: 0 }], { loop: true });
  assert.equal(square.loop, true);
  assert.equal(square.pointCount, 4);
  assert.equal(square.segmentCount, 4);
  assert.deepEqual(square.segment(3), { ghost1: { x: 1, y: 1 }, p1: { x: 0, y: 1 }, p2: { x: 0, y: 0 }, ghost2: { x: 1, y: 0 } });
  square.destroy();
});

test('Chain2: one-sided ray casts, with the segment hit, placed by a transform', () => {
  const chain = new c.Chain2(TERRAIN);
  const down = chain.raycast({ origin: { x: 5, y: 2 }, translation: { x: 0, y: -4 } });
  assert.deepEqual(down, { fraction: 0.5, point: { x: 5, y: 0 }, normal: { x: 0, y: 1 }, segmentIndex: 0 });
  // From behind (below) the ray passes through.
  assert.equal(chain.raycast({ origin: { x: 5, y: -2 }, translation: { x: 0, y: 4 } }), null);
  // The slope (0,0) -> (-4,1): normal (-1, -4) rotated... its free side is to the right of the
  // direction (-4, 1), i.e. (1, 4)/sqrt(17).
  const slope = chain.raycast({ origin: { x: -2, y: 3 }, translation: { x: 0, y: -4 } });
  assert.equal(slope.segmentIndex, 2);
  near(slope.point.y, 0.5, 1e-6, 'slope y');
  near(slope.normal.x, 1 / Math.sqrt(17), 1e-6, 'slope nx'); near(slope.normal.y, 4 / Math.sqrt(17), 1e-6, 'slope ny');
  // The chain turned a quarter counter-clockwise about the origin and moved to (10, 0): the floor
  // segment 0 now runs from (10, 8) to (10, 4) with its free side towards -x.
  const tf = { position: { x: 10, y: 0 }, angle: Math.PI / 2 };
  const side = chain.raycast({ origin: { x: 7, y: 5 }, translation: { x: 6, y: 0 } }, tf);
  assert.equal(side.segmentIndex, 0);
  near(side.fraction, 0.5, 1e-6, 'placed fraction');
  near(side.normal.x, -1, 1e-6, 'placed normal');
  assert.equal(chain.raycast({ origin: { x: 13, y: 5 }, translation: { x: -6, y: 0 } }, tf), null);
  chain.destroy();
  // A loop around a solid (counter-clockwise): hit from outside, not from inside.
  const island = new c.Chain2([{ x: 0, y: 0 }, { x: 2, y: 0 }, { x: 2, y: 2 }, { x: 0, y: 2 }], { loop: true });
  assert.equal(island.raycast({ origin: { x: -1, y: 1 }, translation: { x: 2, y: 0 } }).segmentIndex, 3);
  assert.equal(island.raycast({ origin: { x: 1, y: 1 }, translation: { x: 3, y: 0 } }), null);
  island.destroy();
});

test('Chain2: queryAabb reports the segments whose bounds meet the box, in increasing order', () => {
  // A zig-zag of 600 segments: many leaves of the hierarchy.
  const pts = [];
  for (let i = 600; i >= 0; i--) pts.push({ x: i, y: (i % 2) * 0.5 });
  const chain = new c.Chain2(pts);
  const r = rng(3);
  for (let k = 0; k < 40; k++) {
    const x0 = r() * 600 + 0.13, x1 = x0 + r() * 50 + 0.21, y0 = r() * 0.7 - 0.1, y1 = y0 + 0.05;
    const got = [...chain.queryAabb({ min: { x: x0, y: y0 }, max: { x: x1, y: y1 } })];
    const want = [];
    for (let s = 0; s < 600; s++) {
      const a = pts[s], b = pts[s + 1];
      if (Math.min(a.x, b.x) <= x1 && Math.max(a.x, b.x) >= x0 && Math.min(a.y, b.y) <= y1 && Math.max(a.y, b.y) >= y0) want.push(s);
    }
    assert.deepEqual(got, want, `box ${k}`);
  }
  // Moved right by 1000: the same box finds nothing; moved back by the box, the same segments.
  assert.equal(chain.queryAabb({ min: { x: 10.3, y: -1 }, max: { x: 20.3, y: 1 } }, { position: { x: 1000, y: 0 } }).length, 0);
  assert.deepEqual([...chain.queryAabb({ min: { x: 1010.3, y: -1 }, max: { x: 1020.3, y: 1 } }, { position: { x: 1000, y: 0 } })],
    [...chain.queryAabb({ min: { x: 10.3, y: -1 }, max: { x: 20.3, y: 1 } })]);
  assert.equal(chain.queryAabb({ min: { x: -1, y: -1 }, max: { x: 601, y: 1 } }).length, 600);
  chain.destroy();
});

test('Chain2: manifolds with the terrain as A, one-sided, equal to the segment manifold inside a segment', () => {
  const chain = new c.Chain2(TERRAIN);
  const ball = c.circle({ x: 6, y: 0.4 }, 0.5);
  const ms = chain.manifolds(ball);
  assert.equal(ms.length, 1);
  assert.equal(ms[0].segmentIndex, 0);
  assert.deepEqual(ms[0].normal, { x: 0, y: 1 });
  near(ms[0].points[0].separation, -0.1, 1e-6, 'separation');
  const single = c.manifold2(c.segment2({ x: 8, y: 0 }, { x: 4, y: 0 }), ball);
  assert.deepEqual(ms[0].normal, single.normal);
  near(ms[0].points[0].point.x, single.points[0].point.x, 1e-6, 'point x');
  near(ms[0].points[0].point.y, single.points[0].point.y, 1e-6, 'point y');
  // Behind the floor: nothing (a segment shape would push it down).
  assert.equal(chain.manifolds(c.circle({ x: 6, y: -0.4 }, 0.5)).length, 0);
  assert.equal(c.manifold2(c.segment2({ x: 8, y: 0 }, { x: 4, y: 0 }), c.circle({ x: 6, y: -0.4 }, 0.5)).points.length, 1);
  // A box over the flat vertex (4, 0) between segments 0 and 1: no ghost collision, every normal
  // is straight up; each segment clips the box's base to itself, so the points are the two
  // corners and the shared vertex, each once.
  const box = c.box2({ x: 4, y: 0.45 }, { x: 0.5, y: 0.5 });
  const bm = chain.manifolds(box);
  const points = bm.flatMap((m) => m.points);
  assert.ok(bm.every((m) => Math.abs(m.normal.x) < 1e-6 && Math.abs(m.normal.y - 1) < 1e-6));
  assert.equal(points.length, 3);
  for (const p of points) near(p.separation, -0.05, 1e-5, 'box separation');
  assert.deepEqual(points.map((p) => Math.round(p.point.x * 2)).sort((a, b) => a - b), [7, 8, 9]);
  // Placed 1 higher: the ball now sits 1.1 below the terrain (behind it): nothing; speculative reach.
  assert.equal(chain.manifolds(ball, { position: { x: 0, y: 1 } }).length, 0);
  assert.equal(chain.manifolds(c.circle({ x: 6, y: 0.55 }, 0.5)).length, 0);
  assert.equal(chain.manifolds(c.circle({ x: 6, y: 0.55 }, 0.5), undefined, { speculativeDistance: 0.1 }).length, 1);
  assert.equal(chain.manifolds(c.capsule2({ x: -1, y: 0.5 }, { x: 6, y: 0.5 }, 0.6), undefined, { capacity: 1 }).length, 1);
  chain.destroy();
});

test('Chain2: bad input throws TypeError/RangeError naming the argument', () => {
  assert.throws(() => new c.Chain2('points'), (e) => e instanceof TypeError && /points/.test(e.message));
  assert.throws(() => new c.Chain2([{ x: 0, y: 0 }]), (e) => e instanceof RangeError && /points/.test(e.message));
  assert.throws(() => new c.Chain2([{ x: 0, y: 0 }, { x: 0, y: 0 }]), (e) => e instanceof RangeError && /distinct/.test(e.message));
  assert.throws(() => new c.Chain2([{ x: 0, y: 0 }, { x: 1, y: 0 }], { loop: true }), (e) => e instanceof RangeError && /loop/.test(e.message));
  assert.throws(() => new c.Chain2([{ x: 0, y: 0 }, { x: 1, y: NaN }]), (e) => e instanceof RangeError && /points\[1\]\.y/.test(e.message));
  assert.throws(() => new c.Chain2([{ x: 0, y: 0 }, { y: 1 }]), (e) => e instanceof TypeError && /points\[1\]\.x/.test(e.message));
  assert.throws(() => new c.Chain2(new Float32Array(5)), (e) => e instanceof RangeError && /even/.test(e.message));
  assert.throws(() => new c.Chain2(TERRAIN, { loop: 1 }), (e) => e instanceof TypeError && /options\.loop/.test(e.message));
  const chain = new c.Chain2(TERRAIN);
  assert.throws(() => chain.segment(3), (e) => e instanceof RangeError && /index/.test(e.message));
  assert.throws(() => chain.raycast({ origin: { x: 0, y: 0 }, translation: { x: 0, y: 1 } }, { angle: 'x' }), (e) => e instanceof TypeError && /transform\.angle/.test(e.message));
  assert.throws(() => chain.manifolds({ type: 'circle', center: { x: 0, y: 0 }, radius: -1 }), (e) => e instanceof RangeError && /shape\.radius/.test(e.message));
  assert.throws(() => chain.manifolds(c.circle({ x: 0, y: 0 }, 1), undefined, { speculativeDistance: -1 }), (e) => e instanceof RangeError && /speculativeDistance/.test(e.message));
  chain.destroy();
  assert.throws(() => chain.points, (e) => e instanceof TypeError && /destroyed/.test(e.message));
  assert.throws(() => chain.queryAabb({ min: { x: 0, y: 0 }, max: { x: 1, y: 1 } }), TypeError);
});

test('World2 chain shapes: a box rests on a chain floor, falls through once it is destroyed, and filters apply', () => {
  const world = new c.World2({ gravity: { x: 0, y: -10 } });
  const ground = world.createBody();
  const floor = ground.createChain(new Float32Array([10, 0, 5, 0, 0, 0, -5, 0, -10, 0]), { friction: 0.6 });
  assert.ok(floor instanceof c.ChainShape2);
  assert.equal(floor.segmentCount, 4);
  assert.equal(floor.segments.length, 4);
  assert.ok(floor.segments.every((s) => s.type === 'chainSegment'));
  // In chain order: segment k spans x from 10 - 5 (k + 1) to 10 - 5 k.
  floor.segments.forEach((s, k) => { assert.equal(s.aabb.max.x, 10 - 5 * k); assert.equal(s.aabb.min.x, 5 - 5 * k); });
  near(floor.segments[0].friction, 0.6, 1e-7, 'friction');
  assert.equal(ground.shapes.length, 4);
  const box = world.createBody({ type: 'dynamic', position: { x: 2.5, y: 2 } });
  box.createShape(c.box2({ x: 0, y: 0 }, { x: 0.5, y: 0.5 }), { density: 1 });
  for (let i = 0; i < 120; i++) world.step(1 / 60, 4);
  near(box.position.y, 0.5, 0.02, 'resting height on the chain');
  floor.destroy();
  assert.ok(floor.destroyed);
  assert.ok(floor.segments.every((s) => s.destroyed));
  assert.equal(ground.shapes.length, 0);
  assert.throws(() => floor.segmentCount, TypeError);
  floor.destroy(); // twice is harmless
  for (let i = 0; i < 30; i++) world.step(1 / 60, 4);
  assert.ok(box.position.y < 0, `falls through: ${box.position.y}`);

  // One-sided: a floor wound the wrong way (left to right, free side down) does not hold the box.
  const wrong = world.createBody().createChain([{ x: -10, y: -20 }, { x: 10, y: -20 }]);
  // A filter that the box's shape does not collide with.
  const masked = world.createBody().createChain([{ x: 10, y: -30 }, { x: -10, y: -30 }], { filter: { maskBits: 0 } });
  const held = world.createBody().createChain([{ x: 10, y: -40 }, { x: -10, y: -40 }], { loop: false, restitution: 0 });
  for (let i = 0; i < 240; i++) world.step(1 / 60, 4);
  near(box.position.y, -39.5, 0.05, 'rests on the third floor');
  void wrong; void masked; void held;

  // Bad input.
  const body = world.createBody();
  assert.throws(() => body.createChain([{ x: 0, y: 0 }]), (e) => e instanceof RangeError && /points/.test(e.message));
  assert.throws(() => body.createChain([{ x: 0, y: 0 }, { x: 0, y: 0 }]), (e) => e instanceof RangeError && /distinct/.test(e.message));
  assert.throws(() => body.createChain([{ x: 0, y: 0 }, { x: 1, y: Infinity }]), (e) => e instanceof RangeError && /points\[1\]\.y/.test(e.message));
  assert.throws(() => body.createChain({}), (e) => e instanceof TypeError && /points/.test(e.message));
  assert.throws(() => body.createChain(TERRAIN, { friction: -1 }), (e) => e instanceof RangeError && /options\.friction/.test(e.message));
  assert.throws(() => body.createChain(TERRAIN, { filter: { groupIndex: 0.5 } }), (e) => e instanceof RangeError && /options\.filter\.groupIndex/.test(e.message));
  body.destroy();
  assert.throws(() => body.createChain(TERRAIN), (e) => e instanceof TypeError && /createChain/.test(e.message));
  world.destroy();
  assert.ok(floor.destroyed);
});
