#!/usr/bin/env bash
# Runs the JavaScript benchmarks on a fresh machine: installs this folder's npm packages (the
# physics engines compared: planck, matter-js, @dimforge/rapier2d-compat, box2d-wasm,
# box2d3-wasm; versions pinned by package-lock.json) when they are missing, builds collide's wasm
# module (bindings/js: npm install && npm run build, which installs clang-19 with apt-get when it
# is missing) when it is missing or older than the sources, then runs the benchmark.
#   bench/js/run.sh [world2 | queries | broadphase] [ARGS...]     (default: world2)
#   bench/js/run.sh world2 --runs 3 --scene pyramid_20 --engine collide,box2d3-wasm --budget 20
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
js="$root/bindings/js"

command -v npm >/dev/null 2>&1 || {
	sudo=""
	[ "$(id -u)" -eq 0 ] || sudo="sudo"
	$sudo apt-get update -qq
	DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq nodejs npm >/dev/null
}

if [ ! -d "$here/node_modules/box2d3-wasm" ] || [ ! -d "$here/node_modules/planck" ] ||
	[ ! -d "$here/node_modules/@dimforge/rapier2d-compat" ] || [ ! -d "$here/node_modules/box2d-wasm" ] ||
	[ ! -d "$here/node_modules/matter-js" ] || [ ! -e "$here/node_modules/collide" ]; then
	(cd "$here" && npm ci --no-audit --no-fund --loglevel=error)
fi

wasm="$js/dist/collide-simd.wasm"
stale=0
if [ ! -f "$wasm" ] || [ ! -f "$js/dist/collide.wasm" ]; then
	stale=1
elif [ -n "$(find "$root/src" "$root/include" "$js/src" -newer "$wasm" \( -name '*.c' -o -name '*.h' -o -name '*.in' \) -print -quit)" ]; then
	stale=1
fi
if [ "$stale" -eq 1 ]; then
	(cd "$js" && { [ -d node_modules ] || npm install --no-audit --no-fund --loglevel=error; } && npm run --silent build)
fi

what=${1:-world2}
[ $# -gt 0 ] && shift
case "$what" in
world2) exec node "$here/bench_world2.mjs" "$@" ;;
queries) exec node "$here/bench_queries.mjs" "$@" ;;
broadphase) exec node "$here/bench_broadphase.mjs" "$@" ;;
*)
	echo "usage: $0 [world2 | queries | broadphase] [ARGS...]" >&2
	exit 2
	;;
esac
