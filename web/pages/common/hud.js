// The head-up display every page shows: frame time (mean of the last 60 frames, and the time
// the page's own work took in them) and the number of objects on screen. It also publishes the
// page's state on window.__demo for the browser tests.

export function createHud(element) {
  const frames = [];
  const work = [];
  let last = 0;
  let count = 0;
  let countLabel = 'objects';
  const state = { frameMs: 0, workMs: 0, objects: 0, frames: 0 };
  let shown = 0;
  return {
    state,
    /** Call at the start of a frame with the rAF timestamp; returns the frame's start time. */
    begin(now) {
      if (last) {
        frames.push(now - last);
        if (frames.length > 60) frames.shift();
      }
      last = now;
      return performance.now();
    },
    /** Call at the end of the frame with begin()'s value and the current object count. */
    end(t0, objects, label = countLabel) {
      work.push(performance.now() - t0);
      if (work.length > 60) work.shift();
      count = objects;
      countLabel = label;
      state.frames++;
      const now = performance.now();
      if (now - shown < 250) return;
      shown = now;
      const mean = (a) => (a.length ? a.reduce((s, x) => s + x, 0) / a.length : 0);
      state.frameMs = mean(frames);
      state.workMs = mean(work);
      state.objects = count;
      const fps = state.frameMs > 0 ? 1000 / state.frameMs : 0;
      element.innerHTML =
        `frame <b data-frame-ms>${state.frameMs.toFixed(1)}</b> ms (${fps.toFixed(0)} fps) · ` +
        `work <b>${state.workMs.toFixed(2)}</b> ms · ` +
        `${countLabel} <b data-objects>${count}</b>`;
    },
  };
}

/** Runs frame(now) on every animation frame, inside the HUD's begin/end. frame returns the
 * object count (or [count, label]). */
export function runLoop(hud, frame) {
  const tick = (now) => {
    const t0 = hud.begin(now);
    const r = frame(now);
    if (Array.isArray(r)) hud.end(t0, r[0], r[1]);
    else hud.end(t0, r);
    requestAnimationFrame(tick);
  };
  requestAnimationFrame(tick);
}

/** The page's navigation bar; current is the page's folder name. */
export const PAGES = [
  ['explorer', 'Collision explorer'],
  ['bounds3d', 'Bounding volumes 3D'],
  ['scroller', 'Side-scroller'],
  ['slingshot', 'Slingshot'],
];
