// Timing for the JavaScript benchmarks on a shared machine: CPU time of this process
// (process.cpuUsage: user + system), not wall time, so that time spent descheduled while other
// jobs run is not counted; the functions take turns sample after sample, and each reports the
// median of its samples.

export function cpuMs() {
  const u = process.cpuUsage();
  return (u.user + u.system) / 1000;
}

export function median(xs) {
  const s = [...xs].sort((a, b) => a - b);
  return s.length % 2 ? s[s.length >> 1] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
}

/** Milliseconds per call of each fn: `samples` samples of about `sampleMs` CPU ms each, interleaved. */
export function timeAll(fns, samples = 21, sampleMs = 10) {
  const reps = fns.map((fn) => {
    let n = 1;
    for (;;) {
      const t0 = cpuMs();
      for (let r = 0; r < n; r++) fn();
      const t = cpuMs() - t0;
      if (t > sampleMs) return n;
      n = t > 1 ? Math.ceil(n * 1.5 * sampleMs / t) : n * 4;
    }
  });
  const times = fns.map(() => []);
  for (let s = 0; s < samples; s++) {
    fns.forEach((fn, k) => {
      const t0 = cpuMs();
      for (let r = 0; r < reps[k]; r++) fn();
      times[k].push((cpuMs() - t0) / reps[k]);
    });
  }
  return times.map(median);
}
