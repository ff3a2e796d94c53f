#!/usr/bin/env bash
# Builds and runs the whole test suite three times: the float build, the double build
# (COLLIDE_DOUBLE) and the sanitizer build (clang, AddressSanitizer + UBSan, Debug so that
# CD_ASSERT is live, plus short deterministic fuzzer runs). Warnings are errors in all three. Ends with CTest's summary.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# shellcheck source=ensure-deps.sh
. "$root/scripts/ensure-deps.sh"
collide_ensure_deps tests

jobs=$(nproc)
run_suite() {
	local name=$1
	shift
	local build="$root/build/$name"
	echo "=== $name build ==="
	mkdir -p "$build"
	# Quiet when all is well; the whole log when configuring or compiling fails.
	if ! { cmake -S "$root" -B "$build" -DCOLLIDE_WERROR=ON "$@" &&
		cmake --build "$build" -j"$jobs"; } >"$build/build.log" 2>&1; then
		cat "$build/build.log"
		echo "collide: the $name build failed" >&2
		exit 1
	fi
	ctest --test-dir "$build" -j"$jobs" --output-on-failure --timeout 600
}

run_suite float -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCOLLIDE_BUILD_JS_TESTS=ON
run_suite double -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCOLLIDE_DOUBLE=ON -DCOLLIDE_BENCH_BOX2D_V3=OFF
# The sanitizer build also builds the libFuzzer targets and runs each for a fixed number of
# inputs (fuzz/CMakeLists.txt).
CC=clang CXX=clang++ run_suite sanitize -DCMAKE_BUILD_TYPE=Debug -DCOLLIDE_SANITIZE=ON -DCOLLIDE_BUILD_FUZZ=ON -DCOLLIDE_BENCH_BOX2D_V3=OFF
