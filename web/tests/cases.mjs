// The browser tests, one function per test. Each gets { page, url, errors, reference, screenshot }.
import * as THREE from 'three';

/** Thrown by a test that waits for something not written yet; reported as pending, not passed. */
export class Pending extends Error {}

function check(cond, message) {
  if (!cond) throw new Error(message);
}
function near(a, b, tol, what) {
  check(Number.isFinite(a) && Number.isFinite(b) && Math.abs(a - b) <= tol, `${what}: ${a} vs ${b} (tolerance ${tol})`);
}
const fmt = (x) => String(x);
const nextFrames = (page, n = 2) => page.evaluate((k) => new Promise((res) => {
  const step = () => (k-- > 0 ? requestAnimationFrame(step) : res());
  step();
}), n);

async function open(page, url, path) {
  await page.goto(new URL(path, url).href);
  await page.waitForFunction(() => window.__demo && window.__demo.ready && window.__demo.hud.frames > 2, null, { timeout: 20000 });
}

/** The HUD shows a frame time and an object count once it has measured some frames. */
async function checkHud(page, label) {
  await page.waitForFunction(() => window.__demo.hud.frameMs > 0, null, { timeout: 10000 });
  const text = await page.locator('#hud').innerText();
  check(/frame \d+(\.\d+)? ms/.test(text), `HUD shows no frame time: "${text}"`);
  check(text.includes(label), `HUD shows no ${label} count: "${text}"`);
}

// ---- reference query lines (independent of the page's code: from each shape's size and pose) ----
function shape2Line(kind, local, e) {
  const c = Math.cos(e.angle);
  const s = Math.sin(e.angle);
  const p = (x, y) => [e.x + (c * x - s * y), e.y + (s * x + c * y)];
  const l = local[kind];
  switch (kind) {
    case 'circle': return `circle ${fmt(e.x)} ${fmt(e.y)} ${fmt(l.radius)}`;
    case 'capsule': return `capsule ${[...p(-l.halfLength, 0), ...p(l.halfLength, 0)].map(fmt).join(' ')} ${fmt(l.radius)}`;
    case 'box': return `box ${fmt(e.x)} ${fmt(e.y)} ${fmt(l.hx)} ${fmt(l.hy)} ${fmt(e.angle)}`;
    case 'polygon': return `polygon ${l.points.length} ${l.points.flatMap(([x, y]) => p(x, y)).map(fmt).join(' ')} ${fmt(l.radius)}`;
    case 'segment': return `segment ${[...p(-l.halfLength, 0), ...p(l.halfLength, 0)].map(fmt).join(' ')}`;
  }
  throw new Error(kind);
}

function shape3Line(kind, local, e) {
  const pos = new THREE.Vector3(...e.pos);
  const q = new THREE.Quaternion(...e.quat);
  const l = local[kind];
  const v = (x) => [x.x, x.y, x.z].map(fmt).join(' ');
  const qs = [q.x, q.y, q.z, q.w].map(fmt).join(' ');
  switch (kind) {
    case 'sphere': return `sphere ${v(pos)} ${fmt(l.radius)}`;
    case 'capsule': {
      const axis = new THREE.Vector3(0, l.halfLength, 0).applyQuaternion(q);
      return `capsule ${v(pos.clone().sub(axis))} ${v(pos.clone().add(axis))} ${fmt(l.radius)}`;
    }
    case 'box': return `box ${v(pos)} ${fmt(l.hx)} ${fmt(l.hy)} ${fmt(l.hz)} ${qs}`;
    case 'hull': return `hull ${l.points.length} ${l.points.flat().map(fmt).join(' ')} ${v(pos)} ${qs}`;
  }
  throw new Error(kind);
}

const xyz = (p, dim) => (dim === 2 ? [p.x, p.y] : [p.x, p.y, p.z]);

/** The page's manifold against the C library's, point by point (same order, same feature ids). */
function compareManifold(mine, ref, dim, what) {
  check(!ref.error, `${what}: the reference rejected the query`);
  check(mine.points.length === ref.pointCount, `${what}: ${mine.points.length} contact points, the C library has ${ref.pointCount}`);
  if (ref.pointCount === 0) return;
  xyz(mine.normal, dim).forEach((x, k) => near(x, ref.normal[k], 1e-4, `${what}: normal[${k}]`));
  mine.points.forEach((p, i) => {
    xyz(p.point, dim).forEach((x, k) => near(x, ref.points[i].point[k], 2e-4, `${what}: point ${i} [${k}]`));
    near(p.separation, ref.points[i].separation, 2e-4, `${what}: point ${i} separation`);
    check(p.id === ref.points[i].id, `${what}: point ${i} feature id ${p.id}, the C library has ${ref.points[i].id}`);
  });
}

