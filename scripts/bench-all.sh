#!/usr/bin/env bash
# Runs every benchmark program (docs/PERFORMANCE.md, docs/BROADPHASE.md) on a Release build and
# keeps each program's output, with the machine it ran on, in one folder:
#
#   ./scripts/bench-all.sh [--runs N] [--quick] [--out DIR] [--only NAME[,NAME...]]
#
# --runs N   runs of each program (default 3): the machines are shared and noisy, so quote the
#            median of the runs and compare ratios within one run.
# --quick    one run of each program in its smoke mode (checks that everything runs).
# --only     a subset: query, manifold3, gjk3, manifold2, cast, chain2, hull, mesh, broad, broad1m.
# Needs the peers (Bullet, FCL, Box2D 2.4, libccd, qhull): ensure-deps.sh installs them.
# Nothing here is a test: timings never decide a test's outcome.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# shellcheck source=ensure-deps.sh
. "$root/scripts/ensure-deps.sh"
collide_ensure_deps tests

runs=3
quick=0
out=""
only="query,manifold3,gjk3,manifold2,cast,chain2,hull,mesh,broad,broad1m"
while [ $# -gt 0 ]; do
	case "$1" in
	--runs) runs=$2; shift 2 ;;
	--quick) quick=1; runs=1; shift ;;
	--out) out=$2; shift 2 ;;
	--only) only=$2; shift 2 ;;
	*) echo "usage: $0 [--runs N] [--quick] [--out DIR] [--only NAME,...]" >&2; exit 2 ;;
	esac
done
out=${out:-"$root/out/bench-$(date -u +%Y%m%d-%H%M)"}
mkdir -p "$out"

build="$root/build/bench"
echo "=== building (Release) into $build"
if ! { cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCOLLIDE_BUILD_TESTS=OFF \
	-DCOLLIDE_BUILD_BENCH=ON -DCOLLIDE_BUILD_TOOLS=OFF &&
	cmake --build "$build" -j"$(nproc)"; } >"$out/build.log" 2>&1; then
	cat "$out/build.log"
	exit 1
fi

{
	echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
	echo "commit: $(git -C "$root" rev-parse --short HEAD)$(git -C "$root" diff --quiet || echo ' (with uncommitted changes)')"
	echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
	lscpu | grep -E 'Model name|^CPU\(s\)|L1d|L2|L3'
	gcc --version | head -1
} >"$out/machine.txt"
cat "$out/machine.txt"

wanted() { case ",$only," in *",$1,"*) return 0 ;; *) return 1 ;; esac; }

# run NAME RUN-ARGS...: the program's output of run k goes to $out/NAME.k.txt.
run() {
	local name=$1
	shift
	wanted "$name" || return 0
	for k in $(seq 1 "$runs"); do
		echo "=== $name, run $k of $runs: $*"
		"$@" >"$out/$name.$k.txt" 2>&1 || echo "$name run $k exited with $?" | tee -a "$out/errors.txt"
		grep -v '^Warning: distance function' "$out/$name.$k.txt" | tail -n 40
	done
}

b="$build/bench"
if [ "$quick" = 1 ]; then
	run query "$b/collide_bench" --quick
	run manifold3 "$b/manifold3/collide_bench_manifold3" --quick
	run gjk3 "$b/cast/collide_bench_gjk3" --quick
	run manifold2 "$b/manifold2/collide_bench_manifold2" --quick
	run cast "$b/cast/collide_bench_cast" --quick
	run chain2 "$b/chain2/collide_bench_chain2" --quick
	run hull "$b/hull/collide_bench_hull_peers" --quick
	run mesh "$b/mesh/collide_bench_mesh" --quick
	run broad "$b/broad/collide_bench_broad" --quick
else
	run query "$b/collide_bench"
	run manifold3 "$b/manifold3/collide_bench_manifold3"
	run gjk3 "$b/cast/collide_bench_gjk3"
	run manifold2 "$b/manifold2/collide_bench_manifold2"
	run cast "$b/cast/collide_bench_cast"
	run chain2 "$b/chain2/collide_bench_chain2"
	run hull "$b/hull/collide_bench_hull_peers"
	run mesh "$b/mesh/collide_bench_mesh"
	# Up to 100,000 with every peer; a million with collide's structures (the peers need seconds
	# to minutes per frame there). 60 timed frames: the moving scene's fat boxes expire in waves
	# and Bullet's dbvt works in stages, so short windows misstate the cost per frame (compare the
	# means the rows print).
	run broad "$b/broad/collide_bench_broad" --dim 2,3 --n 1000,10000,100000 --scene moving,mix \
		--frames 60 --warmup 20 --cpu-time --max-frame-seconds 5
	run broad1m "$b/broad/collide_bench_broad" --dim 2,3 --n 100000,1000000 --scene moving,mix \
		--structures tree,grid,octree --frames 60 --warmup 20 --cpu-time
fi
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)" >>"$out/machine.txt"
echo "outputs in $out"
