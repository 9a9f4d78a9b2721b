#!/usr/bin/env bash
# The real-sequence benchmark (issue 22): `sextant odometry` with no options over the built-in
# campus and the two trustworthy stretches of the shared MulRan Riverside02 excerpt (0–107 and
# 116–165; its reference is wrong in between, see ../shared/data/README.md), then the same scans
# with PCL's GICP (`--method pcl_gicp --map scan --no-recover`: a plain GICP loop) as the baseline
# row. Prints one table: ATE, RPE, KITTI drift, the signed mean pitch error per step with its
# standard error (`sextant eval`), time per scan (wall: the whole run over its steps; registration:
# the registrations' own seconds over the steps, which the parallel scan-to-scan path overlaps on
# several cores) and the trust counts (untrusted steps, recovered steps).
#
#   bench/sequences.sh [build/experiments/sextant] [path/to/mulran_riverside02] [output folder]
#
# Timings are single runs on whatever the machine is doing: run it on a quiet machine.
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=bench/sequence_common.sh
source bench/sequence_common.sh "$@"

run() {  # run <id> <label> <row> <method> <dataset> [odometry options...]
  local id=$1 label=$2 row=$3 method=$4 dataset=$5
  shift 5
  local dir="$out/$id-${row// /_}"
  "$sextant" odometry "$dataset" --method "$method" --out "$dir" --no-progress "$@" >"$dir.log" 2>&1 ||
    { echo "| $label | $row | failed: see $dir.log |"; return; }
  local m="$dir/metrics.json" steps registration pitch
  steps=$(($(top "$m" scans) - 1))
  # The registrations' own seconds (steps.csv: registration, reference model, sampling; recoveries
  # included), without loading or generating the scans and building the local map.
  registration=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "seconds") c = i; next }
                         { s += $c } END { printf "%.6f", s }' "$dir/steps.csv")
  # The RPE's signed mean pitch per step and its standard error (`sextant eval`): a drift made of one
  # bias every step shares.
  pitch=$("$sextant" eval "$dir/groundtruth.tum" "$dir/trajectory.tum" --json |
          sed -E 's/.*"rotation_deg": \[[^,]*, ([^,]*),.*"rotation_deg_standard_error": \[[^,]*, ([^,]*),.*/\1 \2/')
  awk -v label="$label" -v method="$row" -v steps="$steps" -v secs="$(top "$m" seconds)" \
      -v registration="$registration" -v pitch="$pitch" \
      -v ate="$(field "$m" estimate ate_m)" -v rpe="$(field "$m" estimate rpe_m)" \
      -v rpedeg="$(field "$m" estimate rpe_deg)" -v drift="$(field "$m" estimate drift_percent)" \
      -v untrusted="$(top "$m" untrusted)" -v recovered="$(top "$m" recovered)" \
      -v nc="$(top "$m" not_converged)" 'BEGIN {
        split(pitch, p, " ")
        printf "| %s | %s | %.3f | %.3f / %.2f | %.2f | %.3f ± %.3f | %.1f | %.1f | %d | %d | %d |\n", label, method,
               ate, rpe, rpedeg, drift, p[1], p[2], 1000 * secs / steps, 1000 * registration / steps, nc, untrusted,
               recovered }'
}

echo "| sequence | method | ATE [m] | RPE per step [m / °] | KITTI drift [%] | pitch bias per step [°] | ms per scan | registration ms per scan | not converged | untrusted | recovered |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
# ML-NDT with every core (the default) and on one thread (`-j 1`: the same trajectory, bit for bit).
# The baseline is the peer as a plain GICP loop runs it: scan to scan, no recovery (its trust is
# still counted).
for row in mlndt "mlndt -j 1" pcl_gicp; do
  method=${row%% *}
  extra=()
  [ "$row" = "mlndt -j 1" ] && extra=(-j 1)
  [ "$method" = pcl_gicp ] && extra=(--no-recover --map scan)
  run campus "campus (468 scans, odometry guess)" "$row" "$method" campus "${extra[@]}"
  run mulran0 "MulRan 0–107" "$row" "$method" "$mulran" --first 0 --scans 108 "${extra[@]}"
  run mulran116 "MulRan 116–165" "$row" "$method" "$mulran" --first 116 --scans 50 "${extra[@]}"
done
echo "(outputs in $out)"
