#!/usr/bin/env bash
# Builds and runs the whole test suite three times: the float build, the double build
# (COLLIDE_DOUBLE) and the sanitizer build (clang, AddressSanitizer + UBSan, Debug so that
# CD_ASSERT is live, plus short deterministic fuzzer runs), with a ThreadSanitizer build of the 2D
# world's threads test before the last. Warnings are errors in all of them. Ends with CTest's summary.
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

run_suite float -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCOLLIDE_BUILD_JS_TESTS=ON -DCOLLIDE_TEST_AARCH64=ON
run_suite double -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCOLLIDE_DOUBLE=ON -DCOLLIDE_BENCH_BOX2D_V3=OFF
# ThreadSanitizer (clang, Debug): only the 2D world's threads test (the built-in pool and a user
# task system with 2 and 4 workers), about 45 s to build and run.
echo "=== tsan build (test_world2_determinism) ==="
tsan="$root/build/tsan"
mkdir -p "$tsan"
if ! { CC=clang cmake -S "$root" -B "$tsan" -DCOLLIDE_WERROR=ON -DCMAKE_BUILD_TYPE=Debug \
	-DCMAKE_C_FLAGS="-fsanitize=thread -g" -DCMAKE_EXE_LINKER_FLAGS=-fsanitize=thread \
	-DCMAKE_SHARED_LINKER_FLAGS=-fsanitize=thread -DCOLLIDE_BENCH_BOX2D_V3=OFF &&
	cmake --build "$tsan" -j"$jobs" --target test_world2_determinism; } >"$tsan/build.log" 2>&1; then
	cat "$tsan/build.log"
	echo "collide: the tsan build failed" >&2
	exit 1
fi
TSAN_OPTIONS=halt_on_error=1 ctest --test-dir "$tsan" -R '^test_world2_determinism$' --output-on-failure --timeout 600
# The sanitizer build also builds the libFuzzer targets and runs each for a fixed number of
# inputs (fuzz/CMakeLists.txt).
CC=clang CXX=clang++ run_suite sanitize -DCMAKE_BUILD_TYPE=Debug -DCOLLIDE_SANITIZE=ON -DCOLLIDE_BUILD_FUZZ=ON -DCOLLIDE_BENCH_BOX2D_V3=OFF
