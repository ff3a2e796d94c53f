#!/usr/bin/env bash
# The main job: build the collide tool and run it on the bundled example, printing the table
# of every pair and writing the picture to out/seeds.svg.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# shellcheck source=ensure-deps.sh
. "$root/scripts/ensure-deps.sh"
collide_ensure_deps

build="$root/build/release"
mkdir -p "$build"
if ! { cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCOLLIDE_BUILD_TESTS=OFF \
	-DCOLLIDE_BUILD_BENCH=OFF -DCOLLIDE_BUILD_TOOLS=ON &&
	cmake --build "$build" -j"$(nproc)" --target collide_tool; } >"$build/build.log" 2>&1; then
	cat "$build/build.log"
	exit 1
fi
mkdir -p "$root/out"
"$build/tools/collide" query "$root/examples/seeds.json" --svg "$root/out/seeds.svg"
echo "picture written to out/seeds.svg"
