#!/usr/bin/env bash
# ctest: the quick profile of E1, E4, E10, E17 and E18 through the `sextant` binary, then the whole
# generated report rendered in headless Chromium (scripts/check_report_html.sh): every figure the
# report wrote must appear on the page and render, every experiment must have its section, tables
# and overview row, and every linked 3D view must exist and draw.
# Usage: quick_report_renders.sh <sextant binary> <source dir>
set -euo pipefail
sextant=$1
source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
configs=(e01_convergence_basin e04_init_vs_layer e10_merging_tests e17_seif e18_metric_examples)
for c in "${configs[@]}"; do
  "$sextant" run "$source_dir/experiments/$c.yaml" --quick --results "$work/results" --jobs 2 >/dev/null
done
"$sextant" report "$work/results" --out "$work/report" >/dev/null
index="$work/report/index.html"
fail() { echo "quick_report_renders: $*" >&2; exit 1; }
for c in "${configs[@]}"; do
  grep -q "<section id=\"$c\">" "$index" || fail "no section for $c"
  grep -q "href=\"#$c\"" "$index" || fail "no overview row linking to $c"
  ls "$work/report/$c/"*.md >/dev/null 2>&1 || fail "no Markdown tables for $c"
  ls "$work/report/$c/"*.tex >/dev/null 2>&1 || fail "no LaTeX tables for $c"
done
figures=$(find "$work/report" -name '*.svg' | wc -l)
images=$(grep -o '<img ' "$index" | wc -l)
[[ $figures -gt 0 && $figures -eq $images ]] || fail "$figures SVG files but $images images on the page"
output=$("$source_dir/scripts/check_report_html.sh" "$index") || fail "broken images: $output"
echo "$output"
# The 3D views the report links (E1's snapshot) exist and draw in Chromium (WebGL via SwiftShader).
views=$(grep -o '<p class="sx-view"><a href="[^"]*"' "$index" | sed -E 's/.*href="([^"]*)"/\1/' || true)
[[ -n $views ]] || fail "no 3D view linked (E1's snapshot)"
[[ -f $work/report/three.min.js ]] || fail "no three.min.js beside the 3D views"
for view in $views; do
  [[ -f $work/report/$view ]] || fail "3D view $view is linked but missing"
  dom=$(timeout 120 chromium --headless --no-sandbox --disable-gpu --use-gl=swiftshader --enable-unsafe-swiftshader \
    --no-first-run --disable-background-networking --user-data-dir="$work/chromium" --virtual-time-budget=10000 \
    --dump-dom "file://$work/report/$view" 2>/dev/null) || fail "chromium failed on $view"
  grep -q 'data-sx-webgl="ok"' <<<"$dom" || fail "3D view $view did not draw"
done
echo "quick_report_renders: ${#configs[@]} experiments, $figures figures render, 3D views draw: $views"
