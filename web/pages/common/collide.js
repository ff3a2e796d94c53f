// Loads collide's wasm from next to the page's bundle (web/build.mjs copies the package's two
// builds there): the SIMD build where the browser has wasm SIMD, the scalar one elsewhere. A
// bundled app passes the wasm's URL like this, since the package's own default URL is relative
// to the package's module, which a bundler moves.
import { init, simdSupported } from 'collide';

export function initCollide() {
  return init({ wasm: new URL(simdSupported() ? './collide-simd.wasm' : './collide.wasm', import.meta.url) });
}