function compareDistance(mine, ref, dim, what) {
  check(!ref.error, `${what}: the reference rejected the query`);
  near(mine.distance, ref.distance, 2e-4, `${what}: distance`);
  const gap = Math.hypot(...xyz(mine.pointA, dim).map((x, k) => x - xyz(mine.pointB, dim)[k]));
  near(gap, mine.distance, 2e-4, `${what}: |pointA - pointB| against the distance`);
}

function needReference(reference) {
  check(reference, 'this test compares with the native C library: pass --reference PATH (CMake target web_reference)');
}

// ---- explorer ------------------------------------------------------------------------------------
async function explorerLoad({ page, url, screenshot }) {
  await open(page, url, 'explorer/');
  await checkHud(page, 'shapes');
  const r = await page.evaluate(() => window.__demo.results);
  check(r && r.dim === 2, 'the explorer computed no 2D results');
  for (const name of ['cd2Overlap', 'cd2Distance', 'cd2Collide', 'cd2ShapeCast', 'cd2TimeOfImpact']) {
    check((await page.locator('#panel').innerText()).includes(name), `the panel does not name ${name}`);
  }
  await screenshot('web-explorer-2d.png');
}

async function explorer2d({ page, url, reference, screenshot }) {
  needReference(reference);
  await open(page, url, 'explorer/');
  const view = await page.evaluate(() => window.__demo.view2d);
  const local = await page.evaluate(() => window.__demo.local2);
  const box = await page.locator('#view2d').boundingBox();
  const border = await page.locator('#view2d').evaluate((c) => [c.clientLeft, c.clientTop]);
  const toScreen = (x, y) => ({ x: box.x + border[0] + view.originX + x * view.scale, y: box.y + border[1] + view.originY - y * view.scale });
  let ent = await page.evaluate(() => window.__demo.entities());
  check(ent.a.kind === 'box' && ent.b.kind === 'polygon', `unexpected starting shapes ${ent.a.kind}, ${ent.b.kind}`);

  // Before the drag: A's sweep runs into B. The time of impact stops A where the C library
  // finds the target separation (the linear slop, 0.005) within the tolerance.
  let r = await page.evaluate(() => window.__demo.results);
  check(r.toi.state === 'hit' && r.toi.t > 0 && r.toi.t < 1, `time of impact: ${JSON.stringify(r.toi)}`);
  check(r.cast.hit && r.cast.fraction >= r.toi.t - 1e-3, `shape cast ${JSON.stringify(r.cast)} against the time of impact ${r.toi.t}`);
  {
    const t = r.toi.t;
    const atImpact = { x: ent.a.x + t * ent.sweep.x, y: ent.a.y + t * ent.sweep.y, angle: ent.a.angle + t * ent.spin };
    const d = await reference.query(`distance2 ${shape2Line(ent.a.kind, local, atImpact)} ${shape2Line(ent.b.kind, local, ent.b)}`);
    check(d.distance >= 0.005 - 2e-4 && d.distance <= 0.005 + 0.00125 + 2e-4, `distance at the time of impact: ${d.distance}, expected 0.005 to 0.00625`);
  }

  // Turn B by three wheel notches, then drag it onto A.
  const from = toScreen(ent.b.x, ent.b.y);
  await page.mouse.move(from.x, from.y);
  for (let i = 0; i < 3; i++) await page.mouse.wheel(0, 100);
  await nextFrames(page);
  const dx = -256;
  const dy = -28;
  await page.mouse.down();
  await page.mouse.move(from.x + dx, from.y + dy, { steps: 12 });
  await page.mouse.up();
  await nextFrames(page);
  ent = await page.evaluate(() => window.__demo.entities());
  near(ent.b.angle, -0.15, 1e-9, 'B turned by three wheel notches');
  near(ent.b.x, 3 + dx / view.scale, 1e-6, 'B dragged to x');
  near(ent.b.y, -0.5 - dy / view.scale, 1e-6, 'B dragged to y');
  r = await page.evaluate(() => window.__demo.results);
  check(r.overlap, 'after the drag B overlaps A');
  check(r.manifold.points.length >= 1, 'after the drag the manifold has contact points');
  near(r.speculativeDistance, 0.02, 1e-9, 'speculative distance');
  const shown = await page.locator('[data-point-count]').innerText();
  check(Number(shown) === r.manifold.points.length, `the panel shows ${shown} points, the page computed ${r.manifold.points.length}`);
  await screenshot('web-explorer-2d-drag.png');

  // At this pose, every pair of kinds: the manifold and the distance the C library gives.
  const kinds = ['circle', 'capsule', 'box', 'polygon', 'segment'];
  let compared = 0;
  let touching = 0;
  for (const ka of kinds) {
    for (const kb of kinds) {
      await page.selectOption('#kindA', ka);
      await page.selectOption('#kindB', kb);
      await nextFrames(page);
      const res = await page.evaluate(() => window.__demo.results);
      const lineA = shape2Line(ka, local, ent.a);
      const lineB = shape2Line(kb, local, ent.b);
      const refM = await reference.query(`collide2 ${lineA} ${lineB} ${fmt(res.speculativeDistance)}`);
      compareManifold(res.manifold, refM, 2, `${ka} × ${kb} manifold`);
      compareDistance(res.distance, await reference.query(`distance2 ${lineA} ${lineB}`), 2, `${ka} × ${kb}`);
      check(res.overlap === (res.distance.distance === 0), `${ka} × ${kb}: overlap ${res.overlap} but distance ${res.distance.distance}`);
      const text = await page.locator('[data-point-count]').innerText();
      check(Number(text) === refM.pointCount, `${ka} × ${kb}: the panel shows ${text} points`);
      compared++;
      if (refM.pointCount > 0) touching++;
    }
  }
  check(compared === 25 && touching >= 12, `compared ${compared} pairs, ${touching} touching (expected at least half of them to touch at this pose)`);
}

