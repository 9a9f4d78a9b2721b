#!/usr/bin/env bash
# The test suite under AddressSanitizer + UndefinedBehaviorSanitizer (SEXTANT_SANITIZE=ON: UBSan in
# the algorithm libraries and the CLI, not in the test files or the experiments library;
# CompilerOptions.cmake says why), in its own
# build folder (build-asan/, clang, RelWithDebInfo at -O1 -g1, no benchmarks). Installs what is
# missing through scripts/setup.sh's package list first. CI (.ci/run) runs it after scripts/test.sh,
# which builds with GCC, so the suite passes under both compilers. Clang here: the instrumented build
# takes 1466 s of compile time against GCC's 2111 s (2 cores), and the suite runs in 436 s against 512.
# Usage: scripts/sanitize.sh [extra cmake -D options...]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/ensure_packages.sh clang libclang-rt-14-dev build-essential cmake pkg-config git libeigen3-dev \
  libceres-dev libpcl-dev libgeographiclib-dev libyaml-cpp-dev libtbb-dev libcli11-dev libfmt-dev libgtest-dev libopenmpi-dev \
  libsqlite3-dev libzstd-dev liblz4-dev libbz2-dev
jobs=$(nproc 2>/dev/null || echo 2)
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# -O1 -g1 (ASan's recommended optimisation, line tables for the reports): about half the compile
# time of -O2 -g per file and a third of the object size, which keeps .ci/run within its budget.
# No Python module here: an interpreter cannot load an ASan-instrumented extension without LD_PRELOAD
# of the ASan runtime (python/CMakeLists.txt refuses the combination).
cmake -S . -B build-asan -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DSEXTANT_SANITIZE=ON -DSEXTANT_WERROR=ON -DSEXTANT_BUILD_BENCHMARKS=OFF -DSEXTANT_PYTHON=OFF "${launcher[@]}" "$@"
cmake --build build-asan -j"$jobs"
# Any ASan/LSan/UBSan report fails its test (UBSan: -fno-sanitize-recover, see CompilerOptions.cmake).
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
cd build-asan
# Tests of the Release stage (scripts/test.sh) left out here. Three exercise scripts and outside
# programs whose C++ paths the sanitized suite already runs:
# - `slurm` (the one-node Slurm cluster): shards, merge and resume planning run in
#   sextant_experiments_tests (SlurmScripts.*, Runner.*);
# - `install` (installs the libraries and builds a consumer project against them): CMake packaging;
# - `end_to_end` (quick_report_renders: five quick profiles through the `sextant` binary, the report
#   rendered in Chromium): those profiles run as sextant_experiments_tests, the report tests too.
# - eight quick profiles that repeat a run kind another test already runs here (the same kind, other
#   settings; together 260 s of the stage's CPU, which .ci/run's 45 minutes need). The Release stage
#   runs all eight:
#   - E1, E4 and E3/E4/E6 on MulRan: the registration kind (E3, E5, E6 and E2 on MulRan run);
#   - E13, E19 and E23: the plane-SLAM kind (E12, E14, E16 and E17 run; E23's FastSLAM filter runs in
#     FastSlamCampus.* and FastSlamAssociationCampus.*);
#   - E24: the place-recognition kind (ScanContext.* and OdometryCli.LoopClosureByPlaceRecognition*
#     run its Scan Context on the campus);
#   - the hybrid-SLAM quick profile (HybridSlam.HybridEkfIsCloserEarly* runs the hybrid filter);
#   - deskew over the whole eased route, 1,258 scans (SweepingCampus.OnAStraight* and RoundACorner* run
#     the same deskew on its first 72 and 110).
ctest --output-on-failure -j"$jobs" -LE 'slurm|install|end_to_end' \
  -E '^(E01\.QuickProfileWritesEveryTableAndFigure|RegistrationExperiments\.(E4QuickProfile|E3E4E6OnMulranQuickProfiles)|Experiments/PlaneSlamQuick\.QuickProfileRunsAndReports/e(13|19|23)|PlaceRecognitionKind\.E24QuickProfile[A-Za-z]*|HybridSlam\.QuickProfileOutputShape|SweepingCampus\.OverTheWholeRouteWithEasedCorners[A-Za-z]*)( |$)'
