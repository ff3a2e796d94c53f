#!/usr/bin/env bash
# Builds what the demo pages need: the wasm package (bindings/js: npm install, npm run build, which
# installs its compiler with apt-get when missing) and the pages (web/: npm install, node
# build.mjs -> web/dist). With --tests it also installs Debian's chromium for the browser tests
# when it is missing (nothing downloads a browser of its own). Installs node and npm with apt-get
# when they are missing. Quiet when all is well.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

missing=()
command -v node >/dev/null 2>&1 || missing+=(nodejs)
command -v npm >/dev/null 2>&1 || missing+=(npm)
if [ "${1:-}" = "--tests" ] && [ -z "${CHROMIUM_PATH:-}" ]; then
	command -v chromium >/dev/null 2>&1 || missing+=(chromium)
fi
if [ ${#missing[@]} -gt 0 ]; then
	echo "collide: installing missing packages: ${missing[*]}"
	sudo=""
	[ "$(id -u)" -eq 0 ] || sudo="sudo"
	$sudo apt-get update -qq
	DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

npm_install() {
	# npm ci when a lock file is there (reproducible), npm install otherwise.
	local dir=$1
	if [ -f "$dir/package-lock.json" ]; then
		(cd "$dir" && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
	else
		(cd "$dir" && npm install --no-audit --no-fund --loglevel=error >/dev/null)
	fi
}

js="$root/bindings/js"
[ -d "$js/node_modules" ] || npm_install "$js"
# The wasm build takes half a minute: redo it only when a C source, header or build script is newer.
wasm="$js/dist/collide.wasm"
if [ ! -f "$wasm" ] || [ ! -f "$js/dist/collide-simd.wasm" ] ||
	[ -n "$(find "$root/src" "$root/include" "$js/src" "$js/scripts" -newer "$wasm" -print -quit)" ]; then
	(cd "$js" && npm run --silent build >/dev/null)
fi
[ -d "$root/web/node_modules/playwright-core" ] && [ -e "$root/web/node_modules/collide" ] || npm_install "$root/web"
(cd "$root/web" && node build.mjs)