async function explorer3d({ page, url, reference, screenshot }) {
  needReference(reference);
  await open(page, url, 'explorer/');
  await page.check('input[name=mode][value="3d"]');
  await page.waitForFunction(() => window.__demo.results && window.__demo.results.dim === 3);
  await nextFrames(page, 3);
  const local = await page.evaluate(() => window.__demo.local3);
  let ent = await page.evaluate(() => window.__demo.entities());
  check(ent.a.kind === 'box' && ent.b.kind === 'hull', `unexpected starting shapes ${ent.a.kind}, ${ent.b.kind}`);
  let r = await page.evaluate(() => window.__demo.results);
  check(!r.overlap && r.distance.distance > 0.5, `the shapes start apart (distance ${r.distance.distance})`);
  check(r.toi.state === 'hit' && r.toi.t > 0 && r.toi.t < 1, `3D time of impact: ${JSON.stringify(r.toi)}`);
  await screenshot('web-explorer-3d.png');

  // Drag B (the hull) onto A (the box) on the horizontal plane.
  const from = await page.evaluate(() => window.__demo.screenOf('b'));
  const to = await page.evaluate(() => window.__demo.screenOf('a'));
  const y0 = ent.b.pos[1];
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  await page.mouse.move(to.x + 45, to.y - 10, { steps: 12 });
  await page.mouse.up();
  await nextFrames(page);
  ent = await page.evaluate(() => window.__demo.entities());
  near(ent.b.pos[1], y0, 1e-6, 'the drag keeps B at its height');
  check(ent.b.pos[0] < 0, `B moved towards A (x = ${ent.b.pos[0]})`);
  r = await page.evaluate(() => window.__demo.results);
  check(r.overlap && r.manifold.points.length >= 1, `after the drag B overlaps A with contact points (${r.manifold.points.length})`);
  await screenshot('web-explorer-3d-drag.png');

  const kinds = ['sphere', 'capsule', 'box', 'hull'];
  let touching = 0;
  for (const ka of kinds) {
    for (const kb of kinds) {
      await page.selectOption('#kindA', ka);
      await page.selectOption('#kindB', kb);
      await nextFrames(page);
      const res = await page.evaluate(() => window.__demo.results);
      const lineA = shape3Line(ka, local, ent.a);
      const lineB = shape3Line(kb, local, ent.b);
      const refM = await reference.query(`collide3 ${lineA} ${lineB} ${fmt(res.speculativeDistance)}`);
      compareManifold(res.manifold, refM, 3, `${ka} × ${kb} manifold`);
      compareDistance(res.distance, await reference.query(`distance3 ${lineA} ${lineB}`), 3, `${ka} × ${kb}`);
      const refO = await reference.query(`overlap3 ${lineA} ${lineB}`);
      check(res.overlap === refO.overlap, `${ka} × ${kb}: overlap ${res.overlap}, the C library says ${refO.overlap}`);
      if (refM.pointCount > 0) touching++;
    }
  }
  check(touching >= 12, `only ${touching} of 16 kind pairs touch at the dragged pose`);
}

