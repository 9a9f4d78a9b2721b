#!/usr/bin/env bash
# Builds the libFuzzer harnesses (fuzz/, clang, ASan + UBSan) in build-fuzz/ and runs each for
# SECONDS seconds (default 20) on its seed corpus, one at a time; stops at the first finding
# (the crashing input is left as build-fuzz/fuzz/crash-* / leak-* / timeout-*).
# Usage: scripts/fuzz.sh [SECONDS [harness...]]      e.g. scripts/fuzz.sh 300 pcd ply
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-20}
shift || true
scripts/ensure_packages.sh clang libclang-rt-14-dev build-essential cmake pkg-config libeigen3-dev \
  libpcl-dev libgeographiclib-dev libyaml-cpp-dev libtbb-dev libcli11-dev libfmt-dev libceres-dev libopenmpi-dev \
  libsqlite3-dev libzstd-dev liblz4-dev libbz2-dev
jobs=$(nproc 2>/dev/null || echo 2)
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DSEXTANT_FUZZ=ON -DSEXTANT_BUILD_TESTS=OFF -DSEXTANT_BUILD_BENCHMARKS=OFF "${launcher[@]}" >/dev/null
cmake --build build-fuzz -j"$jobs" --target sextant_fuzz
harnesses=("$@")
((${#harnesses[@]})) || harnesses=(uos_3d uos_pose uos_frames kitti_bin xyz32 kitti_poses kitti_calib pcd ply csv
                                   tum kitti_traj oxts rosbag1 mcap config)
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
cd build-fuzz/fuzz
for h in "${harnesses[@]}"; do
  mkdir -p "work/$h"
  echo "fuzz: $h for ${seconds} s"
  # work/<h> collects new inputs; corpus/<h> (the seeds from data/) is only read.
  ./"fuzz_$h" -max_total_time="$seconds" -max_len=4096 -rss_limit_mb=2048 -timeout=10 -print_final_stats=1 \
    "work/$h" "corpus/$h" 2>"$h.log" || { tail -40 "$h.log"; echo "fuzz: $h found a problem (see build-fuzz/fuzz/$h.log)"; exit 1; }
  grep -E "stat::number_of_executed_units|cov:" "$h.log" | tail -2
done
