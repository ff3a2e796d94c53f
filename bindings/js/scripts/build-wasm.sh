#!/usr/bin/env bash
# Builds dist/collide-simd.wasm (wasm SIMD) and dist/collide.wasm (scalar, for engines without
# wasm SIMD) from the library's own sources (../../src) and the export layer (src/*.c), with
# clang-19 for wasm32-wasi and wasi-libc linked statically. Installs the compiler with apt-get
# when it is missing (Debian 12), as ../../scripts/ensure-deps.sh does for the C build.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
root=$(cd "$here/../.." && pwd)
cc=${COLLIDE_WASM_CC:-clang-19}

missing=()
command -v "$cc" >/dev/null 2>&1 || missing+=(clang-19)
command -v wasm-ld-19 >/dev/null 2>&1 || missing+=(lld-19)
[ -e /usr/share/wasi-sysroot ] || [ -e /usr/lib/wasm32-wasi ] || dpkg -s wasi-libc >/dev/null 2>&1 || missing+=(wasi-libc)
dpkg -s libclang-rt-19-dev-wasm32 >/dev/null 2>&1 || missing+=(libclang-rt-19-dev-wasm32)
command -v wasm-opt >/dev/null 2>&1 || missing+=(binaryen)
if [ ${#missing[@]} -gt 0 ]; then
	echo "collide: installing missing packages: ${missing[*]}"
	sudo=""
	[ "$(id -u)" -eq 0 ] || sudo="sudo"
	$sudo apt-get update -qq
	DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

out="$here/dist"
gen="$here/build/include/collide"
mkdir -p "$out" "$gen"
version=$(sed -n 's/^project(collide VERSION \([0-9.]*\).*/\1/p' "$root/CMakeLists.txt")
IFS=. read -r major minor patch <<<"$version"
# The float configuration of the library (what the native float build generates from the same file).
sed -e 's/@CD_DOUBLE_VALUE@/0/' -e "s/@PROJECT_VERSION_MAJOR@/$major/" \
	-e "s/@PROJECT_VERSION_MINOR@/$minor/" -e "s/@PROJECT_VERSION_PATCH@/$patch/" \
	"$root/include/collide/config.h.in" >"$gen/config.h.tmp"
cmp -s "$gen/config.h.tmp" "$gen/config.h" 2>/dev/null || mv "$gen/config.h.tmp" "$gen/config.h"
rm -f "$gen/config.h.tmp"

# -ffp-contract=off as in the native build (no fused multiply-add: the same bits everywhere).
# 8 MiB stack: the 3D manifolds need more than wasm-ld's 64 KiB default.
common=(--target=wasm32-wasi -O3 -flto -DNDEBUG -std=c11 -ffp-contract=off
	-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Werror
	-I"$root/include" -I"$here/build/include" -I"$root/src" -DCOLLIDE_BUILDING)
link=(-nostartfiles -Wl,--no-entry -Wl,-z,stack-size=8388608 -Wl,--strip-debug)
sources=("$root"/src/*/*.c "$here"/src/*.c)

build() {
	local name=$1
	shift
	"$cc" "${common[@]}" "$@" "${sources[@]}" "${link[@]}" -o "$out/$name.tmp"
	mv "$out/$name.tmp" "$out/$name"
}
build collide-simd.wasm -msimd128 &
simd=$!
build collide.wasm
wait "$simd"
ls -l "$out"/*.wasm