// ---- bounding volumes ----------------------------------------------------------------------------
function boundsLine(o) {
  const v = (p) => `${fmt(p.x)} ${fmt(p.y)} ${fmt(p.z)}`;
  switch (o.kind) {
    case 'aabb': return `aabb ${v(o.shape.min)} ${v(o.shape.max)}`;
    case 'sphere': return `sphere ${v(o.shape.center)} ${fmt(o.shape.radius)}`;
    case 'box': return `box ${v(o.shape.center)} ${v(o.shape.halfExtents)} ${fmt(o.shape.rotation.x)} ${fmt(o.shape.rotation.y)} ${fmt(o.shape.rotation.z)} ${fmt(o.shape.rotation.w)}`;
    case 'capsule': return `capsule ${v(o.shape.p1)} ${v(o.shape.p2)} ${fmt(o.shape.radius)}`;
    case 'hull': return `hull ${o.points.length} ${o.points.flat().map(fmt).join(' ')} ${v(o.position)} ${fmt(o.rotation.x)} ${fmt(o.rotation.y)} ${fmt(o.rotation.z)} ${fmt(o.rotation.w)}`;
  }
  throw new Error(o.kind);
}

async function bounds3dLoad({ page, url, screenshot }) {
  await open(page, url, 'bounds3d/');
  await checkHud(page, 'objects');
  const t = await page.evaluate(() => window.__demo.tests);
  check(t && t.pairs.length === 28, `the page tests ${t ? t.pairs.length : 0} pairs, expected 28 (8 objects)`);
  const fns = new Set(t.pairs.map((p) => p.fn));
  for (const fn of ['isPointInsideAABB', 'isPointInsideSphere', 'intersectAABB', 'intersectSphere', 'intersectSphereAABB']) {
    check(fns.has(fn), `no pair uses ${fn}`);
  }
  await screenshot('web-bounds3d.png');
}

async function bounds3dDrag({ page, url, reference, screenshot }) {
  needReference(reference);
  await open(page, url, 'bounds3d/');
  const before = await page.evaluate(() => window.__demo.tests.overlaps);
  const drags = [['sphere1', 'aabb1', 'aabb1|sphere1'], ['point', 'sphere2', 'point|sphere2'], ['capsule', 'box', 'box|capsule'], ['aabb2', 'hull', 'aabb2|hull']];
  for (const [what] of drags) check(!before.some((k) => k.split('|').includes(what) && drags.some((d) => d[2] === k)), `${what} starts overlapping`);
  for (const [what, onto] of drags) {
    const from = await page.evaluate((n) => window.__demo.screenOf(n), what);
    const to = await page.evaluate((n) => window.__demo.screenOf(n), onto);
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    await page.mouse.move(to.x + 8, to.y + 4, { steps: 10 });
    await page.mouse.up();
    await nextFrames(page);
  }
  const t = await page.evaluate(() => window.__demo.tests);
  for (const [what, onto, key] of drags) check(t.overlaps.includes(key), `after dragging ${what} onto ${onto} the page reports no ${key} overlap (has ${t.overlaps.join(', ')})`);
  check(t.contacts > 0, 'no contact points shown');
  const shownRows = await page.locator('[data-overlap]').evaluateAll((els) => els.map((e) => e.dataset.overlap));
  check(JSON.stringify(shownRows) === JSON.stringify(t.overlaps), `the panel lists ${shownRows.join(', ')} but the page found ${t.overlaps.join(', ')}`);

  // Every pair against the C library.
  const objects = await page.evaluate(() => window.__demo.objects());
  const byName = Object.fromEntries(objects.map((o) => [o.name, o]));
  for (const p of t.pairs) {
    const a = byName[p.a];
    const b = byName[p.b];
    let ref;
    if (a.kind === 'point' || b.kind === 'point') {
      const [pt, o] = a.kind === 'point' ? [a, b] : [b, a];
      ref = (await reference.query(`pointin3 ${fmt(pt.point.x)} ${fmt(pt.point.y)} ${fmt(pt.point.z)} ${boundsLine(o)}`)).inside;
    } else {
      ref = (await reference.query(`overlap3 ${boundsLine(a)} ${boundsLine(b)}`)).overlap;
    }
    check(typeof ref === 'boolean', `${p.a} × ${p.b}: the reference rejected the query`);
    check(p.hit === ref, `${p.a} × ${p.b} (${p.fn}): the page says ${p.hit}, the C library ${ref}`);
  }
  await screenshot('web-bounds3d-drag.png');
}

