#!/usr/bin/env bash
# Installs with apt-get whatever the build, the tool and the test suite need and this machine
# lacks. Sourced by the other scripts; does nothing when everything is already there.
set -euo pipefail

collide_missing_packages() {
	local missing=()
	command -v cmake >/dev/null 2>&1 || missing+=(cmake)
	command -v cc >/dev/null 2>&1 || missing+=(gcc)
	command -v make >/dev/null 2>&1 || missing+=(make)
	command -v pkg-config >/dev/null 2>&1 || missing+=(pkg-config)
	dpkg -s libcjson-dev >/dev/null 2>&1 || missing+=(libcjson-dev)
	# PNG frames of `collide run` (the tool builds without it, with SVG frames only).
	dpkg -s libcairo2-dev >/dev/null 2>&1 || missing+=(libcairo2-dev)
	if [ "${1:-}" = "tests" ]; then
		command -v clang >/dev/null 2>&1 || missing+=(clang)
		# clang's AddressSanitizer/UBSan runtime lives in a separate package on Debian 12.
		ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.asan-x86_64.a >/dev/null 2>&1 ||
			missing+=(libclang-rt-14-dev)
		command -v xmllint >/dev/null 2>&1 || missing+=(libxml2-utils)
		command -v c++ >/dev/null 2>&1 || missing+=(g++)
		# The peers: benchmark columns and differential tests always run against them.
		local peer
		for peer in libbullet-dev libfcl-dev libbox2d-dev libccd-dev libqhull-dev; do
			dpkg -s "$peer" >/dev/null 2>&1 || missing+=("$peer")
		done
		# The 2D world benchmark's Chipmunk column (bench/world2).
		dpkg -s libchipmunk-dev >/dev/null 2>&1 || missing+=(libchipmunk-dev)
		# ODE's trimesh: the mesh-ray column of collide_bench_scenes (bench/scenes).
		dpkg -s libode-dev >/dev/null 2>&1 || missing+=(libode-dev)
	fi
	# scripts/test-aarch64.sh (the test_aarch64_qemu CTest of the float suite): the aarch64 cross
	# compiler and qemu's user-mode emulator.
	if [ "${1:-}" = "aarch64" ] || [ "${1:-}" = "tests" ]; then
		command -v aarch64-linux-gnu-gcc >/dev/null 2>&1 || missing+=(gcc-aarch64-linux-gnu libc6-dev-arm64-cross)
		command -v qemu-aarch64 >/dev/null 2>&1 || missing+=(qemu-user)
	fi
	echo "${missing[@]:-}"
}

collide_ensure_deps() {
	local missing
	missing=$(collide_missing_packages "${1:-}")
	if [ -n "$missing" ]; then
		echo "collide: installing missing packages: $missing"
		local sudo=""
		[ "$(id -u)" -eq 0 ] || sudo="sudo"
		$sudo apt-get update -qq
		# shellcheck disable=SC2086
		DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq $missing >/dev/null
	fi
}
