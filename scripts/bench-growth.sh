#!/usr/bin/env bash
# The tree's growth from 100,000 to 1,000,000 boxes (issue 4's N log N target: at most 12.0x),
# measured so that a shared, noisy machine does not decide it: each (scene, dimension, N) runs in
# its own process, and the rounds alternate all eight cases. Interference only adds time, so the
# fastest run of each case is the estimate of the quiet machine; medians are printed beside it.
# Two tables: the whole frame (moves + UpdatePairs + the bench's pair-set sweep, the figure the
# target is about) and the library's part of it (moves + UpdatePairs, the mean phases per frame).
# A third estimates the quiet machine frame by frame instead of run by run: the scene is
# deterministic, so frame k does the same work in every round, and the mean over k of frame k's
# fastest round removes interference from each frame alike. The fastest whole run could favour the
# short case (a 100,000-box run, 0.2 s of timed frames, finds a quiet spell more often than a
# 1,000,000-box run, 3 s); on the Xeon of docs/BROADPHASE.md the two agreed within 1-3%.
# Two cache protocols, alternated within every round, each with its three tables:
# - warm: a frame starts with the caches as the frame before left them. At 100,000 boxes the
#   broadphase's own data (about 12 MB: tree, proxy table, pair list) stays in a 33 MB L3 from one
#   frame to the next; at 1,000,000 (over 100 MB) it cannot, so the growth also holds the step
#   from L3 hits to main-memory misses on that data;
# - evicted: EVICT_MB megabytes of other memory are read before each frame (the bench's
#   --evict-mb, untimed), so that every frame starts with the caches an engine frame leaves
#   behind: the narrowphase, the solver and the game read far more than the L3 between two
#   broadphase updates. The growth is then the broadphase's own at both sizes.
# Usage: scripts/bench-growth.sh [ROUNDS] [EVICT_MB] (defaults 6 and 64; about two minutes per
# round on 2 cores).
# Needs collide_bench_broad built by scripts/bench-all.sh (build/bench). Nothing here is a test.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
rounds=${1:-6}
evict_mb=${2:-64}
bench="$root/build/bench/bench/broad/collide_bench_broad"
if [ ! -x "$bench" ]; then
	echo "build it first: scripts/bench-all.sh --only broad1m (or cmake with -DCOLLIDE_BUILD_BENCH=ON into build/bench)" >&2
	exit 2
fi
samples=$(mktemp)
frames_warm=$(mktemp)
frames_evicted=$(mktemp)
trap 'rm -f "$samples" "$frames_warm" "$frames_evicted"' EXIT
for round in $(seq 1 "$rounds"); do
	for scene in mix moving; do
		for dim in 2 3; do
			for n in 100000 1000000; do
				for protocol in warm evicted; do
					evict=0
					frames=$frames_warm
					if [ "$protocol" = evicted ]; then
						evict=$evict_mb
						frames=$frames_evicted
					fi
					line=$("$bench" --dim "$dim" --n "$n" --scene "$scene" --structures tree --frames 60 \
						--warmup 20 --cpu-time --evict-mb "$evict" --frame-times "$frames" | grep '^tree')
					mean=$(echo "$line" | grep -o 'frames: mean [0-9.]*' | awk '{print $3}')
					library=$(echo "$line" | grep -o 'move [0-9.]* ms, UpdatePairs [0-9.]*' | awk '{print $2 + $5}')
					echo "$protocol $scene $dim $n $mean $library" >>"$samples"
					echo "round $round/$rounds: ${dim}D $scene N=$n caches $protocol: mean frame $mean ms, library $library ms" >&2
				done
			done
		done
	done
done
# Per case of one protocol ($1; one line "scene dim N estimate [median]"): the fastest and the
# median of the rounds (column $2: 5 frame, 6 library).
rounds_estimate() {
	awk -v protocol="$1" -v column="$2" '
	function median(list, count,    sorted, i, j, t) {
		split(list, sorted, " ")
		for (i = 2; i <= count; ++i) for (j = i; j > 1 && sorted[j - 1] + 0 > sorted[j] + 0; --j) { t = sorted[j]; sorted[j] = sorted[j - 1]; sorted[j - 1] = t }
		return count % 2 ? sorted[(count + 1) / 2] : (sorted[count / 2] + sorted[count / 2 + 1]) / 2
	}
	$1 == protocol { key = $2 " " $3 " " $4; v = $column + 0
	  if (!(key in count) || v < fastest[key]) fastest[key] = v
	  values[key] = (key in count) ? values[key] " " v : v; count[key]++ }
	END { for (key in count) print key, fastest[key], median(values[key], count[key]) }' "$samples"
}
# Per case: the mean over the frames of each frame's fastest round, from the --frame-times file $1
# (lines "dim N scene structure t1 t2 ...").
frames_estimate() {
	awk '
	{ key = $3 " " $1 " " $2
	  for (f = 5; f <= NF; ++f) { k = key SUBSEP f; if (!(k in fastest) || $f + 0 < fastest[k]) fastest[k] = $f + 0 }
	  if (!(key in last) || NF > last[key]) last[key] = NF }
	END {
		for (key in last) {
			sum = 0
			for (f = 5; f <= last[key]; ++f) sum += fastest[key SUBSEP f]
			print key, sum / (last[key] - 4)
		}
	}' "$1"
}
# Reads estimate lines; prints growth = 1,000,000 over 100,000, medians in brackets when given.
growth_table() {
	echo "$1"
	awk '
	{ key = $1 " " $2 " " $3; estimate[key] = $4; if (NF > 4) median[key] = $5 }
	END {
		printf "| | 100,000 | 1,000,000 | growth%s |\n|---|---:|---:|---|\n", length(median) ? ", fastest runs (medians)" : ""
		split("moving mix", scenes, " ")
		for (s = 1; s <= 2; ++s) for (dim = 2; dim <= 3; ++dim) {
			small = scenes[s] " " dim " 100000"; large = scenes[s] " " dim " 1000000"
			if (!(small in estimate) || !(large in estimate)) continue
			if (small in median)
				printf "| %dD %s | %.2f ms (%.2f) | %.1f ms (%.1f) | %.2fx (%.2fx) |\n", dim, scenes[s], estimate[small], median[small], estimate[large], median[large], estimate[large] / estimate[small], median[large] / median[small]
			else
				printf "| %dD %s | %.2f ms | %.1f ms | %.2fx |\n", dim, scenes[s], estimate[small], estimate[large], estimate[large] / estimate[small]
		}
	}'
}
for protocol in warm evicted; do
	if [ "$protocol" = warm ]; then
		echo "## Caches warm: each frame starts with what the frame before left cached"
		frames=$frames_warm
	else
		echo
		echo "## Caches evicted: $evict_mb MB of other memory read before each frame"
		frames=$frames_evicted
	fi
	echo
	rounds_estimate "$protocol" 5 | growth_table "Mean frame (moves + UpdatePairs + the bench's pair-set sweep):"
	echo
	rounds_estimate "$protocol" 6 | growth_table "The library's part (moves + UpdatePairs):"
	echo
	frames_estimate "$frames" | growth_table "Mean over the frames of each frame's fastest round (whole frame; see the top of this script):"
done