async function bounds3dBroadphase({ page, url, screenshot }) {
  await open(page, url, 'bounds3d/');
  await page.check('input[name=mode][value="broad"]');
  await page.waitForFunction(() => window.__demo.broad.n > 0);
  await checkHud(page, 'boxes');
  // Each structure, after some frames of motion: its pairs against all pairs by brute force on
  // the very boxes the page gave it (touching counts).
  for (const structure of ['grid', 'tree', 'sap', 'spatialTree']) {
    await page.selectOption('#structure', structure);
    await nextFrames(page, 12);
    await page.evaluate(() => window.__demo.broad.setPaused(true));
    await nextFrames(page, 2);
    const snap = await page.evaluate(() => window.__demo.broad.snapshot());
    const n = snap.ids.length;
    check(n === 3000, `${structure}: ${n} boxes, expected 3000`);
    const b = snap.boxes;
    const expected = new Set();
    for (let i = 0; i < n; i++) {
      for (let j = i + 1; j < n; j++) {
        if (b[6 * i] <= b[6 * j + 3] && b[6 * j] <= b[6 * i + 3] && b[6 * i + 1] <= b[6 * j + 4] && b[6 * j + 1] <= b[6 * i + 4] &&
            b[6 * i + 2] <= b[6 * j + 5] && b[6 * j + 2] <= b[6 * i + 5]) expected.add(`${i},${j}`);
      }
    }
    const index = new Map(snap.ids.map((id, i) => [id, i]));
    const got = new Set();
    for (let p = 0; p < snap.pairs.length; p += 2) {
      const [i, j] = [index.get(snap.pairs[p]), index.get(snap.pairs[p + 1])].sort((x, y) => x - y);
      check(i !== undefined && j !== undefined && i !== j, `${structure}: pair ${snap.pairs[p]}, ${snap.pairs[p + 1]} names no two boxes`);
      got.add(`${i},${j}`);
    }
    check(got.size === snap.pairs.length / 2, `${structure}: the broadphase reported a pair twice`);
    const missing = [...expected].filter((k) => !got.has(k));
    const extra = [...got].filter((k) => !expected.has(k));
    check(expected.size > 50, `${structure}: only ${expected.size} overlapping pairs in the scene`);
    check(missing.length === 0 && extra.length === 0,
      `${structure}: pairs differ from all-pairs: ${missing.length} missing (${missing.slice(0, 5)}), ${extra.length} extra (${extra.slice(0, 5)})`);
    await page.waitForFunction((k) => Number(document.querySelector('[data-pairs]')?.textContent) === k, expected.size, { timeout: 3000 })
      .catch(async () => {
        throw new Error(`${structure}: the panel shows ${await page.locator('[data-pairs]').innerText()} pairs, all-pairs finds ${expected.size}`);
      });
    if (structure === 'grid') await screenshot('web-bounds3d-broadphase.png');
  }
}

async function bounds3dPhysics({ page, url }) {
  await open(page, url, 'bounds3d/');
  await page.check('input[name=mode][value="physics"]');
  const text = await page.locator('#physicsPending').innerText();
  check(text.includes('needs the 3D world'), `the physics mode does not say it waits for the 3D world: "${text}"`);
}

// ---- the pages that wait for the 2D world ----------------------------------------------------------
function shellLoad(name) {
  return async ({ page, url, screenshot }) => {
    await open(page, url, `${name}/`);
    await checkHud(page, 'bodies');
    const pending = await page.evaluate(() => window.__demo.pending);
    const banner = await page.locator('#pending').innerText();
    check(pending === 'needs the 2D world' && banner.includes('Pending: needs the 2D world'), `the ${name} page does not mark itself pending`);
    await screenshot(`web-${name}.png`);
  };
}
function shellGameplay(name, what) {
  return async ({ page, url }) => {
    await open(page, url, `${name}/`);
    const pending = await page.evaluate(() => window.__demo.pending);
    if (pending) throw new Pending(`${what} (the page says: ${pending})`);
    throw new Error(`the ${name} page is no longer pending: write this test (${what})`);
  };
}

