#!/usr/bin/env bash
# Setup + build + the whole test suite (the README's second command; CI runs it with -DSEXTANT_WERROR=ON).
# The build is scripts/main.sh's: after it, only the tests and benchmarks are compiled.
set -euo pipefail
cd "$(dirname "$0")/.."
# The report tests render every generated page and figure in headless Chromium: install it too.
# The slurm_cluster test stands up a one-node Slurm cluster: slurm-wlm (slurmctld, slurmd, sbatch) and munge.
# The Python module (SEXTANT_PYTHON) and its pytest suite (tests/python/, run by ctest): pybind11, NumPy,
# pytest and Debian's python3 headers.
SEXTANT_EXTRA_PACKAGES="chromium slurm-wlm munge python3-dev pybind11-dev python3-pybind11 python3-numpy \
python3-pytest ${SEXTANT_EXTRA_PACKAGES:-}" scripts/setup.sh "$@"
jobs=$(nproc 2>/dev/null || echo 2)
cd build
ctest --output-on-failure -j"$jobs"
