# shellcheck shell=bash
# Shared by the real-sequence benchmarks (sequences.sh, sequence_settings.sh): their arguments,
# checked — [sextant binary] [MulRan folder] [output folder] — and the reading of metrics.json.
# Sourced from the repository's root with "$@".
sextant=${1:-build/app/sextant}
mulran=${2:-../shared/data/mulran_riverside02}
out=${3:-$(mktemp -d)}
mkdir -p "$out"
script="bench/$(basename "$0")"
[ -x "$sextant" ] || { echo "$script: no sextant at $sextant (build first)" >&2; exit 1; }
[ -d "$mulran" ] || { echo "$script: no MulRan folder at $mulran" >&2; exit 1; }

# Numbers from metrics.json (one line, known layout): a section's key, or a top-level key.
field() {  # field <metrics.json> <section> <key>
  sed -E "s/.*\"$2\": \{[^}]*\"$3\": ([-0-9.eE+]+|null).*/\1/" "$1"
}
top() {  # top <metrics.json> <key>
  sed -E "s/.*\"$2\": ([-0-9.eE+]+|null).*/\1/" "$1"
}