// ---- the pages on the 2D world ------------------------------------------------------------------
async function world2dLoad(name) {
  return async ({ page, url, screenshot }) => {
    await open(page, url, `${name}/`);
    await checkHud(page, 'bodies');
    const demo = await page.evaluate(() => ({ pending: window.__demo.pending, bodies: window.__demo.bodies, error: window.__demo.error }));
    check(demo.pending === null && demo.error === null, `the ${name} page: pending ${demo.pending}, error ${demo.error}`);
    check(demo.bodies > 10, `the ${name} page shows ${demo.bodies} bodies`);
    await screenshot(`web-${name}.png`);
  };
}

/** Scripted keyboard: hold the right arrow until the character reaches the first pick-up. */
async function scrollerGameplay({ page, url, screenshot }) {
  await open(page, url, 'scroller/');
  const start = await page.evaluate(() => ({ score: window.__demo.score, x: window.__demo.character.x, pickups: window.__demo.pickups }));
  check(start.score === 0 && start.pickups === 5, `start: score ${start.score}, pick-ups ${start.pickups}`);
  await page.locator('#stage').focus();
  await page.keyboard.down('ArrowRight');
  await page.waitForFunction(() => window.__demo.score > 0, null, { timeout: 15000 });
  await page.keyboard.up('ArrowRight');
  const end = await page.evaluate(() => ({ score: window.__demo.score, picked: window.__demo.picked, x: window.__demo.character.x, shown: document.getElementById('score').textContent }));
  check(end.picked >= 1 && end.score === 10 * end.picked, `score ${end.score} for ${end.picked} pick-ups`);
  // The first pick-up is at x = 4 (radius 0.3, character radius 0.35): the character walked there.
  check(end.x > start.x + 3 && end.x < 6, `the character is at x = ${end.x}`);
  check(end.shown === String(end.score), `the page shows score ${end.shown}`);
  await screenshot('web-scroller-pickup.png');
}

/** Scripted drag: pull the projectile back from the slingshot and release it at the towers. */
async function slingshotGameplay({ page, url, screenshot }) {
  await open(page, url, 'slingshot/');
  const anchor = await page.evaluate(() => window.__demo.anchor);
  const box = await page.locator('#stage').boundingBox();
  const size = await page.evaluate(() => { const c = document.getElementById('stage'); return [c.width, c.height]; });
  const ax = box.x + anchor[0] * box.width / size[0], ay = box.y + anchor[1] * box.height / size[1];
  // Wait for the level to settle before the shot (it is built resting; sleeping starts after 0.5 s).
  await page.waitForFunction(() => window.__demo.awake === 0, null, { timeout: 20000 });
  await page.mouse.move(ax, ay);
  await page.mouse.down();
  for (let i = 1; i <= 10; i++) await page.mouse.move(ax - 8 * i, ay + 0.8 * i);
  await screenshot('web-slingshot-drag.png');
  await page.mouse.up();
  await page.waitForFunction(() => window.__demo.shots === 1, null, { timeout: 5000 });
  await page.waitForFunction(() => window.__demo.moved > 0, null, { timeout: 15000 });
  const hit = await page.evaluate(() => ({ moved: window.__demo.moved, score: window.__demo.score }));
  check(hit.score >= 100 * hit.moved, `score ${hit.score} for ${hit.moved} blocks moved`);
  // Fast-forward (8 steps per frame) until every body sleeps.
  await page.evaluate(() => { window.__demo.stepsPerFrame = 8; });
  await page.waitForFunction(() => window.__demo.awake === 0, null, { timeout: 45000 });
  const rest = await page.evaluate(() => ({ awake: window.__demo.awake, bodies: window.__demo.bodies, moved: window.__demo.moved }));
  check(rest.awake === 0 && rest.bodies > 20, `at rest: ${rest.awake} of ${rest.bodies} bodies awake`);
  await screenshot('web-slingshot-rest.png');
}

export const TESTS = [
  { name: 'explorer_load', run: explorerLoad },
  { name: 'explorer_2d', run: explorer2d },
  { name: 'explorer_3d', run: explorer3d },
  { name: 'bounds3d_load', run: bounds3dLoad },
  { name: 'bounds3d_drag', run: bounds3dDrag },
  { name: 'bounds3d_broadphase', run: bounds3dBroadphase },
  { name: 'bounds3d_physics', run: bounds3dPhysics },
  { name: 'scroller_load', run: await world2dLoad('scroller') },
  { name: 'scroller_gameplay', run: scrollerGameplay },
  { name: 'slingshot_load', run: await world2dLoad('slingshot') },
  { name: 'slingshot_gameplay', run: slingshotGameplay },
];
