# The arguments of the real-sequence benchmarks (sequences.sh, sequence_settings.sh), checked:
# [sextant binary] [MulRan folder] [output folder]. Sourced from the repository's root with "$@".
sextant=${1:-build/experiments/sextant}
mulran=${2:-../shared/data/mulran_riverside02}
out=${3:-$(mktemp -d)}
mkdir -p "$out"
script="bench/$(basename "$0")"
[ -x "$sextant" ] || { echo "$script: no sextant at $sextant (build first)" >&2; exit 1; }
[ -d "$mulran" ] || { echo "$script: no MulRan folder at $mulran" >&2; exit 1; }
