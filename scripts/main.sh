#!/usr/bin/env bash
# Setup + build + the built-in experiments on the built-in synthetic dataset + the report
# (the README's first command). Pass --full for the full profile instead of --quick.
set -euo pipefail
cd "$(dirname "$0")/.."
profile="--quick"
[ "${1:-}" = "--full" ] && profile=""
scripts/setup.sh
./build/experiments/sextant reproduce $profile --results results --report report
