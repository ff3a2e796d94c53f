// Shared by the pages on collide's 2D world: the navigation bar, a camera from world metres (y up)
// to canvas pixels (y down), and drawing every body of a World2 from one getTransforms() view
// (one call into wasm per frame, not one per body). Each body's userData.draw lists what to draw
// in the body frame: {box: [hx, hy]}, {circle: r}, {capsule: [halfLength, r]} (along y) or
// {poly: [[x, y], ...]}, with a fill colour.
import { PAGES } from './hud.js';

export function navigation(pageName) {
  const nav = document.querySelector('header nav');
  for (const [id, title] of PAGES) {
    const a = document.createElement('a');
    a.href = `../${id}/`;
    a.textContent = title;
    if (id === pageName) a.setAttribute('aria-current', 'page');
    nav.append(a);
  }
}

/**
 * The canvas maps world point (x, y) to pixel ((x - cx) * scale + width / 2, height - (y - cy) *
 * scale - floor): metres to pixels times `scale`, the world's y axis flipped (canvas y points
 * down), the camera at (cx, cy).
 */
export function createCamera(canvas, scale, floor = 40) {
  return {
    scale, cx: 0, cy: 0,
    toCanvas(x, y) { return [(x - this.cx) * this.scale + canvas.width / 2, canvas.height - (y - this.cy) * this.scale - floor]; },
    toWorld(px, py) { return [(px - canvas.width / 2) / this.scale + this.cx, (canvas.height - floor - py) / this.scale + this.cy]; },
    /** Canvas transform for a body at (x, y) with rotation (c, s): world y up becomes canvas y down. */
    apply(ctx, x, y, c, s) {
      const [px, py] = this.toCanvas(x, y);
      const k = this.scale;
      ctx.setTransform(k * c, -k * s, -k * s, -k * c, px, py);
    },
  };
}

export function drawWorld(ctx, camera, world, options = {}) {
  const t = world.getTransforms();
  const bodies = world.bodies;
  const dim = options.showSleep ?? true;
  for (let k = 0; k < bodies.length; k++) {
    const body = bodies[k];
    const d = body.userData;
    if (!d || !d.draw) continue;
    camera.apply(ctx, t[4 * k], t[4 * k + 1], t[4 * k + 2], t[4 * k + 3]);
    const asleep = dim && d.dynamic && !body.awake;
    for (const item of d.draw) {
      ctx.fillStyle = item.color ?? d.color ?? '#8a94a8';
      ctx.globalAlpha = asleep ? 0.55 : 1;
      ctx.beginPath();
      if (item.box) {
        const [hx, hy] = item.box, ox = item.at?.[0] ?? 0, oy = item.at?.[1] ?? 0;
        ctx.rect(ox - hx, oy - hy, 2 * hx, 2 * hy);
      } else if (item.circle) {
        ctx.arc(item.at?.[0] ?? 0, item.at?.[1] ?? 0, item.circle, 0, 2 * Math.PI);
      } else if (item.capsule) {
        const [h, r] = item.capsule, ox = item.at?.[0] ?? 0, oy = item.at?.[1] ?? 0;
        ctx.arc(ox, oy + h, r, 0, Math.PI);
        ctx.arc(ox, oy - h, r, Math.PI, 2 * Math.PI);
        ctx.closePath();
      } else if (item.poly) {
        item.poly.forEach(([x, y], i) => (i ? ctx.lineTo(x, y) : ctx.moveTo(x, y)));
        ctx.closePath();
      }
      ctx.fill();
      if (item.stroke) {
        ctx.strokeStyle = item.stroke;
        ctx.lineWidth = 1.5 / camera.scale;
        ctx.stroke();
      }
    }
  }
  ctx.globalAlpha = 1;
  ctx.setTransform(1, 0, 0, 1, 0, 0);
}
