#!/usr/bin/env bash
# The real-sequence half of the table behind the ML-NDT defaults (docs/matcher_defaults.md): `sextant
# odometry` over the campus and both trustworthy MulRan stretches with the defaults and with one setting
# changed at a time. Prints, per setting and sequence, the KITTI drift, the ATE, the untrusted steps and
# the steps more than 1 m or 5° off the reference that say they are trusted (the issue's bar: none).
#
#   bench/sequence_settings.sh [build/app/sextant] [path/to/mulran_riverside02] [output folder]
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=bench/sequence_common.sh
source bench/sequence_common.sh "$@"

# label | the --config file's body (empty: the defaults)
settings=(
  "defaults|"
  "truncation in the last 2 layers|matcher: {truncated_layers: 2}"
  "5 layers|matcher: {layers: 5}"
  "start layer 1|matcher: {start_layer: 1}"
  "GBS 1 m cells, 10 points each|sampler: {max_per_cell: 10}"
  "GBS 0.5 m cells|sampler: {cell_size: 0.5}"
  "GBS 0.5 m cells, 10 points each|sampler: {cell_size: 0.5, max_per_cell: 10}"
  "bounding box (bounds_quantile: 0)|matcher: {bounds_quantile: 0}"
  "no precision stage|matcher: {precision_min_cell: 0}"
  "LM without a function tolerance (ε alone)|matcher: {function_tolerance: 0}"
)

row() {  # row <dir>
  awk -F, -v drift="$(field "$1/metrics.json" estimate drift_percent)" \
      -v ate="$(field "$1/metrics.json" estimate ate_m)" '
    NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
    { if ($col["trust"] != "ok") ++untrusted
      else if ($col["error_m"] != "" && ($col["error_m"] > 1.0 || $col["error_deg"] > 5.0)) ++wrong }
    END { printf " %.2f %% / %.3f m / %d / %d |", drift, ate, untrusted, wrong }' "$1/steps.csv"
}

echo "| setting | campus: drift / ATE / untrusted / trusted but wrong | MulRan 0–107 | MulRan 116–165 |"
echo "|---|---|---|---|"
k=0
for entry in "${settings[@]}"; do
  label=${entry%%|*} body=${entry#*|}
  k=$((k + 1))
  config="$out/setting$k.yaml"
  printf '%s\n' "$body" >"$config"
  printf "| %s |" "$label"
  for sequence in "campus|campus" "mulran0|$mulran --first 0 --scans 108" "mulran116|$mulran --first 116 --scans 50"; do
    dir="$out/setting$k-${sequence%%|*}"
    # shellcheck disable=SC2086  # the sequence is a folder and its options
    if "$sextant" odometry ${sequence#*|} --config "$config" --out "$dir" --no-progress >"$dir.log" 2>&1; then
      row "$dir"
    else
      printf " failed: see %s.log |" "$dir"
    fi
  done
  echo
done
echo "(outputs in $out)"
