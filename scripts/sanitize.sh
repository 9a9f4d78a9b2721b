#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer (SEXTANT_SANITIZE=ON),
# in its own build folder (build-asan/, RelWithDebInfo, no benchmarks). Installs what is missing
# through scripts/setup.sh's package list first. CI (.ci/run) runs it after scripts/test.sh.
# Usage: scripts/sanitize.sh [extra cmake -D options...]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/ensure_packages.sh build-essential cmake pkg-config git libeigen3-dev libceres-dev libpcl-dev \
  libgeographiclib-dev libyaml-cpp-dev libtbb-dev libcli11-dev libfmt-dev libgtest-dev libopenmpi-dev
jobs=$(nproc 2>/dev/null || echo 2)
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSEXTANT_SANITIZE=ON -DSEXTANT_WERROR=ON \
  -DSEXTANT_BUILD_BENCHMARKS=OFF "${launcher[@]}" "$@"
cmake --build build-asan -j"$jobs"
# detect_leaks: PCL/VTK/MPI keep static allocations alive at exit that LSan would report as leaks
# in code that is not ours; every other ASan/UBSan finding fails the test.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=0:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
cd build-asan
ctest --output-on-failure -j"$jobs"
