#!/usr/bin/env bash
# Builds the WebAssembly module of bindings/js and runs its node tests. Installs what is missing:
# node and npm (apt-get), the wasm compiler (clang-19, lld-19, wasi-libc, binaryen: apt-get, by
# bindings/js/scripts/build-wasm.sh) and the package's npm devDependencies (npm install).
#   scripts/test-web.sh            setup, then every test file
#   scripts/test-web.sh setup      only install and build (CTest's js_setup fixture)
#   scripts/test-web.sh test F...  only run the given test files (names in bindings/js/test/)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
js="$root/bindings/js"

setup() {
	local missing=()
	command -v node >/dev/null 2>&1 || missing+=(nodejs)
	command -v npm >/dev/null 2>&1 || missing+=(npm)
	command -v cc >/dev/null 2>&1 || missing+=(gcc)
	if [ ${#missing[@]} -gt 0 ]; then
		echo "collide: installing missing packages: ${missing[*]}"
		local sudo=""
		[ "$(id -u)" -eq 0 ] || sudo="sudo"
		$sudo apt-get update -qq
		DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
	fi
	cd "$js"
	if [ ! -x node_modules/.bin/tsc ]; then
		npm install --no-audit --no-fund --loglevel=error
	fi
	npm run --silent build
}

run_tests() {
	cd "$js"
	local files=()
	local f
	for f in "$@"; do files+=("test/$f"); done
	node --test "${files[@]}"
}

case "${1:-all}" in
setup) setup ;;
test)
	shift
	run_tests "$@"
	;;
all)
	setup
	run_tests api.test.mjs errors.test.mjs exact.test.mjs types.test.mjs pack.test.mjs world2.test.mjs lockstep.test.mjs mesh_chain.test.mjs
	;;
*)
	echo "usage: $0 [setup | test FILE... | all]" >&2
	exit 2
	;;
esac
