#!/usr/bin/env bash
# Builds and runs the 2D world benchmark (bench/world2, docs/PERFORMANCE.md "2D world"): every scene
# of scenes/world2_quality.h on collide and on the peers in the same run (Box2D v3 built from
# ../shared/peers/box2d-v3.tar.gz by the bench's CMake, Box2D 2.4 and Chipmunk from Debian), with
# 1 and 2 workers, the median of the runs, memory per body and per contact and each engine's
# quality criterion. A missing peer is reported as missing, not as a failure.
#
#   ./scripts/bench-world2.sh [--runs N] [--scene NAME[,NAME...]] [--out FILE]
#
# Nothing here is a test: timings never decide a test's outcome (the CTest is bench_world2_smoke).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# shellcheck source=ensure-deps.sh
. "$root/scripts/ensure-deps.sh"
collide_ensure_deps tests

args=(--runs 3)
out=""
while [ $# -gt 0 ]; do
	case "$1" in
	--runs) args=(--runs "$2"); shift 2 ;;
	--scene) scene=$2; shift 2 ;;
	--out) out=$2; shift 2 ;;
	*) echo "usage: $0 [--runs N] [--scene NAME,...] [--out FILE]" >&2; exit 2 ;;
	esac
done
[ -n "${scene:-}" ] && args+=(--scene "$scene")

build="$root/build/bench"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCOLLIDE_BUILD_TESTS=OFF \
	-DCOLLIDE_BUILD_BENCH=ON -DCOLLIDE_BUILD_TOOLS=OFF >/dev/null
cmake --build "$build" -j"$(nproc)" --target collide_bench_world2 >/dev/null
out=${out:-"$root/out/bench-world2-$(date -u +%Y%m%d-%H%M).txt"}
mkdir -p "$(dirname "$out")"
{
	echo "# $(date -u +%Y-%m-%dT%H:%MZ) $(lscpu | sed -n 's/^Model name: *//p') x $(nproc)"
	"$build/bench/world2/collide_bench_world2" "${args[@]}"
} | tee "$out"
echo "written: $out"
