// Builds the demo pages into web/dist: one esbuild bundle per page (three.js and the collide
// package come from node_modules, exactly as a user's app would get them), the pages' HTML and
// CSS, and the collide package's wasm files next to the bundles that load them.
//   node build.mjs [--dev]     (--dev: no minification, inline source maps)
import { build } from 'esbuild';
import { cp, mkdir, rm } from 'node:fs/promises';
import { createRequire } from 'node:module';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const dev = process.argv.includes('--dev');
const pagesDir = join(here, 'pages');
const dist = join(here, 'dist');

export const PAGES = ['explorer', 'bounds3d', 'scroller', 'slingshot'];

const started = performance.now();
await rm(dist, { recursive: true, force: true });
await mkdir(dist, { recursive: true });

// The collide package's two wasm builds (SIMD and scalar), copied next to every page bundle:
// pages/common/collide.js loads them from there.
const require = createRequire(import.meta.url);
let wasmFiles;
try {
  wasmFiles = ['collide-simd.wasm', 'collide.wasm'].map((f) => require.resolve(`collide/dist/${f}`));
} catch (err) {
  console.error(`web/build.mjs: the collide package has no wasm build (${err.message.split('\n')[0]}); run \`npm run build\` in bindings/js first`);
  process.exit(1);
}

await build({
  entryPoints: PAGES.map((p) => ({ in: join(pagesDir, p, 'main.js'), out: `${p}/main` })),
  bundle: true,
  format: 'esm',
  target: 'es2022',
  outdir: dist,
  minify: !dev,
  sourcemap: dev ? 'inline' : false,
  logLevel: 'warning',
  // The loader may reach for node-only modules behind a runtime check; never in a browser.
  external: ['node:*', 'fs', 'path', 'url', 'module'],
});

await cp(join(pagesDir, 'index.html'), join(dist, 'index.html'));
await cp(join(pagesDir, 'common'), join(dist, 'common'), { recursive: true });
for (const page of PAGES) {
  await cp(join(pagesDir, page, 'index.html'), join(dist, page, 'index.html'));
  for (const wasm of wasmFiles) await cp(wasm, join(dist, page, wasm.split('/').pop()));
}
console.log(`web: built ${PAGES.length} pages into ${dist} in ${Math.round(performance.now() - started)} ms`);
