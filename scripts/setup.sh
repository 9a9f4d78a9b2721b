#!/usr/bin/env bash
# Installs the Debian packages Sextant needs (only the missing ones, non-interactively, with sudo
# when not root, `apt-get update` at most once), then configures and builds Release into build/.
# Usage: [SEXTANT_BUILD_TARGETS="sextant …"] scripts/setup.sh [extra cmake -D options...]
# The configuration is one for every caller (scripts/main.sh and test.sh share build/: the test
# command after the main one compiles only what the main one did not need); SEXTANT_BUILD_TARGETS
# builds only those targets (main.sh: the CLI and the Python module, not the tests).
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake pkg-config git
          libeigen3-dev libceres-dev libpcl-dev libgeographiclib-dev libyaml-cpp-dev libtbb-dev
          libcli11-dev libfmt-dev libbenchmark-dev libgtest-dev libopenmpi-dev
          libboost-math-dev  # χ², normal, Student-t and binomial distributions (core/chi_square, eval/)
          nlohmann-json3-dev  # JSON of the result rows, provenance and metrics (pipeline/json.hpp)
          libnanoflann-dev  # bench/bench_kd_tree.cpp measures ICP's k-d tree against it
          libjs-three  # three.js for the 3D views (eval/cloud_view.hpp), read at run time
          libsqlite3-dev libzstd-dev liblz4-dev libbz2-dev)  # recordings/: ROS 2 .db3, MCAP/bag chunks
# Further packages a caller needs (scripts/test.sh: chromium, which renders the report in the tests;
# scripts/main.sh and test.sh: pybind11, NumPy and pytest for the Python module, -DSEXTANT_PYTHON=ON).
read -r -a extra <<<"${SEXTANT_EXTRA_PACKAGES:-}"
packages+=("${extra[@]}")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSEXTANT_PYTHON=ON "$@"
read -r -a targets <<<"${SEXTANT_BUILD_TARGETS:-}"
if ((${#targets[@]})); then
  cmake --build build -j"$jobs" --target "${targets[@]}"
else
  cmake --build build -j"$jobs"
fi
