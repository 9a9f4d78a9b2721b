#!/usr/bin/env bash
# docs/experiments.md carries the experiment → kind → layout table that `sextant info experiments/
# --markdown` generates from the configs: fails, with the difference, when they disagree (a config
# added or changed without regenerating the table).
#   experiment_table_in_docs.sh <sextant> <source dir>
set -euo pipefail
sextant=$1
src=$2
generated=$(cd "$src" && "$sextant" info experiments --markdown 2>/dev/null)
begin='<!-- generated: sextant info experiments --markdown -->'
end='<!-- end generated -->'
documented=$(sed -n "/^$begin\$/,/^$end\$/p" "$src/docs/experiments.md" | sed '1d;$d')
if [ "$generated" != "$documented" ]; then
  echo "docs/experiments.md: the experiment table differs from 'sextant info experiments --markdown':"
  diff <(echo "$documented") <(echo "$generated") || true
  echo "regenerate it: build/app/sextant info experiments --markdown"
  exit 1
fi
echo "docs/experiments.md: experiment table matches the configs ($(echo "$generated" | wc -l) lines)"
