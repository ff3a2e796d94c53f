#!/usr/bin/env bash
# Cross-builds the library and the 2D world's tests for aarch64 (Debian's gcc-aarch64-linux-gnu)
# and runs them under qemu-user: the wide contact solver's NEON lanes (test_wide2) and the world
# tests, whose golden hash (test_world2_determinism) is the x86-64 SSE2 build's. Float build by
# default; pass -DCOLLIDE_DOUBLE=ON (or any other CMake option) to add it to the configure line.
# About 2 minutes on 2 cores. Installs the cross compiler and qemu when they are missing.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# shellcheck source=ensure-deps.sh
. "$root/scripts/ensure-deps.sh"
collide_ensure_deps aarch64

build="${COLLIDE_AARCH64_BUILD:-$root/build/aarch64}"
mkdir -p "$build"
sysroot=/usr/aarch64-linux-gnu
toolchain="$build/aarch64-toolchain.cmake"
cat >"$toolchain" <<TOOLCHAIN
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_FIND_ROOT_PATH $sysroot)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64 -L $sysroot)
TOOLCHAIN

tests=(test_wide2 test_world2 test_world2_determinism test_world2_features test_world2_random
	test_world2_recycle test_world2_spinner test_world2_pyramid40 test_graph_color)
# No pkg-config packages of the target: the differential tests against the host's peers stay out.
if ! { PKG_CONFIG_LIBDIR="$sysroot/lib/pkgconfig" cmake -S "$root" -B "$build" \
	-DCMAKE_TOOLCHAIN_FILE="$toolchain" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCOLLIDE_WERROR=ON \
	-DCOLLIDE_BUILD_BENCH=OFF -DCOLLIDE_BUILD_TOOLS=OFF "$@" &&
	cmake --build "$build" -j"$(nproc)" --target "${tests[@]}"; } >"$build/build.log" 2>&1; then
	cat "$build/build.log"
	echo "collide: the aarch64 build failed" >&2
	exit 1
fi
regex="^($(IFS='|'; echo "${tests[*]}"))\$"
ctest --test-dir "$build" -R "$regex" --output-on-failure --timeout 600
