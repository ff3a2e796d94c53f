// The stage of the 2D pages that wait for collide's 2D world: a canvas in canvas coordinates
// (y down, pixels), the HUD with frame time and body count, and nothing simulated. When the
// world lands, the page's scene replaces drawStage's placeholder.
import { createHud, runLoop, PAGES } from './hud.js';

export function startShell(pageName, what) {
  const nav = document.querySelector('header nav');
  for (const [id, title] of PAGES) {
    const a = document.createElement('a');
    a.href = `../${id}/`;
    a.textContent = title;
    if (id === pageName) a.setAttribute('aria-current', 'page');
    nav.append(a);
  }
  const canvas = document.getElementById('stage');
  const ctx = canvas.getContext('2d');
  const hud = createHud(document.getElementById('hud'));
  const pending = document.body.dataset.pending || null;
  const demo = (window.__demo = { page: pageName, ready: false, pending, bodies: 0, hud: hud.state });

  function drawStage() {
    const { width: w, height: h } = canvas;
    ctx.fillStyle = '#0b0e14';
    ctx.fillRect(0, 0, w, h);
    // Canvas coordinates: origin top-left, x right, y down, in pixels; a 50 px grid.
    ctx.strokeStyle = '#1c2333';
    ctx.lineWidth = 1;
    ctx.beginPath();
    for (let x = 0; x <= w; x += 50) { ctx.moveTo(x + 0.5, 0); ctx.lineTo(x + 0.5, h); }
    for (let y = 0; y <= h; y += 50) { ctx.moveTo(0, y + 0.5); ctx.lineTo(w, y + 0.5); }
    ctx.stroke();
    ctx.strokeStyle = '#8a94a8';
    ctx.fillStyle = '#8a94a8';
    ctx.font = '12px ui-monospace, monospace';
    ctx.beginPath();
    ctx.moveTo(10, 10); ctx.lineTo(90, 10); ctx.moveTo(10, 10); ctx.lineTo(10, 90);
    ctx.stroke();
    ctx.fillText('x', 95, 14);
    ctx.fillText('y (down)', 4, 104);
    ctx.fillStyle = '#f0a040';
    ctx.font = '20px system-ui, sans-serif';
    ctx.textAlign = 'center';
    ctx.fillText(`${what}: waits for collide's 2D world`, w / 2, h / 2);
    ctx.textAlign = 'start';
  }

  runLoop(hud, () => {
    drawStage();
    return [demo.bodies, 'bodies'];
  });
  demo.ready = true;
  return demo;
}
