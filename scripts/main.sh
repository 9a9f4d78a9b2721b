#!/usr/bin/env bash
# Setup + build + the built-in experiments on the built-in synthetic dataset + the report
# (the README's first command). Pass --full for the full profile instead of --quick.
set -euo pipefail
cd "$(dirname "$0")/.."
profile="--quick"
[ "${1:-}" = "--full" ] && profile=""
# The Python module (python/, SEXTANT_PYTHON) is built too: pybind11, NumPy and Debian's python3 headers.
# Only the CLI and the Python module are compiled; scripts/test.sh, in the same build/, adds the tests.
SEXTANT_BUILD_TARGETS="sextant sextant_python" \
SEXTANT_EXTRA_PACKAGES="python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest \
${SEXTANT_EXTRA_PACKAGES:-}" scripts/setup.sh
./build/app/sextant reproduce $profile --results results --report report
