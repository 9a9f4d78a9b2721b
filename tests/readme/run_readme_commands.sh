#!/usr/bin/env bash
# Runs every command of the README (the `build/app/sextant …` and `PYTHONPATH=… python3 …`
# lines of its bash blocks) in order, as a user would from the source folder after the build: in a
# scratch folder whose build/, data/, docs/, experiments/ and python/ point at this build and
# source tree. Each must exit 0. Two kinds are not run here, and the test says so: the `sextant
# slurm` lines (the test slurm_cluster runs them verbatim on a one-node cluster) and a line whose
# comment says "not run by the tests" (the 13-minute full profile).
#
#   run_readme_commands.sh <source dir> <build dir>
set -euo pipefail
source_dir=$1
build_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
ln -s "$build_dir" "$work/build"
for d in data docs experiments python; do ln -s "$source_dir/$d" "$work/$d"; done
cd "$work"

mapfile -t commands < <(awk '/^```bash/ {inside = 1; next} /^```/ {inside = 0} inside' "$source_dir/README.md" |
  grep -E '^(build/app/sextant|PYTHONPATH=)')
((${#commands[@]} >= 8)) || { echo "readme: expected at least 8 commands in README.md, found ${#commands[@]}" >&2; exit 1; }
ran=0
for line in "${commands[@]}"; do
  if [[ $line == *"sextant slurm"* ]]; then
    echo "readme: left to the test slurm_cluster: $line"
    continue
  fi
  if [[ $line == *"not run by the tests"* ]]; then
    echo "readme: not run (its comment says why): $line"
    continue
  fi
  command=${line%%#*}  # without the trailing comment
  echo "readme: $command"
  status=0
  bash -c "$command" >"$work/last.log" 2>&1 || status=$?
  if ((status != 0)); then
    echo "readme: FAILED (exit $status): $command" >&2
    tail -20 "$work/last.log" >&2
    exit 1
  fi
  ran=$((ran + 1))
done
echo "readme: $ran commands ran and exited 0"
